/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_solver.c - the two contact solvers against exact solutions
 * (Westergaard, full contact of a cosine, egg-box, Hertz), against each
 * other, and their invariants. */
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "solver.h"
#include "synth.h"
#include "rough_cases.h"
#include "testlib.h"

static const enum rc_method methods[2] = { RC_METHOD_FIRE, RC_METHOD_CG };

static rc_solver *
make_solver_blocked(const rc_grid *g, enum rc_method m, double tol,
    size_t block_points)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
	o.method = m;
	o.tol = tol;
	o.fft_block_points = block_points;
	return rc_test_solver(g, &o);
}

static rc_solver *
make_solver(const rc_grid *g, enum rc_method m, double tol)
{
	return make_solver_blocked(g, m, tol, RC_FFT_BLOCKED_POINTS);
}

/* Westergaard: h = h0 cos(2 pi x / lambda) on nx x 1, lambda = L.  Exact:
 * p = p_fc sin^2(pi a_r / 2), p_fc = pi E* h0 / lambda.  The discrete
 * contact is a whole number of points, so a_r carries an error of order
 * dx / lambda = 1/nx; measured at most 1.3/nx.  Tolerance 2/nx; halving dx
 * must halve the largest error over the pressures (first order). */
static double
westergaard(enum rc_method m, size_t nx)
{
	rc_err err;
	rc_grid *g = rc_grid_new(nx, 1, 1.0, 1.0, &err);
	double h0 = 0.01, p_fc = M_PI * h0, worst = 0, f;
	rc_solver *s;
	size_t i;

	for (i = 0; i < nx; i++)
		g->z[i] = h0 * cos(2 * M_PI * (double)i / (double)nx);
	s = make_solver(g, m, 1e-8);
	for (f = 0.1; f < 0.95; f += 0.2) {
		rc_solve_result r;
		double ar, exact;

		test_int(rc_test_solve(s, f * p_fc, &r), 0, "westergaard %s nx %zu p/p_fc %.1f converges",
		    rc_method_name(m), nx, f);
		ar = (double)rc_test_n_contact(s, nx) / (double)nx;
		exact = 2 / M_PI * asin(sqrt(f));
		test_abs(ar, exact, 2.0 / (double)nx, "westergaard %s nx %zu p/p_fc %.1f a_r",
		    rc_method_name(m), nx, f);
		if (fabs(ar - exact) > worst)
			worst = fabs(ar - exact);
	}
	rc_solver_free(s);
	rc_grid_free(g);
	return worst;
}

/* Above p_fc the cosine is in full contact: u = h + const exactly and
 * sigma = p + k_q h0 cos(q x), k_q = pi E* / lambda (our sign: the pressure
 * is largest on the indenter's crests).  Tolerance: the solver's 1e-9
 * (rms, in units of p) times sqrt(nx) for a pointwise bound. */
