/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_checkpoint.c - lib/checkpoint.c: a write/read round trip is exact
 * to the bit (displacement, pressures, options, finished rows), another
 * indenter or other options are refused by rc_checkpoint_match, and a
 * truncated file or one whose fields are out of range is refused by
 * rc_checkpoint_read (never read as a checkpoint). */
#include <inttypes.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "checkpoint.h"
#include "elastic.h"
#include "grid.h"
#include "io.h"
#include "layer.h"
#include "solver.h"
#include "testlib.h"

#define NX 8
#define NY 6

static rc_grid *
indenter(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(NX, NY, 2.5, 1.75, &err);

	for (size_t k = 0; k < NX * NY; k++)
		g->z[k] = sin(0.7 * (double)k) / 3;
	rc_grid_meta_set(g, "H", "0.8", &err);
	return g;
}

/* A checkpoint in the middle of pressure 3 of 3, two rows done. */
static void
fill(rc_checkpoint *c, const rc_grid *g)
{
	static const double p[3] = { 0.1, 1.0 / 3, 0.05 };
	rc_err err;
	rc_row r;

	test_int(rc_checkpoint_init(c, g, p, 3, &err), 0, "init");
	strcpy(c->method, "fire");
	c->tol = 1e-9 / 3;
	c->modulus = 2.0 / 3;
	c->alpha = 0.3;
	c->max_iter = 12345;
	c->stall = 77;
	c->fd = 1;
	c->reduced = 1;
	c->next = 2;
	c->solving = 1;
	c->iterations = 777;
	c->unconverged = 1;
	/* a scene with every key away from its default (the format does not
	 * ask whether gfmd-solve would combine them) */
	c->boundary = RC_BOUNDARY_FREE;
	c->kernel = RC_KERNEL_PIXEL;
	c->hardness = 2.0 / 3;
	c->thickness = 1.0 / 8;
	c->substrate = RC_SUBSTRATE_SLIP;
	c->poisson = 0.3;
	c->adhesion = 1e-4 / 3;
	c->range = 0.01;
	c->law = RC_ADHESION_DUGDALE;
	rc_row_init(&r);
	for (int k = 0; k < 2; k++) {
		rc_row_clear(&r);
		rc_row_num(&r, "p_star", p[k]);
		/* Tab, backslash and space are escaped in row.K: they come back.
		 * (Not as the last column: an empty last value ends the line of
		 * the .surf header in a tab, which its reader trims.) */
		rc_row_str(&r, "label", k ? "a\tb\\c d" : "");
		rc_row_num(&r, "a_r", 1.0 / 7 + k);
		test_int(rc_checkpoint_add_row(c, &r, &err), 0, "add row %d", k);
	}
	rc_row_free(&r);
}

