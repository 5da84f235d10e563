/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_free.c - free boundaries (lib/elastic/elastic_free.c, the CG on them)
 * and displacement control (lib/solver/solver_approach.c) against Hertz and
 * Boussinesq without periodic images; the non-wrapping contact analysis.
 *
 * Units: E* = 1, cell 1 x 1 unless said.  Hertz: h = -r^2/(2R), R = 1,
 * contact radius a = 1/4, so F = 4 a^3 / (3R) and, exactly,
 *   delta = a^2/R,  p0 = 3F/(2 pi a^2),  sigma = p0 sqrt(1 - r^2/a^2).
 * The peak sits on the pixel (n/2, n/2). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "free_cases.h"
#include "elastic_free.h"
#include "fft.h"
#include "gradient.h"
#include "solver.h"
#include "synth.h"
#include "testlib.h"

#define HZ_A	FC_HZ_A
#define HZ_F	FC_HZ_F
#define HZ_P0	FC_HZ_P0

static int verbose;

static rc_solver *
make(const rc_grid *g, enum rc_method m, enum rc_boundary b, double tol)
{
	rc_solver_opts o;
	rc_solver *s;
	rc_err err;

	rc_solver_defaults(&o);
	o.method = m;
	o.boundary = b;
	o.tol = tol;
	if ((s = rc_solver_new(g, &o, &err)) == NULL) {
		fprintf(stderr, "solver_new: %s\n", err.msg);
		exit(1);
	}
	return s;
}

/* A paraboloid of R = 1 peaked at pixel (n/2, n/2) on an l x l cell of
 * n x n points. */
static rc_grid *
paraboloid(size_t n, double l)
{
	rc_err err;
	rc_grid *g = rc_grid_new(n, n, l, l, &err);
	double dx = l / (double)n;

	for (size_t j = 0; j < n; j++)
		for (size_t i = 0; i < n; i++) {
			double x = ((double)i - (double)(n / 2)) * dx;
			double y = ((double)j - (double)(n / 2)) * dx;

			g->z[j * n + i] = -(x * x + y * y) / 2;
		}
	return g;
}

/* Hertz at load HZ_F and tolerance 1e-9 (free_cases.h), asserted to
 * converge. */
static struct fc_hertz
hertz(size_t n, double l, enum rc_boundary b, enum rc_method m)
{
	struct fc_hertz e;
	rc_err err;

	memset(&e, 0, sizeof(e));
	test_int(fc_hertz(n, l, b, m, 1e-9, &e, &err), 0,
	    "hertz %s %s %zu^2 converges", rc_method_name(m), rc_boundary_name(b), n);
	if (verbose)
		printf("hertz %s %s n %zu L %g: delta %.3e p0 %.3e profile %.3e a %.3e "
		    "(dx %.3e) iterations %ld pairs %.0f bytes/point %.1f\n",
		    rc_method_name(m), rc_boundary_name(b), n, l, e.delta, e.p0,
		    e.profile, e.a, e.dx, e.run.iterations, e.run.pairs, e.run.bytes);
	return e;
}

/* Love's pixel: C(0,0) = 4 (d/2) 2 asinh(1) / pi for a square pixel of
 * side d (exact); far away it tends to the point load d^2 / (pi r), with
 * a relative correction of order (d/r)^2 (the pixel's second moment):
 * below 1e-3 at r = 20 d.  The padded operator reproduces C at every
 * offset, up to the far corner, with no periodic image (round-off of the
 * 4N-point FFT: 1e-12 of the self term). */
