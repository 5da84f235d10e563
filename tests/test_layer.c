/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_layer.c - an elastic layer on a rigid substrate (layer.h): the
 * closed-form factor against a second method (the Navier equations across
 * the layer, shot from the substrate with GSL's ODE solver), its limits
 * (half space, thin-layer Winkler foundation, incompressible bonded
 * layer), and the solvers with the layer: a sine in full contact carries
 * exactly k_q A, the approach and energy add the uniform compression, a
 * thin layer on a rough surface is a Winkler foundation, a thick one the
 * half space; refusals. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

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
make(const rc_grid *g, enum rc_method m, double d, enum rc_substrate sub,
    double nu, double tol)
{
	rc_solver_opts o;

	rc_solver_defaults(&o);
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
				rc_solver *s = make(g, m, ds[i], sub, nu, 1e-11);
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

/* Thin slip layer: every k_q within (qd)^2/3 of k_w = E* / d (2e-4 at the
 * corner of the 32^2 zone for d = 1e-4 L), so each point is a spring:
 * sigma = k_w max(h - l, 0), the level l set by the load (bisection).
 * Contact set: the points above l; pressures within 1e-3 of p. */
static void
winkler(void)
{
	size_t n = 32, N = n * n, k, diff = 0;
	double d = 1e-4, kw = 1 / d, p = 5, lo, hi, level = 0, err_max = 0;
	rc_grid *g = rc_test_rough(n, 0, 4);

	lo = -10;
	hi = 10;
	for (int it = 0; it < 200; it++) {
		double sum = 0;

		level = 0.5 * (lo + hi);
		for (k = 0; k < N; k++)
			sum += kw * fmax(g->z[k] - level, 0);
		if (sum / (double)N > p)
			lo = level;
		else
			hi = level;
	}
	for (int m = RC_METHOD_FIRE; m <= RC_METHOD_CG; m++) {
		rc_solver *s = make(g, m, d, RC_SUBSTRATE_SLIP, 0.3, 1e-10);
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
	rc_solver *half = make(g, RC_METHOD_FIRE, 0, RC_SUBSTRATE_NONE, 0, 1e-9);
	rc_solver *lay = make(g, RC_METHOD_FIRE, 100, RC_SUBSTRATE_BONDED, 0.3,
	    1e-9);

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
	o.boundary = RC_BOUNDARY_FREE;
	test_true(rc_solver_new(g, &o, &err) == NULL &&
	    strstr(err.msg, "periodic") != NULL, "layer on free boundaries "
	    "refused: %s", err.msg);
	o.boundary = RC_BOUNDARY_PERIODIC;
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
	against_navier();
	limits();
	sine_full_contact();
	winkler();
	thick();
	refusals();
	return test_summary();
}
