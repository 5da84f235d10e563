/* contact-stats - a_r, kappa and kappa_c of gfmd-solve result rows taken to
 * the continuum limit (Richardson in eps_c), averaged over seeds, and
 * optionally to the fractal and thermodynamic limits (see contact-stats(1)).
 */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "atomic.h"
#include "common.h"
#include "extrap.h"
#include "kappa.h"
#include "rows.h"
#include "table.h"

enum {
	OPT_GROUP_BY = OPT_TOOL_FIRST,
	OPT_IGNORE,
	OPT_ORDER,
	OPT_FIT,
	OPT_ALPHA,
	OPT_NO_EXTRAPOLATE,
	OPT_PER_SEED,
	OPT_FRACTAL,
	OPT_ALPHA_F,
	OPT_THERMO,
	OPT_ALPHA_T,
	OPT_LENIENT,
	OPT_GNUPLOT,
	OPT_SCHEDULE,
	OPT_EPS_REF,
	OPT_P_REF
};


/* Columns gfmd-solve computes: never grouping keys.  nx and ny are the
 * discretisation; everything else (lx, ly, method and the surface's
 * metadata) identifies the problem. */
static const char *const output_cols[] = {
	"p_star", "p", "a_r", "n_c", "n_cl", "n_tot", "a_yastrebov", "gbar",
	"gbar_c", "gbar_c_prime", "kappa", "kappa_c", "mean_gap",
	"elastic_energy", "n_patches", "patch_size_char", "iterations",
	"residual", "seconds", "nx", "ny", NULL
};

/* Metadata derived from the sampled heights, which differ slightly between
 * grids of the same surface: not keys unless --group-by names them. */
static const char *const derived_cols[] = {
	"warp_hmin", "warp_hmax", NULL
};

/* Our own output columns; a key column with one of these names is written
 * as key_NAME. */
static const char *const result_cols[] = {
	"p_star", "a_r", "a_r_err", "kappa", "kappa_err", "kappa_c",
	"kappa_c_err", "a_over_p", "a_r_sd", "n_seeds", "n_disc", "eps_c",
	"eps_f", "eps_t", "order", "order_err", "a_richardson", "a_yastrebov",
	"a_yastrebov_mod", "alpha_mod", "gbar_c_ratio", "method", NULL
};

static void
usage(void)
{
	printf(
"usage: contact-stats [options] [FILE ...]\n"
"       contact-stats --schedule --eps-ref E --p-ref P -p P[,P...] [--json]\n"
"Reads gfmd-solve result rows (TSV or JSON; FILE - or none: standard input),\n"
"extrapolates a_r to the continuum limit per surface and pressure, averages\n"
"over seeds and writes a_r, kappa, kappa_c with errors, one row per group\n"
"and pressure.\n"
"  -o FILE             output (default standard output)\n"
"  --json              JSON instead of TSV\n"
"  -q                  no warnings about missing optional columns\n"
"  -j N                accepted like every tool's; no effect (one thread)\n"
"  --group-by COLS     key columns (comma list) instead of all carried ones\n"
"  --ignore COLS       drop these columns from the keys\n"
"  --order K[,K...]|auto  exponents of the eps_c corrections (default 1);\n"
"                      auto fits one exponent (3+ discretisations; linear\n"
"                      with 2)\n"
"  --fit finest|lsq    exact through the finest points (default) or least\n"
"                      squares over all\n"
"  --alpha A           Yastrebov's alpha in Eq. 22 (default (pi-1+ln2)/24)\n"
"  --no-extrapolate    use the finest raw a_r of each surface, no Richardson\n"
"  --per-seed          one row per seed, no ensemble average\n"
"  --fractal           extrapolate eps_f = lambda_s/lambda_r -> 0\n"
"  --alpha-f K|auto    exponent of the eps_f correction (default 1)\n"
"  --thermo            extrapolate eps_t = lambda_r/lx -> 0\n"
"  --alpha-t K|auto    exponent of the eps_t correction (default 1)\n"
"  --lenient           skip bad rows and groups, with a warning count\n"
"  --gnuplot FILE      write a gnuplot script plotting kappa vs p* to a PNG\n"
"  --schedule          print eps(p) = eps_ref (p/p_ref)^(1/4) (Eq. 27)\n"
"  --eps-ref E, --p-ref P, -p P[,P...]   its parameters\n"
"  -h, --help          this text;  --version\n");
}

struct opts {
	char **group_by, **ignore;
	size_t ngroup_by, nignore;
	int have_group_by;
	rc_extrap_opts cont, frac, therm;
	double alpha;
	int no_extrapolate, per_seed, fractal, thermo, lenient;
	const char *gnuplot;
	int schedule;
	double eps_ref, p_ref;
	double *pressures;
	size_t npressures;
};

/* A validated input row. */
struct rec {
	size_t row;
	double p_star, a_r, eps_c, n_c, n_cl, n_tot, gratio;
	double lambda_s, lambda_r, lx;
	long nx, ny;
	char *key;		/* grouping key of the current stage */
};

/* An estimate at some stage: per surface, per ensemble, per limit. */
struct est {
	size_t row;		/* representative input row: keys, file:line */
	double p_star;
	double a_r, a_r_err, a_r_sd;
	double a_rich, a_y, a_ymod, alpha_mod;
	double gratio, gratio_err;
	double order, order_err;
	double eps_f, eps_t;
	size_t n_seeds, n_disc;
	char eps_c_list[256], eps_f_list[256], eps_t_list[256];
	char *key;
};

static struct tool t;
static rc_rowset rs;
static int *is_key;		/* per rowset column */
static int col_seed, col_lambda_s, col_lambda_r, col_lx, col_ly;
static int excl_lambda_s, excl_lx;	/* limits taken: key shows "limit" */
static size_t nerrs, nskipped;
static char first_skip[1024], first_err[1024];

