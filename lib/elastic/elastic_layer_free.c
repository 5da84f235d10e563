/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elastic_layer_free.c - the layer's real-space pixel compliance
 * (elastic_layer_free.h: the split, the cutoff, the quadratures). */
#include "elastic_layer_free.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include "love.h"

#define S_MAX		24.0	/* w(s) < 1e-17 beyond, either substrate */
#define S_POINTS	16	/* Gauss-Legendre points per s panel */
#define S_PANEL		0.25	/* widest s panel */
#define S_PHASE		6.0	/* s panel width times rho_max (radians) */
#define GL_MAX		RC_LAYER_GAUSS_MAX

/* Gauss-Legendre nodes and weights on [-1, 1] for 1 .. GL_MAX points,
 * n's at offset n (n - 1) / 2, from GSL's tables. */
static int
gauss_fill(rc_layer_pixel *g)
{
	for (size_t n = 1; n <= GL_MAX; n++) {
		gsl_integration_glfixed_table *t =
		    gsl_integration_glfixed_table_alloc(n);
		size_t o = n * (n - 1) / 2;

		if (t == NULL)
			return -1;
		for (size_t i = 0; i < n; i++)
			gsl_integration_glfixed_point(-1, 1, i, &g->gauss_x[o + i],
			    &g->gauss_w[o + i], t);
		gsl_integration_glfixed_table_free(t);
	}
	return 0;
}

double
rc_layer_compliance0(double modulus, double thickness,
    enum rc_substrate substrate, double poisson)
{
	if (substrate == RC_SUBSTRATE_SLIP)
		return thickness / modulus;
	return thickness * (1 - 2 * poisson) /
	    (modulus * (1 - poisson) * (1 - poisson));
}

/* w(s) = 1 - 1/phi(s); w(0) = 1. */
static double
weight(double s, enum rc_substrate sub, double nu)
{
	double phi;

	if (s == 0)
		return 1;
	phi = rc_layer_factor(s, sub, nu);
	return (phi - 1) / phi;
}

/* F(rho) on the s nodes (ws: weight times w(s) at node s). */
static double
hankel(const double *s, const double *ws, size_t m, double rho)
{
	double sum = 0;

	for (size_t k = 0; k < m; k++)
		sum += ws[k] * gsl_sf_bessel_J0(s[k] * rho);
	return sum;
}

/* F by Chebyshev segment; beyond RC_LAYER_CUTOFF, 1/rho (G_L is below
 * round-off there). */
static double
f_eval(const rc_layer_pixel *t, double rho)
{
	size_t seg = (size_t)rho, k;
	const double *c;
	double x, b0 = 0, b1 = 0, b2;

	if (rho >= RC_LAYER_CUTOFF || seg >= t->n_seg)
		return 1 / rho;	/* (no table: never asked) */
	c = t->cheb + seg * (RC_LAYER_CHEB_ORDER + 1);
	x = 2 * (rho - (double)seg) - 1;
	/* Clenshaw */
	for (k = RC_LAYER_CHEB_ORDER; k > 0; k--) {
		b2 = b1;
		b1 = b0;
		b0 = 2 * x * b1 - b2 + c[k];
	}
	return x * b0 - b1 + 0.5 * c[0];
}

double
rc_layer_green_correction(const rc_layer_pixel *t, double r)
{
	return f_eval(t, r / t->thickness) / (M_PI * t->modulus * t->thickness);
}

/* The s-quadrature nodes, then each segment's Chebyshev
 * coefficients from F at its nodes. */
