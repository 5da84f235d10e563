/* psd.c - 2D and radial power spectra, spectral moments, height-difference
 * autocorrelation (conventions in psd.h). */
#include "psd.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "spectral.h"

/* Loops that accumulate into bins give each of NPART fixed row ranges its
 * own accumulators and add them up in order afterwards, so the result does
 * not depend on the thread count. */
#define NPART 16

static size_t
part_start(long p, size_t n)
{
	return (size_t)p * n / NPART;
}

/* Transform g into a plan (fft, or own made here). */
static int
forward(const rc_grid *g, rc_fft *fft, rc_fft *own, rc_fft **use, int demean,
    rc_err *err)
{
	size_t n = rc_grid_size(g);

	memset(own, 0, sizeof(*own));
	if (fft == NULL) {
		if (rc_fft_init(own, g->nx, g->ny, RC_FFT_ESTIMATE, err) != 0)
			return -1;
		fft = own;
	} else if (fft->nx != g->nx || fft->ny != g->ny)
		return rc_seterr(err, "internal: FFT plan %zux%zu for a %zux%zu grid",
		    fft->nx, fft->ny, g->nx, g->ny);
	memcpy(fft->real, g->z, n * sizeof(double));
	if (demean) {
		double mean;
		long nl = (long)n;
		rc_mean_rms(g->z, n, &mean, NULL);
		#pragma omp parallel for schedule(static)
		for (long k = 0; k < nl; k++)
			fft->real[k] -= mean;
	}
	rc_fft_forward(fft);
	*use = fft;
	return 0;
}

/* C of half-complex entry (i, j): |h_k|^2 A / ((2 pi)^2 N^2). */
static double
mode_c(const rc_grid *g, const rc_fft *f, size_t i, size_t j)
{
	double n = (double)rc_grid_size(g);
	double a = cabs(f->spec[j * f->nxc + i]);

	return a * a * g->lx * g->ly / (4 * M_PI * M_PI * n * n);
}

rc_grid *
rc_psd2d(const rc_grid *g, rc_fft *fft, rc_err *err)
{
	rc_fft own, *f;
	rc_grid *s;
	size_t nx = g->nx, ny = g->ny;
	double dqx = 2 * M_PI / g->lx, dqy = 2 * M_PI / g->ly;

	if (forward(g, fft, &own, &f, 0, err) != 0)
		return NULL;
	s = rc_grid_new(nx, ny, dqx * (double)nx, dqy * (double)ny, err);
	if (s == NULL)
		goto out;
	s->kind = RC_KIND_SPECTRUM;
	#pragma omp parallel for schedule(static)
	for (size_t j = 0; j < ny; j++) {
		size_t jj = (j + ny - ny / 2) % ny;	/* DFT index of row j */
		for (size_t i = 0; i < nx; i++) {
			size_t ii = (i + nx - nx / 2) % nx;
			/* The other half plane is the conjugate of (-ii, -jj). */
			double c = ii < f->nxc ? mode_c(g, f, ii, jj) :
			    mode_c(g, f, nx - ii, (ny - jj) % ny);
			s->z[j * nx + i] = c;
		}
	}
	if (rc_grid_meta_copy(s, g, err) != 0 ||
	    rc_grid_meta_setd(s, "dqx", dqx, err) != 0 ||
	    rc_grid_meta_setd(s, "dqy", dqy, err) != 0 ||
	    rc_grid_meta_setf(s, "q0_index", err, "%zu,%zu", nx / 2, ny / 2) != 0 ||
	    rc_grid_meta_set(s, "spectrum_convention",
	    "C(q)=(2pi)^-2*int(d2r<h(0)h(r)>exp(-iq.r)),sum(C)*dqx*dqy=<h^2>",
	    err) != 0) {
		rc_grid_free(s);
		s = NULL;
	}
out:
	rc_fft_free(&own);
	return s;
}

/* Self-conjugate half-complex entries (their own mirror image). */
static int
self_conjugate(const rc_grid *g, size_t i, size_t j)
{
	return (i == 0 || rc_is_nyquist(i, g->nx)) &&
	    (j == 0 || rc_is_nyquist(j, g->ny));
}

/* Independent samples an entry stands for: a weight-2 entry is one
 * conjugate pair; a weight-1 entry that is not its own mirror shares its
 * pair with another entry of the array. */
static double
independent_weight(const rc_grid *g, size_t i, size_t j)
{
	if (rc_fft_weight(i, g->nx) == 2 || self_conjugate(g, i, j))
		return 1;
	return 0.5;
}

