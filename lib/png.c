/* SPDX-License-Identifier: GPL-3.0-or-later */
/* png.c - 8-bit RGB previews of grids on libpng (see png.h).
 *
 * The image has square pixels: a grid of spacing dx by dy is resampled to
 * pixels of size min(dx, dy), then scaled down so the longer side is at
 * most max_size.  Resampling is an area-weighted box average of the grid
 * values (of the overlay mask too), so downsampling averages blocks and
 * upsampling repeats values.  A line (nx x 1 or 1 x ny) becomes a strip.
 * Rows are drawn as stored: grid row j = 0 is the top of the image.
 * Annotations (colour bar, labels, scale bar, caption) are laid out around
 * the map on a white canvas; see png.h.
 */
#include "png.h"

#include <math.h>
/* libpng by its versioned path: our own png.h shadows <png.h> under -Ilib
 * (libpng 1.6 installs its headers in include/libpng16 everywhere). */
#include <libpng16/png.h>
#include <setjmp.h>
#include <stdio.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_statistics_double.h>

#include "atomic.h"
#include "colormap.h"
#include "png_text.h"
#include "si.h"
#include "units.h"

#define DEFAULT_MAX_SIZE 1024
#define STRIP_MIN 16		/* least thickness of a line's strip */
#define BIG_TEXT_FROM 256	/* map side from which text is drawn at scale 2 */
#define LABEL_DIGITS 3		/* significant digits of the range labels */
#define DEFAULT_CLIP 0.005	/* share clipped at each end of the range */

static const uint8_t canvas_rgb[3] = { 255, 255, 255 };
static const uint8_t ink_rgb[3] = { 0, 0, 0 };

void
rc_png_defaults(rc_png_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->style = RC_PNG_AUTO;
	o->max_size = DEFAULT_MAX_SIZE;
	o->overlay = NULL;
	o->annotate = 1;
	o->caption = NULL;
	o->clip = DEFAULT_CLIP;
}

void
rc_png_size(size_t nx, size_t ny, double lx, double ly, size_t max_size,
    size_t *width, size_t *height)
{
	double w, h, pixel, s;

	if (max_size == 0)
		max_size = DEFAULT_MAX_SIZE;
	if (ny == 1 && nx > 1) {
		w = fmin((double)nx, (double)max_size);
		h = fmin(fmax(STRIP_MIN, floor(w / 16)), (double)max_size);
	} else if (nx == 1 && ny > 1) {
		h = fmin((double)ny, (double)max_size);
		w = fmin(fmax(STRIP_MIN, floor(h / 16)), (double)max_size);
	} else {
		pixel = fmin(lx / (double)nx, ly / (double)ny);
		w = lx / pixel;
		h = ly / pixel;
		s = fmax(w, h) > (double)max_size ? (double)max_size / fmax(w, h) : 1;
		w = fmax(1, nearbyint(w * s));
		h = fmax(1, nearbyint(h * s));
	}
	*width = (size_t)w;
	*height = (size_t)h;
}

/* Box weights of pixel u over the cells of an n-cell axis resampled to m
 * pixels: cells first[u] .. first[u] + count[u] - 1, weights in w (each
 * pixel's weights sum to 1). */
struct axis {
	size_t *first, *count, *offset;
	double *w;
};

static void
axis_free(struct axis *a)
{
	free(a->first);
	free(a->count);
	free(a->offset);
	free(a->w);
}

