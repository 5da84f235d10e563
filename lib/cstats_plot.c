/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cstats_plot.c - the gnuplot script of contact-stats: kappa(p*) with
 * error bars, one curve per group, Persson's and BGT's values as lines;
 * written as a script, or run through gnuplot into a PNG.
 *
 * Every tick of the logarithmic p* axis is labelled: ticks at the
 * pressures of the data when there are at most MAX_DATA_TICKS of them (so
 * one pressure still gets one), else at 1, 2 and 5 times the powers of
 * ten in the range.  Curves take colours from a fixed list that leaves out
 * the red of Persson's line and the black of BGT's; the legend goes above
 * the plot, so long group labels cost height, not the plot's width. */
#include "cstats.h"

#include <errno.h>
#include <math.h>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "atomic.h"

#define MAX_DATA_TICKS 10

static const char *const curve_rgb[] = {
	"#1f77b4", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#17becf",
	"#e377c2", "#7f7f7f", "#bcbd22"
};
#define PERSSON_RGB "#d62728"
#define BGT_RGB "#000000"

static int
cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x > y) - (x < y);
}

/* The labelled ticks of the p* axis as a gnuplot "set xtics (...)". */
static int
write_xtics(FILE *fp, const rc_cstats *res, double pmin, double pmax,
    rc_err *err)
{
	double *p = malloc(res->nrows * sizeof(double));
	size_t n = 0;
	int first = 1;

	if (p == NULL)
		return rc_seterr(err, "out of memory");
	for (size_t i = 0; i < res->nrows; i++)
		if (res->point[i].p_star > 0 && isfinite(res->point[i].p_star))
			p[n++] = res->point[i].p_star;
	qsort(p, n, sizeof(double), cmp_double);
	/* distinct values: equal up to the 10 digits the data is written with */
	{
		size_t m = 0;
		for (size_t i = 0; i < n; i++)
			if (m == 0 || p[i] > p[m - 1] * (1 + 1e-10))
				p[m++] = p[i];
		n = m;
	}
	fputs("set xtics (", fp);
	if (n <= MAX_DATA_TICKS) {
		for (size_t i = 0; i < n; i++)
			fprintf(fp, "%s'%.4g' %.10g", i ? ", " : "", p[i], p[i]);
	} else {
		for (double d = pow(10, floor(log10(pmin))); d <= pmax; d *= 10)
			for (int k = 0; k < 3; k++) {
				double t = d * (k == 0 ? 1 : k == 1 ? 2 : 5);
				if (t < pmin || t > pmax)
					continue;
				fprintf(fp, "%s'%g' %.10g", first ? "" : ", ", t, t);
				first = 0;
			}
	}
	fputs(")\n", fp);
	free(p);
	return 0;
}

/* s as the inside of a gnuplot single-quoted string (a quote doubled). */
static void
put_quoted(FILE *fp, const char *s)
{
	for (; *s; s++) {
		if (*s == '\'')
			fputc('\'', fp);
		fputc(*s, fp);
	}
}

int
rc_cstats_gnuplot(FILE *fp, const rc_cstats *res, const char *script,
    const char *png, rc_err *err)
{
	double pmin = INFINITY, pmax = 0;

	for (const char *p = png ? png : ""; *p; p++)
		if ((unsigned char)*p < 0x20 || *p == 0x7f)
			return rc_seterr(err, "%s: a control character in the name",
			    png);
	if (res->nrows == 0)
		return rc_seterr(err, "no rows to plot");
	fprintf(fp, "# Written by contact-stats: kappa(p*) with error bars.\n"
	    "# Run: gnuplot %s\n"
	    "set terminal png size 900,650\n", script);
	if (png != NULL) {
		fputs("set output '", fp);
		put_quoted(fp, png);
		fputs("'\n", fp);
	}
	fprintf(fp, "set logscale x\n"
	    "set xlabel 'p*'\n"
	    "set ylabel 'kappa'\n"
	    "set key above horizontal samplen 2\n"
	    "set grid\n");
	for (size_t i = 0; i < res->nrows; i++) {
		pmin = fmin(pmin, res->point[i].p_star);
		pmax = fmax(pmax, res->point[i].p_star);
	}
	/* reference lines across the whole range, a margin around the data */
	fprintf(fp, "set xrange [%.6g:%.6g]\n", pmin / 1.5, pmax * 1.5);
	if (write_xtics(fp, res, pmin / 1.5, pmax * 1.5, err) != 0)
		return -1;
	for (size_t k = 0, i = 0; k < res->ncurves; k++) {
		fprintf(fp, "$curve%zu << EOD\n# p_star kappa kappa_err\n", k);
		for (; i < res->nrows && res->point[i].curve == k; i++) {
			const rc_cstats_point *p = &res->point[i];
			if (isfinite(p->kappa) && isfinite(p->kappa_err))
				fprintf(fp, "%.10g %.10g %.10g\n", p->p_star, p->kappa,
				    p->kappa_err);
		}
		fprintf(fp, "EOD\n");
	}
	fprintf(fp, "plot \\\n");
	for (size_t k = 0; k < res->ncurves; k++)
		fprintf(fp, "  $curve%zu using 1:2:3 with yerrorlines lw 2 lc rgb '%s' "
		    "title '%s', \\\n", k,
		    curve_rgb[k % (sizeof(curve_rgb) / sizeof(curve_rgb[0]))],
		    res->label[k]);
	fprintf(fp, "  sqrt(8/pi) with lines lw 2 dashtype 2 lc rgb '%s' "
	    "title 'Persson sqrt(8/pi) = 1.596', \\\n"
	    "  sqrt(2*pi) with lines lw 2 dashtype 3 lc rgb '%s' "
	    "title 'BGT sqrt(2 pi) = 2.507'\n", PERSSON_RGB, BGT_RGB);
	if (ferror(fp))
		return rc_seterr(err, "writing the gnuplot script: %s",
		    strerror(errno));
	return 0;
}

