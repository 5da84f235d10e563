/* SPDX-License-Identifier: GPL-3.0-or-later */
/* adhesion.h - the short-range adhesive law of gfmd-solve --adhesion
 * (gfmd-solve(1), ADHESION): an exponential traction on top of the hard
 * wall.  With the gap g = u - h >= 0, work of adhesion dgamma (energy per
 * area: pressure times length) and range rho (length):
 *
 *   energy per area   phi(g)     = -dgamma exp(-g / rho)
 *   traction          sigma_a(g) = -phi'(g) = -(dgamma / rho) exp(-g / rho),
 *                     a pressure on the body (<= 0: tensile);
 *                     int_0^inf sigma_a dg = -dgamma;
 *   strongest tension sigma_max  = dgamma / rho (at g = 0).
 *
 * The force on the surface height u is sigma_a(g) = -d phi / d u.  The
 * wall adds a compressive reaction at g = 0 only; a point is in contact
 * when it sits on the wall and the reaction is positive, i.e. the elastic
 * pressure p + K u exceeds sigma_a(0) = -sigma_max.
 *
 * Length scales.  The adhesive curvature at contact is |phi''(0)| =
 * dgamma / rho^2 = E* / l_adh with
 *   l_adh = E* rho^2 / dgamma,
 * the length of the cohesive (process) zone at the edge of a JKR-type
 * contact: a tension sigma_max over l_adh opens the gap by ~ sigma_max
 * l_adh / E* = rho.  The grid resolves the law when dx <= l_adh (dx the
 * larger pixel side); below that the adhesive curvature exceeds the
 * stiffness of a single pixel and points snap on and off the wall one
 * by one (lattice trapping).  gfmd-solve warns when l_adh < dx.
 * Tabor parameter of a sphere (paraboloid) of radius R, as Tabor's with
 * the range rho for the equilibrium spacing z0:
 *   mu = (R dgamma^2 / (E*^2 rho^3))^(1/3) = (R dgamma / (E* l_adh rho))^(1/3)
 * (DMT for mu << 1, pull-off -2 pi dgamma R; JKR for mu >> 1, pull-off
 * -1.5 pi dgamma R).
 *
 * Beyond RC_ADH_CUTOFF ranges the traction is taken as 0 (relative size
 * e^-40 = 4e-18: below round-off of any pressure it adds to).
 */
#ifndef RC_ADHESION_H
#define RC_ADHESION_H

#include <math.h>

#define RC_ADH_CUTOFF	40.0

typedef struct rc_adhesion {
	double dgamma, range;
	double smax;		/* dgamma / range */
	double inv_range;
	double cutoff;		/* RC_ADH_CUTOFF range */
} rc_adhesion;

/* 0, or -1 when dgamma or range is not positive and finite. */
int rc_adhesion_init(rc_adhesion *a, double dgamma, double range);

/* sigma_a(g), the adhesive pressure on the body (<= 0), g >= 0. */
static inline double
rc_adhesion_traction(const rc_adhesion *a, double g)
{
	return g > a->cutoff ? 0 : -a->smax * exp(-g * a->inv_range);
}

/* phi(g), the adhesive energy per area (<= 0), g >= 0. */
double rc_adhesion_energy(const rc_adhesion *a, double g);
/* l_adh = E* rho^2 / dgamma. */
double rc_adhesion_length(double modulus, double dgamma, double range);
/* Tabor's mu of a sphere of radius R (above). */
double rc_adhesion_tabor(double radius, double modulus, double dgamma,
    double range);

#endif
