/* SPDX-License-Identifier: GPL-3.0-or-later */
/* table_read.c - read TSV and JSON result rows into one table (see
 * table_read.h). */
#include "table_read.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void
rc_rows_init(rc_rowset *rs)
{
	memset(rs, 0, sizeof(*rs));
}

static void
rec_free(rc_rowrec *r)
{
	for (size_t i = 0; i < r->ncell; i++)
		free(r->str[i]);
	free(r->str);
	free(r->num);
	free(r->isnum);
	memset(r, 0, sizeof(*r));
}

void
rc_rows_free(rc_rowset *rs)
{
	for (size_t i = 0; i < rs->nrows; i++)
		rec_free(&rs->row[i]);
	free(rs->row);
	for (size_t i = 0; i < rs->ncols; i++)
		free(rs->col[i]);
	free(rs->col);
	free(rs->colhash);
	for (size_t i = 0; i < rs->nfiles; i++)
		free(rs->file[i]);
	free(rs->file);
	memset(rs, 0, sizeof(*rs));
}

/* ---- the column index: names to column numbers in O(1), so that a table
 * of many columns costs time linear in its size ---- */

static size_t
name_hash(const char *name, size_t len)
{
	size_t h = 14695981039346656037u;	/* FNV-1a */

	for (size_t i = 0; i < len; i++)
		h = (h ^ (unsigned char)name[i]) * 1099511628211u;
	return h;
}

/* The slot of name in the index: its entry, or the empty slot where it
 * would go. */
static size_t *
hash_slot(const rc_rowset *rs, const char *name, size_t len)
{
	size_t mask = rs->hashcap - 1, k = name_hash(name, len) & mask;

	for (;; k = (k + 1) & mask) {
		size_t e = rs->colhash[k];
		if (e == 0 || (strlen(rs->col[e - 1]) == len &&
		    memcmp(rs->col[e - 1], name, len) == 0))
			return &rs->colhash[k];
	}
}

/* (Re)build the index for the columns there are, at most half full. */
static int
hash_rebuild(rc_rowset *rs, size_t want)
{
	size_t cap = 64;

	while (cap < 2 * want)
		cap *= 2;
	free(rs->colhash);
	if ((rs->colhash = calloc(cap, sizeof(*rs->colhash))) == NULL) {
		rs->hashcap = 0;
		return -1;
	}
	rs->hashcap = cap;
	for (size_t i = 0; i < rs->ncols; i++)
		*hash_slot(rs, rs->col[i], strlen(rs->col[i])) = i + 1;
	return 0;
}

int
rc_rows_column(const rc_rowset *rs, const char *name)
{
	size_t *e;

	if (rs->hashcap == 0) {	/* no index (it could not be rebuilt) */
		for (size_t i = 0; i < rs->ncols; i++)
			if (strcmp(rs->col[i], name) == 0)
				return (int)i;
		return -1;
	}
	e = hash_slot(rs, name, strlen(name));
	return *e ? (int)(*e - 1) : -1;
}

const char *
rc_rows_str(const rc_rowset *rs, size_t row, int col)
{
	if (col < 0 || row >= rs->nrows || (size_t)col >= rs->row[row].ncell)
		return NULL;
	return rs->row[row].str[col];
}

int
rc_rows_num(const rc_rowset *rs, size_t row, int col, double *v)
{
	if (rc_rows_str(rs, row, col) == NULL || !rs->row[row].isnum[col])
		return -1;
	*v = rs->row[row].num[col];
	return 0;
}

/* A number is the whole text as strtod reads it, with no leading blank. */
static int
parse_number(const char *s, double *v)
{
	char *end;

	if (*s == '\0' || isspace((unsigned char)*s))
		return 0;
	errno = 0;
	*v = strtod(s, &end);
	return *end == '\0';
}

/* Column index for name, adding it if new; -1 when out of memory or the
 * table is absurdly wide. */
static int
column_add(rc_rowset *rs, const char *name, size_t len)
{
	size_t *e;

	if ((2 * (rs->ncols + 1) > rs->hashcap &&
	    hash_rebuild(rs, rs->ncols + 1) != 0))
		return -1;
	e = hash_slot(rs, name, len);
	if (*e)
		return (int)(*e - 1);
	if (rs->ncols >= 100000)
		return -1;
	/* col holds at least the power of two above ncols: grown to twice
	 * ncols whenever ncols is a power of two (a failed parse may lower
	 * ncols; that keeps this true) */
	if ((rs->ncols & (rs->ncols - 1)) == 0 || rs->ncols == 0) {
		char **c = realloc(rs->col, (rs->ncols ? 2 * rs->ncols : 1) *
		    sizeof(*c));
		if (c == NULL)
			return -1;
		rs->col = c;
	}
	if ((rs->col[rs->ncols] = strndup(name, len)) == NULL)
		return -1;
	*e = rs->ncols + 1;
	return (int)rs->ncols++;
}

