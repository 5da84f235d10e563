/* table.h - result rows written as TSV (one header line) or JSON.
 *
 * Build a row with rc_row_num/int/str, then rc_table_write it.  The first
 * row fixes the columns; later rows must have the same names in the same
 * order.  TSV: tab-separated, one header line, numbers in the shortest form
 * that reads back exactly, NaN as "nan".  JSON: an array of objects, NaN
 * and infinities as null, metadata that is not a JSON number (Infinity,
 * +5, 0x10) as a string, control characters escaped and bytes that are
 * not UTF-8 as U+FFFD: always valid JSON (RFC 8259).
 */
#ifndef RC_TABLE_H
#define RC_TABLE_H

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
} rc_table_out;

void rc_table_begin(rc_table_out *t, FILE *fp, int json);
int rc_table_write(rc_table_out *t, const rc_row *r, rc_err *err);
/* Closes the JSON array; frees the header.  Does not close fp. */
int rc_table_end(rc_table_out *t, rc_err *err);

#endif
