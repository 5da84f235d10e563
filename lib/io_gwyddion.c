/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_gwyddion.c - every other instrument format, through Gwyddion.
 *
 * Gwyddion reads some 150 vendor formats and converts any of them to its
 * native .gwy without a display: `gwyddion --convert-to-gwy=OUT.gwy FILE`.
 * We run it (posix_spawnp, no shell, its output discarded) in a private
 * temporary directory under $TMPDIR and read OUT.gwy.  The program is
 * $RC_GWYDDION if set (an empty value turns the conversion off), else
 * "gwyddion" from PATH.
 *
 * A file must not make us read another one.  Gwyddion reads only the file
 * it is given, except for formats whose data live elsewhere: some name
 * another file (NRRD's "data file", a frame's ExternalDataFileName, SPML's
 * data channels, an XML external entity) and are refused here by their
 * content; the others (Anfatec .txt + .int, Omicron .par + .tf*, MATRIX,
 * Unisoku .hdr + .dat, Hitachi and Tescan .hdr/.txt + image) look for a
 * companion of the same name next to the file, and find none because
 * Gwyddion is given a copy of the bytes alone in the private directory.
 * The conversion gets $RC_GWYDDION_TIMEOUT seconds (default 120), then
 * Gwyddion is killed; SIGINT, SIGTERM and SIGHUP during it kill Gwyddion,
 * remove the directory and then take their course.
 */
#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

#define INSTALL_HINT "install Gwyddion (Debian package gwyddion) to open " \
	"instrument formats"
#define TIMEOUT_DEFAULT 120.0

static int
write_all(int fd, const unsigned char *p, size_t n)
{
	while (n > 0) {
		ssize_t w = write(fd, p, n);

		if (w < 0) {
			if (errno == EINTR)
				continue;
			return -1;
		}
		p += w;
		n -= (size_t)w;
	}
	return 0;
}

/* Does the (case-insensitive) needle occur in the first n bytes? */
static int
has(const unsigned char *p, size_t n, const char *needle)
{
	size_t m = strlen(needle);

	for (size_t k = 0; k + m <= n; k++)
		if (strncasecmp((const char *)p + k, needle, m) == 0)
			return 1;
	return 0;
}

/* The name of a format whose data may be in another file than the one
 * given, or NULL: decided by content, from the header (the first 1 MiB). */
static const char *
detached_format(const unsigned char *p, size_t n)
{
	size_t h = n < RC_HEADER_MAX ? n : RC_HEADER_MAX;

	if (n >= 4 && memcmp(p, "NRRD", 4) == 0) {
		/* Any header line (up to the first empty one) whose key, blanks
		 * and case aside, is "datafile". */
		for (size_t k = 0; k < h; ) {
			size_t e = k, m = 0;
			char key[16];

			while (e < h && p[e] != '\n')
				e++;
			if (e == k || (e == k + 1 && p[k] == '\r'))
				break;
			for (size_t j = k; j < e && p[j] != ':' && m < sizeof(key) - 1;
			    j++)
				if (p[j] != ' ' && p[j] != '\t')
					key[m++] = (char)p[j];
			key[m] = '\0';
			if (strcasecmp(key, "datafile") == 0)
				return "NRRD with a detached data file ('data file:')";
			k = e + 1;
		}
		return NULL;
	}
	if (has(p, h, "ExternalDataFileName"))
		return "a frame whose data are in an external file "
		    "(ExternalDataFileName)";
	if (has(p, h, "<!ENTITY"))
		return "XML with entities (which may name other files)";
	if (has(p, h, "<?xml") && has(p, h, "<spml"))
		return "SPML (its data channels are other files)";
	return NULL;
}

/* Seconds the conversion may take: $RC_GWYDDION_TIMEOUT or the default. */
static double
timeout_seconds(void)
{
	const char *e = getenv("RC_GWYDDION_TIMEOUT");
	char *end;
	double t;

	if (e == NULL || e[0] == '\0')
		return TIMEOUT_DEFAULT;
	t = strtod(e, &end);
	return *end == '\0' && t > 0 && isfinite(t) ? t : TIMEOUT_DEFAULT;
}

