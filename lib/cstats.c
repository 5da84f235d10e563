/* cstats.c - grouping and the continuum, ensemble, fractal and
 * thermodynamic stages of contact-stats (see cstats.h, contact-stats(1)).
 *
 * Everything a run allocates, apart from the result, comes from a pool
 * freed at the end; a data error or a failed allocation longjmps out of
 * the stage to rc_cstats_run, which frees the pool and returns -1.
 */
#include "cstats.h"

#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"
#include "kappa.h"

/* Columns gfmd-solve computes: never grouping keys.  nx and ny are the
 * discretisation; everything else (lx, ly, method and the surface's
 * metadata) identifies the problem. */
static const char *const output_cols[] = {
	"p_star", "p", "a_r", "n_c", "n_cl", "n_tot", "a_yastrebov", "gbar",
	"gbar_c", "gbar_c_prime", "kappa", "kappa_c", "mean_gap",
	"elastic_energy", "n_patches", "patch_size_char", "iterations",
	"residual", "seconds", "plan_seconds", "nx", "ny", NULL
};

/* Metadata derived from the sampled heights, which differ slightly between
 * grids of the same surface: not keys unless group_by names them. */
static const char *const derived_cols[] = {
	"warp_hmin", "warp_hmax", NULL
};

/* Our own output columns; a key column with one of these names is written
 * as key_NAME. */
static const char *const result_cols[] = {
	"p_star", "a_r", "a_r_err", "kappa", "kappa_err", "kappa_c",
	"kappa_c_err", "a_over_p", "a_r_sd", "a_r_se", "n_seeds", "n_disc",
	"eps_c", "eps_c_used", "eps_f", "eps_t", "order", "order_err",
	"a_richardson", "a_yastrebov", "a_yastrebov_011", "a_yastrebov_mod",
	"alpha_mod", "gbar_c_ratio", "method", NULL
};

/* A validated input row. */
struct rec {
	size_t row;
	double p_star, a_r, eps_c, n_c, n_cl, n_tot, gratio;
	double lambda_s, lambda_r, lx;
	long nx, ny;
	const char *key;	/* grouping key of the current stage */
};

/* An estimate at some stage: per surface, per ensemble, per limit.
 * Strings live in the pool and may be shared between copies. */
struct est {
	size_t row;		/* representative input row: keys, file:line */
	double p_star;
	double a_r, a_r_err, a_r_sd, a_r_se;
	double a_rich, a_y, a_y011, a_ymod, alpha_mod;
	double gratio, gratio_err;
	double order, order_err;
	double eps_f, eps_t;
	size_t n_seeds, n_disc;
	const char *eps_c_all, *eps_c_used, *eps_f_list, *eps_t_list;
	const char *key;
};

struct ctx {
	const rc_rowset *rs;
	const rc_cstats_opts *o;
	rc_cstats *res;
	rc_err *err;
	jmp_buf fail;
	void **pool;
	size_t npool, cappool;
	int *is_key;		/* per rowset column */
	int col_seed, col_lambda_s, col_lambda_r, col_lx, col_ly;
	int excl_lambda_s, excl_lx;	/* limits taken: key shows "limit" */
	size_t nerrs;
	char first_err[RC_ERRLEN];
	char shown[2][48];
	char where[2][RC_ERRLEN];
	char group[RC_ERRLEN];
	int shown_k, where_k;
};

/* ---- memory, messages ---- */

