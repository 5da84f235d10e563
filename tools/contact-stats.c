/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact-stats - a_r, kappa and kappa_c of gfmd-solve result rows taken to
 * the continuum limit (Richardson in eps_c), averaged over seeds, and
 * optionally to the fractal and thermodynamic limits: options, input and
 * output around rc_cstats_run (see contact-stats(1)).
 */
#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "atomic.h"
#include "common.h"
#include "cstats.h"
#include "table_read.h"
#include "table_write.h"

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
	OPT_ALLOW_UNCONVERGED,
	OPT_GNUPLOT,
	OPT_SCHEDULE,
	OPT_EPS_REF,
	OPT_P_REF
};

static void
usage(void)
{
	printf(
"usage: contact-stats [options] [FILE ...]\n"
"       contact-stats --schedule --eps-ref E --p-ref P -p P[,P...]\n"
"           [--json | --pretty]\n"
"Reads gfmd-solve result rows (TSV or JSON; FILE - or none: standard input),\n"
"extrapolates a_r to the continuum limit per surface and pressure, averages\n"
"over seeds and writes a_r, kappa, kappa_c with errors, one row per group\n"
"and pressure.\n"
"  -o FILE             output (default standard output)\n"
"  --json              JSON instead of TSV\n"
"  --pretty            aligned, rounded table (default when output is a terminal)\n"
"  -q                  no warnings about missing optional columns\n"
"  -j N                accepted like every tool's; no effect (one thread)\n"
"  --group-by COLS     key columns (comma list) instead of all carried ones\n"
"  --ignore COLS       drop these columns from the keys\n"
"  --order K[,K...]|auto  exponents of the eps_c corrections (default 1);\n"
"                      auto fits one exponent (3+ discretisations; linear\n"
"                      with 2)\n"
"  --fit finest|lsq    exact through the finest points (default) or least\n"
"                      squares over all\n"
"  --alpha A           alpha of a_yastrebov, Eq. 22 (default (pi-1+ln2)/24);\n"
"                      a_yastrebov_011 always uses 0.11 (Eq. 23)\n"
"  --no-extrapolate    use the finest raw a_r of each surface, no Richardson\n"
"  --per-seed          one row per seed, no ensemble average\n"
"  --fractal           extrapolate eps_f = lambda_s/lambda_r -> 0\n"
"  --alpha-f K|auto    exponent of the eps_f correction (default 1)\n"
"  --thermo            extrapolate eps_t = lambda_r/lx -> 0\n"
"  --alpha-t K|auto    exponent of the eps_t correction (default 1)\n"
"  --lenient           skip bad rows and groups, with a warning count\n"
"  --allow-unconverged use rows whose residual exceeds their tol (refused\n"
"                      by default), with a warning\n"
"  --gnuplot FILE      write a gnuplot script plotting kappa vs p* to a PNG\n"
"  --png FILE          run that script through gnuplot, writing FILE\n"
"  --schedule          print eps(p) = eps_ref (p/p_ref)^(1/4) (Eq. 27)\n"
"  --eps-ref E, --p-ref P, -p P[,P...]   its parameters\n"
"  -h, --help          this text;  --version\n"
"At most one of the table, --gnuplot - and --png - goes to standard output.\n");
}

struct opts {
	rc_cstats_opts cs;
	char **group_by, **ignore;
	const char *gnuplot;
	int schedule, fit_set, have_eps_ref, have_p_ref, have_p;
	double eps_ref, p_ref;
	double *pressures;
	size_t npressures;
};

static struct tool t;

/* Split a comma list into strings; empty names are usage errors. */
static void
name_list(const char *opt, const char *arg, char ***out, size_t *n)
{
	char *copy = strdup(arg), *save = NULL, *tok;

	*n = 0;
	if (copy == NULL || (*out = calloc(strlen(arg) + 1, sizeof(**out))) == NULL)
		tool_fail(&t, "out of memory");
	for (tok = strtok_r(copy, ",", &save); tok; tok = strtok_r(NULL, ",", &save))
		(*out)[(*n)++] = tok;
	if (*n == 0 || strstr(arg, ",,") || arg[0] == ',' ||
	    arg[strlen(arg) - 1] == ',')
		tool_bad(&t, "%s %s: want a comma-separated list of column names",
		    opt, arg);
}

static void
order_arg(const char *opt, const char *arg, rc_extrap_opts *e, size_t max)
{
	rc_err err;

	if (rc_extrap_parse(arg, max, e, &err) != 0)
		tool_bad(&t, "%s %s: %s", opt, arg, err.msg);
}

static void
positive(const char *opt, const char *arg, double *v)
{
	if (tool_double(&t, opt, arg, v) == 0 && !(*v > 0))
		tool_bad(&t, "%s %s: must be positive", opt, arg);
}

static int
has_control(const char *s)
{
	for (; s && *s; s++)
		if (iscntrl((unsigned char)*s))
			return 1;
	return 0;
}

