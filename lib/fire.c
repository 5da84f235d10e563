/* fire.c - FIRE-GFMD (experimental header, rewritten below when tuned). */
#include "solver_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>

#define PROGRESS_EVERY	50

static double
knob(const char *name, double def)
{
	const char *s = getenv(name);

	return s ? atof(s) : def;
}

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

static double
wall_force(rc_solver *s, double p, size_t *n_contact, double *power)
{
	rc_elastic *e = &s->el;
	size_t k, n = s->n, on = 0;
	double sum_d2 = 0, sum_s = 0, pw = 0;
	const double *u = s->u, *h = s->height, *v = s->fire_vel;
	double *f = s->sigma;
	unsigned char *contact = s->contact;

	rc_elastic_force(e, u, f);
#pragma omp parallel for reduction(+:sum_d2, sum_s, on, pw) schedule(static)
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
	}
	*n_contact = on;
	*power = pw;
	return rc__residual(s, p, sum_d2, sum_s);
}

/* a = M^-1 f into fft.real */
static void
precondition(rc_solver *s, double inv_m0)
{
	rc_elastic *e = &s->el;
	size_t m, nm = e->nxc * e->ny;
	double inv_n = 1.0 / (double)e->n;
	fftw_complex *spec = e->fft.spec;
	const double *k = e->stiffness;

	rc_elastic_r2c(e, s->sigma, spec);
#pragma omp parallel for schedule(static)
	for (m = 0; m < nm; m++)
		spec[m] *= (k[m] > 0 ? 1.0 / k[m] : inv_m0) * inv_n;
	rc_elastic_c2r(e, spec, e->fft.real);
}

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
	double dt_start = knob("FIRE_DT0", 1.0), dt_max = knob("FIRE_DTMAX", 2.0);
	double n_min = knob("FIRE_NMIN", 1), f_inc = knob("FIRE_FINC", 1.1);
	double f_dec = knob("FIRE_FDEC", 0.85), alpha_start = knob("FIRE_A0", 0.5);
	double f_alpha = knob("FIRE_FA", 0.99);
	double m0 = knob("FIRE_M0", 1.0) * s->el.k_min;
	int clamp = (int)knob("FIRE_CLAMP", 1);
	double dt = dt_start, alpha = alpha_start, residual = HUGE_VAL;
	double *u = s->u, *v = s->fire_vel, *a = s->el.fft.real;
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
		double power, aa = 0, av = 0, vv = 0, mix_v, mix_a;

		residual = wall_force(s, p, &n_contact, &power);
		if (residual <= s->opts.tol) {
			status = 0;
			break;
		}
		if (it >= s->opts.max_iter || (s->opts.stop && *s->opts.stop))
			break;
		if (s->opts.progress && it % PROGRESS_EVERY == 0)
			s->opts.progress(s->opts.progress_ctx, it, residual,
			    (double)n_contact / (double)n);
		if (knob("FIRE_ADAPT", 0) > 0)
			m0 = knob("FIRE_ADAPT", 0) * s->el.k_min * sqrt(fmax((double)n_contact, knob("FIRE_FLOOR", 1)) / (double)n);
		precondition(s, 1.0 / m0);
		if (getenv("FIRE_DBG"))
			fprintf(stderr, "it %ld res %.3e dt %.3f alpha %.3f P %+.2e nc %zu\n", it, residual, dt, alpha, power, n_contact);
		if (power > 0) {
			if (++npos > n_min) {
				dt = fmin(dt * f_inc, dt_max);
				alpha *= f_alpha;
			}
		} else {
			npos = 0;
			dt *= f_dec;
			alpha = alpha_start;
			for (k = 0; k < n; k++)
				v[k] = 0;
		}
#pragma omp parallel for reduction(+:aa, av, vv) schedule(static)
		for (k = 0; k < n; k++) {
			if (clamp && s->contact[k])
				a[k] = 0;
			aa += a[k] * a[k];
			av += a[k] * v[k];
			vv += v[k] * v[k];
		}
		mix_v = 1;
		mix_a = 0;
		if (aa > 0) {
			double vn2 = vv + 2 * dt * av + dt * dt * aa;

			mix_v = 1 - alpha;
			mix_a = alpha * sqrt(vn2 / aa);
		}
#pragma omp parallel for schedule(static)
		for (k = 0; k < n; k++) {
			double vk = mix_v * (v[k] + dt * a[k]) + mix_a * a[k];
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
