/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_gsf.c - Gwyddion Simple Field 1.0.
 *
 * "Gwyddion Simple Field 1.0\n", then "Name = Value" lines, then 1 to 4
 * NUL bytes so the data start at a multiple of 4 (Gwyddion puts the data
 * at the first multiple of 4 after the first NUL), then XRes*YRes float32
 * little-endian values, row by row.  Gwyddion reads XReal and YReal in the
 * base unit of XYUnits (it drops SI prefixes), so lengths in a prefixed
 * metre unit are written in metres.  Our kind, unit, metadata and history
 * travel as extra keys (surf.kind, surf.unit, surf.meta.KEY, surf.history),
 * which Gwyddion shows as metadata; so do the value unit and the periodic
 * flag (surf.z_unit, surf.periodic) and the filled points (surf.filled,
 * one line: Gwyddion keeps the last of repeated keys).  A file without
 * surf.kind is
 * foreign (Gwyddion's, of a measurement): its units are taken as they
 * are, and it is not periodic.  Missing points are NaN values.
 */
#include "io_internal.h"
#include "units.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAGIC "Gwyddion Simple Field 1.0\n"

/* A length unit written in metres: Gwyddion reads sizes in the base unit
 * of XYUnits (it drops SI prefixes). */
static int
metric(const char *u)
{
	return u[0] != '\0' && rc_unit_is_length(u);
}

/* "prefixKEY = VAL\n"; the prefix is printed, not pasted into a buffer,
 * so a key of any length is written whole. */
static int
put_prefixed(FILE *fp, size_t *len, const char *prefix, const char *key,
    const char *val, rc_err *err)
{
	int n = fprintf(fp, "%s%s = %s\n", prefix, key, val);

	if (n < 0)
		return rc_seterr(err, "write error");
	*len += (size_t)n;
	return 0;
}

static int
put(FILE *fp, size_t *len, const char *key, const char *val, rc_err *err)
{
	return put_prefixed(fp, len, "", key, val, err);
}

/* Long: the GSF fields in the order the format defines them. */
int
rc__gsf_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	static const char nul[4] = { 0 };
	size_t n = rc_grid_size(g), len = strlen(MAGIC);
	const char *xyunit = g->unit, *zunit = g->z_unit;
	const char *zfrom = g->z_unit[0] ? g->z_unit : g->unit;
	int zlength = 0, r;
	char num[64], *filled;
	double *d;

	if (zunit[0] == '\0' && rc_kind_is_length(g->kind))
		zunit = g->unit;
	if (metric(xyunit))
		xyunit = "m";
	if (metric(zunit)) {
		zlength = 1;
		zunit = "m";
	}
	for (size_t k = 0; k < n; k++) {
		double v = zlength ? rc_unit_convert(g->z[k], zfrom, "m") : g->z[k];

		if (isfinite(v) && fabs(v) > FLT_MAX)
			return rc_seterr(err, "value %g at i=%zu, j=%zu is beyond the "
			    "float32 range of .gsf", g->z[k], k % g->nx, k / g->nx);
	}
	if (rc__io_write(fp, MAGIC, len, err) != 0)
		return -1;
	snprintf(num, sizeof(num), "%zu", g->nx);
	if (put(fp, &len, "XRes", num, err) != 0)
		return -1;
	snprintf(num, sizeof(num), "%zu", g->ny);
	if (put(fp, &len, "YRes", num, err) != 0)
		return -1;
	rc_format_double(num, sizeof(num), metric(g->unit) ?
	    rc_unit_convert(g->lx, g->unit, "m") : g->lx);
	if (put(fp, &len, "XReal", num, err) != 0)
		return -1;
	rc_format_double(num, sizeof(num), metric(g->unit) ?
	    rc_unit_convert(g->ly, g->unit, "m") : g->ly);
	if (put(fp, &len, "YReal", num, err) != 0)
		return -1;
	if ((xyunit[0] != '\0' && put(fp, &len, "XYUnits", xyunit, err) != 0) ||
	    (zunit[0] != '\0' && put(fp, &len, "ZUnits", zunit, err) != 0))
		return -1;
	if (put(fp, &len, "surf.kind", rc_kind_name(g->kind), err) != 0 ||
	    (g->unit[0] != '\0' && put(fp, &len, "surf.unit", g->unit, err) != 0) ||
	    (g->z_unit[0] != '\0' &&
	    put(fp, &len, "surf.z_unit", g->z_unit, err) != 0) ||
	    put(fp, &len, "surf.periodic", g->periodic ? "1" : "0", err) != 0)
		return -1;
	for (size_t i = 0; i < g->nmeta; i++)
		if (put_prefixed(fp, &len, "surf.meta.", g->meta[i].key,
		    g->meta[i].val, err) != 0)
			return -1;
	for (size_t i = 0; i < g->nhistory; i++)
		if (put(fp, &len, "surf.history", g->history[i], err) != 0)
			return -1;
	if (rc__io_filled_text(g, &filled, err) != 0)
		return -1;
	r = filled != NULL ? put(fp, &len, "surf.filled", filled, err) : 0;
	free(filled);
	if (r != 0 || rc__io_write(fp, nul, 4 - len % 4, err) != 0)
		return -1;
	if (!zlength)
		return rc__io_write_values(fp, g->z, n, 4, err);
	/* Values in metres: through a small buffer. */
	if ((d = rc_malloc(4096 * sizeof(double), err)) == NULL)
		return -1;
	for (size_t k = 0; k < n; k += 4096) {
		size_t m = n - k < 4096 ? n - k : 4096;

		for (size_t i = 0; i < m; i++)
			d[i] = rc_unit_convert(g->z[k + i], zfrom, "m");
		if (rc__io_write_values(fp, d, m, 4, err) != 0) {
			free(d);
			return -1;
		}
	}
	free(d);
	return 0;
}

