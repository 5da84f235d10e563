/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_loop.c - the FIRE loop, written once for every operator
 * and interaction, in surface heights and on pressures (solver_fire_free.c
 * brings its operator, passes and step rules: see the end of this
 * comment).  In heights: FIRE-GFMD, mass-weighted damped
 * dynamics of the elastic surface heights u(r), relaxed with FIRE
 * (Bitzek et al. 2006, in the FIRE 2.0 ordering of Guenole et al. 2020:
 * mix after the velocity update), with Fourier masses m_q proportional to
 * the stiffness k_q as in Zhou, Moseler & Mueser (2019), so that every
 * free elastic mode has the same frequency.
 *
 * The parts (rc__fire_parts, solver_impl.h): the operator, an rc_elastic
 * (the periodic half space, the layer, the padded free grid of
 * solver_fire_adh_free.c), which applies K and the mass-weighting M^-1;
 * the interaction, three passes over ranges of points and a hook after
 * each: the hard wall (solver_fire.c) and the adhesive laws with load,
 * level or substrate control (solver_fire_adh_pass.c).  One iteration:
 *  1. f = -(p + K u): one FFT pair (lib/elastic/elastic.c).
 *  2. The force pass (the interaction): f_eff into f, the contact set C
 *     (points held by the wall, a = 0 there), the residual, the power
 *     P = f_eff . v and the mean mode's mass m_0 for this step.
 *  3. The mass-weighted force a = M^-1 f_eff = IFFT[FFT(f_eff) / m_q]:
 *     the second FFT pair.  m_q = k_q for q != 0 (frequency 1 for every
 *     mode); m_0 from the interaction (solver_fire.c says why it follows
 *     the contact).  a = 0 on C (the mixing and update passes): a contact
 *     point stays on the wall while its pressure is positive.
 *  4. FIRE: power P > 0: after N_MIN such steps in a row dt = min(dt
 *     F_INC, DT_MAX), alpha *= F_ALPHA.  P <= 0: v = 0, dt *= F_DEC,
 *     alpha = ALPHA_START (rc__fire_adapt).  Then v += dt a;  v = (1 -
 *     alpha) v + alpha (|v| / |a|) a (rc__fire_mix, from the mixing
 *     pass's sums |a|^2, a.v, |v|^2).
 *  5. The update pass: u += dt v; where u < h: u = h, v = 0.
 * At equilibrium f_eff = 0 everywhere, so a = 0 and the state is
 * stationary: the fixed point is the solution whatever the masses.
 *
 * Parameters (RC_FIRE_* in solver_impl.h; time in units of 1/omega,
 * omega = 1 the common mode frequency; tuned on 256^2, p* = 0.05,
 * H = 0.8, checked at 128^2 ... 1024^2 and p* 0.002 ... 0.5):
 *   DT_START    1.0   initial time step (each solve starts here)
 *   DT_MAX      2.0   largest time step (the stability limit of a
 *                     frequency-1 oscillator; reached only in free flight)
 *   N_MIN       1     positive-power steps before dt may grow
 *   F_INC       1.1   dt growth factor
 *   F_DEC       0.85  dt shrink factor on P <= 0 (then v = 0); 0.5, the
 *                     classic value, takes 1.6 times as many iterations,
 *                     1.0 never converges
 *   ALPHA_START 0.5   initial mixing, restored on P <= 0 (0.1: 2x the
 *                     iterations; all modes have one frequency, so
 *                     strong damping loses little)
 *   F_ALPHA     0.99  mixing decay per positive-power step past N_MIN
 *   M0_SCALE    2     mean-mode mass (solver_fire.c)
 *
 * Cost: two FFT pairs, two scalings of the spectrum and three O(N)
 * passes per iteration.  Measured at 512^2 on the plain path (perf
 * samples, one thread, the wall's solve at 10 pressures, 725
 * iterations): the passes 0.78 FFT pairs an iteration (the wall's force
 * 0.27, the mixing 0.20, the update 0.31; solver_fire.c says what they
 * read and what made them 0.96 before), the two scalings 0.15 before
 * rc_fft_multiply's loops were vectorised (0.12 measured with them); the
 * solve's seconds 2.47 to 2.61 against 2.68 to 2.78 before (8 alternating
 * runs each).  The update on 8 lanes (solver_fire_wide.c) then made
 * make bench's iter_in_pairs at 512^2 2.83 (2.83, 2.84; on 2 lanes 2.95,
 * 2.94, alternating runs, 9 rounds each, a quiet Xeon VM); at 1024^2 no
 * gain was measured (2.62 to 2.67 against 2.66 to 2.70: its loads of h
 * and u wait on memory).  make bench's iter_in_pairs on this VM moves by
 * up to 0.5 between runs, more than these gains: doc/performance.md
 * gives a run's median with its spread.  The passes are the
 * interaction's functions over ranges of points, called once per range
 * (never per point).  On the plain path a range is a chunk of
 * parts->grain points or, with grain 0, each thread's share of the grid
 * (the order in which each interaction summed before the loop was
 * shared; a sum's rounding depends on it).
 * From RC_FFT_BLOCKED_POINTS on the transforms are blocked (fft.h: rows,
 * then columns in blocks with the scaling while they are in cache, then
 * rows) and, for an interaction that allows it (parts->fuse), the passes
 * run on each block of rows between its row transforms: the c2r of K u,
 * the force pass and the r2c of f_eff; the c2r of a and the mixing sums;
 * the update and the r2c of the new u.  Below, the blocked path does not
 * pay (make bench, one thread, CPU time, FFT pairs per iteration, medians
 * of 8 runs with spec's rows padded, fft.h: blocked 3.46 against plain
 * 3.21 at 512^2; at 1024^2 blocked 2.50, plain 2.87).  The mass's scaling
 * uses a table of 1/(N m_q) made for each solve (mass_table: half a
 * double a point while it runs) instead of a division per mode.  Why not
 * one pair: step 3 needs f_eff, which needs K u of this step at the
 * contact points; tracking K u by linearity instead needs K of the sparse
 * wall corrections (a on C, the projection), again a full transform.
 *
 * On pressures (solver_fire_free.c says what and why): the same loop
 * with the operator's two callbacks, field (u = G sigma and the level;
 * f is then the force pass's own) and accelerate (a = K f, in place of
 * step 3), the interaction's own mixing pass (it zeroes a off the active
 * set and v on a restart, and sums what its step rules need), its
 * largest step in the report (the adapt's limit) and in the mixed hook
 * (it may lower dt), the load's restoration in the updated hook, and its
 * stopping rule (rc__cg_next) through next in place of the loop's.  No
 * mass table, no blocked path (fuse 0); ranges of one thread's share
 * (grain 0), the sums of the `parallel for' loops it had before.
 */
#include "solver_impl.h"

#include <math.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

/* The mass's multiplier c_q = 1/(N m_q) tabled for a solve: scale / k_q
 * where k_q > 0 (the quotient rc_fft_multiply forms, so the product is
 * the same bit for bit), applied as a multiplier of scale 1 (x * 1 = x);
 * the mean mode's entry, 1/(N m_0), is set every iteration.  This saves a
 * division per mode and iteration.  NULL (divide instead) if memory is
 * short, the operator distributed, or k_0 > 0 (the operator's own mean
 * stiffness is then the mean mode's mass) or another mode has k_q = 0. */
static double *
mass_table(rc_elastic *e, double inv_n, void **block)
{
	size_t nm = e->nxc * e->ny, m, bad = 0;
	const double *k = e->stiffness;
	double *q;

	*block = NULL;
	/* on huge pages from 1 MB (fft.h): at 1024^2 its 1026 page faults
	 * took 13 ms of each solve */
	if (e->dist != NULL ||
	    (q = rc_fft_huge(nm * sizeof(double), block)) == NULL)
		return NULL;
#pragma omp parallel for reduction(+:bad) schedule(static)
	for (m = 0; m < nm; m++) {
		q[m] = k[m] > 0 ? inv_n / k[m] : 0;
		bad += m > 0 && !(k[m] > 0);
	}
	if (bad > 0 || k[0] > 0) {
		rc_fft_huge_free(q, *block);
		*block = NULL;
		return NULL;
	}
	return q;
}

/* The operator's side of the loop: the transforms and where the fields
 * live. */
struct fire_op {
	const rc__fire_parts *pt;
	rc_elastic *e;
	int blocked;		/* the fused passes on the blocked transforms */
	double inv_n;
	double *table;		/* mass_table, or NULL */
	void *table_block;	/* the block it sits in (rc_fft_huge) */
	double *f;		/* the force: K u, then f_eff */
	rc_fft_multiplier stiff, mass;
};

/* The point range of this thread's share of n points: the partition of
 * OpenMP's static schedule (GCC's: the first n mod T threads take one
 * more), so that a pass keeps the sums of a `parallel for` over points.
 * A copy of libgomp's split on purpose: the interactions with grain 0
 * summed in a `parallel for ... schedule(static)' before the one loop,
 * and each thread's partial sum (hence its rounding, the rows' bits)
 * depends on where its share starts and ends. */
