/* SPDX-License-Identifier: GPL-3.0-or-later */
/* common.c - shared tool plumbing (see common.h). */
#include "common.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "atomic.h"
#include "fft.h"
#include "gridcheck.h"
#include "level.h"
#include "threads.h"
#include "units.h"

/* The program name for tool_on_signal, which may only write(2). */
static const char *signal_name = "";

static void
say(const char *s)
{
	ssize_t r = write(STDERR_FILENO, s, strlen(s));
	(void)r;
}

void
tool_on_signal(int sig)
{
	int saved = errno, n = rc_atomic_unlink_pending();

	say(signal_name);
	say(sig == SIGINT ? ": interrupted (SIGINT)" : sig == SIGTERM ?
	    ": terminated (SIGTERM)" : sig == SIGHUP ? ": hangup (SIGHUP)" :
	    ": killed by a signal");
	say(n > 0 ? "; unfinished output files removed\n" : "\n");
	errno = saved;
	signal(sig, SIG_DFL);
	raise(sig);
}

/* A standard descriptor left closed (2>&-) would be the next file opened,
 * and messages for stderr would land in that file, a result table
 * perhaps: each closed one is held by /dev/null, opened so that it fails
 * as the closed one did, except stderr (its messages just vanish). */
static void
hold_closed_stdio(void)
{
	static const int mode[3] = { O_WRONLY, O_RDONLY, O_WRONLY };

	for (int fd = 0; fd < 3; fd++)
		if (fcntl(fd, F_GETFD) < 0 && errno == EBADF &&
		    open("/dev/null", mode[fd]) != fd)
			_exit(1);	/* nowhere safe to write: no message */
}

void
tool_init(struct tool *t, const char *name, int argc, char **argv)
{
	static const int sigs[] = { SIGINT, SIGTERM, SIGHUP };
	size_t len = 1;

	hold_closed_stdio();
	signal_name = name;
	for (size_t k = 0; k < sizeof(sigs) / sizeof(sigs[0]); k++) {
		struct sigaction sa, old;

		memset(&sa, 0, sizeof(sa));
		sa.sa_handler = tool_on_signal;
		sigemptyset(&sa.sa_mask);
		if (sigaction(sigs[k], NULL, &old) == 0 && old.sa_handler != SIG_IGN)
			sigaction(sigs[k], &sa, NULL);
	}
	memset(t, 0, sizeof(*t));
	t->name = name;
	t->lx = t->ly = 1.0;
	t->fft_effort = -1;
	t->pretty_on_terminal = 1;
	for (int i = 0; i < argc; i++)
		len += strlen(argv[i]) + 3;
	if ((t->cmdline = malloc(len)) == NULL ||
	    (t->argv = malloc((size_t)(argc + 1) * sizeof(*t->argv))) == NULL)
		tool_fail(t, "out of memory");
	memcpy(t->argv, argv, (size_t)(argc + 1) * sizeof(*t->argv));
	t->cmdline[0] = '\0';
	for (int i = 0; i < argc; i++) {
		const char *a = i == 0 ? name : argv[i];
		int quote = strpbrk(a, " \t'\"") != NULL;
		if (i)
			strcat(t->cmdline, " ");
		if (quote)
			strcat(t->cmdline, "'");
		strcat(t->cmdline, a);
		if (quote)
			strcat(t->cmdline, "'");
	}
}

static void
vmsg(const struct tool *t, const char *fmt, va_list ap)
{
	fprintf(stderr, "%s: ", t->name);
	vfprintf(stderr, fmt, ap);
	fputc('\n', stderr);
}

void
tool_warn(const struct tool *t, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmsg(t, fmt, ap);
	va_end(ap);
}

void
tool_fail(const struct tool *t, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmsg(t, fmt, ap);
	va_end(ap);
	exit(1);
}

void
tool_fail_at(const struct tool *t, const char *what, const char *why)
{
	size_t n;

	if (what == NULL)	/* an output left to standard output */
		what = "standard output";
	n = strlen(what);
	if (strncmp(why, what, n) == 0 && strncmp(why + n, ": ", 2) == 0)
		tool_fail(t, "%s", why);
	tool_fail(t, "%s: %s", what, why);
}

