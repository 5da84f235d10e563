/* SPDX-License-Identifier: GPL-3.0-or-later */
/* level.h - levelling and repair of measured height maps: detrending,
 * scan-line alignment, harmonic filling of missing points, cropping,
 * transposing (resampling is in resample.h).
 *
 * Coordinates: point (i, j) sits at x = i dx, y = j dy (pixel registered,
 * dx = lx/nx, dy = ly/ny).  Every fit uses the valid points only
 * (g->valid, see grid.h) and leaves missing points missing.
 *
 * Detrending fits, by least squares over the valid points,
 *   mean:      z ~ a0
 *   plane:     z ~ a0 + a1 x + a2 y
 *   quadratic: z ~ a0 + a1 x + a2 y + a3 x^2 + a4 x y + a5 y^2
 * and subtracts the fit (an axis of one point, a profile's, has no x or y
 * terms).  Removing a plane or a quadric from one period of
 * a periodic surface breaks its periodicity, so both set g->periodic = 0;
 * removing the mean keeps it.
 *
 * Scan-line alignment (AFM): every row j (a line along x, the fast scan
 * axis) is shifted by its own median or mean, or has its own least-squares
 * line a + b x removed, over its valid points.  The rows become unrelated
 * in their offsets, so the grid is marked non-periodic.
 *
 * Harmonic fill: the missing points get the solution of the discrete
 * Laplace equation (5-point stencil, neighbours along x weighted 1/dx^2,
 * along y 1/dy^2) with the valid points as Dirichlet data; at
 * the edge of a non-periodic grid the missing neighbours outside the grid
 * are left out of the stencil (a zero-flux edge), a periodic grid wraps.
 * Solved by successive over-relaxation, red-black order, with the
 * relaxation factor of a square of the holes' extent; converged when no
 * update in a sweep exceeds 1e-13 times the range of the valid heights
 * (or 1e-300 absolute); failure after 200 (nx + ny) + 1000 sweeps.  A
 * linear function is harmonic, so it is filled exactly (to round-off).
 */
#ifndef RC_LEVEL_H
#define RC_LEVEL_H

#include <stddef.h>
#include "grid.h"

enum rc_detrend { RC_DETREND_MEAN = 0, RC_DETREND_PLANE, RC_DETREND_QUADRATIC };
enum rc_align { RC_ALIGN_MEDIAN = 0, RC_ALIGN_MEAN, RC_ALIGN_PLANE };

/* Names as on the command line; parse returns -1 if unknown. */
int rc_detrend_parse(const char *name);
const char *rc_detrend_name(enum rc_detrend d);
int rc_align_parse(const char *name);
const char *rc_align_name(enum rc_align a);

/* Subtract the least-squares fit; coef (may be NULL) gets the 1, 3 or 6
 * coefficients a0 .. a5 of the fit in x - xc, y - yc (xc, yc the centre
 * of the points, (nx - 1) dx / 2 and (ny - 1) dy / 2), in the units of z
 * and x, y. */
int rc_detrend(rc_grid *g, enum rc_detrend kind, double *coef, rc_err *err);
/* Align every row; rows without a valid point are left alone. */
int rc_align_rows(rc_grid *g, enum rc_align kind, rc_err *err);
/* Fill the missing points harmonically; afterwards g->valid is NULL and
 * g->filled marks them (with the points of an earlier fill).  *filled (may
 * be NULL) gets a malloc'ed nx*ny mask, 1 where a point was filled by this
 * call, or NULL when nothing was missing; *nfilled their count.  The
 * number of points g->filled marks is recorded in the metadata as
 * filled_points. */
int rc_fill_harmonic(rc_grid *g, unsigned char **filled, size_t *nfilled,
    rc_err *err);
/* Points x0 <= i < x1, y0 <= j < y1 as a new grid (a finite patch of the
 * surface unless it is all of a periodic one), with the missing and the
 * filled points among them (filled_points then counts those). */
rc_grid *rc_crop(const rc_grid *g, size_t x0, size_t x1, size_t y0, size_t y1,
    rc_err *err);
/* Swap x and y: value (i, j) of the result is value (j, i) of g, and so
 * are its missing and filled flags. */
rc_grid *rc_transpose(const rc_grid *g, rc_err *err);

#endif
