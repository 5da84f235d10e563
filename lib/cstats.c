/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cstats.c - contact-stats' library entry: the run (rc_cstats_run) and
 * its output rows; the input and the stages are in cstats_input.c and
 * cstats_stages.c (see cstats.h, contact-stats(1)).
 *
 * Everything a run allocates, apart from the result, comes from a pool
 * freed at the end; a data error or a failed allocation longjmps out of
 * the stage to rc_cstats_run, which frees the pool and returns -1.
 */
#include "cstats_impl.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "kappa.h"

/* Our own output columns; a key column with one of these names is written
 * as key_NAME. */
static const char *const result_cols[] = {
	"p_star", "a_r", "a_r_err", "kappa", "kappa_err", "kappa_c",
	"kappa_c_err", "a_over_p", "a_r_sd", "a_r_se", "n_seeds", "n_disc",
	"eps_c", "eps_c_used", "eps_f", "eps_t", "order", "order_err",
	"a_richardson", "a_yastrebov", "a_yastrebov_011", "a_yastrebov_mod",
	"alpha_mod", "gbar_c_ratio", "a_r_floor", "method", NULL
};

static int
by_output(const void *a, const void *b)
{
	const struct est *x = a, *y = b;
	int k;

	if (x->curve_row != y->curve_row)
		return x->curve_row < y->curve_row ? -1 : 1;
	if ((k = strcmp(x->key, y->key)) != 0)
		return k;
	return (x->p_star > y->p_star) - (x->p_star < y->p_star);
}

static int
by_key_row(const void *a, const void *b)
{
	const struct est *x = a, *y = b;
	int k = strcmp(x->key, y->key);

	if (k != 0)
		return k;
	return (x->row > y->row) - (x->row < y->row);
}

/* Sort by curve (keys without p_star; curves in order of first input row)
 * then by p*.  The first row of each curve from one sort by (key, row):
 * n log n (comparing every estimate with every other took 80 s for
 * 18,000 rows --per-seed, issue 27). */
static void
order_output(struct ctx *c, struct est *e, size_t n)
{
	for (size_t i = 0; i < n; i++)
		e[i].key = rc__cs_make_key(c, e[i].row, e[i].p_star,
		    c->o->per_seed, 0);
	qsort(e, n, sizeof(*e), by_key_row);
	for (size_t i = 0; i < n; i++)
		e[i].curve_row = i > 0 && strcmp(e[i].key, e[i - 1].key) == 0 ?
		    e[i - 1].curve_row : e[i].row;
	qsort(e, n, sizeof(*e), by_output);
}

struct derived {
	double a_r, kappa, kappa_err, kappa_c, kappa_c_err;
};

/* Eq. 24 and Eq. 8; errors by linear propagation:
 * d kappa / d a_r = exp(x^2)/p* with x = erfinv(a_r), and kappa_c =
 * kappa gbar_c/gbar. */
static struct derived
derive(const struct est *x)
{
	struct derived d;
	double a = x->a_r < 0 ? 0 : x->a_r > 1 ? 1 : x->a_r;
	double xi = rc_erfinv(a);

	d.a_r = a;
	d.kappa = rc_kappa(a, x->p_star);
	d.kappa_err = a == 1 ? INFINITY : exp(xi * xi) * x->a_r_err / x->p_star;
	d.kappa_c = x->gratio * d.kappa;
	d.kappa_c_err = hypot(x->gratio * d.kappa_err, d.kappa * x->gratio_err);
	return d;
}

static const char *
model_name(const rc_extrap_opts *e, char *buf, size_t len)
{
	if (e->auto_order)
		snprintf(buf, len, "auto");
	else {
		buf[0] = '\0';
		for (size_t j = 0; j < e->nterms; j++) {
			size_t n = strlen(buf);
			snprintf(buf + n, len - n, "%s%g", j ? "," : "", e->exponent[j]);
		}
	}
	return buf;
}

void
rc_cstats_method(const rc_cstats_opts *o, char *buf, size_t len)
{
	char m[64];
	size_t n;

	if (o->no_extrapolate)
		snprintf(buf, len, "finest");
	else
		snprintf(buf, len, "%s(%s)", o->cont.kind == RC_FIT_LSQ ? "lsq" :
		    "richardson", model_name(&o->cont, m, sizeof(m)));
	n = strlen(buf);
	if (!o->per_seed)
		snprintf(buf + n, len - n, "+ensemble");
	n = strlen(buf);
	if (o->fractal)
		snprintf(buf + n, len - n, "+fractal(%s)", model_name(&o->frac, m,
		    sizeof(m)));
	n = strlen(buf);
	if (o->thermo)
		snprintf(buf + n, len - n, "+thermo(%s)", model_name(&o->therm, m,
		    sizeof(m)));
}

static int
key_shown(const struct ctx *c, size_t col)
{
	return c->is_key[col] && ((int)col != c->col_seed || c->o->per_seed);
}

