/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_mnt.c - Digital Surf MountainsMap .mnt documents: their measured
 * surfaces.
 *
 * An .mnt is a Microsoft compound document (OLE2 / CFB: a FAT file system
 * in sectors of 512 or 4096 bytes, whose directory names the streams).
 * The stream ScopedContents holds the document: its size (uint64), then a
 * tree of TLV entries: tag (uint16), size (uint64), then the data or the
 * child entries, all little-endian.  Text is a byte 0x04 then UTF-16LE.
 * Layout as SurfaceTopography's MNT reader documents it:
 *   0x0001 main / 0x02BD contents / 0x0002 document / 0x0001 objects,
 *     whose entries each follow an extra uint64; each object 0x0001 is
 *     0x0001 class (0x0001 uint32 number), 0x0002 body.
 *   A measured surface is class 9012; its body's 0x0001 is an object of
 *   class 9062 whose body is 0xFFFF measurement:
 *     0xFFFF grid: 0xFFFF header / 0xFFFF description / 0x0001 name;
 *       0x0001, 0x0002 the x and y axes: 0xFFFF axis: 0xFFFF scale
 *       (0x0001 step float64, 0x0002 its unit, 0x0003 display unit,
 *       0x0005 origin float64 in the display unit), 0x0001 points uint32;
 *       0x0003 optional mask, class 9056: 0x0002 / 0x0001 width,
 *       0x0002 height, 0x0005 array (class 9048) of (nx+2)(ny+2) bytes
 *       with a one-pixel border, 9 = measured;
 *     0x0001 heights array, class 9049: 0x0002 / 0x0001 count uint32,
 *       0x0002 data;
 *     0x0002 height axis: 0xFFFF scale (as above).
 *   An array's data: its size in bytes (uint64), then blocks of uint64
 *   offset and uint32 count (elements), uint32 compressed size and a zlib
 *   stream; heights are int16 or int32 counts, row by row, x fastest.
 * z = count step + origin; lengths into metres.  Each measured surface is
 * a channel titled by its name.  Every size is checked against what holds
 * it, every stream's sectors against the file.
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#define CFB_MAGIC "\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1"
#define CFB_END 0xfffffffeu	/* ENDOFCHAIN */
#define CLASS_SURFACE 9012
#define CLASS_SURFACE_DATA 9062
#define CLASS_MASK 9056
#define CLASS_ARRAY 9048
#define CLASS_HEIGHTS 9049
#define MASK_MEASURED 9
#define DEFLATE_MAX_RATIO 1100	/* deflate expands at most 1032:1 */

int
rc__mnt_is(const unsigned char *p, size_t n)
{
	return n >= 8 && memcmp(p, CFB_MAGIC, 8) == 0;
}

/* ---- the compound document ---- */

struct cfb {
	const unsigned char *b;
	size_t len, ssize, nsect;
	uint32_t *fat;
	size_t nfat;		/* entries */
};

static const unsigned char *
sector(const struct cfb *c, uint32_t k)
{
	return k < c->nsect ? c->b + (size_t)(k + 1) * c->ssize : NULL;
}

/* The chain from start (at most max bytes, or to its end if max is 0)
 * into a new buffer. */
static int
chain(const struct cfb *c, uint32_t start, uint64_t max, unsigned char **out,
    size_t *outlen, rc_err *err)
{
	size_t n = 0, cap = 0, steps = 0;
	unsigned char *b = NULL, *nb;
	uint32_t k = start;

	while (k != CFB_END && (max == 0 || n < max)) {
		const unsigned char *s = sector(c, k);
		size_t take = c->ssize;

		if (s == NULL || k >= c->nfat || ++steps > c->nsect) {
			free(b);
			return rc_seterr(err, "MountainsMap .mnt: corrupt compound "
			    "document (a sector chain leaves the file or loops)");
		}
		if (max != 0 && max - n < take)
			take = (size_t)(max - n);
		if (n + take > cap) {
			cap = cap ? 2 * cap : 16 * c->ssize;
			if ((nb = realloc(b, cap)) == NULL) {
				free(b);
				return rc_seterr(err, "out of memory");
			}
			b = nb;
		}
		memcpy(b + n, s, take);
		n += take;
		k = c->fat[k];
	}
	if (max != 0 && n < max) {
		free(b);
		return rc_seterr(err, "MountainsMap .mnt: corrupt compound document "
		    "(a stream is shorter than its directory entry says)");
	}
	*out = b;
	*outlen = n;
	return 0;
}

