/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stats.c - height statistics, Phi1..Phi9, gradient tensor by height. */
#include "stats.h"
#include "gridcheck.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/*
 * Sums over the grid are deterministic for any thread count: the points
 * are cut into NPART fixed ranges (depending on the size only), threads
 * sum whole ranges, and the range sums are added in order.  So surfstat
 * prints the same digits whatever -j is.
 */
#define NPART 64

static size_t
part_start(long p, size_t n)
{
	return (size_t)p * n / NPART;
}

/* Add part sums part[p][0 .. k-1] in order into out[0 .. k-1]. */
static void
ordered_sums(double (*part)[16], int k, double *out)
{
	for (int i = 0; i < k; i++) {
		out[i] = 0;
		for (int p = 0; p < NPART; p++)
			out[i] += part[p][i];
	}
}

const char *
rc_deriv_method_name(enum rc_deriv_method m)
{
	return m == RC_DERIV_FD ? "finite-difference" : "spectral";
}

/* The fields of rc_deriv_fields, in enum rc_deriv's order (gradient.h). */
#define F_X	RC_DERIV_X
#define F_Y	RC_DERIV_Y
#define F_LAP	RC_DERIV_LAPLACIAN
#define F_XX	RC_DERIV_XX
#define F_COUNT	4

static int
spectral_fields(const rc_grid *g, rc_fft *fft, double *out[F_COUNT],
    rc_err *err)
{
	rc_fft own;
	size_t n = rc_grid_size(g), nspec;
	double complex *spec0;
	int rc = -1;

	if ((fft = rc_fft_borrow(fft, &own, g->nx, g->ny, err)) == NULL)
		return -1;
	nspec = fft->nxc * g->ny;
	/* The backward transform destroys its input: keep the spectrum. */
	if ((spec0 = fftw_alloc_complex(nspec)) == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes)",
		    nspec * sizeof(double complex));
		goto out;
	}
	memcpy(fft->real, g->z, n * sizeof(double));
	rc_fft_forward(fft);
	memcpy(spec0, fft->spec, nspec * sizeof(double complex));
	for (int d = 0; d < F_COUNT; d++) {
		if (out[d] == NULL)
			continue;
		rc_deriv_spectral(fft->spec, spec0, (enum rc_deriv)d, g->nx,
		    g->ny, g->lx, g->ly, 0, g->ny);
		rc_fft_backward(fft);
		memcpy(out[d], fft->real, n * sizeof(double));
	}
	rc = 0;
	fftw_free(spec0);
out:
	rc_fft_free(&own);
	return rc;
}

/* The central stencil (gradient.h) at every point. */
static void
fd_fields(const rc_grid *g, double *out[F_COUNT])
{
	size_t nx = g->nx, ny = g->ny;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;

	#pragma omp parallel for
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			size_t k = j * nx + i;
			double d[4];

			rc_deriv_central(g->z, nx, ny, i, j, dx, dy, d);
			if (out[F_X])
				out[F_X][k] = d[RC_D_X];
			if (out[F_Y])
				out[F_Y][k] = d[RC_D_Y];
			if (out[F_LAP])
				out[F_LAP][k] = d[RC_D_XX] + d[RC_D_YY];
			if (out[F_XX])
				out[F_XX][k] = d[RC_D_XX];
		}
}

int
rc_deriv_fields(const rc_grid *g, enum rc_deriv_method m, rc_fft *fft,
    double *hx, double *hy, double *lap, double *hxx, rc_err *err)
{
	double *out[F_COUNT] = { hx, hy, lap, hxx };

	if (m == RC_DERIV_FD) {
		fd_fields(g, out);
		return 0;
	}
	return spectral_fields(g, fft, out, err);
}

/* One derivative field into out, which may be fft->real (then no copy).
 * Spectral: the grid is transformed afresh for each field, which costs a
 * transform but saves keeping a copy of the spectrum. */
