/* SPDX-License-Identifier: GPL-3.0-or-later */
/* layer.c - the stiffness factor of an elastic layer (formulas in layer.h),
 * evaluated without overflow for large q d and without cancellation for
 * small q d. */
#include "layer.h"

#include <math.h>
#include <string.h>

const char *
rc_substrate_name(enum rc_substrate s)
{
	switch (s) {
	case RC_SUBSTRATE_NONE:
		return "none";
	case RC_SUBSTRATE_BONDED:
		return "bonded";
	case RC_SUBSTRATE_SLIP:
		return "slip";
	}
	return "unknown";
}

int
rc_substrate_parse(const char *name)
{
	if (strcmp(name, "bonded") == 0)
		return RC_SUBSTRATE_BONDED;
	if (strcmp(name, "slip") == 0)
		return RC_SUBSTRATE_SLIP;
	return -1;
}

/* sinh(x) - x, by its series below 2 (where the difference cancels). */
static double
sinh_minus_x(double x)
{
	double term = x * x * x / 6, sum = 0;
	int k;

	if (x > 2)
		return sinh(x) - x;
	for (k = 2; term > 1e-18 * sum; k++) {
		sum += term;
		term *= x * x / ((2.0 * k) * (2.0 * k + 1));
	}
	return sum;
}

double
rc_layer_factor(double t, enum rc_substrate s, double poisson)
{
	double a = 3 - 4 * poisson;
	double b = 5 - 12 * poisson + 8 * poisson * poisson;

	if (s == RC_SUBSTRATE_NONE)
		return 1;
	if (t > 1) {
		/* numerator and denominator times 2 e^-2t: no overflow */
		double e = exp(-2 * t), one_e = -expm1(-2 * t);

		if (s == RC_SUBSTRATE_SLIP)
			return (4 * t * e + (1 - e * e)) / (one_e * one_e);
		return (a * (1 + e * e) + 2 * e * (2 * t * t + b)) /
		    (a * one_e * (1 + e) - 4 * t * e);
	}
	if (s == RC_SUBSTRATE_SLIP) {
		double sh = sinh(t);

		return (2 * t + sinh(2 * t)) / (2 * sh * sh);
	}
	/* (3 - 4nu) sinh 2t - 2t = (2 - 4nu) 2t + (3 - 4nu)(sinh 2t - 2t) */
	return (a * cosh(2 * t) + 2 * t * t + b) /
	    ((a - 1) * 2 * t + a * sinh_minus_x(2 * t));
}

double
rc_layer_uniform_stiffness(double modulus, double thickness, double poisson)
{
	if (poisson >= 0.5)
		return HUGE_VAL;
	return modulus * (1 - poisson) * (1 - poisson) /
	    ((1 - 2 * poisson) * thickness);
}

int
rc_layer_check(double thickness, enum rc_substrate s, double poisson,
    rc_err *err)
{
	if (s == RC_SUBSTRATE_NONE && thickness == 0)
		return 0;
	if (s != RC_SUBSTRATE_BONDED && s != RC_SUBSTRATE_SLIP)
		return rc_seterr(err, "a layer needs its substrate interface: "
		    "bonded or slip");
	if (!(thickness > 0) || !isfinite(thickness))
		return rc_seterr(err, "layer thickness must be positive and finite");
	if (!(poisson > -1 && poisson <= 0.5))
		return rc_seterr(err, "Poisson's ratio must lie in (-1, 0.5]");
	return 1;
}
