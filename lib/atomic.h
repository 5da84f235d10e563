/* SPDX-License-Identifier: GPL-3.0-or-later */
/* atomic.h - write a file so that it is either complete or untouched,
 * without ever replacing what is not a regular file.
 *
 * What rc_atomic_open does depends on what the path names:
 * - NULL or "-": standard output, written directly.
 * - an existing regular file that is write-protected, or another user's
 *   in someone else's sticky directory (/tmp): refused (EACCES, or
 *   rename(2) could not replace it), as a shell's `>` refuses.
 * - a new name, or an existing regular file: a temporary file is created
 *   in the same directory (so rename(2) is atomic) and rc_atomic_commit
 *   flushes, fsyncs and renames it over the target.  An existing target is
 *   never truncated before the new content is complete, keeps its
 *   permission bits, and may be the file being read.
 * - a symbolic link: followed (also a dangling one) and the file it points
 *   to is treated as above; the link itself stays a link.
 * - /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N: the open
 *   descriptor N is written directly (duplicated), so a shell's `>>` or a
 *   pipe behaves as it would for any Unix tool.
 * - a character or block device, FIFO or socket: opened and written
 *   directly; write errors (ENOSPC on /dev/full) are reported by commit.
 *   Such a target can never be "untouched" if the writer fails half-way,
 *   and is never replaced or removed.
 * rc_atomic_abort removes the temporary file; a direct target is left as
 * it is.
 */
#ifndef RC_ATOMIC_H
#define RC_ATOMIC_H

#include <stdio.h>
#include "rc_err.h"

typedef struct rc_atomic {
	FILE *fp;
	char *path;		/* final target (links resolved); NULL for stdout */
	char *tmp;		/* temporary file; NULL when written directly */
	int direct;		/* 1: fp writes the target itself (device, FIFO, fd) */
} rc_atomic;

int rc_atomic_open(rc_atomic *a, const char *path, rc_err *err);
int rc_atomic_commit(rc_atomic *a, rc_err *err);
void rc_atomic_abort(rc_atomic *a);
/* 1 if path means standard output. */
int rc_is_stdio(const char *path);
/* 0 if rc_atomic_open(path) would find what it needs now, so that a tool
 * can refuse a bad output before hours of work: a non-empty name that is
 * not a directory; an open descriptor for /dev/fd/N; write permission on
 * an existing device, FIFO or socket; otherwise an existing directory
 * (after links) where this process may create the temporary file.
 * Creates nothing; -1 with err set otherwise. */
int rc_atomic_check(const char *path, rc_err *err);

/* Remove an output that is no longer wanted (a finished run's
 * checkpoint): the regular file path names, through links; a device,
 * FIFO or socket is left alone, and so is a missing file.  -1 with err set
 * if the removal fails. */
int rc_atomic_remove(const char *path, rc_err *err);

/* The temporary files of every rc_atomic still open in this process, for
 * a signal handler that must remove them before the process dies
 * (async-signal-safe: only unlink(2) on fixed buffers). */
int rc_atomic_unlink_pending(void);	/* returns how many were removed */
/* Add to those (and take out again) a temporary file made otherwise, such
 * as a script for a helper program; untrack after removing it. */
void rc_atomic_track(const char *tmp);
void rc_atomic_untrack(const char *tmp);

#endif