static int
cfb_open(struct cfb *c, const unsigned char *buf, size_t len, rc_err *err)
{
	size_t shift, nfatsect, per, got = 0;
	uint32_t difat;

	memset(c, 0, sizeof(*c));
	if (len < 512)
		return rc_seterr(err, "MountainsMap .mnt: truncated compound "
		    "document header");
	shift = rc__get_le16(buf + 0x1e);
	if (shift != 9 && shift != 12)
		return rc_seterr(err, "MountainsMap .mnt: compound document with "
		    "sectors of 2^%zu bytes (9 or 12 expected)", shift);
	c->b = buf;
	c->len = len;
	c->ssize = (size_t)1 << shift;
	if (len < c->ssize)
		return rc_seterr(err, "MountainsMap .mnt: truncated compound "
		    "document header");
	c->nsect = (len - c->ssize) / c->ssize;
	nfatsect = rc__get_le32(buf + 0x2c);
	per = c->ssize / 4;
	if (nfatsect > c->nsect)
		return rc_seterr(err, "MountainsMap .mnt: corrupt compound document "
		    "(%zu FAT sectors in a file of %zu)", nfatsect, c->nsect);
	if ((c->fat = rc_malloc((nfatsect ? nfatsect : 1) * c->ssize, err)) ==
	    NULL)
		return -1;
	c->nfat = nfatsect * per;
	/* 109 FAT sector numbers in the header, the rest in DIFAT sectors */
	for (size_t k = 0; k < 109 && got < nfatsect; k++, got++) {
		const unsigned char *s = sector(c, rc__get_le32(buf + 0x4c + 4 * k));

		if (s == NULL)
			goto bad;
		for (size_t j = 0; j < per; j++)
			c->fat[got * per + j] = rc__get_le32(s + 4 * j);
	}
	difat = rc__get_le32(buf + 0x44);
	for (size_t steps = 0; got < nfatsect; steps++) {
		const unsigned char *d = sector(c, difat);

		if (d == NULL || steps > c->nsect)
			goto bad;
		for (size_t k = 0; k + 1 < per && got < nfatsect; k++, got++) {
			const unsigned char *s = sector(c, rc__get_le32(d + 4 * k));

			if (s == NULL)
				goto bad;
			for (size_t j = 0; j < per; j++)
				c->fat[got * per + j] = rc__get_le32(s + 4 * j);
		}
		difat = rc__get_le32(d + 4 * (per - 1));
	}
	return 0;
bad:
	free(c->fat);
	c->fat = NULL;
	return rc_seterr(err, "MountainsMap .mnt: corrupt compound document "
	    "(its allocation table lies outside the file)");
}

/* The stream called name (ASCII) into a new buffer. */
static int
cfb_stream(const struct cfb *c, const char *name, unsigned char **out,
    size_t *outlen, rc_err *err)
{
	unsigned char *dir;
	size_t dlen, nl = strlen(name);
	int r = 1;

	if (chain(c, rc__get_le32(c->b + 0x30), 0, &dir, &dlen, err) != 0)
		return -1;
	for (size_t e = 0; e + 128 <= dlen && r == 1; e += 128) {
		const unsigned char *d = dir + e;
		size_t k;
		uint64_t size;

		if (d[66] != 2 || rc__get_le16(d + 64) != 2 * (nl + 1))
			continue;	/* not a stream of that name's length */
		for (k = 0; k < nl; k++)
			if (rc__get_le16(d + 2 * k) != (unsigned char)name[k])
				break;
		if (k < nl)
			continue;
		size = rc__get_le32(d + 120);
		if (c->ssize == 4096)
			size |= (uint64_t)rc__get_le32(d + 124) << 32;
		if (size < rc__get_le32(c->b + 0x38))
			r = rc_seterr(err, "MountainsMap .mnt: stream %s of %llu bytes "
			    "is too small to hold a map", name,
			    (unsigned long long)size);
		else if (size > c->len)
			r = rc_seterr(err, "MountainsMap .mnt: stream %s is longer than "
			    "the file", name);
		else
			r = chain(c, rc__get_le32(d + 116), size, out, outlen, err);
	}
	free(dir);
	if (r == 1)
		return rc_seterr(err, "MountainsMap .mnt: a compound document "
		    "without the stream %s (not a MountainsMap document)", name);
	return r;
}

/* ---- the TLV tree ---- */

