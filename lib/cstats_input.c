/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cstats_input.c - contact-stats' run context: the memory pool, the
 * messages, the grouping keys and the validation of the input rows.
 */
#include "cstats_impl.h"

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grid.h"

/* Columns gfmd-solve computes: never grouping keys (hardness, an input,
 * is one).  nx and ny are the
 * discretisation; everything else (lx, ly, method and the surface's
 * metadata) identifies the problem. */
static const char *const output_cols[] = {
	"p_star", "p", "a_r", "a_plastic", "n_c", "n_cl", "n_tot", "a_yastrebov",
	"a_subpixel", "gbar",
	"gbar_c", "gbar_c_prime", "kappa", "kappa_c", "mean_gap", "approach",
	"elastic_energy", "n_patches", "patch_size_char", "iterations",
	"residual", "tol", "seconds", "plan_seconds", "nx", "ny",
	"p_adh", "a_attr", "l_adh_dx", "separated", NULL
};

/* Metadata derived from the sampled heights, which differ slightly between
 * grids of the same surface: not keys unless group_by names them. */
static const char *const derived_cols[] = {
	"warp_hmin", "warp_hmax", NULL
};

void
rc__cs_fail(struct ctx *c, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(c->err->msg, sizeof(c->err->msg), fmt, ap);
	va_end(ap);
	longjmp(c->fail, 1);
}

void *
rc__cs_pool_alloc(struct ctx *c, size_t count, size_t size)
{
	void *p;

	if (c->npool == c->cappool) {
		size_t cap = c->cappool ? 2 * c->cappool : 64;
		void **np = realloc(c->pool, cap * sizeof(*np));
		if (np == NULL)
			rc__cs_fail(c, "out of memory (%zu pool entries)", cap);
		c->pool = np;
		c->cappool = cap;
	}
	if ((p = calloc(count ? count : 1, size)) == NULL)
		rc__cs_fail(c, "out of memory (%zu x %zu bytes)", count, size);
	c->pool[c->npool++] = p;
	return p;
}

char *
rc__cs_pool_printf(struct ctx *c, const char *fmt, ...)
{
	va_list ap;
	int n;
	char *s;

	va_start(ap, fmt);
	n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	if (n < 0)
		rc__cs_fail(c, "internal: bad format");
	s = rc__cs_pool_alloc(c, (size_t)n + 1, 1);
	va_start(ap, fmt);
	vsnprintf(s, (size_t)n + 1, fmt, ap);
	va_end(ap);
	return s;
}

void
rc__cs_warn(struct ctx *c, enum rc_cstats_warn_kind kind, const char *fmt, ...)
{
	rc_cstats *r = c->res;
	char msg[RC_ERRLEN], **w;
	unsigned char *k;
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if ((w = realloc(r->warn, (r->nwarn + 1) * sizeof(*w))) == NULL)
		rc__cs_fail(c, "out of memory");
	r->warn = w;
	if ((k = realloc(r->warn_kind, r->nwarn + 1)) == NULL)
		rc__cs_fail(c, "out of memory");
	r->warn_kind = k;
	if ((w[r->nwarn] = strdup(msg)) == NULL)
		rc__cs_fail(c, "out of memory");
	k[r->nwarn++] = (unsigned char)kind;
}

/* A data problem: an error, or with lenient a skipped item. */
void
rc__cs_bad(struct ctx *c, const char *fmt, ...)
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
void
rc__cs_check_errors(struct ctx *c) { if (c->nerrs > 1) rc__cs_fail(c,
    "%s (and %zu more problem%s)", c->first_err, c->nerrs - 1, c->nerrs == 2 ?
    "" : "s");
	if (c->nerrs == 1)
		rc__cs_fail(c, "%s", c->first_err);
}

/* s in list: n names, or NULL-terminated when n is 0 and list not NULL. */
int
rc__cs_in_list(const char *s, const char *const *list, size_t n)
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
const char *
rc__cs_shown(struct ctx *c, const char *s)
{
	char *b = c->shown[c->shown_k ^= 1];
	size_t i;

	for (i = 0; s[i] && i < 40; i++)
		b[i] = (unsigned char)s[i] < 0x20 || s[i] == 0x7f ? '?' : s[i];
	b[i] = '\0';
	return b;
}

/* "file:line" of a row; two buffers, so one message can name two rows. */
const char *
rc__cs_where(struct ctx *c, size_t row)
{
	char *b = c->where[c->where_k ^= 1];

	snprintf(b, RC_ERRLEN, "%s:%ld", c->rs->row[row].file,
	    c->rs->row[row].line);
	return b;
}

/* Is column col part of the grouping key (seed only if keep_seed; the
 * extrapolated columns no longer)? */