/* Long: one case per option, each a few lines; they are read together. */
static void
parse(int argc, char **argv, struct opts *o)
{
	static const char optstring[] = "o:p:j:qh";
	static const struct option longopts[] = {
		{ "json", no_argument, NULL, OPT_JSON },
		{ "pretty", no_argument, NULL, OPT_PRETTY },
		{ "png", required_argument, NULL, OPT_PNG },
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
		{ "allow-unconverged", no_argument, NULL, OPT_ALLOW_UNCONVERGED },
		{ "gnuplot", required_argument, NULL, OPT_GNUPLOT },
		{ "schedule", no_argument, NULL, OPT_SCHEDULE },
		{ "eps-ref", required_argument, NULL, OPT_EPS_REF },
		{ "p-ref", required_argument, NULL, OPT_P_REF },
		{ NULL, 0, NULL, 0 }
	};
	rc_cstats_opts *cs = &o->cs;
	int c, help = 0;

	opterr = 0;	/* unknown options are reported with the others */
	while ((c = getopt_long(argc, argv, optstring, longopts, NULL)) != -1) {
		switch (c) {
		case 'h':
			help = 1;
			break;
		case 'p':
			free(o->pressures);
			o->pressures = NULL;
			o->npressures = 0;
			o->have_p = 1;
			if (tool_double_list(&t, "-p", optarg, &o->pressures,
			    &o->npressures) != 0)
				o->npressures = 0;
			for (size_t i = 0; i < o->npressures; i++)
				if (!(o->pressures[i] > 0)) {
					tool_bad(&t, "-p %s: pressures must be positive", optarg);
					break;
				}
			break;
		case OPT_GROUP_BY:
			name_list("--group-by", optarg, &o->group_by, &cs->ngroup_by);
			cs->group_by = (const char *const *)o->group_by;
			cs->have_group_by = 1;
			break;
		case OPT_IGNORE:
			name_list("--ignore", optarg, &o->ignore, &cs->nignore);
			cs->ignore = (const char *const *)o->ignore;
			break;
		case OPT_ORDER:
			order_arg("--order", optarg, &cs->cont, RC_EXTRAP_MAXTERMS);
			break;
		case OPT_FIT:
			o->fit_set = 1;
			if (strcmp(optarg, "finest") == 0)
				cs->cont.kind = RC_FIT_FINEST;
			else if (strcmp(optarg, "lsq") == 0)
				cs->cont.kind = RC_FIT_LSQ;
			else
				tool_bad(&t, "--fit %s: want finest or lsq", optarg);
			break;
		case OPT_ALPHA:
			if (tool_double(&t, "--alpha", optarg, &cs->alpha) == 0 &&
			    !(cs->alpha > -1 && cs->alpha < 1))
				tool_bad(&t, "--alpha %s: want |alpha| < 1", optarg);
			break;
		case OPT_NO_EXTRAPOLATE: cs->no_extrapolate = 1; break;
		case OPT_PER_SEED: cs->per_seed = 1; break;
		case OPT_FRACTAL: cs->fractal = 1; break;
		case OPT_THERMO: cs->thermo = 1; break;
		case OPT_LENIENT: cs->lenient = 1; break;
		case OPT_ALLOW_UNCONVERGED: cs->allow_unconverged = 1; break;
		case OPT_SCHEDULE: o->schedule = 1; break;
		case OPT_GNUPLOT: o->gnuplot = optarg; break;
		case OPT_ALPHA_F:
			order_arg("--alpha-f", optarg, &cs->frac, 1);
			break;
		case OPT_ALPHA_T:
			order_arg("--alpha-t", optarg, &cs->therm, 1);
			break;
		case OPT_EPS_REF:
			positive("--eps-ref", optarg, &o->eps_ref);
			o->have_eps_ref = 1;
			break;
		case OPT_P_REF:
			positive("--p-ref", optarg, &o->p_ref);
			o->have_p_ref = 1;
			break;
		case 'j': {
			/* checked like every tool's, but one thread runs:
			 * no note about the cores (it said "using 2") */
			long n;

			if (tool_long(&t, "-j", optarg, &n) == 0 &&
			    (n < 1 || n > 4096))
				tool_bad(&t, "-j %s: threads must be 1 to 4096",
				    optarg);
			break;
		}
		case '?':
			tool_bad_option(&t, optstring, longopts, argv);
			break;
		default:
			tool_common_option(&t, c, optarg);
		}
	}
	if (help && tool_help_check(&t)) {
		usage();
		exit(tool_exit(&t, 0));
	}

	/* validated together */
	tool_output(&t, "-o", t.out ? t.out : "-", 0);
	if (o->schedule) {
		if (!o->have_eps_ref || !o->have_p_ref || !o->have_p)
			tool_bad(&t, "--schedule needs --eps-ref, --p-ref and -p");
		if (optind < argc)
			tool_bad(&t, "--schedule reads no input files");
		if (o->gnuplot || t.png)
			tool_bad(&t, "--schedule writes no plot (--gnuplot, --png)");
		return;
	}
	if (o->have_eps_ref || o->have_p_ref || o->have_p)
		tool_bad(&t, "--eps-ref, --p-ref and -p belong to --schedule");
	if (cs->no_extrapolate && (cs->cont.auto_order || cs->cont.nterms > 1 ||
	    cs->cont.exponent[0] != 1 || o->fit_set))
		tool_bad(&t, "--no-extrapolate excludes --order and --fit");
	if (cs->cont.auto_order && o->fit_set && cs->cont.kind == RC_FIT_FINEST)
		tool_bad(&t, "--order auto: the exponent is a fit; --fit finest "
		    "does not apply");
	if (cs->have_group_by && cs->nignore)
		tool_bad(&t, "--group-by and --ignore exclude each other");
	/* At most one output on standard output; the result rows replace no
	 * input rows (they are another table). */
	tool_output(&t, "--gnuplot", o->gnuplot, 0);
	tool_output(&t, "--png", t.png, 1);
	if (has_control(t.png) || has_control(o->gnuplot))
		tool_bad(&t, "--png, --gnuplot: a control character in the file name");
	for (int i = optind; i < argc; i++)
		tool_input(&t, "the input", argv[i]);
	if (optind == argc)
		tool_input(&t, "the input", NULL);
}

