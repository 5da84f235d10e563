/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire.c - FIRE-GFMD: mass-weighted damped dynamics of the elastic
 * surface heights u(r) against a hard wall, relaxed with FIRE (Bitzek et al. 2006,
 * in the FIRE 2.0 ordering of Guenole et al. 2020: mix after the velocity
 * update), with Fourier masses m_q proportional to the stiffness k_q as in
 * Zhou, Moseler & Mueser (2019), so that every free elastic mode has the
 * same frequency.
 *
 * Positions u and velocities v live in real space, so the wall and the
 * velocity projection are local and exact (u >= h bit for bit).  One
 * iteration:
 *  1. f = -(p + K u): one FFT pair (lib/elastic/elastic.c).
 *  2. The wall: at a point on it (u = h) where f pushes into it (f < 0)
 *     the wall takes the force up, f_eff = 0, and the point is in contact
 *     (set C); elsewhere f_eff = f.  The residual (solver_measure.c)
 *     falls out of this pass, so convergence is checked every iteration
 *     for free.
 *  3. The mass-weighted force a = M^-1 f_eff = IFFT[FFT(f_eff) / m_q]:
 *     the second FFT pair.  m_q = k_q for q != 0 (frequency 1 for every
 *     mode); m_0 (the mean height) see below.  Then a = 0 on C: a contact
 *     point stays on the wall while its pressure is positive.  Without
 *     this the non-local a lifts contact points off the wall and the next
 *     step pushes them back; measured: no convergence in 20000 steps.
 *     With it the step is the preconditioner restricted to the free
 *     points, P_F M^-1 P_F f, whose power f.a > 0 (a principal submatrix of
 *     a positive definite matrix), so it always points downhill.
 *  4. FIRE: power P = f_eff . v (the true power).  P > 0: after N_MIN such
 *     steps in a row dt = min(dt F_INC, DT_MAX), alpha *= F_ALPHA.
 *     P <= 0: v = 0, dt *= F_DEC, alpha = ALPHA_START.  Then
 *     v += dt a;  v = (1 - alpha) v + alpha (|v| / |a|) a  (Euclidean
 *     norms; cheap, and with m_q ~ k_q |a| is the displacement error, not
 *     a stiffness-weighted force).
 *  5. u += dt v; where u < h: u = h, v = 0.
 * At equilibrium f_eff = 0 everywhere, so a = 0 and the state is
 * stationary: the fixed point is the contact solution whatever the masses.
 *
 * Mean-mode mass m_0.  The mean height is held only by the contact, whose
 * stiffness (load per mean height) grows with the contact.  A single
 * patch of area a_r L^2 in a half space has stiffness ~ E* sqrt(a_r) L per
 * cell, i.e. ~ k_min sqrt(a_r) per area (k_min = pi E* / L, the softest
 * mode, L the longer side).  So m_0 = M0_SCALE k_min sqrt(max(n_c, 1) / N),
 * updated every step from the current contact count (it changes the
 * rate, not the fixed point).  Measured (H = 0.3 and 0.8): a fixed
 * m_0 = k_min takes 33 ... 113 iterations at 256^2 for p* = 0.002 ... 0.5,
 * the most at small p* (1159 with m_0 = 10 k_min); the adaptive m_0 with
 * M0_SCALE = 2 takes 31 ... 64 at 128^2 and 512^2 for p* = 0.002 ... 0.2.
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
 *   M0_SCALE    2     mean-mode mass (above)
 * Cost: two FFT pairs, two scalings of the spectrum and three O(N) passes
 * per iteration (the wall, the mixing sums, which only read, and the
 * update, which applies the clamp).  From RC_FFT_BLOCKED_POINTS on the
 * transforms are blocked (fft.h: rows, then columns in blocks with the
 * scaling while they are in cache, then rows) and the three passes run
 * on each block of rows between its row transforms (fire_blocked): the
 * c2r of K u, the wall and the r2c of f_eff; the c2r of a and the mixing
 * sums; the update and the r2c of the new u.  Below, the blocked path
 * does not pay (make bench, one thread, CPU time, in FFT pairs per
 * iteration: 3.83 against 3.30 at 256^2, 3.02 against 3.05 at 512^2).
 * The mass's scaling uses a table of 1/(N m_q) made for each solve
 * (mass_table: half a double a point while it runs) instead of a
 * division per mode.  The iteration
 * count at tol 1e-6 is nearly independent of N (256^2: 43, 512^2: 41,
 * 1024^2: 38 at p* = 0.05; the uniform real-space mass this replaces took
 * 262, 299, 467 with one pair each, growing like sqrt(n)).  Why not one
 * pair: step 3 needs f_eff, which needs K u of this step at the contact
 * points; tracking K u by linearity instead needs K of the sparse wall
 * corrections (a on C, the projection), again a full transform.
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
 * and every sum over points is completed through rc_elastic_sum. */
