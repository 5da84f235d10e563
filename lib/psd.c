/* SPDX-License-Identifier: GPL-3.0-or-later */
/* psd.c - 2D and radial power spectra, spectral moments, height-difference
 * autocorrelation (conventions in psd.h). */
#include "psd.h"
#include "gridcheck.h"

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

double
rc_window_value(enum rc_window w, size_t k, size_t n)
{
	double t = ((double)k + 0.5) / (double)n;

	if (n < 2)
		return 1;
	switch (w) {
	case RC_WINDOW_HANN:
		return 0.5 * (1 - cos(2 * M_PI * t));
	case RC_WINDOW_BLACKMAN:
		return 0.42 - 0.5 * cos(2 * M_PI * t) + 0.08 * cos(4 * M_PI * t);
	case RC_WINDOW_TUKEY:
		/* alpha = 1/2: cosine tapers over a quarter at each end */
		if (t < 0.25)
			return 0.5 * (1 - cos(4 * M_PI * t));
		if (t > 0.75)
			return 0.5 * (1 - cos(4 * M_PI * (1 - t)));
		return 1;
	default:
		return 1;
	}
}

static const char *window_names[] = { "none", "hann", "blackman", "tukey" };

const char *
rc_window_name(enum rc_window w)
{
	return (unsigned)w < 4 ? window_names[w] : "auto";
}

int
rc_window_parse(const char *name)
{
	for (int k = 0; k < 4; k++)
		if (strcmp(name, window_names[k]) == 0)
			return k;
	return -1;
}

enum rc_window
rc_window_resolve(const rc_grid *g, enum rc_window w)
{
	if (w == RC_WINDOW_AUTO)
		return g->periodic ? RC_WINDOW_NONE : RC_WINDOW_HANN;
	return w;
}

/* Mean of w^2 along an axis of n points. */
static double
window_power(enum rc_window w, size_t n)
{
	double s = 0;

	for (size_t k = 0; k < n; k++) {
		double v = rc_window_value(w, k, n);
		s += v * v;
	}
	return s / (double)n;
}

/* Transform g into a plan (fft, or own made here).  With a window the
 * mean is removed first (so that it does not leak into the lowest modes
 * through the window's own spectrum) and *scale is 1 / mean(w^2), the
 * factor that makes sum C dq^2 = <h^2> hold on average for white noise;
 * without, *scale = 1. */
static int
forward(const rc_grid *g, rc_fft *fft, rc_fft *own, rc_fft **use, int demean,
    enum rc_window window, double *scale, rc_err *err)
{
	size_t n = rc_grid_size(g);

	memset(own, 0, sizeof(*own));
	if (rc_grid_check_uniform(g, err) != 0)
		return -1;
	if (g->valid != NULL)
		return rc_seterr(err, "the grid has missing points: a spectrum "
		    "needs every point (fill them with surfwarp --fill)");
	window = rc_window_resolve(g, window);
	if ((fft = rc_fft_borrow(fft, own, g->nx, g->ny, err)) == NULL)
		return -1;
	memcpy(fft->real, g->z, n * sizeof(double));
	if (demean || window != RC_WINDOW_NONE) {
		double mean;
		long nl = (long)n;
		rc_mean_rms(g->z, n, &mean, NULL);
		#pragma omp parallel for schedule(static)
		for (long k = 0; k < nl; k++)
			fft->real[k] -= mean;
	}
	if (scale != NULL)
		*scale = 1;
	if (window != RC_WINDOW_NONE) {
		size_t nx = g->nx, ny = g->ny;
		double *wx = rc_malloc(nx * sizeof(double), err);
		if (wx == NULL) {
			rc_fft_free(own);
			return -1;
		}
		for (size_t i = 0; i < nx; i++)
			wx[i] = rc_window_value(window, i, nx);
		#pragma omp parallel for schedule(static)
		for (size_t j = 0; j < ny; j++) {
			double wy = rc_window_value(window, j, ny);
			for (size_t i = 0; i < nx; i++)
				fft->real[j * nx + i] *= wx[i] * wy;
		}
		free(wx);
		if (scale != NULL)
			*scale = 1 / (window_power(window, nx) * window_power(window, ny));
	}
	rc_fft_forward(fft);
	*use = fft;
	return 0;
}

