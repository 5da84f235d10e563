/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io.c - format detection and dispatch: which reader a file goes to,
 * channel selection, the read and write entry points (the helpers the
 * readers and writers share are io_shared.c). */
#define _GNU_SOURCE	/* memmem */
#include "io.h"
#include "io_internal.h"
#include "atomic.h"
#include "units.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>

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
    rc_chanset *, int, rc_err *);

static int
gwy_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	(void)o;
	(void)depth;
	return rc__gwy_read(b, n, s, err);
}

/* The vendor readers of whole files take no nesting depth. */
static int
tmd_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	(void)depth;
	return rc__tmd_read(b, n, o, s, err);
}

static int
opdx_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	(void)depth;
	return rc__opdx_read(b, n, o, s, err);
}

/* A zip: an x3p, else an Excel workbook or a contact.engineering
 * container (their part names are stored uncompressed). */
static int
zip_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	if (rc__x3p_read(b, n, s, err) == 0)
		return 0;
	if (memmem(b, n, "xl/workbook.xml", 15) != NULL)
		return rc__xlsx_read(b, n, o, s, err);
	if (memmem(b, n, "meta.yml", 8) != NULL)
		return rc__ce_read(b, n, o, s, depth, rc__read_member, err);
	return -1;
}

/* netCDF, classic or netCDF-4; an HDF5 file that is not in the
 * contact.engineering layout is said to be one, with what lists it. */
static int
nc_mem(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	char inner[sizeof(err->msg)];

	(void)depth;
	if (rc__nc_read(b, n, o, s, err) == 0)
		return 0;
	if (!starts(b, n, "\x89HDF\r\n\x1a\n", 8))
		return -1;
	snprintf(inner, sizeof(inner), "%s", err->msg);
	return rc_seterr(err, "an HDF5 file (netCDF-4 or plain HDF5): %s; h5ls "
	    "(Debian package hdf5-tools) lists its data sets", inner);
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
	rc_err gerr, terr, merr;
	rc_in *in2 = NULL;
	rc_grid *g = NULL;
	FILE *fp = NULL;
	int ole2;

	if (rc__in_slurp(in, &buf, &len, err) != 0)
		return -1;
	/* a compound document: MountainsMap's, else maybe Gwyddion's */
	if ((ole2 = rc__mnt_is(buf, len)) && rc__mnt_read(buf, len, o, s,
	    &merr) == 0) {
		free(buf);
		return 0;
	}
	if (rc__nms_is(buf, len)) {	/* no magic: known by its length */
		int r = rc__nms_read(buf, len, o, s, err);

		free(buf);
		return r;
	}
	if (rc__gwyddion_read(path, buf, len, s, &gerr) == 0) {
		free(buf);
		return 0;
	}
	rc__chanset_free(s);
	fp = fmemopen(buf, len, "rb");
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
	if (ole2)	/* our reader's word on it, not the text reader's */
		return rc_seterr(err, "a Microsoft compound document (OLE2) not "
		    "read: %s; Gwyddion's converter: %s", merr.msg, gerr.msg);
	return rc_seterr(err, "not a format of ours; Gwyddion's converter: %s; "
	    "read as text: %s", gerr.msg, terr.msg);
}

/* Does the text at path open with a header, a line that is no number
 * (after blank lines and '#' comments)?  Only such text can be the header
 * of an instrument format; numbers the text reader refused are a matrix
 * with a fault, which its message locates. */
static int
opens_with_header(const char *path)
{
	char line[256];
	FILE *fp = fopen(path, "rb");
	int header = 0;

	if (fp == NULL)
		return 0;
	while (fgets(line, sizeof(line), fp) != NULL) {
		const char *p = line + strspn(line, " \t\r\n,;");

		if (*p == '\0' || *p == '#')
			continue;
		header = strchr("+-.0123456789", *p) == NULL &&
		    strncasecmp(p, "nan", 3) != 0 && strncasecmp(p, "inf", 3) != 0;
		break;
	}
	fclose(fp);
	return header;
}

/* Text our text reader refused (terr): it may be the text header of an
 * instrument format (Nanosurf .nid, WSxM .stp), which Gwyddion reads. */
static int
text_or_vendor(const char *path, const rc_err *terr, rc_chanset *s,
    rc_err *err)
{
	unsigned char *buf = NULL;
	size_t len = 0;
	rc_err gerr;
	rc_in *in2 = NULL;
	FILE *fp;
	int r = -1;

	if ((fp = fopen(path, "rb")) == NULL) {
		rc_seterr(&gerr, "%s", strerror(errno));
	} else if ((in2 = rc_malloc(sizeof(*in2), &gerr)) != NULL) {
		rc__in_init(in2, fp);
		if (rc__in_slurp(in2, &buf, &len, &gerr) == 0)
			r = rc__gwyddion_read(path, buf, len, s, &gerr);
	}
	free(in2);
	free(buf);
	if (fp != NULL)
		fclose(fp);
	if (r == 0)
		return 0;
	rc__chanset_free(s);
	return rc_seterr(err, "%s (read as text); Gwyddion's converter: %s",
	    terr->msg, gerr.msg);
}

static int read_channels(FILE *fp, const char *path, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err);

