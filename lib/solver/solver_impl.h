/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_impl.h - the state behind rc_solver and the parts of the solver,
 * private to the library.  Layers, each file calling only those below it
 * (tests/e2e/callgraph.sh checks that no file calls back up):
 *   drivers: solver.c (set-up, dispatch, accessors), solver_approach.c
 *     (displacement control), solver_fire_adh.c and
 *     solver_fire_adh_free.c (the adhesive solve on periodic and free
 *     boundaries);
 *   minimisers: solver_fire.c (FIRE in heights against the hard wall),
 *     solver_fire_free.c (FIRE on pressures), solver_cg.c (CG),
 *     solver_fire_adh_pass.c (FIRE in heights with an adhesive law); the
 *     pressure methods, CG and FIRE on pressures, run on the interface of
 *     interaction.h;
 *   the FIRE loop that the three FIRE files run with their passes and
 *     hooks (solver_fire_loop.c, rc__fire_parts; on pressures with its
 *     operator's callbacks too);
 *     the operator (solver_operator.c: G, FIRE's mass, the stiffness
 *     scale), the interactions (of the pressure methods, interaction.h:
 *     solver_wall.c, the hard wall; solver_hardness.c, the hardness cap;
 *     and adhesion.c: the adhesive laws) and the convergence measure
 *     (solver_measure.c, with the pressure methods' one check);
 *   below them elastic*.c, layer.c, love.c, fft.c. */
#ifndef RC_SOLVER_IMPL_H
#define RC_SOLVER_IMPL_H

#include <math.h>

#include "elastic.h"
#include "elastic_free.h"
#include "solver.h"
#include "interaction.h"

/* Adhesion on free boundaries (solver_fire_adh_free.c): the state on the
 * padded 2nx x 2ny grid, whose operator is then s->el. */
typedef struct rc_adh_pad {
	size_t n;		/* 4 nx ny */
	double *u, *v, *f;	/* height, velocity, force; n each */
	double *h;		/* the indenter, -inf off the given area */
	unsigned char *contact;
	double stiffness0;	/* kappa_0 = 1 / sum C, the mean mode's */
	int valid;		/* u holds a state */
} rc_adh_pad;

/* The watch over one solve: whether it stalls (opts.stall_window: the
 * best convergence measure must halve within every window of that many
 * iterations, counted from the first one's).  Each loop calls
 * rc__watch_stalled once per iteration with the measure it stops on;
 * iteration 0 starts it anew. */
typedef struct rc__watch {
	long mark_it;		/* start of the current window */
	double mark_best;	/* the best measure at that start */
	double best;		/* the best measure so far */
	int stalled;
} rc__watch;

static inline int
rc__watch_stalled(rc__watch *w, long window, long it, double measure)
{
	if (it == 0) {
		w->mark_it = 0;
		w->mark_best = w->best = measure;
		w->stalled = 0;
		return 0;
	}
	if (measure < w->best)
		w->best = measure;
	if (window <= 0 || it - w->mark_it < window)
		return 0;
	if (!(w->best <= 0.5 * w->mark_best))
		return w->stalled = 1;
	w->mark_it = it;
	w->mark_best = w->best;
	return 0;
}

struct rc_solver {
	rc_solver_opts opts;
	size_t nx, ny, n;
	double lx, ly;
	rc_elastic el;		/* periodic operator (unused when free) */
	rc_halfspace fel;	/* free boundaries: the padded compliance */
	int free_bc;		/* opts.boundary == RC_BOUNDARY_FREE */
	double level;		/* free CG: rigid level c of the solution */
	double top;		/* max h */
	double *scratch;	/* n doubles: G t of the free CG, the force
				 * of FIRE on pressures */
	double *height;		/* indenter h, n */
	double *u;		/* elastic surface height; FIRE: el.fft.real */
	double *sigma;		/* contact pressure, n */
	unsigned char *contact;	/* n */
	/* FIRE: the velocity, n. */
	double *fire_vel;
	/* CG: the conjugate direction. */
	double *cg_dir;
	int have_u;		/* u holds a state to start from */
	int have_sigma;		/* CG: sigma holds a pressure to start from */
	double last_pressure;	/* pressure of the last solve (0: none) */
	double energy;		/* elastic energy per area of the solution */
	double k_uniform;	/* a layer: k_0 (layer.h); +inf: half space */
	/* adhesion (solver_fire_adh.c): p_adh and a_attr of the solution */
	double p_adh, a_attr;
	rc_adh_pad pad;		/* adhesion on free boundaries */
	rc__watch watch;	/* the current solve's stall watch */
	/* The blocks rc_fft_huge placed height, sigma, scratch and FIRE's u
	 * and fire_vel in (what rc_fft_huge_free takes); NULL: the arrays
	 * themselves (solver.c). */
	void *height_block, *sigma_block, *scratch_block;
	void *u_block, *vel_block;
};

/* The number of points of the whole grid: s->n, or the global count of a
 * distributed operator (elastic.h), whose s->n is this process's rows. */
double rc__points(const rc_solver *s);
/* Both methods' convergence measure (solver_measure.c) from the sum over all
 * points of (p + K u - sigma)^2 and the sum of sigma. */
double rc__residual(const rc_solver *s, double p, double sum_d2, double sum_sigma);
/* Warm-start pressures scaled to mean p (solver_measure.c). */
void rc__sigma_to_load(rc_solver *s, double p);
int rc__fire_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err);
int rc__cg_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err);
int rc__fire_alloc(rc_solver *s, rc_err *err);
/* FIRE's a = M^-1 f_eff with m_q = k_q of e, m_0 = mass0
 * (solver_operator.c); e's real buffer, returned. */
