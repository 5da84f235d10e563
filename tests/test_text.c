/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_text.c - the text exports people have: CSV with a line of column
 * names and units, an index column, Dektak's CSV (coordinates rounded to
 * one decimal), HFM's validity column, SurfaceTopography's "h= w="
 * matrix, Gwyddion's German export with decimal commas, single-column
 * profiles, UTF-16 and gzip input, and the refusals of text that is not
 * a height file.  Each file is written here by hand; the expected grid
 * follows from its numbers (sizes, steps, units exactly, values to the
 * last bit where the text holds them exactly). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#include "io.h"
#include "testlib.h"

/* The grid the bytes p[0..n) read to (NULL and the message in err). */
static rc_grid *
read_mem(const void *p, size_t n, const rc_read_opts *o, rc_err *err)
{
	const char *path = test_path("in");

	test_put_file(path, p, n);
	return rc_grid_read(path, o, err);
}

/* The bytes of the file at path (malloc'ed), their number in *n. */
static unsigned char *
slurp(const char *path, long *n)
{
	FILE *fp = fopen(path, "rb");
	unsigned char *buf;

	fseek(fp, 0, SEEK_END);
	*n = ftell(fp);
	rewind(fp);
	buf = malloc((size_t)*n);
	test_true(fread(buf, 1, (size_t)*n, fp) == (size_t)*n, "read %s", path);
	fclose(fp);
	return buf;
}

static rc_grid *
read_str(const char *s, rc_err *err)
{
	return read_mem(s, strlen(s), NULL, err);
}

/* A read that must fail with a message containing want. */
static void
refused(const char *what, const char *text, const char *want)
{
	rc_err err;
	rc_grid *g = read_str(text, &err);

	test_true(g == NULL, "%s: refused", what);
	if (g == NULL)
		test_true(strstr(err.msg, want) != NULL &&
		    strstr(err.msg, "is not a number") == NULL,
		    "%s: message '%s' says '%s'", what, err.msg, want);
	rc_grid_free(g);
}

/* nx x ny, lx, ly (relative 1e-12: a step times a count), units. */
static void
shape(const rc_grid *g, const char *what, size_t nx, size_t ny, double lx,
    double ly, const char *unit, const char *z_unit)
{
	if (g == NULL) {
		test_true(0, "%s: read", what);
		return;
	}
	test_int((long long)g->nx, (long long)nx, "%s: nx", what);
	test_int((long long)g->ny, (long long)ny, "%s: ny", what);
	test_rel(g->lx, lx, 1e-12, "%s: lx", what);
	test_rel(g->ly, ly, 1e-12, "%s: ly", what);
	test_true(strcmp(g->unit, unit) == 0, "%s: unit '%s', want '%s'", what,
	    g->unit, unit);
	test_true(strcmp(g->z_unit, z_unit) == 0, "%s: z unit '%s', want '%s'",
	    what, g->z_unit, z_unit);
}

static const char csv[] =
    "x in \xc2\xb5m,z in \xc2\xb5m\n0.0000,1\n0.5000,2\n1.0000,3\n1.5000,5\n";

static void
csv_names(void)
{
	rc_err err;
	rc_grid *g = read_str(csv, &err);

	shape(g, "csv names", 4, 1, 2.0, 0.5, "um", "um");
	if (g != NULL) {
		test_true(g->z[0] == 1 && g->z[3] == 5, "csv values");
		test_true(!g->periodic, "csv: a measurement, not periodic");
	}
	rc_grid_free(g);
	/* "X_(microns),y1": the unit inside a name, none for the heights */
	g = read_str("X_(microns),y1\n0.0386,2\n0.0772,3\n0.1158,4\n"
	    "0.1544,5\n", &err);
	shape(g, "csv X_(microns)", 4, 1, 4 * 0.0386, 0.0386, "um", "");
	rc_grid_free(g);
	/* an index column beside x and z, CRLF */
	g = read_str("index,x in mm,y in mm\r\n0,10.0,1\r\n1,10.5,2\r\n"
	    "2,11.0,3\r\n", &err);
	shape(g, "csv index", 3, 1, 1.5, 0.5, "mm", "mm");
	if (g != NULL)
		test_true(g->z[0] == 1 && g->z[2] == 3, "csv index: heights");
	rc_grid_free(g);
	/* UTF-8's byte-order mark */
	{
		char buf[256];

		snprintf(buf, sizeof(buf), "\xef\xbb\xbf%s", csv);
		g = read_str(buf, &err);
		shape(g, "csv with UTF-8 BOM", 4, 1, 2.0, 0.5, "um", "um");
		rc_grid_free(g);
	}
}

