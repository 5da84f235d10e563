/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_npy.c - numpy's .npy format, versions 1.0, 2.0 and 3.0.
 *
 * Written: float64 '<f8', C order, shape (ny, nx): a[j, i] is the value
 * at x index i, y index j, the row-major layout of the grid (and of an
 * image).  Read: '<f8', '>f8', '<f4', '>f4', either memory order, shape
 * (ny, nx) or (n,) (an n x 1 grid); with o->npy_xy the shape is (nx, ny),
 * a[i, j], as arrays of some other packages are.  The format carries no
 * cell size, units, periodic flag, metadata or history: the cell size and
 * unit come from the caller (-L, --unit), the grid is periodic unless the
 * caller says otherwise, and NaN values are missing points.
 */
#include "io_internal.h"

#include <stdlib.h>
#include <string.h>

static const unsigned char magic[6] = { 0x93, 'N', 'U', 'M', 'P', 'Y' };

int
rc__npy_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	unsigned char pre[10];
	char dict[256];
	size_t n, total;

	n = (size_t)snprintf(dict, sizeof(dict),
	    "{'descr': '<f8', 'fortran_order': False, 'shape': (%zu, %zu), }",
	    g->ny, g->nx);
	/* numpy pads the header with spaces and a final newline so the data
	 * start at a multiple of 64 bytes. */
	total = 10 + n + 1;
	total = (total + 63) / 64 * 64;
	memset(dict + n, ' ', total - 10 - n - 1);
	dict[total - 10 - 1] = '\n';
	memcpy(pre, magic, 6);
	pre[6] = 1;
	pre[7] = 0;
	rc__put_le16(pre + 8, (uint16_t)(total - 10));
	if (rc__io_write(fp, pre, 10, err) != 0 ||
	    rc__io_write(fp, dict, total - 10, err) != 0)
		return -1;
	return rc__io_write_values(fp, g->z, rc_grid_size(g), 8, err);
}

/* A tiny parser of the Python dict literal numpy writes. */
struct parser {
	const char *s, *end;
};

static void
skip_ws(struct parser *p)
{
	while (p->s < p->end && (*p->s == ' ' || *p->s == '\t' ||
	    *p->s == '\n' || *p->s == '\r'))
		p->s++;
}

static int
expect(struct parser *p, char c)
{
	skip_ws(p);
	if (p->s < p->end && *p->s == c) {
		p->s++;
		return 0;
	}
	return -1;
}

/* A quoted string without escapes into out (at most cap - 1 bytes). */
static int
string(struct parser *p, char *out, size_t cap)
{
	char q;
	size_t n = 0;

	skip_ws(p);
	if (p->s >= p->end || (*p->s != '\'' && *p->s != '"'))
		return -1;
	q = *p->s++;
	while (p->s < p->end && *p->s != q) {
		if (*p->s == '\\' || n + 1 >= cap)
			return -1;
		out[n++] = *p->s++;
	}
	if (p->s >= p->end)
		return -1;
	p->s++;
	out[n] = '\0';
	return 0;
}

static int
word(struct parser *p, const char *w)
{
	size_t n = strlen(w);

	skip_ws(p);
	if ((size_t)(p->end - p->s) >= n && memcmp(p->s, w, n) == 0) {
		p->s += n;
		return 0;
	}
	return -1;
}

/* "(a, b)", "(n,)" or "()"; returns the number of dimensions or -1.
 * A dimension beyond the grid limit is kept as SIZE_MAX, for the message. */
static int
shape(struct parser *p, size_t dim[3])
{
	int nd = 0;

	if (expect(p, '(') != 0)
		return -1;
	for (;;) {
		unsigned long long v = 0;
		int digits = 0;

		skip_ws(p);
		if (p->s < p->end && *p->s == ')') {
			p->s++;
			return nd;
		}
		while (p->s < p->end && *p->s >= '0' && *p->s <= '9') {
			if (v <= RC_GRID_MAX_POINTS)
				v = v * 10 + (unsigned)(*p->s - '0');
			p->s++;
			digits++;
		}
		if (digits == 0)
			return -1;
		if (p->s < p->end && *p->s == 'L')	/* Python 2 long */
			p->s++;
		if (nd < 3)
			dim[nd] = v > RC_GRID_MAX_POINTS ? SIZE_MAX : (size_t)v;
		nd++;
		skip_ws(p);
		if (p->s < p->end && *p->s == ',') {
			p->s++;
			continue;
		}
		if (expect(p, ')') != 0)
			return -1;
		return nd;
	}
}

/* Long: the .npy header dictionary (magic, version, descr, order, shape)
 * in file order, each checked where read. */
