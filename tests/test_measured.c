/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_measured.c - what a grid knows besides its values: units and their
 * conversion, the periodic flag and the wrap-around check, missing and
 * filled points; kept by every format that can, and the text reader's
 * Gwyddion header and columns, the npy axis order. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gridcheck.h"
#include "io.h"
#include "level.h"
#include "resample.h"
#include "stats.h"
#include "testlib.h"
#include "units.h"

static rc_grid *
read_text(const char *text, const rc_read_opts *o, rc_err *err)
{
	FILE *fp = fmemopen((void *)text, strlen(text), "rb");
	rc_grid *g = rc_grid_read_stream(fp, o, err);

	fclose(fp);
	return g;
}

static void
test_unit_names(void)
{
	int e = 99;

	test_true(rc_unit_length_exp("\xc2\xb5m", &e) && e == -6, "micro sign um");
	test_true(rc_unit_length_exp("\xce\xbcm", &e) && e == -6, "Greek mu um");
	test_true(rc_unit_length_exp("\xc3\x85", &e) && e == -10, "angstrom");
	test_true(!rc_unit_is_length("deg") && !rc_unit_is_length("V") &&
	    !rc_unit_is_length("A") && !rc_unit_is_length("unitless") &&
	    !rc_unit_is_length(""), "deg, V, A (ampere), unitless, '' are not lengths");
	test_true(strcmp(rc_unit_canonical("\xc2\xb5m"), "um") == 0 &&
	    strcmp(rc_unit_canonical("micron"), "um") == 0 &&
	    strcmp(rc_unit_canonical("deg"), "deg") == 0, "canonical spellings");
	/* One correctly rounded operation by an exact power of ten. */
	test_true(rc_unit_convert(2.5, "um", "nm") == 2500, "2.5 um = 2500 nm exactly");
	test_true(rc_unit_convert(1, "nm", "m") == 1e-9, "1 nm = 1e-9 m (rounded once)");
	test_true(rc_unit_convert(3e-6, "m", "um") == 3, "3e-6 m = 3 um");
}

/* A um x nm map becomes um x um; the gradient is that of the same map in
 * metres, to round-off (two conversions, each correctly rounded: a few
 * ulps). */
static void
test_common_unit(void)
{
	rc_err err;
	rc_grid *a = rc_grid_new(16, 8, 10, 5, &err), *b = rc_grid_new(16, 8,
	    1e-5, 5e-6, &err);

	for (size_t k = 0; k < 128; k++) {
		double h = sin(0.7 * (double)k) + 0.3 * cos(2.1 * (double)(k / 16));

		a->z[k] = 100 * h;	/* nm */
		b->z[k] = 100e-9 * h;	/* m */
	}
	strcpy(a->unit, "um");
	strcpy(a->z_unit, "nm");
	strcpy(b->unit, "m");
	strcpy(b->z_unit, "m");
	test_true(rc_grid_to_common_unit(a, NULL, &err) == 0, "um x nm converts");
	test_true(strcmp(a->unit, "um") == 0 && strcmp(a->z_unit, "um") == 0 &&
	    a->lx == 10 && fabs(a->z[3] - 0.1 * (sin(2.1) + 0.3)) < 1e-15,
	    "values now in um, size kept");
	test_true(rc_grid_to_common_unit(b, NULL, &err) == 0, "m x m is a no-op");
	test_rel(rc_gbar_forward(a), rc_gbar_forward(b), 1e-13, "gbar of um x nm = gbar in m");
	test_true(rc_grid_to_common_unit(a, "nm", &err) == 0 && a->lx == 10000 &&
	    strcmp(a->unit, "nm") == 0, "--unit nm converts sizes");
	test_rel(rc_gbar_forward(a), rc_gbar_forward(b), 1e-13, "gbar unchanged in nm");

	/* Heights that are not lengths are refused, naming the unit. */
	strcpy(b->z_unit, "deg");
	test_true(rc_grid_to_common_unit(b, NULL, &err) != 0 &&
	    strstr(err.msg, "'deg'") && strstr(err.msg, "--z-unit"),
	    "a deg channel is not a height: %s", err.msg);
	/* A mask's values are not lengths, and need not be. */
	b->kind = RC_KIND_MASK;
	test_true(rc_grid_to_common_unit(b, "um", &err) == 0 && b->lx == 10 &&
	    strcmp(b->z_unit, "deg") == 0, "mask: lateral converted, values not");
	strcpy(b->unit, "V");
	test_true(rc_grid_to_common_unit(b, NULL, &err) != 0 &&
	    strstr(err.msg, "'V'"), "lateral unit V refused: %s", err.msg);
	/* No unit at all: nothing to do; a unit for the values only is the
	 * unit of both. */
	rc_grid_free(b);
	b = rc_grid_new(2, 2, 3, 3, &err);
	b->z[0] = 7;
	test_true(rc_grid_to_common_unit(b, NULL, &err) == 0 && b->unit[0] == 0 &&
	    b->z[0] == 7 && b->lx == 3, "unknown units stay unknown");
	strcpy(b->z_unit, "nm");
	test_true(rc_grid_to_common_unit(b, "um", &err) == 0 && b->lx == 3 &&
	    b->z[0] == 0.007 && strcmp(b->unit, "um") == 0,
	    "lateral unknown taken as --unit, nm values converted");
	rc_grid_free(a);
	rc_grid_free(b);
}

