/* SPDX-License-Identifier: GPL-3.0-or-later */
/* iso25178.h - areal surface texture parameters of ISO 25178-2 with their
 * standard names, over the valid points of a grid (g->valid).
 *
 * Heights are taken about the mean of the valid points (the reference
 * plane is whatever levelling the grid had: level it first, surfwarp
 * --detrend).  With n valid points z_k about their mean:
 *   Sq  = sqrt(sum z^2 / n)                 root mean square height
 *   Sa  = sum |z| / n                       arithmetic mean height
 *   Ssk = sum z^3 / (n Sq^3)                skewness
 *   Sku = sum z^4 / (n Sq^4)                kurtosis
 *   Sp  = max z,  Sv = -min z (>= 0),  Sz = Sp + Sv
 * Hybrid parameters from forward differences gx = (z(i+1,j) - z(i,j))/dx,
 * gy = (z(i,j+1) - z(i,j))/dy at every point whose two forward neighbours
 * exist (wrapping on a periodic grid, inside the patch otherwise) and are
 * valid, m such points:
 *   Sdq = sqrt(sum (gx^2 + gy^2) / m)      root mean square gradient
 *   Sdr = sum (sqrt(1 + gx^2 + gy^2) - 1) / m   developed interfacial
 *         area ratio (a fraction; ISO often quotes it in percent)
 * On a periodic grid without missing points Sdq is exactly the gbar_fd of
 * surfstat and Sq is hrms.  An axis of one point contributes no gradient.
 *
 * Spatial parameters from the normalised autocorrelation
 *   f(t) = sum_x z(x) z(x + t) / sum_x z(x)^2
 * (missing points as 0; circular on a periodic grid, zero-padded on a
 * finite patch, i.e. the biased estimator), searched along 180 directions
 * 1 degree apart for the first distance at which f <= s (s = 0.2 by
 * default; bilinear interpolation between lattice lags, steps of a quarter
 * spacing, out to half the cell along each axis):
 *   Sal = the shortest such distance (fastest decay),
 *   Str = Sal / the longest such distance (1 isotropic, -> 0 a lay).
 * A direction that does not decay within the range makes Str NaN (strongly
 * anisotropic or a cell too small); none decaying makes Sal NaN too.
 *
 * Material ratio (Abbott-Firestone): Smr(c) is the fraction of valid
 * points with z >= c; its inverse c(mr), mr in [0, 1], interpolates
 * linearly between the sorted heights placed at mr = (k - 1/2)/n.  The
 * core (ISO 25178-2 after ISO 13565-2): of the secants of c(mr) spanning
 * dmr = 0.4, the one with the least slope (searched in steps of 1/1000 of
 * mr) extended to mr = 0 and 1 gives the heights c_top and c_bot;
 *   Sk   = c_top - c_bot                    core height
 *   Smr1 = Smr(c_top),  Smr2 = Smr(c_bot)   (fractions)
 *   Spk  = 2 A1 / Smr1, A1 = sum over z > c_top of (z - c_top) / n
 *   Svk  = 2 A2 / (1 - Smr2), A2 = sum over z < c_bot of (c_bot - z) / n
 * (the heights of the triangles with the areas of the peaks above and the
 * dales below the core; 0 when there are none).
 */
#ifndef RC_ISO25178_H
#define RC_ISO25178_H

#include <stddef.h>
#include "grid.h"

typedef struct rc_iso {
	size_t n_valid;
	double mean;		/* of the valid heights, the reference */
	double Sq, Sa, Ssk, Sku, Sp, Sv, Sz;
	double Sdq, Sdr;
	double Sal, Str;
	double Sk, Spk, Svk, Smr1, Smr2;
} rc_iso;

/* s: the autocorrelation threshold of Sal and Str, in (0, 1). */
int rc_iso25178(const rc_grid *g, double s, rc_iso *iso, rc_err *err);

/* The material ratio curve at npoints heights evenly spaced from the
 * highest to the lowest valid point: c[k] and Smr(c[k]) into smr[k]. */
int rc_material_ratio(const rc_grid *g, size_t npoints, double *c,
    double *smr, rc_err *err);

#endif
