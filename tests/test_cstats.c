/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_cstats.c - contact-stats' computation (lib/cstats) on synthetic
 * result rows with closed-form limits: grouping by seed, resolution and H,
 * the order continuum -> ensemble -> fractal, every printed estimator, the
 * error propagation, and the error paths.
 *
 * The rows: eps = (lx/nx)/lambda_s, eps_f = lambda_s/lambda_r,
 *   a(eps)   = a0 + c_s eps,  a0 = 0.1 + 0.001 s + 0.01 H + 0.05 eps_f,
 *              c_s = 0.02 + 0.01 s (the slope depends on the seed);
 *   n_c/N    = a(eps),  n_cl/N = b0 + d eps,  b0 = 0.05, d = 0.1;
 *   gbar = 1, gbar_c = r0 + r1 eps,  r0 = 1.2, r1 = 0.4.
 * Everything is linear in eps, so two-point Richardson is exact up to
 * round-off: values of size 0.1 with weights of size 2 lose a few ulps,
 * hence the relative tolerances 1e-12 (1e-9 where a small difference of
 * such values is compared, e.g. a standard deviation of 1e-3).
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cstats.h"
#include "kappa.h"
#include "testlib.h"

#define B0 0.05
#define D1 0.1
#define R0 1.2
#define R1 0.4
#define PI 3.14159265358979323846

static char buf[1 << 16];
static size_t len;

static void
put(const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	len += (size_t)vsnprintf(buf + len, sizeof(buf) - len, fmt, ap);
	va_end(ap);
}

static void
header(void)
{
	len = 0;
	put("p_star\ta_r\tn_c\tn_cl\tn_tot\tgbar\tgbar_c\tnx\tny\tlx\tly\tH\t"
	    "lambda_r\tlambda_s\tseed\n");
}

static double
slope(int seed)
{
	return 0.02 + 0.01 * seed;
}

static double
limit_a(int seed, double H, double lambda_s)
{
	return 0.1 + 0.001 * seed + 0.01 * H + 0.05 * lambda_s / 0.5;
}

static void
row(double p, int seed, double H, int nx, double lambda_s)
{
	double eps = (1.0 / nx) / lambda_s, n = (double)nx * nx;
	double a = limit_a(seed, H, lambda_s) + slope(seed) * eps;

	put("%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t1\t%.17g\t%d\t%d\t1\t1\t%g\t0.5\t"
	    "%.17g\t%d\n", p, a, a * n, (B0 + D1 * eps) * n, n, R0 + R1 * eps, nx,
	    nx, H, lambda_s, seed);
}

/* The counting floor of a linear Richardson pair, grids nx1 (finer) and
 * nx2 = nx1/2 at eps_c e1 and 2 e1: weights 2 and -1, n_cl/n_tot =
 * (B0 + D1 eps)/N (cstats.h). */
static double
pair_floor(double e1, int nx1)
{
	double n1 = (double)nx1 * nx1, n2 = n1 / 4;

	return RC_CSTATS_FLOOR_C * sqrt(4 * (B0 + D1 * e1) / n1 +
	    (B0 + D1 * 2 * e1) / n2);
}

static int
run(rc_cstats *res, const rc_cstats_opts *o, rc_err *err)
{
	rc_rowset rs;
	int rc;

	rc_rows_init(&rs);
	if (rc_rows_parse(&rs, buf, len, "syn.tsv", o->lenient, err) != 0) {
		rc_rows_free(&rs);
		memset(res, 0, sizeof(*res));
		return -1;
	}
	rc = rc_cstats_run(&rs, o, res, err);
	rc_rows_free(&rs);
	return rc;
}

static const char *
cell(const rc_cstats *res, size_t i, const char *name)
{
	if (i >= res->nrows)
		return "(no row)";
	for (size_t k = 0; k < res->row[i].n; k++)
		if (strcmp(res->row[i].name[k], name) == 0)
			return res->row[i].val[k];
	return "(no column)";
}

static double
num(const rc_cstats *res, size_t i, const char *name)
{
	const char *s = cell(res, i, name);
	char *end;
	double v = strtod(s, &end);

	return end != s && *end == '\0' ? v : -999;
}

