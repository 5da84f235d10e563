/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cstats_impl.h - what the parts of contact-stats' library share: the
 * validated rows, the estimates, the run's context and its helpers
 * (cstats_input.c: pool, messages, keys, validation; cstats_stages.c: the
 * continuum, ensemble and limit stages; cstats.c: output and the API).
 * Not installed; nothing outside lib/cstats*.c includes it.
 */
#ifndef RC_CSTATS_IMPL_H
#define RC_CSTATS_IMPL_H

#include <setjmp.h>
#include <stddef.h>

#include "cstats.h"

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
	double a_r_floor;	/* the least a_r_err may be (cstats.h) */
	double a_rich, a_y, a_y011, a_ymod, alpha_mod;
	double gratio, gratio_err;
	double order, order_err;
	double eps_f, eps_t;
	size_t n_seeds, n_disc;
	const char *eps_c_all, *eps_c_used, *eps_f_list, *eps_t_list;
	const char *key;
	size_t curve_row;	/* output: first input row of the curve, its id */
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

/* ---- cstats_input.c ---- */

/* Memory from the run's pool, freed by rc_cstats_run; a failed allocation
 * fails the run. */
void *rc__cs_pool_alloc(struct ctx *c, size_t count, size_t size);
char *rc__cs_pool_printf(struct ctx *c, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

/* Fail the run: the message goes to the caller's rc_err, and control
 * longjmps back to rc_cstats_run. */
void rc__cs_fail(struct ctx *c, const char *fmt, ...)
	__attribute__((noreturn, format(printf, 2, 3)));
/* A warning of the given kind, kept in the result. */
void rc__cs_warn(struct ctx *c, enum rc_cstats_warn_kind kind,
    const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* A data problem: an error, or with lenient a skipped item;
 * rc__cs_check_errors fails the run if a pass found any. */
void rc__cs_bad(struct ctx *c, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
void rc__cs_check_errors(struct ctx *c);

int rc__cs_in_list(const char *s, const char *const *list, size_t n);
const char *rc__cs_shown(struct ctx *c, const char *s);
const char *rc__cs_where(struct ctx *c, size_t row);
const char *rc__cs_group_name(struct ctx *c, size_t row, double p_star,
    int keep_seed);

/* Grouping keys. */
int rc__cs_key_used(const struct ctx *c, size_t col, int keep_seed);
const char *rc__cs_key_text(const struct ctx *c, size_t row, int col,
    char num[32]);
const char *rc__cs_make_key(struct ctx *c, size_t row, double p_star,
    int keep_seed, int with_p);

/* Value lists ("0.125,0.25"). */
const char *rc__cs_list_of(struct ctx *c, const double *v, size_t n);
const char *rc__cs_list_merge(struct ctx *c, const char *dst,
    const char *src);

/* Input: choose the key columns, then check every row. */
void rc__cs_choose_keys(struct ctx *c);
struct rec *rc__cs_validate(struct ctx *c, size_t *nrec);

/* ---- cstats_stages.c ---- */

struct est *rc__cs_stage_continuum(struct ctx *c, struct rec *r, size_t n,
    size_t *nout);
struct est *rc__cs_stage_ensemble(struct ctx *c, struct est *in, size_t n,
    size_t *nout);
/* which: 'f' fractal (eps_f), 't' thermodynamic (eps_t). */
struct est *rc__cs_stage_limit(struct ctx *c, struct est *in, size_t n,
    int which, size_t *nout);

#endif