int
rc_layer_pixel_init(rc_layer_pixel *t, double thickness,
    enum rc_substrate substrate, double poisson, double modulus,
    double dx, double dy, double r_max, rc_err *err)
{
	const size_t nc = RC_LAYER_CHEB_ORDER + 1;
	double rho_max;
	size_t seg;
	int failed = 0;

	memset(t, 0, sizeof(*t));
	if (rc_layer_check(thickness, substrate, poisson, err) <= 0)
		return rc_seterr(err, "a layer's compliance needs a layer");
	t->thickness = thickness;
	t->modulus = modulus;
	t->dx = dx;
	t->dy = dy;
	t->substrate = substrate;
	t->poisson = poisson;
	t->r_cut = RC_LAYER_CUTOFF * thickness;
	t->compliance0 = rc_layer_compliance0(modulus, thickness, substrate,
	    poisson);
	/* a layer so thin that the disk r <= r_cut fits in half a pixel:
	 * every C_L is 0 or compliance0, no F needed */
	if (t->r_cut <= 0.5 * fmin(dx, dy))
		return 0;
	rho_max = fmin(r_max / thickness, RC_LAYER_CUTOFF);
	t->n_seg = (size_t)ceil(rho_max);
	if (t->n_seg == 0)
		t->n_seg = 1;
	if ((t->cheb = malloc(t->n_seg * nc * sizeof(double))) == NULL ||
	    gauss_fill(t) != 0) {
		rc_layer_pixel_release(t);
		return rc_seterr(err, "out of memory (the layer's Green's "
		    "function table)");
	}
#pragma omp parallel for schedule(dynamic)
	for (seg = 0; seg < t->n_seg; seg++) {
		double f[RC_LAYER_CHEB_ORDER + 1], *c = t->cheb + seg * nc;
		/* panels short against J0's phase at the segment's largest
		 * rho and against w's poles (|Im s| >= 0.5) */
		double hs = fmin(S_PANEL, S_PHASE / (double)(seg + 1));
		size_t panels = (size_t)ceil(S_MAX / hs), m = panels * S_POINTS;
		size_t o = S_POINTS * (S_POINTS - 1) / 2;
		double *s = malloc(2 * m * sizeof(double)), *ws = s + m;

		if (s == NULL) {
			failed = 1;
			continue;
		}
		hs = S_MAX / (double)panels;
		for (size_t p = 0; p < panels; p++)
			for (size_t i = 0; i < S_POINTS; i++) {
				size_t k = p * S_POINTS + i;

				s[k] = hs * ((double)p + 0.5 * (1 + t->gauss_x[o + i]));
				ws[k] = 0.5 * hs * t->gauss_w[o + i] *
				    weight(s[k], substrate, poisson);
			}
		for (size_t k = 0; k < nc; k++) {
			double x = cos(M_PI * ((double)k + 0.5) / (double)nc);

			f[k] = hankel(s, ws, m, (double)seg + 0.5 * (x + 1));
		}
		free(s);
		for (size_t j = 0; j < nc; j++) {
			double sum = 0;

			for (size_t k = 0; k < nc; k++)
				sum += f[k] * cos(M_PI * (double)j *
				    ((double)k + 0.5) / (double)nc);
			c[j] = 2 * sum / (double)nc;
		}
	}
	if (failed) {
		rc_layer_pixel_release(t);
		return rc_seterr(err, "out of memory (the layer's Green's "
		    "function nodes)");
	}
	return 0;
}

void
rc_layer_pixel_release(rc_layer_pixel *t)
{
	free(t->cheb);
	memset(t, 0, sizeof(*t));
}

/* Gauss points per side for a sub-panel of half-width hw whose integrand
 * is analytic to distance a: the Bernstein ellipse parameter rho_b =
 * a/hw + sqrt((a/hw)^2 + 1) bounds the error by about rho_b^-2n; n for
 * 1e-17. */
static size_t
gauss_order(double a, double hw)
{
	double r = a / hw, rho_b = r + sqrt(r * r + 1);
	double n = ceil(log(1e17) / (2 * log(rho_b)));

	return n < 2 ? 2 : n > GL_MAX ? GL_MAX : (size_t)n;
}

/* int_pixel D: sub-panels no wider than d per axis (D is analytic in the
 * strip |Im r| < 2d, so to distance d from each panel at least). */
static double
pixel_correction(const rc_layer_pixel *t, double x, double y)
{
	double d = t->thickness, dx = t->dx, dy = t->dy, sum = 0;
	size_t mx = (size_t)ceil(dx / d), my = (size_t)ceil(dy / d);
	double wx = dx / (double)mx, wy = dy / (double)my;
	size_t nx = gauss_order(d, 0.5 * wx), ny = gauss_order(d, 0.5 * wy);
	size_t ox = nx * (nx - 1) / 2, oy = ny * (ny - 1) / 2;

	for (size_t b = 0; b < my; b++)
		for (size_t j = 0; j < ny; j++) {
			double yy = y - 0.5 * dy + wy * ((double)b + 0.5 *
			    (1 + t->gauss_x[oy + j]));
			double row = 0;

			for (size_t a = 0; a < mx; a++)
				for (size_t i = 0; i < nx; i++) {
					double xx = x - 0.5 * dx + wx *
					    ((double)a + 0.5 * (1 + t->gauss_x[ox + i]));

					row += t->gauss_w[ox + i] *
					    rc_layer_green_correction(t,
					    hypot(xx, yy));
				}
			sum += t->gauss_w[oy + j] * row;
		}
	return sum * 0.25 * wx * wy;
}

double
rc_layer_pixel_compliance(const rc_layer_pixel *t, double x, double y)
{
	double hx = 0.5 * t->dx, hy = 0.5 * t->dy;
	double nearx = fmax(fabs(x) - hx, 0), neary = fmax(fabs(y) - hy, 0);

	if (hypot(nearx, neary) >= t->r_cut)
		return 0;
	/* the disk r <= r_cut inside the pixel: all of G_L's integral */
	if (fabs(x) + t->r_cut <= hx && fabs(y) + t->r_cut <= hy)
		return t->compliance0;
	return rc_love_pixel(x, y, t->dx, t->dy) / t->modulus -
	    pixel_correction(t, x, y);
}
