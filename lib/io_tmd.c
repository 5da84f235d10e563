/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_tmd.c - TrueMap .tmd (binary TrueMap data file, version 2.0).
 *
 * Layout (all little-endian), as SurfaceTopography's TMD reader and its
 * synthetic test files have it:
 *   0   32 bytes  "Binary TrueMap Data File v2.0\r\n" and a NUL
 *   32  24 bytes  comment ("Created by TrueMap v6\r\n" and a NUL)
 *   56  uint32    nx
 *   60  uint32    ny
 *   64  float32   lx, ly (mm)
 *   72  float32   x and y offset (mm; not read)
 *   80  nx*ny float32 heights (mm), row by row, x fastest
 * Lengths and heights are millimetres (the example file is a 19 mm field
 * with a 0.35 mm height range); they are read into metres.  A NaN height is
 * a missing point.  Nothing may follow the heights.
 */
#include "io_internal.h"

#include <math.h>
#include <string.h>

#define TMD_MAGIC "Binary TrueMap Data File v2.0"
#define TMD_HEADER 80
#define MM 1e-3		/* metres per millimetre */

int
rc__tmd_is(const unsigned char *p, size_t n)
{
	return n >= sizeof(TMD_MAGIC) - 1 &&
	    memcmp(p, TMD_MAGIC, sizeof(TMD_MAGIC) - 1) == 0;
}

static double
get_f32(const unsigned char *p)
{
	uint32_t u = rc__get_le32(p);
	float f;

	memcpy(&f, &u, sizeof(f));
	return f;
}

int
rc__tmd_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	size_t nx, ny, n;
	double lx, ly;
	rc_grid *g;

	(void)o;
	if (len < TMD_HEADER)
		return rc_seterr(err, "TrueMap .tmd: truncated header (%zu bytes, "
		    "need %d)", len, TMD_HEADER);
	nx = rc__get_le32(buf + 56);
	ny = rc__get_le32(buf + 60);
	lx = get_f32(buf + 64) * MM;
	ly = get_f32(buf + 68) * MM;
	if (nx < 1 || ny < 1 || nx > RC_GRID_MAX_DIM || ny > RC_GRID_MAX_DIM)
		return rc_seterr(err, "TrueMap .tmd: corrupt header: %zu x %zu "
		    "points", nx, ny);
	if (!(isfinite(lx) && lx > 0 && isfinite(ly) && ly > 0))
		return rc_seterr(err, "TrueMap .tmd: corrupt header: size %g x %g "
		    "mm", lx / MM, ly / MM);
	n = nx * ny;	/* both < 2^24: no overflow */
	if ((len - TMD_HEADER) / 4 != n || (len - TMD_HEADER) % 4 != 0)
		return rc_seterr(err, "TrueMap .tmd: %s: %zu x %zu float32 heights "
		    "take %zu bytes after the %d-byte header, the file has %zu",
		    len - TMD_HEADER < 4 * n ? "truncated" : "data after the heights",
		    nx, ny, 4 * n, TMD_HEADER, len - TMD_HEADER);
	if ((g = rc__io_grid_alloc(nx, ny, lx, ly, err)) == NULL)
		return -1;
	for (size_t k = 0; k < n; k++)
		g->z[k] = get_f32(buf + TMD_HEADER + 4 * k) * MM;
	strcpy(g->unit, "m");
	strcpy(g->z_unit, "m");
	g->periodic = 0;	/* a measurement */
	if (rc__io_nan_missing(g, err) != 0) {
		rc_grid_free(g);
		return -1;
	}
	return rc__chanset_add(s, g, "Height", err);
}
