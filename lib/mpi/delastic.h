/* SPDX-License-Identifier: GPL-3.0-or-later */
/* delastic.h - the elastic operator on this rank's rows (make MPI=1): the
 * implementation of elastic.h's distributed seam over FFTW-MPI's slab
 * decomposition (lib/mpi/decomp.h). */
#ifndef RC_MPI_DELASTIC_H
#define RC_MPI_DELASTIC_H

#include "elastic.h"

/* rc_elastic_init for this rank's rows of an nx x ny grid: ny then holds
 * the local row count, n the global point count (the normalisation),
 * fft.ny the global row count and fft.real the padded (2 nxc per row)
 * real array of the MPI plans; fields passed in and out keep nx per row.
 * k_min and k_max are global.  The operator's dist is this layer's (sums
 * and maxima by MPI_Allreduce); rc_elastic_free releases it.  Collective. */
int rc_mpi_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx,
    double ly, double modulus, enum rc_fft_effort effort, rc_err *err);

#endif
