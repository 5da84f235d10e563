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
    size_t changed, size_t flipped, size_t on)
{
	if ((double)flipped > FLIP_FRACTION * (double)on)
		b->dt_flip *= RC_FIRE_F_DEC;
	else
		b->dt_flip = fmin(SIGMA_DT_MAX, b->dt_flip * RC_FIRE_F_INC);
	if (num > 0 && den > 0 && (double)changed <= SET_STABLE * (double)on)
		b->lambda = fmax(num / den, LAMBDA_DECAY * b->lambda);
	b->dt_max = b->lambda > 0 ?
	    fmin(b->dt_flip, STEP_SAFETY / sqrt(b->lambda)) : b->dt_flip;
}

/* a = K f (mean mode 0) into the periodic operator's real buffer. */
static double *
stiffness_times(rc_solver *s, const double *f)
{
	rc_elastic *e = &s->el;

	rc_elastic_force(e, f, e->fft.real);
	return e->fft.real;
}

/* Long: the FIRE iteration on pressures, its passes sharing their sums
 * as in solver_fire_loop.c. */
int
rc__fire_sigma_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	size_t n = s->n, k;
	/* the start at solver_fire_loop.c's 1, stable while all points are
	 * active (the start: uniform pressure), as measured below */
	double dt = RC_FIRE_DT_START, alpha = RC_FIRE_ALPHA_START;
	double residual = HUGE_VAL;
	double *sigma = s->sigma, *u = s->u, *v = s->fire_vel, *f = s->scratch;
	double k_max = rc__stiffness_max(s);
	const double *h = s->height;
	unsigned long small0 = s->el.n_r2c + s->el.n_c2r;
	rc__interaction in;
	double H, max_move;
	long it, npos = 0;
	int status = 1, next;
	struct step_bound bound = { 0, SIGMA_DT_MAX, SIGMA_DT_MAX };
	/* the previous iteration's pressures, forces (0: off A) and
	 * accelerations, and whether each point was in A the iteration
	 * before that (the rules of STEP_SAFETY and FLIP_FRACTION) */
	double *prev = fftw_alloc_real(3 * n);
	double *s_prev = prev, *f_prev = prev + n, *a_prev = prev + 2 * n;
	unsigned char *was_active = calloc(n, 1);

	if (prev == NULL || was_active == NULL) {
		fftw_free(prev);
		free(was_active);
		return rc_seterr(err, "out of memory (asked for %zu bytes of "
		    "FIRE buffers)", n * (3 * sizeof(double) + 1));
	}
	memset(prev, 0, 3 * n * sizeof(double));
	/* the wall: H = +inf, and the rules below are those of sigma >= 0
	 * alone */
	rc__interaction_of(s, &in);
	H = in.H;
	max_move = in.max_move;
	in.start(s, p);
	memset(v, 0, n * sizeof(double));
	for (it = 0; ; it++) {
		double c, ff = 0, power = 0, aa = 0, av = 0, vv = 0, sum = 0;
		double mix_v = 1, mix_a = 0, *a, num = 0, den = 0;
		size_t on, changed = 0, flipped = 0;
		int restart;

		rc__compliance(s, sigma, u);
		on = in.level(s, &c);
#pragma omp parallel for reduction(+:ff, power) schedule(static)
		for (k = 0; k < n; k++) {
			double g = u[k] + c - h[k];

			f[k] = rc__active(sigma[k], g, H) ? -g : 0;
			ff += f[k] * f[k];
			power += f[k] * v[k];
		}
		/* free: the check is the bound itself, so it runs only at
		 * the end */
		next = rc__cg_next(s, &in, p, k_max * sqrt(ff / (double)n) / p,
		    it, !s->free_bc, &residual, &status);
		if (next == RC__CG_STOP)
			break;
		if (next == RC__CG_STALE)
			continue;	/* the check left u' in u: recompute */
		if (s->opts.progress && it % RC_FIRE_PROGRESS_EVERY == 0)
			s->opts.progress(s->opts.progress_ctx, it,
			    k_max * sqrt(ff / (double)n) / p, (double)on / (double)n);
		a = stiffness_times(s, f);
		restart = !(power > 0);
		if (!restart) {
			if (++npos > RC_FIRE_N_MIN) {
				dt = fmin(dt * RC_FIRE_F_INC, bound.dt_max);
				alpha *= RC_FIRE_F_ALPHA;
			}
		} else {
			npos = 0;
			dt *= RC_FIRE_F_DEC;
			alpha = RC_FIRE_ALPHA_START;
		}
#pragma omp parallel for reduction(+:aa, av, vv, num, den, changed, \
    flipped) schedule(static)
		for (k = 0; k < n; k++) {
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
		if (it > 0)
			step_bound_update(&bound, num, den, changed, flipped, on);
		if (it >= 2)
			dt = fmin(dt, bound.dt_max);
		if (aa > 0) {
			double vn2 = vv + 2 * dt * av + dt * dt * aa;

			mix_v = 1 - alpha;
			mix_a = alpha * sqrt(vn2 / aa);
		}
#pragma omp parallel for reduction(+:sum) schedule(static)
		for (k = 0; k < n; k++) {
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
			sum += sk;
		}
		in.restore_load(s, p, sum, NULL);
	}
	/* Free: fft_pairs in padded pairs (solver.c counts those), the
	 * unpadded pairs as a quarter each.  Periodic: both operators are
	 * s->el's, which solver.c counts. */
	if (s->free_bc)
		res->fft_pairs = 0.25 * 0.5 *
		    (double)(s->el.n_r2c + s->el.n_c2r - small0);
	fftw_free(prev);
	free(was_active);
	res->iterations = it;
	res->residual = residual;
	return status;
}
