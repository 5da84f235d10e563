/* SPDX-License-Identifier: GPL-3.0-or-later */
/* checkpoint.c - write, read and check the checkpoint of a list of
 * contact solves (see checkpoint.h for the format). */
#include "checkpoint.h"

#include <errno.h>
#include <fcntl.h>
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io.h"
#include "layer.h"
#include "solver.h"

/* 2: the identity hash covers metadata, units and the missing-point mask;
 * 3: the scene (boundary, kernel, effects); 4: the adhesive law;
 * 5: checkpoint.sum over the whole state (an edited row or displacement is
 * refused).  Versions 2 to 4 are still read, without the sum. */
#define VERSION 6
#define FNV_OFFSET 14695981039346656037ULL
#define FNV_PRIME 1099511628211ULL

static uint64_t
fnv_u64(uint64_t h, uint64_t v)
{
	for (int b = 0; b < 8; b++) {
		h ^= (v >> (8 * b)) & 0xff;
		h *= FNV_PRIME;
	}
	return h;
}

static uint64_t
fnv_double(uint64_t h, double d)
{
	uint64_t v;

	memcpy(&v, &d, sizeof(v));
	return fnv_u64(h, v);
}

/* The bytes of s and its terminating NUL (so "ab","c" and "a","bc" differ). */
static uint64_t
fnv_str(uint64_t h, const char *s)
{
	do {
		h ^= (unsigned char)*s;
		h *= FNV_PRIME;
	} while (*s++ != '\0');
	return h;
}

/* FNV-1a over the size and the values' bit patterns. */
static uint64_t
hash_values(const rc_grid *g)
{
	uint64_t h = FNV_OFFSET;

	h = fnv_u64(h, g->nx);
	h = fnv_u64(h, g->ny);
	h = fnv_double(h, g->lx);
	h = fnv_double(h, g->ly);
	for (size_t k = 0; k < rc_grid_size(g); k++)
		h = fnv_double(h, g->z[k]);
	return h;
}

uint64_t
rc_checkpoint_hash(const rc_grid *g)
{
	uint64_t h = hash_values(g);
	size_t k, n = rc_grid_size(g);

	/* What else reaches the rows or the solve: the metadata (carried as
	 * columns), units, the periodic flag and missing points. */
	h = fnv_u64(h, g->nmeta);
	for (k = 0; k < g->nmeta; k++)
		h = fnv_str(fnv_str(h, g->meta[k].key), g->meta[k].val);
	h = fnv_str(fnv_str(h, g->unit), g->z_unit);
	h = fnv_u64(h, (uint64_t)g->periodic);
	h = fnv_u64(h, g->valid != NULL);
	if (g->valid != NULL)
		for (k = 0; k < n; k++)
			h = fnv_u64(h, g->valid[k]);
	return h;
}

/* checkpoint.sum: FNV-1a over the size, the displacement's bit patterns
 * and every checkpoint.* key and value in file order but the sum's own,
 * so that any edit of a row, the list, the progress or u is caught. */
uint64_t
rc_checkpoint_sum(const rc_grid *g)
{
	uint64_t h = hash_values(g);

	for (size_t k = 0; k < g->nmeta; k++)
		if (strncmp(g->meta[k].key, "checkpoint.", 11) == 0 &&
		    strcmp(g->meta[k].key, "checkpoint.sum") != 0)
			h = fnv_str(fnv_str(h, g->meta[k].key), g->meta[k].val);
	return h;
}

int
rc_checkpoint_init(rc_checkpoint *c, const rc_grid *g, const double *p,
    size_t np, rc_err *err)
{
	memset(c, 0, sizeof(*c));
	c->nx = g->nx;
	c->ny = g->ny;
	c->lx = g->lx;
	c->ly = g->ly;
	c->input_sum = rc_checkpoint_hash(g);
	if (np == 0)
		return rc_seterr(err, "checkpoint: empty pressure list");
	if ((c->pressures = rc_malloc(np * sizeof(double), err)) == NULL)
		return -1;
	memcpy(c->pressures, p, np * sizeof(double));
	c->npressures = np;
	c->stall = RC_STALL_WINDOW;
	c->boundary = RC_BOUNDARY_PERIODIC;
	c->kernel = RC_KERNEL_CONTINUUM;
	c->substrate = RC_SUBSTRATE_NONE;
	return 0;
}

