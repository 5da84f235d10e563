/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_measure.c - what every method of the solver shares about the
 * load: the convergence measure and the warm start scaled to a load.
 *
 * Convergence (one measure for both methods).  A method stops when the
 * residual of its current admissible pair
 *   u >= h  (elastic surface height, no penetration),
 *   sigma >= 0, sigma = 0 off the contact set  (no tension),
 * falls to opts.tol, where
 *   residual = max( rms_r[p + (K u)(r) - sigma(r)] / p,  |<sigma> - p| / p ).
 * The first term is the equilibrium of every point (the elastic pressure
 * that u needs, p + K u, must be supplied by the wall where in contact and
 * vanish elsewhere), measured in units of the applied pressure; the second
 * is load balance.  Both are scale-free (invariant under r -> s r, h -> t h
 * with p and E* scaled to keep p* fixed).  FIRE keeps u admissible and
 * takes sigma = max(p + K u, 0) on u = h; CG keeps sigma admissible and
 * takes u = h on its contact set, max(G sigma + c, h) elsewhere.
 */
#include "solver_impl.h"

#include <math.h>

/* Scale the warm-start pressures to mean p (uniform p when they carry no
 * load: a first solve, or a state without contact). */
void
rc__sigma_to_load(rc_solver *s, double p)
{
	size_t k, n = s->n;
	double sum = 0, *sigma = s->sigma;

	if (s->have_sigma || s->have_u)
		for (k = 0; k < n; k++)
			sum += sigma[k];
	if (!(sum > 0)) {
		for (k = 0; k < n; k++)
			sigma[k] = p;
		sum = p * (double)n;
	}
	for (k = 0; k < n; k++)
		sigma[k] *= p * (double)n / sum;
	s->have_sigma = 1;
}

double
rc__points(const rc_solver *s)
{
	return s->el.dist != NULL ? (double)s->el.n : (double)s->n;
}

double
rc__residual(const rc_solver *s, double p, double sum_d2, double sum_sigma)
{
	double n = rc__points(s);	/* the sums are global (solver_fire.c) */
	double force = sqrt(sum_d2 / n) / p, load = fabs(sum_sigma / n - p) / p;

	return force > load ? force : load;
}

/* The free boundaries' measure (solver_cg.c says why it bounds the
 * residual), from the sums over all points of (u' - u)^2, sigma and
 * sigma u; sets the elastic energy (1/2) <sigma u>. */
static double
gap_measure(rc_solver *s, double p, double sum_d2, double sum_s,
    double sum_e)
{
	double n = (double)s->n, force, load;

	s->energy = 0.5 * sum_e / n;
	force = rc__stiffness_max(s) * sqrt(sum_d2 / n) / p;
	load = fabs(sum_s / n - p) / p;
	return force > load ? force : load;
}

double
rc__pressure_check(rc_solver *s, const rc__interaction *in, double p)
{
	size_t k, n = s->n;
	double c, sum_d2 = 0, sum_s = 0, sum_e = 0, H = in->H;
	double *u = s->u, *ku = s->el.fft.real;
	const double *h = s->height, *sigma = s->sigma;

	in->level(s, &c);
	s->level = c;
	if (s->free_bc) {
#pragma omp parallel for reduction(+:sum_d2, sum_s, sum_e) schedule(static)
		for (k = 0; k < n; k++) {
			double v = u[k] + c;
			double up = rc__admissible(v, h[k], sigma[k], H);

			s->contact[k] = sigma[k] > 0;
			sum_d2 += (up - v) * (up - v);
			sum_s += sigma[k];
			sum_e += sigma[k] * u[k];
			u[k] = up;
		}
		return gap_measure(s, p, sum_d2, sum_s, sum_e);
	}
#pragma omp parallel for schedule(static)
	for (k = 0; k < n; k++) {
		s->contact[k] = sigma[k] > 0;
		u[k] = rc__admissible(u[k] + c, h[k], sigma[k], H);
	}
	rc_elastic_force(&s->el, u, ku);
#pragma omp parallel for reduction(+:sum_d2, sum_s, sum_e) schedule(static)
	for (k = 0; k < n; k++) {
		double d = p + ku[k] - sigma[k];

		sum_d2 += d * d;
		sum_s += sigma[k];
		sum_e += ku[k] * u[k];
	}
	s->energy = 0.5 * sum_e / (double)n;
	return rc__residual(s, p, sum_d2, sum_s);
}

/* The bound can stay far above the residual: the pressure methods check
 * the residual itself every CHECK_EVERY iterations (rc__cg_next). */
#define CHECK_EVERY	100

int
rc__cg_next(rc_solver *s, const rc__interaction *in, double p,
    double bound, long it, int recheck, double *residual, int *status)
{
	if (bound <= s->opts.tol || it >= s->opts.max_iter ||
	    (s->opts.stop && *s->opts.stop) ||
	    rc__watch_stalled(&s->watch, s->opts.stall_window, it, bound)) {
		*residual = rc__pressure_check(s, in, p);
		if (*residual <= s->opts.tol)
			*status = 0;
		return RC__CG_STOP;
	}
	/* The bound can stay far above the residual (seen on strongly
	 * warped surfaces: residual below tol for thousands of
	 * iterations); check the residual itself now and then. */
	if (recheck && it > 0 && it % CHECK_EVERY == 0) {
		*residual = rc__pressure_check(s, in, p);
		if (*residual <= s->opts.tol) {
			*status = 0;
			return RC__CG_STOP;
		}
		return RC__CG_STALE;
	}
	return RC__CG_GO;
}