/* Exact values of the wrap ratio: a plane of slope s along x steps s
 * inside and s (n - 1) across the edge: ratio n - 1.  A sine of one period
 * along x, z = sin(2 pi i / n): the n steps of a period, wrap included,
 * are 2 sin(pi/n) cos(2 pi (i + 1/2) / n), whose squares sum to
 * 2 n sin^2(pi/n); the wrap step squared is 4 sin^2 cos^2 (of pi/n), so
 * ratio^2 = 2 (n - 1) cos^2(pi/n) / (n - 2 cos^2(pi/n)), about 1.43 for
 * n = 32: a periodic grid stays near 1. */
static void
test_wrap(void)
{
	rc_err err;
	size_t n = 32;
	rc_grid *g = rc_grid_new(n, 8, 1, 1, &err);
	unsigned long long s = 12345;

	for (size_t j = 0; j < 8; j++)
		for (size_t i = 0; i < n; i++)
			g->z[j * n + i] = 0.3 * (double)i;
	test_rel(rc_grid_wrap_ratio(g), (double)(n - 1), 1e-12, "tilted plane: n - 1");
	for (size_t j = 0; j < 8; j++)
		for (size_t i = 0; i < n; i++)
			g->z[j * n + i] = sin(2 * M_PI * (double)i / (double)n);
	{
		double c2 = cos(M_PI / (double)n) * cos(M_PI / (double)n);

		test_rel(rc_grid_wrap_ratio(g), sqrt(2 * (double)(n - 1) * c2 /
		    ((double)n - 2 * c2)), 1e-12, "one period of a sine");
	}
	/* A tilted plane with noise of the slope's size, by the LCG
	 * below: well above the warning threshold (about n / 1.4). */
	for (size_t k = 0; k < n * 8; k++) {
		s = s * 6364136223846793005ULL + 1442695040888963407ULL;
		g->z[k] = 0.3 * (double)(k % n) + 0.3 * ((double)(s >> 11) / 9007199254740992.0 - 0.5);
	}
	test_true(rc_grid_wrap_ratio(g) > 4 * RC_WRAP_RATIO_WARN,
	    "tilted plane + noise: ratio %g far above %g", rc_grid_wrap_ratio(g),
	    RC_WRAP_RATIO_WARN);
	memset(g->z, 0, n * 8 * sizeof(double));
	test_true(rc_grid_wrap_ratio(g) == 1, "flat grid: 1");
	g->z[5] = NAN;
	g->valid = calloc(n * 8, 1);
	memset(g->valid, 1, n * 8);
	g->valid[5] = 0;
	test_int((long long)rc_grid_missing_count(g), 1, "one missing point");
	test_true(rc_grid_wrap_ratio(g) == 1, "a missing point is skipped");
	rc_grid_free(g);
}

