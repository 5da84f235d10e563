/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_xlsx.c - Excel workbooks (.xlsx, Office Open XML SpreadsheetML).
 *
 * A workbook is a zip of XML parts: xl/workbook.xml lists the sheets
 * (name and relationship id), xl/_rels/workbook.xml.rels maps an id to
 * the sheet's part (xl/worksheets/sheetN.xml), xl/sharedStrings.xml holds
 * the strings that cells of type "s" index (from 0).  A sheet's
 * sheetData holds rows of cells <c r="E12" t="..."><v>...</v></c>: no t
 * or t="n" a number, "s" a shared string, "str" a formula's string,
 * "inlineStr" the text of <is>.  Cells without a value are empty.
 *
 * Mitutoyo SurfTest exports (sheets "DATA" and "Certificate"): the
 * profile is columns E (x) and F (height) of DATA, the x unit that of
 * the cut-off in Certificate!E48 ("0.08mm"), the heights' that of the
 * first roughness parameter in DATA!A1 ("Ra   0.018  um"), as
 * SurfaceTopography's MitutoyoReader reads them.  Any other workbook:
 * its first sheet, row by row, read as a text table (io_txt.c: a line of
 * column names with units, x-z or x-y-z columns, or a matrix).  Both go
 * through the text reader as CSV, so the checks and rules of columns
 * (uniform spacing, --uniform) are those of text files.
 *
 * Memory: every part is read with io_zip.c's bound (XLSX_PART_MAX) and
 * streamed (never a tree of the whole sheet), and the CSV a sheet makes
 * is at most twice that bound and the shared strings (a sparse sheet, a
 * cell at XFD1048576, would otherwise make gigabytes of empty fields).
 */
#include "io_internal.h"
#include "units.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <libxml/xmlreader.h>
#include <zip.h>
#include "io_dl_internal.h"

#define XLSX_PART_MAX ((uint64_t)64 << 20)
#define REL_NS "http://schemas.openxmlformats.org/officeDocument/2006/" \
    "relationships"
#define MAX_COL 16384u		/* XFD, Excel's last column */

struct book {
	zip_t *za;
	char **shared;		/* the shared strings */
	size_t nshared, cap;
};

/* A growing string. */
struct sbuf {
	char *p;
	size_t n, cap, limit;
};

static int
sb_add(struct sbuf *b, const char *s, size_t n, rc_err *err)
{
	if (b->n + n + 1 > b->limit)
		return rc_seterr(err, "xlsx: the sheet's table is over %zu bytes "
		    "as text (cells far apart in a sparse sheet)", b->limit);
	if (b->n + n + 1 > b->cap) {
		size_t cap = b->cap ? b->cap : 4096;
		char *p;

		while (cap < b->n + n + 1)
			cap *= 2;
		if ((p = realloc(b->p, cap)) == NULL)
			return rc_seterr(err, "out of memory");
		b->p = p;
		b->cap = cap;
	}
	memcpy(b->p + b->n, s, n);
	b->n += n;
	b->p[b->n] = '\0';
	return 0;
}

static int
is_el(const xmlNode *n, const char *name)
{
	return n != NULL && n->type == XML_ELEMENT_NODE &&
	    strcmp((const char *)n->name, name) == 0;
}

static xmlNode *
first(const xmlNode *n, const char *name)
{
	for (xmlNode *c = n ? n->children : NULL; c != NULL; c = c->next)
		if (is_el(c, name))
			return c;
	return NULL;
}

/* Part name of the workbook parsed (the small ones: the workbook and
 * its relationships), or NULL (err set). */
static xmlDoc *
part(struct book *b, const char *name, rc_err *err)
{
	unsigned char *buf;
	size_t len;
	xmlDoc *doc;
	char q[64];

	if (rc__zip_entry(b->za, "xlsx", name, 0, XLSX_PART_MAX, &buf, &len,
	    err) != 0)
		return NULL;
	doc = len > INT32_MAX ? NULL : xmlReadMemory((const char *)buf,
	    (int)len, name, NULL, XML_PARSE_NONET | XML_PARSE_NOERROR |
	    XML_PARSE_NOWARNING);
	free(buf);
	if (doc == NULL || xmlDocGetRootElement(doc) == NULL) {
		xmlFreeDoc(doc);
		rc_seterr(err, "xlsx: %s is not well-formed XML",
		    rc__io_quote(q, sizeof(q), name, strlen(name)));
		return NULL;
	}
	return doc;
}

