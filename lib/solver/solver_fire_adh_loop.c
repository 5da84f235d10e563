/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_adh_loop.c - FIRE-GFMD with an adhesive law of adhesion.h on
 * periodic boundaries (a half space or a layer; free boundaries run the
 * same loop on a padded grid, solver_fire_adh_free.c): the loop of
 * solver_fire.c with the adhesive traction in the wall pass, kept apart so
 * that the plain loop pays nothing for it (solver.c dispatches here only
 * when opts.adhesion > 0).
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
 * (from the contact count).  The body separates when no point is in
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
 * beyond FIRE's.
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

struct adh_pass {
	size_t on;		/* contact points */
	double sum_d2;		/* sum of d^2 off contact */
	double sum_ku_c;	/* sum of K u over contact points */
	double sum_sa_f;	/* sum of sigma_a off contact */
	double sum_abs;		/* sum of |traction| (the state's scale) */
	double power;		/* f_eff . v */
	double gmin;		/* smallest gap off contact */
};

/* The wall pass with adhesion: f_eff into w->f, the contact set. */
static void
adh_wall_force(const rc__adh_view *w, const rc_adhesion *law, double p,
    struct adh_pass *o)
{
	size_t k, n = w->n, on = 0;
	double sum_d2 = 0, sum_kc = 0, sum_sa = 0, sum_abs = 0, pw = 0;
	double gmin = HUGE_VAL;
	const double *u = w->u, *h = w->h, *v = w->v;
	double *f = w->f, sa0 = -law->smax;
	unsigned char *contact = w->contact;