/* Three seeds, two grids, H = 0.3 then 0.8: closed forms of every column. */
static void
test_ensemble(void)
{
	const double e1 = 0.125, p = 0.05;	/* finest eps: 16/128 */
	const double mean_c = 0.04;		/* mean slope over seeds 1..3 */
	const double hs[2] = { 0.3, 0.8 };
	rc_cstats_opts o;
	rc_cstats res;
	rc_err err;

	header();
	for (int h = 0; h < 2; h++)
		for (int s = 1; s <= 3; s++)
			for (int nx = 64; nx <= 128; nx *= 2)
				row(p, s, hs[h], nx, 0.0625);
	rc_cstats_opts_default(&o);
	test_int(run(&res, &o, &err), 0, "ensemble run");
	test_int((long long)res.nrows, 2, "one row per H (seeds, grids grouped)");
	test_int((long long)res.ncurves, 2, "one curve per H");
	for (size_t i = 0; i < res.nrows && i < 2; i++) {
		double H = hs[i], a0 = limit_a(2, H, 0.0625);
		/* each seed's bar: hypot(c_s e1, floor); their mean */
		double fl = pair_floor(e1, 128), mean_bar = 0;
		for (int s = 1; s <= 3; s++)
			mean_bar += hypot(slope(s) * e1, fl) / 3;
		double se = 0.001 / sqrt(3), err_a = sqrt(se * se + mean_bar * mean_bar);
		test_rel(num(&res, i, "H"), H, 0, "curves in input order: H");
		test_rel(num(&res, i, "a_r"), a0, 1e-12, "a_r = mean of a0 (H %g)", H);
		test_rel(num(&res, i, "a_richardson"), a0, 1e-12,
		    "a_richardson = mean a0 (H %g)", H);
		/* Continuum first: the spread of the limits, 0.001 s; averaging
		 * raw values first would give the spread at eps, 0.00225 s. */
		test_rel(num(&res, i, "a_r_sd"), 0.001, 1e-9, "a_r_sd of the limits");
		test_rel(num(&res, i, "a_r_se"), se, 1e-9, "a_r_se = sd/sqrt(3)");
		/* two points: each seed's error is its whole correction c_s e1
		 * with the counting floor */
		test_rel(num(&res, i, "a_r_err"), err_a, 1e-9,
		    "a_r_err = sqrt(se^2 + <hypot(c_s e1, floor)>^2)");
		test_rel(num(&res, i, "a_r_floor"), fl, 1e-12,
		    "a_r_floor = the seeds' mean floor");
		/* alpha_mod = (a(e1) - a(e2))/(b(e1) - b(e2)) = c_s/d, and
		 * a(e1) - alpha_mod b(e1) = a0 - c_s b0/d for every seed */
		test_rel(num(&res, i, "alpha_mod"), mean_c / D1, 1e-9,
		    "alpha_mod = <c_s>/d");
		test_rel(num(&res, i, "a_yastrebov_mod"), a0 - mean_c * B0 / D1,
		    1e-12, "a_yastrebov_mod = a0 - c b0/d");
		test_rel(num(&res, i, "a_yastrebov"), a0 + mean_c * e1 -
		    RC_YASTREBOV_ALPHA * (B0 + D1 * e1), 1e-12,
		    "a_yastrebov at the finest grid, alpha 0.1181");
		test_rel(num(&res, i, "a_yastrebov_011"), a0 + mean_c * e1 -
		    0.11 * (B0 + D1 * e1), 1e-12,
		    "a_yastrebov_011 at the finest grid, alpha 0.11");
		test_rel(num(&res, i, "gbar_c_ratio"), R0, 1e-12,
		    "gbar_c_ratio extrapolated to r0");
		double k = num(&res, i, "kappa"), ke = num(&res, i, "kappa_err");
		double x = sqrt(PI) * k * p / 2;
		test_rel(erf(x), a0, 1e-12, "Eq. 24: erf(sqrt(pi) kappa p*/2) = a_r");
		test_rel(ke, exp(x * x) * err_a / p, 1e-9,
		    "kappa_err = exp(x^2) a_r_err/p*");
		test_rel(num(&res, i, "kappa_c"), R0 * k, 1e-12, "kappa_c = r0 kappa");
		test_rel(num(&res, i, "kappa_c_err"), hypot(R0 * ke, k * R1 * e1),
		    1e-9, "kappa_c_err = hypot(r kappa_err, kappa r_err)");
		test_rel(res.point[i].kappa, k, 1e-15, "plot point = row kappa");
		test_int(num(&res, i, "n_seeds") == 3 && num(&res, i, "n_disc") == 2,
		    1, "n_seeds 3, n_disc 2");
		test_true(strcmp(cell(&res, i, "eps_c"), "0.125,0.25") == 0 &&
		    strcmp(cell(&res, i, "eps_c_used"), "0.125,0.25") == 0,
		    "eps_c and eps_c_used: %s, %s", cell(&res, i, "eps_c"),
		    cell(&res, i, "eps_c_used"));
		test_true(strcmp(cell(&res, i, "seed"), "(no column)") == 0,
		    "seed averaged out");
		test_true(strcmp(cell(&res, i, "method"), "richardson(1)+ensemble") == 0,
		    "method %s", cell(&res, i, "method"));
	}
	test_true(res.nwarn == 0, "no warnings");
	rc_cstats_free(&res);

	/* --alpha overrides only a_yastrebov */
	o.alpha = 0.2;
	o.per_seed = 1;
	test_int(run(&res, &o, &err), 0, "per-seed run");
	test_int((long long)res.nrows, 6, "per seed: one row per seed and H");
	for (size_t i = 0; i < res.nrows; i++) {
		int s = (int)num(&res, i, "seed");
		double H = num(&res, i, "H"), a1 = limit_a(s, H, 0.0625) +
		    slope(s) * e1;
		test_rel(num(&res, i, "a_r"), limit_a(s, H, 0.0625), 1e-12,
		    "per seed %d, H %g: a_r = a0", s, H);
		test_rel(num(&res, i, "a_r_err"), hypot(slope(s) * e1,
		    pair_floor(e1, 128)), 1e-9, "per seed: a_r_err = hypot(c_s e1, floor)");
		test_true(isnan(num(&res, i, "a_r_se")) && isnan(num(&res, i,
		    "a_r_sd")), "per seed: no ensemble sd, se");
		test_rel(num(&res, i, "a_yastrebov"), a1 - 0.2 * (B0 + D1 * e1),
		    1e-12, "--alpha 0.2 in a_yastrebov");
		test_rel(num(&res, i, "a_yastrebov_011"), a1 - 0.11 * (B0 + D1 * e1),
		    1e-12, "a_yastrebov_011 keeps 0.11");
		test_rel(num(&res, i, "alpha_mod"), slope(s) / D1, 1e-9,
		    "per seed alpha_mod = c_s/d");
	}
	rc_cstats_free(&res);
}

