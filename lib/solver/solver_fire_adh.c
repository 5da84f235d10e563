/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_adh.c - FIRE-GFMD with an adhesive law of adhesion.h: the
 * driver that runs the FIRE of solver_fire_adh_pass.c (which says what it
 * solves and how) on the solver's own fields (periodic boundaries, a
 * half space or a layer), or hands the solve to the padded grid of
 * solver_fire_adh_free.c (free boundaries); then the state's pressures,
 * p_adh, a_attr and energy.  Displacement control starts from the warm
 * state shifted to the new mean.
 */
#include "solver_impl.h"

#include <math.h>

#include "adhesion.h"

/* Mean of max(u + c, h). */
static double
shifted_mean(const rc__adh_view *w, double c)
{
	size_t k;
	double sum = 0;

#pragma omp parallel for reduction(+:sum) schedule(static)
	for (k = 0; k < w->n; k++)
		sum += fmax(w->u[k] + c, w->h[k]);
	return sum / (double)w->n;
}

/* Shift u by the c (bisection) that makes <max(u + c, h)> = target, then
 * clamp; target above <h>. */
static void
shift_to_mean(const rc__adh_view *w, double target)
{
	size_t k;
	double lo, hi, umin = HUGE_VAL, umax = -HUGE_VAL;
	int it;

	for (k = 0; k < w->n; k++) {
		umin = fmin(umin, w->u[k]);
		umax = fmax(umax, w->u[k]);
	}
	/* already there (a warm start at the same approach): keep the
	 * contact points on the wall, which any shift up would lift */
	if (fabs(shifted_mean(w, 0) - target) <= 1e-14 * (fabs(target) +
	    umax - umin))
		return;
	/* The mean is non-decreasing in c, at least target at c = target -
	 * umin and tends to <h> < target as c falls: bracket, bisect (about
	 * 50 O(N) passes, a few iterations' worth, once per solve). */
	hi = target - umin;
	lo = target - umax;
	for (it = 0; it < 200 && shifted_mean(w, lo) > target; it++)
		lo -= (hi - lo) + 1;
	for (it = 0; it < 200 && hi - lo > 1e-15 * (fabs(hi) +
	    fabs(lo)); it++) {
		double mid = 0.5 * (lo + hi);

		if (shifted_mean(w, mid) > target)
			hi = mid;
		else
			lo = mid;
	}
	for (k = 0; k < w->n; k++)
		w->u[k] = fmax(w->u[k] + hi, w->h[k]);
}

/* The state's pressures (total traction: p + K u on contact, sigma_a
 * elsewhere), p_adh, a_attr and the elastic energy. */
static void
adh_finish(rc_solver *s, const rc_adhesion *law, double p)
{
	size_t k, n = s->n, attr = 0;
	double sum = 0, sum_a = 0, *sig = s->sigma;

	rc_elastic_force(&s->el, s->u, sig);
#pragma omp parallel for reduction(+:sum, sum_a, attr) schedule(static)
	for (k = 0; k < n; k++) {
		double g = s->u[k] - s->height[k], sa = rc_adhesion_traction(law, g);

		sum += s->u[k] * sig[k];
		sum_a += sa;
		if (!s->contact[k] && g < law->range)
			attr++;
		sig[k] = s->contact[k] ? p + sig[k] : sa;
	}
	s->energy = 0.5 * sum / (double)n;
	s->p_adh = sum_a / (double)n;
	s->a_attr = (double)attr / (double)n;
}

int
rc__fire_adh_solve(rc_solver *s, int control, double *pp, double delta,
    rc_solve_result *res, rc_err *err)
{
	rc__adh_view w = { &s->el, s->n, (double)s->n, s->u, s->fire_vel,
	    s->sigma, s->height, s->contact, 0, s->k_uniform, &s->watch };
	double target = 0, p = *pp;
	rc_adhesion law;
	size_t k;
	int r;

	if (rc_adhesion_init(&law, s->opts.adhesion_law, s->opts.adhesion,
	    s->opts.range) != 0)
		return rc_seterr(err, "adhesion %g, range %g: want both positive "
		    "and finite", s->opts.adhesion, s->opts.range);
	if (s->free_bc)
		return rc__fire_adh_free_solve(s, &law, control, pp, delta, res);
	if (!s->have_u) {
		for (k = 0; k < s->n; k++)
			s->u[k] = s->top;
		s->have_u = 1;
	}
	for (k = 0; k < s->n; k++)
		if (s->u[k] < s->height[k])
			s->u[k] = s->height[k];
	if (control == RC__ADH_LEVEL) {
		target = s->top - delta;
		shift_to_mean(&w, target);
		if (!isfinite(p))
			p = 0;
	} else if (control == RC__ADH_SUBSTRATE)
		/* no shift: the state's mean sets the load (the loop) */
		target = s->top - delta;
	r = rc__adh_relax(&w, &law, control, &p, target, &s->opts, res);
	adh_finish(s, &law, p);
	*pp = p;
	return r;
}