void
rc_checkpoint_free(rc_checkpoint *c)
{
	free(c->pressures);
	free(c->columns);
	free(c->types);
	for (size_t k = 0; k < c->nrows; k++)
		free(c->rows[k]);
	free(c->rows);
	memset(c, 0, sizeof(*c));
}

/* A growing string. */
struct buf {
	char *s;
	size_t len, cap;
	int bad;
};

static void
put(struct buf *b, const char *s, size_t n)
{
	if (b->bad)
		return;
	if (b->len + n + 1 > b->cap) {
		size_t cap = b->cap ? b->cap : 256;
		char *t;

		while (b->len + n + 1 > cap)
			cap *= 2;
		if ((t = realloc(b->s, cap)) == NULL) {
			b->bad = 1;
			return;
		}
		b->s = t;
		b->cap = cap;
	}
	memcpy(b->s + b->len, s, n);
	b->len += n;
	b->s[b->len] = '\0';
}

static void
puts_escaped(struct buf *b, const char *s)
{
	for (; *s; s++)
		switch (*s) {
		case '\\':
			put(b, "\\\\", 2);
			break;
		case '\t':
			put(b, "\\t", 2);
			break;
		case ' ':
			put(b, "\\s", 2);
			break;
		default:
			put(b, s, 1);
		}
}

static char *
finish(struct buf *b, rc_err *err)
{
	if (b->bad || b->s == NULL) {
		free(b->s);
		rc_seterr(err, "checkpoint: out of memory");
		return NULL;
	}
	return b->s;
}

int
rc_checkpoint_add_row(rc_checkpoint *c, const rc_row *r, rc_err *err)
{
	struct buf cols = { 0 }, vals = { 0 };
	char *line, **rows;
	size_t i;

	for (i = 0; i < r->n; i++) {
		if (i) {
			put(&cols, "\t", 1);
			put(&vals, "\t", 1);
		}
		put(&cols, r->name[i], strlen(r->name[i]));
		puts_escaped(&vals, r->val[i]);
	}
	if ((line = finish(&vals, err)) == NULL) {
		free(cols.s);
		return -1;
	}
	if (c->columns == NULL) {
		if ((c->columns = finish(&cols, err)) == NULL ||
		    (c->types = malloc(r->n + 1)) == NULL) {
			free(line);
			return rc_seterr(err, "checkpoint: out of memory");
		}
		for (i = 0; i < r->n; i++)
			c->types[i] = r->is_str[i] ? 's' : 'n';
		c->types[r->n] = '\0';
	} else {
		int same = !cols.bad && cols.s != NULL &&
		    strcmp(cols.s, c->columns) == 0;

		free(cols.s);
		if (!same) {
			free(line);
			return rc_seterr(err, "checkpoint: row %zu has other columns "
			    "than the first", c->nrows);
		}
	}
	if ((rows = realloc(c->rows, (c->nrows + 1) * sizeof(*rows))) == NULL) {
		free(line);
		return rc_seterr(err, "checkpoint: out of memory");
	}
	c->rows = rows;
	c->rows[c->nrows++] = line;
	return 0;
}

/* Next tab-separated field of *s (NULL at the end), unescaped in place. */
static char *
field(char **s, int unescape)
{
	char *f = *s, *w, *r;

	if (f == NULL)
		return NULL;
	if ((r = strchr(f, '\t')) != NULL) {
		*r = '\0';
		*s = r + 1;
	} else
		*s = NULL;
	if (unescape)
		for (w = r = f; *r; r++) {
			if (*r == '\\' && r[1] != '\0') {
				r++;
				*w++ = *r == 't' ? '\t' : *r == 's' ? ' ' : *r;
			} else
				*w++ = *r;
		}
	else
		w = f + strlen(f);
	*w = '\0';
	return f;
}

