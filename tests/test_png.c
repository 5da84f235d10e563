/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_png.c - PNG previews decoded back with libpng: size, aspect,
 * colours of the extremes, mask and overlay colours, log scale,
 * downsampling; the colormap's lightness; the annotations (colour bar,
 * range labels, scale bar, caption) and the bitmap font. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <libpng16/png.h>	/* lib/png.h shadows <png.h> */

#include "colormap.h"
#include "grid.h"
#include "png.h"
#include "png_plot.h"
#include "png_text.h"
#include "si.h"
#include "testlib.h"

struct image {
	size_t width, height;
	uint8_t *rgb;
};

static int
decode(const char *path, struct image *im)
{
	png_image pi;

	memset(&pi, 0, sizeof(pi));
	pi.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_file(&pi, path))
		return -1;
	pi.format = PNG_FORMAT_RGB;
	im->width = pi.width;
	im->height = pi.height;
	im->rgb = malloc(PNG_IMAGE_SIZE(pi));
	if (!png_image_finish_read(&pi, NULL, im->rgb, 0, NULL)) {
		free(im->rgb);
		return -1;
	}
	return 0;
}

static int
same(const uint8_t *px, const uint8_t c[3])
{
	return px[0] == c[0] && px[1] == c[1] && px[2] == c[2];
}

static const uint8_t *
pixel(const struct image *im, size_t u, size_t v)
{
	return im->rgb + 3 * (v * im->width + u);
}

static int
write_png(const rc_grid *g, const char *path, enum rc_png_style style,
    size_t max_size, const rc_grid *overlay)
{
	rc_png_opts o;
	rc_err err;

	rc_png_defaults(&o);
	o.style = style;
	o.max_size = max_size;
	o.overlay = overlay;
	o.annotate = 0;		/* the map alone: its pixels are what is tested */
	o.clip = 0;		/* min to max: the exact mapping is tested */
	if (rc_png_write(g, path, &o, &err) != 0) {
		fprintf(stderr, "rc_png_write: %s\n", err.msg);
		return -1;
	}
	return 0;
}

/* Lightness must rise monotonically: sampled finely in double precision it
 * is the designed ramp L* = 18 + 74 t (checked through the independent
 * inverse conversion sRGB -> CIELAB); the 8-bit table may wobble by the
 * rounding of its channels (< 0.5 in L*) but rises over every 4 entries. */
static void
test_colormap(void)
{
	double rgb[3], lab[3], prev = -1, worst = 0;
	double l8[256];
	int mono = 1, mono8 = 1, wobble = 1;

	for (int k = 0; k <= 1000; k++) {
		rc_colormap_srgb(k / 1000.0, rgb);
		rc_srgb_to_lab(rgb, lab);
		if (lab[0] <= prev)
			mono = 0;
		prev = lab[0];
		worst = fmax(worst, fabs(lab[0] - (18 + 74 * k / 1000.0)));
	}
	test_true(mono, "colormap lightness strictly increasing");
	/* Forward and inverse conversions agree to their coefficients'
	 * precision (7 digits), far below 0.01 in L*. */
	test_abs(worst, 0, 0.01, "colormap lightness is the linear ramp 18..92");
	for (int k = 0; k < 256; k++) {
		uint8_t c[3];
		rc_colormap_rgb8(k / 255.0, c);
		for (int i = 0; i < 3; i++)
			rgb[i] = c[i] / 255.0;
		rc_srgb_to_lab(rgb, lab);
		l8[k] = lab[0];
	}
	for (int k = 1; k < 256; k++) {
		if (l8[k] < l8[k - 1] - 0.5)
			wobble = 0;
		if (k >= 4 && !(l8[k] > l8[k - 4]))
			mono8 = 0;
	}
	test_true(wobble && mono8, "8-bit colormap lightness monotone up to rounding");
	/* Chromatic, not grey: viridis-like ends (blue-violet, yellow). */
	rc_colormap_srgb(0, rgb);
	test_true(rgb[2] > rgb[1] && rgb[2] > rgb[0], "first colour is blue-violet");
	rc_colormap_srgb(1, rgb);
	test_true(rgb[0] > rgb[2] && rgb[1] > rgb[2], "last colour is yellow");
}