/* Grow a row's cells to ncols. */
static int
rec_grow(rc_rowrec *r, size_t ncols)
{
	if (r->ncell >= ncols)
		return 0;
	char **s = realloc(r->str, ncols * sizeof(*s));
	if (s == NULL)
		return -1;
	r->str = s;
	double *n = realloc(r->num, ncols * sizeof(*n));
	if (n == NULL)
		return -1;
	r->num = n;
	unsigned char *f = realloc(r->isnum, ncols);
	if (f == NULL)
		return -1;
	r->isnum = f;
	for (size_t i = r->ncell; i < ncols; i++) {
		s[i] = NULL;
		n[i] = NAN;
		f[i] = 0;
	}
	r->ncell = ncols;
	return 0;
}

enum { CELL_TEXT, CELL_NULL, CELL_STRING };

/* Set a cell from len bytes: TSV text or a JSON number (a number if it
 * reads as one), JSON null (NaN), or a JSON string (never a number: JSON
 * is typed, "0.2" is text). */
static int
rec_set(rc_rowrec *r, size_t col, const char *text, size_t len, int kind)
{
	int null_value = kind == CELL_NULL;

	if (rec_grow(r, col + 1) != 0)
		return -1;
	free(r->str[col]);
	if ((r->str[col] = strndup(null_value ? "nan" : text,
	    null_value ? 3 : len)) == NULL)
		return -1;
	if (null_value) {
		r->num[col] = NAN;
		r->isnum[col] = 1;
	} else if (kind == CELL_STRING)
		r->isnum[col] = 0;
	else
		r->isnum[col] = (unsigned char)parse_number(r->str[col], &r->num[col]);
	if (!r->isnum[col])
		r->num[col] = NAN;
	return 0;
}

static rc_rowrec *
row_new(rc_rowset *rs, const char *file, long line)
{
	if (rs->nrows == rs->caprows) {
		size_t cap = rs->caprows ? 2 * rs->caprows : 64;
		rc_rowrec *r = realloc(rs->row, cap * sizeof(*r));
		if (r == NULL)
			return NULL;
		rs->row = r;
		rs->caprows = cap;
	}
	rc_rowrec *r = &rs->row[rs->nrows++];
	memset(r, 0, sizeof(*r));
	r->file = file;
	r->line = line;
	return r;
}

static void
row_drop_last(rc_rowset *rs)
{
	rec_free(&rs->row[--rs->nrows]);
}

/* Lenient skip: count it, keep the first reason. */
static void
skip_note(rc_rowset *rs, const char *msg)
{
	if (rs->nskipped++ == 0)
		snprintf(rs->first_skip, sizeof(rs->first_skip), "%s", msg);
}

/* ---- TSV ---- */

static int
blank_line(const char *s, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (s[i] != ' ' && s[i] != '\t')
			return 0;
	return 1;
}

/* Long: one pass over the table's lines in order (header, rows, ragged
 * and blank lines); each check sits where its input is read. */
