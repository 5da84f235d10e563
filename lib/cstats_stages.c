/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cstats_stages.c - contact-stats' stages: the continuum limit of each
 * surface (Richardson in eps_c), the ensemble average over seeds, and the
 * fractal and thermodynamic limits (contact-stats(1) has the rules).
 */
#include "cstats_impl.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static int
by_key_rec(const void *a, const void *b)
{
	const struct rec *x = a, *y = b;
	int k = strcmp(x->key, y->key);

	if (k)
		return k;
	if (x->eps_c != y->eps_c)
		return (x->eps_c > y->eps_c) - (x->eps_c < y->eps_c);
	return (x->row > y->row) - (x->row < y->row);
}

static int
by_key_est(const void *a, const void *b)
{
	const struct est *x = a, *y = b;
	int k = strcmp(x->key, y->key);

	if (k)
		return k;
	return (x->row > y->row) - (x->row < y->row);
}

/* Duplicates (same key, same eps_c): an error, or with lenient the later
 * row is dropped.  r is sorted; returns the rows kept. */
static size_t
drop_duplicates(struct ctx *c, struct rec *r, size_t n)
{
	size_t kept = n ? 1 : 0;

	for (size_t i = 1; i < n; i++) {
		struct rec *prev = &r[kept - 1];
		if (strcmp(r[i].key, prev->key) == 0 && r[i].eps_c == prev->eps_c) {
			rc__cs_bad(c,
			    "%s and %s: duplicate rows (same surface, p_star and "
			    "grid %ldx%ld)", rc__cs_where(c, prev->row),
			    rc__cs_where(c, r[i].row), r[i].nx, r[i].ny);
			if (c->o->lenient)
				continue;
		}
		r[kept++] = r[i];
	}
	rc__cs_check_errors(c);
	return kept;
}

/* The Richardson fit of one discretisation set r[0..m-1] (eps increasing)
 * into x, its error bar with the counting floor (cstats.h); -1 (reported)
 * if it cannot be done.  eps, y, w: scratch of m values; cnt: of 2 m. */
static int
continuum_fit(struct ctx *c, const struct rec *r, size_t m, struct est *x,
    double *eps, double *y, double *w, double *cnt)
{
	const rc_cstats_opts *o = c->o;
	rc_extrap_opts model = o->cont;
	rc_fit fit, gfit;
	rc_err err;
	size_t nused = 0, need;
	int have_g = 1;

	/* --order auto fits the exponent where three or more grids exist;
	 * with two it falls back to the linear model, flagged by order_err =
	 * NaN. */
	if (model.auto_order && m == 2) {
		model.auto_order = 0;
		model.nterms = 1;
		model.exponent[0] = 1;
		model.kind = RC_FIT_FINEST;
	}
	need = model.auto_order ? 3 : model.nterms + 1;
	if (m < need) {
		rc__cs_bad(c,
		    "%s (%s): %zu discretisation%s, the extrapolation needs %zu "
		    "(or use --no-extrapolate)", rc__cs_group_name(c, r[0].row,
		    r[0].p_star, 1), rc__cs_where(c, r[0].row), m, m == 1 ? "" :
		    "s", need);
		return -1;
	}
	for (size_t i = 0; i < m; i++) {
		eps[i] = r[i].eps_c;
		y[i] = r[i].a_r;
		have_g &= !isnan(r[i].gratio);
	}
	if (rc_extrapolate(eps, y, m, &model, &fit, w, &err) != 0) {
		rc__cs_bad(c, "%s (%s): a_r: %s", rc__cs_group_name(c, r[0].row,
		    r[0].p_star, 1), rc__cs_where(c, r[0].row), err.msg);
		return -1;
	}
	x->a_r = x->a_rich = fit.value;
	for (size_t i = 0; i < m; i++) {
		cnt[i] = r[i].n_cl;
		cnt[m + i] = r[i].n_tot;
	}
	x->a_r_floor = RC_CSTATS_FLOOR_C * rc_count_noise(w, cnt, cnt + m, m);
	if (isnan(x->a_r_floor))
		x->a_r_floor = 0;	/* no counts: warned at input */
	x->a_r_err = hypot(fit.err, x->a_r_floor);
	x->order = fit.order;
	x->order_err = o->cont.auto_order && !model.auto_order ? NAN :
	    fit.order_err;
	/* the points the estimate depends on: non-zero weight */
	for (size_t i = 0; i < m; i++)
		if (w[i] != 0)
			y[nused++] = eps[i];
	x->eps_c_used = rc__cs_list_of(c, y, nused);
	if (have_g) {
		for (size_t i = 0; i < m; i++)
			y[i] = r[i].gratio;
		/* gbar_c/gbar with the same model; with auto the exponent is
		 * fitted for this ratio separately, and when no power law fits,
		 * the finest value is used with its last change as error. */
		if (rc_extrapolate(eps, y, m, &model, &gfit, NULL, &err) == 0) {
			x->gratio = gfit.value;
			x->gratio_err = gfit.err;
		} else {
			x->gratio = r[0].gratio;
			x->gratio_err = fabs(r[0].gratio - r[1].gratio);
		}
	}
	return 0;
}