static double
now(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Wait for the child pid (its own process group) until it ends, the time
 * limit passes or one of the signals in stop arrives (blocked by the
 * caller, taken here): 0 with *status, else the group is killed and
 * reaped and -1 returned with *sig the signal taken (0 on timeout). */
static int
wait_child(pid_t pid, const sigset_t *stop, double limit, int *status,
    int *sig)
{
	double end = now() + limit;
	pid_t w;

	*sig = 0;
	for (;;) {
		struct timespec slice = { 0, 20 * 1000 * 1000 };
		int got;

		while ((w = waitpid(pid, status, WNOHANG)) < 0 && errno == EINTR)
			;
		if (w == pid)
			return 0;
		if (w < 0)
			return -1;
		if (now() >= end)
			break;
		/* 20 ms slices: SIGCHLD may be ignored, so it is not waited for. */
		got = sigtimedwait(stop, NULL, &slice);
		if (got > 0) {
			*sig = got;
			break;
		}
	}
	kill(-pid, SIGKILL);
	while (waitpid(pid, status, 0) < 0 && errno == EINTR)
		;
	return -1;
}

/* Run prog --convert-to-gwy=out in; 0 when it succeeded, 1 when it ran
 * and failed, -1 (message set) when it could not run or was stopped (*sig
 * the signal that stopped it, else 0). */
static int
convert(const char *prog, const char *in, const char *out, const sigset_t *old,
    const sigset_t *stop, int *sig, rc_err *err)
{
	posix_spawn_file_actions_t fa;
	posix_spawnattr_t attr;
	char *arg = NULL, *argv[4];
	double limit = timeout_seconds();
	pid_t pid;
	int status, e;

	*sig = 0;
	if ((arg = rc_malloc(strlen(out) + 32, err)) == NULL)
		return -1;
	sprintf(arg, "--convert-to-gwy=%s", out);
	argv[0] = (char *)prog;
	argv[1] = arg;
	argv[2] = (char *)in;
	argv[3] = NULL;
	posix_spawn_file_actions_init(&fa);
	posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
	posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
	posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
	/* Its own process group (a timeout kills all it started), the
	 * caller's signal mask, the signals we block at their defaults. */
	posix_spawnattr_init(&attr);
	posix_spawnattr_setpgroup(&attr, 0);
	posix_spawnattr_setsigmask(&attr, old);
	posix_spawnattr_setsigdefault(&attr, stop);
	posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP |
	    POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
	e = posix_spawnp(&pid, prog, &fa, &attr, argv, environ);
	posix_spawnattr_destroy(&attr);
	posix_spawn_file_actions_destroy(&fa);
	free(arg);
	if (e != 0) {
		if (e == ENOENT)
			return rc_seterr(err, "'%s' is not installed: %s", prog,
			    INSTALL_HINT);
		return rc_seterr(err, "cannot run %s: %s", prog, strerror(e));
	}
	if (wait_child(pid, stop, limit, &status, sig) != 0) {
		if (*sig != 0)
			return rc_seterr(err, "stopped by signal %d", *sig);
		return rc_seterr(err, "%s took longer than %g s (RC_GWYDDION_TIMEOUT) "
		    "and was stopped", prog, limit);
	}
	if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
		return rc_seterr(err, "'%s' could not be run: %s", prog,
		    INSTALL_HINT);
	return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? 0 : 1;
}

static int
read_file(const char *path, unsigned char **buf, size_t *len, rc_err *err)
{
	FILE *fp = fopen(path, "rb");
	rc_in *in;
	int r;

	if (fp == NULL)
		return rc_seterr(err, "Gwyddion wrote no file: %s", strerror(errno));
	if ((in = rc_malloc(sizeof(*in), err)) == NULL) {
		fclose(fp);
		return -1;
	}
	rc__in_init(in, fp);
	r = rc__in_slurp(in, buf, len, err);
	free(in);
	fclose(fp);
	return r;
}

/* The extension of name (".nid"), letters and digits only, or "". */
static void
extension(const char *name, char ext[16])
{
	const char *base, *dot;
	size_t k = 0;

	ext[0] = '\0';
	if (name == NULL)
		return;
	base = strrchr(name, '/');
	base = base ? base + 1 : name;
	if ((dot = strrchr(base, '.')) == NULL || dot == base)
		return;
	ext[k++] = '.';
	for (const char *p = dot + 1; *p && k < 15; p++) {
		if (!((*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
		    (*p >= '0' && *p <= '9'))) {
			ext[0] = '\0';
			return;
		}
		ext[k++] = *p;
	}
	ext[k] = '\0';
	if (k == 1)
		ext[0] = '\0';
}

int
rc__gwyddion_read(const char *name, const unsigned char *data, size_t len,
    rc_chanset *s, rc_err *err)
{
	const char *prog = getenv("RC_GWYDDION"), *tmp = getenv("TMPDIR");
	const char *detached = detached_format(data, len);
	char *dir = NULL, *in = NULL, *out = NULL, ext[16];
	unsigned char *gwy = NULL;
	size_t gwylen, dl;
	static const int ends[] = { SIGINT, SIGTERM, SIGHUP };
	sigset_t stop, old;
	int fd, r = -1, made_in = 0, sig = 0;

	if (prog == NULL)
		prog = "gwyddion";
	if (prog[0] == '\0')
		return rc_seterr(err, "Gwyddion's converter is turned off "
		    "(RC_GWYDDION is empty)");
	if (detached != NULL)
		return rc_seterr(err, "not sent to Gwyddion: %s; only a file that "
		    "holds its own data is read", detached);
	if (tmp == NULL || tmp[0] == '\0')
		tmp = "/tmp";
	extension(name, ext);
	/* From the directory's making to its removal, the signals that end
	 * a tool wait (pending), so that the directory is always removed. */
	sigemptyset(&stop);
	for (size_t k = 0; k < sizeof(ends) / sizeof(ends[0]); k++) {
		struct sigaction sa;

		/* One the tool ignores (nohup) stays ignored. */
		if (sigaction(ends[k], NULL, &sa) == 0 && sa.sa_handler != SIG_IGN)
			sigaddset(&stop, ends[k]);
	}
	pthread_sigmask(SIG_BLOCK, &stop, &old);
	dl = strlen(tmp) + 32;
	if ((dir = rc_malloc(dl, err)) == NULL || (out = rc_malloc(dl + 16,
	    err)) == NULL || (in = rc_malloc(dl + 32, err)) == NULL)
		goto out;
	snprintf(dir, dl, "%s/rc-gwy.XXXXXX", tmp);
	if (mkdtemp(dir) == NULL) {
		rc_seterr(err, "cannot make a temporary directory in %s: %s", tmp,
		    strerror(errno));
		dir[0] = '\0';
		goto out;
	}
	sprintf(out, "%s/out.gwy", dir);
	/* The bytes alone in the directory: no companion file to find. */
	sprintf(in, "%s/input%s", dir, ext);
	if ((fd = open(in, O_WRONLY | O_CREAT | O_EXCL, 0600)) < 0) {
		rc_seterr(err, "cannot write %s: %s", in, strerror(errno));
		goto out;
	}
	made_in = 1;
	if (write_all(fd, data, len) != 0 || close(fd) != 0) {
		rc_seterr(err, "cannot write %s: %s", in, strerror(errno));
		goto out;
	}
	if ((r = convert(prog, in, out, &old, &stop, &sig, err)) != 0) {
		if (r > 0)
			rc_seterr(err, "Gwyddion does not read it either");
		r = -1;
		goto out;
	}
	r = -1;
	if (read_file(out, &gwy, &gwylen, err) != 0)
		goto out;
	r = rc__gwy_read(gwy, gwylen, s, err);
out:
	if (dir != NULL && dir[0] != '\0') {
		if (made_in)
			unlink(in);
		unlink(out);
		rmdir(dir);
	}
	free(gwy);
	free(in);
	free(out);
	free(dir);
	/* A signal taken while Gwyddion ran is raised again, now that the
	 * directory is gone: it ends the tool as it would have. */
	if (sig != 0)
		raise(sig);
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	return r;
}
