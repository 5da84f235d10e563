/* SPDX-License-Identifier: GPL-3.0-or-later */
/* extrap.c - Richardson extrapolation, Yastrebov estimates, ensembles.
 *
 * Fits are linear least squares in the basis {1, eps^k_1, ...} through
 * GSL's SVD solver, on eps scaled by its largest value (the value at
 * eps = 0 does not depend on that scale, the conditioning does).  With as
 * many points as parameters the fit is the classical Richardson formula,
 * e.g. y0 = (eps2 y1 - eps1 y2)/(eps2 - eps1) for the linear model.
 */
#include "extrap.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_multifit.h>
#include <gsl/gsl_statistics_double.h>

#define KMIN 0.05	/* range searched for a fitted exponent */
#define KMAX 10.0

/* Least squares of y over the m points idx[] in the basis of columns
 * col(eps) given by basis(); value, its standard error (NaN without
 * residual degrees of freedom), chi^2 and the weights d y0 / d y. */
typedef struct lsq {
	double value, se, chisq;
	double coef[RC_EXTRAP_MAXTERMS + 2];
	double cov00;
	double order_se;	/* with the exponent's column: its standard error */
} lsq;

/* Column j of the design matrix: 1, then eps^k_j; with deriv_c set, an
 * extra last column c eps^k ln eps (the exponent's Jacobian). */
static int
fit_linear(const double *eps, const double *y, const size_t *idx, size_t m,
    const double *k, size_t nk, double deriv_c, int with_deriv, lsq *out,
    double *weight, rc_err *err)
{
	size_t p = 1 + nk + (with_deriv != 0);
	gsl_matrix *X = gsl_matrix_alloc(m, p), *cov = gsl_matrix_alloc(p, p);
	gsl_vector *yy = gsl_vector_alloc(m), *w = gsl_vector_alloc(m);
	gsl_vector *c = gsl_vector_alloc(p);
	gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc(m, p);
	int rc = -1;

	if (!X || !cov || !yy || !w || !c || !ws) {
		rc_seterr(err, "out of memory");
		goto out;
	}
	for (size_t i = 0; i < m; i++) {
		double e = eps[idx[i]];
		gsl_matrix_set(X, i, 0, 1.0);
		for (size_t j = 0; j < nk; j++)
			gsl_matrix_set(X, i, 1 + j, pow(e, k[j]));
		if (with_deriv)
			gsl_matrix_set(X, i, p - 1, deriv_c * pow(e, k[0]) * log(e));
		gsl_vector_set(yy, i, y[idx[i]]);
		gsl_vector_set(w, i, 1.0);
	}
	double chisq;
	/* Unit weights: cov is (X^T X)^-1, unscaled by the residuals. */
	if (gsl_multifit_wlinear(X, w, yy, c, cov, &chisq, ws) != 0) {
		rc_seterr(err, "least-squares fit failed");
		goto out;
	}
	out->value = gsl_vector_get(c, 0);
	for (size_t j = 0; j < p; j++)
		out->coef[j] = gsl_vector_get(c, j);
	out->chisq = chisq;
	out->cov00 = gsl_matrix_get(cov, 0, 0);
	out->se = m > p ? sqrt(chisq / (double)(m - p) * out->cov00) : NAN;
	if (weight != NULL)
		for (size_t i = 0; i < m; i++) {
			double s = 0;
			for (size_t j = 0; j < p; j++)
				s += gsl_matrix_get(cov, 0, j) * gsl_matrix_get(X, i, j);
			weight[idx[i]] = s;
		}
	if (with_deriv) {
		double vk = gsl_matrix_get(cov, p - 1, p - 1);
		out->order_se = m > p ?
		    sqrt(chisq / (double)(m - p) * vk) : NAN;
	}
	rc = 0;
out:
	gsl_matrix_free(X);
	gsl_matrix_free(cov);
	gsl_vector_free(yy);
	gsl_vector_free(w);
	gsl_vector_free(c);
	if (ws)
		gsl_multifit_linear_free(ws);
	return rc;
}

/* Indices of eps in increasing order (a handful of points: insertion). */
static void
sort_by_eps(const double *eps, size_t *idx, size_t n)
{
	for (size_t i = 1; i < n; i++)
		for (size_t j = i; j > 0 && eps[idx[j - 1]] > eps[idx[j]]; j--) {
			size_t t = idx[j];
			idx[j] = idx[j - 1];
			idx[j - 1] = t;
		}
}

/* log of (e3^k - e2^k)/(e2^k - e1^k), increasing in k for e1 < e2 < e3. */
static double
diff_ratio(double e1, double e2, double e3, double k)
{
	return log((pow(e3, k) - pow(e2, k)) / (pow(e2, k) - pow(e1, k)));
}