/* Every writable format keeps units, the periodic flag and missing points
 * to its ability. */
static void
test_roundtrip(void)
{
	static const char *ext[] = { "surf", "npy", "gsf", "txt" };
	rc_err err;
	rc_grid *g = rc_grid_new(5, 3, 2.5, 1.5, &err);

	for (size_t k = 0; k < 15; k++)
		g->z[k] = 0.25 * (double)k - 1;
	g->z[7] = NAN;
	strcpy(g->unit, "um");
	strcpy(g->z_unit, "nm");
	g->periodic = 0;
	for (int f = 0; f < 4; f++) {
		char name[16];
		rc_grid *r;
		int ok = 1;

		snprintf(name, sizeof(name), "rt.%s", ext[f]);
		test_true(rc_grid_write(g, test_path(name), (enum rc_format)f, &err) == 0,
		    "write %s", name);
		r = rc_grid_read(test_path(name), NULL, &err);
		if (r == NULL) {
			test_true(0, "read %s: %s", name, err.msg);
			continue;
		}
		for (size_t k = 0; k < 15; k++)
			/* gsf: float32 in metres; 2^-24 relative */
			ok &= k == 7 ? isnan(r->z[k]) && r->valid && !r->valid[k] :
			    fabs(r->z[k] - g->z[k]) <= (f == RC_FMT_GSF ? 1.2e-7 *
			    fabs(g->z[k]) : 0) && (r->valid == NULL || r->valid[k]);
		test_true(ok && r->valid != NULL, "%s keeps values and the missing point", name);
		if (f == RC_FMT_NPY) {
			test_true(r->unit[0] == 0 && r->periodic == 1,
			    "npy: no units, periodic by rule");
		} else {
			test_true(strcmp(r->unit, "um") == 0 && strcmp(r->z_unit, "nm") == 0 &&
			    r->periodic == 0, "%s keeps unit, z_unit, periodic = 0 (%s %s %d)",
			    name, r->unit, r->z_unit, r->periodic);
			test_rel(r->lx, 2.5, f == RC_FMT_GSF ? 1e-15 : 0, "%s keeps lx", name);
		}
		rc_grid_free(r);
	}
	rc_grid_free(g);
}

static void
test_old_and_foreign(void)
{
	rc_err err;
	rc_grid *g;
	const char *old = "#surf 1\nnx = 1\nny = 1\nlx = 1\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n\0\0\0\0\0\0\0\0";
	FILE *fp = fmemopen((void *)old, strlen(old) + 8, "rb");
	unsigned char gsf[64] = "Gwyddion Simple Field 1.0\nXRes = 1\nYRes = 1\n"
	    "ZUnits = deg\n";
	size_t n = strlen((char *)gsf);
	rc_read_opts o;

	g = rc_grid_read_stream(fp, NULL, &err);
	fclose(fp);
	test_true(g && g->periodic == 1, "a .surf without 'periodic' is periodic");
	rc_grid_free(g);
	/* A foreign GSF phase channel: read as what it says, not periodic. */
	memset(gsf + n, 0, 4 - n % 4 + 4);
	n += 4 - n % 4 + 4;
	fp = fmemopen(gsf, n, "rb");
	g = rc_grid_read_stream(fp, NULL, &err);
	fclose(fp);
	test_true(g && strcmp(g->z_unit, "deg") == 0 && g->periodic == 0,
	    "foreign gsf: ZUnits deg kept, not periodic");
	test_true(g && rc_grid_to_common_unit(g, NULL, &err) != 0 &&
	    strstr(err.msg, "deg"), "... and refused as heights");
	rc_grid_free(g);
	rc_read_opts_init(&o);
	o.z_unit = "nm";
	o.periodic = RC_PERIODIC_YES;
	fp = fmemopen(gsf, n, "rb");
	g = rc_grid_read_stream(fp, &o, &err);
	fclose(fp);
	test_true(g && strcmp(g->z_unit, "nm") == 0 && g->periodic == 1 &&
	    rc_grid_to_common_unit(g, NULL, &err) == 0,
	    "--z-unit nm --periodic override the file");
	rc_grid_free(g);
}

