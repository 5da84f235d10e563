/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_zipped.c - zip containers other than x3p: Excel workbooks (a
 * table on the first sheet, Mitutoyo SurfTest's export, read as
 * SurfaceTopography's tests expect: tests/data/st_text.README) and
 * contact.engineering containers (meta.yml and measurements), with the
 * bound on what a zip may unpack to.  The workbooks and containers but
 * the Mitutoyo ones are written here with libzip; the expected grids
 * follow from their numbers. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zip.h>
#include <zlib.h>

#include "io.h"
#include "units.h"
#include "testlib.h"

/* A zip at path of n entries: names[k] holding texts[k] (lens[k] bytes,
 * or strlen when lens is NULL or lens[k] is 0). */
static void
put_zip(const char *path, size_t n, const char *const *names,
    const char *const *texts, const size_t *lens)
{
	int e;
	zip_t *z = zip_open(path, ZIP_CREATE | ZIP_TRUNCATE, &e);

	for (size_t k = 0; z != NULL && k < n; k++) {
		size_t len = lens && lens[k] ? lens[k] : strlen(texts[k]);
		zip_source_t *src = zip_source_buffer(z, texts[k], len, 0);

		zip_file_add(z, names[k], src, ZIP_FL_OVERWRITE);
	}
	if (z == NULL || zip_close(z) != 0) {
		fprintf(stderr, "cannot write %s\n", path);
		abort();
	}
}

static double
rms_about_mean(const rc_grid *g)
{
	double s = 0, s2 = 0;
	size_t n = rc_grid_size(g);

	for (size_t k = 0; k < n; k++)
		s += g->z[k];
	for (size_t k = 0; k < n; k++)
		s2 += (g->z[k] - s / (double)n) * (g->z[k] - s / (double)n);
	return sqrt(s2 / (double)n);
}

#define WB_NS "xmlns=\"http://schemas.openxmlformats.org/spreadsheetml/" \
    "2006/main\" xmlns:r=\"http://schemas.openxmlformats.org/" \
    "officeDocument/2006/relationships\""
static const char wb[] = "<?xml version=\"1.0\"?><workbook " WB_NS
    "><sheets><sheet name=\"Heights\" sheetId=\"1\" r:id=\"rId7\"/>"
    "</sheets></workbook>";
static const char rels[] = "<?xml version=\"1.0\"?><Relationships xmlns="
    "\"http://schemas.openxmlformats.org/package/2006/relationships\">"
    "<Relationship Id=\"rId7\" Type=\"worksheet\" "
    "Target=\"worksheets/data.xml\"/></Relationships>";
/* "z in um" as rich text in two runs */
static const char sst[] = "<?xml version=\"1.0\"?><sst " WB_NS "><si><t>"
    "x in mm</t></si><si><r><t>z in </t></r><r><t>um</t></r></si></sst>";

/* A workbook whose first sheet is a table with a line of names: x in mm
 * (0, 0.5, 1, 1.5), z in um (1, 2, 4 as an inline string, 8), a shared
 * string in two runs, the sheet's part named by the relationships. */
static void
workbook_table(void)
{
	static const char sheet[] = "<?xml version=\"1.0\"?><worksheet " WB_NS
	    "><sheetData><row r=\"1\"><c r=\"A1\" t=\"s\"><v>0</v></c>"
	    "<c r=\"B1\" t=\"s\"><v>1</v></c></row>"
	    "<row r=\"2\"><c r=\"A2\"><v>0</v></c><c r=\"B2\"><v>1</v></c></row>"
	    "<row r=\"3\"><c r=\"A3\"><v>0.5</v></c><c r=\"B3\"><v>2</v></c></row>"
	    "<row r=\"4\"><c r=\"A4\"><v>1</v></c><c r=\"B4\" t=\"inlineStr\">"
	    "<is><t>4</t></is></c></row>"
	    "<row r=\"5\"><c r=\"A5\"><v>1.5</v></c><c r=\"B5\"><v>8</v></c></row>"
	    "</sheetData></worksheet>";
	const char *names[] = { "xl/workbook.xml", "xl/_rels/workbook.xml.rels",
	    "xl/sharedStrings.xml", "xl/worksheets/data.xml" };
	const char *texts[] = { wb, rels, sst, sheet };
	const char *path = test_path("table.xlsx");
	rc_channel_info *info = NULL;
	size_t n = 0;
	rc_err err;
	rc_grid *g;

	put_zip(path, 4, names, texts, NULL);
	g = rc_grid_read(path, NULL, &err);
	test_true(g != NULL, "a workbook's table is read (%s)", g ? "" : err.msg);
	if (g != NULL) {
		test_int((long long)g->nx, 4, "table: nx");
		test_int((long long)g->ny, 1, "table: ny");
		test_rel(g->lx, 2.0, 1e-15, "table: 4 steps of 0.5 mm");
		test_true(strcmp(g->unit, "mm") == 0 && strcmp(g->z_unit, "um") == 0,
		    "table: x in mm, z in um (from the names)");
		test_true(g->z[0] == 1 && g->z[1] == 2 && g->z[2] == 4 &&
		    g->z[3] == 8, "table: the heights, the inline string's too");
	}
	rc_grid_free(g);
	test_true(rc_grid_list_channels(path, NULL, &info, &n, &err) == 0 &&
	    n == 1 && strcmp(info[0].title, "Heights") == 0,
	    "the channel is titled by the sheet");
	free(info);
}

/* A sheet that unpacks past the bound of 64 MiB (65 MiB of blanks, which
 * deflate packs into some 64 KiB) is refused, not read. */
static void
workbook_bomb(void)
{
	size_t len = (size_t)65 << 20;
	char *sheet = malloc(len + 1);
	const char *names[] = { "xl/workbook.xml", "xl/_rels/workbook.xml.rels",
	    "xl/worksheets/data.xml" };
	const char *texts[] = { wb, rels, sheet };
	size_t lens[] = { 0, 0, len };
	const char *path = test_path("bomb.xlsx");
	rc_err err;
	rc_grid *g;

	memset(sheet, ' ', len);
	memcpy(sheet, "<worksheet>", 11);
	sheet[len] = '\0';
	put_zip(path, 3, names, texts, lens);
	free(sheet);
	g = rc_grid_read(path, NULL, &err);
	test_true(g == NULL && strstr(err.msg, "unpacks to over") != NULL,
	    "a sheet of 65 MiB: refused ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
}

/* SurfaceTopography's Mitutoyo mocks (test/io/test_mitutoyo.py): 960
 * points of step 0.5 um, 480 um long, heights in um of rms
 * 0.16866328079293708 (about their mean, as its rms_height_from_profile);
 * the non-uniform mock moves point 100 from x = 0.05 to 0.0501 mm. */
static void
mitutoyo(void)
{
	rc_read_opts o;
	rc_err err;
	rc_grid *u = rc_grid_read(test_data_path("st_mitutoyo_mock.xlsx"), NULL, &err);
	rc_grid *g;
	double zmax = 0, t;
	int others = 1;

	test_true(u != NULL, "Mitutoyo mock read (%s)", u ? "" : err.msg);
	if (u == NULL)
		return;
	test_int((long long)u->nx, 960, "Mitutoyo: 960 points");
	test_int((long long)u->ny, 1, "Mitutoyo: a profile");
	test_rel(rc_unit_convert(u->lx, u->unit, "um"), 480, 1e-12,
	    "Mitutoyo: 480 um (x in %s)", u->unit);
	test_true(strcmp(u->unit, "mm") == 0 && strcmp(u->z_unit, "um") == 0,
	    "Mitutoyo: x in mm (the cut-off's unit), heights in um (Ra's)");
	test_rel(rms_about_mean(u), 0.16866328079293708, 1e-12,
	    "Mitutoyo: rms of the heights (SurfaceTopography's)");
	g = rc_grid_read(test_data_path("st_mitutoyo_nonuniform_mock.xlsx"), NULL,
	    &err);
	test_true(g == NULL && strstr(err.msg, "--uniform") != NULL &&
	    strstr(err.msg, "Mitutoyo") != NULL,
	    "non-uniform mock without --uniform: refused naming it ('%s')",
	    g ? "read" : err.msg);
	rc_grid_free(g);
	rc_read_opts_init(&o);
	o.uniform = 1;
	g = rc_grid_read(test_data_path("st_mitutoyo_nonuniform_mock.xlsx"), &o, &err);
	test_true(g != NULL && g->nx == 960 && g->lx == u->lx,
	    "non-uniform mock, --uniform: 960 points over 0.48 mm (%s)",
	    g ? "" : err.msg);
	if (g != NULL && g->nx == 960) {
		/* the same heights as the uniform mock at the same x but point
		 * 100 (index 99), now between x 0.0495 and 0.0501 */
		for (size_t k = 0; k < 960; k++)
			zmax = fmax(zmax, fabs(u->z[k]));
		for (size_t k = 0; k < 960; k++)
			if (k != 99 && fabs(g->z[k] - u->z[k]) > 1e-12 * zmax)
				others = 0;
		test_true(others, "resampled: the uniform mock's heights but at "
		    "index 99");
		t = (0.05 - 0.0495) / (0.0501 - 0.0495);
		test_abs(g->z[99], u->z[98] + t * (u->z[99] - u->z[98]),
		    1e-12 * zmax, "resampled: index 99 interpolated between "
		    "x 0.0495 and 0.0501");
	}
	rc_grid_free(g);
	rc_grid_free(u);
}

/* A contact.engineering container, laid out as container-2.zip of
 * SurfaceTopography's examples (sizes as !!python/tuple), of three
 * measurements:
 *   a.txt  x-z without units, uniform step 1 (lx 4): meta.yml gives nm,
 *          size 4, height_scale 2 (raw numbers: applied), periodic
 *   b.txt  x-z at x 0 1 2 2.5 3 4: meta.yml gives um, size 4 (the x span,
 *          SurfaceTopography's size of a non-uniform line scan)
 *   c.surf 2 x 2 in m, 1 um square: meta.yml gives nm and 1000 x 1000
 *          (agreeing), height_scale 3 (the file's unit: not applied) */
static const char meta[] =
    "creation_time: '2021-06-21 15:06:49'\n"
    "surfaces:\n"
    "- category: exp\n"
    "  topographies:\n"
    "  - name: a\n    datafile:\n      original: a.txt\n"
    "    data_source: 0\n    detrend_mode: height\n    height_scale: 2.0\n"
    "    is_periodic: true\n    size: !!python/tuple\n    - 4.0\n"
    "    unit: nm\n"
    "  - name: b\n    datafile: {original: b.txt}\n    size: [4.0]\n"
    "    unit: \"\\xB5m\"\n"
    "  - name: c\n    datafile:\n      original: c.surf\n"
    "    height_scale: 3.0\n    size: !!python/tuple\n    - 1000.0\n"
    "    - 1000.0\n    unit: nm\n"
    "versions:\n  topobank: 0.13.0\n";

static int
put_container(const char *path, const char *yml, const char *c_name)
{
	const char *a = "0 1\n1 2\n2 4\n3 8\n", *b = "0 0\n1 0\n2 0\n2.5 1\n"
	    "3 0\n4 0\n";
	const char *names[] = { "meta.yml", "a.txt", "b.txt", c_name };
	const char *texts[4] = { yml, a, b, NULL };
	size_t lens[4] = { 0 };
	rc_err err;
	rc_grid *c = rc_grid_new(2, 2, 1e-6, 1e-6, &err);
	char *surf = NULL;
	size_t len = 0;
	FILE *fp = open_memstream(&surf, &len);

	strcpy(c->unit, "m");
	strcpy(c->z_unit, "m");
	for (int k = 0; k < 4; k++)
		c->z[k] = 1e-9 * k;
	c->periodic = 0;
	if (rc_grid_write_stream(c, fp, RC_FMT_SURF, &err) != 0)
		abort();
	fclose(fp);
	texts[3] = surf;
	lens[3] = len;
	put_zip(path, 4, names, texts, lens);
	free(surf);
	rc_grid_free(c);
	return 0;
}

static void
container(void)
{
	const char *path = test_path("ce.zip");
	rc_channel_info *info = NULL;
	rc_read_opts o;
	size_t n = 0;
	rc_err err;
	rc_grid *g;
	char bad[sizeof(meta) + 16], *p;

	put_container(path, meta, "c.surf");
	rc_read_opts_init(&o);
	/* b is not uniform: the container is refused naming the member and
	 * the option */
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "'b' (b.txt)") != NULL &&
	    strstr(err.msg, "--uniform") != NULL,
	    "a non-uniform member: refused naming it and --uniform ('%s')",
	    g ? "read" : err.msg);
	rc_grid_free(g);
	o.uniform = 1;
	test_true(rc_grid_list_channels(path, &o, &info, &n, &err) == 0 &&
	    n == 3, "three measurements, three channels (%s)",
	    n == 3 ? "" : err.msg);
	if (n == 3) {
		test_true(strcmp(info[0].title, "a") == 0 &&
		    strcmp(info[1].title, "b") == 0 &&
		    strcmp(info[2].title, "c") == 0, "titled by their names");
		test_true(info[0].nx == 4 && info[0].lx == 4 &&
		    strcmp(info[0].unit, "nm") == 0 &&
		    strcmp(info[0].z_unit, "nm") == 0,
		    "a: 4 points over 4 nm, heights in nm (meta.yml's unit)");
		/* 6 points, x span 4: step 0.8, lx 4.8 */
		test_true(info[1].nx == 6 && fabs(info[1].lx - 4.8) < 1e-12 &&
		    strcmp(info[1].unit, "um") == 0,
		    "b: resampled to 6 points of 0.8 um (lx %.17g %s)", info[1].lx,
		    info[1].unit);
		test_true(info[2].nx == 2 && info[2].ny == 2 && info[2].lx == 1e-6 &&
		    strcmp(info[2].unit, "m") == 0, "c: its own 1 um in m");
	}
	free(info);
	/* the channel chosen by name, its heights */
	o.channel_name = "a";
	g = rc_grid_read(path, &o, &err);
	test_true(g && g->z[0] == 2 && g->z[1] == 4 && g->z[2] == 8 &&
	    g->z[3] == 16 && g->periodic, "a: heights times height_scale 2, "
	    "periodic (%s)", g ? "" : err.msg);
	test_true(g && rc_grid_meta_get(g, "detrend_mode") != NULL,
	    "a: detrend_mode kept as metadata");
	rc_grid_free(g);
	o.channel_name = NULL;
	o.channel = 3;
	g = rc_grid_read(path, &o, &err);
	test_true(g && g->z[3] == 1e-9 * 3 && !g->periodic &&
	    rc_grid_meta_get(g, "height_scale") != NULL,
	    "c: heights with a unit are not scaled again (%s)", g ? "" : err.msg);
	rc_grid_free(g);
	o.channel = 0;
	o.channel_name = "d";
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "no channel titled") != NULL,
	    "a name the container lacks: refused");
	rc_grid_free(g);
	o.channel_name = NULL;
	/* a chosen channel reads only its member: c without --uniform,
	 * although b needs it; b itself still asks for it */
	o.uniform = 0;
	o.channel = 3;
	g = rc_grid_read(path, &o, &err);
	test_true(g && g->nx == 2 && g->z[3] == 1e-9 * 3,
	    "channel 3 read without the option its neighbour needs (%s)",
	    g ? "" : err.msg);
	rc_grid_free(g);
	o.channel = 0;
	o.channel_name = "C";
	g = rc_grid_read(path, &o, &err);
	test_true(g && g->nx == 2, "channel 'C' (case aside) the same (%s)",
	    g ? "" : err.msg);
	rc_grid_free(g);
	o.channel_name = NULL;
	o.channel = 2;
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "--uniform") != NULL,
	    "channel 2 alone still names --uniform ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
	test_true(rc_grid_list_channels(path, &o, &info, &n, &err) != 0,
	    "a listing reads every member, --channel or not");
	free(info);
	info = NULL;
	/* read as it is (rc_read_opts.nonuniform): b keeps its positions,
	 * its size the x span in meta.yml's unit, and the container reads
	 * without --uniform */
	o.channel = 0;
	o.nonuniform = 1;
	test_true(rc_grid_list_channels(path, &o, &info, &n, &err) == 0 &&
	    n == 3 && info[1].nx == 6 && info[1].lx == 4 &&
	    strcmp(info[1].unit, "um") == 0, "non-uniform b listed as 6 "
	    "points over 4 um (%s)", n == 3 ? "" : err.msg);
	free(info);
	info = NULL;
	g = rc_grid_read(path, &o, &err);
	test_true(g != NULL && g->x == NULL && g->nx == 4,
	    "the container reads without --uniform: its first channel, a (%s)",
	    g ? "" : err.msg);
	rc_grid_free(g);
	o.channel = 2;
	g = rc_grid_read(path, &o, &err);
	test_true(g != NULL && g->x != NULL && g->nx == 6 && g->x[3] == 2.5 &&
	    g->z[3] == 1 && g->lx == 4, "b: positions 0 1 2 2.5 3 4, height 1 "
	    "at 2.5 (%s)", g ? "" : err.msg);
	rc_grid_free(g);
	/* meta.yml's size of b, a file without units, wins: 8 for its
	 * span 4 doubles its positions */
	snprintf(bad, sizeof(bad), "%s", meta);
	p = strstr(bad, "size: [4.0]");
	memcpy(p, "size: [8.0]", 11);
	put_container(path, bad, "c.surf");
	g = rc_grid_read(path, &o, &err);
	test_true(g != NULL && g->x != NULL && g->lx == 8 && g->x[3] == 5 &&
	    g->x[5] == 8 && g->ly == 8.0 / 5, "b sized 8 by meta.yml: "
	    "positions doubled, mean step 8/5 (%s)", g ? "" : err.msg);
	rc_grid_free(g);
	put_container(path, meta, "c.surf");
	o.channel = 0;
	o.nonuniform = 0;
	o.uniform = 1;
	/* c's size in meta.yml disagreeing with the file's: refused */
	snprintf(bad, sizeof(bad), "%s", meta);
	p = strstr(bad, "- 1000.0\n    - 1000.0");
	memcpy(p, "- 2000.0", 8);
	put_container(path, bad, "c.surf");
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "differ") != NULL,
	    "sizes that disagree: refused ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
	/* a member meta.yml names but the zip lacks */
	put_container(path, meta, "d.surf");
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "'c' (c.surf): zip: no entry") != NULL,
	    "a missing member: refused ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
	/* meta.yml that is not YAML, and one without topographies */
	put_container(path, "surfaces: [\n", "c.surf");
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "not YAML") != NULL,
	    "broken meta.yml: refused ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
	put_container(path, "datasets: []\n", "c.surf");
	g = rc_grid_read(path, &o, &err);
	test_true(g == NULL && strstr(err.msg, "no topographies") != NULL,
	    "meta.yml without topographies: refused ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
}

