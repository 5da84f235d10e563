/* SPDX-License-Identifier: GPL-3.0-or-later */
/* psd.h - power spectrum and height-difference autocorrelation.
 *
 * Convention (Eq. 7 of Wang & Mueser 2020; roughcontact(7), CONVENTIONS):
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

/*
 * Windows for finite patches.  A non-periodic grid (g->periodic = 0) has
 * unrelated opposite edges; its DFT sees a step there whose spectrum,
 * ~q^-2 per axis, buries any C(q) that falls faster (edge leakage).  So a
 * finite patch is, by default (RC_WINDOW_AUTO), demeaned and multiplied by
 * a separable Hann window w(i) w(j) before the transform, and the power
 * divided by mean(w^2) over the grid: for white noise the expected
 * sum_k C(q_k) dq^2 is then <h^2> again.  A periodic grid gets no window
 * under AUTO, and its spectrum is the same bit for bit as before windows
 * existed.  On an axis of n >= 2 points, with t = (i + 1/2) / n:
 *   hann      w = (1 - cos 2 pi t) / 2
 *   blackman  w = 0.42 - 0.5 cos 2 pi t + 0.08 cos 4 pi t
 *   tukey     w = (1 - cos 4 pi t) / 2 for t < 1/4 (mirrored for t > 3/4),
 *             1 in between (cosine tapers over a quarter at each end)
 *   none      w = 1
 * An axis of one point is not windowed.
 */
enum rc_window {
	RC_WINDOW_AUTO = -1,	/* hann for a finite patch, none if periodic */
	RC_WINDOW_NONE = 0,
	RC_WINDOW_HANN,
	RC_WINDOW_BLACKMAN,
	RC_WINDOW_TUKEY
};
double rc_window_value(enum rc_window w, size_t k, size_t n);
const char *rc_window_name(enum rc_window w);
int rc_window_parse(const char *name);	/* -1 if unknown */
/* AUTO resolved for g. */
enum rc_window rc_window_resolve(const rc_grid *g, enum rc_window w);

/* Full-plane 2D spectrum as a grid of kind spectrum, q = 0 at index
 * (nx/2, ny/2) (integer division): value (i, j) is C at
 * qx = (i - nx/2) 2 pi/lx, qy = (j - ny/2) 2 pi/ly.  The grid's lx, ly are
 * the q extents nx 2 pi/lx, ny 2 pi/ly; metadata records dqx, dqy, the
 * index of q = 0 and the convention. */
rc_grid *rc_psd2d(const rc_grid *g, rc_fft *fft, rc_err *err);
/* With a window (rc_psd2d uses RC_WINDOW_AUTO); metadata window = name. */
rc_grid *rc_psd2d_window(const rc_grid *g, rc_fft *fft, enum rc_window window,
    rc_err *err);

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
int rc_psd_radial_window(const rc_grid *g, rc_fft *fft, double bins_per_decade,
    enum rc_window window, rc_psd_bin **bins, size_t *nbins, rc_err *err);

/*
 * 1D spectra of the lines of a map (along x: the ny rows; along y: the nx
 * columns), averaged over the lines; a profile is an nx x 1 grid.  For a
 * line of n points and length L, h_k its unnormalised DFT (after removing
 * the line's mean and applying the window, power divided by mean(w^2)):
 *   C1D(q_k) = |h_k|^2 L / (2 pi n^2),   q_k = 2 pi k / L,
 * the transform of the height autocorrelation in our convention,
 *   C1D(q) = (2 pi)^-1 int dx <h(0) h(x)> exp(-i q x),
 * so that, with dq = 2 pi / L, sum over all k != 0 (both signs) of
 * C1D dq = <h^2> - <h>^2 of a line.  Units: length^3.  The
 * contact.engineering convention (Jacobs, Junge & Pastewka 2017),
 * C1D(q) = L^-1 |int dx h(x) exp(-i q x)|^2 with
 * <h^2> = (2 pi)^-1 int dq C1D over all q, is 2 pi times ours.
 * Points k = 1 .. n/2 (q = 0 left out); std_err is the standard
 * deviation over the lines / sqrt(lines), NaN for one line.
 */
enum rc_psd1d_dir { RC_PSD1D_X = 0, RC_PSD1D_Y };

typedef struct rc_psd1d_point {
	double q;
	double c;		/* C1D in our convention */
	size_t n_lines;
	double std_err;
} rc_psd1d_point;

int rc_psd1d(const rc_grid *g, enum rc_psd1d_dir dir, enum rc_window window,
    rc_psd1d_point **pts, size_t *npts, rc_err *err);

/* Spectral moments of profiles along x: m0 = sum C dq^2 without q = 0,
 * m2 = sum qx'^2 C dq^2, m4 = sum qx^4 C dq^2 (qx' Nyquist-zeroed as for a
 * first derivative); Nayak's alpha = m0 m4 / m2^2. */
int rc_psd_moments_x(const rc_grid *g, rc_fft *fft, double *m0, double *m2,
    double *m4, rc_err *err);

/* Height-difference autocorrelation G(r) = <(h(r0 + r) - h(r0))^2> over
 * all r0.  Along x: r = i dx, i = 0 .. nx/2; along y likewise;
 * radial: every lattice displacement with |r| <= min(lx, ly)/2 binned by
 * round(|r|/dr), dr = max(dx, dy) (for an nx x 1 or 1 x ny profile: up to
 * half its length, dr its spacing).  A periodic grid averages over every
 * r0 with wrap-around (n = displacements averaged); a finite patch
 * (periodic = 0) over the pairs that lie inside it, from zero-padded
 * transforms (no pair wraps; n = pairs along x and y, displacements in a
 * radial bin, whose mean is weighted by the pairs).  With half set the
 * result is G/2, the convention of the structure function
 * A(r) = <(h(r0 + r) - h(r0))^2> / 2 of contact.engineering. */
enum rc_acf_dir { RC_ACF_X = 0, RC_ACF_Y, RC_ACF_RADIAL };

typedef struct rc_acf_point {
	enum rc_acf_dir dir;
	double r;		/* mean |r| of the displacements averaged */
	double g;		/* G(r) */
	size_t n;		/* displacements averaged */
} rc_acf_point;

int rc_acf(const rc_grid *g, rc_fft *fft, rc_acf_point **pts, size_t *npts,
    rc_err *err);
int rc_acf_ex(const rc_grid *g, rc_fft *fft, int half, rc_acf_point **pts,
    size_t *npts, rc_err *err);
const char *rc_acf_dir_name(enum rc_acf_dir d);

#endif
