/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_layer.c - an elastic layer on a rigid substrate (layer.h): the
 * closed-form factor against a second method (the Navier equations across
 * the layer, shot from the substrate with GSL's ODE solver), its limits
 * (half space, thin-layer Winkler foundation, incompressible bonded
 * layer), and the solvers with the layer: a sine in full contact carries
 * exactly k_q A, the approach and energy add the uniform compression, a
 * thin layer on a rough surface is a Winkler foundation, a thick one the
 * half space.  Free boundaries (elastic_layer_free.h): the Green's
 * function table against QAG, the pixel integrals against nested QAG,
 * the sum rule and the thin and thick limits of C_L, the padded
 * spectrum, and the solves: thick = the free half space, thin = Winkler,
 * a padded periodic cell = the free layer, FIRE = CG.  Refusals. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_odeiv2.h>
#include <gsl/gsl_sf_bessel.h>

#include "elastic_free.h"
#include "elastic_layer_free.h"
#include "solver.h"
#include "synth.h"
#include "rough_cases.h"
#include "testlib.h"

/* Plane strain, a mode e^{iqx} with q = 1: u_x = i w(z), u_z(z), z into
 * the body, Lame constants lam, mu.  Navier:
 *   (lam + 2mu) u_z'' = mu u_z + (lam + mu) w'
 *   mu w''            = (lam + 2mu) w - (lam + mu) u_z'
 * y = (u_z, u_z', w, w'). */
struct lame {
	double lam, mu;
};

static int
navier(double z, const double y[], double dy[], void *params)
{
	const struct lame *l = params;

	(void)z;
	dy[0] = y[1];
	dy[1] = (l->mu * y[0] + (l->lam + l->mu) * y[3]) / (l->lam + 2 * l->mu);
	dy[2] = y[3];
	dy[3] = ((l->lam + 2 * l->mu) * y[2] - (l->lam + l->mu) * y[1]) / l->mu;
	return GSL_SUCCESS;
}

/* phi = k / (q E* / 2) of a layer of thickness t (q = 1, E = 1) by
 * shooting: the two solutions that satisfy the substrate's conditions at
 * z = t, integrated to the top z = 0 and combined so that the top is
 * free of shear and carries sigma_zz = -1:
 *   sigma_zz = (lam + 2mu) u_z' - lam w,   sigma_xz ~ w' + u_z. */
static double
shoot(double t, enum rc_substrate sub, double nu)
{
	struct lame l = { nu / ((1 + nu) * (1 - 2 * nu)), 1 / (2 * (1 + nu)) };
	gsl_odeiv2_system sys = { navier, NULL, 4, &l };
	double top[2][4], szz[2], sxz[2], c0, c1, det, uz0;

	for (int b = 0; b < 2; b++) {
		/* bonded: u_z = w = 0, free u_z', w'; slip: u_z = w' = 0,
		 * free u_z', w */
		double y[4] = { 0, b == 0, 0, 0 }, z = t;
		gsl_odeiv2_driver *d = gsl_odeiv2_driver_alloc_y_new(&sys,
		    gsl_odeiv2_step_rk8pd, -1e-3 * t, 1e-14, 1e-14);

		if (b == 1) {
			if (sub == RC_SUBSTRATE_BONDED)
				y[3] = 1;
			else
				y[2] = 1;
		}
		if (gsl_odeiv2_driver_apply(d, &z, 0.0, y) != GSL_SUCCESS) {
			fprintf(stderr, "ODE failed at t = %g\n", t);
			exit(1);
		}
		gsl_odeiv2_driver_free(d);
		memcpy(top[b], y, sizeof(y));
		szz[b] = (l.lam + 2 * l.mu) * y[1] - l.lam * y[2];
		sxz[b] = y[3] + y[0];
	}
	/* c0 szz0 + c1 szz1 = -1, c0 sxz0 + c1 sxz1 = 0 */
	det = szz[0] * sxz[1] - szz[1] * sxz[0];
	c0 = -sxz[1] / det;
	c1 = sxz[0] / det;
	uz0 = c0 * top[0][0] + c1 * top[1][0];
	/* sigma_zz = -1 pushes into the body: u_z(0) > 0; k = 1 / u_z(0),
	 * E* / 2 = 1 / (2 (1 - nu^2)) */
	return (1 / uz0) * 2 * (1 - nu * nu);
}

static void
against_navier(void)
{
	const double ts[] = { 0.01, 0.05, 0.2, 0.5, 1, 2, 5 };
	const double nus[] = { 0, 0.25, 0.3, 0.45, -0.3 };

	for (size_t i = 0; i < sizeof(ts) / sizeof(ts[0]); i++)
		for (size_t j = 0; j < sizeof(nus) / sizeof(nus[0]); j++)
			for (int sub = RC_SUBSTRATE_BONDED; sub <= RC_SUBSTRATE_SLIP; sub++) {
				double t = ts[i], nu = nus[j];

				/* shooting loses e^2t of its 1e-14: 1e-9 at t = 5 */
				test_rel(rc_layer_factor(t, sub, nu), shoot(t, sub, nu),
				    1e-9, "%s layer: phi(qd = %g, nu = %g) = Navier "
				    "shooting", rc_substrate_name(sub), t, nu);
			}
}

static void
limits(void)
{
	const double nus[] = { 0, 0.3, 0.49 };

	/* half space: phi - 1 = (4t + 2) e^-2t (slip), (4t^2 + 4t + 2b)
	 * e^-2t / a (bonded, a = 3 - 4nu, b = 5 - 12nu + 8nu^2) to first
	 * order in e^-2t; below 1e-14 from t = 20; no overflow at any t */
	for (double t = 20; t < 1e6; t *= 7)
		for (int sub = RC_SUBSTRATE_BONDED; sub <= RC_SUBSTRATE_SLIP; sub++)
			test_abs(rc_layer_factor(t, sub, 0.3), 1, 1e-14,
			    "%s phi(%g) = 1 (half space)", rc_substrate_name(sub), t);
	test_rel(rc_layer_factor(8, RC_SUBSTRATE_SLIP, 0.3) - 1, 34 * exp(-16),
	    1e-5, "slip phi(8) - 1 = (4t + 2) e^-2t");
	test_rel(rc_layer_factor(8, RC_SUBSTRATE_BONDED, 0.3) - 1,
	    (256 + 32 + 2 * 2.12) * exp(-16) / 1.8, 1e-4,
	    "bonded phi(8) - 1 = (4t^2 + 4t + 2b) e^-2t / a");
	/* thin layer: k_q -> k_w, phi t -> 2 k_w d / E* */
	for (size_t j = 0; j < sizeof(nus) / sizeof(nus[0]); j++) {
		double nu = nus[j], t = 1e-6;

		test_rel(t * rc_layer_factor(t, RC_SUBSTRATE_BONDED, nu),
		    2 * (1 - nu) * (1 - nu) / (1 - 2 * nu), 1e-8,
		    "bonded thin layer, nu %g: k_q -> E*(1-nu)^2/((1-2nu) d)", nu);
		test_rel(t * rc_layer_factor(t, RC_SUBSTRATE_SLIP, nu), 2, 1e-8,
		    "slip thin layer, nu %g: k_q -> E*/d", nu);
		test_rel(rc_layer_uniform_stiffness(2, 0.5, nu),
		    2 * (1 - nu) * (1 - nu) / ((1 - 2 * nu) * 0.5), 1e-15,
		    "k_0 = E* (1-nu)^2/((1-2nu) d), nu %g", nu);
	}
	/* incompressible bonded layer: phi ~ 3 / (2 t^3) */
	test_rel(pow(1e-4, 3) * rc_layer_factor(1e-4, RC_SUBSTRATE_BONDED, 0.5),
	    1.5, 1e-6, "incompressible bonded thin layer: phi ~ 3/(2 t^3)");
	test_true(isinf(rc_layer_uniform_stiffness(1, 1, 0.5)),
	    "incompressible layer: k_0 infinite");
	/* the two evaluations meet at t = 1 */
	for (int sub = RC_SUBSTRATE_BONDED; sub <= RC_SUBSTRATE_SLIP; sub++)
		test_rel(rc_layer_factor(nextafter(1, 0), sub, 0.3),
		    rc_layer_factor(nextafter(1, 2), sub, 0.3), 1e-14,
		    "%s phi continuous at t = 1", rc_substrate_name(sub));
}

static rc_solver *
make(const rc_grid *g, enum rc_boundary b, enum rc_method m, double d,
    enum rc_substrate sub, double nu, double tol)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
	o.boundary = b;
	o.method = m;
	o.tol = tol;
	o.thickness = d;
	o.substrate = sub;
	o.poisson = nu;
	return rc_test_solver(g, &o);
}

