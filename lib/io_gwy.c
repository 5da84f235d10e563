/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_gwy.c - Gwyddion native files (.gwy), read.
 *
 * The file is "GWYP" and one serialised GwyContainer.  A serialised object
 * is its type name (NUL-terminated), a uint32 LE byte count and that many
 * bytes of components; a component is its name (NUL-terminated), a type
 * letter and the value: b c (1 byte), i (int32), q (int64), d (double),
 * s (NUL-terminated string), o (an object), and the arrays C I Q D S O of
 * those (a uint32 count first).  Everything is little-endian.  The
 * container's components are keyed "/N/data" (a GwyDataField: xres, yres,
 * xreal, yreal, si_unit_xy and si_unit_z (GwySIUnit objects with unitstr),
 * data (D, row by row)), "/N/mask" (a GwyDataField of 0 and 1) and
 * "/N/data/title" (s).  Every /N/data is a channel, in order of N; a mask
 * marks missing points (Gwyddion marks the invalid points of imported
 * measurements so), which become NaN with valid = 0.  A channel with a
 * lateral unit but none for its values holds unitless values (intensity,
 * colour): its z_unit is "1", which no length reading takes for heights
 * unless --z-unit says what they are.  Graphs, spectra,
 * volume data and everything else are skipped by their byte counts, so
 * nothing recurses and every length is checked against what is left.
 */
#include "io_internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* More channels than any instrument writes; bounds the bookkeeping. */
#define MAX_CHANNELS 4096

struct cur {
	const unsigned char *p, *end;
};

struct field {
	int present;
	size_t xres, yres;
	double xreal, yreal;
	char unit_xy[32], unit_z[32];
	const unsigned char *data;	/* xres*yres doubles LE, in the file */
};

struct entry {
	unsigned long id;
	struct field data, mask;
	const char *title;
};

static int
bad(rc_err *err, const char *what)
{
	return rc_seterr(err, "corrupt .gwy file: %s", what);
}

static size_t
left(const struct cur *c)
{
	return (size_t)(c->end - c->p);
}

static int
get_str(struct cur *c, const char **s, rc_err *err)
{
	const unsigned char *nul = memchr(c->p, 0, left(c));

	if (nul == NULL)
		return bad(err, "string runs past the end");
	*s = (const char *)c->p;
	c->p = nul + 1;
	return 0;
}

static int
get_u32(struct cur *c, uint32_t *v, rc_err *err)
{
	if (left(c) < 4)
		return bad(err, "truncated");
	*v = rc__get_le32(c->p);
	c->p += 4;
	return 0;
}

/* An object's header: *type its type name, *body its components; c moves
 * past the object. */
static int
get_object(struct cur *c, const char **type, struct cur *body, rc_err *err)
{
	uint32_t size = 0;

	if (get_str(c, type, err) != 0 || get_u32(c, &size, err) != 0)
		return -1;
	if (size > left(c))
		return bad(err, "object size beyond the end of the file");
	body->p = c->p;
	body->end = c->p + size;
	c->p += size;
	return 0;
}

/* Skip n values of a scalar type letter. */
static int
skip_values(struct cur *c, char t, size_t n, rc_err *err)
{
	size_t size;
	const char *s = NULL;
	struct cur body;

	switch (t) {
	case 'b': case 'c': size = 1; break;
	case 'i': size = 4; break;
	case 'q': case 'd': size = 8; break;
	case 's':
		for (size_t k = 0; k < n; k++)
			if (get_str(c, &s, err) != 0)
				return -1;
		return 0;
	case 'o':
		for (size_t k = 0; k < n; k++)
			if (get_object(c, &s, &body, err) != 0)
				return -1;
		return 0;
	default:
		return bad(err, "unknown component type");
	}
	if (n > left(c) / size)
		return bad(err, "array runs past the end");
	c->p += n * size;
	return 0;
}

/* Skip one component value of type letter t. */
static int
skip_value(struct cur *c, char t, rc_err *err)
{
	uint32_t n = 0;

	if (t >= 'A' && t <= 'Z') {
		if (t == 'B')	/* no boolean arrays in the format */
			return bad(err, "unknown component type");
		if (get_u32(c, &n, err) != 0)
			return -1;
		return skip_values(c, (char)(t - 'A' + 'a'), n, err);
	}
	return skip_values(c, t, 1, err);
}

static int
get_type(struct cur *c, char *t, rc_err *err)
{
	if (left(c) < 1)
		return bad(err, "truncated component");
	*t = (char)*c->p++;
	return 0;
}