static void
test_text(void)
{
	rc_err err;
	rc_grid *g;
	rc_read_opts o;

	/* Gwyddion has no headless ASCII export (its command line converts
	 * only to .gwy), so the header is written here in the form its
	 * plain-text matrix export documents and writes. */
	g = read_text("# Channel: Topography\n# Width: 10.000 \xc2\xb5m\n"
	    "# Height: 4000 nm\n# Value units: m\n1e-9 2e-9\n3e-9 4e-9\n", NULL, &err);
	test_true(g && g->nx == 2 && g->ny == 2 && g->lx == 10 && g->ly == 4 &&
	    strcmp(g->unit, "\xc2\xb5m") == 0 && strcmp(g->z_unit, "m") == 0 &&
	    g->periodic == 0 && rc_grid_meta_get(g, "channel") &&
	    strcmp(rc_grid_meta_get(g, "channel"), "Topography") == 0,
	    "Gwyddion ASCII header: size, units, channel, not periodic (%s)",
	    g ? "" : err.msg);
	test_true(g && rc_grid_to_common_unit(g, NULL, &err) == 0 &&
	    fabs(g->z[3] - 4e-3) < 1e-18 && strcmp(g->unit, "um") == 0,
	    "... heights 4e-9 m = 4e-3 um");
	rc_grid_free(g);
	/* x-z: a uniform profile of 5 points, spacing 0.5. */
	g = read_text("0 1\n0.5 2\n1 3\n1.5 4\n2 5\n", NULL, &err);
	test_true(g && g->nx == 5 && g->ny == 1 && g->lx == 2.5 && g->ly == 0.5 &&
	    g->z[4] == 5 && g->periodic == 0, "x-z columns: a 5 x 1 profile (%s)",
	    g ? "" : err.msg);
	rc_grid_free(g);
	g = read_text("2 5\n1.5 4\n1 3\n0.5 2\n0 1\n", NULL, &err);
	test_true(g && g->nx == 5 && g->z[0] == 1 && g->z[4] == 5,
	    "x-z columns, x decreasing: reordered");
	rc_grid_free(g);
	g = read_text("0 1\n0.5 2\n1.7 3\n2 5\n", NULL, &err);
	test_true(g == NULL && strstr(err.msg, "not uniformly spaced") &&
	    strstr(err.msg, "# nx = 2"), "non-uniform x-z refused: %s", err.msg);
	rc_grid_free(g);
	/* x-y-z: 3 x 2 points along x first, and the same along y first with
	 * y decreasing. */
	g = read_text("0 0 1\n1 0 2\n2 0 3\n0 1 4\n1 1 5\n2 1 6\n", NULL, &err);
	test_true(g && g->nx == 3 && g->ny == 2 && g->lx == 3 && g->ly == 2 &&
	    g->z[0] == 1 && g->z[2] == 3 && g->z[3] == 4 && g->z[5] == 6,
	    "x-y-z columns along x: 3 x 2 (%s)", g ? "" : err.msg);
	rc_grid_free(g);
	g = read_text("0 1 4\n0 0 1\n1 1 5\n1 0 2\n2 1 6\n2 0 3\n", NULL, &err);
	test_true(g && g->nx == 3 && g->ny == 2 && g->z[0] == 1 && g->z[2] == 3 &&
	    g->z[3] == 4 && g->z[5] == 6, "x-y-z along y, y decreasing (%s)",
	    g ? "" : err.msg);
	rc_grid_free(g);
	g = read_text("0 0 1\n1 0.3 2\n0 1 3\n1 1 4\n", NULL, &err);
	test_true(g == NULL && strstr(err.msg, "x-y-z") && strstr(err.msg, "# nx = 3"),
	    "scattered x-y-z refused: %s", err.msg);
	rc_grid_free(g);
	g = read_text("# nx = 3\n0 0 1\n1 0.3 2\n0 1 3\n1 1 4\n", NULL, &err);
	test_true(g && g->nx == 3 && g->ny == 4, "'# nx = 3' reads a 3-column matrix");
	rc_grid_free(g);
	g = read_text("1 2 3\n4 5 6\n7 8 9\n", NULL, &err);
	test_true(g && g->nx == 3 && g->ny == 3 && g->periodic == 1,
	    "a plain 3 x 3 matrix stays a periodic matrix");
	rc_grid_free(g);
	rc_read_opts_init(&o);
	o.unit = "nm";
	o.periodic = RC_PERIODIC_NO;
	g = read_text("1 2\n3 4\n", &o, &err);
	test_true(g && strcmp(g->unit, "nm") == 0 && g->periodic == 0,
	    "--unit names the unit of a plain matrix, --no-periodic");
	rc_grid_free(g);
}