/* Exponent through three points (sorted, scaled), by bisection. */
static int
order_three(const double *e, const double *y, double *k, rc_err *err)
{
	double d1 = y[1] - y[0], d2 = y[2] - y[1];

	if (!(d1 * d2 > 0))
		return rc_seterr(err, "no power law through the three finest points: "
		    "the differences %.6g and %.6g %s", d1, d2,
		    d1 == 0 || d2 == 0 ? "include zero" : "change sign");
	double target = log(d2 / d1);
	double lo = KMIN, hi = KMAX;
	double flo = diff_ratio(e[0], e[1], e[2], lo) - target;
	double fhi = diff_ratio(e[0], e[1], e[2], hi) - target;
	if (!(flo <= 0 && fhi >= 0))
		return rc_seterr(err, "fitted exponent outside [%g, %g] (successive "
		    "differences %.6g, %.6g)", KMIN, KMAX, d1, d2);
	for (int it = 0; it < 200 && hi - lo > 1e-15 * hi; it++) {
		double mid = 0.5 * (lo + hi);
		if (diff_ratio(e[0], e[1], e[2], mid) - target < 0)
			lo = mid;
		else
			hi = mid;
	}
	*k = 0.5 * (lo + hi);
	return 0;
}

/* chi^2 of the best y0 + c eps^k over all points. */
static double
chisq_at(const double *eps, const double *y, const size_t *idx, size_t n,
    double k)
{
	lsq f;
	if (fit_linear(eps, y, idx, n, &k, 1, 0, 0, &f, NULL, NULL) != 0)
		return INFINITY;
	return f.chisq;
}

static int
order_profile(const double *eps, const double *y, const size_t *idx, size_t n,
    double *k, rc_err *err)
{
	enum { NGRID = 120 };
	double best = INFINITY;
	int ib = -1;

	for (int i = 0; i < NGRID; i++) {
		double kk = KMIN * pow(KMAX / KMIN, (double)i / (NGRID - 1));
		double c = chisq_at(eps, y, idx, n, kk);
		if (c < best) {
			best = c;
			ib = i;
		}
	}
	if (ib <= 0 || ib >= NGRID - 1)
		return rc_seterr(err, "fitted exponent at the edge of [%g, %g]: the "
		    "points do not follow a power law", KMIN, KMAX);
	/* Golden section between the grid neighbours. */
	double a = KMIN * pow(KMAX / KMIN, (double)(ib - 1) / (NGRID - 1));
	double b = KMIN * pow(KMAX / KMIN, (double)(ib + 1) / (NGRID - 1));
	const double g = 0.5 * (sqrt(5.0) - 1);
	double x1 = b - g * (b - a), x2 = a + g * (b - a);
	double f1 = chisq_at(eps, y, idx, n, x1), f2 = chisq_at(eps, y, idx, n, x2);
	for (int it = 0; it < 100 && b - a > 1e-12 * b; it++) {
		if (f1 < f2) {
			b = x2;
			x2 = x1;
			f2 = f1;
			x1 = b - g * (b - a);
			f1 = chisq_at(eps, y, idx, n, x1);
		} else {
			a = x1;
			x1 = x2;
			f1 = f2;
			x2 = a + g * (b - a);
			f2 = chisq_at(eps, y, idx, n, x2);
		}
	}
	*k = 0.5 * (a + b);
	return 0;
}

static int extrapolate(const double *eps_in, const double *y, size_t n,
    const rc_extrap_opts *o, rc_fit *fit, double *weight, rc_err *err);

/* Fit y - y_finest and add y_finest back: the limit of constant data is
 * then exactly that constant (a full contact stays a_r = 1), and the fit
 * works on the small differences. */
/* The error that a neglected next term d eps^(k+1) leaves in the
 * one-term estimate through (a, b): d (b^k a^(k+1) - a^k b^(k+1)) /
 * (b^k - a^k), per unit d. */
static double
next_order_residue(double a, double b, double k)
{
	double ak = pow(a, k), bk = pow(b, k);

	return (bk * ak * a - ak * bk * b) / (bk - ak);
}

/* Which share of the difference between the estimates through (e1, e2)
 * and (e2, e3) is the error of the finer one, if that next term is what
 * both miss: e1 / (e3 - e1) for the linear model, 1/3 for halvings.
 * Measured (bench/accuracy/coverage.sh): with the whole difference as
 * the error, a nominal one-sigma interval covered 90% of 48 surfaces;
 * this share is what brings it to about 68%. */
