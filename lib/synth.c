/* SPDX-License-Identifier: GPL-3.0-or-later */
/* synth.c - surface synthesis: self-affine random roughness (Eqs. 2, 3 of
 * Wang & Mueser 2020), harmonic indenters (Eq. 5), sine, egg box, flat.
 *
 * Self-affine surfaces are built in Fourier space, h(r) = sum_k a_k
 * exp(i q_k . r), and brought to real space by one c2r transform.  Every
 * a_k is a function of (seed, integer wave vector k) and of the spectrum
 * at q_k only, so the surface does not depend on the grid beyond which
 * modes it holds.
 */
#include "synth.h"

#include <complex.h>
#include <fftw3.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "spectral.h"

/* Relative tolerance of the band edges and the divisibility checks: a mode
 * on the circle q = q_r or q = q_s in exact arithmetic counts as on it
 * despite rounding of 2 pi k / L. */
#define EDGE_TOL 1e-9

static const char *type_names[] = {
	"selfaffine", "harmonic", "sine", "eggbox", "flat"
};

const char *
rc_surface_type_name(enum rc_surface_type t)
{
	return (unsigned)t < sizeof(type_names) / sizeof(type_names[0]) ?
	    type_names[t] : "unknown";
}

int
rc_surface_type_parse(const char *name)
{
	for (size_t t = 0; t < sizeof(type_names) / sizeof(type_names[0]); t++)
		if (strcmp(name, type_names[t]) == 0)
			return (int)t;
	return -1;
}

void
rc_synth_defaults(rc_synth_params *p)
{
	memset(p, 0, sizeof(*p));
	p->type = RC_SURF_SELFAFFINE;
	p->nx = p->ny = 256;
	p->lx = p->ly = 1.0;
	p->hurst = 0.8;
	p->lambda_r = 0;	/* resolved to max(lx, ly) */
	p->lambda_s = 0;	/* resolved to two grid spacings */
	p->rolloff = 0;
	p->peklenik = 1.0;
	p->seed = 1;
	p->gaussian_amplitudes = 0;
	p->rms_gradient = 0;	/* selfaffine: 1 when neither is set */
	p->rms_height = 0;
	p->exponent = 2.0;
	p->radius = 1.0;
	p->wavelength = 0;	/* resolved to lx */
	p->amplitude = 1.0;
}

/* The shortest wavelength the grid can hold for the band's ellipse: the
 * band q_P < q_s reaches |qx| = q_s/g and |qy| = g q_s (g the Peklenik
 * parameter), which must stay below the Nyquist wave numbers pi/dx and
 * pi/dy, i.e. lambda_s >= max(2 dx / g, 2 dy g).  An nx x 1 grid is a line:
 * its y spacing bounds no mode (and likewise for 1 x ny). */
static double
min_lambda_s(const rc_synth_params *p)
{
	double g = p->peklenik > 0 && isfinite(p->peklenik) ? p->peklenik : 1;
	double ax = 2 * p->lx / (double)p->nx / g;
	double ay = 2 * p->ly / (double)p->ny * g;

	if (p->ny == 1)
		return ax;
	if (p->nx == 1)
		return ay;
	return ax > ay ? ax : ay;
}

double
rc_synth_lambda_r(const rc_synth_params *p)
{
	if (p->lambda_r > 0)
		return p->lambda_r;
	return p->lx > p->ly || p->ny == 1 ? p->lx : p->ly;
}

double
rc_synth_lambda_s(const rc_synth_params *p)
{
	return p->lambda_s > 0 ? p->lambda_s : min_lambda_s(p);
}

double
rc_synth_wavelength(const rc_synth_params *p)
{
	return p->wavelength > 0 ? p->wavelength : p->lx;
}

/* 1 if length l holds a whole number (>= 1) of wavelengths w. */
static int
divides(double w, double l)
{
	double m = l / w;

	return m >= 1 - EDGE_TOL && fabs(m - nearbyint(m)) <= EDGE_TOL * m;
}

static int
positive(double v)
{
	return v > 0 && isfinite(v);
}

