/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic.c - k_q table (continuum or pixel kernel) and the FFT
 * applications of K and G = 1/K. */
#include "elastic.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

int
rc_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx, double ly,
    double modulus, enum rc_fft_effort effort, rc_err *err)
{
	size_t i, j, bytes;

	memset(e, 0, sizeof(*e));
	if (!(modulus > 0) || !isfinite(modulus))
		return rc_seterr(err, "contact modulus must be positive and finite");
	if (rc_fft_init(&e->fft, nx, ny, effort, err) != 0)
		return -1;
	e->nx = nx;
	e->ny = ny;
	e->nxc = e->fft.nxc;
	e->n = nx * ny;
	e->modulus = modulus;
	if (rc_fft_bytes(e->nxc, ny, sizeof(double), &bytes) != 0) {
		rc_fft_free(&e->fft);
		return rc_seterr(err, "grid %zux%zu too large: its stiffness "
		    "table's size overflows size_t", nx, ny);
	}
	e->stiffness = rc_fft_huge(bytes, &e->stiffness_block);
	if (e->stiffness == NULL) {
		rc_fft_free(&e->fft);
		return rc_seterr(err, "out of memory (asked for %zu bytes of stiffness table)",
		    bytes);
	}
	/* Rows above ny/2 are those below mirrored: their q_y is exactly
	 * the negative (rc_wavenumber), and hypot takes magnitudes; copied,
	 * not computed again (half the hypot calls: 3 of the 100 ms of CPU
	 * a 512^2 gfmd-solve spends outside its iterations, perf).  The rows
	 * on the threads (the table was 1.5 ms of one core's time at 512^2,
	 * the solver's start waits for it); min and max are exact in any
	 * order, so k_min and k_max are those of a serial loop. */
	double kmin = HUGE_VAL, kmax = 0;
	long nhalf = (long)(ny / 2) + 1;

#pragma omp parallel for private(i) reduction(min:kmin) reduction(max:kmax) \
    schedule(static)
	for (long jl = 0; jl < nhalf; jl++) {
		size_t jj = (size_t)jl;
		double qy = rc_wavenumber(jj, ny, ly);

		for (i = 0; i < e->nxc; i++) {
			double qx = rc_wavenumber(i, nx, lx);
			double k = 0.5 * modulus * hypot(qx, qy);

			e->stiffness[jj * e->nxc + i] = k;
			if (k > kmax)
				kmax = k;
			if (k > 0 && k < kmin)
				kmin = k;
		}
	}
	for (j = ny / 2 + 1; j < ny; j++)
		memcpy(&e->stiffness[j * e->nxc],
		    &e->stiffness[(ny - j) * e->nxc], e->nxc * sizeof(double));
	e->k_min = kmin;
	e->k_max = kmax;
	if (e->n == 1)
		e->k_min = e->k_max = 0.5 * modulus * 2 * M_PI / (lx < ly ? lx : ly);
	return 0;
}

int
rc_elastic_set_layer(rc_elastic *e, double lx, double ly, double thickness,
    enum rc_substrate substrate, double poisson, rc_err *err)
{
	size_t i, j;

	/* Its table runs over the global rows. */
	if (e->dist != NULL)
		return rc_seterr(err, "a finite thickness is not in the MPI build");
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
	size_t i, j, nxc = e->nxc, ny = e->ny;
	double dx = lx / (double)e->nx, dy = ly / (double)ny;
	double kmin = HUGE_VAL, kmax = 0;

	if (kernel == RC_KERNEL_CONTINUUM)
		return 0;
	if (kernel != RC_KERNEL_PIXEL)
		return rc_seterr(err, "unknown elastic kernel %d", (int)kernel);
	if (e->dist != NULL)
		return rc_seterr(err, "the pixel kernel is not in the MPI build");
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

void
rc_elastic_free(rc_elastic *e)
{
	rc_fft_free(&e->fft);
	rc_fft_huge_free(e->stiffness, e->stiffness_block);
	memset(e, 0, sizeof(*e));
}

void
rc_elastic_r2c(rc_elastic *e, const double *in, fftw_complex *out)
{
	if (e->dist != NULL)
		e->dist->r2c(e, in, out);
	else
		fftw_execute_dft_r2c(e->fft.forward, (double *)in, out);
	e->n_r2c++;
}

void
rc_elastic_c2r(rc_elastic *e, fftw_complex *in, double *out)
{
	if (e->dist != NULL)
		e->dist->c2r(e, in, out);
	else
		fftw_execute_dft_c2r(e->fft.backward, in, out);
	e->n_c2r++;
}

void
rc_elastic_force(rc_elastic *e, const double *u, double *out)
{
	rc_fft_multiplier mu = { e->stiffness, 1.0 / (double)e->n, 0, 0 };

	rc_elastic_convolve(e, u, out, &mu);
}

void
rc_elastic_displacement(rc_elastic *e, const double *sigma, double *out)
{
	rc_fft_multiplier mu = { e->stiffness, 1.0 / (double)e->n, 1, 0 };

	rc_elastic_convolve(e, sigma, out, &mu);
}

void
rc_elastic_convolve(rc_elastic *e, const double *in, double *out,
    const rc_fft_multiplier *mu)
{
	if (e->dist != NULL) {
		/* the distributed transforms, through the seam */
		rc_elastic_r2c(e, in, e->fft.spec);
		rc_fft_multiply(e->fft.spec, e->nxc * e->ny, mu);
		rc_elastic_c2r(e, e->fft.spec, out);
		return;
	}
	rc_fft_convolve(&e->fft, in, out, mu);
	e->n_r2c++;
	e->n_c2r++;
}

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
	rc_elastic_sum(e, &sum, 1);
	return 0.5 * sum / n2;
}

void
rc_elastic_sum(const rc_elastic *e, double *v, int count)
{
	if (e->dist != NULL)
		e->dist->sum(v, count);
}

void
rc_elastic_max(const rc_elastic *e, double *v, int count)
{
	if (e->dist != NULL)
		e->dist->max(v, count);
}

size_t
rc_elastic_bytes(const rc_elastic *e)
{
	/* rc_fft_init gives spec room for rows nxs apart (fft.h); a
	 * distributed operator's spectrum is its own, rows nxc apart */
	size_t spec_row = e->dist != NULL ? e->nxc : e->fft.nxs;

	return (e->n + (2 * spec_row + e->nxc) * e->ny) * sizeof(double);
}