static void
test_linear(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(64, 32, 2.0, 1.0, &err);
	struct image im;
	uint8_t first[3], last[3], mid[3];
	const char *path = test_path("h.png");

	for (size_t j = 0; j < 32; j++)
		for (size_t i = 0; i < 64; i++)
			g->z[j * 64 + i] = sin(0.1 * i) * cos(0.2 * j);
	g->z[5 * 64 + 3] = -2;		/* minimum */
	g->z[20 * 64 + 10] = 3;		/* maximum */
	g->z[7 * 64 + 40] = 0.5;	/* the middle of [-2, 3] */
	test_true(write_png(g, path, RC_PNG_AUTO, 0, NULL) == 0, "write height PNG");
	test_true(decode(path, &im) == 0, "libpng decodes it");
	test_int((long long)im.width, 64, "width = nx (dx = dy)");
	test_int((long long)im.height, 32, "height = ny");
	rc_colormap_rgb8(0, first);
	rc_colormap_rgb8(1, last);
	rc_colormap_rgb8(128 / 255.0, mid);
	test_true(same(pixel(&im, 3, 5), first), "minimum gets the first colour");
	test_true(same(pixel(&im, 10, 20), last), "maximum gets the last colour");
	test_true(same(pixel(&im, 40, 7), mid), "midpoint gets the middle colour");
	free(im.rgb);

	/* Overlay: a contact point drawn translucent over the height. */
	rc_grid *mask = rc_grid_new(64, 32, 2.0, 1.0, &err);
	uint8_t over[3] = RC_OVERLAY_RGB, want[3];
	mask->kind = RC_KIND_MASK;
	mask->z[20 * 64 + 10] = 1;
	test_true(write_png(g, path, RC_PNG_AUTO, 0, mask) == 0, "write with overlay");
	decode(path, &im);
	for (int c = 0; c < 3; c++)
		want[c] = (uint8_t)lrint((1 - RC_OVERLAY_ALPHA) * last[c] +
		    RC_OVERLAY_ALPHA * over[c]);
	test_true(same(pixel(&im, 10, 20), want), "overlay blends its colour");
	test_true(same(pixel(&im, 3, 5), first), "no overlay where the mask is 0");
	free(im.rgb);
	rc_grid *small = rc_grid_new(8, 8, 1, 1, &err);
	test_true(rc_png_write(g, path, &(rc_png_opts){ .style = RC_PNG_AUTO, .overlay = small }, &err) != 0,
	    "overlay of another size is an error (%s)", err.msg);
	rc_grid_free(small);
	rc_grid_free(mask);
	rc_grid_free(g);
}

static void
test_aspect_and_strip(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(64, 64, 2.0, 1.0, &err), *line;
	struct image im;
	uint8_t first[3], last[3];
	const char *path = test_path("a.png");
	int ok = 1;

	for (size_t k = 0; k < 64 * 64; k++)
		g->z[k] = (double)(k % 64);	/* rises along x */
	write_png(g, path, RC_PNG_LINEAR, 0, NULL);
	decode(path, &im);
	/* dx = 2/64, dy = 1/64: square pixels of dy, 128 x 64. */
	test_int((long long)im.width, 128, "aspect: width 2 lx/ly");
	test_int((long long)im.height, 64, "aspect: height");
	/* Upsampled in x: each grid column becomes two equal pixels. */
	for (size_t u = 0; u < 128; u += 2)
		ok &= memcmp(pixel(&im, u, 9), pixel(&im, u + 1, 9), 3) == 0;
	test_true(ok, "upsampling repeats columns");
	free(im.rgb);
	rc_grid_free(g);

	line = rc_grid_new(100, 1, 1.0, 1.0, &err);
	for (size_t i = 0; i < 100; i++)
		line->z[i] = (double)i;
	write_png(line, path, RC_PNG_AUTO, 0, NULL);
	decode(path, &im);
	test_int((long long)im.width, 100, "line: one pixel per point");
	test_true(im.height >= 16, "line: a strip at least 16 pixels tall (%zu)", im.height);
	rc_colormap_rgb8(0, first);
	rc_colormap_rgb8(1, last);
	test_true(same(pixel(&im, 0, im.height - 1), first) &&
	    same(pixel(&im, 99, 0), last), "line: strip coloured along x");
	free(im.rgb);
	rc_grid_free(line);
}

