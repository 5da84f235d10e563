/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver.c - the contact solver's state, its set-up (every option checked
 * together), the dispatch of a solve to its method and the accessors.
 * The options and their names are solver_opts.c; the convergence measure
 * that every method stops on, solver_measure.c.
 *
 * Free boundaries (opts.boundary): the padded compliance of
 * elastic_free.h replaces K and G; without K the measure is the gap
 * bound of solver_cg.c for both methods (FIRE then runs on the pressures,
 * solver_fire_free.c).
 *
 * A hardness (perfect plasticity): the CG (solver_cg.c) or FIRE on the
 * pressures (solver_fire_free.c) on either boundary kind, both on the
 * hardness cap (interaction.h, solver_hardness.c) instead of the hard
 * wall (solver_wall.c); the elastic periodic FIRE (solver_fire.c) is not
 * involved.
 */
#include "solver_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "clock.h"
#include "gridcheck.h"

/* Free boundaries: the padded compliance's smallest eigenvalue, relative
 * to C(0, 0), below which it is refused as singular (its round-off is
 * ~1e-13; measured on 64^2: 0.58 for the half space and any layer with
 * Poisson 0.3, 4e-5 for a bonded incompressible one with d = 4 dx). */
#define RC_FREE_EIG_MIN	1e-9

/* Whether the scratch field is needed: G t of the free CG, the force of
 * FIRE on pressures (free, or a hardness; the adhesive free FIRE has
 * padded fields of its own). */
static int
scratch_needed(const rc_solver *s)
{
	const rc_solver_opts *o = &s->opts;

	return !rc_solver_opts_adhesive(o) && (s->free_bc ||
	    (o->method == RC_METHOD_FIRE && rc_solver_opts_plastic(o)));
}

/* Long: every option is checked here, together, before anything is
 * allocated. */
