/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_io.c - the grid formats: round trips, pipes, hand-made numpy files,
 * golden files, and every reader fed broken input. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "io.h"
#include "testlib.h"

/* An odd, non-square grid with metadata and history; "wild" values
 * (signed zero, a subnormal, near-overflow) only where the format is
 * meant to be exact. */
static rc_grid *
sample(int wild)
{
	rc_err err;
	rc_grid *g = rc_grid_new(7, 5, 2.5, 1.75, &err);

	for (size_t k = 0; k < 35; k++)
		g->z[k] = (sin(1.3 * (double)k) + 0.25) * pow(10, (double)(k % 7) - 3);
	if (wild) {
		g->z[0] = -0.0;
		g->z[1] = 4.9e-321;
		g->z[2] = -1.7976931348623157e308;
		g->z[3] = M_PI;
		g->z[4] = 0.1 + 0.2;
	}
	strcpy(g->unit, "m");
	rc_grid_meta_setd(g, "H", 0.8, &err);
	rc_grid_meta_set(g, "type", "selfaffine", &err);
	rc_grid_meta_setd(g, "lambda_r", 1.0 / 3, &err);
	rc_grid_history_add(g, "surfgen -n 7x5 -L 2.5x1.75 --seed 42", &err);
	rc_grid_history_add(g, "surfwarp -w 2", &err);
	return g;
}

static int
same_bits(const rc_grid *a, const rc_grid *b)
{
	return a->nx == b->nx && a->ny == b->ny &&
	    memcmp(a->z, b->z, rc_grid_size(a) * sizeof(double)) == 0;
}

static int
same_header(const rc_grid *a, const rc_grid *b)
{
	if (a->lx != b->lx || a->ly != b->ly || a->kind != b->kind ||
	    strcmp(a->unit, b->unit) != 0 || a->nmeta != b->nmeta ||
	    a->nhistory != b->nhistory)
		return 0;
	for (size_t i = 0; i < a->nmeta; i++)
		if (strcmp(a->meta[i].key, b->meta[i].key) != 0 ||
		    strcmp(a->meta[i].val, b->meta[i].val) != 0)
			return 0;
	for (size_t i = 0; i < a->nhistory; i++)
		if (strcmp(a->history[i], b->history[i]) != 0)
			return 0;
	return 1;
}

