/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_extrap.c - Richardson extrapolation, Yastrebov estimates, ensemble
 * statistics and the Eq. 27 schedule against closed forms. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "extrap.h"
#include "testlib.h"

static rc_extrap_opts
model(int auto_order, size_t nterms, double k1, double k2, enum rc_fit_kind kind)
{
	rc_extrap_opts o;

	memset(&o, 0, sizeof(o));
	o.auto_order = auto_order;
	o.nterms = nterms;
	o.exponent[0] = k1;
	o.exponent[1] = k2;
	o.kind = kind;
	return o;
}

static void
test_linear(void)
{
	/* a_r(eps) = a0 + c eps, points given out of order on purpose. */
	const double a0 = 0.123456789, c = 0.37;
	double eps[4] = { 0.125, 0.0625, 0.25, 0.5 }, y[4], w[4];
	rc_extrap_opts lin = model(0, 1, 1, 0, RC_FIT_FINEST);
	rc_fit f;
	rc_err err;

	for (int i = 0; i < 4; i++)
		y[i] = a0 + c * eps[i];
	/* Round-off: y is exact to an ulp and the two-point formula has
	 * weights of size <= 3, so the result is good to a few ulps. */
	test_int(rc_extrapolate(eps, y, 2, &lin, &f, w, &err), 0, "linear, two points");
	test_rel(f.value, a0, 1e-14, "linear two-point Richardson recovers a0");
	/* Closed-form weights: y0 = (e2 y1 - e1 y2)/(e2 - e1), e1 = 1/16
	 * (index 1), e2 = 1/8 (index 0). */
	test_rel(w[1], 0.125 / (0.125 - 0.0625), 1e-15, "weight of the finest point");
	test_rel(w[0], -0.0625 / (0.125 - 0.0625), 1e-15, "weight of the coarser point");
	/* With exactly two points the error estimate is the correction itself. */
	test_rel(f.err, c * 0.0625, 1e-12, "two-point error = |y0 - finest value|");
	test_int((long long)f.nused, 2, "two points used");

	test_int(rc_extrapolate(eps, y, 4, &lin, &f, w, &err), 0, "linear, four points");
	test_rel(f.value, a0, 1e-14, "finest pair of four recovers a0");
	test_abs(f.err, 0, 1e-14, "exactly linear data: next pair agrees, error ~ 0");
	test_abs(w[2] + w[3], 0, 0, "coarse points carry no weight (finest mode)");
	/* SVD pseudo-inverse of a well-conditioned 2x2 system: a few ulps. */
	test_rel(w[0] + w[1], 1, 1e-14, "weights sum to one (constants are exact)");

	rc_extrap_opts lsq = model(0, 1, 1, 0, RC_FIT_LSQ);
	test_int(rc_extrapolate(eps, y, 4, &lsq, &f, w, &err), 0, "lsq, four points");
	test_rel(f.value, a0, 1e-13, "least squares over four points recovers a0");
	test_abs(f.err, 0, 1e-13, "lsq standard error of exact data ~ 0");
}