/* UTF-16 (LE and BE, with their BOM) of the csv above reads to the
 * same grid as the UTF-8 text. */
static void
utf16(void)
{
	rc_err err;
	rc_grid *ref = read_str(csv, &err), *g;
	unsigned char buf[512];

	for (int be = 0; be < 2; be++) {
		size_t n = 0;
		const unsigned char *s = (const unsigned char *)csv;

		buf[n++] = be ? 0xfe : 0xff;
		buf[n++] = be ? 0xff : 0xfe;
		while (*s) {
			unsigned cp = *s++;

			if (cp == 0xc2)		/* the micro sign, U+00B5 */
				cp = *s++;
			buf[n++] = (unsigned char)(be ? 0 : cp);
			buf[n++] = (unsigned char)(be ? cp : 0);
		}
		g = read_mem(buf, n, NULL, &err);
		shape(g, be ? "UTF-16BE csv" : "UTF-16LE csv", 4, 1, 2.0, 0.5,
		    "um", "um");
		test_true(g != NULL && ref != NULL &&
		    memcmp(g->z, ref->z, 4 * sizeof(double)) == 0,
		    "UTF-16%s: the UTF-8 file's heights", be ? "BE" : "LE");
		rc_grid_free(g);
		/* an unpaired surrogate is not text */
		buf[n - 2] = be ? 0xd8 : 0x00;
		buf[n - 1] = be ? 0x00 : 0xd8;
		g = read_mem(buf, n, NULL, &err);
		test_true(g == NULL && strstr(err.msg, "UTF-16") != NULL,
		    "UTF-16%s with an unpaired surrogate: '%s'", be ? "BE" : "LE",
		    g == NULL ? err.msg : "read");
		rc_grid_free(g);
	}
	rc_grid_free(ref);
}

/* Dektak: steps of 1500/9600 = 0.15625 um printed with one decimal lie
 * up to 0.1 off a uniform grid through the first and last point (more
 * than 1% of the step); within one unit of the last printed digit they
 * are read as uniform.  Steps printed with mixed decimals are not. */
static void
dektak(void)
{
	rc_err err;
	rc_grid *g = read_str("Scan Parameters\r\r\nScan Type,Standard Scan\r\n"
	    "Stylus,Radius: 2.5 \xb5m\r\nLength,0.8 um\r\n\r\r\nScan Data\r\r\n"
	    "Lateral um,Raw Micrometer,\r\n0.0,1.0,,\r\n0.2,2.0,,\r\n0.3,3.0,,\r\n"
	    "0.5,4.0,,\r\n0.6,5.0,,\r\n\r\r\n", &err);

	shape(g, "dektak", 5, 1, 0.75, 0.15, "um", "um");
	if (g != NULL)
		test_true(g->z[4] == 5, "dektak heights");
	rc_grid_free(g);
	refused("x printed with mixed decimals (xy-6)", "0 1\n1 1\n2.5 1\n3 1\n",
	    "not uniformly spaced");
	refused("dektak without Scan Data", "Scan Parameters\nID,0\n", "Scan Data");
	refused("csv: an empty field between values", "x,z\n0.0,1\n0.5,,2\n",
	    "empty field");
}

/* HFM: "X;Y;valid" and a line of units; a 0 flag is a missing point. */
static void
hfm(void)
{
	rc_err err;
	rc_grid *g = read_str("X;Y;valid\r\n[mm];[mm];[1/0]\r\n1.000000;5.0;1\r\n"
	    "1.000500;6.0;0\r\n1.001000;7.0;1\r\n", &err);

	shape(g, "hfm", 3, 1, 0.0015, 0.0005, "mm", "mm");
	if (g != NULL)
		test_true(g->z[0] == 5 && g->z[2] == 7 && g->valid != NULL &&
		    g->valid[1] == 0 && g->valid[0] == 1, "hfm: flag 0 missing");
	rc_grid_free(g);
	refused("hfm flag 2", "X;Y;valid\n0.0;1;1\n0.5;1;2\n1.0;1;1\n",
	    "validity flag");
}

