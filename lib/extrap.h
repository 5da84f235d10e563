/* SPDX-License-Identifier: GPL-3.0-or-later */
/* extrap.h - limits of discretised results: Richardson extrapolation in a
 * small parameter eps (eps_c = da/lambda_s, eps_f = lambda_s/lambda_r,
 * eps_t = lambda_r/L of Wang & Mueser 2020, sections 2 and 4), the
 * Yastrebov estimate (Eq. 22) and its modified form, ensemble statistics,
 * and the eps(p) schedule of Eq. 27.
 */
#ifndef RC_EXTRAP_H
#define RC_EXTRAP_H

#include <stddef.h>
#include "rc_err.h"

/* Yastrebov et al.'s alpha = (pi - 1 + ln 2)/24 = 0.11811... */
#define RC_YASTREBOV_ALPHA ((3.14159265358979323846 - 1 + \
	0.69314718055994530942) / 24)
#define RC_EXTRAP_MAXTERMS 3

/* Model y(eps) = y0 + sum_j c_j eps^k_j (fixed exponents k_j), or, with
 * auto_order, y0 + c eps^k with k fitted. */
enum rc_fit_kind {
	RC_FIT_FINEST = 0,	/* exact through the nterms+1 smallest eps */
	RC_FIT_LSQ		/* least squares over all points */
};

typedef struct rc_extrap_opts {
	size_t nterms;				/* 1 .. RC_EXTRAP_MAXTERMS */
	double exponent[RC_EXTRAP_MAXTERMS];	/* increasing, > 0 */
	int auto_order;				/* fit k (needs >= 3 points) */
	enum rc_fit_kind kind;
} rc_extrap_opts;

typedef struct rc_fit {
	double value;		/* the estimate at eps = 0 */
	double err;		/* error estimate (see below) */
	double order;		/* leading exponent used (fitted with auto) */
	double order_err;	/* standard error of a fitted exponent, else 0 */
	size_t nused;		/* points the estimate depends on */
} rc_fit;

/* A model from text: "auto", or at most maxterms comma-separated
 * exponents, increasing, in (0, 10].  e is unchanged on failure; the kind
 * is kept. */
int rc_extrap_parse(const char *text, size_t maxterms, rc_extrap_opts *e,
    rc_err *err);

/* y0 from n points (eps_i > 0, distinct, any order; y_i finite).
 * err: with more points than the model needs, the difference between this
 * estimate and the same model through the next-coarser points (FINEST), or
 * the least-squares standard error of y0 (LSQ, auto with > 3 points: from
 * the residuals, Gauss-Newton for the exponent); with exactly as many
 * points as parameters, the difference from the model with one term less
 * (for the linear model, the finest raw value).
 * weight (n values, may be NULL): y0 = sum_i weight_i y_i for fixed
 * exponents; for auto, the linearised sensitivity d y0 / d y_i. */
int rc_extrapolate(const double *eps, const double *y, size_t n,
    const rc_extrap_opts *o, rc_fit *fit, double *weight, rc_err *err);

/* Eq. 22: (n_c - alpha n_cl) / n_tot. */
double rc_yastrebov(double n_c, double n_cl, double n_tot, double alpha);
/* alpha that makes Eq. 22 agree at two discretisations:
 * (n_c1/N1 - n_c2/N2) / (n_cl1/N1 - n_cl2/N2); NaN if undefined. */
double rc_yastrebov_alpha_mod(double n_c1, double n_cl1, double n_tot1,
    double n_c2, double n_cl2, double n_tot2);

/* The counting noise of an estimate sum_i w_i a_i of contact fractions
 * a_i = n_c_i / n_tot_i: which pixels along a contact line are counted
 * in contact changes from grid to grid like a random draw, of variance
 * proportional to the n_cl_i points on the line, so the estimate scatters
 * by
 *   sqrt(sum_i w_i^2 n_cl_i / n_tot_i^2)
 * times a constant (measured: RC_CSTATS_FLOOR_C, cstats.h).  NaN if any
 * n_cl_i or n_tot_i is missing (NaN) or n_tot_i <= 0. */
double rc_count_noise(const double *w, const double *n_cl,
    const double *n_tot, size_t n);

typedef struct rc_ensemble {
	size_t n;
	double mean;
	double sd;	/* sample standard deviation (n - 1); NaN if n < 2 */
	double se;	/* sd / sqrt(n); NaN if n < 2 */
} rc_ensemble;

int rc_ensemble_stats(const double *x, size_t n, rc_ensemble *e, rc_err *err);

/* Eq. 27: eps_ref (p / p_ref)^(1/4); NaN unless all three are > 0. */
double rc_eps_schedule(double eps_ref, double p_ref, double p);

#endif
