/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_cg.c - Polonsky & Keer's constrained conjugate gradient (Wear 231,
 * 1999, 206-219) for the pressure of mean p in the box of an interaction
 * (interaction.h): sigma >= 0 (the wall), 0 <= sigma <= H (the cap).
 * One loop, two rule sets inside it: the interaction's cg_reentry selects
 * the wall's (1: re-entry and damping, described first) or the cap's (0:
 * projection and a trust region, its changes below).
 *
 * The surface height of the elastic body under sigma is u = G sigma + c,
 * G_q = 1/k_q, c the rigid-body level.  On the contact set I_c = {sigma > 0}
 * the gap g = u - h must vanish; c is the level that makes the mean gap
 * over I_c zero.  Each iteration: conjugate direction t = g + delta
 * (G/G_old) t_old on I_c (zero elsewhere; G = sum over I_c of g^2, delta = 0
 * after points re-entered), r = G t (the one FFT pair), step
 * tau = sum g t / sum (r - <r>_c) t, sigma -= tau t on I_c, negative
 * pressures set to zero, points off contact with negative gap re-enter with
 * sigma = -tau g, then the load is restored by rescaling sigma.
 * Departure from the paper: the direction and the step are taken over
 * I_c plus the penetrating points (sigma = 0, g < 0), so that re-entering
 * points get the pressure -tau t of a line search that saw them.  With
 * the printed re-entry, thousands of points re-entered and were clipped
 * again every step on strongly warped surfaces (surfwarp -w -20, 128^2: a
 * two-cycle at residual 6.8 forever; tests/e2e/hard.sh).
 *
 * Second departure: a step that changed the active set (points clipped
 * or re-entering) and was followed by a larger gap bound overshot, and
 * the next steps are halved (DAMP_DEC, without conjugation) until the
 * bound falls, then grow back by DAMP_INC up to the whole step.  Without
 * it the steepest-descent steps of re-entry cycled on measured maps: a
 * 128^2 crop of SurfaceTopography's bcrf example (tests/data/
 * field_bcrf_128) at p* = 0.01 clipped ~2300 and re-entered ~1700 points
 * every step, the bound alternating 80 and 92 forever (a_r 0.39 for
 * 0.09); with it 48 iterations.  Measured on 256^2 (tol 1e-6, p* =
 * 0.01 and 0.05, same contact sets where both converged): surfgen's
 * default 53, 119 before and 53, 118 after; crops of measured maps
 * (opd, bcrf, metropro, sur, di) 33-600 (one stall) before, 33-151
 * after.
 *
 * G sigma is kept up to date by linearity (G sigma -= tau r; the rescaling
 * scales it); only after an iteration that clipped or re-entered points,
 * and every REFRESH_EVERY iterations against round-off, it is recomputed
 * with a second FFT pair.  Near convergence the contact set is fixed and an
 * iteration costs one pair.
 *
 * Convergence (solver_measure.c): the residual of (u', sigma), u' = h on
 * I_c and max(G sigma + c, h) off it.  Since p + K u' - sigma = K(u' - u)
 * and |K x| <= k_max |x| (Parseval), k_max rms(u' - u) / p bounds it from
 * above at no cost; when the bound falls below the tolerance, or at the
 * end, the residual itself is computed (one FFT pair) and decides.
 *
 * Free boundaries (elastic_free.h): G is the padded Love compliance, whose
 * applications cost one pair of the 2nx x 2ny transform, and G sigma is
 * the whole displacement w (no mean removed), so c is the rigid level
 * against the far field.  There is no stiffness operator K to evaluate
 * the residual with, so the measure is the bound itself, with the largest
 * stiffness of the same grid were it periodic, k_max = (pi/2) E*
 * sqrt(dx^-2 + dy^-2) (a layer: times its phi at that q, layer.h), as
 * the scale that turns a gap error into a
 * pressure: residual = max(k_max rms(u' - u) / p, |<sigma> - p| / p).
 * It is computed without a transform.
 *
 * The cap (perfect plasticity, H = opts.hardness) minimises the
 * complementary energy (1/2) sigma.G sigma - sigma.h over the box
 * [0, H]^N with the mean fixed, c the multiplier of the mean.  Its rules
 * (in->cg_reentry 0) change the wall's in these ways:
 *   - the level c is the mean of h - G sigma over the free points
 *     F = {0 < sigma < H} (solver_hardness.c);
 *   - the direction and step run over F, the penetrating points at zero
 *     pressure (g < 0) and the points at H whose gap opened (g > 0), the
 *     conjugation over all of them, and the new pressures are projected
 *     onto [0, H] (a step of tau <= 0 moves every such point by -g /
 *     G_00);
 *   - no damping; instead a trust region: no pressure moves by more than
 *     the interaction's max_move, H/2, in one step (solver_hardness.c
 *     says why);
 *   - the load is restored by scaling down all pressures when they carry
 *     too much (this keeps them in [0, H]), or else by scaling up those
 *     of F, moving to H the points that would exceed it, until the mean
 *     is p (a few rounds; the H set only grows).  If no point below H
 *     carries pressure, the missing load goes uniformly to the points at
 *     zero pressure that penetrate (or to all at zero).
 * G sigma is recomputed after every iteration that did anything but a
 * uniform scaling (the clipping at H is not linear): about two FFT pairs
 * per iteration where the wall needs one near convergence.  The
 * convergence measure is the wall's with u' = h on F, max(v, h) at zero
 * pressure and min(v, h) at H (v = G sigma + c; rc__pressure_check).
 * FIRE on pressures (solver_fire_free.c) solves the same problem; p > H
 * is refused by solver.c for both.
 */
#include "solver_impl.h"

#include <math.h>
#include <string.h>

#define REFRESH_EVERY	50
#define PROGRESS_EVERY	50
#define DAMP_DEC	0.5
#define DAMP_INC	1.5

int
rc__cg_alloc(rc_solver *s, rc_err *err)
{
	s->u = fftw_alloc_real(s->n);
	s->cg_dir = fftw_alloc_real(s->n);
	if (s->free_bc)
		s->scratch = fftw_alloc_real(s->n);
	if (s->u == NULL || s->cg_dir == NULL || (s->free_bc && s->scratch == NULL))
		return rc_seterr(err, "out of memory (asked for %zu bytes of CG buffers)",
		    3 * s->n * sizeof(double));
	return 0;
}

/* Long: one Polonsky-Keer iteration: its passes share the sums and the
 * conjugate direction. */
int
rc__cg_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	rc__interaction in;
	size_t n = s->n, k, n_contact = 0;
	double *sigma = s->sigma, *disp = s->u, *t = s->cg_dir;
	double *r = s->free_bc ? s->scratch : s->el.fft.real;
	double k_max = rc__stiffness_max(s);
	const double *h = s->height;
	double H, g_old = 1, c = 0, residual = HUGE_VAL, bound = HUGE_VAL;
	double g00 = 0;		/* G_00, computed when first needed */
	double inv_n = 1.0 / (double)n;
	long it, since_refresh = 0;
	double damp = 1, prev_bound = HUGE_VAL;
	int set_changed = 0, reentry;
	int stale = 1, conjugate = 0, status = 1, next;

	(void)err;
	rc__interaction_of(s, &in);
	H = in.H;
	reentry = in.cg_reentry;
	in.start(s, p);
	memset(t, 0, n * sizeof(double));
	for (it = 0; ; it++) {
		double gsum = 0, pen = 0, sum_gt = 0, sum_rt = 0, sum_r = 0;
		double sum_t = 0, sum_s = 0, tau, tau_in, beta, rbar, t_max = 0;
		double fit;	/* the level, copied into c: the passes below
				 * then hold c in a register (an address taken
				 * would make OpenMP share it by reference) */
		size_t reentered = 0, clipped = 0, changed = 0, n_active = 0;

		if (stale || (reentry && since_refresh >= REFRESH_EVERY)) {
			rc__compliance(s, sigma, disp);
			stale = 0;
			since_refresh = 0;
		}
		since_refresh++;
		n_contact = in.level(s, &fit);
		c = fit;
		if (n_contact == 0) {
			/* Cannot happen with sum sigma = p N > 0; guard anyway. */
			break;
		}
		/* the wall conjugates over the contact set, the cap over all
		 * that take part */
#pragma omp parallel for reduction(+:gsum, pen) schedule(static)
		for (k = 0; k < n; k++) {
			double g = disp[k] + c - h[k];

			if (rc__active(sigma[k], g, H)) {
				if (reentry && !(sigma[k] > 0))
					pen += g * g;
				else
					gsum += g * g;
			}
		}
		bound = k_max * sqrt((gsum + pen) * inv_n) / p;
		next = rc__cg_next(s, &in, p, bound, it, 1, &residual, &status);
		if (next == RC__CG_STOP)
			break;
		if (next == RC__CG_STALE) {
			stale = 1;	/* the check left u' in disp */
			continue;
		}
		if (s->opts.progress && it % PROGRESS_EVERY == 0)
			s->opts.progress(s->opts.progress_ctx, it, bound,
			    (double)n_contact * inv_n);

		beta = conjugate ? gsum / g_old : 0;
		g_old = gsum;
#pragma omp parallel for reduction(+:sum_gt, sum_t, n_active) \
    reduction(max:t_max) schedule(static)
		for (k = 0; k < n; k++) {
			double g = disp[k] + c - h[k];

			if (rc__active(sigma[k], g, H)) {
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
#pragma omp parallel for reduction(+:sum_rt, sum_r) schedule(static)
		for (k = 0; k < n; k++)
			if (rc__active(sigma[k], disp[k] + c - h[k], H)) {
				sum_rt += r[k] * t[k];
				sum_r += r[k];
			}
		rbar = n_active ? sum_r / (double)n_active : 0;
		tau = sum_rt - rbar * sum_t > 0 ? sum_gt / (sum_rt - rbar * sum_t) : 0;
		/* The wall: a step that changed the active set and left a
		 * larger gap bound overshot: halve the steps until the bound
		 * falls, then let them grow back (see the top). */
		if (reentry) {
			if (it > 0 && set_changed && bound > prev_bound)
				damp *= DAMP_DEC;
			else
				damp = fmin(1, damp * DAMP_INC);
			prev_bound = bound;
			tau *= damp;
		}
		/* The trust region max_move, under either rule set (the
		 * wall's is +inf: no bound). */
		if (tau * t_max > in.max_move)
			tau = in.max_move / t_max;
		/* The re-entry pressure -tau g needs tau > 0.  With the gap zero
		 * on the whole contact set (one contact point, or a warm start
		 * from a solution at a lower load) there is no step and tau = 0,
		 * so penetrating points would never re-enter and the solve would
		 * stall at the old contact set.  Then let each re-enter with the
		 * pressure that alone closes its gap, -g / G_00 (the cap: each
		 * point that takes part moves so). */
		if (tau > 0)
			tau_in = tau;
		else {
			if (!(g00 > 0))
				g00 = s->free_bc ? s->fel.self :
				    rc__self_compliance(&s->el);
			tau_in = 1 / g00;
		}
#pragma omp parallel for reduction(+:sum_s, reentered, clipped, changed) \
    schedule(static)
		for (k = 0; k < n; k++) {
			double g = disp[k] + c - h[k], old = sigma[k], v = old;

			disp[k] -= tau * r[k];	/* G sigma, if the step stays linear */
			if (rc__active(old, g, H)) {
				v = tau > 0 || (reentry && old > 0) ?
				    old - tau * t[k] : old - tau_in * g;
				if (!reentry) {
					v = rc__project(v, H);
					changed += (old <= 0) != (v <= 0) ||
					    (old >= H) != (v >= H);
				} else if (old > 0) {
					if (v < 0) {
						v = 0;
						clipped++;
					}
				} else if (v > 0)
					reentered++;
				else {
					v = 0;	/* G sigma is stale */
					clipped++;
				}
				sigma[k] = v;
			}
			sum_s += v;
		}
		if (reentry) {
			/* the conjugate directions need whole line-search steps */
			conjugate = reentered == 0 && damp == 1;
			set_changed = reentered > 0 || clipped > 0;
			if (set_changed)
				stale = 1;
		} else {
			conjugate = changed == 0 && tau > 0;
			if (changed || !(tau > 0))
				stale = 1;
		}
		if (in.restore_load(s, p, sum_s, stale ? NULL : disp))
			stale = 1;
	}
	res->iterations = it;
	res->residual = residual;
	return status;
}
