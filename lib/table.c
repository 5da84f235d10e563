/* table.c - TSV/JSON result rows. */
#include "table.h"

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

static int
is_number(const char *s)
{
	char *end;

	if (*s == '\0')
		return 0;
	(void)strtod(s, &end);
	return *end == '\0';
}

int
rc_row_meta(rc_row *r, const rc_grid *g)
{
	for (size_t i = 0; i < g->nmeta; i++) {
		if (row_has(r, g->meta[i].key))
			continue;
		if (row_add(r, g->meta[i].key, g->meta[i].val,
		    !is_number(g->meta[i].val)) != 0)
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

static void
json_string(FILE *fp, const char *s)
{
	fputc('"', fp);
	for (; *s; s++) {
		unsigned char c = (unsigned char)*s;
		if (c == '"' || c == '\\')
			fprintf(fp, "\\%c", c);
		else if (c == '\t')
			fputs("\\t", fp);
		else if (c < 0x20)
			fprintf(fp, "\\u%04x", c);
		else
			fputc(c, fp);
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
			if (r->is_str[i])
				json_string(t->fp, r->val[i]);
			else if (strcmp(r->val[i], "nan") == 0 ||
			    strcmp(r->val[i], "inf") == 0 ||
			    strcmp(r->val[i], "-inf") == 0)
				fputs("null", t->fp);
			else
				fputs(r->val[i], t->fp);
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