static void
solve(rc_solver *s, double p, const char *what)
{
	test_int(rc_test_solve(s, p, NULL), 0, "%s converges", what);
}

/* h = A cos(2 pi x / L) pressed into full contact: u = h, so sigma = p +
 * K h = p + k_q A cos(...) exactly; the approach is max h - <h> + p/k_0
 * = A + p/k_0 and the energy k_q A^2 / 4 + p^2 / (2 k_0). */
static void
sine_full_contact(void)
{
	size_t n = 32, k;
	double amp = 0.01, q = 2 * M_PI, p = 50, nu = 0.3;
	const double ds[] = { 0.01, 0.1, 1 };
	rc_err err;
	rc_grid *g = rc_grid_new(n, n, 1, 1, &err);

	for (k = 0; k < n * n; k++)
		g->z[k] = amp * cos(q * (double)(k % n) / (double)n);
	for (int m = RC_METHOD_FIRE; m <= RC_METHOD_CG; m++)
		for (int sub = RC_SUBSTRATE_BONDED; sub <= RC_SUBSTRATE_SLIP; sub++)
			for (size_t i = 0; i < 3; i++) {
				double kq = 0.5 * q * rc_layer_factor(q * ds[i], sub, nu);
				double k0 = rc_layer_uniform_stiffness(1, ds[i], nu);
				rc_solver *s = make(g, RC_BOUNDARY_PERIODIC, m,
				    ds[i], sub, nu, 1e-11);
				const double *sg;
				double max = 0;
				char what[128];

				snprintf(what, sizeof(what), "%s, %s layer d = %g",
				    rc_method_name(m), rc_substrate_name(sub), ds[i]);
				solve(s, p, what);
				sg = rc_solver_pressure(s);
				for (k = 0; k < n * n; k++)
					if (fabs(sg[k] - p) > max)
						max = fabs(sg[k] - p);
				test_rel(max, kq * amp, 1e-9, "%s: sigma - p = k_q A cos",
				    what);
				test_rel(rc_solver_approach(s), amp + p / k0, 1e-12,
				    "%s: approach = A + p/k_0", what);
				test_rel(rc_solver_elastic_energy(s),
				    kq * amp * amp / 4 + p * p / (2 * k0), 1e-9,
				    "%s: energy = k_q A^2/4 + p^2/(2 k_0)", what);
				rc_solver_free(s);
			}
	rc_grid_free(g);
}

