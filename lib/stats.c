/* stats.c - height statistics, Phi1..Phi9, gradient tensor by height. */
#include "stats.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

const char *
rc_deriv_method_name(enum rc_deriv_method m)
{
	return m == RC_DERIV_FD ? "finite-difference" : "spectral";
}

enum field { F_X, F_Y, F_LAP, F_XX, F_COUNT };

/* Spectral factor of field d at mode (i, j); odd derivatives use the
 * Nyquist-zeroed wave numbers. */
static double complex
spectral_factor(const rc_grid *g, enum field d, size_t i, size_t j)
{
	double qx = rc_wavenumber(i, g->nx, g->lx);
	double qy = rc_wavenumber(j, g->ny, g->ly);

	switch (d) {
	case F_X:
		return I * rc_deriv_wavenumber(i, g->nx, g->lx);
	case F_Y:
		return I * rc_deriv_wavenumber(j, g->ny, g->ly);
	case F_LAP:
		return -(qx * qx + qy * qy);
	default:
		return -qx * qx;
	}
}

static int
spectral_fields(const rc_grid *g, rc_fft *fft, double *out[F_COUNT],
    rc_err *err)
{
	rc_fft own;
	size_t n = rc_grid_size(g), nspec;
	double complex *spec0;
	int rc = -1;

	memset(&own, 0, sizeof(own));
	if (fft == NULL) {
		if (rc_fft_init(&own, g->nx, g->ny, RC_FFT_ESTIMATE, err) != 0)
			return -1;
		fft = &own;
	} else if (fft->nx != g->nx || fft->ny != g->ny)
		return rc_seterr(err, "internal: FFT plan %zux%zu for a %zux%zu grid",
		    fft->nx, fft->ny, g->nx, g->ny);
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
		for (size_t j = 0; j < g->ny; j++)
			for (size_t i = 0; i < fft->nxc; i++)
				fft->spec[j * fft->nxc + i] = spec0[j * fft->nxc + i] *
				    spectral_factor(g, (enum field)d, i, j) / (double)n;
		rc_fft_backward(fft);
		memcpy(out[d], fft->real, n * sizeof(double));
	}
	rc = 0;
	fftw_free(spec0);
out:
	rc_fft_free(&own);
	return rc;
}