/* Continuum limit of each surface (set of discretisations) at each p*. */
struct est *
rc__cs_stage_continuum(struct ctx *c, struct rec *r, size_t n, size_t *nout)
{
	struct est *e = rc__cs_pool_alloc(c, n, sizeof(*e));
	double *eps = rc__cs_pool_alloc(c, n, sizeof(double));
	double *y = rc__cs_pool_alloc(c, n, sizeof(double));
	double *w = rc__cs_pool_alloc(c, n, sizeof(double));
	double *cnt = rc__cs_pool_alloc(c, 2 * n, sizeof(double));
	size_t ne = 0;

	for (size_t i = 0; i < n; i++)
		r[i].key = rc__cs_make_key(c, r[i].row, r[i].p_star, 1, 1);
	qsort(r, n, sizeof(*r), by_key_rec);
	n = drop_duplicates(c, r, n);
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strcmp(r[b].key, r[a].key) == 0; b++)
			;
		size_t m = b - a;
		const struct rec *f = &r[a];	/* finest: smallest eps_c */
		struct est *x = &e[ne];
		memset(x, 0, sizeof(*x));
		x->row = f->row;
		x->p_star = f->p_star;
		x->n_seeds = 1;
		x->n_disc = m;
		x->a_r_sd = x->a_r_se = NAN;
		x->eps_f = f->lambda_s / f->lambda_r;
		x->eps_t = f->lambda_r / f->lx;
		for (size_t i = 0; i < m; i++)
			eps[i] = r[a + i].eps_c;
		x->eps_c_all = rc__cs_list_of(c, eps, m);
		x->eps_f_list = rc__cs_list_of(c, &x->eps_f, 1);
		x->eps_t_list = rc__cs_list_of(c, &x->eps_t, 1);
		x->a_y = rc_yastrebov(f->n_c, f->n_cl, f->n_tot, c->o->alpha);
		x->a_y011 = rc_yastrebov(f->n_c, f->n_cl, f->n_tot,
		    RC_YASTREBOV_ALPHA_011);
		x->alpha_mod = x->a_ymod = NAN;
		if (m >= 2) {
			x->alpha_mod = rc_yastrebov_alpha_mod(f->n_c, f->n_cl, f->n_tot,
			    r[a + 1].n_c, r[a + 1].n_cl, r[a + 1].n_tot);
			x->a_ymod = rc_yastrebov(f->n_c, f->n_cl, f->n_tot, x->alpha_mod);
		}
		x->gratio = x->gratio_err = NAN;
		if (c->o->no_extrapolate) {
			x->a_r = f->a_r;
			x->a_r_err = 0;
			x->a_rich = NAN;
			x->gratio = f->gratio;
			x->gratio_err = 0;
			x->order = x->order_err = NAN;
			x->n_disc = 1;
			x->eps_c_used = rc__cs_list_of(c, &f->eps_c, 1);
		} else if (continuum_fit(c, f, m, x, eps, y, w, cnt) != 0)
			continue;
		ne++;
	}
	rc__cs_check_errors(c);
	*nout = ne;
	return e;
}