static int
one_field(const rc_grid *g, enum rc_deriv_method m, rc_fft *fft, enum rc_deriv d,
    double *out, rc_err *err)
{
	size_t n = rc_grid_size(g);

	if (m == RC_DERIV_FD) {
		double *fields[F_COUNT] = { NULL, NULL, NULL, NULL };
		fields[d] = out;
		fd_fields(g, fields);
		return 0;
	}
	if (fft->nx != g->nx || fft->ny != g->ny)
		return rc_seterr(err, "internal: FFT plan %zux%zu for a %zux%zu grid",
		    fft->nx, fft->ny, g->nx, g->ny);
	memcpy(fft->real, g->z, n * sizeof(double));
	rc_fft_forward(fft);
	rc_deriv_spectral(fft->spec, fft->spec, d, g->nx, g->ny, g->lx, g->ly,
	    0, g->ny);
	rc_fft_backward(fft);
	if (out != fft->real)
		memcpy(out, fft->real, n * sizeof(double));
	return 0;
}

size_t
rc_mask_check(const rc_grid *mask, const rc_grid *g, rc_err *err)
{
	size_t n = rc_grid_size(g), count = 0;

	if (mask->nx != g->nx || mask->ny != g->ny) {
		rc_seterr(err, "mask is %zux%zu but the surface is %zux%zu",
		    mask->nx, mask->ny, g->nx, g->ny);
		return 0;
	}
	for (size_t k = 0; k < n; k++) {
		if (mask->z[k] == 1)
			count++;
		else if (mask->z[k] != 0) {
			rc_seterr(err, "mask value %g at point %zu: want 0 or 1",
			    mask->z[k], k);
			return 0;
		}
	}
	if (count == 0)
		rc_seterr(err, "mask has no point set to 1");
	return count;
}

static int
in_set(const rc_grid *mask, size_t k)
{
	return mask == NULL || mask->z[k] == 1;
}

/* a / b, NaN when b is not positive (an undefined normalisation). */
static double
ratio(double a, double b)
{
	return b > 0 ? a / b : NAN;
}

/* Buffers for two derivative fields at a time: the first of its own, the
 * second the plan's real buffer (spectral) or of its own (FD).  With the
 * plan's two buffers that is 32 bytes per point beyond the grid's 8
 * (spectral), 16 (FD). */
struct pair {
	rc_fft own, *fft;
	double *a, *b, *b_own;
};

static void
pair_free(struct pair *p)
{
	fftw_free(p->a);
	fftw_free(p->b_own);
	rc_fft_free(&p->own);
}

static int
pair_make(const rc_grid *g, enum rc_deriv_method m, rc_fft *fft,
    struct pair *p, rc_err *err)
{
	size_t n = rc_grid_size(g);

	memset(p, 0, sizeof(*p));
	if (m == RC_DERIV_SPECTRAL) {
		if (fft == NULL) {
			if (rc_fft_init(&p->own, g->nx, g->ny, RC_FFT_ESTIMATE, err) != 0)
				return -1;
			fft = &p->own;
		}
		p->fft = fft;
		p->b = fft->real;
	} else if ((p->b = p->b_own = fftw_alloc_real(n)) == NULL)
		goto nomem;
	if ((p->a = fftw_alloc_real(n)) == NULL)
		goto nomem;
	return 0;
nomem:
	pair_free(p);
	return rc_seterr(err, "out of memory (asked for %zu bytes)", n * sizeof(double));
}

int
rc_stats_compute(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_stats *s, rc_err *err)
{
	return rc_stats_compute_fft(g, mask, m, NULL, s, err);
}

/* Heights beyond 2^+-SCALE_EXP_MAX in magnitude are first scaled by a
 * power of two: the statistics take fourth powers of heights and their
 * derivatives, which overflow near 1e150 (and underflow near 1e-150).
 * The scaling is exact, and every statistic is a power of the heights
 * times a scale-free number, so it is undone exactly. */
#define SCALE_EXP_MAX 100

/* The exponent to scale g's heights by (0: none needed), and the scaled
 * copy in *scaled (NULL when none is needed). */
