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
	double lambda_r;	/* roll-off wavelength (default lx) */
	double lambda_s;	/* short-wavelength cutoff (default 2 lx/nx) */
	int rolloff;		/* f_roll: C flat below q_r instead of zero */
	double peklenik;	/* gamma_P, 1 = isotropic */
	uint64_t seed;
	int gaussian_amplitudes;	/* Rayleigh moduli instead of sqrt(C) */
	/* normalisation: exactly one of these is > 0 (rms_gradient default 1);
	 * applies to selfaffine; for the others only if set explicitly */
	double rms_gradient;
	double rms_height;
	/* harmonic */
	double exponent;	/* n */
	double radius;		/* R */
	/* sine, eggbox */
	double wavelength;
	double amplitude;
} rc_synth_params;

void rc_synth_defaults(rc_synth_params *p);
/* Check every parameter; message names the first bad one. */
int rc_synth_check(const rc_synth_params *p, rc_err *err);
/* Make the surface; generation parameters go into the metadata
 * (type, H, lambda_r, lambda_s, rolloff, peklenik, seed, ...). */
rc_grid *rc_synth(const rc_synth_params *p, rc_err *err);

const char *rc_surface_type_name(enum rc_surface_type t);
int rc_surface_type_parse(const char *name);	/* -1 if unknown */

#endif
