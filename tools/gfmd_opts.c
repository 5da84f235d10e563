/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd_opts.c - gfmd-solve's options (see gfmd_opts.h). */
#include "gfmd_opts.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "contact.h"

const char *const gfmd_field_option[GFMD_NFIELDS] = { "--contact", "--gap",
    "--pressure", "--displacement" };

void
gfmd_opts_init(struct gfmd_opts *o)
{
	memset(o, 0, sizeof(*o));
	rc_solver_defaults(&o->so);
	o->modulus = 1;
	o->alpha = RC_YASTREBOV_ALPHA;
	o->boundary = -1;
}

void
gfmd_opts_free(struct gfmd_opts *o)
{
	free(o->reduced);
	free(o->absolute);
	free(o->approach);
	o->reduced = o->absolute = o->approach = NULL;
}

/* A list of pressures (or approaches); their signs are checked with the
 * other options (adhesion allows any). */
static void
pressure_list(struct tool *t, const char *opt, const char *arg, double **v,
    size_t *n)
{
	free(*v);
	*v = NULL;
	*n = 0;
	tool_double_list(t, opt, arg, v, n);
}

/* Without adhesion each value of a list must be positive. */
static void
positive_list(struct tool *t, const char *opt, const double *v, size_t n)
{
	const char *what = strcmp(opt, "--approach") == 0 ? "approach" : "pressure";

	for (size_t i = 0; i < n; i++)
		if (!(v[i] > 0)) {
			tool_bad(t, "%s: %s %g must be positive (zero or negative "
			    "only with --adhesion)", opt, what, v[i]);
			return;
		}
}