int
rc_checkpoint_row(const rc_checkpoint *c, size_t k, rc_row *row, rc_err *err)
{
	char *names, *vals, *np, *vp, *name, *val;
	size_t i = 0;
	int status = 0;

	if (k >= c->nrows)
		return rc_seterr(err, "checkpoint: no row %zu", k);
	names = strdup(c->columns);
	vals = strdup(c->rows[k]);
	if (names == NULL || vals == NULL) {
		free(names);
		free(vals);
		return rc_seterr(err, "checkpoint: out of memory");
	}
	rc_row_clear(row);
	np = names;
	vp = vals;
	while ((name = field(&np, 0)) != NULL) {
		char *end;
		double v;

		if ((val = field(&vp, 1)) == NULL || c->types[i] == '\0') {
			status = rc_seterr(err, "checkpoint: row %zu has fewer values "
			    "than columns", k);
			break;
		}
		if (c->types[i] == 's')
			status = rc_row_str(row, name, val);
		else {
			errno = 0;
			v = strtod(val, &end);
			if (end == val || *end != '\0') {
				status = rc_seterr(err, "checkpoint: row %zu, column %s: "
				    "'%s' is not a number", k, name, val);
				break;
			}
			status = rc_row_num(row, name, v);
		}
		if (status != 0) {
			status = rc_seterr(err, "checkpoint: out of memory");
			break;
		}
		i++;
	}
	if (status == 0 && (vp != NULL || c->types[i] != '\0'))
		status = rc_seterr(err, "checkpoint: row %zu does not match its "
		    "columns", k);
	free(names);
	free(vals);
	return status;
}

static int
setd(rc_grid *g, const char *key, double v, rc_err *err)
{
	return rc_grid_meta_setd(g, key, v, err);
}

int
rc_checkpoint_write(const rc_checkpoint *c, const double *u, const char *path,
    rc_err *err)
{
	struct buf list = { 0 };
	char key[64], num[64], *s;
	rc_grid *g;
	int r = -1;

	if ((g = rc_grid_new(c->nx, c->ny, c->lx, c->ly, err)) == NULL)
		return -1;
	g->kind = RC_KIND_DISPLACEMENT;
	memcpy(g->z, u, c->nx * c->ny * sizeof(double));
	for (size_t k = 0; k < c->npressures; k++) {
		rc_format_double(num, sizeof(num), c->pressures[k]);
		if (k)
			put(&list, ",", 1);
		put(&list, num, strlen(num));
	}
	if ((s = finish(&list, err)) == NULL)
		goto out;
	if (rc_grid_meta_setf(g, "checkpoint.version", err, "%d", VERSION) ||
	    rc_grid_meta_setf(g, "checkpoint.input_sum", err, "%016" PRIx64,
	    c->input_sum) ||
	    rc_grid_meta_set(g, "checkpoint.method", c->method, err) ||
	    setd(g, "checkpoint.tol", c->tol, err) ||
	    setd(g, "checkpoint.E", c->modulus, err) ||
	    setd(g, "checkpoint.alpha", c->alpha, err) ||
	    rc_grid_meta_setf(g, "checkpoint.fd", err, "%d", c->fd != 0) ||
	    rc_grid_meta_setf(g, "checkpoint.max_iter", err, "%ld", c->max_iter) ||
	    rc_grid_meta_setf(g, "checkpoint.stall", err, "%ld", c->stall) ||
	    rc_grid_meta_set(g, "checkpoint.boundary",
	    rc_boundary_name((enum rc_boundary)c->boundary), err) ||
	    rc_grid_meta_set(g, "checkpoint.kernel",
	    rc_kernel_name((enum rc_kernel)c->kernel), err) ||
	    setd(g, "checkpoint.hardness", c->hardness, err) ||
	    setd(g, "checkpoint.thickness", c->thickness, err) ||
	    rc_grid_meta_set(g, "checkpoint.substrate",
	    rc_substrate_name((enum rc_substrate)c->substrate), err) ||
	    setd(g, "checkpoint.poisson", c->poisson, err) ||
	    setd(g, "checkpoint.adhesion", c->adhesion, err) ||
	    setd(g, "checkpoint.range", c->range, err) ||
	    rc_grid_meta_set(g, "checkpoint.law",
	    rc_adhesion_law_name((enum rc_adhesion_law)c->law), err) ||
	    rc_grid_meta_set(g, "checkpoint.pressure_kind",
	    c->reduced ? "reduced" : "absolute", err) ||
	    rc_grid_meta_set(g, "checkpoint.pressures", s, err) ||
	    rc_grid_meta_setf(g, "checkpoint.next", err, "%zu", c->next) ||
	    rc_grid_meta_setf(g, "checkpoint.unconverged", err, "%zu",
	    c->unconverged) ||
	    rc_grid_meta_set(g, "checkpoint.state",
	    c->solving ? "solving" : "between", err) ||
	    rc_grid_meta_setf(g, "checkpoint.iterations", err, "%ld",
	    c->iterations)) {
		free(s);
		goto out;
	}
	free(s);
	if (c->nrows > 0 &&
	    (rc_grid_meta_set(g, "checkpoint.columns", c->columns, err) ||
	    rc_grid_meta_set(g, "checkpoint.types", c->types, err)))
		goto out;
	for (size_t k = 0; k < c->nrows; k++) {
		snprintf(key, sizeof(key), "checkpoint.row.%zu", k);
		if (rc_grid_meta_set(g, key, c->rows[k], err) != 0)
			goto out;
	}
	if (rc_grid_meta_setf(g, "checkpoint.sum", err, "%016" PRIx64,
	    rc_checkpoint_sum(g)) == 0)
		r = rc_grid_write(g, path, RC_FMT_SURF, err);
out:
	rc_grid_free(g);
	return r;
}

