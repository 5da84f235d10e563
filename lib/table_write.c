/* SPDX-License-Identifier: GPL-3.0-or-later */
/* table_write.c - write result rows as TSV/JSON tables. */
#include "table_write.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void
rc_row_init(rc_row *r)
{
	memset(r, 0, sizeof(*r));
}

void
rc_row_clear(rc_row *r)
{
	for (size_t i = 0; i < r->n; i++) {
		free(r->name[i]);
		free(r->val[i]);
	}
	r->n = 0;
}

void
rc_row_free(rc_row *r)
{
	rc_row_clear(r);
	free(r->name);
	free(r->val);
	free(r->is_str);
	memset(r, 0, sizeof(*r));
}

static int
row_add(rc_row *r, const char *name, const char *val, int is_str)
{
	if (r->n == r->cap) {
		size_t cap = r->cap ? 2 * r->cap : 32;
		char **nm = realloc(r->name, cap * sizeof(*nm));
		if (nm == NULL)
			return -1;
		r->name = nm;
		char **vl = realloc(r->val, cap * sizeof(*vl));
		if (vl == NULL)
			return -1;
		r->val = vl;
		unsigned char *s = realloc(r->is_str, cap);
		if (s == NULL)
			return -1;
		r->is_str = s;
		r->cap = cap;
	}
	r->name[r->n] = strdup(name);
	r->val[r->n] = strdup(val);
	if (r->name[r->n] == NULL || r->val[r->n] == NULL) {
		free(r->name[r->n]);
		free(r->val[r->n]);
		return -1;
	}
	r->is_str[r->n++] = (unsigned char)is_str;
	return 0;
}

int
rc_row_num(rc_row *r, const char *name, double v)
{
	char buf[64];

	if (isnan(v))
		strcpy(buf, "nan");
	else if (isinf(v))
		strcpy(buf, v > 0 ? "inf" : "-inf");
	else
		rc_format_double(buf, sizeof(buf), v);
	return row_add(r, name, buf, 0);
}

int
rc_row_int(rc_row *r, const char *name, long long v)
{
	char buf[32];

	snprintf(buf, sizeof(buf), "%lld", v);
	return row_add(r, name, buf, 0);
}

int
rc_row_str(rc_row *r, const char *name, const char *v)
{
	return row_add(r, name, v, 1);
}

static int
row_has(const rc_row *r, const char *name)
{
	for (size_t i = 0; i < r->n; i++)
		if (strcmp(r->name[i], name) == 0)
			return 1;
	return 0;
}

/* A finite number by JSON's grammar:
 * -?(0|[1-9][0-9]*)(.[0-9]+)?([eE][+-]?[0-9]+)? (strtod also takes
 * "Infinity", "+5", "0x10", " 5", which JSON does not). */
static int
is_json_number(const char *text)
{
	const char *s = text;

#define DIGITS(p) do { if (!isdigit((unsigned char)*(p))) return 0; \
	while (isdigit((unsigned char)*(p))) (p)++; } while (0)
	if (*s == '-')
		s++;
	if (*s == '0')
		s++;
	else
		DIGITS(s);
	if (*s == '.') {
		s++;
		DIGITS(s);
	}
	if (*s == 'e' || *s == 'E') {
		s++;
		if (*s == '+' || *s == '-')
			s++;
		DIGITS(s);
	}
#undef DIGITS
	/* 1e999 is grammatical but no double: a string, like Infinity */
	return *s == '\0' && isfinite(strtod(text, NULL));
}

int
rc_row_meta(rc_row *r, const rc_grid *g)
{
	for (size_t i = 0; i < g->nmeta; i++) {
		if (row_has(r, g->meta[i].key))
			continue;
		if (row_add(r, g->meta[i].key, g->meta[i].val,
		    !is_json_number(g->meta[i].val)) != 0)
			return -1;
	}
	return 0;
}

void
rc_table_begin(rc_table_out *t, FILE *fp, int json)
{
	memset(t, 0, sizeof(*t));
	t->fp = fp;
	t->json = json;
}

/* Length of the well-formed UTF-8 sequence at s (RFC 3629: no overlong
 * forms, no surrogates, at most U+10FFFF), 0 if there is none. */
