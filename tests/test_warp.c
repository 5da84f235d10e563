/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_warp.c - warping (direction, identity, monotonicity, stability at
 * large |w|), flipping, carving, the periodic distance transform,
 * renormalisation. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "spectral.h"
#include "stats.h"
#include "testlib.h"
#include "warp.h"

static rc_grid *
wave(size_t nx, size_t ny)
{
	rc_err err;
	rc_grid *g = rc_grid_new(nx, ny, 1, 1, &err);

	/* Two incommensurate-looking modes: skewness 0, distinct extremes. */
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			g->z[j * nx + i] = 0.1 * cos(2 * M_PI * (double)i / nx) +
			    0.05 * sin(2 * M_PI * (2.0 * i + 3.0 * j) / nx) + 0.3;
	return g;
}

static void
test_identity_and_direction(void)
{
	rc_grid *g = wave(64, 64), *c;
	rc_err err;
	rc_stats s0, s2, sm;
	double hmin, hmax;

	c = rc_grid_clone(g, 1, &err);
	rc_warp_default_bounds(g, &hmin, &hmax);
	test_true(rc_warp(c, 0, hmin, hmax, &err) == 0, "w = 0 runs");
	test_true(memcmp(c->z, g->z, 64 * 64 * sizeof(double)) == 0,
	    "w = 0 is the identity bit for bit");
	rc_grid_free(c);

	rc_stats_compute(g, NULL, RC_DERIV_SPECTRAL, &s0, &err);
	c = rc_grid_clone(g, 1, &err);
	rc_warp(c, 2, hmin, hmax, &err);
	rc_stats_compute(c, NULL, RC_DERIV_SPECTRAL, &s2, &err);
	test_true(s2.skewness < -0.1, "w = 2: negative skewness (%g)", s2.skewness);
	/* Peaks blunted: the curvature at the maximum shrinks relative to
	 * the minimum.  Exactly, f'(u) = (1+w) u^w with u = 1/3 at the max
	 * and 2/3 at the min of the defaults: ratio 1/4 for w = 2. */
	size_t imax = 0, imin = 0;
	for (size_t k = 0; k < 64 * 64; k++) {
		if (g->z[k] > g->z[imax])
			imax = k;
		if (g->z[k] < g->z[imin])
			imin = k;
	}
	double lap0[64 * 64], lap2[64 * 64];
	rc_deriv_fields(g, RC_DERIV_FD, NULL, NULL, NULL, lap0, NULL, &err);
	rc_deriv_fields(c, RC_DERIV_FD, NULL, NULL, NULL, lap2, NULL, &err);
	double rmax = lap2[imax] / lap0[imax], rmin = lap2[imin] / lap0[imin];
	/* The grid maximum is not the exact maximum and the Laplacian is a
	 * 5-point one: observed 0.6% off; allow 2%. */
	test_rel(rmax, 1.0 / 3, 0.02, "w = 2 multiplies the peak curvature by (1+w)(1/3)^w = 1/3");
	test_rel(rmin, 4.0 / 3, 0.02, "w = 2 multiplies the valley curvature by (1+w)(2/3)^w = 4/3");
	rc_grid_free(c);

	c = rc_grid_clone(g, 1, &err);
	rc_warp(c, -2, hmin, hmax, &err);
	rc_stats_compute(c, NULL, RC_DERIV_SPECTRAL, &sm, &err);
	test_rel(sm.skewness, -s2.skewness, 1e-10,
	    "w = -2 mirrors w = 2 (symmetric default bounds)");
	rc_grid_free(c);

	/* Bounds are checked: min h = (2 hmin + hmax)/3 for the defaults. */
	c = rc_grid_clone(g, 1, &err);
	test_true(rc_warp(c, 1, (2 * hmin + hmax) / 3 + 0.01, hmax, &err) != 0 && strstr(err.msg, "hmin"),
	    "hmin above min h rejected (%s)", err.msg);
	test_true(rc_warp(c, 1, hmin, (hmin + 2 * hmax) / 3 - 0.01, &err) != 0 && strstr(err.msg, "hmax"),
	    "hmax below max h rejected (%s)", err.msg);
	test_true(rc_warp(c, NAN, hmin, hmax, &err) != 0, "NaN w rejected");
	rc_grid_free(c);
	rc_grid_free(g);
}

/* Large |w|: monotone, inside [hmin, hmax], finite, and accurate against
 * the logarithmic form log(hmax - h_w) = log(range) + (1+w) log u. */