static double
mode_q(const rc_grid *g, size_t i, size_t j)
{
	return hypot(rc_wavenumber(i, g->nx, g->lx), rc_wavenumber(j, g->ny, g->ly));
}

int
rc_psd_radial(const rc_grid *g, rc_fft *fft, double bins_per_decade,
    rc_psd_bin **bins, size_t *nbins, rc_err *err)
{
	rc_fft own, *f;
	double qmin = INFINITY, qmax = 0;
	size_t nb;
	struct acc { double w, wq, wc, v, vc, vdev; } *acc = NULL;
	int rc = -1;

	*bins = NULL;
	*nbins = 0;
	if (!(bins_per_decade > 0) || !isfinite(bins_per_decade))
		return rc_seterr(err, "bins per decade must be positive and finite");
	if (rc_grid_size(g) < 2)
		return rc_seterr(err, "a 1x1 grid has no mode besides q = 0");
	if (forward(g, fft, &own, &f, 0, err) != 0)
		return -1;
	#pragma omp parallel for reduction(min:qmin) reduction(max:qmax) schedule(static)
	for (size_t j = 0; j < g->ny; j++)
		for (size_t i = 0; i < f->nxc; i++) {
			double q = mode_q(g, i, j);
			if (q > 0) {
				qmin = fmin(qmin, q);
				qmax = fmax(qmax, q);
			}
		}
	/* Bins centred on qmin 10^(b / bins_per_decade). */
	nb = (size_t)floor(bins_per_decade * log10(qmax / qmin) + 0.5) + 1;
	if ((acc = rc_calloc((NPART + 1) * nb, sizeof(*acc), err)) == NULL)
		goto out;
	/* acc[0 .. nb-1] the totals, acc[(p+1) nb ..] part p's sums. */
	for (int pass = 0; pass < 2; pass++) {
		#pragma omp parallel for schedule(static)
		for (long p = 0; p < NPART; p++) {
			struct acc *mine = acc + (size_t)(p + 1) * nb;
			for (size_t j = part_start(p, g->ny); j < part_start(p + 1, g->ny); j++)
				for (size_t i = 0; i < f->nxc; i++) {
					double q = mode_q(g, i, j), c, v;
					size_t b;
					if (q == 0)
						continue;
					b = (size_t)floor(bins_per_decade * log10(q / qmin) + 0.5);
					if (b >= nb)
						b = nb - 1;
					c = mode_c(g, f, i, j);
					v = independent_weight(g, i, j);
					if (pass == 0) {
						double w = rc_fft_weight(i, g->nx);
						mine[b].w += w;
						mine[b].wq += w * q;
						mine[b].wc += w * c;
						mine[b].v += v;
						mine[b].vc += v * c;
					} else {
						double d = c - acc[b].vc / acc[b].v;
						mine[b].vdev += v * d * d;
					}
				}
		}
		for (long p = 0; p < NPART; p++) {
			const struct acc *mine = acc + (size_t)(p + 1) * nb;
			for (size_t b = 0; b < nb; b++) {
				if (pass == 0) {
					acc[b].w += mine[b].w;
					acc[b].wq += mine[b].wq;
					acc[b].wc += mine[b].wc;
					acc[b].v += mine[b].v;
					acc[b].vc += mine[b].vc;
				} else
					acc[b].vdev += mine[b].vdev;
			}
		}
	}
	if ((*bins = rc_calloc(nb, sizeof(**bins), err)) == NULL)
		goto out;
	for (size_t b = 0; b < nb; b++) {
		rc_psd_bin *o;
		if (acc[b].w == 0)
			continue;
		o = &(*bins)[(*nbins)++];
		o->q = acc[b].wq / acc[b].w;
		o->c = acc[b].wc / acc[b].w;
		o->n_modes = (size_t)acc[b].w;
		o->std_err = acc[b].v >= 2 ?
		    sqrt(acc[b].vdev / (acc[b].v - 1) / acc[b].v) : NAN;
	}
	rc = 0;
out:
	free(acc);
	rc_fft_free(&own);
	return rc;
}