/* Every long option either build may take, for naming a bad one. */
static const struct option all_longopts[] = {
	GFMD_LONGOPTS,
	TOOL_FFT_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

/* Long: one case per option, each a few lines; they are read together. */
void
gfmd_option(struct tool *t, struct gfmd_opts *o, int c, const char *arg,
    char **argv)
{
	long n;
	int method;

	switch (c) {
	case 'p':
		pressure_list(t, "-p", arg, &o->reduced, &o->nreduced);
		break;
	case OPT_PRESSURE_ABS:
		pressure_list(t, "--pressure-abs", arg, &o->absolute, &o->nabsolute);
		break;
	case OPT_APPROACH:
		pressure_list(t, "--approach", arg, &o->approach, &o->napproach);
		break;
	case OPT_BOUNDARY:
		if ((o->boundary = rc_boundary_parse(arg)) < 0)
			tool_bad(t, "--boundary %s: want periodic or free", arg);
		break;
	case OPT_HARDNESS:
		if (tool_double(t, "--hardness", arg, &o->so.hardness) == 0 &&
		    !(o->so.hardness > 0))
			tool_bad(t, "--hardness %s: want a positive pressure (units "
			    "of E*)", arg);
		o->given_hardness = 1;
		break;
	case OPT_THICKNESS:
		if (tool_double(t, "--thickness", arg, &o->so.thickness) == 0 &&
		    !(o->so.thickness > 0 && isfinite(o->so.thickness)))
			tool_bad(t, "--thickness %s: want a positive length", arg);
		o->given_layer = 1;
		break;
	case OPT_SUBSTRATE: {
		int sub = rc_substrate_parse(arg);

		if (sub < 0)
			tool_bad(t, "--substrate %s: want bonded or slip", arg);
		else
			o->so.substrate = (enum rc_substrate)sub;
		o->given_layer = 1;
		break;
	}
	case OPT_POISSON:
		if (tool_double(t, "--poisson", arg, &o->so.poisson) == 0 &&
		    !(o->so.poisson > -1 && o->so.poisson <= 0.5))
			tool_bad(t, "--poisson %s: want a ratio in (-1, 0.5]", arg);
		o->poisson_given = 1;
		o->given_layer = 1;
		break;
	case OPT_KERNEL: {
		int k = rc_kernel_parse(arg);

		if (k < 0)
			tool_bad(t, "--kernel %s: want continuum or pixel", arg);
		else
			o->so.kernel = (enum rc_kernel)k;
		o->given_kernel = 1;
		break;
	}
	case OPT_ADHESION:
		if (tool_double(t, "--adhesion", arg, &o->so.adhesion) == 0 &&
		    !(o->so.adhesion > 0 && isfinite(o->so.adhesion)))
			tool_bad(t, "--adhesion %s: want a positive work of "
			    "adhesion (units of E* times length)", arg);
		o->given_adhesion = 1;
		break;
	case OPT_RANGE:
		if (tool_double(t, "--range", arg, &o->so.range) == 0 &&
		    !(o->so.range > 0 && isfinite(o->so.range)))
			tool_bad(t, "--range %s: want a positive length", arg);
		o->given_adhesion = 1;
		break;
	case OPT_LAW: {
		int law = rc_adhesion_law_parse(arg);

		if (law < 0)
			tool_bad(t, "--law %s: want exponential or dugdale", arg);
		else
			o->so.adhesion_law = (enum rc_adhesion_law)law;
		o->given_law = 1;
		break;
	}
	case 'E':
		if (tool_double(t, "-E", arg, &o->modulus) == 0 && !(o->modulus > 0))
			tool_bad(t, "-E %s: the contact modulus must be positive", arg);
		o->given_e = 1;
		break;
	case OPT_METHOD:
		if ((method = rc_method_parse(arg)) < 0)
			tool_bad(t, "--method %s: want fire or cg", arg);
		else
			o->so.method = (enum rc_method)method;
		o->given_method = 1;
		break;
	case OPT_TOL:
		if (tool_double(t, "--tol", arg, &o->so.tol) == 0 &&
		    !(o->so.tol > 0 && o->so.tol < 1))
			tool_bad(t, "--tol %s: want a tolerance in (0, 1)", arg);
		o->given_tol = 1;
		break;
	case OPT_MAX_ITER:
		if (tool_long(t, "--max-iter", arg, &n) == 0) {
			if (n < 1)
				tool_bad(t, "--max-iter %s: want at least 1", arg);
			else
				o->so.max_iter = n;
		}
		o->given_max_iter = 1;
		break;
	case OPT_STALL:
		if (tool_long(t, "--stall", arg, &n) == 0) {
			if (n < 0)
				tool_bad(t, "--stall %s: want a number of "
				    "iterations, or 0 for never", arg);
			else
				o->so.stall_window = n;
		}
		o->given_stall = 1;
		break;
	case OPT_ALPHA:
		if (tool_double(t, "--alpha", arg, &o->alpha) == 0 &&
		    !(o->alpha >= 0 && o->alpha <= 1))
			tool_bad(t, "--alpha %s: want a weight in [0, 1]", arg);
		o->given_alpha = 1;
		break;
	case OPT_INIT:
		o->init = arg;
		break;
	case OPT_CONTACT:
	case OPT_GAP:
	case OPT_PRESSURE_FIELD:
	case OPT_DISPLACEMENT:
		o->field[c - OPT_CONTACT] = arg;
		break;
	case OPT_FD:
		o->fd = 1;
		o->given_fd = 1;
		break;
	case OPT_CHECKPOINT:
		o->ck_path = arg;
		break;
	case OPT_CHECKPOINT_EVERY:
		/* Each save restarts the solve: below a few tenths of a second
		 * it would save more than it solves. */
		if (tool_double(t, "--checkpoint-every", arg, &o->ck_every) == 0 &&
		    !(o->ck_every >= GFMD_CHECKPOINT_EVERY_MIN && o->ck_every <= 1e6))
			tool_bad(t, "--checkpoint-every %s: want minutes in [%g, 1e6]",
			    arg, GFMD_CHECKPOINT_EVERY_MIN);
		break;
	case OPT_RESUME:
		o->resume_path = arg;
		break;
	case '?':
		tool_bad_option(t, GFMD_OPTSTRING, all_longopts, argv);
		break;
	default:
		tool_common_option(t, c, arg);
	}
}

const char gfmd_pixel_layer_refusal[] = "--kernel pixel: a periodic layer "
    "(--thickness) has the continuum kernel only (the pixel kernel would "
    "need the layer's factor on every image of its sum; free boundaries "
    "solve a layer with its pixel compliance)";

/* --adhesion with the options it combines with (gfmd-solve(1),
 * ADHESION). */
static void
adhesion_check(struct tool *t, const struct gfmd_opts *o)
{
	if (!(o->so.adhesion > 0) || !(o->so.range > 0))
		tool_bad(t, "--adhesion, --range: give both, the work of "
		    "adhesion DGAMMA and the range RHO of its law");
	if (o->so.method != RC_METHOD_FIRE)
		tool_bad(t, "--adhesion: solved by --method fire only (adhesion "
		    "makes the problem non-convex; the CG solves a convex one)");
	if (o->given_hardness)
		tool_bad(t, "--adhesion with --hardness: not combined (the "
		    "plastic model keeps no history, so it has no unloading "
		    "branch, where pull-off and hysteresis happen)");
}

/* Long: every check between options in one place, so that all problems
 * are reported together. */
void
gfmd_opts_check(struct tool *t, struct gfmd_opts *o, int argc, char **argv)
{
	if ((o->nreduced != 0) + (o->nabsolute != 0) + (o->napproach != 0) > 1)
		tool_bad(t, "-p, --pressure-abs and --approach: give one of them");
	else if (!o->nreduced && !o->nabsolute && !o->napproach && t->nbad == 0 &&
	    o->resume_path == NULL)
		tool_bad(t, "no load: give -p P[,P...], --pressure-abs P[,P...] or "
		    "--approach D[,D...]");
	if (o->given_law && !o->given_adhesion && o->resume_path == NULL)
		tool_bad(t, "--law: the adhesive law of --adhesion DGAMMA "
		    "--range RHO; give them too");
	if (!o->given_adhesion) {
		positive_list(t, "-p", o->reduced, o->nreduced);
		positive_list(t, "--pressure-abs", o->absolute, o->nabsolute);
		positive_list(t, "--approach", o->approach, o->napproach);
	} else
		adhesion_check(t, o);
	if (o->napproach && (o->ck_path != NULL || o->resume_path != NULL))
		tool_bad(t, "--approach: --checkpoint and --resume are for load "
		    "control (-p, --pressure-abs) only");
	if (o->given_layer) {
		if (!(o->so.thickness > 0))
			tool_bad(t, "--substrate, --poisson: describe a layer; "
			    "give its --thickness D");
		else {
			if (o->so.substrate == RC_SUBSTRATE_NONE)
				o->so.substrate = RC_SUBSTRATE_BONDED;
			if (!o->poisson_given)
				tool_bad(t, "--thickness: give the layer's --poisson "
				    "NU (its uniform compression, and the bonded "
				    "kernel, depend on it)");
		}
	}
	if (o->given_kernel) {
		if (o->boundary == RC_BOUNDARY_FREE &&
		    o->so.kernel != RC_KERNEL_PIXEL)
			tool_bad(t, "--kernel %s: free boundaries always solve "
			    "with Love's pixel compliance (the discretisation of "
			    "--kernel pixel); drop --kernel",
			    rc_kernel_name(o->so.kernel));
		/* a free layer is solved with its pixel compliance; a grid
		 * that decides the boundary is checked in gfmd-solve.c */
		if (o->so.kernel == RC_KERNEL_PIXEL && o->given_layer &&
		    o->boundary == RC_BOUNDARY_PERIODIC)
			tool_bad(t, "%s", gfmd_pixel_layer_refusal);
	}
	if (o->ck_every > 0 && o->ck_path == NULL)
		tool_bad(t, "--checkpoint-every: needs --checkpoint FILE");
	if (o->ck_path != NULL && rc_is_stdio(o->ck_path))
		tool_bad(t, "--checkpoint -: give a file name");
	if (o->resume_path != NULL && o->init != NULL)
		tool_bad(t, "--resume and --init: the checkpoint is the start; "
		    "give one of them");
	if (argc - optind > 1)
		tool_bad(t, "%s: one input file at most", argv[optind + 1]);
	for (int k = 0; k < GFMD_NFIELDS; k++) {
		if (o->field[k] != NULL && rc_is_stdio(o->field[k]))
			tool_bad(t, "%s %s: fields go to files; standard output "
			    "carries the result table", gfmd_field_option[k],
			    o->field[k]);
		else
			tool_check_grid_path(t, gfmd_field_option[k], o->field[k]);
	}
	if (t->png != NULL && rc_is_stdio(t->png))
		tool_bad(t, "--png -: give a file name");
	/* Every output is checked now, not after the solve; no two are the
	 * same file, none replaces the indenter; only the fields (which may
	 * update a warm start file) may replace --init, and only the
	 * checkpoint the one it resumes. */
	tool_output(t, "-o", t->out ? t->out : "-", 0);
	if (t->png != NULL && !rc_is_stdio(t->png))
		tool_output(t, "--png", t->png, 1);
	if (o->ck_path != NULL && !rc_is_stdio(o->ck_path))
		tool_output(t, "--checkpoint", o->ck_path, 1);
	for (int k = 0; k < GFMD_NFIELDS; k++)
		if (o->field[k] != NULL && !rc_is_stdio(o->field[k])) {
			tool_output(t, gfmd_field_option[k], o->field[k], 1);
			tool_may_replace(t, gfmd_field_option[k], "--init");
		}
	tool_input(t, "the indenter", optind < argc ? argv[optind] : NULL);
	if (o->init != NULL)
		tool_input(t, "--init", o->init);
	if (o->resume_path != NULL)
		tool_input(t, "--resume", o->resume_path);
	tool_may_replace(t, "--checkpoint", "--resume");
}

void
gfmd_check_scale(const struct tool *t, const char *input, double range,
    double gbar)
{
	const char *in = input == NULL || rc_is_stdio(input) ?
	    "standard input" : input;
	int bad_range = range != 0 && !isnan(range) &&
	    !(range >= GFMD_SCALE_MIN && range <= GFMD_SCALE_MAX);
	int bad_gbar = gbar != 0 &&
	    !(gbar >= GFMD_SCALE_MIN && gbar <= GFMD_SCALE_MAX);

	if (!bad_range && !bad_gbar)
		return;
	if (isnan(range))
		tool_fail(t, "%s: rms gradient %g: outside [%g, %g], where the "
		    "solve would overflow or underflow; rescale the surface (e.g. "
		    "surfwarp --rms-gradient 1)", in, gbar, GFMD_SCALE_MIN,
		    GFMD_SCALE_MAX);
	tool_fail(t, "%s: heights spanning %g with rms gradient %g: outside "
	    "[%g, %g], where the solve would overflow or underflow; rescale the "
	    "surface (e.g. surfwarp --rms-gradient 1)", in, range, gbar,
	    GFMD_SCALE_MIN, GFMD_SCALE_MAX);
}
