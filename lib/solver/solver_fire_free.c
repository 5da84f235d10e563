/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_free.c - FIRE on pressures: on free boundaries, and with a
 * hardness (perfect plasticity) on either boundary kind.  Damped dynamics
 * of the contact pressures sigma >= 0 (not of the surface heights, as
 * solver_fire.c does on a periodic body, which stays the elastic periodic
 * FIRE), with the compliance G as the operator (free: the padded one of
 * elastic_free.h; periodic: 1/k_q of elastic.h, a layer's too) and the
 * periodic stiffness of the same grid as the inverse mass, so that every
 * mode has nearly the same frequency.
 *
 * The pressures minimise the complementary energy
 *   Pi(sigma) = (1/2) sigma.G sigma - sigma.(h - c),  sigma >= 0,
 *   sum sigma = p N (the load; c its multiplier, the rigid level),
 * whose force on sigma is minus the gap, f = -(G sigma + c - h).  G is
 * dense and not diagonal in Fourier space, but at wavelengths below the
 * size of the area it is the half-space compliance 2/(q E*), whose
 * inverse is the periodic stiffness k_q = E* q / 2 (elastic.h).  So the
 * acceleration a = K f, K the periodic operator on the nx x ny grid: a
 * frequency near 1 for every mode, as in Zhou, Moseler & Mueser's mass
 * weighting, and the iteration count does not grow like sqrt(N) (the
 * periodic K is wrong only for the few longest waves, where G feels the
 * edges of the area).  One iteration:
 *  1. u = G sigma (one pair of the padded 2nx x 2ny transform); c the
 *     level that makes the mean gap over {sigma > 0} zero (as in solver_cg.c).
 *  2. f = -(u + c - h) on the active set: sigma > 0, or sigma = 0 with a
 *     negative gap (penetration: the force raises the pressure); f = 0
 *     elsewhere (sigma = 0 and an open gap: the bound sigma >= 0 takes the
 *     force, as the wall does in solver_fire.c).  Convergence: the
 *     free-boundary measure of solver_cg.c, k_max rms(f) / p, from this pass (the load is
 *     exact after step 5).
 *  3. a = K f (one pair of the nx x ny transform; the mean mode gets
 *     0: the mean of sigma is the load, held by step 5), then a = 0 off
 *     the active set.
 *  4. FIRE 2.0 as in solver_fire_loop.c, with its parameters (same meaning:
 *     time in units of the common period) except the largest step
 *     (SIGMA_DT_MAX below: why; lowered further by the rules of
 *     STEP_SAFETY and FLIP_FRACTION), P = f.v.
 *  5. sigma += dt v; where sigma < 0: sigma = 0, v = 0; then sigma is
 *     rescaled to the load (PK's rescaling; it moves the state along the
 *     load constraint only).
 * The iteration is FIRE's one loop (rc__fire_run, solver_fire_loop.c):
 * steps 1 and 3 its operator callbacks, 2 and 5 passes over each thread's
 * share of the points, step 4's rules and the load in its hooks.
 * The interaction (interaction.h: the wall, or with opts.hardness H the
 * cap, perfect plasticity, the same minimisation over the box 0 <= sigma
 * <= H) gives the start, step 1's level (the cap's fitted over 0 < sigma
 * < H), step 2's active set (the cap's adds the points at H whose gap is
 * open, g > 0: the force lowers them, and leaves out those at H with g <=
 * 0: the bound takes the force), step 5's bound (clamped into [0, H], v
 * = 0 where clamped; no point moves by more than the interaction's
 * max_move, H/2, in a step) and its load restoration (the wall's one
 * scale; the cap's scales the pressures below H, with its fallback when
 * they carry nothing), as for the CG.  The stopping rule and measure are the CG's
 * (rc__pressure_check through rc__cg_next: periodic, the residual
 * rms(p + K u' - sigma) / p; free, the gap bound), so both methods stop
 * at comparable accuracy.  The wall's rules are the cap's with H = +inf.
 * Measured (gfmd-solve --hardness 0.2 --pressure-abs 0.05, tol 1e-6,
 * surfgen defaults, seed 1; a_r 0.26, a_plastic 0.24): FIRE 33, 48, 44
 * iterations periodic and 34, 40, 42 free at 128^2, 256^2, 512^2; the
 * plastic CG 22, 30, 42 and 24, 30, 43 (the same contact and plastic
 * sets to the point).  Periodic cost: two pairs of the nx x ny transform
 * per iteration (G sigma and K f), counted by solver.c; one more every
 * 100 iterations when rc__cg_next checks the residual itself.
 *
 * Measured (gfmd-solve --boundary free -p 0.05, surfgen defaults, seed 1,
 * tol 1e-6): FIRE 43, 59, 72 iterations at 128^2, 256^2, 512^2; the CG
 * 48, 97, 187 on the same maps (same a_r to the last point).
 * Cost per iteration: one padded pair and one unpadded pair (about 1.25
 * padded pairs); fft_pairs counts the padded pairs plus a quarter of the
 * unpadded ones.  Memory: sigma, u, v, f and the periodic operator
 * besides the padded one (periodic with a hardness: sigma, u, v, f).
 */
#include "solver_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <fftw3.h>

/* FIRE's largest time step on pressures (solver_fire_loop.c's RC_FIRE_DT_MAX,
 * 2, is for heights).  Why smaller: the mass K makes the frequency 1 for
 * every mode only when every point is active; on an active set A the
 * squared frequencies are the eigenvalues of K_AA G_AA, which are at
 * least 1 (G_AA^-1, the Schur complement of K, is at most K_AA) and grow
 * without bound as A thins out into scattered spots, whose collective
 * long-wave modes K_AA (local) sees far stiffer than G_AA (long-ranged)
 * does.  A step past the stability limit 2/omega_max lets such a mode
 * grow slowly under a positive power until it throws the state back
 * (seen on measured maps at a_r ~ 0.02: the residual fell tenfold, then
 * jumped back every ~550 iterations, 17,102 iterations without
 * converging on a 768x576 map).  Too small a step slows the lowest
 * modes (frequency >= 1) instead.  Measured (gfmd-solve -p 0.01,0.05,
 * tol 1e-6, free; SurfaceTopography's examples levelled and filled):
 * dt_max 2 (before): 256^2 crops of opd, bcrf, metropro, sur, di, 2 of
 * 12 pressures beyond 1500 iterations, the whole opd, metropro and bcrf
 * maps not converged in minutes; 0.3: crops 48-110, whole maps
 * metropro (640x480) 1142 and 194, bcrf (960x600) 893 and 333; 0.2 (and
 * a start at 1): crops 45-103, metropro 365 and 166, bcrf 401 and 205,
 * sur (563x484) 254 and 111, opd, di and al3d 54-100, surfgen's default
 * 256^2 64 and 58 (51 and 57 with 2), the same contact sets as CG; 0.12:
 * metropro 365 at p* = 0.01.  The best step falls with the grid (the
 * spots' longest waves grow with it): a fixed one is a compromise, and
 * metropro and bcrf at p* = 0.01 still take over 300 iterations.  Now
 * the largest step, at most SIGMA_DT_MAX, falls by the two rules below. */
#define SIGMA_DT_MAX	0.2

/* Rule 1, the stiffness along the motion: between successive iterations
 * with (nearly) the same active set A, dsigma = sigma - sigma_prev,
 * df = f - f_prev = -G dsigma on A and da = K df give the Rayleigh
 * quotient lambda = <df, da> / <-df, dsigma> = <y, K y> / <dsigma, y>
 * (y = G dsigma on A) of the operator K_AA G_AA in G's inner product,
 * whose largest value is omega_max^2 (see above): no transform beyond
 * those of the iteration.  It is a lower bound, weighted towards the
 * stiff modes, that the motion's own stiff modes fill in; kept as the
 * largest recent value (each older one decays by LAMBDA_DECAY per
 * iteration), it bounds the step by STEP_SAFETY / sqrt(lambda), half the
 * stability limit.  Only over iterations where at most SET_STABLE of A
 * entered or left (else the quotient mixes points that changed state).
 * Rule 2, flip-flops: a step beyond the limit of the modes of points at
 * the bound shows as points that enter and leave A on alternate
 * iterations (the period-2 mode of an unstable step; clamping keeps it
 * bounded, so the power stays positive and FIRE does not see it); when
 * more than FLIP_FRACTION of A did so, the largest step falls by FIRE's
 * RC_FIRE_F_DEC, else it grows back by RC_FIRE_F_INC up to SIGMA_DT_MAX.
 * The first two iterations keep FIRE's start (its step 1 then 0.85), as
 * before.  Measured (gfmd-solve -j 1 -p 0.01,0.05, tol 1e-6, free,
 * SurfaceTopography's examples levelled and filled): on bcrf-1 (960x600)
 * at p* = 0.01 with SIGMA_DT_MAX alone about 130,000 of the 130,000 active
 * points changed state every iteration for 280 iterations; with rule 2
 * the flip-flops die out in ~40.  Iterations before -> after: metropro-1
 * 365, 166 -> 108, 132; bcrf-1 401, 205 -> 131, 179; sur-2 254, 111 ->
 * 192, 115; opd-1 57, 93 -> 53, 93; di-1 61, 100 -> 59, 72; al3d-1 66, 54
 * -> 66, 52; surfgen -H 0.8 256^2 seeds 1-5 and 512^2 within 3 of
 * before; the same contact sets. */
#define STEP_SAFETY	1.0
#define LAMBDA_DECAY	0.95
#define SET_STABLE	0.01
#define FLIP_FRACTION	0.05

/* The largest step of the rules above. */
struct step_bound {
	double lambda;	/* the largest recent Rayleigh quotient, 0: none */
	double dt_flip;	/* rule 2's bound */
	double dt_max;
};

/* Updates b from one iteration's sums over A: num = <df, da>, den =
 * <-df, dsigma> (over the points active in both iterations), changed
 * (points that entered or left A), flipped (those that also changed the
 * iteration before) and on = |A|. */
static void
step_bound_update(struct step_bound *b, double num, double den,
    double changed, double flipped, double on)
{
	if (flipped > FLIP_FRACTION * on)
		b->dt_flip *= RC_FIRE_F_DEC;
	else
		b->dt_flip = fmin(SIGMA_DT_MAX, b->dt_flip * RC_FIRE_F_INC);
	if (num > 0 && den > 0 && changed <= SET_STABLE * on)
		b->lambda = fmax(num / den, LAMBDA_DECAY * b->lambda);
	b->dt_max = b->lambda > 0 ?
	    fmin(b->dt_flip, STEP_SAFETY / sqrt(b->lambda)) : b->dt_flip;
}

/* The pressures' side of the FIRE loop (rc__fire_run): the state, the
 * interaction, this iteration's level and active set, the step bound. */
struct sigma_fire {
	rc_solver *s;
	rc__interaction in;
	double p, k_max;
	double c;		/* the rigid level of this iteration */
	double on;		/* |A|, from the level fit */
	long it;
	struct step_bound bound;
	/* the previous iteration's pressures, forces (0: off A) and
	 * accelerations, and whether each point was in A the iteration
	 * before that (the rules of STEP_SAFETY and FLIP_FRACTION) */
	double *s_prev, *f_prev, *a_prev;
	unsigned char *was_active;
};

/* Step 1: u = G sigma and the level c; the force pass writes f into
 * s->scratch. */
static double *
sigma_field(void *ctx)
{
	struct sigma_fire *sf = ctx;
	rc_solver *s = sf->s;

	rc__compliance(s, s->sigma, s->u);
	sf->on = (double)sf->in.level(s, &sf->c);
	return s->scratch;
}

/* Step 2 on k0 <= k < k1: f = -g on A, else 0; adds |f|^2 and the power
 * f.v to sum[0..1]. */
static void
sigma_force_range(void *ctx, double *f, const rc__fire_step *st, size_t k0,
    size_t k1, double *sum, double *least)
{
	const struct sigma_fire *sf = ctx;
	const rc_solver *s = sf->s;
	const double *u = s->u, *h = s->height, *sigma = s->sigma;
	const double *v = s->fire_vel;
	double c = sf->c, H = sf->in.H, ff = 0, power = 0;
	size_t k;

	(void)st;
	(void)least;
	for (k = k0; k < k1; k++) {
		double g = u[k] + c - h[k];

		f[k] = rc__active(sigma[k], g, H) ? -g : 0;
		ff += f[k] * f[k];
		power += f[k] * v[k];
	}
	sum[0] += ff;
	sum[1] += power;
}

/* The report: the free-boundary measure k_max rms(f) / p (the stopping
 * rule's bound and the progress report's residual), the power, |A|, the
 * largest step of the rules above. */
static void
sigma_forced(void *ctx, const double *sum, double least, rc__fire_report *r)
{
	const struct sigma_fire *sf = ctx;

	(void)least;
	r->residual = sf->k_max * sqrt(sum[0] / (double)sf->s->n) / sf->p;
	r->power = sum[1];
	r->contact = sf->on;
	r->dt_max = sf->bound.dt_max;
}

/* The pressure methods' stopping rule; free: the check is the bound
 * itself, so it runs only at the end.  STALE: the check left u' in u,
 * which the loop recomputes. */
static int
sigma_next(void *ctx, long it, double bound, double *residual, int *status)
{
	struct sigma_fire *sf = ctx;

	sf->it = it;
	return rc__cg_next(sf->s, &sf->in, sf->p, bound, it, !sf->s->free_bc,
	    residual, status);
}

/* Step 3: a = K f (mean mode 0) into the periodic operator's real
 * buffer. */
static double *
sigma_accelerate(void *ctx, double *f)
{
	rc_elastic *e = &((struct sigma_fire *)ctx)->s->el;

	rc_elastic_force(e, f, e->fft.real);
	return e->fft.real;
}

/* The mixing pass on k0 <= k < k1: a = 0 off A, v = 0 on a restart
 * (written: the update reads them); adds |a|^2, a.v, |v|^2 to sum[0..2]
 * and the rules' sums num, den, changed, flipped to sum[3..6]; moves the
 * forces and accelerations to f_prev and a_prev. */
static void
sigma_mixing_range(void *ctx, double *a, const rc__fire_step *st,
    size_t k0, size_t k1, double *sum, double *least)
{
	const struct sigma_fire *sf = ctx;
	const rc_solver *s = sf->s;
	const double *f = s->scratch, *sigma = s->sigma, *s_prev = sf->s_prev;
	double *v = s->fire_vel, *f_prev = sf->f_prev, *a_prev = sf->a_prev;
	unsigned char *was_active = sf->was_active;
	double aa = 0, av = 0, vv = 0, num = 0, den = 0;
	size_t k, changed = 0, flipped = 0;
	int restart = st->restart;

	(void)least;
	for (k = k0; k < k1; k++) {
		int now = f[k] != 0, before = f_prev[k] != 0;

		if (!now)
			a[k] = 0;
		if (restart)
			v[k] = 0;
		if (now && before) {
			double df = f[k] - f_prev[k];

			num += df * (a[k] - a_prev[k]);
			den -= df * (sigma[k] - s_prev[k]);
		}
		changed += now != before;
		flipped += now != before && before != was_active[k];
		was_active[k] = (unsigned char)before;
		f_prev[k] = f[k];
		a_prev[k] = a[k];
		aa += a[k] * a[k];
		av += a[k] * v[k];
		vv += v[k] * v[k];
	}
	sum[0] += aa;
	sum[1] += av;
	sum[2] += vv;
	sum[3] += num;
	sum[4] += den;
	sum[5] += (double)changed;
	sum[6] += (double)flipped;
}

/* After the mixing pass: the rules' bound, and the step within it (the
 * first two iterations keep FIRE's start). */
static void
sigma_mixed(void *ctx, double *sum, double *dt)
{
	struct sigma_fire *sf = ctx;

	if (sf->it > 0)
		step_bound_update(&sf->bound, sum[3], sum[4], sum[5], sum[6],
		    sf->on);
	if (sf->it >= 2)
		*dt = fmin(*dt, sf->bound.dt_max);
}

/* Step 5 on k0 <= k < k1: sigma += dt v' within max_move a point, clamped
 * into [0, H] (v = 0 there); the new pressures' sum to sum[0]. */
static void
sigma_update_range(void *ctx, double *a, const rc__fire_step *st,
    size_t k0, size_t k1, double *sum, double *least)
{
	const struct sigma_fire *sf = ctx;
	rc_solver *s = sf->s;
	double *sigma = s->sigma, *v = s->fire_vel, *s_prev = sf->s_prev;
	double dt = st->dt, mix_v = st->mix_v, mix_a = st->mix_a;
	double H = sf->in.H, max_move = sf->in.max_move, total = 0;
	size_t k;

	(void)least;
	for (k = k0; k < k1; k++) {
		double vk = mix_v * (v[k] + dt * a[k]) + mix_a * a[k];
		double sk;

		s_prev[k] = sigma[k];
		if (fabs(dt * vk) > max_move)
			vk = copysign(max_move / dt, vk);
		sk = sigma[k] + dt * vk;

		if (sk <= 0) {
			sk = 0;
			vk = 0;
		} else if (sk >= H) {
			sk = H;
			vk = 0;
		}
		sigma[k] = sk;
		v[k] = vk;
		total += sk;
	}
	sum[0] += total;
}

/* The load restored from the update's sum. */
static void
sigma_updated(void *ctx, const double *sum)
{
	struct sigma_fire *sf = ctx;

	sf->in.restore_load(sf->s, sf->p, sum[0], NULL);
}

int
rc__fire_sigma_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	size_t n = s->n;
	unsigned long small0 = s->el.n_r2c + s->el.n_c2r;
	struct sigma_fire sf = { .s = s, .p = p,
	    .k_max = rc__stiffness_max(s),
	    .bound = { 0, SIGMA_DT_MAX, SIGMA_DT_MAX } };
	/* FIRE's start at solver_fire_loop.c's 1, stable while all points
	 * are active (the start: uniform pressure), as measured above;
	 * one range a thread, the sums of a `parallel for' */
	rc__fire_parts pt = { .el = &s->el, .n = n, .points = (double)n,
	    .u = s->u, .f = s->scratch, .v = s->fire_vel, .contact = NULL,
	    .ctx = &sf, .grain = 0, .fuse = 0, .mean_sums = 0,
	    .force = sigma_force_range, .update = sigma_update_range,
	    .forced = sigma_forced, .mixed = sigma_mixed,
	    .updated = sigma_updated, .field = sigma_field,
	    .accelerate = sigma_accelerate, .mixing = sigma_mixing_range,
	    .next = sigma_next };
	double *prev = fftw_alloc_real(3 * n);
	int status;

	sf.was_active = calloc(n, 1);
	if (prev == NULL || sf.was_active == NULL) {
		fftw_free(prev);
		free(sf.was_active);
		return rc_seterr(err, "out of memory (asked for %zu bytes of "
		    "FIRE buffers)", n * (3 * sizeof(double) + 1));
	}
	memset(prev, 0, 3 * n * sizeof(double));
	sf.s_prev = prev;
	sf.f_prev = prev + n;
	sf.a_prev = prev + 2 * n;
	/* the wall: H = +inf, and the rules above are those of sigma >= 0
	 * alone */
	rc__interaction_of(s, &sf.in);
	sf.in.start(s, p);
	memset(s->fire_vel, 0, n * sizeof(double));
	status = rc__fire_run(&pt, &s->opts, &s->watch, &res->iterations,
	    &res->residual);
	/* Free: fft_pairs in padded pairs (solver.c counts those), the
	 * unpadded pairs as a quarter each.  Periodic: both operators are
	 * s->el's, which solver.c counts. */
	if (s->free_bc)
		res->fft_pairs = 0.25 * 0.5 *
		    (double)(s->el.n_r2c + s->el.n_c2r - small0);
	fftw_free(prev);
	free(sf.was_active);
	return status;
}