static void __attribute__((noreturn))
fail(struct ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void
fail(struct ctx *c, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(c->err->msg, sizeof(c->err->msg), fmt, ap);
	va_end(ap);
	longjmp(c->fail, 1);
}

static void *
pool_alloc(struct ctx *c, size_t count, size_t size)
{
	void *p;

	if (c->npool == c->cappool) {
		size_t cap = c->cappool ? 2 * c->cappool : 64;
		void **np = realloc(c->pool, cap * sizeof(*np));
		if (np == NULL)
			fail(c, "out of memory (%zu pool entries)", cap);
		c->pool = np;
		c->cappool = cap;
	}
	if ((p = calloc(count ? count : 1, size)) == NULL)
		fail(c, "out of memory (%zu x %zu bytes)", count, size);
	c->pool[c->npool++] = p;
	return p;
}

static char *
pool_printf(struct ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static char *
pool_printf(struct ctx *c, const char *fmt, ...)
{
	va_list ap;
	int n;
	char *s;

	va_start(ap, fmt);
	n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	if (n < 0)
		fail(c, "internal: bad format");
	s = pool_alloc(c, (size_t)n + 1, 1);
	va_start(ap, fmt);
	vsnprintf(s, (size_t)n + 1, fmt, ap);
	va_end(ap);
	return s;
}

static void
warn(struct ctx *c, enum rc_cstats_warn_kind kind, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

static void
warn(struct ctx *c, enum rc_cstats_warn_kind kind, const char *fmt, ...)
{
	rc_cstats *r = c->res;
	char msg[RC_ERRLEN], **w;
	unsigned char *k;
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if ((w = realloc(r->warn, (r->nwarn + 1) * sizeof(*w))) == NULL)
		fail(c, "out of memory");
	r->warn = w;
	if ((k = realloc(r->warn_kind, r->nwarn + 1)) == NULL)
		fail(c, "out of memory");
	r->warn_kind = k;
	if ((w[r->nwarn] = strdup(msg)) == NULL)
		fail(c, "out of memory");
	k[r->nwarn++] = (unsigned char)kind;
}

/* A data problem: an error, or with lenient a skipped item. */
static void
bad(struct ctx *c, const char *fmt, ...) __attribute__((format(printf, 2, 3)));

static void
bad(struct ctx *c, const char *fmt, ...)
{
	char msg[RC_ERRLEN];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if (c->o->lenient) {
		if (c->res->nskipped++ == 0)
			snprintf(c->res->first_skip, sizeof(c->res->first_skip), "%s",
			    msg);
		return;
	}
	if (c->nerrs++ == 0)
		snprintf(c->first_err, sizeof(c->first_err), "%s", msg);
}

/* One message for all the data problems found in a pass: the first, and
 * how many more (a broken input gives exactly one line). */
static void
check_errors(struct ctx *c)
{
	if (c->nerrs > 1)
		fail(c, "%s (and %zu more problem%s)", c->first_err, c->nerrs - 1,
		    c->nerrs == 2 ? "" : "s");
	if (c->nerrs == 1)
		fail(c, "%s", c->first_err);
}

/* s in list: n names, or NULL-terminated when n is 0 and list not NULL. */
static int
in_list(const char *s, const char *const *list, size_t n)
{
	if (list == NULL)
		return 0;
	for (size_t i = 0; n ? i < n : list[i] != NULL; i++)
		if (strcmp(s, list[i]) == 0)
			return 1;
	return 0;
}

/* Up to 40 bytes of a cell for a message, control characters as '?', so
 * that every message stays on one line; two buffers. */
static const char *
shown(struct ctx *c, const char *s)
{
	char *b = c->shown[c->shown_k ^= 1];
	size_t i;

	for (i = 0; s[i] && i < 40; i++)
		b[i] = (unsigned char)s[i] < 0x20 || s[i] == 0x7f ? '?' : s[i];
	b[i] = '\0';
	return b;
}

/* "file:line" of a row; two buffers, so one message can name two rows. */
static const char *
where(struct ctx *c, size_t row)
{
	char *b = c->where[c->where_k ^= 1];

	snprintf(b, RC_ERRLEN, "%s:%ld", c->rs->row[row].file,
	    c->rs->row[row].line);
	return b;
}

/* Is column col part of the grouping key (seed only if keep_seed; the
 * extrapolated columns no longer)? */
static int
key_used(const struct ctx *c, size_t col, int keep_seed)
{
	int i = (int)col;

	return c->is_key[col] && (i != c->col_seed || keep_seed) &&
	    !(c->excl_lambda_s && i == c->col_lambda_s) &&
	    !(c->excl_lx && (i == c->col_lx || i == c->col_ly));
}

/* "group p_star=0.05 H=0.8 seed=3" for messages. */
static const char *
group_name(struct ctx *c, size_t row, double p_star, int keep_seed)
{
	size_t len;

	snprintf(c->group, sizeof(c->group), "group p_star=%.10g", p_star);
	for (size_t k = 0; k < c->rs->ncols; k++) {
		const char *s;
		if (!key_used(c, k, keep_seed))
			continue;
		s = rc_rows_str(c->rs, row, (int)k);
		len = strlen(c->group);
		snprintf(c->group + len, sizeof(c->group) - len, " %s=%s",
		    c->rs->col[k], s ? shown(c, s) : "(absent)");
	}
	return c->group;
}

/* ---- grouping keys ---- */

/* Text of a key cell: numbers to 12 significant digits (in num), so that
 * 0.5 and 0.50 (or JSON 5e-1) are the same key; "\x1e" for an absent
 * cell; text as it is. */
static const char *
key_text(const struct ctx *c, size_t row, int col, char num[32])
{
	const char *s = rc_rows_str(c->rs, row, col);
	double v;

	if (s == NULL)
		return "\x1e";
	if (rc_rows_num(c->rs, row, col, &v) == 0) {
		snprintf(num, 32, "%.12g", v);
		return num;
	}
	return s;
}

/* Grouping key of a row: p_star (10 digits, with_p) and the key columns
 * in use, separated by 0x1f. */
static const char *
make_key(struct ctx *c, size_t row, double p_star, int keep_seed, int with_p)
{
	size_t len = 0, cap = 64;
	char *k = pool_alloc(c, cap, 1), num[32];

	if (with_p)
		len = (size_t)snprintf(k, cap, "%.10g", p_star);
	for (size_t col = 0; col < c->rs->ncols; col++) {
		if (!key_used(c, col, keep_seed))
			continue;
		const char *cell = key_text(c, row, (int)col, num);
		size_t n = strlen(cell);
		if (len + n + 2 > cap) {
			char *bigger = pool_alloc(c, cap = 2 * (len + n + 2), 1);
			memcpy(bigger, k, len + 1);
			k = bigger;
		}
		k[len++] = '\x1f';
		memcpy(k + len, cell, n + 1);
		len += n;
	}
	return k;
}

/* ---- value lists ---- */

/* The values, increasing, comma-separated, each in the shortest form that
 * reads back exactly. */
static const char *
list_of(struct ctx *c, const double *v, size_t n)
{
	double *s = pool_alloc(c, n, sizeof(*s));
	char *out = pool_alloc(c, n * 26 + 1, 1), num[32];
	size_t len = 0;

	memcpy(s, v, n * sizeof(*s));
	for (size_t i = 1; i < n; i++)	/* insertion sort: lists are short */
		for (size_t j = i; j > 0 && s[j] < s[j - 1]; j--) {
			double t = s[j];
			s[j] = s[j - 1];
			s[j - 1] = t;
		}
	for (size_t i = 0; i < n; i++) {
		if (isnan(s[i]))
			strcpy(num, "nan");
		else
			rc_format_double(num, sizeof(num), s[i]);
		len += (size_t)sprintf(out + len, "%s%s", i ? "," : "", num);
	}
	return out;
}

/* An ensemble's list and a member's: distinct lists joined by ';'. */
static const char *
list_merge(struct ctx *c, const char *dst, const char *src)
{
	size_t n = strlen(src);

	for (const char *p = dst; p; p = strchr(p, ';') ? strchr(p, ';') + 1 : NULL)
		if (strncmp(p, src, n) == 0 && (p[n] == ';' || p[n] == '\0'))
			return dst;
	return pool_printf(c, "%s;%s", dst, src);
}

/* ---- input ---- */

static void
choose_keys(struct ctx *c)
{
	const rc_cstats_opts *o = c->o;
	const rc_rowset *rs = c->rs;

	c->is_key = pool_alloc(c, rs->ncols, sizeof(*c->is_key));
	for (size_t i = 0; i < o->ngroup_by; i++)
		if (rc_rows_column(rs, o->group_by[i]) < 0)
			fail(c, "--group-by: no input has a column '%s'", o->group_by[i]);
	for (size_t i = 0; i < o->nignore; i++)
		if (rc_rows_column(rs, o->ignore[i]) < 0)
			fail(c, "--ignore: no input has a column '%s'", o->ignore[i]);
	for (size_t k = 0; k < rs->ncols; k++) {
		const char *name = rs->col[k];
		if (o->have_group_by)
			c->is_key[k] = in_list(name, o->group_by, o->ngroup_by) ||
			    strcmp(name, "seed") == 0;
		else
			c->is_key[k] = !in_list(name, output_cols, 0) &&
			    !in_list(name, derived_cols, 0);
		if (in_list(name, o->ignore, o->nignore) ||
		    strcmp(name, "nx") == 0 || strcmp(name, "ny") == 0 ||
		    strcmp(name, "p_star") == 0)
			c->is_key[k] = 0;
	}
	c->col_seed = rc_rows_column(rs, "seed");
	c->col_lambda_s = rc_rows_column(rs, "lambda_s");
	c->col_lambda_r = rc_rows_column(rs, "lambda_r");
	c->col_lx = rc_rows_column(rs, "lx");
	c->col_ly = rc_rows_column(rs, "ly");
}

/* A required number; reports and returns -1 if absent or not finite. */
static int
need_num(struct ctx *c, size_t row, const char *name, double *v)
{
	int k = rc_rows_column(c->rs, name);
	const char *s = rc_rows_str(c->rs, row, k);

	if (s == NULL) {
		bad(c, "%s: no column '%s'", where(c, row), name);
		return -1;
	}
	if (rc_rows_num(c->rs, row, k, v) != 0 || !isfinite(*v)) {
		bad(c, "%s: column '%s': '%s' is not a finite number", where(c, row),
		    name, shown(c, s));
		return -1;
	}
	return 0;
}

/* An optional number: NaN if absent or null/nan; text is an error. */
static int
opt_num(struct ctx *c, size_t row, const char *name, double *v)
{
	int k = rc_rows_column(c->rs, name);
	const char *s = rc_rows_str(c->rs, row, k);

	*v = NAN;
	if (s == NULL)
		return 0;
	if (rc_rows_num(c->rs, row, k, v) != 0 || isinf(*v)) {
		bad(c, "%s: column '%s': '%s' is not a number", where(c, row), name,
		    shown(c, s));
		return -1;
	}
	return 0;
}

/* Check one row into x; 0 if it is good. */
static int
check_row(struct ctx *c, size_t i, struct rec *x)
{
	size_t nerr0 = c->nerrs, skip0 = c->res->nskipped;
	double nx, ny, gbar, gbar_c, ly;

	x->row = i;
	need_num(c, i, "p_star", &x->p_star);
	need_num(c, i, "a_r", &x->a_r);
	need_num(c, i, "nx", &nx);
	need_num(c, i, "ny", &ny);
	need_num(c, i, "lx", &x->lx);
	opt_num(c, i, "ly", &ly);
	opt_num(c, i, "n_c", &x->n_c);
	opt_num(c, i, "n_cl", &x->n_cl);
	opt_num(c, i, "n_tot", &x->n_tot);
	opt_num(c, i, "gbar", &gbar);
	opt_num(c, i, "gbar_c", &gbar_c);
	opt_num(c, i, "lambda_s", &x->lambda_s);
	opt_num(c, i, "lambda_r", &x->lambda_r);
	if (c->nerrs != nerr0 || c->res->nskipped != skip0)
		return -1;
	if (!(x->p_star > 0))
		bad(c, "%s: column 'p_star': %g is not positive", where(c, i),
		    x->p_star);
	else if (!(x->a_r >= 0 && x->a_r <= 1))
		bad(c, "%s: column 'a_r': %g is outside [0, 1]", where(c, i), x->a_r);
	else if (nx < 1 || ny < 1 || nx != floor(nx) || ny != floor(ny) ||
	    nx > 1e9 || ny > 1e9)
		bad(c, "%s: nx = %g, ny = %g: want positive integers", where(c, i),
		    nx, ny);
	else if (!(x->lx > 0))
		bad(c, "%s: column 'lx': %g is not positive", where(c, i), x->lx);
	else if (x->lambda_s <= 0 || x->lambda_r <= 0)
		bad(c, "%s: lambda_s = %g, lambda_r = %g: must be positive",
		    where(c, i), x->lambda_s, x->lambda_r);
	else if (x->n_c < 0 || x->n_cl < 0 || x->n_tot <= 0 ||
	    x->n_c > x->n_tot || x->n_cl > x->n_c)
		bad(c, "%s: n_c = %g, n_cl = %g, n_tot = %g: want "
		    "0 <= n_cl <= n_c <= n_tot, n_tot > 0", where(c, i), x->n_c,
		    x->n_cl, x->n_tot);
	if (c->nerrs != nerr0 || c->res->nskipped != skip0)
		return -1;
	x->nx = (long)nx;
	x->ny = (long)ny;
	/* eps_c = da/lambda_s; without lambda_s (indenters) da/lx: the limit
	 * eps -> 0 does not depend on the scale of eps. */
	x->eps_c = x->lx / nx / (isnan(x->lambda_s) ? x->lx : x->lambda_s);
	x->gratio = gbar > 0 && gbar_c > 0 ? gbar_c / gbar : NAN;
	return 0;
}

static struct rec *
validate(struct ctx *c, size_t *nrec)
{
	const rc_rowset *rs = c->rs;
	struct rec *r = pool_alloc(c, rs->nrows, sizeof(*r));
	size_t n = 0;
	int warned_gbar_c = 0, warned_ncl = 0;

	for (size_t i = 0; i < rs->nrows; i++) {
		if (check_row(c, i, &r[n]) != 0)
			continue;
		if (isnan(r[n].gratio) && !warned_gbar_c++)
			warn(c, RC_CSTATS_WARN_MISSING, "%s: no gbar_c (or nan): "
			    "kappa_c is nan for such rows", where(c, i));
		if ((isnan(r[n].n_c) || isnan(r[n].n_cl) || isnan(r[n].n_tot)) &&
		    !warned_ncl++)
			warn(c, RC_CSTATS_WARN_MISSING, "%s: no n_c, n_cl or n_tot: "
			    "Yastrebov estimates are nan for such rows", where(c, i));
		n++;
	}
	check_errors(c);
	*nrec = n;
	return r;
}

/* ---- stages ---- */

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
			bad(c, "%s and %s: duplicate rows (same surface, p_star and "
			    "grid %ldx%ld)", where(c, prev->row), where(c, r[i].row),
			    r[i].nx, r[i].ny);
			if (c->o->lenient)
				continue;
		}
		r[kept++] = r[i];
	}
	check_errors(c);
	return kept;
}

