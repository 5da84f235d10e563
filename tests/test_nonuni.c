/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_nonuni.c - line scans not uniformly spaced, read as they are
 * (rc_read_opts.nonuniform) and analysed as piecewise-linear functions
 * (stats_nonuni.h): integrals done by hand for a few points, a sine and
 * a parabola sampled at random x against their exact integrals within
 * the interpolation error the header derives, the exact spectrum of a
 * tent, and SurfaceTopography's files and the values its tests expect
 * (tests/data/st_text.README). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io.h"
#include "psd.h"
#include "solver.h"
#include "stats.h"
#include "stats_nonuni.h"
#include "units.h"
#include "testlib.h"

/* An n-point line scan at positions x with heights h (NaN: missing). */
static rc_grid *
line_scan(const double *x, const double *h, size_t n)
{
	rc_grid *g = test_new_grid(n, 1, x[n - 1] - x[0],
	    (x[n - 1] - x[0]) / (double)(n - 1));

	g->x = malloc(n * sizeof(*g->x));
	memcpy(g->x, x, n * sizeof(*x));
	memcpy(g->z, h, n * sizeof(*h));
	g->periodic = 0;
	return g;
}

/* x = 0 1 3 4, h = 0 2 2 0: L 4, integral of h 6 (mean 3/2), of h^2
 * 32/3 (hrms^2 = 32/12 - 9/4 = 5/12), of h'^2 4 + 0 + 4 (rms slope
 * sqrt 2), second derivatives -4/3 at x 1 and 3 (rms curvature 4/3). */
static void
by_hand(void)
{
	const double x[] = { 0, 1, 3, 4 }, h[] = { 0, 2, 2, 0 };
	rc_grid *g = line_scan(x, h, 4);
	rc_nonuni_stats s;
	rc_err err;

	test_true(rc_nonuni_stats_compute(g, &s, &err) == 0, "by hand: computed");
	test_rel(s.mean, 1.5, 1e-15, "by hand: mean 3/2");
	test_rel(s.hrms, sqrt(5.0 / 12), 1e-15, "by hand: hrms sqrt(5/12)");
	test_rel(s.rms_slope, sqrt(2.0), 1e-15, "by hand: rms slope sqrt 2");
	test_rel(s.rms_curvature, 4.0 / 3, 1e-15, "by hand: rms curvature 4/3");
	test_true(s.length == 4 && s.n_segments == 3 && s.n_missing == 0,
	    "by hand: 3 segments over 4");
	/* a missing point takes out its two segments: 0 1 left, h 0 2 */
	g->z[2] = NAN;
	test_true(rc_nonuni_stats_compute(g, &s, &err) == 0 && s.n_missing == 1 &&
	    s.n_segments == 1 && s.length == 1, "missing point: one segment "
	    "of length 1 left");
	/* h = 2x on [0, 1]: mean 1, hrms^2 = 4/3 - 1, slope 2 */
	test_rel(s.mean, 1, 1e-15, "missing point: mean over the segment left");
	test_rel(s.hrms, sqrt(1.0 / 3), 1e-15, "missing point: hrms 1/sqrt 3");
	test_rel(s.rms_slope, 2, 1e-15, "missing point: slope 2");
	test_true(isnan(s.rms_curvature), "missing point: no curvature left");
	g->z[1] = NAN;
	test_true(rc_nonuni_stats_compute(g, &s, &err) != 0 &&
	    strstr(err.msg, "no two neighbouring") != NULL,
	    "no valid segment: refused ('%s')", err.msg);
	rc_grid_free(g);
	/* a repeated x: refused by statistics and spectrum alike (it gave
	 * inf and NaN) */
	{
		const double xr[] = { 0, 1, 1, 4 };
		rc_psd1d_point *pts = NULL;
		size_t npts = 0;

		g = line_scan(xr, h, 4);
		test_true(rc_nonuni_stats_compute(g, &s, &err) != 0 &&
		    strstr(err.msg, "strictly increase") != NULL,
		    "repeated x: statistics refused ('%s')", err.msg);
		test_true(rc_nonuni_psd(g, RC_WINDOW_NONE, &pts, &npts, &err) != 0
		    && pts == NULL, "repeated x: spectrum refused ('%s')",
		    err.msg);
		free(pts);
		rc_grid_free(g);
	}
}

/* n positions on [0, 1], both ends included, the others random (a fixed
 * seed); the largest step into *dmax. */
