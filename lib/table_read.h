/* SPDX-License-Identifier: GPL-3.0-or-later */
/* table_read.h - read result rows (TSV with one header line, or a JSON
 * array of flat objects) from any number of files into one table of named
 * columns.
 *
 * Every cell keeps its text and, when it is a number, its value: a TSV
 * field that strtod reads whole (nan and inf included), a JSON number, or
 * JSON null (NaN).  JSON strings and true/false are text, never numbers.  A
 * column absent from a row's file is absent in that row (NULL text).
 * Every row remembers its file and line.  Errors name file, line and
 * column ("name:line:col: why").  The reader accepts arbitrary bytes: it
 * fails cleanly on anything that is not one of the two formats.
 *
 * TSV: tab-separated, first non-blank line the header (distinct, non-empty
 * names), then rows with exactly as many fields; a trailing CR is dropped;
 * blank lines and lines starting with '#' are skipped; a line equal to the
 * header (files joined with cat) starts a new section with that header.
 * JSON: detected by '[' as the first non-blank character; objects whose
 * values are strings, numbers, true/false (kept as text) or null; several
 * arrays one after another (files joined with cat) are read as one.
 */
#ifndef RC_TABLE_READ_H
#define RC_TABLE_READ_H

#include <stdio.h>
#include "rc_err.h"

typedef struct rc_rowrec {
	const char *file;	/* the rowset's copy of the input's name */
	long line;		/* 1-based line of the row (JSON: of its '{') */
	size_t ncell;		/* cells for columns 0 .. ncell-1 */
	char **str;		/* NULL: column absent in this row */
	double *num;		/* NaN when not a number */
	unsigned char *isnum;	/* 1 if str parsed as a number */
} rc_rowrec;

typedef struct rc_rowset {
	size_t ncols;
	char **col;		/* union of the column names, first-seen order */
	size_t *colhash;	/* open-addressing index of col: entry k + 1 for
				 * column k, 0 empty; hashcap a power of two */
	size_t hashcap;
	size_t nrows, caprows;
	rc_rowrec *row;
	size_t nfiles;
	char **file;
	size_t nskipped;	/* rows dropped in lenient mode */
	char first_skip[RC_ERRLEN];	/* why the first one was dropped */
} rc_rowset;

void rc_rows_init(rc_rowset *rs);
void rc_rows_free(rc_rowset *rs);

/* Parse len bytes named name (for messages) and append their rows.
 * lenient: a malformed row (wrong field count, non-flat JSON value) is
 * skipped and counted instead of failing; syntax errors that lose the
 * structure (JSON) and a bad header still fail.  On failure the rowset
 * keeps the rows of earlier inputs only. */
int rc_rows_parse(rc_rowset *rs, const char *buf, size_t len,
    const char *name, int lenient, rc_err *err);
/* Read all of fp, then rc_rows_parse. */
int rc_rows_read(rc_rowset *rs, FILE *fp, const char *name, int lenient,
    rc_err *err);

/* Index of a column, -1 if no input has it. */
int rc_rows_column(const rc_rowset *rs, const char *name);
/* Cell text, NULL if absent (col < 0 allowed). */
const char *rc_rows_str(const rc_rowset *rs, size_t row, int col);
/* 0 and *v if the cell is a number, -1 if absent or not a number. */
int rc_rows_num(const rc_rowset *rs, size_t row, int col, double *v);

#endif