static void
love(void)
{
	rc_halfspace hs;
	rc_err err;
	size_t n = 16, k;
	double d = 1.0 / 16, *sigma = calloc(n * n, sizeof(double)), worst = 0;

	test_rel(rc_love_pixel(0, 0, d, d), 4 * d * asinh(1) / M_PI, 1e-14,
	    "love: centre of a square pixel");
	test_rel(rc_love_pixel(20 * d, 0, d, d), d * d / (M_PI * 20 * d), 1e-3,
	    "love: point-load limit at 20 pixels");
	test_rel(rc_love_pixel(3 * d, -2 * d, d, 2 * d),
	    rc_love_pixel(-3 * d, 2 * d, d, 2 * d), 1e-14, "love: even");
	test_int(rc_halfspace_init(&hs, n, n, 1, 1, 2, RC_FFT_ESTIMATE, &err), 0,
	    "halfspace init");
	sigma[0] = 1;	/* corner pixel: the far corner is the largest offset */
	rc_halfspace_apply(&hs, sigma, sigma);
	for (k = 0; k < n * n; k++) {
		double x = (double)(k % n) * d, y = (double)(k / n) * d;
		double diff = fabs(sigma[k] - rc_love_pixel(x, y, d, d) / 2);

		if (diff > worst)
			worst = diff;
	}
	test_abs(worst, 0, 1e-12 * hs.self, "halfspace: padded convolution = "
	    "direct sum at every offset (E* = 2)");
	rc_halfspace_release(&hs);
	test_int(rc_halfspace_init(&hs, n, 1, 1, 1, 1, RC_FFT_ESTIMATE, &err), -1,
	    "halfspace: a line is refused");
	free(sigma);
}

/* Hertz on free boundaries at 32^2, 64^2, 128^2 (dx = 1/n, a = 8, 16, 32
 * pixels).  Measured errors (delta, p0, profile rms / p0, a):
 *    32: -2.7e-4  1.1e-3  9.7e-3  7.3e-3
 *    64: -8.3e-5  2.5e-4  4.9e-3  1.4e-3
 *   128: -3.4e-5  4.9e-5  2.6e-3  1.2e-3
 * Observed orders 64 -> 128: delta 1.3, p0 2.3, profile 0.9 (the pressure
 * is sqrt-singular in slope at the edge, which a pixel cannot resolve;
 * first order), a: the contact edge is known to a pixel.  Tolerances: twice
 * the 128^2 errors, orders at least 1, 1.5 and 0.7, |a error| < dx / 2.
 * The periodic solver on the same 128^2 grid feels its images: p0 2%
 * high, profile 2.3%, and its approach (against <u>, solver.h) is no
 * Hertz delta at all (40% off): it must differ from Hertz by more than
 * ten times the free errors. */
static void
hertz_free(enum rc_method m)
{
	struct fc_hertz e64 = hertz(64, 1, RC_BOUNDARY_FREE, m);
	struct fc_hertz e128 = hertz(128, 1, RC_BOUNDARY_FREE, m);
	struct fc_hertz per = hertz(128, 1, RC_BOUNDARY_PERIODIC, m);

	test_abs(e128.delta, 0, 8e-5, "hertz free 128^2: approach a^2/R");
	test_abs(e128.p0, 0, 1e-4, "hertz free 128^2: peak pressure 3F/(2 pi a^2)");
	test_abs(e128.profile, 0, 6e-3, "hertz free 128^2: profile p0 sqrt(1 - r^2/a^2)");
	test_abs(e128.a, 0, e128.dx / 2, "hertz free 128^2: contact radius (3FR/4E*)^(1/3)");
	test_abs(e64.delta, 0, 2e-4, "hertz free 64^2: approach");
	test_true(log2(fabs(e64.delta / e128.delta)) >= 1, "hertz free: approach "
	    "converges at first order or better (%.2e, %.2e)", e64.delta, e128.delta);
	test_true(log2(fabs(e64.p0 / e128.p0)) >= 1.5, "hertz free: p0 converges "
	    "at order 1.5 or better (%.2e, %.2e)", e64.p0, e128.p0);
	test_true(log2(e64.profile / e128.profile) >= 0.7, "hertz free: profile "
	    "converges at order 0.7 or better (%.2e, %.2e)", e64.profile, e128.profile);
	test_true(fabs(per.p0) > 10 * fabs(e128.p0) && per.profile > 3 * e128.profile,
	    "hertz periodic 128^2 differs from Hertz (p0 %.2e, profile %.2e) "
	    "and the free solve does not (%.2e, %.2e)", per.p0, per.profile,
	    e128.p0, e128.profile);
	test_true(fabs(per.delta) > 0.1, "hertz periodic: approach against <u> "
	    "is not the half-space delta (%.2e)", per.delta);
}