static int
parse_tsv(rc_rowset *rs, const char *buf, size_t len, const char *name,
    int lenient, rc_err *err)
{
	const char *hdr = NULL;
	size_t hdrlen = 0, nh = 0, pos = 0;
	int *map = NULL;
	size_t *seen = NULL;
	long line = 0;
	char msg[RC_ERRLEN];

	while (pos < len) {
		const char *s = buf + pos, *nl = memchr(s, '\n', len - pos);
		size_t n = nl ? (size_t)(nl - s) : len - pos;
		pos += n + (nl != NULL);
		line++;
		if (n > 0 && s[n - 1] == '\r')
			n--;
		if (blank_line(s, n) || s[0] == '#')
			continue;
		if (memchr(s, '\0', n) != NULL) {
			snprintf(msg, sizeof(msg), "%s:%ld: NUL byte in a text row",
			    name, line);
			if (hdr == NULL || !lenient)
				goto fail_msg;
			skip_note(rs, msg);
			continue;
		}
		if (hdr != NULL && n == hdrlen && memcmp(s, hdr, n) == 0)
			continue;	/* the same header again: files joined by cat */
		/* count fields */
		size_t nf = 1;
		for (size_t i = 0; i < n; i++)
			nf += s[i] == '\t';
		if (hdr == NULL) {
			free(map);
			free(seen);
			/* seen[c]: the header field of column c, + 1 (duplicates
			 * in linear time) */
			if ((map = calloc(nf, sizeof(*map))) == NULL ||
			    (seen = calloc(rs->ncols + nf, sizeof(*seen))) == NULL)
				goto nomem;
			size_t f = 0, a = 0;
			for (size_t i = 0; i <= n; i++) {
				if (i < n && s[i] != '\t')
					continue;
				if (i == a) {
					snprintf(msg, sizeof(msg), "%s:%ld: header field %zu: "
					    "empty column name", name, line, f + 1);
					goto fail_msg;
				}
				for (size_t k = a; k < i; k++)
					if ((unsigned char)s[k] < 0x20) {
						snprintf(msg, sizeof(msg), "%s:%ld: header field %zu: "
						    "control character in a column name",
						    name, line, f + 1);
						goto fail_msg;
					}
				int c = column_add(rs, s + a, i - a);
				if (c < 0)
					goto nomem;
				if (seen[c] != 0) {
					snprintf(msg, sizeof(msg), "%s:%ld: header fields %zu "
					    "and %zu: duplicate column name '%s'", name, line,
					    seen[c], f + 1, rs->col[c]);
					goto fail_msg;
				}
				seen[c] = f + 1;
				map[f++] = c;
				a = i + 1;
			}
			hdr = s;
			hdrlen = n;
			nh = nf;
			continue;
		}
		if (nf != nh) {
			snprintf(msg, sizeof(msg), "%s:%ld: %zu field%s, the header "
			    "(line above) has %zu", name, line, nf, nf == 1 ? "" : "s", nh);
			if (!lenient)
				goto fail_msg;
			skip_note(rs, msg);
			continue;
		}
		rc_rowrec *r = row_new(rs, name, line);
		if (r == NULL || rec_grow(r, rs->ncols) != 0)
			goto nomem;
		size_t f = 0, a = 0;
		for (size_t i = 0; i <= n; i++) {
			if (i < n && s[i] != '\t')
				continue;
			if (rec_set(r, (size_t)map[f++], s + a, i - a, CELL_TEXT) != 0)
				goto nomem;
			a = i + 1;
		}
	}
	free(map);
	free(seen);
	if (hdr == NULL)
		return rc_seterr(err, "%s: no header line (empty input)", name);
	return 0;
nomem:
	free(map);
	free(seen);
	return rc_seterr(err, "%s:%ld: out of memory", name, line);
fail_msg:
	free(map);
	free(seen);
	return rc_seterr(err, "%s", msg);
}

/* ---- JSON ---- */

typedef struct jcur {
	const char *s;
	size_t len, pos, linestart;
	long line;
	const char *name;
	char msg[RC_ERRLEN];
	char *buf;		/* decoded string */
	size_t buflen, bufcap;
} jcur;

static int
jfail(jcur *j, const char *why)
{
	snprintf(j->msg, sizeof(j->msg), "%s:%ld:%zu: %s", j->name, j->line,
	    j->pos - j->linestart + 1, why);
	return -1;
}

static void
jws(jcur *j)
{
	while (j->pos < j->len) {
		char c = j->s[j->pos];
		if (c == '\n') {
			j->line++;
			j->linestart = j->pos + 1;
		} else if (c != ' ' && c != '\t' && c != '\r')
			return;
		j->pos++;
	}
}

static int
jpeek(jcur *j)
{
	return j->pos < j->len ? (unsigned char)j->s[j->pos] : -1;
}

static int
jput(jcur *j, char c)
{
	if (j->buflen + 1 >= j->bufcap) {
		size_t cap = j->bufcap ? 2 * j->bufcap : 256;
		char *b = realloc(j->buf, cap);
		if (b == NULL)
			return jfail(j, "out of memory");
		j->buf = b;
		j->bufcap = cap;
	}
	j->buf[j->buflen++] = c;
	j->buf[j->buflen] = '\0';
	return 0;
}

