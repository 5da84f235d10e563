/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_sdf.c - ISO 25178-71 surface data files (SDF), ASCII and binary;
 * also their predecessor (EUNA 15178, "BCR").
 *
 * ASCII: the line "aISO-1.0" (or "aBCR-1.0"), "Name = Value" lines
 * (ManufacID, CreateDate, ModDate, NumPoints, NumProfiles, Xscale,
 * Yscale, Zscale, Zresolution, Compression, DataType, CheckType, ...), a
 * line "*", NumPoints x NumProfiles numbers (profile after profile, "BAD"
 * for a missing point), "*", an optional trailer, "*".
 * Binary: "bISO-1.0" (or "bBCR-1.0"), then ManufacID (10 bytes),
 * CreateDate (12), ModDate (12), NumPoints and NumProfiles (uint16),
 * Xscale, Yscale, Zscale, Zresolution (float64), Compression, DataType,
 * CheckType (uint8), all little-endian, then the values and an optional
 * trailer.  DataType: 0 uint8, 1 uint16, 2 uint32, 3 float32, 4 int8,
 * 5 int16, 6 int32, 7 float64; the most negative value of a signed type
 * and NaN mark missing points.  Xscale and Yscale are the spacings and
 * Zscale the height of one count, in metres.  The trailer is not read.
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BIN_HEADER 73	/* after the 8-byte magic */

struct hdr {
	size_t nx, ny;
	double xs, ys, zs;
	int compression, type;
};

static const size_t type_size[8] = { 1, 2, 4, 4, 1, 2, 4, 8 };

/* The value of DataType t at p; *missing set for a missing point. */
static double
decode(const unsigned char *p, int t, int *missing)
{
	uint32_t u32;
	float f;
	double v;

	*missing = 0;
	switch (t) {
	case 0: return p[0];
	case 1: return rc__get_le16(p);
	case 2: return rc__get_le32(p);
	case 3:
		u32 = rc__get_le32(p);
		memcpy(&f, &u32, 4);
		*missing = isnan(f);
		return f;
	case 4:
		*missing = p[0] == 0x80;
		return (int8_t)p[0];
	case 5:
		*missing = rc__get_le16(p) == 0x8000;
		return (int16_t)rc__get_le16(p);
	case 6:
		*missing = rc__get_le32(p) == 0x80000000u;
		return (int32_t)rc__get_le32(p);
	default:
		v = rc__get_le64(p);
		*missing = isnan(v);
		return v;
	}
}

static int
check_header(const struct hdr *h, rc_err *err)
{
	if (h->nx < 1 || h->ny < 1)
		return rc_seterr(err, "SDF: NumPoints, NumProfiles must be positive");
	if (!(isfinite(h->xs) && h->xs > 0 && isfinite(h->ys) && h->ys > 0))
		return rc_seterr(err, "SDF: Xscale, Yscale must be positive");
	if (!(isfinite(h->zs) && h->zs != 0))
		return rc_seterr(err, "SDF: Zscale must be a non-zero number");
	if (h->compression != 0)
		return rc_seterr(err, "SDF: Compression %d is not supported "
		    "(only 0, none)", h->compression);
	if (h->type < 0 || h->type > 7)
		return rc_seterr(err, "SDF: DataType %d is unknown (0 to 7)",
		    h->type);
	return rc_grid_check_shape(h->nx, h->ny, (double)h->nx * h->xs,
	    (double)h->ny * h->ys, err);
}

/* Scale counts to metres; missing points NaN with valid 0. */
static int
finish(rc_grid *g, const struct hdr *h, const unsigned char *miss, rc_err *err)
{
	size_t n = rc_grid_size(g);
	int any = 0;

	for (size_t k = 0; k < n; k++)
		any |= miss[k];
	if (any) {
		if ((g->valid = rc_malloc(n, err)) == NULL)
			return -1;
		for (size_t k = 0; k < n; k++)
			g->valid[k] = !miss[k];
	}
	for (size_t k = 0; k < n; k++)
		g->z[k] = miss[k] ? NAN : h->zs == 1 ? g->z[k] : g->z[k] * h->zs;
	strcpy(g->unit, "m");
	strcpy(g->z_unit, "m");
	g->periodic = 0;
	return 0;
}

