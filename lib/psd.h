/* psd.h - power spectrum and height-difference autocorrelation.
 *
 * Convention (DESIGN.md, Eq. 7 of Wang & Mueser 2020):
 *   C(q) = (2 pi)^-2 int d^2r <h(0) h(r)> exp(-i q.r),
 * so <h^2> = int d^2q C(q) and gbar^2 = int d^2q q^2 C(q).  On the grid,
 * with h_k the unnormalised DFT, A = lx ly, N = nx ny:
 *   C(q_k) = |h_k|^2 A / ((2 pi)^2 N^2),  dq^2 = (2 pi)^2 / A,
 * and sum_k C(q_k) dq^2 = <h^2> exactly (Parseval).  The convention of
 * Jacobs, Junge & Pastewka (2017) (contact.engineering) is (2 pi)^2 times
 * larger: C_JJP(q) = (2 pi)^2 C(q).
 */
#ifndef RC_PSD_H
#define RC_PSD_H

#include <stddef.h>
#include "fft.h"
#include "grid.h"

/* Full-plane 2D spectrum as a grid of kind spectrum, q = 0 at index
 * (nx/2, ny/2) (integer division): value (i, j) is C at
 * qx = (i - nx/2) 2 pi/lx, qy = (j - ny/2) 2 pi/ly.  The grid's lx, ly are
 * the q extents nx 2 pi/lx, ny 2 pi/ly; metadata records dqx, dqy, the
 * index of q = 0 and the convention. */
rc_grid *rc_psd2d(const rc_grid *g, rc_fft *fft, rc_err *err);

/* Radial average on logarithmic bins (bins_per_decade per factor 10),
 * over every mode but q = 0; only non-empty bins are returned. */
typedef struct rc_psd_bin {
	double q;		/* mean |q| of the modes in the bin */
	double c;		/* mean C over the modes */
	size_t n_modes;		/* full-plane modes (q and -q count twice) */
	double std_err;		/* sd / sqrt(independent modes); NaN if < 2 */
} rc_psd_bin;

int rc_psd_radial(const rc_grid *g, rc_fft *fft, double bins_per_decade,
    rc_psd_bin **bins, size_t *nbins, rc_err *err);

/* Spectral moments of profiles along x: m0 = sum C dq^2 without q = 0,
 * m2 = sum qx'^2 C dq^2, m4 = sum qx^4 C dq^2 (qx' Nyquist-zeroed as for a
 * first derivative); Nayak's alpha = m0 m4 / m2^2. */
int rc_psd_moments_x(const rc_grid *g, rc_fft *fft, double *m0, double *m2,
    double *m4, rc_err *err);

/* Height-difference autocorrelation G(r) = <(h(r0 + r) - h(r0))^2> over
 * all r0, periodic.  Along x: r = i dx, i = 0 .. nx/2; along y likewise;
 * radial: every lattice displacement with |r| <= min(lx, ly)/2 binned by
 * round(|r|/dr), dr = max(dx, dy). */
enum rc_acf_dir { RC_ACF_X = 0, RC_ACF_Y, RC_ACF_RADIAL };

typedef struct rc_acf_point {
	enum rc_acf_dir dir;
	double r;		/* mean |r| of the displacements averaged */
	double g;		/* G(r) */
	size_t n;		/* displacements averaged */
} rc_acf_point;

int rc_acf(const rc_grid *g, rc_fft *fft, rc_acf_point **pts, size_t *npts,
    rc_err *err);
const char *rc_acf_dir_name(enum rc_acf_dir d);

#endif