static void
test_roundtrip(void)
{
	rc_err err;
	rc_grid *g = sample(1), *tame = sample(0), *r;
	rc_read_opts o = { .lx = 2.5, .ly = 1.75, .have_l = 1, .allow_nonfinite = 0 };

	/* Native: everything exact, bit for bit. */
	test_true(rc_grid_write(g, test_path("a.surf"), RC_FMT_SURF, &err) == 0, "write surf");
	r = rc_grid_read(test_path("a.surf"), NULL, &err);
	test_true(r && same_bits(r, g) && same_header(r, g),
	    "surf round trip is exact (values, lengths, unit, kind, meta, history)");
	test_true(r && signbit(r->z[0]), "surf keeps the sign of -0");
	rc_grid_free(r);

	/* npy: values exact; lengths from -L. */
	test_true(rc_grid_write(g, test_path("a.npy"), RC_FMT_NPY, &err) == 0, "write npy");
	r = rc_grid_read(test_path("a.npy"), &o, &err);
	test_true(r && same_bits(r, g) && r->lx == 2.5 && r->ly == 1.75,
	    "npy round trip is exact, cell size from -L");
	rc_grid_free(r);
	r = rc_grid_read(test_path("a.npy"), NULL, &err);
	test_true(r && r->lx == 1 && r->ly == 1, "npy without -L has L = 1");
	rc_grid_free(r);

	/* txt: %.17g reads back exactly; the comments carry the header. */
	test_true(rc_grid_write(g, test_path("a.txt"), RC_FMT_TXT, &err) == 0, "write txt");
	r = rc_grid_read(test_path("a.txt"), NULL, &err);
	test_true(r && same_bits(r, g) && same_header(r, g),
	    "txt round trip is exact (%%.17g), header kept in comments: %s",
	    r ? "" : err.msg);
	rc_grid_free(r);

	/* gsf: float32.  Round to nearest gives a relative error of at most
	 * 2^-24 for normal float32 values (all of these are). */
	test_true(rc_grid_write(tame, test_path("a.gsf"), RC_FMT_GSF, &err) == 0, "write gsf");
	r = rc_grid_read(test_path("a.gsf"), NULL, &err);
	test_true(r != NULL, "read gsf back: %s", r ? "" : err.msg);
	if (r != NULL) {
		double worst = 0;

		for (size_t k = 0; k < 35; k++)
			worst = fmax(worst, fabs(r->z[k] - tame->z[k]) / fabs(tame->z[k]));
		test_range(worst, 0, ldexp(1, -24), "gsf relative error <= 2^-24");
		test_true(worst > 0, "gsf really is float32 (some value rounded)");
		test_true(same_header(r, tame), "gsf keeps lengths, unit, kind, meta, history");
	}
	rc_grid_free(r);
	/* A metadata key far longer than any fixed buffer (400 characters)
	 * comes back whole, not cut short. */
	{
		char longkey[401];

		memset(longkey, 'k', 400);
		longkey[400] = '\0';
		test_true(rc_grid_meta_set(tame, longkey, "v", &err) == 0 &&
		    rc_grid_write(tame, test_path("k.gsf"), RC_FMT_GSF, &err) == 0,
		    "write gsf with a 400-character key");
		r = rc_grid_read(test_path("k.gsf"), NULL, &err);
		test_true(r && rc_grid_meta_get(r, longkey) != NULL &&
		    strcmp(rc_grid_meta_get(r, longkey), "v") == 0,
		    "gsf keeps a 400-character metadata key whole");
		rc_grid_free(r);
		rc_grid_meta_unset(tame, longkey);
	}
	/* Beyond float32: an error, not Inf. */
	test_true(rc_grid_write(g, test_path("b.gsf"), RC_FMT_GSF, &err) != 0 &&
	    strstr(err.msg, "float32 range") != NULL, "gsf refuses -1.8e308: %s", err.msg);
	test_true(access(test_path("b.gsf"), F_OK) != 0, "no half-written gsf left behind");

	/* A prefixed unit is written in metres (Gwyddion drops prefixes) and
	 * comes back in its own unit to within round-off. */
	strcpy(tame->unit, "um");
	test_true(rc_grid_write(tame, test_path("u.gsf"), RC_FMT_GSF, &err) == 0, "write gsf in um");
	r = rc_grid_read(test_path("u.gsf"), NULL, &err);
	test_true(r && strcmp(r->unit, "um") == 0, "gsf in um reads back in um");
	if (r != NULL) {
		test_rel(r->lx, 2.5, 4 * DBL_EPSILON, "gsf um: lx back");
		/* float32 of z*1e-6, then /1e-6: 2^-24 plus a few double ulps. */
		for (size_t k = 0; k < 35; k += 6)
			test_rel(r->z[k], tame->z[k], ldexp(1, -24) + 1e-15, "gsf um: z[%zu]", k);
	}
	rc_grid_free(r);
	{
		FILE *fp = fopen(test_path("u.gsf"), "rb");
		char head[512] = "";

		fread(head, 1, sizeof(head) - 1, fp);
		fclose(fp);
		test_true(strstr(head, "\nXReal = 2.5") && strstr(head, "\nXYUnits = m\n"),
		    "gsf in um: XReal written in metres");
	}

	/* A 1-row grid: npy shape (1, nx). */
	{
		rc_grid *line = rc_grid_new(6, 1, 1, 1, &err);

		line->z[5] = 1.5;
		rc_grid_write(line, test_path("line.npy"), RC_FMT_NPY, &err);
		r = rc_grid_read(test_path("line.npy"), NULL, &err);
		test_true(r && r->nx == 6 && r->ny == 1 && r->z[5] == 1.5, "1-row grid via npy");
		rc_grid_free(r);
		rc_grid_free(line);
	}
	rc_grid_free(g);
	rc_grid_free(tame);
}

static void
test_surf_layout(void)
{
	rc_err err;
	rc_grid *g = sample(1);
	unsigned char buf[4096];
	size_t n, off;
	FILE *fp;
	char *p;

	rc_grid_write(g, test_path("l.surf"), RC_FMT_SURF, &err);
	fp = fopen(test_path("l.surf"), "rb");
	n = fread(buf, 1, sizeof(buf), fp);
	fclose(fp);
	test_true(memcmp(buf, "#surf 1\n# ", 10) == 0 &&
	    strstr((char *)buf, "\nnx = 7\nny = 5\n") != NULL, "surf starts with magic, nx, ny");
	p = strstr((char *)buf, "data_offset = ");
	off = p ? strtoul(p + 14, NULL, 10) : 0;
	test_int((long long)(off % 8), 0, "data offset is a multiple of 8");
	test_int((long long)n, (long long)(off + 35 * 8), "file = header + 35 float64");
	test_true(off >= 11 && memcmp(buf + off - 1, "\n", 1) == 0 &&
	    strstr((char *)buf, "\nend_header") != NULL, "header ends with end_header line");
	/* Little-endian regardless of the host: decode z[3] = pi by hand. */
	{
		uint64_t u = 0;
		double d;

		for (int k = 7; k >= 0; k--)
			u = u << 8 | buf[off + 3 * 8 + k];
		memcpy(&d, &u, 8);
		test_true(d == M_PI, "value 3 stored as float64 little-endian");
	}
	rc_grid_free(g);
}