static void
thread_share(size_t n, size_t *k0, size_t *k1)
{
	size_t t = 0, nt = 1, q, r;

#ifdef _OPENMP
	t = (size_t)omp_get_thread_num();
	nt = (size_t)omp_get_num_threads();
#endif
	q = n / nt;
	r = n % nt;
	if (t < r) {
		r = 0;
		q++;
	}
	*k0 = q * t + r;
	*k1 = *k0 + q;
}

/* A pass on the plain path, in the interaction's ranges. */
static void
run_pass(const rc__fire_parts *pt, rc__fire_pass *pass, void *ctx,
    double *x, const rc__fire_step *st, double *sum, double *least)
{
	size_t n = pt->n, g = pt->grain, b, nb = g > 0 ? (n + g - 1) / g : 0;
	double s[RC__FIRE_SUMS] = { 0 }, lo = HUGE_VAL;

	if (g > 0) {
#pragma omp parallel for reduction(+:s[:RC__FIRE_SUMS]) reduction(min:lo) \
    schedule(static)
		for (b = 0; b < nb; b++)
			pass(ctx, x, st, b * g, b * g + g < n ? b * g + g : n, s,
			    &lo);
	} else {
#pragma omp parallel reduction(+:s[:RC__FIRE_SUMS]) reduction(min:lo)
		{
			size_t k0, k1;

			thread_share(n, &k0, &k1);
			pass(ctx, x, st, k0, k1, s, &lo);
		}
	}
	memcpy(sum, s, sizeof(s));
	*least = lo;
}