/* The level l at which springs of stiffness kw under h carry the mean
 * pressure p: <kw max(h - l, 0)> = p, by bisection. */
static double
winkler_level(const rc_grid *g, double kw, double p)
{
	size_t N = g->nx * g->ny;
	double lo = -10, hi = 10, level = 0;

	for (int it = 0; it < 200; it++) {
		double sum = 0;

		level = 0.5 * (lo + hi);
		for (size_t k = 0; k < N; k++)
			sum += kw * fmax(g->z[k] - level, 0);
		if (sum / (double)N > p)
			lo = level;
		else
			hi = level;
	}
	return level;
}

/* Thin slip layer: every k_q within (qd)^2/3 of k_w = E* / d (2e-4 at the
 * corner of the 32^2 zone for d = 1e-4 L), so each point is a spring:
 * sigma = k_w max(h - l, 0), the level l set by the load (bisection).
 * Contact set: the points above l; pressures within 1e-3 of p. */
static void
winkler(void)
{
	size_t n = 32, N = n * n, k, diff = 0;
	double d = 1e-4, kw = 1 / d, p = 5, err_max = 0;
	rc_grid *g = rc_test_rough(n, 0, 4);
	double level = winkler_level(g, kw, p);
	for (int m = RC_METHOD_FIRE; m <= RC_METHOD_CG; m++) {
		rc_solver *s = make(g, RC_BOUNDARY_PERIODIC, m, d,
		    RC_SUBSTRATE_SLIP, 0.3, 1e-10);
		const unsigned char *c;
		const double *sg;

		solve(s, p, "thin slip layer");
		c = rc_solver_contact(s);
		sg = rc_solver_pressure(s);
		diff = 0;
		err_max = 0;
		for (k = 0; k < N; k++) {
			double w = kw * fmax(g->z[k] - level, 0);

			diff += c[k] != (g->z[k] > level);
			if (fabs(sg[k] - w) > err_max)
				err_max = fabs(sg[k] - w);
		}
		test_true(diff <= 2, "%s thin layer: contact set = Winkler's "
		    "(%zu of %zu points differ)", rc_method_name(m), diff, N);
		test_range(err_max / p, 0, 1e-3, "%s thin layer: |sigma - "
		    "k_w (h - l)+| / p", rc_method_name(m));
		rc_solver_free(s);
	}
	rc_grid_free(g);
}

/* A layer far thicker than the cell: phi = 1 to round-off at every
 * mode, so the contact and pressures are the half space's. */