/* A data problem: an error, or with --lenient a skipped item. */
static void
bad(const struct opts *o, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

static void
bad(const struct opts *o, const char *fmt, ...)
{
	char msg[1024];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	if (o->lenient) {
		if (nskipped++ == 0)
			snprintf(first_skip, sizeof(first_skip), "%s", msg);
		return;
	}
	if (nerrs++ == 0)
		snprintf(first_err, sizeof(first_err), "%s", msg);
}

/* One line for all the data problems found in a pass: the first, and how
 * many more (a broken input gives exactly one line). */
static void
errors_exit(void)
{
	if (nerrs == 0)
		return;
	if (nerrs > 1)
		fprintf(stderr, "%s: %s (and %zu more problem%s)\n", t.name,
		    first_err, nerrs - 1, nerrs == 2 ? "" : "s");
	else
		fprintf(stderr, "%s: %s\n", t.name, first_err);
	exit(tool_exit(&t, 1));
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

/* Split a comma list into strings; empty names are usage errors. */
static void
name_list(const char *opt, const char *arg, char ***out, size_t *n)
{
	char *copy = strdup(arg), *save = NULL, *tok;

	if (copy == NULL)
		tool_fail(&t, "out of memory");
	*n = 0;
	*out = calloc(strlen(arg) + 1, sizeof(**out));
	if (*out == NULL)
		tool_fail(&t, "out of memory");
	for (tok = strtok_r(copy, ",", &save); tok; tok = strtok_r(NULL, ",", &save))
		(*out)[(*n)++] = tok;
	if (*n == 0 || strstr(arg, ",,") || arg[0] == ',' ||
	    arg[strlen(arg) - 1] == ',')
		tool_bad(&t, "%s %s: want a comma-separated list of column names",
		    opt, arg);
}

/* "auto" or increasing positive exponents. */
static void
order_arg(const char *opt, const char *arg, rc_extrap_opts *e, int many)
{
	double *v;
	size_t n;

	memset(e, 0, sizeof(*e));
	e->nterms = 1;
	e->exponent[0] = 1;
	if (strcmp(arg, "auto") == 0) {
		e->auto_order = 1;
		return;
	}
	if (tool_double_list(&t, opt, arg, &v, &n) != 0)
		return;
	if (n > (many ? RC_EXTRAP_MAXTERMS : 1)) {
		tool_bad(&t, "%s %s: at most %d exponent%s", opt, arg,
		    many ? RC_EXTRAP_MAXTERMS : 1, many ? "s" : "");
		n = 0;
	}
	for (size_t i = 0; i < n; i++)
		if (!(v[i] > 0) || v[i] > 10 || (i && !(v[i] > v[i - 1]))) {
			tool_bad(&t, "%s %s: exponents must be in (0, 10] and increasing",
			    opt, arg);
			n = 0;
			break;
		}
	if (n > 0) {
		e->nterms = n;
		memcpy(e->exponent, v, n * sizeof(*v));
	}
	free(v);
}

/* Text of a key cell: numbers to 12 significant digits, so that 0.5 and
 * 0.50 (or JSON 5e-1) are the same key. */
static void
key_text(size_t row, int col, char *buf, size_t len)
{
	const char *s = rc_rows_str(&rs, row, col);
	double v;

	if (s == NULL)
		snprintf(buf, len, "\x1e");
	else if (rc_rows_num(&rs, row, col, &v) == 0)
		snprintf(buf, len, "%.12g", v);
	else
		snprintf(buf, len, "%s", s);
}

/* Grouping key of a row: p_star (10 digits) and the key columns, minus
 * seed (unless keep_seed) and the columns whose limit has been taken. */
static char *
make_key(size_t row, double p_star, int keep_seed, int with_p)
{
	size_t len = 64, cap = 256;
	char *k = malloc(cap), cell[512];

	if (k == NULL)
		tool_fail(&t, "out of memory");
	if (with_p)
		snprintf(k, cap, "%.10g", p_star);
	else
		k[0] = '\0';
	len = strlen(k);
	for (size_t c = 0; c < rs.ncols; c++) {
		if (!is_key[c] || ((int)c == col_seed && !keep_seed))
			continue;
		if ((excl_lambda_s && (int)c == col_lambda_s) ||
		    (excl_lx && ((int)c == col_lx || (int)c == col_ly)))
			continue;
		key_text(row, (int)c, cell, sizeof(cell));
		size_t n = strlen(cell) + 2;
		if (len + n + 1 > cap) {
			cap = 2 * (len + n + 1);
			if ((k = realloc(k, cap)) == NULL)
				tool_fail(&t, "out of memory");
		}
		k[len++] = '\x1f';
		memcpy(k + len, cell, n - 1);
		len += n - 2;
		k[len] = '\0';
	}
	return k;
}

/* Up to 40 bytes of a cell for a message, control characters as '?', so
 * that every message stays on one line. */
static const char *
shown(const char *s)
{
	static char buf[2][48];
	static int k;
	size_t i;

	k ^= 1;
	for (i = 0; s[i] && i < 40; i++)
		buf[k][i] = (unsigned char)s[i] < 0x20 || s[i] == 0x7f ? '?' : s[i];
	buf[k][i] = '\0';
	return buf[k];
}

/* "p_star=0.05 H=0.8 seed=3" for messages. */
static const char *
group_name(size_t row, double p_star, int keep_seed)
{
	static char buf[1024];
	size_t len;

	snprintf(buf, sizeof(buf), "group p_star=%.10g", p_star);
	for (size_t c = 0; c < rs.ncols; c++) {
		const char *s;
		if (!is_key[c] || ((int)c == col_seed && !keep_seed) ||
		    (excl_lambda_s && (int)c == col_lambda_s) ||
		    (excl_lx && ((int)c == col_lx || (int)c == col_ly)))
			continue;
		s = rc_rows_str(&rs, row, (int)c);
		len = strlen(buf);
		snprintf(buf + len, sizeof(buf) - len, " %s=%s", rs.col[c],
		    s ? shown(s) : "(absent)");
	}
	return buf;
}

/* "file:line" of a row; two buffers, so one message can name two rows. */
static const char *
where(size_t row)
{
	static char buf[2][1100];
	static int k;
	k ^= 1;
	snprintf(buf[k], sizeof(buf[k]), "%s:%ld", rs.row[row].file,
	    rs.row[row].line);
	return buf[k];
}

/* ---- input ---- */

static void
read_inputs(int argc, char **argv, const struct opts *o)
{
	rc_err err;
	int n = argc - optind;

	for (int i = 0; i < (n ? n : 1); i++) {
		const char *path = n ? argv[optind + i] : "-";
		FILE *fp;
		int rc;
		if (rc_is_stdio(path)) {
			if (isatty(STDIN_FILENO))
				tool_fail(&t, "standard input: is a terminal; give files or a pipe");
			rc = rc_rows_read(&rs, stdin, "standard input", o->lenient, &err);
		} else {
			if ((fp = fopen(path, "rb")) == NULL)
				tool_fail(&t, "%s: %s", path, strerror(errno));
			rc = rc_rows_read(&rs, fp, path, o->lenient, &err);
			fclose(fp);
		}
		if (rc != 0)
			tool_fail(&t, "%s", err.msg);
	}
	if (rs.nskipped) {
		nskipped += rs.nskipped;
		if (first_skip[0] == '\0')
			snprintf(first_skip, sizeof(first_skip), "%s", rs.first_skip);
	}
}

/* Which columns are keys. */
static void
choose_keys(const struct opts *o)
{
	if ((is_key = calloc(rs.ncols ? rs.ncols : 1, sizeof(*is_key))) == NULL)
		tool_fail(&t, "out of memory");
	for (size_t i = 0; i < o->ngroup_by; i++)
		if (rc_rows_column(&rs, o->group_by[i]) < 0)
			tool_fail(&t, "--group-by: no input has a column '%s'",
			    o->group_by[i]);
	for (size_t i = 0; i < o->nignore; i++)
		if (rc_rows_column(&rs, o->ignore[i]) < 0)
			tool_fail(&t, "--ignore: no input has a column '%s'", o->ignore[i]);
	for (size_t c = 0; c < rs.ncols; c++) {
		const char *name = rs.col[c];
		if (o->have_group_by)
			is_key[c] = in_list(name, (const char *const *)o->group_by,
			    o->ngroup_by) || strcmp(name, "seed") == 0;
		else
			is_key[c] = !in_list(name, output_cols, 0) &&
			    !in_list(name, derived_cols, 0);
		if (in_list(name, (const char *const *)o->ignore, o->nignore) ||
		    strcmp(name, "nx") == 0 || strcmp(name, "ny") == 0 ||
		    strcmp(name, "p_star") == 0)
			is_key[c] = 0;
	}
	col_seed = rc_rows_column(&rs, "seed");
	col_lambda_s = rc_rows_column(&rs, "lambda_s");
	col_lambda_r = rc_rows_column(&rs, "lambda_r");
	col_lx = rc_rows_column(&rs, "lx");
	col_ly = rc_rows_column(&rs, "ly");
}

/* A required number; reports and returns -1 if absent or not a number. */
static int
need_num(const struct opts *o, size_t row, const char *name, double *v)
{
	int c = rc_rows_column(&rs, name);
	const char *s = rc_rows_str(&rs, row, c);

	if (s == NULL) {
		bad(o, "%s: no column '%s'", where(row), name);
		return -1;
	}
	if (rc_rows_num(&rs, row, c, v) != 0 || !isfinite(*v)) {
		bad(o, "%s: column '%s': '%s' is not a finite number", where(row),
		    name, shown(s));
		return -1;
	}
	return 0;
}

/* An optional number: NaN if absent or null/nan; text is an error. */
static int
opt_num(const struct opts *o, size_t row, const char *name, double *v)
{
	int c = rc_rows_column(&rs, name);
	const char *s = rc_rows_str(&rs, row, c);

	*v = NAN;
	if (s == NULL)
		return 0;
	if (rc_rows_num(&rs, row, c, v) != 0 || isinf(*v)) {
		bad(o, "%s: column '%s': '%s' is not a number", where(row), name,
		    shown(s));
		return -1;
	}
	return 0;
}

static struct rec *
validate(const struct opts *o, size_t *nrec)
{
	struct rec *r = calloc(rs.nrows ? rs.nrows : 1, sizeof(*r));
	size_t n = 0, nerr0;
	int warned_gbar_c = 0, warned_ncl = 0;

	if (r == NULL)
		tool_fail(&t, "out of memory");
	for (size_t i = 0; i < rs.nrows; i++) {
		struct rec *x = &r[n];
		double nx, ny, gbar, gbar_c, ly;
		size_t skip0 = nskipped;
		nerr0 = nerrs;
		x->row = i;
		need_num(o, i, "p_star", &x->p_star);
		need_num(o, i, "a_r", &x->a_r);
		need_num(o, i, "nx", &nx);
		need_num(o, i, "ny", &ny);
		need_num(o, i, "lx", &x->lx);
		opt_num(o, i, "ly", &ly);
		opt_num(o, i, "n_c", &x->n_c);
		opt_num(o, i, "n_cl", &x->n_cl);
		opt_num(o, i, "n_tot", &x->n_tot);
		opt_num(o, i, "gbar", &gbar);
		opt_num(o, i, "gbar_c", &gbar_c);
		opt_num(o, i, "lambda_s", &x->lambda_s);
		opt_num(o, i, "lambda_r", &x->lambda_r);
		if (nerrs != nerr0 || nskipped != skip0)
			continue;
		if (!(x->p_star > 0))
			bad(o, "%s: column 'p_star': %g is not positive", where(i), x->p_star);
		else if (!(x->a_r >= 0 && x->a_r <= 1))
			bad(o, "%s: column 'a_r': %g is outside [0, 1]", where(i), x->a_r);
		else if (nx < 1 || ny < 1 || nx != floor(nx) || ny != floor(ny) ||
		    nx > 1e9 || ny > 1e9)
			bad(o, "%s: nx = %g, ny = %g: want positive integers", where(i),
			    nx, ny);
		else if (!(x->lx > 0))
			bad(o, "%s: column 'lx': %g is not positive", where(i), x->lx);
		else if (x->lambda_s <= 0 || x->lambda_r <= 0)
			bad(o, "%s: lambda_s = %g, lambda_r = %g: must be positive",
			    where(i), x->lambda_s, x->lambda_r);
		else if (x->n_c < 0 || x->n_cl < 0 || x->n_tot <= 0 ||
		    x->n_c > x->n_tot || x->n_cl > x->n_c)
			bad(o, "%s: n_c = %g, n_cl = %g, n_tot = %g: want "
			    "0 <= n_cl <= n_c <= n_tot, n_tot > 0", where(i), x->n_c,
			    x->n_cl, x->n_tot);
		if (nerrs != nerr0 || nskipped != skip0)
			continue;
		x->nx = (long)nx;
		x->ny = (long)ny;
		/* eps_c = da/lambda_s; without lambda_s (indenters) da/lx: the
		 * limit eps -> 0 does not depend on the scale of eps. */
		x->eps_c = x->lx / nx / (isnan(x->lambda_s) ? x->lx : x->lambda_s);
		x->gratio = gbar > 0 && gbar_c > 0 ? gbar_c / gbar : NAN;
		if (isnan(gbar_c) && !warned_gbar_c++ && !t.quiet)
			tool_warn(&t, "%s: no gbar_c (or nan): kappa_c is nan for "
			    "such rows", where(i));
		if ((isnan(x->n_c) || isnan(x->n_cl) || isnan(x->n_tot)) &&
		    !warned_ncl++ && !t.quiet)
			tool_warn(&t, "%s: no n_c, n_cl or n_tot: Yastrebov estimates "
			    "are nan for such rows", where(i));
		n++;
	}
	errors_exit();
	*nrec = n;
	return r;
}

/* ---- stages ---- */

static int
by_key_rec(const void *a, const void *b)
{
	const struct rec *x = a, *y = b;
	int c = strcmp(x->key, y->key);
	if (c)
		return c;
	if (x->eps_c != y->eps_c)
		return (x->eps_c > y->eps_c) - (x->eps_c < y->eps_c);
	return (x->row > y->row) - (x->row < y->row);
}

static int
by_key_est(const void *a, const void *b)
{
	const struct est *x = a, *y = b;
	int c = strcmp(x->key, y->key);
	if (c)
		return c;
	return (x->row > y->row) - (x->row < y->row);
}

static void
list_append(char *buf, size_t len, double v)
{
	size_t n = strlen(buf);
	snprintf(buf + n, len - n, "%s%.6g", n ? "," : "", v);
}

/* Add a member's eps_c list to an ensemble's: distinct lists joined by ';'. */
static void
list_merge(char *dst, size_t len, const char *src)
{
	size_t n = strlen(src), dl = strlen(dst);
	for (const char *p = dst; p && *p; p = strchr(p, ';') ? strchr(p, ';') + 1 : NULL)
		if (strncmp(p, src, n) == 0 && (p[n] == ';' || p[n] == '\0'))
			return;
	if (dl + n + 2 <= len)
		snprintf(dst + dl, len - dl, ";%s", src);
}

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
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

/* Continuum limit of each surface (set of discretisations) at each p*. */
static struct est *
stage_continuum(const struct opts *o, struct rec *r, size_t n, size_t *nout)
{
	struct est *e = calloc(n ? n : 1, sizeof(*e));
	double *eps = malloc((n ? n : 1) * sizeof(double));
	double *y = malloc((n ? n : 1) * sizeof(double));
	double *w = malloc((n ? n : 1) * sizeof(double));
	size_t ne = 0;
	rc_err err;

	if (!e || !eps || !y || !w)
		tool_fail(&t, "out of memory");
	for (size_t i = 0; i < n; i++)
		r[i].key = make_key(r[i].row, r[i].p_star, 1, 1);
	qsort(r, n, sizeof(*r), by_key_rec);
	/* Duplicates: an error, or with --lenient the later row is dropped. */
	size_t kept = n ? 1 : 0;
	for (size_t i = 1; i < n; i++) {
		struct rec *prev = &r[kept - 1];
		if (strcmp(r[i].key, prev->key) == 0 && r[i].eps_c == prev->eps_c) {
			bad(o, "%s and %s: duplicate rows (same surface, p_star and "
			    "grid %ldx%ld)", where(prev->row), where(r[i].row),
			    r[i].nx, r[i].ny);
			if (o->lenient) {
				free(r[i].key);
				r[i].key = NULL;
				continue;
			}
		}
		r[kept++] = r[i];
	}
	for (size_t i = kept; i < n; i++)
		r[i].key = NULL;
	n = kept;
	errors_exit();
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strcmp(r[b].key, r[a].key) == 0; b++)
			;
		size_t m = b - a;
		struct rec *f = &r[a];	/* finest: smallest eps_c */
		struct est *x = &e[ne];
		memset(x, 0, sizeof(*x));
		x->row = f->row;
		x->p_star = f->p_star;
		x->n_seeds = 1;
		x->n_disc = m;
		x->a_r_sd = NAN;
		x->eps_f = f->lambda_s / f->lambda_r;
		x->eps_t = f->lambda_r / f->lx;
		for (size_t i = a; i < b; i++)
			list_append(x->eps_c_list, sizeof(x->eps_c_list), r[i].eps_c);
		list_append(x->eps_f_list, sizeof(x->eps_f_list), x->eps_f);
		list_append(x->eps_t_list, sizeof(x->eps_t_list), x->eps_t);
		x->a_y = rc_yastrebov(f->n_c, f->n_cl, f->n_tot, o->alpha);
		x->alpha_mod = x->a_ymod = NAN;
		if (m >= 2) {
			x->alpha_mod = rc_yastrebov_alpha_mod(f->n_c, f->n_cl, f->n_tot,
			    r[a + 1].n_c, r[a + 1].n_cl, r[a + 1].n_tot);
			x->a_ymod = rc_yastrebov(f->n_c, f->n_cl, f->n_tot, x->alpha_mod);
		}
		int have_g = 1;
		for (size_t i = a; i < b; i++)
			have_g &= !isnan(r[i].gratio);
		if (o->no_extrapolate) {
			x->a_r = f->a_r;
			x->a_r_err = 0;
			x->a_rich = NAN;
			x->gratio = f->gratio;
			x->gratio_err = 0;
			x->order = x->order_err = NAN;
			x->n_disc = 1;
			x->eps_c_list[0] = '\0';
			list_append(x->eps_c_list, sizeof(x->eps_c_list), f->eps_c);
			ne++;
			continue;
		}
		/* --order auto fits the exponent where three or more grids
		 * exist; with two it falls back to the linear model, flagged by
		 * order_err = NaN. */
		rc_extrap_opts model = o->cont;
		if (model.auto_order && m == 2) {
			model.auto_order = 0;
			model.nterms = 1;
			model.exponent[0] = 1;
			model.kind = RC_FIT_FINEST;
		}
		size_t need = model.auto_order ? 3 : model.nterms + 1;
		if (m < need) {
			bad(o, "%s (%s): %zu discretisation%s, the extrapolation needs %zu "
			    "(or use --no-extrapolate)", group_name(f->row, f->p_star, 1),
			    where(f->row), m, m == 1 ? "" : "s", need);
			continue;
		}
		rc_fit fit, gfit;
		for (size_t i = 0; i < m; i++) {
			eps[i] = r[a + i].eps_c;
			y[i] = r[a + i].a_r;
		}
		if (rc_extrapolate(eps, y, m, &model, &fit, w, &err) != 0) {
			bad(o, "%s (%s): a_r: %s", group_name(f->row, f->p_star, 1),
			    where(f->row), err.msg);
			continue;
		}
		x->a_r = x->a_rich = fit.value;
		x->a_r_err = fit.err;
		x->order = fit.order;
		x->order_err = o->cont.auto_order && !model.auto_order ? NAN :
		    fit.order_err;
		x->n_disc = m;
		x->gratio = x->gratio_err = NAN;
		if (have_g) {
			for (size_t i = 0; i < m; i++)
				y[i] = r[a + i].gratio;
			/* gbar_c/gbar with the same model; with auto the exponent is
			 * fitted for this ratio separately, and when no power law
			 * fits, the finest value is used with its last change as error. */
			if (rc_extrapolate(eps, y, m, &model, &gfit, NULL, &err) == 0) {
				x->gratio = gfit.value;
				x->gratio_err = gfit.err;
			} else {
				x->gratio = f->gratio;
				x->gratio_err = fabs(f->gratio - r[a + 1].gratio);
			}
		}
		ne++;
	}
	free(eps);
	free(y);
	free(w);
	errors_exit();
	*nout = ne;
	return e;
}

