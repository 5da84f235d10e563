/* surfstat - statistics of a height map: rms height and gradient, Nayak,
 * the structural parameters Phi1..Phi9 (Wang & Mueser 2020, section 3.2,
 * corrected as documented in surfstat(1)), C(q), the height-difference
 * ACF, and the gradient tensor by height. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "clock.h"
#include "common.h"
#include "fft.h"
#include "png.h"
#include "psd.h"
#include "spectral.h"
#include "stats.h"
#include "table.h"

enum {
	OPT_MASK = OPT_TOOL_FIRST,
	OPT_PSD,
	OPT_PSD2D,
	OPT_ACF,
	OPT_BY_HEIGHT,
	OPT_FD,
	OPT_GNUPLOT,
	OPT_BINS
};

enum table { T_SCALARS, T_PSD, T_ACF, T_BY_HEIGHT };

static void
usage(void)
{
	printf("usage: surfstat [options] [FILE]\n"
	    "  (no table option)     one row of scalars: hrms, gbar, gbar_fd, nayak,\n"
	    "                        phi1 .. phi9, ... (see surfstat(1))\n"
	    "  --psd                 radial C(q) table instead: q C n_modes stderr\n"
	    "  --acf                 height-difference ACF table instead: along x, y, radial\n"
	    "  --by-height N         gbar and gradient tensor in N height bins instead\n"
	    "  --bins-per-decade N   logarithmic q bins for --psd, --gnuplot (default 10)\n"
	    "  --psd2d FILE          also write the 2D spectrum as a grid (kind spectrum)\n"
	    "  --gnuplot FILE        also write a gnuplot script plotting C(q) to PNG\n"
	    "  --mask FILE           average over the points where the mask is 1\n"
	    "  --fd                  finite-difference derivatives (default spectral)\n"
	    "  --png FILE            PNG preview of the surface\n"
	    "  --fft-effort E        estimate, measure or patient FFT planning (default:\n"
	    "                        estimate, or measure for big grids with --wisdom)\n"
	    "  --wisdom FILE         load FFTW wisdom, save it after planning ($RC_WISDOM)\n"
	    "  -o FILE               table output (default stdout)   --json  JSON\n"
	    "  -L LX[xLY]            cell size of an input that has none\n"
	    "  -j N  threads   -q  quiet   -h, --help   --version\n");
}

static const struct option longopts[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ "json", no_argument, NULL, OPT_JSON },
	{ "png", required_argument, NULL, OPT_PNG },
	TOOL_FFT_LONGOPTS,
	{ "mask", required_argument, NULL, OPT_MASK },
	{ "psd", no_argument, NULL, OPT_PSD },
	{ "psd2d", required_argument, NULL, OPT_PSD2D },
	{ "acf", no_argument, NULL, OPT_ACF },
	{ "by-height", required_argument, NULL, OPT_BY_HEIGHT },
	{ "fd", no_argument, NULL, OPT_FD },
	{ "gnuplot", required_argument, NULL, OPT_GNUPLOT },
	{ "bins-per-decade", required_argument, NULL, OPT_BINS },
	{ NULL, 0, NULL, 0 }
};

struct out {
	rc_atomic file;
	rc_table_out table;
};

static void
out_open(const struct tool *t, struct out *o)
{
	rc_err err;

	if (rc_atomic_open(&o->file, t->out, &err) != 0)
		tool_fail(t, "%s: %s", t->out, err.msg);
	rc_table_begin(&o->table, o->file.fp, t->json);
}

static void
out_row(const struct tool *t, struct out *o, const rc_row *r)
{
	rc_err err;

	if (rc_table_write(&o->table, r, &err) != 0) {
		rc_atomic_abort(&o->file);
		tool_fail(t, "%s: %s", t->out ? t->out : "standard output", err.msg);
	}
}

static void
out_close(const struct tool *t, struct out *o)
{
	rc_err err;

	if (rc_table_end(&o->table, &err) != 0 ||
	    rc_atomic_commit(&o->file, &err) != 0) {
		rc_atomic_abort(&o->file);
		tool_fail(t, "%s: %s", t->out ? t->out : "standard output", err.msg);
	}
}

/* Row building never fails short of memory exhaustion. */
static void
num(const struct tool *t, rc_row *r, const char *name, double v)
{
	if (rc_row_num(r, name, v) != 0)
		tool_fail(t, "out of memory");
}