/* C of half-complex entry (i, j): |h_k|^2 A / ((2 pi)^2 N^2). */
static double
mode_c(const rc_grid *g, const rc_fft *f, size_t i, size_t j, double scale)
{
	double n = (double)rc_grid_size(g);
	double a = cabs(f->spec[j * f->nxc + i]);

	return a * a * g->lx * g->ly / (4 * M_PI * M_PI * n * n) * scale;
}

rc_grid *
rc_psd2d(const rc_grid *g, rc_fft *fft, rc_err *err)
{
	return rc_psd2d_window(g, fft, RC_WINDOW_AUTO, err);
}

rc_grid *
rc_psd2d_window(const rc_grid *g, rc_fft *fft, enum rc_window window,
    rc_err *err)
{
	rc_fft own, *f;
	double scale;
	rc_grid *s;
	size_t nx = g->nx, ny = g->ny;
	double dqx = 2 * M_PI / g->lx, dqy = 2 * M_PI / g->ly;

	if (forward(g, fft, &own, &f, 0, window, &scale, err) != 0)
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
			double c = ii < f->nxc ? mode_c(g, f, ii, jj, scale) :
			    mode_c(g, f, nx - ii, (ny - jj) % ny, scale);
			s->z[j * nx + i] = c;
		}
	}
	if (rc_grid_meta_copy(s, g, err) != 0 ||
	    rc_grid_meta_setd(s, "dqx", dqx, err) != 0 ||
	    rc_grid_meta_setd(s, "dqy", dqy, err) != 0 ||
	    rc_grid_meta_setf(s, "q0_index", err, "%zu,%zu", nx / 2, ny / 2) != 0 ||
	    rc_grid_meta_set(s, "spectrum_convention",
	    "C(q)=(2pi)^-2*int(d2r<h(0)h(r)>exp(-iq.r)),sum(C)*dqx*dqy=<h^2>",
	    err) != 0 || rc_grid_meta_set(s, "window",
	    rc_window_name(rc_window_resolve(g, window)), err) != 0) {
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
	return rc_psd_radial_window(g, fft, bins_per_decade, RC_WINDOW_AUTO,
	    bins, nbins, err);
}

/* Long: window, transform and radial binning share the spectrum buffer
 * and the bin counts. */
int
rc_psd_radial_window(const rc_grid *g, rc_fft *fft, double bins_per_decade,
    enum rc_window window, rc_psd_bin **bins, size_t *nbins, rc_err *err)
{
	rc_fft own, *f;
	double scale;
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
	if (forward(g, fft, &own, &f, 0, window, &scale, err) != 0)
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
					c = mode_c(g, f, i, j, scale);
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

	if (forward(g, fft, &own, &f, 0, RC_WINDOW_NONE, NULL, err) != 0)
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
				c = w * mode_c(g, f, i, j, 1) * dq2;
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

static int acf_periodic(const rc_grid *g, rc_fft *fft, rc_acf_point **pts,
    size_t *npts, rc_err *err);

/* Non-periodic G(r): the grid zero-padded to (2 nx) x (2 ny) (an axis
 * of one point is not padded), so that no pair wraps around.  With b the
 * valid-point indicator (1 everywhere here), a = b h^2, c = b h and
 * corr(f, g)(r) = sum_x f(x) g(x + r):
 *   S(r) = sum over pairs inside the patch of (h(x + r) - h(x))^2
 *        = corr(a, b) + corr(b, a) - 2 corr(c, c),   N(r) = corr(b, b),
 * G(r) = S(r) / N(r).  Each correlation is one product of transforms. */
static int
acf_padded(const rc_grid *g, double *gval, double *npairs, size_t *pnx,
    size_t *pny, rc_err *err)
{
	size_t nx = g->nx, ny = g->ny;
	size_t px = nx > 1 ? 2 * nx : 1, py = ny > 1 ? 2 * ny : 1;
	size_t nc, npad = px * py;
	rc_fft f;
	fftw_complex *fa = NULL, *fb = NULL;
	double mean;
	int rc = -1;

	if (rc_fft_init(&f, px, py, RC_FFT_ESTIMATE, err) != 0)
		return -1;
	nc = f.nxc * py;
	if ((fa = fftw_alloc_complex(nc)) == NULL ||
	    (fb = fftw_alloc_complex(nc)) == NULL) {
		rc_seterr(err, "out of memory for the padded ACF (%zux%zu)", px, py);
		goto out;
	}
	rc_mean_rms(g->z, nx * ny, &mean, NULL);
	/* a = h^2 (heights about the mean, for round-off) */
	memset(f.real, 0, npad * sizeof(double));
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double h = g->z[j * nx + i] - mean;
			f.real[j * px + i] = h * h;
		}
	rc_fft_forward(&f);
	memcpy(fa, f.spec, nc * sizeof(fftw_complex));
	/* b = 1 */
	memset(f.real, 0, npad * sizeof(double));
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			f.real[j * px + i] = 1;
	rc_fft_forward(&f);
	memcpy(fb, f.spec, nc * sizeof(fftw_complex));
	/* N(r): the inverse of |B|^2 */
	for (size_t m = 0; m < nc; m++)
		f.spec[m] = fb[m] * conj(fb[m]);
	rc_fft_backward(&f);
	for (size_t m = 0; m < npad; m++)
		npairs[m] = f.real[m] / (double)npad;
	/* 2 Re(conj(A) B) is the transform of corr(a, b) + corr(b, a) */
	for (size_t m = 0; m < nc; m++)
		fa[m] = 2 * creal(conj(fa[m]) * fb[m]);
	/* c = h */
	memset(f.real, 0, npad * sizeof(double));
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			f.real[j * px + i] = g->z[j * nx + i] - mean;
	rc_fft_forward(&f);
	for (size_t m = 0; m < nc; m++)
		f.spec[m] = fa[m] - 2 * f.spec[m] * conj(f.spec[m]);
	rc_fft_backward(&f);
	for (size_t m = 0; m < npad; m++) {
		/* Displacements with no pair (|rx| = nx in the padding) */
		double np = floor(npairs[m] + 0.5);
		npairs[m] = np;
		gval[m] = np >= 1 ? fmax(f.real[m] / (double)npad, 0) / np : NAN;
	}
	*pnx = px;
	*pny = py;
	rc = 0;
out:
	fftw_free(fa);
	fftw_free(fb);
	rc_fft_free(&f);
	return rc;
}

