/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_opdx.c - Bruker Dektak .OPDx (Vision64, "VCA DATA"): profiles and
 * maps of the Dektak stylus profilers.
 *
 * After the 12-byte magic "VCA DATA" 01 00 00 55 the file is a tree of
 * named items, little-endian throughout:
 *   item   = name, type (1 byte), content
 *   name   = uint32 n, n bytes (UTF-8); the empty name with type 0x7f ends
 *            a container (and the file)
 *   varlen = 1 byte k (1, 2 or 4), then the length as a k-byte integer
 * Contents by type: 0x7d, 0x46, 0x47 containers: varlen L, then items up
 * to the terminator and two more bytes, L in all; 0x01 1 byte, 0x04/0x05 2,
 * 0x06/0x07/0x0c 4, 0x0a/0x0b/0x0d 8 (0x0c float32, 0x0d float64, 0x0b
 * uint64); 0x15 a 9-byte time stamp; 0x12 string: varlen, bytes;
 * 0x13 quantity: varlen L, then float64 value, name, symbol (unit);
 * 0x18 unit: varlen L, name, symbol, float64 value, 12 bytes;
 * 0x0e, 0x40, 0x42, 0x7c: a type name, then varlen L and L bytes (0x40 an
 * array of doubles after 5 bytes, 0x42 a list of names); 0x00 matrix: a
 * type name, uint32, a name, varlen L, uint32 rows, uint32 columns and
 * L - 8 bytes of float32, row by row; 0x45 the same without the uint32
 * and the name.
 * A profile is /1D_Data/NAME/Array (NumPoints doubles), heights Array
 * times the quantity DataScale; a map is /2D_Data/NAME/Matrix, ny =
 * Dimension1Points rows of nx = Dimension2Points floats times DataScale.
 * The quantities Extent (Dimension2Extent, Dimension1Extent for maps) are
 * the distance from the first to the last point: the physical size is
 * Extent n / (n - 1).  Lengths are read into metres; NaN is a missing
 * point.  Every length and offset is checked against the file's before
 * use.  Layout as SurfaceTopography's OPDx reader (after Gwyddion's
 * dektakvca.c) reads it; the example file opdx-3.opdx agrees with its
 * text export to the 8 digits of the export.
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define OPDX_MAGIC "VCA DATA\x01\x00\x00\x55"
#define OPDX_MAGIC_LEN 12
#define MAX_DEPTH 16	/* the example nests 3 deep */
#define MAX_PATH 256

int
rc__opdx_is(const unsigned char *p, size_t n)
{
	return n >= OPDX_MAGIC_LEN && memcmp(p, OPDX_MAGIC, OPDX_MAGIC_LEN) == 0;
}

/* The items we use, by path. */
struct entry {
	char path[MAX_PATH];
	int type;
	double value;		/* scalars, quantities */
	char symbol[32];	/* quantities: the unit's symbol */
	size_t off, len;	/* arrays, matrices: the values' bytes */
	size_t rows, cols;	/* matrices */
};

struct parser {
	const unsigned char *b;
	size_t len, pos;
	struct entry *e;
	size_t n, cap;
	rc_err *err;
};

static int
corrupt(struct parser *p, const char *what)
{
	return rc_seterr(p->err, "Dektak .OPDx: corrupt or truncated at byte "
	    "%zu: %s", p->pos, what);
}

static int
need(struct parser *p, size_t n, const char *what)
{
	if (p->len - p->pos < n)
		return corrupt(p, what);
	return 0;
}

static int
get_u32(struct parser *p, uint32_t *v)
{
	if (need(p, 4, "a 4-byte integer past the end") != 0)
		return -1;
	*v = rc__get_le32(p->b + p->pos);
	p->pos += 4;
	return 0;
}

static int
get_varlen(struct parser *p, size_t *v)
{
	unsigned k;

	if (need(p, 1, "a length past the end") != 0)
		return -1;
	k = p->b[p->pos++];
	if (k != 1 && k != 2 && k != 4)
		return corrupt(p, "a length of an unknown size");
	if (need(p, k, "a length past the end") != 0)
		return -1;
	*v = k == 1 ? p->b[p->pos] : k == 2 ? rc__get_le16(p->b + p->pos) :
	    rc__get_le32(p->b + p->pos);
	p->pos += k;
	return need(p, *v, "an item longer than the file");
}