static void
test_quadratic(void)
{
	/* a0 + c eps + d eps^2 at eps = 1/16, 1/8, 1/4. */
	const double a0 = 0.2, c = 0.3, d = 0.8;
	double eps[3] = { 0.0625, 0.125, 0.25 }, y[3], w[3];
	rc_fit f;
	rc_err err;

	for (int i = 0; i < 3; i++)
		y[i] = a0 + c * eps[i] + d * eps[i] * eps[i];
	/* Linear two-point Richardson leaves exactly -d e1 e2. */
	rc_extrap_opts lin = model(0, 1, 1, 0, RC_FIT_FINEST);
	test_int(rc_extrapolate(eps, y, 3, &lin, &f, w, &err), 0, "linear on quadratic data");
	test_rel(f.value, a0 - d * eps[0] * eps[1], 1e-13,
	    "linear Richardson error is -d e1 e2 (second order)");
	/* The error estimate: the share e1/(e3 - e1) of the difference of
	 * the pairs (1,2) and (2,3), d e2 (e3 - e1): exactly the true error
	 * d e1 e2 when the next term is what the pairs miss. */
	test_rel(f.err, d * eps[0] * eps[1], 1e-12,
	    "error estimate = the true error on quadratic data");
	test_rel(f.err, a0 - f.value, 1e-12,
	    "error estimate equals estimate minus truth");
	/* Not a halving: eps = 1/16, 1/10, 1/4 gives share e1/(e3 - e1). */
	{
		double e2[3] = { 0.0625, 0.1, 0.25 }, y2[3];
		for (int i = 0; i < 3; i++)
			y2[i] = a0 + c * e2[i] + d * e2[i] * e2[i];
		test_int(rc_extrapolate(e2, y2, 3, &lin, &f, w, &err), 0,
		    "linear on quadratic data, uneven eps");
		test_rel(f.err, d * e2[0] * e2[1], 1e-12,
		    "error estimate = true error for uneven eps");
	}

	/* Two terms, eps and eps^2, three points: exact. */
	rc_extrap_opts quad = model(0, 2, 1, 2, RC_FIT_FINEST);
	test_int(rc_extrapolate(eps, y, 3, &quad, &f, w, &err), 0, "order 1,2 fit");
	test_rel(f.value, a0, 1e-13, "order 1,2 Richardson recovers a0 to round-off");
	test_rel(f.err, d * eps[0] * eps[1], 1e-11,
	    "its error estimate = difference from the linear estimate");
	/* Classical three-point weights for eps ratio 2: 8/3, -2, 1/3. */
	test_rel(w[0], 8.0 / 3, 1e-13, "three-point weight 8/3");
	test_rel(w[1], -2.0, 1e-13, "three-point weight -2");
	test_rel(w[2], 1.0 / 3, 1e-13, "three-point weight 1/3");

	/* A single fitted power through eps + eps^2 data: the exponent lies in
	 * [1, 2] and tends to 1, and a0 is recovered to second order: refining
	 * all three eps by 2 divides the error by ~4 (asymptotically exactly;
	 * at eps = 2^-10 .. 2^-8 the measured ratios are 3.97-3.99), and the
	 * error is within 2.5x the linear estimate's d e1 e2. */
	rc_extrap_opts aut = model(1, 1, 1, 0, RC_FIT_FINEST);
	test_int(rc_extrapolate(eps, y, 3, &aut, &f, w, &err), 0, "auto order");
	test_range(f.order, 1, 2, "fitted exponent of eps + eps^2 data in [1, 2]");
	double prev = NAN, prevk = NAN;
	for (double s = 1.0 / 64; s >= 1.0 / 256; s /= 2) {
		double e3[3] = { s / 16, s / 8, s / 4 }, y3[3];
		for (int i = 0; i < 3; i++)
			y3[i] = a0 + c * e3[i] + d * e3[i] * e3[i];
		test_int(rc_extrapolate(e3, y3, 3, &aut, &f, NULL, &err), 0, "auto at %g", s);
		test_range(fabs(f.value - a0), 0, 2.5 * d * e3[0] * e3[1],
		    "auto a0 error within 2.5 d e1 e2 at scale %g", s);
		if (!isnan(prev)) {
			test_range(prev / fabs(f.value - a0), 3.7, 4.3,
			    "auto a0 error is second order (ratio at scale %g)", s);
			test_range((prevk - 1) / (f.order - 1), 1.8, 2.2,
			    "fitted exponent -> 1 linearly (ratio at scale %g)", s);
		}
		prev = fabs(f.value - a0);
		prevk = f.order;
	}
}

