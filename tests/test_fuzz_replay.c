/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_fuzz_replay.c - replay the fuzzing regression corpus in `make check`.
 *
 * Every file under tests/data/fuzz/read/ and tests/data/fuzz/rows/ goes
 * through the same entry points the libFuzzer harnesses use (included here
 * under other names), so a crash found once stays fixed, under the normal
 * build and under SANITIZE=1.  The harnesses abort when a reader breaks
 * its contract (see their headers); the test then dies, which run.sh
 * counts as broken.  The file name adds a verdict: "bad-*" must be
 * rejected with a one-line message, "ok-*" must be accepted; other names
 * (crash-*, as libFuzzer writes them) need only return cleanly.
 */
#include <dirent.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testlib.h"

#define FUZZ_ENTRY fuzz_read_entry
#include "fuzz/fuzz_read.c"
#undef FUZZ_ENTRY
#define FUZZ_ENTRY fuzz_rows_entry
#include "fuzz/fuzz_rows.c"
#undef FUZZ_ENTRY

typedef int entry_fn(const uint8_t *, size_t);

/* Whole file into memory; NULL on failure (reported). */
static uint8_t *
slurp(const char *path, size_t *len)
{
	size_t cap = 4096, n;
	uint8_t *buf = malloc(cap), *b;
	FILE *fp = fopen(path, "rb");

	*len = 0;
	if (fp == NULL || buf == NULL) {
		test_true(0, "%s: %s", path, strerror(errno));
		if (fp != NULL)
			fclose(fp);
		free(buf);
		return NULL;
	}
	while ((n = fread(buf + *len, 1, cap - *len, fp)) > 0) {
		*len += n;
		if (*len == cap) {
			if ((b = realloc(buf, cap *= 2)) == NULL) {
				test_true(0, "%s: out of memory", path);
				free(buf);
				fclose(fp);
				return NULL;
			}
			buf = b;
		}
	}
	fclose(fp);
	return buf;
}

/* The verdict of the library itself for a "bad-" or "ok-" file. */
static int
accepted_read(const uint8_t *data, size_t size)
{
	rc_read_opts o = { .lx = 2, .ly = 3, .have_l = 1, .allow_nonfinite = 0 };
	rc_grid *g;
	rc_err err;
	FILE *fp;

	if (size == 0 || (fp = fmemopen((void *)data, size, "rb")) == NULL)
		return 0;
	g = rc_grid_read_stream(fp, &o, &err);
	fclose(fp);
	rc_grid_free(g);
	return g != NULL;
}

static int
accepted_rows(const uint8_t *data, size_t size)
{
	rc_rowset rs;
	rc_err err;
	int ok;

	rc_rows_init(&rs);
	ok = rc_rows_parse(&rs, (const char *)data, size, "replay", 0, &err) == 0;
	rc_rows_free(&rs);
	return ok;
}

/* Replay every file of one directory; returns how many. */
static int
replay(const char *top, const char *harness, entry_fn *entry,
    int (*accepted)(const uint8_t *, size_t))
{
	char dir[4096], path[4096 + 256];
	struct dirent *e;
	int count = 0;
	DIR *d;

	snprintf(dir, sizeof(dir), "%s/tests/data/fuzz/%s", top, harness);
	if ((d = opendir(dir)) == NULL) {
		test_true(0, "%s: %s", dir, strerror(errno));
		return 0;
	}
	while ((e = readdir(d)) != NULL) {
		uint8_t *data;
		size_t len;

		if (e->d_name[0] == '.')
			continue;
		snprintf(path, sizeof(path), "%s/%s", dir, e->d_name);
		if ((data = slurp(path, &len)) == NULL)
			continue;
		count++;
		test_int(entry(data, len), 0, "%s: %s returns cleanly", harness,
		    e->d_name);
		if (strncmp(e->d_name, "bad-", 4) == 0)
			test_true(!accepted(data, len), "%s: %s is rejected", harness,
			    e->d_name);
		else if (strncmp(e->d_name, "ok-", 3) == 0)
			test_true(accepted(data, len), "%s: %s is accepted", harness,
			    e->d_name);
		free(data);
	}
	closedir(d);
	return count;
}

int
main(void)
{
	const char *top = getenv("RC_TOP");

	if (top == NULL)
		top = ".";
	/* Hand-made seeds are there even when the fuzzer never crashed:
	 * fewer files means the corpus went missing. */
	test_range(replay(top, "read", fuzz_read_entry, accepted_read), 20, 1e9,
	    "read regression files");
	test_range(replay(top, "rows", fuzz_rows_entry, accepted_rows), 10, 1e9,
	    "rows regression files");
	return test_summary();
}