/* A 300 x 150 checkerboard mask shown at most 100 wide: 3x3 blocks hold 4
 * or 5 set cells of 9, so each pixel is 4/9 or 5/9 of the way from the
 * first mask colour to the second. */
static void
test_mask_downsampling(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(300, 150, 2.0, 1.0, &err);
	struct image im;
	uint8_t m0[3] = RC_MASK0_RGB, m1[3] = RC_MASK1_RGB, c4[3], c5[3];
	const char *path = test_path("m.png");
	int ok = 1;

	g->kind = RC_KIND_MASK;
	for (size_t j = 0; j < 150; j++)
		for (size_t i = 0; i < 300; i++)
			g->z[j * 300 + i] = (double)((i + j) % 2);
	write_png(g, path, RC_PNG_AUTO, 100, NULL);
	decode(path, &im);
	test_int((long long)im.width, 100, "downsampled width = max_size");
	test_int((long long)im.height, 50, "downsampled height keeps the aspect");
	for (int c = 0; c < 3; c++) {
		c4[c] = (uint8_t)lrint((5.0 / 9) * m0[c] + (4.0 / 9) * m1[c]);
		c5[c] = (uint8_t)lrint((4.0 / 9) * m0[c] + (5.0 / 9) * m1[c]);
	}
	for (size_t v = 0; v < 50; v++)
		for (size_t u = 0; u < 100; u++)
			ok &= same(pixel(&im, u, v), (u + v) % 2 ? c5 : c4);
	test_true(ok, "block average of the mask: 4/9 and 5/9 blends");
	free(im.rgb);

	/* Full resolution: exactly the two colours. */
	write_png(g, path, RC_PNG_AUTO, 0, NULL);
	decode(path, &im);
	test_true(im.width == 300 && same(pixel(&im, 0, 0), m0) && same(pixel(&im, 1, 0), m1),
	    "mask in two colours");
	free(im.rgb);
	rc_grid_free(g);

	size_t w, h;
	rc_png_size(2048, 1024, 2, 1, 0, &w, &h);
	test_true(w == 1024 && h == 512, "default max_size 1024: 2048x1024 -> %zux%zu", w, h);
	rc_png_size(4096, 4096, 1, 1, 300, &w, &h);
	test_true(w == 300 && h == 300, "4096^2 at max 300 -> %zux%zu", w, h);
}

static void
test_log(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(16, 16, 1, 1, &err);
	struct image im;
	uint8_t first[3], last[3], mid[3], nonpos[3] = RC_NONPOS_RGB;
	const char *path = test_path("p.png");

	g->kind = RC_KIND_PRESSURE;
	g->z[1] = 1e-3;
	g->z[2] = 10;
	g->z[3] = 0.1;		/* log10 halfway between -3 and 1 */
	g->z[4] = 2;
	write_png(g, path, RC_PNG_AUTO, 0, NULL);
	decode(path, &im);
	rc_colormap_rgb8(0, first);
	rc_colormap_rgb8(1, last);
	rc_colormap_rgb8(lrint(255 * 0.5) / 255.0, mid);
	test_true(same(pixel(&im, 0, 0), nonpos), "log: zero pressure drawn black");
	test_true(same(pixel(&im, 1, 0), first), "log: smallest positive first colour");
	test_true(same(pixel(&im, 2, 0), last), "log: largest last colour");
	test_true(same(pixel(&im, 3, 0), mid), "log: geometric middle in the middle");
	free(im.rgb);
	rc_grid_free(g);
}

static void
test_failures(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(8, 8, 1, 1, &err);
	struct stat st;
	const char *path = test_path("nodir/x.png");

	test_true(rc_png_write(g, path, NULL, &err) != 0, "unwritable path fails (%s)", err.msg);
	test_true(stat(path, &st) != 0, "and leaves no file");
	test_true(rc_png_write(g, test_tmpdir(), NULL, &err) != 0,
	    "a directory as output fails (%s)", err.msg);
	rc_grid_free(g);
}

