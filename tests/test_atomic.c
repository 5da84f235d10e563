/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_atomic.c - outputs never replace what is not a regular file
 * (atomic.h), are checked before work, leave no temporary behind; and any
 * command line or accepted metadata value survives a .surf round trip
 * (grid.h), so the toolkit never writes a file it then refuses. */
#define _GNU_SOURCE
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic.h"
#include "checkpoint.h"
#include "grid.h"
#include "io.h"
#include "testlib.h"

static int
is_chardev(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 && S_ISCHR(st.st_mode);
}

static long
file_size(const char *path)
{
	struct stat st;

	return stat(path, &st) == 0 ? (long)st.st_size : -1;
}

static void
test_regular_and_links(void)
{
	rc_atomic a;
	rc_err err;
	struct stat st;
	const char *target = test_slot_path(0, "target.txt"), *link = test_slot_path(1, "link.txt");

	/* A new file: written to a temporary beside it, renamed at commit. */
	test_int(rc_atomic_open(&a, target, &err), 0, "open a new file");
	test_true(!a.direct && a.tmp != NULL && access(a.tmp, F_OK) == 0,
	    "a new file goes through a temporary file");
	test_true(access(target, F_OK) != 0, "the target does not exist before commit");
	fputs("one\n", a.fp);
	test_int(rc_atomic_commit(&a, &err), 0, "commit");
	test_int(file_size(target), 4, "the committed file has the content");

	/* A link is followed: the link stays, the file it names changes. */
	test_int(symlink("target.txt", link), 0, "make a relative link");
	test_int(rc_atomic_open(&a, link, &err), 0, "open through the link");
	fputs("longer\n", a.fp);
	test_int(rc_atomic_commit(&a, &err), 0, "commit through the link");
	test_true(lstat(link, &st) == 0 && S_ISLNK(st.st_mode), "the link is still a link");
	test_int(file_size(target), 7, "the target has the new content");

	/* A dangling link: the file is made where it points. */
	test_int(symlink("made.txt", test_slot_path(2, "dangling.txt")), 0, "make a dangling link");
	test_int(rc_atomic_open(&a, test_slot_path(2, "dangling.txt"), &err), 0, "open a dangling link");
	fputs("x", a.fp);
	test_int(rc_atomic_commit(&a, &err), 0, "commit through a dangling link");
	test_int(file_size(test_slot_path(3, "made.txt")), 1, "the file is made where the link points");

	/* Removal of a finished output: through the link, the file. */
	test_int(rc_atomic_remove(link, &err), 0, "remove through a link");
	test_true(access(target, F_OK) != 0, "the file the link named is gone");
}

static void
test_devices(void)
{
	rc_atomic a;
	rc_err err;

	/* Written directly: no temporary, no rename over the device. */
	test_int(rc_atomic_open(&a, "/dev/null", &err), 0, "open /dev/null");
	test_true(a.direct && a.tmp == NULL, "/dev/null is written directly");
	fputs("data\n", a.fp);
	test_int(rc_atomic_commit(&a, &err), 0, "commit to /dev/null");
	test_true(is_chardev("/dev/null"), "/dev/null is still a character device");
	test_int(rc_atomic_remove("/dev/null", &err), 0, "remove leaves a device alone");
	test_true(is_chardev("/dev/null"), "... and it is still there");

	if (access("/dev/full", W_OK) == 0) {
		char big[8192];

		memset(big, 'x', sizeof(big));
		test_int(rc_atomic_open(&a, "/dev/full", &err), 0, "open /dev/full");
		fwrite(big, 1, sizeof(big), a.fp);
		test_int(rc_atomic_commit(&a, &err), -1, "a full device fails the commit");
		test_true(strstr(err.msg, "No space left") != NULL,
		    "the failure says why (%s)", err.msg);
		test_true(is_chardev("/dev/full"), "/dev/full is still a character device");
	} else
		test_skip(3, "/dev/full is not writable here");
}

