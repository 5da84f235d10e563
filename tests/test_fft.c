/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_fft.c - the FFT layer's thread count, effort policy, FFTW wisdom
 * and in-place c2r plan. */
#include <complex.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "gradient.h"
#include "grid.h"
#include "spectral.h"
#include "testlib.h"

/* -j 0 means OMP_NUM_THREADS when it holds a positive number, else all
 * cores; an explicit count wins over the variable. */
static void
test_threads(void)
{
	int all;

	unsetenv("OMP_NUM_THREADS");
	all = rc_fft_set_threads(0);
	test_range(all, 1, 4096, "all cores: %d", all);
	setenv("OMP_NUM_THREADS", "3", 1);
	test_int(rc_fft_set_threads(0), 3, "OMP_NUM_THREADS=3 honoured");
	test_int(rc_fft_set_threads(2), 2, "-j 2 wins over OMP_NUM_THREADS");
	setenv("OMP_NUM_THREADS", "5,2", 1);
	test_int(rc_fft_set_threads(-1), 5, "OMP_NUM_THREADS=5,2: first level");
	setenv("OMP_NUM_THREADS", "lots", 1);
	test_int(rc_fft_set_threads(0), all, "bad OMP_NUM_THREADS: all cores");
	/* the count alone (before a restart) is the count set */
	test_int(rc_fft_thread_count(0), all, "count, bad OMP_NUM_THREADS: all cores");
	setenv("OMP_NUM_THREADS", "3", 1);
	test_int(rc_fft_thread_count(0), 3, "count: OMP_NUM_THREADS=3");
	test_int(rc_fft_thread_count(2), 2, "count: -j 2 wins");
	unsetenv("OMP_NUM_THREADS");
	rc_fft_set_threads(1);
}

static void
test_policy(void)
{
	test_int(rc_fft_effort_auto(1023, 1024, 1e6), RC_FFT_ESTIMATE,
	    "below 1024^2 points: estimate even for a solver");
	test_int(rc_fft_effort_auto(1024, 1024, 1e6), RC_FFT_MEASURE,
	    "1024^2 with many transforms: measure");
	test_int(rc_fft_effort_auto(16384, 64, RC_FFT_MEASURE_PAIRS), RC_FFT_MEASURE,
	    "2^20 points, %g pairs: measure", RC_FFT_MEASURE_PAIRS);
	test_int(rc_fft_effort_auto(2048, 2048, 5), RC_FFT_WISDOM,
	    "a one-shot big transform: wisdom or estimate");
	/* gfmd-solve's one pressure, about 200 pairs: its measured plans
	 * cost more than the solve (issue 29). */
	test_int(rc_fft_effort_auto(1024, 1024, 200), RC_FFT_WISDOM,
	    "one pressure at 1024^2: no measuring");
	test_int(rc_fft_effort_auto(4096, 4096, 200), RC_FFT_WISDOM,
	    "one pressure at 4096^2: no measuring");
	for (int e = RC_FFT_ESTIMATE; e <= RC_FFT_WISDOM; e++)
		test_int(rc_fft_effort_parse(rc_fft_effort_name((enum rc_fft_effort)e)),
		    e, "effort name round trip %d", e);
	test_int(rc_fft_effort_parse("exhaustive"), -1, "unknown effort");
}

/* Wisdom written by one "process" makes the next one's MEASURE plan come
 * from wisdom: after forgetting all wisdom, RC_FFT_WISDOM falls back to
 * ESTIMATE; after importing the saved file it yields a MEASURE plan. */