static const char *
need(const rc_grid *g, const char *key, rc_err *err)
{
	const char *v = rc_grid_meta_get(g, key);

	if (v == NULL)
		rc_seterr(err, "not a gfmd-solve checkpoint (no meta.%s)", key);
	return v;
}

static int
need_double(const rc_grid *g, const char *key, double *v, rc_err *err)
{
	if (need(g, key, err) == NULL)
		return -1;
	if (!rc_grid_meta_getd(g, key, v))
		return rc_seterr(err, "meta.%s: not a number", key);
	return 0;
}

/* A number in [lo, hi] (open at an end where open_lo / open_hi). */
static int
need_range(const rc_grid *g, const char *key, double lo, int open_lo,
    double hi, int open_hi, double *v, rc_err *err)
{
	if (need_double(g, key, v, err) != 0)
		return -1;
	if (!isfinite(*v) || (open_lo ? !(*v > lo) : !(*v >= lo)) ||
	    (open_hi ? !(*v < hi) : !(*v <= hi)))
		return rc_seterr(err, "meta.%s = %s: want a number in %c%g, %g%c",
		    key, rc_grid_meta_get(g, key), open_lo ? '(' : '[', lo, hi,
		    open_hi ? ')' : ']');
	return 0;
}

static int
need_long(const rc_grid *g, const char *key, long lo, long hi, long *v,
    rc_err *err)
{
	const char *s = need(g, key, err);
	char *end;

	if (s == NULL)
		return -1;
	errno = 0;
	*v = strtol(s, &end, 10);
	if (end == s || *end != '\0' || errno != 0 || *v < lo || *v > hi)
		return rc_seterr(err, "meta.%s = %s: want an integer from %ld to %ld",
		    key, s, lo, hi);
	return 0;
}

/* A name among those parse knows (its value into *v). */
static int
need_name(const rc_grid *g, const char *key, int (*parse)(const char *),
    int *v, rc_err *err)
{
	const char *s = need(g, key, err);

	if (s == NULL)
		return -1;
	if ((*v = parse(s)) < 0)
		return rc_seterr(err, "meta.%s = %s: unknown", key, s);
	return 0;
}

static int
substrate_parse(const char *name)
{
	return strcmp(name, "none") == 0 ? RC_SUBSTRATE_NONE :
	    rc_substrate_parse(name);
}

/* The scene (version 3, the adhesive law since 4); a version 2
 * checkpoint's as rc_checkpoint_init leaves it, the boundary kind
 * unrecorded; before 4 the law was the exponential one. */