/* Radial bins of width dr over [0, rmax] of the ACF: per bin the sums of
 * r w, v w and w over its displacements (w a pair count; 1 each on a
 * periodic grid) and their number. */
struct radial {
	size_t nrad;
	double dr, rmax;
	double *rsum, *vsum, *wsum;
	size_t *cnt;
};

static void
radial_free(struct radial *rb)
{
	free(rb->rsum);
	free(rb->vsum);
	free(rb->wsum);
	free(rb->cnt);
}

static int
radial_init(struct radial *rb, double dr, double rmax, rc_err *err)
{
	memset(rb, 0, sizeof(*rb));
	rb->dr = dr;
	rb->rmax = rmax;
	rb->nrad = (size_t)floor(rmax / dr + 0.5) + 1;
	if ((rb->vsum = rc_calloc(rb->nrad, sizeof(double), err)) == NULL ||
	    (rb->wsum = rc_calloc(rb->nrad, sizeof(double), err)) == NULL ||
	    (rb->rsum = rc_calloc(rb->nrad, sizeof(double), err)) == NULL ||
	    (rb->cnt = rc_calloc(rb->nrad, sizeof(size_t), err)) == NULL) {
		radial_free(rb);
		return -1;
	}
	return 0;
}

/* A displacement of length r (none beyond rmax), value v, weight w. */
static void
radial_add(struct radial *rb, double r, double v, double w)
{
	size_t b;

	if (r > rb->rmax * (1 + 1e-12))
		return;
	b = (size_t)floor(r / rb->dr + 0.5);
	if (b >= rb->nrad)
		b = rb->nrad - 1;
	rb->rsum[b] += r * w;
	rb->vsum[b] += v * w;
	rb->wsum[b] += w;
	rb->cnt[b]++;
}

/* The non-empty bins as points pts[*k ...]: weighted means, values
 * times f. */
static void
radial_points(const struct radial *rb, double f, rc_acf_point *pts, size_t *k)
{
	for (size_t b = 0; b < rb->nrad; b++) {
		rc_acf_point *p;

		if (rb->cnt[b] == 0)
			continue;
		p = &pts[(*k)++];
		p->dir = RC_ACF_RADIAL;
		p->r = rb->rsum[b] / rb->wsum[b];
		p->g = f * rb->vsum[b] / rb->wsum[b];
		p->n = rb->cnt[b];
	}
}