static void
read_inputs(int argc, char **argv, rc_rowset *rs, int lenient)
{
	int n = argc - optind;
	rc_err err;

	for (int i = 0; i < (n ? n : 1); i++) {
		const char *path = n ? argv[optind + i] : "-";
		FILE *fp;
		int rc;
		if (rc_is_stdio(path)) {
			if (isatty(STDIN_FILENO))
				tool_fail(&t, "standard input: is a terminal; give files "
				    "or a pipe");
			rc = rc_rows_read(rs, stdin, "standard input", lenient, &err);
		} else {
			if ((fp = fopen(path, "rb")) == NULL)
				tool_fail(&t, "%s: %s", path, strerror(errno));
			rc = rc_rows_read(rs, fp, path, lenient, &err);
			fclose(fp);
		}
		if (rc != 0)
			tool_fail(&t, "%s", err.msg);
	}
}

static void
write_rows(const rc_row *row, size_t n)
{
	rc_atomic out;
	rc_table_out tab;
	rc_err err;

	if (rc_atomic_open(&out, t.out, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	tool_table_begin(&t, &tab, out.fp);
	for (size_t i = 0; i < n; i++)
		if (rc_table_write(&tab, &row[i], &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "%s", err.msg);
		}
	if (rc_table_end(&tab, &err) != 0) {
		rc_atomic_abort(&out);
		tool_fail(&t, "%s", err.msg);
	}
	if (rc_atomic_commit(&out, &err) != 0)
		tool_fail(&t, "%s", err.msg);
}

static void
run_schedule(const struct opts *o)
{
	rc_row *rows = calloc(o->npressures, sizeof(*rows));

	if (rows == NULL)
		tool_fail(&t, "out of memory");
	for (size_t i = 0; i < o->npressures; i++) {
		double eps = rc_eps_schedule(o->eps_ref, o->p_ref, o->pressures[i]);
		if (rc_row_num(&rows[i], "p_star", o->pressures[i]) ||
		    rc_row_num(&rows[i], "eps", eps) ||
		    rc_row_num(&rows[i], "inv_eps", 1 / eps))
			tool_fail(&t, "out of memory");
	}
	write_rows(rows, o->npressures);
	for (size_t i = 0; i < o->npressures; i++)
		rc_row_free(&rows[i]);
	free(rows);
}

int
main(int argc, char **argv)
{
	struct opts o;
	rc_rowset rs;
	rc_cstats res;
	rc_err err;

	tool_init(&t, "contact-stats", argc, argv);
	memset(&o, 0, sizeof(o));
	rc_cstats_opts_default(&o.cs);
	parse(argc, argv, &o);
	tool_usage_check(&t);
	if (o.schedule) {
		run_schedule(&o);
		free(o.pressures);
		return tool_exit(&t, 0);
	}

	rc_rows_init(&rs);
	read_inputs(argc, argv, &rs, o.cs.lenient);
	if (rc_cstats_run(&rs, &o.cs, &res, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	for (size_t i = 0; i < res.nwarn; i++)
		if (!t.quiet || res.warn_kind[i] != RC_CSTATS_WARN_MISSING)
			tool_warn(&t, "%s", res.warn[i]);
	write_rows(res.row, res.nrows);
	if (o.gnuplot && rc_cstats_gnuplot_write(&res, o.gnuplot, &err) != 0)
		tool_fail(&t, "--gnuplot: %s", err.msg);
	if (t.png && rc_cstats_png_write(&res, t.png, &err) != 0)
		tool_fail(&t, "--png: %s", err.msg);
	if (res.nskipped)
		tool_warn(&t, "--lenient: skipped %zu bad row%s or group%s (first: %s)",
		    res.nskipped, res.nskipped == 1 ? "" : "s",
		    res.nskipped == 1 ? "" : "s", res.first_skip);
	rc_cstats_free(&res);
	rc_rows_free(&rs);
	free(o.group_by ? o.group_by[0] : NULL);
	free(o.group_by);
	free(o.ignore ? o.ignore[0] : NULL);
	free(o.ignore);
	return tool_exit(&t, 0);
}