static void
test_stability(void)
{
	double hmin = -3, hmax = 3, ws[] = { 20, -20, 200, -200, 1e6 };
	int bad = 0;

	for (size_t k = 0; k < sizeof(ws) / sizeof(ws[0]); k++) {
		double w = ws[k], prev = -INFINITY;
		int mono = 1, finite = 1, inside = 1;
		for (int i = 0; i <= 1000; i++) {
			double h = -1 + 2.0 * i / 1000, hw = rc_warp_height(h, w, hmin, hmax);
			finite &= isfinite(hw);
			inside &= hw >= hmin && hw <= hmax;
			mono &= hw >= prev;
			prev = hw;
			if (w == 20 && i % 100 == 0) {
				double u = (hmax - h) / (hmax - hmin);
				double want = hmax - exp(log(hmax - hmin) + 21 * log(u));
				bad += fabs(hw - want) > 1e-14 * fabs(want) + 1e-15;
			}
		}
		test_true(finite && inside && mono,
		    "w = %g: finite, in [hmin, hmax], monotone", w);
	}
	test_int(bad, 0, "w = 20 matches the logarithmic form to 1e-14");
	/* Bounds touching the data: u = 0 and u = 1 exactly. */
	test_true(rc_warp_height(3, 50, -3, 3) == 3 && rc_warp_height(-3, 50, -3, 3) == -3,
	    "end points map to themselves");
	test_true(rc_warp_height(-3, -50, -3, 3) == -3 && rc_warp_height(3, -50, -3, 3) == 3,
	    "end points map to themselves for w < 0");
	/* Flat with default bounds: unchanged. */
	rc_err err;
	rc_grid *g = rc_grid_new(4, 4, 1, 1, &err);
	double a, b;
	for (int i = 0; i < 16; i++)
		g->z[i] = 0.7;
	rc_warp_default_bounds(g, &a, &b);
	test_true(rc_warp(g, 3, a, b, &err) == 0 && g->z[5] == 0.7, "flat surface unchanged");
	rc_grid_free(g);
}

static void
test_flip_scale(void)
{
	rc_grid *g = wave(32, 32), *c;
	rc_err err;
	double gbar, v;

	c = rc_grid_clone(g, 1, &err);
	rc_flip(c, &err);
	test_true(c->z[7] == -g->z[7], "flip negates");
	test_true(rc_grid_meta_getd(c, "flip", &v) && v == 1, "flip recorded");
	rc_flip(c, &err);
	test_true(rc_grid_meta_getd(c, "flip", &v) && v == 0 && c->z[7] == g->z[7],
	    "flip twice: back, recorded 0");
	rc_scale_rms_gradient(c, 2.5, &err);
	rc_rms_gradient(c, NULL, &gbar, &err);
	test_rel(gbar, 2.5, 1e-12, "rms gradient renormalised");
	for (int i = 0; i < 32 * 32; i++)
		c->z[i] = 1;
	test_true(rc_scale_rms_gradient(c, 1, &err) != 0, "flat: cannot renormalise");
	rc_grid_free(c);
	rc_grid_free(g);
}

/* Distance transform against brute force over periodic images. */
static void
test_distance(void)
{
	size_t nx = 13, ny = 9;
	rc_err err;
	rc_grid *m = rc_grid_new(nx, ny, 1.3, 0.7, &err);
	double d2[13 * 9], dx = 1.3 / nx, dy = 0.7 / ny;
	int bad = 0;
	unsigned s = 12345;

	for (size_t k = 0; k < nx * ny; k++) {
		s = s * 1103515245u + 12345u;
		m->z[k] = (s >> 16) % 7 == 0;
	}
	rc_distance2_to_mask(m, d2, &err);
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double best = INFINITY;
			for (size_t jj = 0; jj < ny; jj++)
				for (size_t ii = 0; ii < nx; ii++) {
					if (m->z[jj * nx + ii] != 1)
						continue;
					double ax = fabs((double)i - (double)ii), ay = fabs((double)j - (double)jj);
					ax = fmin(ax, nx - ax) * dx;
					ay = fmin(ay, ny - ay) * dy;
					best = fmin(best, ax * ax + ay * ay);
				}
			bad += fabs(d2[j * nx + i] - best) > 1e-12;
		}
	test_int(bad, 0, "periodic distance transform equals brute force");
	rc_grid_free(m);
}

static void
test_carve(void)
{
	size_t n = 32;
	rc_grid *g = wave(n, n), *c, *m;
	rc_err err;
	int kept = 1, lower = 1;
	double far = 0;

	m = rc_grid_new(n, n, 1, 1, &err);
	for (size_t k = 0; k < n * n; k++)
		m->z[k] = g->z[k] > 0.38;
	c = rc_grid_clone(g, 1, &err);
	test_true(rc_carve(c, m, 0.5, 0.05, &err) == 0, "carve runs");
	for (size_t k = 0; k < n * n; k++) {
		if (m->z[k] == 1)
			kept &= c->z[k] == g->z[k];
		lower &= c->z[k] <= g->z[k];
		far = fmax(far, g->z[k] - c->z[k]);
	}
	test_true(kept, "contact points keep their exact heights");
	test_true(lower, "no point rises");
	test_range(far, 0.4, 0.5, "far from contact the depth is approached (%g)", far);
	/* Nayak grows: the carved valleys add curvature. */
	rc_stats a, b;
	rc_stats_compute(g, NULL, RC_DERIV_SPECTRAL, &a, &err);
	rc_stats_compute(c, NULL, RC_DERIV_SPECTRAL, &b, &err);
	test_true(b.nayak > 2 * a.nayak, "carving raises Nayak (%g -> %g)", a.nayak, b.nayak);
	test_true(rc_carve(c, m, -1, 0.05, &err) != 0, "negative depth rejected");
	memset(m->z, 0, n * n * sizeof(double));
	test_true(rc_carve(c, m, 1, 0.05, &err) != 0 && strstr(err.msg, "no point"),
	    "empty mask rejected");
	rc_grid_free(m);
	m = rc_grid_new(n, n + 1, 1, 1, &err);
	test_true(rc_carve(c, m, 1, 0.05, &err) != 0, "wrong-size mask rejected");
	rc_grid_free(m);
	rc_grid_free(c);
	rc_grid_free(g);
}

int
main(void)
{
	test_identity_and_direction();
	test_stability();
	test_flip_scale();
	test_distance();
	test_carve();
	return test_summary();
}
