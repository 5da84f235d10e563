/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_table_read.c - the result-row reader: TSV and JSON, union of columns,
 * file:line of every row, precise errors, lenient skipping, and random
 * garbage (every outcome must be a clean 0 or -1 with a message). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "table_read.h"
#include "testlib.h"

static int
parse(rc_rowset *rs, const char *text, const char *name, int lenient, rc_err *err)
{
	return rc_rows_parse(rs, text, strlen(text), name, lenient, err);
}

static double
num(const rc_rowset *rs, size_t row, const char *col)
{
	double v = -12345;
	if (rc_rows_num(rs, row, rc_rows_column(rs, col), &v) != 0)
		return -12345;
	return v;
}

static void
test_tsv(void)
{
	rc_rowset rs;
	rc_err err;

	rc_rows_init(&rs);
	test_int(parse(&rs, "p_star\ta_r\ttype\tseed\r\n"
	    "0.05\t0.1\tselfaffine\t3\r\n"
	    "\n"
	    "# a comment line\n"
	    "0.1\tnan\t\t0x10\n", "a.tsv", 0, &err), 0, "TSV parses");
	test_int((long long)rs.nrows, 2, "two rows");
	test_int((long long)rs.ncols, 4, "four columns");
	test_int(rs.row[0].line, 2, "first row on line 2");
	test_int(rs.row[1].line, 5, "second row on line 5 (blank and comment skipped)");
	test_true(strcmp(rs.row[1].file, "a.tsv") == 0, "row remembers its file");
	test_rel(num(&rs, 0, "p_star"), 0.05, 0, "number parsed");
	test_true(strcmp(rc_rows_str(&rs, 0, rc_rows_column(&rs, "seed")), "3") == 0,
	    "CR stripped from the last field");
	test_true(strcmp(rc_rows_str(&rs, 0, 2), "selfaffine") == 0, "string kept");
	double v;
	test_int(rc_rows_num(&rs, 0, 2, &v), -1, "a word is not a number");
	test_int(rc_rows_num(&rs, 1, 1, &v), 0, "nan is a number");
	test_true(isnan(v), "... and NaN");
	test_int(rc_rows_num(&rs, 1, 2, &v), -1, "an empty field is not a number");
	test_int(rc_rows_column(&rs, "nope"), -1, "unknown column");
	test_true(rc_rows_str(&rs, 0, -1) == NULL && rc_rows_str(&rs, 7, 0) == NULL,
	    "out-of-range cells are absent");

	/* A second file with other columns: union, absent cells. */
	test_int(parse(&rs, "p_star\tH\n0.2\t0.8\n", "b.tsv", 0, &err), 0, "second file");
	test_int((long long)rs.ncols, 5, "union of columns");
	test_true(rc_rows_str(&rs, 0, rc_rows_column(&rs, "H")) == NULL,
	    "column of file 2 absent in rows of file 1");
	test_true(rc_rows_str(&rs, 2, rc_rows_column(&rs, "a_r")) == NULL,
	    "column of file 1 absent in rows of file 2");
	test_rel(num(&rs, 2, "H"), 0.8, 0, "value of file 2");

	/* Joined with cat: the repeated header starts a new section. */
	test_int(parse(&rs, "x\ty\n1\t2\nx\ty\n3\t4\n", "cat.tsv", 0, &err), 0,
	    "repeated header accepted");
	test_int((long long)rs.nrows, 5, "rows of both sections");

	/* Errors name file and line; the rowset keeps what it had. */
	test_int(parse(&rs, "a\tb\n1\t2\n1\t2\t3\n", "bad.tsv", 0, &err), -1,
	    "wrong field count");
	test_true(strstr(err.msg, "bad.tsv:3:") != NULL && strstr(err.msg, "3 fields"),
	    "message names file:line and the count: %s", err.msg);
	test_int((long long)rs.nrows, 5, "failed input adds no rows");
	test_int(parse(&rs, "a\tb\ta\n", "dup.tsv", 0, &err), -1, "duplicate column");
	test_true(strstr(err.msg, "dup.tsv:1:") && strstr(err.msg, "duplicate"),
	    "duplicate named: %s", err.msg);
	test_int(parse(&rs, "a\t\tb\n", "empty.tsv", 0, &err), -1, "empty column name");
	test_true(strstr(err.msg, "field 2") != NULL, "field named: %s", err.msg);
	test_int(parse(&rs, "\n\n  \n", "blank.tsv", 0, &err), -1, "no header");
	test_true(strstr(err.msg, "blank.tsv") && strstr(err.msg, "no header"),
	    "empty input named: %s", err.msg);
	test_int(rc_rows_parse(&rs, "a\tb\n1\t\0\n", 9, "nul.tsv", 0, &err), -1,
	    "NUL byte refused");
	test_true(strstr(err.msg, "nul.tsv:2:") != NULL, "NUL line named: %s", err.msg);

	/* Lenient: the bad row is skipped and counted. */
	test_int(parse(&rs, "a\tb\n1\t2\n1\n3\t4\n", "len.tsv", 1, &err), 0,
	    "lenient parse");
	test_int((long long)rs.nskipped, 1, "one row skipped");
	test_true(strstr(rs.first_skip, "len.tsv:3:") != NULL, "skip reason: %s",
	    rs.first_skip);
	test_int((long long)rs.nrows, 7, "the two good rows kept");
	rc_rows_free(&rs);
}

