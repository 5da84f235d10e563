/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire.c - FIRE-GFMD against a hard wall: the elastic surface
 * heights u(r) relaxed by the FIRE loop of solver_fire_loop.c (which says
 * what one iteration is and how FIRE is tuned), with the wall as its
 * interaction.
 *
 * Positions u and velocities v live in real space, so the wall and the
 * velocity projection are local and exact (u >= h bit for bit).  The
 * force pass, with implied = p + (K u)(r): at a point on the wall (u = h)
 * where f = -implied pushes into it (implied > 0) the wall takes the
 * force up, f_eff = 0, and the point is in contact (set C); elsewhere
 * f_eff = f.  The residual (solver_measure.c) falls out of this pass, so
 * convergence is checked every iteration for free.  Then a = 0 on C: a
 * contact point stays on the wall while its pressure is positive.
 * Without this the non-local a lifts contact points off the wall and the
 * next step pushes them back; measured: no convergence in 20000 steps.
 * With it the step is the preconditioner restricted to the free points,
 * P_F M^-1 P_F f, whose power f.a > 0 (a principal submatrix of a
 * positive definite matrix), so it always points downhill.  The power
 * P = f_eff . v is the true power.  The update: u += dt v; where u < h:
 * u = h, v = 0.
 *
 * Mean-mode mass m_0 (rc__fire_mass0).  The mean height is held only by
 * the contact, whose stiffness (load per mean height) grows with the
 * contact.  A single patch of area a_r L^2 in a half space has stiffness
 * ~ E* sqrt(a_r) L per cell, i.e. ~ k_min sqrt(a_r) per area (k_min = pi
 * E* / L, the softest mode, L the longer side).  So m_0 = M0_SCALE k_min
 * sqrt(max(n_c, 1) / N), updated every step from the current contact
 * count (it changes the rate, not the fixed point).  Measured (H = 0.3
 * and 0.8): a fixed m_0 = k_min takes 33 ... 113 iterations at 256^2 for
 * p* = 0.002 ... 0.5, the most at small p* (1159 with m_0 = 10 k_min);
 * the adaptive m_0 with M0_SCALE = 2 takes 31 ... 64 at 128^2 and 512^2
 * for p* = 0.002 ... 0.2.
 *
 * Passes: the wall (reads K u, v and the update's mark ON_WALL in
 * contact; writes f_eff and the contact set), the loop's mixing sums
 * (reads a, v, C) and the update (reads a, u, h, v, C; writes u, v and
 * the mark); in chunks of CHUNK points, fused with the row transforms on
 * the blocked path (solver_fire_loop.c).  The mark spares the wall the
 * reads of u and h (16 bytes a point); the update and the mixing run two
 * points at a time without branches (rc__v2d, solver_impl.h), the same
 * operations in the same order, so the same bits; the update first runs
 * on the CPU's widest vectors, 4 or 8 points (solver_fire_wide.c), and
 * leaves the two-point loop the rest of its range.  Measured (perf
 * samples, 512^2, 10 pressures, one thread, 3 runs each): the wall 20 to
 * 27% faster, the update 15 to 22%, the mixing 10 to 15%; together 0.96
 * FFT pairs an iteration before, 0.78 now.  Not kept: the wall without
 * branches (sums adding +0) or two points at a time, 25 to 45% slower;
 * summing two chunks in one loop (two chains of additions), no gain.
 * The iteration count at tol 1e-6 is nearly independent of N (256^2:
 * 43, 512^2: 41, 1024^2: 38 at p* = 0.05; the uniform real-space mass
 * this replaces took 262, 299, 467 with one pair each, growing like
 * sqrt(n)).
 *
 * Start: u = max h (a flat body touching the highest point) unless a
 * displacement was loaded or a previous solve left one (warm start).
 * Memory: u and v (16 bytes per point) besides the shared solver fields,
 * and the mass table (4 bytes per point) during a solve;
 * a lives in the elastic operator's real FFT buffer.
 */
#include "solver_impl.h"

#include <math.h>
#include <string.h>

/* A distributed operator (elastic.h, make MPI=1) runs this file on each
 * rank's rows: s->n is the local point count, rc__points the global one,
 * and every sum over points is completed through rc_elastic_sum (the
 * loop's). */
#define POINTS(s)	rc__points(s)

