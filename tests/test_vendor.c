/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_vendor.c - instrument formats of other vendors read by our own
 * readers (lib/io_tmd.c, ...): the example files of SurfaceTopography in
 * tests/data (tests/data/st_vendor.README) against that project's test
 * values and statistics computed independently from the raw bytes, files
 * built here in the documented layouts (value order, units, missing
 * points), and every truncation of them refused with a message. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <zlib.h>

#include "io.h"
#include "testlib.h"

static const char *
data_path(const char *name)
{
	static char path[4096];
	const char *top = getenv("RC_TOP");

	snprintf(path, sizeof(path), "%s/tests/data/%s", top ? top : ".", name);
	return path;
}

static unsigned char *
slurp(const char *path, size_t *len)
{
	FILE *fp = fopen(path, "rb");
	unsigned char *b = NULL;
	long n;

	if (fp == NULL || fseek(fp, 0, SEEK_END) != 0 || (n = ftell(fp)) < 0 ||
	    fseek(fp, 0, SEEK_SET) != 0 || (b = malloc((size_t)n + 1)) == NULL ||
	    fread(b, 1, (size_t)n, fp) != (size_t)n) {
		if (fp != NULL)
			fclose(fp);
		free(b);
		return NULL;
	}
	fclose(fp);
	*len = (size_t)n;
	return b;
}

struct stats {
	double mean, rms, min, max;
	size_t nvalid;
};

static struct stats
stats_of(const rc_grid *g)
{
	struct stats s = { 0, 0, INFINITY, -INFINITY, 0 };
	size_t n = rc_grid_size(g);

	for (size_t k = 0; k < n; k++)
		if (!isnan(g->z[k])) {
			s.mean += g->z[k];
			s.nvalid++;
			s.min = fmin(s.min, g->z[k]);
			s.max = fmax(s.max, g->z[k]);
		}
	s.mean /= (double)s.nvalid;
	for (size_t k = 0; k < n; k++)
		if (!isnan(g->z[k]))
			s.rms += (g->z[k] - s.mean) * (g->z[k] - s.mean);
	s.rms = sqrt(s.rms / (double)s.nvalid);
	return s;
}

/* Every prefix of the file (all of the first 300 bytes, then a spread up
 * to one byte short of len) must be refused with a message, never read or
 * crash. */
static void
truncations(const char *name, const unsigned char *b, size_t len)
{
	size_t cuts[400], nc = 0;
	int refused = 0, said = 0;
	rc_err err;

	for (size_t k = 1; k < 300 && k < len; k++)
		cuts[nc++] = k;
	for (size_t k = 0; k < 90 && len > 300; k++)
		cuts[nc++] = 300 + (len - 301) * k / 89;
	for (size_t c = 0; c < nc; c++) {
		rc_grid *g;

		test_put_file(test_path("cut.bin"), b, cuts[c]);
		g = rc_grid_read(test_path("cut.bin"), NULL, &err);
		refused += g == NULL;
		said += g == NULL && err.msg[0] != '\0';
		rc_grid_free(g);
	}
	test_int(refused, (long long)nc, "%s: %zu truncations refused", name, nc);
	test_int(said, (long long)nc, "%s: each with a message", name);
}

/* SurfaceTopography's tmd-1.tmd: 300 x 300, 18.9566 mm square (its test,
 * rtol 1e-3), heights in mm with min >= 0 and max < 1 mm (its test); the
 * mean, rms, min and max are numpy's of the float32 values of the file
 * (bytes 80 on), converted to metres. */
