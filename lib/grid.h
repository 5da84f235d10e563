/* SPDX-License-Identifier: GPL-3.0-or-later */
/* grid.h - the grid every tool reads and writes.
 *
 * nx by ny points, pixel registered, spacing lx/nx by ly/ny, row-major with
 * x fastest: value (i, j) is z[j * nx + i].  Besides the values a grid
 * carries what they are (kind), their units, whether the grid is one period
 * of an infinite surface (synthetic) or a finite patch (a measurement),
 * which points are missing, key/value metadata (the generation parameters,
 * which every tool passes on) and the history of command lines that made it.
 *
 * Units: unit is the lateral unit of lx and ly, z_unit the unit of the
 * values; "" means unknown, and an empty z_unit with a length unit means
 * "the same as unit".  Computations that mix lateral and vertical lengths
 * (gradients, gbar, p*, contact) need both in one length unit.
 *
 * Periodic: 1 (the default of rc_grid_new) for a grid that is one period
 * of an infinite surface; 0 for a finite patch whose opposite edges are
 * unrelated.  Measured data is read as 0.
 *
 * Missing points: valid is NULL when every point is valid; otherwise nx*ny
 * flags, 1 valid and 0 missing, and z is NaN at every missing point.
 *
 * Positions: x is NULL for the uniform spacing lx/nx above; otherwise
 * the grid is a line scan not uniformly spaced (ny = 1, read only when
 * rc_read_opts.nonuniform asks): x holds the nx strictly increasing
 * positions of its heights, lx = x[nx-1] - x[0] and ly = lx / (nx - 1),
 * the mean step (SurfaceTopography's NonuniformLineScan).  Only what says
 * so takes such a grid (stats_nonuni.h); the writers, --periodic, the
 * solver (rc_solver_new), the statistics (stats.h) and the spectra and
 * ACF (psd.h) refuse it (rc_grid_check_uniform, gridcheck.h); other
 * steps do not check.
 *
 * Filled points: filled is NULL, or nx*ny flags, 1 where the value was
 * made up by filling a missing point (rc_fill_harmonic) instead of
 * measured; a filled point is valid.  The flags follow the values: steps
 * in place keep them, a crop or a transpose maps them, a resample (whose
 * values mix many points) drops them; results computed from the heights
 * (spectra, pressures) do not have them.  Files keep them as a list of
 * index ranges (rc_grid_filled_format; surf(5) says which formats).
 */
#ifndef RC_GRID_H
#define RC_GRID_H

#include <stddef.h>
#include "rc_err.h"

/* Largest accepted dimension and point count: sane for a 64-bit machine,
 * and small enough that nx*ny*8 never overflows. */
#define RC_GRID_MAX_DIM    (1u << 24)
#define RC_GRID_MAX_POINTS ((size_t)1 << 36)

enum rc_kind {
	RC_KIND_HEIGHT = 0,
	RC_KIND_GAP,
	RC_KIND_PRESSURE,
	RC_KIND_DISPLACEMENT,
	RC_KIND_MASK,
	RC_KIND_SPECTRUM,
	RC_KIND_COUNT
};

typedef struct rc_kv {
	char *key;
	char *val;
} rc_kv;

typedef struct rc_grid {
	size_t nx, ny;
	double lx, ly;
	enum rc_kind kind;
	char unit[32];		/* lateral unit of lx, ly; "" if unknown */
	char z_unit[32];	/* unit of the values; "" = unknown or as unit */
	int periodic;		/* 1 one period of an infinite surface, 0 a patch */
	unsigned char *valid;	/* NULL, or nx*ny flags: 0 = missing (z NaN) */
	unsigned char *filled;	/* NULL, or nx*ny flags: 1 = filled, not measured */
	rc_kv *meta;		/* generation parameters, in insertion order */
	size_t nmeta;
	char **history;		/* one command line per entry, oldest first */
	size_t nhistory;
	double *z;		/* nx*ny values, FFTW-aligned */
	void *z_block;		/* what rc_grid_free frees for z: rc_fft_huge's
				 * block (fft.h), NULL when z is adopted */
	double *x;		/* NULL, or nx increasing positions (ny = 1) */
} rc_grid;