rc_grid *
rc__npy_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	unsigned char pre[12];
	char *head = NULL, key[32], descr[32] = "", q[64];
	size_t hlen, got, dim[3] = { 0, 0, 0 }, nx, ny;
	int major, have_descr = 0, have_order = 0, nd = -1, fortran = 0;
	struct parser p;
	rc_layout layout = { 8, 0, 0 };
	rc_grid *g = NULL;

	if ((got = rc__in_read(in, pre, 10)) < 10) {
		if (rc__in_check(in, err) == 0)
			rc_seterr(err, "truncated npy preamble: %zu of 10 bytes", got);
		return NULL;
	}
	major = pre[6];
	if (major == 1)
		hlen = rc__get_le16(pre + 8);
	else if (major == 2 || major == 3) {
		if ((got = rc__in_read(in, pre + 10, 2)) < 2) {
			if (rc__in_check(in, err) == 0)
				rc_seterr(err, "truncated npy preamble: %zu of 12 bytes",
				    10 + got);
			return NULL;
		}
		hlen = rc__get_le32(pre + 8);
	} else {
		rc_seterr(err, "npy format version %d.%d not supported (1.0, 2.0, 3.0)",
		    pre[6], pre[7]);
		return NULL;
	}
	if (hlen > RC_HEADER_MAX) {
		rc_seterr(err, "npy header length %zu exceeds the %zu-byte limit",
		    hlen, RC_HEADER_MAX);
		return NULL;
	}
	if ((head = rc_malloc(hlen + 1, err)) == NULL)
		return NULL;
	if ((got = rc__in_read(in, head, hlen)) < hlen) {
		if (rc__in_check(in, err) == 0)
			rc_seterr(err, "truncated npy header: expected %zu bytes, got %zu",
			    hlen, got);
		goto out;
	}
	head[hlen] = '\0';
	p.s = head;
	p.end = head + hlen;
	if (expect(&p, '{') != 0)
		goto syntax;
	for (;;) {
		skip_ws(&p);
		if (p.s < p.end && *p.s == '}') {
			p.s++;
			break;
		}
		if (string(&p, key, sizeof(key)) != 0 || expect(&p, ':') != 0)
			goto syntax;
		if (strcmp(key, "descr") == 0 && !have_descr) {
			if (string(&p, descr, sizeof(descr)) != 0) {
				rc_seterr(err, "npy dtype is not a simple type string "
				    "(structured arrays are not supported)");
				goto out;
			}
			have_descr = 1;
		} else if (strcmp(key, "fortran_order") == 0 && !have_order) {
			if (word(&p, "True") == 0)
				fortran = 1;
			else if (word(&p, "False") != 0)
				goto syntax;
			have_order = 1;
		} else if (strcmp(key, "shape") == 0 && nd < 0) {
			if ((nd = shape(&p, dim)) < 0)
				goto syntax;
		} else {
			rc_seterr(err, "npy header: unexpected or repeated key '%s'",
			    rc__io_quote(q, sizeof(q), key, strlen(key)));
			goto out;
		}
		skip_ws(&p);
		if (p.s < p.end && *p.s == ',')
			p.s++;
		else if (p.s < p.end && *p.s == '}')
			continue;
		else
			goto syntax;
	}
	skip_ws(&p);
	if (p.s != p.end)
		goto syntax;
	if (!have_descr || !have_order || nd < 0) {
		rc_seterr(err, "npy header lacks '%s'", !have_descr ? "descr" :
		    !have_order ? "fortran_order" : "shape");
		goto out;
	}
	if (strlen(descr) != 3 || (descr[0] != '<' && descr[0] != '>') ||
	    descr[1] != 'f' || (descr[2] != '4' && descr[2] != '8')) {
		rc_seterr(err, "npy dtype '%s' not supported (use <f8, >f8, <f4 or >f4)",
		    rc__io_quote(q, sizeof(q), descr, strlen(descr)));
		goto out;
	}
	layout.elsize = descr[2] == '8' ? 8 : 4;
	layout.big_endian = descr[0] == '>';
	if (nd == 1) {
		nx = dim[0];
		ny = 1;
	} else if (nd == 2 && o != NULL && o->npy_xy) {
		/* a[i, j]: C order stores it as our column-major */
		nx = dim[0];
		ny = dim[1];
		layout.fortran = !fortran;
	} else if (nd == 2) {
		ny = dim[0];
		nx = dim[1];
		layout.fortran = fortran;
	} else {
		rc_seterr(err, "npy array has %d dimensions; a grid needs 2 (or 1)", nd);
		goto out;
	}
	if (nx == SIZE_MAX || ny == SIZE_MAX) {
		rc_seterr(err, "npy shape too large: a dimension exceeds %u", RC_GRID_MAX_DIM);
		goto out;
	}
	g = rc__in_read_values(in, nx, ny, o && o->have_l ? o->lx : 1,
	    o && o->have_l ? o->ly : 1, &layout, err);
	goto out;
syntax:
	rc_seterr(err, "npy header is not a valid dict near '%s'",
	    rc__io_quote(q, sizeof(q), p.s, (size_t)(p.end - p.s)));
out:
	free(head);
	return g;
}
