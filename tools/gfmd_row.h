/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd_row.h - the result row of one gfmd-solve pressure, the same columns
 * in the serial tool and its MPI build (gfmd-solve(1), RESULT ROWS). */
#ifndef RC_GFMD_ROW_H
#define RC_GFMD_ROW_H

#include "contact.h"
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
	double p_adh, a_attr;		/* rc_solver_adhesive_pressure, ..._fraction */
	double l_adh_dx;		/* l_adh / dx (adhesion.h); 0: none */
	int separated;			/* rc_solve_result.separated */
	const rc_grid *indenter;	/* lx, ly and metadata */
	size_t nx, ny;			/* the whole grid */
};

/* Fill row (cleared first); 0, or -1 when out of memory. */
int gfmd_result_row(rc_row *row, const struct gfmd_row *in);
/* The reason (a static string) why kappa_c, written as nan, cannot be
 * computed for this row, or NULL when it is a number. */
const char *gfmd_kappa_c_why(const struct gfmd_row *in);

#endif
