/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stats_nonuni.h - a line scan not uniformly spaced (grid.h: g->x set),
 * analysed as it is: the piecewise-linear function through its n points
 * (x_i, h_i), as SurfaceTopography (contact.engineering) analyses a
 * NonuniformLineScan.  With dx_i = x_{i+1} - x_i, dh_i = h_{i+1} - h_i and
 * the sums over the segments i whose two ends are valid (a missing
 * height takes out the segments that touch it), L = sum dx_i:
 *   mean  = L^-1 sum dx_i (h_i + h_{i+1}) / 2       (trapezoids: exact)
 *   hrms^2 = (3L)^-1 sum dx_i (d_i^2 + d_i d_{i+1} + d_{i+1}^2),
 *            d = h - mean                            (exact integral)
 *   rms_slope^2 = L^-1 sum dh_i^2 / dx_i             (exact integral;
 *            the mean slope is not removed, as in SurfaceTopography)
 *   rms_curvature^2 = trapezoidal mean of c_i^2 over the interior
 *            points (x_1 .. x_{n-2}) whose neighbours are valid, with
 *            the three-point second derivative, exact for a parabola:
 *            c_i = 2 (dx_- (h_{i+1} - h_i) + dx_+ (h_{i-1} - h_i))
 *                  / (dx_+ dx_- (dx_+ + dx_-)),
 *            dx_- = x_i - x_{i-1}, dx_+ = x_{i+1} - x_i; NaN with
 *            fewer than two such points.  (The piecewise-linear function
 *            itself has no curvature: this is SurfaceTopography's.)
 * Without missing points these are SurfaceTopography's
 * rms_height_from_profile, rms_slope_from_profile and
 * rms_curvature_from_profile to round-off.
 *
 * Interpolation error, for a smooth h sampled at steps up to dx_max:
 * the chord through (x_i, h_i) is off h by at most e = dx_max^2
 * max|h''| / 8, and the chord's mean off h's by at most e, so hrms^2 is
 * off by at most 4 e max|h - mean| + 4 e^2;
 * a chord's slope is h' at a point of its segment, so off h' by at most
 * s = dx_max max|h''|, and rms_slope^2 by at most 2 s max|h'| + s^2.
 */
#ifndef RC_STATS_NONUNI_H
#define RC_STATS_NONUNI_H

#include <stddef.h>
#include "grid.h"
#include "psd.h"
#include "rc_err.h"

typedef struct rc_nonuni_stats {
	size_t n;		/* points */
	size_t n_missing;	/* of them missing */
	size_t n_segments;	/* segments with both ends valid */
	double length;		/* L, their total length */
	double mean, hrms, rms_slope, rms_curvature, hmin, hmax;
} rc_nonuni_stats;

/* The statistics above of g (g->x set; missing points NaN).  An error
 * when no segment has two valid ends. */
int rc_nonuni_stats_compute(const rc_grid *g, rc_nonuni_stats *s,
    rc_err *err);

/*
 * The 1D spectrum of the piecewise-linear function, transformed exactly
 * (SurfaceTopography's "brute-force" algorithm; its default "fft" one
 * interpolates onto a finer uniform grid first): with the mean removed
 * and the window applied at the points (hann, the default: w(x) =
 * sqrt(2/3) (1 - cos(2 pi (x - x_0) / L)), mean w^2 = 1; or none),
 *   H(q) = sum_i dx_i e^{-i q xm_i} (hm_i sinc(u_i) + i dh_i sinc'(u_i)/2),
 *   xm_i, hm_i the segment's midpoint and mean height, u_i = q dx_i / 2,
 *   sinc(u) = sin(u)/u, the exact transform of each straight segment;
 *   C1D_ce(q) = |H(q)|^2 / L (SurfaceTopography's), C1D = C1D_ce / (2 pi)
 *   (ours, psd.h), at q_k = 2 pi k / L for k = 1, 2, ... below 2 pi over
 *   the mean step (SurfaceTopography's default short cutoff), k < n - 1.
 * SurfaceTopography does not remove the mean, which under the Hann window
 * changes q_1 alone (the window's transform has no other mode), and
 * centres its window on x = L/2 rather than on the scan: the same when
 * x_0 = 0.  Every point must be valid.  O(n^2) operations: refused above
 * RC_NONUNI_PSD_MAX points.  n_lines 1, std_err NaN.
 */
#define RC_NONUNI_PSD_MAX 20000
int rc_nonuni_psd(const rc_grid *g, enum rc_window window,
    rc_psd1d_point **pts, size_t *npts, rc_err *err);

#endif
