/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_nms.c - NanoFocus .nms (confocal microscope, "OM_MS_2.0").
 *
 * A 3468-byte header, then the height map and, in the example files, an
 * intensity image; little-endian.  Header fields read (offsets as
 * SurfaceTopography's NMS reader has them, which has no magic either):
 *   16    float64  zmin, zmax (um): the range of the heights
 *   1352  uint32   3468, the size of the header (our signature)
 *   1368  uint32   nx, ny
 *   1376  float64  dx, dy: the spacing
 *   3468  nx*ny uint16 heights, row by row, x fastest:
 *         z = zmin + v (zmax - zmin) / 65535
 *   then  nx*ny uint8 intensities (optional)
 * Two departures from SurfaceTopography's reader, from the example files:
 * the height divisor is 65535, not 65534 (each file has exactly one 0 and
 * one 65535 and no 65534: the range [zmin, zmax] spans all 16 bits), and
 * the spacing is in nm, not mm (312.5: a 160 um field of 512 points, the
 * field of a confocal 100x objective; in mm the field would be 160 m).
 * The file's length must be the header and the heights, with or without
 * the intensities: that and the header-size field recognise the format.
 */
#include "io_internal.h"

#include <math.h>
#include <string.h>

#define NMS_HEADER 3468
#define NMS_NM 1e-9	/* metres per unit of the spacing */
#define NMS_UM 1e-6	/* metres per unit of the heights */

struct nms {
	size_t nx, ny;
	double dx, dy, zmin, zmax;
	int intensity;
};

/* The header's fields if buf is an NMS file, else 0. */
static int
parse(const unsigned char *buf, size_t len, struct nms *h)
{
	size_t n;

	if (len < NMS_HEADER || rc__get_le32(buf + 1352) != NMS_HEADER)
		return 0;
	h->nx = rc__get_le32(buf + 1368);
	h->ny = rc__get_le32(buf + 1372);
	h->dx = rc__get_le64(buf + 1376);
	h->dy = rc__get_le64(buf + 1384);
	h->zmin = rc__get_le64(buf + 16);
	h->zmax = rc__get_le64(buf + 24);
	if (h->nx < 1 || h->ny < 1 || h->nx > RC_GRID_MAX_DIM ||
	    h->ny > RC_GRID_MAX_DIM)
		return 0;
	n = h->nx * h->ny;
	if (len - NMS_HEADER == 2 * n)
		h->intensity = 0;
	else if (len - NMS_HEADER == 3 * n)
		h->intensity = 1;
	else
		return 0;
	return 1;
}

int
rc__nms_is(const unsigned char *buf, size_t len)
{
	struct nms h;

	return parse(buf, len, &h);
}

int
rc__nms_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	const unsigned char *v = buf + NMS_HEADER;
	struct nms h;
	double lx, ly;
	rc_grid *g;
	size_t n;

	(void)o;
	if (!parse(buf, len, &h))
		return rc_seterr(err, "NanoFocus .nms: the file's length is not "
		    "that of the header and the map its header describes");
	if (!(isfinite(h.dx) && h.dx > 0 && isfinite(h.dy) && h.dy > 0))
		return rc_seterr(err, "NanoFocus .nms: corrupt header: spacing %g x "
		    "%g nm", h.dx, h.dy);
	if (!(isfinite(h.zmin) && isfinite(h.zmax) && h.zmax >= h.zmin))
		return rc_seterr(err, "NanoFocus .nms: corrupt header: height range "
		    "%g to %g um", h.zmin, h.zmax);
	n = h.nx * h.ny;
	lx = (double)h.nx * h.dx * NMS_NM;
	ly = (double)h.ny * h.dy * NMS_NM;
	if ((g = rc__io_grid_alloc(h.nx, h.ny, lx, ly, err)) == NULL)
		return -1;
	for (size_t k = 0; k < n; k++)
		g->z[k] = (h.zmin + rc__get_le16(v + 2 * k) * (h.zmax - h.zmin) /
		    65535) * NMS_UM;
	strcpy(g->unit, "m");
	strcpy(g->z_unit, "m");
	g->periodic = 0;	/* a measurement */
	if (rc__chanset_add(s, g, "Height", err) != 0)
		goto fail;
	if (h.intensity) {
		if ((g = rc__io_grid_alloc(h.nx, h.ny, lx, ly, err)) == NULL)
			goto fail;
		for (size_t k = 0; k < n; k++)
			g->z[k] = v[2 * n + k];
		strcpy(g->unit, "m");
		strcpy(g->z_unit, "1");	/* no length: refused as heights */
		g->periodic = 0;
		if (rc__chanset_add(s, g, "Intensity", err) != 0)
			goto fail;
	}
	return 0;
fail:
	rc__chanset_free(s);
	return -1;
}
