/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_threads.c - the default thread count (lib/threads.h): one thread
 * inside a parallel make, OMP_NUM_THREADS and -j above that; the wait
 * policy set before libgomp started. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "testlib.h"
#include "threads.h"

/* MAKEFLAGS as GNU make 4.3 and 4.4 hand them to a recipe (the first word
 * holds single-letter flags without a dash). */
static void
test_makeflags(void)
{
	static const struct {
		const char *flags;
		int parallel;
	} cases[] = {
		{ NULL, 0 },
		{ "", 0 },
		{ "s", 0 },
		{ "s -j1", 0 },
		{ " -j1", 0 },
		{ "s -j2 --jobserver-auth=3,4", 1 },
		{ "ks -j2 --jobserver-auth=3,4", 1 },
		{ " -j8 --jobserver-auth=fifo:/tmp/GMfifo123", 1 },
		{ " -j4 --jobserver-fds=3,4", 1 },
		{ "s -j", 1 },
		{ "-j16", 1 },
		{ "s -- CFLAGS=-j2", 0 },
		{ "s -jx", 0 },
		{ "s -- X=--jobserver-auth=3,4", 0 },
	};

	for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++)
		test_int(rc_threads_parallel_make(cases[c].flags), cases[c].parallel,
		    "MAKEFLAGS \"%s\"", cases[c].flags ? cases[c].flags : "(unset)");
}

/* Precedence: -j, then OMP_NUM_THREADS, then 1 inside a parallel make,
 * then the cores. */
static void
test_precedence(void)
{
	unsetenv("OMP_NUM_THREADS");
	setenv("MAKEFLAGS", "s -j2 --jobserver-auth=3,4", 1);
	test_int(rc_threads_auto(), 1, "parallel make: one thread");
	test_int(rc_fft_set_threads(0), 1, "default inside a parallel make");
	test_int(rc_fft_set_threads(2), 2, "-j 2 inside a parallel make");
	setenv("OMP_NUM_THREADS", "2", 1);
	test_int(rc_fft_set_threads(0), 2, "OMP_NUM_THREADS=2 inside a parallel make");
	unsetenv("OMP_NUM_THREADS");
	setenv("MAKEFLAGS", "s", 1);
	test_range(rc_threads_auto(), 1, 4096, "serial make: the cores (%d)",
	    rc_threads_auto());
	unsetenv("MAKEFLAGS");
	rc_fft_set_threads(1);
}

int
main(void)
{
	test_makeflags();
	test_precedence();
	return test_summary();
}
