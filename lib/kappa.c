/* SPDX-License-Identifier: GPL-3.0-or-later */
/* kappa.c - erf inversion through GSL's normal quantiles. */
#include "kappa.h"

#include <gsl/gsl_cdf.h>
#include <math.h>

double
rc_erfinv(double y)
{
	if (!(y >= -1 && y <= 1))
		return NAN;
	if (y < 0)
		return -rc_erfinv(-y);
	if (y == 1)
		return INFINITY;
	/* erf(x) = 2 Phi(x sqrt2) - 1, so erfinv(y) = Phi^-1((1+y)/2)/sqrt2;
	 * near y = 1 use the tail, Q^-1((1-y)/2), which keeps the digits of 1-y. */
	double x, tail = 1 - y;		/* exact for y > 1/2 (Sterbenz) */
	if (y <= 0.5)
		x = gsl_cdf_ugaussian_Pinv(0.5 * (1 + y)) / M_SQRT2;
	else
		x = gsl_cdf_ugaussian_Qinv(0.5 * tail) / M_SQRT2;
	/* The quantiles lose digits for tiny y (0.5 + y/2 rounds); two Newton
	 * steps on erf, or on erfc in the tail, restore full precision. */
	for (int k = 0; k < 2 && x > 0; k++) {
		double slope = 2 / sqrt(M_PI) * exp(-x * x);
		if (y <= 0.5)
			x -= (erf(x) - y) / slope;
		else
			x += (erfc(x) - tail) / slope;
	}
	return x;
}

double
rc_kappa(double a_r, double p_star)
{
	if (!(p_star > 0) || !(a_r >= 0 && a_r <= 1))
		return NAN;
	return 2 * rc_erfinv(a_r) / (sqrt(M_PI) * p_star);
}