/* Digits and the characters of numbers must be told apart: every pair
 * of glyphs differs in at least 3 of the 35 pixels (one stray pixel of
 * resampling or of a viewer cannot turn one into another). */
static void
test_font(void)
{
	const char set[] = "0123456789.-+=e*";
	int worst = 35, ok = 1;
	uint8_t img[2 * 7 * 2 * 5 * 3], ink[3] = { 1, 2, 3 };

	for (const char *a = set; *a; a++)
		for (const char *b = a + 1; *b; b++) {
			const uint8_t *ga = rc_font_glyph(*a), *gb = rc_font_glyph(*b);
			int d = 0;
			for (int r = 0; r < RC_FONT_H; r++)
				d += __builtin_popcount((unsigned)(ga[r] ^ gb[r]) & 0x1F);
			worst = d < worst ? d : worst;
		}
	test_true(worst >= 3, "glyphs of numbers differ in >= 3 pixels (least %d)", worst);
	test_true(memcmp(rc_font_glyph('A'), rc_font_glyph('a'), RC_FONT_H) == 0,
	    "upper case drawn as lower case");
	test_int((long long)rc_text_width("0123", 2), (4 * 6 - 1) * 2,
	    "text width: 6 columns a character less the last blank, times scale");
	test_int((long long)rc_text_width("", 1), 0, "empty text has no width");
	/* At scale 2 every font pixel is a 2x2 block of the glyph's bits. */
	memset(img, 0, sizeof(img));
	rc_text_draw(img, 10, 14, 0, 0, "8", 2, ink);
	for (int v = 0; v < 14; v++)
		for (int u = 0; u < 10; u++) {
			int bit = (rc_font_glyph('8')[v / 2] >> (4 - u / 2)) & 1;
			ok &= (img[3 * (v * 10 + u)] == (bit ? 1 : 0));
		}
	test_true(ok, "scale 2: each font pixel a 2x2 block");
	/* Clipping: drawing partly outside touches nothing out of bounds
	 * (ASan would tell) and draws the visible part. */
	memset(img, 0, sizeof(img));
	rc_text_draw(img, 10, 14, -3, -5, "88", 1, ink);
	test_true(img[3 * (0 * 10 + 0)] == 1 || img[3 * (1 * 10 + 0)] == 1 ||
	    img[3 * (0 * 10 + 1)] == 1, "clipped text draws its visible part");
}

/* Does the image hold text s drawn at (x, y), pixel for pixel (ink where
 * the font has a pixel, canvas white elsewhere in the glyph cells)? */
static int
has_text(const struct image *im, size_t x, size_t y, const char *s, int scale)
{
	size_t w = rc_text_width(s, scale), h = RC_FONT_H * (size_t)scale;
	uint8_t *want = calloc(w * h * 3, 1);
	uint8_t black[3] = { 0, 0, 0 }, white[3] = { 255, 255, 255 };
	int ok = x + w <= im->width && y + h <= im->height;

	memset(want, 255, w * h * 3);
	rc_text_draw(want, w, h, 0, 0, s, scale, black);
	for (size_t v = 0; ok && v < h; v++)
		for (size_t u = 0; ok && u < w; u++) {
			const uint8_t *got = pixel(im, x + u, y + v);
			ok = same(got, want + 3 * (v * w + u)) &&
			    (same(got, black) || same(got, white));
		}
	free(want);
	return ok;
}

