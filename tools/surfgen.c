/* SPDX-License-Identifier: GPL-3.0-or-later */
/* surfgen - make a height map: self-affine random roughness (Eqs. 2, 3 of
 * Wang & Mueser 2020), harmonic indenters (Eq. 5), sine, egg box, flat;
 * or a periodic self-affine surface like a measured one (--like). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "atomic.h"
#include "clock.h"
#include "fft.h"
#include "fit.h"
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
	    "  --like FILE           self-affine like FILE: a surfstat --fit table, or a\n"
	    "                        surface (fitted as surfstat --fit does): H, lambda_r,\n"
	    "                        lambda_s, rolloff, rms height and (unless -n, -L)\n"
	    "                        the grid from the fit, in the fit's length unit\n"
	    "                        (-L in that unit too); --seed picks the realisation\n"
	    "  -o FILE               output (.surf .npy .gsf .txt .x3p .nc; default\n"
	    "                        stdout, surf)\n"
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
	{ "like", required_argument, NULL, OPT_TOOL_FIRST + 90 },
	{ NULL, 0, NULL, 0 }
};

#define OPT_LIKE (OPT_TOOL_FIRST + 90)

/* The fit of --like FILE: a fit table, else a surface fitted here. */
static void
load_like(struct tool *t, const char *path, rc_selfaffine_fit *f, size_t *nx, size_t *ny,
    double *lx, double *ly, char *advice, size_t advice_len)
{
	FILE *fp = fopen(path, "rb");
	char head[4096];
	size_t n;
	rc_err err;
	int r;

	if (fp == NULL)
		tool_fail(t, "--like %s: cannot open", path);
	n = fread(head, 1, sizeof(head) - 1, fp);
	fclose(fp);
	head[n] = '\0';
	if ((r = rc_fit_table_parse(head, f, nx, ny, lx, ly, &err)) < 0)
		tool_fail(t, "--like %s: %s", path, err.msg);
	if (r == 0) {
		rc_grid *g = tool_read_grid(t, path);
		rc_fit_opts fo;
		rc_fit_opts_default(&fo);
		if (rc_fit_selfaffine(g, NULL, &fo, f, &err) != 0)
			tool_fail(t, "--like %s: %s", path, err.msg);
		rc_fit_advice(f, fmax(g->lx, g->ly), advice, advice_len);
		*nx = g->nx;
		*ny = g->ny;
		*lx = g->lx;
		*ly = g->ly;
		rc_grid_free(g);
	}
}

/* Everything one run holds, so that main reads as the run's steps. */
struct run {
	struct tool t;
	struct surfgen_opts o;
	const char *like;		/* --like FILE, or NULL */
	int have_n, have_l;		/* -n, -L given (they win over --like) */
	char like_unit[32];		/* the fit's length unit: the twin's */
	char advice[1024];		/* rc_fit_advice of a map fitted here */
};

/* --like: the parameters of the self-affine fit of the measurement
 * (the grid's size and cell unless -n, -L say otherwise). */
static void
like_params(struct run *r)
{
	rc_synth_params *p = &r->o.p;
	rc_selfaffine_fit f;
	size_t nx, ny;
	double lx, ly;
	rc_err err;

	tool_input(&r->t, "--like", r->like);	/* checked with the outputs */
	tool_usage_check(&r->t);
	gsl_set_error_handler_off();
	load_like(&r->t, r->like, &f, &nx, &ny, &lx, &ly, r->advice,
	    sizeof(r->advice));
	if (!r->have_n) {
		p->nx = nx;
		p->ny = ny;
	}
	if (!r->have_l) {
		p->lx = lx;
		p->ly = ly;
	}
	p->type = RC_SURF_SELFAFFINE;
	p->hurst = f.H;
	p->lambda_r = 2 * M_PI / f.q_r;
	p->lambda_s = 2 * M_PI / f.q_s;
	p->rolloff = f.rolloff;
	p->rms_height = f.hrms;
	p->rms_gradient = 0;
	memcpy(r->like_unit, f.unit, sizeof(r->like_unit));
	/* A cutoff below two spacings of the new grid is the grid's own
	 * limit (the fit's q_s may be its range end, the Nyquist wave number
	 * of the measurement). */
	if (p->lambda_s < 2 * fmax(p->lx / (double)p->nx, p->ly / (double)p->ny))
		p->lambda_s = 0;
	if (!(f.H > 0 && f.H < 1))
		tool_fail(&r->t, "--like %s: the fit's H = %.4g is outside 0 < H < 1, "
		    "the self-affine surfaces surfgen makes: the map's spectrum is "
		    "not self-affine on the range fitted; fit a narrower one "
		    "(surfstat --fit --min-wavelength, --max-wavelength: its "
		    "warning names a range that is, if there is one)%s%s", r->like,
		    f.H, r->advice[0] ? ": " : "", r->advice);
	if (rc_synth_check(p, &err) != 0)
		tool_fail(&r->t, "--like %s: the fitted model cannot be made: %s",
		    r->like, err.msg);
}