/* The Richardson fit of one discretisation set r[0..m-1] (eps increasing)
 * into x; -1 (reported) if it cannot be done. */
static int
continuum_fit(struct ctx *c, const struct rec *r, size_t m, struct est *x,
    double *eps, double *y, double *w)
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
		bad(c, "%s (%s): %zu discretisation%s, the extrapolation needs %zu "
		    "(or use --no-extrapolate)", group_name(c, r[0].row,
		    r[0].p_star, 1), where(c, r[0].row), m, m == 1 ? "" : "s", need);
		return -1;
	}
	for (size_t i = 0; i < m; i++) {
		eps[i] = r[i].eps_c;
		y[i] = r[i].a_r;
		have_g &= !isnan(r[i].gratio);
	}
	if (rc_extrapolate(eps, y, m, &model, &fit, w, &err) != 0) {
		bad(c, "%s (%s): a_r: %s", group_name(c, r[0].row, r[0].p_star, 1),
		    where(c, r[0].row), err.msg);
		return -1;
	}
	x->a_r = x->a_rich = fit.value;
	x->a_r_err = fit.err;
	x->order = fit.order;
	x->order_err = o->cont.auto_order && !model.auto_order ? NAN :
	    fit.order_err;
	/* the points the estimate depends on: non-zero weight */
	for (size_t i = 0; i < m; i++)
		if (w[i] != 0)
			y[nused++] = eps[i];
	x->eps_c_used = list_of(c, y, nused);
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
static struct est *
stage_continuum(struct ctx *c, struct rec *r, size_t n, size_t *nout)
{
	struct est *e = pool_alloc(c, n, sizeof(*e));
	double *eps = pool_alloc(c, n, sizeof(double));
	double *y = pool_alloc(c, n, sizeof(double));
	double *w = pool_alloc(c, n, sizeof(double));
	size_t ne = 0;

	for (size_t i = 0; i < n; i++)
		r[i].key = make_key(c, r[i].row, r[i].p_star, 1, 1);
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
		x->eps_c_all = list_of(c, eps, m);
		x->eps_f_list = list_of(c, &x->eps_f, 1);
		x->eps_t_list = list_of(c, &x->eps_t, 1);
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
			x->eps_c_used = list_of(c, &f->eps_c, 1);
		} else if (continuum_fit(c, f, m, x, eps, y, w) != 0)
			continue;
		ne++;
	}
	check_errors(c);
	*nout = ne;
	return e;
}