static int
scaled_copy(const rc_grid *g, rc_grid **scaled, int *e, rc_err *err)
{
	size_t n = rc_grid_size(g);
	double zmax = 0;

	*scaled = NULL;
	*e = 0;
	if (rc_grid_check_uniform(g, err) != 0)
		return -1;
	for (size_t k = 0; k < n; k++)
		if (isfinite(g->z[k]))
			zmax = fmax(zmax, fabs(g->z[k]));
	if (zmax == 0 || (ilogb(zmax) <= SCALE_EXP_MAX &&
	    ilogb(zmax) >= -SCALE_EXP_MAX))
		return 0;
	*e = ilogb(zmax);
	if ((*scaled = rc_grid_clone(g, 1, err)) == NULL)
		return -1;
	for (size_t k = 0; k < n; k++)
		(*scaled)->z[k] = ldexp(g->z[k], -*e);
	return 0;
}

static int stats_compute(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, rc_stats *s, rc_err *err);

int
rc_stats_compute_fft(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, rc_stats *s, rc_err *err)
{
	rc_grid *scaled;
	int e, rc;

	if (scaled_copy(g, &scaled, &e, err) != 0)
		return -1;
	if (scaled == NULL)
		return stats_compute(g, mask, m, fft, s, err);
	rc = stats_compute(scaled, mask, m, fft, s, err);
	rc_grid_free(scaled);
	/* heights, gradients, Laplacians scale as h; the tensor M as h^2;
	 * skewness, kurtosis, Nayak and the phi are scale-free */
	s->mean = ldexp(s->mean, e);
	s->hrms = ldexp(s->hrms, e);
	s->hmin = ldexp(s->hmin, e);
	s->hmax = ldexp(s->hmax, e);
	s->gbar = ldexp(s->gbar, e);
	s->gbar_prime = ldexp(s->gbar_prime, e);
	s->rms_laplacian = ldexp(s->rms_laplacian, e);
	s->mxx = ldexp(s->mxx, 2 * e);
	s->myy = ldexp(s->myy, 2 * e);
	s->mxy = ldexp(s->mxy, 2 * e);
	return rc;
}

/* Long: three reduction passes over one derivative buffer (and the
 * rc_field_sums of gbar and gbar_prime, shared with gfmd-solve), ordered
 * to need one field at a time; split, their dozen sums would travel in a
 * struct. */
