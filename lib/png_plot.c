/* SPDX-License-Identifier: GPL-3.0-or-later */
/* png_plot.c - a spectrum as a log-log PNG plot (png_plot.h). */
#include "png_plot.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "colormap.h"
#include "png.h"
#include "png_text.h"

#define WIDTH 800
#define HEIGHT 600
#define SCALE 2			/* font scale */
#define TH (RC_FONT_H * SCALE)	/* text height */
#define GAP 8
#define MARGIN_LEFT (6 * RC_FONT_ADVANCE * SCALE + 2 * GAP)	/* "1e-30" */
#define MARGIN_TOP (2 * TH + 4 * GAP)
#define MARGIN_BOTTOM (2 * TH + 4 * GAP)
#define MARGIN_RIGHT (3 * GAP)
#define MARKER 5		/* point squares, pixels */
#define MAX_LABELS 8		/* per axis */

static const uint8_t ink[3] = { 0, 0, 0 }, white[3] = { 255, 255, 255 };
static const uint8_t fit_rgb[3] = { 214, 39, 40 };

/* The decades around [lo, hi] (log10), at least one. */
static void
decades(double lo, double hi, double *a, double *b)
{
	*a = floor(lo);
	*b = ceil(hi);
	if (*b <= *a)
		*b = *a + 1;
}

/* Point k's q and C. */
static double
at(const rc_spectrum_plot *p, const double *base, size_t k)
{
	size_t stride = p->stride ? p->stride : sizeof(double);

	return *(const double *)(const void *)((const char *)base + k * stride);
}

/* The fit's C at q. */
static double
fit_c(const rc_spectrum_plot *p, double q)
{
	if (q < p->q_r)
		return p->rolloff ? p->c_r : NAN;
	return p->c_r * pow(q / p->q_r, -2 - 2 * p->hurst);
}

int
rc_spectrum_frame(const rc_spectrum_plot *p, rc_plot_frame *f, rc_err *err)
{
	double qlo = INFINITY, qhi = -INFINITY, clo = INFINITY, chi = -INFINITY;

	memset(f, 0, sizeof(*f));
	for (size_t k = 0; k < p->n; k++) {
		double q = at(p, p->q, k), c = at(p, p->c, k);
		if (!(q > 0 && c > 0) || !isfinite(q) || !isfinite(c))
			continue;
		qlo = fmin(qlo, log10(q));
		qhi = fmax(qhi, log10(q));
		clo = fmin(clo, log10(c));
		chi = fmax(chi, log10(c));
	}
	if (!(qlo <= qhi))
		return rc_seterr(err, "no point of the spectrum has q > 0 and C > 0");
	if (p->have_fit && p->fit_q_min > 0 && p->fit_q_max > p->fit_q_min) {
		qlo = fmin(qlo, log10(p->fit_q_min));
		qhi = fmax(qhi, log10(p->fit_q_max));
		/* the line's ends (a power law is monotone; the plateau is C_r) */
		for (int e = 0; e < 2; e++) {
			double c = fit_c(p, e ? p->fit_q_max : p->fit_q_min);
			if (c > 0 && isfinite(c)) {
				clo = fmin(clo, log10(c));
				chi = fmax(chi, log10(c));
			}
		}
	}
	f->width = WIDTH;
	f->height = HEIGHT;
	f->x0 = MARGIN_LEFT;
	f->y0 = MARGIN_TOP;
	f->w = WIDTH - MARGIN_LEFT - MARGIN_RIGHT;
	f->h = HEIGHT - MARGIN_TOP - MARGIN_BOTTOM;
	decades(qlo, qhi, &f->lq_min, &f->lq_max);
	decades(clo, chi, &f->lc_min, &f->lc_max);
	return 0;
}

double
rc_png_plot_x(const rc_plot_frame *f, double q)
{
	return (double)f->x0 + (log10(q) - f->lq_min) / (f->lq_max - f->lq_min) *
	    (double)(f->w - 1);
}

double
rc_png_plot_y(const rc_plot_frame *f, double c)
{
	return (double)f->y0 + (f->lc_max - log10(c)) / (f->lc_max - f->lc_min) *
	    (double)(f->h - 1);
}

/* A filled rectangle, clipped to the image. */
static void
rect(uint8_t *img, const rc_plot_frame *f, long x, long y, long w, long h,
    const uint8_t c[3])
{
	for (long v = y; v < y + h; v++)
		for (long u = x; u < x + w; u++)
			if (u >= 0 && v >= 0 && u < (long)f->width && v < (long)f->height)
				memcpy(img + 3 * ((size_t)v * f->width + (size_t)u), c, 3);
}

static void
text(uint8_t *img, const rc_plot_frame *f, long x, long y, const char *s,
    const uint8_t c[3])
{
	rc_text_draw(img, f->width, f->height, x, y, s, SCALE, c);
}

