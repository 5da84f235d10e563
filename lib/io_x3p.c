/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_x3p.c - ISO 25178-72 XML 3D surface profile files (.x3p).
 *
 * An x3p file is a zip container: main.xml (root ISO5436_2 in the
 * namespace http://www.opengps.eu/2008/ISO5436_2, children unqualified)
 * describes the data, bindata/data.bin holds the values, optionally
 * bindata/valid.bin the validity bits, and md5checksum.hex the MD5 of
 * main.xml.  main.xml:
 *   Record1: Revision, FeatureType (SUR: an area; PRF: a profile),
 *            Axes CX CY CZ with AxisType (I incremental, A absolute),
 *            DataType (I int16, L int32, F float32, D float64), Increment,
 *            Offset.  Lengths and heights are in metres; a stored value
 *            v means v * Increment + Offset.
 *   Record2: date, creator, instrument, probing system, comment.
 *   Record3: MatrixDimension SizeX SizeY SizeZ; DataLink with
 *            PointDataLink, MD5ChecksumPointData and optionally
 *            ValidPointsLink, MD5ChecksumValidPoints (or DataList, the
 *            values as Datum elements).
 *   Record4: ChecksumFile (md5checksum.hex: "HEX *main.xml").
 * data.bin is little-endian, x fastest.  valid.bin has one bit per point,
 * least significant bit first, 1 = valid; without it, NaN values of the
 * floating types are the invalid points.  We write SUR, CX and CY
 * incremental, CZ absolute float64 with Increment 1 and Offset 0, lengths
 * in metres (a grid in another length unit is converted; one in metres
 * or without unit is stored bit for bit), NaN plus valid.bin at missing
 * points; we check every checksum a file carries when reading.
 */
#include "io_internal.h"
#include "md5.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <zip.h>
#include "io_dl_internal.h"

#define NS "http://www.opengps.eu/2008/ISO5436_2"
/* main.xml beyond this is not a surface description. */
#define XML_MAX ((zip_uint64_t)64 << 20)

/* ---- reading ---------------------------------------------------------- */

static xmlNode *
child(const xmlNode *n, const char *name)
{
	if (n == NULL)
		return NULL;
	for (xmlNode *c = n->children; c != NULL; c = c->next)
		if (c->type == XML_ELEMENT_NODE &&
		    strcmp((const char *)c->name, name) == 0)
			return c;
	return NULL;
}

/* The text of element path a/b/c under n, trimmed, into buf; NULL if the
 * element is absent. */
static const char *
text_at(const xmlNode *n, const char *path, char *buf, size_t len)
{
	char part[64];
	const char *p = path, *slash;
	xmlChar *t;
	char *s, *e;

	while (n != NULL && *p) {
		slash = strchr(p, '/');
		snprintf(part, sizeof(part), "%.*s", (int)(slash ? slash - p :
		    (long)strlen(p)), p);
		n = child(n, part);
		p = slash ? slash + 1 : p + strlen(p);
	}
	if (n == NULL)
		return NULL;
	t = xmlNodeGetContent(n);
	snprintf(buf, len, "%s", t ? (const char *)t : "");
	xmlFree(t);
	for (s = buf; isspace((unsigned char)*s); s++)
		;
	e = s + strlen(s);
	while (e > s && isspace((unsigned char)e[-1]))
		e--;
	*e = '\0';
	memmove(buf, s, (size_t)(e - s) + 1);
	return buf;
}

/* Entry name of za: exactly want bytes, or (want 0) any size up to
 * XML_MAX (io_zip.c bounds the memory). */
static int
read_entry(zip_t *za, const char *name, zip_uint64_t want, unsigned char **buf,
    size_t *len, rc_err *err)
{
	return rc__zip_entry(za, "x3p", name, want, XML_MAX, buf, len, err);
}

static int
check_md5(const unsigned char *p, size_t n, const char *want, const char *what,
    rc_err *err)
{
	char hex[33];

	rc_md5_hex(p, n, hex);
	if (strlen(want) < 32 || strncasecmp(hex, want, 32) != 0)
		return rc_seterr(err, "x3p: %s checksum mismatch (file says %.32s, "
		    "content has %s)", what, want, hex);
	return 0;
}

static int
get_number(const xmlNode *n, const char *path, double dflt, double *v,
    rc_err *err)
{
	char buf[128], q[64];

	if (text_at(n, path, buf, sizeof(buf)) == NULL || buf[0] == '\0') {
		*v = dflt;
		return 0;
	}
	if (rc__parse_double(buf, v) != 0 || !isfinite(*v))
		return rc_seterr(err, "x3p: %s '%s' is not a number", path,
		    rc__io_quote(q, sizeof(q), buf, strlen(buf)));
	return 0;
}

static int
get_size(const xmlNode *n, const char *path, size_t *v, rc_err *err)
{
	char buf[128], q[64];

	if (text_at(n, path, buf, sizeof(buf)) == NULL)
		return rc_seterr(err, "x3p: main.xml lacks %s", path);
	if (rc__parse_size(buf, v) != 0 || *v < 1)
		return rc_seterr(err, "x3p: %s '%s' is not a positive integer", path,
		    rc__io_quote(q, sizeof(q), buf, strlen(buf)));
	return 0;
}

struct desc {
	size_t nx, ny;
	double dx, dy, zinc, zoff;
	char type;		/* I L F D */
};

static int
read_desc(const xmlNode *root, struct desc *d, rc_err *err)
{
	const xmlNode *r1 = child(root, "Record1"), *ax = child(r1, "Axes");
	char buf[128], q[64];
	size_t nz;

	if (r1 == NULL || ax == NULL)
		return rc_seterr(err, "x3p: main.xml lacks Record1/Axes");
	if (text_at(r1, "FeatureType", buf, sizeof(buf)) == NULL ||
	    (strcmp(buf, "SUR") != 0 && strcmp(buf, "PRF") != 0))
		return rc_seterr(err, "x3p: FeatureType '%s' is not SUR or PRF "
		    "(point clouds are not grids)", rc__io_quote(q, sizeof(q), buf,
		    strlen(buf)));
	for (int k = 0; k < 2; k++) {
		const char *a = k ? "CY/AxisType" : "CX/AxisType";

		if (text_at(ax, a, buf, sizeof(buf)) == NULL || strcmp(buf, "I"))
			return rc_seterr(err, "x3p: %s is not I (incremental): "
			    "absolute x, y coordinates are not a grid", a);
	}
	if (get_number(ax, "CX/Increment", 1, &d->dx, err) != 0 ||
	    get_number(ax, "CY/Increment", 1, &d->dy, err) != 0 ||
	    get_number(ax, "CZ/Increment", 1, &d->zinc, err) != 0 ||
	    get_number(ax, "CZ/Offset", 0, &d->zoff, err) != 0)
		return -1;
	if (!(d->dx > 0 && d->dy > 0))
		return rc_seterr(err, "x3p: increments %g, %g are not positive",
		    d->dx, d->dy);
	if (text_at(ax, "CZ/DataType", buf, sizeof(buf)) == NULL ||
	    strlen(buf) != 1 || strchr("ILFD", buf[0]) == NULL)
		return rc_seterr(err, "x3p: CZ/DataType '%s' is not I, L, F or D",
		    rc__io_quote(q, sizeof(q), buf, strlen(buf)));
	d->type = buf[0];
	if (get_size(root, "Record3/MatrixDimension/SizeX", &d->nx, err) != 0 ||
	    get_size(root, "Record3/MatrixDimension/SizeY", &d->ny, err) != 0 ||
	    get_size(root, "Record3/MatrixDimension/SizeZ", &nz, err) != 0)
		return -1;
	if (nz != 1)
		return rc_seterr(err, "x3p: SizeZ %zu: only one layer is a height "
		    "map", nz);
	return rc_grid_check_shape(d->nx, d->ny, d->nx * d->dx, d->ny * d->dy,
	    err);
}

static double
raw_value(const unsigned char *p, char type)
{
	uint64_t u = 0;
	double v;
	float f;

	switch (type) {
	case 'I': return (int16_t)rc__get_le16(p);
	case 'L': return (int32_t)rc__get_le32(p);
	case 'F': {
		uint32_t w = rc__get_le32(p);

		memcpy(&f, &w, 4);
		return f;
	}
	default:
		for (int k = 7; k >= 0; k--)
			u = u << 8 | p[k];
		memcpy(&v, &u, 8);
		return v;
	}
}

static int
host_le(void)
{
	const uint16_t one = 1;

	return *(const unsigned char *)&one == 1;
}

/* What reading the values costs, decided before any allocation (issue
 * 27: an x3p of 1.1 MB unpacked to 12000^2 points, 1.16 GB, without a
 * word; zip compresses a smooth or constant map by 1000 and more): the
 * grid (8 bytes a point), the packed values (2, 4 or 8) and a mask (1
 * and 1/8).  Past RC_X3P_MAX_MB MiB (default X3P_MAX_MB) the file is
 * refused with that cost and how to raise the limit. */
#define X3P_MAX_MB 1024.0
static int
check_cost(const struct desc *d, rc_err *err)
{
	double n = (double)d->nx * (double)d->ny;
	double el = d->type == 'I' ? 2 : d->type == 'L' || d->type == 'F' ? 4 : 8;
	double mib = n * (8 + el + 1 + 1.0 / 8) / 1048576.0, limit = X3P_MAX_MB;
	const char *env = getenv("RC_X3P_MAX_MB");

	if (env != NULL && *env != '\0') {
		char *end;

		limit = strtod(env, &end);
		if (*end != '\0' || !(limit >= 0) || !isfinite(limit))
			return rc_seterr(err, "RC_X3P_MAX_MB=%.40s: want a number of "
			    "MiB", env);
	}
	if (mib > limit)
		return rc_seterr(err, "x3p: %zu x %zu values unpack to %.0f MiB of "
		    "memory, past the limit of %g MiB; to read it, set "
		    "RC_X3P_MAX_MB=%.0f (or more) in the environment", d->nx,
		    d->ny, ceil(mib), limit, ceil(mib));
	return 0;
}

/* The values, from the binary file or the DataList, into g. */
/* Long: the two ways x3p holds values (binary file, DataList) with their
 * checks. */
static int
read_values(zip_t *za, const xmlNode *r3, const struct desc *d, rc_grid *g,
    rc_err *err)
{
	const xmlNode *dl = child(r3, "DataLink"), *list = child(r3, "DataList");
	size_t n = d->nx * d->ny, el = d->type == 'I' ? 2 : d->type == 'L' ||
	    d->type == 'F' ? 4 : 8, len, k = 0;
	char name[512], sum[128];
	unsigned char *b = NULL, *vb = NULL;
	int scale = !(d->zinc == 1 && d->zoff == 0);

	if (dl != NULL) {
		if (text_at(dl, "PointDataLink", name, sizeof(name)) == NULL)
			return rc_seterr(err, "x3p: DataLink lacks PointDataLink");
		if (read_entry(za, name, (zip_uint64_t)n * el, &b, &len, err) != 0)
			return -1;
		if (text_at(dl, "MD5ChecksumPointData", sum, sizeof(sum)) != NULL &&
		    check_md5(b, len, sum, "data", err) != 0)
			goto fail;
		if (d->type == 'D' && host_le())
			memcpy(g->z, b, 8 * n);
		else
			for (k = 0; k < n; k++)
				g->z[k] = raw_value(b + k * el, d->type);
		if (text_at(dl, "ValidPointsLink", name, sizeof(name)) != NULL) {
			/* One bit per point, the last byte padded. */
			if (read_entry(za, name, (n + 7) / 8, &vb, &len, err) != 0)
				goto fail;
			if (text_at(dl, "MD5ChecksumValidPoints", sum, sizeof(sum)) !=
			    NULL && check_md5(vb, len, sum, "valid points", err) != 0)
				goto fail;
			if ((g->valid = rc_malloc(n, err)) == NULL)
				goto fail;
			for (k = 0; k < n; k++)
				g->valid[k] = vb[k / 8] >> (k % 8) & 1;
		}
	} else if (list != NULL) {
		for (const xmlNode *c = list->children; c != NULL; c = c->next) {
			char buf[128], *t;

			if (c->type != XML_ELEMENT_NODE || strcmp((const char *)c->name,
			    "Datum") != 0)
				continue;
			if (k == n) {
				rc_seterr(err, "x3p: DataList has more than %zu values", n);
				goto fail;
			}
			t = (char *)xmlNodeGetContent(c);
			snprintf(buf, sizeof(buf), "%s", t ? t : "");
			xmlFree(t);
			if (buf[0] == '\0')
				g->z[k] = NAN;
			else if (rc__parse_double(buf, &g->z[k]) != 0) {
				rc_seterr(err, "x3p: Datum %zu is not a number", k + 1);
				goto fail;
			}
			k++;
		}
		if (k != n) {
			rc_seterr(err, "x3p: DataList has %zu values, not %zu", k, n);
			goto fail;
		}
	} else {
		rc_seterr(err, "x3p: Record3 has neither DataLink nor DataList");
		goto fail;
	}
	/* NaN is the floating types' invalid point; an invalid point is NaN. */
	for (k = 0; k < n; k++)
		if (isnan(g->z[k]) || (g->valid != NULL && !g->valid[k]))
			break;
	if (k == n) {
		free(g->valid);
		g->valid = NULL;
	} else {
		if (g->valid == NULL) {
			if ((g->valid = rc_malloc(n, err)) == NULL)
				goto fail;
			memset(g->valid, 1, n);
		}
		for (k = 0; k < n; k++)
			if (!g->valid[k] || isnan(g->z[k])) {
				g->valid[k] = 0;
				g->z[k] = NAN;
			}
	}
	if (scale)
		for (k = 0; k < n; k++)
			if (g->valid == NULL || g->valid[k])
				g->z[k] = g->z[k] * d->zinc + d->zoff;
	free(b);
	free(vb);
	return 0;
fail:
	free(b);
	free(vb);
	return -1;
}

/* Record4's checksum file, if there is one: the MD5 of main.xml. */
static int
check_main_sum(zip_t *za, const xmlNode *root, const unsigned char *xml,
    size_t xlen, rc_err *err)
{
	char name[512];
	unsigned char *b;
	size_t len;
	int r;

	if (text_at(root, "Record4/ChecksumFile", name, sizeof(name)) == NULL ||
	    name[0] == '\0' || zip_name_locate(za, name, 0) < 0)
		return 0;
	if (read_entry(za, name, 0, &b, &len, err) != 0)
		return -1;
	if (len < 32) {
		free(b);
		return rc_seterr(err, "x3p: checksum file holds no MD5");
	}
	/* The digest is the first 32 characters. */
	{
		char want[33];

		memcpy(want, b, 32);
		want[32] = '\0';
		r = check_md5(xml, xlen, want, "main.xml", err);
	}
	free(b);
	return r;
}

int
rc__x3p_read(const unsigned char *buf, size_t len, rc_chanset *s, rc_err *err)
{
	zip_t *za;
	unsigned char *xml = NULL;
	size_t xlen;
	xmlDoc *doc = NULL;
	xmlNode *root;
	struct desc d;
	rc_grid *g = NULL;
	int r = -1;

	if ((za = rc__zip_open_mem(buf, len, "x3p", err)) == NULL)
		return -1;
	if (rc__dl_xml(err) != 0) {
		zip_discard(za);
		return -1;
	}
	if (zip_name_locate(za, "main.xml", 0) < 0) {
		rc_seterr(err, "a zip without main.xml: not an x3p file "
		    "(ISO 25178-72)");
		goto out;
	}
	if (read_entry(za, "main.xml", 0, &xml, &xlen, err) != 0)
		goto out;
	if (xlen > INT32_MAX || (doc = xmlReadMemory((const char *)xml, (int)xlen,
	    "main.xml", NULL, XML_PARSE_NONET | XML_PARSE_NOERROR |
	    XML_PARSE_NOWARNING)) == NULL) {
		rc_seterr(err, "x3p: main.xml is not well-formed XML");
		goto out;
	}
	root = xmlDocGetRootElement(doc);
	if (root == NULL || strcmp((const char *)root->name, "ISO5436_2") != 0) {
		rc_seterr(err, "x3p: main.xml is not an ISO5436_2 document");
		goto out;
	}
	if (check_main_sum(za, root, xml, xlen, err) != 0 ||
	    read_desc(root, &d, err) != 0 || check_cost(&d, err) != 0)
		goto out;
	if ((g = rc__io_grid_alloc(d.nx, d.ny, d.nx * d.dx, d.ny * d.dy, err)) ==
	    NULL)
		goto out;
	if (read_values(za, child(root, "Record3"), &d, g, err) != 0)
		goto out;
	strcpy(g->unit, "m");
	strcpy(g->z_unit, "m");
	g->periodic = 0;
	r = rc__chanset_add(s, g, "heights", err);
	g = NULL;
out:
	rc_grid_free(g);
	xmlFreeDoc(doc);
	free(xml);
	zip_discard(za);
	return r;
}

/* ---- writing ---------------------------------------------------------- */

/* An unqualified child element (the schema's elementFormDefault); the
 * text is escaped. */
static xmlNode *
add(xmlNode *parent, const char *name, const char *text)
{
	return xmlAddChild(parent, xmlNewDocRawNode(parent->doc, NULL,
	    (const xmlChar *)name, (const xmlChar *)text));
}

static void
add_axis(xmlNode *axes, const char *name, const char *type, double inc)
{
	xmlNode *a = add(axes, name, NULL);
	char num[64];

	add(a, "AxisType", type);
	add(a, "DataType", "D");
	rc_format_double(num, sizeof(num), inc);
	add(a, "Increment", num);
	add(a, "Offset", "0");
}

/* main.xml for g with the given data checksums (vsum NULL: no mask). */
static xmlChar *
main_xml(const rc_grid *g, double scale, const char *dsum, const char *vsum,
    int *len)
{
	xmlDoc *doc = xmlNewDoc((const xmlChar *)"1.0");
	xmlNode *root = xmlNewNode(NULL, (const xmlChar *)"ISO5436_2");
	xmlNode *r, *n, *axes;
	xmlNs *ns;
	xmlChar *out = NULL;
	char num[64], date[64];
	time_t now = time(NULL);
	struct tm tm;

	ns = xmlNewNs(root, (const xmlChar *)NS, (const xmlChar *)"p");
	xmlSetNs(root, ns);
	xmlNewNs(root, (const xmlChar *)"http://www.w3.org/2001/XMLSchema-instance",
	    (const xmlChar *)"xsi");
	xmlSetProp(root, (const xmlChar *)"xsi:schemaLocation", (const xmlChar *)
	    NS " " NS "/ISO5436_2_XML.xsd");
	xmlDocSetRootElement(doc, root);
	r = add(root, "Record1", NULL);
	add(r, "Revision", "ISO5436 - 2000");
	add(r, "FeatureType", "SUR");
	axes = add(r, "Axes", NULL);
	add_axis(axes, "CX", "I", g->lx / (double)g->nx / scale);
	add_axis(axes, "CY", "I", g->ly / (double)g->ny / scale);
	add_axis(axes, "CZ", "A", 1);
	r = add(root, "Record2", NULL);
	gmtime_r(&now, &tm);
	strftime(date, sizeof(date), "%Y-%m-%dT%H:%M:%SZ", &tm);
	add(r, "Date", date);
	add(r, "Creator", "roughcontact");
	n = add(r, "Instrument", NULL);
	add(n, "Manufacturer", "roughcontact");
	add(n, "Model", "surf");
	add(n, "Serial", "0");
	add(n, "Version", "1");
	add(r, "CalibrationDate", date);
	n = add(r, "ProbingSystem", NULL);
	add(n, "Type", "Software");
	add(n, "Identification", "roughcontact");
	add(r, "Comment", g->nhistory > 0 ? g->history[g->nhistory - 1] :
	    "written by roughcontact");
	r = add(root, "Record3", NULL);
	n = add(r, "MatrixDimension", NULL);
	snprintf(num, sizeof(num), "%zu", g->nx);
	add(n, "SizeX", num);
	snprintf(num, sizeof(num), "%zu", g->ny);
	add(n, "SizeY", num);
	add(n, "SizeZ", "1");
	n = add(r, "DataLink", NULL);
	add(n, "PointDataLink", "bindata/data.bin");
	add(n, "MD5ChecksumPointData", dsum);
	if (vsum != NULL) {
		add(n, "ValidPointsLink", "bindata/valid.bin");
		add(n, "MD5ChecksumValidPoints", vsum);
	}
	r = add(root, "Record4", NULL);
	add(r, "ChecksumFile", "md5checksum.hex");
	xmlDocDumpFormatMemoryEnc(doc, &out, len, "UTF-8", 1);
	xmlFreeDoc(doc);
	return out;
}

static int
add_entry(zip_t *za, const char *name, const void *p, size_t n, int store,
    rc_err *err)
{
	zip_source_t *s = zip_source_buffer(za, p, n, 0);
	zip_int64_t idx;

	if (s == NULL || (idx = zip_file_add(za, name, s, ZIP_FL_ENC_UTF_8)) < 0) {
		zip_source_free(s);
		return rc_seterr(err, "x3p: %s", zip_strerror(za));
	}
	if (store && zip_set_file_compression(za, (zip_uint64_t)idx, ZIP_CM_STORE,
	    0) != 0)
		return rc_seterr(err, "x3p: %s", zip_strerror(za));
	return 0;
}

/* Copy the finished in-memory archive to fp. */
static int
copy_out(zip_source_t *src, FILE *fp, rc_err *err)
{
	unsigned char buf[65536];
	zip_int64_t r;

	if (zip_source_open(src) != 0)
		return rc_seterr(err, "x3p: %s",
		    zip_error_strerror(zip_source_error(src)));
	while ((r = zip_source_read(src, buf, sizeof(buf))) > 0)
		if (rc__io_write(fp, buf, (size_t)r, err) != 0) {
			zip_source_close(src);
			return -1;
		}
	zip_source_close(src);
	if (r < 0)
		return rc_seterr(err, "x3p: %s",
		    zip_error_strerror(zip_source_error(src)));
	return 0;
}

/* Long: the x3p XML in document order, as the format defines it. */
int
rc__x3p_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	size_t n = rc_grid_size(g), vlen = (n + 7) / 8;
	double scale = 1;	/* units per metre */
	unsigned char *data = NULL, *valid = NULL;
	char dsum[33], vsum[33], msum[64];
	xmlChar *xml = NULL;
	int xlen = 0, r = -1;
	zip_error_t ze;
	zip_source_t *src = NULL;
	zip_t *za = NULL;

	if (g->unit[0] != '\0' && (scale = rc__io_per_metre(g->unit)) == 0)
		return rc_seterr(err, "x3p holds lengths in metres; unit '%s' is "
		    "not a length", g->unit);
	if (g->z_unit[0] != '\0' && strcmp(g->z_unit, g->unit) != 0 &&
	    rc__io_per_metre(g->z_unit) == 0)
		return rc_seterr(err, "x3p holds heights in metres; z unit '%s' "
		    "is not a length", g->z_unit);
	if (g->kind != RC_KIND_HEIGHT && g->kind != RC_KIND_GAP &&
	    g->kind != RC_KIND_DISPLACEMENT)
		return rc_seterr(err, "x3p holds heights; a %s grid is not one",
		    rc_kind_name(g->kind));
	if (rc__dl_zip(err) != 0 || rc__dl_xml(err) != 0)
		return -1;
	if ((data = rc_malloc(8 * n, err)) == NULL)
		return -1;
	{
		double zs = g->z_unit[0] != '\0' ? rc__io_per_metre(g->z_unit) :
		    scale;

		for (size_t k = 0; k < n; k++) {
			double v = g->valid && !g->valid[k] ? NAN : g->z[k];

			rc__put_le64(data + 8 * k, zs == 1 ? v : v / zs);
		}
	}
	rc_md5_hex(data, 8 * n, dsum);
	if (g->valid != NULL) {
		if ((valid = rc_calloc(vlen, 1, err)) == NULL)
			goto out;
		for (size_t k = 0; k < n; k++)
			if (g->valid[k])
				valid[k / 8] |= (unsigned char)(1u << (k % 8));
		rc_md5_hex(valid, vlen, vsum);
	}
	if ((xml = main_xml(g, scale, dsum, valid ? vsum : NULL, &xlen)) == NULL) {
		rc_seterr(err, "x3p: cannot build main.xml");
		goto out;
	}
	rc_md5_hex(xml, (size_t)xlen, msum);
	strcat(msum, " *main.xml\n");
	zip_error_init(&ze);
	src = zip_source_buffer_create(NULL, 0, 0, &ze);
	if (src == NULL || (zip_source_keep(src),
	    za = zip_open_from_source(src, ZIP_TRUNCATE, &ze)) == NULL) {
		rc_seterr(err, "x3p: %s", zip_error_strerror(&ze));
		zip_error_fini(&ze);
		goto out;
	}
	zip_error_fini(&ze);
	if (add_entry(za, "main.xml", xml, (size_t)xlen, 0, err) != 0 ||
	    add_entry(za, "bindata/data.bin", data, 8 * n, 1, err) != 0 ||
	    (valid != NULL && add_entry(za, "bindata/valid.bin", valid, vlen, 0,
	    err) != 0) ||
	    add_entry(za, "md5checksum.hex", msum, strlen(msum), 0, err) != 0)
		goto out;
	if (zip_close(za) != 0) {
		rc_seterr(err, "x3p: %s", zip_strerror(za));
		goto out;
	}
	za = NULL;
	r = copy_out(src, fp, err);
out:
	if (za != NULL)
		zip_discard(za);
	if (src != NULL)
		zip_source_free(src);
	xmlFree(xml);
	free(valid);
	free(data);
	return r;
}