/* A single Hertz asperity in a growing periodic cell (dx = 1/64 fixed,
 * L = 1, 2, 4): the images recede and the periodic answer tends to the
 * free one.  The images' uniform counter-pressure -F/L^2 bends the
 * surface over the contact by ~ F/(E* L^3), a relative change of the
 * curvature of order F R / (E* L^3) ~ (a/L)^3: the difference in p0 must
 * fall with L at a rate near 3.  Measured |p0 periodic - p0 free| / p0:
 * 2.0e-2 (L = 1), 2.2e-3 (L = 2; rate 3.2), 1.9e-5 (L = 4): by then the
 * images' effect is below the difference between the two discretisations
 * (the periodic spectral compliance at the pixel centres, Love's pixel
 * average; each ~2.4e-4 from Hertz at this dx), so the rate is tested
 * from L = 1 to 2, in [2.5, 3.5], and L = 4 must be within 1e-4. */
static void
growing_cell(void)
{
	struct fc_hertz f = hertz(64, 1, RC_BOUNDARY_FREE, RC_METHOD_CG);
	double d[3];
	int k;

	for (k = 0; k < 3; k++) {
		double l = (double)(1 << k);
		struct fc_hertz p = hertz((size_t)64 << k, l, RC_BOUNDARY_PERIODIC,
		    RC_METHOD_CG);

		d[k] = fabs(p.p0 - f.p0);
		if (verbose)
			printf("growing cell L %g: |p0 periodic - p0 free| / p0 = %.3e\n",
			    l, d[k]);
	}
	test_true(d[1] < d[0] && d[2] < d[1], "growing cell: periodic p0 "
	    "approaches the free one (%.2e, %.2e, %.2e)", d[0], d[1], d[2]);
	test_range(log2(d[0] / d[1]), 2.5, 3.5, "growing cell: rate ~ L^-3 "
	    "(%.2e -> %.2e)", d[0], d[1]);
	test_abs(d[2], 0, 1e-4, "growing cell L = 4: the free answer within "
	    "the discretisations' difference");
}

/* Flat punch (Boussinesq): a rigid cylinder of radius a = 1/4 (h = 0 on
 * r <= a, far below outside) pressed by delta under displacement control
 * (rc_solver_solve_approach) on free boundaries: F = 2 a E* delta, with a
 * the radius of the pixel disc, sqrt(n_disc dx^2 / pi); pressure
 * F / (2 pi a sqrt(a^2 - r^2)) for r < a/2 (the edge singularity is not
 * resolved by pixels).  Measured F / (2 a E* delta) - 1: -6.5e-3 (64^2),
 * -3.3e-3 (128^2), first order; inner profile rms 1.4e-2, 7.1e-3.
 * Tolerances 1e-2 and 2e-2; order at least 0.8 from 64^2 to 128^2. */
static double
flat_punch(size_t n, enum rc_method m)
{
	struct fc_punch e;
	rc_err err;

	memset(&e, 0, sizeof(e));
	test_int(fc_punch(n, m, 1e-9, &e, &err), 0,
	    "flat punch %s %zu^2: displacement control converges",
	    rc_method_name(m), n);
	test_abs(e.approach, 0, 1e-8, "flat punch %zu^2: approach reached", n);
	if (verbose)
		printf("flat punch %s %zu: F/(2 a E* delta) - 1 = %.3e, inner "
		    "profile rms %.3e, iterations %ld\n", rc_method_name(m), n,
		    e.force, e.profile, e.run.iterations);
	test_abs(e.force, 0, 1e-2, "flat punch %zu^2: F = 2 a E* delta", n);
	test_abs(e.profile, 0, 2e-2, "flat punch %zu^2: pressure profile "
	    "for r < a/2", n);
	return e.force;
}

/* Load control then displacement control at the approach it gave (and
 * the reverse) reach the same state: the pressure to the root find's
 * tolerance (tol delta in the approach, times the secant slope: < 1e-6),
 * the same contact points, and the same pressure field. */
