/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stats_nonuni.c - statistics and spectrum of a line scan not uniformly
 * spaced, as a piecewise-linear function (formulas in stats_nonuni.h). */
#include "stats_nonuni.h"

#include <complex.h>
#include <math.h>
#include <stdlib.h>

/* Both ends of segment i valid. */
static int
segment_valid(const rc_grid *g, size_t i)
{
	return isfinite(g->z[i]) && isfinite(g->z[i + 1]);
}

/* The three-point second derivative at interior point i (header). */
static double
second_derivative(const double *x, const double *h, size_t i)
{
	double dm = x[i] - x[i - 1], dp = x[i + 1] - x[i];

	return 2 * (dm * (h[i + 1] - h[i]) + dp * (h[i - 1] - h[i])) /
	    (dp * dm * (dp + dm));
}

static int
check_nonuni(const rc_grid *g, rc_err *err)
{
	if (g->x == NULL || g->ny != 1 || g->nx < 2)
		return rc_seterr(err, "not a line scan with its positions "
		    "(%zux%zu)", g->nx, g->ny);
	/* a repeated or decreasing x makes a step of 0 or less: the slopes
	 * and the spectrum's k range divide by it */
	for (size_t i = 0; i + 1 < g->nx; i++)
		if (!(g->x[i + 1] > g->x[i]) || !isfinite(g->x[i + 1] - g->x[i]))
			return rc_seterr(err, "positions must strictly increase: "
			    "x[%zu] = %g, x[%zu] = %g", i, g->x[i], i + 1,
			    g->x[i + 1]);
	return 0;
}

int
rc_nonuni_stats_compute(const rc_grid *g, rc_nonuni_stats *s, rc_err *err)
{
	const double *x = g->x, *h = g->z;
	size_t n = g->nx, nc = 0;
	double sum_h = 0, sum_h2 = 0, sum_s2 = 0, sum_c2 = 0, lc = 0, c_prev = NAN;

	if (check_nonuni(g, err) != 0)
		return -1;
	s->n = n;
	s->n_missing = 0;
	s->n_segments = 0;
	s->length = 0;
	s->hmin = INFINITY;
	s->hmax = -INFINITY;
	for (size_t i = 0; i < n; i++) {
		if (!isfinite(h[i])) {
			s->n_missing++;
			continue;
		}
		s->hmin = fmin(s->hmin, h[i]);
		s->hmax = fmax(s->hmax, h[i]);
	}
	for (size_t i = 0; i + 1 < n; i++)
		if (segment_valid(g, i)) {
			double dx = x[i + 1] - x[i];

			s->n_segments++;
			s->length += dx;
			sum_h += dx * (h[i] + h[i + 1]) / 2;
		}
	if (s->n_segments == 0)
		return rc_seterr(err, "a line scan of %zu points, %zu missing: no "
		    "two neighbouring points are valid, so no segment to integrate "
		    "over", n, s->n_missing);
	s->mean = sum_h / s->length;
	for (size_t i = 0; i + 1 < n; i++)
		if (segment_valid(g, i)) {
			double dx = x[i + 1] - x[i], d0 = h[i] - s->mean,
			    d1 = h[i + 1] - s->mean, dh = h[i + 1] - h[i];

			sum_h2 += dx * (d0 * d0 + d0 * d1 + d1 * d1);
			sum_s2 += dh * dh / dx;
		}
	s->hrms = sqrt(sum_h2 / (3 * s->length));
	s->rms_slope = sqrt(sum_s2 / s->length);
	/* trapezoids of c^2 between neighbouring interior points that both
	 * have c (their three points valid) */
	for (size_t i = 1; i + 1 < n; i++) {
		double c = isfinite(h[i - 1]) && isfinite(h[i]) && isfinite(h[i + 1]) ?
		    second_derivative(x, h, i) : NAN;

		if (isfinite(c) && isfinite(c_prev)) {
			sum_c2 += (x[i] - x[i - 1]) * (c * c + c_prev * c_prev) / 2;
			lc += x[i] - x[i - 1];
			nc++;
		}
		c_prev = c;
	}
	s->rms_curvature = nc > 0 ? sqrt(sum_c2 / lc) : NAN;
	return 0;
}