static int
read_scene(const rc_grid *g, long version, rc_checkpoint *c, rc_err *err)
{
	c->boundary = -1;
	c->kernel = RC_KERNEL_CONTINUUM;
	c->substrate = RC_SUBSTRATE_NONE;
	c->law = RC_ADHESION_EXPONENTIAL;
	if (version < 3)
		return 0;
	if (version >= 4 && need_name(g, "checkpoint.law",
	    rc_adhesion_law_parse, &c->law, err))
		return -1;
	/* the ranges gfmd-solve accepts, and 0 for an effect that is off
	 * (hardness: 0 or inf, no cap) */
	if (need_name(g, "checkpoint.boundary", rc_boundary_parse, &c->boundary,
	    err) ||
	    need_name(g, "checkpoint.kernel", rc_kernel_parse, &c->kernel, err) ||
	    need_name(g, "checkpoint.substrate", substrate_parse, &c->substrate,
	    err) ||
	    need_double(g, "checkpoint.hardness", &c->hardness, err) ||
	    need_range(g, "checkpoint.thickness", 0, 0, HUGE_VAL, 1,
	    &c->thickness, err) ||
	    need_range(g, "checkpoint.poisson", -1, 1, 0.5, 0, &c->poisson,
	    err) ||
	    need_range(g, "checkpoint.adhesion", 0, 0, HUGE_VAL, 1,
	    &c->adhesion, err) ||
	    need_range(g, "checkpoint.range", 0, 0, HUGE_VAL, 1, &c->range, err))
		return -1;
	if (!(c->hardness >= 0))
		return rc_seterr(err, "meta.checkpoint.hardness = %s: want 0, "
		    "inf or a positive number",
		    rc_grid_meta_get(g, "checkpoint.hardness"));
	return 0;
}

/* The pressures: positive, or (with adhesion, read before) any finite
 * value, as gfmd-solve accepts them. */
static int
parse_list(rc_checkpoint *c, const char *s, rc_err *err)
{
	size_t n = 1;
	const char *q;

	for (q = s; *q; q++)
		n += *q == ',';
	if ((c->pressures = rc_malloc(n * sizeof(double), err)) == NULL)
		return -1;
	for (q = s; c->npressures < n; ) {
		char *end;
		double v = strtod(q, &end);

		if (end == q || (*end != ',' && *end != '\0') ||
		    !(v > 0 || c->adhesion > 0) || !isfinite(v))
			return rc_seterr(err, "meta.checkpoint.pressures: bad list "
			    "'%s'", s);
		c->pressures[c->npressures++] = v;
		q = *end ? end + 1 : end;
	}
	return 0;
}

/* Finished row k belongs to pressures[k]: its p_star (a reduced list) or
 * p (an absolute one) is that pressure, exactly (rows hold shortest
 * round-trip numbers). */
static int
check_rows_pressures(const rc_checkpoint *c, rc_err *err)
{
	const char *want = c->reduced ? "p_star" : "p", *s;
	size_t col = 0, len = strlen(want);
	int found = 0;

	for (s = c->columns; ; col++) {
		size_t n = strcspn(s, "\t");

		if (n == len && strncmp(s, want, len) == 0) {
			found = 1;
			break;
		}
		if (s[n] == '\0')
			break;
		s += n + 1;
	}
	if (!found)
		return rc_seterr(err, "meta.checkpoint.columns: no %s column", want);
	for (size_t k = 0; k < c->nrows; k++) {
		char *end;
		double v;

		s = c->rows[k];
		for (size_t i = 0; i < col && s != NULL; i++)
			if ((s = strchr(s, '\t')) != NULL)
				s++;
		v = s != NULL ? strtod(s, &end) : NAN;
		if (s == NULL || end == s || (*end != '\t' && *end != '\0') ||
		    v != c->pressures[k])
			return rc_seterr(err, "meta.checkpoint.row.%zu: %s is not "
			    "pressure %zu of the list (%.17g)", k, want, k + 1,
			    c->pressures[k]);
	}
	return 0;
}

/* Long: the checkpoint's header keys in file order, each checked where
 * read. */
