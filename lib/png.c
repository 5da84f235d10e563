/* png.c - 8-bit RGB previews of grids on libpng (see png.h).
 *
 * The image has square pixels: a grid of spacing dx by dy is resampled to
 * pixels of size min(dx, dy), then scaled down so the longer side is at
 * most max_size.  Resampling is an area-weighted box average of the grid
 * values (of the overlay mask too), so downsampling averages blocks and
 * upsampling repeats values.  A line (nx x 1 or 1 x ny) becomes a strip.
 * Rows are drawn as stored: grid row j = 0 is the top of the image.
 */
#include "png.h"

#include <math.h>
/* libpng by its versioned path: our own png.h shadows <png.h> under -Ilib
 * (libpng 1.6 installs its headers in include/libpng16 everywhere). */
#include <libpng16/png.h>
#include <setjmp.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "colormap.h"

#define DEFAULT_MAX_SIZE 1024
#define STRIP_MIN 16		/* least thickness of a line's strip */

void
rc_png_defaults(rc_png_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->style = RC_PNG_AUTO;
	o->max_size = DEFAULT_MAX_SIZE;
	o->overlay = NULL;
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

static void
put(uint8_t *px, const uint8_t c[3])
{
	px[0] = c[0];
	px[1] = c[1];
	px[2] = c[2];
}

/* Colour the resampled values; the range is that of the whole grid. */
static void
colour(const rc_grid *g, enum rc_png_style style, const double *val,
    size_t npix, uint8_t *rgb)
{
	static const uint8_t mask0[3] = RC_MASK0_RGB, mask1[3] = RC_MASK1_RGB;
	static const uint8_t nonpos[3] = RC_NONPOS_RGB, nan_rgb[3] = RC_NAN_RGB;
	size_t n = rc_grid_size(g);
	double lo = INFINITY, hi = -INFINITY;
	uint8_t table[256][3];

	for (int k = 0; k < 256; k++)
		rc_colormap_rgb8(k / 255.0, table[k]);
	for (size_t k = 0; k < n; k++) {
		double z = g->z[k];
		if (!isfinite(z) || (style == RC_PNG_LOG && !(z > 0)))
			continue;
		if (style == RC_PNG_LOG)
			z = log10(z);
		lo = fmin(lo, z);
		hi = fmax(hi, z);
	}
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

int
rc_png_write(const rc_grid *g, const char *path, const rc_png_opts *o,
    rc_err *err)
{
	rc_png_opts def;
	enum rc_png_style style;
	struct axis ax, ay;
	size_t width, height, npix;
	double *val = NULL, *line = NULL;
	uint8_t *rgb = NULL;
	int status = -1;

	if (o == NULL) {
		rc_png_defaults(&def);
		o = &def;
	}
	style = o->style;
	if (style == RC_PNG_AUTO)
		style = g->kind == RC_KIND_PRESSURE ? RC_PNG_LOG :
		    g->kind == RC_KIND_MASK ? RC_PNG_MASK : RC_PNG_LINEAR;
	if (o->overlay != NULL && (o->overlay->nx != g->nx || o->overlay->ny != g->ny))
		return rc_seterr(err, "overlay mask is %zux%zu, the map %zux%zu",
		    o->overlay->nx, o->overlay->ny, g->nx, g->ny);
	rc_png_size(g->nx, g->ny, g->lx, g->ly, o->max_size, &width, &height);
	if (width > PNG_UINT_31_MAX || height > PNG_UINT_31_MAX)
		return rc_seterr(err, "PNG of %zux%zu pixels is too large", width, height);
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
	colour(g, style, val, npix, rgb);
	if (o->overlay != NULL) {
		resample(o->overlay->z, g->nx, &ax, width, &ay, height, line, val);
		draw_overlay(val, npix, rgb);
	}
	status = encode(rgb, width, height, path, err);
done:
	free(val);
	free(line);
	free(rgb);
	axis_free(&ax);
	axis_free(&ay);
	return status;
}
