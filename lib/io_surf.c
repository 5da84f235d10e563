/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_surf.c - the native format: a text header of "key = value" lines,
 * then nx*ny float64 little-endian values (see surf(5)).  Missing points
 * are NaN values (rc_grid_read_finish turns them into the mask); periodic
 * is absent from files written before it existed, which were periodic.
 * Filled points are the "filled" list, last in the header so that its
 * beginning stays the grid's description however long the list is. */
#include "io_internal.h"

#include <stdlib.h>
#include <string.h>

#define MAGIC "#surf 1"
#define END "end_header"

/* A growing string for the header. */
struct buf {
	char *s;
	size_t len, cap;
	int bad;
};

static void
add(struct buf *b, const char *s)
{
	size_t n = strlen(s);

	if (b->bad)
		return;
	if (b->len + n + 1 > b->cap) {
		size_t cap = (b->len + n + 1) * 2;
		char *p = realloc(b->s, cap);

		if (p == NULL) {
			b->bad = 1;
			return;
		}
		b->s = p;
		b->cap = cap;
	}
	memcpy(b->s + b->len, s, n + 1);
	b->len += n;
}

static void
addkv(struct buf *b, const char *key, const char *val)
{
	add(b, key);
	add(b, " = ");
	add(b, val);
	add(b, "\n");
}

/* The header for ny rows (g->ny unless only the header is written), then
 * g's values if values is set. */
static int
write_surf(const rc_grid *g, size_t ny, int values, FILE *fp, rc_err *err)
{
	struct buf head = { 0 }, tail = { 0 };
	char num[64], line[96], *filled = NULL;
	size_t offset, total, pad;
	int r = -1;

	if (rc__io_filled_text(g, &filled, err) != 0)
		return -1;

	add(&head, MAGIC "\n# rough-contact grid; float64 LE values from "
	    "data_offset on; see surf(5)\n");
	snprintf(num, sizeof(num), "%zu", g->nx);
	addkv(&head, "nx", num);
	snprintf(num, sizeof(num), "%zu", ny);
	addkv(&head, "ny", num);
	rc_format_double(num, sizeof(num), g->lx);
	addkv(&head, "lx", num);
	rc_format_double(num, sizeof(num), g->ly);
	addkv(&head, "ly", num);
	if (g->unit[0] != '\0')
		addkv(&head, "unit", g->unit);
	if (g->z_unit[0] != '\0')
		addkv(&head, "z_unit", g->z_unit);
	addkv(&head, "periodic", g->periodic ? "1" : "0");
	addkv(&head, "kind", rc_kind_name(g->kind));
	addkv(&head, "encoding", "float64-le");
	for (size_t i = 0; i < g->nmeta; i++) {
		add(&tail, "meta.");
		addkv(&tail, g->meta[i].key, g->meta[i].val);
	}
	for (size_t i = 0; i < g->nhistory; i++)
		addkv(&tail, "history", g->history[i]);
	if (filled != NULL)
		addkv(&tail, "filled", filled);
	if (head.bad || tail.bad) {
		rc_seterr(err, "out of memory");
		goto out;
	}
	/* data_offset = the header's length, a multiple of 8 so the values can
	 * be addressed directly (MPI-IO, numpy.memmap).  Its own digits count,
	 * so iterate to the fixed point (two rounds at most). */
	offset = 0;
	for (;;) {
		snprintf(line, sizeof(line), "data_offset = %zu\n", offset);
		total = head.len + strlen(line) + tail.len + strlen(END) + 1;
		pad = (8 - total % 8) % 8;
		if (total + pad == offset)
			break;
		offset = total + pad;
	}
	if (offset > RC_HEADER_MAX) {
		rc_seterr(err, "header of %zu bytes exceeds the %zu-byte limit "
		    "(too much metadata or history)", offset, RC_HEADER_MAX);
		goto out;
	}
	if (rc__io_write(fp, head.s, head.len, err) != 0 ||
	    rc__io_write(fp, line, strlen(line), err) != 0 ||
	    rc__io_write(fp, tail.s, tail.len, err) != 0 ||
	    rc__io_write(fp, END, strlen(END), err) != 0 ||
	    rc__io_write(fp, "        ", pad, err) != 0 ||
	    rc__io_write(fp, "\n", 1, err) != 0)
		goto out;
	r = values ? rc__io_write_values(fp, g->z, rc_grid_size(g), 8, err) : 0;
out:
	free(head.s);
	free(tail.s);
	free(filled);
	return r;
}