/* Ensemble over seeds: mean, sd, and the error of the mean combined with
 * the mean extrapolation error (systematic: it does not average out). */
static struct est *
stage_ensemble(struct est *in, size_t n, size_t *nout)
{
	struct est *e = calloc(n ? n : 1, sizeof(*e));
	double *v = malloc((n ? n : 1) * sizeof(double));
	size_t ne = 0;
	rc_err err;

	if (!e || !v)
		tool_fail(&t, "out of memory");
	for (size_t i = 0; i < n; i++) {
		free(in[i].key);
		in[i].key = make_key(in[i].row, in[i].p_star, 0, 1);
	}
	qsort(in, n, sizeof(*in), by_key_est);
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strcmp(in[b].key, in[a].key) == 0; b++)
			;
		size_t m = b - a;
		struct est *x = &e[ne++];
		rc_ensemble st;
		double mean_err = 0, mean_gerr = 0;
		*x = in[a];
		x->key = NULL;
		x->n_seeds = m;
#define MEAN(field) do { \
		double s_ = 0; \
		for (size_t i_ = a; i_ < b; i_++) \
			s_ += in[i_].field; \
		x->field = s_ / (double)m; \
	} while (0)
		MEAN(a_rich);
		MEAN(a_y);
		MEAN(a_ymod);
		MEAN(alpha_mod);
		MEAN(order);
		MEAN(order_err);
