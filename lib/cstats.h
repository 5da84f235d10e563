/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cstats.h - what contact-stats computes: result rows of many gfmd-solve
 * runs grouped by surface, taken to the continuum limit (Richardson in
 * eps_c = da/lambda_s), averaged over seeds, optionally extrapolated in
 * eps_f = lambda_s/lambda_r and eps_t = lambda_r/lx, and turned into
 * kappa and kappa_c with errors (Wang & Mueser 2020, sections 4.1, 4.2;
 * the rules are in contact-stats(1)).
 */
#ifndef RC_CSTATS_H
#define RC_CSTATS_H

#include <stdio.h>
#include "extrap.h"
#include "rc_err.h"
#include "table_read.h"
#include "table_write.h"

/* Eq. 23: the alpha the paper suggests for Eq. 22. */
#define RC_YASTREBOV_ALPHA_011 0.11

/* Convergence of the input rows: a row whose residual exceeds the
 * tolerance it was solved to (its tol column) comes from an unconverged
 * solve and is refused unless allow_unconverged.  Rows written before the
 * tol column existed are held to this residual instead: ten times looser
 * than anything gfmd-solve's accuracy table needs (1e-3 moved a_r by one
 * contact point there).  Rows without a residual are taken as they are. */
#define RC_CSTATS_RESIDUAL_NO_TOL 1e-3

/* The floor of a surface's extrapolation error (contact-stats(1), "Error
 * bars"): a_r_err = sqrt(err^2 + floor^2), err the extrapolation's own
 * estimate (rc_fit.err) and
 *   floor = RC_CSTATS_FLOOR_C sqrt(sum_i w_i^2 n_cl_i / n_tot_i^2),
 * the counting noise (rc_count_noise) of the estimate sum_i w_i a_i
 * (w_i its weights).  It keeps the bar from vanishing where the pair
 * difference does by chance.  The constant was calibrated so that
 * a_r +- a_r_err covers 68% of 96 surfaces (seeds 5001-5016, 6001-6016,
 * H 0.8, p* 0.1-0.025, eps_c 1/4-1/16; 0.136) and covered 66.7%, 64.6%,
 * 66.7% +- 6.8% at p* 0.1, 0.05, 0.025 of 48 surfaces never used for it
 * (7001-7048): bench/accuracy/coverage.sh. */
#define RC_CSTATS_FLOOR_C 0.14

typedef struct rc_cstats_opts {
	const char *const *group_by;	/* key columns instead of all carried */
	size_t ngroup_by;
	int have_group_by;
	const char *const *ignore;	/* columns removed from the keys */
	size_t nignore;
	rc_extrap_opts cont;	/* model in eps_c */
	rc_extrap_opts frac;	/* model in eps_f (one exponent or auto) */
	rc_extrap_opts therm;	/* model in eps_t (one exponent or auto) */
	double alpha;		/* alpha of a_yastrebov (Eq. 22) */
	int no_extrapolate;	/* finest raw value per surface */
	int per_seed;		/* no ensemble average */
	int fractal, thermo;	/* take these limits */
	int lenient;		/* skip bad rows and groups, counted */
	int allow_unconverged;	/* use rows whose residual exceeds their
				 * tolerance (with a warning) */
} rc_cstats_opts;

/* Defaults: linear models, finest fit, alpha = RC_YASTREBOV_ALPHA. */
void rc_cstats_opts_default(rc_cstats_opts *o);

enum rc_cstats_warn_kind {
	RC_CSTATS_WARN_MISSING,	/* an optional input column is missing */
	RC_CSTATS_WARN_CLAMPED,	/* an extrapolated a_r left [0, 1] */
	RC_CSTATS_WARN_UNCONVERGED	/* rows used by allow_unconverged */
};

typedef struct rc_cstats_point {
	size_t curve;		/* index into label */
	double p_star, kappa, kappa_err;
} rc_cstats_point;

typedef struct rc_cstats {
	size_t nrows;
	rc_row *row;		/* output rows: curves in order of their first
				 * input row, p_star increasing within each */
	rc_cstats_point *point;	/* per output row, for plots */
	size_t ncurves;
	char **label;		/* per curve: the keys that differ between curves */
	size_t nwarn;
	char **warn;		/* messages for the user, in order */
	unsigned char *warn_kind;
	size_t nskipped;	/* rows and groups skipped by --lenient (the
				 * reader's included) */
	char first_skip[RC_ERRLEN];	/* why the first one was */
} rc_cstats;

/* Everything from the rows to the output rows.  On bad data: -1 and one
 * message, the first problem and how many more ("(and N more problems)");
 * with o->lenient bad rows and groups are skipped and counted instead.
 * res is empty on failure; free it with rc_cstats_free either way. */
int rc_cstats_run(const rc_rowset *rs, const rc_cstats_opts *o, rc_cstats *res,
    rc_err *err);
void rc_cstats_free(rc_cstats *res);

/* The method column, e.g. "richardson(1)+ensemble+fractal(1)". */
void rc_cstats_method(const rc_cstats_opts *o, char *buf, size_t len);

/* A gnuplot script (data inline) that plots kappa against p* with error
 * bars, one curve per group, to the PNG png (NULL: gnuplot's standard
 * output); script is the script's own name, for its comment.  png must
 * not hold control characters (quotes are escaped). */
int rc_cstats_gnuplot(FILE *fp, const rc_cstats *res, const char *script,
    const char *png, rc_err *err);

/* The script written atomically to path ("-": standard output); it plots
 * to path with .png for its extension (kappa.png for standard output). */
int rc_cstats_gnuplot_write(const rc_cstats *res, const char *path,
    rc_err *err);

/* The PNG itself, written atomically to path ("-": standard output), by
 * running gnuplot (found in PATH) on the same script.  Fails with "gnuplot
 * not found; ..." when there is none, or when gnuplot fails. */
int rc_cstats_png_write(const rc_cstats *res, const char *path, rc_err *err);

#endif