/* Calls fn with each element called name of part part_name, its subtree
 * expanded (valid during the call only): libxml2's streaming reader, so
 * that a sheet of millions of cells never stands in memory as a tree
 * (some 30 bytes of tree a byte of XML, measured). */
typedef int (*elem_fn)(void *ctx, xmlNode *n, rc_err *err);
static int
stream_part(struct book *b, const char *part_name, const char *name,
    elem_fn fn, void *ctx, rc_err *err)
{
	unsigned char *buf;
	size_t len;
	xmlTextReaderPtr rd;
	char q[64];
	int ret, r = 0;

	if (rc__zip_entry(b->za, "xlsx", part_name, 0, XLSX_PART_MAX, &buf, &len,
	    err) != 0)
		return -1;
	rd = len > INT32_MAX ? NULL : xmlReaderForMemory((const char *)buf,
	    (int)len, part_name, NULL, XML_PARSE_NONET | XML_PARSE_NOERROR |
	    XML_PARSE_NOWARNING);
	ret = rd ? xmlTextReaderRead(rd) : -1;
	while (ret == 1 && r == 0) {
		const xmlChar *ln = xmlTextReaderConstLocalName(rd);
		xmlNode *n;

		if (xmlTextReaderNodeType(rd) != XML_READER_TYPE_ELEMENT ||
		    ln == NULL || strcmp((const char *)ln, name) != 0) {
			ret = xmlTextReaderRead(rd);
			continue;
		}
		if ((n = xmlTextReaderExpand(rd)) == NULL) {
			ret = -1;
			break;
		}
		r = fn(ctx, n, err);
		ret = xmlTextReaderNext(rd);
	}
	if (r == 0 && ret != 0)
		r = rc_seterr(err, "xlsx: %s is not well-formed XML",
		    rc__io_quote(q, sizeof(q), part_name, strlen(part_name)));
	xmlFreeTextReader(rd);
	free(buf);
	return r;
}

/* The text of every <t> under n but those of phonetic runs (rPh). */
static int
text_of(const xmlNode *n, struct sbuf *out, rc_err *err)
{
	for (const xmlNode *c = n->children; c != NULL; c = c->next) {
		if (is_el(c, "t")) {
			xmlChar *t = xmlNodeGetContent(c);
			int r = t ? sb_add(out, (const char *)t,
			    strlen((const char *)t), err) : 0;

			xmlFree(t);
			if (r != 0)
				return -1;
		} else if (is_el(c, "r") && text_of(c, out, err) != 0)
			return -1;
	}
	return 0;
}

static int
shared_si(void *ctx, xmlNode *si, rc_err *err)
{
	struct book *b = ctx;
	struct sbuf t = { .limit = XLSX_PART_MAX };

	if (b->nshared == b->cap) {
		size_t cap = b->cap ? 2 * b->cap : 64;
		char **p = realloc(b->shared, cap * sizeof(*p));

		if (p == NULL)
			return rc_seterr(err, "out of memory");
		b->shared = p;
		b->cap = cap;
	}
	if (text_of(si, &t, err) != 0 || sb_add(&t, "", 0, err) != 0) {
		free(t.p);
		return -1;
	}
	b->shared[b->nshared++] = t.p;
	return 0;
}

static int
read_shared(struct book *b, rc_err *err)
{
	if (zip_name_locate(b->za, "xl/sharedStrings.xml", 0) < 0)
		return 0;
	return stream_part(b, "xl/sharedStrings.xml", "si", shared_si, b, err);
}

/* "E12" into column 5 and row 12 (1-based); -1 if it is no reference. */
static int
cell_ref(const char *r, unsigned *col, unsigned long *row)
{
	unsigned c = 0;
	char *end;

	for (; isupper((unsigned char)*r); r++)
		if ((c = c * 26 + (unsigned)(*r - 'A' + 1)) > MAX_COL)
			return -1;
	if (c == 0 || !isdigit((unsigned char)*r))
		return -1;
	*row = strtoul(r, &end, 10);
	*col = c;
	return *end == '\0' && *row >= 1 && *row <= 1048576 ? 0 : -1;
}