struct field {
	char *key, *val;
};

static const char *
lookup(const struct field *f, size_t n, const char *key)
{
	const char *v = NULL;

	/* The last one wins, as in Gwyddion's hash table. */
	for (size_t i = 0; i < n; i++)
		if (strcmp(f[i].key, key) == 0)
			v = f[i].val;
	return v;
}

static int
standard(const char *key)
{
	static const char *names[] = { "XRes", "YRes", "XReal", "YReal",
	    "XYUnits", "ZUnits" };

	for (size_t i = 0; i < sizeof(names) / sizeof(names[0]); i++)
		if (strcmp(key, names[i]) == 0)
			return 1;
	return 0;
}

/* Long: the GSF fields in the order the format defines them, each checked
 * where read; the unit rules of our own files need them all at once. */
rc_grid *
rc__gsf_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	char *head = NULL, *line, *next, q[64];
	struct field *f = NULL;
	size_t n = 0, nf = 0, nx, ny, lineno = 1;
	const char *v, *xyunit, *zunit, *unit, *z_to, *per;
	double lx = 1, ly = 1;
	int own, keep_zunit = 1;
	rc_layout layout = { 4, 0, 0 };
	rc_grid *g = NULL;
	int c, kind = RC_KIND_HEIGHT;

	if (o != NULL && o->have_l) {
		lx = o->lx;
		ly = o->ly;
	}
	for (size_t k = 0; k < strlen(MAGIC); k++)
		if (rc__in_getc(in) != MAGIC[k]) {
			rc_seterr(err, "bad magic line: expected 'Gwyddion Simple Field 1.0'");
			return NULL;
		}
	if ((head = rc_malloc(RC_HEADER_MAX + 1, err)) == NULL)
		return NULL;
	/* The header runs to the first NUL. */
	while ((c = rc__in_getc(in)) != 0) {
		if (c == EOF) {
			if (rc__in_check(in, err) == 0)
				rc_seterr(err, "truncated header: no NUL byte ends it");
			goto out;
		}
		if (n + strlen(MAGIC) >= RC_HEADER_MAX) {
			rc_seterr(err, "header longer than %zu bytes", RC_HEADER_MAX);
			goto out;
		}
		head[n++] = (char)c;
	}
	head[n] = '\0';
	/* Data at the next multiple of 4 after that NUL; the rest is padding. */
	while (in->consumed % 4 != 0) {
		if ((c = rc__in_getc(in)) == 0)
			continue;
		if (c != EOF)
			rc_seterr(err, "header padding holds a non-NUL byte");
		else if (rc__in_check(in, err) == 0)
			rc_seterr(err, "truncated header padding");
		goto out;
	}
	if ((f = rc_calloc(n / 2 + 1, sizeof(*f), err)) == NULL)
		goto out;
	for (line = head; line != NULL; line = next, lineno++) {
		char *key, *val;

		if ((next = strchr(line, '\n')) != NULL)
			*next++ = '\0';
		key = rc__header_trim(line);
		if (*key == '\0')
			continue;
		if (rc__header_split(key, &key, &val) != 0) {
			rc_seterr(err, "header line %zu is not 'Name = Value': '%s'",
			    lineno + 1, rc__io_quote(q, sizeof(q), key, strlen(key)));
			goto out;
		}
		f[nf].key = key;
		f[nf++].val = val;
	}
	if ((v = lookup(f, nf, "XRes")) == NULL || (v = lookup(f, nf, "YRes")) == NULL) {
		rc_seterr(err, "header lacks %s", lookup(f, nf, "XRes") ? "YRes" : "XRes");
		goto out;
	}
	if (rc__parse_size(lookup(f, nf, "XRes"), &nx) != 0 ||
	    rc__parse_size(lookup(f, nf, "YRes"), &ny) != 0) {
		rc_seterr(err, "XRes, YRes must be positive integers");
		goto out;
	}
	if ((v = lookup(f, nf, "XReal")) != NULL && rc__parse_double(v, &lx) != 0) {
		rc_seterr(err, "XReal '%s' is not a number", rc__io_quote(q, sizeof(q), v, strlen(v)));
		goto out;
	}
	if ((v = lookup(f, nf, "YReal")) != NULL && rc__parse_double(v, &ly) != 0) {
		rc_seterr(err, "YReal '%s' is not a number", rc__io_quote(q, sizeof(q), v, strlen(v)));
		goto out;
	}
	if ((v = lookup(f, nf, "surf.kind")) != NULL && (kind = rc_kind_parse(v)) < 0) {
		rc_seterr(err, "surf.kind '%s' is unknown", rc__io_quote(q, sizeof(q), v, strlen(v)));
		goto out;
	}
	own = lookup(f, nf, "surf.kind") != NULL;
	xyunit = (v = lookup(f, nf, "XYUnits")) != NULL ? v : "";
	zunit = (v = lookup(f, nf, "ZUnits")) != NULL ? v : "";
	unit = xyunit;
	z_to = zunit;
	if (own) {
		/* Our own file: lengths were written in metres; back to the
		 * units they were written from.  Files from before surf.z_unit
		 * had their values in surf.unit. */
		const char *su = lookup(f, nf, "surf.unit");
		const char *sz = lookup(f, nf, "surf.z_unit");

		if (su != NULL && metric(su) && strcmp(xyunit, "m") == 0)
			unit = su;
		if (sz != NULL && metric(sz) && strcmp(zunit, "m") == 0)
			z_to = sz;
		else if (sz == NULL && su != NULL && metric(su) &&
		    strcmp(zunit, "m") == 0 && rc_kind_is_length((enum rc_kind)kind)) {
			z_to = su;
			keep_zunit = 0;
		}
		if (su != NULL && !metric(su))
			unit = su;
		if (sz != NULL && !metric(sz))
			z_to = sz;
	}
	if (strlen(unit) >= sizeof(g->unit) || strlen(z_to) >= sizeof(g->z_unit)) {
		const char *u = strlen(unit) >= sizeof(g->unit) ? unit : z_to;

		rc_seterr(err, "unit '%s' longer than %zu characters", rc__io_quote(q,
		    sizeof(q), u, strlen(u)), sizeof(g->unit) - 1);
		goto out;
	}
	if (strcmp(unit, xyunit) != 0) {
		lx = rc_unit_convert(lx, xyunit, unit);
		ly = rc_unit_convert(ly, xyunit, unit);
	}
	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		goto out;
	if ((g = rc__in_read_values(in, nx, ny, lx, ly, &layout, err)) == NULL)
		goto out;
	g->kind = (enum rc_kind)kind;
	strcpy(g->unit, unit);
	if (keep_zunit)
		strcpy(g->z_unit, z_to);
	if (strcmp(z_to, zunit) != 0 && metric(z_to) && metric(zunit))
		for (size_t k = 0; k < nx * ny; k++)
			g->z[k] = rc_unit_convert(g->z[k], zunit, z_to);
	/* Ours say; a foreign file is a measured patch. */
	per = lookup(f, nf, "surf.periodic");
	g->periodic = own && (per == NULL || strcmp(per, "0") != 0);
	if ((v = lookup(f, nf, "surf.filled")) != NULL &&
	    rc_grid_filled_parse(g, v, err) != 0) {
		rc_grid_free(g);
		g = NULL;
		goto out;
	}
	for (size_t i = 0; i < nf; i++) {
		const char *key = f[i].key;
		int r = 0;

		if (strncmp(key, "surf.meta.", 10) == 0)
			r = rc_grid_meta_set(g, key + 10, f[i].val, err);
		else if (strcmp(key, "surf.history") == 0)
			r = rc_grid_history_add(g, f[i].val, err);
		else if (strncmp(key, "surf.", 5) == 0 || standard(key))
			continue;
		else if (rc__header_key_valid(key))
			/* Foreign fields (XOffset, Title, ...) are kept as metadata. */
			r = rc_grid_meta_set(g, key, f[i].val, err);
		else
			continue;	/* a name our metadata cannot hold */
		if (r != 0) {
			char msg[RC_ERRLEN];

			snprintf(msg, sizeof(msg), "%s", err ? err->msg : "");
			rc_seterr(err, "header field '%s': %s", rc__io_quote(q, sizeof(q),
			    key, strlen(key)), msg);
			rc_grid_free(g);
			g = NULL;
			goto out;
		}
	}
out:
	free(f);
	free(head);
	return g;
}
