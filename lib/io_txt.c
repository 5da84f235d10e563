/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_txt.c - whitespace matrix: one grid row (fixed j) per line, x fastest
 * along the line, j = 0 first.  Lines starting with '#' are comments (as
 * numpy.loadtxt has them); "# key = value" comments carry what the other
 * formats keep in their headers (nx, ny, lx, ly, unit, z_unit, periodic,
 * kind, meta.KEY, history, filled), so a round trip loses nothing.  Values are
 * printed with %.17g, which reads back exactly; missing points are "nan".
 *
 * Read besides: the header of Gwyddion's ASCII matrix export ("# Width:
 * 10.000 um", "# Height:", "# Value units:", "# Channel:", "# Lateral
 * units:"), and columns: a file of 2 or 3 values per line on 4 lines or
 * more, without our "# nx" or Gwyddion's header, is x-z (a profile) or
 * x-y-z (a map), never a 2- or 3-column matrix.  Columns must lie on a
 * uniform grid (to 1% of the spacing: coordinates printed with 6
 * significant digits on lines of up to 10^4 points are that close); any
 * other set of points is refused, not resampled.  Periodic: our own files
 * say (1 when they do not), a plain matrix is periodic, Gwyddion's export
 * and columns (measurements) are not.
 */
#include "io_internal.h"
#include "units.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define MAGIC "# surf text grid: one row (fixed y) per line, x along the line"
#define TOKEN_MAX 128

int
rc__txt_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	char num[64], *filled;
	int bad = 0;

	if (rc__io_filled_text(g, &filled, err) != 0)
		return -1;
	bad |= fprintf(fp, "%s\n# nx = %zu\n# ny = %zu\n", MAGIC, g->nx, g->ny) < 0;
	rc_format_double(num, sizeof(num), g->lx);
	bad |= fprintf(fp, "# lx = %s\n", num) < 0;
	rc_format_double(num, sizeof(num), g->ly);
	bad |= fprintf(fp, "# ly = %s\n", num) < 0;
	if (g->unit[0] != '\0')
		bad |= fprintf(fp, "# unit = %s\n", g->unit) < 0;
	if (g->z_unit[0] != '\0')
		bad |= fprintf(fp, "# z_unit = %s\n", g->z_unit) < 0;
	bad |= fprintf(fp, "# periodic = %d\n", g->periodic ? 1 : 0) < 0;
	bad |= fprintf(fp, "# kind = %s\n", rc_kind_name(g->kind)) < 0;
	for (size_t i = 0; i < g->nmeta; i++)
		bad |= fprintf(fp, "# meta.%s = %s\n", g->meta[i].key,
		    g->meta[i].val) < 0;
	for (size_t i = 0; i < g->nhistory; i++)
		bad |= fprintf(fp, "# history = %s\n", g->history[i]) < 0;
	if (filled != NULL)
		bad |= fprintf(fp, "# filled = %s\n", filled) < 0;
	free(filled);
	for (size_t j = 0; j < g->ny && !bad; j++) {
		const double *row = g->z + j * g->nx;

		for (size_t i = 0; i < g->nx; i++)
			bad |= fprintf(fp, i ? " %.17g" : "%.17g", row[i]) < 0;
		bad |= putc('\n', fp) == EOF;
	}
	if (bad)
		return rc_seterr(err, "write error");
	return 0;
}

struct header {
	int have_nx, have_ny, have_lx, have_ly, kind;
	size_t nx, ny;
	double lx, ly;
	char unit[32], z_unit[32];
	int periodic;		/* -1 not said */
	int own;		/* our magic line */
	int gwy;		/* Gwyddion's export header */
	int have_width, have_height;
	double width, height;	/* Gwyddion's, in wunit and hunit */
	char wunit[32], hunit[32];
	char **mkey, **mval, **hist;
	size_t nmeta, nhist;
	char *filled;		/* our list of filled points */
};

static int
push(char ***v, size_t n, const char *s)
{
	char **p = realloc(*v, (n + 1) * sizeof(**v));

	if (p == NULL)
		return -1;
	*v = p;
	return (p[n] = strdup(s)) == NULL ? -1 : 0;
}

/* A unit of at most 31 bytes into dst. */
static int
unit_copy(char *dst, const char *s, size_t lineno, rc_err *err)
{
	if (strlen(s) >= 32)
		return rc_seterr(err, "line %zu: unit longer than 31 characters", lineno);
	strcpy(dst, s);
	return 0;
}

/* Gwyddion's "# Key: value" header lines (English labels); anything else
 * is a free comment.  Width and Height are "NUMBER UNIT". */