rc_solver *
rc_solver_new(const rc_grid *ind, const rc_solver_opts *o, rc_err *err)
{
	rc_solver *s;
	size_t n, bad;

	if (rc_grid_check_uniform(ind, err) != 0)
		return NULL;
	if (o->method != RC_METHOD_FIRE && o->method != RC_METHOD_CG) {
		rc_seterr(err, "unknown solver method %d", (int)o->method);
		return NULL;
	}
	if (!(o->tol > 0) || !isfinite(o->tol)) {
		rc_seterr(err, "tolerance must be positive and finite");
		return NULL;
	}
	if (o->boundary != RC_BOUNDARY_PERIODIC && o->boundary != RC_BOUNDARY_FREE) {
		rc_seterr(err, "unknown boundary kind %d", (int)o->boundary);
		return NULL;
	}
	if (!(o->hardness >= 0)) {
		rc_seterr(err, "hardness must be positive (0 or inf: no cap)");
		return NULL;
	}
	if (rc_layer_check(o->thickness, o->substrate, o->poisson, err) < 0)
		return NULL;
	if (!(o->adhesion >= 0 && isfinite(o->adhesion)) ||
	    (o->adhesion > 0 && !(o->range > 0 && isfinite(o->range)))) {
		rc_seterr(err, "adhesion: want a work of adhesion >= 0 and a "
		    "positive, finite range");
		return NULL;
	}
	if (rc_adhesion_law_name(o->adhesion_law) == NULL) {
		rc_seterr(err, "unknown adhesive law %d", (int)o->adhesion_law);
		return NULL;
	}
	if (rc_solver_opts_adhesive(o) && o->method != RC_METHOD_FIRE) {
		rc_seterr(err, "adhesion needs the FIRE method (--method fire): "
		    "the CG solves a convex problem and adhesion is not one");
		return NULL;
	}
	if (rc_solver_opts_adhesive(o) && rc_solver_opts_plastic(o)) {
		rc_seterr(err, "adhesion with a hardness: not combined (the "
		    "plastic model keeps no history, so it has no unloading "
		    "branch, where pull-off and hysteresis happen)");
		return NULL;
	}
	if (o->kernel != RC_KERNEL_CONTINUUM && o->kernel != RC_KERNEL_PIXEL) {
		rc_seterr(err, "unknown elastic kernel %d", (int)o->kernel);
		return NULL;
	}
	if (o->kernel == RC_KERNEL_PIXEL && o->boundary == RC_BOUNDARY_PERIODIC &&
	    rc_layer_check(o->thickness, o->substrate, o->poisson, NULL) > 0) {
		rc_seterr(err, "a finite thickness has the continuum kernel only: "
		    "the pixel kernel would need the layer's factor on every "
		    "image of its sum (elastic.h)");
		return NULL;
	}
	if (o->stall_window < 0) {
		rc_seterr(err, "stall_window must not be negative");
		return NULL;
	}
	if (o->max_iter < 1) {
		rc_seterr(err, "max_iter must be at least 1");
		return NULL;
	}
	if (rc_grid_check_shape(ind->nx, ind->ny, ind->lx, ind->ly, err) != 0)
		return NULL;
	if (!rc_grid_all_finite(ind, &bad)) {
		rc_seterr(err, "indenter height %zu is not finite", bad);
		return NULL;
	}
	if ((s = rc_calloc(1, sizeof(*s), err)) == NULL)
		return NULL;
	s->opts = *o;
	s->nx = ind->nx;
	s->ny = ind->ny;
	s->n = n = ind->nx * ind->ny;
	s->lx = ind->lx;
	s->ly = ind->ly;
	s->free_bc = o->boundary == RC_BOUNDARY_FREE;
	/* Free boundaries: the padded compliance; FIRE on them also uses
	 * the periodic stiffness as its inverse mass (solver_fire_free.c);
	 * with adhesion the operator is the padded one, made later from the
	 * compliance (solver_fire_adh_free.c). */
	if ((s->free_bc && rc_halfspace_init_layer(&s->fel, s->nx, s->ny,
	    s->lx, s->ly, o->modulus, o->thickness, o->substrate, o->poisson,
	    o->fft_effort, err) != 0) ||
	    ((!s->free_bc || (o->method == RC_METHOD_FIRE &&
	    !rc_solver_opts_adhesive(o))) &&
	    rc_elastic_init(&s->el, s->nx, s->ny, s->lx, s->ly, o->modulus,
	    o->fft_effort, err) != 0)) {
		rc_halfspace_release(&s->fel);
		free(s);
		return NULL;
	}
	/* FIRE on pressures and CG minimise sigma.C sigma / 2, and the
	 * adhesive free FIRE inverts C: all need C positive definite.  A
	 * layer can lose it: an incompressible bonded layer keeps its
	 * volume, its compliance at q -> 0 (the mean eigenvalue) is 0. */
	if (s->free_bc && !(s->fel.eig_min > RC_FREE_EIG_MIN * s->fel.self)) {
		rc_seterr(err, "free boundaries need a positive definite "
		    "compliance: this layer's smallest eigenvalue is %.3g of "
		    "its self-compliance (an incompressible bonded layer, "
		    "Poisson 0.5, displaces no volume: on an area more than "
		    "about 20 thicknesses across give Poisson < 0.5)",
		    s->fel.eig_min / s->fel.self);
		rc_elastic_free(&s->el);
		rc_halfspace_release(&s->fel);
		free(s);
		return NULL;
	}
	if (!s->free_bc && (rc_elastic_set_kernel(&s->el, s->lx, s->ly,
	    o->kernel, err) != 0 || rc_fft_conv_init(&s->el.fft,
	    o->fft_effort, o->fft_block_points, err) != 0)) {
		rc_elastic_free(&s->el);
		free(s);
		return NULL;
	}
	/* A layer: the periodic operator's k_q (free FIRE: its inverse
	 * mass); the uniform compression only where the periodic body has
	 * no rigid level (free: in C_L, the approach the substrate's travel). */
	s->k_uniform = HUGE_VAL;
	if (rc_layer_check(o->thickness, o->substrate, o->poisson, NULL) > 0) {
		if (s->el.stiffness != NULL && rc_elastic_set_layer(&s->el,
		    s->lx, s->ly, o->thickness, o->substrate, o->poisson,
		    err) != 0) {
			rc_elastic_free(&s->el);
			rc_halfspace_release(&s->fel);
			free(s);
			return NULL;
		}
		if (!s->free_bc)
			s->k_uniform = rc_layer_uniform_stiffness(o->modulus,
			    o->thickness, o->poisson);
	}
	/* on huge pages (fft.h): they are first touched here */
	s->height = rc_fft_huge(n * sizeof(double), &s->height_block);
	s->sigma = rc_fft_huge(n * sizeof(double), &s->sigma_block);
	s->contact = calloc(n, 1);
	if (s->height == NULL || s->sigma == NULL || s->contact == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes of solver fields)",
		    n * (2 * sizeof(double) + 1));
		rc_solver_free(s);
		return NULL;
	}
	memcpy(s->height, ind->z, n * sizeof(double));
	memset(s->sigma, 0, n * sizeof(double));
	s->top = -HUGE_VAL;
	for (size_t k = 0; k < n; k++)
		if (s->height[k] > s->top)
			s->top = s->height[k];
	if ((o->method == RC_METHOD_FIRE ? rc__fire_alloc(s, err) :
	    rc__cg_alloc(s, err)) != 0 || (scratch_needed(s) &&
	    s->scratch == NULL && (s->scratch = rc_fft_huge(n * sizeof(double),
	    &s->scratch_block)) == NULL)) {
		if (scratch_needed(s) && s->scratch == NULL)
			rc_seterr(err, "out of memory (asked for %zu bytes)",
			    n * sizeof(double));
		rc_solver_free(s);
		return NULL;
	}
	if (s->free_bc && rc_solver_opts_adhesive(o) &&
	    rc__adh_free_init(s, err) != 0) {
		rc_solver_free(s);
		return NULL;
	}
	return s;
}

