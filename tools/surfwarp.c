/* SPDX-License-Identifier: GPL-3.0-or-later */
/* surfwarp - transform a height map: levelling and repair of measured
 * maps (detrending, scan-line alignment, harmonic filling, cropping,
 * resampling, transposing; in command-line order), then warping (Eq. 4 of
 * Wang & Mueser 2020, in the paper's meaning of w; see surfwarp(1)),
 * flipping, carving the non-contact zone, renormalising the rms
 * gradient. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "common.h"
#include "fft.h"
#include "level.h"
#include "png.h"
#include "resample.h"
#include "threads.h"
#include "warp.h"

enum {
	OPT_FLIP = OPT_TOOL_FIRST,
	OPT_HMIN,
	OPT_HMAX,
	OPT_RMS_GRADIENT,
	OPT_CARVE,
	OPT_CARVE_WIDTH,
	OPT_CARVE_ROUGH,
	OPT_CARVE_SEED,
	OPT_DETREND,
	OPT_ALIGN_ROWS,
	OPT_FILL,
	OPT_FILLED_MASK,
	OPT_CROP,
	OPT_RESAMPLE,
	OPT_TRANSPOSE
};

/* A levelling or repair step, applied in command-line order. */
struct step {
	int op;			/* OPT_DETREND ... OPT_TRANSPOSE */
	int mode;		/* detrend or alignment kind */
	size_t x0, x1, y0, y1;	/* crop */
	double dx, dy;		/* resample */
};

#define MAX_STEPS 64

static void
usage(void)
{
	printf("usage: surfwarp [options] [FILE]\n"
	    "  levelling and repair, applied in the order given:\n"
	    "  --detrend M           subtract the least-squares mean, plane or quadratic\n"
	    "                        over the valid points (plane, quadratic: periodic = 0)\n"
	    "  --align-rows M        per scan line (row) remove its median, mean or plane\n"
	    "  --fill                fill missing points harmonically (Laplace); the\n"
	    "                        output marks them (.surf, .txt, .gsf: filled)\n"
	    "  --crop X0:X1,Y0:Y1    keep points X0 <= i < X1, Y0 <= j < Y1\n"
	    "  --resample D[xD]      new spacing: spectral on periodic grids, cubic\n"
	    "                        splines on finite patches\n"
	    "  --transpose           swap x and y\n"
	    "  --filled-mask FILE    write a mask of the points --fill filled\n"
	    "  then, in this order:\n"
	    "  -w W                  warp (Eq. 4): W > 0 blunts the peaks (maxima of h)\n"
	    "                        and sharpens the valleys, W < 0 the opposite\n"
	    "  --hmin H, --hmax H    warp bounds (default 2 min h - max h, 2 max h - min h)\n"
	    "  --flip                h -> -h\n"
	    "  --carve MASK DEPTH    lower points outside the contact mask by\n"
	    "                        DEPTH (1 - exp(-d^2 / 2 W^2)), d the distance to contact\n"
	    "  --carve-width W       W above (default 4 grid spacings)\n"
	    "  --carve-rough A       also lower the carved zone by A |xi| (1 - exp(..)),\n"
	    "                        xi standard normal per point: grid-scale roughness\n"
	    "  --carve-seed S        seed of xi (default 1)\n"
	    "  --rms-gradient G      finally scale heights to rms gradient G\n"
	    "  -o FILE               output (.surf .npy .gsf .txt .x3p .nc; default\n"
	    "                        stdout, surf)\n"
	    "  --png FILE            PNG preview of the result\n"
	    "  -L LX[xLY]            cell size of an input that has none\n"
	    "  --unit U              length unit of the output, and of H, DEPTH, A\n"
	    "                        (m mm um nm pm angstrom); the unit of an input\n"
	    "                        that has none\n"
	    "  --z-unit U            the input's heights are in length unit U\n"
	    "  --periodic, --no-periodic  the input is (not) one period of a surface\n"
	    "  --npy-order yx|xy     .npy shape (ny, nx) (default) or (nx, ny)\n"
	    "  --uniform             resample an x-z profile whose x is not uniformly\n"
	    "                        spaced linearly onto as many points\n"
	    "  --channel N|NAME      channel of a multi-channel input (default: the\n"
	    "                        first whose values are lengths)\n"
	    "  -j N  threads   -q  quiet   -h, --help   --version\n");
}

