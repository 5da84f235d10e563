/* common.c - shared tool plumbing (see common.h). */
#include "common.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic.h"
#include "fft.h"
#include "threads.h"

void
tool_init(struct tool *t, const char *name, int argc, char **argv)
{
	size_t len = 1;

	memset(t, 0, sizeof(*t));
	t->name = name;
	t->lx = t->ly = 1.0;
	t->fft_effort = -1;
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
tool_bad(struct tool *t, const char *fmt, ...)
{
	va_list ap;

	va_start(ap, fmt);
	vmsg(t, fmt, ap);
	va_end(ap);
	t->nbad++;
}

void
tool_usage_check(const struct tool *t)
{
	if (t->nbad == 0)
		return;
	fprintf(stderr, "%s: %d usage problem%s; see '%s --help'\n", t->name,
	    t->nbad, t->nbad == 1 ? "" : "s", t->name);
	exit(2);
}

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
	case OPT_VERSION:
		printf("%s %s\n", t->name, RC_VERSION);
		exit(tool_exit(t, 0));
	case OPT_WISDOM:
		if (arg[0] == '\0' || rc_is_stdio(arg))
			tool_bad(t, "--wisdom %s: want a file name", arg);
		else
			t->wisdom = arg;
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

void
tool_fft_setup(struct tool *t)
{
	const char *env = getenv("RC_WISDOM");
	rc_err err;

	rc_threads_wait_passively(rc_fft_set_threads(t->threads), t->argv);
	if (t->wisdom == NULL && env != NULL && env[0] != '\0')
		t->wisdom = env;
	if (t->wisdom != NULL && rc_fft_wisdom_import(t->wisdom, &err) < 0)
		tool_fail(t, "%s: %s", t->wisdom, err.msg);
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

rc_grid *
tool_read_grid(const struct tool *t, const char *path)
{
	rc_read_opts o;
	rc_err err;
	rc_grid *g;

	rc_read_opts_init(&o);
	o.lx = t->lx;
	o.ly = t->ly;
	o.have_l = t->have_l;

	if (rc_is_stdio(path) && isatty(STDIN_FILENO))
		tool_fail(t, "standard input: is a terminal; give a file or a pipe");
	g = rc_grid_read(path, &o, &err);
	if (g == NULL)
		tool_fail(t, "%s: %s", rc_is_stdio(path) ? "standard input" : path,
		    err.msg);
	return g;
}

void
tool_output(struct tool *t, const char *opt, const char *path, int binary)
{
	if (path == NULL || !rc_is_stdio(path))
		return;
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
		tool_bad(t, "%s %s: unknown extension; use .surf, .npy, .gsf or .txt",
		    opt, path);
}

void
tool_write_grid(const struct tool *t, rc_grid *g, const char *path)
{
	rc_err err;
	int fmt = rc_format_from_name(path);

	if (fmt < 0)
		tool_fail(t, "%s: unknown extension; use .surf, .npy, .gsf or .txt", path);
	if (rc_is_stdio(path) && fmt != RC_FMT_TXT && isatty(STDOUT_FILENO))
		tool_fail(t, "standard output is a terminal; refusing to write binary "
		    "data there (use -o FILE or a pipe)");
	if (rc_grid_history_add(g, t->cmdline, &err) != 0 ||
	    rc_grid_write(g, path, (enum rc_format)fmt, &err) != 0)
		tool_fail(t, "%s: %s", rc_is_stdio(path) ? "standard output" : path,
		    err.msg);
	/* The history line belongs to this output only. */
	free(g->history[--g->nhistory]);
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

void
tool_not_input(struct tool *t, const char *opt, const char *out, const char *in)
{
	struct stat so, si;

	if (out == NULL || in == NULL || rc_is_stdio(out) || rc_is_stdio(in))
		return;
	if (stat(out, &so) == 0 && stat(in, &si) == 0 && so.st_dev == si.st_dev &&
	    so.st_ino == si.st_ino)
		tool_bad(t, "%s %s: that is the input %s; refusing to replace it "
		    "with output of another kind", opt, out, in);
}
