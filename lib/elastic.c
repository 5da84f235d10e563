/* elastic.c - k_q table and the FFT applications of K and G = 1/K. */
#include "elastic.h"

#include <math.h>
#include <string.h>

int
rc_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx, double ly,
    double modulus, enum rc_fft_effort effort, rc_err *err)
{
	size_t i, j;

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
	fftw_execute_dft_r2c(e->fft.forward, (double *)in, out);
	e->n_r2c++;
}

void
rc_elastic_c2r(rc_elastic *e, fftw_complex *in, double *out)
{
	fftw_execute_dft_c2r(e->fft.backward, in, out);
	e->n_c2r++;
}

/* spec *= factor(k) / N, factor(0) = 0. */
static void
scale_spec(rc_elastic *e, int inverse)
{
	size_t m, nm = e->nxc * e->ny;
	double inv_n = 1.0 / (double)e->n;
	fftw_complex *spec = e->fft.spec;
	const double *k = e->stiffness;

#pragma omp parallel for schedule(static)
	for (m = 0; m < nm; m++) {
		double f;

		if (k[m] > 0)
			f = (inverse ? 1.0 / k[m] : k[m]) * inv_n;
		else
			f = 0;
		spec[m] *= f;
	}
}

void
rc_elastic_force(rc_elastic *e, const double *u, double *out)
{
	rc_elastic_r2c(e, u, e->fft.spec);
	scale_spec(e, 0);
	rc_elastic_c2r(e, e->fft.spec, out);
}

void
rc_elastic_displacement(rc_elastic *e, const double *sigma, double *out)
{
	rc_elastic_r2c(e, sigma, e->fft.spec);
	scale_spec(e, 1);
	rc_elastic_c2r(e, e->fft.spec, out);
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
	return 0.5 * sum / n2;
}

size_t
rc_elastic_bytes(const rc_elastic *e)
{
	return (e->n + 3 * e->nxc * e->ny) * sizeof(double);
}