static const struct option longopts[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ "png", required_argument, NULL, OPT_PNG },
	{ "flip", no_argument, NULL, OPT_FLIP },
	{ "hmin", required_argument, NULL, OPT_HMIN },
	{ "hmax", required_argument, NULL, OPT_HMAX },
	{ "rms-gradient", required_argument, NULL, OPT_RMS_GRADIENT },
	{ "carve", required_argument, NULL, OPT_CARVE },
	{ "carve-width", required_argument, NULL, OPT_CARVE_WIDTH },
	{ "carve-rough", required_argument, NULL, OPT_CARVE_ROUGH },
	{ "carve-seed", required_argument, NULL, OPT_CARVE_SEED },
	{ "detrend", required_argument, NULL, OPT_DETREND },
	{ "align-rows", required_argument, NULL, OPT_ALIGN_ROWS },
	{ "fill", no_argument, NULL, OPT_FILL },
	{ "filled-mask", required_argument, NULL, OPT_FILLED_MASK },
	{ "crop", required_argument, NULL, OPT_CROP },
	{ "resample", required_argument, NULL, OPT_RESAMPLE },
	{ "transpose", no_argument, NULL, OPT_TRANSPOSE },
	TOOL_GRID_LONGOPTS,
	TOOL_CHANNEL_LONGOPT,
	{ NULL, 0, NULL, 0 }
};

/* "X0:X1,Y0:Y1", non-negative integers. */
static int
parse_crop(struct tool *t, const char *arg, struct step *st)
{
	unsigned long long v[4];
	int used = 0;

	if (sscanf(arg, "%llu:%llu,%llu:%llu%n", &v[0], &v[1], &v[2], &v[3],
	    &used) != 4 || arg[used] != '\0' || strchr(arg, '-') != NULL) {
		tool_bad(t, "--crop %s: want X0:X1,Y0:Y1 (point indices)", arg);
		return -1;
	}
	if (!(v[0] < v[1] && v[2] < v[3])) {
		tool_bad(t, "--crop %s: want X0 < X1 and Y0 < Y1", arg);
		return -1;
	}
	st->x0 = (size_t)v[0];
	st->x1 = (size_t)v[1];
	st->y0 = (size_t)v[2];
	st->y1 = (size_t)v[3];
	return 0;
}

/* Apply one step; the grid may be replaced. */
static rc_grid *
apply(const struct tool *t, rc_grid *g, const struct step *st,
    const char *filled_mask)
{
	rc_grid *n = NULL;
	rc_err err;

	switch (st->op) {
	case OPT_DETREND:
		if (rc_detrend(g, (enum rc_detrend)st->mode, NULL, &err) != 0)
			tool_fail(t, "--detrend: %s", err.msg);
		return g;
	case OPT_ALIGN_ROWS:
		if (rc_align_rows(g, (enum rc_align)st->mode, &err) != 0)
			tool_fail(t, "--align-rows: %s", err.msg);
		return g;
	case OPT_FILL: {
		size_t nf;
		if (rc_fill_harmonic(g, NULL, &nf, &err) != 0)
			tool_fail(t, "--fill: %s", err.msg);
		/* g->filled, which the output keeps too, as a grid of its own */
		if (filled_mask != NULL) {
			rc_grid *m = rc_grid_new(g->nx, g->ny, g->lx, g->ly, &err);
			if (m == NULL)
				tool_fail(t, "%s", err.msg);
			m->kind = RC_KIND_MASK;
			memcpy(m->unit, g->unit, sizeof(m->unit));
			m->periodic = g->periodic;
			for (size_t k = 0; k < rc_grid_size(m); k++)
				m->z[k] = g->filled != NULL && g->filled[k];
			tool_write_grid(t, m, filled_mask);
			rc_grid_free(m);
		}
		if (!t->quiet && nf > 0)
			tool_warn(t, "--fill: %zu missing points filled", nf);
		return g;
	}
	case OPT_CROP:
		n = rc_crop(g, st->x0, st->x1, st->y0, st->y1, &err);
		break;
	case OPT_RESAMPLE:
		n = rc_resample(g, st->dx, st->dy, &err);
		break;
	case OPT_TRANSPOSE:
		n = rc_transpose(g, &err);
		break;
	}
	if (n == NULL)
		tool_fail(t, "%s", err.msg);
	rc_grid_free(g);
	return n;
}

/* surfwarp's options: one struct, parsed, then checked together. */
struct warp_opts {
	const char *in, *carve_mask, *filled_mask;
	double w, hmin, hmax, rmsg, depth, width, rough;
	long carve_seed;
	int have_w, have_hmin, have_hmax, flip, have_rough_opts, have_fill;
	struct step steps[MAX_STEPS];	/* levelling, in command-line order */
	size_t nsteps;
};

