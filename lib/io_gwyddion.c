/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_gwyddion.c - every other instrument format, through Gwyddion.
 *
 * Gwyddion reads some 150 vendor formats and converts any of them to its
 * native .gwy without a display: `gwyddion --convert-to-gwy=OUT.gwy FILE`.
 * We run it (posix_spawnp, no shell, its output discarded) in a private
 * temporary directory under $TMPDIR and read OUT.gwy.  The program is
 * $RC_GWYDDION if set (an empty value turns the conversion off), else
 * "gwyddion" from PATH.
 */
#include "io_internal.h"

#include <errno.h>
#include <fcntl.h>
#include <spawn.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

#define INSTALL_HINT "install Gwyddion (Debian package gwyddion) to open " \
	"instrument formats"

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

/* Run prog --convert-to-gwy=out in; 0 when it succeeded, 1 when it ran
 * and failed, -1 (message set) when it could not run. */
static int
convert(const char *prog, const char *in, const char *out, rc_err *err)
{
	posix_spawn_file_actions_t fa;
	char *arg = NULL, *argv[4];
	pid_t pid;
	int status, e;

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
	e = posix_spawnp(&pid, prog, &fa, NULL, argv, environ);
	posix_spawn_file_actions_destroy(&fa);
	free(arg);
	if (e != 0) {
		if (e == ENOENT)
			return rc_seterr(err, "not a format roughcontact reads itself, "
			    "and '%s' is not installed: %s", prog, INSTALL_HINT);
		return rc_seterr(err, "cannot run %s: %s", prog, strerror(e));
	}
	while (waitpid(pid, &status, 0) < 0)
		if (errno != EINTR)
			return rc_seterr(err, "waiting for %s: %s", prog,
			    strerror(errno));
	if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
		return rc_seterr(err, "not a format roughcontact reads itself, "
		    "and '%s' could not be run: %s", prog, INSTALL_HINT);
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

int
rc__gwyddion_read(const char *path, const unsigned char *data, size_t len,
    rc_chanset *s, rc_err *err)
{
	const char *prog = getenv("RC_GWYDDION"), *tmp = getenv("TMPDIR");
	char *dir = NULL, *in = NULL, *out = NULL, *rel = NULL;
	unsigned char *gwy = NULL;
	size_t gwylen, dl;
	int fd, r = -1, made_in = 0;

	if (prog == NULL)
		prog = "gwyddion";
	if (prog[0] == '\0')
		return rc_seterr(err, "not a format roughcontact reads itself (and "
		    "RC_GWYDDION is empty, which turns Gwyddion off)");
	if (tmp == NULL || tmp[0] == '\0')
		tmp = "/tmp";
	dl = strlen(tmp) + 32;
	if ((dir = rc_malloc(dl, err)) == NULL || (out = rc_malloc(dl + 16,
	    err)) == NULL || (in = rc_malloc(dl + 16, err)) == NULL)
		goto out;
	snprintf(dir, dl, "%s/rc-gwy.XXXXXX", tmp);
	if (mkdtemp(dir) == NULL) {
		rc_seterr(err, "cannot make a temporary directory in %s: %s", tmp,
		    strerror(errno));
		dir[0] = '\0';
		goto out;
	}
	sprintf(out, "%s/out.gwy", dir);
	if (path == NULL) {
		/* Standard input: Gwyddion needs a file. */
		sprintf(in, "%s/input", dir);
		if ((fd = open(in, O_WRONLY | O_CREAT | O_EXCL, 0600)) < 0) {
			rc_seterr(err, "cannot write %s: %s", in, strerror(errno));
			goto out;
		}
		made_in = 1;
		if (write_all(fd, data, len) != 0 || close(fd) != 0) {
			rc_seterr(err, "cannot write %s: %s", in, strerror(errno));
			goto out;
		}
	} else if (path[0] != '/') {
		/* "./" so that a name starting with '-' is no option. */
		if ((rel = rc_malloc(strlen(path) + 3, err)) == NULL)
			goto out;
		sprintf(rel, "./%s", path);
	}
	if ((r = convert(prog, path == NULL ? in : rel ? rel : path, out, err))
	    != 0) {
		if (r > 0)
			rc_seterr(err, "not a format roughcontact or Gwyddion can read");
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
	free(rel);
	free(in);
	free(out);
	free(dir);
	return r;
}
