/* surfgen - make a height map: self-affine random roughness (Eqs. 2, 3 of
 * Wang & Mueser 2020), harmonic indenters (Eq. 5), sine, egg box, flat. */
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "common.h"
#include "fft.h"
#include "png.h"
#include "synth.h"

enum {
	OPT_LAMBDA_R = OPT_TOOL_FIRST,
	OPT_LAMBDA_S,
	OPT_ROLLOFF,
	OPT_PEKLENIK,
	OPT_SEED,
	OPT_RMS_GRADIENT,
	OPT_RMS_HEIGHT,
	OPT_GAUSSIAN,
	OPT_TYPE,
	OPT_EXPONENT,
	OPT_RADIUS,
	OPT_WAVELENGTH,
	OPT_AMPLITUDE
};

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
	{ "lambda-r", required_argument, NULL, OPT_LAMBDA_R },
	{ "lambda-s", required_argument, NULL, OPT_LAMBDA_S },
	{ "rolloff", no_argument, NULL, OPT_ROLLOFF },
	{ "peklenik", required_argument, NULL, OPT_PEKLENIK },
	{ "seed", required_argument, NULL, OPT_SEED },
	{ "rms-gradient", required_argument, NULL, OPT_RMS_GRADIENT },
	{ "rms-height", required_argument, NULL, OPT_RMS_HEIGHT },
	{ "gaussian-amplitudes", no_argument, NULL, OPT_GAUSSIAN },
	{ "type", required_argument, NULL, OPT_TYPE },
	{ "exponent", required_argument, NULL, OPT_EXPONENT },
	{ "radius", required_argument, NULL, OPT_RADIUS },
	{ "wavelength", required_argument, NULL, OPT_WAVELENGTH },
	{ "amplitude", required_argument, NULL, OPT_AMPLITUDE },
	{ NULL, 0, NULL, 0 }
};

/* A positive option value into *v; a bad one is reported and leaves *v
 * at its default, so the library's cross checks still see sane values. */
static void
positive(struct tool *t, const char *opt, const char *arg, double *v)
{
	double d;

	if (tool_double(t, opt, arg, &d) != 0)
		return;
	if (!(d > 0))
		tool_bad(t, "%s %s: must be positive", opt, arg);
	else
		*v = d;
}

static void
parse_seed(struct tool *t, const char *arg, uint64_t *seed)
{
	char *end;
	unsigned long long s;

	if (arg[0] == '-' || arg[0] == '+' || arg[0] == '\0') {
		tool_bad(t, "--seed %s: want an integer 0 to 2^64-1", arg);
		return;
	}
	errno = 0;
	s = strtoull(arg, &end, 10);
	if (*end != '\0' || errno == ERANGE)
		tool_bad(t, "--seed %s: want an integer 0 to 2^64-1", arg);
	else
		*seed = (uint64_t)s;
}