/* Three grids: the linear finest fit uses two of them, lsq all three. */
static void
test_used(void)
{
	rc_cstats_opts o;
	rc_cstats res;
	rc_err err;

	header();
	for (int nx = 64; nx <= 256; nx *= 2)
		row(0.1, 1, 0.8, nx, 0.0625);
	rc_cstats_opts_default(&o);
	o.per_seed = 1;
	test_int(run(&res, &o, &err), 0, "three grids");
	test_true(strcmp(cell(&res, 0, "eps_c"), "0.0625,0.125,0.25") == 0,
	    "eps_c lists all: %s", cell(&res, 0, "eps_c"));
	test_true(strcmp(cell(&res, 0, "eps_c_used"), "0.0625,0.125") == 0,
	    "finest fit uses the two finest: %s", cell(&res, 0, "eps_c_used"));
	rc_cstats_free(&res);
	o.cont.kind = RC_FIT_LSQ;
	test_int(run(&res, &o, &err), 0, "three grids, lsq");
	test_true(strcmp(cell(&res, 0, "eps_c_used"), "0.0625,0.125,0.25") == 0,
	    "lsq uses all: %s", cell(&res, 0, "eps_c_used"));
	test_rel(num(&res, 0, "a_r"), limit_a(1, 0.8, 0.0625), 1e-12,
	    "lsq recovers a0");
	rc_cstats_free(&res);
	o.cont.kind = RC_FIT_FINEST;
	o.no_extrapolate = 1;
	test_int(run(&res, &o, &err), 0, "three grids, no extrapolation");
	test_true(strcmp(cell(&res, 0, "eps_c_used"), "0.0625") == 0,
	    "raw: the finest only: %s", cell(&res, 0, "eps_c_used"));
	test_rel(num(&res, 0, "a_r"), limit_a(1, 0.8, 0.0625) + slope(1) / 16,
	    1e-14, "raw finest value");
	rc_cstats_free(&res);
}