static double
next_order_share(double e1, double e2, double e3, double k)
{
	double fine = next_order_residue(e1, e2, k);
	double coarse = next_order_residue(e2, e3, k);

	return fine != coarse ? fabs(fine / (fine - coarse)) : 1;
}

int
rc_extrapolate(const double *eps, const double *y, size_t n,
    const rc_extrap_opts *o, rc_fit *fit, double *weight, rc_err *err)
{
	double *dy, shift;
	size_t finest = 0;
	int rc;

	if (n == 0)
		return extrapolate(eps, y, n, o, fit, weight, err);
	for (size_t i = 1; i < n; i++)
		if (eps[i] < eps[finest])
			finest = i;
	shift = y[finest];
	if (!isfinite(shift))
		return extrapolate(eps, y, n, o, fit, weight, err);
	if ((dy = malloc(n * sizeof(*dy))) == NULL)
		return rc_seterr(err, "out of memory");
	for (size_t i = 0; i < n; i++)
		dy[i] = y[i] - shift;
	rc = extrapolate(eps, dy, n, o, fit, weight, err);
	if (rc == 0)
		fit->value += shift;
	free(dy);
	return rc;
}

/* Long: the Richardson fit, its weights and its error estimate share the
 * per-grid residuals. */
static int
extrapolate(const double *eps_in, const double *y, size_t n,
    const rc_extrap_opts *o, rc_fit *fit, double *weight, rc_err *err)
{
	size_t nk = o->auto_order ? 1 : o->nterms, need = o->auto_order ? 3 : nk + 1;
	double *eps = NULL, emax = 0;
	size_t *idx = NULL;
	lsq f, g;
	int rc = -1;

	memset(fit, 0, sizeof(*fit));
	if (!o->auto_order && (nk < 1 || nk > RC_EXTRAP_MAXTERMS))
		return rc_seterr(err, "internal: %zu correction terms", nk);
	for (size_t j = 0; !o->auto_order && j < nk; j++)
		if (!(o->exponent[j] > 0) || (j > 0 && !(o->exponent[j] > o->exponent[j - 1])))
			return rc_seterr(err, "exponents must be positive and increasing");
	if (n < need)
		return rc_seterr(err, "%zu point%s, the model needs at least %zu", n,
		    n == 1 ? "" : "s", need);
	for (size_t i = 0; i < n; i++) {
		if (!(eps_in[i] > 0) || !isfinite(eps_in[i]))
			return rc_seterr(err, "eps = %g: must be positive and finite",
			    eps_in[i]);
		if (!isfinite(y[i]))
			return rc_seterr(err, "value %g at eps = %g is not finite", y[i],
			    eps_in[i]);
		emax = fmax(emax, eps_in[i]);
	}
	if ((eps = malloc(n * sizeof(*eps))) == NULL ||
	    (idx = malloc(n * sizeof(*idx))) == NULL) {
		rc_seterr(err, "out of memory");
		goto out;
	}
	for (size_t i = 0; i < n; i++) {
		eps[i] = eps_in[i] / emax;
		idx[i] = i;
	}
	sort_by_eps(eps, idx, n);
	for (size_t i = 1; i < n; i++)
		if (eps[idx[i]] == eps[idx[i - 1]]) {
			rc_seterr(err, "two points at the same eps = %g", eps_in[idx[i]]);
			goto out;
		}
	if (weight != NULL)
		for (size_t i = 0; i < n; i++)
			weight[i] = 0;

	if (o->auto_order) {
		double k, e3[3], y3[3];
		for (int i = 0; i < 3; i++) {
			e3[i] = eps[idx[i]];
			y3[i] = y[idx[i]];
		}
		if (n == 3 ? order_three(e3, y3, &k, err) :
		    order_profile(eps, y, idx, n, &k, err))
			goto out;
		size_t m = n == 3 ? 3 : n;
		if (fit_linear(eps, y, idx, n, &k, 1, 0, 0, &f, NULL, err) != 0)
			goto out;
		/* Gauss-Newton Jacobian [1, eps^k, c eps^k ln eps]: the weights
		 * and, with residual freedom, the standard errors. */
		if (fit_linear(eps, y, idx, n, &k, 1, f.coef[1], 1, &g, weight, err) != 0)
			goto out;
		fit->value = f.value;
		fit->order = k;
		fit->nused = m;
		if (n > 3) {
			fit->err = g.se;
			fit->order_err = g.order_se;
		} else {
			double one = 1;
			lsq lin;
			if (fit_linear(eps, y, idx, 2, &one, 1, 0, 0, &lin, NULL, err) != 0)
				goto out;
			fit->err = fabs(f.value - lin.value);
		}
		rc = 0;
		goto out;
	}

	size_t m = o->kind == RC_FIT_LSQ ? n : need;
	if (fit_linear(eps, y, idx, m, o->exponent, nk, 0, 0, &f, weight, err) != 0)
		goto out;
	fit->value = f.value;
	fit->order = o->exponent[0];
	fit->nused = m;
	if (o->kind == RC_FIT_LSQ && n > need)
		fit->err = f.se;
	else if (n > need) {
		/* The same model one point coarser. */
		if (fit_linear(eps, y, idx + 1, need, o->exponent, nk, 0, 0, &g, NULL,
		    err) != 0)
			goto out;
		fit->err = fabs(f.value - g.value);
		if (nk == 1)
			fit->err *= next_order_share(eps[idx[0]], eps[idx[1]],
			    eps[idx[2]], o->exponent[0]);
	} else if (nk == 1)
		fit->err = fabs(f.value - y[idx[0]]);
	else {
		if (fit_linear(eps, y, idx, need - 1, o->exponent, nk - 1, 0, 0, &g,
		    NULL, err) != 0)
			goto out;
		fit->err = fabs(f.value - g.value);
	}
	rc = 0;
out:
	free(eps);
	free(idx);
	return rc;
}