#undef MEAN
		for (size_t i = a; i < b; i++) {
			v[i - a] = in[i].a_r;
			mean_err += in[i].a_r_err / (double)m;
			mean_gerr += in[i].gratio_err / (double)m;
			x->n_disc = in[i].n_disc < x->n_disc ? in[i].n_disc : x->n_disc;
			list_merge(x->eps_c_list, sizeof(x->eps_c_list), in[i].eps_c_list);
		}
		if (rc_ensemble_stats(v, m, &st, &err) != 0)
			tool_fail(&t, "%s: %s", group_name(x->row, x->p_star, 0), err.msg);
		x->a_r = st.mean;
		x->a_r_sd = st.sd;
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
	free(v);
	*nout = ne;
	return e;
}

/* Extrapolate eps_f (which = 'f') or eps_t ('t') to zero across groups
 * that differ only in lambda_s (f) or in lx, ly (t). */
static struct est *
stage_limit(const struct opts *o, struct est *in, size_t n, int which,
    size_t *nout)
{
	const rc_extrap_opts *model = which == 'f' ? &o->frac : &o->therm;
	struct est *e = calloc(n ? n : 1, sizeof(*e));
	double *eps = malloc((n ? n : 1) * sizeof(double));
	double *y = malloc((n ? n : 1) * sizeof(double));
	double *w = malloc((n ? n : 1) * sizeof(double));
	size_t ne = 0;
	rc_err err;
	const char *what = which == 'f' ? "eps_f = lambda_s/lambda_r" :
	    "eps_t = lambda_r/lx";

	if (!e || !eps || !y || !w)
		tool_fail(&t, "out of memory");
	if (which == 'f')
		excl_lambda_s = 1;
	else
		excl_lx = 1;
	for (size_t i = 0; i < n; i++) {
		free(in[i].key);
		in[i].key = make_key(in[i].row, in[i].p_star, o->per_seed, 1);
	}
	qsort(in, n, sizeof(*in), by_key_est);
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strcmp(in[b].key, in[a].key) == 0; b++)
			;
		size_t m = b - a, need = model->auto_order ? 3 : model->nterms + 1;
		const char *gname = group_name(in[a].row, in[a].p_star, o->per_seed);
		int ok = 1;
		for (size_t i = a; i < b; i++) {
			eps[i - a] = which == 'f' ? in[i].eps_f : in[i].eps_t;
			y[i - a] = in[i].a_r;
			if (!(eps[i - a] > 0)) {
				bad(o, "%s (%s): %s is undefined (lambda_s or lambda_r "
				    "missing)", gname, where(in[i].row), what);
				ok = 0;
				break;
			}
		}
		if (!ok)
			continue;
		if (m < need) {
			bad(o, "%s (%s): %zu value%s of %s, the extrapolation needs %zu",
			    gname, where(in[a].row), m, m == 1 ? "" : "s", what, need);
			continue;
		}
		rc_fit fit;
		if (rc_extrapolate(eps, y, m, model, &fit, w, &err) != 0) {
			bad(o, "%s (%s): %s: %s", gname, where(in[a].row), what, err.msg);
			continue;
		}
		struct est *x = &e[ne++];
		double stat = 0, gstat = 0, g = 0, gmodel = 0;
		*x = in[a];
		x->key = NULL;
		x->a_r = fit.value;
		x->a_rich = x->a_y = x->a_ymod = x->gratio = 0;
		x->alpha_mod = NAN;
		x->a_r_sd = NAN;
		char *list = which == 'f' ? x->eps_f_list : x->eps_t_list;
		list[0] = '\0';
		for (size_t i = a; i < b; i++) {
			double wi = w[i - a];
			stat += wi * wi * in[i].a_r_err * in[i].a_r_err;
			gstat += wi * wi * in[i].gratio_err * in[i].gratio_err;
			x->a_rich += wi * in[i].a_rich;
			x->a_y += wi * in[i].a_y;
			x->a_ymod += wi * in[i].a_ymod;
			g += wi * in[i].gratio;
			x->n_seeds = in[i].n_seeds < x->n_seeds ? in[i].n_seeds : x->n_seeds;
			x->n_disc = in[i].n_disc < x->n_disc ? in[i].n_disc : x->n_disc;
			list_merge(x->eps_c_list, sizeof(x->eps_c_list), in[i].eps_c_list);
		}
		/* the eps values used, increasing */
		double *sorted = malloc(m * sizeof(double));
		if (sorted == NULL)
			tool_fail(&t, "out of memory");
		memcpy(sorted, eps, m * sizeof(double));
		qsort(sorted, m, sizeof(double), cmp_double);
		for (size_t i = 0; i < m; i++)
			list_append(list, 256, sorted[i]);
		free(sorted);
		/* The ratio's model error: how far the extrapolation moves it
		 * from the member at the smallest eps (cf. a two-point estimate). */
		size_t best = 0;
		for (size_t i = 1; i < m; i++)
			if (eps[i] < eps[best])
				best = i;
		gmodel = fabs(g - in[a + best].gratio);
		x->gratio = g;
		x->gratio_err = sqrt(gstat + gmodel * gmodel);
		x->a_r_err = sqrt(stat + fit.err * fit.err);
		if (which == 'f')
			x->eps_f = 0;
		else
			x->eps_t = 0;
	}
	free(eps);
	free(y);
	free(w);
	errors_exit();
	*nout = ne;
	return e;
}