static void
scalars(const struct tool *t, const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft)
{
	rc_stats s;
	rc_err err;
	rc_row r;
	struct out o;
	double gbar, seconds;
	char name[8];

	seconds = rc_clock();
	if (rc_rms_gradient(g, fft, &gbar, &err) != 0 ||
	    rc_stats_compute_fft(g, mask, m, fft, &s, &err) != 0)
		tool_fail(t, "%s", err.msg);
	seconds = rc_clock() - seconds;
	rc_row_init(&r);
	if (rc_row_int(&r, "nx", (long long)g->nx) != 0 ||
	    rc_row_int(&r, "ny", (long long)g->ny) != 0 ||
	    rc_row_str(&r, "derivatives", rc_deriv_method_name(m)) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "lx", g->lx);
	num(t, &r, "ly", g->ly);
	num(t, &r, "mean", s.mean);
	num(t, &r, "hrms", s.hrms);
	num(t, &r, "gbar", gbar);
	num(t, &r, "gbar_fd", rc_gbar_fd(g));
	num(t, &r, "rms_laplacian", s.rms_laplacian);
	num(t, &r, "skewness", s.skewness);
	num(t, &r, "kurtosis", s.kurtosis);
	num(t, &r, "hmin", s.hmin);
	num(t, &r, "hmax", s.hmax);
	num(t, &r, "range", s.hmax - s.hmin);
	num(t, &r, "nayak", s.nayak);
	for (int i = 1; i <= 9; i++) {
		snprintf(name, sizeof(name), "phi%d", i);
		num(t, &r, name, s.phi[i]);
	}
	if (mask != NULL) {
		if (rc_row_int(&r, "n_c", (long long)s.n_avg) != 0)
			tool_fail(t, "out of memory");
		num(t, &r, "contact_fraction", s.fraction);
		num(t, &r, "gbar_c", s.gbar);
		num(t, &r, "gbar_c_prime", s.gbar_prime);
	}
	num(t, &r, "plan_seconds", fft->plan_seconds);
	num(t, &r, "seconds", seconds);
	if (rc_row_meta(&r, g) != 0)
		tool_fail(t, "out of memory");
	out_open(t, &o);
	out_row(t, &o, &r);
	out_close(t, &o);
	rc_row_free(&r);
}

static void
psd_table(const struct tool *t, const rc_psd_bin *b, size_t nb)
{
	struct out o;
	rc_row r;

	rc_row_init(&r);
	out_open(t, &o);
	for (size_t k = 0; k < nb; k++) {
		rc_row_clear(&r);
		num(t, &r, "q", b[k].q);
		num(t, &r, "C", b[k].c);
		if (rc_row_int(&r, "n_modes", (long long)b[k].n_modes) != 0)
			tool_fail(t, "out of memory");
		num(t, &r, "stderr", b[k].std_err);
		out_row(t, &o, &r);
	}
	out_close(t, &o);
	rc_row_free(&r);
}

static void
acf_table(const struct tool *t, const rc_grid *g, rc_fft *fft)
{
	rc_acf_point *p;
	size_t np;
	rc_err err;
	struct out o;
	rc_row r;

	if (rc_acf(g, fft, &p, &np, &err) != 0)
		tool_fail(t, "%s", err.msg);
	rc_row_init(&r);
	out_open(t, &o);
	for (size_t k = 0; k < np; k++) {
		rc_row_clear(&r);
		if (rc_row_str(&r, "direction", rc_acf_dir_name(p[k].dir)) != 0)
			tool_fail(t, "out of memory");
		num(t, &r, "r", p[k].r);
		num(t, &r, "hdacf", p[k].g);
		if (rc_row_int(&r, "n", (long long)p[k].n) != 0)
			tool_fail(t, "out of memory");
		out_row(t, &o, &r);
	}
	out_close(t, &o);
	rc_row_free(&r);
	free(p);
}