static void
test_pipe(void)
{
	rc_err err;
	rc_grid *g = sample(1), *big, *r;
	char cmd[600];
	const char *ext[] = { "surf", "npy", "gsf", "txt" };
	FILE *fp;

	for (int f = 0; f < 4; f++) {
		rc_grid *src = f == RC_FMT_GSF ? sample(0) : g;
		char name[32];

		snprintf(name, sizeof(name), "p.%s", ext[f]);
		rc_grid_write(src, test_path(name), (enum rc_format)f, &err);
		snprintf(cmd, sizeof(cmd), "cat '%s'", test_path(name));
		fp = popen(cmd, "r");
		r = rc_grid_read_stream(fp, NULL, &err);
		pclose(fp);
		test_true(r && r->nx == 7 && r->ny == 5 &&
		    (f == RC_FMT_GSF || same_bits(r, g)), "%s through a pipe: %s",
		    ext[f], r ? "ok" : err.msg);
		rc_grid_free(r);
		if (src != g)
			rc_grid_free(src);
	}
	/* A grid bigger than the input buffer, through a pipe. */
	big = rc_grid_new(301, 257, 1, 1, &err);
	for (size_t k = 0; k < rc_grid_size(big); k++)
		big->z[k] = (double)k * 0.125 - 7;
	rc_grid_write(big, test_path("big.surf"), RC_FMT_SURF, &err);
	snprintf(cmd, sizeof(cmd), "cat '%s'", test_path("big.surf"));
	fp = popen(cmd, "r");
	r = rc_grid_read_stream(fp, NULL, &err);
	pclose(fp);
	test_true(r && same_bits(r, big), "301x257 surf through a pipe");
	rc_grid_free(r);
	/* And the same from memory (no file descriptor at all). */
	{
		char *mem;
		size_t len;
		FILE *w = open_memstream(&mem, &len);

		rc_grid_write_stream(big, w, RC_FMT_NPY, &err);
		fclose(w);
		fp = fmemopen(mem, len, "rb");
		r = rc_grid_read_stream(fp, NULL, &err);
		fclose(fp);
		test_true(r && same_bits(r, big), "npy from fmemopen");
		rc_grid_free(r);
		free(mem);
	}
	rc_grid_free(big);
	rc_grid_free(g);
}

/* A numpy file made by hand: preamble of the given version, dict, pad. */
static size_t
make_npy(unsigned char *out, int major, const char *dict, const void *data,
    size_t nbytes)
{
	size_t pre = major == 1 ? 10 : 12, dl = strlen(dict), hl;

	hl = (pre + dl + 1 + 63) / 64 * 64 - pre;
	memcpy(out, "\x93NUMPY", 6);
	out[6] = (unsigned char)major;
	out[7] = 0;
	if (major == 1) {
		out[8] = (unsigned char)(hl & 0xff);
		out[9] = (unsigned char)(hl >> 8);
	} else
		for (int k = 0; k < 4; k++)
			out[8 + k] = (unsigned char)(hl >> (8 * k));
	memcpy(out + pre, dict, dl);
	memset(out + pre + dl, ' ', hl - dl - 1);
	out[pre + hl - 1] = '\n';
	memcpy(out + pre + hl, data, nbytes);
	return pre + hl + nbytes;
}

static void
put32(unsigned char *p, float f, int big)
{
	uint32_t u;

	memcpy(&u, &f, 4);
	for (int k = 0; k < 4; k++)
		p[big ? 3 - k : k] = (unsigned char)(u >> (8 * k));
}

static void
put64(unsigned char *p, double d, int big)
{
	uint64_t u;

	memcpy(&u, &d, 8);
	for (int k = 0; k < 8; k++)
		p[big ? 7 - k : k] = (unsigned char)(u >> (8 * k));
}

