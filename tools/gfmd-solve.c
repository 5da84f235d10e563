/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd-solve - contact of a linearly elastic half space on a rigid rough
 * indenter, one result row per pressure (see gfmd-solve(1)). */
#include <getopt.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/time.h>
#include <unistd.h>

#include "adhesion.h"
#include "atomic.h"
#include "checkpoint.h"
#include "clock.h"
#include "common.h"
#include "contact.h"
#include "fft.h"
#include "gradient.h"
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

/* 1 if argv element a is the option that took value v (getopt_long's
 * optarg: inside a, as in --init=F or an abbreviation --ini=F) or the
 * option word just before v's own element (--ini F).  By pointer, so an
 * abbreviated option is found and an argument that merely reads
 * "--init" is not. */
static int
takes_value(char *const *argv, int i, int argc, const char *v)
{
	const char *a = argv[i];

	if (v == NULL)
		return 0;
	if (v > a && v <= a + strlen(a))
		return 1;
	return v == a || (i + 1 < argc && v == argv[i + 1]);
}

/* The command that resumes this run: the same arguments without --init
 * or an earlier --resume (skip: their values, as parsed), plus --resume
 * PATH. */
static char *
resume_command(int argc, char **argv, const char *path,
    const char *const skip[2])
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
		if (i > 0 && i < argc && (takes_value(argv, i, argc, skip[0]) ||
		    takes_value(argv, i, argc, skip[1])))
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

/* The progress line on a terminal: shown once a solve has run
 * PROGRESS_AFTER seconds, redrawn in place at most every PROGRESS_EVERY,
 * erased when the solve ends (progress_clear). */
#define PROGRESS_AFTER	2.0
#define PROGRESS_EVERY	0.25

struct progress {
	const char *name;
	double p_star, p;
	double start, drawn;	/* the solve's start, the last drawing */
	int width;		/* characters drawn, 0: none */
};

static void
show_progress(void *ctx, long iter, double residual, double contact_fraction)
{
	struct progress *pr = ctx;
	double now = rc_clock();
	int w;

	if (now - pr->start < PROGRESS_AFTER ||
	    (pr->width > 0 && now - pr->drawn < PROGRESS_EVERY))
		return;
	w = fprintf(stderr, "\r%s: p* = %.4g (p = %.4g): iteration %ld, "
	    "residual %.3e, a_r %.4f, %.0f s", pr->name, pr->p_star, pr->p,
	    iter, residual, contact_fraction, now - pr->start);
	/* blank what a longer line left */
	if (w > 0 && w < pr->width)
		fprintf(stderr, "%*s", pr->width - w, "");
	if (w > pr->width)
		pr->width = w;
	pr->drawn = now;
}

static void
progress_clear(struct progress *pr)
{
	if (pr->width > 0)
		fprintf(stderr, "\r%*s\r", pr->width, "");
	pr->width = 0;
}