static void
test_tmd_file(void)
{
	rc_channel_info *info = NULL;
	size_t nch = 0, len = 0;
	unsigned char *b;
	struct stats s;
	rc_err err;
	rc_grid *g;

	g = rc_grid_read(data_path("st_tmd-1.tmd"), NULL, &err);
	test_true(g != NULL, "tmd-1.tmd read: %s", g ? "" : err.msg);
	if (g == NULL)
		return;
	test_int((long long)g->nx, 300, "tmd-1: nx");
	test_int((long long)g->ny, 300, "tmd-1: ny");
	test_rel(g->lx, 18.9566e-3, 1e-3, "tmd-1: lx (SurfaceTopography)");
	test_rel(g->ly, 18.9566e-3, 1e-3, "tmd-1: ly");
	test_true(strcmp(g->unit, "m") == 0 && strcmp(g->z_unit, "m") == 0,
	    "tmd-1: in metres ('%s', '%s')", g->unit, g->z_unit);
	test_int(g->periodic, 0, "tmd-1: a measurement is not periodic");
	s = stats_of(g);
	test_int((long long)s.nvalid, 90000, "tmd-1: no missing point");
	test_rel(s.rms, 0.07434134067352181e-3, 1e-12, "tmd-1: rms (numpy)");
	test_rel(s.mean, 0.17287914127574167e-3, 1e-12, "tmd-1: mean (numpy)");
	test_true(s.min == 0, "tmd-1: min 0 (numpy): %g", s.min);
	test_rel(s.max, 0.3509870171546936e-3, 1e-15, "tmd-1: max (numpy)");
	rc_grid_free(g);
	test_true(rc_grid_list_channels(data_path("st_tmd-1.tmd"), NULL, &info,
	    &nch, &err) == 0 && nch == 1 && strcmp(info[0].title, "Height") == 0,
	    "tmd-1: one channel, Height");
	free(info);
	if ((b = slurp(data_path("st_tmd-1.tmd"), &len)) != NULL) {
		truncations("tmd-1", b, len);
		/* One byte more is as wrong as one less. */
		b[len] = 0;
		test_put_file(test_path("long.tmd"), b, len + 1);
		g = rc_grid_read(test_path("long.tmd"), NULL, &err);
		test_true(g == NULL && strstr(err.msg, "data after") != NULL,
		    "tmd: trailing byte refused: %s", g ? "read" : err.msg);
		rc_grid_free(g);
	}
	free(b);
}

static void
put_le32(unsigned char *p, uint32_t v)
{
	for (int k = 0; k < 4; k++)
		p[k] = (unsigned char)(v >> (8 * k));
}

static void
put_f32(unsigned char *p, float f)
{
	uint32_t u;

	memcpy(&u, &f, 4);
	put_le32(p, u);
}

/* The layout of SurfaceTopography's synthetic test: 3 x 2, 1.5 x 1 mm,
 * heights 0..5 (mm) row by row; a NaN is a missing point. */
static void
test_tmd_synthetic(void)
{
	unsigned char b[80 + 24];
	rc_err err;
	rc_grid *g;

	memset(b, 0, sizeof(b));
	memcpy(b, "Binary TrueMap Data File v2.0\r\n", 31);
	memcpy(b + 32, "Synthetic test file 1\r\n", 23);
	put_le32(b + 56, 3);
	put_le32(b + 60, 2);
	put_f32(b + 64, 1.5f);
	put_f32(b + 68, 1.0f);
	put_f32(b + 72, 0.5f);
	put_f32(b + 76, 0.25f);
	for (int k = 0; k < 6; k++)
		put_f32(b + 80 + 4 * k, k == 4 ? NAN : (float)k);
	test_put_file(test_path("s.tmd"), b, sizeof(b));
	g = rc_grid_read(test_path("s.tmd"), NULL, &err);
	test_true(g != NULL, "tmd synthetic: %s", g ? "" : err.msg);
	if (g == NULL)
		return;
	test_true(g->nx == 3 && g->ny == 2, "tmd synthetic: 3 x 2");
	test_rel(g->lx, 1.5e-3, 1e-15, "tmd synthetic: lx 1.5 mm");
	test_rel(g->ly, 1.0e-3, 1e-15, "tmd synthetic: ly 1 mm");
	test_true(g->z[1] == 1e-3 && g->z[3] == 3e-3 && g->z[5] == 5e-3,
	    "tmd synthetic: z(i, j) = (3 j + i) mm, x fastest");
	test_true(g->valid != NULL && !g->valid[4] && isnan(g->z[4]) &&
	    g->valid[5], "tmd synthetic: NaN is a missing point");
	rc_grid_free(g);
	put_le32(b + 56, 0);
	test_put_file(test_path("z.tmd"), b, sizeof(b));
	g = rc_grid_read(test_path("z.tmd"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "corrupt header") != NULL,
	    "tmd: nx 0 refused: %s", g ? "read" : err.msg);
	rc_grid_free(g);
	put_le32(b + 56, 0xffffffffu);
	test_put_file(test_path("h.tmd"), b, sizeof(b));
	g = rc_grid_read(test_path("h.tmd"), NULL, &err);
	test_true(g == NULL && err.msg[0] != '\0', "tmd: nx 2^32-1 refused: %s",
	    g ? "read" : err.msg);
	rc_grid_free(g);
}