double *rc__fire_mass_weighted(rc_elastic *e, const double *f, double mass0);
/* FIRE with the adhesive law (solver_fire_adh.c, its interaction
 * solver_fire_adh_pass.c): load control at p
 * (RC__ADH_LOAD), the mean height held at max h - delta (RC__ADH_LEVEL;
 * the pressure found into *p) or, a periodic layer, its rigid substrate
 * held at approach delta (RC__ADH_SUBSTRATE: the mean mode on the spring
 * k_0, p = k_0 (<u> - max h + delta) found into *p). */
enum { RC__ADH_LOAD = 0, RC__ADH_LEVEL = 1, RC__ADH_SUBSTRATE = 2 };
int rc__fire_adh_solve(rc_solver *s, int control, double *p, double delta,
    rc_solve_result *res, rc_err *err);
/* What the adhesive FIRE runs on (solver_fire_adh_pass.c): the
 * operator's grid of n points, of which n_act interact (the rest: h =
 * -inf); mass0 > 0 the mean mode's mass when the rigid level is held
 * (free boundaries: p = 0, the load the sum of the tractions, which then
 * scales the residual); else load control's rule (rc__fire_mass0).
 * Control 0, p on every one of the n points; control 1, <u> held at
 * target (periodic only), p found; control 2 (periodic only), p = spring
 * (<u> - target) from the state, spring = k_0 > 0 of the layer (unused by
 * the other two).  Status as rc_solver_solve. */
typedef struct rc__adh_view {
	rc_elastic *el;
	size_t n;
	double n_act;
	double *u, *v, *f;
	const double *h;
	unsigned char *contact;
	double mass0;
	double spring;
	rc__watch *watch;
} rc__adh_view;
struct rc_adhesion;
int rc__adh_relax(const rc__adh_view *w, const struct rc_adhesion *law,
    int control, double *p, double target, const rc_solver_opts *opts,
    rc_solve_result *res);
/* Free boundaries (solver_fire_adh_free.c): the padded operator and
 * state, made from s->fel (released after); the solve, as
 * rc__fire_adh_solve. */
int rc__adh_free_init(rc_solver *s, rc_err *err);
void rc__adh_free_release(rc_solver *s);
size_t rc__adh_free_bytes(const rc_solver *s);
int rc__fire_adh_free_solve(rc_solver *s, const struct rc_adhesion *law,
    int control, double *p, double delta, rc_solve_result *res);
