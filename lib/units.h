/* SPDX-License-Identifier: GPL-3.0-or-later */
/* units.h - length units, and bringing a grid to one length unit.
 *
 * Units are SI metres with a prefix: m, mm, um (also spelled µm with the
 * micro sign or the Greek mu, and micron), nm, pm, and the angstrom
 * (Å, angstrom).  Each is an exact power of ten of a metre, so a
 * conversion multiplies or divides by an exactly representable 10^k and
 * is correctly rounded.  The canonical spelling is ASCII: m mm um nm pm
 * angstrom.  Any other unit string (V, deg, A, unitless, ...) is not a
 * length.  "" is an unknown unit: dimensionless lengths, as surfgen's.
 *
 * Gradients, gbar, p* and contact mix lateral lengths and heights, so a
 * grid is brought to one length unit after reading (rc_grid_to_common_unit):
 * heights in nm over a µm cell become heights in µm.
 */
#ifndef RC_UNITS_H
#define RC_UNITS_H

#include "grid.h"
#include "rc_err.h"

/* 1 and *exp10 set (one unit = 10^exp10 m) if u is a length unit, else 0. */
int rc_unit_length_exp(const char *u, int *exp10);
/* Is u a length unit? */
int rc_unit_is_length(const char *u);
/* The canonical spelling of a length unit; u itself otherwise. */
const char *rc_unit_canonical(const char *u);
/* x, in length unit from, expressed in length unit to (both lengths);
 * exact powers of ten, correctly rounded. */
double rc_unit_convert(double x, const char *from, const char *to);

/* Do the values of this kind of grid share the lateral length unit
 * (height, gap, displacement)? */
int rc_kind_is_length(enum rc_kind k);

/* Bring g to one length unit: unit if not NULL or "", else the grid's
 * lateral unit, else its value unit.  Lateral sizes and, for a grid of
 * lengths (rc_kind_is_length), the values are converted; an unknown ("")
 * lateral or value unit is taken to be that unit.  Afterwards g->unit and
 * (for lengths) g->z_unit are the canonical spelling of that unit, or both
 * stay "" when no unit is known.  Fails, naming the unit, when the
 * lateral unit or the values of a grid of lengths are not lengths (a
 * phase channel in deg: say --z-unit if they are heights). */
int rc_grid_to_common_unit(rc_grid *g, const char *unit, rc_err *err);

#endif
