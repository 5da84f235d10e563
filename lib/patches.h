/* SPDX-License-Identifier: GPL-3.0-or-later */
/* patches.h - contact patches: periodic connected components (4-
 * neighbourhood) of a contact mask, labelled run by run (Hoshen-Kopelman
 * on row runs).  rc_contact_patches (contact.h) does a whole grid; the
 * parts below let the MPI build (lib/mpi/dsolver.c) label each rank's
 * rows and join the slabs without gathering the mask.
 */
#ifndef RC_PATCHES_H
#define RC_PATCHES_H

#include <stddef.h>
#include "rc_err.h"

/* A run of contact points in one row: columns [start, end). */
typedef struct rc_run {
	size_t start, end;
	size_t label;		/* union-find entry */
} rc_run;

/* Union-find with sizes (points per component). */
typedef struct rc_uf {
	size_t *parent, *size;
	size_t n, cap;
} rc_uf;

/* A new component of the given size; its entry into *label. */
int rc_uf_add(rc_uf *u, size_t size, size_t *label, rc_err *err);
size_t rc_uf_find(rc_uf *u, size_t a);
void rc_uf_union(rc_uf *u, size_t a, size_t b);
void rc_uf_free(rc_uf *u);
/* The number of components and the sum of their squared sizes. */
void rc_uf_components(const rc_uf *u, size_t *count, double *sum_sq);

/* Join the runs of two vertically adjacent rows that share a column
 * (both lists sorted by start). */
void rc_runs_join(rc_uf *u, const rc_run *a, size_t na, const rc_run *b,
    size_t nb);

/* Label the runs of the ny rows of nx points in contact (row-major),
 * periodic in x, joined between consecutive rows but not across the y
 * boundary, into u (which may hold entries already).  The runs of the
 * first and the last row are copied to first and last (each room for
 * nx / 2 + 1 runs), their counts to *nfirst and *nlast; ny = 0 leaves
 * both empty. */
int rc_patches_slab(const unsigned char *contact, size_t nx, size_t ny,
    rc_uf *u, rc_run *first, size_t *nfirst, rc_run *last, size_t *nlast,
    rc_err *err);

#endif
