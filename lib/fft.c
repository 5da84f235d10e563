/* fft.c - FFTW plans, threads, wave numbers. */
#include "fft.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#ifdef _OPENMP
#include <omp.h>
#endif

int
rc_fft_set_threads(int n)
{
#ifdef _OPENMP
	static int initialised;	/* FFTW's own global state: init once */
	if (n <= 0)
		n = omp_get_num_procs();
	if (!initialised) {
		fftw_init_threads();
		initialised = 1;
	}
	omp_set_num_threads(n);
	fftw_plan_with_nthreads(n);
	return n;
#else
	(void)n;
	return 1;
#endif
}

/* Room FFTW needs beyond the two buffers, with a wide margin (measured:
 * 3.2 MB in all for planning and executing a 4096^2 pair). */
#define FFTW_HEADROOM(nx, ny) (((size_t)16 << 20) + 64 * ((nx) + (ny)) * \
	sizeof(fftw_complex))

int
rc_fft_init(rc_fft *f, size_t nx, size_t ny, enum rc_fft_effort effort,
    rc_err *err)
{
	struct timespec t0, t1;
	unsigned flags = effort == RC_FFT_MEASURE ? FFTW_MEASURE : FFTW_ESTIMATE;
	void *probe;

	memset(f, 0, sizeof(*f));
	if (nx > (size_t)INT32_MAX || ny > (size_t)INT32_MAX)
		return rc_seterr(err, "grid %zux%zu too large for FFTW's int sizes", nx, ny);
	f->nx = nx;
	f->ny = ny;
	f->nxc = nx / 2 + 1;
	f->real = fftw_alloc_real(nx * ny);
	f->spec = fftw_alloc_complex(f->nxc * ny);
	if (f->real == NULL || f->spec == NULL) {
		rc_fft_free(f);
		return rc_seterr(err, "out of memory (asked for %zu bytes of FFT buffers)",
		    (nx * ny + 2 * f->nxc * ny) * sizeof(double));
	}
	/* FFTW aborts when one of its own allocations (plans, twiddle factors,
	 * buffers: a few MB for a 4096^2 grid) fails: fail cleanly here instead
	 * when not even that much is left. */
	if ((probe = malloc(FFTW_HEADROOM(nx, ny))) == NULL) {
		rc_fft_free(f);
		return rc_seterr(err, "out of memory (asked for %zu bytes of FFT buffers "
		    "and %zu bytes of FFTW workspace)", (nx * ny + 2 * (nx / 2 + 1) * ny) *
		    sizeof(double), FFTW_HEADROOM(nx, ny));
	}
	free(probe);
	clock_gettime(CLOCK_MONOTONIC, &t0);
	f->forward = fftw_plan_dft_r2c_2d((int)ny, (int)nx, f->real, f->spec, flags);
	f->backward = fftw_plan_dft_c2r_2d((int)ny, (int)nx, f->spec, f->real, flags);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	f->plan_seconds = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
	if (f->forward == NULL || f->backward == NULL) {
		rc_fft_free(f);
		return rc_seterr(err, "FFTW could not plan a %zux%zu transform", nx, ny);
	}
	/* MEASURE scribbles on the buffers. */
	memset(f->real, 0, nx * ny * sizeof(double));
	return 0;
}

void
rc_fft_free(rc_fft *f)
{
	if (f->forward)
		fftw_destroy_plan(f->forward);
	if (f->backward)
		fftw_destroy_plan(f->backward);
	fftw_free(f->real);
	fftw_free(f->spec);
	memset(f, 0, sizeof(*f));
}

void
rc_fft_forward(rc_fft *f)
{
	fftw_execute(f->forward);
}

void
rc_fft_backward(rc_fft *f)
{
	fftw_execute(f->backward);
}

double
rc_wavenumber(size_t k, size_t n, double l)
{
	double kk = k <= n / 2 ? (double)k : (double)k - (double)n;

	return 2 * M_PI * kk / l;
}

int
rc_is_nyquist(size_t k, size_t n)
{
	return n % 2 == 0 && k == n / 2;
}

int
rc_fft_weight(size_t i, size_t nx)
{
	return (i == 0 || rc_is_nyquist(i, nx)) ? 1 : 2;
}

double
rc_deriv_wavenumber(size_t k, size_t n, double l)
{
	return rc_is_nyquist(k, n) ? 0.0 : rc_wavenumber(k, n, l);
}