static int
jhex4(jcur *j, unsigned *u)
{
	*u = 0;
	for (int k = 0; k < 4; k++) {
		int c = jpeek(j);
		if (c < 0 || !isxdigit(c))
			return jfail(j, "bad \\u escape: want four hex digits");
		*u = *u * 16 + (unsigned)(isdigit(c) ? c - '0' : tolower(c) - 'a' + 10);
		j->pos++;
	}
	return 0;
}

/* A string at '"' into j->buf (UTF-8 for \u escapes). */
static int
jstring(jcur *j)
{
	j->buflen = 0;
	if (jput(j, 0) != 0)
		return -1;
	j->buflen = 0;
	j->pos++;
	for (;;) {
		int c = jpeek(j);
		if (c < 0)
			return jfail(j, "unterminated string");
		if (c == '"') {
			j->pos++;
			return 0;
		}
		if (c < 0x20)
			return jfail(j, "control character in a string");
		if (c != '\\') {
			if (jput(j, (char)c) != 0)
				return -1;
			j->pos++;
			continue;
		}
		j->pos++;
		c = jpeek(j);
		const char *from = "\"\\/bfnrt", *to = "\"\\/\b\f\n\r\t", *p;
		if (c > 0 && (p = strchr(from, c)) != NULL) {
			j->pos++;
			if (jput(j, to[p - from]) != 0)
				return -1;
			continue;
		}
		if (c != 'u')
			return jfail(j, "bad escape in a string");
		j->pos++;
		unsigned u, lo;
		if (jhex4(j, &u) != 0)
			return -1;
		if (u >= 0xdc00 && u <= 0xdfff)
			return jfail(j, "lone low surrogate in a \\u escape");
		if (u >= 0xd800 && u <= 0xdbff) {
			if (j->pos + 2 > j->len || j->s[j->pos] != '\\' ||
			    j->s[j->pos + 1] != 'u')
				return jfail(j, "high surrogate without a low one");
			j->pos += 2;
			if (jhex4(j, &lo) != 0)
				return -1;
			if (lo < 0xdc00 || lo > 0xdfff)
				return jfail(j, "high surrogate without a low one");
			u = 0x10000 + ((u - 0xd800) << 10) + (lo - 0xdc00);
		}
		if (u == 0)
			return jfail(j, "\\u0000 in a string");
		char enc[4];
		int ne;
		if (u < 0x80) {
			enc[0] = (char)u;
			ne = 1;
		} else if (u < 0x800) {
			enc[0] = (char)(0xc0 | (u >> 6));
			enc[1] = (char)(0x80 | (u & 0x3f));
			ne = 2;
		} else if (u < 0x10000) {
			enc[0] = (char)(0xe0 | (u >> 12));
			enc[1] = (char)(0x80 | ((u >> 6) & 0x3f));
			enc[2] = (char)(0x80 | (u & 0x3f));
			ne = 3;
		} else {
			enc[0] = (char)(0xf0 | (u >> 18));
			enc[1] = (char)(0x80 | ((u >> 12) & 0x3f));
			enc[2] = (char)(0x80 | ((u >> 6) & 0x3f));
			enc[3] = (char)(0x80 | (u & 0x3f));
			ne = 4;
		}
		for (int k = 0; k < ne; k++)
			if (jput(j, enc[k]) != 0)
				return -1;
	}
}

/* A number by the JSON grammar; its text into j->buf. */
static int
jnumber(jcur *j)
{
	size_t a = j->pos;
	const char *s = j->s;

#define DIGIT(k) ((k) < j->len && s[k] >= '0' && s[k] <= '9')
	if (j->pos < j->len && s[j->pos] == '-')
		j->pos++;
	if (!DIGIT(j->pos))
		return jfail(j, "bad number");
	if (s[j->pos] == '0')
		j->pos++;
	else
		while (DIGIT(j->pos))
			j->pos++;
	if (j->pos < j->len && s[j->pos] == '.') {
		j->pos++;
		if (!DIGIT(j->pos))
			return jfail(j, "bad number: digits must follow '.'");
		while (DIGIT(j->pos))
			j->pos++;
	}
	if (j->pos < j->len && (s[j->pos] == 'e' || s[j->pos] == 'E')) {
		j->pos++;
		if (j->pos < j->len && (s[j->pos] == '+' || s[j->pos] == '-'))
			j->pos++;
		if (!DIGIT(j->pos))
			return jfail(j, "bad number: digits must follow the exponent");
		while (DIGIT(j->pos))
			j->pos++;
	}
#undef DIGIT
	j->buflen = 0;
	for (size_t k = a; k < j->pos; k++)
		if (jput(j, s[k]) != 0)
			return -1;
	return 0;
}