void
tool_bad(struct tool *t, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmsg(t, fmt, ap);
	va_end(ap);
	t->nbad++;
}

void
tool_bad_option(struct tool *t, const char *optstring,
    const struct option *longopts, char **argv)
{
	/* getopt_long leaves optind past a long option, but inside a group
	 * of short ones ("-qx") it may still point at the group: a long
	 * option is recognised by its name matching the option code. */
	const char *arg = optind > 0 ? argv[optind - 1] : NULL;
	const struct option *lo = NULL;
	size_t len = 0;

	if (arg != NULL && strncmp(arg, "--", 2) == 0 && arg[2] != '\0') {
		len = strcspn(arg + 2, "=");
		if (optopt == 0) {
			char names[256] = "";
			int nmatch = 0;
			/* an abbreviation of several: name them */
			for (lo = longopts; lo != NULL && lo->name != NULL; lo++)
				if (len > 0 && strncmp(lo->name, arg + 2, len) == 0 &&
				    nmatch++ < 4) {
					size_t used = strlen(names);
					snprintf(names + used, sizeof(names) - used, "%s--%s",
					    used ? ", " : "", lo->name);
				}
			if (nmatch > 1)
				tool_bad(t, "--%.*s: ambiguous: %s%s", (int)len, arg + 2,
				    names, nmatch > 4 ? ", ..." : "");
			else
				tool_bad(t, "--%.*s: unknown option", (int)len, arg + 2);
			return;
		}
		for (lo = longopts; lo != NULL && lo->name != NULL; lo++)
			if (lo->flag == NULL && lo->val == optopt &&
			    strncmp(lo->name, arg + 2, len) == 0)
				break;
	}
	if (lo != NULL && lo->name != NULL) {
		if (lo->has_arg == no_argument)
			tool_bad(t, "--%s: takes no value (given '%s')", lo->name,
			    arg[2 + len] == '=' ? arg + 3 + len : "");
		else
			tool_bad(t, "--%s: needs a value", lo->name);
	} else if (optopt > 0 && optopt < 128 && isgraph(optopt) &&
	    optopt != ':' && strchr(optstring, optopt) != NULL)
		tool_bad(t, "-%c: needs a value", optopt);
	else if (optopt > 0 && optopt < 128 && isgraph(optopt))
		tool_bad(t, "-%c: unknown option", optopt);
	else
		tool_bad(t, "%s: unknown option", arg != NULL ? arg : "?");
}

/* What identifies a file: device and inode of an existing one, else of
 * its directory plus its name.  0 if it cannot clash (standard input that
 * is not a regular file, a device, a FIFO, a missing directory). */
struct file_id {
	dev_t dev;
	ino_t ino;
	const char *base;	/* NULL for an existing file */
};

static int
file_id(const char *path, struct file_id *id)
{
	struct stat st;
	const char *slash;

	id->base = NULL;
	if (path == NULL) {
		if (fstat(STDIN_FILENO, &st) != 0 || !S_ISREG(st.st_mode))
			return 0;
	} else if (stat(path, &st) == 0) {
		if (!S_ISREG(st.st_mode))
			return 0;
	} else {
		char *dir;
		int ok;

		if ((slash = strrchr(path, '/')) == NULL) {
			ok = stat(".", &st) == 0;
			id->base = path;
		} else {
			if ((dir = strdup(path)) == NULL)
				return 0;
			dir[slash - path + (slash == path)] = '\0';
			ok = stat(dir, &st) == 0;
			free(dir);
			id->base = slash + 1;
		}
		if (!ok || *id->base == '\0')
			return 0;
	}
	id->dev = st.st_dev;
	id->ino = st.st_ino;
	return 1;
}

static int
same_file(const struct file_id *a, const struct file_id *b)
{
	if (a->dev != b->dev || a->ino != b->ino || (a->base == NULL) !=
	    (b->base == NULL))
		return 0;
	return a->base == NULL || strcmp(a->base, b->base) == 0;
}