/* SurfaceTopography's opdx-3.opdx (a Dektak profile, 3001 points) and
 * opdx-3.txt, the instrument software's text export of the same profile
 * (x and height in metres, 8 digits): a second, independent source of
 * every height and of the spacing.  Heights agree to the export's
 * rounding (half a unit of the 8th digit: relative 5e-8, 1e-7 allowed). */
static void
test_opdx_file(void)
{
	rc_channel_info *info = NULL;
	size_t nch = 0, len = 0, n = 0, far = 0;
	double x[3001], z[3001], worst = 0;
	unsigned char *b;
	FILE *fp;
	rc_err err;
	rc_grid *g;

	if ((fp = fopen(data_path("st_opdx-3.txt"), "r")) != NULL) {
		while (n < 3001 && fscanf(fp, "%lf %lf", &x[n], &z[n]) == 2)
			n++;
		fclose(fp);
	}
	test_int((long long)n, 3001, "opdx-3.txt: 3001 rows of the export");
	g = rc_grid_read(data_path("st_opdx-3.opdx"), NULL, &err);
	test_true(g != NULL, "opdx-3.opdx read: %s", g ? "" : err.msg);
	if (g == NULL || n != 3001)
		goto out;
	test_true(g->nx == 3001 && g->ny == 1, "opdx-3: a profile of 3001");
	test_rel(g->lx / 3001, x[3000] / 3000, 1e-7, "opdx-3: spacing as the "
	    "export's x");
	test_rel(g->lx, 3001 * 49.966688862798314e-6 / 3000, 1e-15,
	    "opdx-3: lx = Extent n / (n - 1)");
	test_true(strcmp(g->unit, "m") == 0 && strcmp(g->z_unit, "m") == 0,
	    "opdx-3: in metres");
	for (size_t k = 0; k < 3001; k++) {
		double r = fabs(g->z[k] - z[k]) / fabs(z[k]);

		worst = fmax(worst, r);
		far += !(r <= 1e-7);
	}
	test_int((long long)far, 0, "opdx-3: every height as the export's "
	    "(worst relative %.2g)", worst);
	{
		struct stats a = stats_of(g);
		rc_grid *t = rc_grid_new(3001, 1, g->lx, g->ly, &err);

		memcpy(t->z, z, sizeof(z));
		struct stats e = stats_of(t);

		test_rel(a.rms, e.rms, 1e-7, "opdx-3: rms %.9g as the export's", a.rms);
		test_rel(a.min, e.min, 1e-7, "opdx-3: min as the export's");
		test_rel(a.max, e.max, 1e-7, "opdx-3: max as the export's");
		rc_grid_free(t);
	}
	test_true(rc_grid_list_channels(data_path("st_opdx-3.opdx"), NULL, &info,
	    &nch, &err) == 0 && nch == 1 && strcmp(info[0].title, "Raw") == 0,
	    "opdx-3: one channel, Raw");
	free(info);
	if ((b = slurp(data_path("st_opdx-3.opdx"), &len)) != NULL)
		/* The 2 bytes after the last terminator hold nothing read. */
		truncations("opdx-3", b, len - 2);
	free(b);
out:
	rc_grid_free(g);
}

static void
put_f64(unsigned char *p, double d)
{
	uint64_t u;

	memcpy(&u, &d, 8);
	for (int k = 0; k < 8; k++)
		p[k] = (unsigned char)(u >> (8 * k));
}

/* An .nms in the layout of the example files (lib/io_nms.c): 3 x 2
 * heights 0, 65535, 32768, ... between zmin 2 and zmax 6 um, spacing
 * 312.5 nm, and an intensity image; every truncation refused. */