static void
test_annotated(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(64, 32, 2.0, 1.0, &err);
	struct image im, bare;
	rc_png_layout l;
	rc_png_opts o;
	uint8_t table[256][3], white[3] = { 255, 255, 255 }, black[3] = { 0, 0, 0 };
	const char *path = test_path("ann.png"), *bpath = test_path("bare.png");
	int ok = 1;
	size_t y, th;

	for (size_t j = 0; j < 32; j++)
		for (size_t i = 0; i < 64; i++)
			g->z[j * 64 + i] = sin(0.1 * i) * cos(0.2 * j);
	g->z[5 * 64 + 3] = -2;
	g->z[20 * 64 + 10] = 3;
	for (int k = 0; k < 256; k++)
		rc_colormap_rgb8(k / 255.0, table[k]);
	rc_png_defaults(&o);
	test_true(o.annotate == 1, "annotated by default");
	o.clip = 0;	/* the labels are min and max (percentiles: below) */
	test_true(rc_png_write(g, path, &o, &err) == 0, "write annotated PNG");
	write_png(g, bpath, RC_PNG_AUTO, 0, NULL);
	test_true(decode(path, &im) == 0 && decode(bpath, &bare) == 0, "both decode");
	rc_png_layout_of(g, &o, &l);
	test_true(im.width == l.width && im.height == l.height,
	    "image size is the layout's (%zux%zu)", im.width, im.height);
	test_true(l.bar_w > 0 && l.width >= l.map_x + 64 + l.bar_w &&
	    l.bar_x >= l.map_x + 64, "the image grows by the colour bar, right of the map");
	test_true(l.height > 32 + 2 * RC_FONT_H, "and by the scale bar below");
	/* The map is the bare map, pixel for pixel, at its offset. */
	for (size_t v = 0; v < 32; v++)
		ok &= memcmp(pixel(&im, l.map_x, l.map_y + v), pixel(&bare, 0, v), 64 * 3) == 0;
	test_true(ok, "map pixels unchanged by the annotations");
	/* The bar runs through the colormap, top = max, bottom = min. */
	ok = l.bar_h >= 32;
	for (size_t v = 0; v < l.bar_h; v++) {
		double t = 1 - (double)v / (double)(l.bar_h - 1);
		for (size_t u = l.bar_x; u < l.bar_x + l.bar_w; u++)
			ok &= same(pixel(&im, u, l.bar_y + v), table[lrint(255 * t)]);
	}
	test_true(ok, "colour bar pixels follow the colormap");
	test_true(same(pixel(&im, l.bar_x, l.bar_y), table[255]) &&
	    same(pixel(&im, l.bar_x, l.bar_y + l.bar_h - 1), table[0]),
	    "bar: last colour at the top, first at the bottom");
	test_true(same(pixel(&im, 0, 0), white), "white canvas");
	/* The range as text beside the bar: max 3 at the top, min -2 at the
	 * bottom (the map is 64 wide: font scale 1). */
	th = RC_FONT_H;
	test_int(l.scale, 1, "small map: font scale 1");
	test_true(has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y, "3", 1),
	    "max written at the top of the bar");
	test_true(has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y + l.bar_h - th, "-2", 1),
	    "min written at the bottom of the bar");
	/* Scale bar: lx = 2, so a quarter is 0.5 (a round length), 16 px of
	 * the 64 px map; labelled "0.5" after a gap. */
	y = (l.map_y + 32 > l.bar_y + l.bar_h ? l.map_y + 32 : l.bar_y + l.bar_h) + 8;
	ok = 1;
	for (size_t u = l.map_x; u < l.map_x + 16; u++)
		ok &= same(pixel(&im, u, y + 3), black);
	ok &= same(pixel(&im, l.map_x + 16, y + 3), white);
	test_true(ok, "scale bar 16 px long for 0.5 of lx = 2 on 64 px");
	test_true(has_text(&im, l.map_x + 16 + 4, y, "0.5", 1), "scale bar labelled 0.5");
	free(im.rgb);

	/* A caption and an overlay add a line: the text and a swatch in the
	 * overlay colour. */
	rc_grid *mask = rc_grid_new(64, 32, 2.0, 1.0, &err);
	uint8_t over[3] = RC_OVERLAY_RGB;
	rc_png_layout lc;
	mask->kind = RC_KIND_MASK;
	o.overlay = mask;
	o.caption = "p*=0.05 a_r=0.1";
	rc_png_layout_of(g, &o, &lc);
	test_true(lc.height == l.height + 8 + th, "a caption line adds 8 + 7 px");
	rc_png_write(g, path, &o, &err);
	decode(path, &im);
	y += th + 8;
	test_true(has_text(&im, lc.map_x, y, "p*=0.05 a_r=0.1", 1), "caption written");
	test_true(same(pixel(&im, lc.map_x + rc_text_width(o.caption, 1) + 8, y), over),
	    "contact swatch in the overlay colour");
	free(im.rgb);
	free(bare.rgb);

	/* A mask has no colour bar; a log map says "pressure log" on its bar. */
	rc_png_defaults(&o);
	o.clip = 0;
	rc_png_layout_of(mask, &o, &l);
	test_true(l.bar_w == 0, "mask: no colour bar");
	g->kind = RC_KIND_PRESSURE;
	for (size_t k = 0; k < 64 * 32; k++)
		g->z[k] = k < 100 ? 0 : (double)k;
	g->z[100] = 1e-3;
	rc_png_write(g, path, &o, &err);
	decode(path, &im);
	rc_png_layout_of(g, &o, &l);
	test_true(has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y, "2.05e+03", 1) &&
	    has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y + l.bar_h - th, "0.001", 1),
	    "log map: the real values at the ends");
	test_true(has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y + (l.bar_h - th) / 2,
	    "pressure log", 1), "log map: 'pressure log' at the middle of the bar");
	free(im.rgb);
	/* Big maps get text at scale 2. */
	rc_grid *big = rc_grid_new(300, 300, 1, 1, &err);
	rc_png_layout_of(big, NULL, &l);
	test_int(l.scale, 2, "map of 300 px: font scale 2");
	rc_grid_free(big);
	rc_grid_free(mask);
	rc_grid_free(g);
}

