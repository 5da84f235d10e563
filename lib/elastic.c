/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic.c - k_q table (continuum or pixel kernel) and the FFT
 * applications of K and G = 1/K. */
#include "elastic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifdef RC_MPI
/* The MPI build (make MPI=1): the operator runs on this rank's rows of
 * FFTW-MPI's slab decomposition (lib/mpi/decomp.h).  ny is then the local
 * row count, n stays the global point count (the normalisation), fft.ny
 * is the global row count and fft.real the padded (2 nxc per row) real
 * array of the MPI plans; fields passed in and out keep nx per row. */
#include <fftw3-mpi.h>
#include "mpi/decomp.h"

static int
mpi_init(rc_elastic *e, size_t nx, size_t ny, double lx, double ly,
    double modulus, enum rc_fft_effort effort, rc_err *err)
{
	size_t i, j, rows, j0, alloc;
	unsigned flags = effort == RC_FFT_ESTIMATE ? FFTW_ESTIMATE : FFTW_MEASURE;
	double k_range[2];

	rc_mpi_rows(nx, ny, &rows, &j0, &alloc);
	e->nx = e->fft.nx = nx;
	e->fft.ny = ny;
	e->ny = rows;
	e->nxc = e->fft.nxc = nx / 2 + 1;
	e->n = nx * ny;
	e->modulus = modulus;
	e->fft.effort = effort;
	e->fft.real = fftw_alloc_real(2 * alloc);
	e->fft.spec = fftw_alloc_complex(alloc);
	e->stiffness = fftw_alloc_real(alloc);
	if (e->fft.real == NULL || e->fft.spec == NULL || e->stiffness == NULL) {
		rc_elastic_free(e);
		return rc_seterr(err, "out of memory (asked for %zu bytes of FFT buffers)",
		    alloc * 4 * sizeof(double));
	}
	e->fft.forward = fftw_mpi_plan_dft_r2c_2d((ptrdiff_t)ny, (ptrdiff_t)nx,
	    e->fft.real, e->fft.spec, MPI_COMM_WORLD, flags);
	e->fft.backward = fftw_mpi_plan_dft_c2r_2d((ptrdiff_t)ny, (ptrdiff_t)nx,
	    e->fft.spec, e->fft.real, MPI_COMM_WORLD, flags);
	if (e->fft.forward == NULL || e->fft.backward == NULL) {
		rc_elastic_free(e);
		return rc_seterr(err, "FFTW-MPI could not plan a %zu x %zu transform",
		    nx, ny);
	}
	e->k_min = HUGE_VAL;
	e->k_max = 0;
	for (j = 0; j < rows; j++) {
		double qy = rc_wavenumber(j0 + j, ny, ly);

		for (i = 0; i < e->nxc; i++) {
			double k = 0.5 * modulus * hypot(rc_wavenumber(i, nx, lx), qy);

			e->stiffness[j * e->nxc + i] = k;
			if (k > e->k_max)
				e->k_max = k;
			if (k > 0 && k < e->k_min)
				e->k_min = k;
		}
	}
	k_range[0] = -e->k_min;
	k_range[1] = e->k_max;
	rc_mpi_max(k_range, 2);
	e->k_min = -k_range[0];
	e->k_max = k_range[1];
	if (e->n == 1)
		e->k_min = e->k_max = 0.5 * modulus * 2 * M_PI / (lx < ly ? lx : ly);
	return 0;
}
#endif