/* A levelling step (--detrend ... --transpose), in order. */
static void
add_step(struct tool *t, struct warp_opts *wo, int opt, const char *arg)
{
	struct step st;

	memset(&st, 0, sizeof(st));
	st.op = opt;
	if (wo->nsteps == MAX_STEPS) {
		tool_bad(t, "more than %d levelling steps", MAX_STEPS);
		return;
	}
	if (opt == OPT_DETREND && (st.mode = rc_detrend_parse(arg)) < 0)
		tool_bad(t, "--detrend %s: want mean, plane or quadratic", arg);
	if (opt == OPT_ALIGN_ROWS && (st.mode = rc_align_parse(arg)) < 0)
		tool_bad(t, "--align-rows %s: want median, mean or plane", arg);
	if (opt == OPT_CROP && parse_crop(t, arg, &st) != 0)
		return;
	if (opt == OPT_RESAMPLE)
		tool_length_pair(t, "--resample", arg, &st.dx, &st.dy);
	if (opt == OPT_FILL)
		wo->have_fill = 1;
	wo->steps[wo->nsteps++] = st;
}

/* One option c of getopt_long (--carve takes the next word too). */
static void
warp_option(struct tool *t, struct warp_opts *wo, int c, const char *arg,
    int argc, char **argv)
{
	switch (c) {
	case 'w':
		if (tool_double(t, "-w", arg, &wo->w) == 0)
			wo->have_w = 1;
		break;
	case OPT_HMIN:
		if (tool_double(t, "--hmin", arg, &wo->hmin) == 0)
			wo->have_hmin = 1;
		break;
	case OPT_HMAX:
		if (tool_double(t, "--hmax", arg, &wo->hmax) == 0)
			wo->have_hmax = 1;
		break;
	case OPT_FLIP:
		wo->flip = 1;
		break;
	case OPT_RMS_GRADIENT:
		if (tool_double(t, "--rms-gradient", arg, &wo->rmsg) == 0 &&
		    !(wo->rmsg > 0))
			tool_bad(t, "--rms-gradient %s: must be positive", arg);
		break;
	case OPT_CARVE:
		/* Two arguments: MASK here, DEPTH the next word. */
		wo->carve_mask = arg;
		if (optind >= argc) {
			tool_bad(t, "--carve: needs MASK and DEPTH");
			break;
		}
		if (tool_double(t, "--carve DEPTH", argv[optind], &wo->depth) == 0 &&
		    !(wo->depth >= 0))
			tool_bad(t, "--carve DEPTH %s: must be >= 0", argv[optind]);
		optind++;
		break;
	case OPT_CARVE_ROUGH:
		wo->have_rough_opts = 1;
		if (tool_double(t, "--carve-rough", arg, &wo->rough) == 0 &&
		    !(wo->rough >= 0))
			tool_bad(t, "--carve-rough %s: must be >= 0", arg);
		break;
	case OPT_CARVE_SEED:
		wo->have_rough_opts = 1;
		if (tool_long(t, "--carve-seed", arg, &wo->carve_seed) == 0 &&
		    wo->carve_seed < 0)
			tool_bad(t, "--carve-seed %s: must be >= 0", arg);
		break;
	case OPT_DETREND:
	case OPT_ALIGN_ROWS:
	case OPT_FILL:
	case OPT_CROP:
	case OPT_RESAMPLE:
	case OPT_TRANSPOSE:
		add_step(t, wo, c, arg);
		break;
	case OPT_FILLED_MASK:
		wo->filled_mask = arg;
		break;
	case OPT_CARVE_WIDTH:
		if (tool_double(t, "--carve-width", arg, &wo->width) == 0 &&
		    !(wo->width > 0))
			tool_bad(t, "--carve-width %s: must be positive", arg);
		break;
	default:
		tool_bad_option(t, "hw:o:j:qL:", longopts, argv);
	}
}

/* The checks between options, the operand, and the run's files. */
static void
warp_opts_check(struct tool *t, struct warp_opts *wo, int argc, char **argv)
{
	if (optind < argc)
		wo->in = argv[optind++];
	if (optind < argc)
		tool_bad(t, "%s: unexpected argument (one input file)", argv[optind]);
	if ((wo->have_hmin || wo->have_hmax) && !wo->have_w)
		tool_bad(t, "--hmin, --hmax: only with -w");
	if (wo->width > 0 && wo->carve_mask == NULL)
		tool_bad(t, "--carve-width: only with --carve");
	if (wo->have_rough_opts && wo->carve_mask == NULL)
		tool_bad(t, "--carve-rough, --carve-seed: only with --carve");
	if (wo->have_hmin && wo->have_hmax && !(wo->hmin < wo->hmax))
		tool_bad(t, "--hmin %g, --hmax %g: need hmin < hmax", wo->hmin,
		    wo->hmax);
	if (wo->filled_mask != NULL && !wo->have_fill)
		tool_bad(t, "--filled-mask: only with --fill");
	tool_check_grid_path(t, "-o", t->out);
	if (wo->filled_mask != NULL)
		tool_check_grid_path(t, "--filled-mask", wo->filled_mask);
	tool_output(t, "-o", t->out ? t->out : "-", 0);
	tool_output(t, "--filled-mask", wo->filled_mask, 0);
	tool_output(t, "--png", t->png, 1);
	/* -o may be the input (written atomically after reading it), not the
	 * mask; the preview is never either. */
	tool_input(t, "the input", wo->in);
	if (wo->carve_mask != NULL)
		tool_input(t, "--carve", wo->carve_mask);
	tool_may_replace(t, "-o", "the input");
	tool_usage_check(t);
}