static void
test_nms_synthetic(void)
{
	static const uint16_t raw[6] = { 0, 65535, 32768, 1, 65534, 13107 };
	unsigned char b[3468 + 18];
	rc_channel_info *info = NULL;
	rc_read_opts o;
	size_t nch = 0;
	rc_err err;
	rc_grid *g;

	memset(b, 0, sizeof(b));
	memcpy(b + 32, "OM_MS_2.0", 9);
	put_f64(b + 16, 2.0);
	put_f64(b + 24, 6.0);
	put_le32(b + 1352, 3468);
	put_le32(b + 1368, 3);
	put_le32(b + 1372, 2);
	put_f64(b + 1376, 312.5);
	put_f64(b + 1384, 250.0);
	for (int k = 0; k < 6; k++) {
		b[3468 + 2 * k] = (unsigned char)(raw[k] & 255);
		b[3469 + 2 * k] = (unsigned char)(raw[k] >> 8);
		b[3480 + k] = (unsigned char)(10 * k);
	}
	test_put_file(test_path("s.nms"), b, sizeof(b));
	g = rc_grid_read(test_path("s.nms"), NULL, &err);
	test_true(g != NULL, "nms synthetic: %s", g ? "" : err.msg);
	if (g != NULL) {
		test_true(g->nx == 3 && g->ny == 2, "nms synthetic: 3 x 2");
		test_rel(g->lx, 3 * 312.5e-9, 1e-15, "nms: lx = nx dx (nm)");
		test_rel(g->ly, 2 * 250e-9, 1e-15, "nms: ly = ny dy (nm)");
		test_rel(g->z[0], 2e-6, 1e-15, "nms: 0 is zmin");
		test_rel(g->z[1], 6e-6, 1e-15, "nms: 65535 is zmax");
		test_rel(g->z[2], (2 + 4 * 32768.0 / 65535) * 1e-6, 1e-15,
		    "nms: z = zmin + v (zmax - zmin) / 65535 (um)");
		test_rel(g->z[5], 2.8e-6, 1e-15, "nms: 13107 is a fifth of the "
		    "range, x fastest");
		test_true(g->valid == NULL && g->periodic == 0 &&
		    strcmp(g->z_unit, "m") == 0, "nms: no missing point, a patch, m");
	}
	rc_grid_free(g);
	test_true(rc_grid_list_channels(test_path("s.nms"), NULL, &info, &nch,
	    &err) == 0 && nch == 2 && strcmp(info[0].title, "Height") == 0 &&
	    strcmp(info[1].title, "Intensity") == 0 &&
	    strcmp(info[1].z_unit, "1") == 0, "nms: channels Height and "
	    "Intensity (unitless)");
	free(info);
	rc_read_opts_init(&o);
	o.channel = 2;
	o.z_unit = "1";
	g = rc_grid_read(test_path("s.nms"), &o, &err);
	test_true(g != NULL && g->z[5] == 50 && g->z[1] == 10,
	    "nms: intensity channel, x fastest: %s", g ? "" : err.msg);
	rc_grid_free(g);
	/* Without the intensity image: the heights alone. */
	test_put_file(test_path("h.nms"), b, 3468 + 12);
	g = rc_grid_read(test_path("h.nms"), NULL, &err);
	test_true(g != NULL && g->nx == 3 && g->z[1] == 6e-6,
	    "nms: heights alone: %s", g ? "" : err.msg);
	rc_grid_free(g);
	truncations("nms synthetic", b, sizeof(b) - 6);
	put_f64(b + 1376, -1);
	test_put_file(test_path("n.nms"), b, sizeof(b));
	g = rc_grid_read(test_path("n.nms"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "spacing") != NULL,
	    "nms: negative spacing refused: %s", g ? "read" : err.msg);
	rc_grid_free(g);
}

/* ---- MountainsMap .mnt, built here: a compound document (CFB, 512-byte
 * sectors) holding a ScopedContents stream in the layout lib/io_mnt.c
 * describes. ---- */

struct bytes {
	unsigned char *p;
	size_t n, cap;
};

static void
put(struct bytes *b, const void *p, size_t n)
{
	if (b->n + n > b->cap) {
		b->cap = 2 * (b->n + n) + 256;
		b->p = realloc(b->p, b->cap);
		if (b->p == NULL)
			abort();
	}
	memcpy(b->p + b->n, p, n);
	b->n += n;
}