static void
round_trip(void)
{
	rc_grid *g = indenter(), *u = NULL;
	rc_checkpoint c, back;
	rc_row r0, r1;
	rc_err err;
	double *z = malloc(NX * NY * sizeof(double));

	fill(&c, g);
	/* Values whose every bit matters: thirds, a subnormal, -0, huge. */
	for (size_t k = 0; k < NX * NY; k++)
		z[k] = (double)k / 3 - 5;
	z[1] = 4.9e-324;
	z[2] = -0.0;
	z[3] = 1.7976931348623157e308;
	test_int(rc_checkpoint_write(&c, z, test_slot_path(0, "a.ck"), &err), 0,
	    "write: %s", err.msg);
	test_int(rc_checkpoint_read(&back, &u, test_slot_path(0, "a.ck"), &err), 0,
	    "read back: %s", err.msg);
	if (u == NULL) {
		rc_checkpoint_free(&c);
		rc_grid_free(g);
		free(z);
		return;
	}
	test_true(u->nx == NX && u->ny == NY &&
	    memcmp(u->z, z, sizeof(double) * NX * NY) == 0,
	    "displacement back bit for bit");
	test_int(rc_checkpoint_match(&back, &c, &err), 0,
	    "read-back matches what was written: %s", err.msg);
	test_true(back.input_sum == rc_checkpoint_hash(g), "input_sum back");
	test_true(memcmp(back.pressures, c.pressures, 3 * sizeof(double)) == 0 &&
	    back.npressures == 3, "pressures back bit for bit");
	test_true(memcmp(&back.tol, &c.tol, sizeof(double)) == 0 &&
	    memcmp(&back.modulus, &c.modulus, sizeof(double)) == 0 &&
	    memcmp(&back.alpha, &c.alpha, sizeof(double)) == 0,
	    "tol, E, alpha back bit for bit");
	test_true(back.next == 2 && back.solving == 1 && back.iterations == 777 &&
	    back.max_iter == 12345 && back.fd == 1 && back.reduced == 1 &&
	    strcmp(back.method, "fire") == 0, "progress and options back");
	test_int(back.stall, 77, "--stall back (version 6)");
	test_int((long long)back.unconverged, 1, "the unconverged rows' count "
	    "back (version 6)");
	test_true(back.boundary == RC_BOUNDARY_FREE &&
	    back.kernel == RC_KERNEL_PIXEL && back.substrate == RC_SUBSTRATE_SLIP &&
	    memcmp(&back.hardness, &c.hardness, sizeof(double)) == 0 &&
	    memcmp(&back.thickness, &c.thickness, sizeof(double)) == 0 &&
	    memcmp(&back.poisson, &c.poisson, sizeof(double)) == 0 &&
	    memcmp(&back.adhesion, &c.adhesion, sizeof(double)) == 0 &&
	    memcmp(&back.range, &c.range, sizeof(double)) == 0 &&
	    back.law == RC_ADHESION_DUGDALE, "the scene back bit for bit");
	test_int((long long)back.nrows, 2, "two finished rows back");
	rc_row_init(&r0);
	rc_row_init(&r1);
	for (size_t k = 0; k < 2 && back.nrows == 2; k++) {
		test_int(rc_checkpoint_row(&c, k, &r0, &err), 0, "row %zu written", k);
		test_int(rc_checkpoint_row(&back, k, &r1, &err), 0, "row %zu read: %s", k, err.msg);
		test_true(r0.n == 3 && r1.n == r0.n, "row %zu: 3 cells", k);
		for (size_t i = 0; i < r0.n && i < r1.n; i++)
			test_true(strcmp(r0.name[i], r1.name[i]) == 0 &&
			    strcmp(r0.val[i], r1.val[i]) == 0 &&
			    r0.is_str[i] == r1.is_str[i],
			    "row %zu cell %zu: '%s' back as '%s'", k, i, r0.val[i],
			    r1.val[i]);
	}
	/* The string with tab, backslash and space, unescaped. */
	if (r1.n == 3)
		test_true(strcmp(r1.val[1], "a\tb\\c d") == 0,
		    "escaped string back: '%s'", r1.val[1]);
	/* The number's text reads back to the same double. */
	if (r1.n == 3)
		test_true(strtod(r1.val[2], NULL) == 1.0 / 7 + 1,
		    "a_r of row 1 back exactly: %s", r1.val[2]);
	test_int(rc_checkpoint_row(&back, 2, &r1, &err), -1,
	    "row 2 (not finished) refused");
	rc_row_free(&r0);
	rc_row_free(&r1);
	rc_grid_free(u);
	rc_checkpoint_free(&back);
	rc_checkpoint_free(&c);
	rc_grid_free(g);
	free(z);
}