void
rc_solver_free(rc_solver *s)
{
	if (s == NULL)
		return;
	if (s->u != s->el.fft.real)
		rc_fft_huge_free(s->u, s->u_block);
	rc_elastic_free(&s->el);
	rc_halfspace_release(&s->fel);
	rc__adh_free_release(s);
	rc_fft_huge_free(s->scratch, s->scratch_block);
	rc_fft_huge_free(s->height, s->height_block);
	rc_fft_huge_free(s->sigma, s->sigma_block);
	free(s->contact);
	rc_fft_huge_free(s->fire_vel, s->vel_block);
	fftw_free(s->cg_dir);
	free(s);
}

int
rc_solver_set_max_iter(rc_solver *s, long max_iter, rc_err *err)
{
	if (max_iter < 1)
		return rc_seterr(err, "max_iter must be at least 1");
	s->opts.max_iter = max_iter;
	return 0;
}

int
rc_solver_set_displacement(rc_solver *s, const double *u, rc_err *err)
{
	size_t k;

	for (k = 0; k < s->n; k++)
		if (!isfinite(u[k]))
			return rc_seterr(err, "initial displacement %zu is not finite", k);
	memcpy(s->u, u, s->n * sizeof(double));
	s->have_u = 1;
	s->have_sigma = 0;
	s->pad.valid = 0;
	return 0;
}

int
rc_solver_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	double t0 = rc_clock();
	unsigned long transforms = s->el.n_r2c + s->el.n_c2r;
	unsigned long padded = s->fel.n_pairs;
	int r;

	memset(res, 0, sizeof(*res));
	s->watch.stalled = 0;
	if (rc_solver_opts_adhesive(&s->opts)) {
		if (!isfinite(p))
			return rc_seterr(err, "pressure must be finite");
		r = rc__fire_adh_solve(s, 0, &p, 0, res, err);
	} else if (!(p > 0) || !isfinite(p))
		return rc_seterr(err, "pressure must be positive and finite");
	else if (rc_solver_opts_plastic(&s->opts) && p > s->opts.hardness)
		return rc_seterr(err, "pressure %g exceeds the hardness %g: no "
		    "pressure field bounded by the hardness carries it", p,
		    s->opts.hardness);
	else if (s->opts.method == RC_METHOD_FIRE && (s->free_bc ||
	    rc_solver_opts_plastic(&s->opts)))
		r = rc__fire_sigma_solve(s, p, res, err);
	else if (s->opts.method == RC_METHOD_FIRE)
		r = rc__fire_solve(s, p, res, err);
	else
		r = rc__cg_solve(s, p, res, err);
	if (r < 0)
		return -1;
	s->last_pressure = p;
	res->seconds = rc_clock() - t0;
	/* Free: pairs of the padded 2nx x 2ny transform (FIRE adds its
	 * unpadded ones, solver_fire_free.c). */
	if (s->free_bc)
		res->fft_pairs += (double)(s->fel.n_pairs - padded);
	else
		res->fft_pairs = 0.5 * (double)(s->el.n_r2c + s->el.n_c2r - transforms);
	res->converged = r == 0;
	res->stalled = r == 1 && s->watch.stalled;
	return r;
}