/* sinc(u) = sin(u)/u and its derivative (cos u - sinc u)/u, by their
 * Taylor series near 0, where the latter cancels (terms to u^7: the next
 * is below 3e-16 for |u| < 0.1). */
static void
sinc_and_derivative(double u, double *sinc, double *dsinc)
{
	if (fabs(u) < 0.1) {
		double u2 = u * u;

		*sinc = 1 - u2 / 6 * (1 - u2 / 20 * (1 - u2 / 42 * (1 - u2 / 72)));
		*dsinc = -u / 3 * (1 - u2 / 10 * (1 - u2 / 28 * (1 - u2 / 54)));
		return;
	}
	*sinc = sin(u) / u;
	*dsinc = (cos(u) - *sinc) / u;
}

int
rc_nonuni_psd(const rc_grid *g, enum rc_window window, rc_psd1d_point **pts,
    size_t *npts, rc_err *err)
{
	const double *x = g->x;
	size_t n = g->nx, nq;
	double L, *y = NULL;
	rc_nonuni_stats st;

	*pts = NULL;
	*npts = 0;
	if (check_nonuni(g, err) != 0)
		return -1;
	if (window == RC_WINDOW_AUTO)
		window = RC_WINDOW_HANN;	/* a measurement: never periodic */
	if (window != RC_WINDOW_NONE && window != RC_WINDOW_HANN)
		return rc_seterr(err, "window %s: a line scan not uniformly spaced "
		    "takes hann or none (--uniform resamples it for the others)",
		    rc_window_name(window));
	if (n > RC_NONUNI_PSD_MAX)
		return rc_seterr(err, "a line scan of %zu points not uniformly "
		    "spaced: its exact spectrum costs n^2 operations, done up to "
		    "%d points; --uniform resamples it onto a uniform step",
		    n, RC_NONUNI_PSD_MAX);
	if (rc_nonuni_stats_compute(g, &st, err) != 0)
		return -1;
	if (st.n_missing > 0)
		return rc_seterr(err, "%zu of %zu points are missing: the spectrum "
		    "needs every point", st.n_missing, n);
	L = x[n - 1] - x[0];
	/* q_k below 2 pi / (L / (n - 1)), the mean step: k < n - 1 */
	nq = n - 2;
	if ((y = rc_malloc(n * sizeof(*y), err)) == NULL)
		return -1;
	for (size_t i = 0; i < n; i++) {
		double w = window == RC_WINDOW_HANN ? sqrt(2.0 / 3.0) *
		    (1 - cos(2 * M_PI * (x[i] - x[0]) / L)) : 1;

		y[i] = w * (g->z[i] - st.mean);
	}
	if (nq > 0 && (*pts = rc_malloc(nq * sizeof(**pts), err)) == NULL) {
		free(y);
		return -1;
	}
	for (size_t k = 1; k <= nq; k++) {
		double q = 2 * M_PI * (double)k / L;
		double complex sum = 0;

		for (size_t i = 0; i + 1 < n; i++) {
			double dx = x[i + 1] - x[i], sc, dsc;

			sinc_and_derivative(q * dx / 2, &sc, &dsc);
			sum += dx * cexp(-I * q * (x[i] + x[i + 1]) / 2) *
			    ((y[i] + y[i + 1]) / 2 * sc +
			    I * (y[i + 1] - y[i]) * dsc / 2);
		}
		(*pts)[k - 1].q = q;
		(*pts)[k - 1].c = creal(sum * conj(sum)) / L / (2 * M_PI);
		(*pts)[k - 1].n_lines = 1;
		(*pts)[k - 1].std_err = NAN;
	}
	*npts = nq;
	free(y);
	return 0;
}
