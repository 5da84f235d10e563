/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit.c - fit of the self-affine model of Eq. 2 to a surface's spectrum
 * (method in fit.h). */
#include "fit.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "si.h"
#include "spectral.h"
#include "units.h"

/* Below this fraction of the largest mode, power is FFT round-off. */
#define POWER_FLOOR 1e-20
#define HINGE_STEPS 200

void
rc_fit_opts_default(rc_fit_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->bins_per_decade = 10;
	o->window = RC_WINDOW_AUTO;
}

int
rc_fit_length_parse(const char *text, rc_fit_length *l, rc_err *err)
{
	char *end;

	memset(l, 0, sizeof(*l));
	l->value = strtod(text, &end);
	if (end == text || !isfinite(l->value) || !(l->value > 0))
		return rc_seterr(err, "'%s': want a positive length: a number in "
		    "the map's unit, a fraction of the scan (0.05L) or a length "
		    "with its unit (5um)", text);
	if (*end == '\0')
		return 0;
	if (strcmp(end, "L") == 0) {
		l->scan = 1;
		return 0;
	}
	if (!rc_unit_is_length(end) || strlen(rc_unit_canonical(end)) >=
	    sizeof(l->unit))
		return rc_seterr(err, "'%s': '%s' is neither L (a fraction of the "
		    "scan) nor a length unit (m mm um nm pm angstrom)", text, end);
	snprintf(l->unit, sizeof(l->unit), "%s", rc_unit_canonical(end));
	return 0;
}

int
rc_fit_length_resolve(const rc_fit_length *l, const rc_grid *g, double *out,
    rc_err *err)
{
	if (l->scan)
		*out = l->value * fmax(g->lx, g->ly);
	else if (l->unit[0] != '\0') {
		if (!rc_unit_is_length(g->unit))
			return rc_seterr(err, "%g%s: the map has no length unit; "
			    "give the wavelength as a fraction of the scan (e.g. "
			    "0.05L) or in the map's own lengths", l->value, l->unit);
		*out = rc_unit_convert(l->value, l->unit, g->unit);
	} else
		*out = l->value;
	if (!(*out > 0) || !isfinite(*out))
		return rc_seterr(err, "the wavelength %g is not a positive length "
		    "in the map's unit", *out);
	return 0;
}

double
rc_fit_model_hrms(double c_r, double hurst, double q_r, double q_s, int rolloff)
{
	double l = log(q_s / q_r);
	double band = hurst > 0 ? -expm1(-2 * hurst * l) / (2 * hurst) : l;

	return sqrt(2 * M_PI * c_r * q_r * q_r * (0.5 * rolloff + band));
}

/* Where the power starts and stops inside the range (step 1 of fit.h). */
struct edges {
	double lo_power, hi_power;	/* extreme |q| with power */
	double lo_empty, hi_empty;	/* nearest empty |q| outside them */
	int lo_cut, hi_cut;
};

static void
find_edges(const rc_grid *s, double qa, double qb, struct edges *e)
{
	double cmax = 0, dqx, dqy;
	size_t n = rc_grid_size(s), i0 = s->nx / 2, j0 = s->ny / 2;

	rc_grid_meta_getd(s, "dqx", &dqx);
	rc_grid_meta_getd(s, "dqy", &dqy);
	for (size_t k = 0; k < n; k++)
		cmax = fmax(cmax, s->z[k]);
	e->lo_power = INFINITY;
	e->hi_power = 0;
	e->lo_empty = -INFINITY;
	e->hi_empty = INFINITY;
	for (int pass = 0; pass < 2; pass++) {
		for (size_t j = 0; j < s->ny; j++)
			for (size_t i = 0; i < s->nx; i++) {
				double q = hypot(((double)i - (double)i0) * dqx,
				    ((double)j - (double)j0) * dqy);
				int power = s->z[j * s->nx + i] > POWER_FLOOR * cmax;
				if (q == 0 || q < qa || q > qb)
					continue;
				if (pass == 0 && power) {
					e->lo_power = fmin(e->lo_power, q);
					e->hi_power = fmax(e->hi_power, q);
				} else if (pass == 1 && !power) {
					if (q > e->hi_power)
						e->hi_empty = fmin(e->hi_empty, q);
					if (q < e->lo_power)
						e->lo_empty = fmax(e->lo_empty, q);
				}
			}
	}
	e->hi_cut = isfinite(e->hi_empty);
	e->lo_cut = isfinite(e->lo_empty);
}

