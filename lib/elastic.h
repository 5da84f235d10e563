/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic.h - the elastic operator of a periodic half space, shared by the
 * contact solvers.
 *
 * Mode q of the surface height u has stiffness k_q = |q| E* / 2 per unit
 * area, so the pressure that holds u is p + (K u)(r) with
 *   K u = IFFT[k_q FFT(u)],
 * and the height that a pressure field sigma of mean p produces is
 *   u = G sigma + const,   G_q = 1 / k_q (q != 0), G_0 = 0.
 * The Nyquist modes are kept: k_q is even in q.  An nx x 1 grid is a line
 * contact (plane strain): qy = 0 for every mode.
 *
 * The operator owns one FFTW plan pair and its two buffers (fft.real,
 * fft.spec) and a table of k_q over the half-complex modes; the transforms
 * below may also run on other FFTW-allocated arrays (new-array execute).
 */
#ifndef RC_ELASTIC_H
#define RC_ELASTIC_H

#include "fft.h"
#include "layer.h"

typedef struct rc_elastic {
	size_t nx, ny, nxc, n;	/* n = nx * ny */
	double modulus;		/* E* */
	double *stiffness;	/* k_q, ny * nxc, row j, column i */
	double k_min, k_max;	/* smallest non-zero and largest k_q */
	rc_fft fft;
	/* Transforms run through this operator (for the cost report). */
	unsigned long n_r2c, n_c2r;
} rc_elastic;

int rc_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx,
    double ly, double modulus, enum rc_fft_effort effort, rc_err *err);
void rc_elastic_free(rc_elastic *e);
/* An elastic layer of the given thickness on a rigid substrate instead of
 * the half space: every k_q (q != 0) times rc_layer_factor(|q| d) (layer.h);
 * k_0 stays 0 (the uniform mode is the solver's, see solver.c).  Serial
 * build only. */
int rc_elastic_set_layer(rc_elastic *e, double lx, double ly,
    double thickness, enum rc_substrate substrate, double poisson, rc_err *err);

/* Unnormalised r2c from in (nx*ny reals) to out (ny*nxc); in is kept. */
void rc_elastic_r2c(rc_elastic *e, const double *in, fftw_complex *out);
/* Unnormalised c2r from in to out; in is destroyed. */
void rc_elastic_c2r(rc_elastic *e, fftw_complex *in, double *out);

/* out = K u (mean zero).  Uses fft.spec; out may be fft.real or u. */
void rc_elastic_force(rc_elastic *e, const double *u, double *out);
/* out = G sigma (mean zero).  Uses fft.spec; out may be fft.real or sigma. */
void rc_elastic_displacement(rc_elastic *e, const double *sigma, double *out);
/* Elastic energy per unit area (1/2) sum_q k_q |u_q|^2 / N^2 of the
 * unnormalised spectrum U = FFT(u) (full-spectrum sum over half storage). */
double rc_elastic_energy_spec(const rc_elastic *e, const fftw_complex *spec);

/* Bytes held (table and FFT buffers). */
size_t rc_elastic_bytes(const rc_elastic *e);

#endif
