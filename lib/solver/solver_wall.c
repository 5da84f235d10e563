/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_wall.c - the hard wall (sigma >= 0) as an interaction of the
 * pressure methods (interaction.h): the start pressure, the rigid level
 * c = <h - G sigma> over the contact set, and the load restored by one
 * scale.  Its pointwise rules are interaction.h's with H = +inf.
 */
#include "solver_impl.h"

#include <math.h>

/* Rigid level c = <h - G sigma> over I_c = {sigma > 0}; returns |I_c|. */
static size_t
wall_level(const rc_solver *s, double *c)
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

/* Mean p by one scale of sigma (and of G sigma, which stays in step). */
static int
wall_restore_load(rc_solver *s, double p, double sum, double *disp)
{
	size_t k, n = s->n;
	double f, *sigma = s->sigma;

	if (!(sum > 0))
		return 0;
	f = p * (double)n / sum;
#pragma omp parallel for schedule(static)
	for (k = 0; k < n; k++) {
		sigma[k] *= f;
		if (disp)
			disp[k] *= f;
	}
	return 0;
}

/* Initial pressure: the previous solution rescaled, the pressure a loaded
 * displacement implies, or uniform. */
void
rc__wall_start(rc_solver *s, double p)
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

/* The CG runs Polonsky & Keer's rules with re-entry (solver_cg.c). */
void
rc__wall(const rc_solver *s, rc__interaction *in)
{
	(void)s;
	*in = (rc__interaction){ .H = HUGE_VAL, .start = rc__wall_start,
	    .level = wall_level, .restore_load = wall_restore_load,
	    .max_move = HUGE_VAL,
	    .plastic_fraction = NULL, .cg_reentry = 1 };
}
