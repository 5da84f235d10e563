/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic_free.h - the compliance of an isolated patch of elastic half
 * space (free boundaries), by zero padding.
 *
 * A pressure sigma acts on the nx x ny pixels of the given area (pixel
 * dx = lx/nx by dy = ly/ny); outside it the surface is traction-free.  The
 * surface of the body then lies at
 *   u(r_i) = c + w_i,   w_i = sum_j C(r_i - r_j) sigma_j,
 * c the rigid level (the height of the surface far from the area, where
 * w -> 0), w the displacement into the body (upward: the body is above the
 * indenter).  C is Love's (1929) closed form for a uniform unit pressure on
 * one rectangular pixel centred at the origin, observed at (x, y):
 *   C(x, y) = 1/(pi E*) [ H(x+dx/2, y+dy/2) - H(x-dx/2, y+dy/2)
 *                        - H(x+dx/2, y-dy/2) + H(x-dx/2, y-dy/2) ],
 *   H(x, y) = sgn(x) sgn(y) [ |x| asinh(|y|/|x|) + |y| asinh(|x|/|y|) ],
 * H(x, y) the integral of 1/sqrt(x'^2 + y'^2) over [0, x] x [0, y] (and 0
 * on the axes), from Boussinesq's point-load Green's function
 * w = F / (pi E* r), E* = E / (1 - nu^2) the contact modulus.  The
 * pressure is taken constant on each pixel and w is sampled at the pixel
 * centres (the discretisation; its error is measured in
 * tests/test_free.c).
 *
 * The sum is a linear (not cyclic) convolution over offsets
 * -(n-1) ... n-1 per axis, so it is computed as a cyclic one on the
 * padded 2nx x 2ny grid (Hockney 1970; Liu, Wang & Liu, Wear 243, 2000):
 * C is tabulated there in wrap-around order (offset i at index i for
 * i < nx, at 2nx + i for i < 0; the unused offset nx gets C(nx dx) to
 * keep the table even), transformed once (real and even, so its spectrum
 * is real), and each application is one r2c of the zero-padded pressure,
 * a product, one c2r and a crop: one transform pair of 4N points.
 *
 * An elastic layer on a rigid substrate (layer.h) replaces C by its own
 * pixel compliance C_L (elastic_layer_free.h), exponentially local;
 * everything else is the same.  The padded circulant must be positive
 * definite for the solvers (the pressures minimise sigma.C sigma / 2;
 * adhesion inverts it): eig_min, its smallest eigenvalue, tells.
 *
 * Memory: the padded real buffer (4N doubles), its half spectrum
 * (about 2N complex) and the kernel's real spectrum (about 2N doubles):
 * about 80 bytes per point of the given area.
 */
#ifndef RC_ELASTIC_FREE_H
#define RC_ELASTIC_FREE_H

#include "fft.h"
#include "layer.h"
#include "love.h"

typedef struct rc_halfspace {
	size_t nx, ny, n;	/* the given area; n = nx * ny */
	double modulus;		/* E* */
	double self;		/* C(0, 0): lift of a pixel under its own unit pressure */
	double eig_min;		/* the padded circulant's smallest eigenvalue */
	double *kernel;		/* real spectrum of C / (4N), 2ny * (nx + 1) */
	rc_fft fft;		/* the 2nx x 2ny plans and buffers */
	unsigned long n_pairs;	/* applications (padded transform pairs) */
} rc_halfspace;

/* nx, ny >= 2 (a line has no free-boundary reference: the plane-strain
 * displacement grows logarithmically with distance). */
int rc_halfspace_init(rc_halfspace *e, size_t nx, size_t ny,
    double lx, double ly, double modulus, enum rc_fft_effort effort,
    rc_err *err);
/* The same with an elastic layer (layer.h; thickness 0 and
 * RC_SUBSTRATE_NONE: the half space) instead of the half space: the
 * table holds the layer's pixel compliance C_L of elastic_layer_free.h. */
int rc_halfspace_init_layer(rc_halfspace *e, size_t nx, size_t ny,
    double lx, double ly, double modulus, double thickness,
    enum rc_substrate substrate, double poisson, enum rc_fft_effort effort,
    rc_err *err);
void rc_halfspace_release(rc_halfspace *e);
/* out = w = C * sigma on the given area (nx*ny values each; out may be
 * sigma). */
void rc_halfspace_apply(rc_halfspace *e, const double *sigma,
    double *out);
size_t rc_halfspace_bytes(const rc_halfspace *e);

#endif