/* A GwySIUnit's unitstr into u. */
static int
read_unit(struct cur *c, char u[32], rc_err *err)
{
	const char *type = NULL, *name = NULL, *s = NULL;
	struct cur body;
	char t = 0;

	if (get_object(c, &type, &body, err) != 0)
		return -1;
	if (strcmp(type, "GwySIUnit") != 0)
		return bad(err, "a unit is not a GwySIUnit");
	u[0] = '\0';
	while (body.p < body.end) {
		if (get_str(&body, &name, err) != 0 || get_type(&body, &t, err) != 0)
			return -1;
		if (strcmp(name, "unitstr") == 0 && t == 's') {
			if (get_str(&body, &s, err) != 0 ||
			    rc__io_set_unit(u, s, err) != 0)
				return -1;
		} else if (skip_value(&body, t, err) != 0)
			return -1;
	}
	return 0;
}

static int
read_field(struct cur *c, struct field *f, rc_err *err)
{
	const char *type = NULL, *name = NULL;
	struct cur body;
	int32_t i32;
	uint32_t n = 0;
	int have_data = 0;
	char t = 0;

	if (get_object(c, &type, &body, err) != 0)
		return -1;
	memset(f, 0, sizeof(*f));
	f->xreal = f->yreal = 1;	/* Gwyddion's defaults */
	while (body.p < body.end) {
		if (get_str(&body, &name, err) != 0 || get_type(&body, &t, err) != 0)
			return -1;
		if ((strcmp(name, "xres") == 0 || strcmp(name, "yres") == 0) &&
		    t == 'i') {
			if (left(&body) < 4)
				return bad(err, "truncated");
			i32 = (int32_t)rc__get_le32(body.p);
			body.p += 4;
			if (i32 < 1)
				return bad(err, "xres or yres below 1");
			*(name[0] == 'x' ? &f->xres : &f->yres) = (size_t)i32;
		} else if ((strcmp(name, "xreal") == 0 || strcmp(name, "yreal") == 0)
		    && t == 'd') {
			if (left(&body) < 8)
				return bad(err, "truncated");
			*(name[0] == 'x' ? &f->xreal : &f->yreal) = rc__get_le64(body.p);
			body.p += 8;
		} else if (strcmp(name, "si_unit_xy") == 0 && t == 'o') {
			if (read_unit(&body, f->unit_xy, err) != 0)
				return -1;
		} else if (strcmp(name, "si_unit_z") == 0 && t == 'o') {
			if (read_unit(&body, f->unit_z, err) != 0)
				return -1;
		} else if (strcmp(name, "data") == 0 && t == 'D') {
			if (get_u32(&body, &n, err) != 0)
				return -1;
			if (n > left(&body) / 8)
				return bad(err, "data array runs past the end");
			f->data = body.p;
			body.p += (size_t)n * 8;
			have_data = 1;
		} else if (skip_value(&body, t, err) != 0)
			return -1;
	}
	if (strcmp(type, "GwyDataField") != 0)
		return 0;	/* not a field: ignored */
	if (!have_data || f->xres == 0 || f->yres == 0)
		return bad(err, "a data field lacks xres, yres or data");
	if (f->xres > RC_GRID_MAX_DIM || f->yres > RC_GRID_MAX_DIM ||
	    (uint64_t)f->xres * f->yres != n)
		return rc_seterr(err, "corrupt .gwy file: data field of %zux%zu "
		    "holds %u values", f->xres, f->yres, (unsigned)n);
	f->present = 1;
	return 0;
}

/* "/N/data", "/N/mask", "/N/data/title": *id and the rest, else NULL. */
static const char *
parse_key(const char *key, unsigned long *id)
{
	unsigned long v = 0;
	const char *p = key;

	if (*p++ != '/' || *p < '0' || *p > '9')
		return NULL;
	for (; *p >= '0' && *p <= '9'; p++) {
		if (v > 100000000)
			return NULL;
		v = v * 10 + (unsigned long)(*p - '0');
	}
	*id = v;
	return p;
}

static struct entry *
find_entry(struct entry **e, size_t *n, unsigned long id, rc_err *err)
{
	struct entry *ne;

	for (size_t i = 0; i < *n; i++)
		if ((*e)[i].id == id)
			return &(*e)[i];
	if (*n == MAX_CHANNELS) {
		bad(err, "more than 4096 channels");
		return NULL;
	}
	if ((ne = realloc(*e, (*n + 1) * sizeof(**e))) == NULL) {
		rc_seterr(err, "out of memory");
		return NULL;
	}
	*e = ne;
	memset(&ne[*n], 0, sizeof(ne[*n]));
	ne[*n].id = id;
	return &ne[(*n)++];
}

