/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io.c - format detection and dispatch, the buffered input every reader
 * shares, and the checks every grid passes after reading. */
#include "io.h"
#include "io_internal.h"
#include "atomic.h"
#include "units.h"

#include <ctype.h>
#include <errno.h>
#include <fftw3.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

/* Input of unknown length is read in pieces of this size, so a header that
 * lies about the size costs at most one piece of memory. */
#define CHUNK ((size_t)16 << 20)

void
rc__in_init(rc_in *in, FILE *fp)
{
	in->fp = fp;
	in->pos = in->len = 0;
	in->consumed = 0;
	in->eof = 0;
	in->error = 0;
}

static void
fill(rc_in *in)
{
	size_t got;

	if (in->eof || in->error)
		return;
	if (in->pos > 0) {
		memmove(in->buf, in->buf + in->pos, in->len - in->pos);
		in->len -= in->pos;
		in->pos = 0;
	}
	if (in->len == RC_IN_BUFSIZE)
		return;
	got = fread(in->buf + in->len, 1, RC_IN_BUFSIZE - in->len, in->fp);
	in->len += got;
	if (got == 0) {
		if (ferror(in->fp))
			in->error = errno ? errno : EIO;
		else
			in->eof = 1;
	}
}

size_t
rc__in_peek(rc_in *in, size_t n, const unsigned char **p)
{
	if (n > RC_IN_BUFSIZE)
		n = RC_IN_BUFSIZE;
	while (in->len - in->pos < n && !in->eof && !in->error)
		fill(in);
	*p = in->buf + in->pos;
	return in->len - in->pos < n ? in->len - in->pos : n;
}

int
rc__in_getc(rc_in *in)
{
	if (in->pos == in->len) {
		fill(in);
		if (in->pos == in->len)
			return EOF;
	}
	in->consumed++;
	return in->buf[in->pos++];
}

size_t
rc__in_read(rc_in *in, void *dst, size_t n)
{
	unsigned char *d = dst;
	size_t have = in->len - in->pos, done, got;

	done = have < n ? have : n;
	memcpy(d, in->buf + in->pos, done);
	in->pos += done;
	/* Big reads bypass the buffer. */
	while (done < n && !in->eof && !in->error) {
		got = fread(d + done, 1, n - done, in->fp);
		done += got;
		if (got == 0) {
			if (ferror(in->fp))
				in->error = errno ? errno : EIO;
			else
				in->eof = 1;
		}
	}
	in->consumed += done;
	return done;
}

int
rc__in_line(rc_in *in, char *buf, size_t cap, size_t *len)
{
	size_t n = 0;
	int c;

	for (;;) {
		if ((c = rc__in_getc(in)) == EOF) {
			buf[n] = '\0';
			*len = n;
			return n > 0 ? 2 : 0;
		}
		if (c == '\n') {
			buf[n] = '\0';
			*len = n;
			return 1;
		}
		if (n + 1 >= cap) {
			buf[n] = '\0';
			*len = n;
			return -1;
		}
		buf[n++] = (char)c;
	}
}

int
rc__in_check(const rc_in *in, rc_err *err)
{
	if (in->error)
		return rc_seterr(err, "read error: %s", strerror(in->error));
	return 0;
}

/* Bytes left in the input if it is a regular file, else -1. */
static long long
remaining(rc_in *in)
{
	struct stat st;
	off_t at;
	int fd = fileno(in->fp);

	if (fd < 0 || fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
		return -1;
	if ((at = ftello(in->fp)) < 0 || at > st.st_size)
		return -1;
	return (long long)(st.st_size - at) + (long long)(in->len - in->pos);
}

rc_grid *
rc__io_grid_alloc(size_t nx, size_t ny, double lx, double ly, rc_err *err)
{
	rc_grid *g;
	double *z;

	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		return NULL;
	if ((z = fftw_alloc_real(nx * ny)) == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes for a %zux%zu grid)",
		    nx * ny * sizeof(double), nx, ny);
		return NULL;
	}
	/* A 1x1 grid carries the defaults; its value array is replaced. */
	if ((g = rc_grid_new(1, 1, lx, ly, err)) == NULL) {
		fftw_free(z);
		return NULL;
	}
	fftw_free(g->z);
	g->z = z;
	g->nx = nx;
	g->ny = ny;
	return g;
}