/* ---- output ---- */

static int
by_output(const void *a, const void *b)
{
	const struct est *x = a, *y = b;
	int c = strcmp(x->key, y->key);
	if (c)
		return c;
	return (x->p_star > y->p_star) - (x->p_star < y->p_star);
}

/* Sort by curve (keys without p_star; curves in order of first input row)
 * then by p*. */
static void
order_output(const struct opts *o, struct est *e, size_t n)
{
	char **k = calloc(n ? n : 1, sizeof(*k));

	if (k == NULL)
		tool_fail(&t, "out of memory");
	for (size_t i = 0; i < n; i++)
		k[i] = make_key(e[i].row, e[i].p_star, o->per_seed, 0);
	for (size_t i = 0; i < n; i++) {
		size_t first = e[i].row;
		for (size_t j = 0; j < n; j++)
			if (e[j].row < first && strcmp(k[i], k[j]) == 0)
				first = e[j].row;
		free(e[i].key);
		if ((e[i].key = malloc(strlen(k[i]) + 32)) == NULL)
			tool_fail(&t, "out of memory");
		snprintf(e[i].key, strlen(k[i]) + 32, "%020zu%s", first, k[i]);
	}
	for (size_t i = 0; i < n; i++)
		free(k[i]);
	free(k);
	qsort(e, n, sizeof(*e), by_output);
}

