/* SPDX-License-Identifier: GPL-3.0-or-later */
/* surfstat - statistics of a height map: rms height and gradient, Nayak,
 * the structural parameters Phi1..Phi9 (Wang & Mueser 2020, section 3.2,
 * corrected as documented in surfstat(1)), C(q) (windowed on finite
 * patches), 1D spectra, the height-difference ACF, the gradient tensor by
 * height, ISO 25178 parameters, the material ratio curve and the fit of
 * the self-affine model of Eq. 2. */
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "clock.h"
#include "common.h"
#include <gsl/gsl_errno.h>

#include "fft.h"
#include "fit.h"
#include "iso25178.h"
#include "png.h"
#include "png_plot.h"
#include "si.h"
#include "psd.h"
#include "spectral.h"
#include "stats.h"
#include "stats_nonuni.h"
#include "table_write.h"
#include "units.h"

enum {
	OPT_MASK = OPT_TOOL_FIRST,
	OPT_PSD,
	OPT_PSD2D,
	OPT_ACF,
	OPT_BY_HEIGHT,
	OPT_FD,
	OPT_GNUPLOT,
	OPT_BINS,
	OPT_WINDOW,
	OPT_PSD1D,
	OPT_ACF_HALF,
	OPT_ISO,
	OPT_ACF_THRESHOLD,
	OPT_MATERIAL_RATIO,
	OPT_FIT,
	OPT_MIN_WAVELENGTH,
	OPT_MAX_WAVELENGTH,
	OPT_CHANNELS
};

enum table { T_SCALARS, T_PSD, T_ACF, T_BY_HEIGHT, T_PSD1D, T_ISO, T_MR, T_FIT };

static void
usage(void)
{
	printf("usage: surfstat [options] [FILE]\n"
	    "  (no table option)     one row of scalars: hrms, gbar, gbar_fd, nayak,\n"
	    "                        phi1 .. phi9, ... (see surfstat(1))\n"
	    "  --psd                 radial C(q) table instead: q C n_modes stderr\n"
	    "  --acf                 height-difference ACF table instead: along x, y, radial\n"
	    "  --by-height N         gbar and gradient tensor in N height bins instead\n"
	    "  --psd1d x|y           1D spectrum of the lines along x or y, averaged:\n"
	    "                        q C1D C1D_ce n_lines stderr (a profile's --psd)\n"
	    "  --iso                 ISO 25178 parameters instead: Sq Sa Ssk Sku Sp Sv Sz\n"
	    "                        Sdq Sdr Sal Str Sk Spk Svk Smr1 Smr2 (valid points)\n"
	    "  --material-ratio N    material ratio (Abbott-Firestone) curve at N heights\n"
	    "  --fit                 fit the self-affine model of Eq. 2 to C(q): H, q_r,\n"
	    "                        q_s, hrms with standard errors\n"
	    "  --window W            none, hann, blackman or tukey before a spectrum\n"
	    "                        (default hann on finite patches, none if periodic)\n"
	    "  --acf-half            --acf gives G(r)/2 (contact.engineering's convention)\n"
	    "  --acf-threshold S     autocorrelation level of Sal and Str (default 0.2)\n"
	    "  --min-wavelength L    --fit ignores wavelengths below L (unreliable data):\n"
	    "                        in the map's unit, a fraction of the scan (0.05L)\n"
	    "                        or with a unit (5um)\n"
	    "  --max-wavelength L    --fit ignores wavelengths above L (the same forms)\n"
	    "  --bins-per-decade N   logarithmic q bins for --psd, --gnuplot (default 10)\n"
	    "  --psd2d FILE          also write the 2D spectrum as a grid (kind spectrum)\n"
	    "  --gnuplot FILE        also write a gnuplot script plotting C(q) to PNG\n"
	    "  --mask FILE           average over the points where the mask is 1\n"
	    "  --fd                  finite-difference derivatives (default spectral)\n"
	    "  --png FILE            PNG preview of the surface; with --psd, --psd1d\n"
	    "                        or --fit the spectrum, log-log (and the fit)\n"
	    "  --fft-effort E        estimate, measure or patient FFT planning (default:\n"
	    "                        estimate, or measure for big grids with --wisdom)\n"
	    "  --wisdom FILE         load FFTW wisdom, save it after planning ($RC_WISDOM)\n"
	    "  -o FILE               table output (default stdout)   --json  JSON\n"
	    "  --pretty              aligned, rounded table (default on a terminal)\n"
	    "  -L LX[xLY]            cell size of an input that has none\n"
	    "  --unit U              length unit of the results (m mm um nm pm\n"
	    "                        angstrom); the unit of an input that has none\n"
	    "  --z-unit U            the input's heights are in length unit U\n"
	    "  --periodic, --no-periodic  the input is (not) one period of a surface\n"
	    "  --npy-order yx|xy     .npy shape (ny, nx) (default) or (nx, ny)\n"
	    "  --uniform             resample an x-z profile whose x is not uniformly\n"
	    "                        spaced linearly onto as many points (default:\n"
	    "                        analysed as it is, piecewise linear: hrms,\n"
	    "                        rms_slope, rms_curvature, --psd)\n"
	    "  --channel N|NAME      channel of a multi-channel input (default: the\n"
	    "                        first whose values are lengths)\n"
	    "  --channels            list the input's channels instead: channel title\n"
	    "                        nx ny lx ly unit z_unit mask\n"
	    "  -j N  threads   -q  quiet   -h, --help   --version\n");
}