static int
acf_nonperiodic(const rc_grid *g, int half, rc_acf_point **pts, size_t *npts,
    rc_err *err)
{
	size_t nx = g->nx, ny = g->ny, px = 1, py = 1, cap, k = 0;
	size_t npad = (nx > 1 ? 2 * nx : 1) * (ny > 1 ? 2 * ny : 1);
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;
	double dr = ny == 1 ? dx : nx == 1 ? dy : fmax(dx, dy);
	double rmax = ny == 1 ? 0.5 * g->lx : nx == 1 ? 0.5 * g->ly :
	    0.5 * fmin(g->lx, g->ly), f = half ? 0.5 : 1;
	double *gv = NULL, *np = NULL;
	struct radial rb;
	int rc = -1;

	*pts = NULL;
	*npts = 0;
	memset(&rb, 0, sizeof(rb));
	if ((gv = rc_malloc(npad * sizeof(double), err)) == NULL ||
	    (np = rc_malloc(npad * sizeof(double), err)) == NULL ||
	    acf_padded(g, gv, np, &px, &py, err) != 0 ||
	    radial_init(&rb, dr, rmax, err) != 0)
		goto out;
	cap = (nx / 2 + 1) + (ny / 2 + 1) + rb.nrad;
	if ((*pts = rc_calloc(cap, sizeof(**pts), err)) == NULL)
		goto out;
	for (size_t i = 0; i <= nx / 2; i++) {
		rc_acf_point *p = &(*pts)[k++];
		p->dir = RC_ACF_X;
		p->r = (double)i * dx;
		p->g = f * gv[i];
		p->n = (size_t)np[i];
	}
	for (size_t j = 0; j <= ny / 2; j++) {
		rc_acf_point *p = &(*pts)[k++];
		p->dir = RC_ACF_Y;
		p->r = (double)j * dy;
		p->g = f * gv[j * px];
		p->n = (size_t)np[j * px];
	}
	/* Radial: pair-weighted mean over the displacements of each bin. */
	for (size_t j = 0; j < py; j++)
		for (size_t i = 0; i < px; i++) {
			double r = hypot(min_image(i, px) * dx, min_image(j, py) * dy);
			size_t m = j * px + i;

			if (np[m] >= 1)
				radial_add(&rb, r, gv[m], np[m]);
		}
	radial_points(&rb, f, *pts, &k);
	*npts = k;
	rc = 0;
out:
	if (rc != 0) {
		free(*pts);
		*pts = NULL;
	}
	free(gv);
	free(np);
	radial_free(&rb);
	return rc;
}

int
rc_acf(const rc_grid *g, rc_fft *fft, rc_acf_point **pts, size_t *npts,
    rc_err *err)
{
	return rc_acf_ex(g, fft, 0, pts, npts, err);
}

int
rc_acf_ex(const rc_grid *g, rc_fft *fft, int half, rc_acf_point **pts,
    size_t *npts, rc_err *err)
{
	int rc;

	*pts = NULL;
	*npts = 0;
	if (rc_grid_check_uniform(g, err) != 0)
		return -1;
	if (g->valid != NULL)
		return rc_seterr(err, "the grid has missing points: the ACF needs "
		    "every point (fill them with surfwarp --fill)");
	if (!g->periodic)
		return acf_nonperiodic(g, half, pts, npts, err);
	rc = acf_periodic(g, fft, pts, npts, err);
	if (rc == 0 && half)
		for (size_t k = 0; k < *npts; k++)
			(*pts)[k].g *= 0.5;
	return rc;
}

static int
acf_periodic(const rc_grid *g, rc_fft *fft, rc_acf_point **pts, size_t *npts,
    rc_err *err)
{
	rc_fft own, *f;
	size_t nx = g->nx, ny = g->ny, n = nx * ny, cap, k = 0;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;
	double dr = fmax(dx, dy), rmax = 0.5 * fmin(g->lx, g->ly), r0;
	struct radial rb;
	int rc = -1;

	*pts = NULL;
	*npts = 0;
	memset(&rb, 0, sizeof(rb));
	if (forward(g, fft, &own, &f, 1, RC_WINDOW_NONE, NULL, err) != 0)
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
	if (radial_init(&rb, dr, rmax, err) != 0)
		goto out;
	cap = (nx / 2 + 1) + (ny / 2 + 1) + rb.nrad;
	if ((*pts = rc_calloc(cap, sizeof(**pts), err)) == NULL)
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

			radial_add(&rb, r, 2 * (r0 - acr[j * nx + i]) /
			    ((double)n * (double)n), 1);
		}
	radial_points(&rb, 1, *pts, &k);
	*npts = k;
	rc = 0;
