/* SPDX-License-Identifier: GPL-3.0-or-later */
/* si.c - lengths with SI prefixes (si.h). */
#include "si.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "units.h"

void
rc_si_length(char *buf, size_t len, double v, const char *unit, int micro_sign)
{
	static const char *const name[] = { "m", "mm", "um", "nm", "pm" };
	int e, k;
	double m, r;
	char digits[32];

	if (!rc_unit_length_exp(unit, &e) || !isfinite(v) || v == 0) {
		snprintf(buf, len, "%.3g%s%s", v, unit[0] ? " " : "", unit);
		if (v == 0 && rc_unit_length_exp(unit, &e))
			snprintf(buf, len, "0 %s", rc_unit_canonical(unit));
		return;
	}
	/* Round to three digits first: 999.7 um is 1 mm, not 1e+03 um. */
	snprintf(digits, sizeof(digits), "%.2e", v);
	r = strtod(digits, NULL);
	/* the decade of |r| in metres, then the prefix (k = 0 for m) */
	k = (int)floor((floor(log10(fabs(r))) + e) / 3.0);
	k = k > 0 ? 0 : k < -4 ? -4 : k;
	m = r * pow(10, e - 3 * k);
	snprintf(buf, len, "%.3g %s", m, k == -2 && micro_sign ? "\xc2\xb5m" :
	    name[-k]);
}