static int
axis_init(struct axis *a, size_t n, size_t m, rc_err *err)
{
	double step = (double)n / (double)m;
	size_t total = 0;

	memset(a, 0, sizeof(*a));
	a->first = rc_calloc(m, sizeof(size_t), err);
	a->count = rc_calloc(m, sizeof(size_t), err);
	a->offset = rc_calloc(m, sizeof(size_t), err);
	/* Each pixel touches at most ceil(step) + 1 cells. */
	a->w = rc_calloc(m * ((size_t)ceil(step) + 2), sizeof(double), err);
	if (!a->first || !a->count || !a->offset || !a->w) {
		axis_free(a);
		return -1;
	}
	for (size_t u = 0; u < m; u++) {
		double x0 = (double)u * step, x1 = (double)(u + 1) * step;
		size_t i0 = (size_t)floor(x0), c = 0;

		if (u + 1 == m)
			x1 = (double)n;
		a->first[u] = i0;
		a->offset[u] = total;
		for (size_t i = i0; i < n && (double)i < x1; i++) {
			double lo = fmax(x0, (double)i), hi = fmin(x1, (double)i + 1);
			if (hi > lo) {
				a->w[total + c] = (hi - lo) / (x1 - x0);
				c++;
			} else if (c == 0)
				a->first[u] = i + 1;
		}
		a->count[u] = c;
		total += c;
	}
	return 0;
}

/* Resample z (nx by ny) to out (width by height). */
static void
resample(const double *z, size_t nx, const struct axis *ax, size_t width,
    const struct axis *ay, size_t height, double *line, double *out)
{
	for (size_t v = 0; v < height; v++) {
		memset(line, 0, nx * sizeof(double));
		for (size_t c = 0; c < ay->count[v]; c++) {
			const double *row = z + (ay->first[v] + c) * nx;
			double w = ay->w[ay->offset[v] + c];
			for (size_t i = 0; i < nx; i++)
				line[i] += w * row[i];
		}
		for (size_t u = 0; u < width; u++) {
			double s = 0;
			for (size_t c = 0; c < ax->count[u]; c++)
				s += ax->w[ax->offset[u] + c] * line[ax->first[u] + c];
			out[v * width + u] = s;
		}
	}
}

struct png_ctx {
	rc_err *err;
	jmp_buf jmp;
};

static void
png_error_fn(png_structp png, png_const_charp msg)
{
	struct png_ctx *ctx = png_get_error_ptr(png);

	rc_seterr(ctx->err, "PNG: %s", msg);
	longjmp(ctx->jmp, 1);
}

static void
png_warning_fn(png_structp png, png_const_charp msg)
{
	(void)png;
	(void)msg;
}

static int
encode(const uint8_t *rgb, size_t width, size_t height, const char *path,
    rc_err *err)
{
	rc_atomic out;
	struct png_ctx ctx;
	png_structp png = NULL;
	png_infop info = NULL;

	if (rc_atomic_open(&out, path, err) != 0)
		return -1;
	ctx.err = err;
	png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, png_error_fn,
	    png_warning_fn);
	if (png == NULL || (info = png_create_info_struct(png)) == NULL) {
		png_destroy_write_struct(&png, NULL);
		rc_atomic_abort(&out);
		return rc_seterr(err, "PNG: out of memory");
	}
	if (setjmp(ctx.jmp)) {
		png_destroy_write_struct(&png, &info);
		rc_atomic_abort(&out);
		return -1;
	}
	png_init_io(png, out.fp);
	png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8,
	    PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
	    PNG_FILTER_TYPE_DEFAULT);
	png_write_info(png, info);
	for (size_t v = 0; v < height; v++)
		png_write_row(png, (png_const_bytep)(rgb + v * width * 3));
	png_write_end(png, NULL);
	png_destroy_write_struct(&png, &info);
	return rc_atomic_commit(&out, err);
}

int
rc_png_encode(const uint8_t *rgb, size_t width, size_t height, const char *path,
    rc_err *err)
{
	return encode(rgb, width, height, path, err);
}

static void
put(uint8_t *px, const uint8_t c[3])
{
	px[0] = c[0];
	px[1] = c[1];
	px[2] = c[2];
}

/* qsort's order of doubles (glibc's merge sort: 0.85 s of CPU for
 * 2048^2 random doubles against gsl_sort's heap sort, 1.57 s; measured
 * under load, -O2). */
