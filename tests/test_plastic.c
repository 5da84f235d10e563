/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_plastic.c - perfect plasticity (opts.hardness, solver_cg_plastic.c):
 * the bound, load balance and complementarity; the full-plasticity limit
 * a_r = p/H; H -> infinity against the elastic CG; a flat punch that
 * flows entirely at the load H A; FIRE refused. */
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
make(const rc_grid *g, enum rc_boundary b, double hardness)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
	o.method = RC_METHOD_CG;
	o.boundary = b;
	o.tol = TOL;
	o.hardness = hardness;
	return rc_test_solver(g, &o);
}

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
 * and H/10; tolerance 0.01). */
static void
full_plasticity(void)
{
	rc_grid *g = rc_test_rough(64, 1.0 / 16, 3);
	size_t n = 64 * 64;
	double H = 0.01, f[] = { 0.5, 0.1 };
	rc_solver *s = make(g, RC_BOUNDARY_PERIODIC, H);

	for (int i = 0; i < 2; i++) {
		double p = f[i] * H, ar, ap;

		test_int(rc_test_solve(s, p, NULL), 0, "full plasticity p/H %g converges", f[i]);
		ar = fraction(s, n);
		ap = rc_solver_plastic_fraction(s);
		test_true(ap <= f[i] && f[i] <= ar, "full plasticity: a_plastic "
		    "%.6f <= p/H %g <= a_r %.6f", ap, f[i], ar);
		test_abs(ar, f[i], 0.01, "full plasticity: a_r = p/H");
		invariants(s, g, p, H, "full plasticity");
	}
	rc_solver_free(s);
	rc_grid_free(g);
}

/* H -> infinity: H = 1e6 p never binds, so the solution is the elastic
 * one: the same contact set and pressures within the tolerance (both
 * solves to 1e-9 in the residual; rms difference / p below 1e-6). */
static void
elastic_limit(enum rc_boundary b)
{
	rc_grid *g = rc_test_rough(32, 1.0 / 16, 5);
	size_t n = 32 * 32, k, diff = 0;
	double p = 0.05, d2 = 0;
	rc_solver *el = make(g, b, 0), *pl = make(g, b, 1e6 * p);
	const char *bn = rc_boundary_name(b);

	test_int(rc_test_solve(el, p, NULL), 0, "%s elastic converges", bn);
	test_int(rc_test_solve(pl, p, NULL), 0, "%s H = 1e6 p converges", bn);
	for (k = 0; k < n; k++) {
		double d = rc_solver_pressure(el)[k] - rc_solver_pressure(pl)[k];

		d2 += d * d;
		diff += rc_solver_contact(el)[k] != rc_solver_contact(pl)[k];
	}
	test_int((long long)diff, 0, "%s H = 1e6 p: same contact set", bn);
	test_true(sqrt(d2 / (double)n) / p < 1e-6, "%s H = 1e6 p: rms pressure "
	    "difference %.2g p < 1e-6 p", bn, sqrt(d2 / (double)n) / p);
	test_abs(rc_solver_plastic_fraction(pl), 0, 0, "%s H = 1e6 p: no plastic "
	    "point", bn);
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
flat_punch(void)
{
	size_t n = 32, k, m = 0, centre = (n / 2) * n + n / 2;
	rc_err err;
	rc_grid *g = rc_grid_new(n, n, 1.0, 1.0, &err);
	double H = 1, p_lim, ap;
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
	s = make(g, RC_BOUNDARY_FREE, H);
	test_int(rc_test_solve(s, 0.5 * p_lim, NULL), 0, "punch p_lim/2 converges");
	ap = rc_solver_plastic_fraction(s);
	test_true(ap > 0 && ap < 0.5 * (double)m / (double)(n * n),
	    "punch p_lim/2: the rim flows (a_plastic %.4f), not the face", ap);
	test_true(rc_solver_pressure(s)[centre] < H, "punch p_lim/2: centre "
	    "elastic (sigma %.3f < H)", rc_solver_pressure(s)[centre]);
	invariants(s, g, 0.5 * p_lim, H, "punch p_lim/2");
	test_int(rc_test_solve(s, p_lim, NULL), 0, "punch p_lim converges");
	for (k = 0; k < n * n; k++)
		if (g->z[k] == 0 && !(rc_solver_pressure(s)[k] >= H * (1 - 1e-12)))
			break;
	test_int((long long)k, (long long)(n * n), "punch p_lim: every face "
	    "point at H");
	invariants(s, g, p_lim, H, "punch p_lim");
	rc_solver_free(s);
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
	s = rc_solver_new(g, &o, &err);
	test_true(s == NULL && strstr(err.msg, "cg") != NULL,
	    "FIRE with a hardness refused, naming cg: %s", err.msg);
	rc_solver_free(s);
	o.method = RC_METHOD_CG;
	o.hardness = -1;
	s = rc_solver_new(g, &o, &err);
	test_true(s == NULL, "negative hardness refused");
	rc_solver_free(s);
	o.hardness = 0.1;
	s = rc_solver_new(g, &o, &err);
	{
		rc_solve_result r;

		test_int(rc_solver_solve(s, 0.2, &r, &err), -1,
		    "p > H refused: %s", err.msg);
	}
	rc_solver_free(s);
	rc_grid_free(g);
}

int
main(void)
{
	full_plasticity();
	elastic_limit(RC_BOUNDARY_PERIODIC);
	elastic_limit(RC_BOUNDARY_FREE);
	flat_punch();
	refusals();
	return test_summary();
}
