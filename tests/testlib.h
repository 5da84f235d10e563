/* SPDX-License-Identifier: GPL-3.0-or-later */
/* testlib.h - GSL-style checks for the C tests.
 *
 * Each check prints nothing when it passes (unless TEST_VERBOSE is set)
 * and "FAIL: description: observed ..., expected ..." when it fails.
 * test_summary() prints "N passed, N failed" (", N skipped" added when
 * test_skip counted checks that cannot run here) and returns the exit
 * status.
 */
#ifndef RC_TESTLIB_H
#define RC_TESTLIB_H

/* |obs - exp| <= reltol * |exp|  (exp == 0: |obs| <= reltol). */
void test_rel(double obs, double exp, double reltol, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
/* |obs - exp| <= abstol. */
void test_abs(double obs, double exp, double abstol, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
/* lo <= obs <= hi. */
void test_range(double obs, double lo, double hi, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
void test_true(int cond, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* Integer equality. */
void test_int(long long obs, long long exp, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* n checks that cannot run here: "SKIP: n check(s): reason". */
void test_skip(int n, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
int test_summary(void);

/* A temporary directory for the test's files, removed by test_summary. */
const char *test_tmpdir(void);

#endif
