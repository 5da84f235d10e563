/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_formats.c - the measured-data formats: x3p and netCDF round trips
 * (bit-exact heights, sizes, units, periodic flag, mask), .gwy files built
 * here from the documented serialisation (channels, titles, units, masks,
 * hostile lengths), SDF from its documented header, MD5 against the test
 * suite of RFC 1321, and the channel selection rules. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zip.h>

#include "io.h"
#include "md5.h"
#include "testlib.h"

static void
test_md5(void)
{
	/* RFC 1321, appendix A.5. */
	static const char *in[] = { "", "a", "abc", "message digest",
	    "abcdefghijklmnopqrstuvwxyz",
	    "12345678901234567890123456789012345678901234567890123456789012345678901234567890" };
	static const char *want[] = { "d41d8cd98f00b204e9800998ecf8427e",
	    "0cc175b9c0f1b6a831c399e269772661", "900150983cd24fb0d6963f7d28e17f72",
	    "f96b697d7cb7938d525a2f31aaf161d0", "c3fcd3d76192e4007dfb496cca67e13b",
	    "57edf4a22be3c955ac49da2e2107b67a" };
	char hex[33];

	for (int k = 0; k < 6; k++) {
		rc_md5_hex(in[k], strlen(in[k]), hex);
		test_true(strcmp(hex, want[k]) == 0, "md5(\"%s\") = %s", in[k], hex);
	}
}

/* A 7x5 grid of values no decimal conversion keeps exactly, with one
 * missing point if masked. */
static rc_grid *
sample(int masked)
{
	rc_err err;
	rc_grid *g = rc_grid_new(7, 5, 3.5e-6, 2.5e-6, &err);

	for (size_t k = 0; k < 35; k++)
		g->z[k] = 1e-7 * sin(0.7 * (double)k + 0.1) / 3;
	strcpy(g->unit, "m");
	strcpy(g->z_unit, "m");
	g->periodic = 0;
	if (masked) {
		g->valid = malloc(35);
		memset(g->valid, 1, 35);
		g->valid[9] = 0;
		g->z[9] = NAN;
	}
	return g;
}

/* Same shape, units, flag, mask; values bit for bit. */
static void
same(const rc_grid *a, const rc_grid *b, const char *what, int check_periodic)
{
	int vals = 1, mask = 1;

	test_true(b != NULL, "%s: read back", what);
	if (b == NULL)
		return;
	test_int((long long)b->nx, (long long)a->nx, "%s: nx", what);
	test_int((long long)b->ny, (long long)a->ny, "%s: ny", what);
	if (b->nx != a->nx || b->ny != a->ny)
		return;
	/* x3p stores lx/nx: nx times that is lx within one rounding. */
	test_rel(b->lx, a->lx, 2.3e-16, "%s: lx", what);
	test_rel(b->ly, a->ly, 2.3e-16, "%s: ly", what);
	test_true(strcmp(b->unit, a->unit) == 0, "%s: unit '%s'", what, b->unit);
	test_true(strcmp(b->z_unit, a->z_unit) == 0, "%s: z_unit '%s'", what,
	    b->z_unit);
	if (check_periodic)
		test_int(b->periodic, a->periodic, "%s: periodic", what);
	for (size_t k = 0; k < a->nx * a->ny; k++) {
		int va = a->valid ? a->valid[k] : 1, vb = b->valid ? b->valid[k] : 1;

		mask &= va == vb;
		if (va && vb && memcmp(&a->z[k], &b->z[k], 8) != 0)
			vals = 0;
	}
	test_true(vals, "%s: heights bit for bit", what);
	test_true(mask, "%s: mask", what);
}

static void
roundtrip(int fmt, const char *name, int masked, int periodic)
{
	rc_err err;
	rc_grid *g = sample(masked), *r;
	char what[64];

	g->periodic = periodic;
	snprintf(what, sizeof(what), "%s%s%s", name, masked ? " masked" : "",
	    periodic ? " periodic" : "");
	test_true(rc_grid_write(g, test_path(name), (enum rc_format)fmt, &err) == 0,
	    "%s: write: %s", what, err.msg);
	r = rc_grid_read(test_path(name), NULL, &err);
	if (r == NULL)
		printf("  (%s: %s)\n", what, err.msg);
	same(g, r, what, fmt == RC_FMT_NC);
	rc_grid_free(r);
	rc_grid_free(g);
}