static void
test_wisdom(void)
{
	char path[512], bad[512], missing[512];
	rc_fft f;
	rc_err err;
	FILE *fp;
	size_t n = 24;

	snprintf(path, sizeof(path), "%s/w.wisdom", test_tmpdir());
	snprintf(bad, sizeof(bad), "%s/bad.wisdom", test_tmpdir());
	snprintf(missing, sizeof(missing), "%s/none/w.wisdom", test_tmpdir());
	fftw_forget_wisdom();
	test_int(rc_fft_init(&f, n, n, RC_FFT_WISDOM, &err), 0, "plan (wisdom)");
	test_int(f.effort, RC_FFT_ESTIMATE, "no wisdom yet: estimate");
	rc_fft_free(&f);
	test_int(rc_fft_init(&f, n, n, RC_FFT_MEASURE, &err), 0, "plan (measure)");
	test_int(f.effort, RC_FFT_MEASURE, "measure asked, measure made");
	rc_fft_free(&f);
	test_int(rc_fft_wisdom_export(path, &err), 0, "export");
	fftw_forget_wisdom();
	test_int(rc_fft_wisdom_import(path, &err), 1, "import what was saved");
	test_int(rc_fft_init(&f, n, n, RC_FFT_WISDOM, &err), 0, "plan (wisdom)");
	test_int(f.effort, RC_FFT_MEASURE, "wisdom loaded: a measured plan");
	rc_fft_free(&f);
	test_int(rc_fft_wisdom_import(missing, &err), 0, "a missing file: nothing");
	if ((fp = fopen(bad, "w")) != NULL) {
		fputs("nx = 3\n", fp);
		fclose(fp);
	}
	test_int(rc_fft_wisdom_import(bad, &err), -1, "not wisdom: an error");
	test_true(strstr(err.msg, "not FFTW wisdom") != NULL, "message: %s", err.msg);
	test_int(rc_fft_wisdom_export(missing, &err), -1, "export into no directory");
	/* A device that never ends was read forever (issue 27). */
	test_int(rc_fft_wisdom_import("/dev/zero", &err), -1, "/dev/zero: refused");
	test_true(strstr(err.msg, "not FFTW wisdom") != NULL, "message: %s", err.msg);
	test_int(rc_fft_wisdom_import("/dev/null", &err), 0, "/dev/null: nothing yet");
	fftw_forget_wisdom();
}

/* A plan made under FFTW's time limit is still the transform: with a
 * limit of a microsecond, MEASURE stops at once with some plan, whose
 * round trip gives N x to round-off (1e-12 of N for O(1) values); the
 * limit for the work grows with the work. */
static void
test_plan_limit(void)
{
	size_t n = 48, k;
	double l1, l2, worst = 0;
	rc_fft f;
	rc_err err;

	l1 = rc_fft_plan_limit(n, n, 1000);
	l2 = rc_fft_plan_limit(n, n, 1e6);
	test_true(l1 > 0 && l2 > l1, "limits %g s for 1e3 pairs, %g for 1e6", l1, l2);
	fftw_forget_wisdom();
	rc_fft_set_plan_limit(1e-6);
	test_int(rc_fft_init(&f, n, n, RC_FFT_MEASURE, &err), 0, "plan (limited)");
	rc_fft_set_plan_limit(-1);
	for (k = 0; k < n * n; k++)
		f.real[k] = sin(0.37 * (double)k) + 0.25 * (double)(k % 7);
	rc_fft_forward(&f);
	rc_fft_backward(&f);
	for (k = 0; k < n * n; k++) {
		double want = (double)(n * n) * (sin(0.37 * (double)k) +
		    0.25 * (double)(k % 7));

		worst = fmax(worst, fabs(f.real[k] - want));
	}
	test_true(worst <= 1e-12 * (double)(n * n), "limited plan: round trip "
	    "within %g", worst);
	rc_fft_free(&f);
	fftw_forget_wisdom();
}

/* The in-place c2r plan gives the out-of-place transform's values (to
 * round-off: 1e-13 of the largest value for 30 terms of O(1)), for even
 * and odd nx. */
