/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_adhesion.c - the exponential adhesive law of adhesion.h in FIRE
 * (solver_fire_adh.c, solver_fire_adh_free.c), against closed forms:
 *  - the law: its traction integrates to -dgamma, is -dphi/dg;
 *  - a sphere (paraboloid, E* = 1, dx = 1) traced under displacement
 *    control: pull-off -2 pi dgamma R in the DMT limit (Tabor mu << 1),
 *    -1.5 pi dgamma R in the JKR limit (mu >> 1), and the JKR contact
 *    radius at zero load, a0^3 = 9 pi dgamma R^2 / (2 E*);
 *  - Johnson (1995): a 1-D sine h = A cos(2 pi x / L) under displacement
 *    control: the mean pressure p at contact half-width a against
 *      p(a) = p* sin^2(pi a / L) - sqrt(2 E* dgamma tan(pi a / L) / L),
 *    p* = pi E* A / L (Westergaard's full-contact pressure; the second
 *    term the tension of a periodic flat punch whose edge stress
 *    intensity K meets Griffith's K^2 / (2 E*) = dgamma; gfmd-solve(1),
 *    ADHESION), and its pull-off, the minimum of p(a);
 *  - free boundaries: the sphere's DMT and JKR pull-off and JKR radius,
 *    the transition between them against Maugis' curve, load against
 *    displacement control, separation;
 *  - dgamma -> 0: the non-adhesive contact (on free boundaries against
 *    the CG on pressures, a second method);
 *  - hysteresis: loading and unloading branches, the pull-off on the
 *    unloading one; separation past pull-off under load control;
 *  - warm starts; refusals;
 *  - a periodic layer under displacement control (its substrate held):
 *    load against displacement control both ways, dgamma -> 0 against
 *    the non-adhesive layer's root find, hysteresis and pull-off.
 * Measured errors, and the tolerances from them, at each check. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "adhesion.h"
#include "layer.h"
#include "solver.h"
#include "synth.h"
#include "testlib.h"

static rc_grid *
sphere(size_t n, double R)
{
	rc_grid *g = rc_grid_new(n, n, (double)n, (double)n, NULL);

	for (size_t j = 0; j < n; j++)
		for (size_t i = 0; i < n; i++) {
			double x = (double)i - 0.5 * (double)n;
			double y = (double)j - 0.5 * (double)n;

			g->z[j * n + i] = -(x * x + y * y) / (2 * R);
		}
	g->periodic = 1;
	return g;
}

static rc_grid *
sine(size_t nx, size_t ny, double A)
{
	rc_grid *g = rc_grid_new(nx, ny, (double)nx, (double)ny, NULL);

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			g->z[j * nx + i] = A * cos(2 * M_PI * (double)i / (double)nx);
	g->periodic = 1;
	return g;
}

/* A solver, the test ended when it cannot be made (set-up). */
static rc_solver *
solver_or_exit(const rc_grid *g, const rc_solver_opts *o)
{
	rc_err err;
	rc_solver *s = rc_solver_new(g, o, &err);

	if (s == NULL) {
		fprintf(stderr, "rc_solver_new: %s\n", err.msg);
		exit(1);
	}
	return s;
}

/* FIRE with the law on boundaries bc. */
static rc_solver *
adhesive_law(const rc_grid *g, enum rc_adhesion_law law, double dgamma,
    double range, double tol, enum rc_boundary bc)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
	o.adhesion_law = law;
	o.adhesion = dgamma;
	o.range = range;
	o.tol = tol;
	o.boundary = bc;
	return solver_or_exit(g, &o);
}

static rc_solver *
adhesive_bc(const rc_grid *g, double dgamma, double range, double tol,
    enum rc_boundary bc)
{
	return adhesive_law(g, RC_ADHESION_EXPONENTIAL, dgamma, range, tol, bc);
}

static rc_solver *
adhesive(const rc_grid *g, double dgamma, double range, double tol)
{
	return adhesive_bc(g, dgamma, range, tol, RC_BOUNDARY_PERIODIC);
}

static size_t
n_contact(const rc_solver *s, size_t n)
{
	const unsigned char *c = rc_solver_contact(s);
	size_t on = 0;

	for (size_t k = 0; k < n; k++)
		on += c[k];
	return on;
}

/* The mean pressure at approach delta (displacement control). */
static double
at_approach(rc_solver *s, double delta, int *status, long *iterations)
{
	rc_solve_result res;
	rc_err err;
	double p;
	int st = rc_solver_solve_approach(s, delta, &p, &res, &err);

	if (st < 0) {
		fprintf(stderr, "approach %g: %s\n", delta, err.msg);
		exit(1);
	}
	if (status && st != 0)
		*status = st;
	if (iterations)
		*iterations = res.iterations;
	return p;
}

struct sweep {
	double fmin;		/* least force (p n^2) */
	double a0;		/* contact radius where the force crosses 0 */
	int status;		/* worst solve status */
	double d_out;		/* the last approach in contact */
	double d_at, f_at;	/* the force at approach d_at */
	size_t n_at;		/* and the contact points there */
	long it_max, it_sum;	/* iterations: most in one solve, all */
	long solves;
	double m_min;		/* at the least force: sqrt((n_c + attracted)
				 * / n_c), the zone's outer over the contact's
				 * radius */
};

/* A sphere unloaded from approach d0 in steps of -step until it has come
 * off the indenter for 4 steps: the least force and the zero-load
 * contact radius (linear interpolation of sqrt(n_c / pi)). */
static struct sweep
unload(rc_solver *s, size_t n, double d0, double step)
{
	struct sweep w = { HUGE_VAL, NAN, 0, NAN, -2, NAN, 0, 0, 0, 0, NAN };
	double f_prev = NAN, a_prev = NAN;
	int off = 0;

	for (double d = d0; off < 4; d -= step) {
		long it;
		double f = at_approach(s, d, &w.status, &it) * (double)(n * n);
		double a = sqrt((double)n_contact(s, n * n) / M_PI);

		w.it_max = it > w.it_max ? it : w.it_max;
		w.it_sum += it;
		w.solves++;

		if (f < w.fmin) {
			w.fmin = f;
			w.m_min = sqrt(1 + rc_solver_attractive_fraction(s) *
			    (double)(n * n) / (double)n_contact(s, n * n));
		}
		if (f_prev > 0 && f <= 0)
			w.a0 = a_prev + (a - a_prev) * f_prev / (f_prev - f);
		if (a > 0)
			w.d_out = d;
		if (d == w.d_at) {
			w.f_at = f;
			w.n_at = n_contact(s, n * n);
		}
		f_prev = f;
		a_prev = a;
		off = a == 0 ? off + 1 : 0;
		if (d < -50)
			break;
	}
	return w;
}

