/* SPDX-License-Identifier: GPL-3.0-or-later */
/* threads.c - default thread count and OpenMP wait policy (see threads.h). */
#include "threads.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

int
rc_threads_parallel_make(const char *flags)
{
	const char *p = flags;

	if (p == NULL)
		return 0;
	while (*p != '\0') {
		size_t len;

		while (*p == ' ')
			p++;
		len = strcspn(p, " ");
		if (len == 0)
			break;
		if (len == 2 && strncmp(p, "--", 2) == 0)
			return 0;
		if (strncmp(p, "--jobserver-auth=", 17) == 0 ||
		    strncmp(p, "--jobserver-fds=", 16) == 0)
			return 1;
		if (len >= 2 && p[0] == '-' && p[1] == 'j') {
			char *end;
			long n;

			if (len == 2)
				return 1;
			n = strtol(p + 2, &end, 10);
			if ((size_t)(end - p) == len && n > 1)
				return 1;
		}
		p += len;
	}
	return 0;
}

int
rc_threads_auto(void)
{
	if (rc_threads_parallel_make(getenv("MAKEFLAGS")))
		return 1;
#ifdef _OPENMP
	return omp_get_num_procs();	/* the affinity mask's CPUs */
#else
	return 1;
#endif
}

int
rc_threads_wait_passively(int threads, char **argv)
{
#ifdef _OPENMP
	const char *again = getenv(RC_THREADS_REEXEC_ENV);
	int tunables = getenv("GLIBC_TUNABLES") == NULL;

	if (threads <= 1 || getenv("OMP_WAIT_POLICY") != NULL) {
		/* restarted: the malloc tunable was for this program only */
		if (again != NULL && strcmp(again, "tunables") == 0)
			unsetenv("GLIBC_TUNABLES");
		return 0;
	}
	if (setenv("OMP_WAIT_POLICY", "passive", 1) != 0 ||
	    (tunables && setenv("GLIBC_TUNABLES", "glibc.malloc.hugetlb=1",
	    1) != 0) || setenv(RC_THREADS_REEXEC_ENV, tunables ? "tunables" :
	    "1", 1) != 0)
		return -1;
	execv("/proc/self/exe", argv);
	unsetenv(RC_THREADS_REEXEC_ENV);
	if (tunables)
		unsetenv("GLIBC_TUNABLES");
	return -1;	/* no /proc: run on, as before */
#else
	(void)threads;
	(void)argv;
	return 0;
#endif
}