static int
may_replace(const struct tool *t, const char *out_opt, const char *in_opt)
{
	for (size_t k = 0; k < t->nmay_replace; k++)
		if (strcmp(t->may_replace[k][0], out_opt) == 0 &&
		    strcmp(t->may_replace[k][1], in_opt) == 0)
			return 1;
	return 0;
}


/* Every output against every other declared file. */
static void
check_files(struct tool *t)
{
	struct file_id *ids = calloc(t->nfiles ? t->nfiles : 1, sizeof(*ids));
	int *ok = calloc(t->nfiles ? t->nfiles : 1, sizeof(*ok));

	if (ids == NULL || ok == NULL)
		tool_fail(t, "out of memory");
	for (size_t i = 0; i < t->nfiles; i++)
		ok[i] = file_id(t->files[i].path, &ids[i]);
	for (size_t i = 0; i < t->nfiles; i++) {
		const struct tool_file *a = &t->files[i];

		if (!a->output || !ok[i])
			continue;
		for (size_t j = 0; j < t->nfiles; j++) {
			const struct tool_file *b = &t->files[j];

			if (j == i || !ok[j] || (b->output && j < i) ||
			    !same_file(&ids[i], &ids[j]))
				continue;
			if (b->output)
				tool_bad(t, "%s %s and %s %s: the same file; one output "
				    "would be lost", b->opt, b->path, a->opt, a->path);
			else if (!may_replace(t, a->opt, b->opt))
				tool_bad(t, "%s %s: the same file as %s%s%s; refusing to "
				    "replace an input", a->opt, a->path, b->path ? b->opt :
				    "standard input", b->path ? " " : "", b->path ?
				    b->path : "");
		}
	}
	free(ids);
	free(ok);
	free(t->files);
	t->files = NULL;
	t->nfiles = 0;
	free(t->may_replace);
	t->may_replace = NULL;
	t->nmay_replace = 0;
}

static void
add_file(struct tool *t, const char *opt, const char *path, int output)
{
	struct tool_file *f = realloc(t->files, (t->nfiles + 1) * sizeof(*f));

	if (f == NULL)
		tool_fail(t, "out of memory");
	t->files = f;
	f[t->nfiles].opt = opt;
	f[t->nfiles].path = path;
	f[t->nfiles].output = output;
	t->nfiles++;
}

void
tool_input(struct tool *t, const char *opt, const char *path)
{
	add_file(t, opt, rc_is_stdio(path) ? NULL : path, 0);
}

void
tool_may_replace(struct tool *t, const char *out_opt, const char *in_opt)
{
	const char *(*p)[2] = realloc(t->may_replace,
	    (t->nmay_replace + 1) * sizeof(*p));

	if (p == NULL)
		tool_fail(t, "out of memory");
	t->may_replace = p;
	p[t->nmay_replace][0] = out_opt;
	p[t->nmay_replace][1] = in_opt;
	t->nmay_replace++;
}

int
tool_help_check(struct tool *t)
{
	if (t->nbad == 0)
		return 1;
	fprintf(stderr, "%s: %d usage problem%s; see '%s --help'\n", t->name,
	    t->nbad, t->nbad == 1 ? "" : "s", t->name);
	exit(2);
}

void
tool_usage_check(struct tool *t)
{
	/* --wisdom is read and rewritten: an output like any other. */
	if (t->wisdom != NULL)
		add_file(t, "--wisdom", t->wisdom, 1);
	check_files(t);
	if (t->nbad == 0)
		return;
	fprintf(stderr, "%s: %d usage problem%s; see '%s --help'\n", t->name,
	    t->nbad, t->nbad == 1 ? "" : "s", t->name);
	exit(2);
}

