/* SPDX-License-Identifier: GPL-3.0-or-later */
/* peakrss - run a command and report its peak resident set size.
 *
 *   peakrss [-o FILE] CMD [ARG...]
 *
 * Runs CMD (fork, execvp, wait4) and writes one line "PEAK_BYTES STATUS"
 * to FILE (default standard error): the peak RSS of CMD from wait4's
 * ru_maxrss (Linux counts it in KiB) and its exit status (128 + signal
 * number if it was killed).  Exits with CMD's status, 127 if it could not
 * be run.  A helper of bench/bench_memory.sh; it measures, it never judges.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

int
main(int argc, char **argv)
{
	const char *report = NULL;
	struct rusage ru;
	FILE *out = stderr;
	pid_t pid;
	int status, code, argi = 1;

	if (argc > 2 && strcmp(argv[1], "-o") == 0) {
		report = argv[2];
		argi = 3;
	}
	if (argi >= argc) {
		fprintf(stderr, "usage: peakrss [-o FILE] CMD [ARG...]\n");
		return 2;
	}
	if ((pid = fork()) < 0) {
		fprintf(stderr, "peakrss: fork: %s\n", strerror(errno));
		return 127;
	}
	if (pid == 0) {
		execvp(argv[argi], argv + argi);
		fprintf(stderr, "peakrss: %s: %s\n", argv[argi], strerror(errno));
		_exit(127);
	}
	while (wait4(pid, &status, 0, &ru) < 0)
		if (errno != EINTR) {
			fprintf(stderr, "peakrss: wait4: %s\n", strerror(errno));
			return 127;
		}
	code = WIFEXITED(status) ? WEXITSTATUS(status) :
	    WIFSIGNALED(status) ? 128 + WTERMSIG(status) : 127;
	if (report != NULL && (out = fopen(report, "w")) == NULL) {
		fprintf(stderr, "peakrss: %s: %s\n", report, strerror(errno));
		return 127;
	}
	fprintf(out, "%lld %d\n", (long long)ru.ru_maxrss * 1024, code);
	if (out != stderr && fclose(out) != 0) {
		fprintf(stderr, "peakrss: %s: write error\n", report);
		return 127;
	}
	return code;
}