static void
test_json(void)
{
	rc_rowset rs;
	rc_err err;

	rc_rows_init(&rs);
	test_int(parse(&rs, "\xef\xbb\xbf [\n"
	    "  {\"p_star\": 0.05, \"a_r\": 1e-1, \"type\": \"self\\u00e9\\t\", \"k\": null},\n"
	    "  {\"p_star\": -2.5E+2, \"ok\": true, \"s\": \"\\ud83d\\ude00\"}\n"
	    "]\n", "a.json", 0, &err), 0, "JSON parses: %s", err.msg);
	test_int((long long)rs.nrows, 2, "two objects");
	test_int(rs.row[0].line, 2, "first object on line 2");
	test_int(rs.row[1].line, 3, "second object on line 3");
	test_rel(num(&rs, 0, "a_r"), 0.1, 0, "exponent number");
	test_rel(num(&rs, 1, "p_star"), -250, 0, "negative exponent form");
	test_true(strcmp(rc_rows_str(&rs, 0, rc_rows_column(&rs, "type")),
	    "self\xc3\xa9\t") == 0, "\\u escape to UTF-8, \\t decoded");
	test_true(strcmp(rc_rows_str(&rs, 1, rc_rows_column(&rs, "s")),
	    "\xf0\x9f\x98\x80") == 0, "surrogate pair to 4-byte UTF-8");
	double v;
	test_int(rc_rows_num(&rs, 0, rc_rows_column(&rs, "k"), &v), 0, "null is a number");
	test_true(isnan(v), "... NaN");
	test_true(strcmp(rc_rows_str(&rs, 1, rc_rows_column(&rs, "ok")), "true") == 0,
	    "true kept as text");
	test_true(rc_rows_str(&rs, 1, rc_rows_column(&rs, "a_r")) == NULL,
	    "key missing in an object: absent");
	test_int(parse(&rs, "[]", "empty.json", 0, &err), 0, "empty array");
	test_int(parse(&rs, "[{\"q\": \"0.5\"}]", "str.json", 0, &err), 0, "string value");
	test_int(rc_rows_num(&rs, rs.nrows - 1, rc_rows_column(&rs, "q"), &v), -1,
	    "a JSON string is text, not a number (JSON is typed)");

	static const struct { const char *text, *where; } bad[] = {
		{ "[\n {\"a\": 1},\n]", "bad.json:3:1" },
		{ "[{\"a\": 1}", "bad.json:1:10" },
		{ "[{\"a\": \"x}]", "bad.json:1:" },
		{ "[{\"a\": 01}]", "bad.json:1:" },
		{ "[{\"a\": 1.}]", "bad.json:1:" },
		{ "[{\"a\": [1]}]", "bad.json:1:8" },
		{ "[{\"a\": 1, \"a\": 2}]", "bad.json:1:" },
		{ "[{\"a\": 1}] x", "bad.json:1:12" },
		{ "[{\"a\" 1}]", "bad.json:1:7" },
		{ "[{\"\": 1}]", "bad.json:1:" },
		{ "[{\"a\": \"\\u0000\"}]", "bad.json:1:" },
		{ "[{\"a\": \"\\ud800\"}]", "bad.json:1:" },
		{ "[{\"a\": tru}]", "bad.json:1:8" },
		{ "[\n\n 5]", "bad.json:3:2" },
		{ "[{\"a\\nb\": 1}]", "bad.json:1:" },
	};
	for (size_t i = 0; i < sizeof(bad) / sizeof(bad[0]); i++) {
		size_t before = rs.nrows;
		test_int(parse(&rs, bad[i].text, "bad.json", 0, &err), -1, "bad JSON %zu", i);
		test_true(strncmp(err.msg, bad[i].where, strlen(bad[i].where)) == 0,
		    "bad JSON %zu: message '%s' starts with %s", i, err.msg, bad[i].where);
		test_int((long long)rs.nrows, (long long)before, "bad JSON %zu adds no rows", i);
	}
	/* Lenient: a nested value drops its object only. */
	test_int(parse(&rs, "[{\"a\": 1}, {\"a\": {\"b\": [1, \"]\"]}}, {\"a\": 3}]",
	    "n.json", 1, &err), 0, "lenient nested");
	test_int((long long)rs.nskipped, 1, "nested object skipped");
	test_rel(num(&rs, rs.nrows - 1, "a"), 3, 0, "object after it read");
	rc_rows_free(&rs);
}