static int
gwy_comment(struct header *h, char *key, size_t lineno, rc_err *err)
{
	char *colon = strstr(key, ": "), *val, *e, q[64];

	if (colon == NULL)
		return 0;
	*colon = '\0';
	for (val = colon + 2; *val == ' ' || *val == '\t'; val++)
		;
	for (e = val + strlen(val); e > val && isspace((unsigned char)e[-1]); e--)
		;
	*e = '\0';
	if (strcmp(key, "Width") == 0 || strcmp(key, "Height") == 0) {
		int w = key[0] == 'W';
		double *v = w ? &h->width : &h->height;
		char *end;

		*v = strtod(val, &end);
		if (end == val || !(*v > 0) || !isfinite(*v) ||
		    (*end != '\0' && *end != ' ' && *end != '\t'))
			return rc_seterr(err, "line %zu: %s '%s' is not a positive "
			    "length", lineno, key, rc__io_quote(q, sizeof(q), val,
			    strlen(val)));
		while (*end == ' ' || *end == '\t')
			end++;
		if (unit_copy(w ? h->wunit : h->hunit, end, lineno, err) != 0)
			return -1;
		*(w ? &h->have_width : &h->have_height) = 1;
		h->gwy = 1;
	} else if (strcmp(key, "Value units") == 0) {
		if (unit_copy(h->z_unit, val, lineno, err) != 0)
			return -1;
		h->gwy = 1;
	} else if (strcmp(key, "Lateral units") == 0) {
		if (unit_copy(h->unit, val, lineno, err) != 0)
			return -1;
		h->gwy = 1;
	} else if (strcmp(key, "Channel") == 0) {
		if (push(&h->mkey, h->nmeta, "channel") != 0)
			return rc_seterr(err, "out of memory");
		if (push(&h->mval, h->nmeta, val) != 0) {
			free(h->mkey[h->nmeta]);
			return rc_seterr(err, "out of memory");
		}
		h->nmeta++;
		h->gwy = 1;
	}
	return 0;
}

/* A "# key = value" comment we know; anything else is a free comment. */
static int
comment(struct header *h, char *line, size_t lineno, rc_err *err)
{
	char *key, *eq, *val, *e, q[64];
	int r;

	if (strcmp(line, MAGIC) == 0)
		h->own = 1;
	for (key = line + 1; *key == ' ' || *key == '\t'; key++)
		;
	if ((eq = strstr(key, " = ")) == NULL)
		return gwy_comment(h, key, lineno, err);
	*eq = '\0';
	val = eq + 3;
	for (e = val + strlen(val); e > val && isspace((unsigned char)e[-1]); e--)
		;
	*e = '\0';
	if (strcmp(key, "nx") == 0 || strcmp(key, "ny") == 0) {
		size_t *v = key[1] == 'x' ? &h->nx : &h->ny;
		int *have = key[1] == 'x' ? &h->have_nx : &h->have_ny;

		if (*have)
			return rc_seterr(err, "line %zu: %s given twice", lineno, key);
		if (rc__parse_size(val, v) != 0)
			return rc_seterr(err, "line %zu: %s = '%s' is not a size",
			    lineno, key, rc__io_quote(q, sizeof(q), val, strlen(val)));
		*have = 1;
	} else if (strcmp(key, "lx") == 0 || strcmp(key, "ly") == 0) {
		double *v = key[1] == 'x' ? &h->lx : &h->ly;
		int *have = key[1] == 'x' ? &h->have_lx : &h->have_ly;

		if (*have)
			return rc_seterr(err, "line %zu: %s given twice", lineno, key);
		if (rc__parse_double(val, v) != 0)
			return rc_seterr(err, "line %zu: %s = '%s' is not a number",
			    lineno, key, rc__io_quote(q, sizeof(q), val, strlen(val)));
		*have = 1;
	} else if (strcmp(key, "unit") == 0) {
		if (strlen(val) >= sizeof(h->unit))
			return rc_seterr(err, "line %zu: unit longer than %zu characters",
			    lineno, sizeof(h->unit) - 1);
		strcpy(h->unit, val);
	} else if (strcmp(key, "z_unit") == 0) {
		if (strlen(val) >= sizeof(h->z_unit))
			return rc_seterr(err, "line %zu: z_unit longer than %zu characters",
			    lineno, sizeof(h->z_unit) - 1);
		strcpy(h->z_unit, val);
	} else if (strcmp(key, "periodic") == 0) {
		if (strcmp(val, "0") != 0 && strcmp(val, "1") != 0)
			return rc_seterr(err, "line %zu: periodic = '%s': want 0 or 1",
			    lineno, rc__io_quote(q, sizeof(q), val, strlen(val)));
		h->periodic = val[0] == '1';
	} else if (strcmp(key, "kind") == 0) {
		if ((r = rc_kind_parse(val)) < 0)
			return rc_seterr(err, "line %zu: unknown kind '%s'", lineno,
			    rc__io_quote(q, sizeof(q), val, strlen(val)));
		h->kind = r;
	} else if (strncmp(key, "meta.", 5) == 0 && key[5] != '\0') {
		if (push(&h->mkey, h->nmeta, key + 5) != 0)
			return rc_seterr(err, "out of memory");
		if (push(&h->mval, h->nmeta, val) != 0) {
			free(h->mkey[h->nmeta]);
			return rc_seterr(err, "out of memory");
		}
		h->nmeta++;
	} else if (strcmp(key, "history") == 0) {
		if (push(&h->hist, h->nhist, val) != 0)
			return rc_seterr(err, "out of memory");
		h->nhist++;
	} else if (strcmp(key, "filled") == 0) {
		if (h->filled != NULL)
			return rc_seterr(err, "line %zu: filled given twice", lineno);
		if ((h->filled = strdup(val)) == NULL)
			return rc_seterr(err, "out of memory");
	}
	return 0;
}