static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* The colour range: the clip and 1 - clip quantiles of the finite values
 * (of log10 of the positive ones on a log scale), min and max if they
 * coincide; lo > hi if there are none.  *clipped: the share of the values
 * outside [lo, hi]. */
static int
value_range(const rc_grid *g, enum rc_png_style style, double clip,
    double *lo, double *hi, double *clipped, rc_err *err)
{
	size_t n = rc_grid_size(g), m = 0, out = 0;
	double *v;

	*lo = INFINITY;
	*hi = -INFINITY;
	*clipped = 0;
	if ((v = rc_malloc((n ? n : 1) * sizeof(double), err)) == NULL)
		return -1;
	for (size_t k = 0; k < n; k++) {
		double z = g->z[k];
		if (!isfinite(z) || (style == RC_PNG_LOG && !(z > 0)))
			continue;
		v[m++] = style == RC_PNG_LOG ? log10(z) : z;
	}
	if (m > 0) {
		qsort(v, m, sizeof(double), cmp_double);
		*lo = v[0];
		*hi = v[m - 1];
		if (clip > 0 && style != RC_PNG_MASK) {
			double a = gsl_stats_quantile_from_sorted_data(v, 1, m, clip);
			double b = gsl_stats_quantile_from_sorted_data(v, 1, m,
			    1 - clip);
			if (a < b) {
				*lo = a;
				*hi = b;
			}
			for (size_t k = 0; k < m; k++)
				out += v[k] < *lo || v[k] > *hi;
			*clipped = (double)out / (double)m;
		}
	}
	free(v);
	return 0;
}

static void
colormap_table(uint8_t table[256][3])
{
	for (int k = 0; k < 256; k++)
		rc_colormap_rgb8(k / 255.0, table[k]);
}

/* Colour the resampled values over the range [lo, hi] of the whole grid. */
static void
colour(enum rc_png_style style, double lo, double hi, const double *val,
    size_t npix, uint8_t *rgb)
{
	static const uint8_t mask0[3] = RC_MASK0_RGB, mask1[3] = RC_MASK1_RGB;
	static const uint8_t nonpos[3] = RC_NONPOS_RGB, nan_rgb[3] = RC_NAN_RGB;
	uint8_t table[256][3];

	colormap_table(table);
	for (size_t p = 0; p < npix; p++) {
		double v = val[p], t;
		uint8_t *px = rgb + 3 * p;

		if (!isfinite(v)) {
			put(px, nan_rgb);
			continue;
		}
		if (style == RC_PNG_MASK) {
			t = fmin(1, fmax(0, v));
			for (int c = 0; c < 3; c++)
				px[c] = (uint8_t)lrint((1 - t) * mask0[c] + t * mask1[c]);
			continue;
		}
		if (style == RC_PNG_LOG) {
			if (!(v > 0)) {
				put(px, nonpos);
				continue;
			}
			v = log10(v);
		}
		t = hi > lo ? (v - lo) / (hi - lo) : 0.5;
		t = fmin(1, fmax(0, t));
		put(px, table[lrint(255 * t)]);
	}
}

static void
draw_overlay(const double *frac, size_t npix, uint8_t *rgb)
{
	static const uint8_t over[3] = RC_OVERLAY_RGB;

	for (size_t p = 0; p < npix; p++) {
		double a = RC_OVERLAY_ALPHA * fmin(1, fmax(0, frac[p]));
		if (!(a > 0))
			continue;
		for (int c = 0; c < 3; c++)
			rgb[3 * p + c] = (uint8_t)lrint((1 - a) * rgb[3 * p + c] +
			    a * over[c]);
	}
}

static enum rc_png_style
resolve_style(const rc_grid *g, enum rc_png_style style)
{
	if (style != RC_PNG_AUTO)
		return style;
	return g->kind == RC_KIND_PRESSURE ? RC_PNG_LOG :
	    g->kind == RC_KIND_MASK ? RC_PNG_MASK : RC_PNG_LINEAR;
}