static void
test_inplace(void)
{
	size_t sizes[][2] = { { 16, 12 }, { 15, 7 } };
	rc_err err;

	for (size_t s = 0; s < 2; s++) {
		size_t nx = sizes[s][0], ny = sizes[s][1], nxc = nx / 2 + 1;
		rc_fft f;
		fftw_complex *buf = fftw_alloc_complex(nxc * ny);
		double secs = -1, maxd = 0, maxv = 0;
		enum rc_fft_effort used;
		fftw_plan p = rc_fft_plan_c2r_inplace(nx, ny, buf, RC_FFT_ESTIMATE, &secs,
		    &used, &err);

		test_true(p != NULL, "in-place plan %zux%zu", nx, ny);
		test_range(secs, 0, 60, "plan seconds");
		test_int(used, RC_FFT_ESTIMATE, "effort used");
		if (p == NULL || rc_fft_init(&f, nx, ny, RC_FFT_ESTIMATE, &err) != 0)
			continue;
		/* A real field's spectrum, so both transforms see the same
		 * Hermitian input. */
		for (size_t k = 0; k < nx * ny; k++)
			f.real[k] = sin(0.7 * (double)k) + 0.1 * (double)(k % 5);
		rc_fft_forward(&f);
		memcpy(buf, f.spec, nxc * ny * sizeof(fftw_complex));
		rc_fft_backward(&f);
		fftw_execute(p);
		for (size_t j = 0; j < ny; j++)
			for (size_t i = 0; i < nx; i++) {
				double a = f.real[j * nx + i], b = ((double *)buf)[j * 2 * nxc + i];
				maxd = fmax(maxd, fabs(a - b));
				maxv = fmax(maxv, fabs(a));
			}
		test_abs(maxd / maxv, 0, 1e-13, "in place = out of place %zux%zu", nx, ny);
		rc_fft_free(&f);
		fftw_destroy_plan(p);
		fftw_free(buf);
	}
}

/* The blocked convolution (rows, then columns in blocks with the
 * multiplier, then rows) against the plain one (FFTW's 2D pair and a
 * pass over the spectrum) on sizes with and without a tail block in
 * either direction, odd nx included: the same values to rounding (a few
 * ulps of the largest output; 1e-12 leaves a wide margin and would
 * catch any misplaced block, which errs by O(1)).  In place too. */
static void
test_blocked(void)
{
	static const size_t sizes[][2] = { { 14, 8 }, { 24, 9 }, { 33, 17 },
		{ 64, 40 }, { 130, 72 }, { 256, 256 } };
	rc_err err;

	for (size_t z = 0; z < sizeof(sizes) / sizeof(sizes[0]); z++) {
		size_t nx = sizes[z][0], ny = sizes[z][1], n = nx * ny, k;
		rc_fft plain, blocked;
		double *in, *a, *b, *mult;
		int inv;

		if (rc_fft_init(&plain, nx, ny, RC_FFT_ESTIMATE, &err) != 0 ||
		    rc_fft_init(&blocked, nx, ny, RC_FFT_ESTIMATE, &err) != 0 ||
		    rc_fft_conv_init(&blocked, RC_FFT_ESTIMATE, 0, &err) != 0) {
			fprintf(stderr, "fft: %s\n", err.msg);
			exit(1);
		}
		test_true(rc_fft_conv_blocked(&blocked) && !rc_fft_conv_blocked(&plain),
		    "%zux%zu: blocked path planned only where asked", nx, ny);
		in = fftw_alloc_real(n);
		a = fftw_alloc_real(n);
		b = fftw_alloc_real(n);
		mult = fftw_alloc_real(plain.nxc * ny);
		for (k = 0; k < n; k++)
			in[k] = sin(0.37 * (double)k) + cos(0.011 * (double)(k * k % 977));
		for (k = 0; k < plain.nxc * ny; k++)
			mult[k] = k % 5 == 0 ? 0 : 1 + (double)(k % 13);
		for (inv = 0; inv < 2; inv++) {
			rc_fft_multiplier mu = { mult, 1.0 / (double)n, inv, 0.25 };
			double maxd = 0, maxv = 0;

			rc_fft_convolve(&plain, in, a, &mu);
			memcpy(b, in, n * sizeof(double));
			rc_fft_convolve(&blocked, b, b, &mu);
			for (k = 0; k < n; k++) {
				maxd = fmax(maxd, fabs(a[k] - b[k]));
				maxv = fmax(maxv, fabs(a[k]));
			}
			test_abs(maxd / maxv, 0, 1e-12, "%zux%zu %s: blocked (in place) "
			    "= plain", nx, ny, inv ? "c/k" : "c k");
		}
		fftw_free(in);
		fftw_free(a);
		fftw_free(b);
		fftw_free(mult);
		rc_fft_free(&plain);
		rc_fft_free(&blocked);
	}
}