static void
thick(void)
{
	size_t N = 64 * 64, k, diff = 0;
	double max = 0;
	rc_grid *g = rc_test_rough(64, 0, 4);
	rc_solver *half = make(g, RC_BOUNDARY_PERIODIC, RC_METHOD_FIRE, 0,
	    RC_SUBSTRATE_NONE, 0, 1e-9);
	rc_solver *lay = make(g, RC_BOUNDARY_PERIODIC, RC_METHOD_FIRE, 100,
	    RC_SUBSTRATE_BONDED, 0.3, 1e-9);

	solve(half, 0.05, "half space");
	solve(lay, 0.05, "thick layer");
	for (k = 0; k < N; k++) {
		diff += rc_solver_contact(half)[k] != rc_solver_contact(lay)[k];
		max = fmax(max, fabs(rc_solver_pressure(half)[k] -
		    rc_solver_pressure(lay)[k]));
	}
	test_int((long long)diff, 0, "thick layer: the half space's contact");
	test_abs(max, 0, 1e-14, "thick layer: the half space's pressures");
	rc_solver_free(half);
	rc_solver_free(lay);
	rc_grid_free(g);
}

/* --- Free boundaries: the layer's pixel compliance (elastic_layer_free.h). */

struct f_params {
	double rho, nu;
	enum rc_substrate sub;
};

static double
f_integrand(double s, void *vp)
{
	const struct f_params *fp = vp;
	double phi = rc_layer_factor(s, fp->sub, fp->nu);

	return gsl_sf_bessel_J0(s * fp->rho) * (phi - 1) / phi;
}

/* F(rho) = int J0(s rho) (1 - 1/phi(s)) ds by GSL's adaptive QAG: a
 * second method for the table's fixed composite rule and Chebyshev
 * series. */
static double
f_reference(double rho, enum rc_substrate sub, double nu)
{
	struct f_params fp = { rho, nu, sub };
	gsl_function fn = { f_integrand, &fp };
	gsl_integration_workspace *w = gsl_integration_workspace_alloc(4000);
	double r, e;

	gsl_integration_qag(&fn, 0, 30, 1e-16, 1e-14, 4000,
	    GSL_INTEG_GAUSS61, w, &r, &e);
	gsl_integration_workspace_free(w);
	return r;
}

/* int over the pixel centred at (x, y) of D, by nested QAG (a second
 * method for the table's sub-panel Gauss rule). */
struct pix_params {
	const rc_layer_pixel *t;
	double x, y;
	gsl_integration_workspace *w;
};

static double
pix_inner(double xx, void *vp)
{
	const struct pix_params *pp = vp;

	return rc_layer_green_correction(pp->t, hypot(xx, pp->y));
}

static double
pix_outer(double yy, void *vp)
{
	struct pix_params *pp = vp, q = *pp;
	gsl_function fn = { pix_inner, &q };
	double r, e;

	q.y = yy;
	gsl_integration_qag(&fn, pp->x - 0.5 * pp->t->dx, pp->x + 0.5 *
	    pp->t->dx, 1e-15, 1e-13, 1000, GSL_INTEG_GAUSS41, pp->w, &r, &e);
	return r;
}

static double
pixel_reference(const rc_layer_pixel *t, double x, double y)
{
	gsl_integration_workspace *wi = gsl_integration_workspace_alloc(1000);
	gsl_integration_workspace *wo = gsl_integration_workspace_alloc(1000);
	struct pix_params pp = { t, x, y, wi };
	gsl_function fn = { pix_outer, &pp };
	double r, e;

	gsl_integration_qag(&fn, y - 0.5 * t->dy, y + 0.5 * t->dy, 1e-15,
	    1e-13, 1000, GSL_INTEG_GAUSS41, wo, &r, &e);
	gsl_integration_workspace_free(wi);
	gsl_integration_workspace_free(wo);
	return r;
}

/* The three layers the table is checked on: both substrates, and a
 * nearly incompressible bonded one (the slowest decay of G_L). */
static const struct {
	enum rc_substrate sub;
	double nu;
} kinds[] = {
	{ RC_SUBSTRATE_SLIP, 0.3 },
	{ RC_SUBSTRATE_BONDED, 0.3 },
	{ RC_SUBSTRATE_BONDED, 0.45 },
};
#define N_KINDS (sizeof(kinds) / sizeof(kinds[0]))

static int
table(rc_layer_pixel *t, size_t kind, double d, double dx, double dy,
    double r_max)
{
	rc_err err;
	int r = rc_layer_pixel_init(t, d, kinds[kind].sub, kinds[kind].nu, 1,
	    dx, dy, r_max, &err);

	test_int(r, 0, "layer table d = %g: %s", d, r ? err.msg : "made");
	return r;
}