static void
inverse(enum rc_method m, enum rc_boundary b)
{
	rc_grid *g = paraboloid(64, 1);
	rc_solver *s1 = make(g, m, b, 1e-9), *s2 = make(g, m, b, 1e-9);
	rc_solve_result r;
	rc_err err;
	double delta, p, worst = 0, top = 0;
	size_t k, same = 0;

	test_int(rc_solver_solve(s1, HZ_F, &r, &err), 0, "inverse %s %s: load",
	    rc_method_name(m), rc_boundary_name(b));
	delta = rc_solver_approach(s1);
	test_int(rc_solver_solve_approach(s2, delta, &p, &r, &err), 0,
	    "inverse %s %s: displacement", rc_method_name(m), rc_boundary_name(b));
	test_rel(p, HZ_F, 1e-6, "inverse %s %s: the same pressure",
	    rc_method_name(m), rc_boundary_name(b));
	for (k = 0; k < 64 * 64; k++) {
		double d = fabs(rc_solver_pressure(s1)[k] - rc_solver_pressure(s2)[k]);

		same += rc_solver_contact(s1)[k] == rc_solver_contact(s2)[k];
		if (d > worst)
			worst = d;
		if (rc_solver_pressure(s1)[k] > top)
			top = rc_solver_pressure(s1)[k];
	}
	if (b == RC_BOUNDARY_PERIODIC) {
		/* The periodic approach is the mean-gap change (solver.h):
		 * max h - <h> - <u - h>, an identity up to round-off. */
		double hmean = 0;

		for (k = 0; k < 64 * 64; k++)
			hmean += g->z[k] / (64.0 * 64.0);
		test_rel(rc_solver_approach(s2), 0 - hmean - rc_solver_mean_gap(s2),
		    1e-12, "inverse %s periodic: approach = mean-gap change",
		    rc_method_name(m));
	}
	test_int((long long)same, 64 * 64, "inverse %s %s: the same contact",
	    rc_method_name(m), rc_boundary_name(b));
	test_abs(worst, 0, 1e-4 * top, "inverse %s %s: the same pressure field",
	    rc_method_name(m), rc_boundary_name(b));
	rc_solver_free(s1);
	rc_solver_free(s2);
	rc_grid_free(g);
}

/* FIRE on pressures and the CG on free boundaries solve the same
 * problem: on a rough 128^2 surface (rc_synth defaults, seed 1, p* =
 * 0.05 E* gbar-ish) at tol 1e-9 they give the same contact points and
 * pressures within 1e-6 of the largest (both converged to 1e-9 of p in
 * the gap measure, which bounds pressure differences by about
 * sqrt(N) 1e-9 p; measured 3.0e-10 and 1.1e-10 at 64^2 and 128^2).
 * And FIRE's iteration count stays nearly
 * flat from 64^2 to 128^2 (the periodic stiffness as inverse mass): at
 * most 1.5 times (measured 62 and 64). */
static void
methods_agree(void)
{
	rc_synth_params sp;
	rc_grid *g[2];
	rc_err err;
	long its[2];

	for (int k = 0; k < 2; k++) {
		rc_solver *s[2];
		rc_solve_result r;
		size_t n = (size_t)64 << k, same = 0;
		double worst = 0, top = 0;

		rc_synth_defaults(&sp);
		sp.nx = sp.ny = n;
		sp.seed = 1;
		if ((g[k] = rc_synth(&sp, &err)) == NULL) {
			fprintf(stderr, "synth: %s\n", err.msg);
			exit(1);
		}
		for (int m = 0; m < 2; m++) {
			s[m] = make(g[k], m ? RC_METHOD_FIRE : RC_METHOD_CG,
			    RC_BOUNDARY_FREE, 1e-9);
			test_int(rc_solver_solve(s[m], 0.05, &r, &err), 0, "rough %zu^2 "
			    "free %s converges", n, m ? "fire" : "cg");
			if (m)
				its[k] = r.iterations;
		}
		for (size_t i = 0; i < n * n; i++) {
			double d = fabs(rc_solver_pressure(s[0])[i] -
			    rc_solver_pressure(s[1])[i]);

			same += rc_solver_contact(s[0])[i] == rc_solver_contact(s[1])[i];
			worst = d > worst ? d : worst;
			top = rc_solver_pressure(s[0])[i] > top ?
			    rc_solver_pressure(s[0])[i] : top;
		}
		if (verbose)
			printf("rough %zu free: fire %ld iterations; differing contact "
			    "points %zu, max |dsigma| / max sigma %.2e\n", n, its[k],
			    n * n - same, worst / top);
		test_int((long long)same, (long long)(n * n), "rough %zu^2 free: "
		    "fire and cg agree on the contact", n);
		test_abs(worst, 0, 1e-6 * top, "rough %zu^2 free: fire and cg "
		    "agree on the pressure", n);
		rc_solver_free(s[0]);
		rc_solver_free(s[1]);
		rc_grid_free(g[k]);
	}
	test_true(its[1] <= 1.5 * (double)its[0], "free fire iterations nearly "
	    "flat in N: %ld at 64^2, %ld at 128^2", its[0], its[1]);
}

