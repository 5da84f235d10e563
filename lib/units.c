/* SPDX-License-Identifier: GPL-3.0-or-later */
/* units.c - length units and the conversion of a grid to one of them
 * (see units.h). */
#include "units.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const struct {
	const char *name;
	int exp10;		/* one unit = 10^exp10 m */
	const char *canonical;
} units[] = {
	{ "m", 0, "m" },
	{ "mm", -3, "mm" },
	{ "um", -6, "um" },
	{ "\xc2\xb5m", -6, "um" },	/* micro sign */
	{ "\xce\xbcm", -6, "um" },	/* Greek small mu */
	{ "micron", -6, "um" },
	{ "nm", -9, "nm" },
	{ "pm", -12, "pm" },
	{ "angstrom", -10, "angstrom" },
	{ "\xc3\x85", -10, "angstrom" },	/* Å, precomposed */
	{ "\xe2\x84\xab", -10, "angstrom" },	/* Å, the angstrom sign */
};
#define NUNITS (sizeof(units) / sizeof(units[0]))

static int
find(const char *u)
{
	for (size_t i = 0; i < NUNITS; i++)
		if (strcmp(u, units[i].name) == 0)
			return (int)i;
	return -1;
}

int
rc_unit_length_exp(const char *u, int *exp10)
{
	int i = find(u);

	if (i < 0)
		return 0;
	*exp10 = units[i].exp10;
	return 1;
}

int
rc_unit_is_length(const char *u)
{
	return find(u) >= 0;
}

const char *
rc_unit_canonical(const char *u)
{
	int i = find(u);

	return i < 0 ? u : units[i].canonical;
}

/* x * 10^k with one correctly rounded operation (10^k is exact for
 * |k| <= 22, and units differ by at most 12). */
static double
scale10(double x, int k)
{
	if (k == 0)
		return x;
	return k > 0 ? x * pow(10, k) : x / pow(10, -k);
}

double
rc_unit_convert(double x, const char *from, const char *to)
{
	int a = 0, b = 0;

	rc_unit_length_exp(from, &a);
	rc_unit_length_exp(to, &b);
	return scale10(x, a - b);
}

int
rc_kind_is_length(enum rc_kind k)
{
	return k == RC_KIND_HEIGHT || k == RC_KIND_GAP || k == RC_KIND_DISPLACEMENT;
}

int
rc_grid_to_common_unit(rc_grid *g, const char *unit, rc_err *err)
{
	const char *target;
	int elat = 0, ez = 0, et = 0, lengths = rc_kind_is_length(g->kind);

	if (g->unit[0] != '\0' && !rc_unit_length_exp(g->unit, &elat))
		return rc_seterr(err, "lateral unit '%s' is not a length (want m, mm, "
		    "um, nm, pm or angstrom)", g->unit);
	if (lengths && strcmp(g->z_unit, "1") == 0)
		return rc_seterr(err, "values are unitless (an intensity or colour "
		    "channel?), not a %s; if they are %ss in a length unit, say "
		    "which with --z-unit", rc_kind_name(g->kind),
		    rc_kind_name(g->kind));
	if (lengths && g->z_unit[0] != '\0' && !rc_unit_length_exp(g->z_unit, &ez))
		return rc_seterr(err, "values are in '%s', not a length: not a %s; "
		    "if they are %ss in a length unit, say which with --z-unit",
		    g->z_unit, rc_kind_name(g->kind), rc_kind_name(g->kind));
	if (unit != NULL && unit[0] != '\0') {
		if (!rc_unit_length_exp(unit, &et))
			return rc_seterr(err, "unit '%s' is not a length", unit);
		target = unit;
	} else if (g->unit[0] != '\0')
		target = g->unit, et = elat;
	else if (lengths && g->z_unit[0] != '\0')
		target = g->z_unit, et = ez;
	else
		return 0;	/* no unit known: dimensionless lengths */
	target = rc_unit_canonical(target);
	if (g->unit[0] == '\0')
		elat = et;
	if (g->z_unit[0] == '\0')
		ez = elat;
	g->lx = scale10(g->lx, elat - et);
	g->ly = scale10(g->ly, elat - et);
	for (size_t i = 0; g->x != NULL && i < g->nx; i++)
		g->x[i] = scale10(g->x[i], elat - et);
	if (rc_grid_check_shape(g->nx, g->ny, g->lx, g->ly, err) != 0)
		return -1;
	if (lengths && ez != et) {
		size_t n = rc_grid_size(g);

		for (size_t k = 0; k < n; k++) {
			g->z[k] = scale10(g->z[k], ez - et);
			if (isinf(g->z[k]))
				return rc_seterr(err, "value at i=%zu, j=%zu overflows "
				    "in %s", k % g->nx, k / g->nx, target);
		}
	}
	/* target may point into g->unit or g->z_unit: copy via a buffer. */
	char t[sizeof(g->unit)];

	snprintf(t, sizeof(t), "%s", target);
	strcpy(g->unit, t);
	if (lengths)
		strcpy(g->z_unit, t);
	return 0;
}
