/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_adh_pass.c - FIRE-GFMD with an adhesive law of adhesion.h
 * on periodic boundaries (a half space or a layer; free boundaries run
 * the same on a padded grid, solver_fire_adh_free.c): the FIRE loop of
 * solver_fire_loop.c with the adhesive law as its interaction, whose
 * passes add the adhesive traction, the controls' sums and their hooks
 * (solver.c comes here only when opts.adhesion > 0).
 *
 * Total energy per area E(u) = (1/2) <u K u> + <phi(u - h)> + p <u>,
 * u >= h: non-convex (phi is concave), so it has stable and unstable
 * equilibria and, under load control past pull-off, none.  FIRE only
 * descends E, so it finds a stable equilibrium (a local minimum) near the
 * warm start: a list of loads or approaches traces a branch, and one
 * that goes up and down shows the hysteresis.
 *
 * The wall pass, per point, with implied = p + (K u)(r) (the pressure the
 * elastic body needs there) and sigma_a = sigma_a(u - h):
 *   on the wall (u = h) and implied > sigma_a(0) = -sigma_max: contact,
 *     the wall takes implied - sigma_a(0) >= 0, f_eff = 0;
 *   elsewhere f_eff = sigma_a - implied (d = -f_eff, the equilibrium
 *     error).
 * Convergence: rms(d) / P <= tol, P = max(|p|, T), T the mean |traction|
 * the state carries (|p + K u| on contact, |sigma_a| elsewhere): the
 * load, or the stresses adhesion makes when the load is small or zero.
 * (P was max(|p|, sigma_max): with sigma_max 2e6 times the load, as for
 * --adhesion 1 --range 1e-5 on a 32^2 map at p* = 0.05, the flat start's
 * error, the load itself, passed as converged after 0 iterations with
 * one point in contact, and more adhesion gave less contact; issue 27.)
 * The load balance error is the mean of d over the points off contact
 * (<K u> = 0), so the rms bounds it.
 *
 * Load control (control 0): the mean mode has the mass of solver_fire.c
 * (rc__fire_mass0, from the contact count).  The body separates when no point is in
 * contact and the tension -p exceeds the strongest attraction left,
 * rc_adhesion_tension_beyond(min g) (exponential: sigma_max exp(-min g /
 * rho)): then every point pulls less than the load and the mean
 * accelerates away; the solve stops there with
 * res->separated = 1 (returns 1).
 *
 * Displacement control (control 1): <u> = max h - delta is held (the
 * approach of solver.h).  The mean of p + K u - sigma is then the unknown
 * p: p = (sum_C (K u) + sum_F sigma_a) / n_F (C the contact points, F the
 * rest, n_F their count), updated every pass; the mean mode of the step
 * is removed (infinite m_0) and the step's mean over F subtracted, which
 * keeps f_eff . a > 0 (sum_F f_eff = 0 by the choice of p); the drift the
 * wall's clamp adds is put back by a shift of the points off the wall
 * after each step.  No equilibrium is skipped: the unstable branch of a
 * load-controlled curve is stable at fixed approach.  The start shifts the
 * warm state to the new mean (bisection on the shift with the clamp).
 *
 * Substrate control (control 2, a periodic layer under displacement
 * control): the approach is the rigid substrate's travel, delta = max h -
 * <u> + p / k_0 (solver.h), so holding the substrate at delta ties the
 * mean mode to it by a spring of stiffness k_0 (view->spring):
 *   E(u) = (1/2) <u K u> + <phi(u - h)> + (k_0 / 2) (<u> - s)^2,
 * s = max h - delta, i.e. load control at a load p = k_0 (<u> - s) that
 * follows the state: p is taken from the mean, which the step's update
 * pass sums on the way (no pass of its own; one at the start).  The mean
 * mode's mass is the larger of load control's rule and k_0, so that its
 * frequency on the spring stays at most 1 like the other modes' (m_q =
 * k_q; measured on a sphere's 37 approaches in and out, the layer
 * hysteresis of tests/test_adhesion.c: 1566 iterations, 1436 to 1511 for
 * 0.5 to 4 k_0, 2526 with the rule alone).  No separation test: with the substrate
 * held the state has an equilibrium (the spring pulls the mean back).
 * The state is not shifted at the start (the load follows it); the
 * approach it reports is delta to rounding, and a layer can be pressed
 * past full contact (its compression keeps growing).
 *
 * Dugdale's law: its force jumps from -sigma_max to 0 at g = rho, where
 * no equilibrium point sits; the loop runs unchanged on the exact law and
 * converges in about as many iterations as on the exponential one
 * (tests/test_adhesion.c).
 *
 * Cost per iteration: that of solver_fire.c plus one exp per point within
 * RC_ADH_CUTOFF ranges of the wall (Dugdale: a comparison instead;
 * displacement control: one more O(N) pass for the mean; substrate
 * control: none, its mean summed in the update pass).  Memory: none
 * beyond FIRE's.  The passes sum over each thread's share of the grid,
 * as this loop did before the FIRE loop was shared, and are not fused
 * with the blocked transforms (the level control's drift correction
 * moves u after the update; the rounding of the sums, so the answers on
 * grids from 1024^2, the padded 512^2 included, would change).
 *
 * The loop runs on a view (rc__adh_view, solver_impl.h) of the grid: the
 * solver's own fields (solver_fire_adh.c), the padded grid of
 * solver_fire_adh_free.c on free boundaries, where only the given area
 * interacts.
 */