int
rc_checkpoint_read(rc_checkpoint *c, rc_grid **up, const char *path,
    rc_err *err)
{
	rc_grid *g;
	const char *s;
	char key[64], *end;
	long v, version;

	memset(c, 0, sizeof(*c));
	*up = NULL;
	if ((g = rc_grid_read(path, NULL, err)) == NULL)
		return -1;
	c->nx = g->nx;
	c->ny = g->ny;
	c->lx = g->lx;
	c->ly = g->ly;
	if (need_long(g, "checkpoint.version", 0, LONG_MAX, &v, err) != 0)
		goto bad;
	if (v < 2 || v > VERSION) {
		rc_seterr(err, "checkpoint version %ld, this program reads 2 "
		    "to %d", v, VERSION);
		goto bad;
	}
	version = v;
	if (read_scene(g, v, c, err) != 0)
		goto bad;
	if ((s = need(g, "checkpoint.input_sum", err)) == NULL)
		goto bad;
	errno = 0;
	c->input_sum = strtoull(s, &end, 16);
	if (strlen(s) != 16 || *end != '\0' || errno != 0) {
		rc_seterr(err, "meta.checkpoint.input_sum = %s: want 16 hex digits", s);
		goto bad;
	}
	if ((s = need(g, "checkpoint.method", err)) == NULL)
		goto bad;
	if (strlen(s) >= sizeof(c->method) || rc_method_parse(s) < 0) {
		rc_seterr(err, "meta.checkpoint.method = %s: unknown", s);
		goto bad;
	}
	strcpy(c->method, s);
	/* The ranges gfmd-solve accepts for the options. */
	if (need_range(g, "checkpoint.tol", 0, 1, 1, 1, &c->tol, err) ||
	    need_range(g, "checkpoint.E", 0, 1, HUGE_VAL, 1, &c->modulus, err) ||
	    need_range(g, "checkpoint.alpha", 0, 0, 1, 0, &c->alpha, err) ||
	    need_long(g, "checkpoint.fd", 0, 1, &v, err))
		goto bad;
	c->fd = v != 0;
	c->stall = -1;
	if (need_long(g, "checkpoint.max_iter", 1, LONG_MAX, &c->max_iter, err) ||
	    (version >= 6 && need_long(g, "checkpoint.stall", 0, LONG_MAX,
	    &c->stall, err)) ||
	    (s = need(g, "checkpoint.pressure_kind", err)) == NULL)
		goto bad;
	if (strcmp(s, "reduced") != 0 && strcmp(s, "absolute") != 0) {
		rc_seterr(err, "meta.checkpoint.pressure_kind = %s: want reduced "
		    "or absolute", s);
		goto bad;
	}
	c->reduced = strcmp(s, "reduced") == 0;
	if ((s = need(g, "checkpoint.pressures", err)) == NULL ||
	    parse_list(c, s, err) != 0 ||
	    need_long(g, "checkpoint.next", 0, LONG_MAX, &v, err) != 0)
		goto bad;
	if ((size_t)v > c->npressures) {
		rc_seterr(err, "meta.checkpoint.next = %ld: the list has %zu "
		    "pressures", v, c->npressures);
		goto bad;
	}
	c->next = (size_t)v;
	c->unconverged = 0;
	if (version >= 6) {
		if (need_long(g, "checkpoint.unconverged", 0, LONG_MAX, &v, err))
			goto bad;
		if ((size_t)v > c->next) {
			rc_seterr(err, "meta.checkpoint.unconverged = %ld: more "
			    "than the %zu finished rows", v, c->next);
			goto bad;
		}
		c->unconverged = (size_t)v;
	}
	if ((s = need(g, "checkpoint.state", err)) == NULL)
		goto bad;
	if (strcmp(s, "solving") != 0 && strcmp(s, "between") != 0) {
		rc_seterr(err, "meta.checkpoint.state = %s: want solving or between", s);
		goto bad;
	}
	c->solving = strcmp(s, "solving") == 0;
	/* solving: pressures[next] exists; between: pressures[next - 1] does */
	if (c->solving ? c->next >= c->npressures : c->next == 0) {
		rc_seterr(err, "meta.checkpoint.state = %s with next = %zu of %zu "
		    "pressures: inconsistent", s, c->next, c->npressures);
		goto bad;
	}
	if (need_long(g, "checkpoint.iterations", 0, LONG_MAX, &c->iterations,
	    err) != 0)
		goto bad;
	if (!c->solving && c->iterations != 0) {
		rc_seterr(err, "meta.checkpoint.iterations = %ld between pressures: "
		    "want 0", c->iterations);
		goto bad;
	}
	if (g->kind != RC_KIND_DISPLACEMENT) {
		rc_seterr(err, "kind %s: a checkpoint holds a displacement",
		    rc_kind_name(g->kind));
		goto bad;
	}
	for (size_t k = 0; k < rc_grid_size(g); k++)
		if (!isfinite(g->z[k])) {
			rc_seterr(err, "displacement value %zu is not finite", k);
			goto bad;
		}
	if (c->next > 0) {
		const char *cols, *types;
		size_t ncols = 1;

		if ((cols = need(g, "checkpoint.columns", err)) == NULL ||
		    (types = need(g, "checkpoint.types", err)) == NULL)
			goto bad;
		for (s = cols; *s; s++)
			ncols += *s == '\t';
		if (strlen(types) != ncols || strspn(types, "ns") != ncols) {
			rc_seterr(err, "meta.checkpoint.types: want one n or s for "
			    "each of the %zu columns", ncols);
			goto bad;
		}
		if ((c->columns = strdup(cols)) == NULL ||
		    (c->types = strdup(types)) == NULL ||
		    (c->rows = calloc(c->next, sizeof(*c->rows))) == NULL) {
			rc_seterr(err, "out of memory");
			goto bad;
		}
		for (size_t k = 0; k < c->next; k++) {
			snprintf(key, sizeof(key), "checkpoint.row.%zu", k);
			if ((s = need(g, key, err)) == NULL)
				goto bad;
			if ((c->rows[k] = strdup(s)) == NULL) {
				rc_seterr(err, "out of memory");
				goto bad;
			}
			c->nrows++;
		}
		if (check_rows_pressures(c, err) != 0)
			goto bad;
	}
	/* last, so that a field out of range is named as such */
	if (version >= 5) {
		uint64_t want;

		if ((s = need(g, "checkpoint.sum", err)) == NULL)
			goto bad;
		errno = 0;
		want = strtoull(s, &end, 16);
		if (strlen(s) != 16 || *end != '\0' || errno != 0 ||
		    want != rc_checkpoint_sum(g)) {
			rc_seterr(err, "meta.checkpoint.sum = %s does not match its "
			    "content: the checkpoint was changed or damaged "
			    "since it was written", s);
			goto bad;
		}
	}
	*up = g;
	return 0;
bad:
	rc_grid_free(g);
	rc_checkpoint_free(c);
	return -1;
}

