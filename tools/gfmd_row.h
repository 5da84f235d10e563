/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd_row.h - the result row of one gfmd-solve pressure, the same columns
 * in the serial tool and its MPI build (gfmd-solve(1), RESULT ROWS), and
 * the steps of their pressure loop that both share. */
#ifndef RC_GFMD_ROW_H
#define RC_GFMD_ROW_H

#include <stdio.h>

#include "common.h"
#include "contact.h"
#include "gfmd_opts.h"
#include "grid.h"
#include "solver.h"
#include "table_write.h"

struct gfmd_row {
	double p_star, p, gbar;
	const rc_contact_stats *stats;
	double a_subpixel;		/* rc_contact_subpixel; NaN: none */
	double mean_gap, elastic_energy;
	long iterations;
	double residual, tol;		/* reached, and asked for */
	double seconds, plan_seconds;
	const char *method;
	const char *boundary;		/* "periodic" or "free" */
	const char *kernel;		/* "continuum" or "pixel"; NULL: continuum */
	double approach;		/* rc_solver_approach */
	double hardness;		/* the cap on sigma; 0: none */
	double a_plastic;		/* rc_solver_plastic_fraction */
	double thickness;		/* the layer's; 0: a half space */
	enum rc_substrate substrate;	/* RC_SUBSTRATE_NONE: a half space */
	double poisson;			/* the layer's; 0 for a half space */
	double adhesion, range;		/* the adhesive law's; 0: none */
	const char *law;		/* its name (adhesion.h); "none" */
	double p_adh, a_attr;		/* rc_solver_adhesive_pressure, ..._fraction */
	double l_adh_dx;		/* l_adh / dx (adhesion.h); 0: none */
	int separated;			/* rc_solve_result.separated */
	long stalled;			/* rc_solve_result.stalled: the
					 * window (opts.stall_window); 0 */
	const rc_grid *indenter;	/* lx, ly and metadata */
	size_t nx, ny;			/* the whole grid */
};

/* Fill row (cleared first); 0, or -1 when out of memory. */
int gfmd_result_row(rc_row *row, const struct gfmd_row *in);
/* The reason (a static string) why kappa_c, written as nan, cannot be
 * computed for this row, or NULL when it is a number. */
const char *gfmd_kappa_c_why(const struct gfmd_row *in);

/* p and p* of pressure k of the options for an indenter of rms gradient
 * gbar: p NaN under --approach (the solve finds it); a requested p*
 * echoed exactly (p/(E* gbar) rounds). */
void gfmd_pressure(const struct gfmd_opts *o, size_t k, double gbar,
    double *p, double *p_star);
/* A pressure done: the row of in into row, written to table and flushed
 * when fp is not NULL (the process that writes the table), with the
 * warnings on a nan kappa_c, on a body that separated (in->separated)
 * and else on a solve that did not converge (converged 0; counted in
 * *nunconverged).  0; -1: out of memory; -2: the
 * table could not be written (err: why). */
#define GFMD_ROW_NOMEM	(-1)
#define GFMD_ROW_WRITE	(-2)
int gfmd_emit_row(const struct tool *t, const struct gfmd_row *in,
    int converged, rc_row *row, rc_table_out *table, FILE *fp,
    size_t *nunconverged, rc_err *err);

#endif