/* rc_rms_gradient finds its scale from the moduli of the coefficients
 * near the largest component only and scales by a multiplication: the
 * same bits as the method it replaced, every modulus scanned and ldexp
 * on each (below, with the same 64 ordered parts), on odd and even grids
 * of heights near 1, 1e150, 1e-150, 1e300 and 1e-300. */
static void
test_gbar_bits(void)
{
	static const double scales[] = { 1, 1e150, 1e-150, 1e300, 1e-300,
	    INFINITY, NAN };
	static const size_t sizes[][2] = { { 24, 16 }, { 17, 9 } };
	unsigned long seed = 12345;

	/* The last two put one inf or NaN height among heights near 1: a
	 * NaN as before (max_num's NaN case cannot reach the result: a NaN
	 * modulus makes the sum NaN). */
	for (size_t s = 0; s < 2; s++)
		for (size_t c = 0; c < sizeof(scales) / sizeof(scales[0]); c++) {
			size_t nx = sizes[s][0], ny = sizes[s][1];
			rc_grid *g = rc_grid_new(nx, ny, 1.0, 0.8, NULL);
			double got, mmax = 0, partial[64], want = 0;
			rc_fft f;
			int e;

			for (size_t k = 0; k < nx * ny; k++) {
				seed = seed * 6364136223846793005UL + 1442695040888963407UL;
				g->z[k] = (isfinite(scales[c]) ? scales[c] : 1) *
				    ((double)(seed >> 11) / 9007199254740992.0 - 0.5);
			}
			if (!isfinite(scales[c]))
				g->z[5] = scales[c];
			rc_rms_gradient(g, NULL, &got, NULL);
			rc_fft_init(&f, nx, ny, RC_FFT_ESTIMATE, NULL);
			memcpy(f.real, g->z, nx * ny * sizeof(double));
			rc_fft_forward(&f);
			for (size_t k = 0; k < ny * f.nxc; k++)
				mmax = fmax(mmax, cabs(f.spec[k]));
			e = mmax > 0 && isfinite(mmax) ? ilogb(mmax) : 0;
			for (long p = 0; p < 64; p++) {
				partial[p] = 0;
				for (size_t j = (size_t)p * ny / 64; j < (size_t)(p + 1) * ny / 64; j++)
					for (size_t i = 0; i < f.nxc; i++) {
						double qx = rc_deriv_wavenumber(i, nx, g->lx);
						double qy = rc_deriv_wavenumber(j, ny, g->ly);
						double m = ldexp(cabs(f.spec[j * f.nxc + i]), -e);

						partial[p] += rc_fft_weight(i, nx) * (qx * qx + qy * qy) * m * m;
					}
			}
			for (int p = 0; p < 64; p++)
				want += partial[p];
			want = ldexp(sqrt(want), e) / (double)(nx * ny);
			test_true(memcmp(&got, &want, sizeof(got)) == 0 ||
			    (isnan(got) && isnan(want)), "rms gradient "
			    "%zux%zu, heights ~%g: %.17g, full scan %.17g", nx, ny,
			    scales[c], got, want);
			rc_fft_free(&f);
			rc_grid_free(g);
		}
}