struct derived {
	double a_r, kappa, kappa_err, kappa_c, kappa_c_err;
};

/* Eq. 24 and Eq. 8; errors by linear propagation:
 * d kappa / d a_r = exp(x^2)/p* with x = erfinv(a_r), and kappa_c =
 * kappa gbar_c/gbar. */
static struct derived
derive(const struct est *x, int warn)
{
	struct derived d;
	double a = x->a_r;

	if ((a < 0 || a > 1) && warn)
		tool_warn(&t, "%s: extrapolated a_r = %.6g left [0, 1]; clamped",
		    group_name(x->row, x->p_star, 0), a);
	if (a < 0 || a > 1)
		a = a < 0 ? 0 : 1;
	d.a_r = a;
	double xi = rc_erfinv(a);
	d.kappa = rc_kappa(a, x->p_star);
	d.kappa_err = a == 1 ? INFINITY : exp(xi * xi) * x->a_r_err / x->p_star;
	d.kappa_c = x->gratio * d.kappa;
	d.kappa_c_err = hypot(x->gratio * d.kappa_err, d.kappa * x->gratio_err);
	return d;
}

static void
method_text(const struct opts *o, char *buf, size_t len)
{
	char m[64];

	if (o->no_extrapolate)
		snprintf(buf, len, "finest");
	else
		snprintf(buf, len, "%s(%s)", o->cont.kind == RC_FIT_LSQ ? "lsq" :
		    "richardson", model_name(&o->cont, m, sizeof(m)));
	if (!o->per_seed)
		strncat(buf, "+ensemble", len - strlen(buf) - 1);
	if (o->fractal) {
		size_t n = strlen(buf);
		snprintf(buf + n, len - n, "+fractal(%s)", model_name(&o->frac, m,
		    sizeof(m)));
	}
	if (o->thermo) {
		size_t n = strlen(buf);
		snprintf(buf + n, len - n, "+thermo(%s)", model_name(&o->therm, m,
		    sizeof(m)));
	}
}

static int
key_shown(const struct opts *o, size_t c)
{
	return is_key[c] && ((int)c != col_seed || o->per_seed);
}

static void
fill_row(const struct opts *o, rc_row *row, const struct est *x,
    const char *method)
{
	struct derived d = derive(x, 1);
	char name[600];
	int bad_alloc = 0;

	rc_row_clear(row);
	bad_alloc |= rc_row_num(row, "p_star", x->p_star);
	bad_alloc |= rc_row_num(row, "a_r", d.a_r);
	bad_alloc |= rc_row_num(row, "a_r_err", x->a_r_err);
	bad_alloc |= rc_row_num(row, "kappa", d.kappa);
	bad_alloc |= rc_row_num(row, "kappa_err", d.kappa_err);
	bad_alloc |= rc_row_num(row, "kappa_c", d.kappa_c);
	bad_alloc |= rc_row_num(row, "kappa_c_err", d.kappa_c_err);
	bad_alloc |= rc_row_num(row, "a_over_p", d.a_r / x->p_star);
	bad_alloc |= rc_row_num(row, "a_r_sd", x->a_r_sd);
	bad_alloc |= rc_row_int(row, "n_seeds", (long long)x->n_seeds);
	bad_alloc |= rc_row_int(row, "n_disc", (long long)x->n_disc);
	bad_alloc |= rc_row_str(row, "eps_c", x->eps_c_list);
	bad_alloc |= rc_row_str(row, "eps_f", x->eps_f_list);
	bad_alloc |= rc_row_str(row, "eps_t", x->eps_t_list);
	bad_alloc |= rc_row_num(row, "order", x->order);
	bad_alloc |= rc_row_num(row, "order_err", x->order_err);
	bad_alloc |= rc_row_num(row, "a_richardson", x->a_rich);
	bad_alloc |= rc_row_num(row, "a_yastrebov", x->a_y);
	bad_alloc |= rc_row_num(row, "a_yastrebov_mod", x->a_ymod);
	bad_alloc |= rc_row_num(row, "alpha_mod", x->alpha_mod);
	bad_alloc |= rc_row_num(row, "gbar_c_ratio", x->gratio);
	for (size_t c = 0; c < rs.ncols; c++) {
		if (!key_shown(o, c))
			continue;
		const char *s = rc_rows_str(&rs, x->row, (int)c);
		double v;
		snprintf(name, sizeof(name), "%s%s", in_list(rs.col[c], result_cols, 0) ?
		    "key_" : "", rs.col[c]);
		if ((excl_lambda_s && (int)c == col_lambda_s) ||
		    (excl_lx && ((int)c == col_lx || (int)c == col_ly)))
			bad_alloc |= rc_row_str(row, name, "limit");
		else if (s == NULL)
			bad_alloc |= rc_row_str(row, name, "");
		else if (rc_rows_num(&rs, x->row, (int)c, &v) == 0)
			bad_alloc |= rc_row_num(row, name, v);
		else
			bad_alloc |= rc_row_str(row, name, s);
	}
	bad_alloc |= rc_row_str(row, "method", method);
	if (bad_alloc)
		tool_fail(&t, "out of memory");
}

/* Label of a curve: the key columns whose values differ between curves. */
static void
curve_label(const struct opts *o, const struct est *e, size_t n, size_t i,
    char *buf, size_t len)
{
	buf[0] = '\0';
	for (size_t c = 0; c < rs.ncols; c++) {
		char a[512], b[512];
		int varies = 0;
		if (!key_shown(o, c))
			continue;
		key_text(e[0].row, (int)c, a, sizeof(a));
		for (size_t j = 1; j < n && !varies; j++) {
			key_text(e[j].row, (int)c, b, sizeof(b));
			varies = strcmp(a, b) != 0;
		}
		if (!varies)
			continue;
		const char *s = rc_rows_str(&rs, e[i].row, (int)c);
		size_t k = strlen(buf);
		snprintf(buf + k, len - k, "%s%s=%s", k ? " " : "", rs.col[c],
		    s ? s : "");
	}
	for (char *p = buf; *p; p++)
		if (*p == '\'' || *p == '"' || *p == '\\' || (unsigned char)*p < 0x20)
			*p = '_';
	if (buf[0] == '\0')
		snprintf(buf, len, "kappa");
}

