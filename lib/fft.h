/* SPDX-License-Identifier: GPL-3.0-or-later */
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
	RC_FFT_MEASURE,		/* slower planning, faster transforms */
	RC_FFT_PATIENT,		/* slower still; rarely worth it but with wisdom */
	RC_FFT_WISDOM		/* a MEASURE (or better) plan if FFTW's wisdom
				 * already holds one, else ESTIMATE: never pays
				 * for planning; for one-shot transforms */
};

/* Effort policy, from timings of an r2c + c2r pair on this project's
 * 2-core test machine: the plans MEASURE finds are no faster than
 * ESTIMATE's at 512^2 (within the noise, 5%), 0-25% faster at 1024^2,
 * 8-17% at 2048^2 and 28% at 4096^2; MEASURE planning costs 1 to 22 s at
 * 512^2 .. 4096^2 (roughcontact(7), "Running large problems"; on the
 * loaded machine of issue 29, in units of the ESTIMATE pair: 166-233
 * pairs at 1024^2 and 31-47 at 2048^2 for the pair, 55-76 and 7-11 more
 * for the blocked convolution's plans).  So planning pays only for long
 * work: ESTIMATE below RC_FFT_MEASURE_POINTS; above, MEASURE when the
 * caller expects at least RC_FFT_MEASURE_PAIRS transform pairs (many
 * pressures of a solver), else RC_FFT_WISDOM (a plan from wisdom, which
 * costs nothing to make, or ESTIMATE).  A solve of one pressure (50-300
 * pairs) is planned with ESTIMATE. */
#define RC_FFT_MEASURE_POINTS ((size_t)1024 * 1024)
#define RC_FFT_MEASURE_PAIRS 2000.0
enum rc_fft_effort rc_fft_effort_auto(size_t nx, size_t ny, double pairs);
/* A bound on FFTW's planning for work of `pairs` transform pairs of nx x
 * ny: RC_FFT_PLAN_SHARE of the work's time, from one pair of ESTIMATE
 * plans timed here (buffers of the grid's size for that moment), shared
 * among the RC_FFT_PLAN_CALLS planner calls of a solver (the pair, the
 * blocked convolution's row and column plans and their rests), each of
 * which FFTW then stops at its time limit with the best plan so far.
 * Returns the limit per call in seconds, or a negative number if it could
 * not time a pair (no limit then).  rc_fft_set_plan_limit sets FFTW's
 * time limit for the plans made after (FFTW's process-wide state, as its
 * thread count and wisdom); seconds < 0: none. */
#define RC_FFT_PLAN_SHARE 0.1
#define RC_FFT_PLAN_CALLS 10
double rc_fft_plan_limit(size_t nx, size_t ny, double pairs);
void rc_fft_set_plan_limit(double seconds);
/* "estimate", "measure", "patient", "wisdom"; parse returns -1 if unknown. */
const char *rc_fft_effort_name(enum rc_fft_effort e);
int rc_fft_effort_parse(const char *name);

/* The row stride of spec on the blocked path: nxc rounded up to whole
 * 64-byte cache lines (4 complex values).  With rows nxc apart (odd for
 * even nx) a block of RC_FFT_BLOCK columns straddles 3 lines of most
 * rows instead of 2, and the columns' stage moves half as much again
 * through the cache (the gain: rc_fft_convolve below; the values are the
 * same bit for bit, FFTW runs the same codelets on other addresses).
 * The plain pair's spectrum is the first ny*nxc values (rows nxc
 * apart), as every user of spec expects; the buffer holds ny*nxs. */
#define RC_FFT_SPEC_ROW(nx)	(((nx) / 2 + 1 + 3) / 4 * 4)
typedef struct rc_fft {
	size_t nx, ny, nxc;
	size_t nxs;			/* RC_FFT_SPEC_ROW(nx) */
	double *real;			/* nx*ny */
	fftw_complex *spec;		/* ny*nxc; room for ny*nxs */
	/* The blocks rc_fft_huge placed real and spec in (what rc_fft_free
	 * gives fftw_free); NULL: real and spec themselves. */
	void *real_block, *spec_block;
	fftw_plan forward, backward;
	double plan_seconds;		/* time spent planning */
	enum rc_fft_effort effort;	/* the effort the plans were made with
					 * (RC_FFT_WISDOM resolved) */
	/* The blocked convolution (rc_fft_conv_init): NULL unless the
	 * grid is large enough for it to pay.  Plans of RC_FFT_BLOCK rows
	 * r2c and c2r, columns forward and backward, and of the rest.  The
	 * column plans work on a block of columns gathered, each column
	 * contiguous, column_dist values apart, into one of ncolumn_buf
	 * buffers (one per thread, of RC_FFT_BLOCK * column_dist values;
	 * column_buf_all holds them). */
	fftw_plan block[4], block_tail[4];
	fftw_complex *column_buf_all;
	size_t column_dist;
	int ncolumn_buf;
} rc_fft;

