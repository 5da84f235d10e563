/* SPDX-License-Identifier: GPL-3.0-or-later */
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
#include "clock.h"
#include "common.h"
#include "contact.h"
#include "fft.h"
#include "gfmd_opts.h"
#include "gfmd_row.h"
#include "png.h"
#include "solver.h"
#include "spectral.h"
#include "table_write.h"
#include "units.h"

/* Set by SIGINT/SIGTERM; the solver polls it every iteration. */
static volatile sig_atomic_t stop_signal;
static volatile sig_atomic_t stop_flag;

/* The first SIGINT/SIGTERM stops the solve (rows kept, checkpoint
 * written); a second one ends the process at once, removing temporaries. */
static void
on_signal(int sig)
{
	if (stop_signal)
		tool_on_signal(sig);
	stop_signal = sig;
	stop_flag = 1;
}

/* SIGALRM every --checkpoint-every minutes: the solve stops, the
 * checkpoint is written and the same pressure goes on (stop_signal stays
 * 0, which is how the loop tells a timer stop from a signal). */
static void
on_alarm(int sig)
{
	(void)sig;
	stop_flag = 1;
}

/* The --checkpoint lock, released (and its file removed) at exit, also
 * through tool_fail. */
static int lock_fd = -1;
static char *lock_path;

static void
unlock_at_exit(void)
{
	rc_checkpoint_unlock(lock_fd, lock_path);
	lock_fd = -1;
	lock_path = NULL;
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
"usage: gfmd-solve (-p P[,P...] | --pressure-abs P[,P...] | --approach D[,D...])\n"
"           [-E MODULUS] [--boundary periodic|free] [--method fire|cg] [--hardness H]\n"
"           [--kernel continuum|pixel]\n"
"           [--thickness D --poisson NU [--substrate bonded|slip]]\n"
"           [--tol TOL] [--max-iter N] [--alpha A] [--fd]\n"
"           [--init FILE] [--contact FILE] [--gap FILE] [--pressure FILE]\n"
"           [--displacement FILE] [--png FILE] [--checkpoint FILE]\n"
"           [--checkpoint-every MIN] [--resume FILE] [-o FILE] [--json] [--pretty]\n"
"           [-j N] [-q]\n"
"           [-L LX[xLY]] [--unit U] [--z-unit U] [--periodic|--no-periodic]\n"
"           [--npy-order yx|xy] [FILE]\n"
"Solve the frictionless contact of an elastic half space (above) on the\n"
"rigid indenter in FILE (or standard input) and write one row per pressure.\n"
"  -p P[,P...]          reduced pressures p* = p/(E* gbar), gbar the rms\n"
"                       gradient of the whole indenter\n"
"  --pressure-abs P[,P...]  absolute mean pressures p (units of E*)\n"
"  --approach D[,D...]  displacement control: approaches D (length units)\n"
"  --boundary periodic|free  one period of an infinite surface, or an\n"
"                       isolated patch of half space (default: the grid's\n"
"                       periodic flag)\n"
"  -E MODULUS           contact modulus E* (default 1)\n"
"  --kernel continuum|pixel  periodic elastic kernel: q E*/2 (default) or\n"
"                       the response to pressure uniform on each pixel\n"
"                       (free boundaries: always pixel)\n"
"  --method fire|cg     FIRE-GFMD (default) or Polonsky-Keer CG\n"
"  --hardness H         perfect plasticity: cap the contact pressure at H\n"
"                       (units of E*; needs --method cg; default no cap)\n"
"  --thickness D        an elastic layer of thickness D (length units) on a\n"
"                       rigid substrate instead of the half space (periodic\n"
"                       boundaries; default: a half space)\n"
"  --poisson NU         the layer's Poisson ratio, in (-1, 0.5]\n"
"  --substrate bonded|slip  the layer's interface with the substrate: bonded\n"
"                       (default) or frictionless\n"
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
"  --checkpoint-every MIN  also save it every MIN minutes (at least 0.005)\n"
"                       during a solve\n"
"  --resume FILE        continue the run saved in FILE (same indenter; the\n"
"                       pressures and solver options default to FILE's)\n"
"  -o FILE              result table (default standard output)\n"
"  --json               JSON instead of TSV\n"
"  --pretty             aligned, rounded table (default on a terminal)\n"
"  -j N                 threads (default OMP_NUM_THREADS, else 1 under\n"
"                       make -j, else all cores)\n"
"  --fft-effort E       estimate, measure or patient FFT planning (default:\n"
"                       measure for 1024^2 points and more, else estimate)\n"
"  --wisdom FILE        load FFTW wisdom, save it after planning ($RC_WISDOM)\n"
"  -q                   no progress display\n"
"  -L LX[xLY]           cell size of an input that carries none\n"
"  --unit U             length unit of the work and the output fields (m mm\n"
"                       um nm pm angstrom); the unit of an input that has none\n"
"  --z-unit U           the indenter's heights are in length unit U\n"
"  --periodic, --no-periodic  the indenter is (not) one period of a surface\n"
"  --npy-order yx|xy    .npy shape (ny, nx) (default) or (nx, ny)\n"
"  --channel N|NAME     channel of a multi-channel input (default: the first\n"
"                       whose values are lengths)\n"
"  -h, --help           this help\n"
"  --version            the version\n");
}