#include "solver_impl.h"

#include <math.h>
#include <string.h>

#include "adhesion.h"

/* The interaction's state in the loop. */
struct adh {
	const rc__adh_view *w;
	const rc_adhesion *law;
	int control;
	double p;		/* the load on every point of the view */
	double target;		/* level and substrate control's mean */
	double nf;		/* points off contact, of the last force pass */
	double shift;		/* level control: the step's mean over them */
};

/* The force pass with adhesion on k0 <= k < k1: f_eff into f, the
 * contact set; adds the squared error off contact, K u over the contact
 * points, sigma_a off them, the |traction|, the contact count and the
 * power to sum[0..5]; the smallest gap off contact into *least.
 * wall_range (solver_fire.c) is its near-copy for the hard wall, kept
 * apart for the sums' order and form (see there): bit for bit rows. */
static void
adh_range(void *ctx, double *f, const rc__fire_step *st, size_t k0,
    size_t k1, double *sum, double *least)
{
	const struct adh *ad = ctx;
	const rc__adh_view *w = ad->w;
	size_t k, on = 0;
	double sum_d2 = 0, sum_kc = 0, sum_sa = 0, sum_abs = 0, pw = 0;
	double gmin = HUGE_VAL, p = ad->p;
	const double *u = w->u, *h = w->h, *v = w->v;
	double sa0 = -ad->law->smax;
	unsigned char *contact = w->contact;

	(void)st;
	for (k = k0; k < k1; k++) {
		double implied = p + f[k], g = u[k] - h[k];

		if (g <= 0 && implied > sa0) {
			contact[k] = 1;
			sum_kc += f[k];
			sum_abs += fabs(implied);
			on++;
			f[k] = 0;
		} else {
			double sa = rc_adhesion_traction(ad->law, g), d = implied - sa;

			contact[k] = 0;
			f[k] = -d;
			sum_d2 += d * d;
			sum_sa += sa;
			sum_abs += fabs(sa);
			if (g < gmin)
				gmin = g;
		}
		pw += f[k] * v[k];
	}
	sum[0] += sum_d2;
	sum[1] += sum_kc;
	sum[2] += sum_sa;
	sum[3] += sum_abs;
	sum[4] += (double)on;
	sum[5] += pw;
	if (gmin < *least)
		*least = gmin;
}

/* The report from adh_range's sums under the control; level control
 * finds its load here. */
static void
adh_forced(void *ctx, const double *sum, double gmin, rc__fire_report *r)
{
	struct adh *ad = ctx;
	const rc__adh_view *w = ad->w;
	double n = (double)w->n, on = sum[4], load, scale, mass0;
	/* the view's points per interacting one: 1 on a periodic grid */
	double spread = n / w->n_act, p = ad->p;

	ad->nf = n - on;
	/* p on every point of the view: the load p n over the points that
	 * interact; with the level held (mass0 > 0) the load is the
	 * tractions' sum */
	load = w->mass0 > 0 ? fabs(sum[1] + sum[2]) / w->n_act :
	    fabs(p) * spread;
	/* a prescribed load: the state's mean traction (sigma_max may be
	 * millions of times the load, which then passed unsolved); with the
	 * level held (any control with mass0 > 0, the free boundaries'
	 * approach too) tractions near separation are tiny, so the adhesive
	 * stress stays the scale there */
	scale = ad->control == RC__ADH_LOAD && !(w->mass0 > 0) ?
	    fmax(load, sum[3] / w->n_act) : fmax(load, ad->law->smax);
	r->residual = sqrt(sum[0] / w->n_act) / scale;
	if (ad->control == RC__ADH_LEVEL && ad->nf > 0)
		ad->p = (sum[1] + sum[2]) / ad->nf;
	/* separation: no contact, and the tension beyond the strongest
	 * attraction left */
	r->halt = ad->control == RC__ADH_LOAD && on == 0 && p < 0 &&
	    rc_adhesion_tension_beyond(ad->law, gmin) < -p * spread;
	r->contact = on;
	r->power = sum[5];
	mass0 = ad->control == RC__ADH_LEVEL ? HUGE_VAL : w->mass0 > 0 ?
	    w->mass0 : rc__fire_mass0(w->el->k_min, on, n);
	/* the substrate's spring k_0 on the mean mode: m_0 >= k_0 keeps its
	 * frequency at most 1, as m_q = k_q does for the other modes
	 * (FIRE's dt_max = 2 is stable for those) */
	if (ad->control == RC__ADH_SUBSTRATE && mass0 < w->spring)
		mass0 = w->spring;
	r->mass0 = mass0;
}

