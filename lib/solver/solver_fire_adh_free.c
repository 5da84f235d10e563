/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_adh_free.c - adhesion (adhesion.h) on free boundaries: the
 * adhesive FIRE loop of solver_fire_adh.c on the padded grid of
 * elastic_free.h, in surface heights.
 *
 * Why heights: the free FIRE of solver_fire_free.c relaxes pressures, the
 * dual of the hard-wall problem, and the adhesive energy, concave in the
 * gap, has no such dual.  So the heights are the unknowns here, and the
 * operator is the inverse of the padded compliance.
 *
 * The padded grid (2nx x 2ny): Love's compliance C in wrap-around order
 * is a circulant whose eigenvalues Chat_q (elastic_free.h's kernel times
 * 4N) are all positive (measured: 0.58069 dx / E* at the zone corner up
 * to sum C at q = 0, 8x8 to 256^2 grids; a layer's C_L,
 * elastic_layer_free.h, is refused by solver.c unless they are too).  On
 * it, displacements w = C * f of forces f that vanish off the given area
 * are exactly the free-boundary ones on that area (Hockney's argument).
 * So the padded height field u = c + w, c the rigid level, with stiffness
 * kappa_q = 1 / Chat_q, and no interaction off the area (h = -inf
 * there), is the free body: at equilibrium the traction kappa (u - c)
 * vanishes off the area, so it holds only the pressures of the area.
 *
 * Load control (total force F = p N over the N points of the area):
 * minimising the energy over c gives c = <u> - F / (4N kappa_0), <u> over
 * the 4N padded points, and leaves the energy
 *   (1/2) sum_{q != 0} kappa_q |u_q|^2 + (F / 4N) sum u + sum_area phi,
 * which is solver_fire_adh.c's periodic problem on the padded grid with
 * k_0 = 0 and the pressure p / 4 on every padded point.
 * Displacement control (the rigid level c = max h - delta held; the
 * approach of solver.h on free boundaries): w = u - c with the whole
 * kappa (kappa_0 included) and no applied load; the pressure is the
 * total traction over N.  The mean mode then has mass kappa_0, every
 * mode its own stiffness, as in load control.
 *
 * Cost per iteration: two pairs of the 4N-point transform (K u and the
 * mass weighting, as solver_fire.c; the free FIRE on pressures: 1.25),
 * plus the adhesive wall pass on 4N points.  Memory: the padded operator
 * (elastic.h: its buffers and table) and five padded fields (132 bytes
 * per point of the area), besides the solver's own fields; the
 * compliance's own transform (elastic_free.h) is released once kappa is
 * made.  Measured (make bench, fire-adh, free): 245 bytes per point; 79
 * and 56 iterations at 256^2 and 512^2 (the free FIRE on pressures
 * without adhesion: 58 and 61).
 */
#include "solver_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "adhesion.h"

int
rc__adh_free_init(rc_solver *s, rc_err *err)
{
	rc_adh_pad *pad = &s->pad;
	rc_elastic *e = &s->el;
	size_t nx = s->nx, ny = s->ny, px = 2 * nx, py = 2 * ny, m, i, j;
	double n4 = (double)px * (double)py;

	if (rc_elastic_init(e, px, py, 2 * s->lx, 2 * s->ly, s->opts.modulus,
	    s->opts.fft_effort, err) != 0)
		return -1;
	/* kappa_q = 1 / Chat_q, the table in the layout of both operators
	 * (py rows of nx + 1 half-complex columns) */
	e->k_min = HUGE_VAL;
	e->k_max = 0;
	for (m = 0; m < e->nxc * py; m++) {
		double k = 1.0 / (s->fel.kernel[m] * n4);

		e->stiffness[m] = m == 0 ? 0 : k;
		if (m == 0)
			pad->stiffness0 = k;
		else {
			e->k_min = fmin(e->k_min, k);
			e->k_max = fmax(e->k_max, k);
		}
	}
	rc_halfspace_release(&s->fel);
	pad->n = px * py;
	pad->u = fftw_alloc_real(pad->n);
	pad->v = fftw_alloc_real(pad->n);
	pad->f = fftw_alloc_real(pad->n);
	pad->h = fftw_alloc_real(pad->n);
	pad->contact = calloc(pad->n, 1);
	if (pad->u == NULL || pad->v == NULL || pad->f == NULL ||
	    pad->h == NULL || pad->contact == NULL)
		return rc_seterr(err, "out of memory (asked for %zu bytes of "
		    "the padded adhesive fields)", rc__adh_free_bytes(s));
	for (j = 0; j < py; j++)
		for (i = 0; i < px; i++)
			pad->h[j * px + i] = i < nx && j < ny ?
			    s->height[j * nx + i] : -HUGE_VAL;
	pad->valid = 0;
	return 0;
}

void
rc__adh_free_release(rc_solver *s)
{
	rc_adh_pad *pad = &s->pad;

	fftw_free(pad->u);
	fftw_free(pad->v);
	fftw_free(pad->f);
	fftw_free(pad->h);
	free(pad->contact);
	memset(pad, 0, sizeof(*pad));
}

size_t
rc__adh_free_bytes(const rc_solver *s)
{
	return s->pad.n * (4 * sizeof(double) + 1);
}

/* The start: the last state, or the solver's u on the area (the body
 * flat at max h where none), clamped to the indenter. */
static void
pad_start(rc_solver *s)
{
	rc_adh_pad *pad = &s->pad;
	size_t nx = s->nx, px = 2 * nx, i, j;

	if (!pad->valid)
		for (j = 0; j < 2 * s->ny; j++)
			for (i = 0; i < px; i++)
				pad->u[j * px + i] = s->have_u && i < nx &&
				    j < s->ny ? s->u[j * nx + i] : s->top;
	pad->valid = 1;
	for (i = 0; i < pad->n; i++)
		if (pad->u[i] < pad->h[i])
			pad->u[i] = pad->h[i];
}

/* The area's fields from the padded state at rigid level c: the total
 * traction kappa (u - c) = K'u + kappa_0 (<u> - c) on contact, sigma_a
 * off it; p_adh, a_attr, the elastic energy; returns the mean pressure. */
static double
pad_finish(rc_solver *s, const rc_adhesion *law, double c)
{
	rc_adh_pad *pad = &s->pad;
	size_t nx = s->nx, ny = s->ny, px = 2 * nx, k, attr = 0;
	double mean = 0, lift, energy = 0, sum_a = 0, total = 0;
	double *f = pad->f;

	for (k = 0; k < pad->n; k++)
		mean += pad->u[k];
	lift = s->pad.stiffness0 * (mean / (double)pad->n - c);
	rc_elastic_force(&s->el, pad->u, f);
	for (k = 0; k < pad->n; k++) {
		f[k] += lift;
		energy += (pad->u[k] - c) * f[k];
	}
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			size_t a = j * nx + i, q = j * px + i;
			double g = pad->u[q] - pad->h[q];
			double sa = rc_adhesion_traction(law, g);

			s->u[a] = pad->u[q];
			s->contact[a] = pad->contact[q];
			s->sigma[a] = pad->contact[q] ? f[q] : sa;
			sum_a += sa;
			total += s->sigma[a];
			if (!pad->contact[q] && g < law->range)
				attr++;
		}
	s->have_u = 1;
	s->level = c;
	s->energy = 0.5 * energy / (double)s->n;
	s->p_adh = sum_a / (double)s->n;
	s->a_attr = (double)attr / (double)s->n;
	return total / (double)s->n;
}

