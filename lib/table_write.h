/* SPDX-License-Identifier: GPL-3.0-or-later */
/* table_write.h - result rows written as TSV (one header line) or JSON.
 *
 * Build a row with rc_row_num/int/str, then rc_table_write it.  The first
 * row fixes the columns; later rows must have the same names in the same
 * order.  TSV: tab-separated, one header line, numbers in the shortest form
 * that reads back exactly, NaN as "nan".  JSON: an array of objects, NaN
 * and infinities as null, metadata that is not a JSON number (Infinity,
 * +5, 0x10) as a string, control characters escaped and bytes that are
 * not UTF-8 as U+FFFD: always valid JSON (RFC 8259).
 */
#ifndef RC_TABLE_WRITE_H
#define RC_TABLE_WRITE_H

#include <stdio.h>
#include "grid.h"
#include "rc_err.h"

typedef struct rc_row {
	size_t n, cap;
	char **name;
	char **val;
	unsigned char *is_str;
} rc_row;

void rc_row_init(rc_row *r);
void rc_row_clear(rc_row *r);	/* keep the allocation, drop the cells */
void rc_row_free(rc_row *r);
int rc_row_num(rc_row *r, const char *name, double v);
int rc_row_int(rc_row *r, const char *name, long long v);
int rc_row_str(rc_row *r, const char *name, const char *v);
/* Append the grid's metadata (generation parameters) as string-or-number
 * columns, skipping names already in the row. */
int rc_row_meta(rc_row *r, const rc_grid *g);

typedef struct rc_table_out {
	FILE *fp;
	int json;
	size_t nrows;
	size_t ncols;
	char **header;
	struct rc_table_kept *kept;	/* rows of the pretty view, or NULL */
	size_t pretty_width;
} rc_table_out;

void rc_table_begin(rc_table_out *t, FILE *fp, int json);
int rc_table_write(rc_table_out *t, const rc_row *r, rc_err *err);
/* Closes the JSON array; frees the header.  Does not close fp. */
int rc_table_end(rc_table_out *t, rc_err *err);

/* The pretty view, for a person at a terminal (table_pretty.c): after
 * rc_table_begin (not JSON), rows are kept and rc_table_end draws them
 * aligned, numbers rounded to 4 significant digits (integers whole), a
 * rule under the header; a table wider than `width` characters (0 = 80)
 * is drawn transposed, one line per column.  Not for reading back. */
int rc_table_pretty(rc_table_out *t, size_t width, rc_err *err);
int rc_table_keep_pretty(rc_table_out *t, const rc_row *r, rc_err *err);
int rc_table_write_pretty(rc_table_out *t, rc_err *err);

#endif
