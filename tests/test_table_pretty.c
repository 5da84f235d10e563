/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_table_pretty.c - the terminal view of result tables (lib/
 * table_pretty.c): exact text for a small table in columns and
 * transposed, rounding, whole integers, alignment, control characters,
 * UTF-8 width; and that a table without the view stays exact TSV. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "table_write.h"
#include "testlib.h"

/* Write rows of (p, n, method, k = row number) through the view of the given width
 * (0: no view, TSV); returns the text (malloc'ed). */
static char *
render(size_t width, int pretty, size_t nrows, const double *p,
    const long long *n, const char *const *method)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *fp = open_memstream(&buf, &len);
	rc_table_out t;
	rc_row r;
	rc_err err;

	rc_table_begin(&t, fp, 0);
	if (pretty && rc_table_pretty(&t, width, &err) != 0)
		return NULL;
	rc_row_init(&r);
	for (size_t i = 0; i < nrows; i++) {
		rc_row_clear(&r);
		rc_row_num(&r, "p", p[i]);
		rc_row_int(&r, "n", n[i]);
		rc_row_str(&r, "method", method[i]);
		rc_row_int(&r, "k", (long long)i + 1);
		if (rc_table_write(&t, &r, &err) != 0)
			return NULL;
	}
	rc_table_end(&t, &err);
	rc_row_free(&r);
	fclose(fp);
	return buf;
}

int
main(void)
{
	const double p[] = { 0.0123456789, -12345.678 };
	const long long n[] = { 1234567, 5 };
	const char *const method[] = { "fire", "cg\tx" };
	char *s;

	/* Columns: numbers right-aligned under right-aligned headers, rounded
	 * to 4 digits; integers whole; text left-aligned, no trailing blanks;
	 * a tab in a cell shown as a space. */
	s = render(80, 1, 2, p, n, method);
	test_true(s && strcmp(s,
	    "         p        n  method  k\n"
	    "------------------------------\n"
	    "   0.01235  1234567  fire    1\n"
	    "-1.235e+04        5  cg x    2\n") == 0, "columns view:\n%s", s);
	free(s);
	/* Narrower than the table (30 characters): transposed, one line per
	 * column, rows side by side as they fit (6 + 2 + 7 + 2 + 10 = 27). */
	s = render(28, 1, 2, p, n, method);
	test_true(s && strcmp(s,
	    "          row 1       row 2\n"
	    "---------------------------\n"
	    "p       0.01235  -1.235e+04\n"
	    "n       1234567           5\n"
	    "method     fire        cg x\n"
	    "k             1           2\n") == 0, "transposed view:\n%s", s);
	free(s);
	/* Too narrow for two rows: one row per block. */
	s = render(20, 1, 2, p, n, method);
	test_true(s && strcmp(s,
	    "          row 1\n"
	    "---------------\n"
	    "p       0.01235\n"
	    "n       1234567\n"
	    "method     fire\n"
	    "k             1\n"
	    "\n"
	    "             row 2\n"
	    "------------------\n"
	    "p       -1.235e+04\n"
	    "n                5\n"
	    "method        cg x\n"
	    "k                2\n") == 0, "one row per block:\n%s", s);
	free(s);
	/* One row, narrow: name and value, no row label. */
	s = render(10, 1, 1, p, n, method);
	test_true(s && strcmp(s,
	    "p       0.01235\n"
	    "n       1234567\n"
	    "method     fire\n"
	    "k             1\n") == 0, "single row transposed:\n%s", s);
	free(s);
	/* UTF-8 text takes one column per character. */
	{
		const char *const m2[] = { "\xce\xbc" "m", "ab" };
		s = render(80, 1, 2, p, n, m2);
		test_true(s && strstr(s, "  method  k\n") &&
		    strstr(s, "  \xce\xbc" "m      1\n") &&
		    strstr(s, "  ab      2\n"), "UTF-8 cell width:\n%s", s);
		free(s);
	}
	/* Without the view: the exact TSV, shortest round-trip numbers. */
	s = render(0, 0, 2, p, n, method);
	test_true(s && strcmp(s,
	    "p\tn\tmethod\tk\n"
	    "0.0123456789\t1234567\tfire\t1\n"
	    "-12345.678\t5\tcg x\t2\n") == 0, "TSV unchanged:\n%s", s);
	free(s);
	return test_summary();
}