static rc_grid *
read_bytes(const char *name, const void *p, size_t n, rc_err *err)
{
	test_put_file(test_path(name), p, n);
	return rc_grid_read(test_path(name), NULL, err);
}

static void
test_npy_variants(void)
{
	unsigned char file[1024], data[256];
	rc_err err;
	rc_grid *r;
	size_t n;
	/* The grid z(i, j) = 10 j + i, 3 wide (nx) and 2 high (ny). */
	const double want[6] = { 0, 1, 2, 10, 11, 12 };

	/* <f4, C order. */
	for (int k = 0; k < 6; k++)
		put32(data + 4 * k, (float)want[k], 0);
	n = make_npy(file, 1, "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }", data, 24);
	r = read_bytes("f4.npy", file, n, &err);
	test_true(r && r->nx == 3 && r->ny == 2 && memcmp(r->z, want, sizeof(want)) == 0,
	    "npy <f4 C order");
	rc_grid_free(r);
	/* >f8, C order, npy 2.0. */
	for (int k = 0; k < 6; k++)
		put64(data + 8 * k, want[k], 1);
	n = make_npy(file, 2, "{'descr': '>f8', 'fortran_order': False, 'shape': (2, 3), }", data, 48);
	r = read_bytes("be8.npy", file, n, &err);
	test_true(r && r->nx == 3 && r->ny == 2 && memcmp(r->z, want, sizeof(want)) == 0,
	    "npy >f8 version 2.0: %s", r ? "" : err.msg);
	rc_grid_free(r);
	/* >f4, Fortran order (columns first), npy 3.0, keys in another order. */
	{
		const double col[6] = { 0, 10, 1, 11, 2, 12 };

		for (int k = 0; k < 6; k++)
			put32(data + 4 * k, (float)col[k], 1);
	}
	n = make_npy(file, 3, "{\"shape\": (2, 3), \"fortran_order\": True, \"descr\": \">f4\"}", data, 24);
	r = read_bytes("fo.npy", file, n, &err);
	test_true(r && r->nx == 3 && r->ny == 2 && memcmp(r->z, want, sizeof(want)) == 0,
	    "npy >f4 Fortran order version 3.0: %s", r ? "" : err.msg);
	rc_grid_free(r);
	/* <f8 Fortran order. */
	{
		const double col[6] = { 0, 10, 1, 11, 2, 12 };

		for (int k = 0; k < 6; k++)
			put64(data + 8 * k, col[k], 0);
	}
	n = make_npy(file, 1, "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 3), }", data, 48);
	r = read_bytes("fo8.npy", file, n, &err);
	test_true(r && memcmp(r->z, want, sizeof(want)) == 0, "npy <f8 Fortran order");
	rc_grid_free(r);
	/* 1-D: shape (n,) is an n x 1 grid. */
	for (int k = 0; k < 6; k++)
		put64(data + 8 * k, want[k], 0);
	n = make_npy(file, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (6,), }", data, 48);
	r = read_bytes("1d.npy", file, n, &err);
	test_true(r && r->nx == 6 && r->ny == 1 && memcmp(r->z, want, sizeof(want)) == 0,
	    "npy 1-D shape (6,) -> 6x1");
	rc_grid_free(r);
	/* Python 2 long integers in the shape. */
	n = make_npy(file, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (2L, 3L), }", data, 48);
	r = read_bytes("long.npy", file, n, &err);
	test_true(r && r->nx == 3 && r->ny == 2, "npy shape with Python 2 longs");
	rc_grid_free(r);
}

static const char *
top(void)
{
	const char *t = getenv("RC_TOP");

	return t ? t : ".";
}

/* Golden files (see tests/data/io_small.README): a numpy-written layout and a
 * Gwyddion-layout gsf, both z(i, j) = 10 j + i on 3 x 2. */
static void
test_golden(void)
{
	char path[1024];
	rc_err err;
	rc_grid *r;
	const double want[6] = { 0, 1, 2, 10, 11, 12 };

	snprintf(path, sizeof(path), "%s/tests/data/io_small.npy", top());
	r = rc_grid_read(path, NULL, &err);
	test_true(r && r->nx == 3 && r->ny == 2 && memcmp(r->z, want, sizeof(want)) == 0,
	    "golden io_small.npy: %s", r ? "" : err.msg);
	rc_grid_free(r);
	snprintf(path, sizeof(path), "%s/tests/data/io_small.gsf", top());
	r = rc_grid_read(path, NULL, &err);
	test_true(r && r->nx == 3 && r->ny == 2 && memcmp(r->z, want, sizeof(want)) == 0 &&
	    r->lx == 3e-6 && r->ly == 2e-6 && strcmp(r->unit, "m") == 0,
	    "golden io_small.gsf: %s", r ? "" : err.msg);
	test_true(r && rc_grid_meta_get(r, "Title") &&
	    strcmp(rc_grid_meta_get(r, "Title"), "golden") == 0,
	    "golden gsf: foreign Title kept as metadata");
	rc_grid_free(r);
}