/* rc_deriv_spectral makes each column's factor once for all rows: the
 * same bits as the factor made at every point (below, the loop it
 * replaced), for the four derivatives, on an even and an odd grid and on
 * one of 2050 columns (1026 half-complex ones: past a block of 1024),
 * in place and into another buffer, on a band of rows (j0 > 0, as an MPI
 * rank's), with an inf and a NaN among the values (the complex product's
 * special cases). */
static void
test_deriv_bits(void)
{
	static const size_t sizes[][2] = { { 24, 16 }, { 17, 9 }, { 2050, 5 } };
	unsigned long seed = 777;

	for (size_t s = 0; s < 3; s++)
		for (int d = RC_DERIV_X; d <= RC_DERIV_XX; d++) {
			size_t nx = sizes[s][0], ny = sizes[s][1], nxc = nx / 2 + 1;
			size_t j0 = 1, rows = ny - 2, m = rows * nxc;
			double lx = 1.3, ly = 0.7, n = (double)(nx * ny);
			double complex *in = malloc(m * sizeof(*in));
			double complex *got = malloc(m * sizeof(*got));
			double complex *want = malloc(m * sizeof(*want));

			for (size_t k = 0; k < m; k++) {
				double re, im;

				seed = seed * 6364136223846793005UL + 1442695040888963407UL;
				re = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
				seed = seed * 6364136223846793005UL + 1442695040888963407UL;
				im = (double)(seed >> 11) / 9007199254740992.0 - 0.5;
				in[k] = CMPLX(re, im);
			}
			in[3] = CMPLX(INFINITY, 0.25);
			in[m - 2] = CMPLX(0.5, NAN);
			for (size_t j = 0; j < rows; j++) {
				double qy = rc_wavenumber(j0 + j, ny, ly);
				double dqy = rc_deriv_wavenumber(j0 + j, ny, ly);

				for (size_t i = 0; i < nxc; i++) {
					double qx = rc_wavenumber(i, nx, lx);
					double complex factor;

					switch (d) {
					case RC_DERIV_X:
						factor = I * rc_deriv_wavenumber(i, nx, lx);
						break;
					case RC_DERIV_Y:
						factor = I * dqy;
						break;
					case RC_DERIV_LAPLACIAN:
						factor = -(qx * qx + qy * qy);
						break;
					default:
						factor = -qx * qx;
						break;
					}
					want[j * nxc + i] = in[j * nxc + i] * (factor / n);
				}
			}
			rc_deriv_spectral(got, in, (enum rc_deriv)d, nx, ny, lx, ly,
			    j0, rows);
			test_true(memcmp(got, want, m * sizeof(*got)) == 0,
			    "rc_deriv_spectral %d, %zux%zu rows %zu-%zu: the same "
			    "bits as a factor made at every point", d, nx, ny, j0,
			    j0 + rows - 1);
			rc_deriv_spectral(in, in, (enum rc_deriv)d, nx, ny, lx, ly,
			    j0, rows);
			test_true(memcmp(in, want, m * sizeof(*in)) == 0,
			    "rc_deriv_spectral %d, %zux%zu, in place: the same bits",
			    d, nx, ny);
			free(in);
			free(got);
			free(want);
		}
}

/* rc_fft_init's buffers of 2 MB and more start on a 2 MB boundary (huge
 * pages, rc_fft_huge), and the transforms on them give the same bits as
 * FFTW's on buffers of fftw_malloc; below 1 MB they are fftw_malloc's. */