/* D's table against QAG, and the pixel integrals against nested QAG. */
static void
green_table(void)
{
	const double rhos[] = { 0, 0.3, 1, 2.5, 7, 15, 30, 47 };
	const double ds[] = { 0.05, 0.3, 1, 5 };

	for (size_t k = 0; k < N_KINDS; k++) {
		rc_layer_pixel t;
		double worst = 0;

		if (table(&t, k, 1, 1, 1, 100) != 0)
			continue;
		for (size_t i = 0; i < sizeof(rhos) / sizeof(rhos[0]); i++)
			worst = fmax(worst, fabs(M_PI * rc_layer_green_correction(
			    &t, rhos[i]) - f_reference(rhos[i], kinds[k].sub,
			    kinds[k].nu)));
		/* measured: 3e-15 (nu 0.3), 1e-14 (0.45) */
		test_abs(worst, 0, 1e-13, "%s nu %g: F(rho) table = QAG",
		    rc_substrate_name(kinds[k].sub), kinds[k].nu);
		rc_layer_pixel_release(&t);
	}
	for (size_t k = 0; k < N_KINDS; k++)
		for (size_t i = 0; i < sizeof(ds) / sizeof(ds[0]); i++) {
			rc_layer_pixel t;
			double worst = 0, self;

			if (table(&t, k, ds[i], 1, 1, 10) != 0)
				continue;
			self = rc_love_pixel(0, 0, 1, 1);
			for (int j = 0; j <= 3; j++)
				for (int m = 0; m <= j; m++) {
					double c = rc_love_pixel(j, m, 1, 1) -
					    rc_layer_pixel_compliance(&t, j, m);

					if (hypot(j - 0.5, m - 0.5) < t.r_cut)
						worst = fmax(worst, fabs(c -
						    pixel_reference(&t, j, m)));
				}
			/* measured: 8e-16 at worst */
			test_abs(worst / self, 0, 1e-13, "%s nu %g d/dx = %g: "
			    "pixel integral of D = nested QAG",
			    rc_substrate_name(kinds[k].sub), kinds[k].nu, ds[i]);
			rc_layer_pixel_release(&t);
		}
}

/* Sum of C_L over all offsets: the displacement under a uniform unit
 * pressure, the integral of G_L over the plane (the pixels tile it),
 * 1 / k(q -> 0). */
static double
pixel_sum(const rc_layer_pixel *t)
{
	long mx = (long)ceil(t->r_cut / t->dx) + 1;
	long my = (long)ceil(t->r_cut / t->dy) + 1;
	double sum = 0;

#pragma omp parallel for reduction(+:sum) schedule(dynamic)
	for (long j = 0; j <= my; j++)
		for (long i = 0; i <= mx; i++)
			sum += (i ? 2 : 1) * (j ? 2 : 1) *
			    rc_layer_pixel_compliance(t, (double)i * t->dx,
			    (double)j * t->dy);
	return sum;
}

static void
sum_rule_and_limits(void)
{
	const double ds[] = { 1e-3, 0.02, 0.1, 1, 10 };

	for (size_t k = 0; k < N_KINDS; k++) {
		double nu = kinds[k].nu;
		const char *sub = rc_substrate_name(kinds[k].sub);

		for (size_t i = 0; i < sizeof(ds) / sizeof(ds[0]); i++)
			for (int aspect = 1; aspect <= 2; aspect++) {
				rc_layer_pixel t;

				if (table(&t, k, ds[i], aspect, 1, HUGE_VAL) != 0)
					continue;
				/* measured: 4e-13 at worst (the sum of
				 * ~1e5 Love terms at d = 10 dx cancels
				 * to 1/k(0)) */
				test_rel(pixel_sum(&t), t.compliance0, 5e-12,
				    "%s nu %g d = %g, %dx1 pixel: sum C_L = "
				    "1/k(0)", sub, nu, ds[i], aspect);
				rc_layer_pixel_release(&t);
			}
		/* thin (through the quadrature: r_cut = 0.96 dx): the
		 * Winkler foundation, C_L = 1/k_w on the own pixel, up to
		 * the pixel-edge term, G_L's tail beyond dx/2 = 25 d (its
		 * slowest decay, bonded nu 0.45: e^-0.75 r/d, measured
		 * 8e-9 of 1/k_w; 2e-11 for nu 0.3) */
		{
			rc_layer_pixel t;

			if (table(&t, k, 0.02, 1, 1, 10) == 0) {
				test_rel(rc_layer_pixel_compliance(&t, 0, 0),
				    t.compliance0, 3e-8, "%s nu %g d = 0.02 dx: "
				    "C_L(0) = 1/k_w", sub, nu);
				test_abs(rc_layer_pixel_compliance(&t, 1, 0) /
				    t.compliance0, 0, 3e-8, "%s nu %g d = 0.02 "
				    "dx: C_L(dx) = 0", sub, nu);
				rc_layer_pixel_release(&t);
			}
		}
		/* thick: C_L = C_love - D(0) dx dy (1 + O((r/d)^2)),
		 * D(0) = F(0) / (pi E* d); (r/d)^2 = 1e-7 at (3, 1),
		 * measured 5e-8 there */
		{
			rc_layer_pixel t;
			double d = 1e4, f0 = f_reference(0, kinds[k].sub, nu);

			if (table(&t, k, d, 1, 1, 10) == 0) {
				for (int j = 0; j < 4; j++)
					test_rel(rc_love_pixel(j, 1, 1, 1) -
					    rc_layer_pixel_compliance(&t, j, 1),
					    f0 / (M_PI * d), 1e-6, "%s nu %g d = "
					    "1e4 dx: C_love - C_L = D(0) at "
					    "offset (%d, 1)", sub, nu, j);
				rc_layer_pixel_release(&t);
			}
		}
	}
}

