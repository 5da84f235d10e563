/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_interaction.c - the pointwise rules of the pressure methods'
 * interactions (lib/solver/interaction.h), written once in the cap H:
 * the active-set test against its definition (three cases) for every
 * sign, zero, infinity and NaN of sigma and g; and with H = +inf, the
 * hard wall, each rule against the wall's own (sigma > 0 or g < 0;
 * sigma clipped at 0 alone; h on contact, max(v, h) off it) for every
 * finite sigma, which is what lets one CG loop serve both. */
#include <math.h>
#include <stdio.h>

#include "interaction.h"
#include "testlib.h"

/* The definition: free, or the force -g pointing into the box. */
static int
active_def(double sigma, double g, double H)
{
	return (sigma > 0 && sigma < H) || (sigma <= 0 && g < 0) ||
	    (sigma >= H && g > 0);
}

int
main(void)
{
	const double sig[] = { -1, -0.0, 0, 0.25, 1, 2, HUGE_VAL, -HUGE_VAL,
	    NAN };
	const double gap[] = { -1, -0.0, 0, 1, HUGE_VAL, -HUGE_VAL, NAN };
	const double caps[] = { 1, HUGE_VAL };
	size_t i, j, m, ns = sizeof(sig) / sizeof(sig[0]);
	size_t ng = sizeof(gap) / sizeof(gap[0]);
	int bad = 0, bad_wall = 0, bad_proj = 0, bad_adm = 0;

	for (m = 0; m < 2; m++)
		for (i = 0; i < ns; i++)
			for (j = 0; j < ng; j++)
				if (rc__active(sig[i], gap[j], caps[m]) !=
				    active_def(sig[i], gap[j], caps[m])) {
					bad++;
					printf("# active(%g, %g, %g)\n", sig[i],
					    gap[j], caps[m]);
				}
	test_int(bad, 0, "rc__active is its definition for all %zu cases",
	    2 * ns * ng);
	for (i = 0; i < ns; i++) {
		double s = sig[i], h = 0.5, v = 0.25 * s;

		if (!isfinite(s))
			continue;
		for (j = 0; j < ng; j++)
			bad_wall += rc__active(s, gap[j], HUGE_VAL) !=
			    (s > 0 || gap[j] < 0);
		bad_proj += rc__project(s, HUGE_VAL) != (s < 0 ? 0 : s);
		bad_adm += rc__admissible(v, h, s, HUGE_VAL) !=
		    (s > 0 ? h : (v > h ? v : h));
		bad_adm += rc__admissible(v + 1, h, s, HUGE_VAL) !=
		    (s > 0 ? h : (v + 1 > h ? v + 1 : h));
	}
	test_int(bad_wall, 0, "H = inf: the active set is the wall's, "
	    "sigma > 0 or g < 0");
	test_int(bad_proj, 0, "H = inf: the projection clips at 0 alone");
	test_int(bad_adm, 0, "H = inf: u' = h on contact, max(v, h) off it");
	/* the cap: u' = min(v, h) at H, the projection onto [0, H] */
	test_abs(rc__admissible(2, 1, 1, 1), 1, 0, "at H: min(v, h), v above");
	test_abs(rc__admissible(0.5, 1, 1, 1), 0.5, 0, "at H: min(v, h), "
	    "v below (flattened)");
	test_abs(rc__project(1.5, 1), 1, 0, "projection onto [0, H]: above");
	test_abs(rc__project(-0.5, 1), 0, 0, "projection onto [0, H]: below");
	test_abs(rc__project(0.75, 1), 0.75, 0, "projection onto [0, H]: "
	    "inside");
	return test_summary();
}
