/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io.h - reading and writing grids in every supported format.
 *
 * Formats: native .surf (text header + float64 LE, see surf(5)), .npy
 * (numpy), .gsf (Gwyddion Simple Field), .txt (whitespace matrix), .x3p
 * (ISO 25178-72) and .nc (netCDF) read and written; .gwy (Gwyddion),
 * SDF (ISO 25178-71), Excel workbooks (.xlsx), contact.engineering
 * containers (a zip with meta.yml) and, through Gwyddion when it is
 * installed, every instrument format Gwyddion reads, read only.  The
 * output format follows the file name's extension (.surf when there is
 * none or the output is standard output); the input format is detected
 * from the content, so pipes work.  Readers reject anything inconsistent
 * with a message naming the reason; the caller prefixes the file name.
 */
#ifndef RC_IO_H
#define RC_IO_H

#include <stdio.h>
#include "grid.h"
#include "rc_err.h"

enum rc_format {
	RC_FMT_SURF = 0,
	RC_FMT_NPY,
	RC_FMT_GSF,
	RC_FMT_TXT,
	RC_FMT_X3P,	/* ISO 25178-72 XML 3D (zip + main.xml) */
	RC_FMT_NC	/* netCDF, contact.engineering convention */
};

enum rc_periodic_opt {
	RC_PERIODIC_AUTO = 0,	/* as the file says (format rule if it has no flag) */
	RC_PERIODIC_YES,	/* --periodic */
	RC_PERIODIC_NO		/* --no-periodic */
};

typedef struct rc_read_opts {
	double lx, ly;		/* cell size for formats that carry none */
	int have_l;		/* lx, ly given (-L): also overrides nothing else */
	int allow_nonfinite;	/* accept NaN/Inf values (default: reject) */
	/* Multi-channel files (.gwy, x3p, netCDF, vendor formats): which
	 * channel is the grid.  channel 0 and channel_name NULL: the first
	 * channel whose values are lengths.  A zeroed struct is the default. */
	int channel;		/* 1-based, as listed by rc_grid_list_channels */
	const char *channel_name;	/* or the channel of this title */
	enum rc_periodic_opt periodic;	/* AUTO: the file's flag or the format's rule */
	const char *unit;	/* lateral unit for formats that carry none */
	const char *z_unit;	/* the user's --z-unit: values are in this unit,
				 * also when the file says they are not lengths */
	int npy_xy;		/* npy arrays are (nx, ny), x the first index
				 * (default (ny, nx): numpy's row-major image) */
	int uniform;		/* x-z columns whose x is not uniformly spaced
				 * are resampled linearly onto n points of a
				 * uniform step (default: refused) */
	int nonuniform;		/* such columns are read as they are: an
				 * nx x 1 grid with its positions in x
				 * (grid.h); for a caller that analyses them
				 * (stats_nonuni.h).  uniform wins. */
} rc_read_opts;

/* The defaults: zeroes, except L = 1 x 1. */
void rc_read_opts_init(rc_read_opts *o);

/* What every reader's grid goes through (rc_grid_read_stream calls it):
 * NaN values become missing points (g->valid), infinite values are
 * refused unless o->allow_nonfinite, a mask must hold 0 and 1 only; then
 * the options: periodic YES/NO overrides the file's flag, o->unit names
 * the lateral unit of a grid that has none, o->z_unit the unit of the
 * values whatever the file says. */
int rc_grid_read_finish(rc_grid *g, const rc_read_opts *o, rc_err *err);

/* What one channel of a file is, for listing (surfstat --channels). */
typedef struct rc_channel_info {
	char title[128];
	char z_unit[32];
	char unit[32];
	size_t nx, ny;
	double lx, ly;
	int has_mask;		/* some points missing */
} rc_channel_info;

/* Every channel of the file at path (a single-channel format gives one);
 * *info is malloc'ed, *n its length. */
int rc_grid_list_channels(const char *path, const rc_read_opts *o,
    rc_channel_info **info, size_t *n, rc_err *err);

/* Path "-" or NULL reads standard input.  o may be NULL (L = 1). */
rc_grid *rc_grid_read(const char *path, const rc_read_opts *o, rc_err *err);
rc_grid *rc_grid_read_stream(FILE *fp, const rc_read_opts *o, rc_err *err);

/* By extension: .surf .npy .gsf .txt .x3p .nc; anything else -> -1.
 * NULL/"-" -> surf. */
int rc_format_from_name(const char *path);
const char *rc_format_name(enum rc_format f);

/* The longest list of filled points (rc_grid_filled_format) a header
 * holds: 512 KiB, some 40000 ranges.  A longer one is left out. */
#define RC_FILLED_MAX ((size_t)1 << 19)
/* 1 if writing g as fmt keeps its filled points, or it has none: .surf,
 * .txt and .gsf keep them while their list fits in RC_FILLED_MAX; .npy,
 * .x3p and .nc have no place for them.  0 if they would be lost (a tool
 * says so), -1 (err set) when out of memory. */
int rc_format_keeps_filled(const rc_grid *g, enum rc_format fmt, rc_err *err);

/* Atomic (see atomic.h); "-" or NULL writes standard output. */
int rc_grid_write(const rc_grid *g, const char *path, enum rc_format fmt,
    rc_err *err);
int rc_grid_write_stream(const rc_grid *g, FILE *fp, enum rc_format fmt,
    rc_err *err);

#endif