/* Frame, decade ticks and their labels. */
static void
axes(uint8_t *img, const rc_plot_frame *f)
{
	long x0 = (long)f->x0, y0 = (long)f->y0, w = (long)f->w, h = (long)f->h;
	int nq = (int)(f->lq_max - f->lq_min), nc = (int)(f->lc_max - f->lc_min);
	int sq = (nq + MAX_LABELS - 1) / MAX_LABELS, sc = (nc + MAX_LABELS - 1) / MAX_LABELS;
	char lab[16];

	rect(img, f, x0 - 1, y0 - 1, w + 2, 1, ink);
	rect(img, f, x0 - 1, y0 + h, w + 2, 1, ink);
	rect(img, f, x0 - 1, y0 - 1, 1, h + 2, ink);
	rect(img, f, x0 + w, y0 - 1, 1, h + 2, ink);
	for (int k = 0; k <= nq; k++) {
		long x = lrint(rc_png_plot_x(f, pow(10, f->lq_min + k)));
		int major = k % sq == 0;
		rect(img, f, x, y0 + h - (major ? GAP : GAP / 2), 1,
		    major ? GAP : GAP / 2, ink);
		if (!major)
			continue;
		snprintf(lab, sizeof(lab), "1e%d", (int)(f->lq_min + k));
		text(img, f, x - (long)rc_text_width(lab, SCALE) / 2, y0 + h + GAP, lab,
		    ink);
	}
	for (int k = 0; k <= nc; k++) {
		long y = lrint(rc_png_plot_y(f, pow(10, f->lc_min + k)));
		int major = k % sc == 0;
		rect(img, f, x0, y, major ? GAP : GAP / 2, 1, ink);
		if (!major)
			continue;
		snprintf(lab, sizeof(lab), "1e%d", (int)(f->lc_min + k));
		text(img, f, x0 - GAP - (long)rc_text_width(lab, SCALE), y - TH / 2,
		    lab, ink);
	}
}

/* The fit as a 2-pixel line, column by column, joined vertically; inside
 * the frame only. */
static void
fit_line(uint8_t *img, const rc_plot_frame *f, const rc_spectrum_plot *p)
{
	long xa = lrint(ceil(rc_png_plot_x(f, p->fit_q_min)));
	long xb = lrint(floor(rc_png_plot_x(f, p->fit_q_max)));
	double prev = NAN;
	long top = (long)f->y0, bottom = (long)(f->y0 + f->h - 1);
	char lab[48];

	for (long x = xa; x <= xb; x++) {
		double lq = f->lq_min + ((double)x - (double)f->x0) /
		    (double)(f->w - 1) * (f->lq_max - f->lq_min);
		double y = rc_png_plot_y(f, fit_c(p, pow(10, lq)));
		long ya, yb;
		if (!isfinite(y)) {
			prev = NAN;
			continue;
		}
		ya = lrint(isfinite(prev) ? fmin(prev, y) : y);
		yb = lrint(isfinite(prev) ? fmax(prev, y) : y);
		ya = ya < top ? top : ya;
		yb = yb > bottom - 1 ? bottom - 1 : yb;
		if (ya <= yb)
			rect(img, f, x, ya, 2, yb - ya + 2, fit_rgb);
		prev = y;
	}
	snprintf(lab, sizeof(lab), "fit H = %.3g", p->hurst);
	text(img, f, (long)(f->x0 + f->w) - GAP - (long)rc_text_width(lab, SCALE),
	    (long)f->y0 + GAP, lab, fit_rgb);
}

int
rc_png_spectrum(const rc_spectrum_plot *p, const char *path, rc_plot_frame *fo,
    rc_err *err)
{
	rc_plot_frame f;
	uint8_t *img, point[3];
	char lab[96];
	const char *u = p->unit && p->unit[0] ? p->unit : NULL;
	int rc;

	if (rc_spectrum_frame(p, &f, err) != 0)
		return -1;
	if ((img = rc_malloc(f.width * f.height * 3, err)) == NULL)
		return -1;
	rect(img, &f, 0, 0, (long)f.width, (long)f.height, white);
	rc_colormap_rgb8(0, point);
	if (p->title)
		text(img, &f, (long)f.x0, GAP, p->title, ink);
	if (u)
		snprintf(lab, sizeof(lab), "%s (%s^%d)", p->c_name, u, p->c_power);
	else
		snprintf(lab, sizeof(lab), "%s (length^%d)", p->c_name, p->c_power);
	text(img, &f, (long)f.x0, (long)f.y0 - GAP - TH, lab, ink);
	snprintf(lab, sizeof(lab), "q (1/%s)", u ? u : "length");
	text(img, &f, (long)(f.x0 + f.w / 2) - (long)rc_text_width(lab, SCALE) / 2,
	    (long)(f.y0 + f.h) + 2 * GAP + TH, lab, ink);
	axes(img, &f);
	for (size_t k = 0; k < p->n; k++) {
		double q = at(p, p->q, k), c = at(p, p->c, k);
		if (!(q > 0 && c > 0) || !isfinite(q) || !isfinite(c))
			continue;
		rect(img, &f, lrint(rc_png_plot_x(&f, q)) - MARKER / 2,
		    lrint(rc_png_plot_y(&f, c)) - MARKER / 2, MARKER, MARKER, point);
	}
	if (p->have_fit && p->fit_q_max > p->fit_q_min && p->fit_q_min > 0)
		fit_line(img, &f, p);
	rc = rc_png_encode(img, f.width, f.height, path, err);
	free(img);
	if (fo != NULL)
		*fo = f;
	return rc;
}