static const struct option longopts[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ "json", no_argument, NULL, OPT_JSON },
	{ "pretty", no_argument, NULL, OPT_PRETTY },
	{ "png", required_argument, NULL, OPT_PNG },
	TOOL_FFT_LONGOPTS,
	TOOL_GRID_LONGOPTS,
	{ "mask", required_argument, NULL, OPT_MASK },
	{ "psd", no_argument, NULL, OPT_PSD },
	{ "psd2d", required_argument, NULL, OPT_PSD2D },
	{ "acf", no_argument, NULL, OPT_ACF },
	{ "by-height", required_argument, NULL, OPT_BY_HEIGHT },
	{ "fd", no_argument, NULL, OPT_FD },
	{ "gnuplot", required_argument, NULL, OPT_GNUPLOT },
	{ "bins-per-decade", required_argument, NULL, OPT_BINS },
	{ "window", required_argument, NULL, OPT_WINDOW },
	{ "psd1d", required_argument, NULL, OPT_PSD1D },
	{ "acf-half", no_argument, NULL, OPT_ACF_HALF },
	{ "iso", no_argument, NULL, OPT_ISO },
	{ "acf-threshold", required_argument, NULL, OPT_ACF_THRESHOLD },
	{ "material-ratio", required_argument, NULL, OPT_MATERIAL_RATIO },
	{ "fit", no_argument, NULL, OPT_FIT },
	{ "min-wavelength", required_argument, NULL, OPT_MIN_WAVELENGTH },
	{ "max-wavelength", required_argument, NULL, OPT_MAX_WAVELENGTH },
	TOOL_CHANNEL_LONGOPT,
	{ "channels", no_argument, NULL, OPT_CHANNELS },
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
		tool_fail_at(t, t->out, err.msg);
	tool_table_begin(t, &o->table, o->file.fp);
}

static void
out_row(const struct tool *t, struct out *o, const rc_row *r)
{
	rc_err err;

	if (rc_table_write(&o->table, r, &err) != 0) {
		rc_atomic_abort(&o->file);
		tool_fail_at(t, t->out ? t->out : "standard output", err.msg);
	}
}

static void
out_close(const struct tool *t, struct out *o)
{
	rc_err err;

	if (rc_table_end(&o->table, &err) != 0 ||
	    rc_atomic_commit(&o->file, &err) != 0) {
		rc_atomic_abort(&o->file);
		tool_fail_at(t, t->out ? t->out : "standard output", err.msg);
	}
}

/* A scalar row with the grid's metadata, written alone, then freed. */
static void
write_scalar_row(const struct tool *t, rc_row *r, const rc_grid *g)
{
	struct out o;

	if (rc_row_meta(r, g) != 0)
		tool_fail(t, "out of memory");
	out_open(t, &o);
	out_row(t, &o, r);
	out_close(t, &o);
	rc_row_free(r);
}

/* Row building never fails short of memory exhaustion. */
static void
num(const struct tool *t, rc_row *r, const char *name, double v)
{
	if (rc_row_num(r, name, v) != 0)
		tool_fail(t, "out of memory");
}

/* Why the scale-free columns of s that are nan are undefined (they are
 * ratios of moments: lib/stats.h); NULL if none is.  names (at least 80
 * bytes: all twelve fit) gets them. */
static const char *
scalars_nan_why(const rc_stats *s, char *names, size_t size)
{
	static const char *const name[] = { "skewness", "kurtosis", "nayak" };
	double v[3] = { s->skewness, s->kurtosis, s->nayak };
	int nphi = 0, first = 1;
	size_t len = 0;

	names[0] = '\0';
	for (int i = 0; i < 3; i++)
		if (isnan(v[i])) {
			len += (size_t)snprintf(names + len, size - len, "%s%s",
			    first ? "" : ", ", name[i]);
			first = 0;
		}
	for (int i = 1; i <= 9; i++)
		nphi += isnan(s->phi[i]) != 0;
	for (int i = 1; i <= 9 && nphi > 0 && len < size; i++)
		if (nphi == 9 || isnan(s->phi[i])) {
			len += (size_t)snprintf(names + len, size - len,
			    nphi == 9 ? "%sphi1 .. phi9" : "%sphi%d", first ? "" : ", ",
			    i);
			first = 0;
			if (nphi == 9)
				break;
		}
	if (first)
		return NULL;
	if (!(s->hrms > 0))
		return "the heights are constant (hrms = 0), and these are "
		    "normalised by hrms or the rms gradient";
	if (!(s->gbar > 0))
		return "the rms gradient is 0 (the heights are constant up to "
		    "round-off), and the Nayak parameter and the phi are "
		    "normalised by it";
	if (!(s->mxx > 0))
		return "the rms slope along x is 0, and the Nayak parameter (of "
		    "profiles along x) is normalised by it";
	return "a moment they are normalised by is 0";
}