static double
decode_one(const unsigned char *p, const rc_layout *l)
{
	unsigned char b[8];
	uint64_t u = 0;
	double d;
	float f;

	for (size_t k = 0; k < l->elsize; k++)
		b[k] = l->big_endian ? p[l->elsize - 1 - k] : p[k];
	for (size_t k = l->elsize; k-- > 0;)
		u = u << 8 | b[k];
	if (l->elsize == 8) {
		memcpy(&d, &u, 8);
		return d;
	}
	uint32_t u32 = (uint32_t)u;
	memcpy(&f, &u32, 4);
	return f;
}

/* Values first .. first+n-1 of the file, raw in p, into g. */
static int
host_is_little_endian(void)
{
	const uint16_t one = 1;

	return *(const unsigned char *)&one == 1;
}

static void
decode(const unsigned char *p, size_t first, size_t n, const rc_layout *l,
    rc_grid *g)
{
	if (l->elsize == 8 && !l->big_endian && !l->fortran &&
	    host_is_little_endian()) {
		memcpy(g->z + first, p, n * 8);
		return;
	}
	for (size_t k = 0; k < n; k++) {
		size_t idx = first + k, dst;

		if (l->fortran)		/* file index = i * ny + j */
			dst = (idx % g->ny) * g->nx + idx / g->ny;
		else
			dst = idx;
		g->z[dst] = decode_one(p + k * l->elsize, l);
	}
}

static int
check_trailing(rc_in *in, rc_err *err)
{
	const unsigned char *p;
	size_t n = rc__in_peek(in, 4096, &p);

	if (rc__in_check(in, err) != 0)
		return -1;
	if (n > 0)
		return rc_seterr(err, "trailing garbage: %s%zu bytes after the data",
		    n == 4096 ? "at least " : "", n);
	return 0;
}

rc_grid *
rc__in_read_values(rc_in *in, size_t nx, size_t ny, double lx, double ly,
    const rc_layout *l, rc_err *err)
{
	unsigned char **chunk = NULL, *buf = NULL;
	size_t need, nchunk = 0, got = 0, count, k;
	long long left;
	rc_grid *g = NULL;

	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		return NULL;
	count = nx * ny;
	need = count * l->elsize;	/* at most 2^39: no overflow */
	left = remaining(in);
	if (left >= 0) {
		/* A regular file: its size tells before anything is allocated. */
		if ((unsigned long long)left < need) {
			rc_seterr(err, "truncated: expected %zu data bytes, got %lld",
			    need, left);
			return NULL;
		}
		if ((g = rc__io_grid_alloc(nx, ny, lx, ly, err)) == NULL)
			return NULL;
		if ((buf = rc_malloc(CHUNK < need ? CHUNK : need, err)) == NULL)
			goto fail;
		for (k = 0; got < need; ) {
			size_t want = need - got < CHUNK ? need - got : CHUNK, r;

			r = rc__in_read(in, buf, want);
			/* A piece holds whole values: CHUNK is a multiple of 8. */
			decode(buf, k, r / l->elsize, l, g);
			k += r / l->elsize;
			got += r;
			if (r < want) {
				if (rc__in_check(in, err) == 0)
					rc_seterr(err, "truncated: expected %zu data bytes, got %zu",
					    need, got);
				goto fail;
			}
		}
		free(buf);
		buf = NULL;
	} else {
		/* A pipe: read piece by piece, growing from 64 KiB to CHUNK, and
		 * allocate the grid once all is in: a lying header costs about
		 * as much memory as the input really holds. */
		size_t maxchunks = 10 + need / CHUNK, piece = (size_t)64 << 10;
		size_t *bytes;

		if ((chunk = rc_calloc(maxchunks, sizeof(*chunk) + sizeof(*bytes),
		    err)) == NULL)
			return NULL;
		bytes = (size_t *)(chunk + maxchunks);
		while (got < need) {
			size_t want = need - got < piece ? need - got : piece, r;

			if ((chunk[nchunk] = rc_malloc(want, err)) == NULL)
				goto fail;
			r = rc__in_read(in, chunk[nchunk], want);
			bytes[nchunk++] = r;
			got += r;
			if (r < want) {
				if (rc__in_check(in, err) == 0)
					rc_seterr(err, "truncated: expected %zu data bytes, got %zu",
					    need, got);
				goto fail;
			}
			if (piece < CHUNK)
				piece *= 2;
		}
		if ((g = rc__io_grid_alloc(nx, ny, lx, ly, err)) == NULL)
			goto fail;
		/* Every piece is a power of two of at least 64 KiB, or the
		 * rest: whole values each. */
		for (k = 0, got = 0; k < nchunk; k++) {
			decode(chunk[k], got / l->elsize, bytes[k] / l->elsize, l, g);
			got += bytes[k];
			free(chunk[k]);
			chunk[k] = NULL;
		}
		free(chunk);
		chunk = NULL;
	}
	if (check_trailing(in, err) != 0)
		goto fail;
	return g;
fail:
	if (chunk != NULL) {
		for (k = 0; k < nchunk; k++)
			free(chunk[k]);
		free(chunk);
	}
	free(buf);
	rc_grid_free(g);
	return NULL;
}