/* Ensemble over seeds: mean, sd, se, and the error of the mean combined
 * with the mean extrapolation error (systematic: it does not average
 * out). */
static struct est *
stage_ensemble(struct ctx *c, struct est *in, size_t n, size_t *nout)
{
	struct est *e = pool_alloc(c, n, sizeof(*e));
	double *v = pool_alloc(c, n, sizeof(double));
	size_t ne = 0;
	rc_err err;

	for (size_t i = 0; i < n; i++)
		in[i].key = make_key(c, in[i].row, in[i].p_star, 0, 1);
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
#undef MEAN
		for (size_t i = a; i < b; i++) {
			v[i - a] = in[i].a_r;
			mean_err += in[i].a_r_err / (double)m;
			mean_gerr += in[i].gratio_err / (double)m;
			if (in[i].n_disc < x->n_disc)
				x->n_disc = in[i].n_disc;
			x->eps_c_all = list_merge(c, x->eps_c_all, in[i].eps_c_all);
			x->eps_c_used = list_merge(c, x->eps_c_used, in[i].eps_c_used);
		}
		if (rc_ensemble_stats(v, m, &st, &err) != 0)
			fail(c, "%s: %s", group_name(c, x->row, x->p_star, 0), err.msg);
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
	double stat = 0, gstat = 0, sestat = 0, g = 0, gmodel;
	rc_fit fit;
	rc_err err;

	if (m < need) {
		bad(c, "%s (%s): %zu value%s of %s, the extrapolation needs %zu",
		    group_name(c, in[0].row, in[0].p_star, c->o->per_seed),
		    where(c, in[0].row), m, m == 1 ? "" : "s", what, need);
		return -1;
	}
	for (size_t i = 0; i < m; i++)
		y[i] = in[i].a_r;
	if (rc_extrapolate(eps, y, m, model, &fit, w, &err) != 0) {
		bad(c, "%s (%s): %s: %s", group_name(c, in[0].row, in[0].p_star,
		    c->o->per_seed), where(c, in[0].row), what, err.msg);
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
		x->a_rich += wi * in[i].a_rich;
		x->a_y += wi * in[i].a_y;
		x->a_y011 += wi * in[i].a_y011;
		x->a_ymod += wi * in[i].a_ymod;
		g += wi * in[i].gratio;
		if (in[i].n_seeds < x->n_seeds)
			x->n_seeds = in[i].n_seeds;
		if (in[i].n_disc < x->n_disc)
			x->n_disc = in[i].n_disc;
		x->eps_c_all = list_merge(c, x->eps_c_all, in[i].eps_c_all);
		x->eps_c_used = list_merge(c, x->eps_c_used, in[i].eps_c_used);
		if (eps[i] < eps[best])
			best = i;
	}
	if (which == 'f') {
		x->eps_f_list = list_of(c, eps, m);
		x->eps_f = 0;
	} else {
		x->eps_t_list = list_of(c, eps, m);
		x->eps_t = 0;
	}
	/* The ratio's model error: how far the extrapolation moves it from
	 * the member at the smallest eps (cf. a two-point estimate). */
	gmodel = fabs(g - in[best].gratio);
	x->gratio = g;
	x->gratio_err = sqrt(gstat + gmodel * gmodel);
	x->a_r_err = sqrt(stat + fit.err * fit.err);
	x->a_r_se = sqrt(sestat);
	return 0;
}

