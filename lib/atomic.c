/* SPDX-License-Identifier: GPL-3.0-or-later */
/* atomic.c - temporary file + fsync + rename for regular files, direct
 * writes for everything else (atomic.h says which is which). */
#define _POSIX_C_SOURCE 200809L
#include "atomic.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The only process-wide state of the library: the names of the temporary
 * files now open (or tracked), so that a signal handler can remove them
 * (rc_atomic_unlink_pending).  Fixed buffers, because a handler may not
 * allocate; a slot is taken with the name written before the flag is set,
 * so a handler never sees half a name.  More than RC_ATOMIC_SLOTS files
 * open at once only means the extra ones are not cleaned up on a signal. */
#define RC_ATOMIC_SLOTS 16
static char pending_name[RC_ATOMIC_SLOTS][PATH_MAX];
static volatile sig_atomic_t pending_used[RC_ATOMIC_SLOTS];

static void
pending_add(const char *tmp)
{
	if (strlen(tmp) >= PATH_MAX)
		return;
	for (int i = 0; i < RC_ATOMIC_SLOTS; i++)
		if (!pending_used[i]) {
			strcpy(pending_name[i], tmp);
			pending_used[i] = 1;
			return;
		}
}

static void
pending_remove(const char *tmp)
{
	for (int i = 0; i < RC_ATOMIC_SLOTS; i++)
		if (pending_used[i] && strcmp(pending_name[i], tmp) == 0) {
			pending_used[i] = 0;
			return;
		}
}

void
rc_atomic_track(const char *tmp)
{
	pending_add(tmp);
}

void
rc_atomic_untrack(const char *tmp)
{
	pending_remove(tmp);
}

int
rc_atomic_unlink_pending(void)
{
	int n = 0;

	for (int i = 0; i < RC_ATOMIC_SLOTS; i++)
		if (pending_used[i]) {
			n += unlink(pending_name[i]) == 0;
			pending_used[i] = 0;
		}
	return n;
}

int
rc_is_stdio(const char *path)
{
	return path == NULL || strcmp(path, "-") == 0;
}

/* The descriptor a path names by itself (/dev/stdout, /dev/fd/3, ...), or
 * -1.  Opening these by name would reopen the file behind the descriptor
 * at offset 0 (losing `>>`) or, renamed over, replace the link. */
static int
named_descriptor(const char *path)
{
	const char *num = NULL;
	char *end;
	long fd;

	if (strcmp(path, "/dev/stdout") == 0)
		return 1;
	if (strcmp(path, "/dev/stderr") == 0)
		return 2;
	if (strncmp(path, "/dev/fd/", 8) == 0)
		num = path + 8;
	else if (strncmp(path, "/proc/self/fd/", 14) == 0)
		num = path + 14;
	if (num == NULL || *num < '0' || *num > '9')
		return -1;
	errno = 0;
	fd = strtol(num, &end, 10);
	if (*end != '\0' || errno != 0 || fd > INT_MAX)
		return -1;
	return (int)fd;
}

/* Where a chain of symbolic links ends, also when the last link dangles
 * (the file is then created there, as a shell's `>` would).  A malloc'ed
 * path; NULL and err set on a loop or an unreadable link. */
static char *
follow_links(const char *path, rc_err *err)
{
	char *cur = strdup(path);
	struct stat st;

	if (cur == NULL) {
		rc_seterr(err, "out of memory");
		return NULL;
	}
	for (int hops = 0; lstat(cur, &st) == 0 && S_ISLNK(st.st_mode); hops++) {
		char target[PATH_MAX], *next;
		const char *slash;
		ssize_t n;
		size_t dirlen;

		if (hops == 40) {
			rc_seterr(err, "%s: too many levels of symbolic links", path);
			free(cur);
			return NULL;
		}
		if ((n = readlink(cur, target, sizeof(target) - 1)) < 0) {
			rc_seterr(err, "%s: %s", path, strerror(errno));
			free(cur);
			return NULL;
		}
		target[n] = '\0';
		slash = strrchr(cur, '/');
		dirlen = target[0] == '/' || slash == NULL ? 0 :
		    (size_t)(slash - cur) + 1;
		if ((next = malloc(dirlen + (size_t)n + 1)) == NULL) {
			rc_seterr(err, "out of memory");
			free(cur);
			return NULL;
		}
		memcpy(next, cur, dirlen);
		memcpy(next + dirlen, target, (size_t)n + 1);
		free(cur);
		cur = next;
	}
	return cur;
}