int
rc__parse_size(const char *s, size_t *v)
{
	unsigned long long u = 0;

	if (*s == '\0')
		return -1;
	for (; *s; s++) {
		if (*s < '0' || *s > '9')
			return -1;
		if (u > (ULLONG_MAX - 9) / 10)
			return -1;
		u = u * 10 + (unsigned)(*s - '0');
	}
	if (u > SIZE_MAX)
		return -1;
	*v = (size_t)u;
	return 0;
}

int
rc__parse_double(const char *s, double *v)
{
	char *end;

	if (*s == '\0' || isspace((unsigned char)*s))
		return -1;
	errno = 0;
	*v = strtod(s, &end);
	if (end == s || *end != '\0')
		return -1;
	/* Underflow to a denormal is a legal value; overflow is not. */
	if (errno == ERANGE && isinf(*v))
		return -1;
	return 0;
}

const char *
rc__io_quote(char *buf, size_t len, const char *s, size_t n)
{
	size_t o = 0;

	for (size_t i = 0; i < n && o + 5 < len; i++) {
		unsigned char c = (unsigned char)s[i];

		if (o >= 40) {
			memcpy(buf + o, "...", 3);
			o += 3;
			break;
		}
		if (c >= 0x20 && c < 0x7f)
			buf[o++] = (char)c;
		else
			o += (size_t)snprintf(buf + o, len - o, "\\x%02x", c);
	}
	buf[o < len ? o : len - 1] = '\0';
	return buf;
}

void
rc__put_le64(unsigned char *p, double v)
{
	uint64_t u;

	memcpy(&u, &v, 8);
	for (int k = 0; k < 8; k++, u >>= 8)
		p[k] = (unsigned char)(u & 0xff);
}

void
rc__put_le32(unsigned char *p, uint32_t v)
{
	for (int k = 0; k < 4; k++, v >>= 8)
		p[k] = (unsigned char)(v & 0xff);
}

void
rc__put_le32f(unsigned char *p, float v)
{
	uint32_t u;

	memcpy(&u, &v, 4);
	rc__put_le32(p, u);
}

void
rc__put_le16(unsigned char *p, uint16_t v)
{
	p[0] = (unsigned char)(v & 0xff);
	p[1] = (unsigned char)(v >> 8);
}

uint32_t
rc__get_le32(const unsigned char *p)
{
	return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 |
	    (uint32_t)p[3] << 24;
}

uint16_t
rc__get_le16(const unsigned char *p)
{
	return (uint16_t)(p[0] | p[1] << 8);
}

int
rc__io_write(FILE *fp, const void *p, size_t n, rc_err *err)
{
	if (n > 0 && fwrite(p, 1, n, fp) != n)
		return rc_seterr(err, "write error: %s", strerror(errno));
	return 0;
}