int
rc_psd_moments_x(const rc_grid *g, rc_fft *fft, double *m0, double *m2,
    double *m4, rc_err *err)
{
	rc_fft own, *f;
	double part[NPART][3];
	double dq2 = 4 * M_PI * M_PI / (g->lx * g->ly);

	if (forward(g, fft, &own, &f, 0, err) != 0)
		return -1;
	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double s0 = 0, s2 = 0, s4 = 0;
		for (size_t j = part_start(p, g->ny); j < part_start(p + 1, g->ny); j++)
			for (size_t i = 0; i < f->nxc; i++) {
				double w, c, qx, dqx;
				if (i == 0 && j == 0)
					continue;
				w = rc_fft_weight(i, g->nx);
				c = w * mode_c(g, f, i, j) * dq2;
				qx = rc_wavenumber(i, g->nx, g->lx);
				dqx = rc_deriv_wavenumber(i, g->nx, g->lx);
				s0 += c;
				s2 += dqx * dqx * c;
				s4 += qx * qx * qx * qx * c;
			}
		part[p][0] = s0;
		part[p][1] = s2;
		part[p][2] = s4;
	}
	*m0 = *m2 = *m4 = 0;
	for (int p = 0; p < NPART; p++) {
		*m0 += part[p][0];
		*m2 += part[p][1];
		*m4 += part[p][2];
	}
	rc_fft_free(&own);
	return 0;
}

const char *
rc_acf_dir_name(enum rc_acf_dir d)
{
	return d == RC_ACF_X ? "x" : d == RC_ACF_Y ? "y" : "radial";
}

/* Signed minimal-image displacement index. */
static double
min_image(size_t k, size_t n)
{
	return k <= n / 2 ? (double)k : (double)k - (double)n;
}

int
rc_acf(const rc_grid *g, rc_fft *fft, rc_acf_point **pts, size_t *npts,
    rc_err *err)
{
	rc_fft own, *f;
	size_t nx = g->nx, ny = g->ny, n = nx * ny, nrad, cap, k = 0;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;
	double dr = fmax(dx, dy), rmax = 0.5 * fmin(g->lx, g->ly), r0;
	double *rsum = NULL, *gsum = NULL;
	size_t *cnt = NULL;
	int rc = -1;

	*pts = NULL;
	*npts = 0;
	if (forward(g, fft, &own, &f, 1, err) != 0)
		return -1;
	/* Autocorrelation R(r) = (1/N) sum_r0 dh(r0) dh(r0 + r): the inverse
	 * transform of |h_k|^2, divided by N^2. */
	#pragma omp parallel for schedule(static)
	for (size_t m = 0; m < f->nxc * ny; m++) {
		double a = cabs(f->spec[m]);
		f->spec[m] = a * a;
	}
	rc_fft_backward(f);
	const double *acr = f->real;
	r0 = acr[0];
	nrad = (size_t)floor(rmax / dr + 0.5) + 1;
	cap = (nx / 2 + 1) + (ny / 2 + 1) + nrad;
	if ((*pts = rc_calloc(cap, sizeof(**pts), err)) == NULL ||
	    (rsum = rc_calloc(nrad, sizeof(double), err)) == NULL ||
	    (gsum = rc_calloc(nrad, sizeof(double), err)) == NULL ||
	    (cnt = rc_calloc(nrad, sizeof(size_t), err)) == NULL)
		goto out;
	/* G(r) = 2 (R(0) - R(r)). */
	for (size_t i = 0; i <= nx / 2; i++) {
		rc_acf_point *p = &(*pts)[k++];
		p->dir = RC_ACF_X;
		p->r = (double)i * dx;
		p->g = 2 * (r0 - acr[i]) / ((double)n * (double)n);
		p->n = (i == 0 || 2 * i == nx) ? 1 : 2;
	}
	for (size_t j = 0; j <= ny / 2; j++) {
		rc_acf_point *p = &(*pts)[k++];
		p->dir = RC_ACF_Y;
		p->r = (double)j * dy;
		p->g = 2 * (r0 - acr[j * nx]) / ((double)n * (double)n);
		p->n = (j == 0 || 2 * j == ny) ? 1 : 2;
	}
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double r = hypot(min_image(i, nx) * dx, min_image(j, ny) * dy);
			size_t b;
			if (r > rmax * (1 + 1e-12))
				continue;
			b = (size_t)floor(r / dr + 0.5);
			if (b >= nrad)
				b = nrad - 1;
			rsum[b] += r;
			gsum[b] += 2 * (r0 - acr[j * nx + i]) / ((double)n * (double)n);
			cnt[b]++;
		}
	for (size_t b = 0; b < nrad; b++) {
		rc_acf_point *p;
		if (cnt[b] == 0)
			continue;
		p = &(*pts)[k++];
		p->dir = RC_ACF_RADIAL;
		p->r = rsum[b] / (double)cnt[b];
		p->g = gsum[b] / (double)cnt[b];
		p->n = cnt[b];
	}
	*npts = k;
	rc = 0;
out:
	if (rc != 0) {
		free(*pts);
		*pts = NULL;
	}
	free(rsum);
	free(gsum);
	free(cnt);
	rc_fft_free(&own);
	return rc;
}