/* Make a field grid shaped and labelled like the indenter, periodic as
 * the solve was: free boundaries make an isolated patch of any grid. */
static rc_grid *
field_grid(const struct tool *t, const rc_grid *h, enum rc_kind kind,
    double p, double p_star, double modulus, const char *method,
    enum rc_boundary boundary)
{
	rc_err err;
	rc_grid *g = rc_grid_clone(h, 0, &err);

	if (g == NULL)
		tool_fail(t, "%s", err.msg);
	g->kind = kind;
	g->periodic = boundary == RC_BOUNDARY_PERIODIC;
	/* Pressures (units of E*) and the mask are no lengths. */
	if (!rc_kind_is_length(kind))
		g->z_unit[0] = '\0';
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
		GFMD_LONGOPTS,
		TOOL_FFT_LONGOPTS,
		TOOL_GRID_LONGOPTS,
		TOOL_CHANNEL_LONGOPT,
		{ NULL, 0, NULL, 0 }
	};
	struct tool t;
	struct gfmd_opts o;
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
	double gbar, last_p = 0, last_p_star = 0, plan_seconds;
	size_t npressures = 0, nunconverged = 0;
	const char *input;
	rc_checkpoint ck, saved;
	rc_grid *saved_u = NULL;
	size_t first = 0;
	long resumed_iterations = 0;
	int c, method, status = 0;

	tool_init(&t, "gfmd-solve", argc, argv);
	gfmd_opts_init(&o);
	opterr = 0;	/* tool_bad reports, so that all problems are counted */
	while ((c = getopt_long(argc, argv, GFMD_OPTSTRING, longopts, NULL)) != -1) {
		if (c == 'h') {
			usage();
			return tool_exit(&t, 0);
		}
		gfmd_option(&t, &o, c, optarg, argv);
	}
	gfmd_opts_check(&t, &o, argc, argv);
	tool_usage_check(&t);
	input = optind < argc ? argv[optind] : NULL;
	if (o.ck_path != NULL) {
		if ((lock_fd = rc_checkpoint_lock(o.ck_path, &lock_path, &err)) == -1)
			tool_fail(&t, "--checkpoint %s: %s", o.ck_path, err.msg);
		atexit(unlock_at_exit);
	}
	npressures = o.napproach ? o.napproach : o.nreduced ? o.nreduced :
	    o.nabsolute;

	tool_fft_setup(&t);
	h = tool_read_input(&t, input);
	if (o.resume_path != NULL) {
		/* Options that decide the rows default to the checkpoint's;
		 * those given must match it (rc_checkpoint_match below). */
		if (rc_checkpoint_read(&saved, &saved_u, o.resume_path, &err) != 0)
			tool_fail_at(&t, o.resume_path, err.msg);
		if (!o.given_method && (method = rc_method_parse(saved.method)) >= 0)
			o.so.method = (enum rc_method)method;
		if (!o.given_tol)
			o.so.tol = saved.tol;
		if (!o.given_e)
			o.modulus = saved.modulus;
		if (!o.given_alpha)
			o.alpha = saved.alpha;
		if (!o.given_fd)
			o.fd = saved.fd;
		if (!o.given_max_iter)
			o.so.max_iter = saved.max_iter;
		if (!o.nreduced && !o.nabsolute) {
			double *copy = malloc(saved.npressures * sizeof(double));

			if (copy == NULL)
				tool_fail(&t, "out of memory");
			memcpy(copy, saved.pressures, saved.npressures * sizeof(double));
			if (saved.reduced) {
				o.reduced = copy;
				o.nreduced = saved.npressures;
			} else {
				o.absolute = copy;
				o.nabsolute = saved.npressures;
			}
			npressures = saved.npressures;
		}
	}
	if (o.ck_path != NULL || o.resume_path != NULL) {
		if (rc_checkpoint_init(&ck, h, o.nreduced ? o.reduced : o.absolute,
		    npressures, &err) != 0)
			tool_fail(&t, "%s", err.msg);
		snprintf(ck.method, sizeof(ck.method), "%s", rc_method_name(o.so.method));
		ck.tol = o.so.tol;
		ck.modulus = o.modulus;
		ck.alpha = o.alpha;
		ck.fd = o.fd;
		ck.max_iter = o.so.max_iter;
		ck.reduced = o.nreduced != 0;
	}
	if (o.resume_path != NULL) {
		if (rc_checkpoint_match(&saved, &ck, &err) != 0)
			tool_fail(&t, "--resume %s: %s", o.resume_path, err.msg);
		if (saved_u->nx != h->nx || saved_u->ny != h->ny)
			tool_fail(&t, "--resume %s: %zux%zu field, the indenter is "
			    "%zux%zu", o.resume_path, saved_u->nx, saved_u->ny, h->nx,
			    h->ny);
	}
	/* Free boundaries (issue 16): the grid's periodic flag decides unless
	 * --boundary is given. */
	o.so.boundary = o.boundary >= 0 ? (enum rc_boundary)o.boundary :
	    h->periodic ? RC_BOUNDARY_PERIODIC : RC_BOUNDARY_FREE;
	if (o.so.boundary == RC_BOUNDARY_PERIODIC)
		tool_check_wrap(&t, h, input);
	else if (o.given_kernel && o.so.kernel != RC_KERNEL_PIXEL)
		tool_fail(&t, "--kernel %s: %s is solved with free boundaries "
		    "(not marked periodic), which always use Love's pixel "
		    "compliance; drop --kernel or add --boundary periodic",
		    rc_kernel_name(o.so.kernel), input ? input : "standard input");
	/* The analysis plan lives as long as the solver; --fd and free
	 * boundaries need none. */
	memset(&fft, 0, sizeof(fft));
	if (o.so.boundary == RC_BOUNDARY_FREE)
		gbar = rc_contact_gbar_open(h);
	else if (o.fd)
		gbar = rc_contact_gbar_fd(h);
	else if (rc_fft_init(&fft, h->nx, h->ny, RC_FFT_ESTIMATE, &err) != 0 ||
	    rc_rms_gradient(h, &fft, &gbar, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	{
		double lo = INFINITY, hi = -INFINITY;

		for (size_t k = 0; k < rc_grid_size(h); k++) {
			lo = fmin(lo, h->z[k]);
			hi = fmax(hi, h->z[k]);
		}
		gfmd_check_scale(&t, input, hi - lo, gbar);
	}
	if (o.nreduced && !(gbar > 0))
		tool_fail(&t, "%s: the indenter is flat (rms gradient 0), so the "
		    "reduced pressure p* = p/(E* gbar) is undefined; use --pressure-abs",
		    input ? input : "standard input");

	o.so.modulus = o.modulus;
	o.so.stop = (volatile int *)&stop_flag;
	pr.name = t.name;
	pr.shown = 0;
	if (!t.quiet && isatty(STDERR_FILENO)) {
		o.so.progress = show_progress;
		o.so.progress_ctx = &pr;
	}
	/* A solve runs hundreds of transform pairs: worth MEASURE on big grids. */
	o.so.fft_effort = tool_fft_effort(&t, h->nx, h->ny, 1e4);
	plan_seconds = rc_clock();
	if ((solver = rc_solver_new(h, &o.so, &err)) == NULL)
		tool_fail(&t, "%s", err.msg);
	tool_fft_finish(&t);
	plan_seconds = rc_clock() - plan_seconds;
	if (o.init != NULL) {
		rc_grid *u = tool_read_grid(&t, o.init);

		tool_grid_to_unit(&t, u, o.init, h->unit);
		if (u->nx != h->nx || u->ny != h->ny)
			tool_fail(&t, "%s: %zux%zu grid, the indenter is %zux%zu", o.init,
			    u->nx, u->ny, h->nx, h->ny);
		if (rc_solver_set_displacement(solver, u->z, &err) != 0)
			tool_fail_at(&t, o.init, err.msg);
		rc_grid_free(u);
	}
	if (o.resume_path != NULL) {
		if (rc_solver_set_displacement(solver, saved_u->z, &err) != 0)
			tool_fail(&t, "--resume %s: %s", o.resume_path, err.msg);
		rc_grid_free(saved_u);
		first = saved.next;
		if (saved.solving)
			resumed_iterations = saved.iterations;
	}

	memset(&sa, 0, sizeof(sa));
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);

	if (rc_atomic_open(&out, t.out, &err) != 0)
		tool_fail_at(&t, t.out, err.msg);
	tool_table_begin(&t, &table, out.fp);
	rc_row_init(&row);
	rc_contact_defaults(&co);
	co.alpha = o.alpha;
	co.modulus = o.modulus;
	co.gbar = gbar;
	co.fft = o.fd || o.so.boundary == RC_BOUNDARY_FREE ? NULL : &fft;
	co.fd = o.fd;
	co.nonperiodic = o.so.boundary == RC_BOUNDARY_FREE;
	/* A resumed run first repeats the rows its checkpoint finished. */
	for (size_t k = 0; k < first; k++) {
		if (rc_checkpoint_row(&saved, k, &row, &err) != 0 ||
		    (o.ck_path != NULL && rc_checkpoint_add_row(&ck, &row, &err) != 0)) {
			rc_atomic_abort(&out);
			tool_fail(&t, "--resume %s: %s", o.resume_path, err.msg);
		}
		if (rc_table_write(&table, &row, &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail_at(&t, t.out ? t.out : "standard output", err.msg);
		}
	}
	if (o.resume_path != NULL && first >= npressures) {
		rc_atomic_abort(&out);
		tool_fail(&t, "--resume %s: every pressure of it is done; nothing "
		    "to resume", o.resume_path);
	}
	if (o.ck_every > 0) {
		struct sigaction alarm_sa;

		memset(&alarm_sa, 0, sizeof(alarm_sa));
		alarm_sa.sa_handler = on_alarm;
		alarm_sa.sa_flags = SA_RESTART;
		sigemptyset(&alarm_sa.sa_mask);
		sigaction(SIGALRM, &alarm_sa, NULL);
		arm_timer(o.ck_every);
	}
	for (size_t k = first; k < npressures; k++) {
		rc_solve_result res;
		rc_contact_stats st;
		double p = o.napproach ? NAN : o.nreduced ?
		    o.reduced[k] * o.modulus * gbar : o.absolute[k];
		/* Echo a requested p* exactly: p/(E* gbar) rounds. */
		double p_star = o.nreduced ? o.reduced[k] :
		    gbar > 0 ? p / (o.modulus * gbar) : NAN;
		double seconds = 0;
		long iterations = k == first ? resumed_iterations : 0;
		int r;

		pr.p = p;
		pr.p_star = p_star;
		/* A periodic checkpoint stops the solve through o.so.stop; it is
		 * saved and the same pressure goes on from where it stopped. */
		for (;;) {
			if (o.napproach) {
				r = rc_solver_solve_approach(solver, o.approach[k], &p,
				    &res, &err);
				p_star = gbar > 0 ? p / (o.modulus * gbar) : NAN;
			} else
				r = rc_solver_solve(solver, p, &res, &err);
			if (pr.shown) {
				fputc('\n', stderr);
				pr.shown = 0;
			}
			if (r < 0) {
				rc_atomic_abort(&out);
				if (o.napproach)
					tool_fail(&t, "approach %g: %s", o.approach[k], err.msg);
				tool_fail(&t, "p = %g: %s", p, err.msg);
			}
			/* A resumed count plus this piece, saturating. */
			iterations = rc_checkpoint_iterations_add(iterations,
			    res.iterations);
			seconds += res.seconds;
			if (r == 0 || !stop_flag)
				break;
			if (o.ck_path != NULL) {
				ck.next = k;
				ck.solving = 1;
				ck.iterations = iterations;
				if (rc_checkpoint_write(&ck, rc_solver_displacement(solver),
				    o.ck_path, &err) != 0) {
					if (stop_signal) {
						rc_err werr;

						/* The finished rows are kept all the same. */
						if (k == 0 || rc_table_end(&table, &werr) != 0 ||
						    rc_atomic_commit(&out, &werr) != 0)
							rc_atomic_abort(&out);
						tool_fail(&t, "interrupted by signal %d while "
						    "solving p = %g; the checkpoint %s could not be "
						    "written: %s; the rows of the %zu of %zu "
						    "pressures done before it are written",
						    (int)stop_signal, p, o.ck_path, err.msg, k,
						    npressures);
					}
					tool_warn(&t, "checkpoint %s: %s; going on", o.ck_path,
					    err.msg);
				}
			}
			if (stop_signal) {
				char *cmd = o.ck_path ? resume_command(argc, argv, o.ck_path) : NULL;

				/* The rows of finished pressures are complete: keep them. */
				if (k == 0 || rc_table_end(&table, &err) != 0 ||
				    rc_atomic_commit(&out, &err) != 0)
					rc_atomic_abort(&out);
				if (o.ck_path == NULL)
					tool_fail(&t, "interrupted by signal %d while solving "
					    "p = %g (iteration %ld); the rows of the %zu of %zu "
					    "pressures done before it are written, no fields "
					    "(--checkpoint FILE makes a run resumable)",
					    (int)stop_signal, p, iterations, k, npressures);
				tool_fail(&t, "interrupted by signal %d while solving p = %g "
				    "(pressure %zu of %zu, iteration %ld); state saved in %s; "
				    "resume with: %s%s", (int)stop_signal, p, k + 1,
				    npressures, iterations, o.ck_path, cmd ? cmd : "",
				    input == NULL || rc_is_stdio(input) ?
				    " (with the same indenter on standard input)" : "");
			}
			stop_flag = 0;
			if (stop_signal)
				stop_flag = 1;
			arm_timer(o.ck_every);
		}
		res.iterations = iterations;
		res.seconds = seconds;
		co.pressure = p;
		if (rc_contact_analyse(h, rc_solver_contact(solver), &co, &st,
		    &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail(&t, "p = %g: %s", p, err.msg);
		}
		{
			struct gfmd_row in = { .p_star = p_star, .p = p, .gbar = gbar,
			    .stats = &st, .mean_gap = rc_solver_mean_gap(solver),
			    .a_subpixel = o.so.boundary == RC_BOUNDARY_FREE ? NAN :
			    rc_contact_subpixel(rc_solver_displacement(solver),
			    h->z, rc_solver_pressure(solver),
			    rc_solver_contact(solver), h->nx, h->ny, h->lx, h->ly,
			    o.so.modulus),
			    .elastic_energy = rc_solver_elastic_energy(solver),
			    .iterations = res.iterations, .residual = res.residual,
			    .tol = o.so.tol,
			    .seconds = res.seconds, .plan_seconds = plan_seconds,
			    .method = rc_method_name(o.so.method),
			    .boundary = rc_boundary_name(o.so.boundary),
			    .kernel = rc_kernel_name(o.so.boundary ==
			    RC_BOUNDARY_FREE ? RC_KERNEL_PIXEL : o.so.kernel),
			    .approach = rc_solver_approach(solver), .indenter = h,
			    .hardness = rc_solver_opts_plastic(&o.so) ?
			    o.so.hardness : 0,
			    .a_plastic = rc_solver_plastic_fraction(solver),
			    .thickness = o.so.thickness,
			    .substrate = o.so.substrate, .poisson = o.so.poisson,
			    .nx = h->nx, .ny = h->ny };

			const char *why = gfmd_kappa_c_why(&in);

			if (why != NULL)
				tool_warn(&t, "p = %g: kappa_c written as nan: %s", p,
				    why);
			if (gfmd_result_row(&row, &in) != 0) {
				rc_atomic_abort(&out);
				tool_fail(&t, "out of memory");
			}
		}
		if (rc_table_write(&table, &row, &err) != 0) {
			rc_atomic_abort(&out);
			tool_fail_at(&t, t.out ? t.out : "standard output", err.msg);
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
			    p, res.iterations, res.residual, o.so.tol);
		}
		last_p = p;
		last_p_star = p_star;
		if (o.ck_path != NULL && k + 1 < npressures) {
			/* Saved after each finished pressure: a stop from here
			 * on loses nothing. */
			ck.next = k + 1;
			ck.solving = 0;
			ck.iterations = 0;
			if (rc_checkpoint_add_row(&ck, &row, &err) != 0 ||
			    rc_checkpoint_write(&ck, rc_solver_displacement(solver),
			    o.ck_path, &err) != 0) {
				if (stop_signal) {
					rc_err werr;

					if (rc_table_end(&table, &werr) != 0 ||
					    rc_atomic_commit(&out, &werr) != 0)
						rc_atomic_abort(&out);
					tool_fail(&t, "interrupted by signal %d after pressure "
					    "%zu of %zu; the checkpoint %s could not be written: "
					    "%s; the rows of the pressures done are written",
					    (int)stop_signal, k + 1, npressures, o.ck_path,
					    err.msg);
				}
				tool_warn(&t, "checkpoint %s: %s; going on", o.ck_path,
				    err.msg);
			}
			if (stop_signal) {
				char *cmd = resume_command(argc, argv, o.ck_path);

				if (rc_table_end(&table, &err) != 0 ||
				    rc_atomic_commit(&out, &err) != 0)
					rc_atomic_abort(&out);
				tool_fail(&t, "interrupted by signal %d after pressure %zu "
				    "of %zu; state saved in %s; resume with: %s%s",
				    (int)stop_signal, k + 1, npressures, o.ck_path,
				    cmd ? cmd : "", input == NULL || rc_is_stdio(input) ?
				    " (with the same indenter on standard input)" : "");
			}
		}
	}
	if (o.ck_every > 0) {
		struct itimerval off;

		memset(&off, 0, sizeof(off));
		setitimer(ITIMER_REAL, &off, NULL);
	}
	rc_row_free(&row);
	/* From here a signal ends the process, removing the temporary files
	 * of the fields being written. */
	sa.sa_handler = tool_on_signal;
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
	if (rc_table_end(&table, &err) != 0 || rc_atomic_commit(&out, &err) != 0) {
		rc_atomic_abort(&out);
		tool_fail_at(&t, t.out ? t.out : "standard output", err.msg);
	}
	if (!o.fd)
		rc_fft_free(&fft);

	/* Fields of the last pressure, only those asked for, one at a time. */
	{
		const char *method_name = rc_method_name(o.so.method);
		const double *u = rc_solver_displacement(solver);
		const double *sigma = rc_solver_pressure(solver);
		const unsigned char *mask = rc_solver_contact(solver);
		size_t np = rc_grid_size(h);
		rc_grid *g;

		if (o.field[GFMD_DISPLACEMENT] != NULL) {
			g = field_grid(&t, h, RC_KIND_DISPLACEMENT, last_p, last_p_star,
			    o.modulus, method_name, o.so.boundary);
			memcpy(g->z, u, np * sizeof(double));
			tool_write_grid(&t, g, o.field[GFMD_DISPLACEMENT]);
			rc_grid_free(g);
		}
		if (o.field[GFMD_GAP] != NULL) {
			g = field_grid(&t, h, RC_KIND_GAP, last_p, last_p_star, o.modulus,
			    method_name, o.so.boundary);
			for (size_t k = 0; k < np; k++)
				g->z[k] = u[k] - h->z[k];
			tool_write_grid(&t, g, o.field[GFMD_GAP]);
			rc_grid_free(g);
		}
		if (o.field[GFMD_PRESSURE] != NULL) {
			g = field_grid(&t, h, RC_KIND_PRESSURE, last_p, last_p_star,
			    o.modulus, method_name, o.so.boundary);
			memcpy(g->z, sigma, np * sizeof(double));
			tool_write_grid(&t, g, o.field[GFMD_PRESSURE]);
			rc_grid_free(g);
		}
		if (o.field[GFMD_CONTACT] != NULL || t.png != NULL) {
			g = field_grid(&t, h, RC_KIND_MASK, last_p, last_p_star, o.modulus,
			    method_name, o.so.boundary);
			for (size_t k = 0; k < np; k++)
				g->z[k] = mask[k] != 0;
			if (o.field[GFMD_CONTACT] != NULL)
				tool_write_grid(&t, g, o.field[GFMD_CONTACT]);
			if (t.png != NULL) {
				rc_png_opts po;
				char caption[96];
				size_t n_c = 0;

				for (size_t k = 0; k < np; k++)
					n_c += mask[k] != 0;
				/* The last pressure's, as in its row (a_r = n_c/n_tot). */
				snprintf(caption, sizeof(caption), "p*=%.4g  a_r=%.4g",
				    last_p_star, (double)n_c / (double)np);
				rc_png_defaults(&po);
				po.overlay = g;
				po.caption = caption;
				if (rc_png_write(h, t.png, &po, &err) != 0)
					tool_fail_at(&t, t.png, err.msg);
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
	if (o.ck_path != NULL && rc_atomic_remove(o.ck_path, &err) != 0)
		tool_warn(&t, "%s", err.msg);
	if (o.ck_path != NULL || o.resume_path != NULL)
		rc_checkpoint_free(&ck);
	if (o.resume_path != NULL)
		rc_checkpoint_free(&saved);
	rc_solver_free(solver);
	rc_grid_free(h);
	gfmd_opts_free(&o);
	return tool_exit(&t, status);
}