int
rc_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx, double ly,
    double modulus, enum rc_fft_effort effort, rc_err *err)
{
	size_t i, j;

	memset(e, 0, sizeof(*e));
	if (!(modulus > 0) || !isfinite(modulus))
		return rc_seterr(err, "contact modulus must be positive and finite");
#ifdef RC_MPI
	return mpi_init(e, nx, ny, lx, ly, modulus, effort, err);
#endif
	if (rc_fft_init(&e->fft, nx, ny, effort, err) != 0)
		return -1;
	e->nx = nx;
	e->ny = ny;
	e->nxc = e->fft.nxc;
	e->n = nx * ny;
	e->modulus = modulus;
	e->stiffness = fftw_alloc_real(e->nxc * ny);
	if (e->stiffness == NULL) {
		rc_fft_free(&e->fft);
		return rc_seterr(err, "out of memory (asked for %zu bytes of stiffness table)",
		    e->nxc * ny * sizeof(double));
	}
	e->k_min = HUGE_VAL;
	e->k_max = 0;
	for (j = 0; j < ny; j++) {
		double qy = rc_wavenumber(j, ny, ly);

		for (i = 0; i < e->nxc; i++) {
			double qx = rc_wavenumber(i, nx, lx);
			double k = 0.5 * modulus * hypot(qx, qy);

			e->stiffness[j * e->nxc + i] = k;
			if (k > e->k_max)
				e->k_max = k;
			if (k > 0 && k < e->k_min)
				e->k_min = k;
		}
	}
	if (e->n == 1)
		e->k_min = e->k_max = 0.5 * modulus * 2 * M_PI / (lx < ly ? lx : ly);
	return 0;
}

int
rc_elastic_set_layer(rc_elastic *e, double lx, double ly, double thickness,
    enum rc_substrate substrate, double poisson, rc_err *err)
{
#ifdef RC_MPI
	(void)e;
	(void)lx;
	(void)ly;
	(void)thickness;
	(void)substrate;
	(void)poisson;
	return rc_seterr(err, "a finite thickness is not in the MPI build");
#else
	size_t i, j;

	if (rc_layer_check(thickness, substrate, poisson, err) < 0)
		return -1;
	if (e->kernel != RC_KERNEL_CONTINUUM)
		return rc_seterr(err, "a finite thickness has the continuum "
		    "kernel only (the pixel kernel would need the layer's "
		    "factor on every image)");
	if (e->n == 1)
		return 0;	/* no mode but the uniform one: scales kept */
	e->k_min = HUGE_VAL;
	e->k_max = 0;
	for (j = 0; j < e->ny; j++) {
		double qy = rc_wavenumber(j, e->ny, ly);

		for (i = 0; i < e->nxc; i++) {
			double q = hypot(rc_wavenumber(i, e->nx, lx), qy);
			double *k = &e->stiffness[j * e->nxc + i];

			if (q > 0)
				*k *= rc_layer_factor(q * thickness, substrate,
				    poisson);
			if (*k > e->k_max)
				e->k_max = *k;
			if (*k > 0 && *k < e->k_min)
				e->k_min = *k;
		}
	}
	return 0;
#endif
}

const char *
rc_kernel_name(enum rc_kernel k)
{
	return k == RC_KERNEL_PIXEL ? "pixel" : "continuum";
}

int
rc_kernel_parse(const char *name)
{
	if (strcmp(name, "continuum") == 0)
		return RC_KERNEL_CONTINUUM;
	if (strcmp(name, "pixel") == 0)
		return RC_KERNEL_PIXEL;
	return -1;
}

/* Images per axis of the pixel kernel (elastic.h: truncation, error). */
#define PIXEL_M 8

/* One axis of the image sum: sinc(c + pi m) and (Q_m)^2 = (2 (c + pi m) /
 * d)^2 for m = -PIXEL_M ... PIXEL_M.  sin(c + pi m) = (-1)^m sin c, so
 * the form factor is exactly 0 on every image of q = 0. */
static void
pixel_axis(double q, double d, double *form, double *q2)
{
	double c = 0.5 * q * d, sc = sin(c);

	for (int m = -PIXEL_M; m <= PIXEL_M; m++) {
		double x = c + M_PI * m, qm = 2 * x / d;

		form[m + PIXEL_M] = x == 0 ? 1 : (m % 2 ? -sc : sc) / x;
		q2[m + PIXEL_M] = qm * qm;
	}
}