/* Ensemble over seeds: mean, sd, se, and the error of the mean combined
 * with the mean extrapolation error (systematic: it does not average
 * out). */
struct est *
rc__cs_stage_ensemble(struct ctx *c, struct est *in, size_t n, size_t *nout)
{
	struct est *e = rc__cs_pool_alloc(c, n, sizeof(*e));
	double *v = rc__cs_pool_alloc(c, n, sizeof(double));
	size_t ne = 0;
	rc_err err;

	for (size_t i = 0; i < n; i++)
		in[i].key = rc__cs_make_key(c, in[i].row, in[i].p_star, 0, 1);
	qsort(in, n, sizeof(*in), by_key_est);
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strcmp(in[b].key, in[a].key) == 0; b++)
			;
		size_t m = b - a;
		struct est *x = &e[ne++];
		rc_ensemble st;
		double mean_err = 0, mean_gerr = 0;
		*x = in[a];
		x->n_seeds = m;
#define MEAN(field) do { \
		double s_ = 0; \
		for (size_t i_ = a; i_ < b; i_++) \
			s_ += in[i_].field; \
		x->field = s_ / (double)m; \
	} while (0)
		MEAN(a_rich);
		MEAN(a_y);
		MEAN(a_y011);
		MEAN(a_ymod);
		MEAN(alpha_mod);
		MEAN(order);
		MEAN(order_err);
		MEAN(a_r_floor);
#undef MEAN
		for (size_t i = a; i < b; i++) {
			v[i - a] = in[i].a_r;
			mean_err += in[i].a_r_err / (double)m;
			mean_gerr += in[i].gratio_err / (double)m;
			if (in[i].n_disc < x->n_disc)
				x->n_disc = in[i].n_disc;
			x->eps_c_all = rc__cs_list_merge(c, x->eps_c_all,
			    in[i].eps_c_all);
			x->eps_c_used = rc__cs_list_merge(c, x->eps_c_used,
			    in[i].eps_c_used);
		}
		if (rc_ensemble_stats(v, m, &st, &err) != 0)
			rc__cs_fail(c, "%s: %s", rc__cs_group_name(c, x->row,
			    x->p_star, 0), err.msg);
		x->a_r = st.mean;
		x->a_r_sd = st.sd;
		x->a_r_se = st.se;
		x->a_r_err = sqrt((m > 1 ? st.se * st.se : 0) + mean_err * mean_err);
		x->gratio = x->gratio_err = NAN;
		for (size_t i = a; i < b; i++)
			v[i - a] = in[i].gratio;
		if (rc_ensemble_stats(v, m, &st, &err) == 0) {
			x->gratio = st.mean;
			x->gratio_err = sqrt((m > 1 ? st.se * st.se : 0) +
			    mean_gerr * mean_gerr);
		}
	}
	*nout = ne;
	return e;
}

/* One scaling set in[0..m-1] with eps values eps taken to eps = 0 into x;
 * -1 (reported) if it cannot be done. */