int
rc__io_write_values(FILE *fp, const double *z, size_t n, size_t elsize,
    rc_err *err)
{
	unsigned char buf[8192];
	size_t per = sizeof(buf) / elsize;

	if (elsize == 8 && host_is_little_endian())
		return rc__io_write(fp, z, n * 8, err);
	for (size_t i = 0; i < n; i += per) {
		size_t m = n - i < per ? n - i : per;

		for (size_t k = 0; k < m; k++)
			if (elsize == 8)
				rc__put_le64(buf + 8 * k, z[i + k]);
			else
				rc__put_le32f(buf + 4 * k, (float)z[i + k]);
		if (rc__io_write(fp, buf, m * elsize, err) != 0)
			return -1;
	}
	return 0;
}

/* What every grid must satisfy, whatever format it came in.  Missing
 * points (valid 0) are NaN by definition. */
static int
check_values(rc_grid *g, const rc_read_opts *o, rc_err *err)
{
	size_t n = rc_grid_size(g);

	for (size_t k = 0; k < n; k++) {
		if (isnan(g->z[k])) {
			if (g->kind == RC_KIND_MASK)
				return rc_seterr(err, "mask value at i=%zu, j=%zu is NaN; "
				    "a mask holds only 0 and 1", k % g->nx, k / g->nx);
			/* A missing point (optical profilers leave them). */
			if (g->valid == NULL && (g->valid = rc_malloc(n, err)) == NULL)
				return -1;
			continue;	/* the flags are set below */
		}
		if (isinf(g->z[k]) && !(o != NULL && o->allow_nonfinite))
			return rc_seterr(err, "value at i=%zu, j=%zu is infinite; "
			    "infinite values are not allowed (missing points are NaN)",
			    k % g->nx, k / g->nx);
	}
	if (g->valid != NULL)
		for (size_t k = 0; k < n; k++) {
			g->valid[k] = !isnan(g->z[k]);
			/* a filled point has a value */
			if (g->filled != NULL && g->filled[k] && !g->valid[k])
				return rc_seterr(err, "point i=%zu, j=%zu is listed as "
				    "filled but is missing (NaN)", k % g->nx, k / g->nx);
		}
	if (g->kind == RC_KIND_MASK)
		for (size_t k = 0; k < n; k++)
			if (g->z[k] != 0 && g->z[k] != 1)
				return rc_seterr(err, "mask value at i=%zu, j=%zu is %.17g; "
				    "a mask holds only 0 and 1", k % g->nx, k / g->nx,
				    g->z[k]);
	return 0;
}

static int
copy_unit(char *dst, size_t cap, const char *u, const char *what, rc_err *err)
{
	if (strlen(u) >= cap)
		return rc_seterr(err, "%s '%.40s' longer than %zu characters", what,
		    u, cap - 1);
	strcpy(dst, u);
	return 0;
}

int
rc_grid_read_finish(rc_grid *g, const rc_read_opts *o, rc_err *err)
{
	if (check_values(g, o, err) != 0)
		return -1;
	if (o == NULL)
		return 0;
	if (o->periodic == RC_PERIODIC_YES)
		g->periodic = 1;
	else if (o->periodic == RC_PERIODIC_NO)
		g->periodic = 0;
	if (o->unit != NULL && g->unit[0] == '\0' &&
	    copy_unit(g->unit, sizeof(g->unit), o->unit, "unit", err) != 0)
		return -1;
	if (o->z_unit != NULL && o->z_unit[0] != '\0' &&
	    copy_unit(g->z_unit, sizeof(g->z_unit), o->z_unit, "z unit", err) != 0)
		return -1;
	return 0;
}

static const char npy_magic[] = "\x93NUMPY";
/* Any version: the reader names the one it knows. */
static const char gsf_magic[] = "Gwyddion Simple Field";

static int
starts(const unsigned char *p, size_t n, const char *magic, size_t len)
{
	return n >= len && memcmp(p, magic, len) == 0;
}

/* Not text: a control character other than white space in the first
 * 4 KiB (text in any ASCII-compatible encoding has none), or the text
 * header of Bruker/Digital Instruments files, which lead to binary data. */