/* The levelling steps in order, then -w, --flip, --carve and the
 * renormalisation; returns the grid (a step may replace it). */
static rc_grid *
warp_run(struct tool *t, struct warp_opts *wo, rc_grid *g)
{
	rc_err err;

	for (size_t k = 0; k < wo->nsteps; k++) {
		const struct step *st = &wo->steps[k];

		g = apply(t, g, st, wo->filled_mask);
		/* Levelling, cropping and resampling change the heights'
		 * statistics: the generation target no longer holds. */
		if (st->op != OPT_TRANSPOSE && st->op != OPT_FILL &&
		    !(st->op == OPT_DETREND && st->mode == RC_DETREND_MEAN)) {
			rc_grid_meta_unset(g, "rms_gradient");
			rc_grid_meta_unset(g, "rms_height");
		}
	}
	if (g->valid != NULL && (wo->have_w || wo->flip ||
	    wo->carve_mask != NULL || wo->rmsg > 0))
		tool_fail(t, "%s: the grid has missing points; -w, --flip, --carve "
		    "and --rms-gradient need every point (add --fill first)",
		    wo->in ? wo->in : "standard input");
	if (wo->have_w) {
		double dmin, dmax;

		rc_warp_default_bounds(g, &dmin, &dmax);
		if (!wo->have_hmin)
			wo->hmin = dmin;
		if (!wo->have_hmax)
			wo->hmax = dmax;
		if (rc_warp(g, wo->w, wo->hmin, wo->hmax, &err) != 0)
			tool_fail(t, "%s", err.msg);
	}
	if (wo->flip && rc_flip(g, &err) != 0)
		tool_fail(t, "%s", err.msg);
	if (wo->carve_mask != NULL) {
		rc_grid *mask = tool_read_grid(t, wo->carve_mask);

		if (wo->width == 0)
			wo->width = 4 * fmax(g->lx / (double)g->nx,
			    g->ly / (double)g->ny);
		if (rc_carve_rough(g, mask, wo->depth, wo->width, wo->rough,
		    (unsigned long)wo->carve_seed, &err) != 0)
			tool_fail_at(t, wo->carve_mask, err.msg);
		rc_grid_free(mask);
	}
	if (wo->rmsg > 0) {
		if (rc_scale_rms_gradient(g, wo->rmsg, &err) != 0)
			tool_fail(t, "%s", err.msg);
	} else if (wo->have_w || wo->carve_mask != NULL)
		/* The generation target no longer describes the heights. */
		rc_grid_meta_unset(g, "rms_gradient");
	return g;
}

int
main(int argc, char **argv)
{
	struct tool t;
	struct warp_opts wo;
	rc_grid *g;
	rc_err err;
	int opt, help = 0;

	memset(&wo, 0, sizeof(wo));
	wo.carve_seed = 1;
	tool_init(&t, "surfwarp", argc, argv);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "hw:o:j:qL:", longopts, NULL)) != -1) {
		if (tool_common_option(&t, opt, optarg))
			continue;
		if (opt == 'h')
			help = 1;
		else
			warp_option(&t, &wo, opt, optarg, argc, argv);
	}
	if (help && tool_help_check(&t)) {
		usage();
		return tool_exit(&t, 0);
	}
	warp_opts_check(&t, &wo, argc, argv);
	tool_threads_setup(&t);
	gsl_set_error_handler_off();	/* GSL reports through return codes */
	/* Levelling steps use the valid points; -w, --flip, --carve and the
	 * renormalisation are refused while points are missing. */
	t.accept_missing = 1;
	g = warp_run(&t, &wo, tool_read_input(&t, wo.in));
	if (t.png != NULL && rc_png_write(g, t.png, NULL, &err) != 0)
		tool_fail_at(&t, t.png, err.msg);
	tool_write_grid(&t, g, t.out);
	rc_grid_free(g);
	return tool_exit(&t, 0);
}