static void
write_gnuplot(const struct opts *o, const struct est *e, size_t n)
{
	rc_atomic out;
	rc_err err;
	char png[4096], label[1024];
	const char *path = o->gnuplot, *dot = strrchr(path, '.');
	const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
	/* FILE.gp -> FILE.png; a name without an extension gets .png added */
	size_t stem = dot && dot > base ? (size_t)(dot - path) : strlen(path);

	if (stem > sizeof(png) - 5)
		tool_fail(&t, "--gnuplot %s: name too long", path);
	snprintf(png, sizeof(png), "%.*s.png", (int)stem, path);
	for (char *p = png; *p; p++)
		if (*p == '\'')
			tool_fail(&t, "--gnuplot %s: a quote in the name", path);
	if (rc_atomic_open(&out, path, &err) != 0)
		tool_fail(&t, "%s: %s", path, err.msg);
	FILE *fp = out.fp;
	fprintf(fp, "# Written by contact-stats: kappa(p*) with error bars.\n"
	    "# Run: gnuplot %s   (writes %s)\n"
	    "set terminal png size 900,650\n"
	    "set output '%s'\n"
	    "set logscale x\n"
	    "set xlabel 'p*'\n"
	    "set ylabel 'kappa'\n"
	    "set key outside right\n"
	    "set grid\n", path, png, png);
	double pmin = INFINITY, pmax = 0;
	for (size_t i = 0; i < n; i++) {
		pmin = fmin(pmin, e[i].p_star);
		pmax = fmax(pmax, e[i].p_star);
	}
	/* reference lines across the whole range, a margin around the data */
	fprintf(fp, "set xrange [%.6g:%.6g]\n", pmin / 1.5, pmax * 1.5);
	size_t ncurve = 0;
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strncmp(e[b].key, e[a].key, 20) == 0; b++)
			;
		fprintf(fp, "$curve%zu << EOD\n# p_star kappa kappa_err\n", ncurve++);
		for (size_t i = a; i < b; i++) {
			struct derived d = derive(&e[i], 0);
			if (isfinite(d.kappa) && isfinite(d.kappa_err))
				fprintf(fp, "%.10g %.10g %.10g\n", e[i].p_star, d.kappa,
				    d.kappa_err);
		}
		fprintf(fp, "EOD\n");
	}
	fprintf(fp, "plot \\\n");
	ncurve = 0;
	for (size_t a = 0, b; a < n; a = b) {
		for (b = a + 1; b < n && strncmp(e[b].key, e[a].key, 20) == 0; b++)
			;
		curve_label(o, e, n, a, label, sizeof(label));
		fprintf(fp, "  $curve%zu using 1:2:3 with yerrorlines title '%s', \\\n",
		    ncurve++, label);
	}
	fprintf(fp, "  sqrt(8/pi) dashtype 2 title 'Persson sqrt(8/pi)', \\\n"
	    "  sqrt(2*pi) dashtype 3 title 'BGT sqrt(2 pi)'\n");
	if (rc_atomic_commit(&out, &err) != 0)
		tool_fail(&t, "%s: %s", path, err.msg);
}

static int
run_schedule(const struct opts *o)
{
	rc_table_out tab;
	rc_row row;
	rc_err err;
	rc_atomic out;

	if (rc_atomic_open(&out, t.out, &err) != 0)
		tool_fail(&t, "%s: %s", t.out, err.msg);
	rc_table_begin(&tab, out.fp, t.json);
	rc_row_init(&row);
	for (size_t i = 0; i < o->npressures; i++) {
		double eps = rc_eps_schedule(o->eps_ref, o->p_ref, o->pressures[i]);
		rc_row_clear(&row);
		if (rc_row_num(&row, "p_star", o->pressures[i]) ||
		    rc_row_num(&row, "eps", eps) ||
		    rc_row_num(&row, "inv_eps", 1 / eps) ||
		    rc_table_write(&tab, &row, &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "writing the schedule failed");
		}
	}
	rc_table_end(&tab, &err);
	rc_row_free(&row);
	if (rc_atomic_commit(&out, &err) != 0)
		tool_fail(&t, "%s: %s", t.out ? t.out : "standard output", err.msg);
	return 0;
}

