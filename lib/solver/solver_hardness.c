/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_hardness.c - the hardness cap (perfect plasticity, 0 <= sigma
 * <= H) as an interaction of the pressure methods (interaction.h, which
 * states the complementarity; its pointwise rules with H finite): the
 * level c fitted over the free points 0 < sigma < H, the load restored to
 * mean p within [0, H], and the start (the wall's, clipped at H).
 */
#include "solver_impl.h"

#include <math.h>

/* No pressure moves by more than TRUST H in one step of either method,
 * the CG's trust region and a cap on each point's step of FIRE.  Without
 * it, the CG from a uniform p near H sent half the points to 0 and half
 * to H and back (a two-cycle, 64^2 self-affine, p = H/2); FIRE near p = H
 * (128^2 self-affine, H = 0.2, p = 0.988 H) sent every free point to a
 * bound, the load restoration then spread the load over all points and
 * the iteration cycled (3000 iterations, residual 0.6); with it 35.
 * TRUST 0.25 converged too, in 10-30 % more FIRE iterations. */
#define TRUST	0.5

/* Level c: the mean of h - G sigma over F; when F is empty, the middle of
 * the interval the bounds allow, c >= h - G sigma at zero pressure and
 * c <= h - G sigma at H (its end when one side is empty).  Returns the
 * number of points with sigma > 0. */
static size_t
cap_level(const rc_solver *s, double *c)
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
static int
cap_restore_load(rc_solver *s, double p, double sum_sigma, double *disp)
{
	size_t k, n = s->n;
	double *sigma = s->sigma, H = s->opts.hardness, pn = p * (double)n;
	int round;

	(void)sum_sigma;	/* it sums by the classes of sigma below */
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

		cap_level(s, &c);
		for (k = 0; k < n; k++)
			n_a += sigma[k] > 0 || (disp && disp[k] + c < s->height[k]);
		all = (double)n_a * H < pn;
		for (i = 0; i < 100 && hi - lo > 1e-15 * H; i++) {
			double mu = 0.5 * (lo + hi), sum = 0;

			for (k = 0; k < n; k++)
				if (all || sigma[k] > 0 || (disp && disp[k] + c <
				    s->height[k])) {
					double v = sigma[k] + mu;

					sum += rc__project(v, H);
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

				sigma[k] = rc__project(v, H);
			}
	}
	return 1;
}

/* The wall's start (solver_wall.c) clipped at H, the load restored. */
static void
cap_start(rc_solver *s, double p)
{
	size_t k;

	rc__wall_start(s, p);
	for (k = 0; k < s->n; k++)
		if (s->sigma[k] > s->opts.hardness)
			s->sigma[k] = s->opts.hardness;
	cap_restore_load(s, p, 0, NULL);
}

/* The fraction of the points at H: flattened plastically. */
static double
cap_plastic_fraction(const rc_solver *s)
{
	size_t k, at = 0;

	for (k = 0; k < s->n; k++)
		at += s->sigma[k] >= s->opts.hardness;
	return (double)at / (double)s->n;
}

/* The CG runs projected steps in a trust region (solver_cg.c). */
void
rc__cap(const rc_solver *s, rc__interaction *in)
{
	*in = (rc__interaction){ .H = s->opts.hardness, .start = cap_start,
	    .level = cap_level, .restore_load = cap_restore_load,
	    .max_move = TRUST * s->opts.hardness,
	    .plastic_fraction = cap_plastic_fraction, .cg_reentry = 0 };
}
