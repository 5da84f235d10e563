/* fft.h - real 2D transforms on the periodic grid, around FFTW.
 *
 * A plan pair owns one real buffer (ny rows of nx doubles) and one
 * half-complex buffer (ny rows of nxc = nx/2+1 complex values) and
 * transforms between them out of place, so a caller fills `real`, calls
 * rc_fft_forward, works on `spec`, calls rc_fft_backward and reads `real`.
 * Neither direction is normalised: backward(forward(x)) = nx*ny*x.
 * Plans are made once per size and reused for every transform.
 *
 * Mode (i, j) of spec, 0 <= i < nxc, 0 <= j < ny, has the wave vector
 * (rc_wavenumber(i, nx, lx), rc_wavenumber(j, ny, ly)).
 */
#ifndef RC_FFT_H
#define RC_FFT_H

#include <complex.h>
#include <fftw3.h>
#include <stddef.h>
#include "rc_err.h"

enum rc_fft_effort {
	RC_FFT_ESTIMATE = 0,	/* instant planning; default for small grids */
	RC_FFT_MEASURE		/* slower planning, faster transforms */
};

typedef struct rc_fft {
	size_t nx, ny, nxc;
	double *real;			/* nx*ny */
	fftw_complex *spec;		/* ny*nxc */
	fftw_plan forward, backward;
	double plan_seconds;		/* time spent planning */
} rc_fft;

/* Set how many threads FFTW (and OpenMP loops) use; n <= 0 means all cores.
 * Call before making plans.  Returns the number in effect. */
int rc_fft_set_threads(int n);

int rc_fft_init(rc_fft *f, size_t nx, size_t ny, enum rc_fft_effort effort,
    rc_err *err);
void rc_fft_free(rc_fft *f);
void rc_fft_forward(rc_fft *f);		/* real -> spec */
void rc_fft_backward(rc_fft *f);	/* spec -> real (destroys spec) */

/* Signed wave number of index k on an n-point axis of length l:
 * 2*pi*k/l for k <= n/2, 2*pi*(k-n)/l above.  For even n the Nyquist
 * index n/2 gets +pi*n/l; use rc_is_nyquist to treat it specially. */
double rc_wavenumber(size_t k, size_t n, double l);
/* 1 if k is the Nyquist index of an even-length axis. */
int rc_is_nyquist(size_t k, size_t n);

/* Multiplicity of half-complex column i in a sum over the full spectrum:
 * 1 for i = 0 and (even nx) i = nx/2, else 2. */
int rc_fft_weight(size_t i, size_t nx);

/* Spectral derivative factor i*q for an odd derivative: zero at Nyquist,
 * because the Nyquist mode's derivative is not representable (it would make
 * a real field complex). */
double rc_deriv_wavenumber(size_t k, size_t n, double l);

#endif