struct hinge_data {
	const double *x, *y;
	size_t n;
};

/* ln C = a - (2 + 2H) max(0, x - xh); parameters (a, H, xh). */
static int
hinge_f(const gsl_vector *p, void *data, gsl_vector *f)
{
	const struct hinge_data *d = data;
	double a = gsl_vector_get(p, 0), h = gsl_vector_get(p, 1);
	double xh = gsl_vector_get(p, 2);

	for (size_t k = 0; k < d->n; k++)
		gsl_vector_set(f, k, a - (2 + 2 * h) * fmax(0, d->x[k] - xh) - d->y[k]);
	return GSL_SUCCESS;
}

static int
hinge_df(const gsl_vector *p, void *data, gsl_matrix *jac)
{
	const struct hinge_data *d = data;
	double h = gsl_vector_get(p, 1), xh = gsl_vector_get(p, 2);

	for (size_t k = 0; k < d->n; k++) {
		int above = d->x[k] > xh;
		gsl_matrix_set(jac, k, 0, 1);
		gsl_matrix_set(jac, k, 1, above ? -2 * (d->x[k] - xh) : 0);
		gsl_matrix_set(jac, k, 2, above ? 2 + 2 * h : 0);
	}
	return GSL_SUCCESS;
}

/* Linear fit y = a + b t, t = -max(0, x - xh) (a line if xh <= x[0]):
 * returns the residual sum of squares; a, b and their covariance. */
static double
line_fit(const double *x, const double *y, const double *wt, size_t n,
    double xh, double *c, double cov[2][2])
{
	gsl_matrix *X = gsl_matrix_alloc(n, 2), *cv = gsl_matrix_alloc(2, 2);
	gsl_vector *yy = gsl_vector_alloc(n), *cc = gsl_vector_alloc(2);
	gsl_vector *ww = gsl_vector_alloc(n);
	gsl_multifit_linear_workspace *w = gsl_multifit_linear_alloc(n, 2);
	double chisq = INFINITY;

	if (X && cv && yy && cc && ww && w) {
		for (size_t k = 0; k < n; k++) {
			gsl_matrix_set(X, k, 0, 1);
			gsl_matrix_set(X, k, 1, -fmax(0, x[k] - xh));
			gsl_vector_set(yy, k, y[k]);
			gsl_vector_set(ww, k, wt[k]);
		}
		if (gsl_multifit_wlinear(X, ww, yy, cc, cv, &chisq, w) != 0)
			chisq = INFINITY;
		else {
			c[0] = gsl_vector_get(cc, 0);
			c[1] = gsl_vector_get(cc, 1);
			/* the weights fix only relative variances: scale by
			 * the residual variance */
			if (cov != NULL)
				for (int i = 0; i < 2; i++)
					for (int j = 0; j < 2; j++)
						cov[i][j] = gsl_matrix_get(cv, i, j) *
						    chisq / (double)(n - 2);
		}
	}
	gsl_vector_free(ww);
	gsl_matrix_free(X);
	gsl_matrix_free(cv);
	gsl_vector_free(yy);
	gsl_vector_free(cc);
	gsl_multifit_linear_free(w);
	return chisq;
}

/* H and its error of a line through bins a .. b - 1; 0 if it fails. */
static int
segment_h(const double *x, const double *y, const double *wt, size_t a,
    size_t b, double *h, double *h_err)
{
	double c[2], cov[2][2];

	if (b < a + 3 || !isfinite(line_fit(x + a, y + a, wt + a, b - a, x[a],
	    c, cov)))
		return 0;
	*h = c[1] / 2 - 1;
	*h_err = sqrt(cov[1][1]) / 2;
	return 1;
}

