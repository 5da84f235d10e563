/* surfwarp - transform a height map: warping (Eq. 4 of Wang & Mueser
 * 2020, in the paper's meaning of w; see surfwarp(1)), flipping, carving
 * the non-contact zone, renormalising the rms gradient. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common.h"
#include "fft.h"
#include "png.h"
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
	OPT_CARVE_SEED
};

static void
usage(void)
{
	printf("usage: surfwarp [options] [FILE]\n"
	    "  applied in this order:\n"
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
	    "  -o FILE               output (.surf .npy .gsf .txt; default stdout, surf)\n"
	    "  --png FILE            PNG preview of the result\n"
	    "  -L LX[xLY]            cell size of an input that has none\n"
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
	{ NULL, 0, NULL, 0 }
};

int
main(int argc, char **argv)
{
	struct tool t;
	const char *in = NULL, *carve_mask = NULL;
	double w = 0, hmin = 0, hmax = 0, rmsg = 0, depth = 0, width = 0, rough = 0;
	long carve_seed = 1;
	int have_rough_opts = 0;
	int have_w = 0, have_hmin = 0, have_hmax = 0, flip = 0, opt;
	rc_grid *g;
	rc_err err;

	tool_init(&t, "surfwarp", argc, argv);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "hw:o:j:qL:", longopts, NULL)) != -1) {
		if (tool_common_option(&t, opt, optarg))
			continue;
		switch (opt) {
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case 'w':
			if (tool_double(&t, "-w", optarg, &w) == 0)
				have_w = 1;
			break;
		case OPT_HMIN:
			if (tool_double(&t, "--hmin", optarg, &hmin) == 0)
				have_hmin = 1;
			break;
		case OPT_HMAX:
			if (tool_double(&t, "--hmax", optarg, &hmax) == 0)
				have_hmax = 1;
			break;
		case OPT_FLIP:
			flip = 1;
			break;
		case OPT_RMS_GRADIENT:
			if (tool_double(&t, "--rms-gradient", optarg, &rmsg) == 0 &&
			    !(rmsg > 0))
				tool_bad(&t, "--rms-gradient %s: must be positive", optarg);
			break;
		case OPT_CARVE:
			/* Two arguments: MASK here, DEPTH the next word. */
			carve_mask = optarg;
			if (optind >= argc) {
				tool_bad(&t, "--carve: needs MASK and DEPTH");
				break;
			}
			if (tool_double(&t, "--carve DEPTH", argv[optind], &depth) == 0 &&
			    !(depth >= 0))
				tool_bad(&t, "--carve DEPTH %s: must be >= 0", argv[optind]);
			optind++;
			break;
		case OPT_CARVE_ROUGH:
			have_rough_opts = 1;
			if (tool_double(&t, "--carve-rough", optarg, &rough) == 0 &&
			    !(rough >= 0))
				tool_bad(&t, "--carve-rough %s: must be >= 0", optarg);
			break;
		case OPT_CARVE_SEED:
			have_rough_opts = 1;
			if (tool_long(&t, "--carve-seed", optarg, &carve_seed) == 0 &&
			    carve_seed < 0)
				tool_bad(&t, "--carve-seed %s: must be >= 0", optarg);
			break;
		case OPT_CARVE_WIDTH:
			if (tool_double(&t, "--carve-width", optarg, &width) == 0 &&
			    !(width > 0))
				tool_bad(&t, "--carve-width %s: must be positive", optarg);
			break;
		default:
			if (optopt != 0 && strchr("wojL", optopt) != NULL)
				tool_bad(&t, "-%c: needs a value", optopt);
			else
				tool_bad(&t, "%s: unknown option or missing value",
				    argv[optind - 1]);
		}
	}
	if (optind < argc)
		in = argv[optind++];
	if (optind < argc)
		tool_bad(&t, "%s: unexpected argument (one input file)", argv[optind]);
	if ((have_hmin || have_hmax) && !have_w)
		tool_bad(&t, "--hmin, --hmax: only with -w");
	if (width > 0 && carve_mask == NULL)
		tool_bad(&t, "--carve-width: only with --carve");
	if (have_rough_opts && carve_mask == NULL)
		tool_bad(&t, "--carve-rough, --carve-seed: only with --carve");
	if (have_hmin && have_hmax && !(hmin < hmax))
		tool_bad(&t, "--hmin %g, --hmax %g: need hmin < hmax", hmin, hmax);
	tool_check_grid_path(&t, "-o", t.out);
	tool_output(&t, "-o", t.out ? t.out : "-", 0);
	tool_output(&t, "--png", t.png, 1);
	/* -o may be the input (written atomically after reading it), not the
	 * mask; the preview is never either. */
	tool_not_input(&t, "-o", t.out, carve_mask);
	tool_not_input(&t, "--png", t.png, in);
	tool_not_input(&t, "--png", t.png, carve_mask);
	tool_usage_check(&t);

	rc_threads_wait_passively(rc_fft_set_threads(t.threads), t.argv);
	g = tool_read_grid(&t, in);
	if (have_w) {
		double dmin, dmax;
		rc_warp_default_bounds(g, &dmin, &dmax);
		if (!have_hmin)
			hmin = dmin;
		if (!have_hmax)
			hmax = dmax;
		if (rc_warp(g, w, hmin, hmax, &err) != 0)
			tool_fail(&t, "%s", err.msg);
	}
	if (flip && rc_flip(g, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	if (carve_mask != NULL) {
		rc_grid *mask = tool_read_grid(&t, carve_mask);
		if (width == 0)
			width = 4 * fmax(g->lx / (double)g->nx, g->ly / (double)g->ny);
		if (rc_carve_rough(g, mask, depth, width, rough,
		    (unsigned long)carve_seed, &err) != 0)
			tool_fail(&t, "%s: %s", carve_mask, err.msg);
		rc_grid_free(mask);
	}
	if (rmsg > 0) {
		if (rc_scale_rms_gradient(g, rmsg, &err) != 0)
			tool_fail(&t, "%s", err.msg);
	} else if (have_w || carve_mask != NULL)
		/* The generation target no longer describes the heights. */
		rc_grid_meta_unset(g, "rms_gradient");
	if (t.png != NULL && rc_png_write(g, t.png, NULL, &err) != 0)
		tool_fail(&t, "%s: %s", t.png, err.msg);
	tool_write_grid(&t, g, t.out);
	rc_grid_free(g);
	return tool_exit(&t, 0);
}