/* The pressure methods (the CG, solver_cg.c, one loop for the wall and
 * the cap; FIRE on pressures, solver_fire_free.c: free boundaries, and a
 * hardness on either boundary kind) run on the interaction of s
 * (interaction.h): the cap with a hardness, else the wall. */
static inline void
rc__interaction_of(const rc_solver *s, rc__interaction *in)
{
	if (rc_solver_opts_plastic(&s->opts))
		rc__cap(s, in);
	else
		rc__wall(s, in);
}
int rc__fire_sigma_solve(rc_solver *s, double p, rc_solve_result *res,
    rc_err *err);
int rc__cg_alloc(rc_solver *s, rc_err *err);
/* The operator (solver_operator.c): out = G x; G_00 of the periodic
 * compliance; the stiffness scale of the free boundaries' measure. */
void rc__compliance(rc_solver *s, const double *x, double *out);
double rc__self_compliance(const rc_elastic *e);
double rc__stiffness_max(const rc_solver *s);
/* The wall's start pressure (solver_wall.c), which the cap's clips. */
void rc__wall_start(rc_solver *s, double p);
/* The stopping rule of the pressure methods (solver_measure.c), after
 * iteration it has its gap bound: STOP (rc__pressure_check ran:
 * *residual, and *status 0 if it met opts.tol), STALE (recheck: a
 * periodic check of the residual itself ran and missed: the iterate must
 * be recomputed) or GO. */
enum { RC__CG_GO, RC__CG_STOP, RC__CG_STALE };
int rc__cg_next(rc_solver *s, const rc__interaction *in, double p,
    double bound, long it, int recheck, double *residual, int *status);

/* FIRE's parameters, shared by its two loops (solver_fire_loop.c, which
 * says what each is and how it was tuned, in heights; solver_fire_free.c
 * on pressures). */
#define RC_FIRE_DT_START	1.0
#define RC_FIRE_DT_MAX		2.0
#define RC_FIRE_N_MIN		1
#define RC_FIRE_F_INC		1.1
#define RC_FIRE_F_DEC		0.85
#define RC_FIRE_ALPHA_START	0.5
#define RC_FIRE_F_ALPHA		0.99
#define RC_FIRE_M0_SCALE	2.0
#define RC_FIRE_PROGRESS_EVERY	50

/* FIRE's schedule and mixing, written once for its loops
 * (solver_fire_loop.c says what they are): after a step of power P, dt and alpha grow when
 * P > 0 (after RC_FIRE_N_MIN such steps in a row; dt up to dt_max), else
 * the step restarts (v = 0; returns 1) with a smaller dt and alpha reset;
 * the FIRE 2.0 mixing v' = mix_v (v + dt a) + mix_a a, |v'| = |v + dt a|,
 * from the sums |a|^2, a.v and |v|^2. */
typedef struct rc__fire {
	double dt, alpha;
	long npos;		/* positive-power steps in a row */
} rc__fire;
#define RC__FIRE_START	{ RC_FIRE_DT_START, RC_FIRE_ALPHA_START, 0 }

static inline int
rc__fire_adapt(rc__fire *fs, double power, double dt_max)
{
	if (!(power > 0)) {
		fs->npos = 0;
		fs->dt *= RC_FIRE_F_DEC;
		fs->alpha = RC_FIRE_ALPHA_START;
		return 1;
	}
	if (++fs->npos > RC_FIRE_N_MIN) {
		fs->dt = fmin(fs->dt * RC_FIRE_F_INC, dt_max);
		fs->alpha *= RC_FIRE_F_ALPHA;
	}
	return 0;
}

static inline void
rc__fire_mix(const rc__fire *fs, double aa, double av, double vv,
    double *mix_v, double *mix_a)
{
	*mix_v = 1;
	*mix_a = 0;
	if (aa > 0) {
		double vn2 = vv + 2 * fs->dt * av + fs->dt * fs->dt * aa;

		*mix_v = 1 - fs->alpha;
		*mix_a = fs->alpha * sqrt(vn2 / aa);
	}
}

/* The mean mode's mass of FIRE in heights while the load is prescribed
 * (solver_fire.c says why): M0_SCALE k_min sqrt(max(n_c, 1) / N) from
 * the contact count n_c of N points. */
