/* SPDX-License-Identifier: GPL-3.0-or-later */
/* grid.c - the grid type, its metadata and history. */
#include "grid.h"

#include "fft.h"

#include <fftw3.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *kind_names[RC_KIND_COUNT] = {
	"height", "gap", "pressure", "displacement", "mask", "spectrum"
};

const char *
rc_kind_name(enum rc_kind k)
{
	return (unsigned)k < RC_KIND_COUNT ? kind_names[k] : "unknown";
}

int
rc_kind_parse(const char *name)
{
	for (int k = 0; k < RC_KIND_COUNT; k++)
		if (strcmp(name, kind_names[k]) == 0)
			return k;
	return -1;
}

void
rc_format_double(char *buf, size_t len, double v)
{
	for (int prec = 6; prec <= 17; prec++) {
		snprintf(buf, len, "%.*g", prec, v);
		if (strtod(buf, NULL) == v || !isfinite(v))
			return;
	}
}

int
rc_grid_check_shape(size_t nx, size_t ny, double lx, double ly, rc_err *err)
{
	if (nx == 0 || ny == 0)
		return rc_seterr(err, "grid size %zux%zu: both sizes must be at least 1", nx, ny);
	if (nx > RC_GRID_MAX_DIM || ny > RC_GRID_MAX_DIM)
		return rc_seterr(err, "grid size %zux%zu: a size exceeds %u", nx, ny,
		    RC_GRID_MAX_DIM);
	if (rc_mul_size(nx, ny) == 0 || nx * ny > RC_GRID_MAX_POINTS)
		return rc_seterr(err, "grid size %zux%zu: too many points", nx, ny);
	if (!(lx > 0) || !(ly > 0) || !isfinite(lx) || !isfinite(ly))
		return rc_seterr(err, "cell size %gx%g: lengths must be positive and finite",
		    lx, ly);
	return 0;
}

rc_grid *
rc_grid_new(size_t nx, size_t ny, double lx, double ly, rc_err *err)
{
	rc_grid *g;
	double *z;
	void *block;
	size_t n;

	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		return NULL;
	n = nx * ny;
	if ((z = rc_grid_values(n, &block, err)) == NULL)
		return NULL;
	memset(z, 0, n * sizeof(double));
	if ((g = rc_grid_adopt(nx, ny, lx, ly, z, err)) == NULL) {
		rc_fft_huge_free(z, block);
		return NULL;
	}
	g->z_block = block;
	return g;
}

/* From RC_FFT_HUGE_MIN up on transparent huge pages (rc_fft_huge): the
 * values' first touch, by reading or by the memset above, faults once per
 * 2 MB instead of once per 4 kB (reading a 512^2 grid took 9.5 ms of wall,
 * 6 of them 530 faults and 2.5 the first look at what the kernel copied
 * in; 1.4 ms on a huge page: clock_gettime, quiet machine). */
double *
rc_grid_values(size_t n, void **block, rc_err *err)
{
	double *z = rc_fft_huge(n * sizeof(double), block);

	if (z == NULL)
		rc_seterr(err, "out of memory (asked for %zu bytes for %zu grid "
		    "values)", n * sizeof(double), n);
	return z;
}

rc_grid *
rc_grid_adopt(size_t nx, size_t ny, double lx, double ly, double *z,
    rc_err *err)
{
	rc_grid *g;

	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		return NULL;
	if ((g = rc_calloc(1, sizeof(*g), err)) == NULL)
		return NULL;
	g->nx = nx;
	g->ny = ny;
	g->lx = lx;
	g->ly = ly;
	g->kind = RC_KIND_HEIGHT;
	g->periodic = 1;
	g->z = z;
	return g;
}

void
rc_grid_free(rc_grid *g)
{
	if (g == NULL)
		return;
	for (size_t i = 0; i < g->nmeta; i++) {
		free(g->meta[i].key);
		free(g->meta[i].val);
	}
	free(g->meta);
	for (size_t i = 0; i < g->nhistory; i++)
		free(g->history[i]);
	free(g->history);
	rc_fft_huge_free(g->z, g->z_block);
	free(g->valid);
	free(g->filled);
	free(g->x);
	free(g);
}

rc_grid *
rc_grid_new_like(const rc_grid *g, size_t nx, size_t ny, double lx, double ly,
    rc_err *err)
{
	rc_grid *c = rc_grid_new(nx, ny, lx, ly, err);

	if (c == NULL)
		return NULL;
	c->kind = g->kind;
	memcpy(c->unit, g->unit, sizeof(c->unit));
	memcpy(c->z_unit, g->z_unit, sizeof(c->z_unit));
	c->periodic = g->periodic;
	if (rc_grid_meta_copy(c, g, err) != 0)
		goto fail;
	for (size_t i = 0; i < g->nhistory; i++)
		if (rc_grid_history_add(c, g->history[i], err) != 0)
			goto fail;
	return c;
fail:
	rc_grid_free(c);
	return NULL;
}

