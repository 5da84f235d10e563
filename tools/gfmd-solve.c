/* gfmd-solve - contact of a linearly elastic half space on a rigid rough
 * indenter, one result row per pressure (see gfmd-solve(1)). */
#include <errno.h>
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>
#include <unistd.h>

#include "atomic.h"
#include "checkpoint.h"
#include "common.h"
#include "contact.h"
#include "fft.h"
#include "png.h"
#include "solver.h"
#include "spectral.h"
#include "table.h"

enum {
	OPT_PRESSURE_ABS = OPT_TOOL_FIRST,
	OPT_METHOD,
	OPT_TOL,
	OPT_MAX_ITER,
	OPT_ALPHA,
	OPT_INIT,
	OPT_CONTACT,
	OPT_GAP,
	OPT_PRESSURE_FIELD,
	OPT_DISPLACEMENT,
	OPT_FD,
	OPT_CHECKPOINT,
	OPT_CHECKPOINT_EVERY,
	OPT_RESUME
};

/* Set by SIGINT/SIGTERM; the solver polls it every iteration. */
static volatile sig_atomic_t stop_signal;
static volatile sig_atomic_t stop_flag;

/* Set by SIGALRM every --checkpoint-every minutes: the solve stops, the
 * checkpoint is written and the same pressure goes on. */
static volatile sig_atomic_t checkpoint_due;

static void
on_signal(int sig)
{
	stop_signal = sig;
	stop_flag = 1;
}

static void
on_alarm(int sig)
{
	(void)sig;
	checkpoint_due = 1;
	stop_flag = 1;
}

static void
arm_timer(double minutes)
{
	struct itimerval it;
	double sec = minutes * 60;

	memset(&it, 0, sizeof(it));
	it.it_value.tv_sec = (time_t)sec;
	it.it_value.tv_usec = (suseconds_t)((sec - (double)(time_t)sec) * 1e6);
	if (it.it_value.tv_sec == 0 && it.it_value.tv_usec == 0)
		it.it_value.tv_usec = 1;
	setitimer(ITIMER_REAL, &it, NULL);
}

/* The command that resumes this run: the same arguments without --init
 * or an earlier --resume, plus --resume PATH. */
static char *
resume_command(int argc, char **argv, const char *path)
{
	size_t len = 4 * strlen(path) + 32;
	char *cmd, *w;
	int i;

	for (i = 0; i < argc; i++)
		len += 4 * strlen(argv[i]) + 4;	/* ' -> '\'' at worst */
	if ((cmd = malloc(len)) == NULL)
		return NULL;
	w = cmd;
	for (i = 0; i <= argc; i++) {
		const char *a = i < argc ? argv[i] : "--resume";

		if (i == 0)
			a = "gfmd-solve";
		if (i > 0 && i < argc && (strcmp(a, "--init") == 0 ||
		    strcmp(a, "--resume") == 0)) {
			i++;
			continue;
		}
		if (i > 0 && i < argc && (strncmp(a, "--init=", 7) == 0 ||
		    strncmp(a, "--resume=", 9) == 0))
			continue;
		for (int twice = 0; twice < (i == argc ? 2 : 1); twice++) {
			int quote;

			if (twice)
				a = path;
			quote = a[0] == '\0' || strpbrk(a, " \t'\"\\$`*?[]();&|<>~#!") != NULL;
			if (w != cmd)
				*w++ = ' ';
			if (quote)
				*w++ = '\'';
			for (; *a; a++) {
				if (quote && *a == '\'') {
					memcpy(w, "'\\''", 4);
					w += 4;
				} else
					*w++ = *a;
			}
			if (quote)
				*w++ = '\'';
		}
	}
	*w = '\0';
	return cmd;
}

struct progress {
	const char *name;
	double p_star, p;
	int shown;
};

static void
show_progress(void *ctx, long iter, double residual, double contact_fraction)
{
	struct progress *pr = ctx;

	fprintf(stderr, "\r%s: p* = %-10.4g p = %-10.4g iteration %-8ld "
	    "residual %-10.3e a_r %.6f ", pr->name, pr->p_star, pr->p, iter,
	    residual, contact_fraction);
	pr->shown = 1;
}

