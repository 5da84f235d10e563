/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact_internal.h - the pieces of rc_contact_subpixel's edge fraction,
 * for its tests (contact.c says how and why).  Private to the library
 * (not installed): the internal prefix rc__, as in io_internal.h.
 */
#ifndef RC_CONTACT_INTERNAL_H
#define RC_CONTACT_INTERNAL_H

/* The bisection's test at m, r2 = r * r: pow(1 - m, 1.5) > r sqrt(m). */
int rc__edge_above(double m, double r, double r2);
/* The interval [lo, hi] the 50-step bisection from [0, 1] reaches after
 * the returned number of steps (0: [0, 1], no certified start). */
int rc__edge_start(double r, double *lo, double *hi);
/* The root f of (1 - f)^(3/2) / f^(1/2) = r as rc_contact_subpixel
 * finds it: the bisection from rc__edge_start on. */
double rc__edge_fraction(double r);

#endif