static void
test_law(void)
{
	rc_adhesion a;
	double sum = 0, h = 1e-3;

	test_int(rc_adhesion_init(&a, RC_ADHESION_EXPONENTIAL, 0.3, 0.2), 0, "law: init");
	test_int(rc_adhesion_init(&a, RC_ADHESION_EXPONENTIAL, 0, 0.2), -1, "law: dgamma 0 refused");
	rc_adhesion_init(&a, RC_ADHESION_EXPONENTIAL, 0.3, 0.2);
	/* midpoint rule to 40 ranges: error (h^2/24) |sigma''| ~ 1e-6 */
	for (double g = 0.5 * h; g < 8; g += h)
		sum += rc_adhesion_traction(&a, g) * h;
	test_rel(sum, -0.3, 1e-5, "law: int_0^inf sigma_a dg = -dgamma");
	test_rel(rc_adhesion_traction(&a, 0.1),
	    -(rc_adhesion_energy(&a, 0.1 + 1e-6) - rc_adhesion_energy(&a,
	    0.1 - 1e-6)) / 2e-6, 1e-8, "law: sigma_a = -dphi/dg");
	test_rel(rc_adhesion_length(2, 0.3, 0.2), 2 * 0.04 / 0.3, 1e-15,
	    "law: l_adh = E* rho^2 / dgamma");
	test_rel(rc_adhesion_tabor(128, 1, 0.25, 0.5), 4, 1e-14,
	    "law: Tabor mu of R 128, dgamma 0.25, rho 0.5");
	test_int(rc_adhesion_law_parse("dugdale"), RC_ADHESION_DUGDALE,
	    "law: dugdale by name");
	test_int(rc_adhesion_law_parse("linear"), -1, "law: unknown name");
	test_true(rc_adhesion_init(&a, (enum rc_adhesion_law)7, 0.3, 0.2) == -1,
	    "law: unknown law refused");
}

/* Dugdale's law: sigma_0 = dgamma / delta_c up to the opening delta_c =
 * rho, 0 beyond; phi linear up to rho and 0 beyond, continuous there. */
static void
test_dugdale_law(void)
{
	rc_adhesion a;
	double sum = 0, h = 1e-3, rho = 0.2, s0 = 0.3 / 0.2;

	test_int(rc_adhesion_init(&a, RC_ADHESION_DUGDALE, 0.3, rho), 0,
	    "Dugdale: init");
	/* midpoint rule, the step at a node (200 steps of 1e-3): exact but
	 * for the rounding of the sum */
	for (int k = 0; k < 8000; k++)
		sum += rc_adhesion_traction(&a, (k + 0.5) * h) * h;
	test_rel(sum, -0.3, 1e-12, "Dugdale: int_0^inf sigma_a dg = -dgamma");
	test_rel(rc_adhesion_traction(&a, 0), -s0, 1e-15, "Dugdale: sigma_0 "
	    "= dgamma / rho at contact");
	test_rel(rc_adhesion_traction(&a, rho * (1 - 1e-12)), -s0, 1e-15,
	    "Dugdale: sigma_0 just inside delta_c = rho");
	test_rel(rc_adhesion_traction(&a, rho * (1 + 1e-12)), 0, 0,
	    "Dugdale: 0 just beyond delta_c");
	test_rel(rc_adhesion_traction(&a, rho), 0, 0, "Dugdale: 0 at delta_c");
	test_rel(rc_adhesion_energy(&a, 0), -0.3, 1e-15, "Dugdale: phi(0) = "
	    "-dgamma");
	test_abs(rc_adhesion_energy(&a, rho * (1 - 1e-12)), 0, 1e-12,
	    "Dugdale: phi continuous at delta_c");
	test_rel(rc_adhesion_traction(&a, 0.1),
	    -(rc_adhesion_energy(&a, 0.1 + 1e-6) - rc_adhesion_energy(&a,
	    0.1 - 1e-6)) / 2e-6, 1e-8, "Dugdale: sigma_a = -dphi/dg");
	test_true(rc_adhesion_tension_beyond(&a, 0.5 * rho) == s0 &&
	    rc_adhesion_tension_beyond(&a, rho) == 0, "Dugdale: the strongest "
	    "tension left");
}

/* DMT: R = 50, rho = 2 (l_adh = 400 and 1600 dx); measured
 * -1.969 pi dgamma R at mu = 0.085 and -1.986 at mu = 0.034 (the elastic
 * flattening lowers the rigid sphere's 2 by O(mu)); tolerance 2.5% and
 * 1.0%, and the error must fall with mu. */
/* Returns the pull-off at mu 0.085, for test_free_sphere. */
static double
test_dmt(void)
{
	rc_grid *g = sphere(128, 50);
	double err[2], dg[2] = { 0.01, 0.0025 }, tol[2] = { 0.025, 0.010 };

	for (int i = 0; i < 2; i++) {
		rc_solver *s = adhesive(g, dg[i], 2, 1e-8);
		struct sweep w = unload(s, 128, 0.3, 0.01);
		double f = w.fmin / (M_PI * dg[i] * 50);

		test_int(w.status, 0, "DMT mu %.3f: every solve converges",
		    rc_adhesion_tabor(50, 1, dg[i], 2));
		test_range(f, -2, -2 * (1 - tol[i]), "DMT mu %.3f: pull-off "
		    "F / (pi dgamma R) (-2 in the limit)",
		    rc_adhesion_tabor(50, 1, dg[i], 2));
		err[i] = f + 2;
		rc_solver_free(s);
	}
	test_true(err[1] < err[0], "DMT: the error falls with mu (%.4f at mu "
	    "0.085, %.4f at 0.034)", err[0], err[1]);
	rc_grid_free(g);
	return err[0] - 2;
}

/* JKR: dgamma 0.25, rho 0.5 (l_adh = dx), 256^2.  Measured: pull-off
 * -1.5453 pi dgamma R at mu = 4 (R = 128), -1.5634 at mu = 3 (R = 54):
 * the finite mu, falling towards -1.5.  Tolerance 4.5% at mu 4 (3.0%
 * measured), and the error must fall from mu 3 to 4.  a0 at mu 4:
 * measured 0.9% below (9 pi dgamma R^2 / 2)^(1/3) = 38.7 dx; tolerance 4%
 * (one pixel of radius is 2.6%).
 * Hysteresis at mu 4: loaded from approach -3 up to 5 before the
 * unloading: the loading branch jumps into contact at -1.75, the
 * unloading one out at -2.75 (measured); at -2 the loading branch is off
 * the indenter (force -0.05 pi dgamma R, the attraction alone), the
 * unloading one in contact (-1.39); the least force, the pull-off, lies
 * on the unloading branch.  Load control past it (-1.6 pi dgamma R)
 * separates, before max_iter (measured 106 iterations); at -1.4 it
 * holds. */