/* Step 4 on bins a .. b - 1: H of the whole in (0, 1) and no bend
 * between the halves (halves only from 8 bins on).  lo, hi get the
 * halves' H and errors (NAN if not split). */
static int
is_selfaffine(const double *x, const double *y, const double *wt, size_t a,
    size_t b, double hurst, double lo[2], double hi[2])
{
	size_t m = (a + b) / 2;

	int bend = 0;

	lo[0] = lo[1] = hi[0] = hi[1] = NAN;
	if (b - a >= 8 && segment_h(x, y, wt, a, m, &lo[0], &lo[1]) &&
	    segment_h(x, y, wt, m, b, &hi[0], &hi[1]))
		bend = !(fabs(lo[0] - hi[0]) < fmax(RC_FIT_BEND_TOL,
		    3 * hypot(lo[1], hi[1])));
	else
		lo[0] = lo[1] = hi[0] = hi[1] = NAN;
	return hurst > 0 && hurst < 1 && !bend;
}

/* Step 4: the verdict on the power-law bins, and the widest self-affine
 * run of bins of at least a decade when the verdict is no. */
static void
diagnose(const double *x, const double *y, const double *wt, size_t n,
    double bins_per_decade, rc_selfaffine_fit *fit)
{
	size_t a0 = 0, need = (size_t)ceil(bins_per_decade) + 1;
	double lo[2], hi[2], best = 0, half = 0.5 * log(10) / bins_per_decade;

	if (fit->rolloff)
		while (a0 < n && x[a0] <= log(fit->q_r))
			a0++;
	fit->selfaffine = is_selfaffine(x, y, wt, a0, n, fit->H, lo, hi);
	fit->h_lo = lo[0];
	fit->h_lo_err = lo[1];
	fit->h_hi = hi[0];
	fit->h_hi_err = hi[1];
	fit->q_mid = exp(x[(a0 + n) / 2]);
	if (fit->selfaffine)
		return;
	fit->good_H = NAN;
	for (size_t a = 0; a < n; a++)
		for (size_t b = a + need; b <= n; b++) {
			double h, e, l2[2], h2[2];
			/* a suggestion needs H inside (0, 1) by 2 errors */
			if (!(x[b - 1] - x[a] > best) ||
			    !segment_h(x, y, wt, a, b, &h, &e) ||
			    !(h > 2 * e && h < 1 - 2 * e) ||
			    !is_selfaffine(x, y, wt, a, b, h, l2, h2))
				continue;
			best = x[b - 1] - x[a];
			/* bounds half a bin outside the end bins, so that a
			 * rounded bound keeps them in and their neighbours out */
			fit->good_q_min = a == 0 ? 0 : exp(x[a] - half);
			fit->good_q_max = b == n ? 0 : exp(x[b - 1] + half);
			fit->good_lo = x[a];
			fit->good_hi = x[b - 1];
			fit->good_H = h;
			fit->good_H_err = e;
		}
}

/* Refine the hinge; cov 3x3 scaled by the residual variance. */
static int
hinge_refine(const double *x, const double *y, const double *wt, size_t n,
    double p0[3], double cov[3][3], double *chisq)
{
	gsl_multifit_nlinear_parameters fp = gsl_multifit_nlinear_default_parameters();
	gsl_multifit_nlinear_workspace *w;
	gsl_multifit_nlinear_fdf fdf;
	struct hinge_data d = { x, y, n };
	gsl_vector_view pv = gsl_vector_view_array(p0, 3);
	gsl_vector_const_view wv = gsl_vector_const_view_array(wt, n);
	gsl_matrix *cv = gsl_matrix_alloc(3, 3);
	int info, rc = -1;

	memset(&fdf, 0, sizeof(fdf));
	fdf.f = hinge_f;
	fdf.df = hinge_df;
	fdf.n = n;
	fdf.p = 3;
	fdf.params = &d;
	w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fp, n, 3);
	if (w == NULL || cv == NULL)
		goto out;
	if (gsl_multifit_nlinear_winit(&pv.vector, &wv.vector, &fdf, w) != 0 ||
	    gsl_multifit_nlinear_driver(200, 1e-12, 1e-12, 1e-12, NULL, NULL,
	    &info, w) != 0)
		goto out;
	gsl_blas_ddot(gsl_multifit_nlinear_residual(w),
	    gsl_multifit_nlinear_residual(w), chisq);
	if (gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w), 0.0, cv) != 0)
		goto out;
	for (int i = 0; i < 3; i++) {
		p0[i] = gsl_vector_get(gsl_multifit_nlinear_position(w), (size_t)i);
		for (int j = 0; j < 3; j++)
			cov[i][j] = gsl_matrix_get(cv, i, j) * *chisq / (double)(n - 3);
	}
	rc = 0;