/* lambda_s = 1/16 and 1/32 (eps_f = 1/8, 1/16): the fractal limit of the
 * seed means, with the linear weights w = 2 (eps_f 1/16), -1 (1/8). */
static void
test_fractal(void)
{
	rc_cstats_opts o;
	rc_cstats res;
	rc_err err;
	double se = 0.001 / sqrt(3);

	header();
	for (int s = 1; s <= 3; s++) {
		row(0.05, s, 0.8, 64, 0.0625);
		row(0.05, s, 0.8, 128, 0.0625);
		row(0.05, s, 0.8, 128, 0.03125);
		row(0.05, s, 0.8, 256, 0.03125);
	}
	rc_cstats_opts_default(&o);
	o.fractal = 1;
	test_int(run(&res, &o, &err), 0, "fractal run");
	test_int((long long)res.nrows, 1, "one row: two lambda_s joined");
	test_rel(num(&res, 0, "a_r"), limit_a(2, 0.8, 0), 1e-12,
	    "fractal limit of the seed mean");
	test_rel(num(&res, 0, "a_richardson"), limit_a(2, 0.8, 0), 1e-12,
	    "a_richardson carried by the weights");
	test_rel(num(&res, 0, "a_r_se"), sqrt(5) * se, 1e-9,
	    "a_r_se = sqrt(2^2 + 1^2) se");
	/* each member's error: sqrt(se^2 + (<c_s> e1)^2), e1 = eps_c = 1/8
	 * in both sets; the two-point model term is the whole correction in
	 * eps_f, 0.05 eps_f at the finest eps_f = 1/16 */
	double bar16 = 0, bar32 = 0;	/* mean per-seed bars, lambda_s 1/16, 1/32 */
	for (int s = 1; s <= 3; s++) {
		bar16 += hypot(slope(s) * 0.125, pair_floor(0.125, 128)) / 3;
		bar32 += hypot(slope(s) * 0.125, pair_floor(0.125, 256)) / 3;
	}
	double m16 = sqrt(se * se + bar16 * bar16), m32 = sqrt(se * se + bar32 * bar32);
	test_rel(num(&res, 0, "a_r_err"), sqrt(4 * m32 * m32 + m16 * m16 +
	    pow(0.05 / 16, 2)), 1e-9, "a_r_err = sqrt(sum w^2 err^2 + model^2)");
	test_rel(num(&res, 0, "a_r_floor"), hypot(2 * pair_floor(0.125, 256),
	    pair_floor(0.125, 128)), 1e-9, "a_r_floor = sqrt(sum w^2 floor^2)");
	double a011 = 2 * (limit_a(2, 0.8, 0.03125) + 0.04 * 0.125) -
	    (limit_a(2, 0.8, 0.0625) + 0.04 * 0.125) - 0.11 * (B0 + D1 * 0.125);
	test_rel(num(&res, 0, "a_yastrebov_011"), a011, 1e-12,
	    "a_yastrebov_011 carried by the weights");
	test_true(isnan(num(&res, 0, "a_r_sd")), "no sd after a limit");
	test_int((long long)num(&res, 0, "n_seeds"), 3, "n_seeds after the limit");
	test_true(strcmp(cell(&res, 0, "lambda_s"), "limit") == 0 &&
	    strcmp(cell(&res, 0, "eps_f"), "0.0625,0.125") == 0,
	    "lambda_s = limit, eps_f listed: %s", cell(&res, 0, "eps_f"));
	test_true(strcmp(cell(&res, 0, "method"),
	    "richardson(1)+ensemble+fractal(1)") == 0, "method %s",
	    cell(&res, 0, "method"));
	rc_cstats_free(&res);
}

