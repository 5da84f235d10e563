/* SPDX-License-Identifier: GPL-3.0-or-later */
/* synth.h - surface synthesis (surfgen's library side).
 *
 * Self-affine random roughness with the spectrum of Eq. (2) of Wang &
 * Mueser (2020), optional Peklenik anisotropy (Eq. 3, renormalised so that
 * gamma = 1 is exactly isotropic), and deterministic single-asperity and
 * wave indenters.  Random phases are a function of (seed, integer wave
 * vector) only, so the same seed on a finer grid or with a smaller
 * lambda_s gives the same modes plus new ones.
 */
#ifndef RC_SYNTH_H
#define RC_SYNTH_H

#include <stdint.h>
#include "fft.h"
#include "grid.h"

enum rc_surface_type {
	RC_SURF_SELFAFFINE = 0,
	RC_SURF_HARMONIC,	/* Eq. 5, periodically repeated, apex at centre */
	RC_SURF_SINE,		/* h = amplitude * cos(2 pi x / wavelength) */
	RC_SURF_EGGBOX,		/* h = amplitude * cos(k x) cos(k y) */
	RC_SURF_FLAT
};

typedef struct rc_synth_params {
	enum rc_surface_type type;
	size_t nx, ny;
	double lx, ly;
	/* self-affine */
	double hurst;		/* H in (0, 1) */
	double lambda_r;	/* roll-off wavelength (0: max(lx, ly)) */
	double lambda_s;	/* short-wavelength cutoff (0: the least
				 * legal, two grid spacings in the Peklenik
				 * metric: max(2 dx/g, 2 dy g)) */
	int rolloff;		/* f_roll: C flat below q_r instead of zero */
	double peklenik;	/* gamma_P, 1 = isotropic */
	uint64_t seed;
	int gaussian_amplitudes;	/* Rayleigh moduli instead of sqrt(C) */
	/* normalisation: at most one of these is > 0.  selfaffine with both
	 * 0 (the default) is normalised to rms_gradient 1; the other types
	 * are scaled only if one is set explicitly (> 0). */
	double rms_gradient;
	double rms_height;
	/* harmonic */
	double exponent;	/* n */
	double radius;		/* R */
	/* sine, eggbox */
	double wavelength;	/* 0: lx; must divide lx (and ly for eggbox) */
	double amplitude;
} rc_synth_params;

/*
 * Self-affine modes: h(r) = sum_k a_k exp(i q_k . r) over the grid's wave
 * vectors q_k = 2 pi (kx/lx, ky/ly).  |a_k| is proportional to
 * sqrt(C(q_P)) with q_P = sqrt(g^2 qx^2 + qy^2/g^2), g the Peklenik
 * parameter (Eq. 3 without its 1/sqrt(g^4 + g^-4), so that g = 1 is
 * exactly isotropic).  A mode is kept iff q_r <= q_P < q_s (with a
 * relative tolerance of 1e-9 on both edges); with rolloff also every
 * 0 < q_P < q_r, at C(q_r).  The mean (k = 0) and the Nyquist row/column
 * are zero.  Phases (and Rayleigh moduli) come from a hash of (seed, kx,
 * ky) of the canonical half plane (kx > 0, or kx = 0 and ky > 0).
 */


void rc_synth_defaults(rc_synth_params *p);
/* Check every parameter; message names the first bad one. */
int rc_synth_check(const rc_synth_params *p, rc_err *err);
/* Make the surface; generation parameters go into the metadata
 * (type, H, lambda_r, lambda_s, rolloff, peklenik, seed, ...). */
rc_grid *rc_synth(const rc_synth_params *p, rc_err *err);
/* The same with the FFT planning effort of the self-affine transform
 * (rc_synth uses ESTIMATE, whose output is the same bit for bit for any
 * thread count) and the planning time into *plan_seconds (may be NULL;
 * 0 for types that need no transform).  The transform is done in place:
 * peak memory is one grid plus 2 ny values. */
rc_grid *rc_synth_planned(const rc_synth_params *p, enum rc_fft_effort effort,
    double *plan_seconds, rc_err *err);

/* The defaults resolved: lambda_r, lambda_s, wavelength actually used. */
double rc_synth_lambda_r(const rc_synth_params *p);
double rc_synth_lambda_s(const rc_synth_params *p);
double rc_synth_wavelength(const rc_synth_params *p);
/* Rows j0 ... j0 + rows - 1 of the unnormalised self-affine spectrum (nx/2+1
 * complex values per row, as rc_synth fills them before scaling), for a
 * distributed transform (make MPI=1); sums[j - j0] gets row j's share of
 * the normalisation sum (full plane of weight |a|^2, weight q^2 for the rms
 * gradient, 1 if rms_height is set): scale by target / sqrt(total). */
void rc_synth_selfaffine_rows(const rc_synth_params *p, fftw_complex *spec,
    size_t j0, size_t rows, double *sums);
/* Rows j0 ... j0 + rows - 1 (nx values each, into z) of a harmonic, sine,
 * egg-box or flat surface before any normalisation (make MPI=1). */
int rc_synth_pointwise_rows(const rc_synth_params *p, double *z, size_t j0,
    size_t rows, rc_err *err);
/* The kind and generation metadata rc_synth gives the surface, set on g,
 * scale the factor the normalisation applied to a pointwise type (1 for
 * selfaffine): for a header written without the values (make MPI=1). */
int rc_synth_meta(const rc_synth_params *p, rc_grid *g, double scale, rc_err *err);
/* The hash that seeds mode (kx, ky)'s random stream (exposed for tests). */
uint64_t rc_synth_mode_key(uint64_t seed, long kx, long ky);

const char *rc_surface_type_name(enum rc_surface_type t);
int rc_surface_type_parse(const char *name);	/* -1 if unknown */

#endif
