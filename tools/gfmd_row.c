/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd_row.c - gfmd-solve's result row (see gfmd_row.h). */
#include "gfmd_row.h"

#include <errno.h>
#include <math.h>
#include <string.h>

int
gfmd_result_row(rc_row *row, const struct gfmd_row *in)
{
	const rc_contact_stats *st = in->stats;

	rc_row_clear(row);
	if (rc_row_num(row, "p_star", in->p_star) ||
	    rc_row_num(row, "p", in->p) ||
	    rc_row_num(row, "approach", in->approach) ||
	    rc_row_num(row, "a_r", st->a_r) ||
	    rc_row_num(row, "hardness", in->hardness) ||
	    rc_row_num(row, "a_plastic", in->a_plastic) ||
	    rc_row_num(row, "thickness", in->thickness) ||
	    rc_row_str(row, "substrate", rc_substrate_name(in->substrate)) ||
	    rc_row_num(row, "poisson", in->substrate == RC_SUBSTRATE_NONE ? 0 :
	    in->poisson) ||
	    rc_row_num(row, "adhesion", in->adhesion) ||
	    rc_row_num(row, "range", in->range) ||
	    rc_row_str(row, "law", in->law ? in->law : "none") ||
	    rc_row_num(row, "p_adh", in->p_adh) ||
	    rc_row_num(row, "a_attr", in->a_attr) ||
	    rc_row_num(row, "l_adh_dx", in->l_adh_dx) ||
	    rc_row_int(row, "separated", in->separated) ||
	    rc_row_int(row, "n_c", (long long)st->n_c) ||
	    rc_row_int(row, "n_cl", (long long)st->n_cl) ||
	    rc_row_int(row, "n_tot", (long long)st->n_tot) ||
	    rc_row_num(row, "a_yastrebov", st->a_yastrebov) ||
	    rc_row_num(row, "a_subpixel", in->a_subpixel) ||
	    rc_row_num(row, "gbar", in->gbar) ||
	    rc_row_num(row, "gbar_c", st->gbar_c) ||
	    rc_row_num(row, "gbar_c_prime", st->gbar_c_prime) ||
	    rc_row_num(row, "kappa", st->kappa) ||
	    rc_row_num(row, "kappa_c", st->kappa_c) ||
	    rc_row_num(row, "mean_gap", in->mean_gap) ||
	    rc_row_num(row, "elastic_energy", in->elastic_energy) ||
	    rc_row_int(row, "n_patches", (long long)st->n_patches) ||
	    rc_row_num(row, "patch_size_char", st->patch_size_char) ||
	    rc_row_int(row, "iterations", in->iterations) ||
	    rc_row_num(row, "residual", in->residual) ||
	    rc_row_num(row, "tol", in->tol) ||
	    rc_row_num(row, "seconds", in->seconds) ||
	    rc_row_num(row, "plan_seconds", in->plan_seconds) ||
	    rc_row_str(row, "method", in->method) ||
	    rc_row_str(row, "boundary", in->boundary) ||
	    rc_row_str(row, "kernel", in->kernel ? in->kernel : "continuum") ||
	    rc_row_int(row, "nx", (long long)in->nx) ||
	    rc_row_int(row, "ny", (long long)in->ny) ||
	    rc_row_num(row, "lx", in->indenter->lx) ||
	    rc_row_num(row, "ly", in->indenter->ly) ||
	    rc_row_meta(row, in->indenter))
		return -1;
	return 0;
}

const char *
gfmd_kappa_c_why(const struct gfmd_row *in)
{
	const rc_contact_stats *st = in->stats;

	if (!isnan(st->kappa_c))
		return NULL;
	if (st->n_c == 0)
		return "no point is in contact, so gbar_c is undefined";
	if (!(st->gbar_c > 0))
		return "the rms gradient over the contact, gbar_c, is 0 (a contact "
		    "only where the indenter is flat, e.g. at the apex of a "
		    "harmonic indenter), so p*_c = p/(E* gbar_c) is undefined";
	return "a_r or p*_c is outside the range of Eq. 8";
}

void
gfmd_pressure(const struct gfmd_opts *o, size_t k, double gbar, double *p,
    double *p_star)
{
	*p = o->napproach ? NAN : o->nreduced ?
	    o->reduced[k] * o->modulus * gbar : o->absolute[k];
	*p_star = o->nreduced ? o->reduced[k] :
	    gbar > 0 ? *p / (o->modulus * gbar) : NAN;
}

int
gfmd_emit_row(const struct tool *t, const struct gfmd_row *in,
    int converged, rc_row *row, rc_table_out *table, FILE *fp,
    size_t *nunconverged, rc_err *err)
{
	const char *why = gfmd_kappa_c_why(in);

	if (why != NULL)
		tool_warn(t, "p = %g: kappa_c written as nan: %s", in->p, why);
	if (gfmd_result_row(row, in) != 0)
		return GFMD_ROW_NOMEM;
	if (fp != NULL && rc_table_write(table, row, err) != 0)
		return GFMD_ROW_WRITE;
	if (fp != NULL && fflush(fp) != 0) {
		rc_seterr(err, "%s", strerror(errno));
		return GFMD_ROW_WRITE;
	}
	if (in->separated)
		tool_warn(t, "p = %g: no equilibrium: the body separated (no "
		    "contact, and the tension exceeds the strongest attraction "
		    "left: past pull-off); row written with separated 1, going "
		    "on", in->p);
	else if (!converged && in->stalled) {
		(*nunconverged)++;
		tool_warn(t, "p = %g: stalled: the residual (%.3g; tolerance "
		    "%.3g) did not halve in %ld iterations, stopped after %ld; "
		    "try --method %s, --boundary periodic, or an indenter "
		    "levelled and filled (surfwarp --detrend plane --fill); "
		    "--stall 0 runs on to --max-iter; row written, going on",
		    in->p, in->residual, in->tol, in->stalled, in->iterations,
		    in->method != NULL && strcmp(in->method, "cg") == 0 ?
		    "fire" : "cg");
	} else if (!converged) {
		(*nunconverged)++;
		tool_warn(t, "p = %g: not converged after %ld iterations "
		    "(residual %.3g, tolerance %.3g); row written, going on",
		    in->p, in->iterations, in->residual, in->tol);
	}
	return 0;
}
