/* SPDX-License-Identifier: GPL-3.0-or-later */
/* delastic.c - the distributed elastic operator (delastic.h): FFTW-MPI
 * plans over this rank's rows and the seam of elastic.h they run
 * through. */
#include "mpi/delastic.h"

#include <fftw3-mpi.h>
#include <math.h>
#include <string.h>

#include "mpi/decomp.h"

/* Rows of nx into the plan's padded rows, last first (in may be the
 * padded array itself). */
static void
mpi_r2c(rc_elastic *e, const double *in, fftw_complex *out)
{
	for (size_t j = e->ny; j-- > 0;)
		memmove(e->fft.real + j * 2 * e->nxc, in + j * e->nx,
		    e->nx * sizeof(double));
	fftw_mpi_execute_dft_r2c(e->fft.forward, e->fft.real, out);
}

static void
mpi_c2r(rc_elastic *e, fftw_complex *in, double *out)
{
	fftw_mpi_execute_dft_c2r(e->fft.backward, in, e->fft.real);
	for (size_t j = 0; j < e->ny; j++)
		memmove(out + j * e->nx, e->fft.real + j * 2 * e->nxc,
		    e->nx * sizeof(double));
}

static const rc_elastic_dist mpi_dist = {
	.sum = rc_mpi_sum,
	.max = rc_mpi_max,
	.r2c = mpi_r2c,
	.c2r = mpi_c2r,
};

int
rc_mpi_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx,
    double ly, double modulus, enum rc_fft_effort effort, rc_err *err)
{
	size_t i, j, rows, j0, alloc;
	unsigned flags = effort == RC_FFT_ESTIMATE ? FFTW_ESTIMATE : FFTW_MEASURE;
	double k_range[2];

	memset(e, 0, sizeof(*e));
	if (!(modulus > 0) || !isfinite(modulus))
		return rc_seterr(err, "contact modulus must be positive and finite");
	rc_mpi_rows(nx, ny, &rows, &j0, &alloc);
	e->dist = &mpi_dist;
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