static int
stats_compute(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, rc_stats *s, rc_err *err)
{
	size_t n = rc_grid_size(g), count = n;
	struct pair pr;
	const double *h = g->z;
	double sum, mean, hmin = INFINITY, hmax = -INFINITY;
	double part[NPART][16], sums[16];
	/* Sums of the averages, named after what they average. */
	double m2, m3, m4, mxx, myy, mxy, hxx2;
	double dh_g2, dh2_lap, lap1, dh2_g2, dh3_lap;
	double lap2, dh2_lap2, g4, dh_lap, grad2, unused;
	unsigned char *set = NULL;	/* the mask for rc_field_sums */

	if (mask != NULL && (count = rc_mask_check(mask, g, err)) == 0)
		return -1;
	if (mask != NULL && (set = rc_malloc(n, err)) == NULL)
		return -1;
	for (size_t k = 0; set != NULL && k < n; k++)
		set[k] = mask->z[k] == 1;
	if (pair_make(g, m, fft, &pr, err) != 0) {
		free(set);
		return -1;
	}
	const double *hx = pr.a, *hy = pr.b, *lap = pr.b, *hxx = pr.b;

	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double acc = 0, lo = INFINITY, hi = -INFINITY;
		for (size_t k = part_start(p, n); k < part_start(p + 1, n); k++) {
			if (!in_set(mask, k))
				continue;
			acc += h[k];
			lo = fmin(lo, h[k]);
			hi = fmax(hi, h[k]);
		}
		part[p][0] = acc;
		part[p][1] = lo;
		part[p][2] = hi;
	}
	ordered_sums(part, 1, &sum);
	for (int p = 0; p < NPART; p++) {
		hmin = fmin(hmin, part[p][1]);
		hmax = fmax(hmax, part[p][2]);
	}
	mean = sum / (double)count;

	/* The gradient: both components at once (M_xy, |grad h|^4). */
	if (one_field(g, m, pr.fft, F_X, pr.a, err) != 0 ||
	    one_field(g, m, pr.fft, F_Y, pr.b, err) != 0)
		goto fail;
	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double *a = part[p];
		memset(a, 0, 9 * sizeof(double));
		for (size_t k = part_start(p, n); k < part_start(p + 1, n); k++) {
			if (!in_set(mask, k))
				continue;
			double d = h[k] - mean, d2 = d * d;
			double gx2 = hx[k] * hx[k], gy2 = hy[k] * hy[k], g2 = gx2 + gy2;
			a[0] += d2;
			a[1] += d2 * d;
			a[2] += d2 * d2;
			a[3] += gx2;
			a[4] += gy2;
			a[5] += hx[k] * hy[k];
			a[6] += d * g2;
			a[7] += d2 * g2;
			a[8] += g2 * g2;
		}
	}
	ordered_sums(part, 9, sums);
	m2 = sums[0]; m3 = sums[1]; m4 = sums[2]; mxx = sums[3]; myy = sums[4];
	mxy = sums[5]; dh_g2 = sums[6]; dh2_g2 = sums[7]; g4 = sums[8];
	rc_field_sums(h, hx, hy, NULL, set, n, mean, &grad2, &unused);
	if (one_field(g, m, pr.fft, F_LAP, pr.b, err) != 0)
		goto fail;
	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double *a = part[p];
		memset(a, 0, 5 * sizeof(double));
		for (size_t k = part_start(p, n); k < part_start(p + 1, n); k++) {
			if (!in_set(mask, k))
				continue;
			double d = h[k] - mean, d2 = d * d, l = lap[k];
			a[0] += d2 * l;
			a[1] += l;
			a[2] += d2 * d * l;
			a[3] += l * l;
			a[4] += d2 * l * l;
		}
	}
	ordered_sums(part, 5, sums);
	dh2_lap = sums[0]; lap1 = sums[1]; dh3_lap = sums[2]; lap2 = sums[3];
	dh2_lap2 = sums[4];
	rc_field_sums(h, NULL, NULL, lap, set, n, mean, &unused, &dh_lap);
	if (one_field(g, m, pr.fft, F_XX, pr.b, err) != 0)
		goto fail;
	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double acc = 0;
		for (size_t k = part_start(p, n); k < part_start(p + 1, n); k++)
			if (in_set(mask, k))
				acc += hxx[k] * hxx[k];
		part[p][0] = acc;
	}
	ordered_sums(part, 1, &hxx2);
	pair_free(&pr);
	free(set);

	double c = (double)count;
	m2 /= c; m3 /= c; m4 /= c; mxx /= c; myy /= c; mxy /= c; hxx2 /= c;
	dh_g2 /= c; dh2_lap /= c; lap1 /= c; dh2_g2 /= c; dh3_lap /= c;
	lap2 /= c; dh2_lap2 /= c; g4 /= c; dh_lap /= c; grad2 /= c;

	double gg = mxx + myy, rm2 = sqrt(m2), gg2 = gg * gg;
	double trm2 = mxx * mxx + myy * myy + 2 * mxy * mxy;

	s->n_avg = count;
	s->fraction = c / (double)n;
	s->mean = mean;
	s->hrms = rm2;
	s->skewness = ratio(m3, m2 * rm2);
	s->kurtosis = ratio(m4, m2 * m2);
	s->hmin = hmin;
	s->hmax = hmax;
	s->gbar = sqrt(grad2);
	s->gbar_prime = rc_signed_root(-dh_lap);
	s->rms_laplacian = sqrt(lap2);
	s->mxx = mxx;
	s->myy = myy;
	s->mxy = mxy;
	s->nayak = ratio(m2 * hxx2, mxx * mxx);
	s->phi[0] = NAN;
	s->phi[1] = ratio(dh_g2, rm2 * gg);
	s->phi[2] = ratio(-dh2_lap, 2 * rm2 * gg);
	s->phi[3] = ratio(-m2 * lap1, 2 * rm2 * gg);
	s->phi[4] = ratio(dh2_g2, m2 * gg);
	s->phi[5] = ratio(-dh3_lap, 3 * m2 * gg);
	s->phi[6] = ratio(m2 * lap2, gg2);
	s->phi[7] = ratio(2 * dh2_lap2, 3 * gg2);
	s->phi[8] = ratio(g4 - gg2 - 2 * trm2, gg2);
	s->phi[9] = ratio((mxx - myy) * (mxx - myy) + 4 * mxy * mxy, gg2);
	return 0;