/* The padded circulant stays positive definite (FIRE on pressures, CG
 * and the adhesive free FIRE need it). */
static void
padded_spectrum(void)
{
	const double ds[] = { 1e-3, 0.05, 0.3, 1, 4, 100 };
	rc_err err;

	for (size_t k = 0; k < N_KINDS; k++)
		for (size_t i = 0; i < sizeof(ds) / sizeof(ds[0]); i++) {
			rc_halfspace h;

			if (rc_halfspace_init_layer(&h, 16, 16, 16, 16, 1, ds[i],
			    kinds[k].sub, kinds[k].nu, RC_FFT_ESTIMATE, &err) != 0) {
				test_true(0, "padded layer: %s", err.msg);
				continue;
			}
			/* measured: 0.58 dx / E* (the half space's) from d =
			 * 1 dx on; 1/k(0) below */
			test_range(h.eig_min, 0.5 * fmin(rc_layer_compliance0(1,
			    ds[i], kinds[k].sub, kinds[k].nu), 0.58), 1,
			    "%s nu %g d = %g: smallest eigenvalue of the padded "
			    "compliance positive", rc_substrate_name(kinds[k].sub),
			    kinds[k].nu, ds[i]);
			rc_halfspace_release(&h);
		}
}

/* --- Free boundaries: solves on a layer. */

/* Points whose contact differs, and max |sigma_a - sigma_b| / max sigma_b
 * over the nx x ny points (a's rows nxa long: a periodic cell's). */
static size_t
compare(const rc_solver *a, size_t nxa, const rc_solver *b, size_t nx,
    size_t ny, double *rel)
{
	const double *pa = rc_solver_pressure(a), *pb = rc_solver_pressure(b);
	const unsigned char *ca = rc_solver_contact(a), *cb = rc_solver_contact(b);
	double max = 0, top = 0;
	size_t diff = 0;

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			size_t ka = j * nxa + i, kb = j * nx + i;

			diff += ca[ka] != cb[kb];
			max = fmax(max, fabs(pa[ka] - pb[kb]));
			top = fmax(top, pb[kb]);
		}
	*rel = max / top;
	return diff;
}

/* A thick layer (d = 100 L) on free boundaries: C_L = C_love - D(0)
 * dx dy - (non-uniform part, relative (L/d)^2 F''(0)/F(0) ~ 1e-4 of
 * D(0), itself L/d = 1e-2 of G_half at r = L): the uniform part only
 * moves the rigid level, so the pressures are the half space's to about
 * 1e-6 (measured: 3.5e-8); the approach less by D(0) F. */
static void
free_thick(void)
{
	size_t n = 32, diff;
	double rel, p = 0.05, f0 = f_reference(0, RC_SUBSTRATE_BONDED, 0.3);
	rc_grid *g = rc_test_rough(n, 0, 4);
	rc_solver *half = make(g, RC_BOUNDARY_FREE, RC_METHOD_CG, 0,
	    RC_SUBSTRATE_NONE, 0, 1e-10);
	rc_solver *lay = make(g, RC_BOUNDARY_FREE, RC_METHOD_CG, 100,
	    RC_SUBSTRATE_BONDED, 0.3, 1e-10);

	solve(half, p, "free half space");
	solve(lay, p, "free thick layer");
	diff = compare(lay, n, half, n, n, &rel);
	test_int((long long)diff, 0, "free thick layer: the half space's contact");
	test_range(rel, 0, 1e-6, "free thick layer: the half space's pressures");
	/* approach: max h - c, c lower by D(0) F (F = p L^2) */
	test_rel(rc_solver_approach(half) - rc_solver_approach(lay),
	    f0 / (M_PI * 100) * p, 1e-3, "free thick layer: approach less by "
	    "D(0) F");
	rc_solver_free(half);
	rc_solver_free(lay);
	rc_grid_free(g);
}