/* Feed bytes; the read must fail with a message containing want. */
static void
bad(const char *what, const void *p, size_t n, const char *want)
{
	rc_err err = { "" };
	rc_grid *r;
	FILE *fp;

	test_put_file(test_path("bad"), p, n);
	r = rc_grid_read(test_path("bad"), NULL, &err);
	test_true(r == NULL && strstr(err.msg, want) != NULL,
	    "%s: rejected with '%s' (got '%s')", what, want, err.msg);
	rc_grid_free(r);
	/* The same through memory (the reader cannot learn the size). */
	fp = fmemopen((void *)p, n ? n : 1, "rb");
	if (n == 0) {
		fclose(fp);
		fp = fopen("/dev/null", "rb");
	}
	r = rc_grid_read_stream(fp, NULL, &err);
	fclose(fp);
	test_true(r == NULL && strstr(err.msg, want) != NULL,
	    "%s (stream): rejected with '%s' (got '%s')", what, want, err.msg);
	rc_grid_free(r);
}

/* Feed bytes; the read must succeed with exactly point k missing: valid[k]
 * 0 and z[k] NaN, every other point valid (from a file and a stream). */
static void
missing(const char *what, const void *p, size_t n, size_t k)
{
	rc_err err = { "" };
	rc_grid *r;
	FILE *fp;

	test_put_file(test_path("nan"), p, n);
	for (int stream = 0; stream < 2; stream++) {
		size_t nmiss = 0;

		if (stream) {
			fp = fmemopen((void *)p, n, "rb");
			r = rc_grid_read_stream(fp, NULL, &err);
			fclose(fp);
		} else
			r = rc_grid_read(test_path("nan"), NULL, &err);
		for (size_t i = 0; r != NULL && r->valid != NULL &&
		    i < rc_grid_size(r); i++)
			nmiss += r->valid[i] == 0;
		test_true(r && r->valid && k < rc_grid_size(r) && !r->valid[k] &&
		    isnan(r->z[k]) && nmiss == 1, "%s%s: point %zu read as missing "
		    "(%s)", what, stream ? " (stream)" : "", k, r ? "" : err.msg);
		rc_grid_free(r);
	}
}

static void
bads(const char *what, const char *s, const char *want)
{
	bad(what, s, strlen(s), want);
}

/* A surf file from a header text and n float64 values. */
static size_t
make_surf(unsigned char *out, const char *head, const double *v, size_t n)
{
	size_t hl = strlen(head);

	memcpy(out, head, hl);
	for (size_t k = 0; k < n; k++)
		put64(out + hl + 8 * k, v[k], 0);
	return hl + 8 * n;
}

#define H2x2 "#surf 1\nnx = 2\nny = 2\nlx = 1\nly = 1\nkind = height\nencoding = float64-le\n"

