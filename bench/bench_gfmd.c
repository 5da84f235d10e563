/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bench_gfmd.c - cost of the two contact solvers (prints, never fails).
 *
 * For n^2 = 256^2 ... 2048^2 (4096^2 with BENCH_BIG=1, only 256^2 and 512^2
 * with BENCH_QUICK=1, for a loaded machine): an rc_synth surface
 * with H = 0.8, lambda_r = L/2, lambda_s = L/64, gbar = 1, solved at
 * p* = 0.05 by FIRE and CG at the default tolerance (1e-6).  Columns:
 * iterations; fft_pairs, the r2c + c2r transforms of the solve counted by
 * the elastic operator, halved (the primary cost figure: it does not
 * depend on the machine's load); pairs_per_iter; seconds; pair_seconds,
 * one FFTW r2c + c2r pair of the same size timed here; iter_in_pairs,
 * seconds per iteration in units of pair_seconds (FFTs plus the O(N)
 * passes); bytes per point (rc_solver_bytes, and the peak RSS of the
 * process so far, which includes the indenter and the timing plan); and
 * |a_r - a_r_ref| / a_r_ref against a FIRE solve at tol 1e-10 (FIRE and CG
 * agree at that tolerance: tests/test_solver.c); cpu_iter_in_pairs, the
 * same ratio in process CPU time (the solve's over the pair's), which
 * other processes on the machine disturb far less than the wall time.
 * Two more method rows, cg-plastic and fire-plastic, solve with the pressure
 * capped at the hardness H = 4 p (gfmd-solve --hardness;
 * lib/solver/solver_cg.c and FIRE on pressures,
 * lib/solver/solver_fire_free.c, on the cap of lib/solver/solver_hardness.c,
 * both boundary kinds): the cost of
 * plasticity against the elastic rows of the same map (their a_r error is
 * against the elastic reference, so it shows the effect).
 * Two more, fire-layer and cg-layer, solve the same map on a bonded elastic
 * layer of thickness L/8, nu = 0.3 (gfmd-solve --thickness;
 * lib/elastic/layer.h; free boundaries: the layer's pixel compliance,
 * lib/elastic/elastic_layer_free.h, its table made in the solver's setup, not
 * timed): the cost of a finite thickness against the half space's rows (a_r
 * error again against the half space).
 * One more, fire-adh, adds the exponential adhesion of gfmd-solve
 * --adhesion (lib/solver/adhesion.h) with range rho = dx and sigma_max =
 * dgamma / rho = p (l_adh = 20 dx, resolved): the cost of adhesion
 * against the fire row (a_r error against the non-adhesive reference: the
 * effect); fire-dug the same with Dugdale's law (--law dugdale: sigma_max
 * up to the opening rho), a comparison per point instead of an exp.  On free boundaries it solves heights on the padded grid
 * (lib/solver/solver_fire_adh_free.c), the fire row pressures: its fft_pairs
 * are padded pairs, as the fire row's.
 * From RC_FFT_BLOCKED_POINTS (1024^2) on, where the periodic solves take
 * the blocked transforms (fft.h) and FIRE runs its passes block by block
 * between them (solver_fire_loop.c), fire-plain and cg-plain solve the same
 * map with FFTW's whole-grid pair and separate passes: the gain.
 *
 * Both boundary kinds side by side (column boundary): free boundaries
 * (lib/elastic/elastic_free.c) solve the same map as an isolated patch; their
 * fft_pairs count pairs of the padded 2n x 2n transform (FIRE's unpadded
 * pairs as a quarter each, lib/solver/solver_fire_free.c), pair_seconds is
 * then a padded pair, and the reference is a free FIRE solve at 1e-10.  Free
 * boundaries stop at 1024^2 (a padded 2048^2) unless BENCH_BIG=1.
 *
 * Then the contention rows: the 512^2 FIRE solve with the default thread
 * count (rc_fft_set_threads(0), as a tool without -j) and with one
 * thread, each with no competitor and with one busy competitor (a child
 * process spinning on a core, started before the solve and killed after
 * it; alarm() ends it if this program dies first), CONTENTION_ROUNDS
 * rounds in turn; medians and the ratio default / one thread.  Inside
 * make -j N the default is one thread (lib/threads.h), which the header
 * line says: run `make bench` without -j to measure two.
 *
 * Last the one-thread rows (issue 29), for n^2 = 256^2 ... 1024^2 (2048^2
 * with BENCH_BIG=1, 256^2 and 512^2 with BENCH_QUICK=1), the periodic
 * FIRE solve at p* = 0.05 in ITER_ROUNDS interleaved rounds of: an FFTW
 * pair (ESTIMATE, as the solver's for one pressure); the solve; gfmd-solve's
 * contact analysis of it (rc_contact_analyse, every field, and
 * rc_contact_subpixel, on a plan made beforehand); the solve again on
 * whole-grid transforms with separate passes (plain) and on the blocked
 * ones (blocked), whichever RC_FFT_BLOCKED_POINTS picks by default; each
 * solve after a pair timed just before it, each ratio of one round's
 * times.  All in process CPU seconds (one thread: the work's own time).
 * Medians over the rounds: pair_seconds, solve_seconds, iter_in_pairs
 * (goals 3.0 at 512^2, 2.3 at 1024^2), analysis_in_solve (the analysis
 * over the solve: goal at most 0.25), plain_ and blocked_iter_in_pairs;
 * then the spread of iter_in_pairs over the rounds, iter_in_pairs_min and
 * _max.  BENCH_ITER_ONLY=1 prints only these; BENCH_ITER_ROUNDS=R runs R
 * rounds (1 ... ITER_ROUNDS_MAX, default ITER_ROUNDS) on a noisy machine.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "contact.h"
#include "fft.h"
#include "../tests/rough_cases.h"
#include "solver.h"
#include "synth.h"
#include "threads.h"

static double
now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double
cpu_now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double
peak_rss_bytes(void)
{
	struct rusage ru;

	getrusage(RUSAGE_SELF, &ru);
	return 1024.0 * (double)ru.ru_maxrss;
}

/* Wall and CPU seconds of one r2c + c2r pair. */
static double
fft_pair_seconds(size_t n, double *cpu)
{
	rc_fft f;
	rc_err err;
	double t0, c0;
	int reps = 0;

	if (rc_fft_init(&f, n, n, RC_FFT_ESTIMATE, &err) != 0)
		return *cpu = NAN;
	t0 = now();
	c0 = cpu_now();
	do {
		rc_fft_forward(&f);
		rc_fft_backward(&f);
		reps++;
	} while (now() - t0 < 0.5 || reps < 5);
	*cpu = (cpu_now() - c0) / reps;
	t0 = (now() - t0) / reps;
	rc_fft_free(&f);
	return t0;
}

/* The benchmark's surface on an n^2 grid: lambda_s = L/64, seed 1. */
#define SURFACE(n)	rc_test_rough((n), 1.0 / 64, 1)

/* A solve at p* = 0.05 and tolerance tol; the solver (NULL after a
 * message), its result and the process CPU seconds of the solve. */
static rc_solver *
solve(const rc_grid *g, enum rc_method method, enum rc_boundary boundary,
    double tol, double hardness, double thickness, size_t block_points,
    int adhesive, rc_solve_result *r, double *cpu)
{
	rc_solver_opts o;
	rc_solver *s;
	rc_err err;
	double c0;

	rc_solver_defaults(&o);
	o.method = method;
	o.boundary = boundary;
	o.hardness = hardness;
	o.fft_block_points = block_points;
	if (thickness > 0) {
		o.thickness = thickness;
		o.substrate = RC_SUBSTRATE_BONDED;
		o.poisson = 0.3;
	}
	if (adhesive) {
		o.adhesion_law = adhesive == 2 ? RC_ADHESION_DUGDALE :
		    RC_ADHESION_EXPONENTIAL;
		o.range = g->lx / (double)g->nx;
		o.adhesion = 0.05 * o.range;
	}
	if (tol > 0)
		o.tol = tol;
	if ((s = rc_solver_new(g, &o, &err)) == NULL) {
		fprintf(stderr, "bench_gfmd: %s\n", err.msg);
		return NULL;
	}
	c0 = cpu_now();
	if (rc_solver_solve(s, 0.05, r, &err) < 0) {
		fprintf(stderr, "bench_gfmd: %s\n", err.msg);
		rc_solver_free(s);
		return NULL;
	}
	*cpu = cpu_now() - c0;
	return s;
}

/* The method rows: the plain solves, plasticity, a layer, adhesion, and from
 * RC_FFT_BLOCKED_POINTS on the periodic solves again with FFTW's whole-grid
 * transforms and separate passes (fire-plain, cg-plain) for the gain of
 * the blocked ones. */
static const struct bench_row {
	const char *name;
	enum rc_method method;
	double hardness_over_p, thickness;
	int free_too, plain;
	int adhesive;		/* 1: exponential, 2: Dugdale */
} rows[] = {
	{ "fire", RC_METHOD_FIRE, 0, 0, 1, 0, 0 },
	{ "cg", RC_METHOD_CG, 0, 0, 1, 0, 0 },
	{ "cg-plastic", RC_METHOD_CG, 4, 0, 1, 0, 0 },
	{ "fire-plastic", RC_METHOD_FIRE, 4, 0, 1, 0, 0 },
	{ "fire-layer", RC_METHOD_FIRE, 0, 1.0 / 8, 1, 0, 0 },
	{ "cg-layer", RC_METHOD_CG, 0, 1.0 / 8, 1, 0, 0 },
	{ "fire-adh", RC_METHOD_FIRE, 0, 0, 1, 0, 1 },
	{ "fire-dug", RC_METHOD_FIRE, 0, 0, 1, 0, 2 },
	{ "fire-plain", RC_METHOD_FIRE, 0, 0, 0, 1, 0 },
	{ "cg-plain", RC_METHOD_CG, 0, 0, 0, 1, 0 },
};

/* One boundary kind on the map g of n x n points: the reference (FIRE at
 * tol 1e-10), then both methods; a row each.  Free boundaries count pairs
 * of the padded 2n x 2n transform and compare with a padded pair. */
static int
bench_boundary(const rc_grid *g, size_t n, enum rc_boundary b)
{
	size_t nn = n * n;
	double pair, pair_cpu, ref, cpu;
	rc_solver *s;
	rc_solve_result r;
	int m;

	pair = fft_pair_seconds(b == RC_BOUNDARY_FREE ? 2 * n : n, &pair_cpu);
	if ((s = solve(g, RC_METHOD_FIRE, b, 1e-10, 0, 0, RC_FFT_BLOCKED_POINTS,
	    0, &r, &cpu)) == NULL)
		return -1;
	ref = (double)rc_test_n_contact(s, nn) / (double)nn;
	rc_solver_free(s);
	for (m = 0; m < (int)(sizeof(rows) / sizeof(rows[0])); m++) {
		const struct bench_row *w = &rows[m];
		double ar, iters;

		if ((b == RC_BOUNDARY_FREE && !w->free_too) ||
		    (w->plain && (b == RC_BOUNDARY_FREE ||
		    nn < RC_FFT_BLOCKED_POINTS)))
			continue;
		if ((s = solve(g, w->method, b, 0, w->hardness_over_p * 0.05,
		    w->thickness, w->plain ? SIZE_MAX : RC_FFT_BLOCKED_POINTS,
		    w->adhesive, &r, &cpu)) == NULL)
			return -1;
		ar = (double)rc_test_n_contact(s, nn) / (double)nn;
		iters = (double)(r.iterations ? r.iterations : 1);
		printf("%zu\t%s\t%s\t%ld\t%.0f\t%.2f\t%.3f\t%.5f\t%.2f\t%.2f\t"
		    "%.1f\t%.1f\t%.6f\t%.1e\n",
		    n, rc_boundary_name(b), w->name, r.iterations,
		    r.fft_pairs, r.fft_pairs / iters, r.seconds, pair,
		    r.seconds / iters / pair, cpu / iters / pair_cpu,
		    (double)rc_solver_bytes(s) / (double)nn,
		    peak_rss_bytes() / (double)nn, ar, fabs(ar - ref) / ref);
		fflush(stdout);
		rc_solver_free(s);
	}
	return 0;
}

#define CONTENTION_N		512
#define CONTENTION_ROUNDS	5
#define COMPETITOR_SECONDS	120	/* alarm: the competitor's life at most */

/* A child that spins until killed (or its alarm rings); -1 if none. */
static pid_t
competitor_start(void)
{
	pid_t pid;

	fflush(stdout);
	pid = fork();

	if (pid == 0) {
		volatile unsigned long spin = 0;

		alarm(COMPETITOR_SECONDS);
		for (;;)
			spin++;
	}
	if (pid < 0)
		perror("bench_gfmd: fork");
	return pid;
}

static void
competitor_stop(pid_t pid)
{
	kill(pid, SIGKILL);
	waitpid(pid, NULL, 0);
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

static double
median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof(*v), cmp_double);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* The contention rows (see the top of the file). */
static int
contention(void)
{
	double t[2][2][CONTENTION_ROUNDS], med[2][2], cpu;
	int def = rc_fft_set_threads(0), busy, j, round;
	rc_grid *g = SURFACE(CONTENTION_N);
	rc_solve_result r;
	rc_solver *s;

	for (round = 0; round < CONTENTION_ROUNDS; round++)
		for (busy = 0; busy < 2; busy++)
			for (j = 0; j < 2; j++) {
				pid_t pid = busy ? competitor_start() : 0;

				if (pid < 0)
					return 1;
				rc_fft_set_threads(j == 0 ? 0 : 1);
				s = solve(g, RC_METHOD_FIRE, RC_BOUNDARY_PERIODIC, 0, 0, 0,
				    RC_FFT_BLOCKED_POINTS, 0, &r, &cpu);
				if (pid > 0)
					competitor_stop(pid);
				if (s == NULL)
					return 1;
				t[busy][j][round] = r.seconds;
				rc_solver_free(s);
			}
	for (busy = 0; busy < 2; busy++)
		for (j = 0; j < 2; j++)
			med[busy][j] = median(t[busy][j], CONTENTION_ROUNDS);
	printf("\n# contention: %d^2 FIRE solve (%ld iterations), medians of %d "
	    "rounds; default = %d thread%s\n", CONTENTION_N, r.iterations,
	    CONTENTION_ROUNDS, def, def == 1 ? "" : "s");
	printf("competitors\tseconds_default\tseconds_j1\tratio\n");
	for (busy = 0; busy < 2; busy++)
		printf("%d\t%.3f\t%.3f\t%.2f\n", busy, med[busy][0], med[busy][1],
		    med[busy][0] / med[busy][1]);
	rc_grid_free(g);
	rc_fft_set_threads(0);
	return 0;
}

#define ITER_ROUNDS	5
#define ITER_ROUNDS_MAX	99

/* The solve's CPU seconds at p* = 0.05 with the transforms blocked from
 * block_points on (fft.h); with plan not NULL also the contact analysis's
 * into *analysis and the iterations into *iters.  -1 on failure. */
static double
iter_solve(const rc_grid *g, size_t block_points, rc_fft *plan,
    double *analysis, long *iters)
{
	rc_solver_opts o;
	rc_solver *s;
	rc_solve_result r;
	rc_contact_opts co;
	rc_contact_stats st;
	rc_err err;
	double t0, t1;

	rc_solver_defaults(&o);
	o.fft_block_points = block_points;
	if ((s = rc_solver_new(g, &o, &err)) == NULL)
		goto fail;
	t0 = cpu_now();
	if (rc_solver_solve(s, 0.05, &r, &err) < 0)
		goto fail;
	t0 = cpu_now() - t0;
	if (plan != NULL) {
		rc_contact_defaults(&co);
		co.modulus = o.modulus;
		co.gbar = 1;
		co.pressure = 0.05;
		co.fft = plan;
		t1 = cpu_now();
		if (rc_contact_analyse(g, rc_solver_contact(s), &co, &st, &err) != 0)
			goto fail;
		if (!isfinite(rc_contact_subpixel(rc_solver_displacement(s), g->z,
		    rc_solver_pressure(s), rc_solver_contact(s), g->nx, g->ny,
		    g->lx, g->ly, o.modulus)))
			fprintf(stderr, "bench_gfmd: sub-pixel area not finite\n");
		*analysis = cpu_now() - t1;
		*iters = r.iterations;
	}
	rc_solver_free(s);
	return t0;
fail:
	fprintf(stderr, "bench_gfmd: %s\n", err.msg);
	rc_solver_free(s);
	return -1;
}

/* The rounds of the one-thread rows: BENCH_ITER_ROUNDS, else
 * ITER_ROUNDS; -1 after a message if it is not a count in range. */
static int
iter_rounds(void)
{
	const char *e = getenv("BENCH_ITER_ROUNDS");
	char *end;
	long r;

	if (e == NULL || *e == '\0')
		return ITER_ROUNDS;
	r = strtol(e, &end, 10);
	if (*end != '\0' || r < 1 || r > ITER_ROUNDS_MAX) {
		fprintf(stderr, "bench_gfmd: BENCH_ITER_ROUNDS: '%s' is not a "
		    "count of rounds from 1 to %d\n", e, ITER_ROUNDS_MAX);
		return -1;
	}
	return (int)r;
}

/* The one-thread rows (see the top of the file) of the first ns sizes,
 * in rounds rounds. */
static int
iteration_rows(size_t ns, int rounds)
{
	size_t sizes[] = { 256, 512, 1024, 2048 }, z;

	rc_fft_set_threads(1);
	printf("\n# one thread, FIRE at p* = 0.05, process CPU seconds, medians "
	    "of %d rounds\n", rounds);
	printf("n\titerations\tpair_seconds\tsolve_seconds\titer_in_pairs\t"
	    "analysis_in_solve\tplain_iter_in_pairs\tblocked_iter_in_pairs\t"
	    "iter_in_pairs_min\titer_in_pairs_max\n");
	for (z = 0; z < ns; z++) {
		size_t n = sizes[z];
		rc_grid *g = SURFACE(n);
		double t[6][ITER_ROUNDS_MAX], med[6], lo, hi;
		long iters = 0;
		rc_fft plan;
		rc_err err;

		if (rc_fft_init(&plan, n, n, RC_FFT_ESTIMATE, &err) != 0) {
			fprintf(stderr, "bench_gfmd: %s\n", err.msg);
			return 1;
		}
		/* Each solve in pairs of a pair timed just before it. */
		for (int k = 0; k < rounds; k++) {
			double pair[3], solve[3];

			fft_pair_seconds(n, &pair[0]);
			solve[0] = iter_solve(g, RC_FFT_BLOCKED_POINTS, &plan,
			    &t[2][k], &iters);
			fft_pair_seconds(n, &pair[1]);
			solve[1] = iter_solve(g, SIZE_MAX, NULL, NULL, NULL);
			fft_pair_seconds(n, &pair[2]);
			solve[2] = iter_solve(g, 0, NULL, NULL, NULL);
			if (solve[0] < 0 || solve[1] < 0 || solve[2] < 0)
				return 1;
			t[0][k] = pair[0];
			t[1][k] = solve[0];
			t[2][k] /= solve[0];
			t[3][k] = solve[1] / (double)iters / pair[1];
			t[4][k] = solve[2] / (double)iters / pair[2];
			t[5][k] = solve[0] / (double)iters / pair[0];
		}
		for (int c = 0; c < 6; c++)
			med[c] = median(t[c], rounds);	/* sorts t[c] */
		lo = t[5][0];
		hi = t[5][rounds - 1];
		printf("%zu\t%ld\t%.5f\t%.4f\t%.2f\t%.3f\t%.2f\t%.2f\t%.2f\t"
		    "%.2f\n", n, iters, med[0], med[1], med[5], med[2], med[3],
		    med[4], lo, hi);
		fflush(stdout);
		rc_fft_free(&plan);
		rc_grid_free(g);
	}
	rc_fft_set_threads(0);
	return 0;
}

int
main(int argc, char **argv)
{
	size_t sizes[] = { 256, 512, 1024, 2048, 4096 }, ns = 4, z;
	int threads = rc_fft_set_threads(0), rounds;

	(void)argc;
	rc_threads_wait_passively(threads, argv);	/* as the tools do */
	rounds = iter_rounds();

	if (getenv("BENCH_BIG"))
		ns = 5;
	if (getenv("BENCH_QUICK"))
		ns = 2;
	if (rounds < 0)
		return 2;
	if (getenv("BENCH_ITER_ONLY"))	/* only the one-thread rows */
		return iteration_rows(ns == 5 ? 4 : ns == 2 ? 2 : 3, rounds);
	printf("# gfmd-solve solvers, %d threads, p* = 0.05, H = 0.8, lambda_r = L/2,"
	    " lambda_s = L/64\n", threads);
	printf("n\tboundary\tmethod\titerations\tfft_pairs\tpairs_per_iter\t"
	    "seconds\tpair_seconds\titer_in_pairs\tcpu_iter_in_pairs\t"
	    "bytes_solver\tbytes_rss\ta_r\ta_r_relerr\n");
	for (z = 0; z < ns; z++) {
		size_t n = sizes[z];
		rc_grid *g = SURFACE(n);

		if (bench_boundary(g, n, RC_BOUNDARY_PERIODIC) != 0 ||
		    ((n <= 1024 || ns == 5) &&
		    bench_boundary(g, n, RC_BOUNDARY_FREE) != 0))
			return 1;
		rc_grid_free(g);
	}
	return contention() || iteration_rows(ns == 5 ? 4 : ns == 2 ? 2 : 3,
	    rounds);
}