double
rc_pixel_compliance(double qx, double qy, double dx, double dy)
{
	double fx[2 * PIXEL_M + 1], fy[2 * PIXEL_M + 1];
	double qx2[2 * PIXEL_M + 1], qy2[2 * PIXEL_M + 1];
	double s8 = 0, s4 = 0;

	if (qx == 0 && qy == 0)
		return 0;
	pixel_axis(qx, dx, fx, qx2);
	pixel_axis(qy, dy, fy, qy2);
	for (int my = -PIXEL_M; my <= PIXEL_M; my++) {
		double wy8 = abs(my) == PIXEL_M ? 0.5 : 1;
		double wy4 = abs(my) == PIXEL_M / 2 ? 0.5 : 1;
		double row8 = 0, row4 = 0;

		if (fy[my + PIXEL_M] == 0)
			continue;
		for (int mx = -PIXEL_M; mx <= PIXEL_M; mx++) {
			double t;

			if (fx[mx + PIXEL_M] == 0)
				continue;
			t = fx[mx + PIXEL_M] / sqrt(qx2[mx + PIXEL_M] + qy2[my + PIXEL_M]);
			row8 += (abs(mx) == PIXEL_M ? 0.5 : 1) * t;
			if (abs(mx) <= PIXEL_M / 2)
				row4 += (abs(mx) == PIXEL_M / 2 ? 0.5 : 1) * t;
		}
		s8 += wy8 * fy[my + PIXEL_M] * row8;
		if (abs(my) <= PIXEL_M / 2)
			s4 += wy4 * fy[my + PIXEL_M] * row4;
	}
	/* 2 / |Q| per image; Richardson on the M^-4 error of the halved sums. */
	return 2 * (16 * s8 - s4) / 15;
}

int
rc_elastic_set_kernel(rc_elastic *e, double lx, double ly,
    enum rc_kernel kernel, rc_err *err)
{
	if (kernel == RC_KERNEL_CONTINUUM)
		return 0;
	if (kernel != RC_KERNEL_PIXEL)
		return rc_seterr(err, "unknown elastic kernel %d", (int)kernel);
#ifdef RC_MPI
	(void)e;
	(void)lx;
	(void)ly;
	return rc_seterr(err, "the pixel kernel is not in the MPI build");
#else
	{
		size_t i, j, nxc = e->nxc, ny = e->ny;
		double dx = lx / (double)e->nx, dy = ly / (double)ny;
		double kmin = HUGE_VAL, kmax = 0;

		e->kernel = kernel;
		if (e->n == 1)
			return 0;	/* no mode but the uniform one: scales kept */
		/* Even in qy: rows j and ny - j are the same; compute the first
		 * half and copy. */
#pragma omp parallel for private(i) schedule(dynamic, 4)
		for (j = 0; j <= ny / 2; j++) {
			double qy = rc_wavenumber(j, ny, ly);

			for (i = 0; i < nxc; i++) {
				double g = rc_pixel_compliance(rc_wavenumber(i,
				    e->nx, lx), qy, dx, dy);

				e->stiffness[j * nxc + i] = g > 0 ?
				    e->modulus / g : 0;
			}
		}
		for (j = ny / 2 + 1; j < ny; j++)
			memcpy(e->stiffness + j * nxc, e->stiffness +
			    (ny - j) * nxc, nxc * sizeof(double));
		for (i = 0; i < nxc * ny; i++) {
			double k = e->stiffness[i];

			if (k > kmax)
				kmax = k;
			if (k > 0 && k < kmin)
				kmin = k;
		}
		e->k_min = kmin;
		e->k_max = kmax;
		return 0;
	}
#endif
}

void
rc_elastic_free(rc_elastic *e)
{
	rc_fft_free(&e->fft);
	fftw_free(e->stiffness);
	memset(e, 0, sizeof(*e));
}