/* A name: its bytes at *s, *n of them. */
static int
get_name(struct parser *p, const unsigned char **s, size_t *n)
{
	uint32_t len;

	if (get_u32(p, &len) != 0 || need(p, len, "a name past the end") != 0)
		return -1;
	*s = p->b + p->pos;
	*n = len;
	p->pos += len;
	return 0;
}

static struct entry *
add(struct parser *p, const char *path, int type)
{
	struct entry *e;

	if (p->n == p->cap) {
		size_t cap = p->cap ? 2 * p->cap : 64;

		if ((e = realloc(p->e, cap * sizeof(*e))) == NULL) {
			rc_seterr(p->err, "out of memory");
			return NULL;
		}
		p->e = e;
		p->cap = cap;
	}
	e = &p->e[p->n++];
	memset(e, 0, sizeof(*e));
	snprintf(e->path, sizeof(e->path), "%s", path);
	e->type = type;
	return e;
}

static int scalar_size(int type)
{
	switch (type) {
	case 0x01: return 1;
	case 0x04: case 0x05: return 2;
	case 0x06: case 0x07: case 0x0c: return 4;
	case 0x0a: case 0x0b: case 0x0d: return 8;
	case 0x15: return 9;
	default: return 0;
	}
}

static double
scalar_value(const unsigned char *q, int type)
{
	uint32_t u;
	float f;

	switch (type) {
	case 0x01: return q[0];
	case 0x04: return (int16_t)rc__get_le16(q);
	case 0x05: return rc__get_le16(q);
	case 0x06: return (int32_t)rc__get_le32(q);
	case 0x07: return rc__get_le32(q);
	case 0x0c:
		u = rc__get_le32(q);
		memcpy(&f, &u, 4);
		return f;
	case 0x0a:
		return (double)(int64_t)((uint64_t)rc__get_le32(q) |
		    (uint64_t)rc__get_le32(q + 4) << 32);
	case 0x0b:
		return (double)((uint64_t)rc__get_le32(q) |
		    (uint64_t)rc__get_le32(q + 4) << 32);
	case 0x0d: return rc__get_le64(q);
	default: return 0;
	}
}

/* Items up to the terminator (end: the container's last byte + 1). */
static int items(struct parser *p, const char *prefix, size_t end, int depth);

static int
item(struct parser *p, const char *prefix, size_t end, int depth, int *done)
{
	const unsigned char *nm, *s;
	char path[MAX_PATH];
	size_t nlen, L, start, slen;
	struct entry *e;
	int type;

	if (get_name(p, &nm, &nlen) != 0 || need(p, 1, "an item without a "
	    "type") != 0)
		return -1;
	type = p->b[p->pos++];
	if (type == 0x7f) {
		*done = 1;
		return 0;
	}
	if (strlen(prefix) + 1 + nlen >= sizeof(path))
		return corrupt(p, "an item's path is too long");
	snprintf(path, sizeof(path), "%s/%.*s", prefix, (int)nlen,
	    (const char *)nm);
	if (memchr(nm, '\0', nlen) != NULL)
		return corrupt(p, "a NUL byte in a name");
	if (type == 0x7d || type == 0x46 || type == 0x47) {
		if (depth >= MAX_DEPTH)
			return corrupt(p, "containers nested too deep");
		if (get_varlen(p, &L) != 0)
			return -1;
		start = p->pos;
		if (start + L > end)
			return corrupt(p, "a container longer than its parent");
		if (items(p, path, start + L, depth + 1) != 0)
			return -1;
		/* two bytes after the terminator belong to the container */
		if (p->pos > start + L)
			return corrupt(p, "a container overruns its length");
		p->pos = start + L;
		return 0;
	}
	if (scalar_size(type) > 0) {
		if (need(p, (size_t)scalar_size(type), "a value past the end") != 0)
			return -1;
		if ((e = add(p, path, type)) == NULL)
			return -1;
		e->value = scalar_value(p->b + p->pos, type);
		p->pos += (size_t)scalar_size(type);
		return 0;
	}
	switch (type) {
	case 0x12:	/* string: skipped */
		return get_varlen(p, &L) != 0 ? -1 : (p->pos += L, 0);
	case 0x13:	/* quantity: value, name, symbol */
		if (get_varlen(p, &L) != 0)
			return -1;
		start = p->pos;
		if (L < 8)
			return corrupt(p, "a quantity shorter than its value");
		if ((e = add(p, path, type)) == NULL)
			return -1;
		e->value = rc__get_le64(p->b + p->pos);
		p->pos += 8;
		{
			struct parser q = *p;

			/* the names inside the quantity's L bytes */
			q.len = start + L;
			if (get_name(&q, &s, &slen) != 0 ||
			    get_name(&q, &s, &slen) != 0) {
				p->pos = q.pos;
				return -1;
			}
			if (slen >= sizeof(e->symbol) || memchr(s, '\0', slen))
				return corrupt(p, "a unit symbol too long");
			memcpy(e->symbol, s, slen);
		}
		p->pos = start + L;
		return 0;
	case 0x18:	/* unit: skipped */
		return get_varlen(p, &L) != 0 ? -1 : (p->pos += L, 0);
	case 0x0e: case 0x40: case 0x42: case 0x7c:
		if (get_name(p, &s, &slen) != 0 || get_varlen(p, &L) != 0)
			return -1;
		if (type == 0x40) {
			if ((e = add(p, path, type)) == NULL)
				return -1;
			e->off = p->pos;
			e->len = L;
		}
		p->pos += L;
		return 0;
	case 0x00: case 0x45:
		if (get_name(p, &s, &slen) != 0)
			return -1;
		if (type == 0x00) {
			uint32_t skip;

			if (get_u32(p, &skip) != 0 || get_name(p, &s, &slen) != 0)
				return -1;
		}
		if (get_varlen(p, &L) != 0)
			return -1;
		if (L < 8)
			return corrupt(p, "a matrix shorter than its size");
		if ((e = add(p, path, type)) == NULL)
			return -1;
		e->rows = rc__get_le32(p->b + p->pos);
		e->cols = rc__get_le32(p->b + p->pos + 4);
		e->off = p->pos + 8;
		e->len = L - 8;
		p->pos += L;
		return 0;
	default:
		return rc_seterr(p->err, "Dektak .OPDx: item '%s' at byte %zu has "
		    "type 0x%02x, which no reader knows", path, p->pos - 1, type);
	}
}

