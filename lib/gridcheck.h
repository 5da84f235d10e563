/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gridcheck.h - is a grid fit for a computation that assumes it periodic,
 * or complete?
 *
 * Wrap-around ratio: a periodic grid continues across its edges, so the
 * step from its last column to its first (and last row to first) is like
 * any step inside.  For each direction d with at least two points,
 *
 *   r_d = rms over the edge of (z at index 0 - z at index n_d - 1)
 *         / rms over the interior of (z at index k+1 - z at index k),
 *
 * over pairs of valid points; the ratio is the larger r_d.  A periodic
 * random surface gives about 1; a tilted or unlevelled measurement, whose
 * edges do not meet, gives about the number of points across (a plane of
 * slope s: edge step s L against s L/n).  Tools that treat a grid as
 * periodic warn above RC_WRAP_RATIO_WARN.
 */
#ifndef RC_GRIDCHECK_H
#define RC_GRIDCHECK_H

#include <stddef.h>
#include "grid.h"
#include "rc_err.h"

/* surfgen's periodic surfaces measured at most 1.63 (30 of them, 8^2 to
 * 64^2 points, H 0.3 and 0.8); a tilted plane gives n - 1 along a side of
 * n points, above 5 from 7 points on. */
#define RC_WRAP_RATIO_WARN 5.0

/* The ratio above; 1 when no direction has two points or no step
 * differs from zero (a flat grid); +Inf if the interior is flat and the
 * edge step is not. */
double rc_grid_wrap_ratio(const rc_grid *g);

/* Points flagged missing (0 if g->valid is NULL). */
size_t rc_grid_missing_count(const rc_grid *g);

/* 0 if g is uniformly spaced (g->x NULL), else an error naming --uniform:
 * what assumes the step lx/nx (solver, statistics, spectra) calls it. */
int rc_grid_check_uniform(const rc_grid *g, rc_err *err);

#endif