#define CHUNK		8192	/* points per range of a pass */

/* contact[k] between the update pass and the next force pass: the point
 * is on the wall, u == h (the update clamped it, or the start), so that
 * the force pass need not read u and h; the force pass leaves the
 * contact set C (0 or 1) for the mixing and update passes and for every
 * reader after the solve. */
#define ON_WALL		RC__ON_WALL

int
rc__fire_alloc(rc_solver *s, rc_err *err)
{
	/* on huge pages from 1 MB (fft.h): at 1024^2 the two took 4096 page
	 * faults, 53 ms, in a solve's first pass */
	s->u = rc_fft_huge(s->n * sizeof(double), &s->u_block);
	s->fire_vel = rc_fft_huge(s->n * sizeof(double), &s->vel_block);
	if (s->u == NULL || s->fire_vel == NULL)
		return rc_seterr(err, "out of memory (asked for %zu bytes of FIRE buffers)",
		    2 * s->n * sizeof(double));
	return 0;
}

/* The wall's state in the loop: the solver, the load, and the vector
 * lanes of the update's wide loop (solver_fire_wide.c). */
struct wall {
	rc_solver *s;
	double p;
	int lanes;
};

/* The force pass on the points k0 <= k < k1 of f, which holds K u: f_eff
 * into f and the contact set; adds the squared force off the wall, the
 * pressure on it, the contact count and the power f_eff . v to
 * sum[0..3].  On the wall means u == h, which the update (or the start)
 * marked ON_WALL: the same truth value without reading u and h.  Close
 * to adh_range (solver_fire_adh_pass.c) with smax = 0, but not that with
 * a law: the wall tests u == h (adh_range g <= 0), sums the pressure p +
 * K u (adh_range K u alone) and keeps four sums, each as the wall summed
 * before the one loop; merged, the sums' order and roundings would
 * change and with them the rows' bits.  The count is an integer (exact,
 * converted once). */
static void
wall_range(void *ctx, double *f, const rc__fire_step *st, size_t k0,
    size_t k1, double *sum, double *least)
{
	const struct wall *w = ctx;
	rc_solver *s = w->s;
	size_t k, on = 0;
	double p = w->p, sum_d2 = 0, sum_s = 0, pw = 0;
	const double *v = s->fire_vel;
	unsigned char *contact = s->contact;

	(void)st;
	(void)least;
	for (k = k0; k < k1; k++) {
		double implied = p + f[k];

		if (contact[k] == ON_WALL && implied > 0) {
			contact[k] = 1;
			sum_s += implied;
			on++;
			f[k] = 0;
		} else {
			contact[k] = 0;
			f[k] = -implied;
			sum_d2 += implied * implied;
		}
		pw += f[k] * v[k];
	}
	sum[0] += sum_d2;
	sum[1] += sum_s;
	sum[2] += (double)on;
	sum[3] += pw;
}

/* The report from wall_range's sums: the residual, the contact count,
 * the power, the mean mode's mass. */
static void
wall_forced(void *ctx, const double *sum, double least, rc__fire_report *r)
{
	const struct wall *w = ctx;

	(void)least;
	r->residual = rc__residual(w->s, w->p, sum[0], sum[1]);
	r->contact = sum[2];
	r->power = sum[3];
	r->mass0 = rc__fire_mass0(w->s->el.k_min, r->contact, POINTS(w->s));
}

/* The update on k0 <= k < k1: the velocity and the clamped position,
 * and the mark ON_WALL where it clamps (u = h; elsewhere u > h, so the
 * mark is exactly u == h), the contact set C it read being no longer
 * needed.  Two points at a time (the lanes of rc__v2d: masks for the
 * selects), the rest one by one.  adh_update_range's twin without the
 * level shift and the heights' sum; kept apart because the clamp is
 * written differently there (fmax, then v = 0 where u == h, against uk
 * <= h here) and the rows must stay bit for bit what each interaction
 * gave before the one loop. */
