/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rough_cases.h - the rough test surface and the solver set-up the solver
 * tests (test_solver.c, test_plastic.c, test_layer.c) and
 * bench/bench_gfmd.c share.  Failures end the program after a message:
 * they are set-up, not the thing tested. */
#ifndef ROUGH_CASES_H
#define ROUGH_CASES_H

#include <stddef.h>
#include <stdint.h>

#include "grid.h"
#include "solver.h"

/* A self-affine rc_synth surface on an n x n unit cell: H = 0.8,
 * lambda_r = 0.5, lambda_s as given (0: rc_synth's default, two grid
 * spacings), rms gradient 1, the seed as given. */
rc_grid *rc_test_rough(size_t n, double lambda_s, uint64_t seed);
/* rc_solver_new of o. */
rc_solver *rc_test_solver(const rc_grid *g, const rc_solver_opts *o);
/* rc_solver_solve, its message on stderr when it fails (r may be NULL). */
int rc_test_solve(rc_solver *s, double p, rc_solve_result *r);
/* Points in the solver's contact set among its n. */
size_t rc_test_n_contact(const rc_solver *s, size_t n);

#endif
