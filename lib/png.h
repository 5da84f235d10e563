/* SPDX-License-Identifier: GPL-3.0-or-later */
/* png.h - 8-bit PNG previews of grids (o may be NULL: defaults).
 *
 * Heights with a perceptually uniform colormap (computed, viridis-like),
 * masks in two colours, pressures optionally on a log scale; an optional
 * contact mask drawn over a height map.  One image pixel per grid point
 * unless the grid exceeds max_size, in which case it is block-averaged
 * down; the aspect ratio follows lx:ly.  Written atomically.
 *
 * Colour range: the clip and 1 - clip quantiles of the finite values (of
 * log10 of the positive ones on a log scale; sorted by qsort, then
 * gsl_stats_quantile_from_sorted_data), values beyond drawn in the end
 * colours; min to max if the quantiles coincide.
 *
 * Annotated (the default): the map on a white canvas with, at its right, a
 * colour bar from the bottom of the range to its top labelled with both (3
 * significant digits; lengths with an SI prefix, si.h, the micro sign
 * drawn as such) and, at its middle, the quantity (the grid's kind:
 * height, gap, pressure ...; "log" after it on a log scale; no bar for a
 * mask); below it a scale bar of a round length (1, 2 or 5 times a power
 * of ten, at most a quarter of lx) labelled with that length; then, when
 * values were clipped, "N% clipped" (their share of the finite values);
 * and below that an optional caption, with a swatch labelled "contact"
 * when an overlay is drawn.
 * Text is drawn with the font of png_text.h, twice as large for maps
 * whose longer side is 256 pixels or more.
 */
#ifndef RC_PNG_H
#define RC_PNG_H

#include <stdint.h>
#include "grid.h"

enum rc_png_style {
	RC_PNG_AUTO = 0,	/* from the grid's kind */
	RC_PNG_LINEAR,		/* colormap over [min, max] */
	RC_PNG_LOG,		/* colormap over log10 of positive values */
	RC_PNG_MASK		/* 0/1 in two colours */
};

typedef struct rc_png_opts {
	enum rc_png_style style;
	size_t max_size;		/* longest image side; 0 = 1024 */
	const rc_grid *overlay;		/* mask drawn over the map, or NULL */
	int annotate;			/* colour bar, range, scale bar, caption */
	const char *caption;		/* text under the scale bar, or NULL */
	/* Share of the values left out at each end of the colour range
	 * (default 0.005: the 0.5th to 99.5th percentile), so that one
	 * spike does not take the whole colormap; 0: min to max. */
	double clip;
} rc_png_opts;

/* Where rc_png_write puts things (pixels; bar_w = 0: no colour bar). */
typedef struct rc_png_layout {
	size_t width, height;		/* the whole image */
	size_t map_x, map_y, map_w, map_h;
	size_t bar_x, bar_y, bar_w, bar_h;
	int scale;			/* font scale */
} rc_png_layout;

void rc_png_defaults(rc_png_opts *o);
/* The image size rc_png_write uses: square pixels of min(dx, dy), longest
 * side at most max_size (0 = 1024); a line (nx x 1 or 1 x ny) becomes a
 * strip at least 16 pixels thick.  Colours: see colormap.h. */
void rc_png_size(size_t nx, size_t ny, double lx, double ly, size_t max_size,
    size_t *width, size_t *height);
/* The layout rc_png_write uses for g with o (NULL: defaults). */
void rc_png_layout_of(const rc_grid *g, const rc_png_opts *o, rc_png_layout *l);
int rc_png_write(const rc_grid *g, const char *path, const rc_png_opts *o,
    rc_err *err);
/* An 8-bit RGB image (rows top first) written as PNG, atomically. */
int rc_png_encode(const uint8_t *rgb, size_t width, size_t height,
    const char *path, rc_err *err);

#endif
