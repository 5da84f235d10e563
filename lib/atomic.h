/* atomic.h - write a file so that it is either complete or untouched.
 *
 * rc_atomic_open creates a temporary file next to the target (same
 * directory, so rename(2) is atomic); rc_atomic_commit flushes, fsyncs and
 * renames it over the target; rc_atomic_abort removes it.  An existing
 * target is never truncated before the new content is complete, and the
 * target may be the file being read.  A path of NULL or "-" writes to
 * standard output directly.
 */
#ifndef RC_ATOMIC_H
#define RC_ATOMIC_H

#include <stdio.h>
#include "rc_err.h"

typedef struct rc_atomic {
	FILE *fp;
	char *path;		/* target, NULL for stdout */
	char *tmp;		/* temporary file, NULL for stdout */
} rc_atomic;

int rc_atomic_open(rc_atomic *a, const char *path, rc_err *err);
int rc_atomic_commit(rc_atomic *a, rc_err *err);
void rc_atomic_abort(rc_atomic *a);
/* 1 if path means standard output. */
int rc_is_stdio(const char *path);

#endif