static rc_grid *
read_binary(rc_in *in, rc_err *err)
{
	unsigned char h[BIN_HEADER], *b = NULL, *miss = NULL;
	struct hdr d;
	rc_grid *g = NULL;
	size_t n, el;
	int m;

	if (rc__in_read(in, h, BIN_HEADER) != BIN_HEADER) {
		if (rc__in_check(in, err) == 0)
			rc_seterr(err, "SDF: truncated binary header");
		return NULL;
	}
	d.nx = rc__get_le16(h + 34);
	d.ny = rc__get_le16(h + 36);
	d.xs = rc__get_le64(h + 38);
	d.ys = rc__get_le64(h + 46);
	d.zs = rc__get_le64(h + 54);
	d.compression = h[70];
	d.type = h[71];
	if (check_header(&d, err) != 0)
		return NULL;
	n = d.nx * d.ny;
	el = type_size[d.type];
	if (rc__in_read_exact(in, n * el, &b, err) != 0)
		return NULL;
	if ((miss = rc_malloc(n, err)) == NULL ||
	    (g = rc__io_grid_alloc(d.nx, d.ny, (double)d.nx * d.xs,
	    (double)d.ny * d.ys, err)) == NULL)
		goto fail;
	for (size_t k = 0; k < n; k++) {
		g->z[k] = decode(b + k * el, d.type, &m);
		miss[k] = (unsigned char)m;
	}
	if (finish(g, &d, miss, err) != 0)
		goto fail;
	free(b);
	free(miss);
	return g;
fail:
	rc_grid_free(g);
	free(b);
	free(miss);
	return NULL;
}

/* The next white-space separated word into w (cap bytes); 0 at end. */
static int
word(rc_in *in, char *w, size_t cap, rc_err *err)
{
	size_t n = 0;
	int c;

	while ((c = rc__in_getc(in)) != EOF && (c == ' ' || (c >= '\t' &&
	    c <= '\r')))
		;
	while (c != EOF && !(c == ' ' || (c >= '\t' && c <= '\r'))) {
		if (n + 1 >= cap)
			return rc_seterr(err, "SDF: a value longer than %zu characters",
			    cap - 1);
		w[n++] = (char)c;
		c = rc__in_getc(in);
	}
	w[n] = '\0';
	if (rc__in_check(in, err) != 0)
		return -1;
	return n > 0;
}

/* Long: one pass over the ASCII SDF in file order; each check sits where
 * its input is read. */
