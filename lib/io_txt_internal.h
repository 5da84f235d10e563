/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_txt_internal.h - private to the text reader: what the lines before the first
 * line of numbers say (io_txt_head.c reads them, io_txt.c the numbers).
 */
#ifndef RC_IO_TXT_H
#define RC_IO_TXT_H

#include "io_internal.h"

#define RC_TXT_MAGIC \
    "# surf text grid: one row (fixed y) per line, x along the line"

/* Columns a line of names or units may describe: x, y, z and one more
 * (an index or a validity flag). */
#define TXT_MAXCOL 4

struct txt_header {
	/* our "# key = value" comments */
	int have_nx, have_ny, have_lx, have_ly, kind;
	size_t nx, ny;
	double lx, ly;
	char unit[32], z_unit[32];
	int periodic;		/* -1 not said */
	int own;		/* our magic line */
	/* Gwyddion's export, English or German labels */
	int gwy;
	int have_width, have_height;
	double width, height;	/* in wunit and hunit */
	char wunit[32], hunit[32];
	char **mkey, **mval, **hist;
	size_t nmeta, nhist;
	char *filled;		/* our list of filled points */
	/* SurfaceTopography's (and SPIP's) matrix header: "h=ROWS w=COLUMNS",
	 * "pixel size=D UNIT", "data unit=U", "height conversion factor
	 * (-> UNIT)=F" (a value times F is a height in UNIT) */
	int have_hw, have_pixel, have_zfac;
	size_t h_rows, w_cols;
	double pixel, zfac;
	char pixel_unit[32], zfac_unit[32], data_unit[32];
	/* a line of column names (its line number, for messages) and a line
	 * of units, one per column */
	size_t ncolname, colname_line;
	char colname[TXT_MAXCOL][64];
	char colname_text[80];	/* the line as it was, for messages */
	size_t ncolunit;
	char colunit[TXT_MAXCOL][32];
	int have_count;		/* a line giving the number of points */
	size_t count;
	int dektak;		/* Bruker Dektak's CSV export */
};

/* Read the lines before the first line of numbers, leaving that line
 * unread; *lineno becomes its line number (1-based).  Returns 0, or -1
 * with err (a header line it does not know, or text and no numbers). */
int rc__txt_preamble(rc_in *in, struct txt_header *h, size_t *lineno,
    rc_err *err);
void rc__txt_header_free(struct txt_header *h);
/* The first word of a column name that is a length unit ("x in \xc2\xb5m",
 * "X_(microns)", "Raw Micrometer") in canonical spelling; 0 if none. */
int rc__txt_name_unit(const char *name, char out[32]);

#endif
