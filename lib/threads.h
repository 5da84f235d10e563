/* threads.h - how many threads to use when the user did not say, and how
 * idle OpenMP threads wait.
 *
 * Waiting.  An OpenMP thread that reaches the end of a parallel region
 * before the others spins (libgomp: some 300000 polls) unless
 * OMP_WAIT_POLICY=passive.  On a machine where other processes compete
 * for the cores, a spinning thread holds a core the descheduled thread it
 * waits for needs, and every region stalls: a 512^2 FIRE solve with one
 * busy competitor took 5 to 40 times as long with two spinning threads as
 * with -j 1 (roughcontact(7), RUNNING LARGE PROBLEMS).  libgomp reads the
 * policy once, when it is loaded, before main runs, so a program linking
 * this file (anything that calls rc_fft_set_threads) sets
 * OMP_WAIT_POLICY=passive from the ELF pre-initialisation array, which
 * glibc runs before any shared library's constructor.  A policy the user
 * set is kept.  The variable is set for libgomp's start-up only: glibc
 * hands main and child processes the environment the program was started
 * with.  Passive waiting costs a futex wake per region on an idle
 * machine (measured: within the noise of the benchmark, bench_gfmd).
 *
 * Count.  rc_threads_auto is the count when neither the caller (-j) nor
 * OMP_NUM_THREADS gave one: 1 inside a parallel make (MAKEFLAGS holds -j
 * or a jobserver: each job there is one of make's slots, so the jobs
 * together already fill the cores), else the cores this process may run
 * on (its affinity mask).
 */
#ifndef RC_THREADS_H
#define RC_THREADS_H

int rc_threads_auto(void);

/* 1 if the make flags string (MAKEFLAGS) asks for parallel jobs: a word
 * -j (unlimited), -jN with N > 1, or --jobserver-auth= / --jobserver-fds=
 * (a jobserver exists only for N > 1); words after "--" are variable
 * assignments and are not read.  NULL: 0. */
int rc_threads_parallel_make(const char *makeflags);

#endif