static void
test_auto_order(void)
{
	/* Pure power law a0 + c eps^1.5: three points give k and a0 exactly
	 * (bisection to 1e-15 relative), five points by least squares to the
	 * golden-section tolerance (chi^2 is quadratic at its minimum, so k
	 * is found to ~sqrt(1e-16) relative: test 1e-6). */
	const double a0 = 0.05, c = -0.2, k = 1.5;
	double eps[5] = { 1.0 / 32, 1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2 }, y[5], w[5];
	rc_extrap_opts aut = model(1, 1, 1, 0, RC_FIT_LSQ);
	rc_fit f;
	rc_err err;

	for (int i = 0; i < 5; i++)
		y[i] = a0 + c * pow(eps[i], k);
	test_int(rc_extrapolate(eps, y, 3, &aut, &f, w, &err), 0, "auto, 3 points");
	test_rel(f.order, k, 1e-10, "three-point fitted exponent");
	test_rel(f.value, a0, 1e-10, "three-point auto a0");
	double s = w[0] + w[1] + w[2];
	test_rel(s, 1, 1e-9, "auto weights sum to one");
	test_int(rc_extrapolate(eps, y, 5, &aut, &f, w, &err), 0, "auto, 5 points");
	test_rel(f.order, k, 1e-6, "five-point fitted exponent");
	test_rel(f.value, a0, 1e-7, "five-point auto a0");
	test_range(f.err, 0, 1e-7, "five-point auto standard error ~ 0 for exact data");

	/* Not a power law: differences change sign. */
	double yb[3] = { 0.1, 0.2, 0.15 };
	test_int(rc_extrapolate(eps, yb, 3, &aut, &f, w, &err), -1,
	    "auto refuses a non-monotone set");
	/* Noisy power law with 6 points: the fit's standard error covers the
	 * truth (a 4-sigma check against a fixed noise draw). */
	double e6[6] = { 1.0 / 64, 1.0 / 32, 1.0 / 16, 1.0 / 8, 1.0 / 4, 1.0 / 2 }, y6[6];
	const double noise[6] = { 3e-6, -2e-6, 4e-6, -1e-6, 2e-6, -3e-6 };
	for (int i = 0; i < 6; i++)
		y6[i] = a0 + 0.1 * e6[i] + noise[i];
	test_int(rc_extrapolate(e6, y6, 6, &aut, &f, NULL, &err), 0, "auto, noisy");
	test_range(f.err, 1e-7, 1e-4, "noisy data: a finite standard error");
	test_range(fabs(f.value - a0), 0, 4 * f.err, "truth within 4 standard errors");
	test_range(fabs(f.order - 1), 0, 4 * f.order_err + 1e-12,
	    "exponent within 4 standard errors of 1");
}

static void
test_bad(void)
{
	double eps[3] = { 0.1, 0.1, 0.2 }, y[3] = { 1, 2, 3 };
	rc_extrap_opts lin = model(0, 1, 1, 0, RC_FIT_FINEST);
	rc_fit f;
	rc_err err;

	test_int(rc_extrapolate(eps, y, 1, &lin, &f, NULL, &err), -1, "one point refused");
	test_true(strstr(err.msg, "1 point") != NULL, "message says one point: %s", err.msg);
	test_int(rc_extrapolate(eps, y, 3, &lin, &f, NULL, &err), -1, "equal eps refused");
	eps[1] = -1;
	test_int(rc_extrapolate(eps, y, 3, &lin, &f, NULL, &err), -1, "negative eps refused");
	eps[1] = 0.15;
	y[2] = NAN;
	test_int(rc_extrapolate(eps, y, 3, &lin, &f, NULL, &err), -1, "NaN value refused");
}

static void
test_yastrebov(void)
{
	/* Eq. 22's constant. */
	test_rel(RC_YASTREBOV_ALPHA, (M_PI - 1 + log(2)) / 24, 1e-15,
	    "alpha = (pi - 1 + ln 2)/24");
	test_rel(RC_YASTREBOV_ALPHA, 0.1181142, 1e-6, "alpha = 0.1181142");
	test_rel(rc_yastrebov(1000, 200, 10000, 0.11), (1000 - 22.0) / 10000, 1e-15,
	    "Eq. 22");
	/* Two discretisations that follow n_c/N = a + alpha n_cl/N exactly
	 * with a = 0.1, alpha = 0.0937: the modified alpha recovers alpha and
	 * Eq. 22 then gives a at both. */
	double a = 0.1, al = 0.0937, N1 = 65536, N2 = 16384, ncl1 = 3000, ncl2 = 1480;
	double nc1 = a * N1 + al * ncl1, nc2 = a * N2 + al * ncl2;
	double am = rc_yastrebov_alpha_mod(nc1, ncl1, N1, nc2, ncl2, N2);
	test_rel(am, al, 1e-12, "modified-Yastrebov alpha, closed form");
	test_rel(rc_yastrebov(nc1, ncl1, N1, am), a, 1e-13, "fine estimate = a");
	test_rel(rc_yastrebov(nc2, ncl2, N2, am), a, 1e-13, "coarse estimate = a");
	test_true(isnan(rc_yastrebov_alpha_mod(10, 5, 100, 40, 20, 400)),
	    "equal contact-line fractions: alpha undefined (NaN)");
}