static int
limit_fit(struct ctx *c, const struct est *in, size_t m, const double *eps,
    int which, struct est *x, double *y, double *w)
{
	const rc_extrap_opts *model = which == 'f' ? &c->o->frac : &c->o->therm;
	const char *what = which == 'f' ? "eps_f = lambda_s/lambda_r" :
	    "eps_t = lambda_r/lx";
	size_t need = model->auto_order ? 3 : model->nterms + 1, best = 0;
	double stat = 0, gstat = 0, sestat = 0, fstat = 0, g = 0, gmodel;
	rc_fit fit;
	rc_err err;

	if (m < need) {
		rc__cs_bad(c,
		    "%s (%s): %zu value%s of %s, the extrapolation needs %zu",
		    rc__cs_group_name(c, in[0].row, in[0].p_star,
		    c->o->per_seed), rc__cs_where(c, in[0].row), m, m == 1 ? ""
		    : "s", what, need);
		return -1;
	}
	for (size_t i = 0; i < m; i++)
		y[i] = in[i].a_r;
	if (rc_extrapolate(eps, y, m, model, &fit, w, &err) != 0) {
		rc__cs_bad(c, "%s (%s): %s: %s", rc__cs_group_name(c, in[0].row,
		    in[0].p_star, c->o->per_seed), rc__cs_where(c, in[0].row),
		    what, err.msg);
		return -1;
	}
	*x = in[0];
	x->a_r = fit.value;
	x->a_rich = x->a_y = x->a_y011 = x->a_ymod = 0;
	x->alpha_mod = x->a_r_sd = NAN;
	for (size_t i = 0; i < m; i++) {
		double wi = w[i];
		stat += wi * wi * in[i].a_r_err * in[i].a_r_err;
		gstat += wi * wi * in[i].gratio_err * in[i].gratio_err;
		sestat += wi * wi * in[i].a_r_se * in[i].a_r_se;
		fstat += wi * wi * in[i].a_r_floor * in[i].a_r_floor;
		x->a_rich += wi * in[i].a_rich;
		x->a_y += wi * in[i].a_y;
		x->a_y011 += wi * in[i].a_y011;
		x->a_ymod += wi * in[i].a_ymod;
		g += wi * in[i].gratio;
		if (in[i].n_seeds < x->n_seeds)
			x->n_seeds = in[i].n_seeds;
		if (in[i].n_disc < x->n_disc)
			x->n_disc = in[i].n_disc;
		x->eps_c_all = rc__cs_list_merge(c, x->eps_c_all,
		    in[i].eps_c_all);
		x->eps_c_used = rc__cs_list_merge(c, x->eps_c_used,
		    in[i].eps_c_used);
		if (eps[i] < eps[best])
			best = i;
	}
	if (which == 'f') {
		x->eps_f_list = rc__cs_list_of(c, eps, m);
		x->eps_f = 0;
	} else {
		x->eps_t_list = rc__cs_list_of(c, eps, m);
		x->eps_t = 0;
	}
	/* The ratio's model error: how far the extrapolation moves it from
	 * the member at the smallest eps (cf. a two-point estimate). */
	gmodel = fabs(g - in[best].gratio);
	x->gratio = g;
	x->gratio_err = sqrt(gstat + gmodel * gmodel);
	x->a_r_err = sqrt(stat + fit.err * fit.err);
	x->a_r_se = sqrt(sestat);
	x->a_r_floor = sqrt(fstat);
	return 0;
}

/* Extrapolate eps_f (which = 'f') or eps_t ('t') to zero across groups
 * that differ only in lambda_s (f) or in lx, ly (t). */
struct est *
rc__cs_stage_limit(struct ctx *c, struct est *in, size_t n, int which, size_t
    *nout) { struct est *e = rc__cs_pool_alloc(c, n, sizeof(*e));
	double *eps = rc__cs_pool_alloc(c, n, sizeof(double));
	double *y = rc__cs_pool_alloc(c, n, sizeof(double));
	double *w = rc__cs_pool_alloc(c, n, sizeof(double));
	size_t ne = 0;

	if (which == 'f')
		c->excl_lambda_s = 1;
	else
		c->excl_lx = 1;
	for (size_t i = 0; i < n; i++)
		in[i].key = rc__cs_make_key(c, in[i].row, in[i].p_star,
		    c->o->per_seed, 1);
	qsort(in, n, sizeof(*in), by_key_est);
	for (size_t a = 0, b; a < n; a = b) {
		int ok = 1;
		for (b = a + 1; b < n && strcmp(in[b].key, in[a].key) == 0; b++)
			;
		for (size_t i = a; i < b && ok; i++) {
			eps[i - a] = which == 'f' ? in[i].eps_f : in[i].eps_t;
			if (!(eps[i - a] > 0)) {
				rc__cs_bad(c,
				    "%s (%s): %s is undefined (lambda_s or lambda_r "
				    "missing)", rc__cs_group_name(c, in[a].row,
				    in[a].p_star, c->o->per_seed),
				    rc__cs_where(c, in[i].row), which == 'f' ?
				    "eps_f = lambda_s/lambda_r" :
				    "eps_t = lambda_r/lx");
				ok = 0;
			}
		}
		if (ok && limit_fit(c, in + a, b - a, eps, which, &e[ne], y, w) == 0)
			ne++;
	}
	rc__cs_check_errors(c);
	*nout = ne;
	return e;
}