/* SurfaceTopography's matrix header: w columns, h rows, heights times
 * the conversion factor. */
static void
st_matrix(void)
{
	rc_err err;
	rc_grid *g = read_str("h=2 w=3\npixel size=2e-06 m\ndata unit=rad\n"
	    "height conversion factor (-> m)=0.5\n1 2 3\n4 5 6\n", &err);

	shape(g, "h= w= matrix", 3, 2, 6e-6, 4e-6, "m", "m");
	if (g != NULL) {
		test_true(g->z[0] == 0.5 && g->z[5] == 3,
		    "h= w= matrix: values times the conversion factor");
		test_true(!g->periodic, "h= w= matrix: a measurement");
	}
	rc_grid_free(g);
	refused("h= w= mismatch", "h=3 w=3\npixel size=1 m\n1 2 3\n4 5 6\n",
	    "h=3 w=3");
	refused("pixel size without unit", "h=1 w=2\npixel size=1\n1 2\n",
	    "pixel size");
}

/* Gwyddion's export in a German locale: German labels, decimal commas. */
static void
german(void)
{
	rc_err err;
	rc_grid *g = read_str("# Kanal: K\n# Breite: 1,5 \xc2\xb5m\n"
	    "# H\xc3\xb6he: 500 nm\n# Value units: m\n1,5\t2,5\n-3\t4\n", &err);

	shape(g, "German export", 2, 2, 1.5, 0.5, "\xc2\xb5m", "m");
	if (g != NULL)
		test_true(g->z[0] == 1.5 && g->z[1] == 2.5 && g->z[2] == -3,
		    "German export: decimal commas");
	rc_grid_free(g);
}

/* One value per line is a profile; -L gives its length. */
static void
single_column(void)
{
	rc_err err;
	rc_read_opts o;
	rc_grid *g = read_str("1\n2\n3\n4\n5\n6\n7\n8\n9", &err);

	shape(g, "single column", 9, 1, 1, 1.0 / 9, "", "");
	if (g != NULL)
		test_true(g->z[0] == 1 && g->z[8] == 9, "single column values");
	rc_grid_free(g);
	rc_read_opts_init(&o);
	o.have_l = 1;
	o.lx = 2.25;
	o.ly = 1;
	g = read_mem("1\n2\n3\n", 6, &o, &err);
	shape(g, "single column -L 2.25", 3, 1, 2.25, 0.75, "", "");
	rc_grid_free(g);
	/* a line of units, a count line (of points or intervals), then x z */
	g = read_str("\xc2\xb5m \xc2\xb5m\n3\n 0.0,  1.0\n 1.0,  2.0\n"
	    " 2.0,  3.0\n 3.0,  4.0\n", &err);
	shape(g, "units line and count", 4, 1, 4, 1, "um", "um");
	rc_grid_free(g);
	refused("count line off by two", "um um\n2\n0.0 1\n1.0 2\n2.0 3\n3.0 4\n",
	    "gives 2 points");
}

/* gzip of any format reads as the format itself; one or two members;
 * truncated or corrupt input is said to be. */
