/* SPDX-License-Identifier: GPL-3.0-or-later */
/* interaction.h - the interactions of the pressure methods (the CG,
 * solver_cg.c, and FIRE on pressures, solver_fire_free.c), private to
 * the library: what the wall or the cap between the surfaces does to the
 * pressure sigma, behind one interface that both methods run on.
 *
 * The admissible set is the box 0 <= sigma <= H with mean sigma = p:
 *   the hard wall (solver_wall.c): H = +inf, sigma >= 0 alone;
 *   the hardness cap (solver_hardness.c, perfect plasticity): H =
 *     opts.hardness.
 * The pointwise rules below are written once in H: with H = +inf and a
 * finite sigma, sigma < H always holds and sigma >= H never does, so they
 * are exactly the wall's (sigma > 0 on contact, max(v, h) off it).  The rules over the
 * whole field (the start, the level fit, the load restoration) differ and
 * are the interaction's functions.  The CG (solver_cg.c) runs one loop
 * with two rule sets inside it, and cg_reentry selects which: the
 * wall's (re-entry, damping) or the cap's (projection, trust region).  Complementarity, with the gap
 * g = u - h, u = G sigma + c (c the rigid level):
 *   g > 0 => sigma = 0;  0 < sigma < H => g = 0;  sigma = H => g <= 0. */
#ifndef RC_INTERACTION_H
#define RC_INTERACTION_H

#include <stddef.h>

struct rc_solver;

typedef struct rc__interaction {
	double H;		/* the cap; +inf: the wall */
	/* sigma of mean p to start from (the warm start, or uniform) */
	void (*start)(struct rc_solver *s, double p);
	/* the rigid level c from s->u = G sigma over the points that
	 * must touch; returns the count of sigma > 0 */
	size_t (*level)(const struct rc_solver *s, double *c);
	/* mean sigma restored to p within the box, sum = sum sigma (the
	 * wall's scale uses it); disp: G sigma to keep in step, or NULL.
	 * With disp != NULL returns 1 if disp no longer equals G sigma
	 * (the change was not a uniform scale), else 0.  With disp ==
	 * NULL there is no G sigma to keep and the return means nothing:
	 * the wall returns 0, the cap 1; a caller passing NULL must treat
	 * G sigma as stale (the CG passes NULL only when it already is,
	 * FIRE on pressures recomputes it every step). */
	int (*restore_load)(struct rc_solver *s, double p, double sum,
	    double *disp);
	/* the largest move of one pressure in one step of either method
	 * (the cap's trust region, solver_hardness.c; +inf: the wall) */
	double max_move;
	/* its column of the solution: the fraction of the points at H
	 * (a_plastic; rc_solver_plastic_fraction); NULL: none (the wall) */
	double (*plastic_fraction)(const struct rc_solver *s);
	/* Which of the CG loop's two rule sets runs (solver_cg.c says
	 * what they are and why): 1, Polonsky & Keer's with re-entry and
	 * damping (the wall's); 0, projected steps within the trust region
	 * max_move (the cap's).  One loop, two rule sets, not two
	 * methods. */
	int cg_reentry;
} rc__interaction;

/* The two interactions filled in for s: solver_wall.c, solver_hardness.c
 * (rc__interaction_of, solver_impl.h, picks the cap when opts.hardness
 * is finite and positive, else the wall). */
void rc__wall(const struct rc_solver *s, rc__interaction *in);
void rc__cap(const struct rc_solver *s, rc__interaction *in);

/* Whether a point with pressure sigma and gap g takes part in a bounded
 * step: free (0 < sigma < H), or its force f = -g pointing into the box
 * (at zero and penetrating, or at H with an open gap).  Written as
 * (sigma > 0 or g < 0) and (sigma < H or g > 0), the same for every
 * sigma and g (H > 0), so that the points out of contact (most of them)
 * cost the wall's two comparisons. */
static inline int
rc__active(double sigma, double g, double H)
{
	return (sigma > 0 || g < 0) && (sigma < H || g > 0);
}

/* sigma projected onto [0, H]. */
static inline double
rc__project(double sigma, double H)
{
	return sigma < 0 ? 0 : sigma > H ? H : sigma;
}

/* The admissible height u' from v = G sigma + c: h where the pressure
 * is free, max(v, h) at zero pressure, min(v, h) at H. */
static inline double
rc__admissible(double v, double h, double sigma, double H)
{
	if (sigma <= 0)
		return v > h ? v : h;
	if (sigma >= H)
		return v < h ? v : h;
	return h;
}

/* The convergence measure of (u', sigma) from s->u = G sigma, one pass
 * for both interactions (solver_measure.c): leaves u' in s->u, the
 * contact set, the level and the elastic energy.  Periodic: the residual
 * rms(p + K u' - sigma) / p (rc__residual); free: the gap measure
 * max(k_max rms(u' - u) / p, |<sigma> - p| / p). */
double rc__pressure_check(struct rc_solver *s, const rc__interaction *in,
    double p);

#endif