/* What --like took from the fit, said once the run will not be
 * restarted (tool_fft_setup may re-execute the tool: a message before
 * it would be written twice). */
static void
like_report(const struct run *r)
{
	const rc_synth_params *p = &r->o.p;

	if (r->like == NULL || r->t.quiet)
		return;
	if (r->advice[0])
		tool_warn(&r->t, "--like %s: %s", r->like, r->advice);
	tool_warn(&r->t, "--like %s: H = %.4g, lambda_r = %.4g%s, "
	    "lambda_s = %.4g, rms height %.4g%s%s", r->like, p->hurst,
	    p->lambda_r, p->rolloff ? " (roll-off)" : "",
	    rc_synth_lambda_s(p), p->rms_height,
	    r->like_unit[0] ? "; lengths in " : "", r->like_unit);
}

/* Options into r->o, checked together; 1 after --help. */
static int
parse_options(struct run *r, int argc, char **argv)
{
	struct tool *t = &r->t;
	int opt, spectrum_opts = 0, help = 0;

	tool_init(t, "surfgen", argc, argv);
	surfgen_opts_init(&r->o);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "hn:L:H:o:j:q", longopts, NULL)) != -1) {
		if (opt == 'h') {
			help = 1;
			continue;
		}
		if (opt == OPT_LIKE) {
			r->like = optarg;
			continue;
		}
		r->have_n |= opt == 'n';
		r->have_l |= opt == 'L';
		spectrum_opts |= opt == 'H' || opt == OPT_LAMBDA_R || opt == OPT_LAMBDA_S ||
		    opt == OPT_ROLLOFF || opt == OPT_RMS_GRADIENT || opt == OPT_RMS_HEIGHT ||
		    opt == OPT_TYPE;
		if ((opt != 'L' && tool_common_option(t, opt, optarg)) ||
		    surfgen_option(t, &r->o, opt, optarg))
			continue;
		tool_bad_option(t, "hn:L:H:o:j:q", longopts, argv);
	}
	if (help && tool_help_check(t)) {
		usage();
		return 1;
	}
	if (optind < argc)
		tool_bad(t, "%s: unexpected argument (surfgen reads no input)", argv[optind]);
	if (r->like != NULL && spectrum_opts)
		tool_bad(t, "--like: takes H, lambda_r, lambda_s, rolloff and the rms "
		    "height from the fit; -H, --lambda-r, --lambda-s, --rolloff, "
		    "--rms-gradient, --rms-height and --type do not go with it");
	if (r->like != NULL)
		like_params(r);
	surfgen_opts_check(t, &r->o);
	tool_check_grid_path(t, "-o", t->out);
	tool_output(t, "-o", t->out ? t->out : "-", 0);
	tool_output(t, "--png", t->png, 1);
	tool_usage_check(t);
	return 0;
}

/* The surface made, timed, written (and previewed). */
static void
generate(struct run *r)
{
	struct tool *t = &r->t;
	const rc_synth_params *p = &r->o.p;
	enum rc_fft_effort effort;
	double plan_seconds, seconds;
	rc_err err;
	rc_grid *g;

	tool_fft_setup(t);
	like_report(r);
	effort = tool_fft_effort(t, p->nx, p->ny, 1);
	seconds = rc_clock();
	if ((g = rc_synth_planned(p, effort, &plan_seconds, &err)) == NULL)
		tool_fail(t, "%s", err.msg);
	seconds = rc_clock() - seconds;
	memcpy(g->unit, r->like_unit, sizeof(g->unit));
	/* Planning time is worth a line only when it was asked for. */
	if (!t->quiet && (effort == RC_FFT_MEASURE || effort == RC_FFT_PATIENT))
		tool_warn(t, "FFT plan %zux%zu (%s): %.3g s; synthesis: %.3g s",
		    p->nx, p->ny, rc_fft_effort_name(effort), plan_seconds,
		    seconds - plan_seconds);
	tool_fft_finish(t);
	if (t->png != NULL && rc_png_write(g, t->png, NULL, &err) != 0)
		tool_fail_at(t, t->png, err.msg);
	tool_write_grid(t, g, t->out);
	rc_grid_free(g);
}

int
main(int argc, char **argv)
{
	struct run r;

	memset(&r, 0, sizeof(r));
	if (parse_options(&r, argc, argv))
		return tool_exit(&r.t, 0);
	generate(&r);
	return tool_exit(&r.t, 0);
}