static void
test_roundtrips(void)
{
	rc_err err;
	rc_grid *g, *r;

	test_int(rc_format_from_name("a.x3p"), RC_FMT_X3P, "extension .x3p");
	test_int(rc_format_from_name("a.NC"), RC_FMT_NC, "extension .nc");
	roundtrip(RC_FMT_X3P, "a.x3p", 0, 0);
	roundtrip(RC_FMT_X3P, "b.x3p", 1, 0);
	roundtrip(RC_FMT_NC, "a.nc", 0, 0);
	roundtrip(RC_FMT_NC, "b.nc", 1, 1);

	/* x3p stores metres: a grid in um comes back in m, each value
	 * divided by 1e6 once (correctly rounded: within half an ulp). */
	g = sample(0);
	strcpy(g->unit, "um");
	strcpy(g->z_unit, "um");
	g->lx = 3.5;
	g->ly = 2.5;
	rc_grid_write(g, test_path("um.x3p"), RC_FMT_X3P, &err);
	r = rc_grid_read(test_path("um.x3p"), NULL, &err);
	test_true(r != NULL && strcmp(r->unit, "m") == 0, "x3p in um reads as m");
	if (r != NULL) {
		double worst = 0;

		for (size_t k = 0; k < 35; k++)
			worst = fmax(worst, fabs(r->z[k] * 1e6 - g->z[k]) / fabs(g->z[k]));
		test_range(worst, 0, 2.3e-16, "x3p um -> m: values within rounding");
		test_rel(r->lx, 3.5e-6, 2.3e-16, "x3p um -> m: lx");
	}
	rc_grid_free(r);
	/* netCDF has one unit: lengths go to the height unit, heights stay. */
	strcpy(g->z_unit, "nm");
	rc_grid_write(g, test_path("nm.nc"), RC_FMT_NC, &err);
	r = rc_grid_read(test_path("nm.nc"), NULL, &err);
	test_true(r != NULL && strcmp(r->unit, "nm") == 0 &&
	    strcmp(r->z_unit, "nm") == 0, "nc um x nm: unit nm");
	if (r != NULL) {
		test_true(memcmp(r->z, g->z, 35 * 8) == 0, "nc um x nm: heights bit for bit");
		test_rel(r->lx, 3500, 2.3e-16, "nc um x nm: lx in nm");
	}
	rc_grid_free(r);
	/* Non-lengths have no place in either. */
	strcpy(g->z_unit, "V");
	test_true(rc_grid_write(g, test_path("v.x3p"), RC_FMT_X3P, &err) != 0 &&
	    strstr(err.msg, "'V'") != NULL, "x3p refuses z unit V: %s", err.msg);
	test_true(rc_grid_write(g, test_path("v.nc"), RC_FMT_NC, &err) != 0,
	    "nc refuses um x V: %s", err.msg);
	rc_grid_free(g);
}

/* ---- .gwy files from the documented serialisation -------------------- */

struct buf {
	unsigned char *p;
	size_t n, cap;
};

static void
b_put(struct buf *b, const void *p, size_t n)
{
	if (b->n + n > b->cap) {
		b->cap = 2 * (b->n + n) + 64;
		b->p = realloc(b->p, b->cap);
	}
	memcpy(b->p + b->n, p, n);
	b->n += n;
}

static void
b_str(struct buf *b, const char *s)
{
	b_put(b, s, strlen(s) + 1);
}

static void
b_u32(struct buf *b, uint32_t v)
{
	unsigned char c[4] = { v & 255, v >> 8 & 255, v >> 16 & 255, v >> 24 };

	b_put(b, c, 4);
}

static void
b_f64(struct buf *b, double v)
{
	unsigned char c[8];
	uint64_t u;

	memcpy(&u, &v, 8);
	for (int k = 0; k < 8; k++)
		c[k] = (unsigned char)(u >> (8 * k));
	b_put(b, c, 8);
}

/* Wrap the components in body as an object of type name. */
static void
b_object(struct buf *b, const char *type, const struct buf *body)
{
	b_str(b, type);
	b_u32(b, (uint32_t)body->n);
	b_put(b, body->p, body->n);
}

static void
b_unit(struct buf *b, const char *key, const char *unit)
{
	struct buf u = { 0 };

	b_str(&u, "unitstr");
	b_put(&u, "s", 1);
	b_str(&u, unit);
	b_str(b, key);
	b_put(b, "o", 1);
	b_object(b, "GwySIUnit", &u);
	free(u.p);
}