#define POINTS(s)	rc__points(s)

#define CHUNK		8192	/* points per step of a threaded pass */

int
rc__fire_alloc(rc_solver *s, rc_err *err)
{
	s->u = fftw_alloc_real(s->n);
	s->fire_vel = fftw_alloc_real(s->n);
	if (s->u == NULL || s->fire_vel == NULL)
		return rc_seterr(err, "out of memory (asked for %zu bytes of FIRE buffers)",
		    2 * s->n * sizeof(double));
	return 0;
}

/* Step 2 on the points k0 <= k < k1 of f, which holds K u: f_eff into f
 * and the contact set; adds the squared force off the wall, the pressure
 * on it, the contact count and the power f_eff . v to sums[0..3]. */
static void
wall_range(rc_solver *s, double *f, double p, size_t k0, size_t k1,
    double *sums)
{
	size_t k;
	double sum_d2 = 0, sum_s = 0, on = 0, pw = 0;
	const double *u = s->u, *h = s->height, *v = s->fire_vel;
	unsigned char *contact = s->contact;

	for (k = k0; k < k1; k++) {
		double implied = p + f[k];

		if (u[k] == h[k] && implied > 0) {
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
	sums[0] += sum_d2;
	sums[1] += sum_s;
	sums[2] += on;
	sums[3] += pw;
}

/* The residual from wall_range's sums, completed over the ranks; the
 * contact count and the power. */
static double
wall_result(rc_solver *s, double p, double *sums, size_t *n_contact,
    double *power)
{
	rc_elastic_sum(&s->el, sums, 4);
	*n_contact = (size_t)sums[2];
	*power = sums[3];
	return rc__residual(s, p, sums[0], sums[1]);
}

/* Steps 1 and 2 over the grid: f_eff into f (s->sigma, or the
 * operator's real buffer) and the contact set; returns the residual of
 * this state, the number of contact points and the power f_eff . v. */
static double
wall_force(rc_solver *s, double *f, double p, size_t *n_contact,
    double *power)
{
	size_t b, nb = (s->n + CHUNK - 1) / CHUNK;
	double sums[4] = { 0, 0, 0, 0 };

	rc_elastic_force(&s->el, s->u, f);
#pragma omp parallel for reduction(+:sums[:4]) schedule(static)
	for (b = 0; b < nb; b++)
		wall_range(s, f, p, b * CHUNK, b * CHUNK + CHUNK < s->n ?
		    b * CHUNK + CHUNK : s->n, sums);
	return wall_result(s, p, sums, n_contact, power);
}


/* sigma on the contact set wall_force found; returns the elastic energy
 * per area (1/2) <u K u>. */
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

/* The FIRE parameters of one step, set from the power of the state. */
struct fire_step {
	rc__fire f;		/* dt, alpha, the positive steps in a row */
	int restart;		/* this step: P <= 0, so v = 0 */
	double mix_v, mix_a;	/* v = mix_v (v + dt a) + mix_a a */
};

/* Step 4's schedule: dt and alpha from the sign of the power. */
static void
fire_schedule(struct fire_step *st, double power)
{
	st->restart = rc__fire_adapt(&st->f, power, RC_FIRE_DT_MAX);
}

/* The sums for the FIRE 2.0 mixing over k0 <= k < k1, |v + dt a|^2 =
 * |v|^2 + 2 dt a.v + dt^2 |a|^2, with a = 0 on C (the clamp) and v = 0 on
 * a restart: adds |a|^2, a.v and |v|^2 to sums[0..2].  Read only: the
 * update applies the clamp and the restart again, so a and v are not
 * written twice. */
static void
mixing_range(const rc_solver *s, const double *a, int restart, size_t k0,
    size_t k1, double *sums)
{
	const unsigned char *contact = s->contact;
	const double *v = s->fire_vel;
	double aa = 0, av = 0, vv = 0;
	size_t k;

	if (restart)
		for (k = k0; k < k1; k++) {
			double ak = contact[k] ? 0 : a[k];

			aa += ak * ak;
		}
	else
		for (k = k0; k < k1; k++) {
			double ak = contact[k] ? 0 : a[k];

			aa += ak * ak;
			av += ak * v[k];
			vv += v[k] * v[k];
		}
	sums[0] += aa;
	sums[1] += av;
	sums[2] += vv;
}

/* The mixing coefficients from mixing_range's sums, completed over the
 * ranks. */
static void
fire_mixing(const rc_solver *s, struct fire_step *st, double *sums)
{
	rc_elastic_sum(&s->el, sums, 3);
	rc__fire_mix(&st->f, sums[0], sums[1], sums[2], &st->mix_v, &st->mix_a);
}

/* Steps 4 and 5 on k0 <= k < k1: the velocity and the clamped position. */
static void
update_range(rc_solver *s, const double *a, const struct fire_step *st,
    size_t k0, size_t k1)
{
	const unsigned char *contact = s->contact;
	const double *h = s->height;
	double *u = s->u, *v = s->fire_vel;
	double dt = st->f.dt, mix_v = st->mix_v, mix_a = st->mix_a;
	int restart = st->restart;
	size_t k;

	for (k = k0; k < k1; k++) {
		double ak = contact[k] ? 0 : a[k], vk = restart ? 0 : v[k];
		double uk;

		vk = mix_v * (vk + dt * ak) + mix_a * ak;
		uk = u[k] + dt * vk;

		if (uk <= h[k]) {
			uk = h[k];
			vk = 0;
		}
		u[k] = uk;
		v[k] = vk;
	}
}

/* The start: u = max h unless a state was loaded, u >= h, v = 0. */
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
	}
}