static void
height_table(const struct tool *t, const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, size_t nbins)
{
	rc_height_bin *b;
	rc_err err;
	struct out o;
	rc_row r;
	size_t total = 0;

	if ((b = rc_malloc(nbins * sizeof(*b), &err)) == NULL ||
	    rc_stats_by_height_fft(g, mask, m, fft, nbins, b, &err) != 0)
		tool_fail(t, "%s", err.msg);
	for (size_t k = 0; k < nbins; k++)
		total += b[k].n;
	rc_row_init(&r);
	out_open(t, &o);
	for (size_t k = 0; k < nbins; k++) {
		rc_row_clear(&r);
		num(t, &r, "h_lo", b[k].h_lo);
		num(t, &r, "h_hi", b[k].h_hi);
		num(t, &r, "h_mid", b[k].h_mid);
		if (rc_row_int(&r, "n", (long long)b[k].n) != 0)
			tool_fail(t, "out of memory");
		num(t, &r, "fraction", (double)b[k].n / (double)total);
		num(t, &r, "gbar", b[k].gbar);
		num(t, &r, "gxx", b[k].mxx);
		num(t, &r, "gyy", b[k].myy);
		num(t, &r, "gxy", b[k].mxy);
		if (rc_row_str(&r, "derivatives", rc_deriv_method_name(m)) != 0)
			tool_fail(t, "out of memory");
		out_row(t, &o, &r);
	}
	out_close(t, &o);
	rc_row_free(&r);
	free(b);
}

/* A self-contained gnuplot script: the table as a data block, log-log
 * axes, error bars, output to the script's name with .png. */
static void
gnuplot_script(const struct tool *t, const char *path, const rc_grid *g,
    const rc_psd_bin *b, size_t nb)
{
	rc_atomic a;
	rc_err err;
	char *png;
	size_t len = strlen(path);

	if ((png = malloc(len + 5)) == NULL)
		tool_fail(t, "out of memory");
	strcpy(png, path);
	if (len > 3 && strcmp(png + len - 3, ".gp") == 0)
		png[len - 3] = '\0';
	strcat(png, ".png");
	if (rc_atomic_open(&a, path, &err) != 0)
		tool_fail(t, "%s: %s", path, err.msg);
	fprintf(a.fp, "# C(q) written by surfstat %s\n"
	    "# convention: C(q) = (2pi)^-2 int d^2r <h(0)h(r)> exp(-iq.r);\n"
	    "# contact.engineering (Jacobs, Junge, Pastewka 2017) uses (2pi)^2 C(q)\n"
	    "$psd << EOD\n# q C n_modes stderr\n", RC_VERSION);
	/* Bins outside the surface's band hold FFT round-off, ~1e-30 of
	 * the peak: leave them out of the plot. */
	double cmax = 0;
	for (size_t k = 0; k < nb; k++)
		cmax = fmax(cmax, b[k].c);
	for (size_t k = 0; k < nb; k++)
		if (b[k].c > 1e-20 * cmax)
			fprintf(a.fp, "%.17g %.17g %zu %.17g\n", b[k].q, b[k].c,
			    b[k].n_modes, b[k].std_err);
	fprintf(a.fp, "EOD\n"
	    "set terminal pngcairo size 800,600\n"
	    "set output '%s'\n"
	    "set logscale xy\n"
	    "set format y '10^{%%L}'\n"
	    "set xlabel 'q (1/%s)'\n"
	    "set ylabel 'C(q)'\n"
	    "set title 'radially averaged spectrum, %zux%zu, L = %gx%g'\n"
	    "plot $psd using 1:2:4 with yerrorbars pt 7 ps 0.5 title 'C(q)'\n",
	    png, g->unit[0] ? g->unit : "length", g->nx, g->ny, g->lx, g->ly);
	free(png);
	if (ferror(a.fp) || rc_atomic_commit(&a, &err) != 0) {
		rc_atomic_abort(&a);
		tool_fail(t, "%s: %s", path, ferror(a.fp) ? "write error" : err.msg);
	}
}