/* Lengths with SI prefixes, exact strings. */
static void
test_si(void)
{
	static const struct { double v; const char *unit; int micro; const char *want; } c[] = {
		{ 1.999e-4, "m", 0, "200 um" },
		{ 5.99e-8, "m", 0, "59.9 nm" },
		{ 0.5, "um", 0, "500 nm" },
		{ 20, "um", 1, "20 \xc2\xb5m" },
		{ 2e-3, "m", 0, "2 mm" },
		{ 1.5, "m", 0, "1.5 m" },
		{ 999.7, "um", 0, "1 mm" },
		{ 2.5e-13, "m", 0, "0.25 pm" },
		{ -3e-6, "m", 0, "-3 um" },
		{ 5, "angstrom", 0, "500 pm" },
		{ 0, "nm", 0, "0 nm" },
		{ 0.25, "", 0, "0.25" },
		{ 3, "V", 0, "3 V" },
	};
	char buf[64];

	for (size_t k = 0; k < sizeof(c) / sizeof(c[0]); k++) {
		rc_si_length(buf, sizeof(buf), c[k].v, c[k].unit, c[k].micro);
		test_true(strcmp(buf, c[k].want) == 0, "si: %g %s -> '%s' (want '%s')",
		    c[k].v, c[k].unit, buf, c[k].want);
	}
	test_int((long long)rc_text_width("20 \xc2\xb5m", 1), 5 * 6 - 1,
	    "the micro sign's two bytes are one character");
	test_true(memcmp(rc_font_glyph('\xb5'), rc_font_glyph('u'), RC_FONT_H) != 0 &&
	    memcmp(rc_font_glyph('\xb5'), rc_font_glyph('?'), RC_FONT_H) != 0,
	    "the font has a micro sign (not u, not the empty box)");
}

/* The number of distinct colours of an image. */
static size_t
colours(const struct image *im)
{
	size_t n = 0, npix = im->width * im->height;
	uint8_t (*seen)[3] = malloc(npix * 3);

	for (size_t p = 0; p < npix; p++) {
		size_t k = 0;
		while (k < n && !same(im->rgb + 3 * p, seen[k]))
			k++;
		if (k == n)
			memcpy(seen[n++], im->rgb + 3 * p, 3);
	}
	free(seen);
	return n;
}

/* One spike does not take the colormap: the 0.5-99.5% range colours the
 * rest; the legend says how much was clipped, names the quantity, and
 * writes lengths with SI prefixes. */