/* A container at path: meta.yml holding yml, and member holding the bytes
 * of the file at file. */
static void
put_zip_of_file(const char *path, const char *yml, const char *member,
    const char *file)
{
	const char *names[2] = { "meta.yml", member };
	const char *texts[2] = { yml, NULL };
	size_t lens[2] = { 0 };
	FILE *fp = fopen(file, "rb");
	long n;
	char *buf;

	if (fp == NULL || fseek(fp, 0, SEEK_END) != 0 || (n = ftell(fp)) <= 0)
		abort();
	rewind(fp);
	if ((buf = malloc((size_t)n)) == NULL ||
	    fread(buf, 1, (size_t)n, fp) != (size_t)n)
		abort();
	fclose(fp);
	texts[1] = buf;
	lens[1] = (size_t)n;
	put_zip(path, 2, names, texts, lens);
	free(buf);
}

/* A container inside a container is refused, not read in turn. */
static void
nested(void)
{
	const char *inner = test_path("inner.zip"), *outer = test_path("outer.zip");
	static const char yml[] = "surfaces:\n- topographies:\n  - name: in\n"
	    "    datafile: {original: inner.zip}\n";
	rc_err err;
	rc_grid *g;

	put_container(inner, meta, "c.surf");
	put_zip_of_file(outer, yml, "inner.zip", inner);
	g = rc_grid_read(outer, NULL, &err);
	test_true(g == NULL && strstr(err.msg, "inside another") != NULL,
	    "a container in a container: refused ('%s')", g ? "read" : err.msg);
	rc_grid_free(g);
}

