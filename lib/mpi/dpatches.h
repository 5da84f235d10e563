/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dpatches.h - contact patches of a mask distributed by rows over the
 * ranks, without gathering it (lib/mpi/dpatches.c). */
#ifndef RC_MPI_DPATCHES_H
#define RC_MPI_DPATCHES_H

#include <stddef.h>
#include "rc_err.h"

/* This rank's rows of nx points (rows may be 0); collective.  On every
 * rank: the number of periodic patches of the whole mask and the sum of
 * their squared sizes in points, equal to rc_contact_patches on the
 * gathered mask. */
int rc_mpi_patches(const unsigned char *contact, size_t nx, size_t rows,
    size_t *n_patches, double *sum_sq, rc_err *err);

#endif
