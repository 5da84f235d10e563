/* SPDX-License-Identifier: GPL-3.0-or-later */
/* si.h - a length written for people: three significant digits and the
 * SI prefix that puts them in [1, 1000): 200 um, 59.9 nm, 1.5 mm.
 *
 * The value is in a length unit of units.h (m mm um nm pm angstrom); it
 * is written in m, mm, um, nm or pm (1 m and above in m, below 1 pm in
 * pm), the micro sign as "u" or, with micro_sign, as U+00B5 in UTF-8
 * ("µm").  A unit that is not a length ("" for surfgen's unitless
 * lengths, V, deg) leaves the number as %.3g followed by the unit.
 */
#ifndef RC_SI_H
#define RC_SI_H

#include <stddef.h>

void rc_si_length(char *buf, size_t len, double v, const char *unit,
    int micro_sign);

#endif