static void
test_jkr(void)
{
	double R[2] = { 54, 128 }, err[2], pc = M_PI * 0.25 * 128;
	rc_solve_result res;
	rc_err e;
	rc_grid *g;

	for (int i = 0; i < 2; i++) {
		rc_solver *s;
		struct sweep w;
		double f, a0 = cbrt(9 * M_PI * 0.25 * R[i] * R[i] / 2);
		double fmin_load = HUGE_VAL, f_load = NAN, d_in = NAN;
		size_t n_load = 0;
		int st;

		g = sphere(256, R[i]);
		s = adhesive(g, 0.25, 0.5, 1e-6);
		for (double d = -3; i == 1 && d <= 5; d += 0.25) {
			double fl = at_approach(s, d, &st, NULL) * 256 * 256;
			size_t nc = n_contact(s, 256 * 256);

			if (nc == 0)
				fmin_load = fmin(fmin_load, fl);
			else if (isnan(d_in))
				d_in = d;
			if (d == -2) {
				n_load = nc;
				f_load = fl;
			}
		}
		w = unload(s, 256, i == 0 ? 3 : 5, 0.25);
		f = w.fmin / (M_PI * 0.25 * R[i]);
		test_int(w.status, 0, "JKR R %g: every solve converges", R[i]);
		err[i] = f + 1.5;
		if (i == 0) {
			rc_solver_free(s);
			rc_grid_free(g);
			continue;
		}
		test_rel(f, -1.5, 0.045, "JKR mu 4: pull-off F / (pi dgamma R)");
		test_rel(w.a0, a0, 0.04, "JKR mu 4: contact radius at zero load");
		test_true(w.d_out < d_in, "hysteresis sphere: contact from "
		    "approach %g loading, down to %g unloading", d_in, w.d_out);
		test_true(n_load == 0 && w.n_at > 0, "hysteresis sphere: at "
		    "approach -2 loading n_c %zu, unloading n_c %zu", n_load,
		    w.n_at);
		test_true(w.f_at < -1 * pc && f_load > -0.1 * pc, "hysteresis "
		    "sphere: at approach -2 the force unloading %.3f, loading "
		    "%.3f pi dgamma R", w.f_at / pc, f_load / pc);
		test_true(w.fmin < 10 * fmin_load, "hysteresis sphere: the "
		    "pull-off %.4f (unloading) far beyond the least force off "
		    "contact on loading, %.4f pi dgamma R", w.fmin / pc,
		    fmin_load / pc);
		at_approach(s, 3, NULL, NULL);
		pc /= 256.0 * 256.0;
		st = rc_solver_solve(s, -1.4 * pc, &res, &e);
		test_true(st == 0 && !res.separated && n_contact(s, 256 * 256) > 0,
		    "load control at -1.4 pi dgamma R: in contact, converged");
		st = rc_solver_solve(s, -1.6 * pc, &res, &e);
		test_true(st == 1 && res.separated, "load control at -1.6 pi "
		    "dgamma R: separated (status %d, separated %d)", st,
		    res.separated);
		test_true(res.iterations < 100000, "separation found before "
		    "max_iter (%ld iterations)", res.iterations);
		rc_solver_free(s);
		rc_grid_free(g);
	}
	test_true(fabs(err[1]) < fabs(err[0]), "JKR: the error falls with mu "
	    "(%.4f at mu 3, %.4f at mu 4)", err[0], err[1]);
}

/* Johnson's p(a) of a sine, alpha = sqrt(2 dgamma L / (pi^2 E* A^2)). */
static double
johnson(double a, double L, double A, double dgamma)
{
	double psi = M_PI * a / L, s = sin(psi);

	return M_PI * A / L * s * s - sqrt(2 * dgamma * tan(psi) / L);
}

/* Johnson (1995): L = 256, A = 2, alpha = 0.3 (dgamma = 0.00694),
 * 256 x 4 points, dx = 1; the contact half-width a = n_c / (2 ny).
 * Measured max |p - p(a)| over approaches 1.9 ... 0:
 * 0.0095 p* at rho = 0.1 (l_adh = 1.44 dx = 0.0056 L), 0.027 p* at rho =
 * 0.2 (l_adh 4x): the finite range, shrinking with l_adh / L (a grid
 * twice as fine at the same l_adh / L, 512 x 4 with A = 4: 0.0098 p*, so
 * not the grid).  Tolerance 0.02 p*.  Pull-off: min over a of p(a) =
 * -0.0959 p*; measured -0.0993 p* (0.0033 off: the finite range again);
 * tolerance 0.01 p*. */
static void
test_johnson(void)
{
	const size_t nx = 256, ny = 4;
	const double A = 2, L = 256, dgamma = 0.00694, ps = M_PI * A / L;
	double worst[2] = { 0, 0 }, rho[2] = { 0.1, 0.2 };
	double delta[5] = { 1.9, 1.5, 1, 0.5, 0 };
	rc_grid *g = sine(nx, ny, A);

	for (int r = 0; r < 2; r++) {
		rc_solver *s = adhesive(g, dgamma, rho[r], 1e-8);
		int status = 0;

		for (int i = 0; i < 5; i++) {
			double p = at_approach(s, delta[i], &status, NULL);
			double a = 0.5 * (double)n_contact(s, nx * ny) / (double)ny;
			double e = fabs(p - johnson(a, L, A, dgamma)) / ps;

			if (e > worst[r])
				worst[r] = e;
		}
		test_int(status, 0, "Johnson rho %g: every solve converges",
		    rho[r]);
		if (r == 0) {
			double pmin = HUGE_VAL, tmin = HUGE_VAL;

			test_range(worst[0], 0, 0.02, "Johnson rho 0.1: max "
			    "|p - p(a)| / p* over 5 approaches");
			/* pull-off: the least p along the unloading, against
			 * the least p(a) */
			for (double d = 0; d > -1; d -= 0.02) {
				double p = at_approach(s, d, NULL, NULL);

				if (n_contact(s, nx * ny) == 0)
					break;
				pmin = fmin(pmin, p);
			}
			for (double a = 0.01; a < 60; a += 0.01)
				tmin = fmin(tmin, johnson(a, L, A, dgamma));
			test_abs(tmin / ps, -0.0958, 5e-4, "Johnson: min p(a) / p* "
			    "at alpha 0.3");
			test_abs(pmin / ps, tmin / ps, 0.01, "Johnson: pull-off "
			    "p / p*");
		}
		rc_solver_free(s);
	}
	test_true(worst[0] < worst[1], "Johnson: the error falls with the "
	    "range (%.4f p* at rho 0.1, %.4f at 0.2)", worst[0], worst[1]);
	rc_grid_free(g);
}