/* A member that is gzip-compressed is read through one gzip layer (it
 * was refused as "gzip inside gzip"); gzip inside that stays refused. */
static void
gzip_member(void)
{
	const char *path = test_path("gz.zip"), *gz = test_path("m.txt.gz");
	static const char yml[] = "surfaces:\n- topographies:\n  - name: m\n"
	    "    datafile: {original: m.txt.gz}\n    unit: nm\n";
	rc_err err;
	rc_grid *g;
	gzFile z;

	for (int layers = 1; layers <= 2; layers++) {
		z = gzopen(gz, "wb");
		if (layers == 1)
			gzputs(z, "0 1\n1 2\n2 4\n3 8\n");
		else {
			/* a gzip file as the content of a gzip file */
			static const unsigned char inner[] = { 0x1f, 0x8b, 8, 0, 0,
			    0, 0, 0, 0, 3, 3, 0, 0, 0, 0, 0, 0, 0, 0, 0 };

			gzwrite(z, inner, sizeof(inner));
		}
		gzclose(z);
		put_zip_of_file(path, yml, "m.txt.gz", gz);
		g = rc_grid_read(path, NULL, &err);
		if (layers == 1)
			test_true(g != NULL && g->nx == 4 && g->z[3] == 8 &&
			    strcmp(g->unit, "nm") == 0, "a gzip-compressed member: "
			    "read (%s)", g ? "" : err.msg);
		else
			test_true(g == NULL && strstr(err.msg, "gzip inside gzip"),
			    "gzip inside a gzip member: refused ('%s')",
			    g ? "read" : err.msg);
		rc_grid_free(g);
	}
}