fail:
	pair_free(&pr);
	free(set);
	return -1;
}

int
rc_stats_by_height(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, size_t nbins, rc_height_bin *bins, rc_err *err)
{
	return rc_stats_by_height_fft(g, mask, m, NULL, nbins, bins, err);
}

static int by_height(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, size_t nbins, rc_height_bin *bins,
    rc_err *err);

int
rc_stats_by_height_fft(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, size_t nbins, rc_height_bin *bins,
    rc_err *err)
{
	rc_grid *scaled;
	int e, rc;

	if (scaled_copy(g, &scaled, &e, err) != 0)
		return -1;
	if (scaled == NULL)
		return by_height(g, mask, m, fft, nbins, bins, err);
	rc = by_height(scaled, mask, m, fft, nbins, bins, err);
	rc_grid_free(scaled);
	for (size_t b = 0; rc == 0 && b < nbins; b++) {
		bins[b].h_lo = ldexp(bins[b].h_lo, e);
		bins[b].h_hi = ldexp(bins[b].h_hi, e);
		bins[b].h_mid = ldexp(bins[b].h_mid, e);
		bins[b].gbar = ldexp(bins[b].gbar, e);
		bins[b].mxx = ldexp(bins[b].mxx, 2 * e);
		bins[b].myy = ldexp(bins[b].myy, 2 * e);
		bins[b].mxy = ldexp(bins[b].mxy, 2 * e);
	}
	return rc;
}

static int
by_height(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, size_t nbins, rc_height_bin *bins,
    rc_err *err)
{
	size_t n = rc_grid_size(g);
	struct pair pr;
	double hmin = INFINITY, hmax = -INFINITY, width;

	if (nbins == 0)
		return rc_seterr(err, "number of height bins must be positive");
	if (mask != NULL && rc_mask_check(mask, g, err) == 0)
		return -1;
	#pragma omp parallel for reduction(min:hmin) reduction(max:hmax)
	for (size_t k = 0; k < n; k++) {
		if (!in_set(mask, k))
			continue;
		hmin = fmin(hmin, g->z[k]);
		hmax = fmax(hmax, g->z[k]);
	}
	if (pair_make(g, m, fft, &pr, err) != 0)
		return -1;
	if (one_field(g, m, pr.fft, F_X, pr.a, err) != 0 ||
	    one_field(g, m, pr.fft, F_Y, pr.b, err) != 0) {
		pair_free(&pr);
		return -1;
	}
	width = (hmax - hmin) / (double)nbins;
	for (size_t b = 0; b < nbins; b++) {
		memset(&bins[b], 0, sizeof(bins[b]));
		bins[b].h_lo = hmin + width * (double)b;
		bins[b].h_hi = b + 1 == nbins ? hmax : hmin + width * (double)(b + 1);
		bins[b].h_mid = 0.5 * (bins[b].h_lo + bins[b].h_hi);
	}
	for (size_t k = 0; k < n; k++) {
		if (!in_set(mask, k))
			continue;
		/* A flat set (width 0) goes into the first bin. */
		size_t b = width > 0 ? (size_t)((g->z[k] - hmin) / width) : 0;
		if (b >= nbins)
			b = nbins - 1;	/* the maximum itself */
		double gx = pr.a[k], gy = pr.b[k];
		bins[b].n++;
		bins[b].mxx += gx * gx;
		bins[b].myy += gy * gy;
		bins[b].mxy += gx * gy;
	}
	pair_free(&pr);
	for (size_t b = 0; b < nbins; b++) {
		double c = (double)bins[b].n;
		if (bins[b].n == 0) {
			bins[b].mxx = bins[b].myy = bins[b].mxy = bins[b].gbar = NAN;
			continue;
		}
		bins[b].mxx /= c;
		bins[b].myy /= c;
		bins[b].mxy /= c;
		bins[b].gbar = sqrt(bins[b].mxx + bins[b].myy);
	}
	return 0;
}