/* Once per step: 1 if the solve ends here (converged: status 0, or out
 * of iterations or stopped); the progress report. */
static int
fire_done(rc_solver *s, long it, double residual, size_t n_contact,
    int *status)
{
	if (residual <= s->opts.tol) {
		*status = 0;
		return 1;
	}
	if (it >= s->opts.max_iter || (s->opts.stop && *s->opts.stop) ||
	    rc__watch_stalled(&s->watch, s->opts.stall_window, it, residual))
		return 1;
	if (s->opts.progress && it % RC_FIRE_PROGRESS_EVERY == 0)
		s->opts.progress(s->opts.progress_ctx, it, residual,
		    (double)n_contact / POINTS(s));
	return 0;
}

static double
mass0_of(const rc_solver *s, size_t n_contact)
{
	return RC_FIRE_M0_SCALE * s->el.k_min *
	    sqrt((double)(n_contact > 0 ? n_contact : 1) / POINTS(s));
}

/* The mass's multiplier c_q = 1/(N m_q) tabled for a solve: scale / k_q
 * where k_q > 0 (the quotient rc_fft_multiply forms, so the product is
 * the same bit for bit), applied as a multiplier of scale 1 (x * 1 = x);
 * the mean mode's entry, 1/(N m_0), is set every iteration.  This saves a
 * division per mode and iteration.  NULL (divide instead) if memory is
 * short, the operator distributed, or another mode has k_q = 0. */
static double *
mass_table(rc_elastic *e, double inv_n)
{
	size_t nm = e->nxc * e->ny, m, bad = 0;
	const double *k = e->stiffness;
	double *q;

	if (e->dist != NULL || (q = fftw_alloc_real(nm)) == NULL)
		return NULL;
#pragma omp parallel for reduction(+:bad) schedule(static)
	for (m = 0; m < nm; m++) {
		q[m] = k[m] > 0 ? inv_n / k[m] : 0;
		bad += m > 0 && !(k[m] > 0);
	}
	if (bad > 0 || k[0] > 0) {
		fftw_free(q);
		return NULL;
	}
	return q;
}

/* The iterations on a grid whose transforms take the blocked path
 * (fft.h): the passes of steps 2, 3 and 5 run on each block of rows
 * between its row transforms, while it is in cache, instead of as
 * passes of their own over the grid.  The same arithmetic as the
 * plain loop below, point by point. */