int
rc__cs_key_used(const struct ctx *c, size_t col, int keep_seed)
{
	int i = (int)col;

	return c->is_key[col] && (i != c->col_seed || keep_seed) &&
	    !(c->excl_lambda_s && i == c->col_lambda_s) &&
	    !(c->excl_lx && (i == c->col_lx || i == c->col_ly));
}

/* "group p_star=0.05 H=0.8 seed=3" for messages. */
const char *
rc__cs_group_name(struct ctx *c, size_t row, double p_star, int keep_seed)
{
	size_t len;

	snprintf(c->group, sizeof(c->group), "group p_star=%.10g", p_star);
	for (size_t k = 0; k < c->rs->ncols; k++) {
		const char *s;
		if (!rc__cs_key_used(c, k, keep_seed))
			continue;
		s = rc_rows_str(c->rs, row, (int)k);
		len = strlen(c->group);
		snprintf(c->group + len, sizeof(c->group) - len, " %s=%s",
		    c->rs->col[k], s ? rc__cs_shown(c, s) : "(absent)");
	}
	return c->group;
}

/* ---- grouping keys ---- */

/* Text of a key cell: numbers to 12 significant digits (in num), so that
 * 0.5 and 0.50 (or JSON 5e-1) are the same key; "\x1e" for an absent
 * cell; text as it is. */