out:
	gsl_multifit_nlinear_free(w);
	gsl_matrix_free(cv);
	return rc;
}

/* Long: the fit's stages (spectrum, range, start values, GSL solve,
 * errors) share the binned spectrum and the fit state. */
int
rc_fit_selfaffine(const rc_grid *g, rc_fft *fft, const rc_fit_opts *o,
    rc_selfaffine_fit *fit, rc_err *err)
{
	rc_grid *s2d = NULL;
	rc_psd_bin *b = NULL;
	size_t nb = 0, n = 0;
	double wsum = 0, *x = NULL, *y = NULL, *wt = NULL, qa, qb, cmax = 0, widen;
	struct edges e;
	int rc = -1;

	memset(fit, 0, sizeof(*fit));
	memcpy(fit->unit, g->unit, sizeof(fit->unit));
	if (g->nx < 2 || g->ny < 2)
		return rc_seterr(err, "the self-affine fit is for maps (a profile's "
		    "1D spectrum has another exponent): not available for %zux%zu",
		    g->nx, g->ny);
	if ((s2d = rc_psd2d_window(g, fft, o->window, err)) == NULL)
		return -1;
	qa = o->q_min > 0 ? o->q_min : 0;
	qb = o->q_max > 0 ? o->q_max : INFINITY;
	/* A finite patch: wavelengths of fewer than 4 spacings are left out
	 * unless the caller says otherwise (the window's leakage and most
	 * instruments' transfer functions make them unreliable). */
	if (o->q_max == 0 && !g->periodic)
		qb = M_PI / (2 * fmax(g->lx / (double)g->nx, g->ly / (double)g->ny));
	find_edges(s2d, qa, qb, &e);
	rc_grid_free(s2d);
	if (!(e.hi_power > 0)) {
		rc_seterr(err, "no spectral power in the fit range");
		goto out;
	}
	if (rc_psd_radial_window(g, fft, o->bins_per_decade, o->window, &b, &nb,
	    err) != 0)
		goto out;
	if ((x = rc_malloc(nb * sizeof(double), err)) == NULL ||
	    (y = rc_malloc(nb * sizeof(double), err)) == NULL ||
	    (wt = rc_malloc(nb * sizeof(double), err)) == NULL)
		goto out;
	for (size_t k = 0; k < nb; k++)
		cmax = fmax(cmax, b[k].c);
	widen = pow(10, 1 / o->bins_per_decade);
	fit->q_s = e.hi_cut ? 0.5 * (e.hi_power + e.hi_empty) : e.hi_power;
	fit->q_s_err = e.hi_cut ? 0.5 * (e.hi_empty - e.hi_power) : NAN;
	fit->q_s_from = e.hi_cut ? "cutoff" : "range";
	for (size_t k = 0; k < nb; k++) {
		double q = b[k].q;
		if (!(b[k].c > POWER_FLOOR * cmax) || q < qa || q > qb ||
		    (e.hi_cut && q > fit->q_s / widen) ||
		    (e.lo_cut && q < e.lo_power * widen))
			continue;
		x[n] = log(q);
		y[n] = log(b[k].c);
		/* var(ln C) of a bin ~ 1 / (its independent modes) */
		wt[n] = (double)b[k].n_modes;
		n++;
	}
	if (n < 4) {
		rc_seterr(err, "only %zu spectral bins in the fit range: widen it "
		    "or use more --bins-per-decade", n);
		goto out;
	}
	fit->n_bins = n;
	for (size_t k = 0; k < n; k++)
		wsum += wt[k];
	fit->fit_q_min = exp(x[0]);
	fit->fit_q_max = exp(x[n - 1]);
	{
		double c[2], cov[2][2], sse_pow, best = INFINITY, bx = 0, bc[2] = { 0, 0 };
		double chisq;
		int plateau = 0;

		sse_pow = line_fit(x, y, wt, n, x[0], c, cov);
		if (!e.lo_cut)
			for (int s = 1; s < HINGE_STEPS; s++) {
				double xh = x[0] + (x[n - 1] - x[0]) * s / HINGE_STEPS, hc[2];
				size_t below = 0;
				double sse;
				for (size_t k = 0; k < n; k++)
					below += x[k] <= xh;
				if (below < 2 || n - below < 2)
					continue;
				sse = line_fit(x, y, wt, n, xh, hc, NULL);
				if (sse < best) {
					best = sse;
					bx = xh;
					bc[0] = hc[0];
					bc[1] = hc[1];
				}
			}
		if (isfinite(best) && best < 0.5 * sse_pow) {
			double p[3] = { bc[0], bc[1] / 2 - 1, bx }, cv[3][3];
			size_t below = 0;
			if (hinge_refine(x, y, wt, n, p, cv, &chisq) == 0) {
				for (size_t k = 0; k < n; k++)
					below += x[k] <= p[2];
				if (below >= 2 && n - below >= 2) {
					plateau = 1;
					fit->c_r = exp(p[0]);
					fit->H = p[1];
					fit->H_err = sqrt(cv[1][1]);
					fit->q_r = exp(p[2]);
					fit->q_r_err = fit->q_r * sqrt(cv[2][2]);
					fit->rolloff = 1;
					fit->q_r_from = "fit";
					fit->rms_residual = sqrt(chisq / wsum);
					/* hrms error from ln C_r, H, ln q_r */
					{
						double pp[3] = { p[0], p[1], p[2] }, gr[3], v = 0;
						double h0 = rc_fit_model_hrms(exp(pp[0]), pp[1],
						    exp(pp[2]), fit->q_s, 1);
						for (int i = 0; i < 3; i++) {
							double d = 1e-6 * fmax(fabs(pp[i]), 1);
							pp[i] += d;
							gr[i] = (rc_fit_model_hrms(exp(pp[0]), pp[1],
							    exp(pp[2]), fit->q_s, 1) - h0) / d;
							pp[i] -= d;
						}
						for (int i = 0; i < 3; i++)
							for (int j = 0; j < 3; j++)
								v += gr[i] * cv[i][j] * gr[j];
						fit->hrms_err = sqrt(v);
					}
				}
			}
		}
		if (!plateau) {
			double x0 = e.lo_cut ? log(0.5 * (e.lo_power + e.lo_empty)) :
			    log(e.lo_power);
			double lc[2], lcov[2][2];
			/* y = a - slope (x - x0) on every bin (all lie above x0) */
			sse_pow = line_fit(x, y, wt, n, x0, lc, lcov);
			if (!isfinite(sse_pow)) {
				rc_seterr(err, "the power-law fit failed");
				goto out;
			}
			fit->c_r = exp(lc[0]);
			fit->H = lc[1] / 2 - 1;
			fit->H_err = sqrt(lcov[1][1]) / 2;
			fit->q_r = exp(x0);
			fit->q_r_err = e.lo_cut ? 0.5 * (e.lo_power - e.lo_empty) : NAN;
			fit->q_r_from = e.lo_cut ? "cutoff" : "range";
			fit->rolloff = 0;
			fit->rms_residual = sqrt(sse_pow / wsum);
			{
				double pp[2] = { lc[0], fit->H }, gr[2], v = 0;
				double h0 = rc_fit_model_hrms(exp(pp[0]), pp[1], fit->q_r,
				    fit->q_s, 0);
				double cv2[2][2] = { { lcov[0][0], lcov[0][1] / 2 },
				    { lcov[1][0] / 2, lcov[1][1] / 4 } };
				for (int i = 0; i < 2; i++) {
					double d = 1e-6 * fmax(fabs(pp[i]), 1);
					pp[i] += d;
					gr[i] = (rc_fit_model_hrms(exp(pp[0]), pp[1], fit->q_r,
					    fit->q_s, 0) - h0) / d;
					pp[i] -= d;
				}
				for (int i = 0; i < 2; i++)
					for (int j = 0; j < 2; j++)
						v += gr[i] * cv2[i][j] * gr[j];
				fit->hrms_err = sqrt(v);
			}
		}
	}
	fit->hrms = rc_fit_model_hrms(fit->c_r, fit->H, fit->q_r, fit->q_s,
	    fit->rolloff);
	diagnose(x, y, wt, n, o->bins_per_decade, fit);
	rc = 0;
out:
	free(b);
	free(x);
	free(y);
	free(wt);
	return rc;
}

