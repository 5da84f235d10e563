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
 * Two kernels (enum rc_kernel, rc_elastic_set_kernel):
 *
 *   continuum  k_q = |q| E* / 2 on the first Brillouin zone: the
 *              continuum half space, its heights band-limited to the grid
 *              (the default).
 *   pixel      the lattice-consistent kernel: the pressure is uniform on
 *              each dx x dy pixel and the height is sampled at the pixel
 *              centres, the discretisation of the boundary-element method
 *              and of free boundaries (Love's pixel compliance,
 *              elastic_free.h), here periodic.  The pressure field
 *              sum_j sigma_j Pi(r - r_j), Pi the pixel's indicator, has the
 *              Fourier coefficients (1/N) S(Q) F(Q), S the DFT of sigma_j
 *              (periodic in Q with the reciprocal lattice 2 pi m / dx) and
 *              F(Q) = sinc(Qx dx/2) sinc(Qy dy/2), sinc x = sin x / x, the
 *              pixel's transform over its area.  Each Q responds with
 *              2 / (E* |Q|); sampling at the centres r_i = i dx folds every
 *              image Q = q + 2 pi (mx/dx, my/dy) onto q, so
 *                G_q = sum_m  2 / (E* |q + 2 pi m / d|)
 *                             sinc(a + pi mx) sinc(b + pi my),
 *                a = qx dx / 2, b = qy dy / 2,  k_q = 1 / G_q (q != 0).
 *              One sinc per axis, not its square: the height is sampled at
 *              a point, not averaged over the pixel (that would be the
 *              Galerkin kernel, sinc^2).  sinc(a + pi m) = (-1)^m sin a /
 *              (a + pi m), so the images alternate in sign and fall like
 *              1 / (mx my |m|): the sum converges absolutely.  Truncation
 *              (rc_pixel_compliance): |mx|, |my| <= 8 with the outermost
 *              ring weighted 1/2 (its error then falls like M^-4 instead of
 *              M^-3), and one Richardson step from M = 4 to 8,
 *              G = (16 S_8 - S_4) / 15.  Measured against M = 600 on a
 *              13 x 13 net of the quarter zone: worst relative error
 *              3.9e-6 for square pixels, 6.0e-6 for dx/dy = 2, 4.0e-5 for
 *              dx/dy = 4, 1.6e-6 for a line (nx x 1: a = 0 on the uniform
 *              axis leaves its m = 0 image only); the halved sum alone at
 *              M = 8 errs by 1.3e-4.  Small q: G_q = 2/(E* |q|) (1 +
 *              O((q dx)^2)), the continuum kernel; at the zone corner
 *              (a = b = pi/2, square pixels) the pixel body is 1.29 times
 *              softer.  Both kernels tend to the same self-compliance
 *              (1/N) sum_q G_q -> 4 ln(1 + sqrt 2) dx / (pi E*) for
 *              square pixels as N grows, Love's C(0, 0): they differ in
 *              how a pixel's load spreads, not in how much it sinks.  Cost: (2M+1)^2 = 289 terms for
 *              each of about N/2 distinct |qx|, |qy| (even in each).
 *
 * The operator owns one FFTW plan pair and its two buffers (fft.real,
 * fft.spec) and a table of k_q over the half-complex modes; the transforms
 * below may also run on other FFTW-allocated arrays (new-array execute).
 */
#ifndef RC_ELASTIC_H
#define RC_ELASTIC_H

#include "fft.h"
#include "layer.h"

enum rc_kernel {
	RC_KERNEL_CONTINUUM = 0,
	RC_KERNEL_PIXEL
};

const char *rc_kernel_name(enum rc_kernel k);
int rc_kernel_parse(const char *name);		/* -1 if unknown */

struct rc_elastic;

/* The seam to a distributed build (make MPI=1; lib/mpi/delastic.c
 * implements it): an operator with dist set holds this process's rows of
 * the grid (ny and the fields local, n the global point count), its
 * transforms run through r2c and c2r, and every sum or maximum over
 * points, here and in the solver, is completed through sum and max (in
 * place, over all processes).  NULL, the serial operator: no call goes
 * through it, so one build of the library serves both. */
