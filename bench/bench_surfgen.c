/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bench_surfgen.c - cost of rc_synth against one bare FFTW c2r of the same
 * size, timed in the same run (the target: one inverse FFT plus O(N)).
 * Prints only; never fails on time. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "clock.h"
#include "synth.h"

/* Best of `reps` runs: the least disturbed by the rest of the machine. */
static double
time_c2r(size_t n, int reps)
{
	size_t nxc = n / 2 + 1;
	fftw_complex *spec = fftw_alloc_complex(nxc * n);
	double *real = fftw_alloc_real(n * n), best = 1e30;
	/* The same planning effort as rc_synth's. */
	fftw_plan p = fftw_plan_dft_c2r_2d((int)n, (int)n, spec, real, FFTW_ESTIMATE);

	for (int r = 0; r < reps; r++) {
		for (size_t k = 0; k < nxc * n; k++)
			spec[k] = (double)(k % 7) - 3.0 * I;
		double t0 = rc_clock();
		fftw_execute(p);
		double t = rc_clock() - t0;
		if (t < best)
			best = t;
	}
	fftw_destroy_plan(p);
	fftw_free(spec);
	fftw_free(real);
	return best;
}

static double
time_synth(size_t n, int reps)
{
	rc_synth_params p;
	rc_err err;
	double best = 1e30;

	rc_synth_defaults(&p);
	p.nx = p.ny = n;
	p.hurst = 0.8;
	p.lambda_r = 0.5;
	for (int r = 0; r < reps; r++) {
		p.seed = (uint64_t)r + 1;
		double t0 = rc_clock();
		rc_grid *g = rc_synth(&p, &err);
		double t = rc_clock() - t0;
		if (g == NULL) {
			fprintf(stderr, "bench_surfgen: %s\n", err.msg);
			exit(1);
		}
		rc_grid_free(g);
		if (t < best)
			best = t;
	}
	return best;
}

int
main(void)
{
	size_t sizes[] = { 512, 1024, 2048 };
	int threads = rc_fft_set_threads(0);

	printf("# rc_synth (self-affine, H 0.8, whole band, allocation and planning\n"
	    "# included) vs one bare FFTW c2r (planned outside the timing);\n"
	    "# best of 3, %d thread%s\n", threads, threads == 1 ? "" : "s");
	printf("n\tsynth_seconds\tc2r_seconds\tratio\n");
	for (size_t k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
		size_t n = sizes[k];
		double tc = time_c2r(n, 3), ts = time_synth(n, 3);
		printf("%zu\t%.4f\t%.4f\t%.2f\n", n, ts, tc, ts / tc);
	}
	return 0;
}