int
main(int argc, char **argv)
{
	struct tool t;
	const char *mask_path = NULL, *psd2d = NULL, *gp = NULL, *in = NULL;
	enum table table = T_SCALARS;
	enum rc_deriv_method method = RC_DERIV_SPECTRAL;
	int ntables = 0, opt;
	size_t nbins = 0;
	double bpd = 10;
	long v;
	rc_grid *g, *mask = NULL;
	rc_fft fft, *plan;
	rc_err err;

	tool_init(&t, "surfstat", argc, argv);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "ho:j:qL:", longopts, NULL)) != -1) {
		if (tool_common_option(&t, opt, optarg))
			continue;
		switch (opt) {
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case OPT_MASK:
			mask_path = optarg;
			break;
		case OPT_PSD:
			table = T_PSD;
			ntables++;
			break;
		case OPT_ACF:
			table = T_ACF;
			ntables++;
			break;
		case OPT_BY_HEIGHT:
			table = T_BY_HEIGHT;
			ntables++;
			if (tool_long(&t, "--by-height", optarg, &v) == 0) {
				if (v < 1 || v > 1000000)
					tool_bad(&t, "--by-height %s: want 1 to 1000000 bins",
					    optarg);
				else
					nbins = (size_t)v;
			}
			break;
		case OPT_PSD2D:
			psd2d = optarg;
			break;
		case OPT_GNUPLOT:
			gp = optarg;
			break;
		case OPT_FD:
			method = RC_DERIV_FD;
			break;
		case OPT_BINS:
			if (tool_double(&t, "--bins-per-decade", optarg, &bpd) == 0 &&
			    !(bpd >= 1 && bpd <= 1000))
				tool_bad(&t, "--bins-per-decade %s: want 1 to 1000", optarg);
			break;
		default:
			if (optopt != 0 && strchr("ojL", optopt) != NULL)
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
	if (ntables > 1)
		tool_bad(&t, "--psd, --acf, --by-height: choose one table per run");
	if (mask_path != NULL && (table == T_PSD || table == T_ACF))
		tool_bad(&t, "--mask: applies to the scalar row and --by-height, "
		    "not to spectra or the ACF");
	if (method == RC_DERIV_FD && (table == T_PSD || table == T_ACF))
		tool_bad(&t, "--fd: applies to the scalar row and --by-height only");
	if (psd2d != NULL)
		tool_check_grid_path(&t, "--psd2d", psd2d);
	tool_output(&t, "-o", t.out ? t.out : "-", 0);
	tool_output(&t, "--psd2d", psd2d, 0);
	tool_output(&t, "--gnuplot", gp, 0);
	tool_output(&t, "--png", t.png, 1);
	{
		const char *outs[] = { t.out, psd2d, gp, t.png };
		const char *opts[] = { "-o", "--psd2d", "--gnuplot", "--png" };

		for (int k = 0; k < 4; k++) {
			tool_not_input(&t, opts[k], outs[k], in);
			tool_not_input(&t, opts[k], outs[k], mask_path);
		}
	}
	tool_usage_check(&t);

	tool_fft_setup(&t);
	g = tool_read_grid(&t, in);
	if (mask_path != NULL) {
		mask = tool_read_grid(&t, mask_path);
		if (rc_mask_check(mask, g, &err) == 0)
			tool_fail(&t, "%s: %s", mask_path, err.msg);
	}
	if (t.png != NULL && rc_png_write(g, t.png, NULL, &err) != 0)
		tool_fail(&t, "%s: %s", t.png, err.msg);
	/* One plan for every transform of the run (a handful: the scalars
	 * take nine), made after the mask so that planning never waits on
	 * input that turns out bad. */
	memset(&fft, 0, sizeof(fft));
	if ((table != T_BY_HEIGHT || method == RC_DERIV_SPECTRAL || psd2d != NULL ||
	    gp != NULL) && rc_fft_init(&fft, g->nx, g->ny,
	    tool_fft_effort(&t, g->nx, g->ny, 5), &err) != 0)
		tool_fail(&t, "%s", err.msg);
	plan = fft.nx ? &fft : NULL;
	tool_fft_finish(&t);
	if (!t.quiet && plan && fft.effort != RC_FFT_ESTIMATE && table != T_SCALARS)
		tool_warn(&t, "FFT plan %zux%zu (%s): %.3g s", g->nx, g->ny,
		    rc_fft_effort_name(fft.effort), fft.plan_seconds);
	if (psd2d != NULL) {
		rc_grid *s = rc_psd2d(g, plan, &err);
		if (s == NULL)
			tool_fail(&t, "%s", err.msg);
		tool_write_grid(&t, s, psd2d);
		rc_grid_free(s);
	}
	if (table == T_PSD || gp != NULL) {
		rc_psd_bin *b;
		size_t nb;
		if (rc_psd_radial(g, plan, bpd, &b, &nb, &err) != 0)
			tool_fail(&t, "%s", err.msg);
		if (gp != NULL)
			gnuplot_script(&t, gp, g, b, nb);
		if (table == T_PSD)
			psd_table(&t, b, nb);
		free(b);
	}
	switch (table) {
	case T_SCALARS:
		scalars(&t, g, mask, method, plan);
		break;
	case T_ACF:
		acf_table(&t, g, plan);
		break;
	case T_BY_HEIGHT:
		height_table(&t, g, mask, method, plan, nbins);
		break;
	case T_PSD:
		break;
	}
	rc_fft_free(&fft);
	rc_grid_free(mask);
	rc_grid_free(g);
	return tool_exit(&t, 0);
}
