/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_rows.c - libFuzzer harness for contact-stats' row parser
 * (table_read.h).
 *
 * The input is parsed strictly, leniently, a second time into the same
 * rowset (as a second file is) and through rc_rows_read from a stream.
 * Besides crashes, leaks, sanitizer reports and hangs, the harness aborts
 * when the parser breaks its contract: a failure without a one-line
 * message; a rowset whose columns are not distinct or not found by
 * rc_rows_column; a cell whose number flag disagrees with rc_rows_num; a
 * strict success that lenient mode does not repeat row for row; a failed
 * second file that does not leave the first one's rows as they were; the
 * stream and memory paths disagreeing.  `make fuzz` builds and runs it; a
 * crashing input is kept under tests/data/fuzz/rows/, which
 * test_fuzz_replay feeds to this same function in `make check`.
 *
 * FUZZ_ENTRY names the entry point: LLVMFuzzerTestOneInput for libFuzzer,
 * something else when the replay test includes this file.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "table_read.h"

#ifndef FUZZ_ENTRY
#define FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif

int FUZZ_ENTRY(const uint8_t *data, size_t size);

static void
rows_check_failure(const rc_err *err)
{
	if (err->msg[0] == '\0' || strchr(err->msg, '\n') != NULL)
		abort();
}

static void
rows_check_set(const rc_rowset *rs)
{
	double v;

	for (size_t c = 0; c < rs->ncols; c++) {
		if (rs->col[c] == NULL || rs->col[c][0] == '\0' ||
		    rc_rows_column(rs, rs->col[c]) != (int)c)
			abort();
	}
	for (size_t r = 0; r < rs->nrows; r++) {
		const rc_rowrec *row = &rs->row[r];

		if (row->file == NULL || row->line < 1 || row->ncell > rs->ncols)
			abort();
		for (size_t c = 0; c < rs->ncols; c++) {
			const char *s = rc_rows_str(rs, r, (int)c);
			int isnum = c < row->ncell && s != NULL && row->isnum[c];

			if ((rc_rows_num(rs, r, (int)c, &v) == 0) != isnum)
				abort();
			if (!isnum && c < row->ncell && !isnan(row->num[c]))
				abort();
		}
	}
	if (rc_rows_str(rs, rs->nrows, 0) != NULL || rc_rows_str(rs, 0, -1) != NULL)
		abort();
}

/* Same number of rows with the same texts. */
static void
rows_check_same(const rc_rowset *a, size_t a0, const rc_rowset *b, size_t b0,
    size_t n)
{
	for (size_t r = 0; r < n; r++)
		for (size_t c = 0; c < a->ncols; c++) {
			const char *sa = rc_rows_str(a, a0 + r, (int)c);
			const char *sb = rc_rows_str(b, b0 + r,
			    rc_rows_column(b, a->col[c]));

			if ((sa == NULL) != (sb == NULL) ||
			    (sa != NULL && strcmp(sa, sb) != 0))
				abort();
		}
}

int
FUZZ_ENTRY(const uint8_t *data, size_t size)
{
	rc_rowset strict, lenient, stream;
	const char *buf = (const char *)data;
	size_t n1;
	int ok, ok2;
	rc_err err;
	FILE *fp;

	rc_rows_init(&strict);
	rc_rows_init(&lenient);
	rc_rows_init(&stream);

	err.msg[0] = '\0';
	ok = rc_rows_parse(&strict, buf, size, "fuzz", 0, &err) == 0;
	if (!ok) {
		rows_check_failure(&err);
		if (strict.nrows != 0)
			abort();
	}
	rows_check_set(&strict);
	n1 = strict.nrows;

	err.msg[0] = '\0';
	if (rc_rows_parse(&lenient, buf, size, "fuzz", 1, &err) == 0) {
		rows_check_set(&lenient);
		if (ok && (lenient.nrows != n1 || lenient.nskipped != 0))
			abort();
		if (ok)
			rows_check_same(&strict, 0, &lenient, 0, n1);
	} else {
		rows_check_failure(&err);
		if (ok)		/* lenient fails only where strict does */
			abort();
	}

	/* The same bytes as a second file: same verdict, first rows kept. */
	err.msg[0] = '\0';
	ok2 = rc_rows_parse(&strict, buf, size, "fuzz2", 0, &err) == 0;
	if (ok2 != ok)
		abort();
	if (!ok2)
		rows_check_failure(&err);
	if (strict.nrows != (ok ? 2 * n1 : 0))
		abort();
	rows_check_set(&strict);
	if (ok)
		rows_check_same(&strict, 0, &strict, n1, n1);

	/* fmemopen refuses size 0. */
	if (size > 0 && (fp = fmemopen((void *)data, size, "rb")) != NULL) {
		err.msg[0] = '\0';
		if (rc_rows_read(&stream, fp, "fuzz", 0, &err) == 0) {
			if (!ok || stream.nrows != n1)
				abort();
			rows_check_same(&stream, 0, &strict, 0, n1);
		} else {
			rows_check_failure(&err);
			if (ok)
				abort();
		}
		fclose(fp);
	}
	rc_rows_free(&strict);
	rc_rows_free(&lenient);
	rc_rows_free(&stream);
	return 0;
}