static void
put_le(struct bytes *b, uint64_t v, int n)
{
	unsigned char c[8];

	for (int k = 0; k < n; k++)
		c[k] = (unsigned char)(v >> (8 * k));
	put(b, c, (size_t)n);
}

/* A TLV entry: tag and a size filled in by tlv_close. */
static size_t
tlv_open(struct bytes *b, unsigned tag)
{
	size_t at = b->n;

	put_le(b, tag, 2);
	put_le(b, 0, 8);
	return at;
}

static void
tlv_close(struct bytes *b, size_t at)
{
	uint64_t size = b->n - at - 10;

	for (int k = 0; k < 8; k++)
		b->p[at + 2 + k] = (unsigned char)(size >> (8 * k));
}

static void
tlv_u32(struct bytes *b, unsigned tag, uint32_t v)
{
	size_t at = tlv_open(b, tag);

	put_le(b, v, 4);
	tlv_close(b, at);
}

static void
tlv_f64(struct bytes *b, unsigned tag, double v)
{
	size_t at = tlv_open(b, tag);
	uint64_t u;

	memcpy(&u, &v, 8);
	put_le(b, u, 8);
	tlv_close(b, at);
}

/* Text: 0x04, then UTF-16LE of Latin-1 (0xb5 is the micro sign). */
static void
tlv_text(struct bytes *b, unsigned tag, const char *latin1)
{
	size_t at = tlv_open(b, tag);

	put_le(b, 4, 1);
	for (const char *c = latin1; *c; c++)
		put_le(b, (unsigned char)*c, 2);
	tlv_close(b, at);
}

static size_t
tlv_class(struct bytes *b, uint32_t cls)
{
	size_t at = tlv_open(b, 1);

	tlv_u32(b, 1, cls);
	tlv_close(b, at);
	return tlv_open(b, 2);	/* the body, closed by the caller */
}

/* An array object: count elements of esize bytes in two zlib blocks,
 * stored second block first. */
static void
tlv_array(struct bytes *b, unsigned tag, uint32_t cls, const void *v,
    uint32_t count, size_t esize)
{
	size_t at = tlv_open(b, tag), body = tlv_class(b, cls), data;
	uint32_t half = count / 2;

	tlv_u32(b, 1, count);
	data = tlv_open(b, 2);
	put_le(b, (uint64_t)count * esize, 8);
	for (int blk = 1; blk >= 0; blk--) {
		uint32_t off = blk ? half : 0, ne = blk ? count - half : half;
		uLongf clen = compressBound(ne * esize);
		unsigned char *z = malloc(clen);

		compress(z, &clen, (const unsigned char *)v + off * esize,
		    ne * esize);
		put_le(b, off, 8);
		put_le(b, ne, 4);
		put_le(b, clen, 4);
		put(b, z, clen);
		free(z);
	}
	tlv_close(b, data);
	tlv_close(b, body);
	tlv_close(b, at);
}

/* An axis scale: step in unit, display unit, origin. */
static void
tlv_scale(struct bytes *b, double step, const char *unit, const char *dunit,
    double origin)
{
	size_t at = tlv_open(b, 0xffff);

	tlv_f64(b, 1, step);
	tlv_text(b, 2, unit);
	tlv_text(b, 3, dunit);
	tlv_f64(b, 5, origin);
	tlv_close(b, at);
}

static void
tlv_axis(struct bytes *b, unsigned tag, uint32_t n, double step,
    const char *unit)
{
	size_t at = tlv_open(b, tag), ax = tlv_open(b, 0xffff);

	tlv_scale(b, step, unit, unit, 0);
	tlv_u32(b, 1, n);
	tlv_close(b, ax);
	tlv_close(b, at);
}

/* 4 x 3 int32 counts 1000 k - 5000 of 0.0001 nm, origin 50 um, x step
 * 2.5 um, y step 0.5 um, point (1, 2) not measured in the mask. */