/* Set how many threads FFTW (and OpenMP loops) use; n <= 0 means the
 * OMP_NUM_THREADS environment variable if it holds a positive number, else
 * rc_threads_auto() (lib/threads.h: 1 inside a parallel make, else the
 * cores this process may use).  Call before making plans.  Returns the
 * number in effect. */
int rc_fft_set_threads(int n);
/* n bytes for a large array, as fftw_malloc gives them (NULL when out of
 * memory), but from RC_FFT_HUGE_MIN (1 MB, half a huge page) up starting
 * on a 2 MB boundary, its whole 2 MB pieces, and a rest of 1 MB or more,
 * advised to the kernel as transparent huge pages (MADV_HUGEPAGE): one
 * page fault per 2 MB instead of per 4 kB, a first touch of 0.5 ms per
 * MB less on this project's virtual machine (13 us a 4 kB fault; 0.15 ms
 * a huge page, but about 5.5 ms when the hypervisor has taken the guest's
 * free memory back, free page reporting: measured there).  *block is
 * what to give fftw_free. */
#define RC_FFT_HUGE_MIN ((size_t)1 << 20)
void *rc_fft_huge(size_t n, void **block);
/* Frees what rc_fft_huge gave (x, block), or x from fftw_malloc when
 * block is NULL (a zeroed struct's field filled elsewhere). */
void rc_fft_huge_free(void *x, void *block);
/* *bytes = a b size; -1 if that overflows size_t (then *bytes is 0). */
int rc_fft_bytes(size_t a, size_t b, size_t size, size_t *bytes);
/* The number rc_fft_set_threads(n) would put in effect, without starting
 * FFTW's threads (2.5 ms of CPU: wasted in a program about to restart
 * for passive waiting, threads.h). */
int rc_fft_thread_count(int n);

/* FFTW's wisdom (plans it has measured) is FFTW's own process-wide state,
 * not this library's: loading it makes later MEASURE plans of the same
 * sizes and thread counts instant.  Import: 1 if loaded, 0 if path does
 * not exist or is empty (nothing to load yet), -1 if it cannot be read or
 * is not FFTW wisdom: text with a NUL byte, or RC_FFT_WISDOM_MAX_BYTES
 * or more (so a device such as /dev/zero is refused, not read forever).
 * Export writes all wisdom atomically (temporary file + rename), so
 * concurrent runs sharing one file never see a torn one. */
#define RC_FFT_WISDOM_MAX_BYTES (16 << 20)
int rc_fft_wisdom_import(const char *path, rc_err *err);
int rc_fft_wisdom_export(const char *path, rc_err *err);

/* An in-place c2r plan of buf, ny rows of nxc = nx/2+1 complex values whose
 * real output rows are padded to 2 nxc doubles (FFTW's in-place layout).
 * Makes it before buf is filled (MEASURE overwrites it); *plan_seconds and
 * *used (either may be NULL) receive the planning time and the effort
 * used.  NULL with err set if memory is short or FFTW cannot plan. */
fftw_plan rc_fft_plan_c2r_inplace(size_t nx, size_t ny, fftw_complex *buf,
    enum rc_fft_effort effort, double *plan_seconds, enum rc_fft_effort *used,
    rc_err *err);

int rc_fft_init(rc_fft *f, size_t nx, size_t ny, enum rc_fft_effort effort,
    rc_err *err);
void rc_fft_free(rc_fft *f);
/* The plan an analysis runs on: given, when not NULL (it must be nx x ny),
 * else a new FFTW_ESTIMATE plan made in *own (zeroed first; the caller
 * frees it with rc_fft_free, harmless when unused).  NULL on failure. */
rc_fft *rc_fft_borrow(rc_fft *given, rc_fft *own, size_t nx, size_t ny,
    rc_err *err);