/* Long: one case per option, each a few lines; they are read together. */
int
tool_common_option(struct tool *t, int opt, const char *arg)
{
	long n;

	switch (opt) {
	case 'o':
		t->out = arg;
		return 1;
	case 'q':
		t->quiet = 1;
		return 1;
	case 'j':
		if (tool_long(t, "-j", arg, &n) == 0) {
			if (n < 1 || n > 4096)
				tool_bad(t, "-j %s: threads must be 1 to 4096", arg);
			else
				t->threads = (int)n;
#ifdef _OPENMP
			/* More threads than cores only contend (-j 4096 made a
			 * 64^2 solve take 38 s): clamped, with a note. */
			if (t->threads > omp_get_num_procs()) {
				t->threads = omp_get_num_procs();
				/* said once: not again after the re-execution
				 * for passive waiting (threads.h) */
				if (getenv(RC_THREADS_REEXEC_ENV) == NULL)
					tool_warn(t, "-j %s: more threads than the "
					    "%d core%s available; using %d", arg,
					    t->threads, t->threads == 1 ? "" : "s",
					    t->threads);
			}
#endif
		}
		return 1;
	case 'L':
		if (tool_length_pair(t, "-L", arg, &t->lx, &t->ly) == 0)
			t->have_l = 1;
		return 1;
	case OPT_JSON:
		t->json = 1;
		return 1;
	case OPT_PNG:
		t->png = arg;
		return 1;
	case OPT_PRETTY:
		t->pretty = 1;
		return 1;
	case OPT_VERSION:
		printf("%s %s\n", t->name, RC_VERSION);
		exit(tool_exit(t, 0));
	case OPT_UNIT:
	case OPT_Z_UNIT:
		if (!rc_unit_is_length(arg))
			tool_bad(t, "%s %s: want a length unit: m, mm, um, nm, pm or "
			    "angstrom", opt == OPT_UNIT ? "--unit" : "--z-unit", arg);
		else
			*(opt == OPT_UNIT ? &t->unit : &t->z_unit) = arg;
		return 1;
	case OPT_PERIODIC:
	case OPT_NO_PERIODIC:
		if (t->periodic != RC_PERIODIC_AUTO)
			tool_bad(t, "--periodic, --no-periodic: give one of them, once");
		t->periodic = opt == OPT_PERIODIC ? RC_PERIODIC_YES : RC_PERIODIC_NO;
		return 1;
	case OPT_NPY_ORDER:
		if (strcmp(arg, "xy") != 0 && strcmp(arg, "yx") != 0)
			tool_bad(t, "--npy-order %s: want yx (shape (ny, nx), the "
			    "default) or xy (shape (nx, ny))", arg);
		t->npy_xy = strcmp(arg, "xy") == 0;
		return 1;
	case OPT_UNIFORM:
		t->uniform = 1;
		return 1;
	case OPT_WISDOM:
		if (arg[0] == '\0' || rc_is_stdio(arg))
			tool_bad(t, "--wisdom %s: want a file name", arg);
		else
			t->wisdom = arg;
		return 1;
	case OPT_CHANNEL:
		if (arg[0] == '\0')
			tool_bad(t, "--channel: want a number or a title");
		else if (strspn(arg, "0123456789") == strlen(arg) &&
		    (strlen(arg) > 6 || atoi(arg) < 1))
			tool_bad(t, "--channel %s: channels count from 1", arg);
		else
			t->channel = arg;
		return 1;
	case OPT_FFT_EFFORT:
		if ((n = rc_fft_effort_parse(arg)) < 0 || n == RC_FFT_WISDOM)
			tool_bad(t, "--fft-effort %s: want estimate, measure or patient",
			    arg);
		else
			t->fft_effort = (int)n;
		return 1;
	}
	return 0;
}

/* OpenMP's threads are made here, with the termination signals blocked,
 * so that those signals always run their handler on the main thread.  A
 * worker may otherwise take one (the kernel hands a signal that comes
 * while the process is stopped to whichever thread runs first after
 * SIGCONT), and the main thread then exits before the handler has removed
 * the temporaries and raised the signal again: seen as exit 1 instead of
 * 143 in tests/e2e/outputs.sh, about one run in seven. */