/* Gwyddion's Width and Height (each with its unit) into lx, ly in one
 * unit, which becomes the lateral unit unless the header names one. */
static int
gwy_size(struct header *h, double *lx, double *ly, rc_err *err)
{
	*lx = h->width;
	*ly = h->height;
	if (strcmp(h->wunit, h->hunit) != 0) {
		if (!rc_unit_is_length(h->wunit) || !rc_unit_is_length(h->hunit))
			return rc_seterr(err, "Gwyddion header: Width in '%s', Height "
			    "in '%s': not one length unit", h->wunit, h->hunit);
		*ly = rc_unit_convert(h->height, h->hunit, h->wunit);
	}
	if (h->unit[0] == '\0')
		strcpy(h->unit, h->wunit);
	else if (strcmp(h->unit, h->wunit) != 0 && h->wunit[0] != '\0') {
		if (!rc_unit_is_length(h->wunit) || !rc_unit_is_length(h->unit))
			return rc_seterr(err, "Gwyddion header: Width in '%s', "
			    "lateral units '%s'", h->wunit, h->unit);
		*lx = rc_unit_convert(*lx, h->wunit, h->unit);
		*ly = rc_unit_convert(*ly, h->wunit, h->unit);
	}
	return 0;
}

/* Does a coordinate lie on the uniform grid a0 + k d (to 1% of d)? */
static int
on_grid(double a, double a0, double d, size_t k)
{
	return fabs(a - (a0 + (double)k * d)) <= 0.01 * fabs(d);
}

/* x-z (ncol 2) or x-y-z (ncol 3) columns of n points on a uniform grid:
 * a profile of n x 1 points, or the map they cover.  Points are taken in
 * the order of the file, along x first or along y first; either axis may
 * run backwards. */