/* A changed indenter or option: match refuses, naming it. */
static void
identity(void)
{
	rc_grid *g = indenter();
	rc_checkpoint c, d;
	rc_err err;
	uint64_t h0 = rc_checkpoint_hash(g);

	fill(&c, g);
	g->z[17] = nextafter(g->z[17], 1);
	test_true(rc_checkpoint_hash(g) != h0, "hash sees one ulp of one height");
	fill(&d, g);
	test_int(rc_checkpoint_match(&c, &d, &err), -1, "one ulp: refused");
	test_true(strstr(err.msg, "another indenter") != NULL, "message: %s",
	    err.msg);
	rc_checkpoint_free(&d);
	g->z[17] = nextafter(g->z[17], -1);
	test_true(rc_checkpoint_hash(g) == h0, "same heights, same hash");

	rc_grid_meta_set(g, "H", "0.7", &err);
	test_true(rc_checkpoint_hash(g) != h0, "hash sees the metadata");
	rc_grid_meta_set(g, "H", "0.8", &err);
	strcpy(g->unit, "um");
	test_true(rc_checkpoint_hash(g) != h0, "hash sees the unit");
	g->unit[0] = '\0';
	g->periodic = !g->periodic;
	test_true(rc_checkpoint_hash(g) != h0, "hash sees the periodic flag");
	g->periodic = !g->periodic;
	test_true(rc_checkpoint_hash(g) == h0, "restored: same hash");

	fill(&d, g);
	d.tol = nextafter(d.tol, 1);
	test_int(rc_checkpoint_match(&c, &d, &err), -1, "tol one ulp off: refused");
	test_true(strstr(err.msg, "--tol") != NULL, "message: %s", err.msg);
	d.tol = c.tol;
	d.pressures[2] = nextafter(d.pressures[2], 1);
	test_int(rc_checkpoint_match(&c, &d, &err), -1,
	    "pressure one ulp off: refused");
	test_true(strstr(err.msg, "pressure 3") != NULL, "message: %s", err.msg);
	d.pressures[2] = c.pressures[2];
	strcpy(d.method, "cg");
	test_int(rc_checkpoint_match(&c, &d, &err), -1, "other method: refused");
	strcpy(d.method, c.method);
	d.reduced = 0;
	test_int(rc_checkpoint_match(&c, &d, &err), -1,
	    "absolute vs reduced: refused");
	d.reduced = 1;
	d.stall = c.stall + 1;
	test_int(rc_checkpoint_match(&c, &d, &err), -1, "other --stall: refused");
	test_true(strstr(err.msg, "--stall 77, this run 78") != NULL,
	    "message: %s", err.msg);
	c.stall = -1;	/* a version 5 checkpoint: any --stall */
	test_int(rc_checkpoint_match(&c, &d, &err), 0, "--stall unrecorded: "
	    "accepted");
	c.stall = d.stall = 77;
	d.nx = NX + 1;
	test_int(rc_checkpoint_match(&c, &d, &err), -1, "other grid: refused");
	d.nx = NX;
	/* the scene: each option named */
	{
		struct { int *i; double *v; const char *name; } f[] = {
			{ &d.boundary, NULL, "--boundary" },
			{ &d.kernel, NULL, "--kernel" },
			{ &d.substrate, NULL, "--substrate" },
			{ &d.law, NULL, "--law" },
			{ NULL, &d.hardness, "--hardness" },
			{ NULL, &d.thickness, "--thickness" },
			{ NULL, &d.poisson, "--poisson" },
			{ NULL, &d.adhesion, "--adhesion" },
			{ NULL, &d.range, "--range" },
		};

		for (size_t k = 0; k < sizeof(f) / sizeof(f[0]); k++) {
			int i0 = f[k].i ? *f[k].i : 0;
			double v0 = f[k].v ? *f[k].v : 0;

			if (f[k].i)
				*f[k].i = !i0;
			else
				*f[k].v = nextafter(v0, 1);
			test_int(rc_checkpoint_match(&c, &d, &err), -1, "other %s: "
			    "refused", f[k].name);
			test_true(strstr(err.msg, f[k].name) != NULL, "message: %s",
			    err.msg);
			if (f[k].i)
				*f[k].i = i0;
			else
				*f[k].v = v0;
		}
	}
	/* a version 2 checkpoint does not record the boundary kind: any */
	c.boundary = -1;
	d.boundary = RC_BOUNDARY_PERIODIC;
	test_int(rc_checkpoint_match(&c, &d, &err), 0, "boundary unrecorded: "
	    "accepted");
	c.boundary = d.boundary = RC_BOUNDARY_FREE;
	test_int(rc_checkpoint_match(&c, &d, &err), 0, "all restored: accepted");
	rc_checkpoint_free(&d);
	rc_checkpoint_free(&c);
	rc_grid_free(g);
}

/* A checkpoint edited on purpose gets its checkpoint.sum recomputed, so
 * that the check under test, not the sum, decides. */