/* A gzip member charged what it decodes to, not its compressed length:
 * a little table, then 1025 gzip members of 1 MiB of blank lines each
 * (some 1 KiB each: gzip allows concatenation), decode to over the
 * container's bound of 1 GiB and are refused. */
static void
gzip_member_bomb(void)
{
	const char *path = test_path("gzbomb.zip");
	static const char yml[] = "surfaces:\n- topographies:\n  - name: m\n"
	    "    datafile: {original: m.txt.gz}\n";
	static const char table[] = "0 1\n1 2\n2 4\n3 8\n";
	const char *names[] = { "meta.yml", "m.txt.gz" };
	const char *texts[2] = { yml, NULL };
	size_t lens[2] = { 0 }, blank = (size_t)1 << 20, copies = 1025, cap;
	size_t nt, nb;
	unsigned char *lines = malloc(blank), *t, *one, *all;
	z_stream z;
	rc_err err;
	rc_grid *g;

	memset(lines, '\n', blank);
	cap = deflateBound(&(z_stream){ 0 }, blank) + 64;
	t = malloc(cap);
	one = malloc(cap);
	for (int k = 0; k < 2; k++) {
		memset(&z, 0, sizeof(z));
		deflateInit2(&z, 9, Z_DEFLATED, 16 + MAX_WBITS, 8,
		    Z_DEFAULT_STRATEGY);
		z.next_in = k == 0 ? (unsigned char *)table : lines;
		z.avail_in = (uInt)(k == 0 ? strlen(table) : blank);
		z.next_out = k == 0 ? t : one;
		z.avail_out = (uInt)cap;
		if (deflate(&z, Z_FINISH) != Z_STREAM_END)
			abort();
		*(k == 0 ? &nt : &nb) = cap - z.avail_out;
		deflateEnd(&z);
	}
	all = malloc(nt + copies * nb);
	memcpy(all, t, nt);
	for (size_t k = 0; k < copies; k++)
		memcpy(all + nt + k * nb, one, nb);
	texts[1] = (const char *)all;
	lens[1] = nt + copies * nb;
	put_zip(path, 2, names, texts, lens);
	g = rc_grid_read(path, NULL, &err);
	test_true(g == NULL && strstr(err.msg, "unpack to over") != NULL,
	    "a gzip member of %zu bytes decoding to over 1 GiB: refused ('%s')",
	    lens[1], g ? "read" : err.msg);
	rc_grid_free(g);
	/* the table with 5 of them (5 MiB) is read */
	lens[1] = nt + 5 * nb;
	put_zip(path, 2, names, texts, lens);
	g = rc_grid_read(path, NULL, &err);
	test_true(g != NULL && g->nx == 4 && g->z[3] == 8, "the same member "
	    "decoding to 5 MiB: read (%s)", g ? "" : err.msg);
	rc_grid_free(g);
	free(all);
	free(one);
	free(t);
	free(lines);
}

int
main(void)
{
	workbook_table();
	workbook_bomb();
	mitutoyo();
	container();
	nested();
	gzip_member();
	gzip_member_bomb();
	return test_summary();
}
