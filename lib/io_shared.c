/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_shared.c - what the format readers and writers share
 * (io_internal.h): the buffered input and the decoding of raw values,
 * the "key = value" header lines of .surf and .gsf, parsers of header
 * values, little-endian encoding, writing helpers, and the checks every
 * grid passes after reading (rc_grid_read_finish).  It calls no reader
 * or writer, so the format files depend on it and io.c on both, without
 * cycles. */
#include "io.h"
#include "io_internal.h"
#include "fft.h"
#include "units.h"

#include <ctype.h>
#include <errno.h>
#include <fftw3.h>
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
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
	void *block;

	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		return NULL;
	if ((z = rc_grid_values(nx * ny, &block, err)) == NULL)
		return NULL;
	/* A 1x1 grid carries the defaults; its value array is replaced. */
	if ((g = rc_grid_new(1, 1, lx, ly, err)) == NULL) {
		rc_fft_huge_free(z, block);
		return NULL;
	}
	rc_fft_huge_free(g->z, g->z_block);
	g->z = z;
	g->z_block = block;
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

/* 1 if the file's values are this host's doubles in the grid's order. */
static int
decode_is_copy(const rc_layout *l)
{
	return l->elsize == 8 && !l->big_endian && !l->fortran &&
	    host_is_little_endian();
}

static void
decode(const unsigned char *p, size_t first, size_t n, const rc_layout *l,
    rc_grid *g)
{
	if (decode_is_copy(l)) {
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

/* Read want bytes into dst, adding the count read to *got and into *r;
 * -1 with a message when fewer came (need: all the data bytes expected). */
static int
read_piece(rc_in *in, void *dst, size_t want, size_t need, size_t *got,
    size_t *r, rc_err *err)
{
	*r = rc__in_read(in, dst, want);
	*got += *r;
	if (*r == want)
		return 0;
	if (rc__in_check(in, err) == 0)
		rc_seterr(err, "truncated: expected %zu data bytes, got %zu", need,
		    *got);
	return -1;
}

/* Long: the two ways in (a file of known size, a pipe read piece by
 * piece) share the decoding and the error paths. */
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
		/* This host's doubles: read into the grid, no buffer between
		 * (at 512^2 a 2 MB buffer's first touch and copy were a
		 * quarter of the reading). */
		if (decode_is_copy(l)) {
			size_t r;

			if (read_piece(in, g->z, need, need, &got, &r, err) != 0)
				goto fail;
		} else {
			if ((buf = rc_malloc(CHUNK < need ? CHUNK : need, err)) ==
			    NULL)
				goto fail;
			for (k = 0; got < need; ) {
				size_t want = need - got < CHUNK ? need - got :
				    CHUNK, r;

				if (read_piece(in, buf, want, need, &got, &r,
				    err) != 0)
					goto fail;
				/* A piece holds whole values: CHUNK is a
				 * multiple of 8. */
				decode(buf, k, r / l->elsize, l, g);
				k += r / l->elsize;
			}
			free(buf);
			buf = NULL;
		}
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
			/* counted before the check: fail frees it */
			if (read_piece(in, chunk[nchunk++], want, need, &got, &r,
			    err) != 0)
				goto fail;
			bytes[nchunk - 1] = r;
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

double
rc__get_le64(const unsigned char *p)
{
	uint64_t u = 0;
	double d;

	for (int k = 7; k >= 0; k--)
		u = u << 8 | p[k];
	memcpy(&d, &u, 8);
	return d;
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
rc__io_nan_missing(rc_grid *g, rc_err *err)
{
	size_t n = rc_grid_size(g), k;

	for (k = 0; k < n && !isnan(g->z[k]); k++)
		;
	if (k == n)
		return 0;
	if (g->valid == NULL && (g->valid = rc_malloc(n, err)) == NULL)
		return -1;
	for (k = 0; k < n; k++)
		g->valid[k] = !isnan(g->z[k]);
	return 0;
}

int
rc_grid_read_finish(rc_grid *g, const rc_read_opts *o, rc_err *err)
{
	if (check_values(g, o, err) != 0)
		return -1;
	if (o == NULL)
		return 0;
	if (o->periodic == RC_PERIODIC_YES && g->x != NULL)
		return rc_seterr(err, "--periodic: a line scan not uniformly "
		    "spaced is a measurement, not one period of a surface");
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
rc__header_key_valid(const char *key)
{
	for (const char *p = key; *p; p++)
		if (!(*p == '_' || *p == '-' || *p == '.' ||
		    (*p >= 'a' && *p <= 'z') || (*p >= 'A' && *p <= 'Z') ||
		    (*p >= '0' && *p <= '9')))
			return 0;
	return *key != '\0';
}

char *
rc__header_trim(char *s)
{
	char *e;

	while (*s == ' ' || *s == '\t')
		s++;
	e = s + strlen(s);
	while (e > s && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r'))
		e--;
	*e = '\0';
	return s;
}

int
rc__header_split(char *line, char **key, char **val)
{
	char *eq = strchr(line, '=');

	if (eq == NULL)
		return -1;
	*eq = '\0';
	*key = rc__header_trim(line);
	*val = rc__header_trim(eq + 1);
	return 0;
}

/* The reading defaults (io.h), here below io.c and the readers it
 * dispatches to, which set up their members' reading with them. */
void
rc_read_opts_init(rc_read_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->lx = o->ly = 1;
}