static size_t
utf8_len(const unsigned char *s)
{
	unsigned char c = s[0];
	size_t n;
	unsigned lo = 0x80, hi = 0xbf;

	if (c < 0x80)
		return 1;
	if (c >= 0xc2 && c <= 0xdf)
		n = 2;
	else if (c >= 0xe0 && c <= 0xef) {
		n = 3;
		lo = c == 0xe0 ? 0xa0 : 0x80;
		hi = c == 0xed ? 0x9f : 0xbf;
	} else if (c >= 0xf0 && c <= 0xf4) {
		n = 4;
		lo = c == 0xf0 ? 0x90 : 0x80;
		hi = c == 0xf4 ? 0x8f : 0xbf;
	} else
		return 0;
	if (s[1] < lo || s[1] > hi)
		return 0;
	for (size_t k = 2; k < n; k++)
		if (s[k] < 0x80 || s[k] > 0xbf)
			return 0;
	return n;
}

/* A JSON string: quotes, backslashes and control characters escaped, a
 * byte that is not UTF-8 written as U+FFFD (JSON text is Unicode). */
static void
json_string(FILE *fp, const char *str)
{
	const unsigned char *s = (const unsigned char *)str;

	fputc('"', fp);
	while (*s) {
		size_t n = utf8_len(s);
		if (*s == '"' || *s == '\\')
			fprintf(fp, "\\%c", *s);
		else if (*s == '\t')
			fputs("\\t", fp);
		else if (*s == '\n')
			fputs("\\n", fp);
		else if (*s < 0x20 || *s == 0x7f)
			fprintf(fp, "\\u%04x", *s);
		else if (n == 0)
			fputs("\\ufffd", fp);
		else
			fwrite(s, 1, n, fp);
		s += n ? n : 1;
	}
	fputc('"', fp);
}

/* TSV cells may not hold tabs or newlines. */
static void
tsv_cell(FILE *fp, const char *s)
{
	for (; *s; s++)
		fputc((*s == '\t' || *s == '\n' || *s == '\r') ? ' ' : *s, fp);
}

int
rc_table_write(rc_table_out *t, const rc_row *r, rc_err *err)
{
	if (t->kept != NULL)
		return rc_table_keep_pretty(t, r, err);
	if (t->nrows == 0) {
		t->header = calloc(r->n ? r->n : 1, sizeof(*t->header));
		if (t->header == NULL)
			return rc_seterr(err, "out of memory");
		for (size_t i = 0; i < r->n; i++)
			if ((t->header[i] = strdup(r->name[i])) == NULL)
				return rc_seterr(err, "out of memory");
		t->ncols = r->n;
		if (!t->json) {
			for (size_t i = 0; i < r->n; i++) {
				if (i)
					fputc('\t', t->fp);
				tsv_cell(t->fp, r->name[i]);
			}
			fputc('\n', t->fp);
		} else
			fputs("[\n", t->fp);
	} else {
		if (r->n != t->ncols)
			return rc_seterr(err, "internal: row has %zu columns, header %zu",
			    r->n, t->ncols);
		for (size_t i = 0; i < r->n; i++)
			if (strcmp(r->name[i], t->header[i]) != 0)
				return rc_seterr(err, "internal: column %zu is '%s', header says '%s'",
				    i, r->name[i], t->header[i]);
	}
	if (t->json) {
		fputs(t->nrows ? ",\n  {" : "  {", t->fp);
		for (size_t i = 0; i < r->n; i++) {
			if (i)
				fputs(", ", t->fp);
			json_string(t->fp, r->name[i]);
			fputs(": ", t->fp);
			/* JSON has no NaN or infinity: null; any other text a
			 * JSON number does not spell is a string. */
			if (!r->is_str[i] && (strcmp(r->val[i], "nan") == 0 ||
			    strcmp(r->val[i], "inf") == 0 ||
			    strcmp(r->val[i], "-inf") == 0))
				fputs("null", t->fp);
			else if (!r->is_str[i] && is_json_number(r->val[i]))
				fputs(r->val[i], t->fp);
			else
				json_string(t->fp, r->val[i]);
		}
		fputc('}', t->fp);
	} else {
		for (size_t i = 0; i < r->n; i++) {
			if (i)
				fputc('\t', t->fp);
			tsv_cell(t->fp, r->val[i]);
		}
		fputc('\n', t->fp);
	}
	t->nrows++;
	return 0;
}

int
rc_table_end(rc_table_out *t, rc_err *err)
{
	if (t->kept != NULL)
		return rc_table_write_pretty(t, err);
	if (t->json)
		fputs(t->nrows ? "\n]\n" : "[]\n", t->fp);
	for (size_t i = 0; i < t->ncols; i++)
		free(t->header[i]);
	free(t->header);
	t->header = NULL;
	t->ncols = 0;
	return 0;
}
