/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_cg_plastic.c - Polonsky & Keer's constrained conjugate gradient with
 * the pressure bounded above by the hardness H (perfect plasticity):
 * 0 <= sigma <= H, mean sigma = p <= H.
 *
 * The complementarity (gap g = u - h, u = G sigma + c):
 *   g > 0          =>  sigma = 0
 *   0 < sigma < H  =>  g = 0
 *   sigma = H      =>  g <= 0  (the surface passes into the indenter: its
 *                               asperity is flattened plastically)
 * It is the minimum of the complementary energy (1/2) sigma.G sigma -
 * sigma.h over the box [0, H]^N with the mean fixed, c the multiplier of
 * the mean.  The iteration is solver_cg.c's with three changes:
 *   - the level c is the mean of h - G sigma over the free points
 *     F = {0 < sigma < H} (over sigma > 0 when F is empty);
 *   - the direction and step run over F, the penetrating points at zero
 *     pressure (g < 0) and the points at H whose gap opened (g > 0), and
 *     the new pressures are projected onto [0, H];
 *   - the load is restored by scaling down all pressures when they carry
 *     too much (this keeps them in [0, H]), or else by scaling up those
 *     of F, moving to H the points that would exceed it, until the mean is
 *     p (a few rounds; the H set only grows).  If no point below H
 *     carries pressure, the missing load goes uniformly to the points at
 *     zero pressure that penetrate (or to all at zero).
 * G sigma is recomputed after every iteration that did anything but a
 * uniform scaling (the clipping at H is not linear): about two FFT pairs
 * per iteration where solver_cg.c needs one near convergence.
 *
 * The level, the load restoration, the start and the convergence check
 * are shared with FIRE on pressures (solver_fire_free.c), which solves the
 * same problem; p > H is refused by solver.c for both.
 *
 * Convergence: solver_cg.c's measure with u' = h on F, max(v, h) at zero
 * pressure and min(v, h) at H (v = G sigma + c): the residual
 * rms(p + K u' - sigma)/p (periodic) or the gap bound (free).
 */
#include "solver_impl.h"

#include <math.h>
#include <string.h>

#define PROGRESS_EVERY	50
#define TRUST	0.5

/* The admissible u' of the top from v = u + c. */
static double
admissible(double v, double h, double sigma, double H)
{
	if (sigma <= 0)
		return v > h ? v : h;
	if (sigma >= H)
		return v < h ? v : h;
	return h;
}

/* Level c: the mean of h - G sigma over F; when F is empty, the middle of
 * the interval the bounds allow, c >= h - G sigma at zero pressure and
 * c <= h - G sigma at H (its end when one side is empty).  Returns the
 * number of points with sigma > 0. */
size_t
rc__plastic_level(const rc_solver *s, double *c)
{
	size_t k, on = 0, nf = 0, nz = 0;
	double sum_f = 0, H = s->opts.hardness, lo = -HUGE_VAL, hi = HUGE_VAL;

	for (k = 0; k < s->n; k++) {
		double d = s->height[k] - s->u[k];

		if (s->sigma[k] <= 0) {
			nz++;
			if (d > lo)
				lo = d;
		} else if (s->sigma[k] >= H) {
			on++;
			if (d < hi)
				hi = d;
		} else {
			on++;
			sum_f += d;
			nf++;
		}
	}
	if (nf)
		*c = sum_f / (double)nf;
	else if (nz == 0)
		*c = hi;
	else if (on == 0)
		*c = lo;
	else
		*c = 0.5 * (lo + hi);
	return on;
}

/* Restore mean sigma = p within [0, H] (see the top): the points of F
 * scaled, those that reach H moved to H, until the mean is p.  disp holds
 * G sigma (or NULL); returns 1 if G sigma is now stale, 0 if the change
 * was a uniform scale (applied to disp too). */
/* Long: the bisection on the level and the clamp at 0 and H share the
 * pressure bounds. */
int
rc__plastic_restore_load(rc_solver *s, double p, double *disp)
{
	size_t k, n = s->n;
	double *sigma = s->sigma, H = s->opts.hardness, pn = p * (double)n;
	int round;

	for (round = 0; round < 64; round++) {
		double sum_f = 0, at_h = 0, total, f;
		size_t moved = 0, n_h = 0;
		int uniform;

		for (k = 0; k < n; k++) {
			if (sigma[k] >= H) {
				at_h += H;
				n_h++;
			} else
				sum_f += sigma[k];
		}
		total = sum_f + at_h;
		f = total > 0 ? pn / total : 0;
		if (total > 0 && !(pn - at_h > 0))
			uniform = 1;	/* the points at H alone carry too much */
		else if (total > 0 && n_h == 0) {
			uniform = 1;	/* unless scaling up crosses H */
			for (k = 0; k < n && uniform; k++)
				uniform = !(sigma[k] * f > H);
		} else
			uniform = 0;
		if (uniform) {
			for (k = 0; k < n; k++) {
				sigma[k] *= f;
				if (disp)
					disp[k] *= f;
			}
			return round > 0 || disp == NULL;
		}
		if (!(sum_f > 0))
			break;
		f = (pn - at_h) / sum_f;
		for (k = 0; k < n; k++)
			if (sigma[k] < H) {
				sigma[k] *= f;
				if (sigma[k] >= H) {
					sigma[k] = H;
					moved++;
				}
			}
		if (moved == 0)
			return 1;
	}
	/* The points below H carry nothing: shift the pressures of the
	 * loaded and penetrating points (all points if these cannot carry
	 * p at H) by the mu that makes the mean p, clipped to [0, H] (the
	 * Euclidean projection; bisection to round-off). */
	{
		double c, lo = -H, hi = H;
		size_t n_a = 0;
		int all, i;

		rc__plastic_level(s, &c);
		for (k = 0; k < n; k++)
			n_a += sigma[k] > 0 || (disp && disp[k] + c < s->height[k]);
		all = (double)n_a * H < pn;
		for (i = 0; i < 100 && hi - lo > 1e-15 * H; i++) {
			double mu = 0.5 * (lo + hi), sum = 0;

			for (k = 0; k < n; k++)
				if (all || sigma[k] > 0 || (disp && disp[k] + c <
				    s->height[k])) {
					double v = sigma[k] + mu;

					sum += v < 0 ? 0 : v > H ? H : v;
				}
			if (sum < pn)
				lo = mu;
			else
				hi = mu;
		}
		for (k = 0; k < n; k++)
			if (all || sigma[k] > 0 || (disp && disp[k] + c <
			    s->height[k])) {
				double v = sigma[k] + hi;

				sigma[k] = v < 0 ? 0 : v > H ? H : v;
			}
	}
	return 1;
}

/* The CG's start (solver_cg.c) clipped at H, the load restored. */
void
rc__plastic_initial_pressure(rc_solver *s, double p)
{
	size_t k;

	rc__cg_initial_pressure(s, p);
	for (k = 0; k < s->n; k++)
		if (s->sigma[k] > s->opts.hardness)
			s->sigma[k] = s->opts.hardness;
	rc__plastic_restore_load(s, p, NULL);
}

/* Residual of (u', sigma); leaves u' in s->u, the contact set, level and
 * energy.  s->u holds G sigma on entry. */
double
rc__plastic_check(rc_solver *s, double p)
{
	size_t k, n = s->n;
	double c, sum_d2 = 0, sum_s = 0, sum_e = 0, H = s->opts.hardness;
	double *u = s->u;
	const double *h = s->height, *sigma = s->sigma;

	rc__plastic_level(s, &c);
	s->level = c;
	if (s->free_bc) {
		for (k = 0; k < n; k++) {
			double v = u[k] + c, up = admissible(v, h[k], sigma[k], H);

			s->contact[k] = sigma[k] > 0;
			sum_d2 += (up - v) * (up - v);
			sum_s += sigma[k];
			sum_e += sigma[k] * u[k];
			u[k] = up;
		}
		return rc__gap_measure(s, p, sum_d2, sum_s, sum_e);
	} else {
		double *ku = s->el.fft.real;

		for (k = 0; k < n; k++) {
			s->contact[k] = sigma[k] > 0;
			u[k] = admissible(u[k] + c, h[k], sigma[k], H);
		}
		rc_elastic_force(&s->el, u, ku);
		for (k = 0; k < n; k++) {
			double d = p + ku[k] - sigma[k];

			sum_d2 += d * d;
			sum_s += sigma[k];
			sum_e += ku[k] * u[k];
		}
		s->energy = 0.5 * sum_e / (double)n;
		return rc__residual(s, p, sum_d2, sum_s);
	}
}

/* Long: one bounded-pressure CG iteration: its passes share the sums and
 * the conjugate direction. */
int
rc__cg_plastic_solve(rc_solver *s, double p, rc_solve_result *res,
    rc_err *err)
{
	size_t n = s->n, k;
	double H = s->opts.hardness;
	double *sigma = s->sigma, *disp = s->u, *t = s->cg_dir;
	double *r = s->free_bc ? s->scratch : s->el.fft.real;
	double k_max = rc__stiffness_max(s);
	const double *h = s->height;
	double g_old = 1, c = 0, residual = HUGE_VAL, bound;
	double g00 = 0, inv_n = 1.0 / (double)n;
	long it;
	int stale = 1, conjugate = 0, status = 1, next;

	(void)err;
	rc__plastic_initial_pressure(s, p);
	memset(t, 0, n * sizeof(double));
	for (it = 0; ; it++) {
		double viol = 0, gsum = 0, sum_gt = 0, sum_rt = 0, sum_r = 0;
		double sum_t = 0, tau, tau_in, beta, rbar, t_max = 0;
		size_t n_contact, n_active = 0, changed = 0;

		if (stale) {
			rc__compliance(s, sigma, disp);
			stale = 0;
		}
		n_contact = rc__plastic_level(s, &c);
		for (k = 0; k < n; k++) {
			double g = disp[k] + c - h[k];

			if (rc__plastic_active(sigma[k], g, H)) {
				viol += g * g;
				gsum += g * g;
			}
		}
		bound = k_max * sqrt(viol * inv_n) / p;
		next = rc__cg_next(s, p, bound, it, rc__plastic_check, &residual,
		    &status);
		if (next == RC__CG_STOP)
			break;
		if (next == RC__CG_STALE) {
			stale = 1;
			continue;
		}
		if (s->opts.progress && it % PROGRESS_EVERY == 0)
			s->opts.progress(s->opts.progress_ctx, it, bound,
			    (double)n_contact * inv_n);
		beta = conjugate ? gsum / g_old : 0;
		g_old = gsum;
		for (k = 0; k < n; k++) {
			double g = disp[k] + c - h[k];

			if (rc__plastic_active(sigma[k], g, H)) {
				t[k] = g + beta * t[k];
				n_active++;
				sum_gt += g * t[k];
				sum_t += t[k];
				if (fabs(t[k]) > t_max)
					t_max = fabs(t[k]);
			} else
				t[k] = 0;
		}
		rc__compliance(s, t, r);
		for (k = 0; k < n; k++)
			if (t[k] != 0 || rc__plastic_active(sigma[k], disp[k] + c - h[k], H)) {
				sum_rt += r[k] * t[k];
				sum_r += r[k];
			}
		rbar = n_active ? sum_r / (double)n_active : 0;
		tau = sum_rt - rbar * sum_t > 0 ? sum_gt / (sum_rt - rbar * sum_t) : 0;
		/* A trust region: no pressure moves by more than TRUST H in
		 * one step.  Without it, starting from a uniform p near H
		 * the step sent half the points to 0 and half to H and back
		 * (a two-cycle, 64^2 self-affine, p = H/2). */
		if (tau * t_max > TRUST * H)
			tau = TRUST * H / t_max;
		if (tau > 0)
			tau_in = tau;
		else {
			if (!(g00 > 0))
				g00 = s->free_bc ? s->fel.self :
				    rc__self_compliance(&s->el);
			tau_in = 1 / g00;
		}
		for (k = 0; k < n; k++) {
			double g = disp[k] + c - h[k], old = sigma[k], v;

			disp[k] -= tau * r[k];	/* G sigma, if the step stays linear */
			if (!rc__plastic_active(old, g, H))
				continue;
			v = tau > 0 ? old - tau * t[k] : old - tau_in * g;
			if (v < 0)
				v = 0;
			if (v > H)
				v = H;
			if ((old <= 0) != (v <= 0) || (old >= H) != (v >= H))
				changed++;
			sigma[k] = v;
		}
		conjugate = changed == 0 && tau > 0;
		if (changed || !(tau > 0))
			stale = 1;
		if (rc__plastic_restore_load(s, p, stale ? NULL : disp))
			stale = 1;
	}
	res->iterations = it;
	res->residual = residual;
	return status;
}