void rc_fft_forward(rc_fft *f);		/* real -> spec */
void rc_fft_backward(rc_fft *f);	/* spec -> real (destroys spec) */

/* Convolution with a real Fourier multiplier: out = IFFT[c_q FFT(in)],
 * with c_q = scale k_q, or with inverse set c_q = scale / k_q where
 * k_q > 0 and c_q = at_zero where k_q = 0 (k: ny rows of nxc, as spec).
 * The multiplier holds the 1/N of the unnormalised pair.  in is kept,
 * out may be in or f->real; f->spec is scratch.
 *
 * Large grids take a blocked path: the rows' r2c (RC_FFT_BLOCK rows per
 * thread's step), then for each block of RC_FFT_BLOCK columns, gathered
 * contiguous into a buffer (fft.c says why), the column DFT, the
 * multiplier and the inverse column DFT, then the rows' c2r.  This saves
 * the separate pass over the spectrum and one trip of the columns through
 * memory.  Measured on this project's 2-core machine, one thread, ESTIMATE
 * plans, per convolution in units of FFTW's own 2D r2c + c2r pair
 * (medians [ranges] of 5 runs of 5 rounds, issue 29): plain (pair +
 * multiplier pass) 1.05 [1.03-1.07] at 512^2, 1.02 [0.98-1.05] at 1024^2,
 * 1.03 [1.00-1.12] at 2048^2; blocked, spec's rows nxs apart, 1.09
 * [1.04-1.19], 0.85 [0.78-0.90] and 0.71 [0.68-0.74] (rows nxc apart, as
 * before: 1.11, 1.00, 1.04).  Blocks of 16, 32 or 64 columns, or 4 or 16
 * rows, were within 0.04 of these (the same bits).  Below 1024^2 the
 * blocked path is slower (the whole spectrum stays in cache anyway):
 * hence RC_FFT_BLOCKED_POINTS.  Both paths give the same values to
 * rounding.  With the columns gathered (issue 29; a harness of medians of
 * 9 wall times, one thread, the pair FFTW's ESTIMATE 2D pair): blocked
 * 1.08 at 1024^2 and 0.81 at 2048^2, against 1.14 and 1.01 with the
 * columns transformed in place (plain: 1.13 and 1.10). */
#define RC_FFT_BLOCK		8
#define RC_FFT_BLOCKED_POINTS	((size_t)1024 * 1024)
typedef struct rc_fft_multiplier {
	const double *k;
	double scale;
	int inverse;
	double at_zero;		/* inverse only */
} rc_fft_multiplier;
/* Plans for the blocked path on f (after rc_fft_init, same effort) when
 * nx * ny >= min_points (RC_FFT_BLOCKED_POINTS where it pays; 0 in tests)
 * and both nxc and ny are at least RC_FFT_BLOCK; nothing otherwise.  -1
 * with err set if FFTW cannot plan. */
int rc_fft_conv_init(rc_fft *f, enum rc_fft_effort effort, size_t min_points,
    rc_err *err);
void rc_fft_convolve(rc_fft *f, const double *in, double *out,
    const rc_fft_multiplier *m);
/* spec[m] *= c_q for the nm half-complex values of spec and the table
 * mu->k of the same layout (the unblocked convolution's step; also the
 * distributed operator's, elastic.c). */
void rc_fft_multiply(fftw_complex *spec, size_t nm, const rc_fft_multiplier *mu);
/* 1 if f takes the blocked path. */
int rc_fft_conv_blocked(const rc_fft *f);
/* The blocked path's stages, for a caller that works on each block of
 * rows while it is in cache (lib/solver/solver_fire_loop.c): the r2c of block b of
 * RC_FFT_BLOCK rows of in into spec, the columns with the multiplier
 * (threads over column blocks), the c2r of block b of spec into out (it
 * destroys that block of spec).  Blocks b < rc_fft_row_blocks(f) hold
 * rows j0 <= j < j1 (rc_fft_block_rows).  Only where rc_fft_conv_blocked;
 * each stage is one thread's work, call them from the caller's loop. */
size_t rc_fft_row_blocks(const rc_fft *f);
void rc_fft_block_rows(const rc_fft *f, size_t b, size_t *j0, size_t *j1);
void rc_fft_rows_r2c(rc_fft *f, const double *in, size_t b);
void rc_fft_columns(rc_fft *f, const rc_fft_multiplier *mu);
void rc_fft_rows_c2r(rc_fft *f, double *out, size_t b);

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