static void
make_scoped(struct bytes *sc)
{
	int32_t counts[12];
	unsigned char mask[6 * 5];
	size_t main_, contents, doc, objs, obj, body, sub, subbody, meas, grid, h;

	for (int k = 0; k < 12; k++)
		counts[k] = 1000 * k - 5000;
	memset(mask, 9, sizeof(mask));
	mask[(2 + 1) * 6 + 1 + 1] = 22;
	put_le(sc, 0, 8);	/* the stream's size, not read */
	main_ = tlv_open(sc, 1);
	tlv_text(sc, 0xcb, "DS-0");
	contents = tlv_open(sc, 0x2bd);
	tlv_u32(sc, 1, 1);
	doc = tlv_open(sc, 2);
	objs = tlv_open(sc, 1);
	put_le(sc, 0, 8);	/* the prefix of each object */
	obj = tlv_open(sc, 1);
	body = tlv_class(sc, 9012);
	h = tlv_open(sc, 0xffff);
	tlv_text(sc, 4, "1 : synthetic");
	tlv_close(sc, h);
	sub = tlv_open(sc, 1);
	subbody = tlv_class(sc, 9062);
	meas = tlv_open(sc, 0xffff);
	grid = tlv_open(sc, 0xffff);
	h = tlv_open(sc, 0xffff);
	{
		size_t d = tlv_open(sc, 0xffff);

		tlv_text(sc, 1, "synthetic");
		tlv_close(sc, d);
	}
	tlv_close(sc, h);
	tlv_axis(sc, 1, 4, 2.5, "\xb5m");
	tlv_axis(sc, 2, 3, 0.0005, "mm");
	{
		size_t m = tlv_open(sc, 3), mb = tlv_class(sc, 9056);

		tlv_u32(sc, 1, 4);
		tlv_u32(sc, 2, 3);
		tlv_array(sc, 5, 9048, mask, sizeof(mask), 1);
		tlv_close(sc, mb);
		tlv_close(sc, m);
	}
	tlv_close(sc, grid);
	tlv_array(sc, 1, 9049, counts, 12, 4);
	h = tlv_open(sc, 2);
	tlv_scale(sc, 0.0001, "nm", "\xb5m", 50);
	tlv_close(sc, h);
	tlv_close(sc, meas);
	tlv_close(sc, subbody);
	tlv_close(sc, sub);
	tlv_close(sc, body);
	tlv_close(sc, obj);
	tlv_close(sc, objs);
	tlv_close(sc, doc);
	tlv_close(sc, contents);
	tlv_close(sc, main_);
	/* Past the mini-stream cutoff (4096 bytes): a top-level entry of
	 * padding. */
	h = tlv_open(sc, 2);
	for (int k = 0; k < 4096; k++)
		put_le(sc, 0, 1);
	tlv_close(sc, h);
}

/* The compound document: header, FAT (sector 0), directory (sector 1),
 * the stream from sector 2. */
static void
make_cfb(struct bytes *f, const struct bytes *sc)
{
	size_t nsec = (sc->n + 511) / 512;
	unsigned char hdr[512], fat[512], dir[512];

	memset(hdr, 0, 512);
	memcpy(hdr, "\xd0\xcf\x11\xe0\xa1\xb1\x1a\xe1", 8);
	hdr[0x18] = 0x3e;
	hdr[0x1a] = 3;
	hdr[0x1c] = 0xfe;
	hdr[0x1d] = 0xff;
	hdr[0x1e] = 9;
	hdr[0x20] = 6;
	put_le32(hdr + 0x2c, 1);
	put_le32(hdr + 0x30, 1);
	put_le32(hdr + 0x38, 4096);
	put_le32(hdr + 0x3c, 0xfffffffeu);
	put_le32(hdr + 0x44, 0xfffffffeu);
	memset(hdr + 0x4c, 0xff, 512 - 0x4c);
	put_le32(hdr + 0x4c, 0);
	memset(fat, 0xff, 512);
	put_le32(fat, 0xfffffffdu);
	put_le32(fat + 4, 0xfffffffeu);
	for (size_t k = 0; k < nsec; k++)
		put_le32(fat + 4 * (2 + k), k + 1 < nsec ? (uint32_t)(3 + k) :
		    0xfffffffeu);
	memset(dir, 0, 512);
	for (int k = 0; k < 10; k++)
		dir[2 * k] = (unsigned char)"Root Entry"[k];
	dir[64] = 22;
	dir[66] = 5;
	put_le32(dir + 116, 0xfffffffeu);
	for (int k = 0; k < 14; k++)
		dir[128 + 2 * k] = (unsigned char)"ScopedContents"[k];
	dir[128 + 64] = 30;
	dir[128 + 66] = 2;
	put_le32(dir + 128 + 116, 2);
	put_le32(dir + 128 + 120, (uint32_t)sc->n);
	put(f, hdr, 512);
	put(f, fat, 512);
	put(f, dir, 512);
	put(f, sc->p, sc->n);
	while (f->n % 512 != 0)
		put_le(f, 0, 1);
}