struct span {
	const unsigned char *p;
	size_t n;
};

/* The k-th (from 0) child tagged tag in s (each after a uint64 if
 * prefixed); 1 found, 0 not, -1 when the children overrun s. */
static int
child(struct span s, int prefixed, unsigned tag, size_t k, struct span *out)
{
	size_t pos = 0, head = prefixed ? 18 : 10;

	while (pos < s.n) {
		unsigned t;
		uint64_t size;

		if (s.n - pos < head)
			return -1;
		pos += prefixed ? 8 : 0;
		t = rc__get_le16(s.p + pos);
		size = (uint64_t)rc__get_le32(s.p + pos + 2) |
		    (uint64_t)rc__get_le32(s.p + pos + 6) << 32;
		pos += 10;
		if (size > s.n - pos)
			return -1;
		if (t == tag && k-- == 0) {
			out->p = s.p + pos;
			out->n = (size_t)size;
			return 1;
		}
		pos += (size_t)size;
	}
	return 0;
}

/* Follow a path of tags (0 ends it) from s; 1 found. */
static int
path(struct span s, struct span *out, const unsigned *tags)
{
	for (; *tags != 0; tags++)
		if (child(s, 0, *tags, 0, &s) != 1)
			return 0;
	*out = s;
	return 1;
}

/* The bytes of a child of exactly size bytes. */
static const unsigned char *
fixed(struct span s, unsigned tag, size_t size)
{
	struct span c;

	return child(s, 0, tag, 0, &c) == 1 && c.n == size ? c.p : NULL;
}

static int
get_u32(struct span s, unsigned tag, uint32_t *v)
{
	const unsigned char *p = fixed(s, tag, 4);

	if (p != NULL)
		*v = rc__get_le32(p);
	return p != NULL;
}

static int
get_f64(struct span s, unsigned tag, double *v)
{
	const unsigned char *p = fixed(s, tag, 8);

	if (p != NULL)
		*v = rc__get_le64(p);
	return p != NULL;
}

/* A text entry as UTF-8 (characters up to U+07FF) into dst (cap bytes). */
static int
get_text(struct span s, unsigned tag, char *dst, size_t cap)
{
	struct span c;
	size_t n = 0;

	if (child(s, 0, tag, 0, &c) != 1 || c.n < 1 || c.p[0] != 0x04 ||
	    (c.n - 1) % 2 != 0)
		return 0;
	for (size_t k = 1; k + 1 < c.n; k += 2) {
		unsigned u = rc__get_le16(c.p + k);

		if (u == 0)
			break;
		if (n + 3 > cap)
			return 0;
		if (u < 0x80)
			dst[n++] = (char)u;
		else if (u < 0x800) {
			dst[n++] = (char)(0xc0 | u >> 6);
			dst[n++] = (char)(0x80 | (u & 0x3f));
		} else
			dst[n++] = '?';
	}
	dst[n] = '\0';
	return 1;
}

/* An object's class number and body. */
static int
object(struct span o, uint32_t *cls, struct span *body)
{
	struct span c;

	return child(o, 0, 1, 0, &c) == 1 && get_u32(c, 1, cls) &&
	    child(o, 0, 2, 0, body) == 1;
}

/* An axis scale (0xFFFF of an axis): the step in metres and the origin in
 * metres (heights) or the unit of a value that is no length (z_unit). */
struct scale {
	double step, origin;
	char unit[32];		/* "m", or the file's unit if no length */
};

static int
scale_of(struct span axis, struct scale *sc, rc_err *err)
{
	char u[64], du[64], unit[32], dunit[32];
	struct span s;
	double per, dper;

	if (child(axis, 0, 0xffff, 0, &s) != 1 || !get_f64(s, 1, &sc->step) ||
	    !get_text(s, 2, u, sizeof(u)))
		return rc_seterr(err, "MountainsMap .mnt: an axis without its "
		    "step and unit");
	if (!get_text(s, 3, du, sizeof(du)) || du[0] == '\0')
		strcpy(du, u);
	sc->origin = 0;
	get_f64(s, 5, &sc->origin);
	if (rc__io_set_unit(unit, u, err) != 0 ||
	    rc__io_set_unit(dunit, du, err) != 0)
		return -1;
	per = rc__io_per_metre(unit);
	dper = rc__io_per_metre(dunit);
	if (!(isfinite(sc->step) && isfinite(sc->origin)))
		return rc_seterr(err, "MountainsMap .mnt: an axis step of %g",
		    sc->step);
	if (per > 0 && dper > 0) {
		sc->step /= per;
		sc->origin /= dper;
		strcpy(sc->unit, "m");
	} else
		strcpy(sc->unit, unit);
	return 0;
}