static rc_grid *
read_ascii(rc_in *in, rc_err *err)
{
	char line[512], q[64], *eq, *key, *val, *e;
	struct hdr d = { 0, 0, 0, 0, 0, 0, -1 };
	size_t len, n, k = 0;
	unsigned char *miss = NULL;
	rc_grid *g = NULL;
	int r, seen = 0;

	for (;;) {
		if ((r = rc__in_line(in, line, sizeof(line), &len)) <= 0) {
			if (r < 0)
				rc_seterr(err, "SDF: header line over %zu bytes",
				    sizeof(line) - 1);
			else if (rc__in_check(in, err) == 0)
				rc_seterr(err, "SDF: header without the '*' line that ends it");
			return NULL;
		}
		for (key = line; *key == ' ' || *key == '\t'; key++)
			;
		for (e = key + strlen(key); e > key && (e[-1] == ' ' ||
		    e[-1] == '\t' || e[-1] == '\r'); e--)
			;
		*e = '\0';
		if (strcmp(key, "*") == 0)
			break;
		if (*key == '\0')
			continue;
		if ((eq = strchr(key, '=')) == NULL) {
			rc_seterr(err, "SDF: header line '%s' is not 'Name = Value'",
			    rc__io_quote(q, sizeof(q), key, strlen(key)));
			return NULL;
		}
		for (e = eq; e > key && (e[-1] == ' ' || e[-1] == '\t'); e--)
			;
		*e = '\0';
		for (val = eq + 1; *val == ' ' || *val == '\t'; val++)
			;
		{
			double v;
			size_t u;
			int isnum = rc__parse_double(val, &v) == 0;

			if (strcmp(key, "NumPoints") == 0 || strcmp(key, "NumProfiles") == 0
			    || strcmp(key, "Compression") == 0 ||
			    strcmp(key, "DataType") == 0) {
				if (rc__parse_size(val, &u) != 0 || u > 1000000000) {
					rc_seterr(err, "SDF: %s '%s' is not a count", key,
					    rc__io_quote(q, sizeof(q), val, strlen(val)));
					return NULL;
				}
				if (key[0] == 'N' && key[3] == 'P' && key[4] == 'o')
					d.nx = u, seen |= 1;
				else if (key[0] == 'N')
					d.ny = u, seen |= 2;
				else if (key[0] == 'C')
					d.compression = (int)u;
				else
					d.type = (int)u;
			} else if (strcmp(key, "Xscale") == 0 || strcmp(key, "Yscale") == 0
			    || strcmp(key, "Zscale") == 0) {
				if (!isnum) {
					rc_seterr(err, "SDF: %s '%s' is not a number", key,
					    rc__io_quote(q, sizeof(q), val, strlen(val)));
					return NULL;
				}
				*(key[0] == 'X' ? &d.xs : key[0] == 'Y' ? &d.ys : &d.zs) = v;
				seen |= key[0] == 'X' ? 4 : key[0] == 'Y' ? 8 : 16;
			}
		}
	}
	if (seen != 31) {
		rc_seterr(err, "SDF: header lacks NumPoints, NumProfiles, Xscale, "
		    "Yscale or Zscale");
		return NULL;
	}
	if (d.type < 0)
		d.type = 7;	/* the ASCII values are numbers whatever it says */
	if (check_header(&d, err) != 0)
		return NULL;
	n = d.nx * d.ny;
	/* Values arrive one by one: grow with them, not with the header. */
	{
		size_t cap = n < 4096 ? n : 4096;
		double *z = rc_malloc(cap * sizeof(double), err), *nz;
		unsigned char *nm;

		if (z == NULL || (miss = rc_malloc(cap, err)) == NULL) {
			free(z);
			return NULL;
		}
		for (;;) {
			if ((r = word(in, line, 64, err)) < 0)
				goto fail_z;
			if (r == 0) {
				rc_seterr(err, "SDF: data not ended by '*'");
				goto fail_z;
			}
			if (strcmp(line, "*") == 0)
				break;
			if (k == n) {
				rc_seterr(err, "SDF: more than NumPoints x NumProfiles = "
				    "%zu values", n);
				goto fail_z;
			}
			if (k == cap) {
				cap = 2 * cap < n ? 2 * cap : n;
				if ((nz = realloc(z, cap * sizeof(double))) == NULL)
					goto oom;
				z = nz;
				if ((nm = realloc(miss, cap)) == NULL)
					goto oom;
				miss = nm;
			}
			miss[k] = strcmp(line, "BAD") == 0;
			if (!miss[k] && (rc__parse_double(line, &z[k]) != 0 ||
			    !isfinite(z[k]))) {
				rc_seterr(err, "SDF: value %zu '%s' is not a number", k + 1,
				    rc__io_quote(q, sizeof(q), line, strlen(line)));
				goto fail_z;
			}
			if (miss[k])
				z[k] = 0;
			k++;
		}
		if (k != n) {
			rc_seterr(err, "SDF: %zu values for NumPoints x NumProfiles = %zu",
			    k, n);
			goto fail_z;
		}
		if ((g = rc__io_grid_alloc(d.nx, d.ny, (double)d.nx * d.xs,
		    (double)d.ny * d.ys, err)) == NULL)
			goto fail_z;
		memcpy(g->z, z, n * sizeof(double));
		free(z);
		if (finish(g, &d, miss, err) != 0) {
			rc_grid_free(g);
			g = NULL;
		}
		free(miss);
		return g;
oom:
		rc_seterr(err, "out of memory");
fail_z:
		free(z);
		free(miss);
		return NULL;
	}
}

rc_grid *
rc__sdf_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	unsigned char magic[8];

	(void)o;
	if (rc__in_read(in, magic, 8) != 8) {
		rc_seterr(err, "SDF: truncated magic");
		return NULL;
	}
	if (magic[0] == 'b')
		return read_binary(in, err);
	/* The rest of the magic line. */
	{
		int c;

		while ((c = rc__in_getc(in)) != '\n')
			if (c == EOF || (c != '\r' && c != ' ' && c != '\t')) {
				rc_seterr(err, "SDF: junk after the magic 'aISO-1.0'");
				return NULL;
			}
	}
	return read_ascii(in, err);
}
