/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gradient.h - the derivative stencils of the library, one function each,
 * and the rms gradients of a whole grid built on them.  Every gradient,
 * Laplacian and rms gradient the library computes goes through these.
 *
 *   spectral  rc_deriv_spectral: the half-complex spectrum times i q'x,
 *             i q'y (the derivative wave numbers of fft.h: Nyquist zeroed,
 *             its derivative is not representable), -(qx^2 + qy^2) or
 *             -qx^2 (Nyquist kept, -q^2 is real), over N.  Exact for
 *             band-limited periodic heights.  Columns: gfmd-solve gbar
 *             (rc_rms_gradient, summed from the spectrum), gbar_c and
 *             gbar_c_prime (serial and MPI); surfstat gbar, gbar_c,
 *             gbar_c_prime and Phi1-Phi9 (spectral.c, stats.c, contact.c,
 *             lib/mpi/dsolver.c).
 *   central   rc_deriv_central: h_x = (h[i+1] - h[i-1]) / (2 dx),
 *             h_xx = (h[i+1] - 2 h[i] + h[i-1]) / dx^2, wrapping around;
 *             the Laplacian h_xx + h_yy (5 points).  Error O(dx^2) where
 *             the heights are smooth, no ringing at a kink.  Columns:
 *             gfmd-solve --fd gbar (rc_gbar_central), gbar_c,
 *             gbar_c_prime; surfstat --fd (the same columns as spectral).
 *   open      rc_deriv_open: central differences without wrap-around:
 *             one-sided first differences at the edges, there the second
 *             difference of the nearest interior point (none on an axis
 *             of fewer than 3 points).  Columns: gfmd-solve with free
 *             boundaries, gbar (rc_gbar_open), gbar_c, gbar_c_prime.
 *   forward   rc_deriv_forward: (h[i+1] - h[i]) / dx.  Columns: surfstat
 *             gbar_fd (rc_gbar_forward, wrapping around), Sdq and Sdr
 *             (iso25178.c: only where the forward neighbour exists).
 *
 * The four give different numbers on the same heights (they are
 * different estimates), so each column names its stencil.
 */
#ifndef RC_GRADIENT_H
#define RC_GRADIENT_H

#include <math.h>
#include <stddef.h>

#include "fft.h"
#include "grid.h"

enum rc_deriv {
	RC_DERIV_X = 0,		/* dh/dx */
	RC_DERIV_Y,		/* dh/dy */
	RC_DERIV_LAPLACIAN,	/* d2h/dx2 + d2h/dy2 */
	RC_DERIV_XX		/* d2h/dx2 */
};

/* Spectral: out = in times the factor of derivative which, over N = nx ny,
 * on rows j0 ... j0 + rows - 1 of the half-complex spectrum of an nx x ny
 * grid (all ny rows in a serial build, a rank's rows in the MPI one); out
 * may be in.  The inverse transform of out is the derivative field. */
void rc_deriv_spectral(fftw_complex *out, const fftw_complex *in,
    enum rc_deriv which, size_t nx, size_t ny, double lx, double ly,
    size_t j0, size_t rows);

/* Indices into the d[4] of the point stencils. */
enum { RC_D_X, RC_D_Y, RC_D_XX, RC_D_YY };

/* Central differences at point (i, j) of the periodic nx x ny grid z of
 * spacing dx, dy into d[RC_D_X .. RC_D_YY].  An axis of length 1 has
 * derivative 0 (the neighbours are the point itself). */
static inline void
rc_deriv_central(const double *z, size_t nx, size_t ny, size_t i, size_t j,
    double dx, double dy, double d[4])
{
	const double *row = z + j * nx;
	const double *up = z + (j + 1 < ny ? j + 1 : 0) * nx;
	const double *down = z + (j > 0 ? j - 1 : ny - 1) * nx;
	size_t left = i > 0 ? i - 1 : nx - 1, right = i + 1 < nx ? i + 1 : 0;

	d[RC_D_X] = (row[right] - row[left]) / (2 * dx);
	d[RC_D_Y] = (up[i] - down[i]) / (2 * dy);
	d[RC_D_XX] = (row[right] - 2 * row[i] + row[left]) / (dx * dx);
	d[RC_D_YY] = (up[i] - 2 * row[i] + down[i]) / (dy * dy);
}

/* The open stencil (above) at point (i, j) of a finite nx x ny patch. */
void rc_deriv_open(const double *z, size_t nx, size_t ny, size_t i, size_t j,
    double dx, double dy, double d[4]);

/* Forward difference (next - here) / d of heights scaled by 2^-e (exact:
 * rc_gbar_forward scales them so that squares neither overflow nor
 * underflow; e = 0 for none). */
static inline double
rc_deriv_forward(double here, double next, int e, double d)
{
	return ldexp(next - here, -e) / d;
}

/* By the central (open 0) or open (1) stencil, over the points of mask
 * (NULL: every point): the sum of |grad h|^2 into *grad2 and of
 * (h - hbar) lap h into *dh_lap. */
void rc_deriv_sums(const rc_grid *h, const unsigned char *mask, double hbar,
    int open, double *grad2, double *dh_lap);

/* From derivative fields already computed (any stencil), over the points
 * k < n of set (set[k] != 0; NULL: every point): the sum of hx^2 + hy^2
 * into *grad2 and of (h - hbar) lap into *dh_lap; a NULL field adds
 * nothing (the spectral path has one field at a time).  The sums of
 * gbar_c and gbar_c_prime for gfmd-solve (contact.c; lib/mpi/dsolver.c,
 * each rank its rows) and surfstat (stats.c), in fixed parts added in
 * order: the same digits for any thread count.  The stencil paths without
 * fields (gfmd-solve --fd, free boundaries) are rc_deriv_sums. */
void rc_field_sums(const double *h, const double *hx, const double *hy,
    const double *lap, const unsigned char *set, size_t n, double hbar,
    double *grad2, double *dh_lap);

/* Eq. 9's (gbar_c')^2 = x = -<dh lap h>_c can be negative over a partial
 * contact (dh about the contact mean): gbar_c_prime (gfmd-solve, serial
 * and MPI, and surfstat with a mask) is its signed square root,
 * sign(x) sqrt(|x|), never NaN and squaring back to x. */
static inline double
rc_signed_root(double x)
{
	return x == 0 ? 0 : copysign(sqrt(fabs(x)), x);
}

/* rms gradients of the whole grid, one per stencil but the spectral one
 * (rc_rms_gradient, spectral.h, summed from the spectrum):
 * sqrt(<h_x^2 + h_y^2>). */
double rc_gbar_central(const rc_grid *g);
double rc_gbar_open(const rc_grid *g);
double rc_gbar_forward(const rc_grid *g);

#endif