enum { K_NX, K_NY, K_LX, K_LY, K_UNIT, K_KIND, K_ENC, K_OFFSET, K_ZUNIT,
	K_PERIODIC, K_FILLED, K_N };
static const char *keys[K_N] = {
	"nx", "ny", "lx", "ly", "unit", "kind", "encoding", "data_offset",
	"z_unit", "periodic", "filled"
};
/* Keys a header may leave out: unit and z_unit (unknown), data_offset
 * (where the header ends), periodic (1: files from before the key),
 * filled (no filled point). */
static int
optional(int k)
{
	return k == K_UNIT || k == K_OFFSET || k == K_ZUNIT || k == K_PERIODIC ||
	    k == K_FILLED;
}

/* Bytes of a grid's unit and z_unit, NUL included. */
#define UNIT_CAP	sizeof(((rc_grid *)NULL)->unit)

/* The header's fields as read: the known keys' values (vals), history
 * lines, metadata keys and values; all malloc'ed. */
struct header {
	char *vals[K_N];
	char **hist, **mkey, **mval;
	size_t nhist, nmeta;
};

static void
header_free(struct header *hd)
{
	for (int r = 0; r < K_N; r++)
		free(hd->vals[r]);
	for (size_t i = 0; i < hd->nhist; i++)
		free(hd->hist[i]);
	for (size_t i = 0; i < hd->nmeta; i++) {
		free(hd->mkey[i]);
		free(hd->mval[i]);
	}
	free(hd->hist);
	free(hd->mkey);
	free(hd->mval);
}

/* Store one "key = value" line of the header (line lineno). */
static int
header_field(struct header *hd, const char *key, const char *val,
    size_t lineno, rc_err *err)
{
	char q[64];
	int r;

	if (strcmp(key, "history") == 0) {
		char **h = realloc(hd->hist, (hd->nhist + 1) * sizeof(*h));

		if (h == NULL)
			return rc_seterr(err, "out of memory");
		hd->hist = h;
		if ((h[hd->nhist] = strdup(val)) == NULL)
			return rc_seterr(err, "out of memory");
		hd->nhist++;
		return 0;
	}
	if (strncmp(key, "meta.", 5) == 0) {
		char **mk, **mv;

		if (key[5] == '\0')
			return rc_seterr(err, "header line %zu: empty metadata key",
			    lineno);
		for (size_t i = 0; i < hd->nmeta; i++)
			if (strcmp(hd->mkey[i], key + 5) == 0)
				return rc_seterr(err, "header line %zu: duplicate key "
				    "'%s'", lineno, key);
		mk = realloc(hd->mkey, (hd->nmeta + 1) * sizeof(*mk));
		if (mk != NULL)
			hd->mkey = mk;
		mv = realloc(hd->mval, (hd->nmeta + 1) * sizeof(*mv));
		if (mv != NULL)
			hd->mval = mv;
		if (mk == NULL || mv == NULL)
			return rc_seterr(err, "out of memory");
		hd->mkey[hd->nmeta] = strdup(key + 5);
		hd->mval[hd->nmeta] = strdup(val);
		hd->nmeta++;
		if (hd->mkey[hd->nmeta - 1] == NULL || hd->mval[hd->nmeta - 1] == NULL)
			return rc_seterr(err, "out of memory");
		return 0;
	}
	for (r = 0; r < K_N; r++)
		if (strcmp(key, keys[r]) == 0)
			break;
	if (r == K_N)
		return rc_seterr(err, "header line %zu: unknown key '%s' "
		    "(metadata keys start with 'meta.')", lineno,
		    rc__io_quote(q, sizeof(q), key, strlen(key)));
	if (hd->vals[r] != NULL)
		return rc_seterr(err, "header line %zu: duplicate key '%s'", lineno,
		    key);
	if ((hd->vals[r] = strdup(val)) == NULL)
		return rc_seterr(err, "out of memory");
	return 0;
}

/* One header line (line lineno, len bytes, in line) checked; 1 at the
 * end line, 0 after a field or a comment, -1 on error. */