static double *
random_positions(size_t n, double *dmax)
{
	double *x = malloc(n * sizeof(*x));

	srand48(26);
	x[0] = 0;
	x[n - 1] = 1;
	for (size_t i = 1; i + 1 < n; i++)
		x[i] = drand48();
	for (size_t i = 1; i + 1 < n; i++)	/* insertion sort: n is small */
		for (size_t j = i; j > 1 && x[j] < x[j - 1]; j--) {
			double t = x[j];

			x[j] = x[j - 1];
			x[j - 1] = t;
		}
	*dmax = 0;
	for (size_t i = 0; i + 1 < n; i++)
		*dmax = fmax(*dmax, x[i + 1] - x[i]);
	return x;
}

/* h = A sin(k x), k = 2 pi m, on [0, 1] at 2000 random x: mean 0,
 * hrms^2 = A^2/2, rms slope^2 = (A k)^2 / 2 exactly; the chords are off
 * by the bounds of stats_nonuni.h with max|h''| = A k^2.  The parabola
 * h = 3 x^2 has the curvature 6 at every point, which the three-point
 * formula gives exactly at any spacing. */
static void
sine_and_parabola(void)
{
	const size_t n = 2000;
	const double A = 0.7, k = 2 * M_PI * 5;
	double dmax, *x = random_positions(n, &dmax), *h = malloc(n * sizeof(*h));
	double e, sl, bound;
	rc_nonuni_stats s;
	rc_grid *g;
	rc_err err;

	for (size_t i = 0; i < n; i++)
		h[i] = A * sin(k * x[i]);
	g = line_scan(x, h, n);
	test_true(rc_nonuni_stats_compute(g, &s, &err) == 0, "sine: computed");
	e = dmax * dmax * A * k * k / 8;
	sl = dmax * A * k * k;
	test_abs(s.mean, 0, e, "sine: mean within the chord error %.3g "
	    "(largest step %.3g)", e, dmax);
	bound = 4 * e * A + 4 * e * e;
	test_abs(s.hrms * s.hrms, A * A / 2, bound, "sine: hrms^2 within "
	    "4 e A + 4 e^2 = %.3g", bound);
	bound = 2 * sl * A * k + sl * sl;
	test_abs(s.rms_slope * s.rms_slope, A * A * k * k / 2, bound,
	    "sine: rms slope^2 within 2 s A k + s^2 = %.3g", bound);
	/* the bound is not vacuous */
	test_true(bound < 0.5 * A * A * k * k, "sine: the slope bound is "
	    "below the value it bounds");
	rc_grid_free(g);
	for (size_t i = 0; i < n; i++)
		h[i] = 3 * x[i] * x[i];
	g = line_scan(x, h, n);
	test_true(rc_nonuni_stats_compute(g, &s, &err) == 0, "parabola: computed");
	test_rel(s.rms_curvature, 6, 1e-6, "parabola: curvature 6 at random x "
	    "(round-off of steps down to %.2g)", dmax / n);
	rc_grid_free(g);
	free(x);
	free(h);
}

/* The tent h = 1 - |2x - 1| on [0, 1] at points on its two lines is a
 * piecewise-linear function, so its transform is exact: the mean removed
 * changes no q_k, k > 0.  The tent is twice the convolution of two boxes
 * of width 1/2, |H(q)| = 2 (2 sin(q/4) / q)^2, so with L = 1
 * C1D_ce(2 pi k) = 4 / (pi^4 k^4) for odd k, 0 for even k (no window).
 * 10 points, the shortest step 0.05: k = 1 .. min(1/0.05 - 1, n - 2). */
static void
tent_spectrum(void)
{
	const double x[] = { 0, 0.1, 0.2, 0.3, 0.35, 0.5, 0.6, 0.8, 0.9, 1 };
	double h[10];
	rc_psd1d_point *p = NULL;
	size_t np = 0;
	rc_grid *g;
	rc_err err;
	int ok = 1;

	for (int i = 0; i < 10; i++)
		h[i] = 1 - fabs(2 * x[i] - 1);
	g = line_scan(x, h, 10);
	test_true(rc_nonuni_psd(g, RC_WINDOW_NONE, &p, &np, &err) == 0,
	    "tent: spectrum computed");
	test_int((long long)np, 8, "tent: k = 1 .. 8 (below 2 pi / mean step)");
	for (size_t j = 0; j < np; j++) {
		double kk = (double)(j + 1), want = (j % 2 == 0) ?
		    4 / (pow(M_PI, 4) * pow(kk, 4)) : 0;

		if (fabs(p[j].q - 2 * M_PI * kk) > 1e-12 ||
		    fabs(2 * M_PI * p[j].c - want) > 1e-14)
			ok = 0;
	}
	test_true(ok, "tent: C1D_ce = 4/(pi k)^4 at odd k, 0 at even k, to "
	    "round-off");
	free(p);
	test_true(rc_nonuni_psd(g, RC_WINDOW_BLACKMAN, &p, &np, &err) != 0 &&
	    strstr(err.msg, "hann or none") != NULL, "tent: blackman refused");
	rc_grid_free(g);
}