/* The mixing pass over k0 <= k < k1 (ctx: the parts), FIRE 2.0's
 * |v + dt a|^2 = |v|^2 + 2 dt a.v + dt^2 |a|^2 with a = 0 on C (the
 * clamp) and v = 0 on a restart: adds |a|^2, a.v and |v|^2 to sum[0..2],
 * with mean_sums the sums of a and v to sum[3..4].  Read only: the update
 * applies the clamp and the restart again, so a and v are not written
 * twice.  Without a restart or mean_sums (every step but restarts for
 * the wall and for adhesion under load) the products two points at a
 * time (rc__v2d: the mask of C in place of a branch), added one by one
 * in the points' order: the scalar loop's sums bit for bit, 10 to 15%
 * faster at 512^2. */
static void
mixing_range(void *ctx, double *a, const rc__fire_step *st, size_t k0,
    size_t k1, double *sum, double *least)
{
	const rc__fire_parts *pt = ctx;
	const unsigned char *contact = pt->contact;
	const double *v = pt->v;
	double aa = 0, av = 0, vv = 0, sa = 0, sv = 0;
	size_t k;

	(void)least;
	if (pt->mean_sums) {
		for (k = k0; k < k1; k++) {
			double ak = contact[k] ? 0 : a[k];
			double vk = st->restart ? 0 : v[k];

			aa += ak * ak;
			av += ak * vk;
			vv += vk * vk;
			sa += ak;
			sv += vk;
		}
	} else if (st->restart)
		for (k = k0; k < k1; k++) {
			double ak = contact[k] ? 0 : a[k];

			aa += ak * ak;
		}
	else {
		k = k0;
#ifdef RC__V2
		for (; k + 2 <= k1; k += 2) {
			rc__v2d ak, vk, p_aa, p_av, p_vv;
			rc__v2l held = rc__v2_held(contact + k);

			memcpy(&ak, a + k, sizeof(ak));
			memcpy(&vk, v + k, sizeof(vk));
			ak = (rc__v2d)((rc__v2l)ak & ~held);
			p_aa = ak * ak;
			p_av = ak * vk;
			p_vv = vk * vk;
			aa += p_aa[0];
			av += p_av[0];
			vv += p_vv[0];
			aa += p_aa[1];
			av += p_av[1];
			vv += p_vv[1];
		}
#endif
		for (; k < k1; k++) {
			double ak = contact[k] ? 0 : a[k];

			aa += ak * ak;
			av += ak * v[k];
			vv += v[k] * v[k];
		}
	}
	sum[0] += aa;
	sum[1] += av;
	sum[2] += vv;
	sum[3] += sa;
	sum[4] += sv;
}

