/* SPDX-License-Identifier: GPL-3.0-or-later */
/* testlib.c - counters and messages for the C tests. */
#define _GNU_SOURCE
#include "testlib.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int npassed, nfailed, nskipped;
static char tmpdir[256];

static void
report(int ok, const char *detail, const char *fmt, va_list ap)
{
	if (ok) {
		npassed++;
		if (getenv("TEST_VERBOSE") == NULL)
			return;
		fputs("PASS: ", stdout);
	} else {
		nfailed++;
		fputs("FAIL: ", stdout);
	}
	vprintf(fmt, ap);
	if (detail[0])
		printf(": %s", detail);
	putchar('\n');
	fflush(stdout);
}

void
test_rel(double obs, double exp, double reltol, const char *fmt, ...)
{
	char detail[256];
	double err = fabs(obs - exp), scale = exp == 0 ? 1 : fabs(exp);
	int ok = isfinite(obs) ? err <= reltol * scale : obs == exp;
	va_list ap;

	snprintf(detail, sizeof(detail),
	    "observed %.17g, expected %.17g, relative error %.3g, tolerance %.3g",
	    obs, exp, err / scale, reltol);
	va_start(ap, fmt);
	report(ok, detail, fmt, ap);
	va_end(ap);
}

void
test_abs(double obs, double exp, double abstol, const char *fmt, ...)
{
	char detail[256];
	int ok = fabs(obs - exp) <= abstol;
	va_list ap;

	snprintf(detail, sizeof(detail),
	    "observed %.17g, expected %.17g, error %.3g, tolerance %.3g",
	    obs, exp, fabs(obs - exp), abstol);
	va_start(ap, fmt);
	report(ok, detail, fmt, ap);
	va_end(ap);
}

void
test_range(double obs, double lo, double hi, const char *fmt, ...)
{
	char detail[256];
	int ok = obs >= lo && obs <= hi;
	va_list ap;

	snprintf(detail, sizeof(detail), "observed %.17g, expected in [%.17g, %.17g]",
	    obs, lo, hi);
	va_start(ap, fmt);
	report(ok, detail, fmt, ap);
	va_end(ap);
}

void
test_true(int cond, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	report(cond, "", fmt, ap);
	va_end(ap);
}

void
test_int(long long obs, long long exp, const char *fmt, ...)
{
	char detail[128];
	va_list ap;

	snprintf(detail, sizeof(detail), "observed %lld, expected %lld", obs, exp);
	va_start(ap, fmt);
	report(obs == exp, detail, fmt, ap);
	va_end(ap);
}

const char *
test_tmpdir(void)
{
	if (tmpdir[0] == '\0') {
		const char *base = getenv("TMPDIR");
		snprintf(tmpdir, sizeof(tmpdir), "%s/rctest.XXXXXX", base ? base : "/tmp");
		if (mkdtemp(tmpdir) == NULL) {
			perror("mkdtemp");
			exit(1);
		}
	}
	return tmpdir;
}

const char *
test_path(const char *name)
{
	static char path[4][512];
	static int k;

	k = (k + 1) % 4;
	snprintf(path[k], sizeof(path[k]), "%s/%s", test_tmpdir(), name);
	return path[k];
}

const char *
test_slot_path(int slot, const char *name)
{
	static char path[4][512];

	snprintf(path[slot], sizeof(path[slot]), "%s/%s", test_tmpdir(), name);
	return path[slot];
}

void
test_put_file(const char *path, const void *p, size_t n)
{
	FILE *fp = fopen(path, "wb");

	if (fp == NULL || fwrite(p, 1, n, fp) != n)
		abort();
	fclose(fp);
}

rc_grid *
test_new_grid(size_t nx, size_t ny, double lx, double ly)
{
	rc_err err;
	rc_grid *g = rc_grid_new(nx, ny, lx, ly, &err);

	if (g == NULL) {
		fprintf(stderr, "rc_grid_new: %s\n", err.msg);
		exit(1);
	}
	return g;
}

void
test_skip(int n, const char *fmt, ...)
{
	va_list ap;

	nskipped += n;
	printf("SKIP: %d check(s): ", n);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	putchar('\n');
	fflush(stdout);
}

int
test_summary(void)
{
	if (tmpdir[0] != '\0') {
		char cmd[300];
		snprintf(cmd, sizeof(cmd), "rm -rf '%s'", tmpdir);
		if (system(cmd) != 0)
			fprintf(stderr, "could not remove %s\n", tmpdir);
	}
	if (nskipped)
		printf("%d passed, %d failed, %d skipped\n", npassed, nfailed,
		    nskipped);
	else
		printf("%d passed, %d failed\n", npassed, nfailed);
	return nfailed ? 1 : 0;
}

const char *
test_data_path(const char *name)
{
	static char path[1024];
	const char *top = getenv("RC_TOP");

	snprintf(path, sizeof(path), "%s/tests/data/%s", top ? top : ".", name);
	return path;
}