/* The unit of the values: z_unit, else the lateral unit for lengths. */
static const char *
value_unit(const rc_grid *g)
{
	if (g->z_unit[0] != '\0')
		return g->z_unit;
	if (g->kind == RC_KIND_HEIGHT || g->kind == RC_KIND_GAP ||
	    g->kind == RC_KIND_DISPLACEMENT)
		return g->unit;
	return "";
}

/* What the annotations say: the range labels (top, bottom, middle) and
 * the scale bar's length in pixels and its label. */
struct labels {
	char top[64], bottom[64], middle[32], scale[64], clipped[32];
	int bar;		/* a colour bar is drawn */
	size_t scale_px;	/* 0: no scale bar */
	double lo, hi;		/* the colour range (log10 on a log scale) */
};

static void
range_label(char *buf, size_t len, double v, const char *unit)
{
	if (rc_unit_is_length(unit))
		rc_si_length(buf, len, v, unit, 1);
	else
		snprintf(buf, len, "%.*g%s%s", LABEL_DIGITS, v, unit[0] ? " " : "",
		    unit);
}

static int
make_labels(const rc_grid *g, enum rc_png_style style, double clip,
    size_t map_w, struct labels *lb, rc_err *err)
{
	double lo, hi, clipped;

	memset(lb, 0, sizeof(*lb));
	if (value_range(g, style, clip, &lo, &hi, &clipped, err) != 0)
		return -1;
	lb->lo = lo;
	lb->hi = hi;
	lb->bar = style != RC_PNG_MASK && lo <= hi;
	if (lb->bar) {
		const char *unit = value_unit(g);
		snprintf(lb->middle, sizeof(lb->middle), "%s%s",
		    rc_kind_name(g->kind), style == RC_PNG_LOG ? " log" : "");
		if (style == RC_PNG_LOG) {
			lo = pow(10, lo);
			hi = pow(10, hi);
		}
		range_label(lb->top, sizeof(lb->top), hi, unit);
		range_label(lb->bottom, sizeof(lb->bottom), lo, unit);
		if (clipped > 0)
			snprintf(lb->clipped, sizeof(lb->clipped), "%.2g%% clipped",
			    100 * clipped);
	}
	/* A round length of at most a quarter of lx, along x. */
	if (g->nx > 1 && g->lx > 0 && isfinite(g->lx)) {
		double target = g->lx / 4, p10 = pow(10, floor(log10(target)));
		double m = target / p10, len;

		len = (m >= 5 ? 5 : m >= 2 ? 2 : 1) * p10;
		lb->scale_px = (size_t)fmax(1, nearbyint(len / g->lx * (double)map_w));
		range_label(lb->scale, sizeof(lb->scale), len, g->unit);
	}
	return 0;
}

static size_t
max_sz(size_t a, size_t b)
{
	return a > b ? a : b;
}