static inline double
rc__fire_mass0(double k_min, double n_contact, double points)
{
	return RC_FIRE_M0_SCALE * k_min *
	    sqrt((n_contact > 0 ? n_contact : 1) / points);
}

/* The FIRE loop (solver_fire_loop.c), in heights and on pressures, over
 * an operator (by default an rc_elastic: K and the mass-weighting M^-1,
 * m_q = k_q; else the field and accelerate callbacks) and an interaction
 * given as passes.  A pass runs over the points
 * k0 <= k < k1 (called once per range of points: never per point) and
 * adds its sums to sum[0 .. RC__FIRE_SUMS-1] and lowers *least (this
 * process's; the sums the loop completes over a distributed operator's
 * ranks); after each pass a hook sees the sums over the grid:
 *   force (x = f holding K u, or field's): f_eff = -(p + K u - the
 *     interaction's traction) into f, and the contact set C (held by the
 *     wall: the loop's a = 0 there) into contact; forced fills
 *     the report (the residual, the power f_eff . v, the contact count,
 *     the mean mode's mass for this step, the largest step, whether to
 *     halt);
 *   mixing (the loop's own, or the interaction's when set; x = a =
 *     M^-1 f_eff): |a|^2, a.v, |v|^2 into sum[0..2] with a = 0 on C and
 *     v = 0 on a restart; with mean_sums the sums of a and v into
 *     sum[3..4]; mixed (may be NULL) makes the first three those of the
 *     step the update takes and may lower the step *dt;
 *   update (x = a): v' = mix_v (v + dt a) + mix_a a, u += dt v', the
 *     clamp at h; updated (may be NULL) follows it.  An interaction's
 *     update may leave its own marks in contact for its next force pass
 *     (the wall's ON_WALL, solver_fire.c), so every force pass follows
 *     an update: a next hook that answers STALE (force again without an
 *     update) cannot be combined with such an interaction.
 * The plain path runs a pass on chunks of grain points, or with grain 0
 * on each thread's share; on the blocked transforms (fft.h), when fuse
 * is set, on each block of rows between its row transforms (the update
 * must then leave u final: no updated hook).  Returns 0 converged
 * (residual <= opts.tol), RC__FIRE_HALTED (the report's halt), else 1
 * (out of iterations, stopped, stalled); *iterations, *residual.
 * FIRE on pressures (solver_fire_free.c) brings its operator: field
 * (u = G sigma and the level; returns the grid the force pass writes f
 * into) and accelerate (a = K f; returns a), its mixing pass, and next,
 * its stopping rule in place of the loop's (rc__cg_next's GO, STOP,
 * STALE: from the report's residual, sets *residual and *status). */
#define RC__FIRE_SUMS	7
/* Two doubles and their lane masks (a comparison's result: all ones or
 * zero), GCC's and Clang's vector extension (SSE2 on x86-64), for the
 * wall's update and the loop's mixing pass: gcc 12 at -O2 vectorises
 * neither (a byte mask beside doubles), and element-wise operations in
 * the same order are the scalar code's bit for bit, as long as no a*b + c
 * is fused into an FMA (the Makefile's -ffp-contract=off; the scalar
 * code's and the pairs' sums would then round differently). */
#if defined(__GNUC__) || defined(__clang__)
#define RC__V2
typedef double rc__v2d __attribute__((vector_size(16)));
typedef long long rc__v2l __attribute__((vector_size(16)));

/* The lanes where c[0], c[1] are nonzero (in the contact set C). */
static inline rc__v2l
rc__v2_held(const unsigned char *c)
{
	return (rc__v2l){ c[0] ? -1 : 0, c[1] ? -1 : 0 };
}
#endif
enum { RC__FIRE_HALTED = 2 };
typedef struct rc__fire_step {
	double dt;
	int restart;		/* P <= 0: v = 0 before this step */
	double mix_v, mix_a;	/* v' = mix_v (v + dt a) + mix_a a */
} rc__fire_step;
typedef struct rc__fire_report {
	double residual;
	double power;		/* f_eff . v */
	double contact;		/* points in contact */
	double mass0;		/* the mean mode's mass of this step */
	int halt;		/* end the solve before this step */
	double dt_max;		/* the largest step (RC_FIRE_DT_MAX) */
} rc__fire_report;
typedef void rc__fire_pass(void *ctx, double *x, const rc__fire_step *st,
    size_t k0, size_t k1, double *sum, double *least);