static void
reseal(rc_grid *g, int yes)
{
	rc_err err;

	if (yes && rc_grid_meta_get(g, "checkpoint.sum") != NULL)
		rc_grid_meta_setf(g, "checkpoint.sum", &err, "%016" PRIx64,
		    rc_checkpoint_sum(g));
}

/* Rewrite the good checkpoint with one metadata key changed (val NULL:
 * removed), resealed or not; reading it must fail with a message naming
 * want. */
static void
refused_as(const char *key, const char *val, const char *want, int reseal_it)
{
	rc_grid *g;
	rc_checkpoint c;
	rc_grid *u = (rc_grid *)1;
	rc_err err;

	g = rc_grid_read(test_slot_path(0, "a.ck"), NULL, &err);
	if (g == NULL) {
		test_true(0, "re-read a.ck: %s", err.msg);
		return;
	}
	if (val == NULL)
		rc_grid_meta_unset(g, key);
	else
		rc_grid_meta_set(g, key, val, &err);
	reseal(g, reseal_it);
	rc_grid_write(g, test_slot_path(1, "b.ck"), RC_FMT_SURF, &err);
	rc_grid_free(g);
	test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "b.ck"), &err), -1,
	    "%s = %s: refused", key, val ? val : "(none)");
	test_true(u == NULL, "%s = %s: no displacement handed out", key,
	    val ? val : "(none)");
	test_true(strstr(err.msg, want) != NULL, "%s = %s: message '%s' names %s",
	    key, val ? val : "(none)", err.msg, want);
}

static void
refused(const char *key, const char *val, const char *want)
{
	refused_as(key, val, want, 1);
}

/* Issue 27: an edited row, or an edited displacement, came out as a
 * result.  Refused by the sum; a row whose p_star is not its pressure
 * also without the sum (a version 4 file has none). */
static void
edited(void)
{
	rc_grid *g, *u = NULL;
	rc_checkpoint c;
	rc_err err;

	refused_as("checkpoint.row.1", "0.3333333333333333\ta\\tb\\\\c\\sd\t0.9",
	    "checkpoint.sum", 0);
	refused("checkpoint.row.1", "0.25\tx\t0.5", "is not pressure 2");
	refused_as("checkpoint.sum", "0123456789abcdeg", "checkpoint.sum", 0);
	refused_as("checkpoint.sum", NULL, "checkpoint.sum", 0);
	g = rc_grid_read(test_slot_path(0, "a.ck"), NULL, &err);
	if (g == NULL) {
		test_true(0, "re-read a.ck: %s", err.msg);
		return;
	}
	g->z[5] = 1.8e56;
	rc_grid_write(g, test_slot_path(1, "z.ck"), RC_FMT_SURF, &err);
	test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "z.ck"), &err), -1,
	    "a displacement of 1.8e56 written in: refused");
	test_true(strstr(err.msg, "checkpoint.sum") != NULL,
	    "  by the sum ('%s')", err.msg);
	/* version 4 (no sum): the row's p_star is still checked */
	rc_grid_meta_set(g, "checkpoint.version", "4", &err);
	rc_grid_meta_unset(g, "checkpoint.sum");
	g->z[5] = 0;
	rc_grid_meta_set(g, "checkpoint.row.0", "0.2\t\t0.5", &err);
	rc_grid_write(g, test_slot_path(1, "v4.ck"), RC_FMT_SURF, &err);
	rc_grid_free(g);
	test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "v4.ck"), &err), -1,
	    "version 4 with row 0 at p_star 0.2 of 0.1: refused");
	test_true(strstr(err.msg, "is not pressure 1") != NULL,
	    "  naming the row ('%s')", err.msg);
}

/* The good checkpoint (a.ck) re-read with checkpoint.version set to
 * version, to be edited into an older one; NULL after a failed check. */
static rc_grid *
good_as_version(const char *version)
{
	rc_grid *g = rc_grid_read(test_slot_path(0, "a.ck"), NULL, NULL);
	rc_err err;

	if (g == NULL)
		test_true(0, "re-read a.ck");
	else
		rc_grid_meta_set(g, "checkpoint.version", version, &err);
	return g;
}

