/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver.h - frictionless contact (non-adhesive unless opts.adhesion:
 * adhesion.h, solver_fire_adh.c) of a linearly elastic
 * half space (above) on a rigid indenter of heights h (below), either
 * periodic (the grid is one cell of an infinite periodic surface) or with
 * free boundaries (the grid is an isolated patch of an infinite half
 * space, traction-free outside it: elastic_free.h).
 *
 * The elastic surface height u(r) obeys u >= h; gap g = u - h; the contact
 * pressure sigma(r) >= 0 acts only where g = 0, and its mean equals the
 * applied pressure.  Each Fourier mode of u has stiffness q E* / 2 per unit
 * area (Wang & Mueser 2020, section 2; gfmd-solve(1); or the pixel kernel
 * of elastic.h, opts.kernel).  Two independent
 * methods share this interface: FIRE-GFMD (Zhou, Moseler & Mueser 2019)
 * and Polonsky & Keer's constrained conjugate gradient (1999).
 *
 * A solver keeps its plans, buffers and current solution, so solving a
 * list of pressures in order warm-starts each from the previous one.
 */
#ifndef RC_SOLVER_H
#define RC_SOLVER_H

#include "adhesion.h"
#include "elastic.h"
#include "grid.h"
#include "layer.h"

enum rc_method {
	RC_METHOD_FIRE = 0,
	RC_METHOD_CG
};

enum rc_boundary {
	RC_BOUNDARY_PERIODIC = 0,
	RC_BOUNDARY_FREE
};

typedef struct rc_solver_opts {
	enum rc_method method;
	/* Free boundaries: grids of at least 2 x 2; FIRE runs on pressures
	 * there, and with a hardness (solver_fire_free.c). */
	enum rc_boundary boundary;
	double modulus;		/* contact modulus E* (default 1) */
	/* The periodic elastic kernel (elastic.h): the continuum q E* / 2
	 * (default) or the lattice-consistent pixel one; FIRE's masses and
	 * CG's compliance both follow it.  Free boundaries always solve with
	 * Love's pixel compliance (elastic_free.h), the discretisation of
	 * RC_KERNEL_PIXEL, and ignore it.  The periodic pixel kernel has no
	 * layer. */
	enum rc_kernel kernel;
	/* Perfect plasticity: sigma <= hardness (pressure units, like p);
	 * 0 or +inf: no cap (the default).  Both methods, both boundary
	 * kinds, a layer, displacement control; not with adhesion
	 * (the cap of solver_hardness.c, which solver_cg.c and FIRE on
	 * pressures, solver_fire_free.c, run on; gfmd-solve(1)
	 * PLASTICITY). */
	double hardness;
	/* An elastic layer of this thickness (lateral length units) on a
	 * rigid substrate instead of the half space: k_q of layer.h.  0 with
	 * RC_SUBSTRATE_NONE: the half space (the default).  Either boundary
	 * kind (free: the pixel compliance of elastic_layer_free.h, refused
	 * when it is not positive definite); poisson is the layer's ratio,
	 * in (-1, 0.5]. */
	double thickness;
	enum rc_substrate substrate;
	double poisson;
	/* Adhesion: the law `adhesion_law' of adhesion.h (exponential, the
	 * default, or Dugdale's cohesive zone) with work of adhesion
	 * `adhesion' (pressure times length) and range `range' (length:
	 * the exponential's decay length, Dugdale's critical opening);
	 * 0: none (the default).  FIRE, on either boundary kind
	 * (solver_fire_adh.c, solver_fire_adh_free.c, gfmd-solve(1)
	 * ADHESION); the pressure may then be zero or negative and the
	 * approach any finite value. */
	double adhesion;
	double range;
	enum rc_adhesion_law adhesion_law;
	double tol;		/* scale-free convergence tolerance (see the .c) */
	long max_iter;		/* per solve */
	/* FFT planning effort (fft.h); RC_FFT_ESTIMATE by default.  The MPI
	 * solver (lib/mpi/dsolver.h) plans with FFTW_ESTIMATE for
	 * RC_FFT_ESTIMATE and with FFTW_MEASURE for any other effort. */
	enum rc_fft_effort fft_effort;
	/* Periodic grids of at least this many points take the blocked
	 * transforms (fft.h, rc_fft_convolve), on which FIRE runs its passes
	 * block by block (solver_fire_loop.c); RC_FFT_BLOCKED_POINTS by default,
	 * 0 for always, SIZE_MAX for never (the same answers to rounding).
	 * Serial build. */
	size_t fft_block_points;
	/* A solve whose convergence measure has not halved (its best value
	 * so far against the best before) within this many iterations ends
	 * as stalled (rc_solve_result.stalled; returns 1) instead of running
	 * on to max_iter; 0: never.  Default RC_STALL_WINDOW: measured
	 * converging solves (tol 1e-6, synthetic and measured maps, both
	 * methods and boundary kinds) halve it within 60 iterations. */
	long stall_window;
	/* Called every few iterations if not NULL (progress on a terminal). */
	void (*progress)(void *ctx, long iter, double residual, double contact_fraction);
	void *progress_ctx;
	/* Polled every iteration if not NULL; non-zero stops the solve early
	 * (SIGINT handling); the solve then returns 1 (not converged). */
	volatile int *stop;
} rc_solver_opts;

