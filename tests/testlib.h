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

#include <stddef.h>

#include "grid.h"

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
/* The path of file name in it; the last four results stay valid. */
const char *test_path(const char *name);
/* The same in slot 0 ... 3, which stays valid until that slot is used
 * again. */
const char *test_slot_path(int slot, const char *name);
/* The path of file name in tests/data ($RC_TOP, else the current
 * directory, is the top of the tree); valid until the next call. */
const char *test_data_path(const char *name);
/* Write n bytes to path (abort on failure: set-up, not the test). */
void test_put_file(const char *path, const void *p, size_t n);
/* rc_grid_new, the program ended after a message when it fails. */
rc_grid *test_new_grid(size_t nx, size_t ny, double lx, double ly);

#endif
