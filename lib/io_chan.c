/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_chan.c - what the multi-channel readers share: the channel set, unit
 * strings as files state them, and whole-input reads that allocate only
 * as much as the input really holds. */
#include "io_internal.h"
#include "units.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int
rc__chanset_add(rc_chanset *s, rc_grid *g, const char *title, rc_err *err)
{
	if (s->n == s->cap) {
		size_t cap = s->cap ? 2 * s->cap : 4;
		rc_channel *c = realloc(s->c, cap * sizeof(*c));

		if (c == NULL) {
			rc_grid_free(g);
			return rc_seterr(err, "out of memory");
		}
		s->c = c;
		s->cap = cap;
	}
	s->c[s->n].g = g;
	snprintf(s->c[s->n].title, sizeof(s->c[s->n].title), "%s",
	    title ? title : "");
	s->n++;
	return 0;
}

const char *
rc__io_title(const rc_grid *g)
{
	const char *t = rc_grid_meta_get(g, "Title");

	if (t == NULL)
		t = rc_grid_meta_get(g, "channel");
	return t != NULL ? t : "";
}

void
rc__chanset_free(rc_chanset *s)
{
	for (size_t i = 0; i < s->n; i++)
		rc_grid_free(s->c[i].g);
	free(s->c);
	s->c = NULL;
	s->n = s->cap = 0;
}

int
rc__io_set_unit(char dst[32], const char *u, rc_err *err)
{
	char q[64];

	u = rc_unit_canonical(u);	/* "\xc2\xb5m" and "\xce\xbcm" become "um" */
	if (strlen(u) >= 32)
		return rc_seterr(err, "unit '%s' longer than 31 characters",
		    rc__io_quote(q, sizeof(q), u, strlen(u)));
	for (const char *p = u; *p; p++)
		if ((unsigned char)*p < 0x20 || *p == 0x7f)
			return rc_seterr(err, "unit '%s' holds a control character",
			    rc__io_quote(q, sizeof(q), u, strlen(u)));
	strcpy(dst, u);
	return 0;
}

/* Bytes left in a regular file (what is buffered and what follows), or
 * 0 if the input is no regular file. */
static size_t
file_left(rc_in *in)
{
	struct stat st;
	off_t at;
	int fd = fileno(in->fp);

	if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) ||
	    (at = ftello(in->fp)) < 0 || at > st.st_size)
		return 0;
	return (size_t)(st.st_size - at) + (in->len - in->pos);
}

int
rc__in_slurp(rc_in *in, unsigned char **buf, size_t *len, rc_err *err)
{
	size_t cap = file_left(in) + 1, n = 0, r;
	unsigned char *b, *nb;

	/* A regular file is read at once (the extra byte sees the end); a
	 * pipe's buffer doubles from 64 KiB. */
	if (cap < ((size_t)1 << 16))
		cap = (size_t)1 << 16;
	b = rc_malloc(cap, err);

	if (b == NULL)
		return -1;
	for (;;) {
		if (n == cap) {
			if (cap >= RC_GRID_MAX_POINTS) {
				free(b);
				return rc_seterr(err, "input larger than %zu bytes", cap);
			}
			if ((nb = realloc(b, 2 * cap)) == NULL) {
				free(b);
				return rc_seterr(err, "out of memory (input over %zu bytes)",
				    cap);
			}
			b = nb;
			cap *= 2;
		}
		r = rc__in_read(in, b + n, cap - n);
		n += r;
		if (n < cap)
			break;
	}
	if (rc__in_check(in, err) != 0) {
		free(b);
		return -1;
	}
	*buf = b;
	*len = n;
	return 0;
}

int
rc__in_read_exact(rc_in *in, size_t need, unsigned char **buf, rc_err *err)
{
	size_t cap = need < ((size_t)1 << 16) ? need : (size_t)1 << 16, n = 0, r;
	unsigned char *b = rc_malloc(cap ? cap : 1, err), *nb;

	if (b == NULL)
		return -1;
	while (n < need) {
		if (n == cap) {
			size_t ncap = need - cap < cap ? need : 2 * cap;

			if ((nb = realloc(b, ncap)) == NULL) {
				free(b);
				return rc_seterr(err, "out of memory (asked for %zu bytes)",
				    ncap);
			}
			b = nb;
			cap = ncap;
		}
		r = rc__in_read(in, b + n, cap - n);
		n += r;
		if (n < cap)
			break;
	}
	if (n < need) {
		free(b);
		if (rc__in_check(in, err) != 0)
			return -1;
		return rc_seterr(err, "truncated: expected %zu data bytes, got %zu",
		    need, n);
	}
	*buf = b;
	return 0;
}

double
rc__io_per_metre(const char *u)
{
	int exp10;

	/* units.c knows the length units; one unit is 10^exp10 m */
	return rc_unit_length_exp(u, &exp10) ? pow(10, -exp10) : 0;
}