/* xorshift64*: reproducible garbage without library state. */
static uint64_t
next(uint64_t *s)
{
	*s ^= *s >> 12;
	*s ^= *s << 25;
	*s ^= *s >> 27;
	return *s * 2685821657736338717ULL;
}

static void
test_garbage(void)
{
	static const char *const seeds[] = {
		"p_star\ta_r\tseed\n0.05\t0.1\t1\n0.1\t0.2\t2\n",
		"[{\"p_star\": 0.05, \"a_r\": 0.1, \"s\": \"x\\u00e9\"}, {\"a_r\": null}]\n",
	};
	static const char soup[] = "[]{},:\"\\u0123456789eE+-.tfn \t\r\nabx";
	uint64_t s = 0x9e3779b97f4a7c15ULL;
	char buf[512];
	int ok = 1, nok = 0, nfail = 0;

	/* 6000 inputs: pure random bytes, token soup, and mutated valid files
	 * (random byte flips, truncations).  Each parse must return 0 or -1;
	 * a failure must leave a message naming the input. */
	for (int k = 0; k < 6000; k++) {
		size_t n = next(&s) % sizeof(buf);
		int kind = k % 3;
		if (kind == 0)
			for (size_t i = 0; i < n; i++)
				buf[i] = (char)(next(&s) & 0xff);
		else if (kind == 1)
			for (size_t i = 0; i < n; i++)
				buf[i] = soup[next(&s) % (sizeof(soup) - 1)];
		else {
			const char *v = seeds[next(&s) % 2];
			n = strlen(v);
			memcpy(buf, v, n);
			int flips = 1 + (int)(next(&s) % 4);
			for (int f = 0; f < flips; f++)
				buf[next(&s) % n] = (char)(next(&s) & 0xff);
			n = next(&s) % 4 == 0 ? next(&s) % n : n;
		}
		rc_rowset rs;
		rc_err err;
		rc_rows_init(&rs);
		err.msg[0] = '\0';
		int rc = rc_rows_parse(&rs, buf, n, "fuzz", k % 2, &err);
		if (rc == 0)
			nok++;
		else if (rc == -1 && strncmp(err.msg, "fuzz", 4) == 0 && rs.nrows == 0)
			nfail++;
		else
			ok = 0;
		rc_rows_free(&rs);
	}
	test_true(ok, "garbage: every parse returned 0, or -1 with a named message");
	/* Both outcomes occur (else the generator tests nothing). */
	test_true(nok > 100 && nfail > 100, "garbage: %d accepted, %d refused", nok, nfail);
}

int
main(void)
{
	test_tsv();
	test_json();
	test_garbage();
	return test_summary();
}
