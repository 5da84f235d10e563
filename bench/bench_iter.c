/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bench_iter.c - one thread: a FIRE iteration and a row's contact analysis
 * against an FFT pair and a solve (prints, never fails on time).
 *
 * For n^2 = 256^2 ... 1024^2 (2048^2 with BENCH_BIG=1, 256^2 and 512^2
 * with BENCH_QUICK=1) the surface of bench_gfmd (H = 0.8, lambda_r = L/2,
 * lambda_s = L/64, gbar = 1), at p* = 0.05, on one thread, in ITER_ROUNDS
 * interleaved rounds of: one r2c + c2r pair of FFTW's (ESTIMATE plans, as
 * the solver's for one pressure), timed over at least 0.3 s; the
 * periodic FIRE solve; gfmd-solve's
 * contact analysis of that solution (rc_contact_analyse with every field
 * and rc_contact_subpixel, on a plan made beforehand, as the tool's);
 * and the solve again on FFTW's whole-grid pair with separate passes
 * (plain) and on the blocked transforms with the passes between them
 * (blocked, solver_fire.c), whichever RC_FFT_BLOCKED_POINTS picks.  All
 * in process CPU seconds (one thread: the work's own time, far less
 * disturbed by a loaded machine than the wall clock).
 * Columns, medians over the rounds: iterations, pair_seconds,
 * solve_seconds, iter_in_pairs (a solve's seconds per iteration over the
 * pair's: goals 3.0 at 512^2 and 2.3 at 1024^2, issue 29),
 * analysis_seconds and analysis_in_solve (the analysis over the solve:
 * goal at most 0.25). */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#include <time.h>

#include "contact.h"
#include "fft.h"
#include "../tests/rough_cases.h"
#include "solver.h"

#define ITER_ROUNDS	5

/* Process CPU seconds: on one thread the work's own time, which other
 * processes on a shared machine disturb far less than the wall clock. */
static double
cpu_now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double
pair_seconds(size_t n)
{
	rc_fft f;
	rc_err err;
	double t0;
	int reps = 0;

	if (rc_fft_init(&f, n, n, RC_FFT_ESTIMATE, &err) != 0)
		return NAN;
	t0 = cpu_now();
	do {
		rc_fft_forward(&f);
		rc_fft_backward(&f);
		reps++;
	} while (cpu_now() - t0 < 0.3 || reps < 3);
	t0 = (cpu_now() - t0) / reps;
	rc_fft_free(&f);
	return t0;
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

/* The solve's seconds with the transforms blocked from block_points on
 * (fft.h); -1 on failure. */
static double
solve_path(const rc_grid *g, size_t block_points)
{
	rc_solver_opts o;
	rc_solver *s;
	rc_solve_result r;
	rc_err err;
	double t0;

	rc_solver_defaults(&o);
	o.fft_block_points = block_points;
	if ((s = rc_solver_new(g, &o, &err)) == NULL)
		goto fail;
	t0 = cpu_now();
	if (rc_solver_solve(s, 0.05, &r, &err) < 0)
		goto fail;
	t0 = cpu_now() - t0;
	rc_solver_free(s);
	return t0;
fail:
	fprintf(stderr, "bench_iter: %s\n", err.msg);
	rc_solver_free(s);
	return -1;
}

/* One round at n: the pair, the solve and the analysis, into t[0..2],
 * the solve on the plain and on the blocked path into t[3..4]; the
 * iterations into *iters. */
static int
round_at(const rc_grid *g, rc_fft *plan, double gbar, double *t, long *iters)
{
	rc_solver_opts o;
	rc_solver *s;
	rc_solve_result r;
	rc_contact_opts co;
	rc_contact_stats st;
	rc_err err;
	double t0, sub;

	t[0] = pair_seconds(g->nx);
	rc_solver_defaults(&o);
	if ((s = rc_solver_new(g, &o, &err)) == NULL)
		goto fail;
	t0 = cpu_now();
	if (rc_solver_solve(s, 0.05 * gbar, &r, &err) < 0)
		goto fail;
	t[1] = cpu_now() - t0;
	*iters = r.iterations;
	rc_contact_defaults(&co);
	co.modulus = o.modulus;
	co.gbar = gbar;
	co.pressure = 0.05 * gbar;
	co.fft = plan;
	t0 = cpu_now();
	if (rc_contact_analyse(g, rc_solver_contact(s), &co, &st, &err) != 0)
		goto fail;
	sub = rc_contact_subpixel(rc_solver_displacement(s), g->z,
	    rc_solver_pressure(s), rc_solver_contact(s), g->nx, g->ny, g->lx,
	    g->ly, o.modulus);
	t[2] = cpu_now() - t0;
	rc_solver_free(s);
	t[3] = solve_path(g, SIZE_MAX);
	t[4] = solve_path(g, 0);
	return isfinite(sub) && t[3] > 0 && t[4] > 0 ? 0 : -1;
fail:
	fprintf(stderr, "bench_iter: %s\n", err.msg);
	rc_solver_free(s);
	return -1;
}

int
main(void)
{
	size_t sizes[] = { 256, 512, 1024, 2048 }, ns = 3, z;

	if (getenv("BENCH_BIG"))
		ns = 4;
	if (getenv("BENCH_QUICK"))
		ns = 2;
	rc_fft_set_threads(1);
	printf("# one thread, FIRE at p* = 0.05 (bench_gfmd's surface), medians "
	    "of %d rounds\n", ITER_ROUNDS);
	printf("n\titerations\tpair_seconds\tsolve_seconds\titer_in_pairs\t"
	    "analysis_seconds\tanalysis_in_solve\tplain_iter_in_pairs\t"
	    "blocked_iter_in_pairs\n");
	for (z = 0; z < ns; z++) {
		size_t n = sizes[z];
		rc_grid *g = rc_test_rough(n, 1.0 / 64, 1);
		double t[5][ITER_ROUNDS], pair, solve, ana;
		long iters = 0;
		rc_fft plan;
		rc_err err;

		if (rc_fft_init(&plan, n, n, RC_FFT_ESTIMATE, &err) != 0) {
			fprintf(stderr, "bench_iter: %s\n", err.msg);
			return 1;
		}
		for (int k = 0; k < ITER_ROUNDS; k++) {
			double row[5];

			if (round_at(g, &plan, 1.0, row, &iters) != 0)
				return 1;
			for (int c = 0; c < 5; c++)
				t[c][k] = row[c];
		}
		pair = median(t[0], ITER_ROUNDS);
		solve = median(t[1], ITER_ROUNDS);
		ana = median(t[2], ITER_ROUNDS);
		printf("%zu\t%ld\t%.5f\t%.4f\t%.2f\t%.4f\t%.3f\t%.2f\t%.2f\n", n,
		    iters, pair, solve, solve / (double)iters / pair, ana,
		    ana / solve, median(t[3], ITER_ROUNDS) / (double)iters / pair,
		    median(t[4], ITER_ROUNDS) / (double)iters / pair);
		fflush(stdout);
		rc_fft_free(&plan);
		rc_grid_free(g);
	}
	return 0;
}
