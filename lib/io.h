/* io.h - reading and writing grids in every supported format.
 *
 * Formats: native .surf (text header + float64 LE, see surf(5)), .npy
 * (numpy), .gsf (Gwyddion Simple Field), .txt (whitespace matrix).  The
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
	RC_FMT_TXT
};

typedef struct rc_read_opts {
	double lx, ly;		/* cell size for formats that carry none */
	int have_l;		/* lx, ly given (-L): also overrides nothing else */
	int allow_nonfinite;	/* accept NaN/Inf values (default: reject) */
} rc_read_opts;

/* Path "-" or NULL reads standard input.  o may be NULL (L = 1). */
rc_grid *rc_grid_read(const char *path, const rc_read_opts *o, rc_err *err);
rc_grid *rc_grid_read_stream(FILE *fp, const rc_read_opts *o, rc_err *err);

/* By extension: .surf .npy .gsf .txt; anything else -> -1. NULL/"-" -> surf. */
int rc_format_from_name(const char *path);
const char *rc_format_name(enum rc_format f);

/* Atomic (see atomic.h); "-" or NULL writes standard output. */
int rc_grid_write(const rc_grid *g, const char *path, enum rc_format fmt,
    rc_err *err);
int rc_grid_write_stream(const rc_grid *g, FILE *fp, enum rc_format fmt,
    rc_err *err);

#endif