static void
start_threads_deaf(void)
{
	sigset_t set, old;
	volatile int team = 0;

	sigemptyset(&set);
	sigaddset(&set, SIGINT);
	sigaddset(&set, SIGTERM);
	sigaddset(&set, SIGHUP);
	pthread_sigmask(SIG_BLOCK, &set, &old);
#pragma omp parallel
	team = 1;
	(void)team;
	pthread_sigmask(SIG_SETMASK, &old, NULL);
}

void
tool_threads_setup(struct tool *t)
{
	rc_threads_wait_passively(rc_fft_thread_count(t->threads), t->argv);
	rc_fft_set_threads(t->threads);
	unsetenv(RC_THREADS_REEXEC_ENV);	/* not for the programs we run */
}

void
tool_fft_setup(struct tool *t)
{
	const char *env = getenv("RC_WISDOM");
	rc_err err;

	tool_threads_setup(t);
	start_threads_deaf();
	if (t->wisdom == NULL && env != NULL && env[0] != '\0')
		t->wisdom = env;
	if (t->wisdom != NULL && rc_fft_wisdom_import(t->wisdom, &err) < 0)
		tool_fail_at(t, t->wisdom, err.msg);
}

enum rc_fft_effort
tool_fft_effort(struct tool *t, size_t nx, size_t ny, double pairs)
{
	enum rc_fft_effort e;

	if (t->fft_effort >= 0)
		e = (enum rc_fft_effort)t->fft_effort;
	else if ((e = rc_fft_effort_auto(nx, ny, pairs)) == RC_FFT_WISDOM &&
	    t->wisdom != NULL)
		e = RC_FFT_MEASURE;
	else if (e == RC_FFT_MEASURE)	/* the policy's: planning bounded */
		rc_fft_set_plan_limit(rc_fft_plan_limit(nx, ny, pairs));
	if (e == RC_FFT_MEASURE || e == RC_FFT_PATIENT)
		t->fft_measured = 1;
	return e;
}

void
tool_fft_finish(const struct tool *t)
{
	rc_err err;

	if (t->wisdom != NULL && t->fft_measured &&
	    rc_fft_wisdom_export(t->wisdom, &err) != 0)
		tool_warn(t, "%s: wisdom not saved: %s", t->wisdom, err.msg);
}

int
tool_double(struct tool *t, const char *opt, const char *arg, double *v)
{
	char *end;
	double d;

	errno = 0;
	d = strtod(arg, &end);
	if (end == arg || *end != '\0' || !isfinite(d) || errno == ERANGE) {
		tool_bad(t, "%s %s: not a finite number", opt, arg);
		return -1;
	}
	*v = d;
	return 0;
}

int
tool_long(struct tool *t, const char *opt, const char *arg, long *v)
{
	char *end;
	long n;

	errno = 0;
	n = strtol(arg, &end, 10);
	if (end == arg || *end != '\0' || errno == ERANGE) {
		tool_bad(t, "%s %s: not an integer", opt, arg);
		return -1;
	}
	*v = n;
	return 0;
}

int
tool_size_pair(struct tool *t, const char *opt, const char *arg, size_t *nx,
    size_t *ny)
{
	char *end, *end2;
	long a, b;

	errno = 0;
	a = strtol(arg, &end, 10);
	b = a;
	if (end != arg && *end == 'x') {
		b = strtol(end + 1, &end2, 10);
		if (end2 == end + 1)
			b = 0;
		end = end2;
	}
	if (end == arg || *end != '\0' || errno == ERANGE || a < 1 || b < 1 ||
	    a > (long)RC_GRID_MAX_DIM || b > (long)RC_GRID_MAX_DIM) {
		tool_bad(t, "%s %s: want NX or NXxNY, positive integers up to %u",
		    opt, arg, RC_GRID_MAX_DIM);
		return -1;
	}
	*nx = (size_t)a;
	*ny = (size_t)b;
	return 0;
}