void
rc_elastic_r2c(rc_elastic *e, const double *in, fftw_complex *out)
{
#ifdef RC_MPI
	/* Rows of nx into the plan's padded rows, last first (in may be the
	 * padded array itself). */
	for (size_t j = e->ny; j-- > 0;)
		memmove(e->fft.real + j * 2 * e->nxc, in + j * e->nx,
		    e->nx * sizeof(double));
	fftw_mpi_execute_dft_r2c(e->fft.forward, e->fft.real, out);
#else
	fftw_execute_dft_r2c(e->fft.forward, (double *)in, out);
#endif
	e->n_r2c++;
}

void
rc_elastic_c2r(rc_elastic *e, fftw_complex *in, double *out)
{
#ifdef RC_MPI
	fftw_mpi_execute_dft_c2r(e->fft.backward, in, e->fft.real);
	for (size_t j = 0; j < e->ny; j++)
		memmove(out + j * e->nx, e->fft.real + j * 2 * e->nxc,
		    e->nx * sizeof(double));
#else
	fftw_execute_dft_c2r(e->fft.backward, in, out);
#endif
	e->n_c2r++;
}

/* spec *= factor(k) / N, factor(0) = 0, on the real and imaginary parts
 * as doubles (a complex-times-real product may be compiled as a full
 * complex one, which the vectoriser leaves alone); the products are the
 * same.  K: k/N is 0 at k = 0 without a branch. */
#ifdef RC_MPI
static void
scale_spec(rc_elastic *e, int inverse)
{
	size_t m, nm = e->nxc * e->ny;
	double inv_n = 1.0 / (double)e->n, *z = (double *)e->fft.spec;
	const double *k = e->stiffness;

	if (!inverse) {
#pragma omp parallel for schedule(static)
		for (m = 0; m < nm; m++) {
			double f = k[m] * inv_n;

			z[2 * m] *= f;
			z[2 * m + 1] *= f;
		}
		return;
	}
#pragma omp parallel for schedule(static)
	for (m = 0; m < nm; m++) {
		double f = k[m] > 0 ? 1.0 / k[m] * inv_n : 0;

		z[2 * m] *= f;
		z[2 * m + 1] *= f;
	}
}
#endif

void
rc_elastic_force(rc_elastic *e, const double *u, double *out)
{
#ifdef RC_MPI
	rc_elastic_r2c(e, u, e->fft.spec);
	scale_spec(e, 0);
	rc_elastic_c2r(e, e->fft.spec, out);
#else
	rc_fft_multiplier mu = { e->stiffness, 1.0 / (double)e->n, 0, 0 };

	rc_elastic_convolve(e, u, out, &mu);
#endif
}

void
rc_elastic_displacement(rc_elastic *e, const double *sigma, double *out)
{
#ifdef RC_MPI
	rc_elastic_r2c(e, sigma, e->fft.spec);
	scale_spec(e, 1);
	rc_elastic_c2r(e, e->fft.spec, out);
#else
	rc_fft_multiplier mu = { e->stiffness, 1.0 / (double)e->n, 1, 0 };

	rc_elastic_convolve(e, sigma, out, &mu);
#endif
}

#ifndef RC_MPI
void
rc_elastic_convolve(rc_elastic *e, const double *in, double *out,
    const rc_fft_multiplier *mu)
{
	rc_fft_convolve(&e->fft, in, out, mu);
	e->n_r2c++;
	e->n_c2r++;
}
#endif

double
rc_elastic_energy_spec(const rc_elastic *e, const fftw_complex *spec)
{
	size_t i, j;
	double sum = 0, n2 = (double)e->n * (double)e->n;

#pragma omp parallel for private(i) reduction(+:sum) schedule(static)
	for (j = 0; j < e->ny; j++)
		for (i = 0; i < e->nxc; i++) {
			size_t m = j * e->nxc + i;
			double a = creal(spec[m]), b = cimag(spec[m]);

			sum += rc_fft_weight(i, e->nx) * e->stiffness[m] * (a * a + b * b);
		}
#ifdef RC_MPI
	rc_mpi_sum(&sum, 1);
#endif
	return 0.5 * sum / n2;
}

size_t
rc_elastic_bytes(const rc_elastic *e)
{
	return (e->n + 3 * e->nxc * e->ny) * sizeof(double);
}
