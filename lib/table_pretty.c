/* SPDX-License-Identifier: GPL-3.0-or-later */
/* table_pretty.c - the aligned, rounded view of a result table for a
 * terminal (see table_write.h, rc_table_pretty).
 *
 * Column widths depend on every row, so the rows are kept and drawn by
 * rc_table_end.  Non-integer numbers are rounded to PRETTY_DIGITS
 * significant digits; integers, nan, inf and strings are shown as they
 * are (control characters as spaces).  Numeric columns are right-aligned,
 * text columns left-aligned.  A table wider than the terminal is drawn
 * transposed: one line per column name, one right-aligned value column per
 * row, as many rows side by side as fit (a block of 64 at most).
 */
#include "table_write.h"

#include <stdlib.h>
#include <string.h>

#define PRETTY_DIGITS 4
#define GAP "  "		/* between columns */
#define GAP_WIDTH 2

struct rc_table_kept {
	size_t ncols, nrows, cap;
	char **name;		/* ncols column names */
	unsigned char *text;	/* ncols: 1 if any cell is a string */
	char **cell;		/* nrows * ncols display strings */
};

static void
kept_free(struct rc_table_kept *k)
{
	if (k == NULL)
		return;
	for (size_t i = 0; i < k->ncols; i++)
		free(k->name[i]);
	for (size_t i = 0; i < k->nrows * k->ncols; i++)
		free(k->cell[i]);
	free(k->name);
	free(k->text);
	free(k->cell);
	free(k);
}

int
rc_table_pretty(rc_table_out *t, size_t width, rc_err *err)
{
	if (t->kept == NULL && (t->kept = calloc(1, sizeof(*t->kept))) == NULL)
		return rc_seterr(err, "out of memory");
	t->pretty_width = width ? width : 80;
	return 0;
}

/* An integer literal is shown whole (counts, sizes, seeds). */
static int
is_integer(const char *s)
{
	if (*s == '-')
		s++;
	if (*s == '\0')
		return 0;
	for (; *s; s++)
		if (*s < '0' || *s > '9')
			return 0;
	return 1;
}

static char *
display(const char *val, int is_str)
{
	char buf[64], *s;

	if (!is_str && !is_integer(val)) {
		char *end;
		double v = strtod(val, &end);
		if (end != val && *end == '\0') {
			snprintf(buf, sizeof(buf), "%.*g", PRETTY_DIGITS, v);
			return strdup(buf);
		}
	}
	if ((s = strdup(val)) == NULL)
		return NULL;
	for (char *p = s; *p; p++)
		if ((unsigned char)*p < 0x20 || *p == 0x7f)
			*p = ' ';
	return s;
}

/* Characters on screen: UTF-8 continuation bytes take no column. */
static size_t
text_width(const char *s)
{
	size_t n = 0;

	for (; *s; s++)
		n += ((unsigned char)*s & 0xC0) != 0x80;
	return n;
}

int
rc_table_keep_pretty(rc_table_out *t, const rc_row *r, rc_err *err)
{
	struct rc_table_kept *k = t->kept;

	if (k->nrows == 0) {
		k->ncols = r->n;
		k->name = calloc(r->n ? r->n : 1, sizeof(*k->name));
		k->text = calloc(r->n ? r->n : 1, 1);
		if (k->name == NULL || k->text == NULL)
			return rc_seterr(err, "out of memory");
		for (size_t i = 0; i < r->n; i++)
			if ((k->name[i] = display(r->name[i], 1)) == NULL)
				return rc_seterr(err, "out of memory");
	} else if (r->n != k->ncols)
		return rc_seterr(err, "internal: row has %zu columns, header %zu",
		    r->n, k->ncols);
	if (k->nrows == k->cap) {
		size_t cap = k->cap ? 2 * k->cap : 8;
		char **cell = realloc(k->cell, cap * (k->ncols ? k->ncols : 1) *
		    sizeof(*cell));
		if (cell == NULL)
			return rc_seterr(err, "out of memory");
		k->cell = cell;
		k->cap = cap;
	}
	for (size_t i = 0; i < r->n; i++) {
		char *c = display(r->val[i], r->is_str[i]);
		if (c == NULL) {
			for (size_t j = 0; j < i; j++)
				free(k->cell[k->nrows * k->ncols + j]);
			return rc_seterr(err, "out of memory");
		}
		k->cell[k->nrows * k->ncols + i] = c;
		k->text[i] |= r->is_str[i];
	}
	k->nrows++;
	t->nrows++;
	return 0;
}