/* An array object (class cls) of count elements of esize bytes each
 * (esize 0: 2 or 4, as the data say) into a new buffer. */
static int
array(struct span obj, uint32_t cls, size_t count, size_t *esize,
    unsigned char **out, rc_err *err)
{
	struct span body, data;
	uint32_t c, n;
	uint64_t nbytes;
	size_t pos = 8, done = 0;
	unsigned char *b;

	if (!object(obj, &c, &body) || c != cls || !get_u32(body, 1, &n) ||
	    child(body, 0, 2, 0, &data) != 1 || data.n < 8)
		return rc_seterr(err, "MountainsMap .mnt: a data array without "
		    "its class %u, count or data", (unsigned)cls);
	nbytes = (uint64_t)rc__get_le32(data.p) |
	    (uint64_t)rc__get_le32(data.p + 4) << 32;
	if (n != count || count == 0 || nbytes % count != 0 ||
	    (*esize != 0 && nbytes / count != *esize) ||
	    (*esize == 0 && nbytes / count != 2 && nbytes / count != 4))
		return rc_seterr(err, "MountainsMap .mnt: a data array of %u "
		    "elements in %llu bytes where %zu are expected", (unsigned)n,
		    (unsigned long long)nbytes, count);
	if (nbytes / DEFLATE_MAX_RATIO > data.n)
		return rc_seterr(err, "MountainsMap .mnt: a data array of %llu "
		    "bytes cannot be in %zu compressed bytes",
		    (unsigned long long)nbytes, data.n);
	*esize = (size_t)(nbytes / count);
	if ((b = rc_calloc((size_t)nbytes, 1, err)) == NULL)
		return -1;
	while (pos < data.n) {
		uint64_t off;
		uint32_t ne, clen;
		uLongf got;

		if (data.n - pos < 16)
			goto bad;
		off = (uint64_t)rc__get_le32(data.p + pos) |
		    (uint64_t)rc__get_le32(data.p + pos + 4) << 32;
		ne = rc__get_le32(data.p + pos + 8);
		clen = rc__get_le32(data.p + pos + 12);
		pos += 16;
		if (clen > data.n - pos || off > count || ne > count - off)
			goto bad;
		got = (uLongf)(ne * *esize);
		if (uncompress(b + off * *esize, &got, data.p + pos, clen) != Z_OK ||
		    got != ne * *esize)
			goto bad;
		pos += clen;
		done += got;
	}
	if (done != nbytes)
		goto bad;
	*out = b;
	return 0;
bad:
	free(b);
	return rc_seterr(err, "MountainsMap .mnt: corrupt compressed data "
	    "array");
}

/* The channel of one measured surface (class 9012 body); 0 also when it
 * holds no height map. */