static void
usage(void)
{
	printf(
"usage: gfmd-solve (-p P[,P...] | --pressure-abs P[,P...]) [-E MODULUS]\n"
"           [--method fire|cg] [--tol TOL] [--max-iter N] [--alpha A] [--fd]\n"
"           [--init FILE] [--contact FILE] [--gap FILE] [--pressure FILE]\n"
"           [--displacement FILE] [--png FILE] [--checkpoint FILE]\n"
"           [--checkpoint-every MIN] [--resume FILE] [-o FILE] [--json]\n"
"           [-j N] [-q]\n"
"           [-L LX[xLY]] [FILE]\n"
"Solve the frictionless contact of an elastic half space (above) on the\n"
"rigid indenter in FILE (or standard input) and write one row per pressure.\n"
"  -p P[,P...]          reduced pressures p* = p/(E* gbar), gbar the rms\n"
"                       gradient of the whole indenter\n"
"  --pressure-abs P[,P...]  absolute mean pressures p (units of E*)\n"
"  -E MODULUS           contact modulus E* (default 1)\n"
"  --method fire|cg     FIRE-GFMD (default) or Polonsky-Keer CG\n"
"  --tol TOL            convergence tolerance (default 1e-6)\n"
"  --max-iter N         iterations per pressure (default 100000)\n"
"  --alpha A            contact-line weight of a_yastrebov (default 0.118114)\n"
"  --fd                 gbar, gbar_c, gbar_c_prime by central differences\n"
"                       (default spectral)\n"
"  --init FILE          start from this elastic surface height u\n"
"  --contact FILE       contact mask of the last pressure\n"
"  --gap FILE           gap u - h of the last pressure\n"
"  --pressure FILE      contact pressure of the last pressure\n"
"  --displacement FILE  elastic surface height u of the last pressure\n"
"  --png FILE           contact map over the height map\n"
"  --checkpoint FILE    on SIGINT/SIGTERM, after each finished pressure and\n"
"                       every --checkpoint-every minutes, save the state to\n"
"                       FILE (.surf); removed when the run completes\n"
"  --checkpoint-every MIN  also save it every MIN minutes during a solve\n"
"  --resume FILE        continue the run saved in FILE (same indenter; the\n"
"                       pressures and solver options default to FILE's)\n"
"  -o FILE              result table (default standard output)\n"
"  --json               JSON instead of TSV\n"
"  -j N                 threads (default all cores)\n"
"  --fft-effort E       estimate, measure or patient FFT planning (default:\n"
"                       measure for 1024^2 points and more, else estimate)\n"
"  --wisdom FILE        load FFTW wisdom, save it after planning ($RC_WISDOM)\n"
"  -q                   no progress display\n"
"  -L LX[xLY]           cell size of an input that carries none\n"
"  -h, --help           this help\n"
"  --version            the version\n");
}

static void
check_positive_list(struct tool *t, const char *opt, const double *v, size_t n)
{
	for (size_t i = 0; i < n; i++)
		if (!(v[i] > 0)) {
			tool_bad(t, "%s: pressure %g must be positive", opt, v[i]);
			return;
		}
}

/* Make a field grid shaped and labelled like the indenter. */
static rc_grid *
field_grid(const struct tool *t, const rc_grid *h, enum rc_kind kind,
    double p, double p_star, double modulus, const char *method)
{
	rc_err err;
	rc_grid *g = rc_grid_clone(h, 0, &err);

	if (g == NULL)
		tool_fail(t, "%s", err.msg);
	g->kind = kind;
	if (rc_grid_meta_setd(g, "p", p, &err) != 0 ||
	    rc_grid_meta_setd(g, "p_star", p_star, &err) != 0 ||
	    rc_grid_meta_setd(g, "E", modulus, &err) != 0 ||
	    rc_grid_meta_set(g, "method", method, &err) != 0)
		tool_fail(t, "%s", err.msg);
	return g;
}