static int
looks_binary(rc_in *in)
{
	const unsigned char *p;
	size_t n = rc__in_peek(in, 4096, &p);

	for (size_t k = 0; k < n; k++)
		if ((p[k] < 0x20 && !(p[k] >= '\t' && p[k] <= '\r')) ||
		    p[k] == 0x7f)
			return 1;
	return starts(p, n, "\\*File list", 11) ||
	    starts(p, n, "\\*Force file list", 17) ||
	    starts(p, n, "\\*EC File list", 14);
}

typedef int (*mem_reader)(const unsigned char *, size_t, const rc_read_opts *,
    rc_chanset *, rc_err *);

static int
gwy_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	(void)o;
	return rc__gwy_read(b, n, s, err);
}

static int
x3p_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	(void)o;
	return rc__x3p_read(b, n, s, err);
}

/* Not text and no format of ours: Gwyddion's.  If Gwyddion cannot read
 * it either, the text reader has the last word: it reads text with a
 * stray control character or says where it breaks. */
static int
vendor(rc_in *in, const char *path, const rc_read_opts *o, rc_chanset *s,
    rc_err *err)
{
	unsigned char *buf = NULL;
	size_t len = 0;
	struct stat st;
	rc_err gerr, terr;
	rc_in *in2 = NULL;
	rc_grid *g = NULL;
	FILE *fp = NULL;
	int is_file = path != NULL && stat(path, &st) == 0 && S_ISREG(st.st_mode);

	if (!is_file && rc__in_slurp(in, &buf, &len, err) != 0)
		return -1;
	if (rc__gwyddion_read(is_file ? path : NULL, buf, len, s, &gerr) == 0) {
		free(buf);
		return 0;
	}
	rc__chanset_free(s);
	fp = is_file ? fopen(path, "rb") : fmemopen(buf, len, "rb");
	if (fp != NULL && (in2 = rc_malloc(sizeof(*in2), &terr)) != NULL) {
		rc__in_init(in2, fp);
		g = rc__txt_read(in2, o, &terr);
	} else if (fp == NULL)
		rc_seterr(&terr, "%s", strerror(errno));
	free(in2);
	if (fp != NULL)
		fclose(fp);
	free(buf);
	if (g != NULL)
		return rc__chanset_add(s, g, "", err);
	return rc_seterr(err, "%s; read as text: %s", gerr.msg, terr.msg);
}

/* Every channel of the input; path is the file fp reads, if known (a
 * vendor file is then handed to Gwyddion as it is). */
static int
read_channels(FILE *fp, const char *path, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	rc_in *in;
	const unsigned char *p;
	unsigned char *buf = NULL;
	mem_reader whole = NULL;
	rc_grid *g = NULL;
	size_t n, len;
	int r = -1;

	if ((in = rc_malloc(sizeof(*in), err)) == NULL)
		return -1;
	rc__in_init(in, fp);
	n = rc__in_peek(in, 32, &p);
	if (rc__in_check(in, err) != 0)
		goto out;
	if (n == 0) {
		rc_seterr(err, "empty input");
		goto out;
	}
	if (starts(p, n, "#surf", 5))
		g = rc__surf_read(in, o, err);
	else if (starts(p, n, npy_magic, 6))
		g = rc__npy_read(in, o, err);
	else if (starts(p, n, gsf_magic, sizeof(gsf_magic) - 1))
		g = rc__gsf_read(in, o, err);
	else if (starts(p, n, "aISO-1.0", 8) || starts(p, n, "bISO-1.0", 8) ||
	    starts(p, n, "aBCR-1.0", 8) || starts(p, n, "bBCR-1.0", 8))
		g = rc__sdf_read(in, o, err);
	else if (starts(p, n, "GWYP", 4) || starts(p, n, "GWYO", 4))
		whole = gwy_mem;
	else if (starts(p, n, "PK\x03\x04", 4))
		whole = x3p_mem;
	else if (starts(p, n, "CDF\x01", 4) || starts(p, n, "CDF\x02", 4) ||
	    starts(p, n, "CDF\x05", 4) || starts(p, n, "\x89HDF\r\n\x1a\n", 8))
		whole = rc__nc_read;
	else if (looks_binary(in)) {
		r = vendor(in, path, o, s, err);
		goto out;
	} else
		g = rc__txt_read(in, o, err);
	if (whole != NULL) {
		if (rc__in_slurp(in, &buf, &len, err) == 0)
			r = whole(buf, len, o, s, err);
		goto out;
	}
	if (g != NULL)
		r = rc__chanset_add(s, g, rc__io_title(g), err);
out:
	free(buf);
	free(in);
	return r;
}