static rc_grid *
columns(const double *v, size_t ncol, size_t n, rc_err *err)
{
	size_t nxg = n, nyg = 1, run, bad = n;
	double x0 = v[0], y0 = 0, dx, dy, lx, ly;
	int x_fast = 1;
	rc_grid *g;

	if (ncol == 3) {
		y0 = v[1];
		/* the length of the first run of equal y (or equal x) */
		x_fast = v[ncol] != x0;
		for (run = 1; run < n && v[run * ncol + (x_fast ? 1 : 0)] ==
		    (x_fast ? y0 : x0); run++)
			;
		if (n % run != 0) {
			rc_seterr(err, "%zu x-y-z points (3 values per line): the first "
			    "line of equal %s holds %zu points, which does not divide "
			    "%zu, so they do not form a grid; resample them to a grid, "
			    "or add a '# nx = 3' line to read a 3-column height matrix",
			    n, x_fast ? "y" : "x", run, n);
			return NULL;
		}
		nxg = x_fast ? run : n / run;
		nyg = x_fast ? n / run : run;
	}
	dx = nxg > 1 ? (v[(x_fast ? nxg - 1 : (nxg - 1) * nyg) * ncol] - x0) /
	    (double)(nxg - 1) : 0;
	dy = nyg > 1 ? (v[(x_fast ? (nyg - 1) * nxg : nyg - 1) * ncol + 1] - y0) /
	    (double)(nyg - 1) : 0;
	if (nxg > 1 && dx == 0)
		bad = 0;
	if (nyg > 1 && dy == 0)
		bad = 0;
	for (size_t k = 0; k < n && bad == n; k++) {
		size_t i = x_fast ? k % nxg : k / nyg, j = x_fast ? k / nxg : k % nyg;

		if (!on_grid(v[k * ncol], x0, dx, i) ||
		    (ncol == 3 && !on_grid(v[k * ncol + 1], y0, dy, j)))
			bad = k;
	}
	if (bad < n) {
		if (ncol == 2)
			rc_seterr(err, "%zu x-z points (2 values per line): x is not "
			    "uniformly spaced (line %zu of the data: x = %g, a uniform "
			    "step would give %g); resample the profile to a uniform "
			    "step, or add a '# nx = 2' line to read a 2-column height "
			    "matrix", n, bad + 1, v[bad * ncol], x0 + (double)bad * dx);
		else
			rc_seterr(err, "%zu x-y-z points (3 values per line) do not "
			    "form a uniform %zux%zu grid (line %zu of the data is off "
			    "it); resample them to a grid, or add a '# nx = 3' line to "
			    "read a 3-column height matrix", n, nxg, nyg, bad + 1);
		return NULL;
	}
	/* A line has the spacing of its one axis both ways. */
	if (nxg == 1)
		dx = dy;
	if (nyg == 1)
		dy = dx;
	lx = (double)nxg * fabs(dx);
	ly = (double)nyg * fabs(dy);
	if ((g = rc__io_grid_alloc(nxg, nyg, lx, ly, err)) == NULL)
		return NULL;
	for (size_t k = 0; k < n; k++) {
		size_t i = x_fast ? k % nxg : k / nyg, j = x_fast ? k / nxg : k % nyg;

		if (dx < 0)
			i = nxg - 1 - i;
		if (dy < 0)
			j = nyg - 1 - j;
		g->z[j * nxg + i] = v[k * ncol + ncol - 1];
	}
	g->periodic = 0;	/* a measurement */
	return g;
}

/* Long: one pass over the text in file order (header comments, separator,
 * rows, columns); each check sits where its input is read. */