int
rc_synth_check(const rc_synth_params *p, rc_err *err)
{
	double lr, ls, w;

	if (rc_grid_check_shape(p->nx, p->ny, p->lx, p->ly, err) != 0)
		return -1;
	if ((unsigned)p->type > RC_SURF_FLAT)
		return rc_seterr(err, "unknown surface type %d", (int)p->type);
	if (!(p->rms_gradient >= 0) || !isfinite(p->rms_gradient))
		return rc_seterr(err, "rms gradient %g: must be positive and finite",
		    p->rms_gradient);
	if (!(p->rms_height >= 0) || !isfinite(p->rms_height))
		return rc_seterr(err, "rms height %g: must be positive and finite",
		    p->rms_height);
	if (p->rms_gradient > 0 && p->rms_height > 0)
		return rc_seterr(err, "give either an rms gradient or an rms height, not both");
	switch (p->type) {
	case RC_SURF_SELFAFFINE:
		lr = rc_synth_lambda_r(p);
		ls = rc_synth_lambda_s(p);
		if (!(p->hurst > 0 && p->hurst < 1))
			return rc_seterr(err, "Hurst exponent %g: must be in (0, 1)", p->hurst);
		if (p->lambda_r != 0 && !positive(p->lambda_r))
			return rc_seterr(err, "lambda_r %g: must be positive and finite",
			    p->lambda_r);
		if (p->lambda_s != 0 && !positive(p->lambda_s))
			return rc_seterr(err, "lambda_s %g: must be positive and finite",
			    p->lambda_s);
		if (ls < min_lambda_s(p) * (1 - EDGE_TOL))
			return rc_seterr(err, "lambda_s %g: must be at least two grid "
			    "spacings, max(2 dx/g, 2 dy g) = %g for Peklenik g = %g",
			    ls, min_lambda_s(p), p->peklenik);
		if (!(lr > ls))
			return rc_seterr(err, "lambda_r %g: must exceed lambda_s %g", lr, ls);
		if (!positive(p->peklenik))
			return rc_seterr(err, "Peklenik parameter %g: must be positive and "
			    "finite", p->peklenik);
		if (p->rolloff != 0 && p->rolloff != 1)
			return rc_seterr(err, "rolloff %d: must be 0 or 1", p->rolloff);
		if (p->gaussian_amplitudes != 0 && p->gaussian_amplitudes != 1)
			return rc_seterr(err, "gaussian_amplitudes %d: must be 0 or 1",
			    p->gaussian_amplitudes);
		break;
	case RC_SURF_HARMONIC:
		if (!positive(p->exponent))
			return rc_seterr(err, "exponent %g: must be positive and finite",
			    p->exponent);
		if (!positive(p->radius))
			return rc_seterr(err, "radius %g: must be positive and finite",
			    p->radius);
		break;
	case RC_SURF_SINE:
	case RC_SURF_EGGBOX:
		w = rc_synth_wavelength(p);
		if (p->wavelength != 0 && !positive(p->wavelength))
			return rc_seterr(err, "wavelength %g: must be positive and finite",
			    p->wavelength);
		if (!isfinite(p->amplitude))
			return rc_seterr(err, "amplitude %g: must be finite", p->amplitude);
		if (!divides(w, p->lx))
			return rc_seterr(err, "wavelength %g: must divide the cell length "
			    "lx = %g (periodicity)", w, p->lx);
		if (p->type == RC_SURF_EGGBOX && !divides(w, p->ly))
			return rc_seterr(err, "wavelength %g: must divide the cell length "
			    "ly = %g (periodicity)", w, p->ly);
		break;
	case RC_SURF_FLAT:
		if (p->rms_gradient > 0 || p->rms_height > 0)
			return rc_seterr(err, "a flat surface cannot be normalised to an "
			    "rms gradient or height");
		break;
	}
	return 0;
}