static void
test_mnt_synthetic(void)
{
	struct bytes sc = { NULL, 0, 0 }, f = { NULL, 0, 0 };
	rc_channel_info *info = NULL;
	size_t nch = 0;
	int vals = 1;
	rc_err err;
	rc_grid *g;

	make_scoped(&sc);
	make_cfb(&f, &sc);
	test_put_file(test_path("s.mnt"), f.p, f.n);
	g = rc_grid_read(test_path("s.mnt"), NULL, &err);
	test_true(g != NULL, "mnt synthetic: %s", g ? "" : err.msg);
	if (g != NULL) {
		test_true(g->nx == 4 && g->ny == 3, "mnt: 4 x 3");
		test_rel(g->lx, 4 * 2.5e-6, 1e-15, "mnt: lx = nx step (um)");
		test_rel(g->ly, 3 * 0.5e-6, 1e-15, "mnt: ly = ny step (mm)");
		for (int k = 0; k < 12; k++)
			if (k != 9 && fabs(g->z[k] - ((1000.0 * k - 5000) * 1e-13 +
			    50e-6)) > 1e-15 * 50e-6)
				vals = 0;
		test_true(vals, "mnt: z = count step (nm) + origin (um), x fastest, "
		    "blocks in their offsets' order");
		test_true(g->valid != NULL && !g->valid[9] && isnan(g->z[9]) &&
		    g->valid[8] && g->valid[10], "mnt: the mask's 22 at (1, 2) is "
		    "missing, its border is not the grid");
		test_true(strcmp(g->unit, "m") == 0 && strcmp(g->z_unit, "m") == 0 &&
		    g->periodic == 0, "mnt: metres, a patch");
	}
	rc_grid_free(g);
	test_true(rc_grid_list_channels(test_path("s.mnt"), NULL, &info, &nch,
	    &err) == 0 && nch == 1 && strcmp(info[0].title, "synthetic") == 0 &&
	    info[0].has_mask, "mnt: one channel, titled by its name, with a "
	    "mask");
	free(info);
	truncations("mnt synthetic", f.p, f.n);
	/* A compound document that is no MountainsMap document. */
	memcpy(f.p + 1024 + 128, "X", 1);	/* the stream's name in the directory */
	test_put_file(test_path("x.mnt"), f.p, f.n);
	g = rc_grid_read(test_path("x.mnt"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "compound document") != NULL &&
	    strstr(err.msg, "ScopedContents") != NULL,
	    "other OLE2 refused, saying why: %s", g ? "read" : err.msg);
	rc_grid_free(g);
	free(sc.p);
	free(f.p);
}

/* ---- Dektak .OPDx maps, built here in the layout of lib/io_opdx.c ---- */

static void
opdx_name(struct bytes *b, const char *s)
{
	put_le(b, strlen(s), 4);
	put(b, s, strlen(s));
}

/* An item's name and type, then a 4-byte varlen to be filled in. */
static size_t
opdx_open(struct bytes *b, const char *name, int type)
{
	size_t at;

	opdx_name(b, name);
	put_le(b, (unsigned)type, 1);
	put_le(b, 4, 1);
	at = b->n;
	put_le(b, 0, 4);
	return at;
}

static void
opdx_close(struct bytes *b, size_t at)
{
	uint32_t L = (uint32_t)(b->n - at - 4);

	for (int k = 0; k < 4; k++)
		b->p[at + k] = (unsigned char)(L >> (8 * k));
}

