/* SPDX-License-Identifier: GPL-3.0-or-later */
/* threads.h - how many threads to use when the user did not say, and how
 * idle OpenMP threads wait.
 *
 * Waiting.  An OpenMP thread that reaches the end of a parallel region
 * before the others spins (libgomp: 300000 polls, some milliseconds)
 * unless OMP_WAIT_POLICY=passive.  On a machine where other processes
 * compete for the cores, a spinning thread holds a core that the
 * descheduled thread it waits for needs, and every region stalls: see
 * roughcontact(7), RUNNING LARGE PROBLEMS, for the measured cost.  libgomp
 * reads the policy once, when it is loaded, before main runs; setting it
 * from main is too late, and so is glibc's pre-initialisation array
 * (measured: the variable set there is gone again when libgomp reads the
 * environment).  So rc_threads_wait_passively, called once the thread
 * count is known (rc_fft_set_threads' result) and before any input is
 * read or output written, sets OMP_WAIT_POLICY=passive and executes the
 * program again (/proc/self/exe, the arguments main was given, the same
 * process id and open files).  Unless the user set GLIBC_TUNABLES, the
 * restart also sets glibc.malloc.hugetlb=1 (glibc >= 2.35; older ones
 * ignore it), so that malloc asks for transparent huge pages on its large
 * blocks (those rc_fft_huge does not place, fft.h): a first touch
 * faults once per 2 MB instead of once per 4 kB (on this project's
 * virtual machine a 4 kB fault costs about 13 us; a 512^2 gfmd-solve
 * outside its iterations: 2870 faults and 92 ms of CPU without it, 1256
 * and 71 ms with it; perf stat, medians of 7; its peak resident size 1.2
 * MB larger).  The restarted program removes that variable again, so the
 * programs it runs do not inherit it.  Nothing happens for one thread (no team,
 * nothing spins: so -j 1 and runs under make -j N start once) or when the
 * user set a policy.  Returns 0 then, -1 if it could not execute (no
 * /proc: the program runs on with libgomp's default); otherwise it does
 * not return.  Not for MPI programs after MPI_Init.
 *
 * Count.  rc_threads_auto is the count when neither the caller (-j) nor
 * OMP_NUM_THREADS gave one: 1 inside a parallel make (MAKEFLAGS holds -j
 * or a jobserver: each job there is one of make's slots, so the jobs
 * together already fill the cores), else the cores this process may run
 * on (its affinity mask).
 */
#ifndef RC_THREADS_H
#define RC_THREADS_H

/* Set in the environment of the re-executed program, so that it can tell
 * its second start from its first (the tools then keep quiet about what
 * the first start already said: the -j clamp note). */
#define RC_THREADS_REEXEC_ENV "RC_THREADS_REEXEC"

int rc_threads_wait_passively(int threads, char **argv);
int rc_threads_auto(void);

/* 1 if the make flags string (MAKEFLAGS) asks for parallel jobs: a word
 * -j (unlimited), -jN with N > 1, or --jobserver-auth= / --jobserver-fds=
 * (a jobserver exists only for N > 1); words after "--" are variable
 * assignments and are not read.  NULL: 0. */
int rc_threads_parallel_make(const char *makeflags);

#endif