/* dgamma -> 0: a rough 64^2 surface at p* = 0.05; dgamma = 1e-9 (rho =
 * 0.01 L) changes p by at most dgamma / rho = 1e-7 locally: the same
 * contact set, the mean gap, approach and elastic energy within 1e-6
 * (measured 3e-8 periodic against FIRE, 7e-8 free against the CG on
 * pressures: there the heights on the padded grid of
 * solver_fire_adh_free.c against a second method on the same
 * compliance). */
static void
test_vanishing(enum rc_boundary bc)
{
	const char *name = bc == RC_BOUNDARY_FREE ? "free" : "periodic";
	rc_synth_params sp;
	rc_solver_opts o;
	rc_solve_result res;
	rc_err err;
	rc_grid *g;
	rc_solver *plain, *adh;
	size_t n = 64 * 64, same = 0;

	rc_synth_defaults(&sp);
	sp.nx = sp.ny = 64;
	sp.seed = 5;
	sp.rms_gradient = 1;
	g = rc_synth(&sp, &err);
	if (g == NULL) {
		fprintf(stderr, "%s\n", err.msg);
		exit(1);
	}
	g->periodic = bc == RC_BOUNDARY_PERIODIC;
	rc_solver_defaults(&o);
	o.tol = 1e-9;
	o.boundary = bc;
	if (bc == RC_BOUNDARY_FREE)
		o.method = RC_METHOD_CG;
	plain = rc_solver_new(g, &o, &err);
	adh = adhesive_bc(g, 1e-9, 0.01, 1e-9, bc);
	/* p = 0.05 E* gbar (gbar = 1) */
	test_int(rc_solver_solve(plain, 0.05, &res, &err), 0, "%s, dgamma -> "
	    "0: %s converges", name, rc_method_name(o.method));
	test_int(rc_solver_solve(adh, 0.05, &res, &err), 0, "%s, dgamma -> 0: "
	    "adhesive converges", name);
	for (size_t k = 0; k < n; k++)
		same += rc_solver_contact(plain)[k] == rc_solver_contact(adh)[k];
	test_int((long long)same, (long long)n, "%s, dgamma -> 0: the same "
	    "contact set", name);
	test_rel(rc_solver_mean_gap(adh), rc_solver_mean_gap(plain), 1e-6,
	    "%s, dgamma -> 0: mean gap", name);
	test_rel(rc_solver_approach(adh), rc_solver_approach(plain), 1e-6,
	    "%s, dgamma -> 0: approach", name);
	test_rel(rc_solver_elastic_energy(adh), rc_solver_elastic_energy(plain),
	    1e-6, "%s, dgamma -> 0: elastic energy", name);
	test_range(-rc_solver_adhesive_pressure(adh), 0, 1e-7, "%s, dgamma -> "
	    "0: p_adh", name);
	/* displacement control at the plain solve's approach gives its load
	 * back; the residual is scaled by the load there, not by the law's
	 * sigma_max = 1e-7 (which free boundaries once did: no convergence
	 * in max_iter) */
	{
		double delta = rc_solver_approach(plain), p = NAN;

		test_int(rc_solver_solve_approach(adh, delta, &p, &res, &err), 0,
		    "%s, dgamma -> 0: displacement control converges (%ld "
		    "iterations)", name, res.iterations);
		test_rel(p, 0.05, 1e-6, "%s, dgamma -> 0: displacement control "
		    "gives the load back", name);
	}
	rc_solver_free(plain);
	rc_solver_free(adh);
	rc_grid_free(g);
}

/* Hysteresis at the same load (the sphere's is in test_jkr).  Sine
 * (alpha 0.3, rho 0.1) under load control: Johnson's p(a) peaks at
 * 0.39 p* (psi = 1.2), so loading to 0.5 p* jumps to full contact, which
 * unloading keeps: at 0.2 p* the unloading a_r is 1, the loading one on
 * Johnson's stable branch (a within 2 pixels; measured 0.5). */