static void
opdx_end(struct bytes *b)
{
	put_le(b, 0, 4);	/* the empty name */
	put_le(b, 0x7f, 1);
	put_le(b, 0xffff, 2);
}

static void
opdx_quantity(struct bytes *b, const char *name, double v, const char *sym)
{
	size_t at = opdx_open(b, name, 0x13);
	uint64_t u;

	memcpy(&u, &v, 8);
	put_le(b, u, 8);
	opdx_name(b, "Unit");
	opdx_name(b, sym);
	opdx_close(b, at);
}

static void
opdx_u64(struct bytes *b, const char *name, uint64_t v)
{
	opdx_name(b, name);
	put_le(b, 0x0b, 1);
	put_le(b, v, 8);
}

/* 3 x 2 float32 k (NaN at k = 4) times 0.5 nm; the extents 2 um and
 * 1 um are first to last point.  rows, cols: the matrix's own size. */
static void
make_opdx_map(struct bytes *b, uint32_t rows, uint32_t cols)
{
	size_t d2, raw, m;

	put(b, "VCA DATA\x01\x00\x00\x55", 12);
	d2 = opdx_open(b, "2D_Data", 0x7d);
	raw = opdx_open(b, "Raw", 0x47);
	opdx_name(b, "Matrix");
	put_le(b, 0x00, 1);
	opdx_name(b, "Matrix<float>");
	put_le(b, 0, 4);
	opdx_name(b, "Heights");
	put_le(b, 4, 1);
	m = b->n;
	put_le(b, 0, 4);
	put_le(b, rows, 4);
	put_le(b, cols, 4);
	for (int k = 0; k < 6; k++) {
		float f = k == 4 ? NAN : (float)k;
		uint32_t u;

		memcpy(&u, &f, 4);
		put_le(b, u, 4);
	}
	opdx_close(b, m);
	opdx_u64(b, "Dimension1Points", 2);
	opdx_u64(b, "Dimension2Points", 3);
	opdx_quantity(b, "Dimension1Extent", 1, "\xc2\xb5m");
	opdx_quantity(b, "Dimension2Extent", 2, "\xc2\xb5m");
	opdx_quantity(b, "DataScale", 0.5, "nm");
	opdx_end(b);
	opdx_close(b, raw);
	opdx_end(b);
	opdx_close(b, d2);
	opdx_end(b);
}

static void
test_opdx_map(void)
{
	struct bytes b = { NULL, 0, 0 };
	int vals = 1;
	rc_err err;
	rc_grid *g;

	make_opdx_map(&b, 2, 3);
	test_put_file(test_path("m.opdx"), b.p, b.n);
	g = rc_grid_read(test_path("m.opdx"), NULL, &err);
	test_true(g != NULL, "opdx map: %s", g ? "" : err.msg);
	if (g != NULL) {
		test_true(g->nx == 3 && g->ny == 2, "opdx map: 3 x 2");
		test_rel(g->lx, 3e-6, 1e-15, "opdx map: lx = extent n / (n - 1)");
		test_rel(g->ly, 2e-6, 1e-15, "opdx map: ly = extent n / (n - 1)");
		for (int k = 0; k < 6; k++)
			if (k != 4 && fabs(g->z[k] - 0.5e-9 * k) > 1e-24)
				vals = 0;
		test_true(vals, "opdx map: z = value DataScale, x fastest");
		test_true(g->valid != NULL && !g->valid[4] && isnan(g->z[4]),
		    "opdx map: NaN is a missing point");
	}
	rc_grid_free(g);
	truncations("opdx map", b.p, b.n - 2);
	b.n = 0;
	make_opdx_map(&b, 3, 2);
	test_put_file(test_path("w.opdx"), b.p, b.n);
	g = rc_grid_read(test_path("w.opdx"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "the header says") != NULL,
	    "opdx map: a matrix of another shape refused: %s",
	    g ? "read" : err.msg);
	rc_grid_free(g);
	free(b.p);
}

int
main(void)
{
	setenv("RC_GWYDDION", "", 1);	/* these tests are of our readers */
	test_tmd_file();
	test_tmd_synthetic();
	test_opdx_file();
	test_nms_synthetic();
	test_mnt_synthetic();
	test_opdx_map();
	return test_summary();
}