static void
test_robust_range(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(64, 64, 8e-5, 8e-5, &err);
	struct image im;
	rc_png_opts o;
	rc_png_layout l;
	const char *path = test_path("spike.png");
	size_t n = 64 * 64, same_as_spike = 0, th = RC_FONT_H * 1, y;

	/* distinct values k * 1e-9 m: a 4 um ramp, and a 1 mm spike */
	for (size_t k = 0; k < n; k++)
		g->z[k] = (double)((k * 37) % n) * 1e-9;
	g->z[0] = 1e-3;
	strcpy(g->unit, "m");
	rc_png_defaults(&o);
	o.annotate = 0;
	test_true(rc_png_write(g, path, &o, &err) == 0, "write spiky map");
	decode(path, &im);
	for (size_t v = 0; v < 64; v++)
		for (size_t u = 0; u < 64; u++)
			same_as_spike += same(pixel(&im, u, v), pixel(&im, 0, 0));
	test_true(same_as_spike < n / 50, "percentile range: %zu of %zu pixels "
	    "share the spike's colour", same_as_spike, n);
	test_true(colours(&im) > 200, "... and the rest spans the colormap "
	    "(%zu colours)", colours(&im));
	free(im.rgb);
	o.clip = 0;
	rc_png_write(g, path, &o, &err);
	decode(path, &im);
	test_true(colours(&im) <= 3, "(min to max: %zu colours, the failure "
	    "the range avoids)", colours(&im));
	free(im.rgb);

	/* the legend: 4096 distinct values, quantiles at ranks 20.475 and
	 * 4074.525 (GSL interpolates): 21 below, 21 above, 42/4096 = 1.03%
	 * ("1%" at 2 digits); the quantity; SI lengths */
	rc_png_defaults(&o);
	rc_png_write(g, path, &o, &err);
	decode(path, &im);
	rc_png_layout_of(g, &o, &l);
	test_true(has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y + (l.bar_h - th) / 2,
	    "height", 1), "the quantity at the middle of the bar");
	/* top: quantile 0.995 of 0 .. 4095 nm (the spike replaced 0):
	 * v[4074] + 0.525 = 4075.525 nm -> "4.08 um" */
	test_true(has_text(&im, l.bar_x + l.bar_w + 4, l.bar_y, "4.08 \xc2\xb5m", 1),
	    "top of the range in um with the micro sign");
	/* scale bar: a quarter of 80 um is 20 um */
	y = (l.map_y + 64 > l.bar_y + l.bar_h ? l.map_y + 64 : l.bar_y + l.bar_h) + 8;
	test_true(has_text(&im, l.map_x + 16 + 4, y, "20 \xc2\xb5m", 1),
	    "scale bar labelled 20 um");
	test_true(has_text(&im, l.map_x, y + th + 8, "1% clipped", 1),
	    "the clipped share under the scale bar");
	free(im.rgb);
	rc_grid_free(g);
}

/* The spectrum plot: a known power law C = 1e-20 q^-3 on q = 10 .. 1000
 * (21 points, 0.1 decade apart) spans exactly the decades 1..3 and
 * -29..-23, so its first point is the frame's top-left corner and its
 * last the bottom-right; the markers found in the image lie on a line
 * of slope -3 decades per decade in pixels; the fit is drawn red. */
