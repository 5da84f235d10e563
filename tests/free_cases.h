/* SPDX-License-Identifier: GPL-3.0-or-later */
/* free_cases.h - the closed-form problems of free boundaries, solved and
 * measured: Hertz and the flat punch (Boussinesq).  Shared by
 * tests/test_free.c (small grids, asserted) and bench/bench_free.c (up to
 * 1024^2, printed).
 *
 * Units: E* = 1.  Hertz: h = -r^2/(2R), R = 1, on an l x l cell, loaded
 * with F = 4 a^3 / (3R) for a = 1/4, so that, exactly,
 *   delta = a^2/R,  p0 = 3F/(2 pi a^2),  sigma = p0 sqrt(1 - r^2/a^2).
 * The peak sits on the pixel (n/2, n/2).  The punch: a rigid cylinder of
 * radius 1/4 centred there on a 1 x 1 cell (h = 0 on r <= 1/4, far below
 * outside) pressed by delta = 1e-3 under displacement control: F = 2 a E* delta,
 * a the radius of the pixel disc, sqrt(n_disc dx^2 / pi). */
#ifndef FREE_CASES_H
#define FREE_CASES_H

#include "rc_err.h"
#include "solver.h"

#define FC_HZ_A		0.25
#define FC_HZ_F		(4 * FC_HZ_A * FC_HZ_A * FC_HZ_A / 3)
#define FC_HZ_P0	(3 * FC_HZ_F / (2 * M_PI * FC_HZ_A * FC_HZ_A))
#define FC_PUNCH_A	0.25	/* the nominal radius; a is the pixel disc's */
#define FC_PUNCH_DELTA	1e-3

struct fc_run {
	long iterations;
	double pairs;		/* transform pairs of the solve */
	double seconds;		/* wall time of the solve (not the setup) */
	double bytes;		/* rc_solver_bytes per grid point */
};

/* Relative errors of delta and the peak pressure, the rms of the pressure
 * error over the Hertz disc in units of p0, and the absolute error of the
 * contact radius sqrt(n_c dx^2 / pi); dx the pixel. */
struct fc_hertz {
	double delta, p0, profile, a, dx;
	struct fc_run run;
};

/* F / (2 a E* delta) - 1; the approach reached, relative to delta, minus
 * 1; the rms relative error of the pressure F / (2 pi a sqrt(a^2 - r^2))
 * for r < a/2 (the edge singularity is not resolved by pixels). */
struct fc_punch {
	double force, approach, profile;
	struct fc_run run;
};

/* Each returns as rc_solver_solve: 0 converged, 1 not (the errors are
 * still measured), -1 on an error (message in err). */
int fc_hertz(size_t n, double l, enum rc_boundary b, enum rc_method m,
    double tol, struct fc_hertz *e, rc_err *err);
int fc_punch(size_t n, enum rc_method m, double tol, struct fc_punch *e,
    rc_err *err);

#endif