/* Whether an existing regular file target (st, in its directory) may be
 * replaced, decided as a shell's `>` would: not a write-protected file
 * (EACCES; root may), and not another user's file in a sticky directory
 * of someone else's (/tmp), which rename(2) could not replace (EPERM)
 * and the shell (fs.protected_regular) would not open.  0, or -1 with err
 * set naming path. */
static int
may_replace(const char *path, const char *target, const struct stat *st,
    rc_err *err)
{
	struct stat dir_st;
	char *dir, *slash;
	int r = 0;

	if (faccessat(AT_FDCWD, target, W_OK, AT_EACCESS) != 0)
		return rc_seterr(err, "%s: %s (the file is write-protected; "
		    "remove it or make it writable to replace it)", path,
		    strerror(errno));
	if ((dir = strdup(target)) == NULL)
		return rc_seterr(err, "out of memory");
	if ((slash = strrchr(dir, '/')) == NULL)
		strcpy(dir, ".");
	else
		slash[slash == dir] = '\0';
	if (stat(dir, &dir_st) == 0 && (dir_st.st_mode & S_ISVTX) &&
	    geteuid() != 0 && st->st_uid != geteuid() &&
	    dir_st.st_uid != geteuid())
		r = rc_seterr(err, "%s: belongs to another user in the sticky "
		    "directory %s: it cannot be replaced (name another file)",
		    path, dir);
	free(dir);
	return r;
}

int
rc_atomic_check(const char *path, rc_err *err)
{
	struct stat st;
	char *target, *slash;
	int named, flags, r = 0;

	if (rc_is_stdio(path))
		return 0;
	if (*path == '\0')
		return rc_seterr(err, "an output file name is empty");
	if ((named = named_descriptor(path)) >= 0) {
		if ((flags = fcntl(named, F_GETFL)) < 0)
			return rc_seterr(err, "%s: descriptor %d is not open", path,
			    named);
		if ((flags & O_ACCMODE) == O_RDONLY)
			return rc_seterr(err, "%s: descriptor %d is open for reading "
			    "only", path, named);
		return 0;
	}
	if ((target = follow_links(path, err)) == NULL)
		return -1;
	if (stat(target, &st) == 0) {
		if (S_ISDIR(st.st_mode))
			r = rc_seterr(err, "%s: is a directory", path);
		else if (!S_ISREG(st.st_mode)) {
			if (faccessat(AT_FDCWD, target, W_OK, AT_EACCESS) != 0)
				r = rc_seterr(err, "%s: %s", path, strerror(errno));
			free(target);
			return r;
		} else
			r = may_replace(path, target, &st, err);
	}
	if (r == 0 && (slash = strrchr(target, '/')) != NULL && slash[1] == '\0')
		r = rc_seterr(err, "%s: names a directory, not a file", path);
	if (r == 0) {
		/* the directory the temporary file goes to */
		const char *dir = ".";

		if ((slash = strrchr(target, '/')) != NULL) {
			slash[slash == target] = '\0';	/* "/x" -> "/" */
			dir = target;
		}
		if (stat(dir, &st) != 0 || !S_ISDIR(st.st_mode))
			r = rc_seterr(err, "%s: the directory %s does not exist",
			    path, dir);
		else if (faccessat(AT_FDCWD, dir, W_OK | X_OK, AT_EACCESS) != 0)
			r = rc_seterr(err, "%s: cannot create a file in %s: %s", path,
			    dir, strerror(errno));
	}
	free(target);
	return r;
}

int
rc_atomic_remove(const char *path, rc_err *err)
{
	struct stat st;
	char *target;
	int r = 0;

	if (rc_is_stdio(path) || named_descriptor(path) >= 0)
		return 0;
	if ((target = follow_links(path, err)) == NULL)
		return -1;
	if (lstat(target, &st) == 0 && S_ISREG(st.st_mode) &&
	    unlink(target) != 0 && errno != ENOENT)
		r = rc_seterr(err, "%s: %s", path, strerror(errno));
	free(target);
	return r;
}

static int
open_direct(rc_atomic *a, int fd, const char *path, rc_err *err)
{
	if (fd < 0 || (a->fp = fdopen(fd, "wb")) == NULL) {
		rc_seterr(err, "%s: %s", path, strerror(errno));
		if (fd >= 0)
			close(fd);
		free(a->path);
		memset(a, 0, sizeof(*a));
		return -1;
	}
	a->direct = 1;
	return 0;
}