int
tool_length_pair(struct tool *t, const char *opt, const char *arg, double *lx,
    double *ly)
{
	char *end, *end2;
	double a, b;

	a = strtod(arg, &end);
	b = a;
	if (end != arg && *end == 'x') {
		b = strtod(end + 1, &end2);
		if (end2 == end + 1)
			b = -1;
		end = end2;
	}
	if (end == arg || *end != '\0' || !(a > 0) || !(b > 0) ||
	    !isfinite(a) || !isfinite(b)) {
		tool_bad(t, "%s %s: want L or LXxLY, positive finite lengths", opt, arg);
		return -1;
	}
	*lx = a;
	*ly = b;
	return 0;
}

int
tool_double_list(struct tool *t, const char *opt, const char *arg, double **v,
    size_t *n)
{
	size_t cap = 1;
	const char *p;
	char *end;

	for (p = arg; *p; p++)
		cap += *p == ',';
	if ((*v = malloc(cap * sizeof(**v))) == NULL)
		tool_fail(t, "out of memory");
	*n = 0;
	p = arg;
	for (;;) {
		double d = strtod(p, &end);
		if (end == p || (*end != ',' && *end != '\0') || !isfinite(d)) {
			tool_bad(t, "%s %s: want a comma-separated list of finite numbers",
			    opt, arg);
			free(*v);
			*v = NULL;
			*n = 0;
			return -1;
		}
		(*v)[(*n)++] = d;
		if (*end == '\0')
			return 0;
		p = end + 1;
	}
}

static rc_grid *
read_grid(const struct tool *t, const char *path, const char *channel)
{
	rc_read_opts o;
	rc_err err;
	rc_grid *g;

	rc_read_opts_init(&o);
	o.lx = t->lx;
	o.ly = t->ly;
	o.have_l = t->have_l;
	o.unit = t->unit;
	o.z_unit = t->z_unit;
	o.periodic = (enum rc_periodic_opt)t->periodic;
	o.npy_xy = t->npy_xy;
	o.uniform = t->uniform;
	o.nonuniform = t->nonuniform;
	if (channel != NULL && strspn(channel, "0123456789") == strlen(channel))
		o.channel = atoi(channel);
	else
		o.channel_name = channel;

	if (rc_is_stdio(path) && isatty(STDIN_FILENO))
		tool_fail(t, "standard input: is a terminal; give a file or a pipe");
	g = rc_grid_read(path, &o, &err);
	if (g == NULL)
		tool_fail_at(t, rc_is_stdio(path) ? "standard input" : path,
		    err.msg);
	/* a tool that reads line scans not uniformly spaced as they are
	 * (t->nonuniform) takes their missing points too */
	if (g->valid != NULL && !t->accept_missing && g->x == NULL) {
		size_t missing = rc_grid_missing_count(g), n = rc_grid_size(g);

		rc_grid_free(g);	/* not leaked on the way out (issue 27) */
		tool_fail(t, "%s: %zu of %zu points are missing (NaN); %s needs "
		    "every point: fill them first with surfwarp --fill",
		    rc_is_stdio(path) ? "standard input" : path, missing, n,
		    t->name);
	}
	/* -L sizes formats that carry none; a file's own size wins, which
	 * the user is told (issue 27: ignored without a word). */
	if (t->have_l && (g->lx != t->lx || g->ly != t->ly))
		tool_warn(t, "%s: -L %g,%g ignored: the file gives its size, "
		    "%g x %g%s%s (-L sizes only a format that carries none)",
		    rc_is_stdio(path) ? "standard input" : path, t->lx, t->ly,
		    g->lx, g->ly, g->unit[0] ? " " : "", g->unit);
	tool_grid_to_unit(t, g, path, t->unit);
	return g;
}

rc_grid *
tool_read_grid(const struct tool *t, const char *path)
{
	return read_grid(t, path, NULL);
}

rc_grid *
tool_read_input(const struct tool *t, const char *path)
{
	return read_grid(t, path, t->channel);
}

