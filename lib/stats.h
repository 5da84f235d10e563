/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stats.h - height statistics and the structural parameters Phi1..Phi9.
 *
 * Wang & Mueser (2020), section 3.2, with three printed equations
 * corrected (see surfstat(1)).  Derivatives are taken on the whole
 * periodic surface; every average <.> then runs over the averaging set:
 * all points, or the points where a mask is 1 (the "c" quantities of the
 * paper).  With M_ab = <h_a h_b> the gradient tensor, gbar^2 = tr M,
 * dh = h - <h>:
 *   phi1 = <dh |grad h|^2> / (sqrt<dh^2> gbar^2)
 *   phi2 = -<dh^2 lap h> / (2 sqrt<dh^2> gbar^2)
 *   phi3 = -<dh^2> <lap h> / (2 sqrt<dh^2> gbar^2)
 *   phi4 = <dh^2 |grad h|^2> / (<dh^2> gbar^2)
 *   phi5 = -<dh^3 lap h> / (3 <dh^2> gbar^2)
 *   phi6 = <dh^2> <(lap h)^2> / gbar^4
 *   phi7 = (2/3) <dh^2 (lap h)^2> / gbar^4
 *   phi8 = (<|grad h|^4> - (tr M)^2 - 2 tr(M^2)) / gbar^4
 *   phi9 = 2 sum_ab (M_ab - tr M delta_ab / 2)^2 / gbar^4
 *        = ((M_xx - M_yy)^2 + 4 M_xy^2) / (M_xx + M_yy)^2
 *   nayak = <dh^2> <h_xx^2> / <h_x^2>^2   (profiles along x)
 * A quantity whose denominator vanishes (flat surface, one point) is NaN.
 */
#ifndef RC_STATS_H
#define RC_STATS_H

#include <stddef.h>
#include "fft.h"
#include "gradient.h"
#include "grid.h"

enum rc_deriv_method {
	RC_DERIV_SPECTRAL = 0,	/* exact for band-limited periodic data */
	RC_DERIV_FD		/* central gradient, 5-point Laplacian */
};

const char *rc_deriv_method_name(enum rc_deriv_method m);

/* Derivative fields of the periodic grid; any output may be NULL.
 * The spectral or the central stencil of gradient.h: spectral odd
 * derivatives zero the Nyquist mode, even ones keep it; FD:
 * h_x = (h[i+1] - h[i-1]) / 2dx, h_xx = (h[i+1] - 2h[i] + h[i-1]) / dx^2,
 * lap = h_xx + h_yy, periodic wrap.  fft may be NULL (spectral makes a plan). */
int rc_deriv_fields(const rc_grid *g, enum rc_deriv_method m, rc_fft *fft,
    double *hx, double *hy, double *lap, double *hxx, rc_err *err);

/* The rms forward-difference gradient of the whole grid (surfstat's
 * gbar_fd) is rc_gbar_forward (gradient.h). */

/* Check a mask against a grid: same nx, ny, values 0 or 1, at least one 1.
 * Returns the number of points set, or 0 with err filled. */
size_t rc_mask_check(const rc_grid *mask, const rc_grid *g, rc_err *err);

typedef struct rc_stats {
	size_t n_avg;		/* points in the averaging set */
	double fraction;	/* n_avg / (nx ny) */
	double mean, hrms, skewness, kurtosis, hmin, hmax;
	double gbar;		/* sqrt(tr M) over the set */
	double gbar_prime;	/* sign(x) sqrt(|x|), x = -<dh lap h>, Eq. 9 */
	double rms_laplacian;	/* sqrt(<(lap h)^2>) */
	double mxx, myy, mxy;	/* gradient tensor M */
	double nayak;
	double phi[10];		/* phi[1] .. phi[9]; phi[0] unused (NaN) */
} rc_stats;

/* Every statistic above; mask NULL averages over the whole grid. */
int rc_stats_compute(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_stats *s, rc_err *err);

/* The same with a plan of the grid's size to reuse (NULL: one is made);
 * spectral derivatives then need one more grid's worth of memory beyond
 * the plan's buffers, finite differences two. */
int rc_stats_compute_fft(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, rc_stats *s, rc_err *err);

/* The gradient tensor and rms gradient in nbins equal-width height bins
 * between the smallest and largest height of the averaging set. */
typedef struct rc_height_bin {
	double h_lo, h_hi, h_mid;
	size_t n;		/* points in the bin */
	double gbar;		/* sqrt(mxx + myy); NaN if n = 0 */
	double mxx, myy, mxy;
} rc_height_bin;

int rc_stats_by_height(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, size_t nbins, rc_height_bin *bins, rc_err *err);
int rc_stats_by_height_fft(const rc_grid *g, const rc_grid *mask,
    enum rc_deriv_method m, rc_fft *fft, size_t nbins, rc_height_bin *bins,
    rc_err *err);

#endif
