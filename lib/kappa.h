/* SPDX-License-Identifier: GPL-3.0-or-later */
/* kappa.h - the proportionality coefficient kappa from a relative contact
 * area, by inverting a_r = erf(sqrt(pi) kappa p* / 2) (Eq. 24 of Wang &
 * Mueser 2020; Eq. 8 with p*_c for kappa_c).
 */
#ifndef RC_KAPPA_H
#define RC_KAPPA_H

/* Inverse error function on [0, 1], accurate near both ends (it goes
 * through the upper-tail normal quantile for y > 1/2).  Returns +inf at
 * y = 1, NaN outside [-1, 1]. */
double rc_erfinv(double y);

/* kappa = 2 erfinv(a_r) / (sqrt(pi) p*).  a_r = 0 gives 0; a_r = 1 gives
 * +inf (full contact carries no information on kappa); p* <= 0 or a_r
 * outside [0, 1] gives NaN. */
double rc_kappa(double a_r, double p_star);

#endif