static int
items(struct parser *p, const char *prefix, size_t end, int depth)
{
	int done = 0;
	size_t len = p->len;

	p->len = end;	/* nothing of a container reads past its end */
	while (!done)
		if (item(p, prefix, end, depth, &done) != 0)
			return -1;
	p->len = len;
	return 0;
}

static const struct entry *
find(const struct parser *p, const char *prefix, const char *key, int type)
{
	char path[2 * MAX_PATH];

	snprintf(path, sizeof(path), "%s/%s", prefix, key);
	for (size_t k = 0; k < p->n; k++)
		if (p->e[k].type == type && strcmp(p->e[k].path, path) == 0)
			return &p->e[k];
	return NULL;
}

/* A quantity's value in metres (or in its own unit if that is no length:
 * *unit says which). */
static int
quantity(const struct parser *p, const char *prefix, const char *key,
    double *v, char unit[32], rc_err *err)
{
	const struct entry *e = find(p, prefix, key, 0x13);
	double per_m;

	if (e == NULL)
		return rc_seterr(err, "Dektak .OPDx: %s has no %s", prefix, key);
	if (rc__io_set_unit(unit, e->symbol, err) != 0)
		return -1;
	per_m = rc__io_per_metre(unit);
	*v = per_m > 0 ? e->value / per_m : e->value;
	if (per_m > 0)
		strcpy(unit, "m");
	return 0;
}

/* The count of points along an axis (a scalar). */
static int
count(const struct parser *p, const char *prefix, const char *key, size_t *n,
    rc_err *err)
{
	const struct entry *e = find(p, prefix, key, 0x0b);

	if (e == NULL)
		e = find(p, prefix, key, 0x07);
	if (e == NULL)
		return rc_seterr(err, "Dektak .OPDx: %s has no %s", prefix, key);
	if (!(e->value >= 1 && e->value <= RC_GRID_MAX_DIM))
		return rc_seterr(err, "Dektak .OPDx: %s/%s is %g", prefix, key,
		    e->value);
	*n = (size_t)e->value;
	return 0;
}

static double
size_of(double extent, size_t n)
{
	return n > 1 ? extent * (double)n / (double)(n - 1) : extent;
}