int
rc_atomic_open(rc_atomic *a, const char *path, rc_err *err)
{
	const char *slash, *base;
	size_t dirlen;
	struct stat st;
	mode_t mode;
	int fd, named, exists;

	memset(a, 0, sizeof(*a));
	if (rc_is_stdio(path)) {
		a->fp = stdout;
		return 0;
	}
	if (*path == '\0')
		return rc_seterr(err, "an output file name is empty");
	if ((named = named_descriptor(path)) >= 0) {
		if ((a->path = strdup(path)) == NULL)
			return rc_seterr(err, "out of memory");
		return open_direct(a, dup(named), path, err);
	}
	if ((a->path = follow_links(path, err)) == NULL)
		return -1;
	exists = stat(a->path, &st) == 0;
	if (exists && S_ISDIR(st.st_mode)) {
		free(a->path);
		a->path = NULL;
		return rc_seterr(err, "%s: is a directory", path);
	}
	if (exists && !S_ISREG(st.st_mode))	/* device, FIFO, socket */
		return open_direct(a, open(a->path, O_WRONLY | O_NOCTTY), path,
		    err);
	if (exists && may_replace(path, a->path, &st, err) != 0) {
		free(a->path);
		a->path = NULL;
		return -1;
	}

	slash = strrchr(a->path, '/');
	base = slash ? slash + 1 : a->path;
	dirlen = (size_t)(base - a->path);
	if (*base == '\0') {
		free(a->path);
		a->path = NULL;
		return rc_seterr(err, "%s: names a directory, not a file", path);
	}
	if ((a->tmp = malloc(strlen(a->path) + 16)) == NULL) {
		free(a->path);
		a->path = NULL;
		return rc_seterr(err, "out of memory");
	}
	memcpy(a->tmp, a->path, dirlen);
	sprintf(a->tmp + dirlen, ".%s.XXXXXX", base);
	if ((fd = mkstemp(a->tmp)) < 0) {
		rc_seterr(err, "%s: cannot create a temporary file beside it: %s",
		    path, strerror(errno));
		free(a->tmp);
		free(a->path);
		memset(a, 0, sizeof(*a));
		return -1;
	}
	pending_add(a->tmp);
	/* mkstemp makes 0600: keep an existing file's permission bits, give a
	 * new one what a plain open would. */
	if (exists)
		mode = st.st_mode & 07777;
	else {
		mode = umask(0);
		umask(mode);
		mode = 0666 & ~mode;
	}
	fchmod(fd, mode);
	if ((a->fp = fdopen(fd, "wb")) == NULL) {
		rc_seterr(err, "%s: %s", path, strerror(errno));
		close(fd);
		rc_atomic_abort(a);
		return -1;
	}
	return 0;
}

int
rc_atomic_commit(rc_atomic *a, rc_err *err)
{
	int bad, closed_bad;

	if (a->fp == NULL)
		return rc_seterr(err, "internal: commit of a closed file");
	if (a->path == NULL) {		/* stdout */
		bad = fflush(a->fp) != 0 || ferror(a->fp);
		a->fp = NULL;
		return bad ? rc_seterr(err, "standard output: %s", strerror(errno)) : 0;
	}
	bad = fflush(a->fp) != 0 || ferror(a->fp);
	/* fsync a regular file before the rename makes it visible; a device
	 * or FIFO has nothing to sync (and /dev/null says EINVAL). */
	if (!bad && !a->direct && fsync(fileno(a->fp)) != 0)
		bad = 1;
	closed_bad = fclose(a->fp) != 0;
	a->fp = NULL;
	if (bad || closed_bad) {
		rc_seterr(err, "%s: write failed: %s", a->path, strerror(errno));
		rc_atomic_abort(a);
		return -1;
	}
	if (!a->direct && rename(a->tmp, a->path) != 0) {
		rc_seterr(err, "%s: cannot rename the finished file into place: %s",
		    a->path, strerror(errno));
		rc_atomic_abort(a);
		return -1;
	}
	if (a->tmp != NULL)
		pending_remove(a->tmp);
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
	if (a->tmp != NULL) {
		unlink(a->tmp);
		pending_remove(a->tmp);
	}
	free(a->tmp);
	free(a->path);
	memset(a, 0, sizeof(*a));
}