/* A thin slip layer (d = 1e-3 dx) on free boundaries: C_L is 1/k_w on
 * the diagonal and 0 elsewhere (r_cut = 0.048 dx), so sigma = k_w
 * max(h - c, 0) exactly, c the rigid level (found here by bisection on
 * the load), and the approach is max h - c. */
static void
free_winkler(void)
{
	size_t n = 32, N = n * n, k;
	double d = 1e-3 / n, kw = 1 / d, p = 5;
	rc_grid *g = rc_test_rough(n, 0, 4);
	double level = winkler_level(g, kw, p);
	for (int m = RC_METHOD_FIRE; m <= RC_METHOD_CG; m++) {
		rc_solver *s = make(g, RC_BOUNDARY_FREE, m, d, RC_SUBSTRATE_SLIP,
		    0.3, 1e-10);
		const double *sg;
		double err_max = 0, top = -HUGE_VAL;
		size_t diff = 0;

		solve(s, p, "free thin slip layer");
		sg = rc_solver_pressure(s);
		for (k = 0; k < N; k++) {
			double w = kw * fmax(g->z[k] - level, 0);

			diff += rc_solver_contact(s)[k] != (g->z[k] > level);
			err_max = fmax(err_max, fabs(sg[k] - w));
			top = fmax(top, g->z[k]);
		}
		test_int((long long)diff, 0, "%s free thin layer: contact set "
		    "= Winkler's", rc_method_name(m));
		/* measured: 1e-9 (FIRE), 1e-13 (CG) at tol 1e-10 */
		test_range(err_max / p, 0, 1e-8, "%s free thin layer: |sigma - "
		    "k_w (h - c)+| / p", rc_method_name(m));
		test_rel(rc_solver_approach(s), top - level, 1e-9, "%s free thin "
		    "layer: approach = max h - c", rc_method_name(m));
		rc_solver_free(s);
	}
	rc_grid_free(g);
}

/* A sphere h = -r^2 / 2 (R = 1) on an n x n unit area, its peak on
 * pixel (n/2, n/2), within a cell of m x m such areas (m = 1: the area
 * itself), the rest of the cell far below (1e3 under the area's lowest
 * point): only the area can touch. */
static rc_grid *
sphere(size_t n, size_t m)
{
	rc_grid *g = test_new_grid(m * n, m * n, (double)m, (double)m);

	for (size_t j = 0; j < m * n; j++)
		for (size_t i = 0; i < m * n; i++) {
			double x = ((double)i - (double)(n / 2)) / (double)n;
			double y = ((double)j - (double)(n / 2)) / (double)n;

			g->z[j * m * n + i] = i < n && j < n ?
			    -0.5 * (x * x + y * y) : -1e3;
		}
	return g;
}

/* Second method: the periodic layer (continuum kernel k_q of layer.h)
 * on a cell 3 L wide whose only possible contact is the area: its
 * images are 2 L apart, where G_L has decayed (below 1e-6 of its
 * near field for d <= L/4, bonded nu 0.3: 48 d cutoff table), so it
 * is the free layer up to the kernels' difference (continuum k_q
 * against the pixel compliance C_L), a discretisation error that falls
 * with the pixel.  Same total force: p_periodic = p / 9. */
static void
free_vs_periodic(void)
{
	const size_t ns[] = { 32, 64 };
	const double ds[] = { 1.0 / 8, 1.0 / 4 };
	double p = 0.004, rel[2][2];
	size_t diff[2][2];

	for (size_t i = 0; i < 2; i++) {
		size_t n = ns[i];
		rc_grid *g = sphere(n, 1), *big = sphere(n, 3);

		for (size_t k = 0; k < 2; k++) {
			rc_solver *fr = make(g, RC_BOUNDARY_FREE, RC_METHOD_CG,
			    ds[k], RC_SUBSTRATE_BONDED, 0.3, 1e-10);
			rc_solver *pe = make(big, RC_BOUNDARY_PERIODIC,
			    RC_METHOD_CG, ds[k], RC_SUBSTRATE_BONDED, 0.3, 1e-10);

			solve(fr, p, "free layer, sphere");
			solve(pe, p / 9, "periodic layer, padded sphere");
			diff[i][k] = compare(pe, 3 * n, fr, n, n, &rel[i][k]);
			test_int((long long)diff[i][k], 0, "n = %zu, d = L/%g: "
			    "the periodic 3L cell's contact = the free layer's",
			    n, 1 / ds[k]);
			/* measured: 1.4e-2, 1.3e-2 (n = 32), 8.6e-3, 9.3e-3
			 * (n = 64), at the contact edge */
			test_range(rel[i][k], 0, i == 0 ? 2e-2 : 1.2e-2, "n = "
			    "%zu, d = L/%g: periodic pressures = free ones to "
			    "the kernels' difference", n, 1 / ds[k]);
			rc_solver_free(fr);
			rc_solver_free(pe);
		}
		rc_grid_free(g);
		rc_grid_free(big);
	}
	for (size_t k = 0; k < 2; k++)
		test_true(rel[1][k] < 0.8 * rel[0][k], "d = L/%g: the kernels' "
		    "difference falls with the pixel (%.3g at n = 32, %.3g at "
		    "64)", 1 / ds[k], rel[0][k], rel[1][k]);
}