/* Which end of the range a half's H speaks of, and what to try. */
static const char *
half_advice(double h, int upper)
{
	if (!(h < 0 || h > 1))
		return NULL;
	if (upper)
		return h < 0 ? "flat at short wavelengths (noise, or the "
		    "instrument's resolution: raise --min-wavelength)" :
		    "steep at short wavelengths (the instrument's or tip's "
		    "transfer function: raise --min-wavelength)";
	return h < 0 ? "flat at long wavelengths (a roll-off: the fit models "
	    "one only below a power law of 0 < H < 1; or lower "
	    "--max-wavelength)" : "steep at long wavelengths (form or "
	    "waviness left after levelling: surfwarp --detrend quadratic, or "
	    "lower --max-wavelength)";
}

int
rc_fit_advice(const rc_selfaffine_fit *f, double L, char *buf, size_t len)
{
	const char *u = f->unit;
	const char *lo = half_advice(f->h_lo, 0), *hi = half_advice(f->h_hi, 1);
	char w[4][40];
	size_t k;

	if (f->selfaffine || len == 0)
		return 0;
	rc_si_length(w[0], sizeof(w[0]), 2 * M_PI / f->fit_q_max, u, 0);
	rc_si_length(w[1], sizeof(w[1]), 2 * M_PI / f->fit_q_min, u, 0);
	k = (size_t)snprintf(buf, len, "C(q) is not self-affine on the range "
	    "fitted, q = %.3g to %.3g%s%s (wavelengths %s to %s): ",
	    f->fit_q_min, f->fit_q_max, u[0] ? " 1/" : "", u, w[0], w[1]);
	if (k < len && !(f->H > 0 && f->H < 1))
		k += (size_t)snprintf(buf + k, len - k, "H = %.3g +- %.2g is "
		    "outside 0 < H < 1%s", f->H, f->H_err, isfinite(f->h_lo) ?
		    "; " : "");
	if (k < len && isfinite(f->h_lo))
		k += (size_t)snprintf(buf + k, len - k, "H = %.3g +- %.2g below "
		    "q = %.3g, %.3g +- %.2g above", f->h_lo, f->h_lo_err, f->q_mid,
		    f->h_hi, f->h_hi_err);
	if (k < len && lo != NULL)
		k += (size_t)snprintf(buf + k, len - k, "; %s", lo);
	if (k < len && hi != NULL)
		k += (size_t)snprintf(buf + k, len - k, "; %s", hi);
	if (k < len && isfinite(f->good_H)) {
		char mn[48] = "", mx[48] = "";
		rc_si_length(w[2], sizeof(w[2]), 2 * M_PI / exp(f->good_hi), u, 0);
		rc_si_length(w[3], sizeof(w[3]), 2 * M_PI / exp(f->good_lo), u, 0);
		if (f->good_q_max > 0)
			snprintf(mn, sizeof(mn), " --min-wavelength %.3gL",
			    2 * M_PI / f->good_q_max / L);
		if (f->good_q_min > 0)
			snprintf(mx, sizeof(mx), " --max-wavelength %.3gL",
			    2 * M_PI / f->good_q_min / L);
		snprintf(buf + k, len - k, ". It is self-affine, H = %.3g +- %.2g, "
		    "for wavelengths %s to %s: try%s%s", f->good_H, f->good_H_err,
		    w[2], w[3], mn, mx);
	} else if (k < len)
		snprintf(buf + k, len - k, ". No part of a decade or more is "
		    "(with 0 < H < 1 by two standard errors): the self-affine "
		    "model does not describe this map");
	return 1;
}