static void
test_bad_surf(void)
{
	unsigned char f[4096];
	double v[4] = { 1, 2, 3, 4 };
	size_t n;
	char *huge;

	bad("empty", "", 0, "empty input");
	bads("version 2", "#surf 2\nnx = 1\n", "format version");
	bads("truncated header", "#surf 1\nnx = 2\nny = 2\n", "truncated header");
	bads("missing ly", "#surf 1\nnx = 2\nny = 2\nlx = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", "lacks the required key 'ly'");
	bads("duplicate nx", "#surf 1\nnx = 2\nnx = 2\n", "duplicate key");
	bads("duplicate meta", "#surf 1\nmeta.H = 1\nmeta.H = 2\n", "duplicate key 'meta.H'");
	bads("unknown key", "#surf 1\nnz = 2\n", "unknown key 'nz'");
	bads("not key = value", "#surf 1\nhello\n", "not 'key = value'");
	bad("NUL in header", "#surf 1\nnx = 2\0\n", 16, "NUL byte");
	bads("bad nx", H2x2 "nx = 2x\n", "duplicate");
	bads("bad number", "#surf 1\nnx = 2x\nny = 2\nlx = 1\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", "sizes must be positive integers");
	bads("negative nx", "#surf 1\nnx = -2\nny = 2\nlx = 1\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", "sizes must be positive integers");
	bads("nx*ny overflow", "#surf 1\nnx = 16777216\nny = 16777216\nlx = 1\nly = 1\n"
	    "kind = height\nencoding = float64-le\nend_header\n", "too many points");
	bads("nx beyond max", "#surf 1\nnx = 99999999\nny = 1\nlx = 1\nly = 1\n"
	    "kind = height\nencoding = float64-le\nend_header\n", "exceeds");
	bads("nx 2^64", "#surf 1\nnx = 18446744073709551617\nny = 1\nlx = 1\nly = 1\n"
	    "kind = height\nencoding = float64-le\nend_header\n", "positive integers");
	bads("lx zero", "#surf 1\nnx = 2\nny = 2\nlx = 0\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", "positive and finite");
	bads("lx nan", "#surf 1\nnx = 2\nny = 2\nlx = nan\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", "positive and finite");
	bads("lx overflow", "#surf 1\nnx = 2\nny = 2\nlx = 1e999\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", "must be numbers");
	bads("bad kind", "#surf 1\nnx = 2\nny = 2\nlx = 1\nly = 1\nkind = heigth\n"
	    "encoding = float64-le\nend_header\n", "unknown kind");
	bads("float32", "#surf 1\nnx = 2\nny = 2\nlx = 1\nly = 1\nkind = height\n"
	    "encoding = float32-le\nend_header\n", "encoding");
	n = make_surf(f, H2x2 "end_header\n", v, 4);
	bad("truncated data", f, n - 3, "truncated: expected 32 data bytes, got 29");
	bad("no data", f, n - 32, "truncated: expected 32 data bytes, got 0");
	f[n] = 'x';
	bad("trailing garbage", f, n + 1, "trailing garbage");
	n = make_surf(f, H2x2 "data_offset = 8\nend_header\n", v, 4);
	bad("lying data_offset", f, n, "data_offset = 8");
	/* A header claiming 4096 x 4096 followed by 16 bytes: fails without
	 * allocating 128 MiB first (checked under ASan's allocator). */
	n = make_surf(f, "#surf 1\nnx = 4096\nny = 4096\nlx = 1\nly = 1\nkind = height\n"
	    "encoding = float64-le\nend_header\n", v, 2);
	bad("lying size", f, n, "truncated: expected 134217728 data bytes, got 16");
	v[2] = NAN;
	n = make_surf(f, H2x2 "end_header\n", v, 4);
	missing("NaN value", f, n, 2);
	v[2] = -INFINITY;
	n = make_surf(f, H2x2 "end_header\n", v, 4);
	bad("Inf value", f, n, "infinite");
	{
		rc_read_opts o = { .lx = 1, .ly = 1, .have_l = 0, .allow_nonfinite = 1 };
		rc_err err;
		rc_grid *r;

		test_put_file(test_path("inf.surf"), f, n);
		r = rc_grid_read(test_path("inf.surf"), &o, &err);
		test_true(r && isinf(r->z[2]), "allow_nonfinite admits -Inf");
		rc_grid_free(r);
	}
	v[2] = 0.5;
	n = make_surf(f, "#surf 1\nnx = 2\nny = 2\nlx = 1\nly = 1\nkind = mask\n"
	    "encoding = float64-le\nend_header\n", v, 4);
	v[2] = 3;
	bad("mask with 0.5", f, n, "a mask holds only 0 and 1");
	/* A header that never ends: capped at 1 MiB. */
	huge = malloc(3 << 20);
	memset(huge, 'a', 3 << 20);
	memcpy(huge, "#surf 1\nhistory = ", 18);
	bad("endless header line", huge, 3 << 20, "header longer than");
	for (size_t k = 100; k < (3 << 20); k += 100)
		huge[k] = '\n';
	memcpy(huge, "#surf 1\nhistory = ", 18);
	for (size_t k = 100; k < (3 << 20); k += 100)
		memcpy(huge + k + 1, "history = ", 10);
	bad("endless header", huge, 3 << 20, "header longer than");
	free(huge);
}