/* The channel the options name, or the first one whose values are
 * lengths (else the first); taken out of s. */
static rc_grid *
select_channel(rc_chanset *s, const rc_read_opts *o, rc_err *err)
{
	size_t pick = 0, k;
	char q[64];
	rc_grid *g;

	if (o != NULL && o->channel_name != NULL) {
		for (k = 0; k < s->n; k++)
			if (strcmp(s->c[k].title, o->channel_name) == 0)
				break;
		if (k == s->n)
			for (k = 0; k < s->n; k++)
				if (strcasecmp(s->c[k].title, o->channel_name) == 0)
					break;
		if (k == s->n) {
			rc_seterr(err, "no channel titled '%s' (%zu channel%s; "
			    "surfstat --channels lists them)", rc__io_quote(q, sizeof(q),
			    o->channel_name, strlen(o->channel_name)), s->n,
			    s->n == 1 ? "" : "s");
			return NULL;
		}
		pick = k;
	} else if (o != NULL && o->channel > 0) {
		if ((size_t)o->channel > s->n) {
			rc_seterr(err, "no channel %d: the file has %zu (surfstat "
			    "--channels lists them)", o->channel, s->n);
			return NULL;
		}
		pick = (size_t)o->channel - 1;
	} else {
		for (k = 0; k < s->n; k++) {
			const rc_grid *c = s->c[k].g;

			if (rc_unit_is_length(c->z_unit[0] ? c->z_unit : c->unit))
				break;
		}
		pick = k < s->n ? k : 0;
	}
	g = s->c[pick].g;
	s->c[pick].g = NULL;
	return g;
}

static rc_grid *
read_grid(FILE *fp, const char *path, const rc_read_opts *o, rc_err *err)
{
	rc_chanset s = { 0 };
	rc_grid *g = NULL;

	if (read_channels(fp, path, o, &s, err) == 0)
		g = select_channel(&s, o, err);
	rc__chanset_free(&s);
	if (g != NULL && rc_grid_read_finish(g, o, err) != 0) {
		rc_grid_free(g);
		g = NULL;
	}
	return g;
}

rc_grid *
rc_grid_read_stream(FILE *fp, const rc_read_opts *o, rc_err *err)
{
	return read_grid(fp, NULL, o, err);
}

/* The file at path opened for reading, or standard input. */
static FILE *
open_input(const char *path, rc_err *err)
{
	struct stat st;
	FILE *fp;

	if (rc_is_stdio(path))
		return stdin;
	if ((fp = fopen(path, "rb")) == NULL) {
		rc_seterr(err, "%s", strerror(errno));
		return NULL;
	}
	if (fstat(fileno(fp), &st) == 0 && S_ISDIR(st.st_mode)) {
		fclose(fp);
		rc_seterr(err, "is a directory");
		return NULL;
	}
	return fp;
}

rc_grid *
rc_grid_read(const char *path, const rc_read_opts *o, rc_err *err)
{
	rc_grid *g;
	FILE *fp;

	if ((fp = open_input(path, err)) == NULL)
		return NULL;
	g = read_grid(fp, fp == stdin ? NULL : path, o, err);
	if (fp != stdin)
		fclose(fp);
	return g;
}