/* Extrapolate eps_f (which = 'f') or eps_t ('t') to zero across groups
 * that differ only in lambda_s (f) or in lx, ly (t). */
static struct est *
stage_limit(struct ctx *c, struct est *in, size_t n, int which, size_t *nout)
{
	struct est *e = pool_alloc(c, n, sizeof(*e));
	double *eps = pool_alloc(c, n, sizeof(double));
	double *y = pool_alloc(c, n, sizeof(double));
	double *w = pool_alloc(c, n, sizeof(double));
	size_t ne = 0;

	if (which == 'f')
		c->excl_lambda_s = 1;
	else
		c->excl_lx = 1;
	for (size_t i = 0; i < n; i++)
		in[i].key = make_key(c, in[i].row, in[i].p_star, c->o->per_seed, 1);
	qsort(in, n, sizeof(*in), by_key_est);
	for (size_t a = 0, b; a < n; a = b) {
		int ok = 1;
		for (b = a + 1; b < n && strcmp(in[b].key, in[a].key) == 0; b++)
			;
		for (size_t i = a; i < b && ok; i++) {
			eps[i - a] = which == 'f' ? in[i].eps_f : in[i].eps_t;
			if (!(eps[i - a] > 0)) {
				bad(c, "%s (%s): %s is undefined (lambda_s or lambda_r "
				    "missing)", group_name(c, in[a].row, in[a].p_star,
				    c->o->per_seed), where(c, in[i].row), which == 'f' ?
				    "eps_f = lambda_s/lambda_r" : "eps_t = lambda_r/lx");
				ok = 0;
			}
		}
		if (ok && limit_fit(c, in + a, b - a, eps, which, &e[ne], y, w) == 0)
			ne++;
	}
	check_errors(c);
	*nout = ne;
	return e;
}

