/* SPDX-License-Identifier: GPL-3.0-or-later */
/* layer.h - the stiffness of an elastic layer of thickness d on a rigid
 * substrate, per Fourier mode (gfmd-solve(1), FINITE THICKNESS).
 *
 * A layer 0 <= z <= d (z into the body), its top loaded by a normal
 * pressure p cos(q x) and free of shear, its bottom on a rigid substrate
 * that is either bonded (u = 0) or frictionless (slip: u_z = 0, no shear).
 * Plane strain along q; Airy stress function
 *   phi = cos(q x) [(A + B z) cosh(q z) + (C + D z) sinh(q z)],
 * the displacements integrated from the strains, the four boundary
 * conditions solved for A..D.  With t = q d and E* = E / (1 - nu^2) the
 * stiffness k_q = p / u_z(0) is (q E* / 2) phi(t):
 *
 *   slip:    phi = (2t + sinh 2t) / (cosh 2t - 1)
 *   bonded:  phi = [(3 - 4nu) cosh 2t + 2t^2 + 5 - 12nu + 8nu^2]
 *                  / [(3 - 4nu) sinh 2t - 2t]
 *
 * Limits (tests/test_layer.c checks both, and phi against a shooting
 * solution of the Navier equations across the layer with GSL's ODE
 * solver): phi -> 1 for t -> infinity (the half space; phi - 1 =
 * (4t + 2) e^-2t slip, (4t^2 + 4t + 10 - 24nu + 16nu^2) e^-2t / (3 - 4nu)
 * bonded, to first order in e^-2t: below 1e-14 from t = 20; a layer
 * thicker than its longest wavelength, t >= 2 pi, is within 1e-4 (slip)
 * or 7e-4 (bonded) of the half space); for t -> 0 the thin-layer (Winkler)
 * foundation k_q -> k_w, independent of q:
 *   slip:    k_w = E* / d                          (phi ~ 2/t)
 *   bonded:  k_w = E* (1 - nu)^2 / ((1 - 2nu) d)   (phi ~ 2(1-nu)^2/((1-2nu)t)),
 * the bonded one the constrained (P-wave) modulus over d, infinite for an
 * incompressible layer (nu = 1/2, where phi ~ 3/(2t^3)).  The slip kernel
 * does not depend on nu.
 *
 * The uniform mode q = 0 of a periodic layer is uniaxial strain for
 * either substrate (a periodic lateral displacement has no mean strain):
 * k_0 = E* (1 - nu)^2 / ((1 - 2nu) d).  It moves the body as a whole and
 * so leaves the contact unchanged under load control; it enters the
 * approach (the substrate's travel, p / k_0 more than the surface's) and
 * the elastic energy (p^2 / (2 k_0) per area).
 *
 * Free boundaries need the layer in real space: its pixel compliance,
 * from the inverse transform of 1 / k_q (elastic_layer_free.h).
 */
#ifndef RC_LAYER_H
#define RC_LAYER_H

#include "rc_err.h"

enum rc_substrate {
	RC_SUBSTRATE_NONE = 0,	/* a half space: no layer */
	RC_SUBSTRATE_BONDED,
	RC_SUBSTRATE_SLIP
};

const char *rc_substrate_name(enum rc_substrate s);
int rc_substrate_parse(const char *name);	/* -1 if unknown */

/* phi(t) = k_q / (q E* / 2) for t = q d > 0; 1 for RC_SUBSTRATE_NONE.
 * poisson in (-1, 1/2]. */
double rc_layer_factor(double t, enum rc_substrate s, double poisson);

/* k_0 = E* (1 - nu)^2 / ((1 - 2nu) d): +inf for nu = 1/2. */
double rc_layer_uniform_stiffness(double modulus, double thickness,
    double poisson);

/* Whether (thickness, substrate, poisson) describe a layer; 0 for a half
 * space (thickness 0 and RC_SUBSTRATE_NONE); -1 with a reason when they
 * are inconsistent or out of range. */
int rc_layer_check(double thickness, enum rc_substrate s, double poisson,
    rc_err *err);

#endif