/* Long: the help text, one printf. */
static void
usage(void)
{
	printf(
"usage: gfmd-solve (-p P[,P...] | --pressure-abs P[,P...] | --approach D[,D...])\n"
"           [-E MODULUS] [--boundary periodic|free] [--method fire|cg] [--hardness H]\n"
"           [--kernel continuum|pixel]\n"
"           [--thickness D --poisson NU [--substrate bonded|slip]]\n"
"           [--adhesion DGAMMA --range RHO [--law exponential|dugdale]]\n"
"           [--tol TOL] [--max-iter N] [--stall N] [--alpha A] [--fd]\n"
"           [--init FILE] [--contact FILE] [--gap FILE] [--pressure FILE]\n"
"           [--displacement FILE] [--png FILE] [--checkpoint FILE]\n"
"           [--checkpoint-every MIN] [--resume FILE] [-o FILE] [--json] [--pretty]\n"
"           [-j N] [-q]\n"
"           [-L LX[xLY]] [--unit U] [--z-unit U] [--periodic|--no-periodic]\n"
"           [--npy-order yx|xy] [--uniform] [FILE]\n"
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
"                       (units of E*; either method and boundary kind, with\n"
"                       --approach too; not with --adhesion; default no cap)\n"
"  --thickness D        an elastic layer of thickness D (length units) on a\n"
"                       rigid substrate instead of the half space (either\n"
"                       boundary kind; default: a half space)\n"
"  --poisson NU         the layer's Poisson ratio, in (-1, 0.5]\n"
"  --substrate bonded|slip  the layer's interface with the substrate: bonded\n"
"                       (default) or frictionless\n"
"  --adhesion DGAMMA    adhesion: work of adhesion DGAMMA (units of E* times\n"
"                       length) of the law of --law (FIRE; pressures and\n"
"                       approaches may then be zero or negative; default\n"
"                       none)\n"
"  --range RHO          the adhesive law's range (length units)\n"
"  --law exponential|dugdale  the adhesive law: the tension\n"
"                       (DGAMMA/RHO) exp(-gap/RHO) (default), or Dugdale's\n"
"                       DGAMMA/RHO up to the opening RHO and none beyond\n"
"  --tol TOL            convergence tolerance (default 1e-6)\n"
"  --max-iter N         iterations per pressure (default 100000)\n"
"  --stall N            end a solve whose residual has not halved in N\n"
"                       iterations, as not converged (default 300; 0: never)\n"
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
"                       FILE (.surf, a new file or the --resume one);\n"
"                       removed when the run completes\n"
"  --checkpoint-every MIN  also save it every MIN minutes (at least 0.005)\n"
"                       during a solve\n"
"  --resume FILE        continue the run saved in FILE (same indenter; the\n"
"                       pressures, solver options, boundary and effects\n"
"                       default to FILE's)\n"
"  -o FILE              result table (default standard output)\n"
"  --json               JSON instead of TSV\n"
"  --pretty             aligned, rounded table (default on a terminal)\n"
"  -j N                 threads (default OMP_NUM_THREADS, else 1 under\n"
"                       make -j, else all cores)\n"
"  --fft-effort E       estimate, measure or patient FFT planning (default:\n"
"                       measure, time-bounded, for 1024^2 points and more\n"
"                       and 10 pressures or 2 approaches and more, else\n"
"                       estimate)\n"
"  --wisdom FILE        load FFTW wisdom, save it after planning ($RC_WISDOM)\n"
"  -q                   no progress line (shown on a terminal after 2 s)\n"
"  -L LX[xLY]           cell size of an input that carries none\n"
"  --unit U             length unit of the work and the output fields (m mm\n"
"                       um nm pm angstrom); the unit of an input that has none\n"
"  --z-unit U           the indenter's heights are in length unit U\n"
"  --periodic, --no-periodic  the indenter is (not) one period of a surface\n"
"  --npy-order yx|xy    .npy shape (ny, nx) (default) or (nx, ny)\n"
"  --uniform            resample an x-z profile whose x is not uniformly\n"
"                       spaced linearly onto as many points\n"
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

/* Everything one run holds, so that main reads as the run's steps. */
/* A file's identity, to remove at the end only the file this run wrote
 * (or the checkpoint it resumed). */
struct file_id {
	dev_t dev;
	ino_t ino;
	int set;
};

struct run {
	struct tool t;
	struct gfmd_opts o;
	int argc;
	char **argv;
	const char *input;		/* NULL: standard input */
	rc_grid *h;			/* the indenter */
	double gbar;			/* its rms gradient */
	rc_fft fft;			/* the analysis plan (spectral gbar_c) */
	rc_fft *ana;			/* it, or the solver's when alike */
	rc_solver *solver;
	int effort_set;			/* o.so.fft_effort decided */
	double plan_seconds;
	double l_adh_dx;		/* adhesion: l_adh / dx; 0: none */
	size_t npressures;
	size_t first;			/* the first pressure to solve (resume) */
	long resumed_iterations;	/* of that pressure, from the checkpoint */
	size_t nunconverged;
	double last_p, last_p_star;
	rc_checkpoint ck, saved;	/* written (--checkpoint), read (--resume) */
	/* what is at --checkpoint: the checkpoint --resume read there, the
	 * one this run wrote last; only those are removed at the end */
	struct file_id ck_found, ck_written;
	rc_grid *saved_u;
	rc_atomic out;
	int out_existed;	/* -o named a file that was there before the run */
	char rows_note[256];	/* what a stop did with the finished rows */
	rc_table_out table;
	rc_row row;
	rc_contact_opts co;
	struct progress pr;
	struct sigaction sa;
};

/* The identity of the regular file path names (through links); 0 if
 * there is none. */
static int
file_id(const char *path, struct file_id *id)
{
	struct stat st;

	memset(id, 0, sizeof(*id));
	if (path == NULL || rc_is_stdio(path) || stat(path, &st) != 0 ||
	    !S_ISREG(st.st_mode))
		return 0;
	id->dev = st.st_dev;
	id->ino = st.st_ino;
	id->set = 1;
	return 1;
}

static int
same_file(const struct file_id *a, const struct file_id *b)
{
	return a->set && b->set && a->dev == b->dev && a->ino == b->ino;
}

/* --checkpoint FILE replaces FILE as the run goes and removes it at the
 * end: an existing regular file there may only be the checkpoint that
 * --resume reads.  Anything else is the user's (another file, or the
 * saved state of an unfinished run, which a new run would have replaced
 * and then removed), and the run is refused before any work (exit 2).
 * A device or FIFO is written, never removed. */
static void
checkpoint_target_check(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	struct file_id resume_id;
	rc_checkpoint probe;
	rc_grid *u;
	rc_err err;

	struct file_id found;

	if (!file_id(o->ck_path, &found))
		return;
	if (file_id(o->resume_path, &resume_id) &&
	    same_file(&found, &resume_id)) {
		r->ck_found = found;
		return;
	}
	if (rc_checkpoint_read(&probe, &u, o->ck_path, &err) == 0) {
		tool_bad(&r->t, "--checkpoint %s: the file holds the saved state "
		    "of an unfinished run (%zu of %zu pressures done), which this "
		    "run would replace and remove: continue it with --resume %s, "
		    "or remove it, or name a new file", o->ck_path, probe.next,
		    probe.npressures, o->ck_path);
		rc_checkpoint_free(&probe);
		rc_grid_free(u);
	} else
		tool_bad(&r->t, "--checkpoint %s: the file exists and is not a "
		    "gfmd-solve checkpoint (%s); a checkpoint replaces it and is "
		    "removed at the end: name a new file", o->ck_path, err.msg);
	tool_usage_check(&r->t);
}

/* Options into r->o, checked together; 1 after --help. */
static int
parse_options(struct run *r, int argc, char **argv)
{
	static const struct option longopts[] = {
		GFMD_LONGOPTS,
		TOOL_FFT_LONGOPTS,
		TOOL_GRID_LONGOPTS,
		TOOL_CHANNEL_LONGOPT,
		{ NULL, 0, NULL, 0 }
	};
	struct gfmd_opts *o = &r->o;
	rc_err err;
	int c, help = 0;

	r->argc = argc;
	r->argv = argv;
	tool_init(&r->t, "gfmd-solve", argc, argv);
	gfmd_opts_init(o);
	opterr = 0;	/* tool_bad reports, so that all problems are counted */
	while ((c = getopt_long(argc, argv, GFMD_OPTSTRING, longopts, NULL)) != -1) {
		if (c == 'h')
			help = 1;
		else
			gfmd_option(&r->t, o, c, optarg, argv);
	}
	if (help && tool_help_check(&r->t)) {
		usage();
		return 1;
	}
	gfmd_opts_check(&r->t, o, argc, argv);
	tool_usage_check(&r->t);
	r->input = optind < argc ? argv[optind] : NULL;
	if (o->ck_path != NULL) {
		if ((lock_fd = rc_checkpoint_lock(o->ck_path, &lock_path, &err)) == -1)
			tool_fail(&r->t, "--checkpoint %s: %s", o->ck_path, err.msg);
		atexit(unlock_at_exit);
		checkpoint_target_check(r);
	}
	r->npressures = o->napproach ? o->napproach : o->nreduced ? o->nreduced :
	    o->nabsolute;
	return 0;
}

/* --resume: the options that decide the rows default to the checkpoint's
 * (those given must match it: checkpoint_setup). */
static void
resume_defaults(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_checkpoint *saved = &r->saved;
	rc_err err;
	int method;

	if (rc_checkpoint_read(saved, &r->saved_u, o->resume_path, &err) != 0)
		tool_fail_at(&r->t, o->resume_path, err.msg);
	if (!o->given_method && (method = rc_method_parse(saved->method)) >= 0)
		o->so.method = (enum rc_method)method;
	if (!o->given_tol)
		o->so.tol = saved->tol;
	if (!o->given_e)
		o->modulus = saved->modulus;
	if (!o->given_alpha)
		o->alpha = saved->alpha;
	if (!o->given_fd)
		o->fd = saved->fd;
	if (!o->given_max_iter)
		o->so.max_iter = saved->max_iter;
	if (!o->given_stall && saved->stall >= 0)
		o->so.stall_window = saved->stall;
	/* the scene; the boundary kind only where recorded (version 3) */
	if (o->boundary < 0 && saved->boundary >= 0)
		o->boundary = saved->boundary;
	if (!o->given_kernel)
		o->so.kernel = (enum rc_kernel)saved->kernel;
	if (!o->given_hardness)
		o->so.hardness = saved->hardness;
	if (!o->given_layer) {
		o->so.thickness = saved->thickness;
		o->so.substrate = (enum rc_substrate)saved->substrate;
		o->so.poisson = saved->poisson;
	}
	if (!o->given_adhesion) {
		o->so.adhesion = saved->adhesion;
		o->so.range = saved->range;
	}
	if (!o->given_law)
		o->so.adhesion_law = (enum rc_adhesion_law)saved->law;
	else if (!(o->so.adhesion > 0)) {
		tool_bad(&r->t, "--law: %s has no adhesion to give a law to "
		    "(add --adhesion and --range, or drop --law)",
		    o->resume_path);
		tool_usage_check(&r->t);
	}
	if (!o->nreduced && !o->nabsolute) {
		double *copy = malloc(saved->npressures * sizeof(double));

		if (copy == NULL)
			tool_fail(&r->t, "out of memory");
		memcpy(copy, saved->pressures, saved->npressures * sizeof(double));
		if (saved->reduced) {
			o->reduced = copy;
			o->nreduced = saved->npressures;
		} else {
			o->absolute = copy;
			o->nabsolute = saved->npressures;
		}
		r->npressures = saved->npressures;
	}
}

/* Free boundaries: the grid's periodic flag decides unless --boundary
 * is given (or restored from a checkpoint). */
static enum rc_boundary
run_boundary(const struct run *r)
{
	return r->o.boundary >= 0 ? (enum rc_boundary)r->o.boundary :
	    r->h->periodic ? RC_BOUNDARY_PERIODIC : RC_BOUNDARY_FREE;
}

/* The checkpoint this run writes, and the one it resumes checked
 * against it. */
static void
checkpoint_setup(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_checkpoint *ck = &r->ck;
	rc_err err;

	if (o->ck_path == NULL && o->resume_path == NULL)
		return;
	if (rc_checkpoint_init(ck, r->h, o->nreduced ? o->reduced : o->absolute,
	    r->npressures, &err) != 0)
		tool_fail(&r->t, "%s", err.msg);
	snprintf(ck->method, sizeof(ck->method), "%s", rc_method_name(o->so.method));
	ck->tol = o->so.tol;
	ck->modulus = o->modulus;
	ck->alpha = o->alpha;
	ck->fd = o->fd;
	ck->max_iter = o->so.max_iter;
	ck->stall = o->so.stall_window;
	ck->boundary = (int)run_boundary(r);
	ck->kernel = (int)o->so.kernel;
	ck->hardness = o->so.hardness;
	ck->thickness = o->so.thickness;
	ck->substrate = (int)o->so.substrate;
	ck->poisson = o->so.poisson;
	ck->adhesion = o->so.adhesion;
	ck->range = o->so.range;
	ck->law = (int)o->so.adhesion_law;
	ck->reduced = o->nreduced != 0;
	if (o->resume_path == NULL)
		return;
	if (rc_checkpoint_match(&r->saved, ck, &err) != 0)
		tool_fail(&r->t, "--resume %s: %s", o->resume_path, err.msg);
	if (r->saved_u->nx != r->h->nx || r->saved_u->ny != r->h->ny)
		tool_fail(&r->t, "--resume %s: %zux%zu field, the indenter is "
		    "%zux%zu", o->resume_path, r->saved_u->nx, r->saved_u->ny,
		    r->h->nx, r->h->ny);
}

/* The boundary kind, the indenter's rms gradient gbar (the unit of p*)
 * and the checks on its scale. */
/* Loads and layers past what doubles carry through the solve (issue 27:
 * -p 1e300 and --thickness 1e300 ran 100000 iterations to "not
 * converged"): the solver squares pressures and (q d) (energies, norms,
 * the layer kernel), which overflow past about 1e154 (measured on 32^2:
 * p* = 1e150 solves, 1e160 does not; d = 1e100 solves, 1e200 does not),
 * so |p*| and d / max(lx, ly, height range) are refused past 1e100, a
 * margin of 1e50 for the grid's factors.  Exit 2, before the solve. */
#define RANGE_MAX 1e100
static void
range_check(struct run *r, double height_range)
{
	struct gfmd_opts *o = &r->o;
	const rc_grid *h = r->h;
	double side = fmax(fmax(h->lx, h->ly), height_range);

	for (size_t k = 0; k < o->nreduced; k++)
		if (!(fabs(o->reduced[k]) <= RANGE_MAX))
			tool_bad(&r->t, "-p %g: out of range (|p*| <= %g)",
			    o->reduced[k], RANGE_MAX);
	for (size_t k = 0; k < o->nabsolute && r->gbar > 0; k++)
		if (!(fabs(o->absolute[k]) / (o->modulus * r->gbar) <= RANGE_MAX))
			tool_bad(&r->t, "--pressure-abs %g: out of range (p* = "
			    "p/(E* gbar) = %g, want |p*| <= %g)", o->absolute[k],
			    o->absolute[k] / (o->modulus * r->gbar), RANGE_MAX);
	if (o->so.thickness > 0 && !(o->so.thickness <= RANGE_MAX * side))
		tool_bad(&r->t, "--thickness %g: out of range (at most %g times "
		    "the grid's side %g; a layer that thick is the half space: "
		    "leave out --thickness)", o->so.thickness, RANGE_MAX, side);
	tool_usage_check(&r->t);
}

/* Adhesion: l_adh / dx, and a warning when the grid does not resolve
 * the law (adhesion.h). */
static void
adhesion_setup(struct run *r)
{
	const rc_grid *h = r->h;
	double dx = fmax(h->lx / (double)h->nx, h->ly / (double)h->ny);
	double l = rc_adhesion_length(r->o.modulus, r->o.so.adhesion,
	    r->o.so.range);

	r->l_adh_dx = l / dx;
	if (l < dx)
		tool_warn(&r->t, "--adhesion: the law is not resolved by the grid: "
		    "l_adh = E* rho^2 / dgamma = %g < dx = %g (want l_adh >= dx, "
		    "i.e. --range >= %g); the rows record l_adh_dx = %g",
		    l, dx, sqrt(r->o.so.adhesion * dx / r->o.modulus), l / dx);
}

/* The work ahead of the FFT plans, for the planning effort (fft.h): the
 * transform pairs of one row, 2 a FIRE iteration (38-149 iterations at
 * p* = 0.05 on 512^2-1024^2 surfaces, measured), and the solves of one
 * approach (a bracket, then its refinement: assumed, not measured). */
#define GFMD_PAIRS_PER_ROW		200.0
#define GFMD_SOLVES_PER_APPROACH	5.0

/* The solver's planning effort, decided once: the work ahead,
 * GFMD_PAIRS_PER_ROW transform pairs a row. */
static enum rc_fft_effort
solver_effort(struct run *r)
{
	struct gfmd_opts *o = &r->o;

	if (!r->effort_set) {
		o->so.fft_effort = tool_fft_effort(&r->t, r->h->nx, r->h->ny,
		    GFMD_PAIRS_PER_ROW * (o->napproach ?
		    GFMD_SOLVES_PER_APPROACH : 1) * (double)r->npressures);
		r->effort_set = 1;
	}
	return o->so.fft_effort;
}

/* The solver, planned and timed. */
static void
solver_make(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_err err;

	o->so.modulus = o->modulus;
	o->so.stop = (volatile int *)&stop_flag;
	r->pr.name = r->t.name;
	r->pr.width = 0;
	if (!r->t.quiet && isatty(STDERR_FILENO)) {
		o->so.progress = show_progress;
		o->so.progress_ctx = &r->pr;
	}
	solver_effort(r);
	r->plan_seconds = rc_clock();
	if ((r->solver = rc_solver_new(r->h, &o->so, &err)) == NULL)
		tool_fail(&r->t, "%s", err.msg);
	tool_fft_finish(&r->t);
	r->plan_seconds = rc_clock() - r->plan_seconds;
}

static void
indenter_setup(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	const rc_grid *h = r->h;
	const char *name = r->input ? r->input : "standard input";
	double lo = INFINITY, hi = -INFINITY;
	rc_err err;

	o->so.boundary = run_boundary(r);
	if (o->so.boundary == RC_BOUNDARY_PERIODIC) {
		tool_check_wrap(&r->t, h, r->input, "--boundary periodic "
		    "solves it", "Leave out --boundary periodic: a patch is "
		    "solved with free boundaries");
		if (o->given_kernel && o->so.kernel == RC_KERNEL_PIXEL &&
		    o->given_layer)
			tool_bad(&r->t, "%s (%s is periodic)",
			    gfmd_pixel_layer_refusal, name);
		tool_usage_check(&r->t);
	} else if (o->given_kernel && o->so.kernel != RC_KERNEL_PIXEL)
		tool_fail(&r->t, "--kernel %s: %s is solved with free boundaries "
		    "(not marked periodic), which always use Love's pixel "
		    "compliance; drop --kernel or add --boundary periodic",
		    rc_kernel_name(o->so.kernel), name);
	/* The analysis plan lives as long as the solver; --fd and free
	 * boundaries need none.  It is the solver's when that plans with
	 * FFTW_ESTIMATE too (the same transforms bit for bit): the solver is
	 * then made first and gbar taken on its plan, not on a plan of its
	 * own (planning, buffers and their first touch: 20 ms of CPU of a
	 * 330 ms process at 512^2, perf). */
	memset(&r->fft, 0, sizeof(r->fft));
	r->ana = &r->fft;
	if (o->so.boundary == RC_BOUNDARY_FREE)
		r->gbar = rc_gbar_open(h);
	else if (o->fd)
		r->gbar = rc_gbar_central(h);
	else {
		rc_fft *sf = NULL;

		if (solver_effort(r) == RC_FFT_ESTIMATE) {
			solver_make(r);
			if ((sf = rc_solver_fft(r->solver)) != NULL &&
			    (sf->nx != h->nx || sf->ny != h->ny ||
			    sf->effort != RC_FFT_ESTIMATE))
				sf = NULL;
		}
		if (sf != NULL)
			r->ana = sf;
		else if (rc_fft_init(&r->fft, h->nx, h->ny, RC_FFT_ESTIMATE,
		    &err) != 0)
			tool_fail(&r->t, "%s", err.msg);
		if (rc_rms_gradient(h, r->ana, &r->gbar, &err) != 0)
			tool_fail(&r->t, "%s", err.msg);
	}
	/* Comparisons, not fmin/fmax (a libm call a point each, 1.5% of
	 * the CPU outside the solve at 512^2): the same lo and hi, as a NaN
	 * height compares false and leaves them, as fmin/fmax ignore it.
	 * Only a zero's sign may differ (fmin(0, -0) may be either): then
	 * hi - lo is +0 here, +0 or -0 before; its users compare it (0 ==
	 * -0) and print it only with a bad gbar, which a flat surface (gbar
	 * 0) never has. */
	for (size_t k = 0; k < rc_grid_size(h); k++) {
		if (h->z[k] < lo)
			lo = h->z[k];
		if (h->z[k] > hi)
			hi = h->z[k];
	}
	gfmd_check_scale(&r->t, r->input, hi - lo, r->gbar);
	if (rc_solver_opts_adhesive(&o->so))
		adhesion_setup(r);
	if (o->nreduced && !(r->gbar > 0))
		tool_fail(&r->t, "%s: the indenter is flat (rms gradient 0), so the "
		    "reduced pressure p* = p/(E* gbar) is undefined; use --pressure-abs",
		    name);	range_check(r, hi - lo);
}

/* The solver (unless indenter_setup made it), started from --init or
 * the checkpoint. */
static void
solver_setup(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_fft *sf;
	rc_err err;

	if (r->solver == NULL)
		solver_make(r);
	/* The analysis on the solver's plans when they are made alike (the
	 * same transforms bit for bit): one set of buffers, not two. */
	if (r->fft.real != NULL && (sf = rc_solver_fft(r->solver)) != NULL &&
	    sf->nx == r->fft.nx && sf->ny == r->fft.ny &&
	    sf->effort == r->fft.effort) {
		rc_fft_free(&r->fft);
		r->ana = sf;
	}
	if (o->init != NULL) {
		rc_grid *u = tool_read_grid(&r->t, o->init);

		tool_grid_to_unit(&r->t, u, o->init, r->h->unit);
		if (u->nx != r->h->nx || u->ny != r->h->ny)
			tool_fail(&r->t, "%s: %zux%zu grid, the indenter is %zux%zu",
			    o->init, u->nx, u->ny, r->h->nx, r->h->ny);
		if (rc_solver_set_displacement(r->solver, u->z, &err) != 0)
			tool_fail_at(&r->t, o->init, err.msg);
		rc_grid_free(u);
	}
	if (o->resume_path != NULL) {
		if (rc_solver_set_displacement(r->solver, r->saved_u->z, &err) != 0)
			tool_fail(&r->t, "--resume %s: %s", o->resume_path, err.msg);
		rc_grid_free(r->saved_u);
		r->saved_u = NULL;
		r->first = r->saved.next;
		/* the finished rows that did not converge count in the
		 * exit status as they did in the interrupted run */
		r->nunconverged = r->saved.unconverged;
		r->ck.unconverged = r->saved.unconverged;
		if (r->saved.solving)
			r->resumed_iterations = r->saved.iterations;
	}
}

/* The output opened, the first SIGINT/SIGTERM made a stop request, the
 * rows a resumed run finished repeated, the checkpoint timer armed. */
static void
output_begin(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_err err;

	memset(&r->sa, 0, sizeof(r->sa));
	r->sa.sa_handler = on_signal;
	sigemptyset(&r->sa.sa_mask);
	sigaction(SIGINT, &r->sa, NULL);
	sigaction(SIGTERM, &r->sa, NULL);

	if (rc_atomic_open(&r->out, r->t.out, &err) != 0)
		tool_fail_at(&r->t, r->t.out, err.msg);
	r->out_existed = r->out.tmp != NULL && access(r->out.path, F_OK) == 0;
	tool_table_begin(&r->t, &r->table, r->out.fp);
	rc_row_init(&r->row);
	rc_contact_defaults(&r->co);
	r->co.alpha = o->alpha;
	r->co.modulus = o->modulus;
	r->co.gbar = r->gbar;
	r->co.fft = o->fd || o->so.boundary == RC_BOUNDARY_FREE ? NULL : r->ana;
	r->co.fd = o->fd;
	r->co.nonperiodic = o->so.boundary == RC_BOUNDARY_FREE;
	for (size_t k = 0; k < r->first; k++) {
		if (rc_checkpoint_row(&r->saved, k, &r->row, &err) != 0 ||
		    (o->ck_path != NULL &&
		    rc_checkpoint_add_row(&r->ck, &r->row, &err) != 0)) {
			rc_atomic_abort(&r->out);
			tool_fail(&r->t, "--resume %s: %s", o->resume_path, err.msg);
		}
		if (rc_table_write(&r->table, &r->row, &err) != 0) {
			rc_atomic_abort(&r->out);
			tool_fail_at(&r->t, r->t.out ? r->t.out : "standard output",
			    err.msg);
		}
	}
	if (o->resume_path != NULL && r->first >= r->npressures) {
		rc_atomic_abort(&r->out);
		tool_fail(&r->t, "--resume %s: every pressure of it is done; nothing "
		    "to resume", o->resume_path);
	}
	if (o->ck_every > 0) {
		struct sigaction alarm_sa;

		memset(&alarm_sa, 0, sizeof(alarm_sa));
		alarm_sa.sa_handler = on_alarm;
		alarm_sa.sa_flags = SA_RESTART;
		sigemptyset(&alarm_sa.sa_mask);
		sigaction(SIGALRM, &alarm_sa, NULL);
		arm_timer(o->ck_every);
	}
}

/* The rows of the pressures finished before a stop are complete: keep
 * them in -o when it is a new file; a file that was there stays as it
 * was (a stopped run does not replace it with part of a table; the
 * checkpoint, if saved, has the rows and its resumed run writes them).
 * r->rows_note says which, for the stop's message. */
static void
keep_finished_rows(struct run *r, size_t done, int in_checkpoint)
{
	const char *name = r->t.out ? r->t.out : "standard output";
	rc_err err;

	if (done > 0 && r->out_existed) {
		rc_atomic_abort(&r->out);
		snprintf(r->rows_note, sizeof(r->rows_note), "%s was there "
		    "before and is kept as it was; the rows of the %zu of %zu "
		    "pressures done are %s", name, done, r->npressures,
		    in_checkpoint ? "in the checkpoint" : "not written");
		return;
	}
	if (done == 0 || rc_table_end(&r->table, &err) != 0 ||
	    rc_atomic_commit(&r->out, &err) != 0) {
		rc_atomic_abort(&r->out);
		snprintf(r->rows_note, sizeof(r->rows_note), done == 0 ?
		    "no pressure was done, no row written" : "the rows of the "
		    "%zu of %zu pressures done could not be written to %s: %s",
		    done, r->npressures, name, err.msg);
		return;
	}
	snprintf(r->rows_note, sizeof(r->rows_note), "the rows of the %zu of "
	    "%zu pressures done are written", done, r->npressures);
}

/* A stop inside pressure k (a signal, or the --checkpoint-every timer):
 * save the solver's state; on a signal end the run, telling how to
 * resume it. */
static void
stop_inside(struct run *r, size_t k, double p, long iterations)
{
	struct gfmd_opts *o = &r->o;
	const char *stdin_note = r->input == NULL || rc_is_stdio(r->input) ?
	    " (with the same indenter on standard input)" : "";
	rc_err err;

	if (o->ck_path != NULL) {
		r->ck.next = k;
		r->ck.solving = 1;
		r->ck.iterations = iterations;
		if (rc_checkpoint_write(&r->ck, rc_solver_displacement(r->solver),
		    o->ck_path, &err) == 0)
			file_id(o->ck_path, &r->ck_written);
		else {
			if (stop_signal) {
				keep_finished_rows(r, k, 0);
				tool_fail(&r->t, "interrupted by signal %d while "
				    "solving p = %g; the checkpoint %s could not be "
				    "written: %s; %s", (int)stop_signal, p,
				    o->ck_path, err.msg, r->rows_note);
			}
			tool_warn(&r->t, "checkpoint %s: %s; going on", o->ck_path,
			    err.msg);
		}
	}
	if (stop_signal) {
		const char *skip[2] = { o->init, o->resume_path };
		char *cmd = o->ck_path ? resume_command(r->argc, r->argv,
		    o->ck_path, skip) : NULL;

		keep_finished_rows(r, k, o->ck_path != NULL);
		if (o->ck_path == NULL)
			tool_fail(&r->t, "interrupted by signal %d while solving "
			    "p = %g (iteration %ld); %s, no fields "
			    "(--checkpoint FILE makes a run resumable)",
			    (int)stop_signal, p, iterations, r->rows_note);
		tool_fail(&r->t, "interrupted by signal %d while solving p = %g "
		    "(pressure %zu of %zu, iteration %ld); %s; state saved in "
		    "%s; resume with: %s%s", (int)stop_signal, p, k + 1,
		    r->npressures, iterations, r->rows_note, o->ck_path,
		    cmd ? cmd : "", stdin_note);
	}
	stop_flag = 0;
	if (stop_signal)
		stop_flag = 1;
	arm_timer(o->ck_every);
}

/* Solve pressure k (or approach k): *p, *p_star and *res of the solve,
 * its iterations and seconds summed over the pieces a checkpoint timer
 * cut it into. */
static void
solve_pressure(struct run *r, size_t k, double *p, double *p_star,
    rc_solve_result *res)
{
	struct gfmd_opts *o = &r->o;
	double seconds = 0;
	long iterations = k == r->first ? r->resumed_iterations : 0;
	rc_err err;
	int st;

	gfmd_pressure(o, k, r->gbar, p, p_star);
	r->pr.p = *p;
	r->pr.p_star = *p_star;
	r->pr.start = rc_clock();
	/* A periodic checkpoint stops the solve through o->so.stop; it is
	 * saved and the same pressure goes on from where it stopped. */
	for (;;) {
		/* what is left of --max-iter after the pieces before (a
		 * resumed count, a timer's stops): the row's iterations are
		 * those of one uninterrupted solve */
		if (rc_solver_set_max_iter(r->solver, iterations < o->so.max_iter ?
		    o->so.max_iter - iterations : 1, &err) != 0)
			tool_fail(&r->t, "%s", err.msg);
		if (o->napproach) {
			st = rc_solver_solve_approach(r->solver, o->approach[k], p,
			    res, &err);
			*p_star = r->gbar > 0 ? *p / (o->modulus * r->gbar) : NAN;
		} else
			st = rc_solver_solve(r->solver, *p, res, &err);
		progress_clear(&r->pr);
		if (st < 0) {
			rc_atomic_abort(&r->out);
			if (o->napproach)
				tool_fail(&r->t, "approach %g: %s", o->approach[k],
				    err.msg);
			tool_fail(&r->t, "p = %g: %s", *p, err.msg);
		}
		/* A resumed count plus this piece, saturating. */
		iterations = rc_checkpoint_iterations_add(iterations,
		    res->iterations);
		seconds += res->seconds;
		if (st == 0 || !stop_flag)
			break;
		stop_inside(r, k, *p, iterations);
	}
	res->iterations = iterations;
	res->seconds = seconds;
}

/* The result row of pressure p, written and flushed. */
static void
write_row(struct run *r, double p, double p_star, const rc_solve_result *res)
{
	const struct gfmd_opts *o = &r->o;
	const rc_grid *h = r->h;
	rc_solver *s = r->solver;
	rc_contact_stats st;
	rc_err err;

	r->co.pressure = p;
	if (rc_contact_analyse(h, rc_solver_contact(s), &r->co, &st, &err) != 0) {
		rc_atomic_abort(&r->out);
		tool_fail(&r->t, "p = %g: %s", p, err.msg);
	}
	{
		struct gfmd_row in = { .p_star = p_star, .p = p, .gbar = r->gbar,
		    .stats = &st, .mean_gap = rc_solver_mean_gap(s),
		    .a_subpixel = o->so.boundary == RC_BOUNDARY_FREE ? NAN :
		    rc_contact_subpixel(rc_solver_displacement(s), h->z,
		    rc_solver_pressure(s), rc_solver_contact(s), h->nx, h->ny,
		    h->lx, h->ly, o->so.modulus),
		    .elastic_energy = rc_solver_elastic_energy(s),
		    .iterations = res->iterations, .residual = res->residual,
		    .tol = o->so.tol,
		    .seconds = res->seconds, .plan_seconds = r->plan_seconds,
		    .method = rc_method_name(o->so.method),
		    .boundary = rc_boundary_name(o->so.boundary),
		    .kernel = rc_kernel_name(o->so.boundary ==
		    RC_BOUNDARY_FREE ? RC_KERNEL_PIXEL : o->so.kernel),
		    .approach = rc_solver_approach(s), .indenter = h,
		    .hardness = rc_solver_opts_plastic(&o->so) ?
		    o->so.hardness : 0,
		    .a_plastic = rc_solver_plastic_fraction(s),
		    .thickness = o->so.thickness,
		    .substrate = o->so.substrate, .poisson = o->so.poisson,
		    .adhesion = o->so.adhesion, .range = o->so.range,
		    .law = rc_solver_opts_adhesive(&o->so) ?
		    rc_adhesion_law_name(o->so.adhesion_law) : "none",
		    .p_adh = rc_solver_adhesive_pressure(s),
		    .a_attr = rc_solver_attractive_fraction(s),
		    .l_adh_dx = r->l_adh_dx, .separated = res->separated,
		    .stalled = res->stalled ? o->so.stall_window : 0,
		    .nx = h->nx, .ny = h->ny };
		int w = gfmd_emit_row(&r->t, &in, res->converged, &r->row,
		    &r->table, r->out.fp, &r->nunconverged, &err);

		r->ck.unconverged = r->nunconverged;

		if (w != 0) {
			rc_atomic_abort(&r->out);
			if (w == GFMD_ROW_NOMEM)
				tool_fail(&r->t, "out of memory");
			tool_fail_at(&r->t, r->t.out, err.msg);
		}
	}
	r->last_p = p;
	r->last_p_star = p_star;
}

/* Saved after each finished pressure but the last: a stop from here on
 * loses nothing. */
static void
checkpoint_after(struct run *r, size_t k)
{
	struct gfmd_opts *o = &r->o;
	rc_err err;

	if (o->ck_path == NULL || k + 1 >= r->npressures)
		return;
	r->ck.next = k + 1;
	r->ck.solving = 0;
	r->ck.iterations = 0;
	if (rc_checkpoint_add_row(&r->ck, &r->row, &err) == 0 &&
	    rc_checkpoint_write(&r->ck, rc_solver_displacement(r->solver),
	    o->ck_path, &err) == 0)
		file_id(o->ck_path, &r->ck_written);
	else {
		if (stop_signal) {
			keep_finished_rows(r, k + 1, 0);
			tool_fail(&r->t, "interrupted by signal %d after pressure "
			    "%zu of %zu; the checkpoint %s could not be written: "
			    "%s; %s", (int)stop_signal, k + 1, r->npressures,
			    o->ck_path, err.msg, r->rows_note);
		}
		tool_warn(&r->t, "checkpoint %s: %s; going on", o->ck_path, err.msg);
	}
	if (stop_signal) {
		const char *skip[2] = { o->init, o->resume_path };
		char *cmd = resume_command(r->argc, r->argv, o->ck_path, skip);

		keep_finished_rows(r, k + 1, 1);
		tool_fail(&r->t, "interrupted by signal %d after pressure %zu "
		    "of %zu; %s; state saved in %s; resume with: %s%s",
		    (int)stop_signal, k + 1, r->npressures, r->rows_note,
		    o->ck_path,
		    cmd ? cmd : "", r->input == NULL || rc_is_stdio(r->input) ?
		    " (with the same indenter on standard input)" : "");
	}
}

/* The table complete: timer off, signals back to removing temporaries,
 * the output committed. */
static void
output_end(struct run *r)
{
	rc_err err;

	if (r->o.ck_every > 0) {
		struct itimerval off;

		memset(&off, 0, sizeof(off));
		setitimer(ITIMER_REAL, &off, NULL);
	}
	rc_row_free(&r->row);
	/* From here a signal ends the process, removing the temporary files
	 * of the fields being written. */
	r->sa.sa_handler = tool_on_signal;
	sigaction(SIGINT, &r->sa, NULL);
	sigaction(SIGTERM, &r->sa, NULL);
	if (rc_table_end(&r->table, &err) != 0 ||
	    rc_atomic_commit(&r->out, &err) != 0) {
		rc_atomic_abort(&r->out);
		tool_fail_at(&r->t, r->t.out ? r->t.out : "standard output", err.msg);
	}
	/* A first signal after the last solve (no solve left to stop):
	 * the rows are kept, no fields, as for one inside a solve. */
	if (stop_signal)
		tool_fail(&r->t, "interrupted by signal %d after the last "
		    "pressure; the rows of all %zu pressures are written, no "
		    "fields", (int)stop_signal, r->npressures);
	if (!r->o.fd)
		rc_fft_free(&r->fft);
}

/* Fields of the last pressure, only those asked for, one at a time. */
static void
write_fields(struct run *r)
{
	const struct gfmd_opts *o = &r->o;
	const rc_grid *h = r->h;
	const char *method_name = rc_method_name(o->so.method);
	const double *u = rc_solver_displacement(r->solver);
	const double *sigma = rc_solver_pressure(r->solver);
	const unsigned char *mask = rc_solver_contact(r->solver);
	size_t np = rc_grid_size(h);
	rc_grid *g;
	rc_err err;

	if (o->field[GFMD_DISPLACEMENT] != NULL) {
		g = field_grid(&r->t, h, RC_KIND_DISPLACEMENT, r->last_p,
		    r->last_p_star, o->modulus, method_name, o->so.boundary);
		memcpy(g->z, u, np * sizeof(double));
		tool_write_grid(&r->t, g, o->field[GFMD_DISPLACEMENT]);
		rc_grid_free(g);
	}
	if (o->field[GFMD_GAP] != NULL) {
		g = field_grid(&r->t, h, RC_KIND_GAP, r->last_p, r->last_p_star,
		    o->modulus, method_name, o->so.boundary);
		for (size_t k = 0; k < np; k++)
			g->z[k] = u[k] - h->z[k];
		tool_write_grid(&r->t, g, o->field[GFMD_GAP]);
		rc_grid_free(g);
	}
	if (o->field[GFMD_PRESSURE] != NULL) {
		g = field_grid(&r->t, h, RC_KIND_PRESSURE, r->last_p,
		    r->last_p_star, o->modulus, method_name, o->so.boundary);
		memcpy(g->z, sigma, np * sizeof(double));
		tool_write_grid(&r->t, g, o->field[GFMD_PRESSURE]);
		rc_grid_free(g);
	}
	if (o->field[GFMD_CONTACT] == NULL && r->t.png == NULL)
		return;
	g = field_grid(&r->t, h, RC_KIND_MASK, r->last_p, r->last_p_star,
	    o->modulus, method_name, o->so.boundary);
	for (size_t k = 0; k < np; k++)
		g->z[k] = mask[k] != 0;
	if (o->field[GFMD_CONTACT] != NULL)
		tool_write_grid(&r->t, g, o->field[GFMD_CONTACT]);
	if (r->t.png != NULL) {
		rc_png_opts po;
		char caption[96];
		size_t n_c = 0;

		for (size_t k = 0; k < np; k++)
			n_c += mask[k] != 0;
		/* The last pressure's, as in its row (a_r = n_c/n_tot). */
		snprintf(caption, sizeof(caption), "p*=%.4g  a_r=%.4g",
		    r->last_p_star, (double)n_c / (double)np);
		rc_png_defaults(&po);
		po.overlay = g;
		po.caption = caption;
		if (rc_png_write(h, r->t.png, &po, &err) != 0)
			tool_fail_at(&r->t, r->t.png, err.msg);
	}
	rc_grid_free(g);
}

/* The exit status (1 if a pressure did not converge); the finished run's
 * checkpoint removed, everything freed. */
static int
finish(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_err err;
	int status = 0;

	if (r->nunconverged) {
		tool_warn(&r->t, "%zu of %zu pressures did not converge",
		    r->nunconverged, r->npressures);
		status = 1;
	}
	/* The run is complete: its checkpoint would only resume it again. */
	if (o->ck_path != NULL) {
		struct file_id now;

		if (file_id(o->ck_path, &now) &&
		    (same_file(&now, &r->ck_written) ||
		    same_file(&now, &r->ck_found)) &&
		    rc_atomic_remove(o->ck_path, &err) != 0)
			tool_warn(&r->t, "%s", err.msg);
	}
	if (o->ck_path != NULL || o->resume_path != NULL)
		rc_checkpoint_free(&r->ck);
	if (o->resume_path != NULL)
		rc_checkpoint_free(&r->saved);
	rc_solver_free(r->solver);
	rc_grid_free(r->h);
	gfmd_opts_free(o);
	return tool_exit(&r->t, status);
}

int
main(int argc, char **argv)
{
	struct run r;

	memset(&r, 0, sizeof(r));
	if (parse_options(&r, argc, argv))
		return tool_exit(&r.t, 0);
	tool_fft_setup(&r.t);
	r.h = tool_read_input(&r.t, r.input);
	if (r.o.resume_path != NULL)
		resume_defaults(&r);
	checkpoint_setup(&r);
	indenter_setup(&r);
	solver_setup(&r);
	output_begin(&r);
	for (size_t k = r.first; k < r.npressures; k++) {
		rc_solve_result res;
		double p, p_star;

		solve_pressure(&r, k, &p, &p_star, &res);
		write_row(&r, p, p_star, &res);
		checkpoint_after(&r, k);
	}
	output_end(&r);
	write_fields(&r);
	return finish(&r);
}