typedef struct rc_solve_result {
	long iterations;
	double residual;	/* the convergence measure reached */
	double seconds;		/* wall time of this solve */
	double fft_pairs;	/* (r2c + c2r transforms) / 2 of this solve */
	int converged;
	/* 1 when the solve ended because it stalled (opts.stall_window). */
	int stalled;
	/* Adhesion under load control: 1 when the solve stopped because the
	 * body separated (no contact and the applied tension stronger than
	 * the strongest attraction left: no equilibrium, past pull-off). */
	int separated;
} rc_solve_result;

typedef struct rc_solver rc_solver;

#define RC_STALL_WINDOW	300

void rc_solver_defaults(rc_solver_opts *o);
const char *rc_method_name(enum rc_method m);
int rc_method_parse(const char *name);		/* -1 if unknown */
const char *rc_boundary_name(enum rc_boundary b);
int rc_boundary_parse(const char *name);	/* -1 if unknown */

/* The indenter is copied; it may be freed afterwards. */
rc_solver *rc_solver_new(const rc_grid *indenter, const rc_solver_opts *o,
    rc_err *err);
void rc_solver_free(rc_solver *s);

/* Warm start from an elastic surface height field u (nx*ny values). */
int rc_solver_set_displacement(rc_solver *s, const double *u, rc_err *err);
/* The iteration limit of the solves that follow (at least 1): what is
 * left of opts.max_iter when a solve goes on in pieces (a checkpoint
 * resumed or taken on a timer), so the pieces together stop where one
 * solve would. */
int rc_solver_set_max_iter(rc_solver *s, long max_iter, rc_err *err);

/* Solve at mean (absolute) pressure p > 0 (free: over the given area, so
 * the load is p lx ly; with adhesion any finite p: res->separated).  Returns 0 if converged, 1 if
 * it stopped at max_iter or on *stop (the state is still the best reached
 * and the accessors below are valid), -1 on an error. */
int rc_solver_solve(rc_solver *s, double pressure, rc_solve_result *res,
    rc_err *err);

/* Displacement control: solve for the mean pressure p at which the
 * approach (rc_solver_approach) equals delta > 0, by a bracketed 1-D root
 * find on log p (GSL's Brent), each trial a warm-started load-controlled
 * solve (solver_approach.c); |approach - delta| <= opts.tol * delta at
 * the end.  *pressure gets p; res sums the iterations, transform pairs
 * and time of all trials.  Periodic: delta must be below max h - <h>
 * (full contact), unless a hardness flattens the indenter or a layer
 * with poisson < 0.5 compresses (k_0 finite).  A hardness
 * H: p stays below H, and delta must be below the approach reached as
 * p -> H (about max h - min h plus the elastic deflection; beyond it the
 * whole area flows: an error, solver_approach.c).  Returns as
 * rc_solver_solve. */
