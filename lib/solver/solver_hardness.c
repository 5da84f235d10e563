/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_hardness.c - the hardness cap (perfect plasticity, 0 <= sigma
 * <= H) as the pressure methods see it, shared by the bounded CG
 * (solver_cg_plastic.c, whose top states the complementarity) and FIRE on
 * pressures (solver_fire_free.c): the level c fitted over the free points
 * 0 < sigma < H, the load restored to mean p within [0, H], the start
 * (the CG's, clipped at H) and the convergence check of (u', sigma) with
 * u' = h on the free points, max(v, h) at zero pressure and min(v, h)
 * at H (v = G sigma + c).
 */
#include "solver_impl.h"

#include <math.h>

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