/* A version 5 checkpoint (before --stall and the unconverged rows were
 * recorded): read, the stall unrecorded (-1, any --stall resumes it) and
 * no unconverged row; the keys of version 6 are ignored in it. */
static void
version5(void)
{
	rc_grid *g = good_as_version("5"), *u;
	rc_checkpoint c;
	rc_err err;

	if (g == NULL)
		return;
	rc_grid_meta_unset(g, "checkpoint.stall");
	rc_grid_meta_unset(g, "checkpoint.unconverged");
	reseal(g, 1);
	rc_grid_write(g, test_slot_path(1, "v5.ck"), RC_FMT_SURF, &err);
	rc_grid_free(g);
	test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "v5.ck"), &err), 0,
	    "version 5: read (%s)", err.msg);
	test_true(c.stall == -1 && c.unconverged == 0, "version 5: --stall "
	    "unrecorded (%ld), no unconverged row (%zu)", c.stall,
	    c.unconverged);
	rc_checkpoint_free(&c);
	rc_grid_free(u);
}

/* A version 3 checkpoint (before the adhesive law was recorded): read,
 * with the exponential law, the only one then. */
static void
version3(void)
{
	rc_grid *g = good_as_version("3"), *u;
	rc_checkpoint c;
	rc_err err;

	if (g == NULL)
		return;
	rc_grid_meta_set(g, "checkpoint.law", "dugdale", &err);
	rc_grid_write(g, test_slot_path(1, "v3.ck"), RC_FMT_SURF, &err);
	rc_grid_meta_unset(g, "checkpoint.law");
	rc_grid_write(g, test_slot_path(1, "v3b.ck"), RC_FMT_SURF, &err);
	rc_grid_free(g);
	for (int k = 0; k < 2; k++) {
		test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, k ? "v3b.ck" :
		    "v3.ck"), &err), 0, "version 3: read (%s)", err.msg);
		test_int(c.law, RC_ADHESION_EXPONENTIAL, "version 3: the "
		    "exponential law (a law key %s ignored)", k ? "absent" :
		    "dugdale");
		rc_checkpoint_free(&c);
		rc_grid_free(u);
	}
}

/* A version 2 checkpoint (before the scene was recorded): read, as the
 * half space with no effect and an unrecorded boundary kind. */
static void
version2(void)
{
	static const char *keys[] = { "boundary", "kernel", "hardness",
	    "thickness", "substrate", "poisson", "adhesion", "range", "law" };
	rc_grid *g = good_as_version("2"), *u;
	rc_checkpoint c;
	rc_err err;
	char key[64];

	if (g == NULL)
		return;
	for (size_t k = 0; k < sizeof(keys) / sizeof(keys[0]); k++) {
		snprintf(key, sizeof(key), "checkpoint.%s", keys[k]);
		rc_grid_meta_unset(g, key);
	}
	rc_grid_write(g, test_slot_path(1, "v2.ck"), RC_FMT_SURF, &err);
	rc_grid_free(g);
	test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "v2.ck"), &err), 0,
	    "version 2: read (%s)", err.msg);
	test_true(c.boundary == -1 && c.kernel == RC_KERNEL_CONTINUUM &&
	    c.substrate == RC_SUBSTRATE_NONE && c.hardness == 0 &&
	    c.thickness == 0 && c.poisson == 0 && c.adhesion == 0 &&
	    c.range == 0, "version 2: the half space, no effect, boundary "
	    "unrecorded");
	rc_checkpoint_free(&c);
	rc_grid_free(u);
}