static int
header_line(struct header *hd, char *line, size_t len, size_t lineno,
    rc_err *err)
{
	char *key, *val, q[64];

	if (strlen(line) != len)
		return rc_seterr(err, "header line %zu contains a NUL byte", lineno);
	if (lineno == 1) {
		if (strcmp(line, MAGIC) == 0)
			return 0;
		if (strncmp(line, "#surf ", 6) == 0)
			return rc_seterr(err, "format version '%s': this reader "
			    "knows '" MAGIC "'", rc__io_quote(q, sizeof(q), line, len));
		return rc_seterr(err, "bad magic line '%s': expected '" MAGIC "'",
		    rc__io_quote(q, sizeof(q), line, len));
	}
	if (line[0] == '#')
		return 0;
	for (size_t i = 0; i < len; i++)
		if ((unsigned char)line[i] < 0x20 && line[i] != '\t' &&
		    !(line[i] == '\r' && i == len - 1))
			return rc_seterr(err, "header line %zu contains the control "
			    "character \\x%02x", lineno, (unsigned char)line[i]);
	if (strncmp(line, END, strlen(END)) == 0 &&
	    strspn(line + strlen(END), " \t\r") == len - strlen(END))
		return 1;
	if (rc__header_split(line, &key, &val) != 0 ||
	    !rc__header_key_valid(key))
		return rc_seterr(err, "header line %zu is not 'key = value': '%s'",
		    lineno, rc__io_quote(q, sizeof(q), line, len));
	return header_field(hd, key, val, lineno, err);
}

/* The header up to and including its end line into hd. */
static int
header_read(rc_in *in, struct header *hd, rc_err *err)
{
	char *line;
	size_t len, lineno = 0;
	int r = 0;

	if ((line = rc_malloc(RC_HEADER_MAX + 1, err)) == NULL)
		return -1;
	while (r == 0) {
		/* The header, newlines included, fits in RC_HEADER_MAX bytes. */
		size_t cap = RC_HEADER_MAX - (size_t)in->consumed;

		lineno++;
		r = cap < 2 ? -1 : rc__in_line(in, line, cap, &len);
		if (r == -1) {
			rc_seterr(err, "header longer than %zu bytes (no '" END "' line)",
			    RC_HEADER_MAX);
			break;
		}
		if (r == 0 || r == 2) {
			if (rc__in_check(in, err) == 0)
				rc_seterr(err, "truncated header: input ends at line %zu "
				    "before the '" END "' line", lineno);
			r = -1;
			break;
		}
		r = header_line(hd, line, len, lineno, err);
	}
	free(line);
	return r < 0 ? -1 : 0;
}

/* The known keys' values checked: *nx, *ny, *lx, *ly, *kind. */
static int
header_check(const struct header *hd, const rc_in *in, size_t *nx, size_t *ny,
    double *lx, double *ly, int *kind, rc_err *err)
{
	char *const *vals = hd->vals;
	char q[64];
	size_t offset;

	for (int r = 0; r < K_N; r++)
		if (vals[r] == NULL && !optional(r))
			return rc_seterr(err, "header lacks the required key '%s'",
			    keys[r]);
	if (rc__parse_size(vals[K_NX], nx) != 0 || rc__parse_size(vals[K_NY], ny) != 0)
		return rc_seterr(err, "nx = '%s', ny = '%s': sizes must be positive integers",
		    rc__io_quote(q, 32, vals[K_NX], strlen(vals[K_NX])),
		    rc__io_quote(q + 32, 32, vals[K_NY], strlen(vals[K_NY])));
	if (rc__parse_double(vals[K_LX], lx) != 0 || rc__parse_double(vals[K_LY], ly) != 0)
		return rc_seterr(err, "lx = '%s', ly = '%s': lengths must be numbers",
		    rc__io_quote(q, 32, vals[K_LX], strlen(vals[K_LX])),
		    rc__io_quote(q + 32, 32, vals[K_LY], strlen(vals[K_LY])));
	if ((*kind = rc_kind_parse(vals[K_KIND])) < 0)
		return rc_seterr(err, "unknown kind '%s'", rc__io_quote(q, sizeof(q),
		    vals[K_KIND], strlen(vals[K_KIND])));
	if (strcmp(vals[K_ENC], "float64-le") != 0)
		return rc_seterr(err, "encoding '%s' not supported (only float64-le)",
		    rc__io_quote(q, sizeof(q), vals[K_ENC], strlen(vals[K_ENC])));
	if (vals[K_UNIT] != NULL && strlen(vals[K_UNIT]) >= UNIT_CAP)
		return rc_seterr(err, "unit '%s' longer than %zu characters", rc__io_quote(q,
		    sizeof(q), vals[K_UNIT], strlen(vals[K_UNIT])), UNIT_CAP - 1);
	if (vals[K_ZUNIT] != NULL && strlen(vals[K_ZUNIT]) >= UNIT_CAP)
		return rc_seterr(err, "z_unit '%s' longer than %zu characters", rc__io_quote(q,
		    sizeof(q), vals[K_ZUNIT], strlen(vals[K_ZUNIT])), UNIT_CAP - 1);
	if (vals[K_PERIODIC] != NULL && strcmp(vals[K_PERIODIC], "0") != 0 &&
	    strcmp(vals[K_PERIODIC], "1") != 0)
		return rc_seterr(err, "periodic = '%s': want 0 or 1", rc__io_quote(q,
		    sizeof(q), vals[K_PERIODIC], strlen(vals[K_PERIODIC])));
	if (vals[K_OFFSET] != NULL && (rc__parse_size(vals[K_OFFSET], &offset) != 0 ||
	    offset != in->consumed))
		return rc_seterr(err, "data_offset = %s, but the header ends at byte %llu",
		    rc__io_quote(q, sizeof(q), vals[K_OFFSET], strlen(vals[K_OFFSET])),
		    (unsigned long long)in->consumed);
	return rc_grid_check_shape(*nx, *ny, *lx, *ly, err);
}

