/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_decode.c - input that must be decoded before any reader sees it:
 * gzip-compressed files (any format inside, one or more gzip members,
 * zlib's inflate) and UTF-16 text with a byte-order mark (glibc's iconv
 * to UTF-8).  Each becomes a read-only FILE (fopencookie) that pulls
 * from the rc_in it wraps, so nothing is held whole and a pipe works;
 * io.c then detects the format of the decoded bytes as of any input.
 */
#define _GNU_SOURCE
#include "io_internal.h"

#include <errno.h>
#include <iconv.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>

#define IN_CHUNK 16384

typedef struct decoder {
	rc_in *in;
	int gzip;			/* else UTF-16 */
	z_stream z;
	iconv_t cd;
	unsigned char ibuf[IN_CHUNK];	/* input taken from in, not yet used */
	size_t ipos, ilen;
	int in_end;			/* in has no more bytes */
	int done;			/* the decoded stream has ended */
	char *msg;			/* the caller's: why decoding failed */
} decoder;

/* More input into ibuf (what is left moved to its start). */
static void
refill(decoder *d)
{
	if (d->ipos > 0) {
		memmove(d->ibuf, d->ibuf + d->ipos, d->ilen - d->ipos);
		d->ilen -= d->ipos;
		d->ipos = 0;
	}
	if (!d->in_end && d->ilen < sizeof(d->ibuf)) {
		size_t got = rc__in_read(d->in, d->ibuf + d->ilen,
		    sizeof(d->ibuf) - d->ilen);

		d->ilen += got;
		if (got == 0)
			d->in_end = 1;
	}
}

static ssize_t
gz_read(decoder *d, char *out, size_t n)
{
	size_t made = 0;

	while (made < n && !d->done) {
		int r;

		if (d->ipos == d->ilen)
			refill(d);
		d->z.next_in = d->ibuf + d->ipos;
		d->z.avail_in = (uInt)(d->ilen - d->ipos);
		d->z.next_out = (unsigned char *)out + made;
		d->z.avail_out = (uInt)(n - made > UINT32_MAX / 2 ? UINT32_MAX / 2 :
		    n - made);
		r = inflate(&d->z, Z_NO_FLUSH);
		made = (size_t)((char *)d->z.next_out - out);
		d->ipos = d->ilen - d->z.avail_in;
		if (r == Z_STREAM_END) {
			/* Another member may follow (gzip allows concatenation). */
			refill(d);
			if (d->ipos == d->ilen)
				d->done = 1;
			else if (inflateReset(&d->z) != Z_OK) {
				snprintf(d->msg, RC_DECODE_MSG, "gzip: cannot restart");
				return -1;
			}
		} else if (r == Z_BUF_ERROR && d->in_end && d->ipos == d->ilen) {
			snprintf(d->msg, RC_DECODE_MSG,
			    "gzip-compressed input is truncated");
			return -1;
		} else if (r != Z_OK && r != Z_BUF_ERROR) {
			snprintf(d->msg, RC_DECODE_MSG, "gzip-compressed input is "
			    "corrupt (%s)", d->z.msg ? d->z.msg : "inflate failed");
			return -1;
		}
	}
	return (ssize_t)made;
}

static ssize_t
utf16_read(decoder *d, char *out, size_t n)
{
	char *op = out;
	size_t ol = n;

	while (ol > 0 && !d->done) {
		char *ip;
		size_t il;

		if (d->ilen - d->ipos < 4)
			refill(d);
		if (d->ipos == d->ilen) {
			d->done = 1;
			break;
		}
		ip = (char *)d->ibuf + d->ipos;
		il = d->ilen - d->ipos;
		if (iconv(d->cd, &ip, &il, &op, &ol) == (size_t)-1 &&
		    errno != E2BIG && (errno != EINVAL || d->in_end)) {
			snprintf(d->msg, RC_DECODE_MSG, "UTF-16 text: %s",
			    errno == EINVAL ? "it ends inside a character" :
			    "invalid character (an unpaired surrogate)");
			return -1;
		}
		d->ipos = d->ilen - il;
	}
	return (ssize_t)(op - out);
}

static ssize_t
cookie_read(void *c, char *out, size_t n)
{
	decoder *d = c;
	ssize_t r;

	if (d->msg[0] != '\0')
		return -1;
	r = d->gzip ? gz_read(d, out, n) : utf16_read(d, out, n);
	if (r < 0)
		errno = EILSEQ;
	return r;
}

static int
cookie_close(void *c)
{
	decoder *d = c;

	if (d->gzip)
		inflateEnd(&d->z);
	else
		iconv_close(d->cd);
	free(d);
	return 0;
}

FILE *
rc__decode_open(rc_in *in, enum rc_decoding how, char *msg, rc_err *err)
{
	cookie_io_functions_t io = { .read = cookie_read, .close = cookie_close };
	decoder *d = rc_calloc(1, sizeof(*d), err);
	FILE *fp;

	if (d == NULL)
		return NULL;
	d->in = in;
	d->msg = msg;
	msg[0] = '\0';
	d->gzip = how == RC_DECODE_GZIP;
	if (d->gzip) {
		/* 16 + MAX_WBITS: a gzip header, not a zlib one */
		if (inflateInit2(&d->z, 16 + MAX_WBITS) != Z_OK) {
			free(d);
			rc_seterr(err, "gzip: cannot initialise zlib");
			return NULL;
		}
	} else {
		unsigned char bom[2];

		if (rc__in_read(in, bom, 2) != 2) {
			free(d);
			rc_seterr(err, "UTF-16 text: no byte-order mark");
			return NULL;
		}
		d->cd = iconv_open("UTF-8", bom[0] == 0xff ? "UTF-16LE" : "UTF-16BE");
		if (d->cd == (iconv_t)-1) {
			free(d);
			rc_seterr(err, "UTF-16 text: iconv cannot convert it: %s",
			    strerror(errno));
			return NULL;
		}
	}
	if ((fp = fopencookie(d, "r", io)) == NULL) {
		rc_seterr(err, "%s", strerror(errno));
		cookie_close(d);
		return NULL;
	}
	return fp;
}

uint64_t
rc__gzip_size(const unsigned char *b, size_t n, uint64_t limit)
{
	char msg[RC_DECODE_MSG], chunk[65536];
	uint64_t size = 0;
	rc_err err;
	rc_in in;
	FILE *mem, *fp;
	size_t got;

	if ((mem = fmemopen((void *)b, n, "rb")) == NULL)
		return 0;
	rc__in_init(&in, mem);
	if ((fp = rc__decode_open(&in, RC_DECODE_GZIP, msg, &err)) != NULL) {
		while (size <= limit &&
		    (got = fread(chunk, 1, sizeof(chunk), fp)) > 0)
			size += got;
		fclose(fp);
	}
	fclose(mem);
	return size;
}