static void
bad_files(void)
{
	rc_grid *g = indenter(), *u;
	rc_checkpoint c;
	rc_err err;
	double z[NX * NY] = { 0 };
	FILE *fp;
	char *bytes;
	long size;

	fill(&c, g);
	/* without adhesion: the pressures must be positive */
	c.adhesion = c.range = 0;
	test_int(rc_checkpoint_write(&c, z, test_slot_path(0, "a.ck"), &err), 0, "write");
	rc_checkpoint_free(&c);
	rc_grid_free(g);

	/* Range checks: each field just outside what gfmd-solve accepts. */
	refused("checkpoint.version", "1", "version");
	refused("checkpoint.version", "7", "version");
	refused("checkpoint.stall", "-1", "checkpoint.stall");
	refused("checkpoint.stall", NULL, "checkpoint.stall");
	/* two rows finished (next = 2): at most two unconverged */
	refused("checkpoint.unconverged", "3", "more than the 2 finished rows");
	refused("checkpoint.unconverged", NULL, "checkpoint.unconverged");
	refused("checkpoint.law", "linear", "checkpoint.law");
	refused("checkpoint.law", NULL, "checkpoint.law");
	refused("checkpoint.boundary", "torus", "checkpoint.boundary");
	refused("checkpoint.boundary", NULL, "checkpoint.boundary");
	refused("checkpoint.kernel", "sinc", "checkpoint.kernel");
	refused("checkpoint.substrate", "glued", "checkpoint.substrate");
	refused("checkpoint.hardness", "-1", "checkpoint.hardness");
	refused("checkpoint.thickness", "-0.5", "checkpoint.thickness");
	refused("checkpoint.poisson", "0.6", "checkpoint.poisson");
	refused("checkpoint.adhesion", "inf", "checkpoint.adhesion");
	refused("checkpoint.range", "-1", "checkpoint.range");
	refused("checkpoint.input_sum", "0123", "16 hex digits");
	refused("checkpoint.method", "newton", "method");
	refused("checkpoint.tol", "0", "checkpoint.tol");
	refused("checkpoint.tol", "1.5", "checkpoint.tol");
	refused("checkpoint.E", "-1", "checkpoint.E");
	refused("checkpoint.E", "inf", "checkpoint.E");
	refused("checkpoint.alpha", "1.0000001", "checkpoint.alpha");
	refused("checkpoint.fd", "2", "checkpoint.fd");
	refused("checkpoint.max_iter", "0", "checkpoint.max_iter");
	refused("checkpoint.pressure_kind", "relative", "pressure_kind");
	refused("checkpoint.pressures", "0.1,-1,0.05", "pressures");
	refused("checkpoint.pressures", "0.1,,0.05", "pressures");
	refused("checkpoint.next", "4", "checkpoint.next");
	refused("checkpoint.next", "-1", "checkpoint.next");
	/* solving needs pressures[next], 3 of 3 has none */
	refused("checkpoint.next", "3", "inconsistent");
	refused("checkpoint.state", "between", "iterations");
	refused("checkpoint.state", "done", "state");
	refused("checkpoint.iterations", "-5", "iterations");
	refused("checkpoint.types", "nn", "types");
	refused("checkpoint.row.1", NULL, "row.1");
	refused("checkpoint.state", NULL, "not a gfmd-solve checkpoint");
	version2();
	version3();
	version5();
	edited();
	/* with adhesion any finite pressure (gfmd-solve takes them then) */
	g = rc_grid_read(test_slot_path(0, "a.ck"), NULL, &err);
	if (g != NULL) {
		rc_grid_meta_set(g, "checkpoint.adhesion", "0.001", &err);
		rc_grid_meta_set(g, "checkpoint.pressures",
		    "0.1,0.3333333333333333,-1,0", &err);
		reseal(g, 1);
		rc_grid_write(g, test_slot_path(1, "adh.ck"), RC_FMT_SURF, &err);
		rc_grid_free(g);
		test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "adh.ck"),
		    &err), 0, "with adhesion: pressures 0.1,1/3,-1,0 read (%s)",
		    err.msg);
		test_true(c.npressures == 4 && c.pressures[2] == -1 &&
		    c.pressures[3] == 0, "with adhesion: the pressures back");
		rc_checkpoint_free(&c);
		rc_grid_free(u);
	}

	/* The grid itself: a height field, a missing (NaN) value. */
	for (int t = 0; t < 2; t++) {
		rc_grid *g2 = rc_grid_read(test_slot_path(0, "a.ck"), NULL, &err);

		if (g2 == NULL)
			break;
		if (t == 0)
			g2->kind = RC_KIND_HEIGHT;
		else
			g2->z[5] = NAN;
		rc_grid_write(g2, test_slot_path(1, "g.ck"), RC_FMT_SURF, &err);
		rc_grid_free(g2);
		u = (rc_grid *)1;
		test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "g.ck"), &err), -1,
		    "%s: refused (%s)", t ? "a NaN displacement" : "kind height",
		    err.msg);
		test_true(u == NULL && strstr(err.msg, t ? "not finite" :
		    "displacement") != NULL, "%s: no grid, message says why",
		    t ? "NaN" : "height");
	}

	/* A truncated file (cut inside the values, and inside the header). */
	fp = fopen(test_slot_path(0, "a.ck"), "rb");
	fseek(fp, 0, SEEK_END);
	size = ftell(fp);
	rewind(fp);
	bytes = malloc((size_t)size);
	test_true(fread(bytes, 1, (size_t)size, fp) == (size_t)size, "read bytes");
	fclose(fp);
	for (int cut = 0; cut < 2; cut++) {
		long keep = cut ? size / 3 : size - 8;

		fp = fopen(test_slot_path(1, "t.ck"), "wb");
		fwrite(bytes, 1, (size_t)keep, fp);
		fclose(fp);
		u = (rc_grid *)1;
		test_int(rc_checkpoint_read(&c, &u, test_slot_path(1, "t.ck"), &err), -1,
		    "truncated to %ld of %ld bytes: refused (%s)", keep, size,
		    err.msg);
		test_true(u == NULL, "truncated: no displacement handed out");
	}
	free(bytes);
}

