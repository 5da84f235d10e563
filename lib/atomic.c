/* atomic.c - temporary file + fsync + rename. */
#define _POSIX_C_SOURCE 200809L
#include "atomic.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int
rc_is_stdio(const char *path)
{
	return path == NULL || strcmp(path, "-") == 0;
}

int
rc_atomic_open(rc_atomic *a, const char *path, rc_err *err)
{
	const char *slash;
	size_t dirlen;
	struct stat st;
	mode_t mask;
	int fd;

	memset(a, 0, sizeof(*a));
	if (rc_is_stdio(path)) {
		a->fp = stdout;
		return 0;
	}
	if (stat(path, &st) == 0 && S_ISDIR(st.st_mode))
		return rc_seterr(err, "%s: is a directory", path);
	if ((a->path = strdup(path)) == NULL)
		return rc_seterr(err, "out of memory");
	slash = strrchr(path, '/');
	dirlen = slash ? (size_t)(slash - path) + 1 : 0;
	if ((a->tmp = malloc(strlen(path) + 16)) == NULL) {
		free(a->path);
		return rc_seterr(err, "out of memory");
	}
	memcpy(a->tmp, path, dirlen);
	sprintf(a->tmp + dirlen, ".%s.XXXXXX", path + dirlen);
	if ((fd = mkstemp(a->tmp)) < 0) {
		rc_seterr(err, "%s: cannot create a temporary file beside it: %s",
		    path, strerror(errno));
		free(a->tmp);
		free(a->path);
		memset(a, 0, sizeof(*a));
		return -1;
	}
	/* mkstemp makes 0600; give the file the mode a plain open would. */
	mask = umask(0);
	umask(mask);
	fchmod(fd, 0666 & ~mask);
	if ((a->fp = fdopen(fd, "wb")) == NULL) {
		close(fd);
		rc_atomic_abort(a);
		return rc_seterr(err, "%s: %s", path, strerror(errno));
	}
	return 0;
}

int
rc_atomic_commit(rc_atomic *a, rc_err *err)
{
	int bad;

	if (a->fp == NULL)
		return rc_seterr(err, "internal: commit of a closed file");
	if (a->tmp == NULL) {		/* stdout */
		bad = fflush(a->fp) != 0 || ferror(a->fp);
		a->fp = NULL;
		return bad ? rc_seterr(err, "standard output: %s", strerror(errno)) : 0;
	}
	bad = fflush(a->fp) != 0 || ferror(a->fp) || fsync(fileno(a->fp)) != 0;
	if (fclose(a->fp) != 0)
		bad = 1;
	a->fp = NULL;
	if (bad) {
		rc_seterr(err, "%s: write failed: %s", a->path, strerror(errno));
		rc_atomic_abort(a);
		return -1;
	}
	if (rename(a->tmp, a->path) != 0) {
		rc_seterr(err, "%s: cannot rename the finished file into place: %s",
		    a->path, strerror(errno));
		rc_atomic_abort(a);
		return -1;
	}
	free(a->tmp);
	free(a->path);
	memset(a, 0, sizeof(*a));
	return 0;
}

void
rc_atomic_abort(rc_atomic *a)
{
	if (a->fp != NULL && a->fp != stdout)
		fclose(a->fp);
	if (a->tmp != NULL)
		unlink(a->tmp);
	free(a->tmp);
	free(a->path);
	memset(a, 0, sizeof(*a));
}
