/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bench_free.c - free boundaries against closed forms on growing grids
 * (prints, never fails).
 *
 * The two problems of tests/free_cases.h, which tests/test_free.c asserts
 * at 64^2 and 128^2, here on 64^2 ... 512^2 (1024^2 with BENCH_BIG=1) with
 * FIRE and CG at tolerance 1e-8: Hertz (a paraboloid h = -r^2/(2R) loaded
 * so that a = (3FR/(4E*))^(1/3) = L/4) and the flat punch (a cylinder of
 * radius L/4 pressed by delta under displacement control).  Columns: the
 * relative errors of the contact radius a (from the contact area,
 * sqrt(n_c dx^2 / pi)), the approach a^2/R and the peak pressure
 * 3F/(2 pi a^2) for Hertz, of the load F = 2 a E* delta for the punch;
 * after each, its observed order log2(e(n/2) / e(n)) against the grid of
 * half the points across ("-" on the first); iterations (for the punch,
 * summed over the root find's trials) and the wall seconds of the solve
 * (not of the setup).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "../tests/free_cases.h"
#include "fft.h"
#include "threads.h"

#define NSIZES	5
/* Not the tests' 1e-9: FIRE stalls near 5e-9 at 1024^2 (the residual is
 * scaled by the largest stiffness, which grows with n, and the padded
 * transform's round-off does not shrink); 1e-8 moves the measured errors by
 * less than 1e-3 of themselves. */
#define TOL	1e-8

static const size_t sizes[NSIZES] = { 64, 128, 256, 512, 1024 };
static const enum rc_method methods[2] = { RC_METHOD_FIRE, RC_METHOD_CG };

/* An error and its order against the previous grid's (NAN: none). */
static void
print_err(double e, double prev)
{
	printf("\t%.3e", e);
	if (isnan(prev))
		printf("\t-");
	else
		printf("\t%.2f", log2(fabs(prev / e)));
}

/* A solve's status: an error ends the benchmark, no convergence is said
 * (its row is printed all the same). */
static int
check(int st, const char *problem, size_t n, enum rc_method m,
    const rc_err *err)
{
	if (st < 0)
		fprintf(stderr, "bench_free: %s %zu^2 %s: %s\n", problem, n,
		    rc_method_name(m), err->msg);
	else if (st > 0)
		fprintf(stderr, "bench_free: %s %zu^2 %s: not converged at tol "
		    "%g\n", problem, n, rc_method_name(m), TOL);
	return st < 0 ? -1 : 0;
}

static int
bench_hertz(size_t ns)
{
	double prev[2][3] = { { NAN, NAN, NAN }, { NAN, NAN, NAN } };

	printf("problem\tn\tmethod\titerations\tseconds\ta_relerr\ta_order\t"
	    "delta_relerr\tdelta_order\tp0_relerr\tp0_order\n");
	for (size_t z = 0; z < ns; z++)
		for (int m = 0; m < 2; m++) {
			struct fc_hertz e;
			rc_err err;
			double now[3];
			int st = fc_hertz(sizes[z], 1, RC_BOUNDARY_FREE, methods[m],
			    TOL, &e, &err);

			if (check(st, "hertz", sizes[z], methods[m], &err) != 0)
				return -1;
			now[0] = e.a / FC_HZ_A;
			now[1] = e.delta;
			now[2] = e.p0;
			printf("hertz\t%zu\t%s\t%ld\t%.3f", sizes[z],
			    rc_method_name(methods[m]), e.run.iterations, e.run.seconds);
			for (int q = 0; q < 3; q++) {
				print_err(now[q], prev[m][q]);
				prev[m][q] = now[q];
			}
			putchar('\n');
			fflush(stdout);
		}
	return 0;
}

static int
bench_punch(size_t ns)
{
	double prev[2] = { NAN, NAN };

	printf("\nproblem\tn\tmethod\titerations\tseconds\tF_relerr\tF_order\n");
	for (size_t z = 0; z < ns; z++)
		for (int m = 0; m < 2; m++) {
			struct fc_punch e;
			rc_err err;
			int st = fc_punch(sizes[z], methods[m], TOL, &e, &err);

			if (check(st, "punch", sizes[z], methods[m], &err) != 0)
				return -1;
			printf("punch\t%zu\t%s\t%ld\t%.3f", sizes[z],
			    rc_method_name(methods[m]), e.run.iterations, e.run.seconds);
			print_err(e.force, prev[m]);
			prev[m] = e.force;
			putchar('\n');
			fflush(stdout);
		}
	return 0;
}

int
main(int argc, char **argv)
{
	size_t ns = getenv("BENCH_BIG") ? NSIZES : NSIZES - 1;
	int threads = rc_fft_set_threads(0);

	(void)argc;
	rc_threads_wait_passively(threads, argv);	/* as the tools do */
	printf("# free boundaries against Hertz and the flat punch, %d threads, "
	    "tol %g, a = L/4\n", threads, TOL);
	return bench_hertz(ns) != 0 || bench_punch(ns) != 0;
}