int
rc_grid_list_channels(const char *path, const rc_read_opts *o,
    rc_channel_info **info, size_t *n, rc_err *err)
{
	rc_chanset s = { 0 };
	FILE *fp;
	int r;

	*info = NULL;
	*n = 0;
	if ((fp = open_input(path, err)) == NULL)
		return -1;
	r = read_channels(fp, fp == stdin ? NULL : path, o, &s, err);
	if (fp != stdin)
		fclose(fp);
	if (r == 0 && (*info = rc_calloc(s.n, sizeof(**info), err)) == NULL)
		r = -1;
	for (size_t k = 0; r == 0 && k < s.n; k++) {
		const rc_grid *g = s.c[k].g;
		rc_channel_info *c = &(*info)[k];

		snprintf(c->title, sizeof(c->title), "%s", s.c[k].title);
		strcpy(c->unit, g->unit);
		strcpy(c->z_unit, g->z_unit);
		c->nx = g->nx;
		c->ny = g->ny;
		c->lx = g->lx;
		c->ly = g->ly;
		c->has_mask = g->valid != NULL;
	}
	if (r == 0)
		*n = s.n;
	rc__chanset_free(&s);
	return r;
}

void
rc_read_opts_init(rc_read_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->lx = o->ly = 1;
}

int
rc_format_from_name(const char *path)
{
	static const char *ext[] = { "surf", "npy", "gsf", "txt", "x3p", "nc" };
	const char *base, *dot;

	if (rc_is_stdio(path))
		return RC_FMT_SURF;
	base = strrchr(path, '/');
	base = base ? base + 1 : path;
	if ((dot = strrchr(base, '.')) == NULL || dot == base)
		return RC_FMT_SURF;
	for (int f = 0; f < (int)(sizeof(ext) / sizeof(ext[0])); f++)
		if (strcasecmp(dot + 1, ext[f]) == 0)
			return f;
	return -1;
}

const char *
rc_format_name(enum rc_format f)
{
	switch (f) {
	case RC_FMT_SURF: return "surf";
	case RC_FMT_NPY: return "npy";
	case RC_FMT_GSF: return "gsf";
	case RC_FMT_TXT: return "txt";
	case RC_FMT_X3P: return "x3p";
	case RC_FMT_NC: return "nc";
	}
	return "unknown";
}

int
rc__io_filled_text(const rc_grid *g, char **text, rc_err *err)
{
	*text = NULL;
	if (g->filled == NULL)
		return 0;
	if ((*text = rc_grid_filled_format(g, err)) == NULL)
		return -1;
	if ((*text)[0] == '\0' || strlen(*text) > RC_FILLED_MAX) {
		free(*text);
		*text = NULL;
	}
	return 0;
}

int
rc_format_keeps_filled(const rc_grid *g, enum rc_format fmt, rc_err *err)
{
	char *text;
	int keeps;

	if (rc_grid_filled_count(g) == 0)
		return 1;
	if (fmt != RC_FMT_SURF && fmt != RC_FMT_TXT && fmt != RC_FMT_GSF)
		return 0;
	if (rc__io_filled_text(g, &text, err) != 0)
		return -1;
	keeps = text != NULL;
	free(text);
	return keeps;
}

int
rc_grid_write_stream(const rc_grid *g, FILE *fp, enum rc_format fmt,
    rc_err *err)
{
	int r;

	switch (fmt) {
	case RC_FMT_SURF: r = rc__surf_write(g, fp, err); break;
	case RC_FMT_NPY: r = rc__npy_write(g, fp, err); break;
	case RC_FMT_GSF: r = rc__gsf_write(g, fp, err); break;
	case RC_FMT_TXT: r = rc__txt_write(g, fp, err); break;
	case RC_FMT_X3P: r = rc__x3p_write(g, fp, err); break;
	case RC_FMT_NC: r = rc__nc_write(g, fp, err); break;
	default: return rc_seterr(err, "unknown output format %d", (int)fmt);
	}
	if (r == 0 && (fflush(fp) != 0 || ferror(fp)))
		return rc_seterr(err, "write error: %s", strerror(errno));
	return r;
}

int
rc_grid_write(const rc_grid *g, const char *path, enum rc_format fmt,
    rc_err *err)
{
	rc_atomic a;

	if (rc_atomic_open(&a, path, err) != 0)
		return -1;
	if (rc_grid_write_stream(g, a.fp, fmt, err) != 0) {
		rc_atomic_abort(&a);
		return -1;
	}
	return rc_atomic_commit(&a, err);
}