const char *
rc__cs_key_text(const struct ctx *c, size_t row, int col, char num[32])
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
const char *
rc__cs_make_key(struct ctx *c, size_t row, double p_star, int keep_seed, int
    with_p) { size_t len = 0, cap = 64;
	char *k = rc__cs_pool_alloc(c, cap, 1), num[32];

	if (with_p)
		len = (size_t)snprintf(k, cap, "%.10g", p_star);
	for (size_t col = 0; col < c->rs->ncols; col++) {
		if (!rc__cs_key_used(c, col, keep_seed))
			continue;
		const char *cell = rc__cs_key_text(c, row, (int)col, num);
		size_t n = strlen(cell);
		if (len + n + 2 > cap) {
			char *bigger = rc__cs_pool_alloc(c, cap = 2 * (len + n +
			    2), 1);
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
const char *
rc__cs_list_of(struct ctx *c, const double *v, size_t n)
{
	double *s = rc__cs_pool_alloc(c, n, sizeof(*s));
	char *out = rc__cs_pool_alloc(c, n * 26 + 1, 1), num[32];
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
const char *
rc__cs_list_merge(struct ctx *c, const char *dst, const char *src)
{
	size_t n = strlen(src);

	for (const char *p = dst; p; p = strchr(p, ';') ? strchr(p, ';') + 1 : NULL)
		if (strncmp(p, src, n) == 0 && (p[n] == ';' || p[n] == '\0'))
			return dst;
	return rc__cs_pool_printf(c, "%s;%s", dst, src);
}

/* ---- input ---- */

void
rc__cs_choose_keys(struct ctx *c)
{
	const rc_cstats_opts *o = c->o;
	const rc_rowset *rs = c->rs;

	c->is_key = rc__cs_pool_alloc(c, rs->ncols, sizeof(*c->is_key));
	for (size_t i = 0; i < o->ngroup_by; i++)
		if (rc_rows_column(rs, o->group_by[i]) < 0)
			rc__cs_fail(c, "--group-by: no input has a column '%s'",
			    o->group_by[i]);
	for (size_t i = 0; i < o->nignore; i++)
		if (rc_rows_column(rs, o->ignore[i]) < 0)
			rc__cs_fail(c, "--ignore: no input has a column '%s'",
			    o->ignore[i]);
	for (size_t k = 0; k < rs->ncols; k++) {
		const char *name = rs->col[k];
		if (o->have_group_by)
			c->is_key[k] = rc__cs_in_list(name, o->group_by,
			    o->ngroup_by) || strcmp(name, "seed") == 0;
		else
			c->is_key[k] = !rc__cs_in_list(name, output_cols, 0) &&
			    !rc__cs_in_list(name, derived_cols, 0);
		if (rc__cs_in_list(name, o->ignore, o->nignore) ||
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
		rc__cs_bad(c, "%s: no column '%s'", rc__cs_where(c, row), name);
		return -1;
	}
	if (rc_rows_num(c->rs, row, k, v) != 0 || !isfinite(*v)) {
		rc__cs_bad(c, "%s: column '%s': '%s' is not a finite number",
		    rc__cs_where(c, row), name, rc__cs_shown(c, s));
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
		rc__cs_bad(c, "%s: column '%s': '%s' is not a number",
		    rc__cs_where(c, row), name, rc__cs_shown(c, s));
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
		rc__cs_bad(c, "%s: column 'p_star': %g is not positive",
		    rc__cs_where(c, i), x->p_star);
	else if (!(x->a_r >= 0 && x->a_r <= 1))
		rc__cs_bad(c, "%s: column 'a_r': %g is outside [0, 1]",
		    rc__cs_where(c, i), x->a_r);
	else if (nx < 1 || ny < 1 || nx != floor(nx) || ny != floor(ny) ||
	    nx > 1e9 || ny > 1e9)
		rc__cs_bad(c, "%s: nx = %g, ny = %g: want positive integers",
		    rc__cs_where(c, i), nx, ny);
	else if (!(x->lx > 0))
		rc__cs_bad(c, "%s: column 'lx': %g is not positive",
		    rc__cs_where(c, i), x->lx);
	else if (x->lambda_s <= 0 || x->lambda_r <= 0)
		rc__cs_bad(c,
		    "%s: lambda_s = %g, lambda_r = %g: must be positive",
		    rc__cs_where(c, i), x->lambda_s, x->lambda_r);
	else if (x->n_c < 0 || x->n_cl < 0 || x->n_tot <= 0 ||
	    x->n_c > x->n_tot || x->n_cl > x->n_c)
		rc__cs_bad(c, "%s: n_c = %g, n_cl = %g, n_tot = %g: want "
		    "0 <= n_cl <= n_c <= n_tot, n_tot > 0", rc__cs_where(c, i),
		    x->n_c, x->n_cl, x->n_tot);
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

/* Did row i's solve converge (RC_CSTATS_RESIDUAL_NO_TOL in cstats.h)?  0
 * if so or if it cannot tell; 1 if not (with allow_unconverged, counted
 * in *nbad, the first in *first); -1 if not and the row is refused. */
static int
check_converged(struct ctx *c, size_t i, size_t *nbad, size_t *first)
{
	int kres = rc_rows_column(c->rs, "residual");
	int ktol = rc_rows_column(c->rs, "tol");
	double res, tol = RC_CSTATS_RESIDUAL_NO_TOL;
	int have_tol = rc_rows_str(c->rs, i, ktol) != NULL;

	if (rc_rows_str(c->rs, i, kres) == NULL)
		return 0;
	if (opt_num(c, i, "residual", &res) != 0 ||
	    (have_tol && opt_num(c, i, "tol", &tol) != 0))
		return -1;
	if (have_tol && !(tol > 0)) {
		rc__cs_bad(c, "%s: column 'tol': %g is not a positive tolerance",
		    rc__cs_where(c, i), tol);
		return -1;
	}
	if (res <= tol)
		return 0;
	if (c->o->allow_unconverged) {
		if ((*nbad)++ == 0)
			*first = i;
		return 1;
	}
	if (have_tol)
		rc__cs_bad(c, "%s: residual %.3g exceeds the row's tolerance tol = "
		    "%.3g: an unconverged solve (gfmd-solve --max-iter?); solve "
		    "it again, or --allow-unconverged", rc__cs_where(c, i), res,
		    tol);
	else
		rc__cs_bad(c, "%s: residual %.3g exceeds %.3g (the row has no tol "
		    "column): an unconverged solve; solve it again, or "
		    "--allow-unconverged", rc__cs_where(c, i), res,
		    RC_CSTATS_RESIDUAL_NO_TOL);
	return -1;
}

struct rec *
rc__cs_validate(struct ctx *c, size_t *nrec)
{
	const rc_rowset *rs = c->rs;
	struct rec *r = rc__cs_pool_alloc(c, rs->nrows, sizeof(*r));
	size_t n = 0, nunconv = 0, first_unconv = 0;
	int warned_gbar_c = 0, warned_ncl = 0;

	for (size_t i = 0; i < rs->nrows; i++) {
		if (check_row(c, i, &r[n]) != 0 ||
		    check_converged(c, i, &nunconv, &first_unconv) < 0)
			continue;
		if (isnan(r[n].gratio) && !warned_gbar_c++)
			rc__cs_warn(c, RC_CSTATS_WARN_MISSING,
			    "%s: no gbar_c (or nan): "
			    "kappa_c is nan for such rows", rc__cs_where(c, i));
		if ((isnan(r[n].n_c) || isnan(r[n].n_cl) || isnan(r[n].n_tot)) &&
		    !warned_ncl++)
			rc__cs_warn(c, RC_CSTATS_WARN_MISSING,
			    "%s: no n_c, n_cl or n_tot: "
			    "Yastrebov estimates are nan and a_r_err has no "
			    "counting floor for such rows",
			    rc__cs_where(c, i));
		n++;
	}
	rc__cs_check_errors(c);
	if (nunconv)
		rc__cs_warn(c, RC_CSTATS_WARN_UNCONVERGED, "%s: %zu row%s from "
		    "unconverged solves (residual above tol) used as asked by "
		    "--allow-unconverged; their a_r is not converged",
		    rc__cs_where(c, first_unconv), nunconv, nunconv == 1 ? "" :
		    "s");
	*nrec = n;
	return r;
}
