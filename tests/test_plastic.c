/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_plastic.c - perfect plasticity (opts.hardness; the CG of
 * solver_cg.c and FIRE on pressures of solver_fire_free.c, both on the
 * cap of solver_hardness.c): the
 * bound, load balance and complementarity; FIRE against the CG on the
 * same maps; the full-plasticity limit a_r = p/H; H -> infinity against
 * the elastic solvers; a flat punch that flows entirely at the load H A;
 * displacement control giving back the load; the refusals. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solver.h"
#include "synth.h"
#include "rough_cases.h"
#include "testlib.h"

#define TOL	1e-9

static rc_solver *
make(const rc_grid *g, enum rc_method m, enum rc_boundary b, double hardness)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
	o.method = m;
	o.boundary = b;
	o.tol = TOL;
	o.hardness = hardness;
	return rc_test_solver(g, &o);
}

static const enum rc_method methods[] = { RC_METHOD_CG, RC_METHOD_FIRE };
static const enum rc_boundary bounds[] = { RC_BOUNDARY_PERIODIC,
    RC_BOUNDARY_FREE };

static double
fraction(const rc_solver *s, size_t n)
{
	return (double)rc_test_n_contact(s, n) / (double)n;
}

/* The bound is exact (the projection writes H), the mean is p to the
 * tolerance (the load restoration makes it exact to round-off), the gap
 * of the admissible u' is >= 0 off the plastic set and <= 0 on it
 * (exactly, by construction of u'), and zero where 0 < sigma < H. */
static void
invariants(const rc_solver *s, const rc_grid *g, double p, double H,
    const char *what)
{
	const double *sg = rc_solver_pressure(s), *u = rc_solver_displacement(s);
	size_t k, n = g->nx * g->ny, bad_gap = 0;
	double max = 0, min = 0, sum = 0;

	for (k = 0; k < n; k++) {
		double gap = u[k] - g->z[k];

		if (sg[k] > max)
			max = sg[k];
		if (sg[k] < min)
			min = sg[k];
		sum += sg[k];
		if (sg[k] >= H ? gap > 0 : sg[k] > 0 ? gap != 0 : gap < 0)
			bad_gap++;
	}
	test_true(max <= H * (1 + 1e-12), "%s: max sigma %.17g <= H %g", what,
	    max, H);
	test_true(min >= 0, "%s: sigma >= 0", what);
	test_rel(sum / (double)n, p, 1e-12, "%s: mean sigma = p", what);
	test_int((long long)bad_gap, 0, "%s: complementarity of u'", what);
}

/* Full plasticity: with H small, almost every loaded point is at H and
 * a_plastic <= p/H <= a_r holds exactly (each plastic point carries H,
 * the rest of the load sits on points below H); the band between them is
 * the few elastic points at the edges (measured 0.0010 on 64^2, p = H/2
 * and H/10, both methods; tolerance 0.01). */
static void
full_plasticity(enum rc_method m)
{
	rc_grid *g = rc_test_rough(64, 1.0 / 16, 3);
	size_t n = 64 * 64;
	double H = 0.01, f[] = { 0.5, 0.1 };
	rc_solver *s = make(g, m, RC_BOUNDARY_PERIODIC, H);
	const char *mn = rc_method_name(m);

	for (int i = 0; i < 2; i++) {
		double p = f[i] * H, ar, ap;

		test_int(rc_test_solve(s, p, NULL), 0, "%s full plasticity p/H "
		    "%g converges", mn, f[i]);
		ar = fraction(s, n);
		ap = rc_solver_plastic_fraction(s);
		test_true(ap <= f[i] && f[i] <= ar, "%s full plasticity: "
		    "a_plastic %.6f <= p/H %g <= a_r %.6f", mn, ap, f[i], ar);
		test_abs(ar, f[i], 0.01, "%s full plasticity: a_r = p/H", mn);
		invariants(s, g, p, H, "full plasticity");
	}
	rc_solver_free(s);
	rc_grid_free(g);
}

/* The rms and largest pressure differences of two solvers, in units of
 * p, and the points where their contact sets and plastic sets differ. */
static void
compare(const rc_solver *a, const rc_solver *b, size_t n, double p,
    double H, double *rms, double *max, size_t *d_contact, size_t *d_plastic)
{
	const double *sa = rc_solver_pressure(a), *sb = rc_solver_pressure(b);
	double d2 = 0;

	*max = 0;
	*d_contact = *d_plastic = 0;
	for (size_t k = 0; k < n; k++) {
		double d = fabs(sa[k] - sb[k]);

		d2 += d * d;
		if (d > *max)
			*max = d;
		*d_contact += rc_solver_contact(a)[k] != rc_solver_contact(b)[k];
		*d_plastic += (sa[k] >= H) != (sb[k] >= H);
	}
	*rms = sqrt(d2 / (double)n) / p;
	*max /= p;
}