/* Steps 1 and 2: f_eff into op->f; the pass's sums. */
static void
stage_force(struct fire_op *op, double *sum, double *least)
{
	const rc__fire_parts *pt = op->pt;
	rc_fft *f = &op->e->fft;
	size_t nb, nx = op->e->nx, b;
	double s[RC__FIRE_SUMS] = { 0 }, lo = HUGE_VAL;

	if (!op->blocked) {
		if (pt->field != NULL)
			op->f = pt->field(pt->ctx);
		else
			rc_elastic_force(op->e, pt->u, op->f);
		run_pass(pt, pt->force, pt->ctx, op->f, NULL, sum, least);
		return;
	}
	/* K u, then f_eff, then the r2c of f_eff, block by block */
	nb = rc_fft_row_blocks(f);
	rc_fft_columns(f, &op->stiff);
#pragma omp parallel for reduction(+:s[:RC__FIRE_SUMS]) reduction(min:lo) \
    schedule(static)
	for (b = 0; b < nb; b++) {
		size_t j0, j1;

		rc_fft_block_rows(f, b, &j0, &j1);
		rc_fft_rows_c2r(f, op->f, b);
		pt->force(pt->ctx, op->f, NULL, j0 * nx, j1 * nx, s, &lo);
		rc_fft_rows_r2c(f, op->f, b);
	}
	op->e->n_r2c++;
	op->e->n_c2r++;
	memcpy(sum, s, sizeof(s));
	*least = lo;
}

/* Step 3 and the mixing pass: a = M^-1 f_eff with the mean mode's mass
 * mass0 (returned: the operator's real buffer); the pass's sums. */
static double *
stage_weigh(struct fire_op *op, double mass0, const rc__fire_step *st,
    double *sum)
{
	const rc__fire_parts *pt = op->pt;
	rc_elastic *e = op->e;
	rc_fft *f = &e->fft;
	size_t nb, nx = e->nx, b;
	double s[RC__FIRE_SUMS] = { 0 }, lo = HUGE_VAL, *a = f->real;

	op->mass.at_zero = op->inv_n / mass0;
	if (op->table != NULL)
		op->table[0] = op->mass.at_zero;
	if (!op->blocked) {
		if (pt->accelerate != NULL)
			a = pt->accelerate(pt->ctx, op->f);
		else if (op->table != NULL)
			rc_elastic_convolve(e, op->f, a, &op->mass);
		else
			a = rc__fire_mass_weighted(e, op->f, mass0);
		if (pt->mixing != NULL)
			run_pass(pt, pt->mixing, pt->ctx, a, st, sum, &lo);
		else
			run_pass(pt, mixing_range, (void *)pt, a, st, sum,
			    &lo);
		return a;
	}
	/* the columns, then the c2r of a and the sums block by block */
	nb = rc_fft_row_blocks(f);
	rc_fft_columns(f, &op->mass);
	e->n_r2c++;
	e->n_c2r++;
#pragma omp parallel for reduction(+:s[:RC__FIRE_SUMS]) reduction(min:lo) \
    schedule(static)
	for (b = 0; b < nb; b++) {
		size_t j0, j1;

		rc_fft_block_rows(f, b, &j0, &j1);
		rc_fft_rows_c2r(f, a, b);
		mixing_range((void *)pt, a, st, j0 * nx, j1 * nx, s, &lo);
	}
	memcpy(sum, s, sizeof(s));
	return a;
}

/* Step 5, the update pass; blocked, the r2c of the new u for the next
 * K u on the way. */