static void
test_huge(void)
{
	const size_t nx = 512, ny = 512, nxc = nx / 2 + 1;
	rc_fft f, small, big_fft;
	double *in = fftw_alloc_real(nx * ny);
	fftw_complex *out = fftw_alloc_complex(nxc * ny);
	fftw_plan p;
	void *block;
	char *b;

	rc_fft_init(&f, nx, ny, RC_FFT_ESTIMATE, NULL);
	p = fftw_plan_dft_r2c_2d((int)ny, (int)nx, in, out, FFTW_ESTIMATE);
	test_int((long long)((uintptr_t)f.real % ((size_t)2 << 20)), 0,
	    "512^2 real buffer on a 2 MB boundary");
	test_int((long long)((uintptr_t)f.spec % ((size_t)2 << 20)), 0,
	    "512^2 spectrum on a 2 MB boundary");
	for (size_t k = 0; k < nx * ny; k++)
		in[k] = f.real[k] = sin(0.001 * (double)(k * k % 7919)) + (double)k / (double)(nx * ny);
	rc_fft_forward(&f);
	fftw_execute(p);
	test_true(memcmp(f.spec, out, nxc * ny * sizeof(fftw_complex)) == 0,
	    "512^2 r2c on huge-page buffers: the same bits as on fftw_malloc's");
	rc_fft_init(&small, 64, 64, RC_FFT_ESTIMATE, NULL);
	test_true((void *)small.real == small.real_block && (void *)small.spec ==
	    small.spec_block, "64^2 buffers: fftw_malloc's, as they are");
	b = rc_fft_huge(((size_t)2 << 20) + 5, &block);
	memset(b, 1, ((size_t)2 << 20) + 5);	/* all of it writable (ASan) */
	test_true(b != NULL && (char *)block <= b && (uintptr_t)b %
	    ((size_t)2 << 20) == 0, "rc_fft_huge: aligned inside its block");
	fftw_free(block);
	/* From 1 MB (a rest of half a huge page and more goes on one) */
	b = rc_fft_huge(RC_FFT_HUGE_MIN + 5, &block);
	memset(b, 1, RC_FFT_HUGE_MIN + 5);
	test_true(b != NULL && (char *)block <= b && (uintptr_t)b %
	    ((size_t)2 << 20) == 0, "rc_fft_huge: 1 MB + 5 aligned inside its "
	    "block");
	fftw_free(block);
	b = rc_fft_huge(((size_t)2 << 20) + RC_FFT_HUGE_MIN, &block);
	memset(b, 1, ((size_t)2 << 20) + RC_FFT_HUGE_MIN);
	test_true(b != NULL && (char *)block <= b && (uintptr_t)b %
	    ((size_t)2 << 20) == 0, "rc_fft_huge: 3 MB aligned inside its block");
	fftw_free(block);
	b = rc_fft_huge(RC_FFT_HUGE_MIN - 1, &block);
	test_true(b != NULL && (void *)b == block, "rc_fft_huge: below 1 MB "
	    "fftw_malloc's, as it is");
	fftw_free(block);
	{
		/* INT32_MAX^2 doubles: 2^65 bytes, past size_t */
		rc_err err;
		size_t big = INT32_MAX, bytes;

		test_int(rc_fft_init(&big_fft, big, big, RC_FFT_ESTIMATE,
		    &err), -1, "rc_fft_init: INT32_MAX^2 refused");
		test_true(strstr(err.msg, "overflows size_t") != NULL,
		    "rc_fft_init: INT32_MAX^2 refused as an overflow, not "
		    "tried as a wrapped size");
		test_int(rc_fft_bytes(SIZE_MAX / 2 + 1, 2, 1, &bytes), -1,
		    "rc_fft_bytes: (SIZE_MAX/2+1) 2 overflows");
		test_int(rc_fft_bytes(SIZE_MAX / 16 + 1, 2, 8, &bytes), -1,
		    "rc_fft_bytes: (SIZE_MAX/16+1) 2 8 overflows");
		test_int(rc_fft_bytes(3, 5, 8, &bytes), 0, "rc_fft_bytes 3 5 8");
		test_int((long long)bytes, 120, "rc_fft_bytes 3 5 8 = 120");
	}
	fftw_destroy_plan(p);
	fftw_free(in);
	fftw_free(out);
	rc_fft_free(&small);
	rc_fft_free(&f);
}

int
main(void)
{
	test_gbar_bits();
	test_deriv_bits();
	test_huge();
	test_threads();
	test_policy();
	test_wisdom();
	test_plan_limit();
	test_inplace();
	test_blocked();
	return test_summary();
}
