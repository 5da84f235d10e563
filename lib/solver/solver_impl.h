/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_impl.h - the state behind rc_solver and the parts of the solver,
 * private to the library.  Layers, each file calling only those below it
 * (tests/e2e/callgraph.sh checks that no file calls back up):
 *   drivers: solver.c (set-up, dispatch, accessors), solver_approach.c
 *     (displacement control), solver_fire_adh.c and
 *     solver_fire_adh_free.c (the adhesive solve on periodic and free
 *     boundaries);
 *   minimisers: solver_fire.c (FIRE in heights), solver_fire_free.c
 *     (FIRE on pressures), solver_cg.c, solver_cg_plastic.c (CG),
 *     solver_fire_adh_loop.c (adhesive FIRE in heights);
 *   the operator (solver_operator.c: G, FIRE's mass, the stiffness
 *     scale), the interactions (solver_wall.c: the hard wall of the
 *     pressure methods; solver_hardness.c: the hardness cap; adhesion.c:
 *     the adhesive laws) and the convergence measure (solver_measure.c);
 *   below them elastic*.c, layer.c, love.c, fft.c. */
#ifndef RC_SOLVER_IMPL_H
#define RC_SOLVER_IMPL_H

#include <math.h>

#include "elastic.h"
#include "elastic_free.h"
#include "solver.h"

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
	/* The blocks rc_fft_huge placed height, sigma and scratch in (what
	 * fftw_free takes); NULL: the arrays themselves (solver.c). */
	void *height_block, *sigma_block, *scratch_block;
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
/* FIRE with the adhesive law (solver_fire_adh.c, its loop
 * solver_fire_adh_loop.c): load control at p
 * (RC__ADH_LOAD), the mean height held at max h - delta (RC__ADH_LEVEL;
 * the pressure found into *p) or, a periodic layer, its rigid substrate
 * held at approach delta (RC__ADH_SUBSTRATE: the mean mode on the spring
 * k_0, p = k_0 (<u> - max h + delta) found into *p). */
enum { RC__ADH_LOAD = 0, RC__ADH_LEVEL = 1, RC__ADH_SUBSTRATE = 2 };
int rc__fire_adh_solve(rc_solver *s, int control, double *p, double delta,
    rc_solve_result *res, rc_err *err);
/* What that loop runs on: the operator's grid of n points, of which
 * n_act interact (the rest: h = -inf); mass0 > 0 the mean mode's mass
 * when the rigid level is held (free boundaries: p = 0, the load the sum
 * of the tractions, which then scales the residual); else load
 * control's rule (solver_fire.c).  The loop: control 0, p on
 * every one of the n points; control 1, <u> held at target (periodic
 * only), p found; control 2 (periodic only), p = spring (<u> - target)
 * from the state, spring = k_0 > 0 of the layer (unused by the other
 * two).  Status as rc_solver_solve. */
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
int rc__adh_loop(const rc__adh_view *w, const struct rc_adhesion *law,
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
/* The hard wall of the pressure methods (solver_wall.c): the rigid level
 * c = <h - G sigma> over {sigma > 0} (returns its size); on free
 * boundaries the convergence measure and the admissible u' from s->u =
 * G sigma (leaves u', the contact set, level and energy).  The stiffness
 * scale of that measure (solver_operator.c). */
size_t rc__level(const rc_solver *s, double *c);
double rc__final_check_free(rc_solver *s, double p);
/* That measure, max(k_max rms(u' - u) / p, |<sigma> - p| / p), from the
 * sums over all points of (u' - u)^2, sigma and sigma u; sets the
 * elastic energy (1/2) <sigma u>.  Both CG variants and FIRE on
 * pressures (solver_wall.c). */
double rc__gap_measure(rc_solver *s, double p, double sum_d2, double sum_s,
    double sum_e);
double rc__stiffness_max(const rc_solver *s);
/* FIRE on pressures (solver_fire_free.c): free boundaries, and a
 * hardness on either boundary kind. */
int rc__fire_sigma_solve(rc_solver *s, double p, rc_solve_result *res,
    rc_err *err);
int rc__cg_alloc(rc_solver *s, rc_err *err);
/* The operator (solver_operator.c): out = G x; G_00 of the periodic
 * compliance.  The start pressure of mean p (unbounded) of both pressure
 * methods (solver_wall.c). */
void rc__compliance(rc_solver *s, const double *x, double *out);
double rc__self_compliance(const rc_elastic *e);
void rc__cg_initial_pressure(rc_solver *s, double p);
/* The stopping rule of the pressure methods (solver_measure.c: both CG
 * variants and FIRE on pressures), after iteration it
 * has its gap bound: STOP (the final check ran: *residual, and *status 0
 * if it met opts.tol), STALE (a periodic check of the residual itself
 * ran and missed: the iterate must be recomputed) or GO. */
enum { RC__CG_GO, RC__CG_STOP, RC__CG_STALE };
int rc__cg_next(rc_solver *s, double p, double bound, long it,
    double (*check)(rc_solver *, double), double *residual, int *status);
/* CG with the pressure bounded by opts.hardness (solver_cg_plastic.c). */
int rc__cg_plastic_solve(rc_solver *s, double p, rc_solve_result *res,
    rc_err *err);
/* The hardness cap (solver_hardness.c), shared by that CG and FIRE on
 * pressures with a hardness (solver_fire_free.c): the level c fitted over
 * 0 < sigma < H (returns the count of sigma > 0); the load restored to
 * mean p within [0, H] (disp: G sigma kept in step, or NULL; returns 1 if
 * G sigma is stale); the convergence measure of (u', sigma) from s->u =
 * G sigma (leaves u', the contact set, level and energy). */
size_t rc__plastic_level(const rc_solver *s, double *c);
int rc__plastic_restore_load(rc_solver *s, double p, double *disp);
double rc__plastic_check(rc_solver *s, double p);
/* The start of both: the CG's (rc__cg_initial_pressure) clipped at H,
 * the load restored. */
void rc__plastic_initial_pressure(rc_solver *s, double p);

/* Whether a point with pressure sigma and gap g takes part in a bounded
 * step: free (0 < sigma < H), or its force f = -g pointing into the box
 * (at zero and penetrating, or at H with an open gap). */
static inline int
rc__plastic_active(double sigma, double g, double H)
{
	return (sigma > 0 && sigma < H) || (sigma <= 0 && g < 0) ||
	    (sigma >= H && g > 0);
}

/* FIRE's parameters, shared by its three loops (solver_fire.c, which
 * says what each is and how it was tuned; solver_fire_free.c;
 * solver_fire_adh.c). */
#define RC_FIRE_DT_START	1.0
#define RC_FIRE_DT_MAX		2.0
#define RC_FIRE_N_MIN		1
#define RC_FIRE_F_INC		1.1
#define RC_FIRE_F_DEC		0.85
#define RC_FIRE_ALPHA_START	0.5
#define RC_FIRE_F_ALPHA		0.99
#define RC_FIRE_M0_SCALE	2.0
#define RC_FIRE_PROGRESS_EVERY	50

/* FIRE's schedule and mixing, written once for its loops (solver_fire.c
 * says what they are): after a step of power P, dt and alpha grow when
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

#endif