static void
test_ensemble(void)
{
	gsl_rng *r = gsl_rng_alloc(gsl_rng_mt19937);
	rc_ensemble e;
	rc_err err;
	double x[400];
	const double mu = 0.3, sigma = 0.02;

	gsl_rng_set(r, 12345);
	for (int i = 0; i < 400; i++)
		x[i] = mu + gsl_ran_gaussian(r, sigma);
	/* Closed forms in long double. */
	long double s = 0, ss = 0;
	for (int i = 0; i < 400; i++)
		s += x[i];
	long double m = s / 400;
	for (int i = 0; i < 400; i++)
		ss += (x[i] - m) * (x[i] - m);
	test_int(rc_ensemble_stats(x, 400, &e, &err), 0, "ensemble of 400");
	test_rel(e.mean, (double)m, 1e-14, "mean = sum/n");
	test_rel(e.sd, (double)sqrtl(ss / 399), 1e-12, "sd with n - 1");
	test_rel(e.se, (double)sqrtl(ss / 399 / 400), 1e-12, "se = sd/sqrt(n)");
	test_int(rc_ensemble_stats(x, 1, &e, &err), 0, "ensemble of one");
	test_true(e.mean == x[0] && isnan(e.sd) && isnan(e.se), "n = 1: sd, se NaN");

	/* Statistics of the standard error: over 4000 ensembles of 10,
	 * rms(mean - mu) -> sigma/sqrt(10) and <se^2> -> sigma^2/10.  The
	 * relative sampling error of both is ~ sqrt(2/4000) = 2.2%; allow 8%. */
	double sq = 0, se2 = 0;
	for (int k = 0; k < 4000; k++) {
		for (int i = 0; i < 10; i++)
			x[i] = mu + gsl_ran_gaussian(r, sigma);
		rc_ensemble_stats(x, 10, &e, &err);
		sq += (e.mean - mu) * (e.mean - mu);
		se2 += e.se * e.se;
	}
	test_rel(sqrt(sq / 4000), sigma / sqrt(10), 0.08, "rms error of the mean");
	test_rel(se2 / 4000, sigma * sigma / 10, 0.08, "<se^2> = sigma^2/n");
	x[3] = NAN;
	test_int(rc_ensemble_stats(x, 10, &e, &err), -1, "NaN member refused");
	gsl_rng_free(r);
}

static void
test_schedule(void)
{
	/* Figure 4 of the paper: eps_f = 1/32 at p* = 0.2 goes to 1/64 at
	 * p* = 0.0125 (p ratio 1/16, fourth root 1/2); eps_t 1/2 -> 1/4. */
	test_rel(rc_eps_schedule(1.0 / 32, 0.2, 0.0125), 1.0 / 64, 1e-15, "eps_f schedule");
	test_rel(rc_eps_schedule(0.5, 0.2, 0.0125), 0.25, 1e-15, "eps_t schedule");
	test_rel(rc_eps_schedule(0.03125, 0.2, 0.1), 0.03125 * pow(0.5, 0.25), 1e-15,
	    "eps at p_ref/2");
	test_rel(rc_eps_schedule(0.03125, 0.2, 0.2), 0.03125, 0, "eps at p_ref");
	test_true(isnan(rc_eps_schedule(0.1, 0.2, 0)) && isnan(rc_eps_schedule(0.1, -1, 1)),
	    "bad schedule arguments give NaN");
}

/* rc_count_noise: sqrt(sum w^2 n_cl / n_tot^2), by hand; NaN without
 * counts. */
static void
test_count_noise(void)
{
	const double w[3] = { 2, -1, 0 }, ncl[3] = { 400, 100, 7 };
	const double ntot[3] = { 10000, 2500, 625 };
	double nan_ncl[3] = { 400, NAN, 7 };

	/* 4 * 400 / 1e8 + 100 / 6.25e6 = 1.6e-5 + 1.6e-5 */
	test_rel(rc_count_noise(w, ncl, ntot, 3), sqrt(3.2e-5), 1e-14,
	    "count noise of a Richardson pair");
	test_true(isnan(rc_count_noise(w, nan_ncl, ntot, 3)), "no n_cl: NaN");
	test_true(rc_count_noise(w, ncl, ntot, 0) == 0, "no points: 0");
}

int
main(void)
{
	test_linear();
	test_quadratic();
	test_auto_order();
	test_bad();
	test_yastrebov();
	test_ensemble();
	test_schedule();
	test_count_noise();
	return test_summary();
}
