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
