/* SPDX-License-Identifier: GPL-3.0-or-later */
/* colormap.c - CIELAB lightness ramp converted to sRGB (see colormap.h). */
#include "colormap.h"

#include <math.h>

/* D65 reference white, CIE 1931 2-degree observer. */
static const double white[3] = { 0.95047, 1.0, 1.08883 };

/* IEC 61966-2-1 transfer function and its inverse. */
static double
encode(double c)
{
	return c <= 0.0031308 ? 12.92 * c : 1.055 * pow(c, 1 / 2.4) - 0.055;
}

static double
decode(double c)
{
	return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4);
}

static double
lab_f_inv(double t)
{
	const double d = 6.0 / 29;

	return t > d ? t * t * t : 3 * d * d * (t - 4.0 / 29);
}

static double
lab_f(double t)
{
	const double d = 6.0 / 29;

	return t > d * d * d ? cbrt(t) : t / (3 * d * d) + 4.0 / 29;
}

/* Linear sRGB of L*, C*, h (degrees). */
static void
lch_to_linear(double l, double c, double h, double rgb[3])
{
	double a = c * cos(h * M_PI / 180), b = c * sin(h * M_PI / 180);
	double fy = (l + 16) / 116, fx = fy + a / 500, fz = fy - b / 200;
	double x = white[0] * lab_f_inv(fx), y = white[1] * lab_f_inv(fy);
	double z = white[2] * lab_f_inv(fz);

	rgb[0] = 3.2404542 * x - 1.5371385 * y - 0.4985314 * z;
	rgb[1] = -0.9692660 * x + 1.8760108 * y + 0.0415560 * z;
	rgb[2] = 0.0556434 * x - 0.2040259 * y + 1.0572252 * z;
}

static int
in_gamut(const double rgb[3])
{
	return rgb[0] >= 0 && rgb[0] <= 1 && rgb[1] >= 0 && rgb[1] <= 1 &&
	    rgb[2] >= 0 && rgb[2] <= 1;
}

void
rc_colormap_srgb(double t, double rgb[3])
{
	double l, c, h, lo, hi, lin[3];

	if (!(t >= 0))
		t = 0;
	if (t > 1)
		t = 1;
	l = 18 + 74 * t;
	h = 290 - 190 * t;
	c = 38 + 40 * t * t;
	lch_to_linear(l, c, h, lin);
	if (!in_gamut(lin)) {
		/* Largest in-gamut chroma at this lightness and hue; the
		 * grey axis (c = 0) is always inside. */
		lo = 0;
		hi = c;
		for (int k = 0; k < 50; k++) {
			double mid = 0.5 * (lo + hi);
			lch_to_linear(l, mid, h, lin);
			if (in_gamut(lin))
				lo = mid;
			else
				hi = mid;
		}
		lch_to_linear(l, lo, h, lin);
	}
	for (int k = 0; k < 3; k++)
		rgb[k] = encode(fmin(1, fmax(0, lin[k])));
}

void
rc_colormap_rgb8(double t, uint8_t rgb[3])
{
	double c[3];

	rc_colormap_srgb(t, c);
	for (int k = 0; k < 3; k++)
		rgb[k] = (uint8_t)lrint(255 * c[k]);
}

void
rc_srgb_to_lab(const double rgb[3], double lab[3])
{
	double r = decode(rgb[0]), g = decode(rgb[1]), b = decode(rgb[2]);
	double x = 0.4124564 * r + 0.3575761 * g + 0.1804375 * b;
	double y = 0.2126729 * r + 0.7151522 * g + 0.0721750 * b;
	double z = 0.0193339 * r + 0.1191920 * g + 0.9503041 * b;
	double fx = lab_f(x / white[0]), fy = lab_f(y / white[1]);
	double fz = lab_f(z / white[2]);

	lab[0] = 116 * fy - 16;
	lab[1] = 500 * (fx - fy);
	lab[2] = 200 * (fy - fz);
}