static void
test_bad_npy(void)
{
	unsigned char f[1024], d[64] = { 0 };
	size_t n;

	bads("npy short preamble", "\x93NUMPY\x01", "truncated npy preamble");
	bad("npy version 4", "\x93NUMPY\x04\x00\x10\x00", 10, "version 4.0");
	bad("npy huge header", "\x93NUMPY\x02\x00\xff\xff\xff\xff", 12, "exceeds");
	bad("npy short header", "\x93NUMPY\x01\x00\x40\x00{'descr'", 17, "truncated npy header");
	n = make_npy(f, 1, "{'descr': '<i4', 'fortran_order': False, 'shape': (2, 2), }", d, 16);
	bad("npy int32", f, n, "dtype '<i4' not supported");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 2), }", d, 64);
	bad("npy 3-D", f, n, "3 dimensions");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (), }", d, 8);
	bad("npy 0-D", f, n, "0 dimensions");
	n = make_npy(f, 1, "{'descr': '<f8', 'shape': (2, 2), }", d, 32);
	bad("npy no order", f, n, "lacks 'fortran_order'");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': Maybe, 'shape': (2, 2), }", d, 32);
	bad("npy bad bool", f, n, "not a valid dict");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), 'x': 1}", d, 32);
	bad("npy extra key", f, n, "unexpected or repeated key 'x'");
	n = make_npy(f, 1, "[1, 2]", d, 32);
	bad("npy not a dict", f, n, "not a valid dict");
	n = make_npy(f, 1, "{'descr': [('a', '<f8')], 'fortran_order': False, 'shape': (2,), }", d, 16);
	bad("npy structured", f, n, "structured");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (0, 2), }", d, 0);
	bad("npy empty shape", f, n, "at least 1");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (99999999999999999999999, 1), }", d, 0);
	bad("npy absurd shape", f, n, "exceeds");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (1048576, 1048576), }", d, 0);
	bad("npy too many points", f, n, "too many points");
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", d, 31);
	bad("npy truncated data", f, n, "truncated: expected 32 data bytes, got 31");
	put64(d + 8, NAN, 0);
	n = make_npy(f, 1, "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2), }", d, 32);
	missing("npy NaN", f, n, 1);
}

static void
test_bad_gsf(void)
{
	unsigned char f[1024];
	const char *h;
	size_t n;

	bads("gsf version 2", "Gwyddion Simple Field 2.0\nXRes = 1\n", "bad magic line");
	bads("gsf no NUL", "Gwyddion Simple Field 1.0\nXRes = 1\nYRes = 1\n", "no NUL");
	bad("gsf no XRes", "Gwyddion Simple Field 1.0\nYRes = 1\n\0\0\0\0\0\0\0\0", 44, "lacks XRes");
	bad("gsf bad YRes", "Gwyddion Simple Field 1.0\nXRes = 1\nYRes = x\0\0\0\0\0", 49, "positive integers");
	bad("gsf line without =", "Gwyddion Simple Field 1.0\nXRes 1\n\0\0\0", 36, "not 'Name = Value'");
	/* "...YRes = 1\n" is 45 bytes: one NUL to 46, then data at 48. */
	h = "Gwyddion Simple Field 1.0\nXRes = 1\nYRes = 1\n";
	n = strlen(h);
	memcpy(f, h, n);
	memset(f + n, 0, 4 - n % 4);
	n += 4 - n % 4;
	test_int((long long)n, 48, "gsf test header length");
	put32(f + n, 2.5f, 0);
	{
		rc_err err;
		rc_grid *r = read_bytes("one.gsf", f, n + 4, &err);

		test_true(r && r->z[0] == 2.5 && r->lx == 1, "gsf 1x1 minimal (L = 1 default)");
		rc_grid_free(r);
	}
	bad("gsf truncated data", f, n + 3, "truncated: expected 4 data bytes, got 3");
	bad("gsf trailing data", f, n + 8, "trailing garbage");
	f[n - 1] = 'x';
	bad("gsf bad padding", f, n + 4, "padding");
	bad("gsf truncated padding", f, n - 2, "truncated header padding");
	f[n - 1] = 0;
	put32(f + n, NAN, 0);
	missing("gsf NaN", f, n + 4, 0);
	bad("gsf negative XReal", "Gwyddion Simple Field 1.0\nXRes = 1\nYRes = 1\nXReal = -1\n\0\0\0\0\0\0\0",
	    61, "positive and finite");
	bad("gsf huge size", "Gwyddion Simple Field 1.0\nXRes = 9000\nYRes = 9000\n\0\0", 52,
	    "truncated: expected 324000000 data bytes, got 0");
}