static int
jword(jcur *j, const char *w)
{
	size_t n = strlen(w);
	if (j->len - j->pos < n || memcmp(j->s + j->pos, w, n) != 0)
		return jfail(j, "unexpected character");
	j->pos += n;
	return 0;
}

/* Skip a nested array or object (lenient mode), strings included. */
static int
jskip_nested(jcur *j)
{
	size_t depth = 0;

	do {
		int c = jpeek(j);
		if (c < 0)
			return jfail(j, "unterminated nested value");
		if (c == '"') {
			if (jstring(j) != 0)
				return -1;
			continue;
		}
		if (c == '{' || c == '[')
			depth++;
		else if (c == '}' || c == ']')
			depth--;
		else if (c == '\n') {
			j->line++;
			j->linestart = j->pos + 1;
		}
		j->pos++;
	} while (depth > 0);
	return 0;
}

/* One object at '{' into a new row.  *bad set (and the row dropped) when
 * lenient and the object is well-formed JSON but not a flat row. */
/* Long: one pass over a JSON object's members in order; each check sits
 * where its input is read. */
static int
jobject(jcur *j, rc_rowset *rs, int lenient)
{
	rc_rowrec *r = row_new(rs, j->name, j->line);
	char why[RC_ERRLEN] = "";

	if (r == NULL)
		return jfail(j, "out of memory");
	j->pos++;
	jws(j);
	if (jpeek(j) == '}') {
		j->pos++;
		goto done;
	}
	for (;;) {
		jws(j);
		if (jpeek(j) != '"')
			return jfail(j, "expected a key string");
		if (jstring(j) != 0)
			return -1;
		if (j->buflen == 0)
			return jfail(j, "empty key");
		for (size_t k = 0; k < j->buflen; k++)
			if ((unsigned char)j->buf[k] < 0x20)
				return jfail(j, "control character in a key");
		int c = column_add(rs, j->buf, j->buflen);
		if (c < 0)
			return jfail(j, "out of memory");
		int dup = (size_t)c < r->ncell && r->str[c] != NULL;
		if (dup && why[0] == '\0')
			snprintf(why, sizeof(why), "%s:%ld:%zu: duplicate key '%s'",
			    j->name, j->line, j->pos - j->linestart, rs->col[c]);
		jws(j);
		if (jpeek(j) != ':')
			return jfail(j, "expected ':' after a key");
		j->pos++;
		jws(j);
		int v = jpeek(j), kind = CELL_TEXT, ok = 1;
		if (v == '"') {
			kind = CELL_STRING;
			if (jstring(j) != 0)
				return -1;
		} else if (v == '-' || (v >= '0' && v <= '9')) {
			if (jnumber(j) != 0)
				return -1;
		} else if (v == 't' || v == 'f') {
			if (jword(j, v == 't' ? "true" : "false") != 0)
				return -1;
			j->buflen = 0;
			if (jput(j, 0) != 0)
				return -1;
			strcpy(j->buf, v == 't' ? "true" : "false");
			j->buflen = strlen(j->buf);
		} else if (v == 'n') {
			if (jword(j, "null") != 0)
				return -1;
			kind = CELL_NULL;
		} else if (v == '{' || v == '[') {
			if (!lenient)
				return jfail(j, "nested value: rows must be flat objects");
			if (why[0] == '\0')
				snprintf(why, sizeof(why), "%s:%ld:%zu: nested value for "
				    "key '%s'", j->name, j->line, j->pos - j->linestart + 1,
				    rs->col[c]);
			if (jskip_nested(j) != 0)
				return -1;
			ok = 0;
		} else
			return jfail(j, v < 0 ? "unexpected end of input" :
			    "unexpected character");
		if (dup && !lenient) {
			snprintf(j->msg, sizeof(j->msg), "%s", why);
			return -1;
		}
		if (ok && !dup && rec_set(r, (size_t)c, j->buf, j->buflen, kind) != 0)
			return jfail(j, "out of memory");
		jws(j);
		v = jpeek(j);
		j->pos++;
		if (v == '}')
			break;
		if (v != ',') {
			j->pos--;
			return jfail(j, "expected ',' or '}' in an object");
		}
	}
done:
	if (why[0] != '\0') {
		row_drop_last(rs);
		skip_note(rs, why);
		return 0;
	}
	if (rec_grow(&rs->row[rs->nrows - 1], rs->ncols) != 0)
		return jfail(j, "out of memory");
	return 0;
}

