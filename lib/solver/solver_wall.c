/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_wall.c - the hard wall as the pressure methods (CG,
 * solver_cg.c; FIRE on pressures, solver_fire_free.c) see it: the rigid
 * level c = <h - G sigma> over the contact set, the admissible heights
 * u' (h on contact, max(G sigma + c, h) off it) and their gap measure
 * max(k_max rms(u' - u) / p, |<sigma> - p| / p) (solver_cg.c says why it
 * bounds the residual), the check on free boundaries, and the start
 * pressure.
 */
#include "solver_impl.h"

#include <math.h>

/* Rigid level c = <h - G sigma> over I_c; returns |I_c|. */
size_t
rc__level(const rc_solver *s, double *c)
{
	size_t k, on = 0;
	double sum = 0;
	const double *sigma = s->sigma, *disp = s->u, *h = s->height;

#pragma omp parallel for reduction(+:sum, on) schedule(static)
	for (k = 0; k < s->n; k++)
		if (sigma[k] > 0) {
			sum += h[k] - disp[k];
			on++;
		}
	*c = on ? sum / (double)on : 0;
	return on;
}

/* Free boundaries: the measure of the top of this file for (u', sigma);
 * leaves u' in s->u, the contact set, the level c and the elastic energy
 * (1/2) <sigma w>.  s->u holds w = G sigma on entry. */
double
rc__final_check_free(rc_solver *s, double p)
{
	size_t k, n = s->n;
	double c, sum_d2 = 0, sum_s = 0, sum_e = 0;
	double *u = s->u;
	const double *h = s->height, *sigma = s->sigma;

	rc__level(s, &c);
	s->level = c;
#pragma omp parallel for reduction(+:sum_d2, sum_s, sum_e) schedule(static)
	for (k = 0; k < n; k++) {
		double v = u[k] + c, up = sigma[k] > 0 ? h[k] : (v > h[k] ? v : h[k]);

		s->contact[k] = sigma[k] > 0;
		sum_d2 += (up - v) * (up - v);
		sum_s += sigma[k];
		sum_e += sigma[k] * u[k];
		u[k] = up;
	}
	return rc__gap_measure(s, p, sum_d2, sum_s, sum_e);
}

double
rc__gap_measure(rc_solver *s, double p, double sum_d2, double sum_s,
    double sum_e)
{
	double n = (double)s->n, force, load;

	s->energy = 0.5 * sum_e / n;
	force = rc__stiffness_max(s) * sqrt(sum_d2 / n) / p;
	load = fabs(sum_s / n - p) / p;
	return force > load ? force : load;
}

/* Initial pressure: the previous solution rescaled, the pressure a loaded
 * displacement implies, or uniform. */
void
rc__cg_initial_pressure(rc_solver *s, double p)
{
	size_t k, n = s->n;
	double *sigma = s->sigma;

	if (!s->have_sigma && s->have_u && s->free_bc) {
		/* No K to find the pressure u needs: start uniform on the
		 * points u touches. */
		for (k = 0; k < n; k++)
			sigma[k] = s->u[k] <= s->height[k] ? p : 0;
	} else if (!s->have_sigma && s->have_u) {
		double *ku = s->el.fft.real;

		rc_elastic_force(&s->el, s->u, ku);
		for (k = 0; k < n; k++) {
			double v = p + ku[k];

			sigma[k] = s->u[k] <= s->height[k] && v > 0 ? v : 0;
		}
	}
	rc__sigma_to_load(s, p);
}
