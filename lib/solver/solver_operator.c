/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_operator.c - the elastic operator as the minimisers use it:
 * G sigma (the periodic compliance, mean zero, or the padded free one of
 * elastic_free.h), the stiffness scale that turns a gap error into a
 * pressure (the largest k_q; free boundaries: that of the same grid were
 * it periodic, k_max = (pi/2) E* sqrt(dx^-2 + dy^-2), a layer times its
 * phi at that q, layer.h), G_00, and FIRE's mass-weighted force
 * (M^-1 f, m_q = k_q; solver_fire_loop.c says why).
 */
#include "solver_impl.h"

#include <math.h>

/* out = G x: the periodic compliance (mean zero) or the free one. */
void
rc__compliance(rc_solver *s, const double *x, double *out)
{
	if (s->free_bc)
		rc_halfspace_apply(&s->fel, x, out);
	else
		rc_elastic_displacement(&s->el, x, out);
}

/* The stiffness scale of the convergence bound (see the top; solver_cg.c). */
double
rc__stiffness_max(const rc_solver *s)
{
	double dx = s->lx / (double)s->nx, dy = s->ly / (double)s->ny;
	double q = M_PI * sqrt(1 / (dx * dx) + 1 / (dy * dy));

	if (!s->free_bc)
		return s->el.k_max;
	/* a layer: its k_q at the zone corner (stiffer than the half space) */
	return 0.5 * q * s->opts.modulus * rc_layer_factor(q * s->opts.thickness,
	    s->opts.substrate, s->opts.poisson);
}

/* Self-compliance of one point, G_00 = (1/N) sum_{q != 0} 1/k_q: the lift
 * of a point (against the mean) under a unit pressure on it alone. */
double
rc__self_compliance(const rc_elastic *e)
{
	size_t i, j;
	double sum = 0;

	for (j = 0; j < e->ny; j++)
		for (i = 0; i < e->nxc; i++) {
			double k = e->stiffness[j * e->nxc + i];

			if (k > 0)
				sum += rc_fft_weight(i, e->nx) / k;
		}
	return sum / (double)e->n;
}

/* Step 3 without the clamp: a = M^-1 f_eff into the operator's real
 * buffer (returned); m_q = k_q, m_0 = mass0.  Also the adhesive loop's
 * (solver_fire_adh.c). */
double *
rc__fire_mass_weighted(rc_elastic *e, const double *f, double mass0)
{
	double inv_n = 1.0 / (double)e->n;
	rc_fft_multiplier mu = { e->stiffness, inv_n, 1, inv_n / mass0 };

	rc_elastic_convolve(e, f, e->fft.real, &mu);
	return e->fft.real;
}