/* The whole grid, or (header_ny not NULL) the header only: a grid of nx x 1
 * zeros carrying the header's fields, the row count into *header_ny. */
static rc_grid *
read_surf(rc_in *in, size_t *header_ny, rc_err *err)
{
	struct header hd;
	char *const *vals = hd.vals;
	size_t nx = 0, ny = 0;
	double lx = 0, ly = 0;
	rc_layout layout = { 8, 0, 0 };
	rc_grid *g = NULL;
	int kind = 0;

	memset(&hd, 0, sizeof(hd));
	if (header_read(in, &hd, err) != 0 ||
	    header_check(&hd, in, &nx, &ny, &lx, &ly, &kind, err) != 0)
		goto fail;
	if (header_ny != NULL) {
		*header_ny = ny;
		if ((g = rc_grid_new(nx, 1, lx, ly, err)) == NULL)
			goto fail;
	} else if ((g = rc__in_read_values(in, nx, ny, lx, ly, &layout, err)) == NULL ||
	    (vals[K_FILLED] != NULL &&
	    rc_grid_filled_parse(g, vals[K_FILLED], err) != 0))
		goto fail;
	g->kind = (enum rc_kind)kind;
	if (vals[K_UNIT] != NULL)
		strcpy(g->unit, vals[K_UNIT]);
	if (vals[K_ZUNIT] != NULL)
		strcpy(g->z_unit, vals[K_ZUNIT]);
	g->periodic = vals[K_PERIODIC] == NULL || vals[K_PERIODIC][0] == '1';
	for (size_t i = 0; i < hd.nmeta; i++)
		if (rc_grid_meta_set(g, hd.mkey[i], hd.mval[i], err) != 0)
			goto fail;
	for (size_t i = 0; i < hd.nhist; i++)
		if (rc_grid_history_add(g, hd.hist[i], err) != 0)
			goto fail;
	header_free(&hd);
	return g;
fail:
	rc_grid_free(g);
	header_free(&hd);
	return NULL;
}

int
rc__surf_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	return write_surf(g, g->ny, 1, fp, err);
}

int
rc__surf_write_header(const rc_grid *g, size_t ny, FILE *fp, rc_err *err)
{
	return write_surf(g, ny, 0, fp, err);
}

rc_grid *
rc__surf_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	(void)o;
	return read_surf(in, NULL, err);
}

rc_grid *
rc__surf_read_header(FILE *fp, size_t *ny, size_t *data_offset, rc_err *err)
{
	rc_in in;
	rc_grid *g;

	rc__in_init(&in, fp);
	if ((g = read_surf(&in, ny, err)) != NULL)
		*data_offset = (size_t)in.consumed;
	return g;
}