/* FIRE against the CG on the same 64^2 self-affine map, both to
 * tol 1e-9: H = 4 p (a quarter of the cell plastic) and full plasticity
 * (H = 0.01, p = H/2).  The solution is unique (a strictly convex
 * problem), so the two must agree: the same contact and plastic sets
 * (a point whose pressure is within the tolerance of 0 or H could fall
 * either way; none did: measured 0 differing points on all four cases),
 * pressures within 1e-6 p rms and 1e-5 p at any point (measured rms
 * 2.5e-10 .. 3.4e-10 p, max 6.5e-9 .. 1.6e-8 p: the residual tol 1e-9
 * bounds an rms pressure error in units of p; the margins are three
 * decades, for other FFT plans and thread counts). */
static void
fire_vs_cg(enum rc_boundary b, double H, double p)
{
	rc_grid *g = rc_test_rough(64, 1.0 / 16, 3);
	size_t n = 64 * 64, dc, dp;
	rc_solver *cg = make(g, RC_METHOD_CG, b, H);
	rc_solver *fi = make(g, RC_METHOD_FIRE, b, H);
	const char *bn = rc_boundary_name(b);
	double rms, max;

	test_int(rc_test_solve(cg, p, NULL), 0, "%s H = %g p: CG converges",
	    bn, H / p);
	test_int(rc_test_solve(fi, p, NULL), 0, "%s H = %g p: FIRE "
	    "converges", bn, H / p);
	compare(cg, fi, n, p, H, &rms, &max, &dc, &dp);
	test_int((long long)dc, 0, "%s H = %g p: FIRE and CG contact sets",
	    bn, H / p);
	test_int((long long)dp, 0, "%s H = %g p: FIRE and CG plastic sets",
	    bn, H / p);
	test_true(rms < 1e-6 && max < 1e-5, "%s H = %g p: FIRE - CG "
	    "pressure rms %.2g p < 1e-6 p, max %.2g p < 1e-5 p", bn, H / p,
	    rms, max);
	invariants(fi, g, p, H, "FIRE");
	rc_solver_free(cg);
	rc_solver_free(fi);
	rc_grid_free(g);
}

/* H -> infinity: H = 1e6 p never binds, so the solution is the elastic
 * one of the same method (FIRE periodic: solver_fire.c, on heights): the
 * same contact set and pressures within the tolerance (both solves to
 * 1e-9 in the residual; rms difference / p below 1e-6). */
static void
elastic_limit(enum rc_method m, enum rc_boundary b)
{
	rc_grid *g = rc_test_rough(32, 1.0 / 16, 5);
	size_t n = 32 * 32, dc, dp;
	double p = 0.05, rms, max;
	rc_solver *el = make(g, m, b, 0), *pl = make(g, m, b, 1e6 * p);
	const char *bn = rc_boundary_name(b), *mn = rc_method_name(m);

	test_int(rc_test_solve(el, p, NULL), 0, "%s %s elastic converges", mn,
	    bn);
	test_int(rc_test_solve(pl, p, NULL), 0, "%s %s H = 1e6 p converges",
	    mn, bn);
	compare(el, pl, n, p, 1e6 * p, &rms, &max, &dc, &dp);
	test_int((long long)dc, 0, "%s %s H = 1e6 p: same contact set", mn, bn);
	test_true(rms < 1e-6, "%s %s H = 1e6 p: rms pressure difference %.2g p "
	    "< 1e-6 p", mn, bn, rms);
	test_abs(rc_solver_plastic_fraction(pl), 0, 0, "%s %s H = 1e6 p: no "
	    "plastic point", mn, bn);
	rc_solver_free(el);
	rc_solver_free(pl);
	rc_grid_free(g);
}

/* A flat-ended cylindrical punch (free boundaries): the elastic pressure
 * is singular at the rim, so the rim flows first; the whole face is at H
 * at the limit load H A (A = the m points of the face times dx dy), the
 * mean pressure over the grid p_lim = H m / N.  Below it (p = p_lim / 2)
 * the rim is plastic and the centre is not (elastic centre pressure: half
 * the mean over the face, Boussinesq). */