static void
fd_fields(const rc_grid *g, double *out[F_COUNT])
{
	size_t nx = g->nx, ny = g->ny;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;
	const double *h = g->z;

	#pragma omp parallel for
	for (size_t j = 0; j < ny; j++) {
		size_t jp = (j + 1) % ny, jm = (j + ny - 1) % ny;
		for (size_t i = 0; i < nx; i++) {
			size_t ip = (i + 1) % nx, im = (i + nx - 1) % nx;
			double c = h[j * nx + i];
			double e = h[j * nx + ip], w = h[j * nx + im];
			double nn = h[jp * nx + i], s = h[jm * nx + i];
			double dxx = (e - 2 * c + w) / (dx * dx);
			double dyy = (nn - 2 * c + s) / (dy * dy);
			size_t k = j * nx + i;
			if (out[F_X])
				out[F_X][k] = (e - w) / (2 * dx);
			if (out[F_Y])
				out[F_Y][k] = (nn - s) / (2 * dy);
			if (out[F_LAP])
				out[F_LAP][k] = dxx + dyy;
			if (out[F_XX])
				out[F_XX][k] = dxx;
		}
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

double
rc_gbar_fd(const rc_grid *g)
{
	size_t nx = g->nx, ny = g->ny;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny, sum = 0;
	const double *h = g->z;

	#pragma omp parallel for reduction(+:sum)
	for (size_t j = 0; j < ny; j++) {
		size_t jp = (j + 1) % ny;
		for (size_t i = 0; i < nx; i++) {
			size_t ip = (i + 1) % nx;
			double a = (h[j * nx + ip] - h[j * nx + i]) / dx;
			double b = (h[jp * nx + i] - h[j * nx + i]) / dy;
			sum += a * a + b * b;
		}
	}
	return sqrt(sum / (double)(nx * ny));
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

/* Field buffers for the statistics; NULL entries are not needed. */
struct fields {
	double *f[F_COUNT];
};

static void
fields_free(struct fields *fl)
{
	for (int d = 0; d < F_COUNT; d++)
		fftw_free(fl->f[d]);
}

static int
fields_make(const rc_grid *g, enum rc_deriv_method m, int want_second,
    struct fields *fl, rc_err *err)
{
	size_t n = rc_grid_size(g);

	memset(fl, 0, sizeof(*fl));
	for (int d = 0; d < F_COUNT; d++) {
		if (!want_second && (d == F_LAP || d == F_XX))
			continue;
		if ((fl->f[d] = fftw_alloc_real(n)) == NULL) {
			fields_free(fl);
			return rc_seterr(err, "out of memory (asked for %zu bytes)",
			    n * sizeof(double));
		}
	}
	if (rc_deriv_fields(g, m, NULL, fl->f[F_X], fl->f[F_Y], fl->f[F_LAP],
	    fl->f[F_XX], err) != 0) {
		fields_free(fl);
		return -1;
	}
	return 0;
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

int
rc_stats_compute(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_stats *s, rc_err *err)
{
	size_t n = rc_grid_size(g), count = n;
	struct fields fl;
	const double *h = g->z;
	double sum = 0, mean, hmin = INFINITY, hmax = -INFINITY;
	/* Sums of the averages, named after what they average. */
	double m2 = 0, m3 = 0, m4 = 0, mxx = 0, myy = 0, mxy = 0, hxx2 = 0;
	double dh_g2 = 0, dh2_lap = 0, lap1 = 0, dh2_g2 = 0, dh3_lap = 0;
	double lap2 = 0, dh2_lap2 = 0, g4 = 0, dh_lap = 0;

	if (mask != NULL && (count = rc_mask_check(mask, g, err)) == 0)
		return -1;
	if (fields_make(g, m, 1, &fl, err) != 0)
		return -1;
	const double *hx = fl.f[F_X], *hy = fl.f[F_Y], *lap = fl.f[F_LAP],
	    *hxx = fl.f[F_XX];

	#pragma omp parallel for reduction(+:sum) reduction(min:hmin) reduction(max:hmax)
	for (size_t k = 0; k < n; k++) {
		if (!in_set(mask, k))
			continue;
		sum += h[k];
		hmin = fmin(hmin, h[k]);
		hmax = fmax(hmax, h[k]);
	}
	mean = sum / (double)count;

	#pragma omp parallel for reduction(+:m2,m3,m4,mxx,myy,mxy,hxx2,dh_g2, \
	    dh2_lap,lap1,dh2_g2,dh3_lap,lap2,dh2_lap2,g4,dh_lap)
	for (size_t k = 0; k < n; k++) {
		if (!in_set(mask, k))
			continue;
		double d = h[k] - mean, d2 = d * d;
		double gx2 = hx[k] * hx[k], gy2 = hy[k] * hy[k], g2 = gx2 + gy2;
		double l = lap[k];
		m2 += d2;
		m3 += d2 * d;
		m4 += d2 * d2;
		mxx += gx2;
		myy += gy2;
		mxy += hx[k] * hy[k];
		hxx2 += hxx[k] * hxx[k];
		dh_g2 += d * g2;
		dh2_lap += d2 * l;
		lap1 += l;
		dh2_g2 += d2 * g2;
		dh3_lap += d2 * d * l;
		lap2 += l * l;
		dh2_lap2 += d2 * l * l;
		g4 += g2 * g2;
		dh_lap += d * l;
	}
	fields_free(&fl);

	double c = (double)count;
	m2 /= c; m3 /= c; m4 /= c; mxx /= c; myy /= c; mxy /= c; hxx2 /= c;
	dh_g2 /= c; dh2_lap /= c; lap1 /= c; dh2_g2 /= c; dh3_lap /= c;
	lap2 /= c; dh2_lap2 /= c; g4 /= c; dh_lap /= c;

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
	s->gbar = sqrt(gg);
	s->gbar_prime = -dh_lap >= 0 ? sqrt(-dh_lap) : NAN;
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
}

int
rc_stats_by_height(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, size_t nbins, rc_height_bin *bins, rc_err *err)
{
	size_t n = rc_grid_size(g);
	struct fields fl;
	double hmin = INFINITY, hmax = -INFINITY, width;

	if (nbins == 0)
		return rc_seterr(err, "number of height bins must be positive");
	if (mask != NULL && rc_mask_check(mask, g, err) == 0)
		return -1;
	for (size_t k = 0; k < n; k++) {
		if (!in_set(mask, k))
			continue;
		hmin = fmin(hmin, g->z[k]);
		hmax = fmax(hmax, g->z[k]);
	}
	if (fields_make(g, m, 0, &fl, err) != 0)
		return -1;
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
		double gx = fl.f[F_X][k], gy = fl.f[F_Y][k];
		bins[b].n++;
		bins[b].mxx += gx * gx;
		bins[b].myy += gy * gy;
		bins[b].mxy += gx * gy;
	}
	fields_free(&fl);
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
