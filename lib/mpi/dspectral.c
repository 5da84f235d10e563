/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dspectral.c - spectral sums over a distributed grid (dspectral.h). */
#include "mpi/dspectral.h"

#include <fftw3-mpi.h>
#include <math.h>
#include <string.h>

#include "mpi/decomp.h"

double
rc_mpi_gradient_sum(const fftw_complex *spec, size_t nx, size_t ny, double lx,
    double ly, size_t j0, size_t rows)
{
	size_t nxc = nx / 2 + 1, i, j;
	double sum = 0;

	for (j = 0; j < rows; j++) {
		double qy = rc_deriv_wavenumber(j0 + j, ny, ly), row = 0;

		for (i = 0; i < nxc; i++) {
			double qx = rc_deriv_wavenumber(i, nx, lx);
			double m = cabs(spec[j * nxc + i]);

			row += rc_fft_weight(i, nx) * (qx * qx + qy * qy) * m * m;
		}
		sum += row;
	}
	return sum;
}

int
rc_mpi_rms_gradient(const double *z, size_t nx, size_t ny, double lx,
    double ly, double *gbar, rc_err *err)
{
	size_t rows, j0, alloc, nxc = nx / 2 + 1, j;
	double *real, sum, bad;
	fftw_complex *spec;
	fftw_plan plan = NULL;

	rc_mpi_rows(nx, ny, &rows, &j0, &alloc);
	real = fftw_alloc_real(2 * alloc);
	spec = fftw_alloc_complex(alloc);
	bad = real == NULL || spec == NULL;
	rc_mpi_max(&bad, 1);
	if (!bad) {
		plan = fftw_mpi_plan_dft_r2c_2d((ptrdiff_t)ny, (ptrdiff_t)nx, real, spec,
		    MPI_COMM_WORLD, FFTW_ESTIMATE);
		bad = plan == NULL;
		rc_mpi_max(&bad, 1);
	}
	if (bad) {
		if (plan != NULL)
			fftw_destroy_plan(plan);
		fftw_free(real);
		fftw_free(spec);
		return rc_seterr(err, "out of memory for the rms gradient (%zu bytes)",
		    4 * alloc * sizeof(double));
	}
	for (j = 0; j < rows; j++)
		memcpy(real + j * 2 * nxc, z + j * nx, nx * sizeof(double));
	fftw_execute(plan);
	sum = rc_mpi_gradient_sum(spec, nx, ny, lx, ly, j0, rows);
	rc_mpi_sum(&sum, 1);
	*gbar = sqrt(sum) / ((double)nx * (double)ny);
	fftw_destroy_plan(plan);
	fftw_free(real);
	fftw_free(spec);
	return 0;
}