int
rc_extrap_parse(const char *text, size_t maxterms, rc_extrap_opts *e,
    rc_err *err)
{
	double k[RC_EXTRAP_MAXTERMS];
	size_t n = 0;
	const char *p = text;
	char *end;

	if (strcmp(text, "auto") == 0) {
		e->auto_order = 1;
		e->nterms = 1;
		e->exponent[0] = 1;
		return 0;
	}
	if (maxterms > RC_EXTRAP_MAXTERMS)
		maxterms = RC_EXTRAP_MAXTERMS;
	for (;;) {
		if (n == maxterms)
			return rc_seterr(err, "at most %zu exponent%s", maxterms,
			    maxterms == 1 ? "" : "s");
		k[n] = strtod(p, &end);
		if (end == p || (*end != ',' && *end != '\0') || isspace((unsigned char)*p))
			return rc_seterr(err, "want auto or comma-separated numbers");
		if (!(k[n] > 0 && k[n] <= 10) || (n > 0 && !(k[n] > k[n - 1])))
			return rc_seterr(err, "exponents must be in (0, 10] and "
			    "increasing");
		n++;
		if (*end == '\0')
			break;
		p = end + 1;
	}
	e->auto_order = 0;
	e->nterms = n;
	memcpy(e->exponent, k, n * sizeof(*k));
	return 0;
}

double
rc_yastrebov(double n_c, double n_cl, double n_tot, double alpha)
{
	if (!(n_tot > 0))
		return NAN;
	return (n_c - alpha * n_cl) / n_tot;
}

double
rc_yastrebov_alpha_mod(double n_c1, double n_cl1, double n_tot1, double n_c2,
    double n_cl2, double n_tot2)
{
	if (!(n_tot1 > 0) || !(n_tot2 > 0))
		return NAN;
	double den = n_cl1 / n_tot1 - n_cl2 / n_tot2;
	if (den == 0 || !isfinite(den))
		return NAN;
	return (n_c1 / n_tot1 - n_c2 / n_tot2) / den;
}

double
rc_count_noise(const double *w, const double *n_cl, const double *n_tot,
    size_t n)
{
	double v = 0;

	for (size_t i = 0; i < n; i++) {
		if (!(n_tot[i] > 0) || isnan(n_cl[i]))
			return NAN;
		v += w[i] * w[i] * n_cl[i] / (n_tot[i] * n_tot[i]);
	}
	return sqrt(v);
}

int
rc_ensemble_stats(const double *x, size_t n, rc_ensemble *e, rc_err *err)
{
	if (n == 0)
		return rc_seterr(err, "empty ensemble");
	for (size_t i = 0; i < n; i++)
		if (!isfinite(x[i]))
			return rc_seterr(err, "ensemble member %zu is not finite", i + 1);
	e->n = n;
	e->mean = gsl_stats_mean(x, 1, n);
	e->sd = n > 1 ? gsl_stats_sd_m(x, 1, n, e->mean) : NAN;
	e->se = n > 1 ? e->sd / sqrt((double)n) : NAN;
	return 0;
}

double
rc_eps_schedule(double eps_ref, double p_ref, double p)
{
	if (!(eps_ref > 0) || !(p_ref > 0) || !(p > 0) || !isfinite(eps_ref) ||
	    !isfinite(p_ref) || !isfinite(p))
		return NAN;
	return eps_ref * pow(p / p_ref, 0.25);
}
