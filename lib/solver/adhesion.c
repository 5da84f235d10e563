/* SPDX-License-Identifier: GPL-3.0-or-later */
/* adhesion.c - the adhesive laws (see adhesion.h). */
#include "adhesion.h"

#include <string.h>

static const char *const law_names[] = { "exponential", "dugdale" };

int
rc_adhesion_init(rc_adhesion *a, enum rc_adhesion_law law, double dgamma,
    double range)
{
	if (!(dgamma > 0 && isfinite(dgamma) && range > 0 && isfinite(range)) ||
	    rc_adhesion_law_name(law) == NULL)
		return -1;
	a->law = law;
	a->dgamma = dgamma;
	a->range = range;
	a->smax = dgamma / range;
	a->inv_range = 1 / range;
	a->cutoff = law == RC_ADHESION_DUGDALE ? range : RC_ADH_CUTOFF * range;
	return 0;
}

const char *
rc_adhesion_law_name(enum rc_adhesion_law law)
{
	return (unsigned)law < sizeof(law_names) / sizeof(law_names[0]) ?
	    law_names[law] : NULL;
}

int
rc_adhesion_law_parse(const char *name)
{
	for (size_t k = 0; k < sizeof(law_names) / sizeof(law_names[0]); k++)
		if (strcmp(name, law_names[k]) == 0)
			return (int)k;
	return -1;
}

double
rc_adhesion_energy(const rc_adhesion *a, double g)
{
	if (a->law == RC_ADHESION_DUGDALE)
		return g < a->range ? -a->smax * (a->range - g) : 0;
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
