/* SPDX-License-Identifier: GPL-3.0-or-later */
/* love.c - Love's pixel compliance (love.h). */
#include "love.h"

#include <math.h>

/* Integral of 1/r over [0, x] x [0, y], odd in x and in y. */
static double
love_h(double x, double y)
{
	double a = fabs(x), b = fabs(y), v;

	if (a == 0 || b == 0)
		return 0;
	v = a * asinh(b / a) + b * asinh(a / b);
	return (x < 0) != (y < 0) ? -v : v;
}

double
rc_love_pixel(double x, double y, double dx, double dy)
{
	double hx = 0.5 * dx, hy = 0.5 * dy;

	return (love_h(x + hx, y + hy) - love_h(x - hx, y + hy) -
	    love_h(x + hx, y - hy) + love_h(x - hx, y - hy)) / M_PI;
}