/* (nx, ny) arrays: a[i, j] at x index i. */
static void
test_npy_order(void)
{
	unsigned char f[256] = "\x93NUMPY\x01\x00";
	const char *dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), }";
	size_t h = 128 - 10, n;
	rc_read_opts o;
	rc_err err;
	rc_grid *g;
	FILE *fp;

	f[8] = (unsigned char)h;
	memset(f + 10, ' ', h);
	memcpy(f + 10, dict, strlen(dict));
	f[127] = '\n';
	for (int k = 0; k < 6; k++) {
		double v = 10 * (k / 2) + k % 2;	/* a[i, j] = 10 i + j */

		memcpy(f + 128 + 8 * k, &v, 8);
	}
	n = 128 + 48;
	rc_read_opts_init(&o);
	o.npy_xy = 1;
	fp = fmemopen(f, n, "rb");
	g = rc_grid_read_stream(fp, &o, &err);
	fclose(fp);
	test_true(g && g->nx == 3 && g->ny == 2 && g->z[1 * 3 + 2] == 21 &&
	    g->z[0 * 3 + 1] == 10, "--npy-order xy: shape (nx, ny), a[i, j] = (i, j)");
	rc_grid_free(g);
	fp = fmemopen(f, n, "rb");
	g = rc_grid_read_stream(fp, NULL, &err);
	fclose(fp);
	test_true(g && g->nx == 2 && g->ny == 3 && g->z[2 * 2 + 1] == 21,
	    "default: shape (ny, nx)");
	rc_grid_free(g);
}

/* Filled points: --fill marks them; the list reads back exactly in the
 * formats that keep it, follows crops and transposes, and is dropped by
 * resampling and by the formats without a place for it. */