void
tool_list_channels(const struct tool *t, const char *path)
{
	rc_channel_info *c;
	rc_read_opts o;
	rc_err err;
	size_t n;

	rc_read_opts_init(&o);
	o.lx = t->lx;
	o.ly = t->ly;
	o.have_l = t->have_l;
	o.npy_xy = t->npy_xy;	/* nx, ny as the grid would be read */
	o.uniform = t->uniform;
	o.nonuniform = t->nonuniform;
	if (rc_grid_list_channels(path, &o, &c, &n, &err) != 0)
		tool_fail(t, "%s: %s", rc_is_stdio(path) ? "standard input" : path,
		    err.msg);
	printf("channel\ttitle\tnx\tny\tlx\tly\tunit\tz_unit\tmask\n");
	for (size_t k = 0; k < n; k++) {
		char lx[32], ly[32];

		/* Titles are the file's: tabs and newlines would break the table. */
		for (char *p = c[k].title; *p; p++)
			if ((unsigned char)*p < 0x20)
				*p = ' ';
		rc_format_double(lx, sizeof(lx), c[k].lx);
		rc_format_double(ly, sizeof(ly), c[k].ly);
		printf("%zu\t%s\t%zu\t%zu\t%s\t%s\t%s\t%s\t%s\n", k + 1,
		    c[k].title[0] ? c[k].title : "-", c[k].nx, c[k].ny, lx, ly,
		    c[k].unit[0] ? c[k].unit : "-",
		    c[k].z_unit[0] ? c[k].z_unit : "-", c[k].has_mask ? "yes" : "no");
	}
	free(c);
	exit(tool_exit(t, 0));
}

void
tool_grid_to_unit(const struct tool *t, rc_grid *g, const char *path,
    const char *unit)
{
	rc_err err;

	if (rc_grid_to_common_unit(g, unit, &err) != 0)
		tool_fail(t, "%s: %s", rc_is_stdio(path) ? "standard input" : path,
		    err.msg);
}

/* The wrap ratio of g levelled by a plane (as surfwarp --detrend plane
 * would); NAN if it cannot be computed. */
static double
levelled_wrap_ratio(const rc_grid *g)
{
	rc_err err;
	rc_grid *c = rc_grid_clone(g, 1, &err);
	double r = NAN;

	if (c != NULL && rc_detrend(c, RC_DETREND_PLANE, NULL, &err) == 0)
		r = rc_grid_wrap_ratio(c);
	rc_grid_free(c);
	return r;
}

void
tool_check_wrap(const struct tool *t, const rc_grid *g, const char *path,
    const char *use, const char *instead)
{
	const char *name = rc_is_stdio(path) ? "standard input" : path;
	double r = rc_grid_wrap_ratio(g), rl;
	char level[160];

	if (!(r > RC_WRAP_RATIO_WARN))
		return;
	/* Advise levelling only where it helps: a levelled measurement's
	 * edges still need not meet (a patch is not made periodic by any
	 * levelling). */
	rl = levelled_wrap_ratio(g);
	if (rl <= RC_WRAP_RATIO_WARN)
		snprintf(level, sizeof(level), "it is tilted: levelled "
		    "(surfwarp --detrend plane) the ratio is %.3g", rl);
	else
		snprintf(level, sizeof(level), "levelling does not help "
		    "(levelled by a plane, %.3g): its edges do not meet, as on "
		    "most measurements", rl);
	if (g->periodic)
		tool_warn(t, "%s: read as periodic (%s), but the step across its "
		    "edges is %.3g times the rms step inside (warning above %g); "
		    "%s. A measurement is not periodic: %s", name,
		    t->periodic == RC_PERIODIC_YES ? "--periodic" :
		    "the file's flag or its format's rule", r, RC_WRAP_RATIO_WARN,
		    level, t->periodic == RC_PERIODIC_YES ? "leave out --periodic" :
		    "say --no-periodic");
	else
		tool_warn(t, "%s: a patch (not periodic), but %s as one period, "
		    "and the step across its edges is %.3g times the rms step "
		    "inside (warning above %g); %s. %s", name, use, r,
		    RC_WRAP_RATIO_WARN, level, instead);
}