/* The resumed iteration count saturates at LONG_MAX (a checkpoint may
 * hold up to it, and the sum must not overflow); a count of LONG_MAX
 * survives a write and read. */
static void
saturation(void)
{
	rc_grid *g = indenter(), *u = NULL;
	rc_checkpoint c, back;
	rc_err err;
	double *z = calloc(NX * NY, sizeof(double));

	test_int(rc_checkpoint_iterations_add(0, 0), 0, "iterations: 0 + 0");
	test_int(rc_checkpoint_iterations_add(777, 23), 800, "iterations: 777 + 23");
	test_int(rc_checkpoint_iterations_add(LONG_MAX - 1, 1), LONG_MAX,
	    "iterations: LONG_MAX - 1 + 1 = LONG_MAX exactly");
	test_int(rc_checkpoint_iterations_add(LONG_MAX - 1, 2), LONG_MAX,
	    "iterations: LONG_MAX - 1 + 2 saturates");
	test_int(rc_checkpoint_iterations_add(LONG_MAX, 100000), LONG_MAX,
	    "iterations: LONG_MAX + max_iter saturates");
	test_int(rc_checkpoint_iterations_add(3, LONG_MAX), LONG_MAX,
	    "iterations: 3 + LONG_MAX saturates");
	test_int(rc_checkpoint_iterations_add(LONG_MAX, LONG_MAX), LONG_MAX,
	    "iterations: LONG_MAX + LONG_MAX saturates");
	test_int(rc_checkpoint_iterations_add(LONG_MAX / 2, LONG_MAX / 2),
	    LONG_MAX - 1, "iterations: 2 (LONG_MAX / 2) does not saturate");
	fill(&c, g);
	c.iterations = LONG_MAX;
	test_int(rc_checkpoint_write(&c, z, test_slot_path(0, "max.ck"), &err), 0,
	    "write with iterations LONG_MAX: %s", err.msg);
	test_int(rc_checkpoint_read(&back, &u, test_slot_path(0, "max.ck"), &err), 0,
	    "read it back: %s", err.msg);
	test_int(back.iterations, LONG_MAX, "iterations LONG_MAX back");
	test_int(rc_checkpoint_iterations_add(back.iterations, 1), LONG_MAX,
	    "... and resumed, saturate");
	rc_grid_free(u);
	rc_checkpoint_free(&back);
	rc_checkpoint_free(&c);
	rc_grid_free(g);
	free(z);
}

int
main(void)
{
	round_trip();
	saturation();
	identity();
	bad_files();
	return test_summary();
}
