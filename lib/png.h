/* png.h - 8-bit PNG previews of grids (o may be NULL: defaults).
 *
 * Heights with a perceptually uniform colormap (computed, viridis-like),
 * masks in two colours, pressures optionally on a log scale; an optional
 * contact mask drawn over a height map.  One image pixel per grid point
 * unless the grid exceeds max_size, in which case it is block-averaged
 * down; the aspect ratio follows lx:ly.  Written atomically.
 */
#ifndef RC_PNG_H
#define RC_PNG_H

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
} rc_png_opts;

void rc_png_defaults(rc_png_opts *o);
/* The image size rc_png_write uses: square pixels of min(dx, dy), longest
 * side at most max_size (0 = 1024); a line (nx x 1 or 1 x ny) becomes a
 * strip at least 16 pixels thick.  Colours: see colormap.h. */
void rc_png_size(size_t nx, size_t ny, double lx, double ly, size_t max_size,
    size_t *width, size_t *height);
int rc_png_write(const rc_grid *g, const char *path, const rc_png_opts *o,
    rc_err *err);

#endif