/* A GwyDataField component keyed key; values v(k) = scale * k. */
static void
b_field(struct buf *b, const char *key, int xres, int yres, double xreal,
    const char *uxy, const char *uz, const double *v, uint32_t nclaim)
{
	struct buf f = { 0 };

	b_str(&f, "xres");
	b_put(&f, "i", 1);
	b_u32(&f, (uint32_t)xres);
	b_str(&f, "yres");
	b_put(&f, "i", 1);
	b_u32(&f, (uint32_t)yres);
	b_str(&f, "xreal");
	b_put(&f, "d", 1);
	b_f64(&f, xreal);
	b_str(&f, "yreal");
	b_put(&f, "d", 1);
	b_f64(&f, xreal / 2);
	b_unit(&f, "si_unit_xy", uxy);
	b_unit(&f, "si_unit_z", uz);
	b_str(&f, "data");
	b_put(&f, "D", 1);
	b_u32(&f, nclaim);
	for (int k = 0; k < xres * yres; k++)
		b_f64(&f, v[k]);
	b_str(b, key);
	b_put(b, "o", 1);
	b_object(b, "GwyDataField", &f);
	free(f.p);
}

static void
b_title(struct buf *b, const char *key, const char *title)
{
	b_str(b, key);
	b_put(b, "s", 1);
	b_str(b, title);
}

/* Two channels: /0 phase (deg), /1 height (m) with a mask; also a
 * boolean, an int array and a nested object Gwyddion files carry. */
static void
make_gwy(const char *path, uint32_t nclaim_height)
{
	struct buf c = { 0 }, f = { 0 }, other = { 0 };
	double v[12], m[12] = { 0 };

	for (int k = 0; k < 12; k++)
		v[k] = 1e-9 * (k + 0.25);
	m[5] = 1;
	b_field(&c, "/0/data", 4, 3, 2e-6, "m", "deg", v, 12);
	b_title(&c, "/0/data/title", "Phase");
	b_str(&c, "/0/data/visible");
	b_put(&c, "b\x01", 2);
	b_str(&c, "/0/select/rectangle");
	b_put(&c, "I", 1);
	b_u32(&c, 2);
	b_u32(&c, 7);
	b_u32(&c, 8);
	b_str(&other, "x");
	b_put(&other, "q", 1);
	b_put(&other, "12345678", 8);
	b_str(&c, "/0/graph/graph/1");
	b_put(&c, "o", 1);
	b_object(&c, "GwyGraphModel", &other);
	b_field(&c, "/1/data", 4, 3, 2e-6, "m", "m", v, nclaim_height);
	b_title(&c, "/1/data/title", "Height");
	b_field(&c, "/1/mask", 4, 3, 2e-6, "m", "", m, 12);
	b_put(&f, "GWYP", 4);
	b_object(&f, "GwyContainer", &c);
	test_put_file(path, f.p, f.n);
	free(c.p);
	free(f.p);
	free(other.p);
}

static void
test_gwy(void)
{
	rc_read_opts o;
	rc_channel_info *ci = NULL;
	size_t n = 0;
	rc_err err;
	rc_grid *g;

	make_gwy(test_path("two.gwy"), 12);
	test_true(rc_grid_list_channels(test_path("two.gwy"), NULL, &ci, &n, &err) == 0,
	    "gwy: list channels: %s", err.msg);
	test_int((long long)n, 2, "gwy: two channels");
	if (n == 2) {
		test_true(strcmp(ci[0].title, "Phase") == 0 &&
		    strcmp(ci[1].title, "Height") == 0, "gwy: titles");
		test_true(strcmp(ci[0].z_unit, "deg") == 0 &&
		    strcmp(ci[1].z_unit, "m") == 0, "gwy: z units");
		test_true(!ci[0].has_mask && ci[1].has_mask, "gwy: mask flags");
		test_rel(ci[1].lx, 2e-6, 0, "gwy: xreal");
		test_rel(ci[1].ly, 1e-6, 0, "gwy: yreal");
	}
	free(ci);
	/* Default: the first channel whose values are lengths. */
	g = rc_grid_read(test_path("two.gwy"), NULL, &err);
	test_true(g != NULL && strcmp(g->z_unit, "m") == 0 && g->valid != NULL,
	    "gwy: default channel is Height: %s", g ? g->z_unit : err.msg);
	if (g != NULL) {
		test_true(isnan(g->z[5]) && g->valid[5] == 0 && g->valid[4] == 1,
		    "gwy: mask point 5 is missing");
		test_true(g->z[11] == 1e-9 * 11.25 && g->nx == 4 && g->ny == 3,
		    "gwy: values row by row");
		test_int(g->periodic, 0, "gwy: measured data are not periodic");
	}
	rc_grid_free(g);
	rc_read_opts_init(&o);
	o.channel_name = "phase";
	g = rc_grid_read(test_path("two.gwy"), &o, &err);
	test_true(g != NULL && strcmp(g->z_unit, "deg") == 0,
	    "gwy: --channel phase (any case)");
	rc_grid_free(g);
	o.channel_name = NULL;
	o.channel = 3;
	g = rc_grid_read(test_path("two.gwy"), &o, &err);
	test_true(g == NULL && strstr(err.msg, "no channel 3") != NULL,
	    "gwy: channel 3 refused: %s", err.msg);
	rc_grid_free(g);
	/* A data array that claims more values than the file holds. */
	make_gwy(test_path("lie.gwy"), 1u << 30);
	g = rc_grid_read(test_path("lie.gwy"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "corrupt .gwy") != NULL,
	    "gwy: lying data count refused: %s", err.msg);
	rc_grid_free(g);
	make_gwy(test_path("short.gwy"), 13);
	g = rc_grid_read(test_path("short.gwy"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "corrupt .gwy") != NULL,
	    "gwy: 13 values for 4x3 refused: %s", err.msg);
	rc_grid_free(g);
}

