/* SPDX-License-Identifier: GPL-3.0-or-later */
/* resample.h - a height map on a new grid spacing.
 *
 * Periodic grids: spectral (trigonometric) interpolation.  The new point
 * counts are nx' = round(lx / dx'), ny' = round(ly / dy') (the cell size
 * is kept, so the spacing is lx/nx', within half a spacing of the one
 * asked for); the Fourier modes with |k| < min(n, n')/2 on each axis are
 * kept, the Nyquist mode of the smaller axis dropped, the rest zero.  A
 * band-limited periodic surface is reproduced exactly at the new points.
 *
 * Finite patches (periodic = 0): tensor-product natural cubic spline
 * (GSL's cspline, first along x on every row, then along y on every
 * column).  New points at x = i dx' for 0 <= x <= (nx - 1) dx (likewise
 * y), so the result never extrapolates; lx' = nx' dx'.  An axis of fewer
 * than 3 points is left as it is.  Linear functions are reproduced to
 * round-off.  Grids with missing points are refused (fill them first).
 * The result has no filled-point flags: every new value mixes many old
 * ones (all of them, spectrally), so none is measured or filled alone;
 * the metadata filled_points stays, the count of the grid that was
 * filled.
 */
#ifndef RC_RESAMPLE_H
#define RC_RESAMPLE_H

#include "grid.h"

rc_grid *rc_resample(const rc_grid *g, double dx, double dy, rc_err *err);

#endif