/* FIRE (on pressures, the layer's periodic k_q as inverse mass) and CG
 * on the same free layer: the same contact set, pressures to the
 * tolerance. */
static void
free_fire_cg(void)
{
	size_t n = 64, diff;
	double rel;
	rc_grid *g = rc_test_rough(n, 0, 4);

	for (int sub = RC_SUBSTRATE_BONDED; sub <= RC_SUBSTRATE_SLIP; sub++) {
		rc_solver *f = make(g, RC_BOUNDARY_FREE, RC_METHOD_FIRE, 0.1, sub,
		    0.3, 1e-10);
		rc_solver *c = make(g, RC_BOUNDARY_FREE, RC_METHOD_CG, 0.1, sub,
		    0.3, 1e-10);

		solve(f, 0.05, "FIRE, free layer");
		solve(c, 0.05, "CG, free layer");
		diff = compare(f, n, c, n, n, &rel);
		test_int((long long)diff, 0, "%s free layer: FIRE's contact = "
		    "CG's", rc_substrate_name(sub));
		/* measured: 2e-11 at tol 1e-10 */
		test_range(rel, 0, 1e-9, "%s free layer: FIRE's pressures = "
		    "CG's", rc_substrate_name(sub));
		test_rel(rc_solver_approach(f), rc_solver_approach(c), 1e-8,
		    "%s free layer: FIRE's approach = CG's", rc_substrate_name(sub));
		rc_solver_free(f);
		rc_solver_free(c);
	}
	rc_grid_free(g);
}

static void
refusals(void)
{
	rc_grid *g = rc_test_rough(16, 0, 4);
	rc_solver_opts o;
	rc_err err;

	rc_solver_defaults(&o);
	o.thickness = 0.1;
	o.substrate = RC_SUBSTRATE_BONDED;
	o.poisson = 0.3;
	o.kernel = RC_KERNEL_PIXEL;
	test_true(rc_solver_new(g, &o, &err) == NULL &&
	    strstr(err.msg, "continuum") != NULL, "periodic layer with the "
	    "pixel kernel refused: %s", err.msg);
	o.kernel = RC_KERNEL_CONTINUUM;
	/* an incompressible bonded layer much thinner than a pixel: C_L = 0
	 * (it keeps its volume; r_cut within the pixel), singular */
	o.boundary = RC_BOUNDARY_FREE;
	o.thickness = 1e-4;
	o.poisson = 0.5;
	test_true(rc_solver_new(g, &o, &err) == NULL &&
	    strstr(err.msg, "positive definite") != NULL, "free incompressible "
	    "thin bonded layer refused: %s", err.msg);
	o.boundary = RC_BOUNDARY_PERIODIC;
	o.thickness = 0.1;
	o.poisson = 0.6;
	test_true(rc_solver_new(g, &o, &err) == NULL, "Poisson 0.6 refused");
	o.poisson = 0.3;
	o.thickness = 0;
	test_true(rc_solver_new(g, &o, &err) == NULL, "thickness 0 with a "
	    "substrate refused");
	o.thickness = 0.1;
	o.substrate = RC_SUBSTRATE_NONE;
	test_true(rc_solver_new(g, &o, &err) == NULL, "thickness without a "
	    "substrate refused");
	rc_grid_free(g);
}

int
main(void)
{
	gsl_set_error_handler_off();	/* QAG's status is not needed here */
	against_navier();
	limits();
	sine_full_contact();
	winkler();
	thick();
	green_table();
	sum_rule_and_limits();
	padded_spectrum();
	free_thick();
	free_winkler();
	free_vs_periodic();
	free_fire_cg();
	refusals();
	return test_summary();
}