static void
refusals(void)
{
	rc_grid *g = paraboloid(16, 1);
	rc_solver_opts o;
	rc_solver *s;
	rc_solve_result r;
	rc_err err;
	double p;

	rc_solver_defaults(&o);
	o.boundary = RC_BOUNDARY_FREE;
	test_true(rc_solver_new(&(rc_grid){ .nx = 16, .ny = 1, .lx = 1, .ly = 1,
	    .z = g->z }, &o, &err) == NULL && strstr(err.msg, "line"),
	    "free boundaries: a line contact is refused with a message");
	s = make(g, RC_METHOD_CG, RC_BOUNDARY_PERIODIC, 1e-6);
	/* max h - <h> of the paraboloid: full contact. */
	test_int(rc_solver_solve_approach(s, 1, &p, &r, &err), -1,
	    "periodic approach beyond full contact refused");
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Contact analysis of a finite patch: a mask with contact in columns 0
 * and 7 of row 1 of an 8 x 4 grid is one periodic patch (wrapped) but two
 * on a finite patch; each of its points is on the contact line either
 * way.  A plane h = 0.3 x - 0.2 y has gbar = sqrt(0.13) exactly by
 * non-wrapping differences (central, one-sided at the edges: exact on a
 * plane), while the periodic ones see the step between opposite edges. */
static void
open_analysis(void)
{
	unsigned char m[32] = { 0 };
	size_t np;
	double sq;
	rc_err err;
	rc_grid *g = rc_grid_new(8, 4, 8, 4, &err);

	m[8] = m[15] = 1;
	test_int(rc_contact_patches(m, 8, 4, &np, &sq, &err), 0, "patches run");
	test_int((long long)np, 1, "periodic: one patch across the x edge");
	test_int(rc_contact_patches_open(m, 8, 4, &np, &sq, &err), 0, "open patches run");
	test_int((long long)np, 2, "finite patch: two patches");
	test_rel(sq, 2, 0, "finite patch: sizes 1 and 1");
	memset(m, 1, sizeof(m));
	test_int((long long)rc_contact_line(m, 8, 4), 0, "periodic full contact: no line");
	test_int((long long)rc_contact_line_open(m, 8, 4), 20,
	    "finite full contact: the 20 edge points are the line");
	for (size_t j = 0; j < 4; j++)
		for (size_t i = 0; i < 8; i++)
			g->z[j * 8 + i] = 0.3 * (double)i - 0.2 * (double)j;
	test_rel(rc_gbar_open(g), sqrt(0.13), 1e-12, "gbar of a plane, open");
	test_true(rc_gbar_central(g) > 1.5 * sqrt(0.13), "gbar of a plane, "
	    "periodic, sees the edge step (%g)", rc_gbar_central(g));
	rc_grid_free(g);
}

int
main(void)
{
	verbose = getenv("TEST_VERBOSE") != NULL;
	rc_fft_set_threads(1);
	love();
	hertz_free(RC_METHOD_CG);
	hertz_free(RC_METHOD_FIRE);
	growing_cell();
	for (int m = 0; m < 2; m++) {
		enum rc_method method = m ? RC_METHOD_FIRE : RC_METHOD_CG;
		double e64 = flat_punch(64, method), e128 = flat_punch(128, method);

		test_true(log2(fabs(e64 / e128)) >= 0.8, "flat punch %s: F converges "
		    "at first order (%.2e, %.2e)", rc_method_name(method), e64, e128);
	}
	methods_agree();
	inverse(RC_METHOD_CG, RC_BOUNDARY_FREE);
	inverse(RC_METHOD_FIRE, RC_BOUNDARY_FREE);
	inverse(RC_METHOD_CG, RC_BOUNDARY_PERIODIC);
	inverse(RC_METHOD_FIRE, RC_BOUNDARY_PERIODIC);
	refusals();
	open_analysis();
	return test_summary();
}
