/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bench_fftpair.c - one bare FFTW r2c transform of an N x N grid, the
 * yardstick of bench/bench_analysis.sh (surfstat's spectra are one r2c
 * plus O(N) work).  bench_fftpair N: plans with FFTW_ESTIMATE (as surfstat
 * does without wisdom), times the best of 3 transforms and prints
 * "N seconds"; without an argument, N = 1024.  Prints only; never fails
 * on time. */
#include <fftw3.h>
#include <stdio.h>
#include <stdlib.h>

#include "clock.h"
#include "fft.h"

int
main(int argc, char **argv)
{
	long n = argc > 1 ? strtol(argv[1], NULL, 10) : 1024;
	size_t nn, nxc;
	double *real, best = 1e30;
	fftw_complex *spec;
	fftw_plan p;

	if (n < 2 || n > 65536) {
		fprintf(stderr, "bench_fftpair: N %ld: want 2 to 65536\n", n);
		return 2;
	}
	rc_fft_set_threads(0);
	nn = (size_t)n;
	nxc = nn / 2 + 1;
	real = fftw_alloc_real(nn * nn);
	spec = fftw_alloc_complex(nxc * nn);
	if (real == NULL || spec == NULL) {
		fprintf(stderr, "bench_fftpair: out of memory\n");
		return 1;
	}
	p = fftw_plan_dft_r2c_2d((int)n, (int)n, real, spec, FFTW_ESTIMATE);
	for (int r = 0; r < 3; r++) {
		double t0;
		for (size_t k = 0; k < nn * nn; k++)
			real[k] = (double)(k % 13) - 6.0;
		t0 = rc_clock();
		fftw_execute(p);
		t0 = rc_clock() - t0;
		if (t0 < best)
			best = t0;
	}
	printf("%ld\t%.4g\n", n, best);
	fftw_destroy_plan(p);
	fftw_free(real);
	fftw_free(spec);
	return 0;
}
