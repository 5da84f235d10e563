/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic_layer_free.h - the pixel compliance of an elastic layer on a
 * rigid substrate (layer.h) in real space, for free boundaries
 * (elastic_free.h tabulates it on the padded grid).
 *
 * The layer's point-force Green's function (surface displacement at
 * distance r from a unit normal force) is the inverse 2D Fourier
 * transform of 1 / k_q = 2 / (q E* phi(q d)):
 *   G_L(r) = (1/(pi E*)) int_0^inf J0(q r) / phi(q d) dq.
 * Split off Boussinesq's G_half = 1/(pi E* r) (phi = 1):
 *   G_L = G_half - D,  D(r) = F(r/d) / (pi E* d),
 *   F(rho) = int_0^inf J0(s rho) w(s) ds,  w(s) = 1 - 1/phi(s).
 * w(0) = 1 and w falls like s^2 e^-2s, so F is finite at 0 and analytic
 * in the strip |Im rho| < 2: D is smooth on the scale d.  The layer's
 * pixel compliance (uniform unit pressure on a dx x dy pixel centred at
 * the origin, displacement at (x, y)) is then
 *   C_L(x, y) = C_love(x, y) - int_pixel D,
 * Love's closed form (elastic_free.h) minus a smooth correction.
 *
 * 1 / k_q = 2 / (q E* phi(q d)) is even and analytic in q (1/phi is odd
 * in t), so G_L decays exponentially, at a rate set by the zero of
 * phi's numerator nearest the real axis: slowest for a bonded
 * incompressible layer, e^(-0.73 r/d) (cos 2 tau - 2 tau^2 + 1 = 0, t =
 * i tau); about e^(-1.8 r/d) measured for slip.  Measured: pi E* r
 * |G_L(r)| < 1e-14 beyond r = 48 d (slip; bonded with nu = 0.3 and
 * 0.5, the slowest), the round-off of 1/r - F there (RC_LAYER_CUTOFF);
 * C_L is
 * taken as 0 for pixels beyond that distance, which makes the table's
 * support finite (a thin layer: a few pixels).
 *
 * Construction (rc_layer_pixel_init): F on [0, rho_max] by Chebyshev
 * series of order RC_LAYER_CHEB_ORDER on segments of length d (each
 * node an integral over s in [0, 24], where w < 1e-17, by composite
 * 16-point Gauss-Legendre on panels short against the phase of
 * J0(s rho) and the scale of w); int_pixel D by tensor Gauss-Legendre on
 * sub-panels no wider than d (D is analytic to a distance 2d from the
 * real plane), the order chosen from the Bernstein ellipse that allows
 * (a rule that aims at round-off; the error is measured in
 * tests/test_layer.c: 1e-14 for F, 8e-16 C(0) for the pixel integrals).
 * A pixel that contains the whole disk r <= 48 d about its observation
 * point gets C_L = 1/k(q -> 0) exactly (the integral of G_L over the
 * plane): a layer thinner than dx/96 is the Winkler foundation,
 * diagonal, without a table.
 */
#ifndef RC_ELASTIC_LAYER_FREE_H
#define RC_ELASTIC_LAYER_FREE_H

#include <stddef.h>

#include "layer.h"
#include "rc_err.h"

#define RC_LAYER_CUTOFF		48.0	/* r_cut / d (above) */
#define RC_LAYER_CHEB_ORDER	16
#define RC_LAYER_GAUSS_MAX	16	/* Gauss points per sub-panel side */

typedef struct rc_layer_pixel {
	double thickness, modulus, dx, dy;
	enum rc_substrate substrate;
	double poisson;
	double r_cut;		/* RC_LAYER_CUTOFF d: C_L = 0 beyond */
	double compliance0;	/* 1 / k(q -> 0): the integral of G_L */
	size_t n_seg;		/* Chebyshev segments of F, each d long */
	double *cheb;		/* n_seg * (RC_LAYER_CHEB_ORDER + 1) */
	/* Gauss-Legendre rules of 1 .. RC_LAYER_GAUSS_MAX points on [-1, 1],
	 * n's at offset n (n - 1) / 2 */
	double gauss_x[RC_LAYER_GAUSS_MAX * (RC_LAYER_GAUSS_MAX + 1) / 2];
	double gauss_w[RC_LAYER_GAUSS_MAX * (RC_LAYER_GAUSS_MAX + 1) / 2];
} rc_layer_pixel;

/* The table for pixels whose observation points lie within r_max of the
 * pixel centre (the padded grid's diagonal); modulus E*. */
int rc_layer_pixel_init(rc_layer_pixel *t, double thickness,
    enum rc_substrate substrate, double poisson, double modulus,
    double dx, double dy, double r_max, rc_err *err);
void rc_layer_pixel_release(rc_layer_pixel *t);
/* D(r) = G_half - G_L at r <= r_max (per unit force); tabulated only
 * when some pixel needs it (n_seg > 0: not for a layer so thin that
 * r_cut is within half a pixel, whose C_L is diagonal). */
double rc_layer_green_correction(const rc_layer_pixel *t, double r);
/* C_L(x, y) per unit pressure (0 beyond r_cut), (x, y) an offset of
 * the pixel lattice (multiples of dx, dy: the thin layer's shortcut
 * above covers only those). */
double rc_layer_pixel_compliance(const rc_layer_pixel *t, double x, double y);
/* 1 / k(q -> 0): d / E* slip, d (1 - 2nu) / (E* (1 - nu)^2) bonded. */
double rc_layer_compliance0(double modulus, double thickness,
    enum rc_substrate substrate, double poisson);

#endif
