/* bench_gfmd.c - cost of the two contact solvers (prints, never fails).
 *
 * For n^2 = 256^2 ... 2048^2 (4096^2 with BENCH_BIG=1): an rc_synth surface
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
 * agree at that tolerance: tests/test_solver.c).
 *
 * Both boundary kinds side by side (column boundary): free boundaries
 * (lib/elastic_free.c) solve the same map as an isolated patch; their
 * fft_pairs count pairs of the padded 2n x 2n transform (FIRE's unpadded
 * pairs as a quarter each, lib/fire_free.c), pair_seconds is then a
 * padded pair, and the reference is a free FIRE solve at 1e-10.  Free
 * boundaries stop at 1024^2 (a padded 2048^2) unless BENCH_BIG=1.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "fft.h"
#include "solver.h"
#include "synth.h"

static double
now(void)
{
	struct timespec t;

	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double
peak_rss_bytes(void)
{
	struct rusage ru;

	getrusage(RUSAGE_SELF, &ru);
	return 1024.0 * (double)ru.ru_maxrss;
}

static double
fft_pair_seconds(size_t n)
{
	rc_fft f;
	rc_err err;
	double t0;
	int reps = 0;

	if (rc_fft_init(&f, n, n, RC_FFT_ESTIMATE, &err) != 0)
		return NAN;
	t0 = now();
	do {
		rc_fft_forward(&f);
		rc_fft_backward(&f);
		reps++;
	} while (now() - t0 < 0.5 || reps < 5);
	t0 = (now() - t0) / reps;
	rc_fft_free(&f);
	return t0;
}

static double
contact_fraction(const rc_solver *s, size_t nn)
{
	const unsigned char *c = rc_solver_contact(s);
	size_t k, nc = 0;

	for (k = 0; k < nn; k++)
		nc += c[k];
	return (double)nc / (double)nn;
}

/* One boundary kind on the map g of n x n points: the reference, then
 * both methods; a row each. */
static int
bench_boundary(const rc_grid *g, size_t n, enum rc_boundary b)
{
	size_t nn = n * n;
	rc_err err;
	double pair, ref;
	rc_solver_opts o;
	rc_solver *s;
	rc_solve_result r;
	int m;

	pair = fft_pair_seconds(b == RC_BOUNDARY_FREE ? 2 * n : n);
	rc_solver_defaults(&o);
	o.method = RC_METHOD_FIRE;
	o.boundary = b;
	o.tol = 1e-10;
	if ((s = rc_solver_new(g, &o, &err)) == NULL ||
	    rc_solver_solve(s, 0.05, &r, &err) < 0) {
		fprintf(stderr, "bench_gfmd: %s\n", err.msg);
		return -1;
	}
	ref = contact_fraction(s, nn);
	rc_solver_free(s);
	for (m = 0; m < 2; m++) {
		double ar, iters;

		rc_solver_defaults(&o);
		o.method = m == 0 ? RC_METHOD_FIRE : RC_METHOD_CG;
		o.boundary = b;
		if ((s = rc_solver_new(g, &o, &err)) == NULL ||
		    rc_solver_solve(s, 0.05, &r, &err) < 0) {
			fprintf(stderr, "bench_gfmd: %s\n", err.msg);
			return -1;
		}
		ar = contact_fraction(s, nn);
		iters = (double)(r.iterations ? r.iterations : 1);
		printf("%zu\t%s\t%s\t%ld\t%.0f\t%.2f\t%.3f\t%.5f\t%.2f\t%.1f\t%.1f\t%.6f\t%.1e\n",
		    n, rc_boundary_name(b), rc_method_name(o.method), r.iterations,
		    r.fft_pairs, r.fft_pairs / iters, r.seconds, pair,
		    r.seconds / iters / pair,
		    (double)rc_solver_bytes(s) / (double)nn,
		    peak_rss_bytes() / (double)nn, ar, fabs(ar - ref) / ref);
		fflush(stdout);
		rc_solver_free(s);
	}
	return 0;
}

int
main(void)
{
	size_t sizes[] = { 256, 512, 1024, 2048, 4096 }, ns = 4, z;
	int threads = rc_fft_set_threads(0);

	if (getenv("BENCH_BIG"))
		ns = 5;
	printf("# gfmd-solve solvers, %d threads, p* = 0.05, H = 0.8, lambda_r = L/2,"
	    " lambda_s = L/64\n", threads);
	printf("n\tboundary\tmethod\titerations\tfft_pairs\tpairs_per_iter\tseconds\t"
	    "pair_seconds\titer_in_pairs\tbytes_solver\tbytes_rss\ta_r\ta_r_relerr\n");
	for (z = 0; z < ns; z++) {
		size_t n = sizes[z];
		rc_synth_params sp;
		rc_grid *g;
		rc_err err;

		rc_synth_defaults(&sp);
		sp.nx = sp.ny = n;
		sp.lx = sp.ly = 1;
		sp.hurst = 0.8;
		sp.lambda_r = 0.5;
		sp.lambda_s = 1.0 / 64;
		sp.seed = 1;
		sp.rms_gradient = 1;
		if ((g = rc_synth(&sp, &err)) == NULL) {
			fprintf(stderr, "bench_gfmd: %s\n", err.msg);
			return 1;
		}
		if (bench_boundary(g, n, RC_BOUNDARY_PERIODIC) != 0 ||
		    ((n <= 1024 || ns == 5) &&
		    bench_boundary(g, n, RC_BOUNDARY_FREE) != 0))
			return 1;
		rc_grid_free(g);
	}
	return 0;
}
