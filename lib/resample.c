/* SPDX-License-Identifier: GPL-3.0-or-later */
/* resample.c - spectral resampling of periodic grids, cubic splines for
 * finite patches (see resample.h). */
#include "resample.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_spline.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"

/* Index of signed mode k on an axis of n points; -1 if it is dropped. */
static long
mode_index(long k, size_t n, size_t nmin)
{
	if (2 * labs(k) >= (long)nmin)
		return -1;
	return k >= 0 ? k : (long)n + k;
}

static rc_grid *
spectral(const rc_grid *g, size_t nx, size_t ny, rc_err *err)
{
	rc_fft in, out;
	rc_grid *c = NULL;
	size_t mx = nx < g->nx ? nx : g->nx, my = ny < g->ny ? ny : g->ny;
	double scale = 1.0 / (double)rc_grid_size(g);

	memset(&in, 0, sizeof(in));
	memset(&out, 0, sizeof(out));
	if (rc_fft_init(&in, g->nx, g->ny, RC_FFT_ESTIMATE, err) != 0 ||
	    rc_fft_init(&out, nx, ny, RC_FFT_ESTIMATE, err) != 0)
		goto out;
	memcpy(in.real, g->z, rc_grid_size(g) * sizeof(double));
	rc_fft_forward(&in);
	for (size_t j = 0; j < ny; j++) {
		long kj = j <= ny / 2 ? (long)j : (long)j - (long)ny;
		long sj = mode_index(kj, g->ny, my);
		for (size_t i = 0; i < out.nxc; i++) {
			long si = mode_index((long)i, g->nx, mx);
			out.spec[j * out.nxc + i] = si < 0 || sj < 0 ? 0 :
			    scale * in.spec[(size_t)sj * in.nxc + (size_t)si];
		}
	}
	rc_fft_backward(&out);
	if ((c = rc_grid_new_like(g, nx, ny, g->lx, g->ly, err)) != NULL)
		memcpy(c->z, out.real, nx * ny * sizeof(double));
out:
	rc_fft_free(&in);
	rc_fft_free(&out);
	return c;
}

/* Natural cubic spline through n values y at spacing h, evaluated at m
 * points k h2 into out (stride ostride). */
static int
spline_line(const double *y, size_t ystride, size_t n, double h,
    double *out, size_t ostride, size_t m, double h2, double *xs, double *ys,
    rc_err *err)
{
	gsl_spline *s;
	gsl_interp_accel *a;

	for (size_t k = 0; k < n; k++) {
		xs[k] = (double)k * h;
		ys[k] = y[k * ystride];
	}
	s = gsl_spline_alloc(gsl_interp_cspline, n);
	a = gsl_interp_accel_alloc();
	if (s == NULL || a == NULL || gsl_spline_init(s, xs, ys, n) != 0) {
		gsl_spline_free(s);
		gsl_interp_accel_free(a);
		return rc_seterr(err, "resample: spline set-up failed");
	}
	for (size_t k = 0; k < m; k++) {
		/* The last point may round past the end by an ulp. */
		double x = fmin((double)k * h2, xs[n - 1]);
		out[k * ostride] = gsl_spline_eval(s, x, a);
	}
	gsl_spline_free(s);
	gsl_interp_accel_free(a);
	return 0;
}

static rc_grid *
splines(const rc_grid *g, double dx, double dy, rc_err *err)
{
	double hx = g->lx / (double)g->nx, hy = g->ly / (double)g->ny;
	size_t nx = g->nx < 3 ? g->nx :
	    (size_t)floor((double)(g->nx - 1) * hx / dx * (1 + 1e-12)) + 1;
	size_t ny = g->ny < 3 ? g->ny :
	    (size_t)floor((double)(g->ny - 1) * hy / dy * (1 + 1e-12)) + 1;
	size_t nmax = g->nx > g->ny ? g->nx : g->ny;
	double *tmp = NULL, *xs = NULL, *ys = NULL;
	rc_grid *c = NULL;

	if (g->nx < 3)
		dx = hx;
	if (g->ny < 3)
		dy = hy;
	if (rc_grid_check_shape(nx, ny, (double)nx * dx, (double)ny * dy, err) != 0)
		return NULL;
	if ((tmp = rc_malloc(nx * g->ny * sizeof(double), err)) == NULL ||
	    (xs = rc_malloc(nmax * sizeof(double), err)) == NULL ||
	    (ys = rc_malloc(nmax * sizeof(double), err)) == NULL ||
	    (c = rc_grid_new_like(g, nx, ny, (double)nx * dx, (double)ny * dy, err)) == NULL)
		goto fail;
	for (size_t j = 0; j < g->ny; j++) {
		if (g->nx < 3)
			memcpy(tmp + j * nx, g->z + j * g->nx, nx * sizeof(double));
		else if (spline_line(g->z + j * g->nx, 1, g->nx, hx, tmp + j * nx, 1,
		    nx, dx, xs, ys, err) != 0)
			goto fail;
	}
	for (size_t i = 0; i < nx; i++) {
		if (g->ny < 3) {
			for (size_t j = 0; j < ny; j++)
				c->z[j * nx + i] = tmp[j * nx + i];
		} else if (spline_line(tmp + i, nx, g->ny, hy, c->z + i, nx, ny, dy,
		    xs, ys, err) != 0)
			goto fail;
	}
	free(tmp);
	free(xs);
	free(ys);
	return c;
fail:
	free(tmp);
	free(xs);
	free(ys);
	rc_grid_free(c);
	return NULL;
}

rc_grid *
rc_resample(const rc_grid *g, double dx, double dy, rc_err *err)
{
	if (!(dx > 0 && isfinite(dx) && dy > 0 && isfinite(dy))) {
		rc_seterr(err, "resample: spacing must be positive and finite");
		return NULL;
	}
	if (g->valid != NULL) {
		rc_seterr(err, "resample: the grid has missing points; fill them "
		    "first (surfwarp --fill)");
		return NULL;
	}
	if (g->periodic) {
		double fx = g->nx == 1 ? 1 : floor(g->lx / dx + 0.5);
		double fy = g->ny == 1 ? 1 : floor(g->ly / dy + 0.5);
		if (!(fx >= 1 && fy >= 1 && fx * fy <= (double)RC_GRID_MAX_POINTS)) {
			rc_seterr(err, "resample: spacing %gx%g gives no grid or too "
			    "large a one for %gx%g", dx, dy, g->lx, g->ly);
			return NULL;
		}
		return spectral(g, (size_t)fx, (size_t)fy, err);
	}
	if ((g->nx >= 3 && (double)(g->nx - 1) * g->lx / (double)g->nx / dx >
	    (double)RC_GRID_MAX_DIM) || (g->ny >= 3 &&
	    (double)(g->ny - 1) * g->ly / (double)g->ny / dy > (double)RC_GRID_MAX_DIM)) {
		rc_seterr(err, "resample: spacing %gx%g gives too large a grid", dx, dy);
		return NULL;
	}
	return splines(g, dx, dy, err);
}