static void
fill_row(struct ctx *c, rc_row *row, const struct est *x, const struct derived *d,
    const char *method)
{
	const rc_rowset *rs = c->rs;
	int bad_alloc = 0;

	bad_alloc |= rc_row_num(row, "p_star", x->p_star);
	bad_alloc |= rc_row_num(row, "a_r", d->a_r);
	bad_alloc |= rc_row_num(row, "a_r_err", x->a_r_err);
	bad_alloc |= rc_row_num(row, "kappa", d->kappa);
	bad_alloc |= rc_row_num(row, "kappa_err", d->kappa_err);
	bad_alloc |= rc_row_num(row, "kappa_c", d->kappa_c);
	bad_alloc |= rc_row_num(row, "kappa_c_err", d->kappa_c_err);
	bad_alloc |= rc_row_num(row, "a_over_p", d->a_r / x->p_star);
	bad_alloc |= rc_row_num(row, "a_r_sd", x->a_r_sd);
	bad_alloc |= rc_row_num(row, "a_r_se", x->a_r_se);
	bad_alloc |= rc_row_int(row, "n_seeds", (long long)x->n_seeds);
	bad_alloc |= rc_row_int(row, "n_disc", (long long)x->n_disc);
	bad_alloc |= rc_row_str(row, "eps_c", x->eps_c_all);
	bad_alloc |= rc_row_str(row, "eps_c_used", x->eps_c_used);
	bad_alloc |= rc_row_str(row, "eps_f", x->eps_f_list);
	bad_alloc |= rc_row_str(row, "eps_t", x->eps_t_list);
	bad_alloc |= rc_row_num(row, "order", x->order);
	bad_alloc |= rc_row_num(row, "order_err", x->order_err);
	bad_alloc |= rc_row_num(row, "a_richardson", x->a_rich);
	bad_alloc |= rc_row_num(row, "a_yastrebov", x->a_y);
	bad_alloc |= rc_row_num(row, "a_yastrebov_011", x->a_y011);
	bad_alloc |= rc_row_num(row, "a_yastrebov_mod", x->a_ymod);
	bad_alloc |= rc_row_num(row, "alpha_mod", x->alpha_mod);
	bad_alloc |= rc_row_num(row, "gbar_c_ratio", x->gratio);
	bad_alloc |= rc_row_num(row, "a_r_floor", x->a_r_floor);
	for (size_t k = 0; k < rs->ncols; k++) {
		if (!key_shown(c, k))
			continue;
		const char *s = rc_rows_str(rs, x->row, (int)k);
		const char *name = rc__cs_in_list(rs->col[k], result_cols, 0) ?
		    rc__cs_pool_printf(c, "key_%s", rs->col[k]) : rs->col[k];
		double v;
		if (!rc__cs_key_used(c, k, 1))
			bad_alloc |= rc_row_str(row, name, "limit");
		else if (s == NULL)
			bad_alloc |= rc_row_str(row, name, "");
		else if (rc_rows_num(rs, x->row, (int)k, &v) == 0)
			bad_alloc |= rc_row_num(row, name, v);
		else
			bad_alloc |= rc_row_str(row, name, s);
	}
	bad_alloc |= rc_row_str(row, "method", method);
	if (bad_alloc)
		rc__cs_fail(c, "out of memory");
}

/* Which shown key columns differ between the estimates (the columns a
 * curve's label names): one pass over them, not one per curve (that was
 * quadratic with --per-seed, issue 27).  A pool array of ncols flags. */
static const char *
varying_keys(struct ctx *c, const struct est *e, size_t n)
{
	char *varies = rc__cs_pool_alloc(c, c->rs->ncols ? c->rs->ncols : 1, 1);

	for (size_t k = 0; k < c->rs->ncols; k++) {
		char num0[32], num[32];
		const char *a;

		varies[k] = 0;
		if (!key_shown(c, k) || n == 0)
			continue;
		a = rc__cs_key_text(c, e[0].row, (int)k, num0);
		for (size_t j = 1; j < n && !varies[k]; j++)
			varies[k] = strcmp(a, rc__cs_key_text(c, e[j].row, (int)k,
			    num)) != 0;
	}
	return varies;
}

/* Label of the curve of e[i]: the shown key columns whose values differ
 * between curves (varies); quotes and control characters as '_' (it goes
 * into a gnuplot string). */
static char *
curve_label(struct ctx *c, const struct est *e, const char *varies, size_t i)
{
	char buf[RC_ERRLEN], *lab;

	buf[0] = '\0';
	for (size_t k = 0; k < c->rs->ncols; k++) {
		if (!varies[k])
			continue;
		const char *s = rc_rows_str(c->rs, e[i].row, (int)k);
		size_t len = strlen(buf);
		snprintf(buf + len, sizeof(buf) - len, "%s%s=%s", len ? " " : "",
		    c->rs->col[k], s ? s : "");
	}
	for (char *p = buf; *p; p++)
		if (*p == '\'' || *p == '"' || *p == '\\' || (unsigned char)*p < 0x20)
			*p = '_';
	if ((lab = strdup(buf[0] ? buf : "kappa")) == NULL)
		rc__cs_fail(c, "out of memory");
	return lab;
}