/* Set in the nesting depth below a gzip layer: a container's member
 * (depth 1) may be gzip-compressed, a gzip layer may not hold another. */
#define DEPTH_IN_GZIP 0x100

/* gzip or UTF-16 input: the channels of what it decodes to.  One layer
 * of gzip (a .gz of a .gz is refused, so no nesting multiplies). */
static int
decoded(rc_in *in, enum rc_decoding how, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	char msg[RC_DECODE_MSG];
	FILE *fp;
	int r;

	if ((depth & DEPTH_IN_GZIP) && how == RC_DECODE_GZIP)
		return rc_seterr(err, "gzip inside gzip: decompress the outer "
		    "layer first (gunzip)");
	if ((fp = rc__decode_open(in, how, msg, err)) == NULL)
		return -1;
	r = read_channels(fp, NULL, o, s, (depth + 1) |
	    (how == RC_DECODE_GZIP ? DEPTH_IN_GZIP : 0), err);
	fclose(fp);
	if (msg[0] != '\0') {
		rc__chanset_free(s);
		return rc_seterr(err, "%s", msg);
	}
	if (r != 0 && how == RC_DECODE_GZIP) {
		char inner[sizeof(err->msg)];

		snprintf(inner, sizeof(inner), "%s", err->msg);
		rc_seterr(err, "gzip-compressed: %s", inner);
	}
	return r;
}

/* Every channel of the input; path is the file fp reads, if known (a
 * vendor file is then handed to Gwyddion as it is). */
static int
read_channels(FILE *fp, const char *path, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	rc_in *in;
	const unsigned char *p;
	unsigned char *buf = NULL;
	mem_reader whole = NULL;
	rc_grid *g = NULL;
	struct stat st;
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
	if (starts(p, n, "\x1f\x8b", 2)) {
		r = decoded(in, RC_DECODE_GZIP, o, s, depth, err);
		goto out;
	} else if (starts(p, n, "\xff\xfe", 2) || starts(p, n, "\xfe\xff", 2)) {
		r = decoded(in, RC_DECODE_UTF16, o, s, depth, err);
		goto out;
	}
	if (starts(p, n, "\xef\xbb\xbf", 3)) {	/* UTF-8's byte-order mark */
		unsigned char bom[3];

		rc__in_read(in, bom, sizeof(bom));
		n = rc__in_peek(in, 32, &p);
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
	else if (rc__tmd_is(p, n))
		whole = tmd_mem;
	else if (rc__opdx_is(p, n))
		whole = opdx_mem;
	else if (starts(p, n, "PK\x03\x04", 4))
		whole = zip_mem;
	else if (starts(p, n, "CDF\x01", 4) || starts(p, n, "CDF\x02", 4) ||
	    starts(p, n, "CDF\x05", 4) || starts(p, n, "\x89HDF\r\n\x1a\n", 8))
		whole = nc_mem;
	else if (looks_binary(in)) {
		r = vendor(in, path, o, s, err);
		goto out;
	} else if ((g = rc__txt_read(in, o, err)) == NULL && path != NULL &&
	    stat(path, &st) == 0 && S_ISREG(st.st_mode) &&
	    opens_with_header(path)) {
		rc_err terr = *err;

		r = text_or_vendor(path, &terr, s, err);
		goto out;
	}
	if (whole != NULL) {
		if (rc__in_slurp(in, &buf, &len, err) == 0)
			r = whole(buf, len, o, s, depth, err);
		goto out;
	}
	if (g != NULL)
		r = rc__chanset_add(s, g, rc__io_title(g), err);
out:
	free(buf);
	free(in);
	return r;
}

int
rc__read_member(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err)
{
	FILE *fp;
	int r;

	if (n == 0)
		return rc_seterr(err, "empty input");
	if ((fp = fmemopen((void *)b, n, "rb")) == NULL)
		return rc_seterr(err, "%s", strerror(errno));
	r = read_channels(fp, NULL, o, s, depth, err);
	fclose(fp);
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

	if (read_channels(fp, path, o, &s, 0, err) == 0)
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
	rc_read_opts all;
	FILE *fp;
	int r;

	*info = NULL;
	*n = 0;
	if (o != NULL)
		all = *o;
	else
		rc_read_opts_init(&all);
	all.channel = 0;	/* a listing reads every channel (a container */
	all.channel_name = NULL;	/* reads only the chosen one otherwise) */
	if ((fp = open_input(path, err)) == NULL)
		return -1;
	r = read_channels(fp, fp == stdin ? NULL : path, &all, &s, 0, err);
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
		/* missing points: a mask, or NaN (which a read of the
		 * channel turns into one: rc_grid_read_finish) */
		c->has_mask = g->valid != NULL;
		for (size_t i = 0; !c->has_mask && i < rc_grid_size(g); i++)
			c->has_mask = isnan(g->z[i]);
	}
	if (r == 0)
		*n = s.n;
	rc__chanset_free(&s);
	return r;
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

	if (g->x != NULL)	/* no format keeps the positions */
		return rc_seterr(err, "a line scan not uniformly spaced (%zu "
		    "positions) cannot be written as a grid; --uniform resamples "
		    "it onto a uniform step", g->nx);
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