int
rc_checkpoint_lock(const char *path, char **lock_path, rc_err *err)
{
	const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
	size_t dirlen = (size_t)(base - path);
	struct stat st, held;
	char *name;
	int fd;

	*lock_path = NULL;
	if (stat(path, &st) == 0 && !S_ISREG(st.st_mode))
		return -2;
	if ((name = malloc(strlen(path) + 8)) == NULL)
		return rc_seterr(err, "out of memory");
	memcpy(name, path, dirlen);
	sprintf(name + dirlen, ".%s.lock", base);
	/* A holder removes the file before it releases the lock; a lock on a
	 * file that is no longer the one under this name is retried. */
	for (int tries = 0; tries < 100; tries++) {
		if ((fd = open(name, O_RDWR | O_CREAT | O_CLOEXEC, 0666)) < 0) {
			rc_seterr(err, "%s: cannot create the lock file: %s", name,
			    strerror(errno));
			free(name);
			return -1;
		}
		if (flock(fd, LOCK_EX | LOCK_NB) != 0) {
			int e = errno;

			close(fd);
			if (e == EWOULDBLOCK)
				rc_seterr(err, "another run is using this checkpoint "
				    "(it holds %s)", name);
			else
				rc_seterr(err, "%s: cannot lock: %s", name, strerror(e));
			free(name);
			return -1;
		}
		if (fstat(fd, &held) == 0 && stat(name, &st) == 0 &&
		    held.st_dev == st.st_dev && held.st_ino == st.st_ino) {
			*lock_path = name;
			return fd;
		}
		close(fd);
	}
	free(name);
	return rc_seterr(err, "%s: the lock file keeps changing", path);
}

void
rc_checkpoint_unlock(int fd, char *lock_path)
{
	if (fd >= 0) {
		if (lock_path != NULL)
			unlink(lock_path);
		close(fd);
	}
	free(lock_path);
}

/* Same bits, so that 0.1 written and read back compares equal. */
static int
same(double a, double b)
{
	return memcmp(&a, &b, sizeof(a)) == 0;
}

long
rc_checkpoint_iterations_add(long done, long more)
{
	return more > LONG_MAX - done ? LONG_MAX : done + more;
}