static void
make_output(struct ctx *c, const struct est *e, size_t n)
{
	rc_cstats *res = c->res;
	char method[256];
	const char *varies = varying_keys(c, e, n);

	rc_cstats_method(c->o, method, sizeof(method));
	if ((res->row = calloc(n, sizeof(*res->row))) == NULL ||
	    (res->point = calloc(n, sizeof(*res->point))) == NULL ||
	    (res->label = calloc(n, sizeof(*res->label))) == NULL)
		rc__cs_fail(c, "out of memory (%zu rows)", n);
	for (size_t i = 0; i < n; i++) {
		struct derived d = derive(&e[i]);
		int new_curve = i == 0 || e[i].curve_row != e[i - 1].curve_row;

		if (e[i].a_r < 0 || e[i].a_r > 1)
			rc__cs_warn(c, RC_CSTATS_WARN_CLAMPED,
			    "%s: extrapolated a_r = %.6g "
			    "left [0, 1]; clamped", rc__cs_group_name(c,
			    e[i].row, e[i].p_star, 0), e[i].a_r);
		if (i > 0 && new_curve)
			res->ncurves++;
		if (new_curve)
			res->label[res->ncurves] = curve_label(c, e, varies, i);
		res->point[i].curve = res->ncurves;
		res->point[i].p_star = e[i].p_star;
		res->point[i].kappa = d.kappa;
		res->point[i].kappa_err = d.kappa_err;
		res->nrows = i + 1;
		fill_row(c, &res->row[i], &e[i], &d, method);
	}
	res->ncurves++;
}

void
rc_cstats_opts_default(rc_cstats_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->cont.nterms = o->frac.nterms = o->therm.nterms = 1;
	o->cont.exponent[0] = o->frac.exponent[0] = o->therm.exponent[0] = 1;
	o->cont.kind = o->frac.kind = o->therm.kind = RC_FIT_FINEST;
	o->alpha = RC_YASTREBOV_ALPHA;
}

void
rc_cstats_free(rc_cstats *res)
{
	for (size_t i = 0; i < res->nrows; i++)
		rc_row_free(&res->row[i]);
	free(res->row);
	free(res->point);
	for (size_t i = 0; res->label && i < res->nrows; i++)
		free(res->label[i]);
	free(res->label);
	for (size_t i = 0; i < res->nwarn; i++)
		free(res->warn[i]);
	free(res->warn);
	free(res->warn_kind);
	memset(res, 0, sizeof(*res));
}

/* The stages in the paper's order: continuum, ensemble, fractal, thermo. */
static void
run(struct ctx *c)
{
	size_t nrec, ne;
	struct rec *r;
	struct est *e;

	if (c->rs->nrows == 0)
		rc__cs_fail(c, "%s%s: no result rows (header only)",
		    c->rs->nfiles ? c->rs->file[0] : "input", c->rs->nfiles > 1
		    ? " and the other inputs" : "");
	rc__cs_choose_keys(c);
	r = rc__cs_validate(c, &nrec);
	if (nrec == 0)
		rc__cs_fail(c, "no valid rows left (%zu skipped: %s)",
		    c->res->nskipped, c->res->first_skip);
	e = rc__cs_stage_continuum(c, r, nrec, &ne);
	if (!c->o->per_seed)
		e = rc__cs_stage_ensemble(c, e, ne, &ne);
	if (c->o->fractal)
		e = rc__cs_stage_limit(c, e, ne, 'f', &ne);
	if (c->o->thermo)
		e = rc__cs_stage_limit(c, e, ne, 't', &ne);
	if (ne == 0)
		rc__cs_fail(c, "no group left (%zu skipped: %s)",
		    c->res->nskipped, c->res->first_skip);
	order_output(c, e, ne);
	make_output(c, e, ne);
}

int
rc_cstats_run(const rc_rowset *rs, const rc_cstats_opts *o, rc_cstats *res,
    rc_err *err)
{
	/* volatile: read after a longjmp */
	struct ctx *volatile c = calloc(1, sizeof(*c));
	int rc = 0;

	memset(res, 0, sizeof(*res));
	if (c == NULL)
		return rc_seterr(err, "out of memory");
	c->rs = rs;
	c->o = o;
	c->res = res;
	c->err = err;
	res->nskipped = rs->nskipped;
	snprintf(res->first_skip, sizeof(res->first_skip), "%s", rs->first_skip);
	if (setjmp(c->fail) == 0)
		run(c);
	else {
		rc_cstats_free(res);
		rc = -1;
	}
	for (size_t i = 0; i < c->npool; i++)
		free(c->pool[i]);
	free(c->pool);
	free(c);
	return rc;
}