/* The layout for a map of map_w x map_h pixels with these labels. */
static void
layout(const rc_png_opts *o, size_t map_w, size_t map_h,
    const struct labels *lb, rc_png_layout *l)
{
	int s = max_sz(map_w, map_h) >= BIG_TEXT_FROM ? 2 : 1;
	size_t m = 4 * (size_t)s, gap = 4 * (size_t)s, th = RC_FONT_H * (size_t)s;
	size_t right, y;

	memset(l, 0, sizeof(*l));
	l->map_w = map_w;
	l->map_h = map_h;
	l->scale = s;
	if (!o->annotate) {
		l->width = map_w;
		l->height = map_h;
		return;
	}
	l->map_x = m;
	l->map_y = m;
	right = m + map_w;
	y = m + map_h;
	if (lb->bar) {
		l->bar_x = m + map_w + 2 * gap;
		l->bar_y = m;
		l->bar_w = 8 * (size_t)s;
		/* Room for the top, middle and bottom labels. */
		l->bar_h = max_sz(map_h, 3 * th + 2 * gap);
		right = l->bar_x + l->bar_w + gap +
		    max_sz(rc_text_width(lb->top, s), max_sz(rc_text_width(lb->bottom, s),
		    rc_text_width(lb->middle, s)));
		y = max_sz(y, m + l->bar_h);
	}
	if (lb->scale_px) {
		y += 2 * gap;
		right = max_sz(right, m + lb->scale_px + gap + rc_text_width(lb->scale, s));
		y += th;
	}
	if (lb->clipped[0]) {
		y += 2 * gap;
		right = max_sz(right, m + rc_text_width(lb->clipped, s));
		y += th;
	}
	if ((o->caption && o->caption[0]) || o->overlay) {
		size_t w = o->caption ? rc_text_width(o->caption, s) : 0;
		if (o->overlay)
			w += (w ? 2 * gap : 0) + th + gap + rc_text_width("contact", s);
		y += 2 * gap;
		right = max_sz(right, m + w);
		y += th;
	}
	l->width = right + m;
	l->height = y + m;
}

void
rc_png_layout_of(const rc_grid *g, const rc_png_opts *o, rc_png_layout *l)
{
	rc_png_opts def;
	struct labels lb;
	size_t w, h;
	rc_err err;

	if (o == NULL) {
		rc_png_defaults(&def);
		o = &def;
	}
	rc_png_size(g->nx, g->ny, g->lx, g->ly, o->max_size, &w, &h);
	if (make_labels(g, resolve_style(g, o->style), o->clip, w, &lb, &err) != 0)
		memset(&lb, 0, sizeof(lb));	/* out of memory: no labels */
	layout(o, w, h, &lb, l);
}

static void
fill(uint8_t *img, size_t width, size_t x, size_t y, size_t w, size_t h,
    const uint8_t c[3])
{
	for (size_t v = y; v < y + h; v++)
		for (size_t u = x; u < x + w; u++)
			memcpy(img + 3 * (v * width + u), c, 3);
}

/* Colour bar, its labels, the scale bar and the caption. */
static void
draw_annotations(uint8_t *img, const rc_png_layout *l, const rc_png_opts *o,
    const struct labels *lb)
{
	static const uint8_t over[3] = RC_OVERLAY_RGB;
	int s = l->scale;
	size_t gap = 4 * (size_t)s, th = RC_FONT_H * (size_t)s, y;
	uint8_t table[256][3];

	y = l->map_y + l->map_h;
	if (lb->bar) {
		long lx = (long)(l->bar_x + l->bar_w + gap);
		colormap_table(table);
		for (size_t v = 0; v < l->bar_h; v++) {
			double t = l->bar_h > 1 ? 1 - (double)v / (double)(l->bar_h - 1) : 1;
			fill(img, l->width, l->bar_x, l->bar_y + v, l->bar_w, 1,
			    table[lrint(255 * t)]);
		}
		rc_text_draw(img, l->width, l->height, lx, (long)l->bar_y, lb->top, s,
		    ink_rgb);
		rc_text_draw(img, l->width, l->height, lx,
		    (long)(l->bar_y + l->bar_h - th), lb->bottom, s, ink_rgb);
		rc_text_draw(img, l->width, l->height, lx,
		    (long)(l->bar_y + (l->bar_h - th) / 2), lb->middle, s, ink_rgb);
		y = max_sz(y, l->bar_y + l->bar_h);
	}
	if (lb->scale_px) {
		size_t x = l->map_x, thick = 2 * (size_t)s;
		y += 2 * gap;
		/* A bar with end ticks, as tall as the text beside it. */
		fill(img, l->width, x, y + (th - thick) / 2, lb->scale_px, thick, ink_rgb);
		fill(img, l->width, x, y, (size_t)s, th, ink_rgb);
		fill(img, l->width, x + lb->scale_px - (size_t)s, y, (size_t)s, th,
		    ink_rgb);
		rc_text_draw(img, l->width, l->height, (long)(x + lb->scale_px + gap),
		    (long)y, lb->scale, s, ink_rgb);
		y += th;
	}
	if (lb->clipped[0]) {
		y += 2 * gap;
		rc_text_draw(img, l->width, l->height, (long)l->map_x, (long)y,
		    lb->clipped, s, ink_rgb);
		y += th;
	}
	if ((o->caption && o->caption[0]) || o->overlay) {
		size_t x = l->map_x;
		y += 2 * gap;
		if (o->caption && o->caption[0]) {
			rc_text_draw(img, l->width, l->height, (long)x, (long)y, o->caption,
			    s, ink_rgb);
			x += rc_text_width(o->caption, s) + 2 * gap;
		}
		if (o->overlay) {
			fill(img, l->width, x, y, th, th, over);
			rc_text_draw(img, l->width, l->height, (long)(x + th + gap), (long)y,
			    "contact", s, ink_rgb);
		}
	}
}