static int
by_id(const void *a, const void *b)
{
	unsigned long x = ((const struct entry *)a)->id;
	unsigned long y = ((const struct entry *)b)->id;

	return (x > y) - (x < y);
}

static int
make_channel(const struct entry *e, rc_chanset *s, rc_err *err)
{
	const struct field *f = &e->data, *m = &e->mask;
	size_t n = f->xres * f->yres;
	char title[64];
	rc_grid *g;

	if (!(isfinite(f->xreal) && f->xreal > 0 && isfinite(f->yreal) &&
	    f->yreal > 0))
		return rc_seterr(err, "corrupt .gwy file: channel %lu has size "
		    "%g x %g", e->id, f->xreal, f->yreal);
	if ((g = rc__io_grid_alloc(f->xres, f->yres, f->xreal, f->yreal, err)) ==
	    NULL)
		return -1;
	for (size_t k = 0; k < n; k++)
		g->z[k] = rc__get_le64(f->data + 8 * k);
	strcpy(g->unit, f->unit_xy);
	strcpy(g->z_unit, f->unit_xy[0] != '\0' && f->unit_z[0] == '\0' ? "1" :
	    f->unit_z);
	g->periodic = 0;	/* a measurement */
	if (m->present && m->xres == f->xres && m->yres == f->yres) {
		if ((g->valid = rc_malloc(n, err)) == NULL) {
			rc_grid_free(g);
			return -1;
		}
		for (size_t k = 0; k < n; k++) {
			g->valid[k] = !(rc__get_le64(m->data + 8 * k) > 0.5);
			if (!g->valid[k])
				g->z[k] = NAN;
		}
	}
	if (e->title == NULL)
		snprintf(title, sizeof(title), "channel %lu", e->id);
	return rc__chanset_add(s, g, e->title ? e->title : title, err);
}

int
rc__gwy_read(const unsigned char *buf, size_t len, rc_chanset *s, rc_err *err)
{
	struct cur c = { buf, buf + len }, body;
	struct entry *e = NULL, *ent;
	size_t ne = 0, nchan = 0;
	const char *type = NULL, *key = NULL, *rest, *str = NULL;
	unsigned long id = 0;
	char t = 0;
	int r = -1;

	if (len < 4 || memcmp(buf, "GWYP", 4) != 0) {
		if (len >= 4 && memcmp(buf, "GWYO", 4) == 0)
			return rc_seterr(err, "a Gwyddion 1 file (GWYO): not supported; "
			    "save it again with Gwyddion 2");
		return bad(err, "no GWYP magic");
	}
	c.p += 4;
	if (get_object(&c, &type, &body, err) != 0)
		return -1;
	if (strcmp(type, "GwyContainer") != 0)
		return bad(err, "the top object is not a GwyContainer");
	while (body.p < body.end) {
		if (get_str(&body, &key, err) != 0 || get_type(&body, &t, err) != 0)
			goto out;
		rest = parse_key(key, &id);
		if (rest != NULL && t == 'o' &&
		    (strcmp(rest, "/data") == 0 || strcmp(rest, "/mask") == 0)) {
			struct field f;

			if (read_field(&body, &f, err) != 0)
				goto out;
			if (!f.present)
				continue;
			if ((ent = find_entry(&e, &ne, id, err)) == NULL)
				goto out;
			*(rest[1] == 'd' ? &ent->data : &ent->mask) = f;
		} else if (rest != NULL && t == 's' &&
		    strcmp(rest, "/data/title") == 0) {
			if (get_str(&body, &str, err) != 0)
				goto out;
			if ((ent = find_entry(&e, &ne, id, err)) == NULL)
				goto out;
			ent->title = str;
		} else if (skip_value(&body, t, err) != 0)
			goto out;
	}
	if (ne > 0)
		qsort(e, ne, sizeof(*e), by_id);
	for (size_t i = 0; i < ne; i++) {
		if (!e[i].data.present)
			continue;
		if (make_channel(&e[i], s, err) != 0)
			goto out;
		nchan++;
	}
	if (nchan == 0) {
		rc_seterr(err, ".gwy file holds no image channel (/N/data)");
		goto out;
	}
	r = 0;
out:
	free(e);
	return r;
}