static void
test_sdf(void)
{
	const char *ascii = "aISO-1.0\nManufacID = test\nCreateDate = 010120201200\n"
	    "NumPoints = 3\nNumProfiles = 2\nXscale = 1.0e-6\nYscale = 2.0e-6\n"
	    "Zscale = 1.0e-9\nZresolution = -1\nCompression = 0\nDataType = 7\n"
	    "CheckType = 0\n*\n1 2 3\n4 BAD 6\n*\n<Comment>x</Comment>\n*\n";
	unsigned char bin[81 + 12] = "bISO-1.0";
	int16_t raw[6] = { 1, -2, 3, -32768, 5, 6 };
	double d;
	rc_err err;
	rc_grid *g;

	test_put_file(test_path("a.sdf"), ascii, strlen(ascii));
	g = rc_grid_read(test_path("a.sdf"), NULL, &err);
	test_true(g != NULL, "sdf ascii: %s", g ? "" : err.msg);
	if (g != NULL) {
		test_true(g->nx == 3 && g->ny == 2, "sdf ascii: 3x2");
		test_rel(g->lx, 3e-6, 1e-15, "sdf ascii: lx = NumPoints Xscale");
		test_rel(g->ly, 4e-6, 1e-15, "sdf ascii: ly");
		test_true(g->z[5] == 6 * 1e-9 && g->z[0] == 1e-9, "sdf ascii: z = value Zscale");
		test_true(g->valid && !g->valid[4] && isnan(g->z[4]), "sdf ascii: BAD is missing");
		test_true(strcmp(g->unit, "m") == 0, "sdf ascii: metres");
	}
	rc_grid_free(g);
	/* Binary: the 81-byte header, int16 values, -32768 missing. */
	memcpy(bin + 8, "manufactur", 10);
	bin[42] = 3;	/* NumPoints */
	bin[44] = 2;	/* NumProfiles */
	d = 1e-6;
	memcpy(bin + 46, &d, 8);
	memcpy(bin + 54, &d, 8);
	d = 0.5e-9;
	memcpy(bin + 62, &d, 8);
	bin[79] = 5;	/* DataType int16 */
	for (int k = 0; k < 6; k++) {
		bin[81 + 2 * k] = (unsigned char)(raw[k] & 255);
		bin[82 + 2 * k] = (unsigned char)((uint16_t)raw[k] >> 8);
	}
	test_put_file(test_path("b.sdf"), bin, sizeof(bin));
	g = rc_grid_read(test_path("b.sdf"), NULL, &err);
	test_true(g != NULL, "sdf binary: %s", g ? "" : err.msg);
	if (g != NULL) {
		test_true(g->z[1] == -2 * 0.5e-9 && g->z[5] == 6 * 0.5e-9, "sdf binary: values");
		test_true(g->valid && !g->valid[3], "sdf binary: -32768 is missing");
		test_rel(g->lx, 3e-6, 1e-15, "sdf binary: lx");
	}
	rc_grid_free(g);
	test_put_file(test_path("c.sdf"), bin, sizeof(bin) - 1);
	g = rc_grid_read(test_path("c.sdf"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "truncated") != NULL,
	    "sdf binary truncated: %s", err.msg);
	rc_grid_free(g);
}

