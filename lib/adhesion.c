/* SPDX-License-Identifier: GPL-3.0-or-later */
/* adhesion.c - the exponential adhesive law (see adhesion.h). */
#include "adhesion.h"

int
rc_adhesion_init(rc_adhesion *a, double dgamma, double range)
{
	if (!(dgamma > 0 && isfinite(dgamma) && range > 0 && isfinite(range)))
		return -1;
	a->dgamma = dgamma;
	a->range = range;
	a->smax = dgamma / range;
	a->inv_range = 1 / range;
	a->cutoff = RC_ADH_CUTOFF * range;
	return 0;
}

double
rc_adhesion_energy(const rc_adhesion *a, double g)
{
	return g > a->cutoff ? 0 : -a->dgamma * exp(-g * a->inv_range);
}

double
rc_adhesion_length(double modulus, double dgamma, double range)
{
	return modulus * range * range / dgamma;
}

double
rc_adhesion_tabor(double radius, double modulus, double dgamma, double range)
{
	return cbrt(radius * dgamma * dgamma /
	    (modulus * modulus * range * range * range));
}
