/* SPDX-License-Identifier: GPL-3.0-or-later */
/* adhesion.h - the short-range adhesive laws of gfmd-solve --adhesion
 * (gfmd-solve(1), ADHESION): a tension on top of the hard wall.  With the
 * gap g = u - h >= 0, work of adhesion dgamma (energy per area: pressure
 * times length) and range rho (length), either
 *
 * exponential (the default):
 *   energy per area   phi(g)     = -dgamma exp(-g / rho)
 *   traction          sigma_a(g) = -phi'(g) = -(dgamma / rho) exp(-g / rho),
 * or Dugdale's cohesive zone (Maugis 1992), rho the critical opening:
 *   energy per area   phi(g)     = -sigma_max (rho - g) for g < rho, else 0
 *   traction          sigma_a(g) = -sigma_max for g < rho, else 0;
 * both: a pressure on the body (<= 0: tensile), int_0^inf sigma_a dg =
 * -dgamma, strongest tension sigma_max = dgamma / rho (at g = 0; Dugdale:
 * Maugis' sigma_0, the same at the same rho).
 *
 * The force on the surface height u is sigma_a(g) = -d phi / d u.  The
 * wall adds a compressive reaction at g = 0 only; a point is in contact
 * when it sits on the wall and the reaction is positive, i.e. the elastic
 * pressure p + K u exceeds sigma_a(0) = -sigma_max.  Dugdale's energy has
 * a concave kink at g = rho, where no equilibrium point sits (the force
 * there would have to be both -sigma_max and 0).
 *
 * Length scales.  l_adh = E* rho^2 / dgamma = E* dgamma / sigma_max^2
 * for both laws.  Exponential: the adhesive curvature at contact is
 * |phi''(0)| = E* / l_adh, and l_adh the length of the cohesive
 * (process) zone at the edge of a JKR-type contact: a tension sigma_max
 * over l_adh opens the gap by ~ sigma_max l_adh / E* = rho.  Dugdale: the
 * zone of a crack with stress intensity K under the constant closing
 * tension sigma_max has the length (pi / 8) K^2 / sigma_max^2 (Dugdale
 * 1960, Rice 1968); at the JKR edge K^2 = 2 E* dgamma (Griffith), so
 * that length is (pi / 4) l_adh (small-scale: l_adh << contact radius;
 * the opening at its end is then K^2 / (2 E* sigma_max) = rho).  The grid
 * resolves the law when dx <= l_adh (dx the larger pixel side): below
 * that the zone is narrower than a pixel and points snap on and off the
 * wall one by one (lattice trapping).  gfmd-solve warns when l_adh < dx.
 * Tabor parameter of a sphere (paraboloid) of radius R, as Tabor's with
 * the range rho for the equilibrium spacing z0:
 *   mu = (R dgamma^2 / (E*^2 rho^3))^(1/3) = (R dgamma / (E* l_adh rho))^(1/3)
 * (DMT for mu << 1, pull-off -2 pi dgamma R; JKR for mu >> 1, pull-off
 * -1.5 pi dgamma R).  Maugis' parameter lambda = 2 sigma_max (R / (pi
 * dgamma K^2))^(1/3), K = 4 E* / 3, is (9 / (2 pi))^(1/3) mu = 1.1272 mu,
 * for either law; his pull-off curve is exact for Dugdale's.
 *
 * Exponential: beyond RC_ADH_CUTOFF ranges the traction is taken as 0
 * (relative size e^-40 = 4e-18: below round-off of any pressure it adds
 * to).
 */
#ifndef RC_ADHESION_H
#define RC_ADHESION_H

#include <math.h>

#define RC_ADH_CUTOFF	40.0

enum rc_adhesion_law {
	RC_ADHESION_EXPONENTIAL = 0,
	RC_ADHESION_DUGDALE
};

typedef struct rc_adhesion {
	enum rc_adhesion_law law;
	double dgamma, range;
	double smax;		/* dgamma / range */
	double inv_range;
	double cutoff;		/* the traction is 0 beyond this gap */
} rc_adhesion;

/* 0, or -1 when dgamma or range is not positive and finite or the law
 * unknown. */
int rc_adhesion_init(rc_adhesion *a, enum rc_adhesion_law law, double dgamma,
    double range);
/* "exponential", "dugdale"; NULL if unknown. */
const char *rc_adhesion_law_name(enum rc_adhesion_law law);
int rc_adhesion_law_parse(const char *name);	/* -1 if unknown */

/* sigma_a(g), the adhesive pressure on the body (<= 0), g >= 0. */
static inline double
rc_adhesion_traction(const rc_adhesion *a, double g)
{
	if (a->law == RC_ADHESION_DUGDALE)
		return g < a->range ? -a->smax : 0;
	return g > a->cutoff ? 0 : -a->smax * exp(-g * a->inv_range);
}

/* The strongest tension at any gap >= g: -sigma_a(g) (both laws weaken
 * with the gap); the exponential's without the cutoff. */
static inline double
rc_adhesion_tension_beyond(const rc_adhesion *a, double g)
{
	if (a->law == RC_ADHESION_DUGDALE)
		return g < a->range ? a->smax : 0;
	return a->smax * exp(-g / a->range);
}

/* phi(g), the adhesive energy per area (<= 0), g >= 0. */
double rc_adhesion_energy(const rc_adhesion *a, double g);
/* l_adh = E* rho^2 / dgamma (either law). */
double rc_adhesion_length(double modulus, double dgamma, double range);
/* Tabor's mu of a sphere of radius R (above; either law). */
double rc_adhesion_tabor(double radius, double modulus, double dgamma,
    double range);

#endif