static void
full_contact_cosine(enum rc_method m)
{
	size_t nx = 256, i;
	rc_err err;
	rc_grid *g = rc_grid_new(nx, 1, 1.0, 1.0, &err);
	double h0 = 0.01, kq = M_PI, p = 1.5 * M_PI * h0, worst = 0, gap0, gw = 0;
	rc_solver *s;
	rc_solve_result r;
	const double *sigma, *u;

	for (i = 0; i < nx; i++)
		g->z[i] = h0 * cos(2 * M_PI * (double)i / (double)nx);
	s = make_solver(g, m, 1e-9);
	test_int(rc_test_solve(s, p, &r), 0, "full contact cosine %s converges", rc_method_name(m));
	test_int((long long)rc_test_n_contact(s, nx), (long long)nx, "full contact cosine %s a_r = 1",
	    rc_method_name(m));
	sigma = rc_solver_pressure(s);
	u = rc_solver_displacement(s);
	gap0 = u[0] - g->z[0];
	for (i = 0; i < nx; i++) {
		double exact = p + kq * h0 * cos(2 * M_PI * (double)i / (double)nx);

		if (fabs(sigma[i] - exact) > worst)
			worst = fabs(sigma[i] - exact);
		if (fabs(u[i] - g->z[i] - gap0) > gw)
			gw = fabs(u[i] - g->z[i] - gap0);
	}
	test_abs(worst / p, 0, 1e-9 * sqrt((double)nx), "full contact cosine %s sigma exact",
	    rc_method_name(m));
	test_abs(gw, 0, 1e-12, "full contact cosine %s u = h + const", rc_method_name(m));
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Egg-box h = D (1 - cos kx cos ky), lambda = L: the mode has |q| =
 * sqrt(2) k on the grid exactly, so full contact holds exactly for
 * p >= p_fc = sqrt(2) pi E* D / lambda; 5% below, some points open. */
static void
eggbox(enum rc_method m)
{
	size_t n = 32, i, j;
	rc_err err;
	rc_grid *g = rc_grid_new(n, n, 1.0, 1.0, &err);
	double d = 0.01, p_fc = sqrt(2) * M_PI * d;
	rc_solver *s;
	rc_solve_result r;

	for (j = 0; j < n; j++)
		for (i = 0; i < n; i++)
			g->z[j * n + i] = d * (1 - cos(2 * M_PI * i / (double)n) *
			    cos(2 * M_PI * j / (double)n));
	s = make_solver(g, m, 1e-9);
	test_int(rc_test_solve(s, 1.02 * p_fc, &r), 0, "eggbox %s 1.02 p_fc converges", rc_method_name(m));
	test_int((long long)rc_test_n_contact(s, n * n), (long long)(n * n),
	    "eggbox %s full contact at 1.02 p_fc", rc_method_name(m));
	test_int(rc_test_solve(s, 0.95 * p_fc, &r), 0, "eggbox %s 0.95 p_fc converges", rc_method_name(m));
	test_range((double)rc_test_n_contact(s, n * n), 1, (double)(n * n - 1),
	    "eggbox %s partial contact at 0.95 p_fc", rc_method_name(m));
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Hertz: h = -r^2/(2R), r to the nearest periodic image of the centre,
 * load F = p L^2.  a = (3 F R / (4 E*))^(1/3) = 8 dx here; the discrete
 * radius sqrt(n_c dA / pi) must be within 1 dx (contact edge resolved to a
 * grid spacing; the periodic images shift a by O((a/L)^3), negligible). */
static void
hertz(enum rc_method m)
{
	size_t n = 128, i, j;
	rc_err err;
	rc_grid *g = rc_grid_new(n, n, 1.0, 1.0, &err);
	double dx = 1.0 / (double)n, R = 1, a = 8 * dx, F = 4 * a * a * a / (3 * R);
	rc_solver *s;
	rc_solve_result r;
	double a_num;

	for (j = 0; j < n; j++)
		for (i = 0; i < n; i++) {
			double x = fabs((double)i - n / 2.0) * dx, y = fabs((double)j - n / 2.0) * dx;

			x = fmin(x, 1 - x);
			y = fmin(y, 1 - y);
			g->z[j * n + i] = -(x * x + y * y) / (2 * R);
		}
	s = make_solver(g, m, 1e-8);
	test_int(rc_test_solve(s, F, &r), 0, "hertz %s converges", rc_method_name(m));
	a_num = sqrt((double)rc_test_n_contact(s, n * n) * dx * dx / M_PI);
	test_abs(a_num, a, dx, "hertz %s contact radius", rc_method_name(m));
	rc_solver_free(s);
	rc_grid_free(g);
}

/* Invariants of a solution: load, tension, penetration, pressure off
 * contact; all to the tolerance the solver was given (rms in units of p),
 * exact where the method makes them exact. */
static void
invariants(const rc_solver *s, const rc_grid *g, double p, double tol, const char *what)
{
	const double *sigma = rc_solver_pressure(s), *u = rc_solver_displacement(s);
	const unsigned char *c = rc_solver_contact(s);
	size_t k, n = g->nx * g->ny, neg = 0, pen = 0, off = 0;
	double sum = 0;

	for (k = 0; k < n; k++) {
		sum += sigma[k];
		neg += sigma[k] < 0;
		pen += u[k] < g->z[k];
		off += !c[k] && sigma[k] != 0;
	}
	test_rel(sum / (double)n, p, tol, "%s: mean pressure = load", what);
	test_int((long long)neg, 0, "%s: no tension", what);
	test_int((long long)pen, 0, "%s: no penetration", what);
	test_int((long long)off, 0, "%s: no pressure off contact", what);
}

/* FIRE and CG on one random surface: the same contact set (up to points
 * whose pressure is at the tolerance, none seen), pressures and heights
 * to a small multiple of the tolerance. */
static void
methods_agree(void)
{
	size_t n = 64, k, nn = n * n, diff = 0;
	rc_grid *g = rc_test_rough(n, 1.0 / 16, 7);
	double p = 0.05, tol = 1e-9, d2 = 0, s2 = 0, du = 0, urange = 0;
	rc_solver *s[2];
	rc_solve_result r;
	int m;

	for (m = 0; m < 2; m++) {
		s[m] = make_solver(g, methods[m], tol);
		test_int(rc_test_solve(s[m], p, &r), 0, "random %s converges", rc_method_name(methods[m]));
		invariants(s[m], g, p, tol, rc_method_name(methods[m]));
	}
	for (k = 0; k < nn; k++) {
		const double *a = rc_solver_pressure(s[0]), *b = rc_solver_pressure(s[1]);
		const double *ua = rc_solver_displacement(s[0]), *ub = rc_solver_displacement(s[1]);

		diff += rc_solver_contact(s[0])[k] != rc_solver_contact(s[1])[k];
		d2 += (a[k] - b[k]) * (a[k] - b[k]);
		s2 += b[k] * b[k];
		if (fabs(ua[k] - ub[k]) > du)
			du = fabs(ua[k] - ub[k]);
		if (fabs(ub[k] - g->z[k]) > urange)
			urange = fabs(ub[k] - g->z[k]);
	}
	test_int((long long)diff, 0, "FIRE and CG contact sets agree");
	test_abs(sqrt(d2 / s2), 0, 100 * tol, "FIRE and CG pressures agree (relative L2)");
	test_abs(du / urange, 0, 100 * tol, "FIRE and CG heights agree (relative to max gap)");
	test_rel(rc_solver_elastic_energy(s[0]), rc_solver_elastic_energy(s[1]), 100 * tol,
	    "FIRE and CG elastic energy agree");
	rc_solver_free(s[0]);
	rc_solver_free(s[1]);
	rc_grid_free(g);
}

/* 1 and 2 threads: the same contact set and pressures to the tolerance
 * (reductions are summed in a different order, so FIRE's step decisions
 * may differ at round-off; the converged states then differ by at most
 * the tolerance, not by round-off). */
static void
threads(enum rc_method m)
{
	size_t n = 64, k, nn = n * n, diff = 0;
	rc_grid *g = rc_test_rough(n, 1.0 / 16, 3);
	double p = 0.05, tol = 1e-9, d2 = 0, s2 = 0;
	const double *a, *b;
	rc_solver *s[2];
	rc_solve_result r;
	int t;

	for (t = 0; t < 2; t++) {
		rc_fft_set_threads(t + 1);
		s[t] = make_solver(g, m, tol);
		rc_test_solve(s[t], p, &r);
	}
	a = rc_solver_pressure(s[0]);
	b = rc_solver_pressure(s[1]);
	for (k = 0; k < nn; k++) {
		diff += rc_solver_contact(s[0])[k] != rc_solver_contact(s[1])[k];
		d2 += (a[k] - b[k]) * (a[k] - b[k]);
		s2 += b[k] * b[k];
	}
	test_int((long long)diff, 0, "%s: 1 and 2 threads same contact", rc_method_name(m));
	test_abs(sqrt(d2 / s2), 0, 100 * tol, "%s: 1 and 2 threads same pressure",
	    rc_method_name(m));
	rc_solver_free(s[0]);
	rc_solver_free(s[1]);
	rc_grid_free(g);
}

/* A warm-started sweep of increasing pressure gives non-decreasing a_r
 * (exact physics: contact area grows monotonically with load for
 * frictionless non-adhesive contact), and a restart from the displacement
 * reproduces the contact set. */
static void
sweep(enum rc_method m)
{
	size_t n = 64, nn = n * n, prev = 0, nc;
	rc_grid *g = rc_test_rough(n, 1.0 / 16, 11);
	rc_solver *s = make_solver(g, m, 1e-8), *t;
	rc_solve_result r;
	rc_err err;
	double p;
	int mono = 1, conv = 1;

	for (p = 0.01; p < 0.5; p *= 1.5) {
		conv &= rc_test_solve(s, p, &r) == 0;
		nc = rc_test_n_contact(s, nn);
		mono &= nc >= prev;
		prev = nc;
	}
	test_true(conv, "%s: sweep converges", rc_method_name(m));
	test_true(mono, "%s: warm-started sweep has monotone a_r", rc_method_name(m));
	t = make_solver(g, m, 1e-8);
	rc_solver_set_displacement(t, rc_solver_displacement(s), &err);
	p /= 1.5;
	test_int(rc_test_solve(t, p, &r), 0, "%s: restart from displacement converges", rc_method_name(m));
	test_int((long long)rc_test_n_contact(t, nn), (long long)prev, "%s: restart reproduces n_c",
	    rc_method_name(m));
	rc_solver_free(s);
	rc_solver_free(t);
	rc_grid_free(g);
}

/* FIRE-GFMD's masses m_q ~ k_q give every free mode the same frequency,
 * so its iteration count at tol 1e-6 must stay small and grow slowly with
 * the grid.  The same surface (lambda_s = L/16 is resolved on both grids)
 * at 64^2 and 256^2: measured 29 and 39 iterations (the uniform-mass
 * dynamics this replaced: 211 and 290).  Bounds: at most 1.6x from 64^2
 * to 256^2 (sqrt of the 4x in n would be 2x) and at most 80 iterations at
 * 256^2, which the uniform mass misses by 3.6x.  Counted transforms, not
 * time: an iteration costs two pairs (plus one for the last residual and
 * one for the pressure), and FIRE needs fewer pairs than CG at 256^2
 * (measured 80 against 93). */
static void
fire_scaling(void)
{
	size_t sizes[2] = { 64, 256 };
	long iters[2] = { 0, 0 };
	double pairs[2] = { 0, 0 };
	int z, m;

	for (z = 0; z < 2; z++) {
		rc_grid *g = rc_test_rough(sizes[z], 1.0 / 16, 5);

		for (m = 0; m < 2; m++) {
			rc_solver *s = make_solver(g, methods[m], 1e-6);
			rc_solve_result r;

			test_int(rc_test_solve(s, 0.05, &r), 0, "scaling %s %zu^2 converges",
			    rc_method_name(methods[m]), sizes[z]);
			if (methods[m] == RC_METHOD_FIRE) {
				iters[z] = r.iterations;
				test_abs(r.fft_pairs, 2.0 * (double)r.iterations + 2, 0,
				    "FIRE %zu^2: two FFT pairs per iteration", sizes[z]);
			}
			pairs[m] = r.fft_pairs;
			rc_solver_free(s);
		}
		rc_grid_free(g);
	}
	test_range((double)iters[1], 1, 80, "FIRE iterations at 256^2 (%ld)", iters[1]);
	test_range((double)iters[1], 1, 1.6 * (double)iters[0],
	    "FIRE iterations 64^2 -> 256^2 grow slowly (%ld -> %ld)", iters[0], iters[1]);
	test_true(pairs[0] < pairs[1], "FIRE needs fewer FFT pairs than CG at 256^2"
	    " (%.0f against %.0f)", pairs[0], pairs[1]);
}

/* The blocked transforms, with FIRE's passes run block by block between
 * the row transforms (solver_fire_loop.c), against the plain ones on a
 * non-square grid with tail blocks both ways: the same iterations and
 * contact set, heights and pressures to rounding (1e-10 of their range:
 * the arithmetic is the same point by point, only the transforms' and
 * the sums' rounding differs, and 40 steps amplify that little). */
static void
blocked_agrees(void)
{
	rc_synth_params sp;
	rc_err err;
	rc_grid *g;
	int m;

	rc_synth_defaults(&sp);
	sp.nx = 132;
	sp.ny = 90;
	sp.lx = 1;
	sp.ly = 90.0 / 132;
	sp.hurst = 0.8;
	sp.lambda_r = 0.3;
	sp.lambda_s = 1.0 / 20;
	sp.seed = 11;
	sp.rms_gradient = 1;
	if ((g = rc_synth(&sp, &err)) == NULL) {
		fprintf(stderr, "synth: %s\n", err.msg);
		exit(1);
	}
	for (m = 0; m < 2; m++) {
		rc_solver *a = make_solver_blocked(g, methods[m], 1e-8, SIZE_MAX);
		rc_solver *b = make_solver_blocked(g, methods[m], 1e-8, 0);
		rc_solve_result ra, rb;
		size_t k, n = g->nx * g->ny, diff = 0;
		double du = 0, ds = 0, urange = 0, smax = 0;

		test_int(rc_test_solve(a, 0.05, &ra), 0, "plain %s converges", rc_method_name(methods[m]));
		test_int(rc_test_solve(b, 0.05, &rb), 0, "blocked %s converges", rc_method_name(methods[m]));
		test_int(rb.iterations, ra.iterations, "blocked %s: the same iterations",
		    rc_method_name(methods[m]));
		for (k = 0; k < n; k++) {
			diff += rc_solver_contact(a)[k] != rc_solver_contact(b)[k];
			du = fmax(du, fabs(rc_solver_displacement(a)[k] -
			    rc_solver_displacement(b)[k]));
			ds = fmax(ds, fabs(rc_solver_pressure(a)[k] -
			    rc_solver_pressure(b)[k]));
			urange = fmax(urange, fabs(rc_solver_displacement(a)[k]));
			smax = fmax(smax, rc_solver_pressure(a)[k]);
		}
		test_int((long long)diff, 0, "blocked %s: the same contact set",
		    rc_method_name(methods[m]));
		test_abs(du / urange, 0, 1e-10, "blocked %s: the same heights",
		    rc_method_name(methods[m]));
		test_abs(ds / smax, 0, 1e-10, "blocked %s: the same pressures",
		    rc_method_name(methods[m]));
		rc_solver_free(a);
		rc_solver_free(b);
	}
	rc_grid_free(g);
}

/* FIRE's contact set after a solve, converged or stopped by --max-iter,
 * on the plain and the blocked path: the force pass's C, 0 or 1 (the
 * update's mark ON_WALL, solver_fire.c, never left behind), every point
 * of C on the indenter (u == h exactly) under a positive pressure, and
 * the same set as the one the solution's pressures imply (sigma > 0). */
/* After a converged FIRE solve: the same pressure again starts from the
 * solution, so the start must mark the points on the wall (u == h) for
 * the first force pass (solver_fire.c): then the start's residual is the
 * solution's and no iteration is taken; unmarked, those points would
 * count as free and the residual be that of their whole pressure.  Then
 * warm starts at a higher and a lower pressure converge. */
static void
fire_warm_start(rc_solver *s, const rc_grid *g, int path)
{
	rc_solve_result r;
	rc_err err;
	const double p[] = { 0.2, 0.01 };
	size_t k, n = g->nx * g->ny, bad;
	int i;

	test_int(rc_solver_solve(s, 0.05, &r, &err), 0, "fire warm %s: again "
	    "at the same pressure: converged", path ? "blocked" : "plain");
	test_int(r.iterations, 0, "fire warm %s: again at the same pressure: "
	    "iterations", path ? "blocked" : "plain");
	for (i = 0; i < 2; i++) {
		const unsigned char *c;
		const double *u, *sigma;

		test_int(rc_solver_solve(s, p[i], &r, &err), 0, "fire warm %s: "
		    "p %g: converged", path ? "blocked" : "plain", p[i]);
		c = rc_solver_contact(s);
		u = rc_solver_displacement(s);
		sigma = rc_solver_pressure(s);
		for (k = 0, bad = 0; k < n; k++)
			bad += c[k] > 1 || (c[k] && !(u[k] == g->z[k] &&
			    sigma[k] > 0)) || (c[k] != 0) != (sigma[k] > 0);
		test_int((long long)bad, 0, "fire warm %s: p %g: contact set",
		    path ? "blocked" : "plain", p[i]);
	}
}

static void
fire_contact_is_c(void)
{
	rc_grid *g = rc_test_rough(96, 1.0 / 16, 3);
	size_t n = g->nx * g->ny;
	static const int max_iters[] = { 5, 100000 };	/* stopped, converged */
	int path, i, max_iter;

	for (path = 0; path < 2; path++)
		for (i = 0; i < 2; i++) {
			rc_solver_opts o;
			rc_solver *s;
			size_t k, bad = 0, off = 0, cs = 0;
			const unsigned char *c;
			const double *u, *sigma;
			int st;

			rc_solver_defaults(&o);
			o.method = RC_METHOD_FIRE;
			o.max_iter = max_iter = max_iters[i];
			o.fft_block_points = path ? 0 : SIZE_MAX;
			s = rc_test_solver(g, &o);
			st = rc_test_solve(s, 0.05, NULL);
			test_int(st, max_iter == 5 ? 1 : 0, "fire contact %s max_iter %d: "
			    "status", path ? "blocked" : "plain", max_iter);
			c = rc_solver_contact(s);
			u = rc_solver_displacement(s);
			sigma = rc_solver_pressure(s);
			for (k = 0; k < n; k++) {
				bad += c[k] > 1;
				off += c[k] && !(u[k] == g->z[k] && sigma[k] > 0);
				cs += c[k] != (sigma[k] > 0);
			}
			test_int((long long)bad, 0, "fire contact %s max_iter %d: 0 or 1",
			    path ? "blocked" : "plain", max_iter);
			test_int((long long)off, 0, "fire contact %s max_iter %d: on the "
			    "indenter, pressed", path ? "blocked" : "plain", max_iter);
			test_int((long long)cs, 0, "fire contact %s max_iter %d: sigma > 0 "
			    "exactly there", path ? "blocked" : "plain", max_iter);
			test_true(rc_test_n_contact(s, n) > 0, "fire contact %s max_iter "
			    "%d: some contact", path ? "blocked" : "plain", max_iter);
			if (max_iter != 5)
				fire_warm_start(s, g, path);
			rc_solver_free(s);
		}
	rc_grid_free(g);
}

int
main(void)
{
	int m;

	rc_fft_set_threads(1);	/* tiny grids: threads cost more than they give */
	for (m = 0; m < 2; m++) {
		double e512 = westergaard(methods[m], 512);
		double e2048 = westergaard(methods[m], 2048);

		test_true(e2048 < 0.5 * e512, "westergaard %s first order: error %.2e at nx 512,"
		    " %.2e at 2048", rc_method_name(methods[m]), e512, e2048);
		full_contact_cosine(methods[m]);
		eggbox(methods[m]);
		hertz(methods[m]);
		threads(methods[m]);
		rc_fft_set_threads(1);
		sweep(methods[m]);
	}
	methods_agree();
	blocked_agrees();
	rc_fft_set_threads(2);	/* the blocks shared by threads */
	blocked_agrees();
	rc_fft_set_threads(1);
	fire_scaling();
	fire_contact_is_c();
	return test_summary();
}