/* SplitMix64's output function: a bijective, well-mixed 64-bit hash. */
static uint64_t
mix64(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

#define GOLDEN 0x9e3779b97f4a7c15ULL

/* The random stream of mode (kx, ky): a hash of the seed and the two
 * integers, each folded in through the mixer so that nearby wave vectors
 * and nearby seeds give unrelated streams. */
static uint64_t
mode_key(uint64_t seed, long kx, long ky)
{
	uint64_t h = mix64(seed + GOLDEN);

	h = mix64(h ^ ((uint64_t)(int64_t)kx + 2 * GOLDEN));
	h = mix64(h ^ ((uint64_t)(int64_t)ky + 3 * GOLDEN));
	return h;
}

/* Draw number `draw` of a mode's stream as a uniform number in (0, 1). */
static double
mode_uniform(uint64_t key, unsigned draw)
{
	uint64_t z = mix64(key + (uint64_t)(draw + 1) * GOLDEN);

	return ((double)(z >> 11) + 0.5) * 0x1.0p-53;
}

uint64_t
rc_synth_mode_key(uint64_t seed, long kx, long ky)
{
	return mode_key(seed, kx, ky);
}

/* sqrt(C(q_P)/C(q_r)) for the self-affine spectrum of Eq. 2, with the
 * band q_r <= q_P < q_s (see synth.h); takes squares, saving a sqrt. */
static double
spectrum_amplitude(double qp2, double qr2, double qs2, double hurst, int rolloff)
{
	if (qp2 >= qs2 * (1 - 2 * EDGE_TOL))
		return 0;
	if (qp2 < qr2 * (1 - 2 * EDGE_TOL))
		return rolloff ? 1 : 0;
	return exp(-0.5 * (1 + hurst) * log(qp2 / qr2));
}

/* Signed integer index of row/column k on an n-point axis. */
static long
signed_index(size_t k, size_t n)
{
	return k <= n / 2 ? (long)k : (long)k - (long)n;
}

/* Fill spec (rows j0 ... j0 + rows - 1 of the ny x nxc half-complex
 * modes) with the unnormalised self-affine modes; sums[j - j0] receives
 * row j's contribution to sum over the full plane of weight * |a|^2,
 * weight q^2 (gradient) or 1 (height). */
static void
fill_rows(const rc_synth_params *p, fftw_complex *spec, size_t nxc,
    size_t j0, size_t rows, double *sums, int by_gradient)
{
	double qr = 2 * M_PI / rc_synth_lambda_r(p);
	double qs = 2 * M_PI / rc_synth_lambda_s(p);
	double g2 = p->peklenik * p->peklenik;
	long jy;

#pragma omp parallel for schedule(static)
	for (jy = 0; jy < (long)rows; jy++) {
		size_t j = j0 + (size_t)jy;
		long ky = signed_index(j, p->ny);
		double qy = rc_wavenumber(j, p->ny, p->ly), row = 0;
		int nyq_row = rc_is_nyquist(j, p->ny);

		for (size_t i = 0; i < nxc; i++) {
			long kx = (long)i;
			double qx = rc_wavenumber(i, p->nx, p->lx);
			double q2 = qx * qx + qy * qy, amp, phase;
			double complex a = 0;
			int mirror = 0;
			uint64_t key;

			/* Nyquist modes cannot carry a random phase (they
			 * are their own mirror) and q = 0 is the mean. */
			if (nyq_row || rc_is_nyquist(i, p->nx) || (kx == 0 && ky == 0)) {
				spec[(size_t)jy * nxc + i] = 0;
				continue;
			}
			amp = spectrum_amplitude(g2 * qx * qx + qy * qy / g2,
			    qr * qr, qs * qs, p->hurst, p->rolloff);
			if (amp > 0) {
				/* Canonical half plane: kx > 0, or kx = 0 and
				 * ky > 0; the other half holds conjugates. */
				mirror = kx == 0 && ky < 0;
				key = mirror ? mode_key(p->seed, 0, -ky) :
				    mode_key(p->seed, kx, ky);
				phase = 2 * M_PI * mode_uniform(key, 0);
				if (p->gaussian_amplitudes)
					amp *= sqrt(-log(mode_uniform(key, 1)));
				a = amp * cos(phase) + I * (amp * sin(phase));
				if (mirror)
					a = conj(a);
				row += rc_fft_weight(i, p->nx) * amp * amp *
				    (by_gradient ? q2 : 1.0);
			}
			spec[(size_t)jy * nxc + i] = a;
		}
		sums[jy] = row;
	}
}

static void
fill_selfaffine(const rc_synth_params *p, fftw_complex *spec, size_t nxc,
    double *sums, int by_gradient)
{
	fill_rows(p, spec, nxc, 0, p->ny, sums, by_gradient);
}

void
rc_synth_selfaffine_rows(const rc_synth_params *p, fftw_complex *spec,
    size_t j0, size_t rows, double *sums)
{
	fill_rows(p, spec, p->nx / 2 + 1, j0, rows, sums, !(p->rms_height > 0));
}

/* The surface in place: the half-complex modes are filled into one buffer
 * of ny rows of nxc complex values, transformed in place (real rows padded
 * to 2 nxc doubles), and the rows are packed to nx doubles; the buffer then
 * becomes the grid's values, so the peak is one grid plus 2 ny values. */
static rc_grid *
make_selfaffine(const rc_synth_params *p, enum rc_fft_effort effort,
    double *plan_seconds, rc_err *err)
{
	size_t nxc = p->nx / 2 + 1, nspec = nxc * p->ny;
	fftw_complex *spec;
	double *sums, *real, total = 0, target, scale;
	int by_gradient = !(p->rms_height > 0);
	fftw_plan plan;
	rc_grid *g;
	long k;

	target = by_gradient ? (p->rms_gradient > 0 ? p->rms_gradient : 1.0) :
	    p->rms_height;
	if ((spec = fftw_alloc_complex(nspec)) == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes)",
		    nspec * sizeof(fftw_complex));
		return NULL;
	}
	if ((sums = rc_malloc(p->ny * sizeof(double), err)) == NULL) {
		fftw_free(spec);
		return NULL;
	}
	/* Plan before filling: planning may scribble on the array. */
	plan = rc_fft_plan_c2r_inplace(p->nx, p->ny, spec, effort, plan_seconds,
	    NULL, err);
	if (plan == NULL) {
		free(sums);
		fftw_free(spec);
		return NULL;
	}
	fill_selfaffine(p, spec, nxc, sums, by_gradient);
	/* Summed in row order whatever the thread count, so the result is
	 * bit for bit the same for any -j. */
	for (size_t j = 0; j < p->ny; j++)
		total += sums[j];
	free(sums);
	if (!(total > 0)) {
		fftw_destroy_plan(plan);
		fftw_free(spec);
		rc_seterr(err, "no grid mode lies in the band lambda_s = %g <= "
		    "lambda < lambda_r = %g; enlarge the cell or widen the band",
		    rc_synth_lambda_s(p), rc_synth_lambda_r(p));
		return NULL;
	}
	scale = target / sqrt(total);