/* The floor of a_r_err (cstats.h): three grids whose pair difference
 * vanishes by chance (curvature d eps^2 cancelled by a count fluctuation
 * on the coarsest grid), so the extrapolation's own estimate |D|/3 is
 * ~0 while the Richardson value misses a0 by 2 d e1^2.  Before the floor
 * a_r_err was that ~0 (4e-19 in a review's real case); now it is the
 * counting noise of the pair, a stated function of n_cl and n_tot. */
static void
test_floor(void)
{
	const int nx[3] = { 256, 128, 64 };
	const double ncl[3] = { 2000, 1000, 400 };
	const double a0 = 0.1, c = 0.04, d = 0.08, e1 = 0.0625;
	double a[3];
	rc_cstats_opts o;
	rc_cstats res;
	rc_err err;

	for (int pass = 0; pass < 2; pass++) {
		header();
		for (int i = 0; i < 3; i++) {
			double e = e1 * (1 << i), n = (double)nx[i] * nx[i];
			a[i] = a0 + c * e + d * e * e;
			if (i == 2 && pass == 0)
				a[i] -= 6 * d * e1 * e1;	/* D = 2a1 - 3a2 + a3 = 0 */
			put("0.05\t%.17g\t%.17g\t%.17g\t%.17g\t1\t1.2\t%d\t%d\t1\t1\t"
			    "0.8\t0.5\t0.0625\t1\n", a[i], a[i] * n, ncl[i], n,
			    nx[i], nx[i]);
		}
		rc_cstats_opts_default(&o);
		o.per_seed = 1;
		test_int(run(&res, &o, &err), 0, "floor run %d", pass);
		/* weights 2, -1, 0 of the finest pair */
		double fl = RC_CSTATS_FLOOR_C * sqrt(4 * ncl[0] / pow(65536, 2) +
		    ncl[1] / pow(16384, 2));
		double D = (2 * a[0] - a[1]) - (2 * a[1] - a[2]);
		test_rel(num(&res, 0, "a_r"), 2 * a[0] - a[1], 1e-12,
		    "floor case %d: a_r = the finest pair's Richardson value", pass);
		test_rel(num(&res, 0, "a_r_floor"), fl, 1e-12,
		    "a_r_floor = C sqrt(4 n_cl1/N1^2 + n_cl2/N2^2)");
		test_rel(num(&res, 0, "a_r_err"), hypot(fabs(D) / 3, fl), 1e-12,
		    "a_r_err = hypot(|D|/3, floor), |D| = %.3g", fabs(D));
		test_true(num(&res, 0, "a_r_err") >= fl && fl > 1e-4,
		    "a_r_err %.3g >= floor %.3g", num(&res, 0, "a_r_err"), fl);
		if (pass == 0)
			/* the miss 2 d e1^2 = 6.25e-4 is within 2 bars here */
			test_true(fabs(num(&res, 0, "a_r") - a0) <
			    2 * num(&res, 0, "a_r_err"), "vanishing D: the truth "
			    "within two bars (miss %.3g, bar %.3g)", fabs(num(&res,
			    0, "a_r") - a0), num(&res, 0, "a_r_err"));
		rc_cstats_free(&res);
	}
}