/* The channel whose values are entry v (Array or Matrix) of prefix. */
static int
channel(const struct parser *p, const struct entry *v, const char *prefix,
    rc_chanset *s, rc_err *err)
{
	char xunit[32], yunit[32], zunit[32];
	double lx, ly = 0, scale;
	size_t nx, ny = 1, n;
	int map = v->type != 0x40;
	rc_grid *g;

	if (quantity(p, prefix, "DataScale", &scale, zunit, err) != 0)
		return -1;
	if (!map) {
		if (count(p, prefix, "NumPoints", &nx, err) != 0 ||
		    quantity(p, prefix, "Extent", &lx, xunit, err) != 0)
			return -1;
		if (v->len < 5 || (v->len - 5) / 8 != nx || (v->len - 5) % 8 != 0)
			return rc_seterr(err, "Dektak .OPDx: %s holds %zu bytes for "
			    "NumPoints %zu doubles", v->path, v->len, nx);
		strcpy(yunit, xunit);
	} else {
		if (count(p, prefix, "Dimension2Points", &nx, err) != 0 ||
		    count(p, prefix, "Dimension1Points", &ny, err) != 0 ||
		    quantity(p, prefix, "Dimension2Extent", &lx, xunit, err) != 0 ||
		    quantity(p, prefix, "Dimension1Extent", &ly, yunit, err) != 0)
			return -1;
		if (v->rows != ny || v->cols != nx || v->len / 4 != nx * ny ||
		    v->len % 4 != 0)
			return rc_seterr(err, "Dektak .OPDx: %s is %zu x %zu with %zu "
			    "bytes, the header says %zu x %zu float32", v->path, v->cols,
			    v->rows, v->len, nx, ny);
		ly = size_of(ly, ny);
	}
	if (strcmp(xunit, "m") != 0 || strcmp(yunit, "m") != 0)
		return rc_seterr(err, "Dektak .OPDx: %s: lateral unit '%s' is no "
		    "length", prefix, strcmp(xunit, "m") != 0 ? xunit : yunit);
	lx = size_of(lx, nx);
	if (!map)
		ly = lx / (double)nx;	/* a profile: one row, one spacing high */
	if (!(isfinite(scale) && scale != 0))
		return rc_seterr(err, "Dektak .OPDx: %s/DataScale is %g", prefix,
		    scale);
	if ((g = rc__io_grid_alloc(nx, ny, lx, ly, err)) == NULL)
		return -1;
	n = nx * ny;
	for (size_t k = 0; k < n; k++) {
		double raw;

		if (map) {
			uint32_t u = rc__get_le32(p->b + v->off + 4 * k);
			float f;

			memcpy(&f, &u, 4);
			raw = f;
		} else
			raw = rc__get_le64(p->b + v->off + 5 + 8 * k);
		g->z[k] = raw * scale;
	}
	strcpy(g->unit, "m");
	strcpy(g->z_unit, zunit);
	g->periodic = 0;	/* a measurement */
	if (rc__io_nan_missing(g, err) != 0) {
		rc_grid_free(g);
		return -1;
	}
	return rc__chanset_add(s, g, prefix + 9, err);	/* after /1D_Data/ */
}

int
rc__opdx_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	struct parser p = { buf, len, OPDX_MAGIC_LEN, NULL, 0, 0, err };
	int r = -1;

	(void)o;
	if (!rc__opdx_is(buf, len))
		return rc_seterr(err, "Dektak .OPDx: no magic 'VCA DATA'");
	if (items(&p, "", len, 0) != 0)
		goto out;
	for (size_t k = 0; k < p.n; k++) {
		const struct entry *e = &p.e[k];
		char prefix[MAX_PATH];
		size_t pl = strlen(e->path);

		if (!((e->type == 0x40 && strncmp(e->path, "/1D_Data/", 9) == 0 &&
		    pl > 15 && strcmp(e->path + pl - 6, "/Array") == 0) ||
		    ((e->type == 0x00 || e->type == 0x45) &&
		    strncmp(e->path, "/2D_Data/", 9) == 0 && pl > 16 &&
		    strcmp(e->path + pl - 7, "/Matrix") == 0)))
			continue;
		memcpy(prefix, e->path, pl - (e->type == 0x40 ? 6 : 7));
		prefix[pl - (e->type == 0x40 ? 6 : 7)] = '\0';
		if (channel(&p, e, prefix, s, err) != 0)
			goto out;
	}
	if (s->n == 0) {
		rc_seterr(err, "Dektak .OPDx: no profile (/1D_Data/NAME/Array) or "
		    "map (/2D_Data/NAME/Matrix) in the file");
		goto out;
	}
	r = 0;
out:
	free(p.e);
	if (r != 0)
		rc__chanset_free(s);
	return r;
}