/* With adhesion: any finite delta, solved directly by FIRE with the mean
 * height (free boundaries: the rigid level) held (solver_fire_adh.c,
 * solver_fire_adh_free.c), which traces unstable branches too; a periodic
 * layer with its rigid substrate held at delta instead (the mean mode on
 * the spring k_0, the load p = k_0 (<u> - max h + delta) following the
 * state; no full-contact bound), so the approach is delta to rounding;
 * poisson 0.5 (k_0 infinite) is held as the half space. */
int rc_solver_solve_approach(rc_solver *s, double delta, double *pressure,
    rc_solve_result *res, rc_err *err);

/* The approach of the current solution: how far the rigid reference of
 * the elastic body has moved towards the indenter since it first touched
 * it (at zero load, the flat body at the height of the highest point of h):
 *   free:     delta = max h - c, c the rigid level (the surface height far
 *             from the area, elastic_free.h);
 *   periodic: delta = max h - <u>, the mean surface height being the only
 *             reference of a periodic body (so delta = mean-gap change:
 *             (max h - <h>) - <u - h>);
 *   a layer:  periodic, delta = max h - <u> + p / k_0, the travel of
 *             the rigid substrate (k_0 of layer.h: the uniform
 *             compression); free, max h - c as above, c the undeformed
 *             top of the layer far from the area, so again the
 *             substrate's travel (the layer's compliance C_L holds all
 *             of its compression: no p / k_0 term).
 * For a Hertz indenter h = -r^2/(2R) (free) this is the a^2/R of
 * Hertz. */
double rc_solver_approach(const rc_solver *s);

/* The current solution, valid until the next solve or free. */
const double *rc_solver_displacement(const rc_solver *s);	/* u(r) */
const double *rc_solver_pressure(const rc_solver *s);		/* sigma(r) >= 0 */
/* The contact set: 1 where the point is in contact, as decided by the
 * method (documented in gfmd-solve(1)); both methods agree at convergence. */
const unsigned char *rc_solver_contact(const rc_solver *s);
/* Elastic energy per unit area, (1/2) sum_q (q E* / 2) |u_q|^2 / N^2
 * (periodic; a layer: its k_q, plus p^2 / (2 k_0) of the uniform
 * compression); free: (1/2) <sigma w> over the given area, the work of the
 * pressure per unit area of it (a layer's too). */
double rc_solver_elastic_energy(const rc_solver *s);
/* Mean gap <u - h>. */
double rc_solver_mean_gap(const rc_solver *s);
/* Fraction of the points at the hardness, sigma >= H (0 without a cap). */
double rc_solver_plastic_fraction(const rc_solver *s);
/* Whether opts.hardness caps the pressure (finite and positive). */
int rc_solver_opts_plastic(const rc_solver_opts *o);
/* Whether opts.adhesion switches the adhesive law on (positive). */
int rc_solver_opts_adhesive(const rc_solver_opts *o);
/* Adhesion (0 without): the mean adhesive pressure p_adh = <sigma_a(g)>
 * over all points (<= 0; contact points count sigma_a(0) = -sigma_max,
 * so p = <wall reaction> + p_adh), and the attractive-area fraction: the
 * points off contact with g < rho, where the attraction exceeds
 * sigma_max / e. */
double rc_solver_adhesive_pressure(const rc_solver *s);
double rc_solver_attractive_fraction(const rc_solver *s);
/* Bytes the solver holds (for the memory report). */
size_t rc_solver_bytes(const rc_solver *s);
/* The periodic solver's FFT plans (NULL on free boundaries), which a
 * caller may use between solves: their buffers are the solver's scratch
 * and hold nothing a later solve reads (gfmd-solve's contact analysis
 * shares them instead of planning and allocating its own).  NULL on free
 * boundaries and for a distributed operator. */
rc_fft *rc_solver_fft(rc_solver *s);

#endif
