/* SPDX-License-Identifier: GPL-3.0-or-later */
/* free_cases.c - Hertz and the flat punch on free boundaries, measured
 * against their closed forms (free_cases.h). */
#include <math.h>
#include <stddef.h>

#include "free_cases.h"

/* Squared distance of point k of an n x n grid of pixel dx from the
 * pixel (n/2, n/2). */
static double
r2(size_t n, double dx, size_t k)
{
	double x = ((double)(k % n) - (double)(n / 2)) * dx;
	double y = ((double)(k / n) - (double)(n / 2)) * dx;

	return x * x + y * y;
}

/* A solver of g (which it copies; g is freed here either way). */
static rc_solver *
solver(rc_grid *g, enum rc_boundary b, enum rc_method m, double tol,
    rc_err *err)
{
	rc_solver_opts o;
	rc_solver *s;

	rc_solver_defaults(&o);
	o.method = m;
	o.boundary = b;
	o.tol = tol;
	s = rc_solver_new(g, &o, err);
	rc_grid_free(g);
	return s;
}

static void
run_of(const rc_solver *s, const rc_solve_result *r, size_t nn,
    struct fc_run *run)
{
	run->iterations = r->iterations;
	run->pairs = r->fft_pairs;
	run->seconds = r->seconds;
	run->bytes = (double)rc_solver_bytes(s) / (double)nn;
}

int
fc_hertz(size_t n, double l, enum rc_boundary b, enum rc_method m,
    double tol, struct fc_hertz *e, rc_err *err)
{
	size_t nn = n * n, k, nc = 0;
	double dx = l / (double)n, top = 0, sum2 = 0, nd = 0;
	const double *sigma;
	const unsigned char *c;
	rc_solve_result r;
	rc_solver *s;
	rc_grid *g;
	int st;

	if ((g = rc_grid_new(n, n, l, l, err)) == NULL)
		return -1;
	for (k = 0; k < nn; k++)
		g->z[k] = -r2(n, dx, k) / 2;
	if ((s = solver(g, b, m, tol, err)) == NULL)
		return -1;
	if ((st = rc_solver_solve(s, FC_HZ_F / (l * l), &r, err)) < 0) {
		rc_solver_free(s);
		return -1;
	}
	sigma = rc_solver_pressure(s);
	c = rc_solver_contact(s);
	for (k = 0; k < nn; k++) {
		double rr = r2(n, dx, k) / (FC_HZ_A * FC_HZ_A);

		if (sigma[k] > top)
			top = sigma[k];
		nc += c[k];
		if (rr < 1) {
			double diff = sigma[k] - FC_HZ_P0 * sqrt(1 - rr);

			sum2 += diff * diff;
			nd++;
		}
	}
	e->delta = rc_solver_approach(s) / (FC_HZ_A * FC_HZ_A) - 1;
	e->p0 = top / FC_HZ_P0 - 1;
	e->profile = sqrt(sum2 / nd) / FC_HZ_P0;
	e->a = sqrt((double)nc * dx * dx / M_PI) - FC_HZ_A;
	e->dx = dx;
	run_of(s, &r, nn, &e->run);
	rc_solver_free(s);
	return st;
}

int
fc_punch(size_t n, enum rc_method m, double tol, struct fc_punch *e,
    rc_err *err)
{
	size_t nn = n * n, k, disc = 0;
	double dx = 1.0 / (double)n, delta = FC_PUNCH_DELTA, p, a, sum2 = 0;
	double nd = 0;
	const double *sigma;
	rc_solve_result r;
	rc_solver *s;
	rc_grid *g;
	int st;

	if ((g = rc_grid_new(n, n, 1, 1, err)) == NULL)
		return -1;
	for (k = 0; k < nn; k++) {
		int in = r2(n, dx, k) <= FC_PUNCH_A * FC_PUNCH_A;

		g->z[k] = in ? 0 : -1;
		disc += (size_t)in;
	}
	a = sqrt((double)disc * dx * dx / M_PI);
	if ((s = solver(g, RC_BOUNDARY_FREE, m, tol, err)) == NULL)
		return -1;
	if ((st = rc_solver_solve_approach(s, delta, &p, &r, err)) < 0) {
		rc_solver_free(s);
		return -1;
	}
	/* Cell area 1: the mean pressure p is the load F. */
	sigma = rc_solver_pressure(s);
	for (k = 0; k < nn; k++) {
		double rr = r2(n, dx, k);

		if (rr < a * a / 4) {
			double rel = sigma[k] * 2 * M_PI * a * sqrt(a * a - rr) / p - 1;

			sum2 += rel * rel;
			nd++;
		}
	}
	e->force = p / (2 * a * delta) - 1;
	e->approach = rc_solver_approach(s) / delta - 1;
	e->profile = sqrt(sum2 / nd);
	run_of(s, &r, nn, &e->run);
	rc_solver_free(s);
	return st;
}
