/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_read.c - libFuzzer harness for every grid reader.
 *
 * The input goes through the format detector twice: from memory (a stream
 * of unknown size, as a pipe) and from a regular file (whose size the
 * reader checks before allocating).  Besides crashes, leaks, sanitizer
 * reports, hangs and allocations beyond -malloc_limit_mb, the harness
 * aborts when a reader breaks its contract: a failure without a one-line
 * message, a grid with a bad shape, an infinite value or a NaN that is
 * not flagged missing, or the two
 * paths disagreeing (one accepts what the other rejects, or different
 * values).  `make fuzz` builds and runs it (see the Makefile); a crashing
 * input is kept under tests/data/fuzz/read/, which test_fuzz_replay
 * feeds to this same function in `make check`.
 *
 * Gwyddion is turned off (RC_GWYDDION empty): the harness tests our
 * readers, not Gwyddion's, and runs no programs.
 *
 * FUZZ_ENTRY names the entry point: LLVMFuzzerTestOneInput for libFuzzer,
 * something else when the replay test includes this file.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "io.h"

#ifndef FUZZ_ENTRY
#define FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif

int FUZZ_ENTRY(const uint8_t *data, size_t size);

/* A failed read must say why, on one line. */
static void
read_check_failure(const rc_err *err)
{
	if (err->msg[0] == '\0' || strchr(err->msg, '\n') != NULL)
		abort();
}

static void
read_check_grid(const rc_grid *g)
{
	size_t n;

	if (g->nx < 1 || g->ny < 1 || !(g->lx > 0) || !(g->ly > 0) ||
	    !isfinite(g->lx) || !isfinite(g->ly))
		abort();
	n = g->nx * g->ny;
	if (n / g->nx != g->ny)
		abort();
	/* A NaN is a missing point, flagged as one; nothing else is not
	 * finite. */
	for (size_t k = 0; k < n; k++)
		if (isnan(g->z[k]) ? g->valid == NULL || g->valid[k] != 0 :
		    !isfinite(g->z[k]) || (g->valid != NULL && g->valid[k] != 1))
			abort();
	if (g->periodic != 0 && g->periodic != 1)
		abort();
}

int
FUZZ_ENTRY(const uint8_t *data, size_t size)
{
	/* -L 2x3: formats without a cell size get it; others ignore it. */
	rc_read_opts o = { .lx = 2, .ly = 3, .have_l = 1, .allow_nonfinite = 0 };
	char path[] = "/tmp/fuzz_read.XXXXXX";
	rc_grid *from_mem = NULL, *from_file = NULL;
	int mem_tried = 0, file_tried = 0;
	rc_err err;
	FILE *fp;
	int fd;

	if (size == 0)
		return 0;
	setenv("RC_GWYDDION", "", 1);
	if ((fp = fmemopen((void *)data, size, "rb")) != NULL) {
		mem_tried = 1;
		err.msg[0] = '\0';
		if ((from_mem = rc_grid_read_stream(fp, &o, &err)) == NULL)
			read_check_failure(&err);
		else
			read_check_grid(from_mem);
		fclose(fp);
	}
	if ((fd = mkstemp(path)) >= 0) {
		if (write(fd, data, size) == (ssize_t)size) {
			file_tried = 1;
			err.msg[0] = '\0';
			if ((from_file = rc_grid_read(path, &o, &err)) == NULL)
				read_check_failure(&err);
			else
				read_check_grid(from_file);
		}
		close(fd);
		unlink(path);
	}
	if (mem_tried && file_tried) {
		if ((from_mem == NULL) != (from_file == NULL))
			abort();
		if (from_mem != NULL && (from_mem->nx != from_file->nx ||
		    from_mem->ny != from_file->ny || from_mem->lx != from_file->lx ||
		    from_mem->ly != from_file->ly || memcmp(from_mem->z, from_file->z,
		    from_mem->nx * from_mem->ny * sizeof(double)) != 0 ||
		    (from_mem->valid == NULL) != (from_file->valid == NULL) ||
		    from_mem->periodic != from_file->periodic ||
		    strcmp(from_mem->unit, from_file->unit) != 0 ||
		    strcmp(from_mem->z_unit, from_file->z_unit) != 0))
			abort();
	}
	rc_grid_free(from_mem);
	rc_grid_free(from_file);
	return 0;
}
