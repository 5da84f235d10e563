/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warp.c - warping, flipping, carving and renormalising height maps. */
#include "warp.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "spectral.h"

static void
min_max(const rc_grid *g, double *lo, double *hi)
{
	size_t n = rc_grid_size(g);

	*lo = INFINITY;
	*hi = -INFINITY;
	for (size_t k = 0; k < n; k++) {
		*lo = fmin(*lo, g->z[k]);
		*hi = fmax(*hi, g->z[k]);
	}
}

void
rc_warp_default_bounds(const rc_grid *g, double *hmin, double *hmax)
{
	double lo, hi;

	min_max(g, &lo, &hi);
	*hmin = 2 * lo - hi;
	*hmax = 2 * hi - lo;
}

double
rc_warp_height(double h, double w, double hmin, double hmax)
{
	double range = hmax - hmin, x;

	if (w == 0 || !(range > 0))
		return h;
	if (w > 0) {
		x = fmin(fmax((hmax - h) / range, 0), 1);
		return hmax - range * pow(x, 1 + w);
	}
	x = fmin(fmax((h - hmin) / range, 0), 1);
	return hmin + range * pow(x, 1 - w);
}

int
rc_warp(rc_grid *g, double w, double hmin, double hmax, rc_err *err)
{
	size_t n = rc_grid_size(g), k_bad;
	double lo, hi;

	if (!isfinite(w) || !isfinite(hmin) || !isfinite(hmax))
		return rc_seterr(err, "warp: w, hmin and hmax must be finite");
	if (!isfinite(hmax - hmin))
		return rc_seterr(err, "warp: hmax - hmin = %g - (%g) overflows; "
		    "give bounds closer together", hmax, hmin);
	min_max(g, &lo, &hi);
	if (hmin > lo)
		return rc_seterr(err, "warp: hmin %.17g is above the lowest height %.17g",
		    hmin, lo);
	if (hmax < hi)
		return rc_seterr(err, "warp: hmax %.17g is below the highest height %.17g",
		    hmax, hi);
	if (w != 0) {
		#pragma omp parallel for
		for (size_t k = 0; k < n; k++)
			g->z[k] = rc_warp_height(g->z[k], w, hmin, hmax);
		if (!rc_grid_all_finite(g, &k_bad))
			return rc_seterr(err, "warp: w = %g with hmin %g, hmax %g gives "
			    "a non-finite height at i=%zu, j=%zu", w, hmin, hmax,
			    k_bad % g->nx, k_bad / g->nx);
	}
	if (rc_grid_meta_setd(g, "warp", w, err) != 0 ||
	    rc_grid_meta_setd(g, "warp_hmin", hmin, err) != 0 ||
	    rc_grid_meta_setd(g, "warp_hmax", hmax, err) != 0)
		return -1;
	return 0;
}

int
rc_flip(rc_grid *g, rc_err *err)
{
	size_t n = rc_grid_size(g);
	double was = 0;

	for (size_t k = 0; k < n; k++)
		g->z[k] = -g->z[k];
	rc_grid_meta_getd(g, "flip", &was);
	return rc_grid_meta_setf(g, "flip", err, "%d", was != 0 ? 0 : 1);
}

/* Lower envelope of parabolas f(x_k) + (x - x_k)^2 over the m sites
 * (increasing x, f = INFINITY for no site), evaluated at the n queries xq
 * (increasing).  v, z: scratch of m and m + 1 entries. */
static void
envelope(const double *x, const double *f, size_t m, const double *xq,
    double *out, size_t n, size_t *v, double *z)
{
	size_t k = 0, first = m;

	for (size_t q = 0; q < m; q++)
		if (isfinite(f[q])) {
			first = q;
			break;
		}
	if (first == m) {
		for (size_t p = 0; p < n; p++)
			out[p] = INFINITY;
		return;
	}
	v[0] = first;
	z[0] = -INFINITY;
	z[1] = INFINITY;
	for (size_t q = first + 1; q < m; q++) {
		double s;
		if (!isfinite(f[q]))
			continue;
		/* z[0] = -inf stops the loop at k = 0. */
		for (;;) {
			size_t r = v[k];
			s = ((f[q] + x[q] * x[q]) - (f[r] + x[r] * x[r])) /
			    (2 * (x[q] - x[r]));
			if (s > z[k])
				break;
			k--;
		}
		k++;
		v[k] = q;
		z[k] = s;
		z[k + 1] = INFINITY;
	}
	k = 0;
	for (size_t p = 0; p < n; p++) {
		while (z[k + 1] < xq[p])
			k++;
		double d = xq[p] - x[v[k]];
		out[p] = d * d + f[v[k]];
	}
}

/* One periodic pass along an axis of n points of spacing h: in[] are the
 * current squared distances, out[] the new ones.  Periodicity by three
 * copies of the line. */
static void
periodic_pass(const double *in, double *out, size_t n, double h, double *x3,
    double *f3, double *xq, size_t *v, double *z)
{
	for (size_t c = 0; c < 3; c++)
		for (size_t i = 0; i < n; i++) {
			x3[c * n + i] = ((double)(c * n + i) - (double)n) * h;
			f3[c * n + i] = in[i];
		}
	for (size_t i = 0; i < n; i++)
		xq[i] = (double)i * h;
	envelope(x3, f3, 3 * n, xq, out, n, v, z);
}