const double *
rc_solver_displacement(const rc_solver *s)
{
	return s->u;
}

const double *
rc_solver_pressure(const rc_solver *s)
{
	return s->sigma;
}

/* The contact set.  FIRE: points with u = h after the projection onto
 * u >= h (bit-exact equality, the projection writes h) where the elastic
 * pressure p + K u is positive.  CG: points with sigma > 0 (its iterate is
 * zero exactly off contact).  At convergence these agree up to points whose
 * pressure is within the tolerance of zero, on the edge of the contact. */
const unsigned char *
rc_solver_contact(const rc_solver *s)
{
	return s->contact;
}

double
rc_solver_elastic_energy(const rc_solver *s)
{
	double p = s->last_pressure;

	return s->energy + (isfinite(s->k_uniform) ? 0.5 * p * p / s->k_uniform : 0);
}

double
rc_solver_mean_gap(const rc_solver *s)
{
	size_t k;
	double sum = 0;

#pragma omp parallel for reduction(+:sum) schedule(static)
	for (k = 0; k < s->n; k++)
		sum += s->u[k] - s->height[k];
	rc_elastic_sum(&s->el, &sum, 1);
	return sum / rc__points(s);
}

double
rc_solver_approach(const rc_solver *s)
{
	size_t k;
	double sum = 0;

	if (s->free_bc)
		return s->top - s->level;
#pragma omp parallel for reduction(+:sum) schedule(static)
	for (k = 0; k < s->n; k++)
		sum += s->u[k];
	rc_elastic_sum(&s->el, &sum, 1);
	return s->top - sum / rc__points(s) +
	    (isfinite(s->k_uniform) ? s->last_pressure / s->k_uniform : 0);
}

double
rc_solver_adhesive_pressure(const rc_solver *s)
{
	return rc_solver_opts_adhesive(&s->opts) ? s->p_adh : 0;
}

double
rc_solver_attractive_fraction(const rc_solver *s)
{
	return rc_solver_opts_adhesive(&s->opts) ? s->a_attr : 0;
}

/* The interaction's own column (interaction.h): the cap's; 0 for the
 * wall and for the methods in heights, which have no cap. */
double
rc_solver_plastic_fraction(const rc_solver *s)
{
	rc__interaction in;

	rc__interaction_of(s, &in);
	return in.plastic_fraction ? in.plastic_fraction(s) : 0;
}

rc_fft *
rc_solver_fft(rc_solver *s)
{
	return s->free_bc || s->el.dist != NULL || s->el.fft.real == NULL ?
	    NULL : &s->el.fft;
}

size_t
rc_solver_bytes(const rc_solver *s)
{
	size_t b = sizeof(*s) + rc_halfspace_bytes(&s->fel) +
	    rc_elastic_bytes(&s->el) + rc__adh_free_bytes(s);
	b += s->n * (2 * sizeof(double) + 1);	/* height, sigma, contact */
	if (s->u != s->el.fft.real)
		b += s->n * sizeof(double);
	if (s->fire_vel)
		b += s->n * sizeof(double);
	if (s->cg_dir)
		b += s->n * sizeof(double);
	if (s->scratch)
		b += s->n * sizeof(double);
	return b;
}
