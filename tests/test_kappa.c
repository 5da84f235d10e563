/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_kappa.c - erf inversion round trips and the documented limits. */
#include <math.h>

#include "kappa.h"
#include "testlib.h"

int
main(void)
{
	double worst = 0;

	/* Round trip over the range: kappa in [0.5, 5], p* in [1e-4, 1].
	 * erf is evaluated by libm to ~1 ulp; the inverse then loses at most
	 * |d erfinv/dy| * ulp(y), which near a_r -> 1 is large, so compare in
	 * the variable that keeps its digits: kappa itself, relative 1e-9
	 * where a_r < 1 - 1e-6, and skip a_r rounding to exactly 1. */
	for (double kappa = 0.5; kappa <= 5.0001; kappa += 0.25)
		for (double lp = -4; lp <= 0.0001; lp += 0.25) {
			double p = pow(10, lp), a = erf(sqrt(M_PI) * kappa * p / 2);
			if (a > 1 - 1e-6)
				continue;
			double back = rc_kappa(a, p);
			worst = fmax(worst, fabs(back - kappa) / kappa);
		}
	test_abs(worst, 0, 1e-9, "kappa round trip over kappa in [0.5,5], p* in [1e-4,1]");
	/* Near full contact the tail form keeps the digits: erfc is exact there. */
	test_rel(rc_erfinv(1 - erfc(3.0)), 3.0, 1e-9, "erfinv near 1 via the tail");
	test_rel(rc_erfinv(erf(1e-8)), 1e-8, 1e-12, "erfinv near 0");
	test_rel(rc_erfinv(-erf(0.3)), -0.3, 1e-14, "erfinv is odd");
	test_abs(rc_kappa(0, 0.1), 0, 0, "a_r = 0 gives kappa = 0");
	test_true(isinf(rc_kappa(1, 0.1)), "a_r = 1 gives kappa = +inf");
	test_true(isnan(rc_kappa(1.5, 0.1)) && isnan(rc_kappa(0.1, 0)) &&
	    isnan(rc_kappa(-0.1, 0.1)), "illegal inputs give NaN");
	/* Persson's kappa = sqrt(8/pi) is Eq. 6 written as Eq. 24. */
	double p = 0.05, a = erf(sqrt(2.0) * p);
	test_rel(rc_kappa(a, p), sqrt(8 / M_PI), 1e-13, "Eq. 6 gives Persson's sqrt(8/pi)");
	return test_summary();
}
