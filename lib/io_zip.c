/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_zip.c - what the readers of zip containers share (x3p, Excel
 * workbooks, contact.engineering containers): opening a zip held in
 * memory and reading one entry with a bound on memory.
 *
 * Deflate expands at most about 1032 times, so an entry's buffer starts
 * at 1100 times its compressed size (or at the bound) and grows only with
 * what decompression really gives: a size the directory lies about costs
 * nothing, and an entry past the bound (a zip bomb) is refused when the
 * bound is reached, never allocated first.
 */
#include "io_internal.h"

#include <stdlib.h>
#include <string.h>
#include <zip.h>
#include "io_dl_internal.h"

zip_t *
rc__zip_open_mem(const unsigned char *buf, size_t len, const char *what,
    rc_err *err)
{
	zip_error_t ze;
	zip_source_t *src;
	zip_t *za;

	if (rc__dl_zip(err) != 0)
		return NULL;
	zip_error_init(&ze);
	if ((src = zip_source_buffer_create(buf, len, 0, &ze)) == NULL) {
		rc_seterr(err, "%s: %s", what, zip_error_strerror(&ze));
		zip_error_fini(&ze);
		return NULL;
	}
	if ((za = zip_open_from_source(src, ZIP_RDONLY | ZIP_CHECKCONS, &ze)) ==
	    NULL) {
		rc_seterr(err, "not a valid zip (%s) container: %s", what,
		    zip_error_strerror(&ze));
		zip_source_free(src);
	}
	zip_error_fini(&ze);
	return za;
}

int
rc__zip_entry(zip_t *za, const char *what, const char *name,
    uint64_t want, uint64_t limit, unsigned char **buf, size_t *len,
    rc_err *err)
{
	zip_file_t *zf;
	zip_stat_t st;
	size_t cap, n = 0;
	unsigned char *b, *nb;
	zip_int64_t r;
	char q[64];

	if (want)
		limit = want;
	if ((zf = zip_fopen(za, name, 0)) == NULL)
		return rc_seterr(err, "%s: no entry '%s' in the container", what,
		    rc__io_quote(q, sizeof(q), name, strlen(name)));
	if (zip_stat(za, name, ZIP_STAT_COMP_SIZE, &st) == 0 &&
	    (st.valid & ZIP_STAT_COMP_SIZE) && st.comp_size < limit / 1100)
		cap = (size_t)st.comp_size * 1100 + 1;
	else
		cap = (size_t)limit + 1;
	if (cap < (1 << 16))
		cap = 1 << 16;
	if ((b = rc_malloc(cap, err)) == NULL) {
		zip_fclose(zf);
		return -1;
	}
	for (;;) {
		if (n == cap) {
			if ((nb = realloc(b, 2 * cap)) == NULL) {
				rc_seterr(err, "out of memory");
				goto fail;
			}
			b = nb;
			cap *= 2;
		}
		r = zip_fread(zf, b + n, cap - n);
		if (r < 0) {
			rc_seterr(err, "%s: %s: %s", what, rc__io_quote(q, sizeof(q),
			    name, strlen(name)), zip_strerror(za));
			goto fail;
		}
		if (r == 0)
			break;
		n += (size_t)r;
		if (n > limit) {
			rc_seterr(err, want ? "%s: %s holds more than the %zu bytes "
			    "described" : "%s: %s unpacks to over %zu bytes", what,
			    rc__io_quote(q, sizeof(q), name, strlen(name)),
			    (size_t)limit);
			goto fail;
		}
	}
	zip_fclose(zf);
	if (want && n != want) {
		free(b);
		return rc_seterr(err, "%s: %s holds %zu bytes; %zu are described",
		    what, rc__io_quote(q, sizeof(q), name, strlen(name)), n,
		    (size_t)want);
	}
	*buf = b;
	*len = n;
	return 0;
fail:
	zip_fclose(zf);
	free(b);
	return -1;
}
