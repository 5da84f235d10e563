/* SPDX-License-Identifier: GPL-3.0-or-later */
/* spectral.c - spectral gradient, Laplacian, rms gradient. */
#include "spectral.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/*
 * Reductions are deterministic for any thread count: the index range is
 * cut into NPART fixed parts (depending on the size only), threads sum the
 * parts, and one thread adds the partial sums in order.  So every result
 * is the same bit for bit whatever -j is, which surfgen's output relies on.
 */
#define NPART 64

/* Start of part p of n items. */
static size_t
part_start(long p, size_t n)
{
	return (size_t)p * n / NPART;
}

static double
ordered_sum(const double *partial)
{
	double s = 0;

	for (int p = 0; p < NPART; p++)
		s += partial[p];
	return s;
}

/* fmax(a, b) without the libm call (gcc makes one a use, 394k calls
 * here at 512^2): b if a is NaN, a if b is; equal otherwise but for the
 * sign of a zero, and its callers take moduli (no -0). */
static double
max_num(double a, double b)
{
	return isnan(a) || b > a ? b : a;
}

/* Load the grid into fft->real and transform; makes a plan if needed. */
static int
transform(const rc_grid *g, rc_fft *fft, rc_fft *own, rc_fft **use, rc_err *err)
{
	if ((fft = rc_fft_borrow(fft, own, g->nx, g->ny, err)) == NULL)
		return -1;
	memcpy(fft->real, g->z, rc_grid_size(g) * sizeof(double));
	rc_fft_forward(fft);
	*use = fft;
	return 0;
}

int
rc_spectral_derivs(const rc_grid *g, rc_fft *fft, double *hx, double *hy,
    double *lap, rc_err *err)
{
	rc_fft own, *f;
	size_t n = rc_grid_size(g), nxc;
	double complex *spec0;

	memset(&own, 0, sizeof(own));
	if (transform(g, fft, &own, &f, err) != 0)
		return -1;
	nxc = f->nxc;
	/* c2r destroys its input, so keep the height spectrum for each output. */
	if ((spec0 = fftw_alloc_complex(nxc * g->ny)) == NULL) {
		rc_fft_free(&own);
		return rc_seterr(err, "out of memory (asked for %zu bytes)",
		    nxc * g->ny * sizeof(double complex));
	}
	memcpy(spec0, f->spec, nxc * g->ny * sizeof(double complex));
	double *out[3] = { hx, hy, lap };
	for (int d = 0; d < 3; d++) {
		if (out[d] == NULL)
			continue;
		rc_deriv_spectral(f->spec, spec0, (enum rc_deriv)d, g->nx, g->ny,
		    g->lx, g->ly, 0, g->ny);
		rc_fft_backward(f);
		memcpy(out[d], f->real, n * sizeof(double));
	}
	fftw_free(spec0);
	rc_fft_free(&own);
	return 0;
}

int
rc_spectral_deriv(const rc_grid *g, rc_fft *fft, enum rc_deriv which,
    rc_err *err)
{
	rc_fft own, *f;

	if (fft == NULL)
		return rc_seterr(err, "internal: rc_spectral_deriv needs a plan");
	if (transform(g, fft, &own, &f, err) != 0)
		return -1;
	rc_deriv_spectral(f->spec, f->spec, which, g->nx, g->ny, g->lx, g->ly, 0,
	    g->ny);
	rc_fft_backward(f);
	return 0;
}

int
rc_rms_gradient(const rc_grid *g, rc_fft *fft, double *gbar, rc_err *err)
{
	rc_fft own, *f;
	double partial[NPART], n = (double)rc_grid_size(g), mmax = 0;
	int e;

	memset(&own, 0, sizeof(own));
	if (transform(g, fft, &own, &f, err) != 0)
		return -1;
	/* The sum runs on moduli scaled by a power of two near the largest,
	 * so that squares of heights near 1e150 do not overflow (nor those
	 * near 1e-150 underflow); exact otherwise, results unchanged.  The
	 * largest modulus is taken over the coefficients whose larger
	 * component is at least 0.7 of the largest component anywhere: a
	 * modulus lies between its larger component and sqrt 2 times it
	 * (hypot is accurate to an ulp), so every other one is below 0.99 of
	 * the largest.  The same maximum with a few moduli instead of all
	 * (hypot, 21 ns each: 3 ms of a 512^2 gfmd-solve's start, perf). */
	double top = 0, cut, *qx, *w;

	/* Each column's wave number and weight once, not once a point (two
	 * calls a point: 4M of the 30M instructions of this function at
	 * 512^2, callgrind); the same values. */
	if ((qx = rc_malloc(2 * f->nxc * sizeof(double), err)) == NULL) {
		rc_fft_free(&own);
		return -1;
	}
	w = qx + f->nxc;
	for (size_t i = 0; i < f->nxc; i++) {
		qx[i] = rc_deriv_wavenumber(i, g->nx, g->lx);
		w[i] = rc_fft_weight(i, g->nx);
	}
	for (size_t k = 0; k < g->ny * f->nxc; k++)
		top = max_num(top, max_num(fabs(creal(f->spec[k])),
		    fabs(cimag(f->spec[k]))));
	cut = top > 4 * DBL_MIN ? 0.7 * top : 0;
	for (size_t k = 0; k < g->ny * f->nxc; k++)
		if (max_num(fabs(creal(f->spec[k])), fabs(cimag(f->spec[k]))) >=
		    cut)
			mmax = max_num(mmax, cabs(f->spec[k]));
	e = mmax > 0 && isfinite(mmax) ? ilogb(mmax) : 0;
	/* ldexp(x, -e) rounds x 2^-e once, as x times the normal double
	 * 2^-e does: the same bits, without a call per coefficient. */
	double scale = e > -1022 && e < 1022 ? ldexp(1, -e) : 0;
	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double acc = 0;
		for (size_t j = part_start(p, g->ny); j < part_start(p + 1, g->ny); j++) {
			double qy = rc_deriv_wavenumber(j, g->ny, g->ly);
			for (size_t i = 0; i < f->nxc; i++) {
				double a = cabs(f->spec[j * f->nxc + i]);
				double m = scale != 0 ? a * scale : ldexp(a, -e);
				acc += w[i] * (qx[i] * qx[i] + qy * qy) * m * m;
			}
		}
		partial[p] = acc;
	}
	*gbar = ldexp(sqrt(ordered_sum(partial)), e) / n;
	free(qx);
	rc_fft_free(&own);
	return 0;
}

void
rc_mean_rms(const double *z, size_t n, double *mean, double *rms)
{
	double partial[NPART], m;

	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double acc = 0;
		for (size_t i = part_start(p, n); i < part_start(p + 1, n); i++)
			acc += z[i];
		partial[p] = acc;
	}
	m = ordered_sum(partial) / (double)n;
	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double acc = 0;
		for (size_t i = part_start(p, n); i < part_start(p + 1, n); i++)
			acc += (z[i] - m) * (z[i] - m);
		partial[p] = acc;
	}
	if (mean)
		*mean = m;
	if (rms)
		*rms = sqrt(ordered_sum(partial) / (double)n);
}