int
rc_distance2_to_mask(const rc_grid *mask, double *d2, rc_err *err)
{
	size_t nx = mask->nx, ny = mask->ny, nmax = nx > ny ? nx : ny;
	double dx = mask->lx / (double)nx, dy = mask->ly / (double)ny;
	double *x3, *f3, *xq, *z, *line, *res;
	size_t *v;
	int rc = -1;

	x3 = rc_malloc(3 * nmax * sizeof(double), err);
	f3 = rc_malloc(3 * nmax * sizeof(double), err);
	z = rc_malloc((3 * nmax + 1) * sizeof(double), err);
	v = rc_malloc(3 * nmax * sizeof(size_t), err);
	xq = rc_malloc(nmax * sizeof(double), err);
	line = rc_malloc(nmax * sizeof(double), err);
	res = rc_malloc(nmax * sizeof(double), err);
	if (!x3 || !f3 || !z || !v || !xq || !line || !res)
		goto out;
	for (size_t j = 0; j < ny; j++) {
		for (size_t i = 0; i < nx; i++)
			line[i] = mask->z[j * nx + i] == 1 ? 0 : INFINITY;
		periodic_pass(line, res, nx, dx, x3, f3, xq, v, z);
		memcpy(d2 + j * nx, res, nx * sizeof(double));
	}
	for (size_t i = 0; i < nx; i++) {
		for (size_t j = 0; j < ny; j++)
			line[j] = d2[j * nx + i];
		periodic_pass(line, res, ny, dy, x3, f3, xq, v, z);
		for (size_t j = 0; j < ny; j++)
			d2[j * nx + i] = res[j];
	}
	rc = 0;
out:
	free(x3);
	free(f3);
	free(z);
	free(v);
	free(xq);
	free(line);
	free(res);
	return rc;
}

int
rc_carve(rc_grid *g, const rc_grid *mask, double depth, double width,
    rc_err *err)
{
	return rc_carve_rough(g, mask, depth, width, 0, 0, err);
}

int
rc_carve_rough(rc_grid *g, const rc_grid *mask, double depth, double width,
    double roughness, unsigned long seed, rc_err *err)
{
	size_t n = rc_grid_size(g), set = 0;
	double *d2;

	if (!(roughness >= 0) || !isfinite(roughness))
		return rc_seterr(err, "carve: roughness must be finite and >= 0");
	if (!(depth >= 0) || !isfinite(depth))
		return rc_seterr(err, "carve: depth must be finite and >= 0");
	if (!(width > 0) || !isfinite(width))
		return rc_seterr(err, "carve: width must be finite and > 0");
	if (mask->nx != g->nx || mask->ny != g->ny)
		return rc_seterr(err, "carve: mask is %zux%zu but the surface is %zux%zu",
		    mask->nx, mask->ny, g->nx, g->ny);
	for (size_t k = 0; k < n; k++) {
		if (mask->z[k] == 1)
			set++;
		else if (mask->z[k] != 0)
			return rc_seterr(err, "carve: mask value %g at point %zu: "
			    "want 0 or 1", mask->z[k], k);
	}
	if (set == 0)
		return rc_seterr(err, "carve: mask has no point set to 1");
	if ((d2 = rc_malloc(n * sizeof(double), err)) == NULL)
		return -1;
	/* The distance uses the surface's lengths (the mask may carry none). */
	rc_grid shape = *mask;
	shape.lx = g->lx;
	shape.ly = g->ly;
	if (rc_distance2_to_mask(&shape, d2, err) != 0) {
		free(d2);
		return -1;
	}
	gsl_rng *rng = NULL;
	if (roughness > 0) {
		if ((rng = gsl_rng_alloc(gsl_rng_mt19937)) == NULL) {
			free(d2);
			return rc_seterr(err, "out of memory (random number generator)");
		}
		gsl_rng_set(rng, seed);
	}
	for (size_t k = 0; k < n; k++) {
		/* (d/W)^2, not d^2/W^2: a tiny W must not make 0/0 */
		double x = sqrt(d2[k]) / width;
		double ramp = -expm1(-0.5 * x * x);
		double rough = rng ? roughness * fabs(gsl_ran_gaussian_ziggurat(rng, 1.0)) : 0;
		g->z[k] -= (depth + rough) * ramp;
	}
	gsl_rng_free(rng);
	free(d2);
	if (!rc_grid_all_finite(g, &n))
		return rc_seterr(err, "carve: depth %g (roughness %g) overflows the "
		    "height at i=%zu, j=%zu", depth, roughness, n % g->nx, n / g->nx);
	if (rc_grid_meta_setd(g, "carve_depth", depth, err) != 0 ||
	    rc_grid_meta_setd(g, "carve_width", width, err) != 0)
		return -1;
	if (roughness > 0 && (rc_grid_meta_setd(g, "carve_roughness", roughness, err) != 0 ||
	    rc_grid_meta_setf(g, "carve_seed", err, "%lu", seed) != 0))
		return -1;
	return 0;
}

int
rc_scale_rms_gradient(rc_grid *g, double target, rc_err *err)
{
	size_t n = rc_grid_size(g);
	double gbar, f;

	if (!(target > 0) || !isfinite(target))
		return rc_seterr(err, "rms gradient target must be positive and finite");
	if (rc_rms_gradient(g, NULL, &gbar, err) != 0)
		return -1;
	if (!(gbar > 0))
		return rc_seterr(err, "the surface has zero rms gradient; cannot "
		    "renormalise it");
	f = target / gbar;
	for (size_t k = 0; k < n; k++)
		g->z[k] *= f;
	return rc_grid_meta_setd(g, "rms_gradient", target, err);
}
