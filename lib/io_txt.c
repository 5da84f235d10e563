/* io_txt.c - whitespace matrix: one grid row (fixed j) per line, x fastest
 * along the line, j = 0 first.  Lines starting with '#' are comments (as
 * numpy.loadtxt has them); "# key = value" comments carry what the other
 * formats keep in their headers (nx, ny, lx, ly, unit, kind, meta.KEY,
 * history), so a round trip loses nothing.  Values are printed with %.17g,
 * which reads back exactly.
 */
#include "io_internal.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>

#define MAGIC "# surf text grid: one row (fixed y) per line, x along the line"
#define TOKEN_MAX 128

int
rc_txt_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	char num[64];
	int bad = 0;

	bad |= fprintf(fp, "%s\n# nx = %zu\n# ny = %zu\n", MAGIC, g->nx, g->ny) < 0;
	rc_format_double(num, sizeof(num), g->lx);
	bad |= fprintf(fp, "# lx = %s\n", num) < 0;
	rc_format_double(num, sizeof(num), g->ly);
	bad |= fprintf(fp, "# ly = %s\n", num) < 0;
	if (g->unit[0] != '\0')
		bad |= fprintf(fp, "# unit = %s\n", g->unit) < 0;
	bad |= fprintf(fp, "# kind = %s\n", rc_kind_name(g->kind)) < 0;
	for (size_t i = 0; i < g->nmeta; i++)
		bad |= fprintf(fp, "# meta.%s = %s\n", g->meta[i].key,
		    g->meta[i].val) < 0;
	for (size_t i = 0; i < g->nhistory; i++)
		bad |= fprintf(fp, "# history = %s\n", g->history[i]) < 0;
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
	char unit[32];
	char **mkey, **mval, **hist;
	size_t nmeta, nhist;
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

/* A "# key = value" comment we know; anything else is a free comment. */
static int
comment(struct header *h, char *line, size_t lineno, rc_err *err)
{
	char *key, *eq, *val, *e, q[64];
	int r;

	for (key = line + 1; *key == ' ' || *key == '\t'; key++)
		;
	if ((eq = strstr(key, " = ")) == NULL)
		return 0;
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
		if (rc_parse_size(val, v) != 0)
			return rc_seterr(err, "line %zu: %s = '%s' is not a size",
			    lineno, key, rc_io_quote(q, sizeof(q), val, strlen(val)));
		*have = 1;
	} else if (strcmp(key, "lx") == 0 || strcmp(key, "ly") == 0) {
		double *v = key[1] == 'x' ? &h->lx : &h->ly;
		int *have = key[1] == 'x' ? &h->have_lx : &h->have_ly;

		if (*have)
			return rc_seterr(err, "line %zu: %s given twice", lineno, key);
		if (rc_parse_double(val, v) != 0)
			return rc_seterr(err, "line %zu: %s = '%s' is not a number",
			    lineno, key, rc_io_quote(q, sizeof(q), val, strlen(val)));
		*have = 1;
	} else if (strcmp(key, "unit") == 0) {
		if (strlen(val) >= sizeof(h->unit))
			return rc_seterr(err, "line %zu: unit longer than %zu characters",
			    lineno, sizeof(h->unit) - 1);
		strcpy(h->unit, val);
	} else if (strcmp(key, "kind") == 0) {
		if ((r = rc_kind_parse(val)) < 0)
			return rc_seterr(err, "line %zu: unknown kind '%s'", lineno,
			    rc_io_quote(q, sizeof(q), val, strlen(val)));
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
	}
	return 0;
}

rc_grid *
rc_txt_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	struct header h = { 0 };
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
		c = rc_in_getc(in);
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
				    rc_io_quote(q, sizeof(q), tok, TOKEN_MAX));
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
			if (rc_parse_double(tok, &d) != 0) {
				rc_seterr(err, "line %zu: '%s' is not a number", lineno,
				    rc_io_quote(q, sizeof(q), tok, tlen));
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
	if (rc_in_check(in, err) != 0)
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
	if ((g = rc_io_grid_alloc(nx, rows, lx, ly, err)) == NULL)
		goto fail;
	memcpy(g->z, v, nv * sizeof(*v));
	g->kind = (enum rc_kind)h.kind;
	strcpy(g->unit, h.unit);
	for (size_t i = 0; i < h.nmeta; i++)
		if (rc_grid_meta_set(g, h.mkey[i], h.mval[i], err) != 0)
			goto fail;
	for (size_t i = 0; i < h.nhist; i++)
		if (rc_grid_history_add(g, h.hist[i], err) != 0)
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
	free(cline);
	free(v);
	return g;
}