static int
parse_json(rc_rowset *rs, const char *buf, size_t len, const char *name,
    int lenient, rc_err *err)
{
	jcur j;

	memset(&j, 0, sizeof(j));
	j.s = buf;
	j.len = len;
	j.line = 1;
	j.name = name;
	if (memchr(buf, '\0', len) != NULL) {
		const char *z = memchr(buf, '\0', len);
		for (const char *p = buf; p < z; p++)
			if (*p == '\n') {
				j.line++;
				j.linestart = (size_t)(p - buf) + 1;
			}
		j.pos = (size_t)(z - buf);
		jfail(&j, "NUL byte in JSON text");
		goto fail;
	}
	jws(&j);
	/* One array, or several one after another (outputs joined with cat,
	 * like TSV sections). */
next_array:
	j.pos++;		/* the '[' the caller or the loop saw */
	jws(&j);
	if (jpeek(&j) == ']')
		j.pos++;
	else
		for (;;) {
			jws(&j);
			if (jpeek(&j) != '{') {
				jfail(&j, jpeek(&j) < 0 ? "unexpected end of input" :
				    "expected '{': rows are objects");
				goto fail;
			}
			if (jobject(&j, rs, lenient) != 0)
				goto fail;
			jws(&j);
			int c = jpeek(&j);
			j.pos++;
			if (c == ']')
				break;
			if (c != ',') {
				j.pos--;
				jfail(&j, c < 0 ? "unexpected end of input" :
				    "expected ',' or ']' after an object");
				goto fail;
			}
		}
	jws(&j);
	if (jpeek(&j) == '[')
		goto next_array;
	if (j.pos < j.len) {
		jfail(&j, "trailing data after the array");
		goto fail;
	}
	free(j.buf);
	return 0;
fail:
	free(j.buf);
	return rc_seterr(err, "%s", j.msg);
}

int
rc_rows_parse(rc_rowset *rs, const char *buf, size_t len, const char *name,
    int lenient, rc_err *err)
{
	size_t nrows0 = rs->nrows, ncols0 = rs->ncols, i = 0;
	char **f;
	int rc;

	if ((f = realloc(rs->file, (rs->nfiles + 1) * sizeof(*f))) == NULL)
		return rc_seterr(err, "%s: out of memory", name);
	rs->file = f;
	if ((f[rs->nfiles] = strdup(name)) == NULL)
		return rc_seterr(err, "%s: out of memory", name);
	name = f[rs->nfiles++];
	/* A UTF-8 byte-order mark, then blanks, decide the format. */
	if (len >= 3 && memcmp(buf, "\xef\xbb\xbf", 3) == 0) {
		buf += 3;
		len -= 3;
	}
	while (i < len && isspace((unsigned char)buf[i]))
		i++;
	if (i < len && buf[i] == '[')
		rc = parse_json(rs, buf, len, name, lenient, err);
	else
		rc = parse_tsv(rs, buf, len, name, lenient, err);
	if (rc == 0)
		return 0;
	while (rs->nrows > nrows0)
		row_drop_last(rs);
	while (rs->ncols > ncols0)
		free(rs->col[--rs->ncols]);
	if (rs->hashcap > 0 && hash_rebuild(rs, rs->ncols) != 0)
		rs->hashcap = 0;	/* lookups fall back to a scan */
	return -1;
}

int
rc_rows_read(rc_rowset *rs, FILE *fp, const char *name, int lenient,
    rc_err *err)
{
	size_t len = 0, cap = 65536, n;
	char *buf = malloc(cap);
	int rc;

	if (buf == NULL)
		return rc_seterr(err, "%s: out of memory", name);
	while ((n = fread(buf + len, 1, cap - len, fp)) > 0) {
		len += n;
		if (len == cap) {
			char *b = cap > ((size_t)-1) / 2 ? NULL : realloc(buf, 2 * cap);
			if (b == NULL) {
				free(buf);
				return rc_seterr(err, "%s: out of memory reading %zu bytes",
				    name, 2 * cap);
			}
			buf = b;
			cap *= 2;
		}
	}
	if (ferror(fp)) {
		free(buf);
		return rc_seterr(err, "%s: read error: %s", name, strerror(errno));
	}
	rc = rc_rows_parse(rs, buf, len, name, lenient, err);
	free(buf);
	return rc;
}