/* A cell's value as text (malloc'ed; "" when empty). */
static char *
cell_value(const struct book *b, const xmlNode *c, rc_err *err)
{
	xmlChar *t = xmlGetProp(c, (const xmlChar *)"t");
	struct sbuf s = { .limit = XLSX_PART_MAX };
	const xmlNode *v = first(c, "v");
	xmlChar *vt = NULL;
	int r = 0;

	if (t != NULL && strcmp((const char *)t, "inlineStr") == 0) {
		const xmlNode *is = first(c, "is");

		r = is ? text_of(is, &s, err) : 0;
	} else if (v != NULL) {
		vt = xmlNodeGetContent(v);
		if (t != NULL && strcmp((const char *)t, "s") == 0) {
			char *end;
			unsigned long k = strtoul(vt ? (const char *)vt : "", &end, 10);

			if (vt == NULL || end == (char *)vt || *end != '\0' ||
			    k >= b->nshared)
				r = rc_seterr(err, "xlsx: a cell names shared string "
				    "%.20s of %zu", vt ? (const char *)vt : "?", b->nshared);
			else
				r = sb_add(&s, b->shared[k], strlen(b->shared[k]), err);
		} else if (vt != NULL)
			r = sb_add(&s, (const char *)vt, strlen((const char *)vt),
			    err);
	}
	xmlFree(t);
	xmlFree(vt);
	if (r == 0 && s.p == NULL)
		r = sb_add(&s, "", 0, err);
	if (r != 0) {
		free(s.p);
		return NULL;
	}
	return s.p;
}

/* The part of the sheet called name (NULL: the first), or NULL with
 * err naming the sheets there are. */
static int
sheet_part(struct book *b, const char *name, char *path, size_t plen,
    char *title, size_t tlen, rc_err *err)
{
	xmlDoc *wb = NULL, *rels = NULL;
	xmlNode *sheets;
	xmlChar *id = NULL;
	int r = -1;

	if ((wb = part(b, "xl/workbook.xml", err)) == NULL)
		return -1;
	sheets = first(xmlDocGetRootElement(wb), "sheets");
	for (xmlNode *c = sheets ? sheets->children : NULL; c; c = c->next) {
		xmlChar *n;

		if (!is_el(c, "sheet"))
			continue;
		n = xmlGetProp(c, (const xmlChar *)"name");
		if (name == NULL || (n && strcmp((const char *)n, name) == 0)) {
			id = xmlGetNsProp(c, (const xmlChar *)"id",
			    (const xmlChar *)REL_NS);
			snprintf(title, tlen, "%s", n ? (const char *)n : "");
			xmlFree(n);
			break;
		}
		xmlFree(n);
	}
	if (id == NULL) {
		rc_seterr(err, "xlsx: no sheet %s%s%s", name ? "'" : "",
		    name ? name : "at all", name ? "'" : "");
		goto out;
	}
	if ((rels = part(b, "xl/_rels/workbook.xml.rels", err)) == NULL)
		goto out;
	for (xmlNode *c = xmlDocGetRootElement(rels)->children; c; c = c->next) {
		xmlChar *i = xmlGetProp(c, (const xmlChar *)"Id");
		xmlChar *t = xmlGetProp(c, (const xmlChar *)"Target");

		if (is_el(c, "Relationship") && i && t &&
		    strcmp((const char *)i, (const char *)id) == 0) {
			/* relative to xl/, or absolute in the package */
			if (t[0] == '/')
				snprintf(path, plen, "%s", (const char *)t + 1);
			else
				snprintf(path, plen, "xl/%s", (const char *)t);
			r = 0;
		}
		xmlFree(i);
		xmlFree(t);
		if (r == 0)
			break;
	}
	if (r != 0)
		rc_seterr(err, "xlsx: the workbook's relationships lack sheet "
		    "'%s'", title);
out:
	xmlFree(id);
	xmlFreeDoc(wb);
	xmlFreeDoc(rels);
	return r;
}

/* Column and row of cell c from its reference; -1 without one. */
static int
cell_at(const xmlNode *c, unsigned *col, unsigned long *row)
{
	xmlChar *ref = xmlGetProp(c, (const xmlChar *)"r");
	int r = ref ? cell_ref((const char *)ref, col, row) : -1;

	xmlFree(ref);
	return r;
}

/* Looking for one cell (find_cell). */
struct find {
	const struct book *b;
	unsigned col;
	unsigned long row;
	char *value;		/* malloc'ed when found */
};

