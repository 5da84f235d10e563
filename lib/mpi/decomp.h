/* SPDX-License-Identifier: GPL-3.0-or-later */
/* decomp.h - the MPI build's distribution: FFTW-MPI's slab decomposition
 * (each rank owns a contiguous range of rows j, x fastest within a row),
 * global reductions, and MPI-IO of the native .surf format.  Everything
 * runs on MPI_COMM_WORLD; compiled only into the MPI build (make MPI=1). */
#ifndef RC_MPI_DECOMP_H
#define RC_MPI_DECOMP_H

#include <stddef.h>
#include "grid.h"

/* The rows [*j0, *j0 + *rows) of an ny-row grid of nx columns this rank
 * owns in FFTW-MPI's r2c layout; *alloc_complex is the number of complex
 * values its local half-complex array needs (twice that many doubles for
 * the padded real array).  *rows may be 0 on some ranks. */
void rc_mpi_rows(size_t nx, size_t ny, size_t *rows, size_t *j0,
    size_t *alloc_complex);
int rc_mpi_rank(void);
int rc_mpi_size(void);
/* In-place global sums and maxima of count doubles. */
void rc_mpi_sum(double *v, int count);
void rc_mpi_max(double *v, int count);

/* Read the .surf file at path: rank 0 parses the header, every rank reads
 * its rows (rc_mpi_rows) with one collective MPI-IO call.  Returns the
 * header as a grid of nx x 1 (metadata, history, kind, unit, lx, ly; its
 * values unused), *ny the rows of the file and *local the rank's rows
 * (fftw_malloc'ed, at least one double).  Collective; on failure every
 * rank gets NULL and the same message. */
rc_grid *rc_mpi_surf_read(const char *path, size_t *ny, double **local,
    rc_err *err);
/* Write the grid whose header is head (nx x 1, as above) and whose rows
 * [j0, j0 + rows) on this rank are local, ny rows in all, to path as
 * .surf: rank 0 writes the header, every rank its rows at
 * data_offset + j0 nx 8.  The file appears at path only when complete
 * (written to path.mpi-part, renamed).  Collective. */
int rc_mpi_surf_write(const rc_grid *head, size_t ny, const double *local,
    const char *path, rc_err *err);

#endif