/* s in a field of width w, right-aligned if right, no trailing blanks
 * after the last field. */
static void
field(FILE *fp, const char *s, size_t w, int right, int last)
{
	size_t n = text_width(s);

	if (right)
		for (size_t i = n; i < w; i++)
			fputc(' ', fp);
	fputs(s, fp);
	if (!right && !last)
		for (size_t i = n; i < w; i++)
			fputc(' ', fp);
}

static void
rule(FILE *fp, size_t n)
{
	for (size_t i = 0; i < n; i++)
		fputc('-', fp);
	fputc('\n', fp);
}

static void
draw_columns(FILE *fp, const struct rc_table_kept *k, const size_t *w)
{
	size_t total = 0;

	for (size_t i = 0; i < k->ncols; i++) {
		field(fp, k->name[i], w[i], !k->text[i], i + 1 == k->ncols);
		fputs(i + 1 < k->ncols ? GAP : "\n", fp);
		total += w[i] + (i ? GAP_WIDTH : 0);
	}
	rule(fp, total);
	for (size_t r = 0; r < k->nrows; r++)
		for (size_t i = 0; i < k->ncols; i++) {
			field(fp, k->cell[r * k->ncols + i], w[i], !k->text[i],
			    i + 1 == k->ncols);
			fputs(i + 1 < k->ncols ? GAP : "\n", fp);
		}
}

/* One line per column name; rows side by side in blocks that fit. */
static void
draw_transposed(FILE *fp, const struct rc_table_kept *k, size_t width)
{
	size_t namew = 0;
	char label[32];

	for (size_t i = 0; i < k->ncols; i++)
		namew = namew > text_width(k->name[i]) ? namew : text_width(k->name[i]);
	for (size_t first = 0; first < k->nrows;) {
		size_t used = namew, last = first, rw[64];

		/* At least one row per block, at most 64. */
		do {
			size_t w = 0;
			snprintf(label, sizeof(label), "row %zu", last + 1);
			if (k->nrows > 1)
				w = text_width(label);
			for (size_t i = 0; i < k->ncols; i++) {
				size_t n = text_width(k->cell[last * k->ncols + i]);
				w = w > n ? w : n;
			}
			if (last > first && used + GAP_WIDTH + w > width)
				break;
			rw[last - first] = w;
			used += GAP_WIDTH + w;
			last++;
		} while (last < k->nrows && last - first < 64);
		if (first > 0)
			fputc('\n', fp);
		if (k->nrows > 1) {
			field(fp, "", namew, 0, 0);
			for (size_t r = first; r < last; r++) {
				snprintf(label, sizeof(label), "row %zu", r + 1);
				fputs(GAP, fp);
				field(fp, label, rw[r - first], 1, r + 1 == last);
			}
			fputc('\n', fp);
			rule(fp, used);
		}
		for (size_t i = 0; i < k->ncols; i++) {
			field(fp, k->name[i], namew, 0, 0);
			for (size_t r = first; r < last; r++) {
				fputs(GAP, fp);
				field(fp, k->cell[r * k->ncols + i], rw[r - first],
				    1, r + 1 == last);
			}
			fputc('\n', fp);
		}
		first = last;
	}
}

int
rc_table_write_pretty(rc_table_out *t, rc_err *err)
{
	struct rc_table_kept *k = t->kept;
	size_t *w, total = 0;

	if (k == NULL || k->ncols == 0) {
		kept_free(k);
		t->kept = NULL;
		return 0;
	}
	if ((w = calloc(k->ncols, sizeof(*w))) == NULL) {
		kept_free(k);
		t->kept = NULL;
		return rc_seterr(err, "out of memory");
	}
	for (size_t i = 0; i < k->ncols; i++) {
		w[i] = text_width(k->name[i]);
		for (size_t r = 0; r < k->nrows; r++) {
			size_t n = text_width(k->cell[r * k->ncols + i]);
			w[i] = w[i] > n ? w[i] : n;
		}
		total += w[i] + (i ? GAP_WIDTH : 0);
	}
	if (total <= t->pretty_width)
		draw_columns(t->fp, k, w);
	else
		draw_transposed(t->fp, k, t->pretty_width);
	free(w);
	kept_free(k);
	t->kept = NULL;
	return 0;
}