static void
test_check_and_pending(void)
{
	rc_atomic a;
	rc_err err;

	test_int(rc_atomic_check("", &err), -1, "check: an empty name is refused");
	test_int(rc_atomic_check(test_tmpdir(), &err), -1, "check: a directory is refused");
	test_int(rc_atomic_check(test_slot_path(0, "nodir/x.surf"), &err), -1,
	    "check: a missing directory is refused");
	test_true(strstr(err.msg, "does not exist") != NULL, "... saying so (%s)", err.msg);
	test_int(rc_atomic_check(test_slot_path(0, "new.surf"), &err), 0, "check: a new file is fine");
	test_true(access(test_slot_path(0, "new.surf"), F_OK) != 0, "check creates nothing");
	test_int(rc_atomic_check("/dev/null", &err), 0, "check: /dev/null is fine");
	test_int(rc_atomic_check("/dev/fd/987", &err), -1, "check: a closed descriptor is refused");
	test_int(rc_atomic_check("-", &err), 0, "check: standard output is fine");

	/* What a signal handler removes: the temporaries still open. */
	test_int(rc_atomic_open(&a, test_slot_path(1, "pending.surf"), &err), 0, "open for the signal case");
	test_true(a.tmp != NULL && access(a.tmp, F_OK) == 0, "its temporary exists");
	test_int(rc_atomic_unlink_pending(), 1, "unlink_pending removes one file");
	test_true(access(a.tmp, F_OK) != 0, "the temporary is gone");
	test_int(rc_atomic_unlink_pending(), 0, "a second call removes nothing");
	rc_atomic_abort(&a);
	test_true(access(test_slot_path(1, "pending.surf"), F_OK) != 0, "the target was never made");

	/* A temporary file made otherwise, tracked: removed by the handler
	 * until it is untracked. */
	{
		const char *own = test_slot_path(1, "own.gp");
		FILE *fp = fopen(own, "w");

		test_true(fp != NULL && fclose(fp) == 0, "own temporary made");
		rc_atomic_track(own);
		test_int(rc_atomic_unlink_pending(), 1, "a tracked file is removed");
		test_true(access(own, F_OK) != 0, "... and gone");
		fp = fopen(own, "w");
		test_true(fp != NULL && fclose(fp) == 0, "own temporary made again");
		rc_atomic_track(own);
		rc_atomic_untrack(own);
		test_int(rc_atomic_unlink_pending(), 0, "an untracked one is not");
		test_true(access(own, F_OK) == 0, "... and stays");
		unlink(own);
	}
}

/* Any command line is recorded in a form the reader accepts; a metadata
 * value the reader would refuse is refused when set. */
static void
test_metadata_round_trip(void)
{
	const char *cmd = "surfgen -o a\001b\n\351\tc.surf \177";
	const char *want = "surfgen -o a\\x01b\\x0a\351\tc.surf \\x7f";
	rc_grid *g, *r;
	rc_err err;
	const char *path = test_slot_path(0, "meta.surf");
	uint64_t h1, h2;

	if ((g = rc_grid_new(4, 2, 1, 1, &err)) == NULL) {
		test_true(0, "grid_new: %s", err.msg);
		return;
	}
	test_int(rc_grid_history_add(g, cmd, &err), 0, "history takes any bytes");
	test_true(strcmp(g->history[0], want) == 0, "control characters escaped as \\xNN");
	test_true(rc_grid_meta_set(g, "k", "a\001b", &err) != 0,
	    "meta refuses a control character");
	test_true(strstr(err.msg, "\\x01") != NULL, "... naming it (%s)", err.msg);
	test_true(rc_grid_meta_set(g, "k", "a\177b", &err) != 0, "meta refuses DEL");
	test_int(rc_grid_meta_set(g, "latin1", "caf\351", &err), 0,
	    "meta keeps a byte that is not UTF-8");
	test_int(rc_grid_meta_set(g, "tab", "a\tb", &err), 0, "meta keeps a tab");
	h1 = rc_checkpoint_hash(g);
	test_int(rc_grid_write(g, path, RC_FMT_SURF, &err), 0, "write the .surf");
	r = rc_grid_read(path, NULL, &err);
	test_true(r != NULL, "the toolkit reads back what it wrote (%s)",
	    r ? "ok" : err.msg);
	if (r != NULL) {
		test_true(r->nhistory == 1 && strcmp(r->history[0], want) == 0,
		    "history read back as written");
		test_true(rc_grid_meta_get(r, "latin1") != NULL &&
		    strcmp(rc_grid_meta_get(r, "latin1"), "caf\351") == 0,
		    "a non-UTF-8 value read back");
		test_true(rc_grid_meta_get(r, "tab") != NULL &&
		    strcmp(rc_grid_meta_get(r, "tab"), "a\tb") == 0,
		    "a tab read back");
		rc_grid_free(r);
	}
	/* The checkpoint identity sees metadata: another value, another hash. */
	rc_grid_meta_set(g, "seed", "2", &err);
	h2 = rc_checkpoint_hash(g);
	test_true(h1 != h2, "checkpoint hash covers metadata");
	rc_grid_free(g);
}

int
main(void)
{
	test_regular_and_links();
	test_devices();
	test_check_and_pending();
	test_metadata_round_trip();
	return test_summary();
}