/* An x3p as another writer might make it: int16 heights with a CZ
 * Increment and Offset (z = v * Increment + Offset), no checksums, or the
 * values inline as a DataList. */
static void
make_x3p(const char *path, const char *type, const char *record3,
    const void *bin, size_t nbin)
{
	char xml[2048];
	zip_t *z;
	int e;

	snprintf(xml, sizeof(xml), "<?xml version=\"1.0\"?>\n"
	    "<p:ISO5436_2 xmlns:p=\"http://www.opengps.eu/2008/ISO5436_2\">"
	    "<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType>"
	    "<Axes><CX><AxisType>I</AxisType><DataType>D</DataType>"
	    "<Increment>0.5e-6</Increment><Offset>0</Offset></CX>"
	    "<CY><AxisType>I</AxisType><DataType>D</DataType>"
	    "<Increment>0.25e-6</Increment><Offset>0</Offset></CY>"
	    "<CZ><AxisType>A</AxisType><DataType>%s</DataType>"
	    "<Increment>2e-9</Increment><Offset>1e-6</Offset></CZ></Axes></Record1>"
	    "<Record3><MatrixDimension><SizeX>3</SizeX><SizeY>2</SizeY>"
	    "<SizeZ>1</SizeZ></MatrixDimension>%s</Record3></p:ISO5436_2>\n",
	    type, record3);
	z = zip_open(path, ZIP_CREATE | ZIP_TRUNCATE, &e);
	zip_file_add(z, "main.xml", zip_source_buffer(z, xml, strlen(xml), 0), 0);
	if (bin != NULL)
		zip_file_add(z, "bindata/data.bin", zip_source_buffer(z, bin, nbin,
		    0), 0);
	zip_close(z);
}

static void
test_x3p_foreign(void)
{
	unsigned char bin[12];
	int16_t v[6] = { -3, 0, 5, 100, -100, 7 };
	rc_err err;
	rc_grid *g;
	int ok = 1;

	for (int k = 0; k < 6; k++) {
		bin[2 * k] = (unsigned char)((uint16_t)v[k] & 255);
		bin[2 * k + 1] = (unsigned char)((uint16_t)v[k] >> 8);
	}
	make_x3p(test_path("i.x3p"), "I", "<DataLink><PointDataLink>bindata/data.bin"
	    "</PointDataLink></DataLink>", bin, sizeof(bin));
	g = rc_grid_read(test_path("i.x3p"), NULL, &err);
	test_true(g != NULL, "x3p int16: %s", g ? "" : err.msg);
	if (g != NULL) {
		for (int k = 0; k < 6; k++)
			ok &= g->z[k] == v[k] * 2e-9 + 1e-6;
		test_true(ok, "x3p int16: z = v Increment + Offset");
		test_rel(g->lx, 1.5e-6, 2.3e-16, "x3p int16: lx = SizeX CX Increment");
		test_rel(g->ly, 0.5e-6, 2.3e-16, "x3p int16: ly");
	}
	rc_grid_free(g);
	make_x3p(test_path("l.x3p"), "D", "<DataList><Datum>1</Datum><Datum>2</Datum>"
	    "<Datum></Datum><Datum>4</Datum><Datum>5</Datum><Datum>6</Datum>"
	    "</DataList>", NULL, 0);
	g = rc_grid_read(test_path("l.x3p"), NULL, &err);
	test_true(g != NULL && g->z[5] == 6 * 2e-9 + 1e-6 && g->valid != NULL &&
	    !g->valid[2] && isnan(g->z[2]), "x3p DataList, an empty Datum missing: %s",
	    g ? "" : err.msg);
	rc_grid_free(g);
	make_x3p(test_path("s.x3p"), "I", "<DataLink><PointDataLink>bindata/data.bin"
	    "</PointDataLink></DataLink>", bin, sizeof(bin) - 2);
	g = rc_grid_read(test_path("s.x3p"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "holds 10 bytes") != NULL,
	    "x3p: short data file refused: %s", err.msg);
	rc_grid_free(g);
}

int
main(void)
{
	setenv("RC_GWYDDION", "", 1);	/* these tests are of our readers */
	test_md5();
	test_roundtrips();
	test_gwy();
	test_sdf();
	test_x3p_foreign();
	return test_summary();
}