static void
test_filled(void)
{
	static const char *ext[] = { "surf", "npy", "gsf", "txt", "x3p", "nc" };
	const size_t nx = 40, ny = 30, n = nx * ny;
	unsigned char hole[40 * 30];
	size_t nholes = 0;
	rc_err err;
	rc_grid *g = rc_grid_new(nx, ny, 4, 3, &err), *c;
	char *text;
	int same;

	strcpy(g->unit, "um");
	g->periodic = 0;
	/* a 10 x 9 hole, a whole row, scattered points, the first and the
	 * last point */
	for (size_t k = 0; k < n; k++) {
		size_t i = k % nx, j = k / nx;

		hole[k] = (i >= 5 && i < 15 && j >= 3 && j < 12) || j == 20 ||
		    k % 97 == 13 || k == 0 || k == n - 1;
		g->z[k] = hole[k] ? NAN : sin(0.3 * (double)i) * cos(0.2 * (double)j);
		nholes += hole[k];
	}
	test_int(rc_grid_read_finish(g, NULL, &err), 0, "holes are missing points");
	test_int(rc_fill_harmonic(g, NULL, NULL, &err), 0, "fill");
	same = g->filled != NULL && g->valid == NULL;
	for (size_t k = 0; same && k < n; k++)
		same = g->filled[k] == hole[k];
	test_true(same, "the filled mask is the holes");
	test_true(rc_grid_meta_get(g, "filled_points") != NULL &&
	    (size_t)atol(rc_grid_meta_get(g, "filled_points")) == nholes,
	    "filled_points counts them (%zu)", nholes);
	/* one range per row of the hole: the list stays short */
	text = rc_grid_filled_format(g, &err);
	test_true(text != NULL && strncmp(text, "0,13,110,125-134,165-174,", 25) == 0 &&
	    strstr(text, ",800-839,") != NULL && strlen(text) < 300 &&
	    strcmp(text + strlen(text) - 5, ",1199") == 0,
	    "the list: ranges of indices (%.60s...)", text ? text : "");
	free(text);

	for (int f = 0; f < 6; f++) {
		char name[16];
		int keeps = f == RC_FMT_SURF || f == RC_FMT_GSF || f == RC_FMT_TXT;
		rc_grid *r;

		snprintf(name, sizeof(name), "filled.%s", ext[f]);
		test_int(rc_format_keeps_filled(g, (enum rc_format)f, &err), keeps,
		    "%s keeps the filled points: %d", name, keeps);
		if (rc_grid_write(g, test_path(name), (enum rc_format)f, &err) != 0 ||
		    (r = rc_grid_read(test_path(name), NULL, &err)) == NULL) {
			test_true(0, "%s: %s", name, err.msg);
			continue;
		}
		same = (r->filled != NULL) == keeps;
		for (size_t k = 0; same && keeps && k < n; k++)
			same = r->filled[k] == hole[k];
		test_true(same, keeps ? "%s: the filled mask reads back exactly" :
		    "%s: no filled mask", name);
		rc_grid_free(r);
	}

	/* the shape kept: a copy and a step in place keep it */
	c = rc_grid_clone(g, 1, &err);
	rc_detrend(c, RC_DETREND_PLANE, NULL, &err);
	test_true(c->filled != NULL && memcmp(c->filled, hole, n) == 0,
	    "clone and detrend keep the mask");
	rc_grid_free(c);
	/* a crop keeps the filled points inside it and counts them */
	c = rc_crop(g, 10, 30, 5, 25, &err);
	same = c != NULL && c->filled != NULL;
	for (size_t k = 0; same && k < 400; k++)
		same = c->filled[k] == hole[(k / 20 + 5) * nx + k % 20 + 10];
	test_true(same, "crop maps the mask");
	test_true(c != NULL && (size_t)atol(rc_grid_meta_get(c, "filled_points")) ==
	    rc_grid_filled_count(c), "crop: filled_points = %zu", c ?
	    rc_grid_filled_count(c) : 0);
	rc_grid_free(c);
	c = rc_crop(g, 20, 30, 25, 29, &err);
	test_true(c != NULL && c->filled == NULL &&
	    strcmp(rc_grid_meta_get(c, "filled_points"), "0") == 0,
	    "a crop without filled points has no mask");
	rc_grid_free(c);
	c = rc_transpose(g, &err);
	same = c != NULL && c->filled != NULL;
	for (size_t k = 0; same && k < n; k++)
		same = c->filled[(k % nx) * ny + k / nx] == hole[k];
	test_true(same, "transpose maps the mask");
	rc_grid_free(c);
	c = rc_resample(g, 0.05, 0.05, &err);
	test_true(c != NULL && c->filled == NULL &&
	    rc_grid_meta_get(c, "filled_points") != NULL,
	    "resample drops the mask, keeps the count");
	rc_grid_free(c);
	/* a second fill adds to the mask */
	g->z[1] = NAN;
	rc_grid_read_finish(g, NULL, &err);
	rc_fill_harmonic(g, NULL, NULL, &err);
	test_true(g->filled[0] && g->filled[1] && g->filled[n - 1] &&
	    rc_grid_filled_count(g) == nholes + 1, "a second fill adds its point");
	rc_grid_free(g);

	/* the text: parsed strictly */
	g = rc_grid_new(4, 3, 1, 1, &err);
	test_int(rc_grid_filled_parse(g, "0-2,5,11", &err), 0, "parse 0-2,5,11");
	test_true(g->filled && g->filled[0] && g->filled[2] && !g->filled[3] &&
	    g->filled[5] && g->filled[11] && rc_grid_filled_count(g) == 5,
	    "... five points");
	text = rc_grid_filled_format(g, &err);
	test_true(text && strcmp(text, "0-2,5,11") == 0, "... and back: %s", text);
	free(text);
	test_int(rc_grid_filled_parse(g, "", &err), 0, "an empty list");
	test_true(g->filled == NULL, "... leaves no mask");
	{
		static const char *bad[] = { "3-1", "5,4", "0-2,2", "12", "0-12",
		    "1,,2", "a", "1-", "1 ,2", "-1", "1,", "99999999999999999999999" };

		for (size_t k = 0; k < sizeof(bad) / sizeof(bad[0]); k++)
			test_true(rc_grid_filled_parse(g, bad[k], &err) != 0 &&
			    strncmp(err.msg, "filled: ", 8) == 0 && g->filled == NULL,
			    "'%s' refused: %s", bad[k], err.msg);
	}
	rc_grid_free(g);
	/* a listed point that is missing */
	{
		const char *hdr = "#surf 1\nnx = 2\nny = 1\nlx = 1\nly = 1\n"
		    "kind = height\nencoding = float64-le\nfilled = 1\nend_header\n";
		char buf[256];
		size_t len = strlen(hdr);
		FILE *fp;

		memcpy(buf, hdr, len);
		memset(buf + len, 0, 8);			/* 0.0 */
		memcpy(buf + len + 8, "\0\0\0\0\0\0\xf8\x7f", 8);	/* NaN */
		fp = fmemopen(buf, len + 16, "rb");
		g = rc_grid_read_stream(fp, NULL, &err);
		fclose(fp);
		test_true(g == NULL && strstr(err.msg, "listed as filled but is "
		    "missing"), "a filled point that is NaN is refused: %s", err.msg);
		rc_grid_free(g);
	}
	/* a list beyond RC_FILLED_MAX (a checkerboard of dropouts) is left
	 * out of the header, and the format says it does not keep it */
	g = rc_grid_new(512, 512, 1, 1, &err);
	g->filled = calloc(512 * 512, 1);
	for (size_t k = 0; k < 512 * 512; k++)
		g->filled[k] = (k % 512 + k / 512) % 2;
	test_int(rc_format_keeps_filled(g, RC_FMT_SURF, &err), 0,
	    "a list of 131072 ranges does not fit");
	test_int(rc_grid_write(g, test_path("big.surf"), RC_FMT_SURF, &err), 0,
	    "... the grid is written");
	c = rc_grid_read(test_path("big.surf"), NULL, &err);
	test_true(c != NULL && c->filled == NULL, "... without the list");
	rc_grid_free(c);
	rc_grid_free(g);
}

int
main(void)
{
	test_unit_names();
	test_common_unit();
	test_wrap();
	test_roundtrip();
	test_old_and_foreign();
	test_text();
	test_npy_order();
	test_filled();
	return test_summary();
}