static int
find_row(void *ctx, xmlNode *rw, rc_err *err)
{
	struct find *f = ctx;
	unsigned col;
	unsigned long row;

	for (xmlNode *c = rw->children; c && f->value == NULL; c = c->next)
		if (is_el(c, "c") && cell_at(c, &col, &row) == 0 &&
		    col == f->col && row == f->row &&
		    (f->value = cell_value(f->b, c, err)) == NULL)
			return -1;
	return 0;
}

/* The value of cell (col, row) of the sheet at path into *value
 * (malloc'ed; NULL if the cell is absent). */
static int
find_cell(struct book *b, const char *path, unsigned col, unsigned long row,
    char **value, rc_err *err)
{
	struct find f = { b, col, row, NULL };

	if (stream_part(b, path, "row", find_row, &f, err) != 0) {
		free(f.value);
		return -1;
	}
	*value = f.value;
	return 0;
}

/* The length unit at the end of s ("0.08mm", "Ra  0.018  um"), after
 * skip words; 0 if there is none. */
static int
trailing_unit(const char *s, int skip, char out[32])
{
	char buf[128], *p, *save = NULL, *tok;
	int k = 0;

	snprintf(buf, sizeof(buf), "%s", s);
	for (tok = strtok_r(buf, " \t", &save); tok; tok = strtok_r(NULL, " \t",
	    &save), k++) {
		if (k < skip)
			continue;
		p = tok + strspn(tok, "+-.0123456789eE");
		if (k == skip && p != tok && *p == '\0')
			continue;	/* the number; the unit follows */
		if (rc_unit_is_length(rc_unit_canonical(p)) &&
		    strlen(rc_unit_canonical(p)) < 32) {
			strcpy(out, rc_unit_canonical(p));
			return 1;
		}
		return 0;
	}
	return 0;
}

/* A sheet made into CSV, row by row. */
struct table {
	const struct book *b;
	struct sbuf *csv;
};

/* Mitutoyo's row: DATA!E (x) and DATA!F (height), when either is there. */
static int
mitutoyo_row(void *ctx, xmlNode *rw, rc_err *err)
{
	struct table *t = ctx;
	char *v[2] = { NULL, NULL }, line[160], q[64];
	unsigned long row = 0;
	unsigned col;
	int r = -1;

	for (xmlNode *c = rw->children; c; c = c->next) {
		if (!is_el(c, "c") || cell_at(c, &col, &row) != 0 ||
		    (col != 5 && col != 6))
			continue;
		free(v[col - 5]);
		if ((v[col - 5] = cell_value(t->b, c, err)) == NULL)
			goto out;
		if (v[col - 5][0] == '\0') {
			free(v[col - 5]);
			v[col - 5] = NULL;
		}
	}
	if (v[0] == NULL && v[1] == NULL)
		return 0;
	for (int k = 0; k < 2; k++) {
		double d;

		if (v[k] == NULL || rc__parse_double(v[k], &d) != 0) {
			rc_seterr(err, "Mitutoyo workbook: DATA!%c%lu %s%s%s: want a "
			    "number beside the %s", k ? 'F' : 'E', row, v[k] ? "'" :
			    "is empty", v[k] ? rc__io_quote(q, sizeof(q), v[k],
			    strlen(v[k])) : "", v[k] ? "'" : "", k ? "position" :
			    "height");
			goto out;
		}
	}
	snprintf(line, sizeof(line), "%.64s,%.64s\n", v[0], v[1]);
	r = sb_add(t->csv, line, strlen(line), err);
out:
	free(v[0]);
	free(v[1]);
	return r;
}

/* Mitutoyo's profile (the header comment says where its units are). */
static int
mitutoyo_csv(struct book *b, const char *data, const char *cert,
    struct sbuf *csv, rc_err *err)
{
	struct table t = { b, csv };
	char xu[32], zu[32], line[160], q[64];
	char *cut = NULL, *ra = NULL;
	int r = -1;