/* ---- output ---- */

static int
by_output(const void *a, const void *b)
{
	const struct est *x = a, *y = b;
	int k = strcmp(x->key, y->key);

	if (k)
		return k;
	return (x->p_star > y->p_star) - (x->p_star < y->p_star);
}

/* Sort by curve (keys without p_star; curves in order of first input row)
 * then by p*. */
static void
order_output(struct ctx *c, struct est *e, size_t n)
{
	const char **k = pool_alloc(c, n, sizeof(*k));

	for (size_t i = 0; i < n; i++)
		k[i] = make_key(c, e[i].row, e[i].p_star, c->o->per_seed, 0);
	for (size_t i = 0; i < n; i++) {
		size_t first = e[i].row;
		for (size_t j = 0; j < n; j++)
			if (e[j].row < first && strcmp(k[i], k[j]) == 0)
				first = e[j].row;
		e[i].key = pool_printf(c, "%020zu%s", first, k[i]);
	}
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
	for (size_t k = 0; k < rs->ncols; k++) {
		if (!key_shown(c, k))
			continue;
		const char *s = rc_rows_str(rs, x->row, (int)k);
		const char *name = in_list(rs->col[k], result_cols, 0) ?
		    pool_printf(c, "key_%s", rs->col[k]) : rs->col[k];
		double v;
		if (!key_used(c, k, 1))
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
		fail(c, "out of memory");
}

/* Label of the curve of e[i]: the shown key columns whose values differ
 * between curves; quotes and control characters as '_' (it goes into a
 * gnuplot string). */
static char *
curve_label(struct ctx *c, const struct est *e, size_t n, size_t i)
{
	char buf[RC_ERRLEN], *lab;

	buf[0] = '\0';
	for (size_t k = 0; k < c->rs->ncols; k++) {
		int varies = 0;
		if (!key_shown(c, k))
			continue;
		char num0[32], num[32];
		const char *a = key_text(c, e[0].row, (int)k, num0);
		for (size_t j = 1; j < n && !varies; j++)
			varies = strcmp(a, key_text(c, e[j].row, (int)k, num)) != 0;
		if (!varies)
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
		fail(c, "out of memory");
	return lab;
}

static void
make_output(struct ctx *c, const struct est *e, size_t n)
{
	rc_cstats *res = c->res;
	char method[256];

	rc_cstats_method(c->o, method, sizeof(method));
	if ((res->row = calloc(n, sizeof(*res->row))) == NULL ||
	    (res->point = calloc(n, sizeof(*res->point))) == NULL ||
	    (res->label = calloc(n, sizeof(*res->label))) == NULL)
		fail(c, "out of memory (%zu rows)", n);
	for (size_t i = 0; i < n; i++) {
		struct derived d = derive(&e[i]);
		if (e[i].a_r < 0 || e[i].a_r > 1)
			warn(c, RC_CSTATS_WARN_CLAMPED, "%s: extrapolated a_r = %.6g "
			    "left [0, 1]; clamped", group_name(c, e[i].row,
			    e[i].p_star, 0), e[i].a_r);
		if (i > 0 && strncmp(e[i].key, e[i - 1].key, 20) != 0)
			res->ncurves++;
		if (i == 0 || strncmp(e[i].key, e[i - 1].key, 20) != 0)
			res->label[res->ncurves] = curve_label(c, e, n, i);
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
		fail(c, "%s%s: no result rows (header only)", c->rs->nfiles ?
		    c->rs->file[0] : "input", c->rs->nfiles > 1 ?
		    " and the other inputs" : "");
	choose_keys(c);
	r = validate(c, &nrec);
	if (nrec == 0)
		fail(c, "no valid rows left (%zu skipped: %s)", c->res->nskipped,
		    c->res->first_skip);
	e = stage_continuum(c, r, nrec, &ne);
	if (!c->o->per_seed)
		e = stage_ensemble(c, e, ne, &ne);
	if (c->o->fractal)
		e = stage_limit(c, e, ne, 'f', &ne);
	if (c->o->thermo)
		e = stage_limit(c, e, ne, 't', &ne);
	if (ne == 0)
		fail(c, "no group left (%zu skipped: %s)", c->res->nskipped,
		    c->res->first_skip);
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
