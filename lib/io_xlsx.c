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
 * Memory: every part is read with io_zip.c's bound (XLSX_PART_MAX), and
 * the CSV a sheet makes may not outgrow its XML by much (a sparse sheet,
 * a cell at XFD1048576, would otherwise make gigabytes of empty fields).
 */
#include "io_internal.h"
#include "units.h"

#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zip.h>

#define XLSX_PART_MAX ((uint64_t)64 << 20)
#define REL_NS "http://schemas.openxmlformats.org/officeDocument/2006/" \
    "relationships"
#define MAX_COL 16384u		/* XFD, Excel's last column */

struct book {
	zip_t *za;
	char **shared;		/* the shared strings */
	size_t nshared;
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

/* Part name of the workbook parsed, or NULL (err set); *size its bytes
 * if size is not NULL. */
static xmlDoc *
part_sized(struct book *b, const char *name, size_t *size, rc_err *err)
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
	if (size != NULL)
		*size = len;
	if (doc == NULL || xmlDocGetRootElement(doc) == NULL) {
		xmlFreeDoc(doc);
		rc_seterr(err, "xlsx: %s is not well-formed XML",
		    rc__io_quote(q, sizeof(q), name, strlen(name)));
		return NULL;
	}
	return doc;
}

static xmlDoc *
part(struct book *b, const char *name, rc_err *err)
{
	return part_sized(b, name, NULL, err);
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
read_shared(struct book *b, rc_err *err)
{
	xmlDoc *doc;
	size_t n = 0;

	if (zip_name_locate(b->za, "xl/sharedStrings.xml", 0) < 0)
		return 0;
	if ((doc = part(b, "xl/sharedStrings.xml", err)) == NULL)
		return -1;
	for (xmlNode *c = xmlDocGetRootElement(doc)->children; c; c = c->next)
		n += is_el(c, "si");
	if ((b->shared = rc_calloc(n ? n : 1, sizeof(*b->shared), err)) == NULL)
		goto fail;
	for (xmlNode *c = xmlDocGetRootElement(doc)->children; c; c = c->next) {
		struct sbuf s = { .limit = XLSX_PART_MAX };

		if (!is_el(c, "si"))
			continue;
		if (text_of(c, &s, err) != 0 || sb_add(&s, "", 0, err) != 0) {
			free(s.p);
			goto fail;
		}
		b->shared[b->nshared++] = s.p;
	}
	xmlFreeDoc(doc);
	return 0;
fail:
	xmlFreeDoc(doc);
	return -1;
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

/* The rows of a sheet. */
static xmlNode *
sheet_data(xmlDoc *doc)
{
	return first(xmlDocGetRootElement(doc), "sheetData");
}

/* The value of cell (col, row) of a sheet (malloc'ed), NULL if it has
 * none or on error (err set, *failed 1). */
static char *
find_cell(const struct book *b, xmlDoc *doc, unsigned col, unsigned long row,
    int *failed, rc_err *err)
{
	xmlNode *data = sheet_data(doc);

	*failed = 0;
	for (xmlNode *rw = data ? data->children : NULL; rw; rw = rw->next) {
		if (!is_el(rw, "row"))
			continue;
		for (xmlNode *c = rw->children; c; c = c->next) {
			xmlChar *ref;
			unsigned cc;
			unsigned long rr;
			int ok;

			if (!is_el(c, "c"))
				continue;
			ref = xmlGetProp(c, (const xmlChar *)"r");
			ok = ref && cell_ref((const char *)ref, &cc, &rr) == 0 &&
			    cc == col && rr == row;
			xmlFree(ref);
			if (ok) {
				char *v = cell_value(b, c, err);

				*failed = v == NULL;
				return v;
			}
		}
	}
	return NULL;
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

/* Mitutoyo's profile: DATA!E (x) and DATA!F (heights) as CSV. */
static int
mitutoyo_csv(struct book *b, xmlDoc *data, xmlDoc *cert, struct sbuf *csv,
    rc_err *err)
{
	char xu[32], zu[32], line[160], q[64];
	char *cut, *ra;
	int failed, r = -1;
	xmlNode *sd = sheet_data(data);

	if ((cut = find_cell(b, cert, 5, 48, &failed, err)) == NULL && failed)
		return -1;
	if (cut == NULL || !trailing_unit(cut, 0, xu)) {
		rc_seterr(err, "Mitutoyo workbook: Certificate!E48 '%s' is not "
		    "the cut-off with its length unit (as '0.08mm'), which gives "
		    "the unit of x", cut ? rc__io_quote(q, sizeof(q), cut,
		    strlen(cut)) : "");
		free(cut);
		return -1;
	}
	free(cut);
	if ((ra = find_cell(b, data, 1, 1, &failed, err)) == NULL && failed)
		return -1;
	if (ra == NULL || !trailing_unit(ra, 1, zu)) {
		rc_seterr(err, "Mitutoyo workbook: DATA!A1 '%s' is not a "
		    "roughness parameter with its length unit (as 'Ra 0.018 "
		    "\xc2\xb5m'), which gives the unit of the heights",
		    ra ? rc__io_quote(q, sizeof(q), ra, strlen(ra)) : "");
		free(ra);
		return -1;
	}
	free(ra);
	snprintf(line, sizeof(line), "x in %s,z in %s\n", xu, zu);
	if (sb_add(csv, line, strlen(line), err) != 0)
		return -1;
	for (xmlNode *rw = sd ? sd->children : NULL; rw; rw = rw->next) {
		char *v[2] = { NULL, NULL };
		unsigned long row = 0;

		if (!is_el(rw, "row"))
			continue;
		for (xmlNode *c = rw->children; c; c = c->next) {
			xmlChar *ref;
			unsigned col;
			int bad;

			if (!is_el(c, "c"))
				continue;
			ref = xmlGetProp(c, (const xmlChar *)"r");
			bad = ref == NULL || cell_ref((const char *)ref, &col, &row);
			xmlFree(ref);
			if (bad || (col != 5 && col != 6))
				continue;
			free(v[col - 5]);
			if ((v[col - 5] = cell_value(b, c, err)) == NULL)
				goto fail_row;
			if (v[col - 5][0] == '\0') {
				free(v[col - 5]);
				v[col - 5] = NULL;
			}
		}
		if (v[0] == NULL && v[1] == NULL)
			continue;
		for (int k = 0; k < 2; k++) {
			double d;

			if (v[k] == NULL || rc__parse_double(v[k], &d) != 0) {
				rc_seterr(err, "Mitutoyo workbook: DATA!%c%lu %s%s%s: "
				    "want a number beside the %s", k ? 'F' : 'E', row,
				    v[k] ? "'" : "is empty", v[k] ? rc__io_quote(q,
				    sizeof(q), v[k], strlen(v[k])) : "", v[k] ? "'" : "",
				    k ? "position" : "height");
				goto fail_row;
			}
		}
		snprintf(line, sizeof(line), "%.64s,%.64s\n", v[0], v[1]);
		r = sb_add(csv, line, strlen(line), err);
		free(v[0]);
		free(v[1]);
		if (r != 0)
			return -1;
		continue;
fail_row:
		free(v[0]);
		free(v[1]);
		return -1;
	}
	return 0;
}

/* Any sheet as CSV: each row's cells from column A to its last, an
 * empty field where a cell has no value; commas in text become blanks. */
static int
table_csv(struct book *b, xmlDoc *doc, struct sbuf *csv, rc_err *err)
{
	xmlNode *sd = sheet_data(doc);

	for (xmlNode *rw = sd ? sd->children : NULL; rw; rw = rw->next) {
		unsigned at = 1;	/* the next column to write */

		if (!is_el(rw, "row"))
			continue;
		for (xmlNode *c = rw->children; c; c = c->next) {
			xmlChar *ref;
			unsigned col = at;
			unsigned long row;
			char *v;

			if (!is_el(c, "c"))
				continue;
			if ((ref = xmlGetProp(c, (const xmlChar *)"r")) != NULL &&
			    cell_ref((const char *)ref, &col, &row) != 0)
				col = at;
			xmlFree(ref);
			if (col < at)
				col = at;
			for (; at < col; at++)
				if (sb_add(csv, ",", at > 1, err) != 0)
					return -1;
			if ((v = cell_value(b, c, err)) == NULL)
				return -1;
			for (char *p = v; *p; p++)
				if (*p == ',' || *p == '\n' || *p == '\r')
					*p = ' ';
			if ((at > 1 && sb_add(csv, ",", 1, err) != 0) ||
			    sb_add(csv, v, strlen(v), err) != 0) {
				free(v);
				return -1;
			}
			free(v);
			at = col + 1;
		}
		if (at > 1 && sb_add(csv, "\n", 1, err) != 0)
			return -1;
	}
	return 0;
}

int
rc__xlsx_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	struct book b = { 0 };
	struct sbuf csv = { 0 };
	char path[512], title[128], other[128], inner[sizeof(err->msg)];
	xmlDoc *sheet = NULL, *cert = NULL;
	rc_grid *g = NULL;
	size_t xml_len = 0, shared_len = 0;
	int mitutoyo, r = -1;

	if ((b.za = rc__zip_open_mem(buf, len, "xlsx", err)) == NULL)
		return -1;
	if (read_shared(&b, err) != 0)
		goto out;
	for (size_t k = 0; k < b.nshared; k++)
		shared_len += strlen(b.shared[k]);
	/* Mitutoyo's layout if both its sheets are there */
	mitutoyo = sheet_part(&b, "Certificate", path, sizeof(path), other,
	    sizeof(other), err) == 0 && (cert = part(&b, path, err)) != NULL &&
	    sheet_part(&b, "DATA", path, sizeof(path), title, sizeof(title),
	    err) == 0;
	if (!mitutoyo && sheet_part(&b, NULL, path, sizeof(path), title,
	    sizeof(title), err) != 0)
		goto out;
	if ((sheet = part_sized(&b, path, &xml_len, err)) == NULL)
		goto out;
	/* The table's text is shorter than the sheet's XML but for shared
	 * strings used many times and empty fields between cells far apart:
	 * four times the XML and the shared strings is ample. */
	csv.limit = 4 * xml_len + 4 * shared_len + ((size_t)1 << 20);
	if ((mitutoyo ? mitutoyo_csv(&b, sheet, cert, &csv, err) :
	    table_csv(&b, sheet, &csv, err)) != 0)
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
	xmlFreeDoc(sheet);
	xmlFreeDoc(cert);
	for (size_t k = 0; k < b.nshared; k++)
		free(b.shared[k]);
	free(b.shared);
	zip_discard(b.za);
	return r;
}
