/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_opts.c - the contact solver's options: their defaults, names
 * and what they switch on (adhesion, a hardness).
 *
 * Default tolerance: measured on a 256^2 rc_synth surface (H = 0.8,
 * lambda_r = L/2, lambda_s = L/64, gbar = 1, seed 1, p = 0.05 E* gbar,
 * a_r = 0.1093, 7163 contact points) against a reference solve at tol
 * 1e-13 (FIRE, 93 iterations; CG's floor from round-off is ~2e-11):
 *   tol     FIRE iterations, |a_r - ref|/ref    CG iterations, same
 *   1e-3     23   1.4e-4 (one point)             52   0
 *   1e-4     29   0                              59   0
 *   1e-6     43   0                              73   0
 *   1e-9     65   0                              94   0
 * (FIRE iterations cost two FFT pairs, CG's one or two: solver_fire_loop.c,
 * solver_cg.c.)
 * The default 1e-6 leaves a margin of two decades over the first
 * tolerance at which every contact point is right.
 */
#include "solver.h"

#include <math.h>
#include <string.h>

void
rc_solver_defaults(rc_solver_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->method = RC_METHOD_FIRE;
	o->modulus = 1;
	o->tol = 1e-6;
	o->max_iter = 100000;
	o->stall_window = RC_STALL_WINDOW;
	o->fft_effort = RC_FFT_ESTIMATE;
	o->fft_block_points = RC_FFT_BLOCKED_POINTS;
}

const char *
rc_method_name(enum rc_method m)
{
	switch (m) {
	case RC_METHOD_FIRE:
		return "fire";
	case RC_METHOD_CG:
		return "cg";
	}
	return "unknown";
}

const char *
rc_boundary_name(enum rc_boundary b)
{
	return b == RC_BOUNDARY_FREE ? "free" : "periodic";
}

int
rc_boundary_parse(const char *name)
{
	if (strcmp(name, "periodic") == 0)
		return RC_BOUNDARY_PERIODIC;
	if (strcmp(name, "free") == 0)
		return RC_BOUNDARY_FREE;
	return -1;
}

int
rc_method_parse(const char *name)
{
	if (strcmp(name, "fire") == 0)
		return RC_METHOD_FIRE;
	if (strcmp(name, "cg") == 0)
		return RC_METHOD_CG;
	return -1;
}

int
rc_solver_opts_adhesive(const rc_solver_opts *o)
{
	return o->adhesion > 0;
}

int
rc_solver_opts_plastic(const rc_solver_opts *o)
{
	return o->hardness > 0 && isfinite(o->hardness);
}