int
main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "pressure-abs", required_argument, NULL, OPT_PRESSURE_ABS },
		{ "method", required_argument, NULL, OPT_METHOD },
		{ "tol", required_argument, NULL, OPT_TOL },
		{ "max-iter", required_argument, NULL, OPT_MAX_ITER },
		{ "alpha", required_argument, NULL, OPT_ALPHA },
		{ "init", required_argument, NULL, OPT_INIT },
		{ "contact", required_argument, NULL, OPT_CONTACT },
		{ "gap", required_argument, NULL, OPT_GAP },
		{ "pressure", required_argument, NULL, OPT_PRESSURE_FIELD },
		{ "displacement", required_argument, NULL, OPT_DISPLACEMENT },
		TOOL_FFT_LONGOPTS,
		{ "fd", no_argument, NULL, OPT_FD },
		{ "checkpoint", required_argument, NULL, OPT_CHECKPOINT },
		{ "checkpoint-every", required_argument, NULL, OPT_CHECKPOINT_EVERY },
		{ "resume", required_argument, NULL, OPT_RESUME },
		{ "json", no_argument, NULL, OPT_JSON },
		{ "png", required_argument, NULL, OPT_PNG },
		{ "version", no_argument, NULL, OPT_VERSION },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 }
	};
	static const char optstring[] = "p:E:o:j:qL:h";
	struct tool t;
	rc_solver_opts so;
	rc_contact_opts co;
	rc_solver *solver;
	rc_grid *h;
	rc_fft fft;
	rc_err err;
	rc_atomic out;
	rc_table_out table;
	rc_row row;
	struct progress pr;
	struct sigaction sa;
	double *reduced = NULL, *absolute = NULL, gbar, modulus = 1, alpha;
	double last_p = 0, last_p_star = 0;
	size_t npressures = 0, nreduced = 0, nabsolute = 0, nunconverged = 0;
	const char *init = NULL, *contact_path = NULL, *gap_path = NULL;
	const char *pressure_path = NULL, *displacement_path = NULL, *input;
	const char *ck_path = NULL, *resume_path = NULL;
	double ck_every = 0;
	rc_checkpoint ck, saved;
	rc_grid *saved_u = NULL;
	size_t first = 0;
	long n, resumed_iterations = 0;
	int c, method, fd = 0, status = 0;
	int given_method = 0, given_tol = 0, given_e = 0, given_alpha = 0;
	int given_fd = 0, given_max_iter = 0;

	tool_init(&t, "gfmd-solve", argc, argv);
	rc_solver_defaults(&so);
	alpha = RC_YASTREBOV_ALPHA;
	opterr = 0;	/* tool_bad reports, so that all problems are counted */
	while ((c = getopt_long(argc, argv, optstring, longopts, NULL)) != -1) {
		switch (c) {
		case 'p':
			free(reduced);
			if (tool_double_list(&t, "-p", optarg, &reduced, &nreduced) == 0)
				check_positive_list(&t, "-p", reduced, nreduced);
			break;
		case OPT_PRESSURE_ABS:
			free(absolute);
			if (tool_double_list(&t, "--pressure-abs", optarg, &absolute,
			    &nabsolute) == 0)
				check_positive_list(&t, "--pressure-abs", absolute, nabsolute);
			break;
		case 'E':
			if (tool_double(&t, "-E", optarg, &modulus) == 0 && !(modulus > 0))
				tool_bad(&t, "-E %s: the contact modulus must be positive", optarg);
			given_e = 1;
			break;
		case OPT_METHOD:
			if ((method = rc_method_parse(optarg)) < 0)
				tool_bad(&t, "--method %s: want fire or cg", optarg);
			else
				so.method = (enum rc_method)method;
			given_method = 1;
			break;
		case OPT_TOL:
			if (tool_double(&t, "--tol", optarg, &so.tol) == 0 &&
			    !(so.tol > 0 && so.tol < 1))
				tool_bad(&t, "--tol %s: want a tolerance in (0, 1)", optarg);
			given_tol = 1;
			break;
		case OPT_MAX_ITER:
			if (tool_long(&t, "--max-iter", optarg, &n) == 0) {
				if (n < 1)
					tool_bad(&t, "--max-iter %s: want at least 1", optarg);
				else
					so.max_iter = n;
			}
			given_max_iter = 1;
			break;
		case OPT_ALPHA:
			if (tool_double(&t, "--alpha", optarg, &alpha) == 0 &&
			    !(alpha >= 0 && alpha <= 1))
				tool_bad(&t, "--alpha %s: want a weight in [0, 1]", optarg);
			given_alpha = 1;
			break;
		case OPT_INIT:
			init = optarg;
			break;
		case OPT_CONTACT:
			contact_path = optarg;
			break;
		case OPT_GAP:
			gap_path = optarg;
			break;
		case OPT_PRESSURE_FIELD:
			pressure_path = optarg;
			break;
		case OPT_DISPLACEMENT:
			displacement_path = optarg;
			break;
		case OPT_FD:
			fd = 1;
			given_fd = 1;
			break;
		case OPT_CHECKPOINT:
			ck_path = optarg;
			break;
		case OPT_CHECKPOINT_EVERY:
			if (tool_double(&t, "--checkpoint-every", optarg, &ck_every) == 0 &&
			    !(ck_every > 0 && ck_every <= 1e6))
				tool_bad(&t, "--checkpoint-every %s: want minutes in (0, 1e6]",
				    optarg);
			break;
		case OPT_RESUME:
			resume_path = optarg;
			break;
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case '?':
			/* optopt: the option whose argument is missing (a long
			 * option's code, or a letter), 0 for an unknown long one. */
			if (optopt > 0 && optopt < 128 && strchr(optstring, optopt))
				tool_bad(&t, "-%c: missing argument", optopt);
			else if (optopt > 0 && optopt < 128)
				tool_bad(&t, "-%c: unknown option", optopt);
			else if (optopt != 0)
				tool_bad(&t, "%s: missing argument", argv[optind - 1]);
			else
				tool_bad(&t, "%s: unknown option", argv[optind - 1]);
			break;
		default:
			tool_common_option(&t, c, optarg);
		}
	}
	if (nreduced && nabsolute)
		tool_bad(&t, "-p and --pressure-abs: give one of them, not both");
	else if (!nreduced && !nabsolute && t.nbad == 0 && resume_path == NULL)
		tool_bad(&t, "no pressure: give -p P[,P...] or --pressure-abs P[,P...]");
	if (ck_every > 0 && ck_path == NULL)
		tool_bad(&t, "--checkpoint-every: needs --checkpoint FILE");
	if (ck_path != NULL && rc_is_stdio(ck_path))
		tool_bad(&t, "--checkpoint -: give a file name");
	if (resume_path != NULL && init != NULL)
		tool_bad(&t, "--resume and --init: the checkpoint is the start; "
		    "give one of them");
	if (argc - optind > 1)
		tool_bad(&t, "%s: one input file at most", argv[optind + 1]);
	{
		const char *fields[] = { contact_path, gap_path, pressure_path,
		    displacement_path };
		const char *names[] = { "--contact", "--gap", "--pressure",
		    "--displacement" };
		for (int k = 0; k < 4; k++) {
			if (fields[k] != NULL && rc_is_stdio(fields[k]))
				tool_bad(&t, "%s %s: fields go to files; standard output "
				    "carries the result table", names[k], fields[k]);
			else
				tool_check_grid_path(&t, names[k], fields[k]);
		}
		if (t.png != NULL && rc_is_stdio(t.png))
			tool_bad(&t, "--png -: give a file name");
	}
	tool_usage_check(&t);
	input = optind < argc ? argv[optind] : NULL;
	npressures = nreduced ? nreduced : nabsolute;

	tool_fft_setup(&t);
	h = tool_read_grid(&t, input);
	if (resume_path != NULL) {
		/* Options that decide the rows default to the checkpoint's;
		 * those given must match it (rc_checkpoint_match below). */
		if (rc_checkpoint_read(&saved, &saved_u, resume_path, &err) != 0)
			tool_fail(&t, "%s: %s", resume_path, err.msg);
		if (!given_method && (method = rc_method_parse(saved.method)) >= 0)
			so.method = (enum rc_method)method;
		if (!given_tol)
			so.tol = saved.tol;
		if (!given_e)
			modulus = saved.modulus;
		if (!given_alpha)
			alpha = saved.alpha;
		if (!given_fd)
			fd = saved.fd;
		if (!given_max_iter)
			so.max_iter = saved.max_iter;
		if (!nreduced && !nabsolute) {
			double *copy = malloc(saved.npressures * sizeof(double));

			if (copy == NULL)
				tool_fail(&t, "out of memory");
			memcpy(copy, saved.pressures, saved.npressures * sizeof(double));
			if (saved.reduced) {
				reduced = copy;
				nreduced = saved.npressures;
			} else {
				absolute = copy;
				nabsolute = saved.npressures;
			}
			npressures = saved.npressures;
		}
	}
	if (ck_path != NULL || resume_path != NULL) {
		if (rc_checkpoint_init(&ck, h, nreduced ? reduced : absolute,
		    npressures, &err) != 0)
			tool_fail(&t, "%s", err.msg);
		snprintf(ck.method, sizeof(ck.method), "%s", rc_method_name(so.method));
		ck.tol = so.tol;
		ck.modulus = modulus;
		ck.alpha = alpha;
		ck.fd = fd;
		ck.max_iter = so.max_iter;
		ck.reduced = nreduced != 0;
	}
	if (resume_path != NULL) {
		if (rc_checkpoint_match(&saved, &ck, &err) != 0)
			tool_fail(&t, "--resume %s: %s", resume_path, err.msg);
		if (saved_u->nx != h->nx || saved_u->ny != h->ny)
			tool_fail(&t, "--resume %s: %zux%zu field, the indenter is "
			    "%zux%zu", resume_path, saved_u->nx, saved_u->ny, h->nx,
			    h->ny);
	}
	/* The analysis plan lives as long as the solver; --fd needs none. */
	memset(&fft, 0, sizeof(fft));
	if (fd)
		gbar = rc_contact_gbar_fd(h);
	else if (rc_fft_init(&fft, h->nx, h->ny, RC_FFT_ESTIMATE, &err) != 0 ||
	    rc_rms_gradient(h, &fft, &gbar, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	if (nreduced && !(gbar > 0))
		tool_fail(&t, "%s: the indenter is flat (rms gradient 0), so the "
		    "reduced pressure p* = p/(E* gbar) is undefined; use --pressure-abs",
		    input ? input : "standard input");

	so.modulus = modulus;
	so.stop = (volatile int *)&stop_flag;
	pr.name = t.name;
	pr.shown = 0;
	if (!t.quiet && isatty(STDERR_FILENO)) {
		so.progress = show_progress;
		so.progress_ctx = &pr;
	}
	/* A solve runs hundreds of transform pairs: worth MEASURE on big grids. */
	so.measure = (int)tool_fft_effort(&t, h->nx, h->ny, 1e4);
	if ((solver = rc_solver_new(h, &so, &err)) == NULL)
		tool_fail(&t, "%s", err.msg);
	tool_fft_finish(&t);
	if (init != NULL) {
		rc_grid *u = tool_read_grid(&t, init);
		if (u->nx != h->nx || u->ny != h->ny)
			tool_fail(&t, "%s: %zux%zu grid, the indenter is %zux%zu", init,
			    u->nx, u->ny, h->nx, h->ny);
		if (rc_solver_set_displacement(solver, u->z, &err) != 0)
			tool_fail(&t, "%s: %s", init, err.msg);
		rc_grid_free(u);
	}
	if (resume_path != NULL) {
		if (rc_solver_set_displacement(solver, saved_u->z, &err) != 0)
			tool_fail(&t, "--resume %s: %s", resume_path, err.msg);
		rc_grid_free(saved_u);
		first = saved.next;
		if (saved.solving)
			resumed_iterations = saved.iterations;
	}

	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = on_signal;
	sa.sa_flags = SA_RESETHAND;	/* a second signal ends the process */
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);

	if (rc_atomic_open(&out, t.out, &err) != 0)
		tool_fail(&t, "%s: %s", t.out, err.msg);
	rc_table_begin(&table, out.fp, t.json);
	rc_row_init(&row);
	rc_contact_defaults(&co);
	co.alpha = alpha;
	co.modulus = modulus;
	co.gbar = gbar;
	co.fft = fd ? NULL : &fft;
	co.fd = fd;
	/* A resumed run first repeats the rows its checkpoint finished. */
	for (size_t k = 0; k < first; k++) {
		if (rc_checkpoint_row(&saved, k, &row, &err) != 0 ||
		    (ck_path != NULL && rc_checkpoint_add_row(&ck, &row, &err) != 0)) {
			rc_atomic_abort(&out);
			tool_fail(&t, "--resume %s: %s", resume_path, err.msg);
		}
		if (rc_table_write(&table, &row, &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "%s: %s", t.out ? t.out : "standard output", err.msg);
		}
	}
	if (resume_path != NULL && first >= npressures) {
		rc_atomic_abort(&out);
		tool_fail(&t, "--resume %s: every pressure of it is done; nothing "
		    "to resume", resume_path);
	}
	if (ck_every > 0) {
		struct sigaction alarm_sa;

		memset(&alarm_sa, 0, sizeof(alarm_sa));
		alarm_sa.sa_handler = on_alarm;
		alarm_sa.sa_flags = SA_RESTART;
		sigemptyset(&alarm_sa.sa_mask);
		sigaction(SIGALRM, &alarm_sa, NULL);
		arm_timer(ck_every);
	}
	for (size_t k = first; k < npressures; k++) {
		rc_solve_result res;
		rc_contact_stats st;
		double p = nreduced ? reduced[k] * modulus * gbar : absolute[k];
		/* Echo a requested p* exactly: p/(E* gbar) rounds. */
		double p_star = nreduced ? reduced[k] :
		    gbar > 0 ? p / (modulus * gbar) : NAN;
		double seconds = 0;
		long iterations = k == first ? resumed_iterations : 0;
		int r;

		pr.p = p;
		pr.p_star = p_star;
		/* A periodic checkpoint stops the solve through so.stop; it is
		 * saved and the same pressure goes on from where it stopped. */
		for (;;) {
			r = rc_solver_solve(solver, p, &res, &err);
			if (pr.shown) {
				fputc('\n', stderr);
				pr.shown = 0;
			}
			if (r < 0) {
				rc_atomic_abort(&out);
				tool_fail(&t, "p = %g: %s", p, err.msg);
			}
			iterations += res.iterations;
			seconds += res.seconds;
			if (r == 0 || !stop_flag)
				break;
			if (ck_path != NULL) {
				ck.next = k;
				ck.solving = 1;
				ck.iterations = iterations;
				if (rc_checkpoint_write(&ck, rc_solver_displacement(solver),
				    ck_path, &err) != 0) {
					if (stop_signal) {
						rc_atomic_abort(&out);
						tool_fail(&t, "interrupted by signal %d; the "
						    "checkpoint %s could not be written: %s",
						    (int)stop_signal, ck_path, err.msg);
					}
					tool_warn(&t, "checkpoint %s: %s; going on", ck_path,
					    err.msg);
				}
			}
			if (stop_signal) {
				char *cmd = ck_path ? resume_command(argc, argv, ck_path) : NULL;

				/* The rows of finished pressures are complete: keep them. */
				if (k == 0 || rc_table_end(&table, &err) != 0 ||
				    rc_atomic_commit(&out, &err) != 0)
					rc_atomic_abort(&out);
				if (ck_path == NULL)
					tool_fail(&t, "interrupted by signal %d while solving "
					    "p = %g (iteration %ld); the rows of the %zu of %zu "
					    "pressures done before it are written, no fields "
					    "(--checkpoint FILE makes a run resumable)",
					    (int)stop_signal, p, iterations, k, npressures);
				tool_fail(&t, "interrupted by signal %d while solving p = %g "
				    "(pressure %zu of %zu, iteration %ld); state saved in %s; "
				    "resume with: %s%s", (int)stop_signal, p, k + 1,
				    npressures, iterations, ck_path, cmd ? cmd : "",
				    input == NULL || rc_is_stdio(input) ?
				    " (with the same indenter on standard input)" : "");
			}
			checkpoint_due = 0;
			stop_flag = 0;
			if (stop_signal)
				stop_flag = 1;
			arm_timer(ck_every);
		}
		res.iterations = iterations;
		res.seconds = seconds;
		co.pressure = p;
		if (rc_contact_analyse(h, rc_solver_contact(solver), &co, &st,
		    &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "p = %g: %s", p, err.msg);
		}
		rc_row_clear(&row);
		if (rc_row_num(&row, "p_star", p_star) ||
		    rc_row_num(&row, "p", p) ||
		    rc_row_num(&row, "a_r", st.a_r) ||
		    rc_row_int(&row, "n_c", (long long)st.n_c) ||
		    rc_row_int(&row, "n_cl", (long long)st.n_cl) ||
		    rc_row_int(&row, "n_tot", (long long)st.n_tot) ||
		    rc_row_num(&row, "a_yastrebov", st.a_yastrebov) ||
		    rc_row_num(&row, "gbar", gbar) ||
		    rc_row_num(&row, "gbar_c", st.gbar_c) ||
		    rc_row_num(&row, "gbar_c_prime", st.gbar_c_prime) ||
		    rc_row_num(&row, "kappa", st.kappa) ||
		    rc_row_num(&row, "kappa_c", st.kappa_c) ||
		    rc_row_num(&row, "mean_gap", rc_solver_mean_gap(solver)) ||
		    rc_row_num(&row, "elastic_energy",
		    rc_solver_elastic_energy(solver)) ||
		    rc_row_int(&row, "n_patches", (long long)st.n_patches) ||
		    rc_row_num(&row, "patch_size_char", st.patch_size_char) ||
		    rc_row_int(&row, "iterations", res.iterations) ||
		    rc_row_num(&row, "residual", res.residual) ||
		    rc_row_num(&row, "seconds", res.seconds) ||
		    rc_row_str(&row, "method", rc_method_name(so.method)) ||
		    rc_row_int(&row, "nx", (long long)h->nx) ||
		    rc_row_int(&row, "ny", (long long)h->ny) ||
		    rc_row_num(&row, "lx", h->lx) ||
		    rc_row_num(&row, "ly", h->ly) ||
		    rc_row_meta(&row, h)) {
			rc_atomic_abort(&out);
			tool_fail(&t, "out of memory");
		}
		if (rc_table_write(&table, &row, &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "%s: %s", t.out ? t.out : "standard output", err.msg);
		}
		if (fflush(out.fp) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "%s: %s", t.out ? t.out : "standard output",
			    strerror(errno));
		}
		if (!res.converged) {
			nunconverged++;
			tool_warn(&t, "p = %g: not converged after %ld iterations "
			    "(residual %.3g, tolerance %.3g); row written, going on",
			    p, res.iterations, res.residual, so.tol);
		}
		last_p = p;
		last_p_star = p_star;
		if (ck_path != NULL && k + 1 < npressures) {
			/* Saved after each finished pressure: a stop from here
			 * on loses nothing. */
			ck.next = k + 1;
			ck.solving = 0;
			ck.iterations = 0;
			if (rc_checkpoint_add_row(&ck, &row, &err) != 0 ||
			    rc_checkpoint_write(&ck, rc_solver_displacement(solver),
			    ck_path, &err) != 0) {
				if (stop_signal) {
					if (rc_table_end(&table, &err) != 0 ||
					    rc_atomic_commit(&out, &err) != 0)
						rc_atomic_abort(&out);
					tool_fail(&t, "interrupted by signal %d after pressure "
					    "%zu of %zu; the checkpoint %s could not be written: "
					    "%s", (int)stop_signal, k + 1, npressures, ck_path,
					    err.msg);
				}
				tool_warn(&t, "checkpoint %s: %s; going on", ck_path,
				    err.msg);
			}
			if (stop_signal) {
				char *cmd = resume_command(argc, argv, ck_path);

				if (rc_table_end(&table, &err) != 0 ||
				    rc_atomic_commit(&out, &err) != 0)
					rc_atomic_abort(&out);
				tool_fail(&t, "interrupted by signal %d after pressure %zu "
				    "of %zu; state saved in %s; resume with: %s%s",
				    (int)stop_signal, k + 1, npressures, ck_path,
				    cmd ? cmd : "", input == NULL || rc_is_stdio(input) ?
				    " (with the same indenter on standard input)" : "");
			}
		}
	}
	if (ck_every > 0) {
		struct itimerval off;

		memset(&off, 0, sizeof(off));
		setitimer(ITIMER_REAL, &off, NULL);
	}
	rc_row_free(&row);
	sigaction(SIGINT, &(struct sigaction){ .sa_handler = SIG_DFL }, NULL);
	sigaction(SIGTERM, &(struct sigaction){ .sa_handler = SIG_DFL }, NULL);
	if (rc_table_end(&table, &err) != 0 || rc_atomic_commit(&out, &err) != 0) {
		rc_atomic_abort(&out);
		tool_fail(&t, "%s: %s", t.out ? t.out : "standard output", err.msg);
	}
	if (!fd)
		rc_fft_free(&fft);

	/* Fields of the last pressure, only those asked for, one at a time. */
	{
		const char *method_name = rc_method_name(so.method);
		const double *u = rc_solver_displacement(solver);
		const double *sigma = rc_solver_pressure(solver);
		const unsigned char *mask = rc_solver_contact(solver);
		size_t np = rc_grid_size(h);
		rc_grid *g;

		if (displacement_path != NULL) {
			g = field_grid(&t, h, RC_KIND_DISPLACEMENT, last_p, last_p_star,
			    modulus, method_name);
			memcpy(g->z, u, np * sizeof(double));
			tool_write_grid(&t, g, displacement_path);
			rc_grid_free(g);
		}
		if (gap_path != NULL) {
			g = field_grid(&t, h, RC_KIND_GAP, last_p, last_p_star, modulus,
			    method_name);
			for (size_t k = 0; k < np; k++)
				g->z[k] = u[k] - h->z[k];
			tool_write_grid(&t, g, gap_path);
			rc_grid_free(g);
		}
		if (pressure_path != NULL) {
			g = field_grid(&t, h, RC_KIND_PRESSURE, last_p, last_p_star,
			    modulus, method_name);
			memcpy(g->z, sigma, np * sizeof(double));
			tool_write_grid(&t, g, pressure_path);
			rc_grid_free(g);
		}
		if (contact_path != NULL || t.png != NULL) {
			g = field_grid(&t, h, RC_KIND_MASK, last_p, last_p_star, modulus,
			    method_name);
			for (size_t k = 0; k < np; k++)
				g->z[k] = mask[k] != 0;
			if (contact_path != NULL)
				tool_write_grid(&t, g, contact_path);
			if (t.png != NULL) {
				rc_png_opts po;
				rc_png_defaults(&po);
				po.overlay = g;
				if (rc_png_write(h, t.png, &po, &err) != 0)
					tool_fail(&t, "%s: %s", t.png, err.msg);
			}
			rc_grid_free(g);
		}
	}
	if (nunconverged) {
		tool_warn(&t, "%zu of %zu pressures did not converge", nunconverged,
		    npressures);
		status = 1;
	}
	/* The run is complete: its checkpoint would only resume it again. */
	if (ck_path != NULL && unlink(ck_path) != 0 && errno != ENOENT)
		tool_warn(&t, "%s: %s", ck_path, strerror(errno));
	if (ck_path != NULL || resume_path != NULL)
		rc_checkpoint_free(&ck);
	if (resume_path != NULL)
		rc_checkpoint_free(&saved);
	rc_solver_free(solver);
	rc_grid_free(h);
	free(reduced);
	free(absolute);
	return tool_exit(&t, status);
}