static void
scalars(const struct tool *t, const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft)
{
	rc_stats s;
	rc_err err;
	rc_row r;
	double gbar, seconds;
	char name[8], names[128];
	const char *why;

	seconds = rc_clock();
	if (rc_rms_gradient(g, fft, &gbar, &err) != 0 ||
	    rc_stats_compute_fft(g, mask, m, fft, &s, &err) != 0)
		tool_fail(t, "%s", err.msg);
	seconds = rc_clock() - seconds;
	/* nan stays in the table (undefined, not unknown); say why once */
	if ((why = scalars_nan_why(&s, names, sizeof(names))) != NULL)
		tool_warn(t, "%s written as nan%s: %s", names,
		    mask != NULL ? " (averages over the mask)" : "", why);
	rc_row_init(&r);
	if (rc_row_int(&r, "nx", (long long)g->nx) != 0 ||
	    rc_row_int(&r, "ny", (long long)g->ny) != 0 ||
	    rc_row_str(&r, "derivatives", rc_deriv_method_name(m)) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "lx", g->lx);
	num(t, &r, "ly", g->ly);
	/* the unit of every length in the row, when the grid has one */
	if (g->unit[0] != '\0' && rc_row_str(&r, "unit", g->unit) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "mean", s.mean);
	num(t, &r, "hrms", s.hrms);
	num(t, &r, "gbar", gbar);
	num(t, &r, "gbar_fd", rc_gbar_forward(g));
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
	write_scalar_row(t, &r, g);
}

/* The scalar row of a line scan not uniformly spaced (stats_nonuni.h). */
static void
nonuni_scalars(const struct tool *t, const rc_grid *g)
{
	rc_nonuni_stats s;
	rc_err err;
	rc_row r;
	double seconds = rc_clock();

	if (rc_nonuni_stats_compute(g, &s, &err) != 0)
		tool_fail(t, "%s", err.msg);
	seconds = rc_clock() - seconds;
	if (s.n_missing > 0)
		tool_warn(t, "%zu of %zu points missing: the segments touching "
		    "them are left out (%zu of %zu segments kept, length %g of "
		    "%g)", s.n_missing, s.n, s.n_segments, s.n - 1, s.length,
		    g->lx);
	if (isnan(s.rms_curvature))
		tool_warn(t, "rms_curvature written as nan: it needs two "
		    "neighbouring interior points with both neighbours valid");
	rc_row_init(&r);
	if (rc_row_int(&r, "nx", (long long)g->nx) != 0 ||
	    rc_row_int(&r, "ny", (long long)g->ny) != 0 ||
	    rc_row_str(&r, "spacing", "nonuniform") != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "lx", g->lx);
	if (g->unit[0] != '\0' && rc_row_str(&r, "unit", g->unit) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "mean", s.mean);
	num(t, &r, "hrms", s.hrms);
	num(t, &r, "rms_slope", s.rms_slope);
	num(t, &r, "rms_curvature", s.rms_curvature);
	num(t, &r, "hmin", s.hmin);
	num(t, &r, "hmax", s.hmax);
	num(t, &r, "range", s.hmax - s.hmin);
	if (rc_row_int(&r, "n_missing", (long long)s.n_missing) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "seconds", seconds);
	write_scalar_row(t, &r, g);
}

/* --png with a spectrum table: the spectrum drawn log-log (png_plot.h),
 * with the fit when there is one. */
static void
spectrum_png(const struct tool *t, const rc_grid *g, const double *q,
    const double *c, size_t n, size_t stride, int profile,
    const rc_selfaffine_fit *fit)
{
	rc_spectrum_plot p;
	char title[160], lx[40], ly[40];
	rc_err err;

	rc_si_length(lx, sizeof(lx), g->lx, g->unit, 1);
	rc_si_length(ly, sizeof(ly), g->ly, g->unit, 1);
	if (profile)
		snprintf(title, sizeof(title), "1D spectrum, %zu points, L = %s",
		    g->nx * g->ny, g->ny == 1 ? lx : ly);
	else
		snprintf(title, sizeof(title), "radial spectrum, %zux%zu, L = %s x %s",
		    g->nx, g->ny, lx, ly);
	memset(&p, 0, sizeof(p));
	p.q = q;
	p.c = c;
	p.n = n;
	p.stride = stride;
	p.unit = g->unit;
	p.c_power = profile ? 3 : 4;
	p.c_name = profile ? "C1D(q)" : "C(q)";
	p.title = title;
	if (fit != NULL) {
		p.have_fit = 1;
		p.c_r = fit->c_r;
		p.hurst = fit->H;
		p.q_r = fit->q_r;
		p.rolloff = fit->rolloff;
		p.fit_q_min = fit->fit_q_min;
		p.fit_q_max = fit->fit_q_max;
	}
	if (rc_png_spectrum(&p, t->png, NULL, &err) != 0)
		tool_fail_at(t, t->png, err.msg);
}