static int
surface(struct span body, rc_chanset *s, rc_err *err)
{
	static const unsigned to_meas[] = { 0xffff, 0 };
	static const unsigned to_name[] = { 0xffff, 0xffff, 0 };
	struct span o, meas, grid, xa, ya, ha, hobj, mobj, mbody, b, xaxis, yaxis;
	struct scale xs, ys, zs;
	uint32_t cls, nx, ny, mw, mh;
	unsigned char *h = NULL, *m = NULL;
	size_t esize = 0, n;
	char title[128];
	rc_grid *g;

	if (child(body, 0, 1, 0, &o) != 1 || !object(o, &cls, &b) ||
	    cls != CLASS_SURFACE_DATA || !path(b, &meas, to_meas))
		return 0;	/* no measurement in it */
	if (child(meas, 0, 0xffff, 0, &grid) != 1 ||
	    child(grid, 0, 1, 0, &xa) != 1 || child(grid, 0, 2, 0, &ya) != 1 ||
	    child(xa, 0, 0xffff, 0, &xaxis) != 1 ||
	    child(ya, 0, 0xffff, 0, &yaxis) != 1 ||
	    child(meas, 0, 1, 0, &hobj) != 1 || child(meas, 0, 2, 0, &ha) != 1)
		return rc_seterr(err, "MountainsMap .mnt: a measured surface "
		    "without its axes or heights");
	if (!get_u32(xaxis, 1, &nx) || !get_u32(yaxis, 1, &ny))
		return rc_seterr(err, "MountainsMap .mnt: an axis without its "
		    "number of points");
	if (scale_of(xaxis, &xs, err) != 0 || scale_of(yaxis, &ys, err) != 0 ||
	    scale_of(ha, &zs, err) != 0)
		return -1;
	if (strcmp(xs.unit, "m") != 0 || strcmp(ys.unit, "m") != 0)
		return rc_seterr(err, "MountainsMap .mnt: lateral unit '%s' is no "
		    "length", strcmp(xs.unit, "m") ? xs.unit : ys.unit);
	if (!(xs.step > 0 && ys.step > 0))
		return rc_seterr(err, "MountainsMap .mnt: grid spacing %g x %g",
		    xs.step, ys.step);
	if (rc_grid_check_shape(nx, ny, nx * xs.step, ny * ys.step, err) != 0)
		return -1;
	n = (size_t)nx * ny;
	if (array(hobj, CLASS_HEIGHTS, n, &esize, &h, err) != 0)
		return -1;
	/* an object of another class (0 in a file without a mask) there is
	 * no mask */
	if (child(grid, 0, 3, 0, &mobj) == 1 && object(mobj, &cls, &mbody) &&
	    cls == CLASS_MASK) {
		size_t one = 1;

		if (!get_u32(mbody, 1, &mw) || !get_u32(mbody, 2, &mh) ||
		    mw != nx || mh != ny || child(mbody, 0, 5, 0, &mobj) != 1) {
			free(h);
			return rc_seterr(err, "MountainsMap .mnt: a mask that does "
			    "not fit the grid");
		}
		if (array(mobj, CLASS_ARRAY, (size_t)(nx + 2) * (ny + 2), &one, &m,
		    err) != 0) {
			free(h);
			return -1;
		}
	}
	if ((g = rc__io_grid_alloc(nx, ny, nx * xs.step, ny * ys.step, err)) ==
	    NULL) {
		free(h);
		free(m);
		return -1;
	}
	for (size_t k = 0; k < n; k++) {
		double c = esize == 2 ? (int16_t)rc__get_le16(h + 2 * k) :
		    (int32_t)rc__get_le32(h + 4 * k);

		g->z[k] = c * zs.step + zs.origin;
		if (m != NULL && m[(k / nx + 1) * (nx + 2) + k % nx + 1] !=
		    MASK_MEASURED)
			g->z[k] = NAN;
	}
	free(h);
	free(m);
	if (rc__io_nan_missing(g, err) != 0) {
		rc_grid_free(g);
		return -1;
	}
	strcpy(g->unit, "m");
	strcpy(g->z_unit, zs.unit);
	g->periodic = 0;	/* a measurement */
	if (!path(grid, &b, to_name) || !get_text(b, 1, title, sizeof(title)) ||
	    title[0] == '\0')
		snprintf(title, sizeof(title), "surface %zu", s->n + 1);
	return rc__chanset_add(s, g, title, err);
}

int
rc__mnt_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	static const unsigned to_objects[] = { 1, 0x02bd, 2, 1, 0 };
	struct cfb c;
	unsigned char *sc = NULL;
	size_t sclen, k;
	struct span objs, ob, body;
	uint32_t cls;
	int r = -1, found;

	(void)o;
	if (cfb_open(&c, buf, len, err) != 0)
		return -1;
	if (cfb_stream(&c, "ScopedContents", &sc, &sclen, err) != 0)
		goto out;
	if (sclen < 8 || !path((struct span){ sc + 8, sclen - 8 }, &objs,
	    to_objects)) {
		rc_seterr(err, "MountainsMap .mnt: ScopedContents without the list "
		    "of document objects");
		goto out;
	}
	for (k = 0; (found = child(objs, 1, 1, k, &ob)) == 1; k++)
		if (object(ob, &cls, &body) && cls == CLASS_SURFACE &&
		    surface(body, s, err) != 0)
			goto out;
	if (found < 0) {
		rc_seterr(err, "MountainsMap .mnt: corrupt list of document "
		    "objects");
		goto out;
	}
	if (s->n == 0) {
		rc_seterr(err, "MountainsMap .mnt: no measured surface in the "
		    "document (%zu objects)", k);
		goto out;
	}
	r = 0;
out:
	free(sc);
	free(c.fat);
	if (r != 0)
		rc__chanset_free(s);
	return r;
}
