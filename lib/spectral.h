/* SPDX-License-Identifier: GPL-3.0-or-later */
/* spectral.h - derivatives of a periodic grid through the FFT (the
 * spectral stencil of gradient.h).
 *
 * Exact for band-limited periodic data.  Odd derivatives zero the Nyquist
 * row/column (its derivative is not representable on the grid); the
 * Laplacian keeps it (-q^2 is real).  The rms gradient is defined as the rms
 * of the spectral gradient field, so
 *   rc_rms_gradient(g)^2 = (1/N^2) sum_q (qx'^2 + qy'^2) |h_q|^2,
 * q' the derivative wave numbers; this is Eq. (7) of Wang & Mueser (2020)
 * on the grid's modes.
 */
#ifndef RC_SPECTRAL_H
#define RC_SPECTRAL_H

#include "fft.h"
#include "gradient.h"
#include "grid.h"

/* Any of hx, hy (gradient) and lap (Laplacian) may be NULL; each non-NULL
 * one receives nx*ny values.  fft may be NULL (a plan is made and freed) or
 * a plan of the grid's size to reuse; its buffers are overwritten. */
int rc_spectral_derivs(const rc_grid *g, rc_fft *fft, double *hx, double *hy,
    double *lap, rc_err *err);

/* One derivative field (enum rc_deriv, gradient.h) at a time, left
 * normalised in fft->real (which the next use of the plan overwrites),
 * using no memory beyond the plan's two buffers: for callers that reduce
 * each field before making the next. */
int rc_spectral_deriv(const rc_grid *g, rc_fft *fft, enum rc_deriv which,
    rc_err *err);

/* rms gradient over the whole grid, from the spectrum (no gradient field). */
int rc_rms_gradient(const rc_grid *g, rc_fft *fft, double *gbar, rc_err *err);

/* Mean and rms of heights about the mean. */
void rc_mean_rms(const double *z, size_t n, double *mean, double *rms);

#endif