int
main(int argc, char **argv)
{
	struct tool t;
	rc_synth_params p;
	rc_err err;
	rc_grid *g;
	int opt, type, have_h = 0, have_lr = 0, have_ls = 0, have_rolloff = 0;
	int have_pek = 0, have_seed = 0, have_gauss = 0, have_exp = 0, have_rad = 0;
	int have_wave = 0, have_amp = 0;
	double v, plan_seconds;
	enum rc_fft_effort effort;
	struct timespec t0, t1;

	tool_init(&t, "surfgen", argc, argv);
	rc_synth_defaults(&p);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "hn:L:H:o:j:q", longopts, NULL)) != -1) {
		if (opt != 'L' && tool_common_option(&t, opt, optarg))
			continue;
		switch (opt) {
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case 'n':
			tool_size_pair(&t, "-n", optarg, &p.nx, &p.ny);
			break;
		case 'L':
			tool_length_pair(&t, "-L", optarg, &p.lx, &p.ly);
			break;
		case 'H':
			if (tool_double(&t, "-H", optarg, &v) != 0)
				;
			else if (!(v > 0 && v < 1))
				tool_bad(&t, "-H %s: the Hurst exponent must be in (0, 1)", optarg);
			else
				p.hurst = v;
			have_h = 1;
			break;
		case OPT_LAMBDA_R:
			positive(&t, "--lambda-r", optarg, &p.lambda_r);
			have_lr = 1;
			break;
		case OPT_LAMBDA_S:
			positive(&t, "--lambda-s", optarg, &p.lambda_s);
			have_ls = 1;
			break;
		case OPT_ROLLOFF:
			p.rolloff = 1;
			have_rolloff = 1;
			break;
		case OPT_PEKLENIK:
			positive(&t, "--peklenik", optarg, &p.peklenik);
			have_pek = 1;
			break;
		case OPT_SEED:
			parse_seed(&t, optarg, &p.seed);
			have_seed = 1;
			break;
		case OPT_RMS_GRADIENT:
			positive(&t, "--rms-gradient", optarg, &p.rms_gradient);
			break;
		case OPT_RMS_HEIGHT:
			positive(&t, "--rms-height", optarg, &p.rms_height);
			break;
		case OPT_GAUSSIAN:
			p.gaussian_amplitudes = 1;
			have_gauss = 1;
			break;
		case OPT_TYPE:
			if ((type = rc_surface_type_parse(optarg)) < 0)
				tool_bad(&t, "--type %s: want selfaffine, harmonic, sine, "
				    "eggbox or flat", optarg);
			else
				p.type = (enum rc_surface_type)type;
			break;
		case OPT_EXPONENT:
			positive(&t, "--exponent", optarg, &p.exponent);
			have_exp = 1;
			break;
		case OPT_RADIUS:
			positive(&t, "--radius", optarg, &p.radius);
			have_rad = 1;
			break;
		case OPT_WAVELENGTH:
			positive(&t, "--wavelength", optarg, &p.wavelength);
			have_wave = 1;
			break;
		case OPT_AMPLITUDE:
			if (tool_double(&t, "--amplitude", optarg, &v) == 0)
				p.amplitude = v;
			have_amp = 1;
			break;
		default:
			if (optopt != 0 && strchr("nLHoj", optopt) != NULL)
				tool_bad(&t, "-%c: needs a value", optopt);
			else
				tool_bad(&t, "%s: unknown option or missing value",
				    argv[optind - 1]);
			break;
		}
	}
	if (optind < argc)
		tool_bad(&t, "%s: unexpected argument (surfgen reads no input)", argv[optind]);
	if (p.rms_gradient > 0 && p.rms_height > 0)
		tool_bad(&t, "--rms-gradient and --rms-height: give one, not both");
	/* Options that the chosen type would ignore are mistakes. */
	if (p.type != RC_SURF_SELFAFFINE) {
		const char *name = rc_surface_type_name(p.type);
		if (have_h || have_lr || have_ls || have_rolloff || have_pek || have_seed ||
		    have_gauss)
			tool_bad(&t, "-H, --lambda-r, --lambda-s, --rolloff, --peklenik, "
			    "--seed, --gaussian-amplitudes: only for --type selfaffine, "
			    "not %s", name);
	}
	if (p.type != RC_SURF_HARMONIC && (have_exp || have_rad))
		tool_bad(&t, "--exponent, --radius: only for --type harmonic");
	if (p.type != RC_SURF_SINE && p.type != RC_SURF_EGGBOX && (have_wave || have_amp))
		tool_bad(&t, "--wavelength, --amplitude: only for --type sine or eggbox");
	tool_check_grid_path(&t, "-o", t.out);
	tool_output(&t, "-o", t.out ? t.out : "-", 0);
	tool_output(&t, "--png", t.png, 1);
	/* The library's check catches the cross conditions (lambda_s against
	 * the grid, lambda_r > lambda_s, wavelengths that must divide the
	 * cell); values reported above are still at their defaults here. */
	if (!(p.rms_gradient > 0 && p.rms_height > 0) && rc_synth_check(&p, &err) != 0)
		tool_bad(&t, "%s", err.msg);
	tool_usage_check(&t);

	tool_fft_setup(&t);
	effort = tool_fft_effort(&t, p.nx, p.ny, 1);
	clock_gettime(CLOCK_MONOTONIC, &t0);
	if ((g = rc_synth_planned(&p, effort, &plan_seconds, &err)) == NULL)
		tool_fail(&t, "%s", err.msg);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	/* Planning time is worth a line only when it was asked for. */
	if (!t.quiet && (effort == RC_FFT_MEASURE || effort == RC_FFT_PATIENT))
		tool_warn(&t, "FFT plan %zux%zu (%s): %.3g s; synthesis: %.3g s",
		    p.nx, p.ny, rc_fft_effort_name(effort), plan_seconds,
		    (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec -
		    t0.tv_nsec) - plan_seconds);
	tool_fft_finish(&t);
	if (t.png != NULL && rc_png_write(g, t.png, NULL, &err) != 0)
		tool_fail(&t, "%s: %s", t.png, err.msg);
	tool_write_grid(&t, g, t.out);
	rc_grid_free(g);
	return tool_exit(&t, 0);
}