static void
stage_update(struct fire_op *op, double *a, const rc__fire_step *st,
    double *sum)
{
	const rc__fire_parts *pt = op->pt;
	rc_fft *f = &op->e->fft;
	size_t nb, nx = op->e->nx, b;
	double s[RC__FIRE_SUMS] = { 0 }, lo = HUGE_VAL;

	if (!op->blocked) {
		run_pass(pt, pt->update, pt->ctx, a, st, sum, &lo);
		return;
	}
	nb = rc_fft_row_blocks(f);
#pragma omp parallel for reduction(+:s[:RC__FIRE_SUMS]) reduction(min:lo) \
    schedule(static)
	for (b = 0; b < nb; b++) {
		size_t j0, j1;

		rc_fft_block_rows(f, b, &j0, &j1);
		pt->update(pt->ctx, a, st, j0 * nx, j1 * nx, s, &lo);
		rc_fft_rows_r2c(f, pt->u, b);
	}
	memcpy(sum, s, sizeof(s));
}

int
rc__fire_run(const rc__fire_parts *pt, const rc_solver_opts *opts,
    rc__watch *watch, long *iterations, double *residual)
{
	rc_elastic *e = pt->el;
	rc_fft *f = &e->fft;
	struct fire_op op;
	rc__fire fs = RC__FIRE_START;
	rc__fire_step st = { 0, 0, 1, 0 };
	int status = 1;
	long it;
	size_t b;

	op.pt = pt;
	op.e = e;
	/* never a distributed operator (no blocked transforms there) */
	op.blocked = pt->fuse && rc_fft_conv_blocked(f);
	op.inv_n = 1.0 / (double)e->n;
	op.table_block = NULL;
	op.table = pt->accelerate != NULL ? NULL : mass_table(e, op.inv_n,
	    &op.table_block);
	/* plain, with the table: K u, f_eff and a one grid, the operator's
	 * real buffer (a separate force would be a fourth grid through the
	 * cache each iteration); blocked: the force in pt->f, a in the
	 * real buffer */
	op.f = op.table != NULL && !op.blocked ? f->real : pt->f;
	op.stiff = (rc_fft_multiplier){ e->stiffness, op.inv_n, 0, 0 };
	op.mass = op.table != NULL ?
	    (rc_fft_multiplier){ op.table, 1.0, 0, 0 } :
	    (rc_fft_multiplier){ e->stiffness, op.inv_n, 1, 0 };
	*residual = HUGE_VAL;
	if (op.blocked)
#pragma omp parallel for schedule(static)
		for (b = 0; b < rc_fft_row_blocks(f); b++)
			rc_fft_rows_r2c(f, pt->u, b);
	for (it = 0; ; it++) {
		double sum[RC__FIRE_SUMS], least, *a;
		rc__fire_report r = { .residual = HUGE_VAL, .power = 0,
		    .contact = 0, .mass0 = 1, .halt = 0,
		    .dt_max = RC_FIRE_DT_MAX };

		stage_force(&op, sum, &least);
		rc_elastic_sum(e, sum, RC__FIRE_SUMS);
		pt->forced(pt->ctx, sum, least, &r);
		if (pt->next != NULL) {
			int next = pt->next(pt->ctx, it, r.residual, residual,
			    &status);

			if (next == RC__CG_STOP)
				break;
			if (next == RC__CG_STALE)
				continue;
		} else {
			*residual = r.residual;
			if (r.residual <= opts->tol) {
				status = 0;
				break;
			}
			if (r.halt) {
				status = RC__FIRE_HALTED;
				break;
			}
			if (it >= opts->max_iter ||
			    (opts->stop && *opts->stop) ||
			    rc__watch_stalled(watch, opts->stall_window, it,
			    r.residual))
				break;
		}
		if (opts->progress && it % RC_FIRE_PROGRESS_EVERY == 0)
			opts->progress(opts->progress_ctx, it, r.residual,
			    r.contact / pt->points);
		st.restart = rc__fire_adapt(&fs, r.power, r.dt_max);
		st.dt = fs.dt;
		a = stage_weigh(&op, r.mass0, &st, sum);
		rc_elastic_sum(e, sum, RC__FIRE_SUMS);
		if (pt->mixed != NULL) {
			pt->mixed(pt->ctx, sum, &fs.dt);
			st.dt = fs.dt;
		}
		rc__fire_mix(&fs, sum[0], sum[1], sum[2], &st.mix_v, &st.mix_a);
		stage_update(&op, a, &st, sum);
		if (pt->updated != NULL) {
			rc_elastic_sum(e, sum, RC__FIRE_SUMS);
			pt->updated(pt->ctx, sum);
		}
	}
	rc_fft_huge_free(op.table, op.table_block);
	*iterations = it;
	return status;
}