static void
test_bad_txt(void)
{
	rc_err err;
	rc_grid *r;
	rc_read_opts o = { .lx = 3, .ly = 4, .have_l = 1, .allow_nonfinite = 0 };
	const char *ok = "# a numpy.savetxt file\n1 2 3\n4 5 6  # inline comment\n\n";

	bads("txt only comments", "# nothing\n# here\n", "no values");
	bads("txt ragged", "1 2 3 4\n5 6 7 8\n1 2 3 4 5\n", "line 3 has 5 values, line 1 has 4");
	bads("txt not a number", "1 2\n3 abc\n", "line 2: 'abc' is not a number");
	bad("txt NUL", "1 2\n3 4\0\n", 9, "line 2: NUL byte");
	missing("txt NaN", "1 2\n3 nan\n", 10, 3);
	bads("txt header lies", "# nx = 3\n1 2\n3 4\n", "header says 3x2, the data are 2x2");
	bads("txt lx only", "# lx = 3\n1 2\n3 4\n", "lx without ly");
	bads("txt bad kind", "# kind = curvature\n1 2\n", "unknown kind");
	bads("txt mask", "# kind = mask\n1 0\n0 2\n", "a mask holds only 0 and 1");
	bads("txt mask NaN", "# kind = mask\n1 0\n0 nan\n", "is NaN; a mask holds only 0 and 1");
	bads("txt Inf", "1 2\n3 -inf\n", "infinite values are not allowed");
	test_put_file(test_path("ok.txt"), ok, strlen(ok));
	r = rc_grid_read(test_path("ok.txt"), &o, &err);
	test_true(r && r->nx == 3 && r->ny == 2 && r->z[5] == 6 && r->lx == 3 && r->ly == 4,
	    "txt with free comments and blank lines, L from -L: %s", r ? "" : err.msg);
	rc_grid_free(r);
	test_put_file(test_path("crlf.txt"), "1\t2\r\n3\t4\r\n", 10);
	r = rc_grid_read(test_path("crlf.txt"), NULL, &err);
	test_true(r && r->nx == 2 && r->ny == 2 && r->z[3] == 4 && r->lx == 1,
	    "txt with tabs and CRLF");
	rc_grid_free(r);
}

static void
test_names(void)
{
	test_int(rc_format_from_name("a.surf"), RC_FMT_SURF, "a.surf");
	test_int(rc_format_from_name("dir.x/a.NPY"), RC_FMT_NPY, "a.NPY");
	test_int(rc_format_from_name("a.gsf"), RC_FMT_GSF, "a.gsf");
	test_int(rc_format_from_name("a.txt"), RC_FMT_TXT, "a.txt");
	test_int(rc_format_from_name("-"), RC_FMT_SURF, "- is surf");
	test_int(rc_format_from_name(NULL), RC_FMT_SURF, "NULL is surf");
	test_int(rc_format_from_name("dir.x/noext"), RC_FMT_SURF, "no extension is surf");
	test_int(rc_format_from_name("a.png"), -1, ".png is not a grid format");
	test_true(strcmp(rc_format_name(RC_FMT_GSF), "gsf") == 0, "format name");
}

static void
test_files(void)
{
	rc_err err;
	rc_grid *g = sample(1);

	test_true(rc_grid_read(test_path("nonexistent"), NULL, &err) == NULL &&
	    strstr(err.msg, "No such file") != NULL, "missing file: %s", err.msg);
	test_true(rc_grid_read(test_tmpdir(), NULL, &err) == NULL &&
	    strstr(err.msg, "directory") != NULL, "directory: %s", err.msg);
	/* Writing over the input is safe (atomic rename). */
	rc_grid_write(g, test_path("self.surf"), RC_FMT_SURF, &err);
	{
		rc_grid *r = rc_grid_read(test_path("self.surf"), NULL, &err);

		r->z[0] = 42;
		test_true(rc_grid_write(r, test_path("self.surf"), RC_FMT_SURF, &err) == 0,
		    "overwrite the input");
		rc_grid_free(r);
		r = rc_grid_read(test_path("self.surf"), NULL, &err);
		test_true(r && r->z[0] == 42, "overwritten file reads back");
		rc_grid_free(r);
	}
	rc_grid_free(g);
}

int
main(void)
{
	test_names();
	test_roundtrip();
	test_surf_layout();
	test_pipe();
	test_npy_variants();
	test_golden();
	test_bad_surf();
	test_bad_npy();
	test_bad_gsf();
	test_bad_txt();
	test_files();
	return test_summary();
}