	if (find_cell(b, cert, 5, 48, &cut, err) != 0 ||
	    find_cell(b, data, 1, 1, &ra, err) != 0)
		goto out;
	if (cut == NULL || !trailing_unit(cut, 0, xu)) {
		rc_seterr(err, "Mitutoyo workbook: Certificate!E48 '%s' is not "
		    "the cut-off with its length unit (as '0.08mm'), which gives "
		    "the unit of x", cut ? rc__io_quote(q, sizeof(q), cut,
		    strlen(cut)) : "");
		goto out;
	}
	if (ra == NULL || !trailing_unit(ra, 1, zu)) {
		rc_seterr(err, "Mitutoyo workbook: DATA!A1 '%s' is not a "
		    "roughness parameter with its length unit (as 'Ra 0.018 "
		    "\xc2\xb5m'), which gives the unit of the heights",
		    ra ? rc__io_quote(q, sizeof(q), ra, strlen(ra)) : "");
		goto out;
	}
	snprintf(line, sizeof(line), "x in %s,z in %s\n", xu, zu);
	if (sb_add(csv, line, strlen(line), err) != 0)
		goto out;
	r = stream_part(b, data, "row", mitutoyo_row, &t, err);
out:
	free(cut);
	free(ra);
	return r;
}

/* Any sheet's row as CSV: its cells from column A to its last, an empty
 * field where a cell has no value; commas in text become blanks. */
static int
table_row(void *ctx, xmlNode *rw, rc_err *err)
{
	struct table *t = ctx;
	unsigned at = 1;	/* the next column to write */

	for (xmlNode *c = rw->children; c; c = c->next) {
		unsigned col = at;
		unsigned long row;
		char *v;

		if (!is_el(c, "c"))
			continue;
		if (cell_at(c, &col, &row) != 0 || col < at)
			col = at;
		for (; at < col; at++)
			if (sb_add(t->csv, ",", at > 1, err) != 0)
				return -1;
		if ((v = cell_value(t->b, c, err)) == NULL)
			return -1;
		for (char *p = v; *p; p++)
			if (*p == ',' || *p == '\n' || *p == '\r')
				*p = ' ';
		if ((at > 1 && sb_add(t->csv, ",", 1, err) != 0) ||
		    sb_add(t->csv, v, strlen(v), err) != 0) {
			free(v);
			return -1;
		}
		free(v);
		at = col + 1;
	}
	return at > 1 ? sb_add(t->csv, "\n", 1, err) : 0;
}

int
rc__xlsx_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	struct book b = { 0 };
	struct sbuf csv = { 0 };
	struct table t = { &b, &csv };
	char path[512], cert[512], title[128], other[128];
	char inner[sizeof(err->msg)];
	rc_grid *g = NULL;
	size_t shared_len = 0;
	int mitutoyo, r = -1;

	if ((b.za = rc__zip_open_mem(buf, len, "xlsx", err)) == NULL)
		return -1;
	if (rc__dl_xml(err) != 0)
		goto out;
	if (read_shared(&b, err) != 0)
		goto out;
	for (size_t k = 0; k < b.nshared; k++)
		shared_len += strlen(b.shared[k]);
	/* The table's text is shorter than the sheet's XML but for shared
	 * strings used many times and empty fields between cells far apart:
	 * twice the XML part's bound and the shared strings is ample. */
	csv.limit = 2 * (size_t)XLSX_PART_MAX + 2 * shared_len;
	/* Mitutoyo's layout if both its sheets are there */
	mitutoyo = sheet_part(&b, "Certificate", cert, sizeof(cert), other,
	    sizeof(other), err) == 0 && sheet_part(&b, "DATA", path,
	    sizeof(path), title, sizeof(title), err) == 0;
	if (mitutoyo) {
		if (mitutoyo_csv(&b, path, cert, &csv, err) != 0)
			goto out;
	} else if (sheet_part(&b, NULL, path, sizeof(path), title, sizeof(title),
	    err) != 0 || stream_part(&b, path, "row", table_row, &t,
	    err) != 0)
		goto out;
	if ((g = rc__txt_read_mem(csv.p, csv.n, o, err)) == NULL) {
		snprintf(inner, sizeof(inner), "%s", err->msg);
		rc_seterr(err, "%s sheet '%s' read as a table: %s", mitutoyo ?
		    "Mitutoyo SurfTest workbook," : "Excel workbook,", title, inner);
		goto out;
	}
	if (rc_grid_meta_set(g, "sheet", title, err) != 0)
		goto out;
	r = rc__chanset_add(s, g, title, err);
	g = NULL;
out:
	rc_grid_free(g);
	free(csv.p);
	for (size_t k = 0; k < b.nshared; k++)
		free(b.shared[k]);
	free(b.shared);
	zip_discard(b.za);
	return r;
}