/* Allocate a zeroed grid; checks dimensions and overflow. */
rc_grid *rc_grid_new(size_t nx, size_t ny, double lx, double ly, rc_err *err);
void rc_grid_free(rc_grid *g);
/* A grid over values the caller allocated with fftw_malloc (nx*ny or more
 * doubles), which the grid then owns and frees; on failure z is left to
 * the caller.  Saves a copy when a result is computed in place. */
rc_grid *rc_grid_adopt(size_t nx, size_t ny, double lx, double ly, double *z,
    rc_err *err);
/* Room for n grid values as rc_grid_new gives them (not zeroed): FFTW's
 * alignment, from RC_FFT_HUGE_MIN (fft.h) up on transparent huge pages
 * (rc_fft_huge); *block is what rc_fft_huge_free takes with the values,
 * and what a grid holding them keeps in z_block.  NULL and err set when
 * out of memory. */
double *rc_grid_values(size_t n, void **block, rc_err *err);
/* A zeroed grid of another shape with g's kind, units, periodic flag,
 * metadata and history (no mask). */
rc_grid *rc_grid_new_like(const rc_grid *g, size_t nx, size_t ny, double lx,
    double ly, rc_err *err);
/* Same shape, units, periodic flag, metadata and history; values, the
 * missing-point and the filled-point masks copied if copy_values. */
rc_grid *rc_grid_clone(const rc_grid *g, int copy_values, rc_err *err);
/* Check nx, ny, nx*ny, lx, ly before allocating; message names the problem. */
int rc_grid_check_shape(size_t nx, size_t ny, double lx, double ly, rc_err *err);

static inline size_t rc_grid_size(const rc_grid *g) { return g->nx * g->ny; }

/* Metadata: set replaces an existing key.  Keys are [A-Za-z0-9_.-]+;
 * a value with a control character other than tab is refused (a header
 * line of surf(5) may not hold one).  Any other byte is kept. */
int rc_grid_meta_set(rc_grid *g, const char *key, const char *val, rc_err *err);
int rc_grid_meta_setf(rc_grid *g, const char *key, rc_err *err,
    const char *fmt, ...) __attribute__((format(printf, 4, 5)));
/* Shortest text that reads back as exactly v. */
int rc_grid_meta_setd(rc_grid *g, const char *key, double v, rc_err *err);
const char *rc_grid_meta_get(const rc_grid *g, const char *key);
/* Remove a key if present. */
void rc_grid_meta_unset(rc_grid *g, const char *key);
/* 1 and *v set if the key exists and parses as a number, else 0. */
int rc_grid_meta_getd(const rc_grid *g, const char *key, double *v);
int rc_grid_meta_copy(rc_grid *dst, const rc_grid *src, rc_err *err);

/* The filled points as text: comma-separated ranges of point indices
 * k = j nx + i, "A-B" for A <= k <= B or "A" alone, increasing and not
 * touching, e.g. "5,130-141,258-269"; "" when there is none.  Malloc'ed;
 * NULL (err set) when out of memory.  A hole of m rows costs m ranges. */
char *rc_grid_filled_format(const rc_grid *g, rc_err *err);
/* Such text (ranges increasing, disjoint, inside the grid; no blanks)
 * into g->filled, replacing it; "" leaves none. */
int rc_grid_filled_parse(rc_grid *g, const char *text, rc_err *err);
/* How many points are filled (0 if filled is NULL). */
size_t rc_grid_filled_count(const rc_grid *g);

/* Append a command line; a control character other than tab is stored as
 * the four characters \xNN, so that any command line can be recorded and
 * read back. */
int rc_grid_history_add(rc_grid *g, const char *line, rc_err *err);

const char *rc_kind_name(enum rc_kind k);
/* Returns -1 for an unknown name. */
int rc_kind_parse(const char *name);

/* Formats v with the fewest digits (up to 17) that read back exactly. */
void rc_format_double(char *buf, size_t len, double v);

/* 1 if all values are finite, else 0 and *bad the first bad index. */
int rc_grid_all_finite(const rc_grid *g, size_t *bad);

#endif