int
main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "json", no_argument, NULL, OPT_JSON },
		{ "version", no_argument, NULL, OPT_VERSION },
		{ "help", no_argument, NULL, 'h' },
		{ "group-by", required_argument, NULL, OPT_GROUP_BY },
		{ "ignore", required_argument, NULL, OPT_IGNORE },
		{ "order", required_argument, NULL, OPT_ORDER },
		{ "fit", required_argument, NULL, OPT_FIT },
		{ "alpha", required_argument, NULL, OPT_ALPHA },
		{ "no-extrapolate", no_argument, NULL, OPT_NO_EXTRAPOLATE },
		{ "per-seed", no_argument, NULL, OPT_PER_SEED },
		{ "fractal", no_argument, NULL, OPT_FRACTAL },
		{ "alpha-f", required_argument, NULL, OPT_ALPHA_F },
		{ "thermo", no_argument, NULL, OPT_THERMO },
		{ "alpha-t", required_argument, NULL, OPT_ALPHA_T },
		{ "lenient", no_argument, NULL, OPT_LENIENT },
		{ "gnuplot", required_argument, NULL, OPT_GNUPLOT },
		{ "schedule", no_argument, NULL, OPT_SCHEDULE },
		{ "eps-ref", required_argument, NULL, OPT_EPS_REF },
		{ "p-ref", required_argument, NULL, OPT_P_REF },
		{ NULL, 0, NULL, 0 }
	};
	struct opts o;
	int c, have_eps_ref = 0, have_p_ref = 0, have_p = 0, fit_set = 0;

	tool_init(&t, "contact-stats", argc, argv);
	memset(&o, 0, sizeof(o));
	o.alpha = RC_YASTREBOV_ALPHA;
	order_arg("--order", "1", &o.cont, 1);
	order_arg("--alpha-f", "1", &o.frac, 0);
	order_arg("--alpha-t", "1", &o.therm, 0);
	while ((c = getopt_long(argc, argv, "o:p:j:qh", longopts, NULL)) != -1) {
		switch (c) {
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case 'p':
			have_p = 1;
			free(o.pressures);
			if (tool_double_list(&t, "-p", optarg, &o.pressures,
			    &o.npressures) == 0)
				for (size_t i = 0; i < o.npressures; i++)
					if (!(o.pressures[i] > 0)) {
						tool_bad(&t, "-p %s: pressures must be positive", optarg);
						break;
					}
			break;
		case OPT_GROUP_BY:
			name_list("--group-by", optarg, &o.group_by, &o.ngroup_by);
			o.have_group_by = 1;
			break;
		case OPT_IGNORE:
			name_list("--ignore", optarg, &o.ignore, &o.nignore);
			break;
		case OPT_ORDER: {
			enum rc_fit_kind k = o.cont.kind;
			order_arg("--order", optarg, &o.cont, 1);
			o.cont.kind = k;
			break;
		}
		case OPT_FIT:
			fit_set = 1;
			if (strcmp(optarg, "finest") == 0)
				o.cont.kind = RC_FIT_FINEST;
			else if (strcmp(optarg, "lsq") == 0)
				o.cont.kind = RC_FIT_LSQ;
			else
				tool_bad(&t, "--fit %s: want finest or lsq", optarg);
			break;
		case OPT_ALPHA:
			tool_double(&t, "--alpha", optarg, &o.alpha);
			break;
		case OPT_NO_EXTRAPOLATE:
			o.no_extrapolate = 1;
			break;
		case OPT_PER_SEED:
			o.per_seed = 1;
			break;
		case OPT_FRACTAL:
			o.fractal = 1;
			break;
		case OPT_ALPHA_F:
			order_arg("--alpha-f", optarg, &o.frac, 0);
			break;
		case OPT_THERMO:
			o.thermo = 1;
			break;
		case OPT_ALPHA_T:
			order_arg("--alpha-t", optarg, &o.therm, 0);
			break;
		case OPT_LENIENT:
			o.lenient = 1;
			break;
		case OPT_GNUPLOT:
			o.gnuplot = optarg;
			break;
		case OPT_SCHEDULE:
			o.schedule = 1;
			break;
		case OPT_EPS_REF:
			if (tool_double(&t, "--eps-ref", optarg, &o.eps_ref) == 0 &&
			    !(o.eps_ref > 0))
				tool_bad(&t, "--eps-ref %s: must be positive", optarg);
			have_eps_ref = 1;
			break;
		case OPT_P_REF:
			if (tool_double(&t, "--p-ref", optarg, &o.p_ref) == 0 &&
			    !(o.p_ref > 0))
				tool_bad(&t, "--p-ref %s: must be positive", optarg);
			have_p_ref = 1;
			break;
		default:
			if (c == '?' || !tool_common_option(&t, c, optarg))
				t.nbad++;
		}
	}
	if (o.schedule) {
		if (!have_eps_ref || !have_p_ref || !have_p)
			tool_bad(&t, "--schedule needs --eps-ref, --p-ref and -p");
		if (optind < argc)
			tool_bad(&t, "--schedule reads no input files");
	} else {
		if (have_eps_ref || have_p_ref || have_p)
			tool_bad(&t, "--eps-ref, --p-ref and -p belong to --schedule");
		if (o.no_extrapolate && (o.cont.auto_order || o.cont.nterms > 1 ||
		    o.cont.exponent[0] != 1 || fit_set))
			tool_bad(&t, "--no-extrapolate excludes --order and --fit");
		if (o.cont.auto_order && fit_set && o.cont.kind == RC_FIT_FINEST)
			tool_bad(&t, "--order auto: the exponent is a fit; --fit finest "
			    "does not apply");
		if (o.have_group_by && o.nignore)
			tool_bad(&t, "--group-by and --ignore exclude each other");
	}
	if (!(fabs(o.alpha) < 1))
		tool_bad(&t, "--alpha %g: want |alpha| < 1", o.alpha);
	tool_usage_check(&t);
	if (o.schedule) {
		int st = run_schedule(&o);
		free(o.pressures);
		return tool_exit(&t, st);
	}

	rc_rows_init(&rs);
	read_inputs(argc, argv, &o);
	if (rs.nrows == 0)
		tool_fail(&t, "%s%s: no result rows (header only)", rs.file[0],
		    rs.nfiles > 1 ? " and the other inputs" : "");
	choose_keys(&o);

	size_t nrec, ne, n2;
	struct rec *r = validate(&o, &nrec);
	if (nrec == 0)
		tool_fail(&t, "no valid rows left (%zu skipped: %s)", nskipped,
		    first_skip);
	struct est *e = stage_continuum(&o, r, nrec, &ne), *e2;
	if (!o.per_seed) {
		e2 = stage_ensemble(e, ne, &n2);
		for (size_t i = 0; i < ne; i++)
			free(e[i].key);
		free(e);
		e = e2;
		ne = n2;
	}
	if (o.fractal) {
		e2 = stage_limit(&o, e, ne, 'f', &n2);
		for (size_t i = 0; i < ne; i++)
			free(e[i].key);
		free(e);
		e = e2;
		ne = n2;
	}
	if (o.thermo) {
		e2 = stage_limit(&o, e, ne, 't', &n2);
		for (size_t i = 0; i < ne; i++)
			free(e[i].key);
		free(e);
		e = e2;
		ne = n2;
	}
	if (ne == 0)
		tool_fail(&t, "no group left (%zu skipped: %s)", nskipped, first_skip);
	order_output(&o, e, ne);

	char method[256];
	rc_atomic out;
	rc_table_out tab;
	rc_row row;
	rc_err err;
	method_text(&o, method, sizeof(method));
	if (rc_atomic_open(&out, t.out, &err) != 0)
		tool_fail(&t, "%s: %s", t.out, err.msg);
	rc_table_begin(&tab, out.fp, t.json);
	rc_row_init(&row);
	for (size_t i = 0; i < ne; i++) {
		fill_row(&o, &row, &e[i], method);
		if (rc_table_write(&tab, &row, &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "%s", err.msg);
		}
	}
	rc_table_end(&tab, &err);
	rc_row_free(&row);
	if (rc_atomic_commit(&out, &err) != 0)
		tool_fail(&t, "%s: %s", t.out ? t.out : "standard output", err.msg);
	if (o.gnuplot)
		write_gnuplot(&o, e, ne);
	if (nskipped)
		tool_warn(&t, "--lenient: skipped %zu bad row%s or group%s (first: %s)",
		    nskipped, nskipped == 1 ? "" : "s", nskipped == 1 ? "" : "s",
		    first_skip);
	for (size_t i = 0; i < ne; i++)
		free(e[i].key);
	free(e);
	for (size_t i = 0; i < nrec; i++)
		free(r[i].key);
	free(r);
	free(is_key);
	free(o.group_by ? o.group_by[0] : NULL);
	free(o.group_by);
	free(o.ignore ? o.ignore[0] : NULL);
	free(o.ignore);
	rc_rows_free(&rs);
	return tool_exit(&t, 0);
}