int
rc_cstats_gnuplot_write(const rc_cstats *res, const char *path, rc_err *err)
{
	const char *slash = strrchr(path, '/'), *base = slash ? slash + 1 : path;
	const char *dot = strrchr(base, '.');
	size_t stem = dot && dot > base ? (size_t)(dot - path) : strlen(path);
	char *png = malloc(stem + 10);
	rc_atomic out;
	int rc = -1;

	if (png == NULL)
		return rc_seterr(err, "out of memory");
	if (rc_is_stdio(path))
		strcpy(png, "kappa.png");
	else
		snprintf(png, stem + 10, "%.*s.png", (int)stem, path);
	if (rc_atomic_open(&out, path, err) == 0) {
		if (rc_cstats_gnuplot(out.fp, res, rc_is_stdio(path) ? "-" : path,
		    png, err) != 0)
			rc_atomic_abort(&out);
		else
			rc = rc_atomic_commit(&out, err);
	}
	free(png);
	return rc;
}

/* Remove a temporary file of ours; until then a signal handler removes
 * it (rc_atomic_track). */
static void
drop(const char *tmp)
{
	unlink(tmp);
	rc_atomic_untrack(tmp);
}

/* An empty temporary file named like script with ".png" added, tracked. */
static char *
temp_beside_script(const char *script, rc_err *err)
{
	size_t len = strlen(script) + 16;
	char *name = malloc(len);
	int fd;

	if (name == NULL) {
		rc_seterr(err, "out of memory");
		return NULL;
	}
	snprintf(name, len, "%s.png.XXXXXX", script);
	if ((fd = mkstemp(name)) < 0) {
		rc_seterr(err, "temporary file %s: %s", name, strerror(errno));
		free(name);
		return NULL;
	}
	rc_atomic_track(name);
	close(fd);
	return name;
}

/* 1 if the file at path is a whole PNG: the signature first and the
 * IEND chunk (length 0, type, CRC) last.  gnuplot exits 0 when its
 * writes fail (a full disk left 0 bytes or a truncated image), so its
 * status alone does not tell whether the picture was written. */
static int
png_complete(const char *path)
{
	static const unsigned char sig[8] = { 0x89, 'P', 'N', 'G', '\r',
		'\n', 0x1a, '\n' };
	static const unsigned char iend[12] = { 0, 0, 0, 0, 'I', 'E', 'N',
		'D', 0xae, 0x42, 0x60, 0x82 };
	unsigned char head[8], tail[12];
	FILE *in = fopen(path, "rb");
	int ok;

	if (in == NULL)
		return 0;
	ok = fread(head, 1, sizeof(head), in) == sizeof(head) &&
	    memcmp(head, sig, sizeof(sig)) == 0 &&
	    fseek(in, -(long)sizeof(tail), SEEK_END) == 0 &&
	    fread(tail, 1, sizeof(tail), in) == sizeof(tail) &&
	    memcmp(tail, iend, sizeof(iend)) == 0;
	fclose(in);
	return ok;
}

/* Append the file at path to out; an errno value or 0. */
static int
copy_file(const char *path, FILE *out)
{
	char buf[65536];
	FILE *in = fopen(path, "rb");
	size_t n;
	int rc = 0;

	if (in == NULL)
		return errno;
	while ((n = fread(buf, 1, sizeof(buf), in)) > 0)
		if (fwrite(buf, 1, n, out) != n) {
			rc = errno ? errno : EIO;
			break;
		}
	if (ferror(in) && rc == 0)
		rc = EIO;
	fclose(in);
	return rc;
}