int
rc_png_write(const rc_grid *g, const char *path, const rc_png_opts *o,
    rc_err *err)
{
	rc_png_opts def;
	enum rc_png_style style;
	struct axis ax, ay;
	struct labels lb;
	rc_png_layout l;
	size_t width, height, npix;
	double *val = NULL, *line = NULL;
	uint8_t *rgb = NULL, *img = NULL;
	int status = -1;

	if (o == NULL) {
		rc_png_defaults(&def);
		o = &def;
	}
	style = resolve_style(g, o->style);
	if (o->overlay != NULL && (o->overlay->nx != g->nx || o->overlay->ny != g->ny))
		return rc_seterr(err, "overlay mask is %zux%zu, the map %zux%zu",
		    o->overlay->nx, o->overlay->ny, g->nx, g->ny);
	rc_png_size(g->nx, g->ny, g->lx, g->ly, o->max_size, &width, &height);
	if (make_labels(g, style, o->clip, width, &lb, err) != 0)
		return -1;
	layout(o, width, height, &lb, &l);
	if (l.width > PNG_UINT_31_MAX || l.height > PNG_UINT_31_MAX)
		return rc_seterr(err, "PNG of %zux%zu pixels is too large", l.width,
		    l.height);
	npix = width * height;
	if (axis_init(&ax, g->nx, width, err) != 0)
		return -1;
	if (axis_init(&ay, g->ny, height, err) != 0) {
		axis_free(&ax);
		return -1;
	}
	if ((val = rc_malloc(npix * sizeof(double), err)) == NULL ||
	    (line = rc_malloc(g->nx * sizeof(double), err)) == NULL ||
	    (rgb = rc_malloc(npix * 3, err)) == NULL)
		goto done;
	resample(g->z, g->nx, &ax, width, &ay, height, line, val);
	colour(style, lb.lo, lb.hi, val, npix, rgb);
	if (o->overlay != NULL) {
		resample(o->overlay->z, g->nx, &ax, width, &ay, height, line, val);
		draw_overlay(val, npix, rgb);
	}
	if (!o->annotate) {
		status = encode(rgb, width, height, path, err);
		goto done;
	}
	if ((img = rc_malloc(l.width * l.height * 3, err)) == NULL)
		goto done;
	fill(img, l.width, 0, 0, l.width, l.height, canvas_rgb);
	for (size_t v = 0; v < height; v++)
		memcpy(img + 3 * ((l.map_y + v) * l.width + l.map_x),
		    rgb + 3 * v * width, 3 * width);
	draw_annotations(img, &l, o, &lb);
	status = encode(img, l.width, l.height, path, err);
done:
	free(val);
	free(line);
	free(rgb);
	free(img);
	axis_free(&ax);
	axis_free(&ay);
	return status;
}
