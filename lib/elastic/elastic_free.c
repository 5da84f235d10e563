/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic_free.c - Love's pixel compliance on the padded grid (see
 * elastic_free.h). */
#include "elastic_free.h"

#include <math.h>
#include <string.h>

#include "elastic_layer_free.h"
#include "grid.h"

/* Signed offset of padded index k on an axis of n given points (2n padded). */
static double
offset(size_t k, size_t n)
{
	return k <= n ? (double)k : (double)k - 2.0 * (double)n;
}

int
rc_halfspace_init(rc_halfspace *e, size_t nx, size_t ny, double lx,
    double ly, double modulus, enum rc_fft_effort effort, rc_err *err)
{
	return rc_halfspace_init_layer(e, nx, ny, lx, ly, modulus, 0,
	    RC_SUBSTRATE_NONE, 0, effort, err);
}

/* The layer's C_L (elastic_layer_free.h) in wrap-around order: the
 * quadrant of offsets 0 .. n per axis, mirrored (C_L is even in x and in
 * y, and costs a quadrature per offset). */
static int
layer_table(rc_halfspace *e, double dx, double dy, double thickness,
    enum rc_substrate substrate, double poisson, rc_err *err)
{
	size_t i, j, nx = e->nx, ny = e->ny, px = 2 * nx, py = 2 * ny;
	double *c = e->fft.real;
	rc_layer_pixel t;

	if (rc_layer_pixel_init(&t, thickness, substrate, poisson,
	    e->modulus, dx, dy, hypot((double)(nx + 1) * dx,
	    (double)(ny + 1) * dy), err) != 0)
		return -1;
#pragma omp parallel for private(i) schedule(dynamic)
	for (j = 0; j <= ny; j++)
		for (i = 0; i <= nx; i++)
			c[j * px + i] = rc_layer_pixel_compliance(&t,
			    (double)i * dx, (double)j * dy);
	rc_layer_pixel_release(&t);
	for (j = 0; j < py; j++) {
		const double *src = c + (j <= ny ? j : py - j) * px;

		for (i = 0; i < px; i++)
			c[j * px + i] = src[i <= nx ? i : px - i];
	}
	return 0;
}

/* The checks, the plans, the table (Love's or the layer's) and its
 * spectrum with its smallest eigenvalue. */
int
rc_halfspace_init_layer(rc_halfspace *e, size_t nx, size_t ny, double lx,
    double ly, double modulus, double thickness, enum rc_substrate substrate,
    double poisson, enum rc_fft_effort effort, rc_err *err)
{
	size_t i, j, px = 2 * nx, py = 2 * ny, pxc;
	double dx = lx / (double)nx, dy = ly / (double)ny, scale;
	int layer;

	memset(e, 0, sizeof(*e));
	if ((layer = rc_layer_check(thickness, substrate, poisson, err)) < 0)
		return -1;
	if (!(modulus > 0) || !isfinite(modulus))
		return rc_seterr(err, "contact modulus must be positive and finite");
	if (nx < 2 || ny < 2)
		return rc_seterr(err, "free boundaries need a 2D grid (%zux%zu): a "
		    "line contact has no free-boundary reference (its plane-strain "
		    "displacement grows logarithmically with distance)", nx, ny);
	if (nx > RC_GRID_MAX_DIM || ny > RC_GRID_MAX_DIM)
		return rc_seterr(err, "grid %zux%zu too large for padding", nx, ny);
	if (rc_fft_init(&e->fft, px, py, effort, err) != 0)
		return -1;
	pxc = e->fft.nxc;
	e->nx = nx;
	e->ny = ny;
	e->n = nx * ny;
	e->modulus = modulus;
	if ((e->kernel = fftw_alloc_real(pxc * py)) == NULL) {
		rc_fft_free(&e->fft);
		return rc_seterr(err, "out of memory (asked for %zu bytes of the "
		    "padded kernel)", pxc * py * sizeof(double));
	}
	/* C / E* in wrap-around order, symmetric in each axis. */
	if (layer) {
		if (layer_table(e, dx, dy, thickness, substrate, poisson,
		    err) != 0) {
			rc_halfspace_release(e);
			return -1;
		}
	} else
#pragma omp parallel for private(i) schedule(static)
		for (j = 0; j < py; j++)
			for (i = 0; i < px; i++)
				e->fft.real[j * px + i] = rc_love_pixel(
				    offset(i, nx) * dx, offset(j, ny) * dy,
				    dx, dy) / modulus;
	e->self = e->fft.real[0];
	rc_fft_forward(&e->fft);
	/* Even and real: the spectrum is real up to round-off; keep its real
	 * part with the 1/(4N) of the unnormalised round trip. */
	scale = 1.0 / ((double)px * (double)py);
	e->eig_min = HUGE_VAL;
	for (i = 0; i < pxc * py; i++) {
		e->kernel[i] = creal(e->fft.spec[i]) * scale;
		e->eig_min = fmin(e->eig_min, creal(e->fft.spec[i]));
	}
	return 0;
}

void
rc_halfspace_release(rc_halfspace *e)
{
	rc_fft_free(&e->fft);
	fftw_free(e->kernel);
	memset(e, 0, sizeof(*e));
}

void
rc_halfspace_apply(rc_halfspace *e, const double *sigma, double *out)
{
	size_t i, j, nx = e->nx, ny = e->ny, px = 2 * nx, nm = e->fft.nxc * 2 * ny;
	double *pad = e->fft.real;
	fftw_complex *spec = e->fft.spec;

#pragma omp parallel for private(i) schedule(static)
	for (j = 0; j < 2 * ny; j++) {
		double *row = pad + j * px;

		if (j < ny) {
			memcpy(row, sigma + j * nx, nx * sizeof(double));
			for (i = nx; i < px; i++)
				row[i] = 0;
		} else
			memset(row, 0, px * sizeof(double));
	}
	rc_fft_forward(&e->fft);
#pragma omp parallel for schedule(static)
	for (i = 0; i < nm; i++)
		spec[i] *= e->kernel[i];
	rc_fft_backward(&e->fft);
#pragma omp parallel for schedule(static)
	for (j = 0; j < ny; j++)
		memcpy(out + j * nx, pad + j * px, nx * sizeof(double));
	e->n_pairs++;
}

size_t
rc_halfspace_bytes(const rc_halfspace *e)
{
	/* spec holds ny rows of nxs (fft.h), the stiffness ny of nxc */
	size_t m = e->fft.nxc * e->fft.ny, spec = e->fft.nxs * e->fft.ny;

	return (e->fft.nx * e->fft.ny + 2 * spec + m) * sizeof(double);
}
