/* threads.c - default thread count and OpenMP wait policy (see threads.h). */
#include "threads.h"

#include <stdlib.h>
#include <string.h>
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

/* Passive waiting (threads.h).  Only in an executable: a shared object may
 * not have a pre-initialisation array (-fPIC without -fPIE). */
#if defined(_OPENMP) && defined(__ELF__) && defined(__linux__) && \
    (!defined(__PIC__) || defined(__PIE__))
static void
wait_passively(int argc, char **argv, char **envp)
{
	(void)argc;
	(void)argv;
	(void)envp;
	setenv("OMP_WAIT_POLICY", "passive", 0);
}

__attribute__((section(".preinit_array"), used))
static void (*const rc_threads_preinit)(int, char **, char **) = wait_passively;
#endif