static void
test_errors(void)
{
	rc_cstats_opts o;
	rc_cstats res;
	rc_err err;
	const char *const by[] = { "nosuch" };

	rc_cstats_opts_default(&o);
	/* one grid per surface: an error naming group and file:line */
	header();
	row(0.05, 1, 0.8, 64, 0.0625);
	row(0.05, 2, 0.8, 64, 0.0625);
	test_int(run(&res, &o, &err), -1, "one discretisation fails");
	test_true(strstr(err.msg, "seed=1 (syn.tsv:2): 1 discretisation") != NULL &&
	    strstr(err.msg, "(and 1 more problem)") != NULL, "message: %s", err.msg);
	test_int((long long)res.nrows, 0, "nothing on failure");
	o.lenient = 1;
	test_int(run(&res, &o, &err), -1, "lenient: nothing left");
	test_true(strstr(err.msg, "no group left (2 skipped") != NULL,
	    "message: %s", err.msg);
	o.lenient = 0;

	/* a bad row and a duplicate */
	header();
	row(0.05, 1, 0.8, 64, 0.0625);
	row(0.05, 1, 0.8, 128, 0.0625);
	row(0.05, 1, 0.8, 128, 0.0625);
	test_int(run(&res, &o, &err), -1, "duplicate fails");
	test_true(strstr(err.msg, "syn.tsv:3 and syn.tsv:4: duplicate rows") != NULL,
	    "message: %s", err.msg);
	o.lenient = 1;
	test_int(run(&res, &o, &err), 0, "lenient drops the duplicate");
	test_int((long long)res.nskipped, 1, "one skipped");
	test_rel(num(&res, 0, "a_r"), limit_a(1, 0.8, 0.0625), 1e-12,
	    "result unchanged");
	rc_cstats_free(&res);
	o.lenient = 0;

	o.group_by = by;
	o.ngroup_by = 1;
	o.have_group_by = 1;
	test_int(run(&res, &o, &err), -1, "--group-by an absent column");
	test_true(strstr(err.msg, "no input has a column 'nosuch'") != NULL,
	    "message: %s", err.msg);
	rc_cstats_opts_default(&o);

	/* a_r outside [0, 1] after extrapolation: clamped, with a warning;
	 * no gbar_c: kappa_c NaN, with a warning of the other kind */
	len = 0;
	put("p_star\ta_r\tnx\tny\tlx\n0.05\t0.02\t64\t64\t1\n0.05\t0.005\t128\t128\t1\n");
	test_int(run(&res, &o, &err), 0, "negative extrapolation");
	test_rel(num(&res, 0, "a_r"), 0, 0, "clamped to 0");
	test_true(isnan(num(&res, 0, "kappa_c")) && isnan(num(&res, 0,
	    "a_yastrebov")), "no gbar_c, n_c: nan");
	int clamped = 0, missing = 0;
	for (size_t i = 0; i < res.nwarn; i++) {
		clamped += res.warn_kind[i] == RC_CSTATS_WARN_CLAMPED;
		missing += res.warn_kind[i] == RC_CSTATS_WARN_MISSING;
	}
	test_int(clamped, 1, "one clamp warning");
	test_int(missing, 2, "two missing-column warnings (gbar_c, n_c)");
	rc_cstats_free(&res);

	len = 0;
	put("p_star\ta_r\n");
	test_int(run(&res, &o, &err), -1, "header only");
	test_true(strstr(err.msg, "no result rows") != NULL, "message: %s", err.msg);
}

static void
test_parse(void)
{
	rc_extrap_opts e;
	rc_err err;

	memset(&e, 0, sizeof(e));
	test_int(rc_extrap_parse("1,2", 3, &e, &err), 0, "parse 1,2");
	test_int(e.nterms == 2 && e.exponent[1] == 2 && !e.auto_order, 1,
	    "two exponents");
	test_int(rc_extrap_parse("auto", 1, &e, &err), 0, "parse auto");
	test_int(e.auto_order, 1, "auto");
	test_int(rc_extrap_parse("1,2", 1, &e, &err), -1, "too many");
	test_int(rc_extrap_parse("2,1", 3, &e, &err), -1, "decreasing");
	test_int(rc_extrap_parse("0", 3, &e, &err), -1, "zero");
	test_int(rc_extrap_parse("1,", 3, &e, &err), -1, "trailing comma");
	test_int(rc_extrap_parse("", 3, &e, &err), -1, "empty");
	test_int(e.auto_order, 1, "unchanged on failure");
}

int
main(void)
{
	test_ensemble();
	test_used();
	test_fractal();
	test_floor();
	test_errors();
	test_parse();
	return test_summary();
}