/* Start argv[0] from PATH as a child that dies with this process (issue
 * 27: a gnuplot of a killed contact-stats ran on): PR_SET_PDEATHSIG
 * sends it SIGKILL when we end, by any signal; set before exec, checked
 * against a parent already gone.  0 and *pid, or an errno value (ENOENT:
 * not found), passed back from the child through a close-on-exec pipe. */
static int
spawn_tied(char *const argv[], pid_t *pid)
{
	pid_t parent = getpid();
	int fds[2], e = 0;
	ssize_t n;

	if (pipe(fds) != 0)
		return errno;
	if (fcntl(fds[1], F_SETFD, FD_CLOEXEC) != 0 || (*pid = fork()) < 0) {
		e = errno;
		close(fds[0]);
		close(fds[1]);
		return e;
	}
	if (*pid == 0) {
		close(fds[0]);
		if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent)
			_exit(127);
		execvp(argv[0], argv);
		e = errno;
		if (write(fds[1], &e, sizeof(e)) < 0)
			_exit(127);
		_exit(127);
	}
	close(fds[1]);
	while ((n = read(fds[0], &e, sizeof(e))) < 0 && errno == EINTR)
		;
	close(fds[0]);
	if (n == (ssize_t)sizeof(e)) {	/* exec failed */
		waitpid(*pid, NULL, 0);
		return e;
	}
	return 0;
}

/* The script goes to a temporary file; gnuplot writes the PNG to the
 * temporary name rc_atomic made beside path (which rc_atomic_commit then
 * fsyncs and renames), or, for standard output, to its own standard
 * output. */
int
rc_cstats_png_write(const rc_cstats *res, const char *path, rc_err *err)
{
	const char *dir = getenv("TMPDIR");
	char script[4096];
	char *argv[] = { "gnuplot", script, NULL };
	rc_atomic out;
	FILE *fp = NULL;
	char *png_tmp = NULL;
	pid_t pid = -1;
	int fd, st = 0, rc, gnuplot_ok, whole = 1;

	snprintf(script, sizeof(script), "%s/contact-stats.gp.XXXXXX",
	    dir && *dir ? dir : "/tmp");
	if ((fd = mkstemp(script)) < 0)
		return rc_seterr(err, "temporary script %s: %s", script,
		    strerror(errno));
	rc_atomic_track(script);
	if ((fp = fdopen(fd, "w")) == NULL) {
		rc_seterr(err, "temporary script %s: %s", script, strerror(errno));
		close(fd);
		drop(script);
		return -1;
	}
	if (rc_atomic_open(&out, path, err) != 0) {
		fclose(fp);
		drop(script);
		return -1;
	}
	/* A device or FIFO target gets gnuplot's PNG through a temporary file,
	 * copied in by us so that write errors are ours to report. */
	if (out.direct && (png_tmp = temp_beside_script(script, err)) == NULL) {
		fclose(fp);
		drop(script);
		rc_atomic_abort(&out);
		return -1;
	}
	rc = rc_cstats_gnuplot(fp, res, script, png_tmp ? png_tmp : out.tmp,
	    err);
	if (fclose(fp) != 0 && rc == 0)
		rc = rc_seterr(err, "temporary script %s: %s", script,
		    strerror(errno));
	if (rc != 0) {
		drop(script);
		rc_atomic_abort(&out);
		return -1;
	}
	fflush(stdout);
	rc = spawn_tied(argv, &pid);
	while (rc == 0 && waitpid(pid, &st, 0) < 0)
		if (errno != EINTR)
			rc = errno;
	drop(script);
	if (rc == ENOENT) {
		if (png_tmp != NULL) {
			drop(png_tmp);
			free(png_tmp);
		}
		rc_atomic_abort(&out);
		return rc_seterr(err, "gnuplot not found; use --gnuplot FILE to get "
		    "the script");
	}
	gnuplot_ok = rc == 0 && WIFEXITED(st) && WEXITSTATUS(st) == 0;
	if (gnuplot_ok && !png_complete(png_tmp != NULL ? png_tmp : out.tmp))
		whole = 0;
	else if (gnuplot_ok && png_tmp != NULL)
		rc = copy_file(png_tmp, out.fp);
	if (png_tmp != NULL) {
		drop(png_tmp);
		free(png_tmp);
	}
	if (rc != 0 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
		rc_atomic_abort(&out);
		if (rc != 0)
			return rc_seterr(err, "running gnuplot: %s", strerror(rc));
		return rc_seterr(err, "%s: gnuplot failed (exit status %d)", path,
		    WIFEXITED(st) ? WEXITSTATUS(st) : -1);
	}
	if (!whole) {
		rc_atomic_abort(&out);
		return rc_seterr(err, "%s: gnuplot exited 0 but wrote no whole "
		    "PNG (a full disk?); nothing written", path);
	}
	return rc_atomic_commit(&out, err);
}
