/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warp.h - height transformations of surfwarp: warping (Eq. 4 of Wang &
 * Mueser 2020), flipping, carving the non-contact zone, renormalising.
 *
 * Heights point toward the elastic body: maxima of h touch it first.  The
 * paper's w > 0 blunts those peaks and sharpens the valleys.  Eq. 4 as
 * printed (branch t^(1+w) for w >= 0) does the opposite in this
 * convention: at a maximum (grad h = 0) the warped curvature is
 * f'(t) h_xx with f(t) = t^(1+w), f'(t) = (1+w) t^w, which at t = 2/3 (the
 * maximum under the default bounds) is 4/3 for w = 2, against 1/3 at the
 * minimum.  So Eq. 4 is applied with its branches exchanged, which is Eq.
 * 4 applied to -h with the bounds mirrored:
 *   w > 0: h_w = hmax - (hmax - hmin) u^(1+w),  u = (hmax - h)/(hmax - hmin)
 *   w < 0: h_w = hmin + (hmax - hmin) t^(1+|w|), t = (h - hmin)/(hmax - hmin)
 *   w = 0: h_w = h (bit for bit).
 * u, t lie in [0, 1] and are raised by pow(), so no intermediate overflows
 * for any finite w; the map is monotone non-decreasing in h and maps
 * [hmin, hmax] onto itself.
 */
#ifndef RC_WARP_H
#define RC_WARP_H

#include "grid.h"

/* Default bounds of the paper: hmin = 2 min h - max h, hmax = 2 max h - min h. */
void rc_warp_default_bounds(const rc_grid *g, double *hmin, double *hmax);

/* Warp in place.  Requires hmin <= min h, hmax >= max h; a flat surface
 * (hmin = hmax) is left unchanged.  Records warp, warp_hmin, warp_hmax. */
int rc_warp(rc_grid *g, double w, double hmin, double hmax, rc_err *err);

/* The scalar map, for one height (exported for tests). */
double rc_warp_height(double h, double w, double hmin, double hmax);

/* h -> -h; records flip = 1 (toggled if already flipped). */
int rc_flip(rc_grid *g, rc_err *err);

/* Lower every point outside the contact mask by
 *   depth * (1 - exp(-d^2 / (2 width^2))),
 * d the periodic Euclidean distance to the nearest contact point: zero
 * (exactly) on the contact, smooth, never raising a point, tending to
 * depth far from contact.  Records carve_depth, carve_width. */
int rc_carve(rc_grid *g, const rc_grid *mask, double depth, double width,
    rc_err *err);

/* rc_carve, then roughen the carved zone downward only: every point k is
 * further lowered by roughness * |xi_k| * (1 - exp(-d^2 / (2 width^2))),
 * xi_k independent standard normal numbers (GSL's MT19937 seeded with
 * seed, drawn in storage order).  Contact points keep their heights
 * exactly and no point rises, so the contact of the original surface at
 * this and smaller loads is unchanged, while grid-scale roughness raises
 * the curvature moments (m4) and so the Nayak parameter by orders of
 * magnitude: the paper's first thought experiment.  Records
 * carve_roughness and carve_seed when roughness > 0. */
int rc_carve_rough(rc_grid *g, const rc_grid *mask, double depth,
    double width, double roughness, unsigned long seed, rc_err *err);

/* Squared periodic Euclidean distance from every point to the nearest
 * point with mask value 1 (exact; Felzenszwalb-Huttenlocher per axis).
 * d2 has nx*ny entries. */
int rc_distance2_to_mask(const rc_grid *mask, double *d2, rc_err *err);

/* Scale h -> (target / gbar) h, gbar the spectral rms gradient; records
 * rms_gradient.  A flat surface (gbar = 0) is an error. */
int rc_scale_rms_gradient(rc_grid *g, double target, rc_err *err);

#endif