int
rc__fire_adh_free_solve(rc_solver *s, const rc_adhesion *law, int control,
    double *pp, double delta, rc_solve_result *res)
{
	rc_adh_pad *pad = &s->pad;
	rc__adh_view w = { &s->el, pad->n, (double)s->n, pad->u, pad->v,
	    pad->f, pad->h, pad->contact, 0, 0, &s->watch };
	unsigned long transforms = s->el.n_r2c + s->el.n_c2r;
	size_t k, nx = s->nx, px = 2 * nx;
	double c, p, spread = (double)pad->n / (double)s->n;
	int r;

	pad_start(s);
	if (!control) {
		p = *pp / spread;
		r = rc__adh_relax(&w, law, 0, &p, 0, &s->opts, res);
		for (c = 0, k = 0; k < pad->n; k++)
			c += pad->u[k];
		c = c / (double)pad->n - p / pad->stiffness0;
		pad_finish(s, law, c);
	} else {
		/* w = u - c, h - c: the whole kappa, no load */
		c = s->top - delta;
		for (k = 0; k < pad->n; k++) {
			pad->u[k] -= c;
			pad->h[k] -= c;
		}
		s->el.stiffness[0] = pad->stiffness0;
		w.mass0 = pad->stiffness0;
		p = 0;
		r = rc__adh_relax(&w, law, 0, &p, 0, &s->opts, res);
		s->el.stiffness[0] = 0;
		for (k = 0; k < pad->n; k++)
			pad->u[k] += c;
		/* the indenter exactly as given again */
		for (size_t j = 0; j < s->ny; j++)
			memcpy(pad->h + j * px, s->height + j * nx,
			    nx * sizeof(double));
		/* contact points exactly on the wall ((h - c) + c need not
		 * be h), the rest not below it */
		for (k = 0; k < pad->n; k++)
			if (pad->contact[k] || pad->u[k] < pad->h[k])
				pad->u[k] = pad->h[k];
		*pp = pad_finish(s, law, c);
	}
	res->fft_pairs = 0.5 * (double)(s->el.n_r2c + s->el.n_c2r - transforms);
	return r;
}