static long
fire_blocked(rc_solver *s, double p, double *residual, int *status)
{
	rc_elastic *e = &s->el;
	rc_fft *f = &e->fft;
	size_t nb = rc_fft_row_blocks(f), nx = e->nx, n_contact, b;
	double *a = f->real, inv_n = 1.0 / (double)e->n;
	struct fire_step st = { RC__FIRE_START, 0, 1, 0 };
	rc_fft_multiplier stiff = { e->stiffness, inv_n, 0, 0 };
	rc_fft_multiplier mass = { e->stiffness, inv_n, 1, 0 };
	double *table = mass_table(e, inv_n);
	long it;

	if (table != NULL) {
		mass.k = table;
		mass.scale = 1.0;
		mass.inverse = 0;
	}

#pragma omp parallel for schedule(static)
	for (b = 0; b < nb; b++)
		rc_fft_rows_r2c(f, s->u, b);
	for (it = 0; ; it++) {
		double sums[4] = { 0, 0, 0, 0 }, power;

		/* K u, then f_eff, then the r2c of f_eff, block by block. */
		rc_fft_columns(f, &stiff);
#pragma omp parallel for reduction(+:sums[:4]) schedule(static)
		for (b = 0; b < nb; b++) {
			size_t j0, j1;

			rc_fft_block_rows(f, b, &j0, &j1);
			rc_fft_rows_c2r(f, s->sigma, b);
			wall_range(s, s->sigma, p, j0 * nx, j1 * nx, sums);
			rc_fft_rows_r2c(f, s->sigma, b);
		}
		e->n_r2c++;
		e->n_c2r++;
		*residual = wall_result(s, p, sums, &n_contact, &power);
		if (fire_done(s, it, *residual, n_contact, status))
			break;
		/* a = M^-1 f_eff and the mixing sums, block by block. */
		mass.at_zero = inv_n / mass0_of(s, n_contact);
		if (table != NULL)
			table[0] = mass.at_zero;
		rc_fft_columns(f, &mass);
		e->n_r2c++;
		e->n_c2r++;
		fire_schedule(&st, power);
		sums[0] = sums[1] = sums[2] = 0;
#pragma omp parallel for reduction(+:sums[:3]) schedule(static)
		for (b = 0; b < nb; b++) {
			size_t j0, j1;

			rc_fft_block_rows(f, b, &j0, &j1);
			rc_fft_rows_c2r(f, a, b);
			mixing_range(s, a, st.restart, j0 * nx, j1 * nx, sums);
		}
		fire_mixing(s, &st, sums);
		/* The update, then the r2c of the new u for the next K u. */
#pragma omp parallel for schedule(static)
		for (b = 0; b < nb; b++) {
			size_t j0, j1;

			rc_fft_block_rows(f, b, &j0, &j1);
			update_range(s, a, &st, j0 * nx, j1 * nx);
			rc_fft_rows_r2c(f, s->u, b);
		}
	}
	fftw_free(table);
	return it;
}

/* The iterations with whole-grid transforms and passes.  With the mass
 * table (one process) the force stays in the operator's real buffer,
 * where a follows it: K u, f_eff and a are one grid, not s->sigma as
 * well, which would be a fourth grid through the cache each iteration. */
static long
fire_plain(rc_solver *s, double p, double *residual, int *status)
{
	rc_elastic *e = &s->el;
	size_t n = s->n, nb = (n + CHUNK - 1) / CHUNK, n_contact, b;
	struct fire_step st = { RC__FIRE_START, 0, 1, 0 };
	double inv_n = 1.0 / (double)e->n, *table = mass_table(e, inv_n);
	double *force = table != NULL ? e->fft.real : s->sigma;
	rc_fft_multiplier tabled = { table, 1.0, 0, 0 };
	long it;

	for (it = 0; ; it++) {
		double power, sums[3] = { 0, 0, 0 }, *a;

		*residual = wall_force(s, force, p, &n_contact, &power);
		if (fire_done(s, it, *residual, n_contact, status))
			break;
		if (table != NULL) {
			table[0] = inv_n / mass0_of(s, n_contact);
			a = e->fft.real;
			rc_elastic_convolve(e, force, a, &tabled);
		} else
			a = rc__fire_mass_weighted(e, s->sigma,
			    mass0_of(s, n_contact));
		fire_schedule(&st, power);
#pragma omp parallel for reduction(+:sums[:3]) schedule(static)
		for (b = 0; b < nb; b++)
			mixing_range(s, a, st.restart, b * CHUNK,
			    b * CHUNK + CHUNK < n ? b * CHUNK + CHUNK : n, sums);
		fire_mixing(s, &st, sums);
#pragma omp parallel for schedule(static)
		for (b = 0; b < nb; b++)
			update_range(s, a, &st, b * CHUNK,
			    b * CHUNK + CHUNK < n ? b * CHUNK + CHUNK : n);
	}
	fftw_free(table);
	return it;
}

int
rc__fire_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	double residual = HUGE_VAL;
	int status = 1;
	long it;

	(void)err;
	fire_start(s);
	if (rc_fft_conv_blocked(&s->el.fft))	/* never a distributed one */
		it = fire_blocked(s, p, &residual, &status);
	else
		it = fire_plain(s, p, &residual, &status);
	s->energy = contact_pressure(s, p);
	res->iterations = it;
	res->residual = residual;
	return status;
}