static void
flat_punch(enum rc_method meth)
{
	size_t n = 32, k, m = 0, centre = (n / 2) * n + n / 2;
	rc_err err;
	rc_grid *g = rc_grid_new(n, n, 1.0, 1.0, &err);
	double H = 1, p_lim, ap;
	const char *mn = rc_method_name(meth);
	rc_solver *s;

	for (size_t j = 0; j < n; j++)
		for (size_t i = 0; i < n; i++) {
			double x = ((double)i + 0.5) / (double)n - 0.5;
			double y = ((double)j + 0.5) / (double)n - 0.5;
			int in = x * x + y * y < 0.2 * 0.2;

			g->z[j * n + i] = in ? 0 : -1;
			m += in;
		}
	p_lim = H * (double)m / (double)(n * n);
	s = make(g, meth, RC_BOUNDARY_FREE, H);
	test_int(rc_test_solve(s, 0.5 * p_lim, NULL), 0, "%s punch p_lim/2 "
	    "converges", mn);
	ap = rc_solver_plastic_fraction(s);
	test_true(ap > 0 && ap < 0.5 * (double)m / (double)(n * n),
	    "%s punch p_lim/2: the rim flows (a_plastic %.4f), not the face",
	    mn, ap);
	test_true(rc_solver_pressure(s)[centre] < H, "%s punch p_lim/2: centre "
	    "elastic (sigma %.3f < H)", mn, rc_solver_pressure(s)[centre]);
	invariants(s, g, 0.5 * p_lim, H, "punch p_lim/2");
	test_int(rc_test_solve(s, p_lim, NULL), 0, "%s punch p_lim converges",
	    mn);
	for (k = 0; k < n * n; k++)
		if (g->z[k] == 0 && !(rc_solver_pressure(s)[k] >= H * (1 - 1e-12)))
			break;
	test_int((long long)k, (long long)(n * n), "%s punch p_lim: every face "
	    "point at H", mn);
	invariants(s, g, p_lim, H, "punch p_lim");
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Displacement control: the approach D a load p = 0.05 (H = 4 p)
 * produces under load control gives p back under rc_solver_solve_approach
 * on a fresh solver: |approach - D| <= tol D (the root find's stop) and p
 * within 1e-6 relative (d ln p / d ln D is about 2 here, so the root
 * find's 1e-9 allows ~2e-9; measured 1e-13 .. 1e-12).  An approach past
 * the one reached as p -> H is refused, naming the hardness. */
static void
approach_roundtrip(enum rc_method m, enum rc_boundary b)
{
	rc_grid *g = rc_test_rough(64, 1.0 / 16, 3);
	double p = 0.05, H = 4 * p, d, q;
	rc_solver *s = make(g, m, b, H), *t = make(g, m, b, H);
	const char *bn = rc_boundary_name(b), *mn = rc_method_name(m);
	rc_solve_result r;
	rc_err err;

	test_int(rc_test_solve(s, p, NULL), 0, "%s %s approach: load "
	    "control converges", mn, bn);
	d = rc_solver_approach(s);
	test_int(rc_solver_solve_approach(t, d, &q, &r, &err), 0, "%s %s "
	    "--approach %g converges", mn, bn, d);
	test_true(fabs(rc_solver_approach(t) - d) <= TOL * d, "%s %s approach "
	    "%.17g = D %.17g to tol D", mn, bn, rc_solver_approach(t), d);
	test_rel(q, p, 1e-6, "%s %s approach: the load back", mn, bn);
	invariants(t, g, q, H, "approach");
	test_int(rc_solver_solve_approach(t, 100 * d, &q, &r, &err), -1,
	    "%s %s approach 100 D refused: %s", mn, bn, err.msg);
	test_true(strstr(err.msg, "hardness") != NULL, "%s %s approach 100 D: "
	    "the message names the hardness", mn, bn);
	rc_solver_free(s);
	rc_solver_free(t);
	rc_grid_free(g);
}

static void
refusals(void)
{
	rc_grid *g = rc_test_rough(32, 1.0 / 16, 1);
	rc_solver_opts o;
	rc_err err;
	rc_solver *s;

	rc_solver_defaults(&o);
	o.hardness = 1;
	o.adhesion = 0.01;
	o.range = 0.01;
	s = rc_solver_new(g, &o, &err);
	test_true(s == NULL && strstr(err.msg, "hardness") != NULL,
	    "adhesion with a hardness refused: %s", err.msg);
	rc_solver_free(s);
	o.adhesion = 0;
	o.method = RC_METHOD_CG;
	o.hardness = -1;
	s = rc_solver_new(g, &o, &err);
	test_true(s == NULL, "negative hardness refused");
	rc_solver_free(s);
	o.hardness = 0.1;
	for (int i = 0; i < 2; i++) {
		rc_solve_result r;

		o.method = methods[i];
		s = rc_solver_new(g, &o, &err);
		test_int(rc_solver_solve(s, 0.2, &r, &err), -1,
		    "%s p > H refused: %s", rc_method_name(o.method), err.msg);
		rc_solver_free(s);
	}
	rc_grid_free(g);
}

int
main(void)
{
	for (int b = 0; b < 2; b++) {
		fire_vs_cg(bounds[b], 0.2, 0.05);
		fire_vs_cg(bounds[b], 0.01, 0.005);
	}
	for (int m = 0; m < 2; m++) {
		full_plasticity(methods[m]);
		for (int b = 0; b < 2; b++) {
			elastic_limit(methods[m], bounds[b]);
			approach_roundtrip(methods[m], bounds[b]);
		}
		flat_punch(methods[m]);
	}
	refusals();
	return test_summary();
}