typedef struct rc_elastic_dist {
	void (*sum)(double *v, int count);
	void (*max)(double *v, int count);
	void (*r2c)(struct rc_elastic *e, const double *in, fftw_complex *out);
	void (*c2r)(struct rc_elastic *e, fftw_complex *in, double *out);
} rc_elastic_dist;

typedef struct rc_elastic {
	size_t nx, ny, nxc, n;	/* n = nx * ny (dist: ny local, n global) */
	double modulus;		/* E* */
	double *stiffness;	/* k_q, ny * nxc, row j, column i */
	void *stiffness_block;	/* rc_fft_huge's block; NULL: stiffness */
	double k_min, k_max;	/* smallest non-zero and largest k_q */
	enum rc_kernel kernel;	/* of the table */
	rc_fft fft;
	/* Transforms run through this operator (for the cost report). */
	unsigned long n_r2c, n_c2r;
	const rc_elastic_dist *dist;	/* NULL: serial (above) */
} rc_elastic;

int rc_elastic_init(rc_elastic *e, size_t nx, size_t ny, double lx,
    double ly, double modulus, enum rc_fft_effort effort, rc_err *err);
void rc_elastic_free(rc_elastic *e);
/* An elastic layer of the given thickness on a rigid substrate instead of
 * the half space: every k_q (q != 0) times rc_layer_factor(|q| d) (layer.h);
 * k_0 stays 0 (the uniform mode is the solver's, see solver.c).  Serial
 * operator only. */
int rc_elastic_set_layer(rc_elastic *e, double lx, double ly,
    double thickness, enum rc_substrate substrate, double poisson, rc_err *err);

/* The pixel kernel instead of the continuum one (RC_KERNEL_CONTINUUM:
 * nothing changes): every k_q (q != 0) becomes 1 / G_q of the pixel
 * compliance above; k_0 stays 0.  Before rc_elastic_set_layer, which
 * refuses to follow it (the layer's factor would have to weight every
 * image).  Serial operator only. */
int rc_elastic_set_kernel(rc_elastic *e, double lx, double ly,
    enum rc_kernel kernel, rc_err *err);
/* E* G_q of the pixel kernel for the wave vector (qx, qy) and pixel
 * dx x dy (0 at q = 0, whose mean is the solver's). */
double rc_pixel_compliance(double qx, double qy, double dx, double dy);

/* Unnormalised r2c from in (nx*ny reals) to out (ny*nxc); in is kept. */
void rc_elastic_r2c(rc_elastic *e, const double *in, fftw_complex *out);
/* Unnormalised c2r from in to out; in is destroyed. */
void rc_elastic_c2r(rc_elastic *e, fftw_complex *in, double *out);

/* out = K u (mean zero).  Uses fft.spec; out may be fft.real or u. */
void rc_elastic_force(rc_elastic *e, const double *u, double *out);
/* out = G sigma (mean zero).  Uses fft.spec; out may be fft.real or sigma. */
void rc_elastic_displacement(rc_elastic *e, const double *sigma, double *out);
/* out = IFFT[c_q FFT(in)] with the multiplier mu (fft.h), one transform
 * pair counted; a distributed operator's through its r2c and c2r. */
void rc_elastic_convolve(rc_elastic *e, const double *in, double *out,
    const rc_fft_multiplier *mu);
/* Elastic energy per unit area (1/2) sum_q k_q |u_q|^2 / N^2 of the
 * unnormalised spectrum U = FFT(u) (full-spectrum sum over half storage). */
double rc_elastic_energy_spec(const rc_elastic *e, const fftw_complex *spec);

/* v[0 .. count-1] summed, or maximised, over the processes a distributed
 * operator spans, in place; nothing for a serial one. */
void rc_elastic_sum(const rc_elastic *e, double *v, int count);
void rc_elastic_max(const rc_elastic *e, double *v, int count);

/* Bytes held (table and FFT buffers). */
size_t rc_elastic_bytes(const rc_elastic *e);

#endif