rc_grid *
rc__txt_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	struct header h = { .periodic = -1 };
	double *v = NULL, lx = 1, ly = 1;
	size_t nv = 0, cap = 0, nx = 0, rows = 0, lineno = 1, first_line = 0;
	size_t inrow = 0, tlen = 0;
	char tok[TOKEN_MAX + 1], q[64], *cline = NULL;
	rc_grid *g = NULL;
	int c, at_start = 1, in_comment = 0, comment_is_header = 0;

	if (o != NULL && o->have_l) {
		lx = o->lx;
		ly = o->ly;
	}
	if ((cline = rc_malloc(RC_HEADER_MAX + 1, err)) == NULL)
		return NULL;
	/* One pass over characters: no line is ever held whole, so a long
	 * row costs nothing beyond its values. */
	for (;;) {
		c = rc__in_getc(in);
		if (in_comment) {
			if (c != '\n' && c != EOF) {
				if (comment_is_header) {
					if (tlen >= RC_HEADER_MAX) {
						rc_seterr(err, "line %zu: comment longer than %zu bytes",
						    lineno, RC_HEADER_MAX);
						goto fail;
					}
					cline[tlen++] = (char)c;
				}
				continue;
			}
			if (comment_is_header) {
				cline[tlen] = '\0';
				if (strlen(cline) == tlen &&
				    comment(&h, cline, lineno, err) != 0)
					goto fail;
			}
			in_comment = 0;
			tlen = 0;
		} else if (c == '#') {
			if (tlen > 0)
				goto token;
			/* Only whole-line comments before the data carry keys. */
			in_comment = 1;
			comment_is_header = at_start && rows == 0 && inrow == 0;
			cline[0] = '#';
			tlen = 1;
			continue;
		} else if (c == 0) {
			rc_seterr(err, "line %zu: NUL byte: not a text file", lineno);
			goto fail;
		} else if (c != EOF && c != '\n' && !isspace(c)) {
			if (tlen >= TOKEN_MAX) {
				tok[TOKEN_MAX] = '\0';
				rc_seterr(err, "line %zu: '%s' is not a number", lineno,
				    rc__io_quote(q, sizeof(q), tok, TOKEN_MAX));
				goto fail;
			}
			tok[tlen++] = (char)c;
			at_start = 0;
			continue;
		}
token:
		if (tlen > 0) {
			double d;

			tok[tlen] = '\0';
			if (rc__parse_double(tok, &d) != 0) {
				rc_seterr(err, "line %zu: '%s' is not a number", lineno,
				    rc__io_quote(q, sizeof(q), tok, tlen));
				goto fail;
			}
			if (nv == cap) {
				size_t ncap = cap ? 2 * cap : 1024;
				double *p;

				if (ncap > RC_GRID_MAX_POINTS)
					ncap = RC_GRID_MAX_POINTS;
				if (nv >= ncap) {
					rc_seterr(err, "line %zu: more than %zu values", lineno,
					    (size_t)RC_GRID_MAX_POINTS);
					goto fail;
				}
				if ((p = realloc(v, ncap * sizeof(*v))) == NULL) {
					rc_seterr(err, "out of memory (asked for %zu bytes)",
					    ncap * sizeof(*v));
					goto fail;
				}
				v = p;
				cap = ncap;
			}
			/* A side longer than any grid may have ends the read now,
			 * not when memory runs out (an endless pipe of "1\n"). */
			if (inrow >= RC_GRID_MAX_DIM) {
				rc_seterr(err, "line %zu: more than %u values in a row",
				    lineno, RC_GRID_MAX_DIM);
				goto fail;
			}
			v[nv++] = d;
			inrow++;
			tlen = 0;
		}
		if (c == '#') {		/* a comment after values */
			in_comment = 1;
			comment_is_header = 0;
			continue;
		}
		if (c == '\n' || c == EOF) {
			if (inrow > 0) {
				if (rows == 0) {
					nx = inrow;
					first_line = lineno;
				} else if (inrow != nx) {
					rc_seterr(err, "line %zu has %zu values, line %zu has %zu",
					    lineno, inrow, first_line, nx);
					goto fail;
				} else if (rows >= RC_GRID_MAX_DIM) {
					rc_seterr(err, "line %zu: more than %u rows", lineno,
					    RC_GRID_MAX_DIM);
					goto fail;
				}
				rows++;
				inrow = 0;
			}
			at_start = 1;
			if (c == EOF)
				break;
			lineno++;
		}
	}
	if (rc__in_check(in, err) != 0)
		goto fail;
	if (rows == 0) {
		rc_seterr(err, "no values (empty input or only comments)");
		goto fail;
	}
	if ((h.have_nx && h.nx != nx) || (h.have_ny && h.ny != rows)) {
		rc_seterr(err, "header says %zux%zu, the data are %zux%zu",
		    h.have_nx ? h.nx : nx, h.have_ny ? h.ny : rows, nx, rows);
		goto fail;
	}
	if (h.have_lx != h.have_ly) {
		rc_seterr(err, "header gives %s without %s", h.have_lx ? "lx" : "ly",
		    h.have_lx ? "ly" : "lx");
		goto fail;
	}
	if (h.have_lx) {
		lx = h.lx;
		ly = h.ly;
	}
	if (h.have_width != h.have_height) {
		rc_seterr(err, "Gwyddion header gives %s without %s",
		    h.have_width ? "Width" : "Height", h.have_width ? "Height" : "Width");
		goto fail;
	}
	if (h.have_width && gwy_size(&h, &lx, &ly, err) != 0)
		goto fail;
	if (!h.own && !h.have_nx && !h.have_ny && !h.have_width &&
	    (nx == 2 || nx == 3) && rows >= 4)
		g = columns(v, nx, rows, err);
	else if ((g = rc__io_grid_alloc(nx, rows, lx, ly, err)) != NULL) {
		memcpy(g->z, v, nv * sizeof(*v));
		/* Our files say; a plain matrix is periodic by rule; Gwyddion
		 * exports measurements. */
		g->periodic = h.periodic >= 0 ? h.periodic : !h.gwy;
	}
	if (g == NULL)
		goto fail;
	strcpy(g->z_unit, h.z_unit);
	g->kind = (enum rc_kind)h.kind;
	if (h.unit[0] != '\0')
		strcpy(g->unit, h.unit);
	for (size_t i = 0; i < h.nmeta; i++)
		if (rc_grid_meta_set(g, h.mkey[i], h.mval[i], err) != 0)
			goto fail;
	for (size_t i = 0; i < h.nhist; i++)
		if (rc_grid_history_add(g, h.hist[i], err) != 0)
			goto fail;
	if (h.filled != NULL && rc_grid_filled_parse(g, h.filled, err) != 0)
		goto fail;
	goto out;
fail:
	rc_grid_free(g);
	g = NULL;
out:
	for (size_t i = 0; i < h.nmeta; i++) {
		free(h.mkey[i]);
		free(h.mval[i]);
	}
	for (size_t i = 0; i < h.nhist; i++)
		free(h.hist[i]);
	free(h.mkey);
	free(h.mval);
	free(h.hist);
	free(h.filled);
	free(cline);
	free(v);
	return g;
}