static void
update_range(void *ctx, double *a, const rc__fire_step *st, size_t k0,
    size_t k1, double *sum, double *least)
{
	const struct wall *w = ctx;
	rc_solver *s = w->s;
	unsigned char *contact = s->contact;
	const double *h = s->height;
	double *u = s->u, *v = s->fire_vel;
	double dt = st->dt, mix_v = st->mix_v, mix_a = st->mix_a;
	int restart = st->restart;
	size_t k;

	(void)sum;
	(void)least;
	k = rc__wall_update_lanes(w->lanes, contact, h, u, v, a, st, k0, k1);
#ifdef RC__V2
	for (; k + 2 <= k1; k += 2) {
		rc__v2d ak, vk, uk, hk;
		rc__v2l held = rc__v2_held(contact + k), clamp;

		memcpy(&ak, a + k, sizeof(ak));
		memcpy(&vk, v + k, sizeof(vk));
		memcpy(&uk, u + k, sizeof(uk));
		memcpy(&hk, h + k, sizeof(hk));
		ak = (rc__v2d)((rc__v2l)ak & ~held);
		if (restart)
			vk = (rc__v2d){ 0, 0 };
		vk = mix_v * (vk + dt * ak) + mix_a * ak;
		uk = uk + dt * vk;
		clamp = uk <= hk;
		uk = (rc__v2d)(((rc__v2l)hk & clamp) |
		    ((rc__v2l)uk & ~clamp));
		vk = (rc__v2d)((rc__v2l)vk & ~clamp);
		memcpy(u + k, &uk, sizeof(uk));
		memcpy(v + k, &vk, sizeof(vk));
		contact[k] = clamp[0] ? ON_WALL : 0;
		contact[k + 1] = clamp[1] ? ON_WALL : 0;
	}
#endif
	for (; k < k1; k++) {
		double ak = contact[k] ? 0 : a[k], vk = restart ? 0 : v[k];
		double uk;

		vk = mix_v * (vk + dt * ak) + mix_a * ak;
		uk = u[k] + dt * vk;
		if (uk <= h[k]) {
			u[k] = h[k];
			v[k] = 0;
			contact[k] = ON_WALL;
		} else {
			u[k] = uk;
			v[k] = vk;
			contact[k] = 0;
		}
	}
}

/* sigma on the contact set of the last force pass; returns the elastic
 * energy per area (1/2) <u K u>. */
static double
contact_pressure(rc_solver *s, double p)
{
	size_t k;
	double sum = 0;

	rc_elastic_force(&s->el, s->u, s->sigma);
#pragma omp parallel for reduction(+:sum) schedule(static)
	for (k = 0; k < s->n; k++) {
		sum += s->u[k] * s->sigma[k];
		s->sigma[k] = s->contact[k] ? p + s->sigma[k] : 0;
	}
	rc_elastic_sum(&s->el, &sum, 1);
	return 0.5 * sum / POINTS(s);
}

/* The start: u = max h unless a state was loaded, u >= h, v = 0, and
 * the mark ON_WALL where u == h for the first force pass. */
static void
fire_start(rc_solver *s)
{
	size_t n = s->n, k;
	double *u = s->u, *v = s->fire_vel;
	const double *h = s->height;

	if (!s->have_u) {
		double top = -HUGE_VAL;

		for (k = 0; k < n; k++)
			if (h[k] > top)
				top = h[k];
		rc_elastic_max(&s->el, &top, 1);
		for (k = 0; k < n; k++)
			u[k] = top;
		s->have_u = 1;
	}
#pragma omp parallel for schedule(static)
	for (k = 0; k < n; k++) {
		if (u[k] < h[k])
			u[k] = h[k];
		v[k] = 0;
		s->contact[k] = u[k] == h[k] ? ON_WALL : 0;
	}
}

int
rc__fire_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	struct wall w = { s, p, rc__lanes_best() };
	/* with the sigma grid as the force where the operator's buffer
	 * cannot hold it (the blocked path, no mass table) */
	rc__fire_parts pt = { .el = &s->el, .n = s->n, .points = POINTS(s),
	    .u = s->u, .f = s->sigma, .v = s->fire_vel, .contact = s->contact,
	    .ctx = &w, .grain = CHUNK, .fuse = 1, .mean_sums = 0,
	    .force = wall_range, .update = update_range,
	    .forced = wall_forced, .mixed = NULL, .updated = NULL,
	    .field = NULL, .accelerate = NULL, .mixing = NULL, .next = NULL };
	int status;

	(void)err;
	fire_start(s);
	status = rc__fire_run(&pt, &s->opts, &s->watch, &res->iterations,
	    &res->residual);
	s->energy = contact_pressure(s, p);
	return status;
}