out:
	if (rc != 0) {
		free(*pts);
		*pts = NULL;
	}
	radial_free(&rb);
	rc_fft_free(&own);
	return rc;
}

/* Long: window, row transforms and averaging share the buffers of one
 * axis. */
int
rc_psd1d(const rc_grid *g, enum rc_psd1d_dir dir, enum rc_window window,
    rc_psd1d_point **pts, size_t *npts, rc_err *err)
{
	size_t n = dir == RC_PSD1D_X ? g->nx : g->ny;
	size_t lines = dir == RC_PSD1D_X ? g->ny : g->nx;
	size_t stride = dir == RC_PSD1D_X ? 1 : g->nx;	/* along a line */
	size_t step = dir == RC_PSD1D_X ? g->nx : 1;	/* between lines */
	size_t nc = n / 2 + 1;
	double len = dir == RC_PSD1D_X ? g->lx : g->ly, scale = 1;
	double *w = NULL, *re = NULL, *sum = NULL, *sum2 = NULL;
	fftw_complex *sp = NULL;
	fftw_plan plan = NULL;
	int rc = -1;

	*pts = NULL;
	*npts = 0;
	if (rc_grid_check_uniform(g, err) != 0)
		return -1;
	if (g->valid != NULL)
		return rc_seterr(err, "the grid has missing points: a spectrum "
		    "needs every point (fill them with surfwarp --fill)");
	if (n < 2)
		return rc_seterr(err, "a 1D spectrum along %s needs at least 2 points "
		    "on that axis", dir == RC_PSD1D_X ? "x" : "y");
	window = rc_window_resolve(g, window);
	if ((w = rc_malloc(n * sizeof(double), err)) == NULL ||
	    (sum = rc_calloc(nc, sizeof(double), err)) == NULL ||
	    (sum2 = rc_calloc(nc, sizeof(double), err)) == NULL)
		goto out;
	for (size_t k = 0; k < n; k++)
		w[k] = rc_window_value(window, k, n);
	if (window != RC_WINDOW_NONE)
		scale = 1 / window_power(window, n);
	re = fftw_alloc_real(n * lines);
	sp = fftw_alloc_complex(nc * lines);
	if (re == NULL || sp == NULL) {
		rc_seterr(err, "out of memory for %zu lines of %zu points", lines, n);
		goto out;
	}
	{
		int ni = (int)n;
		plan = fftw_plan_many_dft_r2c(1, &ni, (int)lines, re, NULL, 1, ni,
		    sp, NULL, 1, (int)nc, FFTW_ESTIMATE);
	}
	if (plan == NULL) {
		rc_seterr(err, "FFTW could not plan %zu transforms of %zu points",
		    lines, n);
		goto out;
	}
	/* Each line with its own mean removed before the window (for a
	 * periodic grid without a window the mean only changes q = 0). */
	#pragma omp parallel for schedule(static)
	for (size_t l = 0; l < lines; l++) {
		const double *src = g->z + l * step;
		double *dst = re + l * n, mean = 0;
		for (size_t k = 0; k < n; k++)
			mean += src[k * stride];
		mean /= (double)n;
		for (size_t k = 0; k < n; k++)
			dst[k] = (src[k * stride] - mean) * w[k];
	}
	fftw_execute(plan);
	/* C1D(q_k) = |h_k|^2 L / (2 pi n^2) / mean(w^2), averaged over lines */
	for (size_t l = 0; l < lines; l++)
		for (size_t k = 1; k < nc; k++) {
			double a = cabs(sp[l * nc + k]);
			double c = a * a * len / (2 * M_PI * (double)n * (double)n) * scale;
			sum[k] += c;
			sum2[k] += c * c;
		}
	if ((*pts = rc_calloc(nc - 1, sizeof(**pts), err)) == NULL)
		goto out;
	for (size_t k = 1; k < nc; k++) {
		rc_psd1d_point *p = &(*pts)[k - 1];
		double mean = sum[k] / (double)lines;
		p->q = 2 * M_PI * (double)k / len;
		p->c = mean;
		p->n_lines = lines;
		p->std_err = lines >= 2 ? sqrt(fmax(sum2[k] / (double)lines - mean * mean,
		    0) * (double)lines / (double)(lines - 1) / (double)lines) : NAN;
	}
	*npts = nc - 1;
	rc = 0;
out:
	if (plan != NULL)
		fftw_destroy_plan(plan);
	fftw_free(re);
	fftw_free(sp);
	free(w);
	free(sum);
	free(sum2);
	return rc;
}