int
rc_checkpoint_match(const rc_checkpoint *s, const rc_checkpoint *n,
    rc_err *err)
{
	if (s->nx != n->nx || s->ny != n->ny)
		return rc_seterr(err, "checkpoint is for a %zux%zu grid, the "
		    "indenter is %zux%zu", s->nx, s->ny, n->nx, n->ny);
	if (!same(s->lx, n->lx) || !same(s->ly, n->ly))
		return rc_seterr(err, "checkpoint is for a %gx%g cell, the "
		    "indenter's is %gx%g", s->lx, s->ly, n->lx, n->ly);
	if (s->input_sum != n->input_sum)
		return rc_seterr(err, "checkpoint is for another indenter (heights "
		    "hash %016" PRIx64 ", this one %016" PRIx64 ")", s->input_sum,
		    n->input_sum);
	if (strcmp(s->method, n->method) != 0)
		return rc_seterr(err, "checkpoint has --method %s, this run %s",
		    s->method, n->method);
	if (!same(s->tol, n->tol))
		return rc_seterr(err, "checkpoint has --tol %.16g, this run %.16g",
		    s->tol, n->tol);
	if (!same(s->modulus, n->modulus))
		return rc_seterr(err, "checkpoint has -E %.16g, this run %.16g",
		    s->modulus, n->modulus);
	if (!same(s->alpha, n->alpha))
		return rc_seterr(err, "checkpoint has --alpha %.16g, this run %.16g",
		    s->alpha, n->alpha);
	if (s->fd != n->fd)
		return rc_seterr(err, "checkpoint was %s --fd, this run %s",
		    s->fd ? "with" : "without", n->fd ? "has it" : "has not");
	if (s->max_iter != n->max_iter)
		return rc_seterr(err, "checkpoint has --max-iter %ld, this run %ld",
		    s->max_iter, n->max_iter);
	if (s->stall >= 0 && s->stall != n->stall)
		return rc_seterr(err, "checkpoint has --stall %ld, this run %ld",
		    s->stall, n->stall);
	if (s->boundary >= 0 && s->boundary != n->boundary)
		return rc_seterr(err, "checkpoint has --boundary %s, this run %s",
		    rc_boundary_name((enum rc_boundary)s->boundary),
		    rc_boundary_name((enum rc_boundary)n->boundary));
	if (s->kernel != n->kernel)
		return rc_seterr(err, "checkpoint has --kernel %s, this run %s",
		    rc_kernel_name((enum rc_kernel)s->kernel),
		    rc_kernel_name((enum rc_kernel)n->kernel));
	if (!same(s->hardness, n->hardness))
		return rc_seterr(err, "checkpoint has --hardness %.16g, this run "
		    "%.16g (0: none)", s->hardness, n->hardness);
	if (!same(s->thickness, n->thickness) || s->substrate != n->substrate ||
	    !same(s->poisson, n->poisson))
		return rc_seterr(err, "checkpoint has --thickness %.16g "
		    "--substrate %s --poisson %.16g, this run %.16g, %s, %.16g "
		    "(0 and none: the half space)", s->thickness,
		    rc_substrate_name((enum rc_substrate)s->substrate), s->poisson,
		    n->thickness, rc_substrate_name((enum rc_substrate)n->substrate),
		    n->poisson);
	if (!same(s->adhesion, n->adhesion) || !same(s->range, n->range))
		return rc_seterr(err, "checkpoint has --adhesion %.16g --range "
		    "%.16g, this run %.16g, %.16g (0: none)", s->adhesion,
		    s->range, n->adhesion, n->range);
	if (s->law != n->law)
		return rc_seterr(err, "checkpoint has --law %s, this run %s",
		    rc_adhesion_law_name((enum rc_adhesion_law)s->law),
		    rc_adhesion_law_name((enum rc_adhesion_law)n->law));
	if (s->reduced != n->reduced)
		return rc_seterr(err, "checkpoint has %s pressures, this run %s",
		    s->reduced ? "reduced (-p)" : "absolute (--pressure-abs)",
		    n->reduced ? "reduced (-p)" : "absolute (--pressure-abs)");
	if (s->npressures != n->npressures)
		return rc_seterr(err, "checkpoint has %zu pressures, this run %zu",
		    s->npressures, n->npressures);
	for (size_t k = 0; k < s->npressures; k++)
		if (!same(s->pressures[k], n->pressures[k]))
			return rc_seterr(err, "pressure %zu: checkpoint has %.16g, "
			    "this run %.16g", k + 1, s->pressures[k], n->pressures[k]);
	return 0;
}