rc_grid *
rc_grid_clone(const rc_grid *g, int copy_values, rc_err *err)
{
	rc_grid *c = rc_grid_new_like(g, g->nx, g->ny, g->lx, g->ly, err);

	if (c == NULL)
		return NULL;
	if (copy_values) {
		memcpy(c->z, g->z, rc_grid_size(g) * sizeof(double));
		if (g->valid != NULL) {
			if ((c->valid = rc_calloc(rc_grid_size(g), 1, err)) == NULL)
				goto fail;
			memcpy(c->valid, g->valid, rc_grid_size(g));
		}
		if (g->filled != NULL) {
			if ((c->filled = rc_calloc(rc_grid_size(g), 1, err)) == NULL)
				goto fail;
			memcpy(c->filled, g->filled, rc_grid_size(g));
		}
	}
	if (g->x != NULL) {	/* the positions are the shape's, not values */
		if ((c->x = rc_malloc(g->nx * sizeof(*c->x), err)) == NULL)
			goto fail;
		memcpy(c->x, g->x, g->nx * sizeof(*c->x));
	}
	return c;
fail:
	rc_grid_free(c);
	return NULL;
}

static int
valid_key(const char *key)
{
	if (*key == '\0')
		return 0;
	for (const char *p = key; *p; p++)
		if (!(*p == '_' || *p == '-' || *p == '.' ||
		    (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
		    (*p >= '0' && *p <= '9')))
			return 0;
	return 1;
}

int
rc_grid_meta_set(rc_grid *g, const char *key, const char *val, rc_err *err)
{
	char *v;

	if (!valid_key(key))
		return rc_seterr(err, "metadata key '%s': only letters, digits, '_', '-', '.'", key);
	/* One header line of surf(5), which refuses control characters other
	 * than tab: refused here, so that no grid is written unreadable. */
	for (const char *p = val; *p; p++)
		if (((unsigned char)*p < 0x20 && *p != '\t') || *p == 0x7f) {
			if (*p == '\n')
				return rc_seterr(err, "metadata value for '%s' contains "
				    "a newline", key);
			return rc_seterr(err, "metadata value for '%s' contains the "
			    "control character \\x%02x", key, (unsigned char)*p);
		}
	if ((v = strdup(val)) == NULL)
		return rc_seterr(err, "out of memory");
	for (size_t i = 0; i < g->nmeta; i++)
		if (strcmp(g->meta[i].key, key) == 0) {
			free(g->meta[i].val);
			g->meta[i].val = v;
			return 0;
		}
	rc_kv *m = realloc(g->meta, (g->nmeta + 1) * sizeof(*m));
	if (m == NULL || (m[g->nmeta].key = strdup(key)) == NULL) {
		if (m != NULL)
			g->meta = m;
		free(v);
		return rc_seterr(err, "out of memory");
	}
	g->meta = m;
	m[g->nmeta++].val = v;
	return 0;
}

int
rc_grid_meta_setf(rc_grid *g, const char *key, rc_err *err, const char *fmt, ...)
{
	char buf[1024];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(buf, sizeof(buf), fmt, ap);
	va_end(ap);
	return rc_grid_meta_set(g, key, buf, err);
}

int
rc_grid_meta_setd(rc_grid *g, const char *key, double v, rc_err *err)
{
	char buf[64];

	rc_format_double(buf, sizeof(buf), v);
	return rc_grid_meta_set(g, key, buf, err);
}

const char *
rc_grid_meta_get(const rc_grid *g, const char *key)
{
	for (size_t i = 0; i < g->nmeta; i++)
		if (strcmp(g->meta[i].key, key) == 0)
			return g->meta[i].val;
	return NULL;
}

void
rc_grid_meta_unset(rc_grid *g, const char *key)
{
	for (size_t i = 0; i < g->nmeta; i++)
		if (strcmp(g->meta[i].key, key) == 0) {
			free(g->meta[i].key);
			free(g->meta[i].val);
			memmove(&g->meta[i], &g->meta[i + 1],
			    (g->nmeta - i - 1) * sizeof(g->meta[0]));
			g->nmeta--;
			return;
		}
}

int
rc_grid_meta_getd(const rc_grid *g, const char *key, double *v)
{
	const char *s = rc_grid_meta_get(g, key);
	char *end;
	double d;

	if (s == NULL)
		return 0;
	d = strtod(s, &end);
	if (end == s || *end != '\0')
		return 0;
	*v = d;
	return 1;
}

int
rc_grid_meta_copy(rc_grid *dst, const rc_grid *src, rc_err *err)
{
	for (size_t i = 0; i < src->nmeta; i++)
		if (rc_grid_meta_set(dst, src->meta[i].key, src->meta[i].val, err) != 0)
			return -1;
	return 0;
}

size_t
rc_grid_filled_count(const rc_grid *g)
{
	size_t n = 0;

	if (g->filled != NULL)
		for (size_t k = 0; k < rc_grid_size(g); k++)
			n += g->filled[k] != 0;
	return n;
}

char *
rc_grid_filled_format(const rc_grid *g, rc_err *err)
{
	size_t n = rc_grid_size(g), len = 0, cap = 64;
	char *s = rc_malloc(cap, err), *t;

	if (s == NULL)
		return NULL;
	s[0] = '\0';
	for (size_t a = 0; g->filled != NULL && a < n; a++) {
		size_t b = a;

		if (!g->filled[a])
			continue;
		while (b + 1 < n && g->filled[b + 1])
			b++;
		/* two indices of at most 20 digits, '-', ',' and the NUL */
		if (len + 44 > cap) {
			if ((t = realloc(s, 2 * cap)) == NULL) {
				free(s);
				rc_seterr(err, "out of memory");
				return NULL;
			}
			s = t;
			cap *= 2;
		}
		len += (size_t)(a == b ? sprintf(s + len, "%s%zu", len ? "," : "", a) :
		    sprintf(s + len, "%s%zu-%zu", len ? "," : "", a, b));
		a = b;
	}
	return s;
}

/* A point index: decimal digits only; *p moves past them. */
static int
parse_index(const char **p, size_t *v)
{
	size_t x = 0;

	if (**p < '0' || **p > '9')
		return -1;
	for (; **p >= '0' && **p <= '9'; (*p)++) {
		if (x > (SIZE_MAX - 9) / 10)
			return -1;
		x = 10 * x + (size_t)(**p - '0');
	}
	*v = x;
	return 0;
}

int
rc_grid_filled_parse(rc_grid *g, const char *text, rc_err *err)
{
	size_t n = rc_grid_size(g), next = 0, a, b;
	const char *p = text;
	unsigned char *f;

	free(g->filled);
	g->filled = NULL;
	if (*p == '\0')
		return 0;
	if ((f = rc_calloc(n, 1, err)) == NULL)
		return -1;
	for (;;) {
		const char *at = p;
		int bad = parse_index(&p, &a) != 0;

		b = a;
		if (!bad && *p == '-') {
			p++;
			bad = parse_index(&p, &b) != 0;
		}
		if (bad || (*p != ',' && *p != '\0')) {
			free(f);
			return rc_seterr(err, "filled: '%.24s' at character %zu is not "
			    "a range A-B or an index A (digits, ranges separated by "
			    "commas)", at, (size_t)(at - text) + 1);
		}
		if (b < a || a < next || b >= n) {
			char what[48];

			free(f);
			snprintf(what, sizeof(what), a == b ? "index %zu" :
			    "range %zu-%zu", a, b);
			return rc_seterr(err, "filled: %s %s", what, b < a ?
			    "runs backwards" : a < next ? "does not follow the one "
			    "before it (ranges increase and do not overlap)" :
			    "lies beyond the last point of the grid");
		}
		memset(f + a, 1, b - a + 1);
		next = b + 1;
		if (*p++ == '\0')
			break;
	}
	g->filled = f;
	return 0;
}

int
rc_grid_history_add(rc_grid *g, const char *line, rc_err *err)
{
	char **h = realloc(g->history, (g->nhistory + 1) * sizeof(*h));
	char *s, *w;

	if (h == NULL)
		return rc_seterr(err, "out of memory");
	g->history = h;
	/* A history line is one header line of surf(5), which refuses control
	 * characters other than tab: each becomes the four characters \xNN
	 * (a command line may hold any byte, say in a file name). */
	if ((s = malloc(4 * strlen(line) + 1)) == NULL)
		return rc_seterr(err, "out of memory");
	for (w = s; *line; line++) {
		unsigned char c = (unsigned char)*line;

		if ((c < 0x20 && c != '\t') || c == 0x7f)
			w += sprintf(w, "\\x%02x", c);
		else
			*w++ = (char)c;
	}
	*w = '\0';
	h[g->nhistory++] = s;
	return 0;
}

int
rc_grid_all_finite(const rc_grid *g, size_t *bad)
{
	size_t n = rc_grid_size(g);

	for (size_t i = 0; i < n; i++)
		if (!isfinite(g->z[i])) {
			if (bad)
				*bad = i;
			return 0;
		}
	return 1;
}
