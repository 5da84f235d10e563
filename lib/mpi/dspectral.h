/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dspectral.h - spectral sums over a distributed grid (make MPI=1). */
#ifndef RC_MPI_DSPECTRAL_H
#define RC_MPI_DSPECTRAL_H

#include <stddef.h>
#include "fft.h"

/* This rank's share of sum over the full spectrum of |q|^2 |Z_q|^2, Z the
 * unnormalised half-complex spectrum of rows j0 ... j0 + rows - 1 (the
 * derivative wave numbers of fft.h: Nyquist zeroed), as rc_rms_gradient
 * sums it; rms gradient = sqrt(global sum) / (nx ny). */
double rc_mpi_gradient_sum(const fftw_complex *spec, size_t nx, size_t ny,
    double lx, double ly, size_t j0, size_t rows);

/* The rms gradient (spectral, as rc_rms_gradient) of the grid whose rows
 * this rank holds in z (nx apart, rc_mpi_rows).  Collective. */
int rc_mpi_rms_gradient(const double *z, size_t nx, size_t ny, double lx,
    double ly, double *gbar, rc_err *err);

#endif