/* A sine of m = 4 periods over [0, 1] at 400 random x, no window: at
 * q = 2 pi m, |H| = A/2, C1D_ce = A^2/4; elsewhere 0; the chords' error
 * e (above) moves H by at most e: |C1D_ce - A^2/4| <= A e + e^2. */
static void
sine_spectrum(void)
{
	const size_t n = 400;
	const double A = 2, m = 4, k = 2 * M_PI * m;
	double dmax, *x = random_positions(n, &dmax), *h = malloc(n * sizeof(*h));
	double e, worst = 0;
	rc_psd1d_point *p = NULL;
	size_t np = 0;
	rc_grid *g;
	rc_err err;

	for (size_t i = 0; i < n; i++)
		h[i] = A * sin(k * x[i]);
	g = line_scan(x, h, n);
	e = dmax * dmax * A * k * k / 8;
	test_true(rc_nonuni_psd(g, RC_WINDOW_NONE, &p, &np, &err) == 0 &&
	    np > 10, "sine spectrum: computed (%zu q)", np);
	if (np > 10) {
		test_abs(2 * M_PI * p[3].c, A * A / 4, A * e + e * e,
		    "sine spectrum: C1D_ce(2 pi 4) = A^2/4 within A e + e^2 = %.3g",
		    A * e + e * e);
		for (size_t j = 0; j < 10; j++)
			if (j != 3)
				worst = fmax(worst, 2 * M_PI * p[j].c);
		test_range(worst, 0, e * e, "sine spectrum: other k up to 10 "
		    "below e^2 = %.3g", e * e);
	}
	free(p);
	rc_grid_free(g);
	free(x);
	free(h);
}