static void
gzip_input(void)
{
	rc_err err;
	rc_grid *src = test_new_grid(5, 3, 2.5, 1.5), *g;
	const char *plain = test_slot_path(1, "plain.surf");
	const char *gz = test_slot_path(2, "g.gz");
	unsigned char *buf;
	long n;
	gzFile z;

	for (size_t k = 0; k < 15; k++)
		src->z[k] = sin((double)k) * 1e-7;
	strcpy(src->unit, "um");
	test_true(rc_grid_write(src, plain, RC_FMT_SURF, &err) == 0, "write surf");
	buf = slurp(plain, &n);
	for (int members = 1; members <= 2; members++) {
		z = gzopen(gz, "wb");
		gzwrite(z, buf, (unsigned)(members == 1 ? n : n / 2));
		gzclose(z);
		if (members == 2) {
			z = gzopen(gz, "ab");	/* a second member */
			gzwrite(z, buf + n / 2, (unsigned)(n - n / 2));
			gzclose(z);
		}
		g = rc_grid_read(gz, NULL, &err);
		test_true(g != NULL && g->nx == 5 && g->ny == 3 &&
		    memcmp(g->z, src->z, 15 * sizeof(double)) == 0 &&
		    strcmp(g->unit, "um") == 0, "gzip of a .surf, %d member%s: %s",
		    members, members > 1 ? "s" : "", g == NULL ? err.msg : "ok");
		rc_grid_free(g);
	}
	/* the csv, gzip-compressed */
	z = gzopen(gz, "wb");
	gzwrite(z, csv, (unsigned)strlen(csv));
	gzclose(z);
	g = rc_grid_read(gz, NULL, &err);
	shape(g, "gzip of a csv", 4, 1, 2.0, 0.5, "um", "um");
	rc_grid_free(g);
	/* truncated: the first half of the compressed file */
	free(buf);
	buf = slurp(gz, &n);
	g = read_mem(buf, (size_t)n / 2, NULL, &err);
	test_true(g == NULL && strstr(err.msg, "truncated") != NULL,
	    "truncated gzip: '%s'", g == NULL ? err.msg : "read");
	rc_grid_free(g);
	buf[n / 2] ^= 0xff;	/* a corrupt deflate stream */
	buf[n / 2 + 1] ^= 0x55;
	g = read_mem(buf, (size_t)n, NULL, &err);
	test_true(g == NULL && strstr(err.msg, "gzip") != NULL,
	    "corrupt gzip: '%s'", g == NULL ? err.msg : "read");
	rc_grid_free(g);
	free(buf);
	rc_grid_free(src);
}

/* Text that is not a height file says what it looks like, never
 * "'X' is not a number" for a header line. */
static void
refusals(void)
{
	refused("prose", "This is not a height file.", "is text and no numbers "
	    "follow");
	refused("two text lines before a matrix", "My title\nanother line\n"
	    "1 2 3\n4 5 6\n", "header line this reader does not know");
	refused("names that do not fit the columns", "a b\n1 2 3\n4 5 6\n",
	    "nor a line of names for the 3 columns");
	refused("names over a wide matrix", "a,b,c,d,e\n1,2,3,4,5\n6,7,8,9,10\n",
	    "columns with a line of names");
}

/* The text s read with --uniform (o.uniform). */
static rc_grid *
read_uniform(const char *s, rc_err *err)
{
	rc_read_opts o;

	rc_read_opts_init(&o);
	o.uniform = 1;
	return read_mem(s, strlen(s), &o, err);
}

/* --uniform: x-z points not uniformly spaced are interpolated linearly
 * onto as many points of a uniform step; checked against exact linear
 * functions, the error bound of linear interpolation on a sine, points on
 * the grid (kept exactly) and SurfaceTopography's xy files. */