#pragma omp parallel for schedule(static)
	for (k = 0; k < (long)nspec; k++)
		spec[k] *= scale;
	fftw_execute(plan);
	fftw_destroy_plan(plan);
	/* Pack the padded rows (2 nxc apart) to nx apart.  Row j moves to
	 * where earlier rows were, so this runs in row order. */
	real = (double *)spec;
	for (size_t j = 1; j < p->ny; j++)
		memmove(real + j * p->nx, real + j * 2 * nxc, p->nx * sizeof(double));
	if ((g = rc_grid_adopt(p->nx, p->ny, p->lx, p->ly, real, err)) == NULL)
		fftw_free(spec);
	return g;
}

/* Distance along an axis of length l to the nearest image of l/2. */
static double
periodic_offset(double x, double l)
{
	double d = x - 0.5 * l;

	return d - l * nearbyint(d / l);
}

/* Rows j0 ... j0 + rows - 1 of the harmonic indenter into z (nx apart). */
static void
harmonic_rows(const rc_synth_params *p, double *z, size_t j0, size_t rows)
{
	double n = p->exponent, r0 = p->radius;
	long jy;

#pragma omp parallel for schedule(static)
	for (jy = 0; jy < (long)rows; jy++) {
		size_t j = j0 + (size_t)jy;
		double dy = periodic_offset(p->ly * (double)j / (double)p->ny, p->ly);
		for (size_t i = 0; i < p->nx; i++) {
			double dx = periodic_offset(p->lx * (double)i / (double)p->nx,
			    p->lx);
			double r = hypot(dx, dy);
			/* -(r0/n) (r/r0)^n as -r^n r0^(1-n)/n in logarithms:
			 * r/r0 overflows for a tiny r0 long before z does */
			z[(size_t)jy * p->nx + i] = r == 0 ? 0 :
			    -exp(n * log(r) + (1 - n) * log(r0)) / n;
		}
	}
}