/* SurfaceTopography's files (tests/data/st_text.README). */
static void
surface_topography_files(void)
{
	rc_read_opts o;
	rc_nonuni_stats s;
	rc_err err;
	rc_grid *g;

	rc_read_opts_init(&o);
	o.nonuniform = 1;
	/* its test_mitutoyo.py: rms_height_from_profile 0.1371261153644389
	 * um (assert_almost_equal: 7 decimals), 960 points over 479.5 um */
	g = rc_grid_read(test_data_path("st_mitutoyo_nonuniform_mock.xlsx"), &o,
	    &err);
	test_true(g != NULL && g->x != NULL && g->nx == 960,
	    "Mitutoyo non-uniform mock: 960 positions (%s)", g ? "" : err.msg);
	if (g != NULL && rc_grid_to_common_unit(g, "um", &err) == 0 &&
	    rc_nonuni_stats_compute(g, &s, &err) == 0) {
		test_rel(g->lx, 479.5, 1e-12, "Mitutoyo: x span 479.5 um");
		test_abs(s.hrms, 0.1371261153644389, 5e-8,
		    "Mitutoyo: rms height %.17g um (SurfaceTopography's test, "
		    "7 decimals)", s.hrms);
	}
	rc_grid_free(g);
	/* xy-3: 0 everywhere but 1 at x 4.5 (between 4 and 5), L 9: the
	 * triangle's integral 1/2 (mean 1/18), of h^2 1/3 (hrms^2 = 1/27 -
	 * 1/324 = 11/324), of h'^2 2 x 1/0.5 = 4 (rms slope 2/3) */
	g = rc_grid_read(test_data_path("st_xy-3.txt"), &o, &err);
	test_true(g != NULL && g->x != NULL && g->nx == 11 && g->lx == 9 &&
	    !g->periodic, "xy-3: 11 positions over 9, not periodic (%s)",
	    g ? "" : err.msg);
	if (g != NULL && rc_nonuni_stats_compute(g, &s, &err) == 0) {
		test_rel(s.mean, 1.0 / 18, 1e-15, "xy-3: mean 1/18");
		test_rel(s.hrms, sqrt(11.0) / 18, 1e-15, "xy-3: hrms sqrt(11)/18");
		test_rel(s.rms_slope, 2.0 / 3, 1e-15, "xy-3: rms slope 2/3");
	}
	rc_grid_free(g);
	/* xy-6: x 0 1 2.5 3, h 1 NaN 1 1: one segment [2.5, 3] is valid */
	g = rc_grid_read(test_data_path("st_xy-6.txt"), &o, &err);
	test_true(g != NULL && g->x != NULL && g->valid != NULL,
	    "xy-6: read with its missing point (%s)", g ? "" : err.msg);
	if (g != NULL && rc_nonuni_stats_compute(g, &s, &err) == 0)
		test_true(s.n_missing == 1 && s.n_segments == 1 && s.length == 0.5 &&
		    s.mean == 1 && s.hrms == 0, "xy-6: one segment of 0.5, "
		    "height 1");
	rc_grid_free(g);
	/* xy-2: 24 points in um, x from 13.381669 to 42.591941 */
	g = rc_grid_read(test_data_path("st_xy-2.txt"), &o, &err);
	test_true(g != NULL && g->x != NULL && g->nx == 24 &&
	    fabs(g->lx - (42.591941 - 13.381669)) < 1e-12 &&
	    strcmp(g->unit, "um") == 0, "xy-2: 24 positions over 29.210272 um "
	    "(%s)", g ? "" : err.msg);
	/* no format keeps the positions: writing refuses */
	test_true(g != NULL && rc_grid_write(g, test_path("o.surf"), RC_FMT_SURF,
	    &err) != 0 && strstr(err.msg, "--uniform") != NULL,
	    "a line scan with positions is not written as a grid ('%s')",
	    err.msg);
	rc_grid_free(g);
	/* without the option: refused as before, naming --uniform */
	g = rc_grid_read(test_data_path("st_xy-2.txt"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "--uniform") != NULL,
	    "without the option: refused naming --uniform");
	rc_grid_free(g);
	/* --uniform wins */
	o.uniform = 1;
	g = rc_grid_read(test_data_path("st_xy-2.txt"), &o, &err);
	test_true(g != NULL && g->x == NULL, "--uniform wins: resampled");
	rc_grid_free(g);
}

/* What assumes the uniform step lx/nx refuses a grid with positions,
 * naming --uniform (grid.h): the solver, statistics, spectra, ACF. */
static void
uniform_only(void)
{
	const double x[] = { 0, 1, 3, 4 }, h[] = { 0, 2, 2, 0 };
	rc_grid *g = line_scan(x, h, 4);
	rc_solver_opts so;
	rc_solver *sv;
	rc_stats st;
	rc_psd1d_point *p1 = NULL;
	rc_psd_bin *pb = NULL;
	rc_acf_point *pa = NULL;
	size_t n = 0;
	rc_err err;

	rc_solver_defaults(&so);
	sv = rc_solver_new(g, &so, &err);
	test_true(sv == NULL && strstr(err.msg, "--uniform") != NULL,
	    "positions: solver refused ('%s')", sv ? "made" : err.msg);
	rc_solver_free(sv);
	err.msg[0] = '\0';
	test_true(rc_stats_compute(g, NULL, RC_DERIV_FD, &st, &err) != 0 &&
	    strstr(err.msg, "--uniform") != NULL,
	    "positions: statistics refused ('%s')", err.msg);
	err.msg[0] = '\0';
	test_true(rc_psd1d(g, RC_PSD1D_X, RC_WINDOW_NONE, &p1, &n, &err) != 0 &&
	    strstr(err.msg, "--uniform") != NULL,
	    "positions: 1D spectrum refused ('%s')", err.msg);
	free(p1);
	err.msg[0] = '\0';
	test_true(rc_psd_radial(g, NULL, 5, &pb, &n, &err) != 0 &&
	    strstr(err.msg, "--uniform") != NULL,
	    "positions: radial spectrum refused ('%s')", err.msg);
	free(pb);
	err.msg[0] = '\0';
	test_true(rc_acf(g, NULL, &pa, &n, &err) != 0 &&
	    strstr(err.msg, "--uniform") != NULL,
	    "positions: ACF refused ('%s')", err.msg);
	free(pa);
	rc_grid_free(g);
}

int
main(void)
{
	by_hand();
	sine_and_parabola();
	tent_spectrum();
	sine_spectrum();
	surface_topography_files();
	uniform_only();
	return test_summary();
}