/* Displacement control: the step's mean over F removed from the sums. */
static void
adh_mixed(void *ctx, double *sum, double *dt)
{
	struct adh *ad = ctx;

	(void)dt;
	ad->shift = 0;
	if (ad->control == RC__ADH_LEVEL && ad->nf > 0) {
		ad->shift = sum[3] / ad->nf;
		sum[0] -= ad->nf * ad->shift * ad->shift;
		sum[1] -= ad->shift * sum[4];
	}
}

/* The update on k0 <= k < k1; the new heights' sum to sum[0] (the
 * substrate's load, next).  update_range (solver_fire.c) is the wall's
 * near-copy, kept apart for its own clamp and no sum (see there): bit
 * for bit rows. */
static void
adh_update_range(void *ctx, double *a, const rc__fire_step *st, size_t k0,
    size_t k1, double *sum, double *least)
{
	const struct adh *ad = ctx;
	const rc__adh_view *w = ad->w;
	const unsigned char *contact = w->contact;
	const double *h = w->h;
	double *u = w->u, *v = w->v, shift = ad->shift, usum = 0;
	double dt = st->dt, mix_v = st->mix_v, mix_a = st->mix_a;
	int restart = st->restart;
	size_t k;

	(void)least;
	for (k = k0; k < k1; k++) {
		double ak = contact[k] ? 0 : a[k] - shift;
		double vk = mix_v * ((restart ? 0 : v[k]) + dt * ak) +
		    mix_a * ak;

		u[k] = fmax(u[k] + dt * vk, h[k]);
		v[k] = u[k] > h[k] ? vk : 0;
		usum += u[k];
	}
	sum[0] += usum;
}

/* After the update: the substrate's load from the new mean; level
 * control puts the clamp's drift of the mean back off the wall. */
static void
adh_updated(void *ctx, const double *sum)
{
	struct adh *ad = ctx;
	const rc__adh_view *w = ad->w;
	size_t n = w->n, k, nfree = 0;
	double *u = w->u, s = 0, c;
	const double *h = w->h;

	if (ad->control == RC__ADH_SUBSTRATE)
		ad->p = w->spring * (sum[0] / (double)n - ad->target);
	if (ad->control != RC__ADH_LEVEL)
		return;
#pragma omp parallel for reduction(+:s, nfree) schedule(static)
	for (k = 0; k < n; k++) {
		s += u[k];
		nfree += u[k] > h[k];
	}
	c = nfree > 0 ? (ad->target * (double)n - s) / (double)nfree : 0;
	if (c != 0)
#pragma omp parallel for schedule(static)
		for (k = 0; k < n; k++)
			if (u[k] > h[k])
				u[k] = fmax(u[k] + c, h[k]);
}

int
rc__adh_relax(const rc__adh_view *w, const rc_adhesion *law, int control,
    double *pp, double target, const rc_solver_opts *opts,
    rc_solve_result *res)
{
	struct adh ad = { w, law, control, *pp, target, 0, 0 };
	rc__fire_parts pt = { .el = w->el, .n = w->n, .points = w->n_act,
	    .u = w->u, .f = w->f, .v = w->v, .contact = w->contact,
	    .ctx = &ad, .grain = 0, .fuse = 0,
	    .mean_sums = control == RC__ADH_LEVEL, .force = adh_range,
	    .update = adh_update_range, .forced = adh_forced,
	    .mixed = adh_mixed, .updated = adh_updated, .field = NULL,
	    .accelerate = NULL, .mixing = NULL, .next = NULL };
	size_t n = w->n, k;
	int status;

	memset(w->v, 0, n * sizeof(double));
	res->separated = 0;
	if (control == RC__ADH_SUBSTRATE) {
		double sum = 0;

#pragma omp parallel for reduction(+:sum) schedule(static)
		for (k = 0; k < n; k++)
			sum += w->u[k];
		ad.p = w->spring * (sum / (double)n - target);
	}
	status = rc__fire_run(&pt, opts, w->watch, &res->iterations,
	    &res->residual);
	if (status == RC__FIRE_HALTED) {
		res->separated = 1;
		status = 1;
	}
	*pp = ad.p;
	return status;
}