/* The hard wall's mark (solver_fire.c): contact[k] between the update
 * pass and the next force pass, the point is on the wall (u == h). */
#define RC__ON_WALL	2
/* The wall's update loop on vectors of `lanes' doubles
 * (solver_fire_wide.c): RC__LANES_BASE (none: returns k0),
 * RC__LANES_AVX2 (4), RC__LANES_AVX512 (8); rc__lanes_best, the widest
 * this CPU runs.  It does the whole vectors from k0 on, the same
 * operations point for point as update_range's loops, and returns the
 * first point it left to them. */
enum { RC__LANES_BASE = 0, RC__LANES_AVX2 = 4, RC__LANES_AVX512 = 8 };
int rc__lanes_best(void);
size_t rc__wall_update_lanes(int lanes, unsigned char *contact,
    const double *h, double *u, double *v, const double *a,
    const rc__fire_step *st, size_t k0, size_t k1);
typedef struct rc__fire_parts {
	rc_elastic *el;		/* the operator */
	size_t n;		/* its points (this process's) */
	double points;		/* the points that interact (the progress
				 * report's contact share) */
	const double *u;	/* the heights (the update's); const to the
				 * loop only: the update pass writes u
				 * through ctx, and the blocked path's r2c
				 * reads the new u from here */
	double *f;		/* n doubles for the force where the
				 * operator's own buffer cannot hold it:
				 * required when there is no mass table
				 * (a distributed operator, k_0 > 0 or a
				 * k_q <= 0, or accelerate set) or on the
				 * blocked path; NULL only when neither
				 * holds (the force is then the operator's
				 * real buffer) or field supplies it */
	const double *v;	/* the velocities (the mixing's) */
	const unsigned char *contact;	/* C, of the force pass, read by
				 * the loop's mixing pass; unused (may be
				 * NULL) when mixing is set */
	void *ctx;		/* the interaction's state, each pass's and
				 * hook's first argument */
	size_t grain;		/* plain path: points a range (chunks of a
				 * `parallel for'), or 0 for one range a
				 * thread (thread_share); it fixes the
				 * order of the sums, hence the rows */
	int fuse;		/* run the passes on the blocked
				 * transforms between their row transforms
				 * (then updated must be NULL) */
	int mean_sums;		/* the mixing pass also sums a and v into
				 * sum[3..4] (the level control's mean) */
	rc__fire_pass *force;	/* step 2: f_eff, C, the force sums */
	rc__fire_pass *update;	/* step 5: v', u += dt v', the clamp */
	void (*forced)(void *ctx, const double *sum, double least,
	    rc__fire_report *r);	/* the force sums -> the report */
	void (*mixed)(void *ctx, double *sum, double *dt);	/* or NULL:
				 * the mixing sums of the step the update
				 * takes; may lower *dt */
	void (*updated)(void *ctx, const double *sum);	/* or NULL: after
				 * the update pass, with its sums */
	/* NULL but on pressures (see above) */
	double *(*field)(void *ctx);	/* u = G sigma; returns the grid
				 * the force pass writes f into */
	double *(*accelerate)(void *ctx, double *f);	/* a = K f;
				 * returns a (no mass table then) */
	rc__fire_pass *mixing;	/* the interaction's own mixing pass in
				 * place of the loop's (contact unused) */
	int (*next)(void *ctx, long it, double bound, double *residual,
	    int *status);	/* the stopping rule in place of the
				 * loop's: returns RC__CG_GO, RC__CG_STOP
				 * or RC__CG_STALE (rc__cg_next's codes) */
} rc__fire_parts;
int rc__fire_run(const rc__fire_parts *pt, const rc_solver_opts *opts,
    rc__watch *watch, long *iterations, double *residual);

#endif