static void
resample(void)
{
	static const double xs[] = { 0, 0.3, 1.1, 1.5, 2.9, 4 };
	char buf[16384];
	size_t n = 0, m = 0;
	rc_read_opts o;
	rc_err err;
	rc_grid *g, *u;
	double hmax = 0, worst = 0, prev = 0;

	/* a uniform profile reads bit for bit the same with --uniform */
	g = read_str(csv, &err);
	u = read_uniform(csv, &err);
	test_true(g && u && u->nx == g->nx && u->lx == g->lx &&
	    memcmp(u->z, g->z, g->nx * sizeof(double)) == 0 &&
	    rc_grid_meta_get(u, "resampled") == NULL,
	    "--uniform leaves a uniform profile as it is");
	rc_grid_free(g);
	rc_grid_free(u);
	/* z = 3 x + 1 at 6 uneven x: exact on the grid of step 0.8 */
	for (size_t k = 0; k < 6; k++)
		n += (size_t)snprintf(buf + n, sizeof(buf) - n, "%.17g %.17g\n",
		    xs[k], 3 * xs[k] + 1);
	refused("uneven x without --uniform", buf, "--uniform resamples");
	g = read_uniform(buf, &err);
	shape(g, "--uniform, 6 uneven points", 6, 1, 6 * 0.8, 0.8, "", "");
	for (size_t i = 0; g != NULL && i < 6; i++)
		test_abs(g->z[i], 3 * 0.8 * (double)i + 1, 1e-13,
		    "linear heights resampled exactly, point %zu", i);
	test_true(g && rc_grid_meta_get(g, "resampled") != NULL,
	    "the grid says it was resampled");
	rc_grid_free(g);
	/* sin x on the uniform step 0.05 over [0, 10] with every third point
	 * removed: resampled onto m points, within h^2/8 max|f''| = h^2/8 of
	 * sin, h the widest gap (0.1) */
	n = 0;
	for (int k = 0; k <= 200; k++) {
		double x = 0.05 * k;

		if (k % 3 == 1 && k != 200)
			continue;
		if (m > 0 && x - prev > hmax)
			hmax = x - prev;
		prev = x;
		m++;
		n += (size_t)snprintf(buf + n, sizeof(buf) - n, "%.17g %.17g\n", x,
		    sin(x));
	}
	g = read_uniform(buf, &err);
	shape(g, "--uniform, sine with points removed", m, 1,
	    (double)m * 10 / (double)(m - 1), 10 / (double)(m - 1), "", "");
	for (size_t i = 0; g != NULL && i < m; i++)
		worst = fmax(worst, fabs(g->z[i] - sin(10 * (double)i /
		    (double)(m - 1))));
	test_true(g && worst <= hmax * hmax / 8 + 1e-15 && worst > 0,
	    "sine resampled within h^2/8 = %g of sin (largest error %g)",
	    hmax * hmax / 8, worst);
	rc_grid_free(g);
	/* xy-3: a point at 4.5 among integers; 11 points of step 0.9 put a
	 * grid point on it, which keeps its height; all others lie between
	 * zeros */
	rc_read_opts_init(&o);
	o.uniform = 1;
	g = rc_grid_read(test_data_path("st_xy-3.txt"), &o, &err);
	shape(g, "xy-3 --uniform", 11, 1, 9.9, 0.9, "", "");
	for (size_t i = 0; g != NULL && i < 11; i++)
		test_abs(g->z[i], i == 5 ? 1 : 0, 1e-15, "xy-3 resampled: point %zu",
		    i);
	rc_grid_free(g);
	/* xy-6: 0 1, 1 NaN, 2.5 1, 3 1 -> x 0 1 2 3: 1 on a grid point next to
	 * a missing height is kept; the grid points touching the missing one
	 * are missing */
	g = rc_grid_read(test_data_path("st_xy-6.txt"), &o, &err);
	shape(g, "xy-6 --uniform", 4, 1, 4, 1, "", "");
	test_true(g && g->z[0] == 1 && g->z[3] == 1 && g->valid && g->valid[0] &&
	    !g->valid[1] && !g->valid[2] && g->valid[3],
	    "xy-6: 1, missing, missing, 1");
	rc_grid_free(g);
	/* xy-2: a "µm µm" line, a count, 24 points from 13.381669 to
	 * 42.591941 um */
	g = rc_grid_read(test_data_path("st_xy-2.txt"), &o, &err);
	shape(g, "xy-2 --uniform", 24, 1, 24 * (4.2591941e+01 - 1.3381669e+01) /
	    23, (4.2591941e+01 - 1.3381669e+01) / 23, "um", "um");
	test_true(g && g->z[0] == 1.7854970e+01 && g->z[23] == 2.9477905e+01,
	    "xy-2: the end points keep their heights");
	rc_grid_free(g);
	g = rc_grid_read(test_data_path("st_xy-2.txt"), NULL, &err);
	test_true(g == NULL && strstr(err.msg, "--uniform") != NULL,
	    "xy-2 without --uniform: refused naming it ('%s')", g ? "" : err.msg);
	rc_grid_free(g);
	/* what cannot be resampled */
	g = read_uniform("0 1\n2 1\n1 1\n3 1\n", &err);
	test_true(g == NULL && strstr(err.msg, "not strictly monotonic") != NULL,
	    "x out of order: refused ('%s')", g ? "" : err.msg);
	rc_grid_free(g);
	g = read_uniform("0 0 1\n1 0.3 2\n0 1 3\n1 1 4\n", &err);
	test_true(g == NULL && strstr(err.msg, "x-z profiles only") != NULL,
	    "x-y-z off a grid: refused ('%s')", g ? "" : err.msg);
	rc_grid_free(g);
}

int
main(void)
{
	csv_names();
	utf16();
	dektak();
	hfm();
	st_matrix();
	german();
	single_column();
	gzip_input();
	refusals();
	resample();
	return test_summary();
}