	rc_elastic_force(w->el, u, f);
#pragma omp parallel for reduction(+:sum_d2, sum_kc, sum_sa, sum_abs, on, \
    pw) reduction(min:gmin) schedule(static)
	for (k = 0; k < n; k++) {
		double implied = p + f[k], g = u[k] - h[k];

		if (g <= 0 && implied > sa0) {
			contact[k] = 1;
			sum_kc += f[k];
			sum_abs += fabs(implied);
			on++;
			f[k] = 0;
		} else {
			double sa = rc_adhesion_traction(law, g), d = implied - sa;

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
	o->on = on;
	o->sum_d2 = sum_d2;
	o->sum_ku_c = sum_kc;
	o->sum_sa_f = sum_sa;
	o->sum_abs = sum_abs;
	o->power = pw;
	o->gmin = gmin;
}

/* Long: one FIRE iteration's passes share their sums, and the three
 * controls differ inside them (the mean mode, the load, the separation
 * test), not around them. */
int
rc__adh_loop(const rc__adh_view *w, const rc_adhesion *law, int control,
    double *pp, double target, const rc_solver_opts *opts,
    rc_solve_result *res)
{
	size_t n = w->n, k;
	rc__fire fs = RC__FIRE_START;
	double residual = HUGE_VAL, *u = w->u, *v = w->v, p = *pp;
	double k0 = w->spring;
	const double *h = w->h;
	const unsigned char *contact = w->contact;
	/* the view's points per interacting one: 1 on a periodic grid */
	double spread = (double)n / w->n_act;
	struct adh_pass ps;
	long it;
	int status = 1;

	memset(v, 0, n * sizeof(double));
	res->separated = 0;
	if (control == RC__ADH_SUBSTRATE) {
		double sum = 0;

#pragma omp parallel for reduction(+:sum) schedule(static)
		for (k = 0; k < n; k++)
			sum += u[k];
		p = k0 * (sum / (double)n - target);
	}
	for (it = 0; ; it++) {
		double mass0, aa = 0, av = 0, vv = 0, sa_f = 0, sv = 0, shift = 0;
		double mix_v, mix_a, *a, scale, load, usum = 0;
		size_t nf;
		int restart;

		adh_wall_force(w, law, p, &ps);
		nf = n - ps.on;
		/* p on every point of the view: the load p n over the
		 * points that interact; with the level held (mass0 > 0) the
		 * load is the tractions' sum */
		load = w->mass0 > 0 ? fabs(ps.sum_ku_c + ps.sum_sa_f) /
		    w->n_act : fabs(p) * spread;
		/* a prescribed load: the state's mean traction (sigma_max may
		 * be millions of times the load, which then passed unsolved);
		 * with the level held (any control with mass0 > 0, the free
		 * boundaries' approach too) tractions near separation are
		 * tiny, so the adhesive stress stays the scale there */
		scale = control == RC__ADH_LOAD && !(w->mass0 > 0) ?
		    fmax(load, ps.sum_abs / w->n_act) : fmax(load, law->smax);
		residual = sqrt(ps.sum_d2 / w->n_act) / scale;
		if (control == RC__ADH_LEVEL && nf > 0)
			p = (ps.sum_ku_c + ps.sum_sa_f) / (double)nf;
		if (residual <= opts->tol) {
			status = 0;
			break;
		}
		if (control == RC__ADH_LOAD && ps.on == 0 && p < 0 &&
		    rc_adhesion_tension_beyond(law, ps.gmin) < -p * spread) {
			res->separated = 1;
			break;
		}
		if (it >= opts->max_iter || (opts->stop && *opts->stop) ||
		    rc__watch_stalled(w->watch, opts->stall_window, it,
		    residual))
			break;
		if (opts->progress && it % RC_FIRE_PROGRESS_EVERY == 0)
			opts->progress(opts->progress_ctx, it, residual,
			    (double)ps.on / w->n_act);
		mass0 = control == RC__ADH_LEVEL ? HUGE_VAL : w->mass0 > 0 ?
		    w->mass0 : RC_FIRE_M0_SCALE * w->el->k_min *
		    sqrt((double)(ps.on > 0 ? ps.on : 1) / (double)n);
		/* the substrate's spring k_0 on the mean mode: m_0 >= k_0
		 * keeps its frequency at most 1, as m_q = k_q does for the
		 * other modes (FIRE's dt_max = 2 is stable for those) */
		if (control == RC__ADH_SUBSTRATE && mass0 < k0)
			mass0 = k0;
		a = rc__fire_mass_weighted(w->el, w->f, mass0);
		restart = rc__fire_adapt(&fs, ps.power, RC_FIRE_DT_MAX);
		/* Displacement control: the step's mean over F removed
		 * first (a = 0 on C, v = 0 on a restart). */
#pragma omp parallel for reduction(+:aa, av, vv, sa_f, sv) schedule(static)
		for (k = 0; k < n; k++) {
			double ak = contact[k] ? 0 : a[k], vk = restart ? 0 : v[k];

			aa += ak * ak;
			av += ak * vk;
			vv += vk * vk;
			sa_f += ak;
			sv += vk;
		}
		if (control == RC__ADH_LEVEL && nf > 0) {
			shift = sa_f / (double)nf;
			aa -= (double)nf * shift * shift;
			av -= shift * sv;
		}
		rc__fire_mix(&fs, aa, av, vv, &mix_v, &mix_a);
		/* the new mean on the way (the substrate's load, next) */
#pragma omp parallel for reduction(+:usum) schedule(static)
		for (k = 0; k < n; k++) {
			double ak = contact[k] ? 0 : a[k] - shift;
			double vk = mix_v * ((restart ? 0 : v[k]) + fs.dt * ak) +
			    mix_a * ak;

			u[k] = fmax(u[k] + fs.dt * vk, h[k]);
			v[k] = u[k] > h[k] ? vk : 0;
			usum += u[k];
		}
		if (control == RC__ADH_SUBSTRATE)
			p = k0 * (usum / (double)n - target);
		if (control == RC__ADH_LEVEL) {
			/* the clamp's drift of the mean, put back off the wall */
			double sum = 0, c;
			size_t nfree = 0;

#pragma omp parallel for reduction(+:sum, nfree) schedule(static)
			for (k = 0; k < n; k++) {
				sum += u[k];
				nfree += u[k] > h[k];
			}
			c = nfree > 0 ? (target * (double)n - sum) / (double)nfree : 0;
			if (c != 0)
#pragma omp parallel for schedule(static)
				for (k = 0; k < n; k++)
					if (u[k] > h[k])
						u[k] = fmax(u[k] + c, h[k]);
		}
	}
	*pp = p;
	res->iterations = it;
	res->residual = residual;
	return status;
}