static void
make_harmonic(const rc_synth_params *p, rc_grid *g)
{
	harmonic_rows(p, g->z, 0, p->ny);
}

/* Rows j0 ... j0 + rows - 1 of the sine or egg-box surface into z. */
static void
wave_rows(const rc_synth_params *p, double *z, size_t j0, size_t rows)
{
	double w = rc_synth_wavelength(p);
	/* Whole periods per cell: the phase of point i is 2 pi m i / nx
	 * exactly, which keeps the wave periodic without rounding drift. */
	double mx = nearbyint(p->lx / w), my = nearbyint(p->ly / w);
	long jy;

#pragma omp parallel for schedule(static)
	for (jy = 0; jy < (long)rows; jy++) {
		size_t j = j0 + (size_t)jy;
		double cy = p->type == RC_SURF_EGGBOX ?
		    cos(2 * M_PI * fmod(my * (double)j, (double)p->ny) / (double)p->ny) : 1;
		for (size_t i = 0; i < p->nx; i++) {
			double cx = cos(2 * M_PI * fmod(mx * (double)i, (double)p->nx) /
			    (double)p->nx);
			z[(size_t)jy * p->nx + i] = p->amplitude * cx * cy;
		}
	}
}

static void
make_waves(const rc_synth_params *p, rc_grid *g)
{
	wave_rows(p, g->z, 0, p->ny);
}

int
rc_synth_pointwise_rows(const rc_synth_params *p, double *z, size_t j0,
    size_t rows, rc_err *err)
{
	switch (p->type) {
	case RC_SURF_HARMONIC:
		harmonic_rows(p, z, j0, rows);
		return 0;
	case RC_SURF_SINE:
	case RC_SURF_EGGBOX:
		wave_rows(p, z, j0, rows);
		return 0;
	case RC_SURF_FLAT:
		memset(z, 0, rows * p->nx * sizeof(double));
		return 0;
	default:
		return rc_seterr(err, "internal: %s is not a pointwise surface type",
		    rc_surface_type_name(p->type));
	}
}

/* Scale a deterministic surface to the rms gradient or height asked for. */
static int
normalise(const rc_synth_params *p, rc_grid *g, double *scale, rc_err *err)
{
	double now, n = (double)rc_grid_size(g);

	*scale = 1;
	if (p->rms_gradient > 0) {
		if (rc_rms_gradient(g, NULL, &now, err) != 0)
			return -1;
	} else if (p->rms_height > 0) {
		rc_mean_rms(g->z, rc_grid_size(g), NULL, &now);
	} else
		return 0;
	if (!(now > 0))
		return rc_seterr(err, "the surface has zero rms %s; it cannot be "
		    "normalised", p->rms_gradient > 0 ? "gradient" : "height");
	*scale = (p->rms_gradient > 0 ? p->rms_gradient : p->rms_height) / now;
	double factor = *scale;
	long nl = (long)n;
#pragma omp parallel for schedule(static)
	for (long k = 0; k < nl; k++)
		g->z[k] *= factor;
	return 0;
}

