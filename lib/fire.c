/* fire.c - FIRE-GFMD: damped dynamics of the elastic surface heights
 * u(r) against a hard wall, relaxed with FIRE (Bitzek et al. 2006; the
 * FIRE 2.0 ordering of Guenole et al. 2020: mix after the velocity update).
 *
 * One iteration: K u by one FFT pair (lib/elastic.c), the force
 * f = -(p + K u) on every point; on the wall (u = h) a force pushing into
 * it is taken up by the wall (f = 0, the point is in contact); FIRE's power
 * P = f.v decides the step; v += dt f/m, v <- (1 - alpha) v +
 * alpha |v| f/|f|; u += dt v; points that reach the wall stop there
 * (u = h, v = 0).  Every quantity lives in real space, so the wall is exact
 * (u >= h bit for bit) and the fixed point is the equilibrium.
 *
 * Why not Fourier-space masses m_q ~ k_q (Zhou, Moseler & Mueser 2019)?
 * Tried first: with the hard wall applied by projection after the
 * c2r, the preconditioned step a_q = F_q / m_q is non-local, spreads the
 * wall's reaction over free points, and the iteration has no fixed point
 * at the equilibrium (or, with the wall force removed before the
 * preconditioning, the contact set flips every step and dt collapses);
 * doing it right needs a second FFT pair per iteration.  The real-space
 * variant costs one pair; its iteration count grows like
 * sqrt(k_max / k_min) ~ sqrt(n) (see bench/bench_gfmd.c for the figures).
 *
 * Parameters (fixed, in units where the stiffest mode has frequency 1:
 * the mass is m = k_max, so semi-implicit Euler is stable for dt < 2):
 *   DT_START    0.1   initial time step (each solve starts here)
 *   DT_MAX      1.0   largest time step
 *   N_MIN       5     positive-power steps before dt may grow
 *   F_INC       1.1   dt growth factor
 *   F_DEC       0.5   dt shrink factor on P <= 0 (then v = 0)
 *   ALPHA_START 0.1   initial mixing, restored on P <= 0
 *   F_ALPHA     0.99  mixing decay per positive-power step past N_MIN
 * The residual (solver.c) falls out of the force pass at no cost, so it is
 * checked every iteration.  Start: u = max h (a flat body touching the
 * highest point) unless a displacement is loaded or a previous solve left
 * one (warm start).
 */
#include "solver_impl.h"

#include <math.h>
#include <string.h>

#define DT_START	0.1
#define DT_MAX		1.0
#define N_MIN		5
#define F_INC		1.1
#define F_DEC		0.5
#define ALPHA_START	0.1
#define F_ALPHA		0.99
#define PROGRESS_EVERY	50

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

/* The force on every point, with the wall, into s->sigma: K u by one FFT
 * pair, f = -(p + K u); on the wall (u = h) where f pushes into it the
 * wall takes it up, f = 0, and the point is in contact with pressure
 * p + K u.  Returns the residual (solver.c) of this state and the FIRE
 * sums: power F.v, |v|^2, |F|^2. */
static double
wall_force(rc_solver *s, double p, size_t *n_contact, double *power,
    double *vv, double *ff)
{
	rc_elastic *e = &s->el;
	size_t k, n = s->n, on = 0;
	double sum_d2 = 0, sum_s = 0;
	double pw = 0, v2 = 0, f2 = 0;
	const double *u = s->u, *h = s->height, *v = s->fire_vel;
	double *f = s->sigma;
	unsigned char *contact = s->contact;

	rc_elastic_force(e, u, f);
#pragma omp parallel for reduction(+:sum_d2, sum_s, on, pw, v2, f2) schedule(static)
	for (k = 0; k < n; k++) {
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
		v2 += v[k] * v[k];
		f2 += f[k] * f[k];
	}
	*n_contact = on;
	*power = pw;
	*vv = v2;
	*ff = f2;
	return rc__residual(s, p, sum_d2, sum_s);
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
	return 0.5 * sum / (double)s->n;
}

int
rc__fire_solve(rc_solver *s, double p, rc_solve_result *res, rc_err *err)
{
	size_t n = s->n, k, n_contact = 0;
	double inv_mass = 1.0 / s->el.k_max;
	double dt = DT_START, alpha = ALPHA_START, residual = HUGE_VAL;
	double *u = s->u, *v = s->fire_vel, *f = s->sigma;
	const double *h = s->height;
	long it, npos = 0;
	int status = 1;

	(void)err;
	if (!s->have_u) {
		double top = -HUGE_VAL;

		for (k = 0; k < n; k++)
			if (h[k] > top)
				top = h[k];
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
	for (it = 0; ; it++) {
		double power, vv, ff, mix_v, mix_f;

		residual = wall_force(s, p, &n_contact, &power, &vv, &ff);
		if (residual <= s->opts.tol) {
			status = 0;
			break;
		}
		if (it >= s->opts.max_iter || (s->opts.stop && *s->opts.stop))
			break;
		if (s->opts.progress && it % PROGRESS_EVERY == 0)
			s->opts.progress(s->opts.progress_ctx, it, residual,
			    (double)n_contact / (double)n);
		mix_v = 1;
		mix_f = 0;
		if (power > 0) {
			if (++npos > N_MIN) {
				dt = fmin(dt * F_INC, DT_MAX);
				alpha *= F_ALPHA;
			}
			/* FIRE 2.0 order: mix after v += dt a, with |v| after
			 * the update: |v + dt a|^2 = |v|^2 + 2 dt a.v + dt^2 |a|^2. */
			if (ff > 0) {
				double vn2 = vv + 2 * dt * inv_mass * power +
				    dt * dt * inv_mass * inv_mass * ff;

				mix_v = 1 - alpha;
				mix_f = alpha * sqrt(vn2 / ff);
			}
		} else {
			npos = 0;
			dt *= F_DEC;
			alpha = ALPHA_START;
			/* v = 0, then v = dt a below */
			for (k = 0; k < n; k++)
				v[k] = 0;
		}
#pragma omp parallel for schedule(static)
		for (k = 0; k < n; k++) {
			double vk = mix_v * (v[k] + dt * inv_mass * f[k]) + mix_f * f[k];
			double uk = u[k] + dt * vk;

			if (uk <= h[k]) {
				uk = h[k];
				vk = 0;
			}
			u[k] = uk;
			v[k] = vk;
		}
	}
	s->energy = contact_pressure(s, p);
	res->iterations = it;
	res->residual = residual;
	return status;
}