void
tool_output(struct tool *t, const char *opt, const char *path, int binary)
{
	rc_err err;

	if (path == NULL)
		return;
	if (!rc_is_stdio(path)) {
		if (rc_atomic_check(path, &err) != 0)
			tool_bad(t, "%s: %s", opt, err.msg);
		else
			add_file(t, opt, path, 1);
		return;
	}
	if (++t->nstdout == 2)
		tool_bad(t, "%s -: only one output may go to standard output", opt);
	else if (binary && isatty(STDOUT_FILENO))
		tool_bad(t, "%s -: standard output is a terminal; refusing to "
		    "write binary data there", opt);
}

void
tool_check_grid_path(struct tool *t, const char *opt, const char *path)
{
	if (path != NULL && rc_format_from_name(path) < 0)
		tool_bad(t, "%s %s: unknown extension; use .surf, .npy, .gsf, .txt, .x3p or .nc",
		    opt, path);
}

void
tool_write_grid(const struct tool *t, rc_grid *g, const char *path)
{
	rc_err err;
	int fmt = rc_format_from_name(path), keep;

	if (fmt < 0)
		tool_fail(t, "%s: unknown extension; use .surf, .npy, .gsf, .txt, .x3p or .nc", path);
	if (rc_is_stdio(path) && fmt != RC_FMT_TXT && isatty(STDOUT_FILENO))
		tool_fail(t, "standard output is a terminal; refusing to write binary "
		    "data there (use -o FILE or a pipe)");
	/* No NaN or infinity leaves a tool (but at missing points, which
	 * are NaN by convention): a result that overflowed is an error. */
	for (size_t k = 0; k < rc_grid_size(g); k++)
		if (!isfinite(g->z[k]) && (g->valid == NULL || g->valid[k]))
			tool_fail(t, "%s: the result's value at i=%zu, j=%zu is %s; "
			    "not written (the options overflow on this input)",
			    rc_is_stdio(path) ? "standard output" : path, k % g->nx,
			    k / g->nx, isnan(g->z[k]) ? "NaN" : "infinite");
	if (rc_grid_history_add(g, t->cmdline, &err) != 0 ||
	    rc_grid_write(g, path, (enum rc_format)fmt, &err) != 0)
		tool_fail_at(t, rc_is_stdio(path) ? "standard output" : path,
		    err.msg);
	/* The history line belongs to this output only. */
	free(g->history[--g->nhistory]);
	/* Which points were made up, not measured, is never dropped
	 * silently (surf(5) says which formats keep it). */
	if (!t->quiet && (keep = rc_format_keeps_filled(g, (enum rc_format)fmt,
	    &err)) <= 0) {
		if (keep < 0)
			tool_fail(t, "%s", err.msg);
		tool_warn(t, "%s: the %zu filled points are not marked (%s)",
		    rc_is_stdio(path) ? "standard output" : path,
		    rc_grid_filled_count(g), fmt == RC_FMT_SURF ||
		    fmt == RC_FMT_TXT || fmt == RC_FMT_GSF ? "their list is "
		    "longer than a header holds" : "only .surf, .txt and .gsf "
		    "files keep them");
	}
}

int
tool_exit(const struct tool *t, int status)
{
	if (fflush(stdout) != 0 || ferror(stdout)) {
		fprintf(stderr, "%s: standard output: %s\n", t->name, strerror(errno));
		status = status ? status : 1;
	}
	free(t->cmdline);
	free(t->argv);
	return status;
}

/* The terminal's width: TIOCGWINSZ, else $COLUMNS, else 0 (the default). */
static size_t
terminal_width(int fd)
{
	struct winsize ws;
	const char *env = getenv("COLUMNS");
	long n;

	if (ioctl(fd, TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0)
		return ws.ws_col;
	if (env != NULL && (n = strtol(env, NULL, 10)) > 0 && n < 100000)
		return (size_t)n;
	return 0;
}

void
tool_table_begin(const struct tool *t, rc_table_out *tab, FILE *fp)
{
	rc_err err;

	rc_table_begin(tab, fp, t->json);
	if (t->json || !(t->pretty || (t->pretty_on_terminal && isatty(fileno(fp)))))
		return;
	if (rc_table_pretty(tab, terminal_width(fileno(fp)), &err) != 0)
		tool_fail(t, "%s", err.msg);
}