/* The bins drawn (spectrum_png). */
static void
bins_png(const struct tool *t, const rc_grid *g, const rc_psd_bin *b,
    size_t nb, const rc_selfaffine_fit *fit)
{
	spectrum_png(t, g, nb ? &b[0].q : NULL, nb ? &b[0].c : NULL, nb,
	    sizeof(*b), 0, fit);
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
acf_table(const struct tool *t, const rc_grid *g, rc_fft *fft, int half)
{
	rc_acf_point *p;
	size_t np;
	rc_err err;
	struct out o;
	rc_row r;

	if (rc_acf_ex(g, fft, half, &p, &np, &err) != 0)
		tool_fail(t, "%s", err.msg);
	rc_row_init(&r);
	out_open(t, &o);
	for (size_t k = 0; k < np; k++) {
		rc_row_clear(&r);
		if (rc_row_str(&r, "direction", rc_acf_dir_name(p[k].dir)) != 0)
			tool_fail(t, "out of memory");
		num(t, &r, "r", p[k].r);
		num(t, &r, half ? "hdacf_half" : "hdacf", p[k].g);
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

static void
psd1d_table(const struct tool *t, const rc_grid *g, enum rc_psd1d_dir dir,
    enum rc_window window)
{
	rc_psd1d_point *p;
	size_t np;
	rc_err err;
	struct out o;
	rc_row r;

	if ((g->x != NULL ? rc_nonuni_psd(g, window, &p, &np, &err) :
	    rc_psd1d(g, dir, window, &p, &np, &err)) != 0)
		tool_fail(t, "%s", err.msg);
	if (t->png != NULL)
		spectrum_png(t, g, np ? &p[0].q : NULL, np ? &p[0].c : NULL, np,
		    sizeof(*p), 1, NULL);
	rc_row_init(&r);
	out_open(t, &o);
	for (size_t k = 0; k < np; k++) {
		rc_row_clear(&r);
		num(t, &r, "q", p[k].q);
		num(t, &r, "C1D", p[k].c);
		num(t, &r, "C1D_ce", 2 * M_PI * p[k].c);
		if (rc_row_int(&r, "n_lines", (long long)p[k].n_lines) != 0)
			tool_fail(t, "out of memory");
		num(t, &r, "stderr", p[k].std_err);
		out_row(t, &o, &r);
	}
	out_close(t, &o);
	rc_row_free(&r);
	free(p);
}

static void
iso_row(const struct tool *t, const char *in, const rc_grid *g, double s)
{
	rc_iso iso;
	rc_err err;
	rc_row r;
	struct out o;

	if (rc_iso25178(g, s, &iso, &err) != 0)
		tool_fail_at(t, in && !rc_is_stdio(in) ? in : "standard input",
		    err.msg);
	rc_row_init(&r);
	if (rc_row_int(&r, "nx", (long long)g->nx) != 0 ||
	    rc_row_int(&r, "ny", (long long)g->ny) != 0 ||
	    rc_row_int(&r, "n_valid", (long long)iso.n_valid) != 0 ||
	    rc_row_int(&r, "periodic", g->periodic) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "mean", iso.mean);
	num(t, &r, "Sq", iso.Sq);
	num(t, &r, "Sa", iso.Sa);
	num(t, &r, "Ssk", iso.Ssk);
	num(t, &r, "Sku", iso.Sku);
	num(t, &r, "Sp", iso.Sp);
	num(t, &r, "Sv", iso.Sv);
	num(t, &r, "Sz", iso.Sz);
	num(t, &r, "Sdq", iso.Sdq);
	num(t, &r, "Sdr", iso.Sdr);
	num(t, &r, "Sal", iso.Sal);
	num(t, &r, "Str", iso.Str);
	num(t, &r, "Sk", iso.Sk);
	num(t, &r, "Spk", iso.Spk);
	num(t, &r, "Svk", iso.Svk);
	num(t, &r, "Smr1", iso.Smr1);
	num(t, &r, "Smr2", iso.Smr2);
	out_open(t, &o);
	out_row(t, &o, &r);
	out_close(t, &o);
	rc_row_free(&r);
}

static void
mr_table(const struct tool *t, const rc_grid *g, size_t npoints)
{
	double *c, *smr;
	rc_err err;
	rc_row r;
	struct out o;

	if ((c = rc_malloc(npoints * sizeof(double), &err)) == NULL ||
	    (smr = rc_malloc(npoints * sizeof(double), &err)) == NULL ||
	    rc_material_ratio(g, npoints, c, smr, &err) != 0)
		tool_fail(t, "%s", err.msg);
	rc_row_init(&r);
	out_open(t, &o);
	for (size_t k = 0; k < npoints; k++) {
		rc_row_clear(&r);
		num(t, &r, "height", c[k]);
		num(t, &r, "Smr", smr[k]);
		out_row(t, &o, &r);
	}
	out_close(t, &o);
	rc_row_free(&r);
	free(c);
	free(smr);
}

static void
fit_row(const struct tool *t, const rc_grid *g, rc_fft *fft,
    const rc_fit_opts *fo)
{
	rc_selfaffine_fit f;
	rc_err err;
	rc_row r;
	struct out o;

	if (rc_fit_selfaffine(g, fft, fo, &f, &err) != 0)
		tool_fail(t, "--fit: %s", err.msg);
	{
		char advice[1024];
		if (rc_fit_advice(&f, fmax(g->lx, g->ly), advice, sizeof(advice)))
			tool_warn(t, "--fit: %s", advice);
	}
	if (t->png != NULL) {
		/* the spectrum the fit saw: its bins and window */
		rc_psd_bin *b;
		size_t nb;
		if (rc_psd_radial_window(g, fft, fo->bins_per_decade, fo->window,
		    &b, &nb, &err) != 0)
			tool_fail(t, "%s", err.msg);
		bins_png(t, g, b, nb, &f);
		free(b);
	}
	rc_row_init(&r);
	if (rc_row_int(&r, "nx", (long long)g->nx) != 0 ||
	    rc_row_int(&r, "ny", (long long)g->ny) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "lx", g->lx);
	num(t, &r, "ly", g->ly);
	/* as on the scalar row; surfgen --like makes its twin in this unit */
	if (f.unit[0] != '\0' && rc_row_str(&r, "unit", f.unit) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "H", f.H);
	num(t, &r, "H_err", f.H_err);
	num(t, &r, "q_r", f.q_r);
	num(t, &r, "q_r_err", f.q_r_err);
	num(t, &r, "q_s", f.q_s);
	num(t, &r, "q_s_err", f.q_s_err);
	num(t, &r, "lambda_r", 2 * M_PI / f.q_r);
	num(t, &r, "lambda_s", 2 * M_PI / f.q_s);
	num(t, &r, "C_r", f.c_r);
	num(t, &r, "hrms", f.hrms);
	num(t, &r, "hrms_err", f.hrms_err);
	if (rc_row_int(&r, "rolloff", f.rolloff) != 0 ||
	    rc_row_str(&r, "q_r_from", f.q_r_from) != 0 ||
	    rc_row_str(&r, "q_s_from", f.q_s_from) != 0 ||
	    rc_row_str(&r, "window", rc_window_name(rc_window_resolve(g,
	    fo->window))) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "fit_q_min", f.fit_q_min);
	num(t, &r, "fit_q_max", f.fit_q_max);
	if (rc_row_int(&r, "n_bins", (long long)f.n_bins) != 0)
		tool_fail(t, "out of memory");
	num(t, &r, "rms_residual", f.rms_residual);
	out_open(t, &o);
	out_row(t, &o, &r);
	out_close(t, &o);
	rc_row_free(&r);
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
		tool_fail_at(t, path, err.msg);
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
	    "set ylabel 'C(q) (%s^4)'\n"
	    "set title 'radially averaged spectrum, %zux%zu, L = %gx%g %s'\n"
	    "plot $psd using 1:2:4 with yerrorbars pt 7 ps 0.5 title 'C(q)'\n",
	    png, g->unit[0] ? g->unit : "length", g->unit[0] ? g->unit : "length",
	    g->nx, g->ny, g->lx, g->ly, g->unit[0] ? g->unit : "(no unit)");
	free(png);
	/* commit reports a write error too (and has closed a.fp either way) */
	if (rc_atomic_commit(&a, &err) != 0) {
		rc_atomic_abort(&a);
		tool_fail_at(t, path, err.msg);
	}
}

/* surfstat's options: one struct, parsed, then checked together. */
struct stat_opts {
	const char *mask_path, *psd2d, *gp, *in;
	enum table table;
	enum rc_deriv_method method;
	enum rc_window window;
	enum rc_psd1d_dir dir1d;
	int ntables, acf_half, have_window, have_s, list;
	size_t nbins, nmr;
	double bpd, acf_s;
	/* --min-wavelength, --max-wavelength as given (fit.h); value 0 if
	 * not given */
	rc_fit_length min_wl, max_wl;
};

/* A table option: the table, counted (one per run). */
static void
choose_table(struct stat_opts *so, enum table table)
{
	so->table = table;
	so->ntables++;
}

/* One option c of getopt_long. */
/* Long: one case per option, each a few lines; they are read together. */
static void
stat_option(struct tool *t, struct stat_opts *so, int c, const char *arg,
    char **argv)
{
	rc_err err;
	long v;

	switch (c) {
	case OPT_MASK:
		so->mask_path = arg;
		break;
	case OPT_PSD:
		choose_table(so, T_PSD);
		break;
	case OPT_ACF:
		choose_table(so, T_ACF);
		break;
	case OPT_BY_HEIGHT:
		choose_table(so, T_BY_HEIGHT);
		if (tool_long(t, "--by-height", arg, &v) == 0) {
			if (v < 1 || v > 1000000)
				tool_bad(t, "--by-height %s: want 1 to 1000000 bins", arg);
			else
				so->nbins = (size_t)v;
		}
		break;
	case OPT_PSD2D:
		so->psd2d = arg;
		break;
	case OPT_PSD1D:
		choose_table(so, T_PSD1D);
		if (strcmp(arg, "x") == 0)
			so->dir1d = RC_PSD1D_X;
		else if (strcmp(arg, "y") == 0)
			so->dir1d = RC_PSD1D_Y;
		else
			tool_bad(t, "--psd1d %s: want x or y", arg);
		break;
	case OPT_ISO:
		choose_table(so, T_ISO);
		break;
	case OPT_FIT:
		choose_table(so, T_FIT);
		break;
	case OPT_MATERIAL_RATIO:
		choose_table(so, T_MR);
		if (tool_long(t, "--material-ratio", arg, &v) == 0) {
			if (v < 2 || v > 1000000)
				tool_bad(t, "--material-ratio %s: want 2 to 1000000 "
				    "heights", arg);
			else
				so->nmr = (size_t)v;
		}
		break;
	case OPT_WINDOW: {
		int w = rc_window_parse(arg);

		so->have_window = 1;
		if (w < 0)
			tool_bad(t, "--window %s: want none, hann, blackman or tukey",
			    arg);
		else
			so->window = (enum rc_window)w;
		break;
	}
	case OPT_ACF_HALF:
		so->acf_half = 1;
		break;
	case OPT_ACF_THRESHOLD:
		so->have_s = 1;
		if (tool_double(t, "--acf-threshold", arg, &so->acf_s) == 0 &&
		    !(so->acf_s > 0 && so->acf_s < 1))
			tool_bad(t, "--acf-threshold %s: want 0 < S < 1", arg);
		break;
	case OPT_MIN_WAVELENGTH:
		if (rc_fit_length_parse(arg, &so->min_wl, &err) != 0)
			tool_bad(t, "--min-wavelength %s", err.msg);
		break;
	case OPT_MAX_WAVELENGTH:
		if (rc_fit_length_parse(arg, &so->max_wl, &err) != 0)
			tool_bad(t, "--max-wavelength %s", err.msg);
		break;
	case OPT_GNUPLOT:
		so->gp = arg;
		break;
	case OPT_FD:
		so->method = RC_DERIV_FD;
		break;
	case OPT_CHANNELS:
		so->list = 1;
		break;
	case OPT_BINS:
		if (tool_double(t, "--bins-per-decade", arg, &so->bpd) == 0 &&
		    !(so->bpd >= 1 && so->bpd <= 1000))
			tool_bad(t, "--bins-per-decade %s: want 1 to 1000", arg);
		break;
	default:
		tool_bad_option(t, "ho:j:qL:", longopts, argv);
	}
}

/* The checks between options, the operand, and the run's files. */
static void
stat_opts_check(struct tool *t, struct stat_opts *so, int argc, char **argv)
{
	enum table table = so->table;

	if (optind < argc)
		so->in = argv[optind++];
	if (optind < argc)
		tool_bad(t, "%s: unexpected argument (one input file)", argv[optind]);
	if (so->ntables > 1)
		tool_bad(t, "--psd, --psd1d, --acf, --by-height, --iso, "
		    "--material-ratio, --fit: choose one table per run");
	if (so->mask_path != NULL && table != T_SCALARS && table != T_BY_HEIGHT)
		tool_bad(t, "--mask: applies to the scalar row and --by-height, "
		    "not to spectra, the ACF, --iso, --material-ratio or --fit");
	if (so->method == RC_DERIV_FD && table != T_SCALARS && table != T_BY_HEIGHT)
		tool_bad(t, "--fd: applies to the scalar row and --by-height only");
	if (so->have_window && table != T_PSD && table != T_PSD1D &&
	    table != T_FIT && so->psd2d == NULL && so->gp == NULL)
		tool_bad(t, "--window: applies to --psd, --psd1d, --psd2d, --gnuplot "
		    "and --fit");
	if (so->acf_half && table != T_ACF)
		tool_bad(t, "--acf-half: only with --acf");
	if (so->have_s && table != T_ISO)
		tool_bad(t, "--acf-threshold: only with --iso");
	if ((so->min_wl.value > 0 || so->max_wl.value > 0) && table != T_FIT)
		tool_bad(t, "--min-wavelength, --max-wavelength: only with --fit");
	else if (so->min_wl.value > 0 && so->max_wl.value > 0) {
		/* bounds of one kind compare without the map (a usage error);
		 * of two kinds (L and a unit, ...) only on it (fit_range) */
		const rc_fit_length *a = &so->min_wl, *b = &so->max_wl;
		double bmax = NAN;

		if (a->scan == b->scan && !a->unit[0] == !b->unit[0])
			bmax = a->unit[0] ? rc_unit_convert(b->value, b->unit,
			    a->unit) : b->value;
		if (!(bmax > a->value) && !isnan(bmax))
			tool_bad(t, "--min-wavelength %g%s%s, --max-wavelength "
			    "%g%s%s: need min < max", a->value, a->scan ? "L" : "",
			    a->unit, b->value, b->scan ? "L" : "", b->unit);
	}
	if (so->psd2d != NULL)
		tool_check_grid_path(t, "--psd2d", so->psd2d);
	tool_output(t, "-o", t->out ? t->out : "-", 0);
	tool_output(t, "--psd2d", so->psd2d, 0);
	tool_output(t, "--gnuplot", so->gp, 0);
	tool_output(t, "--png", t->png, 1);
	tool_input(t, "the input", so->in);
	if (so->mask_path != NULL)
		tool_input(t, "--mask", so->mask_path);
	tool_usage_check(t);
}

/* A line scan not uniformly spaced (g->x) has the scalar row and the 1D
 * spectrum of stats_nonuni.h; what needs a uniform grid says so. */
static void
check_nonuniform(const struct tool *t, struct stat_opts *so, const rc_grid *g)
{
	static const char *const table_option[] = { [T_ACF] = "--acf",
	    [T_BY_HEIGHT] = "--by-height", [T_ISO] = "--iso",
	    [T_MR] = "--material-ratio", [T_FIT] = "--fit" };
	const char *name = so->in ? so->in : "standard input", *what = NULL;

	if (so->table == T_PSD) {
		so->table = T_PSD1D;
		so->dir1d = RC_PSD1D_X;
	}
	if (so->table != T_SCALARS && so->table != T_PSD1D)
		what = table_option[so->table];
	else if (so->table == T_PSD1D && so->dir1d != RC_PSD1D_X)
		what = "--psd1d y";
	else if (so->mask_path != NULL)
		what = "--mask";
	else if (so->psd2d != NULL)
		what = "--psd2d";
	else if (so->gp != NULL)
		what = "--gnuplot";
	else if (so->method == RC_DERIV_FD)
		what = "--fd";
	else if (t->png != NULL && so->table != T_PSD1D)
		what = "--png (without --psd)";
	if (what != NULL)
		tool_fail(t, "%s: a line scan of %zu points not uniformly spaced "
		    "is analysed as it is for the scalar row and --psd only; %s "
		    "needs a uniform grid: --uniform resamples the profile "
		    "linearly onto %zu points", name, g->nx, what, g->nx);
}

/* What a grid allows: a profile's spectrum is 1D; missing points only
 * for --iso and --material-ratio. */
static void
check_grid(const struct tool *t, struct stat_opts *so, const rc_grid *g)
{
	const char *name = so->in ? so->in : "standard input";
	/* A profile (nx x 1 or 1 x ny) has a 1D spectrum only: a 2D C(q)
	 * would scale with the meaningless strip width. */
	int profile = (g->nx == 1) != (g->ny == 1);

	if (profile && so->table == T_PSD) {
		so->table = T_PSD1D;
		so->dir1d = g->ny == 1 ? RC_PSD1D_X : RC_PSD1D_Y;
	}
	if (profile && (so->psd2d != NULL || so->gp != NULL))
		tool_fail(t, "%s: a %zux%zu profile has no 2D spectrum "
		    "(--psd2d, --gnuplot); --psd gives its 1D spectrum",
		    name, g->nx, g->ny);
	if (g->valid != NULL && so->table != T_ISO && so->table != T_MR)
		tool_fail(t, "%s: the grid has missing points; --iso and "
		    "--material-ratio use the valid ones, everything else "
		    "needs them filled (surfwarp --fill)", name);
}

/* --min-wavelength, --max-wavelength in g's unit, as the fit's q range;
 * a bound that leaves no wavelength of the map is an error naming the
 * scan and the ways to give a bound relative to it. */
static void
fit_range(const struct tool *t, const struct stat_opts *so, const rc_grid *g,
    rc_fit_opts *fo)
{
	double lmin = 0, lmax = 0, L = fmax(g->lx, g->ly);
	double dx = fmax(g->lx / (double)g->nx, g->ly / (double)g->ny);
	char u[40];
	rc_err err;

	snprintf(u, sizeof(u), "%s%s", g->unit[0] ? " " : "", g->unit);

	if (so->min_wl.value > 0 &&
	    rc_fit_length_resolve(&so->min_wl, g, &lmin, &err) != 0)
		tool_fail(t, "--min-wavelength %s", err.msg);
	if (so->max_wl.value > 0 &&
	    rc_fit_length_resolve(&so->max_wl, g, &lmax, &err) != 0)
		tool_fail(t, "--max-wavelength %s", err.msg);
	if (lmin >= L)
		tool_fail(t, "--min-wavelength: %g%s is not below the scan's length "
		    "L = %g%s: no wavelength is left to fit (a bare number is in "
		    "the map's unit; give it as a fraction of the scan, e.g. "
		    "0.05L, or with a unit, e.g. 5um)", lmin, u, L, u);
	if (lmax > 0 && lmax <= 2 * dx)
		tool_fail(t, "--max-wavelength: %g%s is not above two spacings "
		    "(%g%s): no wavelength is left to fit (a bare number is in the "
		    "map's unit; give it as a fraction of the scan, e.g. 0.5L, or "
		    "with a unit, e.g. 50um)", lmax, u, 2 * dx, u);
	if (lmin > 0 && lmax > 0 && !(lmin < lmax))
		tool_fail(t, "--min-wavelength %g%s, --max-wavelength %g%s: need "
		    "min < max", lmin, u, lmax, u);
	fo->q_max = lmin > 0 ? 2 * M_PI / lmin : 0;
	fo->q_min = lmax > 0 ? 2 * M_PI / lmax : 0;
}

/* The statistics of g that the options ask for, written. */
static void
run_stats(struct tool *t, const struct stat_opts *so, const rc_grid *g,
    const rc_grid *mask)
{
	enum table table = so->table;
	rc_fit_opts fo;
	rc_fft fft, *plan;
	rc_err err;

	rc_fit_opts_default(&fo);
	fo.window = so->window;
	fo.bins_per_decade = so->bpd;
	if (table == T_FIT)
		fit_range(t, so, g, &fo);
	/* One plan for every transform of the run (a handful: the scalars
	 * take nine), made after the mask so that planning never waits on
	 * input that turns out bad. */
	memset(&fft, 0, sizeof(fft));
	if (g->x == NULL && table != T_PSD1D && table != T_ISO && table != T_MR &&
	    (table != T_BY_HEIGHT || so->method == RC_DERIV_SPECTRAL ||
	    so->psd2d != NULL || so->gp != NULL) && rc_fft_init(&fft, g->nx,
	    g->ny, tool_fft_effort(t, g->nx, g->ny, 5), &err) != 0)
		tool_fail(t, "%s", err.msg);
	plan = fft.nx ? &fft : NULL;
	tool_fft_finish(t);
	if (!t->quiet && plan && fft.effort != RC_FFT_ESTIMATE && table != T_SCALARS)
		tool_warn(t, "FFT plan %zux%zu (%s): %.3g s", g->nx, g->ny,
		    rc_fft_effort_name(fft.effort), fft.plan_seconds);
	if (so->psd2d != NULL) {
		rc_grid *s = rc_psd2d_window(g, plan, so->window, &err);

		if (s == NULL)
			tool_fail(t, "%s", err.msg);
		tool_write_grid(t, s, so->psd2d);
		rc_grid_free(s);
	}
	if (table == T_PSD || so->gp != NULL) {
		rc_psd_bin *b;
		size_t nb;

		if (rc_psd_radial_window(g, plan, so->bpd, so->window, &b, &nb,
		    &err) != 0)
			tool_fail(t, "%s", err.msg);
		if (so->gp != NULL)
			gnuplot_script(t, so->gp, g, b, nb);
		if (table == T_PSD)
			psd_table(t, b, nb);
		if (table == T_PSD && t->png != NULL)
			bins_png(t, g, b, nb, NULL);
		free(b);
	}
	switch (table) {
	case T_SCALARS:
		if (g->x != NULL)
			nonuni_scalars(t, g);
		else
			scalars(t, g, mask, so->method, plan);
		break;
	case T_ACF:
		acf_table(t, g, plan, so->acf_half);
		break;
	case T_PSD1D:
		psd1d_table(t, g, so->dir1d, so->window);
		break;
	case T_ISO:
		iso_row(t, so->in, g, so->acf_s);
		break;
	case T_MR:
		mr_table(t, g, so->nmr);
		break;
	case T_FIT:
		fit_row(t, g, plan, &fo);
		break;
	case T_BY_HEIGHT:
		height_table(t, g, mask, so->method, plan, so->nbins);
		break;
	case T_PSD:
		break;
	}
	rc_fft_free(&fft);
}

int
main(int argc, char **argv)
{
	struct tool t;
	struct stat_opts so = { .table = T_SCALARS, .method = RC_DERIV_SPECTRAL,
	    .window = RC_WINDOW_AUTO, .dir1d = RC_PSD1D_X, .bpd = 10,
	    .acf_s = 0.2 };
	rc_grid *g, *mask = NULL;
	rc_err err;
	int opt, help = 0;

	tool_init(&t, "surfstat", argc, argv);
	opterr = 0;	/* unknown options are reported with the others */
	while ((opt = getopt_long(argc, argv, "ho:j:qL:", longopts, NULL)) != -1) {
		if (tool_common_option(&t, opt, optarg))
			continue;
		if (opt == 'h')
			help = 1;
		else
			stat_option(&t, &so, opt, optarg, argv);
	}
	if (help && tool_help_check(&t)) {
		usage();
		return tool_exit(&t, 0);
	}
	stat_opts_check(&t, &so, argc, argv);
	t.nonuniform = 1;	/* x-z profiles not uniformly spaced: as they are */
	if (so.list)
		tool_list_channels(&t, so.in);
	tool_fft_setup(&t);
	gsl_set_error_handler_off();	/* GSL reports through return codes */
	/* only --iso and --material-ratio use the valid points alone */
	t.accept_missing = so.table == T_ISO || so.table == T_MR;
	g = tool_read_input(&t, so.in);
	t.nonuniform = 0;	/* a mask is a grid */
	if (g->x != NULL)
		check_nonuniform(&t, &so, g);
	else
		check_grid(&t, &so, g);
	/* Windowed spectra, the zero-padded ACF, --iso and --fit treat a
	 * finite patch as one; the scalar row's spectral derivatives and
	 * --by-height do not. */
	if (g->x == NULL && (g->periodic || so.table == T_SCALARS ||
	    so.table == T_BY_HEIGHT))
		tool_check_wrap(&t, g, so.in, so.method == RC_DERIV_FD ?
		    "the spectral gbar takes it" : "the spectral derivatives "
		    "(gbar, rms_laplacian, nayak, phi1..phi9) take it",
		    so.method == RC_DERIV_FD ? "gbar_fd and --iso's Sdq do not" :
		    "--fd takes the derivatives without the wrap (gbar stays "
		    "spectral: use gbar_fd), --iso uses the patch alone");
	if (so.mask_path != NULL) {
		mask = tool_read_grid(&t, so.mask_path);
		if (rc_mask_check(mask, g, &err) == 0)
			tool_fail_at(&t, so.mask_path, err.msg);
	}
	/* with a spectrum table, --png draws the spectrum (run_stats) */
	if (t.png != NULL && so.table != T_PSD && so.table != T_PSD1D &&
	    so.table != T_FIT && rc_png_write(g, t.png, NULL, &err) != 0)
		tool_fail_at(&t, t.png, err.msg);
	run_stats(&t, &so, g, mask);
	rc_grid_free(mask);
	rc_grid_free(g);
	return tool_exit(&t, 0);
}