static void
test_hysteresis(void)
{
	const size_t nx = 256, ny = 4;
	const double A = 2, L = 256, dgamma = 0.00694, ps = M_PI * A / L;
	double load[5] = { 0.2, 0.5, 0.2, 0, -0.05 }, ar[5];
	rc_grid *g = sine(nx, ny, A);
	rc_solver *s = adhesive(g, dgamma, 0.1, 1e-8);
	rc_solve_result res;
	rc_err err;
	int status = 0;

	/* onto the loading branch from outside: displacement control to a
	 * partial contact, then load control */
	at_approach(s, -0.5, &status, NULL);
	at_approach(s, 1, &status, NULL);
	for (int i = 0; i < 5; i++) {
		if (rc_solver_solve(s, load[i] * ps, &res, &err) != 0)
			status = 1;
		ar[i] = (double)n_contact(s, nx * ny) / (double)(nx * ny);
	}
	test_int(status, 0, "hysteresis sine: every load converges");
	{
		/* the stable root of p(a) = 0.2 p* by bisection on [L/8, 0.38 L] */
		double lo = L / 8, hi = 0.38 * L;

		for (int it = 0; it < 60; it++) {
			double mid = 0.5 * (lo + hi);

			if (johnson(mid, L, A, dgamma) > 0.2 * ps)
				hi = mid;
			else
				lo = mid;
		}
		test_abs(ar[0] * L / 2, lo, 2, "hysteresis sine: loading a at "
		    "0.2 p* on Johnson's stable branch");
	}
	test_rel(ar[1], 1, 0, "hysteresis sine: full contact at 0.5 p*");
	test_rel(ar[2], 1, 0, "hysteresis sine: unloading keeps full contact "
	    "at 0.2 p*");
	test_true(ar[2] > ar[0], "hysteresis sine: a_r unloading %.3f > "
	    "loading %.3f at 0.2 p*", ar[2], ar[0]);
	test_rel(ar[4], 1, 0, "hysteresis sine: full contact holds at -0.05 "
	    "p* (tension below sigma_max - p*)");
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Free boundaries (solver_fire_adh_free.c): the sphere alone on its area,
 * no images.  Measured: DMT (96^2, as test_dmt's first case) pull-off
 * -1.9690 pi dgamma R against -1.9694 on test_dmt's 128^2 periodic cell;
 * JKR at mu 3 (R 54, l_adh = dx, 128^2) -1.5600 against -1.5634 on a
 * 256^2 periodic cell; its zero-load radius within 2% of JKR's.  The two
 * boundary kinds solve different bodies (an isolated sphere, a lattice of
 * them 2.4 or 4.7 contact diameters apart), so they agree only as far as
 * the images are weak: tolerance 0.005 (measured 0.0004) for DMT, whose
 * attraction is long-range, the limits' tolerances for the rest.  The
 * two controls meet: the load that displacement control found, applied
 * under load control, gives back the approach (the rigid level c =
 * <u> - F / (4N kappa_0) of solver_fire_adh_free.c) to the tolerance;
 * load control past pull-off separates, below it holds.  Hysteresis: the
 * JKR sphere loaded from approach -4 jumps into contact at -1.5, and
 * unloaded leaves it at -2.5 (measured). */
static void
test_free_sphere(double dmt_periodic)
{
	rc_solve_result res;
	rc_err e;
	rc_grid *g = sphere(96, 50);
	rc_solver *s;
	struct sweep w;
	double f, pc, p1, a0 = cbrt(9 * M_PI * 0.25 * 54 * 54 / 2), d_in = NAN;
	int st = 0;

	g->periodic = 0;
	s = adhesive_bc(g, 0.01, 2, 1e-8, RC_BOUNDARY_FREE);
	w = unload(s, 96, 0.3, 0.01);
	f = w.fmin / (M_PI * 0.01 * 50);
	test_int(w.status, 0, "free DMT: every solve converges");
	test_range(f, -2, -2 * (1 - 0.025), "free DMT mu 0.085: pull-off "
	    "F / (pi dgamma R) (-2 in the limit)");
	test_abs(f, dmt_periodic, 0.005, "free DMT: pull-off as on the "
	    "periodic cell");
	rc_solver_free(s);
	rc_grid_free(g);

	g = sphere(128, 54);
	g->periodic = 0;
	s = adhesive_bc(g, 0.25, 0.5, 1e-6, RC_BOUNDARY_FREE);
	/* loading from outside first: the jump into contact */
	for (double d = -4; d <= 3; d += 0.25) {
		at_approach(s, d, &st, NULL);
		if (n_contact(s, 128 * 128) > 0 && isnan(d_in))
			d_in = d;
	}
	w = unload(s, 128, 3, 0.25);
	test_true(w.d_out < d_in, "free hysteresis: contact from approach %g "
	    "loading, down to %g unloading", d_in, w.d_out);
	f = w.fmin / (M_PI * 0.25 * 54);
	test_int(w.status, 0, "free JKR: every solve converges");
	test_rel(f, -1.5, 0.06, "free JKR mu 3: pull-off F / (pi dgamma R)");
	test_abs(f, -1.5634, 0.01, "free JKR mu 3: pull-off as on the "
	    "periodic cell");
	test_rel(w.a0, a0, 0.04, "free JKR mu 3: contact radius at zero load");
	st = 0;
	p1 = at_approach(s, 1, &st, NULL);
	test_int(st, 0, "free: approach 1 converges");
	test_int(rc_solver_solve(s, p1, &res, &e), 0, "free: load control at "
	    "the pressure of approach 1 (%g) converges", p1);
	/* each solve's load is off by at most N tol sigma_max (the residual
	 * bounds the rms traction error), 8e-3 here, over the contact's
	 * stiffness 2 a E* >= 40: 2e-4 each, 4e-4 for the two (measured
	 * 1.8e-6) */
	test_abs(rc_solver_approach(s), 1, 4e-4, "free: load control at the "
	    "pressure of approach 1 gives it back");
	pc = M_PI * 0.25 * 54 / (128.0 * 128.0);
	st = rc_solver_solve(s, -1.4 * pc, &res, &e);
	test_true(st == 0 && !res.separated && n_contact(s, 128 * 128) > 0,
	    "free: load control at -1.4 pi dgamma R holds");
	st = rc_solver_solve(s, -1.7 * pc, &res, &e);
	test_true(st == 1 && res.separated, "free: load control at -1.7 pi "
	    "dgamma R separates (status %d, separated %d, %ld iterations)",
	    st, res.separated, res.iterations);
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Maugis' (1992) pull-off, F / (pi dgamma R), of a sphere under the
 * Dugdale law (tension sigma_0 up to the gap dgamma / sigma_0), as the
 * least load along his solution curve, parametrised by m = c / a (c the
 * edge of the cohesive zone, a of the contact; A = a (K / (pi dgamma
 * R^2))^(1/3), K = 4 E* / 3, lambda = 2 sigma_0 (R / (pi dgamma
 * K^2))^(1/3)):
 *   (lambda A^2 / 2) [s + (m^2 - 2) t] + (4 lambda^2 A / 3) [s t - m + 1] = 1,
 *   F / (pi dgamma R) = A^3 - lambda A^2 [s + m^2 t],
 * s = sqrt(m^2 - 1), t = atan s; the first is a quadratic in A (its
 * positive root).  The least load on a grid of 1e-4 in log(m - 1), from
 * m - 1 = 6e-6 to 400: -1.9983 at lambda 0.01, -1.5004 at 20 (the limits
 * -2 and -1.5). */
/* The point m of Maugis' curve: the load, A into *A. */
static double
maugis_load(double lambda, double m, double *A)
{
	double sq = sqrt(m * m - 1), t = atan(sq);
	double c2 = 0.5 * lambda * (sq + (m * m - 2) * t);
	double c1 = 4 * lambda * lambda / 3 * (sq * t - m + 1);

	*A = (-c1 + sqrt(c1 * c1 + 4 * c2)) / (2 * c2);
	return *A * *A * *A - lambda * *A * *A * (sq + m * m * t);
}

static double
maugis_pulloff_m(double lambda, double *m_at)
{
	double least = HUGE_VAL;

	for (double lm = -12; lm < 6; lm += 1e-4) {
		double A, m = 1 + exp(lm), f = maugis_load(lambda, m, &A);

		if (A > 0 && f < least) {
			least = f;
			if (m_at)
				*m_at = m;
		}
	}
	return least;
}

static double
maugis_pulloff(double lambda)
{
	return maugis_pulloff_m(lambda, NULL);
}

/* Maugis' contact radius at zero load, A = a (K / (pi dgamma
 * R^2))^(1/3), on the same grid in m (the largest A where F changes
 * sign: the stable branch). */
static double
maugis_zero_load_A(double lambda)
{
	double best = NAN, a_prev = NAN, f_prev = NAN;

	for (double lm = -12; lm < 6; lm += 1e-4) {
		double A, f = maugis_load(lambda, 1 + exp(lm), &A);

		if (f_prev * f <= 0 && !(A < best))
			best = a_prev + (A - a_prev) * f_prev / (f_prev - f);
		a_prev = A;
		f_prev = f;
	}
	return best;
}

/* The transition between the limits on free boundaries, against Maugis'
 * curve.  Maugis' curve is exact for the Dugdale law only; the
 * exponential law with the same strongest tension (sigma_0 = dgamma /
 * rho, so lambda = 1.127 mu) pulls off harder at intermediate mu.
 * Measured, with the grid's own error below 0.003 (mu 1 on 64^2 and
 * 128^2 at the same l_adh / dx ratio doubled: -1.6669, -1.6638): -1.854
 * against Maugis' -1.794 at mu 0.3, -1.776 against -1.695 at 0.5,
 * -1.667 against -1.585 at 1, -1.575 against -1.528 at 2; 3.1 to 5.0%
 * apart, so a tolerance of 7% (the shape of the law, not the solver); and
 * the pull-off must lie between the limits and move from DMT to JKR as
 * mu grows. */
static void
test_transition(void)
{
	/* mu 0.5: R 50, rho 1, 96^2; mu 1: R 50, rho 0.5, 64^2 */
	const double mu[2] = { 0.5, 1 }, rho[2] = { 1, 0.5 }, d0[2] = { 2, 2 };
	const size_t n[2] = { 96, 64 };
	double f[2];

	for (int i = 0; i < 2; i++) {
		double dg = sqrt(mu[i] * mu[i] * mu[i] * pow(rho[i], 3) / 50);
		rc_grid *g = sphere(n[i], 50);
		rc_solver *s;
		struct sweep w;

		g->periodic = 0;
		s = adhesive_bc(g, dg, rho[i], 1e-7, RC_BOUNDARY_FREE);
		w = unload(s, n[i], d0[i], 0.02);
		f[i] = w.fmin / (M_PI * dg * 50);
		test_int(w.status, 0, "transition mu %g: every solve converges",
		    mu[i]);
		test_range(f[i], -2, -1.5, "transition mu %g: pull-off between "
		    "DMT and JKR", mu[i]);
		test_rel(f[i], maugis_pulloff(1.127 * mu[i]), 0.07, "transition "
		    "mu %g: pull-off against Maugis' at lambda = 1.127 mu", mu[i]);
		rc_solver_free(s);
		rc_grid_free(g);
	}
	test_true(f[0] < f[1], "transition: from DMT towards JKR as mu grows "
	    "(%.4f at mu 0.5, %.4f at 1)", f[0], f[1]);
	test_rel(maugis_pulloff(0.01), -2, 0.001, "Maugis' curve: the DMT "
	    "limit");
	test_rel(maugis_pulloff(20), -1.5, 0.001, "Maugis' curve: the JKR "
	    "limit");
}

/* A sphere R = 50 s under the Dugdale law at Maugis' lambda, range s,
 * on a free 64 s grid (dx = 1): everything but dx scaled by s, unloaded
 * from approach 2 s in steps of step s. */
static struct sweep
dugdale_sphere(double lambda, double s, double step, double *dgamma)
{
	double R = 50 * s, rho = s, mu = lambda / cbrt(9 / (2 * M_PI));
	size_t n = (size_t)(64 * s);
	rc_grid *g = sphere(n, R);
	rc_solver *sv;
	struct sweep w;

	*dgamma = sqrt(mu * mu * mu * rho * rho * rho / R);
	g->periodic = 0;
	sv = adhesive_law(g, RC_ADHESION_DUGDALE, *dgamma, rho, 1e-7,
	    RC_BOUNDARY_FREE);
	w = unload(sv, n, 2 * s, step * s);
	w.fmin /= M_PI * *dgamma * R;
	rc_solver_free(sv);
	rc_grid_free(g);
	return w;
}

/* The Dugdale law against Maugis' curve, exact for it: free sphere,
 * lambda 0.3, 0.5, 1, 2, two grids (s = 1, 2: l_adh / dx doubled; l_adh
 * = 51.5, 23.9, 8.46, 2.99 dx on the coarse one).  FIRE converges at the
 * kink as anywhere: at most 40 to 62 iterations per solve at tol 1e-7
 * (the exponential law on the same sphere at lambda 1: 36).  Measured
 * pull-off / (pi dgamma R), coarse and fine, against Maugis':
 *   lambda 0.3  -1.8715 -1.8389  (-1.8156: +3.1%, +1.3%)
 *   lambda 0.5  -1.8006 -1.7570  (-1.7183: +4.8%, +2.3%)
 *   lambda 1    -1.7846 -1.6785  (-1.6007: +11.5%, +4.9%)
 *   lambda 2    -1.8683 -1.7100  (-1.5346: +21.7%, +11.4%)
 * (lambda 1 at s = 3 and 4: +2.2%, +1.65%).  The grid's error is first
 * order in dx / l_adh (0.4 to 1.1 times it), always a stronger pull-off:
 * a pixel at the zone's edge is bistable over a band of openings of its
 * own compliance times sigma_0 dx^2 ~ rho dx / l_adh (attached it opens
 * less, released more), so the zone lets go late, as if delta_c were
 * larger by about that band.  The error halves with dx, so the
 * extrapolation 2 F(dx/2) - F(dx) removes it: -1.8063, -1.7134, -1.5725,
 * -1.5516, within 1.8% of Maugis' (-0.5%, -0.3%, -1.8%, +1.1%);
 * tolerance 2.5%.  Approach steps of 0.02 s, but 0.005 s at lambda 0.3,
 * whose contact at pull-off is a few pixels across: the least force there
 * hangs on the last pixels' release, and steps of 0.02, 0.005, 0.00125
 * give -1.8538, -1.8715, -1.8799 (s = 1; at lambda 0.5 and 1 a step 4x
 * finer moves it by 0.0000 and 0.0044).  Each grid: pull-off between DMT and Maugis' (the
 * bias's sign); the error falls with dx; the extrapolation moves from
 * DMT to JKR as lambda grows.  The zone's extent m = c / a at pull-off
 * (c from the points attracted, a from those in contact), fine grid:
 * 2.475, 1.457, 1.149 against Maugis' 2.408, 1.472, 1.144 at lambda 0.5,
 * 1, 2 (2.8% at most; tolerance 4%); not at 0.3 (the few pixels).
 * The contact radius at zero load at lambda 1 (Maugis': A = 1.636,
 * a0 = A (pi dgamma R^2 / K)^(1/3)): 14.64 and 29.37 dx against 14.50
 * and 29.00 (+0.9%, +1.3%; one pixel is 6.9% and 3.4% of it);
 * tolerance 3%.
 * The DMT end, lambda 0.05 (s = 1, steps of 0.002): -1.9643 against
 * Maugis' -1.9814 (0.9%; tolerance 1.5%) and DMT's -2 (1.8%; 2.5%).
 * The JKR end of the Dugdale law would need l_adh of tens of dx at
 * lambda >> 1, i.e. R of thousands of dx: not run. */
static void
test_dugdale_transition(void)
{
	const double lambda[4] = { 0.3, 0.5, 1, 2 }, step[4] = { 0.005, 0.02,
	    0.02, 0.02 };
	double prev = -HUGE_VAL, dg;
	struct sweep w;

	for (int i = 0; i < 4; i++) {
		double m_theory = NAN, f[2], m[2], x;
		double fm = maugis_pulloff_m(lambda[i], &m_theory);
		long it = 0;
		int st = 0;

		for (int k = 0; k < 2; k++) {
			w = dugdale_sphere(lambda[i], 1 + k, step[i], &dg);

			f[k] = w.fmin;
			m[k] = w.m_min;
			if (lambda[i] == 1)
				test_rel(w.a0, maugis_zero_load_A(1) / cbrt(4.0 / 3 /
				    (M_PI * dg * 2500 * (1 + k) * (1 + k))), 0.03,
				    "Dugdale lambda 1, s = %d: contact radius at zero "
				    "load", 1 + k);
			st |= w.status;
			it = w.it_max > it ? w.it_max : it;
			test_range(f[k], -2, fm, "Dugdale lambda %g, l_adh %.3g dx: "
			    "pull-off %.4f between DMT and Maugis' %.4f (%+.2f%%)",
			    lambda[i], rc_adhesion_length(1, dg, 1 + k),
			    f[k], fm, 100 * (f[k] / fm - 1));
		}
		x = 2 * f[1] - f[0];
		test_int(st, 0, "Dugdale lambda %g: every solve converges (at "
		    "most %ld iterations)", lambda[i], it);
		test_true(f[1] > f[0], "Dugdale lambda %g: the error falls with "
		    "dx", lambda[i]);
		test_rel(x, fm, 0.025, "Dugdale lambda %g: pull-off extrapolated "
		    "to dx -> 0, %.4f, against Maugis' %.4f", lambda[i], x, fm);
		test_true(x > prev, "Dugdale: from DMT towards JKR (lambda %g)",
		    lambda[i]);
		prev = x;
		if (i > 0)
			test_rel(m[1], m_theory, 0.04, "Dugdale lambda %g: the "
			    "zone's extent m = c/a at pull-off (%.4f on the "
			    "coarse grid)", lambda[i], m[0]);
	}
	/* the DMT end: the action within approaches of 0.1, so steps of
	 * 0.002 */
	w = dugdale_sphere(0.05, 1, 0.002, &dg);
	test_int(w.status, 0, "Dugdale lambda 0.05: every solve converges");
	test_rel(w.fmin, -2, 0.025, "Dugdale lambda 0.05: pull-off near DMT's "
	    "-2");
	test_rel(w.fmin, maugis_pulloff(0.05), 0.015, "Dugdale lambda 0.05: "
	    "pull-off against Maugis'");
}

/* Warm start: solving the same approach again takes no iterations (the
 * state is already the solution); refusals. */
static void
test_warm_and_refusals(void)
{
	rc_grid *g = sphere(64, 20);
	rc_solver *s = adhesive(g, 0.1, 0.5, 1e-8);
	rc_solver_opts o;
	rc_err err;
	long it1, it2;

	at_approach(s, 1, NULL, &it1);
	at_approach(s, 1, NULL, &it2);
	test_true(it1 > 5 && it2 <= 1, "warm start: %ld iterations, then %ld "
	    "for the same approach", it1, it2);
	rc_solver_free(s);
	rc_solver_defaults(&o);
	o.adhesion = 0.1;
	o.range = 0.5;
	o.method = RC_METHOD_CG;
	test_true(rc_solver_new(g, &o, &err) == NULL && strstr(err.msg, "FIRE"),
	    "CG refused, naming FIRE: %s", err.msg);
	o.method = RC_METHOD_FIRE;
	o.range = 0;
	test_true(rc_solver_new(g, &o, &err) == NULL, "range 0 refused");
	rc_grid_free(g);
}

/* FIRE on a periodic layer of thickness d, poisson 0.3; dgamma 0: none. */
static rc_solver *
adhesive_layer(const rc_grid *g, enum rc_substrate sub, double d,
    double dgamma, double range, double tol)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
	o.thickness = d;
	o.substrate = sub;
	o.poisson = 0.3;
	o.adhesion = dgamma;
	o.range = range;
	o.tol = tol;
	return solver_or_exit(g, &o);
}

static size_t
n_same(const rc_solver *a, const rc_solver *b, size_t n)
{
	size_t same = 0;

	for (size_t k = 0; k < n; k++)
		same += rc_solver_contact(a)[k] == rc_solver_contact(b)[k];
	return same;
}

/* Displacement control at delta (at_approach); the worst |approach -
 * delta| kept in *dev. */
static double
layer_approach(rc_solver *s, double delta, int *status, long *iterations,
    double *dev)
{
	double p = at_approach(s, delta, status, iterations);

	*dev = fmax(*dev, fabs(rc_solver_approach(s) - delta));
	return p;
}

/* Sphere R 20 on a 64^2 cell, dgamma 0.05, rho 0.5 (l_adh = 5 dx), on a
 * layer d = 16, nu = 0.3 (k_0 = 0.077 E* per length), at p = 0.002 E*
 * (161 points in contact).  Displacement control starts cold (the flat
 * body at max h), so it finds the state on its own.  Measured at tol
 * 1e-10: p back to 3.3e-10 (bonded) and 3.5e-9 (slip) relative in 54
 * and 65 iterations, every contact point the same, |approach - delta|
 * 0.  Tolerances: p 1e-6 (that of test_adhesion.c's round trips; the
 * residual bounds the load balance, 1e-10 sigma_max here, and a wrong
 * spring or load sign moves p by its own order); approach 1e-12
 * absolute (delta ~ 1.4: the rounding of a mean of 4096 points). */
static void
test_layer_round_trip(enum rc_substrate sub)
{
	const char *name = rc_substrate_name(sub);
	rc_grid *g = sphere(64, 20);
	rc_solver *lc = adhesive_layer(g, sub, 16, 0.05, 0.5, 1e-10);
	rc_solver *dc = adhesive_layer(g, sub, 16, 0.05, 0.5, 1e-10);
	rc_solve_result res;
	rc_err err;
	double p0 = 0.002, delta, p, dev = 0;
	long it;
	int status = 0;

	test_int(rc_solver_solve(lc, p0, &res, &err), 0, "layer %s: load "
	    "control converges", name);
	delta = rc_solver_approach(lc);
	p = layer_approach(dc, delta, &status, &it, &dev);
	test_int(status, 0, "layer %s: displacement control converges (%ld "
	    "iterations)", name, it);
	test_rel(p, p0, 1e-6, "layer %s: displacement control gives the load "
	    "back", name);
	test_true(n_contact(lc, 64 * 64) > 20, "layer %s: a contact of %zu "
	    "points", name, n_contact(lc, 64 * 64));
	test_int((long long)n_same(lc, dc, 64 * 64), 64 * 64, "layer %s: the "
	    "same contact set", name);
	test_range(dev, 0, 1e-12, "layer %s: approach = delta", name);
	rc_solver_free(lc);
	rc_solver_free(dc);
	rc_grid_free(g);
}

/* dgamma -> 0 against the non-adhesive root find on a random surface
 * (the one of test_adhesion.c's test_vanishing) on a bonded layer d = 8,
 * at 1.05 times the approach of p = 0.05 E* gbar.  Measured: p to 9e-9
 * relative (63 iterations), every contact point the same; tolerance
 * 1e-6 as above (the law's sigma_max 1e-7 moves p by less). */
static void
test_layer_vanishing(void)
{
	rc_synth_params sp;
	rc_solve_result res;
	rc_err err;
	rc_grid *g;
	rc_solver *plain, *adh;
	double delta, pp = NAN, pa, dev = 0;
	long it;
	int status = 0;

	rc_synth_defaults(&sp);
	sp.nx = sp.ny = 64;
	sp.seed = 5;
	sp.rms_gradient = 1;
	if ((g = rc_synth(&sp, &err)) == NULL) {
		fprintf(stderr, "%s\n", err.msg);
		exit(1);
	}
	g->periodic = 1;
	plain = adhesive_layer(g, RC_SUBSTRATE_BONDED, 8, 0, 0, 1e-10);
	adh = adhesive_layer(g, RC_SUBSTRATE_BONDED, 8, 1e-9, 0.01, 1e-10);
	/* an approach from a load: p = 0.05 E* gbar */
	test_int(rc_solver_solve(plain, 0.05, &res, &err), 0, "layer, dgamma "
	    "-> 0: plain load control converges");
	delta = 1.05 * rc_solver_approach(plain);
	test_int(rc_solver_solve_approach(plain, delta, &pp, &res, &err), 0,
	    "layer, dgamma -> 0: the plain root find converges");
	pa = layer_approach(adh, delta, &status, &it, &dev);
	test_int(status, 0, "layer, dgamma -> 0: adhesive displacement control "
	    "converges (%ld iterations)", it);
	test_rel(pa, pp, 1e-6, "layer, dgamma -> 0: the same load");
	test_int((long long)n_same(plain, adh, 64 * 64), 64 * 64,
	    "layer, dgamma -> 0: the same contact set");
	test_range(dev, 0, 1e-12, "layer, dgamma -> 0: approach = delta");
	rc_solver_free(plain);
	rc_solver_free(adh);
	rc_grid_free(g);
}

/* Hysteresis: a JKR-like sphere (R 20, dgamma 0.25, rho 0.5: mu = 2.2,
 * l_adh = dx) on a bonded layer d = 16, approaches from -2 to 2 and back
 * to -4 in steps of 0.25.  Measured: into contact at -1.25 loading (57
 * points), contact kept to -1.5 unloading (21 points; 0 there loading);
 * the least load -0.00615 E* = -1.60 pi dgamma R (JKR -1.5; the layer
 * and l_adh = dx move it) at -0.5; load control from that state holds
 * 0.95 of it and separates at 1.05 of it (the jump FIRE sees with the
 * mean mode's mass of load control alone comes at -1.5 instead: the
 * check needs the k_0 floor, solver_fire_adh.c). */
static void
test_layer_hysteresis(void)
{
	rc_grid *g = sphere(64, 20);
	rc_solver *s = adhesive_layer(g, RC_SUBSTRATE_BONDED, 16, 0.25, 0.5,
	    1e-8);
	rc_solve_result res;
	rc_err err;
	double d, p, pmin = HUGE_VAL, dmin = NAN, dev = 0;
	double d_in = NAN, d_out = NAN;
	size_t on, on_prev = 0;
	int status = 0;

	for (d = -2; d <= 2; d += 0.25) {
		p = layer_approach(s, d, &status, NULL, &dev);
		on = n_contact(s, 64 * 64);
		if (on_prev == 0 && on > 0 && isnan(d_in))
			d_in = d;
		on_prev = on;
	}
	for (d = 2; d >= -4; d -= 0.25) {
		p = layer_approach(s, d, &status, NULL, &dev);
		on = n_contact(s, 64 * 64);
		if (on > 0)
			d_out = d;
		if (p < pmin) {
			pmin = p;
			dmin = d;
		}
	}
	test_int(status, 0, "layer hysteresis: every approach converges");
	test_range(dev, 0, 1e-12, "layer hysteresis: approach = delta");
	test_true(d_out < d_in, "layer hysteresis: contact kept unloading to "
	    "%g, made loading at %g", d_out, d_in);
	test_true(pmin < 0, "layer hysteresis: tension %g on unloading", pmin);
	/* load control: past the tension held it separates; warm-started
	 * from the unloading branch at the least load */
	layer_approach(s, dmin, &status, NULL, &dev);
	test_int(rc_solver_solve(s, 0.95 * pmin, &res, &err), 0, "layer "
	    "hysteresis: load control holds 0.95 p_min");
	test_true(!res.separated && n_contact(s, 64 * 64) > 0, "layer "
	    "hysteresis: in contact at 0.95 p_min (%zu points)",
	    n_contact(s, 64 * 64));
	layer_approach(s, dmin, &status, NULL, &dev);
	rc_solver_solve(s, 1.05 * pmin, &res, &err);
	test_true(res.separated, "layer hysteresis: load control at 1.05 p_min "
	    "separates");
	rc_solver_free(s);
	rc_grid_free(g);
}

int
main(void)
{
	test_law();
	test_dugdale_law();
	test_free_sphere(test_dmt());
	test_transition();
	test_dugdale_transition();
	test_jkr();
	test_johnson();
	test_vanishing(RC_BOUNDARY_PERIODIC);
	test_vanishing(RC_BOUNDARY_FREE);
	test_hysteresis();
	test_warm_and_refusals();
	test_layer_round_trip(RC_SUBSTRATE_BONDED);
	test_layer_round_trip(RC_SUBSTRATE_SLIP);
	test_layer_vanishing();
	test_layer_hysteresis();
	return test_summary();
}
