/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rough_cases.c - the shared rough surface and solver set-up
 * (rough_cases.h). */
#include "rough_cases.h"

#include <stdio.h>
#include <stdlib.h>

#include "synth.h"

rc_grid *
rc_test_rough(size_t n, double lambda_s, uint64_t seed)
{
	rc_synth_params sp;
	rc_err err;
	rc_grid *g;

	rc_synth_defaults(&sp);
	sp.nx = sp.ny = n;
	sp.lx = sp.ly = 1;
	sp.hurst = 0.8;
	sp.lambda_r = 0.5;
	sp.lambda_s = lambda_s;
	sp.seed = seed;
	sp.rms_gradient = 1;
	if ((g = rc_synth(&sp, &err)) == NULL) {
		fprintf(stderr, "synth: %s\n", err.msg);
		exit(1);
	}
	return g;
}

rc_solver *
rc_test_solver(const rc_grid *g, const rc_solver_opts *o)
{
	rc_solver *s;
	rc_err err;

	if ((s = rc_solver_new(g, o, &err)) == NULL) {
		fprintf(stderr, "solver_new: %s\n", err.msg);
		exit(1);
	}
	return s;
}

int
rc_test_solve(rc_solver *s, double p, rc_solve_result *r)
{
	rc_solve_result own;
	rc_err err;
	int st = rc_solver_solve(s, p, r != NULL ? r : &own, &err);

	if (st < 0)
		fprintf(stderr, "solve: %s\n", err.msg);
	return st;
}

size_t
rc_test_n_contact(const rc_solver *s, size_t n)
{
	const unsigned char *c = rc_solver_contact(s);
	size_t k, nc = 0;

	for (k = 0; k < n; k++)
		nc += c[k];
	return nc;
}
