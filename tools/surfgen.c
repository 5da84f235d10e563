/* surfgen - make a height map: self-affine random roughness (Eqs. 2, 3 of
 * Wang & Mueser 2020), harmonic indenters (Eq. 5), sine, egg box, flat. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "fft.h"
#include "png.h"
#include "surfgen_opts.h"

static void
usage(void)
{
	printf("usage: surfgen [-n NX[xNY]] [-L LX[xLY]] [--type TYPE] [-o FILE] [--png FILE]\n"
	    "               [-j N] [-q] [-h] [--version] [type options]\n"
	    "  -n NX[xNY]            grid points (default 256)\n"
	    "  -L LX[xLY]            cell size (default 1)\n"
	    "  --type T              selfaffine (default), harmonic, sine, eggbox, flat\n"
	    " selfaffine:\n"
	    "  -H H                  Hurst exponent in (0, 1) (default 0.8)\n"
	    "  --lambda-r L          roll-off wavelength (default the longer cell side)\n"
	    "  --lambda-s L          short-wavelength cutoff (default and least: two grid\n"
	    "                        spacings, max(2 dx/G, 2 dy G) with --peklenik G)\n"
	    "  --rolloff             C(q) flat below q_r instead of zero\n"
	    "  --peklenik G          Peklenik anisotropy (default 1, isotropic)\n"
	    "  --seed S              random seed, 0 to 2^64-1 (default 1)\n"
	    "  --gaussian-amplitudes Rayleigh moduli instead of sqrt(C)\n"
	    "  --rms-gradient G      normalise to rms gradient G (default 1)\n"
	    "  --rms-height H        normalise to rms height H instead\n"
	    " harmonic:  --exponent N (default 2)  --radius R (default 1)\n"
	    " sine, eggbox:  --wavelength W (default LX)  --amplitude A (default 1)\n"
	    "  (--rms-gradient/--rms-height rescale these types too when given)\n"
	    "  -o FILE               output (.surf .npy .gsf .txt; default stdout, surf)\n"
	    "  --png FILE            PNG preview\n"
	    "  --fft-effort E        estimate (default), measure or patient FFT planning\n"
	    "  --wisdom FILE         load FFTW wisdom, save it after planning (default\n"
	    "                        $RC_WISDOM); with it, big grids are planned with measure\n"
	    "  -j N  threads   -q  quiet   -h, --help   --version\n");
}

static const struct option longopts[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ "png", required_argument, NULL, OPT_PNG },
	TOOL_FFT_LONGOPTS,
	SURFGEN_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

int
main(int argc, char **argv)
{
	struct tool t;
	struct surfgen_opts o;
	rc_synth_params *p = &o.p;
	rc_err err;
	rc_grid *g;
	int opt;
	double plan_seconds, seconds;
	enum rc_fft_effort effort;

	tool_init(&t, "surfgen", argc, argv);
	surfgen_opts_init(&o);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "hn:L:H:o:j:q", longopts, NULL)) != -1) {
		if (opt == 'h') {
			usage();
			return tool_exit(&t, 0);
		}
		if ((opt != 'L' && tool_common_option(&t, opt, optarg)) ||
		    surfgen_option(&t, &o, opt, optarg))
			continue;
		if (optopt != 0 && strchr("nLHoj", optopt) != NULL)
			tool_bad(&t, "-%c: needs a value", optopt);
		else
			tool_bad(&t, "%s: unknown option or missing value",
			    argv[optind - 1]);
	}
	if (optind < argc)
		tool_bad(&t, "%s: unexpected argument (surfgen reads no input)", argv[optind]);
	surfgen_opts_check(&t, &o);
	tool_check_grid_path(&t, "-o", t.out);
	tool_output(&t, "-o", t.out ? t.out : "-", 0);
	tool_output(&t, "--png", t.png, 1);
	tool_usage_check(&t);

	tool_fft_setup(&t);
	effort = tool_fft_effort(&t, p->nx, p->ny, 1);
	seconds = rc_clock();
	if ((g = rc_synth_planned(p, effort, &plan_seconds, &err)) == NULL)
		tool_fail(&t, "%s", err.msg);
	seconds = rc_clock() - seconds;
	/* Planning time is worth a line only when it was asked for. */
	if (!t.quiet && (effort == RC_FFT_MEASURE || effort == RC_FFT_PATIENT))
		tool_warn(&t, "FFT plan %zux%zu (%s): %.3g s; synthesis: %.3g s",
		    p->nx, p->ny, rc_fft_effort_name(effort), plan_seconds,
		    seconds - plan_seconds);
	tool_fft_finish(&t);
	if (t.png != NULL && rc_png_write(g, t.png, NULL, &err) != 0)
		tool_fail(&t, "%s: %s", t.png, err.msg);
	tool_write_grid(&t, g, t.out);
	rc_grid_free(g);
	return tool_exit(&t, 0);
}