static void
test_spectrum_plot(void)
{
	double q[21], c[21], sx = 0, sy = 0, sxx = 0, sxy = 0, worst = 0;
	double cx[21], cy[21], ppd_x, ppd_y, slope, icpt;
	rc_spectrum_plot p;
	rc_plot_frame f;
	rc_err err;
	struct image im = { 0 };
	uint8_t point[3], red[3] = { 214, 39, 40 };
	size_t found = 0, n = 21;
	const char *path = test_path("psd.png");

	for (size_t k = 0; k < n; k++) {
		q[k] = pow(10, 1 + 0.1 * (double)k);
		c[k] = 1e-20 * pow(q[k], -3);
	}
	memset(&p, 0, sizeof(p));
	p.q = q;
	p.c = c;
	p.n = n;
	p.unit = "um";
	p.c_power = 4;
	p.c_name = "C(q)";
	p.title = "test";
	test_true(rc_png_spectrum(&p, path, &f, &err) == 0, "spectrum PNG written");
	test_true(decode(path, &im) == 0 && im.width == 800 && im.height == 600,
	    "an 800x600 plot (%zux%zu)", im.width, im.height);
	test_true(f.lq_min == 1 && f.lq_max == 3 && f.lc_min == -29 &&
	    f.lc_max == -23, "axes: the decades of the data");
	/* the markers: squares of the colormap's first colour, found by
	 * scanning the image column by column (they are 35 px apart) */
	rc_colormap_rgb8(0, point);
	for (size_t u = 0; u < im.width && found < n; u++) {
		size_t cnt = 0;
		double ysum = 0;
		for (size_t v = 0; v < im.height; v++)
			if (same(pixel(&im, u, v), point)) {
				cnt++;
				ysum += (double)v;
			}
		if (cnt == 0)
			continue;
		/* a marker is 5 columns wide: take its middle column */
		cx[found] = (double)u + 2;
		cy[found] = ysum / (double)cnt;
		found++;
		u += 4;
	}
	test_int((long long)found, 21, "21 markers found");
	test_true(fabs(cx[0] - (double)f.x0) <= 1 && fabs(cy[0] - (double)f.y0) <= 1,
	    "q = 10, C = 1e-23: the frame's top-left corner (%.1f, %.1f; frame "
	    "at %zu, %zu)", cx[0], cy[0], f.x0, f.y0);
	test_true(fabs(cx[20] - (double)(f.x0 + f.w - 1)) <= 1 &&
	    fabs(cy[20] - (double)(f.y0 + f.h - 1)) <= 1,
	    "q = 1000, C = 1e-29: the bottom-right corner");
	for (size_t k = 0; k < found; k++) {
		sx += cx[k];
		sy += cy[k];
		sxx += cx[k] * cx[k];
		sxy += cx[k] * cy[k];
	}
	slope = (found * sxy - sx * sy) / (found * sxx - sx * sx);
	icpt = (sy - slope * sx) / (double)found;
	for (size_t k = 0; k < found; k++)
		worst = fmax(worst, fabs(cy[k] - (icpt + slope * cx[k])));
	ppd_x = (double)(f.w - 1) / 2;
	ppd_y = (double)(f.h - 1) / 6;
	test_rel(slope, 3 * ppd_y / ppd_x, 0.01, "markers on a line of slope -3 "
	    "decades per decade (pixels, y down)");
	test_true(worst <= 1, "... within 1 pixel (%.2f)", worst);
	free(im.rgb);

	/* with the fit C_r (q/q_r)^(-2-2H), H = 0.5, q_r = 10: red on the
	 * line between markers */
	p.have_fit = 1;
	p.c_r = 1e-23;
	p.hurst = 0.5;
	p.q_r = 10;
	p.fit_q_min = 10;
	p.fit_q_max = 1000;
	rc_png_spectrum(&p, path, &f, &err);
	decode(path, &im);
	{
		double qm = pow(10, 1.55);
		long x = lrint(rc_png_plot_x(&f, qm)), y = lrint(rc_png_plot_y(&f,
		    1e-20 * pow(qm, -3)));
		int hit = 0;
		for (long dy = -1; dy <= 1; dy++)
			hit |= same(pixel(&im, (size_t)x, (size_t)(y + dy)), red);
		test_true(hit, "the fit line runs through the power law");
		test_true(!same(pixel(&im, (size_t)x, (size_t)(y - 30)), red),
		    "... and not 30 px above it");
	}
	free(im.rgb);
	p.n = 0;
	test_true(rc_png_spectrum(&p, path, &f, &err) != 0, "no points: an "
	    "error (%s)", err.msg);
}

int
main(void)
{
	test_font();
	test_annotated();
	test_colormap();
	test_linear();
	test_aspect_and_strip();
	test_mask_downsampling();
	test_log();
	test_failures();
	test_si();
	test_robust_range();
	test_spectrum_plot();
	return test_summary();
}
