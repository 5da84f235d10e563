/* SPDX-License-Identifier: GPL-3.0-or-later */
/* png_plot.h - a spectrum as a log-log PNG plot (surfstat --psd --png,
 * --fit --png).
 *
 * 800 x 600 pixels, text at font scale 2 (png_text.h): a title; the
 * frame with ticks at powers of ten (every step-th decade, at most 8
 * labels per axis, labelled 1eK); the axis names with their units,
 * "q (1/unit)" under the frame and "C(q) (unit^4)" (a 1D spectrum:
 * unit^3) above it; the points as 5-pixel squares in the colormap's
 * first colour; the fit, when given, as a 2-pixel red line over its q
 * range (C_r (q/q_r)^(-2-2H) above q_r; C_r below it with a roll-off)
 * with "fit H = ..." in red at the frame's top right.  The axes span
 * the decades around the points with C > 0 (and the fit's range).
 * A point at (q, C) is drawn centred on pixel (rc_png_plot_x(f, q),
 * rc_png_plot_y(f, C)), rounded.
 */
#ifndef RC_PNG_PLOT_H
#define RC_PNG_PLOT_H

#include <stddef.h>
#include "rc_err.h"

typedef struct rc_spectrum_plot {
	const double *q, *c;	/* n points; those with q, C <= 0 are left out */
	size_t n;
	size_t stride;		/* bytes from one point's q (c) to the next's;
				 * 0: sizeof(double) (arrays of structs can be
				 * passed as &a[0].q, &a[0].c, sizeof(a[0])) */
	const char *unit;	/* length unit ("" none: "1/length") */
	int c_power;		/* 4: C(q) of a map, 3: a profile's C1D */
	const char *c_name;	/* "C(q)" or "C1D(q)" */
	const char *title;
	int have_fit;		/* draw the fit below */
	double c_r, hurst, q_r, fit_q_min, fit_q_max;
	int rolloff;
} rc_spectrum_plot;

/* Where the frame lies and what it spans (log10 of q and C). */
typedef struct rc_plot_frame {
	size_t width, height;	/* the image */
	size_t x0, y0, w, h;	/* the frame's inside: x0 .. x0 + w - 1 */
	double lq_min, lq_max, lc_min, lc_max;
} rc_plot_frame;

/* -1 (err set) if no point has q, C > 0. */
int rc_spectrum_frame(const rc_spectrum_plot *p, rc_plot_frame *f, rc_err *err);
double rc_png_plot_x(const rc_plot_frame *f, double q);
double rc_png_plot_y(const rc_plot_frame *f, double c);
/* Written atomically; the frame used goes into *f if f is not NULL. */
int rc_png_spectrum(const rc_spectrum_plot *p, const char *path,
    rc_plot_frame *f, rc_err *err);

#endif