/* Field k (0-based) of a tab-separated line, into buf. */
static int
field(const char *line, size_t k, char *buf, size_t len)
{
	for (size_t i = 0; i < k; i++) {
		line = strchr(line, '\t');
		if (line == NULL)
			return -1;
		line++;
	}
	{
		size_t n = strcspn(line, "\t\n");
		if (n >= len)
			return -1;
		memcpy(buf, line, n);
		buf[n] = '\0';
	}
	return 0;
}

/* The index of the column named want in a header line of ncol fields;
 * ncol if there is none. */
static size_t
column(const char *head, size_t ncol, const char *want)
{
	char name[64];
	size_t c;

	for (c = 0; c < ncol; c++)
		if (field(head, c, name, sizeof(name)) == 0 &&
		    strcmp(name, want) == 0)
			break;
	return c;
}

int
rc_fit_table_parse(const char *text, rc_selfaffine_fit *fit, size_t *nx, size_t *ny,
    double *lx, double *ly, rc_err *err)
{
	static const char *need[] = { "nx", "ny", "lx", "ly", "H", "q_r", "q_s",
	    "hrms", "rolloff" };
	double v[9];
	const char *row = strchr(text, '\n');
	size_t hlen = row ? (size_t)(row - text) : strlen(text), ncol = 1, unit_col;
	char val[64];

	memset(fit, 0, sizeof(*fit));
	{
		/* a fit table names lambda_r in its header line */
		char *head = strndup(text, hlen);
		int is_table = head != NULL && strstr(head, "\tlambda_r\t") != NULL;
		free(head);
		if (!is_table)
			return 0;
	}
	if (row == NULL || row[1] == '\0')
		return rc_seterr(err, "fit table without a data row");
	row++;
	for (size_t i = 0; i < hlen; i++)
		ncol += text[i] == '\t';
	for (size_t k = 0; k < 9; k++) {
		size_t c = column(text, ncol, need[k]);
		char *end;
		if (c == ncol)
			return rc_seterr(err, "fit table lacks the column %s", need[k]);
		if (field(row, c, val, sizeof(val)) != 0)
			return rc_seterr(err, "fit table: no value for %s", need[k]);
		v[k] = strtod(val, &end);
		if (end == val || *end != '\0' || !isfinite(v[k]))
			return rc_seterr(err, "fit table: %s = '%s' is not a finite number",
			    need[k], val);
	}
	/* the unit column, when there is one: the lengths' unit */
	if ((unit_col = column(text, ncol, "unit")) < ncol) {
		if (field(row, unit_col, val, sizeof(val)) != 0)
			return rc_seterr(err, "fit table: no value for unit");
		if (!rc_unit_is_length(val))
			return rc_seterr(err, "fit table: unit '%s' is not a "
			    "length unit (m mm um nm pm angstrom)", val);
		snprintf(fit->unit, sizeof(fit->unit), "%s", rc_unit_canonical(val));
	}
	if (!(v[0] >= 1 && v[0] <= RC_GRID_MAX_DIM && v[1] >= 1 &&
	    v[1] <= RC_GRID_MAX_DIM && v[0] == floor(v[0]) && v[1] == floor(v[1])))
		return rc_seterr(err, "fit table: nx, ny must be positive integers");
	if (!(v[2] > 0 && v[3] > 0 && v[5] > 0 && v[6] > v[5] && v[7] > 0) ||
	    (v[8] != 0 && v[8] != 1))
		return rc_seterr(err, "fit table: need lx, ly, q_r, hrms > 0, "
		    "q_s > q_r, rolloff 0 or 1");
	*nx = (size_t)v[0];
	*ny = (size_t)v[1];
	*lx = v[2];
	*ly = v[3];
	fit->H = v[4];
	fit->q_r = v[5];
	fit->q_s = v[6];
	fit->hrms = v[7];
	fit->rolloff = (int)v[8];
	return 1;
}