static int
write_meta(const rc_synth_params *p, rc_grid *g, double scale, rc_err *err)
{
	int bad = 0;

	bad |= rc_grid_meta_set(g, "type", rc_surface_type_name(p->type), err);
	switch (p->type) {
	case RC_SURF_SELFAFFINE:
		bad |= rc_grid_meta_setd(g, "H", p->hurst, err);
		bad |= rc_grid_meta_setd(g, "lambda_r", rc_synth_lambda_r(p), err);
		bad |= rc_grid_meta_setd(g, "lambda_s", rc_synth_lambda_s(p), err);
		bad |= rc_grid_meta_setf(g, "rolloff", err, "%d", p->rolloff);
		bad |= rc_grid_meta_setd(g, "peklenik", p->peklenik, err);
		bad |= rc_grid_meta_setf(g, "seed", err, "%llu",
		    (unsigned long long)p->seed);
		bad |= rc_grid_meta_set(g, "amplitudes",
		    p->gaussian_amplitudes ? "gaussian" : "sqrt", err);
		if (p->rms_height > 0)
			bad |= rc_grid_meta_setd(g, "rms_height", p->rms_height, err);
		else
			bad |= rc_grid_meta_setd(g, "rms_gradient",
			    p->rms_gradient > 0 ? p->rms_gradient : 1.0, err);
		return bad ? -1 : 0;
	case RC_SURF_HARMONIC:
		bad |= rc_grid_meta_setd(g, "exponent", p->exponent, err);
		bad |= rc_grid_meta_setd(g, "radius", p->radius, err);
		break;
	case RC_SURF_SINE:
	case RC_SURF_EGGBOX:
		bad |= rc_grid_meta_setd(g, "wavelength", rc_synth_wavelength(p), err);
		/* The amplitude of the surface as written, after any scaling. */
		bad |= rc_grid_meta_setd(g, "amplitude", p->amplitude * scale, err);
		break;
	case RC_SURF_FLAT:
		break;
	}
	if (p->rms_gradient > 0)
		bad |= rc_grid_meta_setd(g, "rms_gradient", p->rms_gradient, err);
	else if (p->rms_height > 0)
		bad |= rc_grid_meta_setd(g, "rms_height", p->rms_height, err);
	return bad ? -1 : 0;
}

int
rc_synth_meta(const rc_synth_params *p, rc_grid *g, double scale, rc_err *err)
{
	g->kind = RC_KIND_HEIGHT;
	return write_meta(p, g, scale, err);
}

rc_grid *
rc_synth(const rc_synth_params *p, rc_err *err)
{
	return rc_synth_planned(p, RC_FFT_ESTIMATE, NULL, err);
}

rc_grid *
rc_synth_planned(const rc_synth_params *p, enum rc_fft_effort effort,
    double *plan_seconds, rc_err *err)
{
	rc_grid *g;
	double scale = 1;
	size_t bad;

	if (plan_seconds != NULL)
		*plan_seconds = 0;
	if (rc_synth_check(p, err) != 0)
		return NULL;
	if (p->type == RC_SURF_SELFAFFINE)
		g = make_selfaffine(p, effort, plan_seconds, err);
	else
		g = rc_grid_new(p->nx, p->ny, p->lx, p->ly, err);
	if (g == NULL)
		return NULL;
	g->kind = RC_KIND_HEIGHT;
	switch (p->type) {
	case RC_SURF_SELFAFFINE:
		break;
	case RC_SURF_HARMONIC:
		make_harmonic(p, g);
		break;
	case RC_SURF_SINE:
	case RC_SURF_EGGBOX:
		make_waves(p, g);
		break;
	case RC_SURF_FLAT:
		break;
	}
	if (p->type != RC_SURF_SELFAFFINE && normalise(p, g, &scale, err) != 0)
		goto fail;
	if (!rc_grid_all_finite(g, &bad)) {
		rc_seterr(err, "%s surface: the height at i=%zu, j=%zu is not finite "
		    "(it overflows: %s)", rc_surface_type_name(p->type), bad % p->nx,
		    bad / p->nx, p->type == RC_SURF_HARMONIC ? "a larger --radius "
		    "or a smaller --exponent" : "smaller amplitudes or lengths");
		goto fail;
	}
	if (write_meta(p, g, scale, err) != 0)
		goto fail;
	return g;
fail:
	rc_grid_free(g);
	return NULL;
}
