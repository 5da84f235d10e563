/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_internal.h - what the format readers and writers share.
 *
 * Readers never seek: the input may be a pipe.  rc_in wraps a FILE with a
 * buffer the format detector and the header parsers can peek into, and
 * counts the bytes consumed so far (the data offset of a file).
 *
 * Private to the library (not installed): its functions carry the
 * internal prefix rc__, as in solver_impl.h and cstats_impl.h.
 */
#ifndef RC_IO_INTERNAL_H
#define RC_IO_INTERNAL_H

#include <stdint.h>
#include <stdio.h>
#include "grid.h"
#include "io.h"
#include "rc_err.h"

#define RC_IN_BUFSIZE 65536
/* No header of any format may be longer than this. */
#define RC_HEADER_MAX ((size_t)1 << 20)

typedef struct rc_in {
	FILE *fp;
	unsigned char buf[RC_IN_BUFSIZE];
	size_t pos, len;	/* unread bytes are buf[pos .. len) */
	uint64_t consumed;	/* bytes handed to the caller so far */
	int eof;		/* the FILE reported end of file */
	int error;		/* errno of a read error, 0 if none */
} rc_in;

/* How raw values are laid out in a file. */
typedef struct rc_layout {
	size_t elsize;		/* 4 (float32) or 8 (float64) */
	int big_endian;
	int fortran;		/* column-major (npy fortran_order) */
} rc_layout;

void rc__in_init(rc_in *in, FILE *fp);
/* Buffer at least n bytes (n <= RC_IN_BUFSIZE) if the input has them;
 * *p points at them.  Returns how many are available (< n only at end). */
size_t rc__in_peek(rc_in *in, size_t n, const unsigned char **p);
int rc__in_getc(rc_in *in);
size_t rc__in_read(rc_in *in, void *dst, size_t n);
/* One line into buf (NUL-terminated, without the newline); *len its
 * length (it may contain NUL bytes).  Returns 1 for a line ended by '\n',
 * 2 for a last line without one, 0 at end of input, -1 if the line does
 * not fit in cap - 1 bytes. */
int rc__in_line(rc_in *in, char *buf, size_t cap, size_t *len);
/* A read error becomes an rc_err message; returns -1 if there was one. */
int rc__in_check(const rc_in *in, rc_err *err);

/* Read nx*ny values laid out as l into a new grid of that shape, never
 * allocating more than the input proves to hold, and check that nothing
 * follows them. */
rc_grid *rc__in_read_values(rc_in *in, size_t nx, size_t ny, double lx,
    double ly, const rc_layout *l, rc_err *err);
/* A grid whose values are not initialised (the reader fills them). */
rc_grid *rc__io_grid_alloc(size_t nx, size_t ny, double lx, double ly,
    rc_err *err);

/* A header line "key = value" of .surf and .gsf split in place, the
 * blanks around key and value (and a trailing CR) dropped; -1 without
 * '='.  A key is valid when it is one or more of [A-Za-z0-9_.-] (the
 * names grid metadata can hold). */
int rc__header_split(char *line, char **key, char **val);
/* s without the blanks around it (and a trailing CR), in place. */
char *rc__header_trim(char *s);
int rc__header_key_valid(const char *key);
/* Parsers of header values; 0 on success. */
int rc__parse_size(const char *s, size_t *v);
int rc__parse_double(const char *s, double *v);
/* Make a string printable for an error message (at most 40 characters). */
const char *rc__io_quote(char *buf, size_t len, const char *s, size_t n);

/* Little-endian encoding, independent of the host's byte order. */
void rc__put_le64(unsigned char *p, double v);
void rc__put_le32f(unsigned char *p, float v);
void rc__put_le32(unsigned char *p, uint32_t v);
void rc__put_le16(unsigned char *p, uint16_t v);
double rc__get_le64(const unsigned char *p);
uint32_t rc__get_le32(const unsigned char *p);
uint16_t rc__get_le16(const unsigned char *p);
/* Write n bytes; -1 with a message on failure. */
int rc__io_write(FILE *fp, const void *p, size_t n, rc_err *err);
/* Values as float64 LE (elsize 8) or float32 LE (elsize 4). */
int rc__io_write_values(FILE *fp, const double *z, size_t n, size_t elsize,
    rc_err *err);

/* The filled points as a header writes them: *text malloc'ed, or NULL
 * when g has none or their list exceeds RC_FILLED_MAX (left out). */
int rc__io_filled_text(const rc_grid *g, char **text, rc_err *err);

/* The format readers (after detection) and writers. */
rc_grid *rc__surf_read(rc_in *in, const rc_read_opts *o, rc_err *err);
rc_grid *rc__npy_read(rc_in *in, const rc_read_opts *o, rc_err *err);
rc_grid *rc__gsf_read(rc_in *in, const rc_read_opts *o, rc_err *err);
rc_grid *rc__txt_read(rc_in *in, const rc_read_opts *o, rc_err *err);
int rc__surf_write(const rc_grid *g, FILE *fp, rc_err *err);
/* The .surf header alone, for MPI-IO (lib/mpi/): write g's header for a
 * grid of ny rows (g's own values are not written); read a header from
 * fp into a grid of nx x 1 (values zero), the rows into *ny and the byte
 * offset of the values into *data_offset. */
int rc__surf_write_header(const rc_grid *g, size_t ny, FILE *fp, rc_err *err);
rc_grid *rc__surf_read_header(FILE *fp, size_t *ny, size_t *data_offset,
    rc_err *err);
int rc__npy_write(const rc_grid *g, FILE *fp, rc_err *err);
int rc__gsf_write(const rc_grid *g, FILE *fp, rc_err *err);
int rc__txt_write(const rc_grid *g, FILE *fp, rc_err *err);

/* The channels of one file (.gwy, x3p, netCDF, vendor formats through
 * Gwyddion); a single-channel format gives one. */
typedef struct rc_channel {
	rc_grid *g;
	char title[128];
} rc_channel;
typedef struct rc_chanset {
	rc_channel *c;
	size_t n, cap;
} rc_chanset;
/* The title of a single-channel file's grid: a GSF's Title field or the
 * "# Channel:" line of Gwyddion's text export, which their readers keep as
 * the metadata Title and channel (a grid converted from them keeps it);
 * "" if neither. */
const char *rc__io_title(const rc_grid *g);
/* Append g (the set owns it from now on, also on failure). */
int rc__chanset_add(rc_chanset *s, rc_grid *g, const char *title, rc_err *err);
void rc__chanset_free(rc_chanset *s);
/* Store a unit string from a file in dst (32 bytes): "\xc2\xb5m" and
 * "\xce\xbcm" become "um", anything too long is an error. */
int rc__io_set_unit(char dst[32], const char *u, rc_err *err);
/* Units of a length unit per metre (1e6 for "um"), 0 if u is none
 * (the length units are those of units.h). */
double rc__io_per_metre(const char *u);

/* Input decoded before detection (io_decode.c): gzip (magic 1f 8b) and
 * UTF-16 text (after its byte-order mark FF FE or FE FF, which the
 * decoder reads) as a read-only stream of the plain bytes, pulling from
 * in.  msg (RC_DECODE_MSG bytes, the caller's) says why decoding failed
 * when a read from the stream fails; "" otherwise. */
#define RC_DECODE_MSG 160
enum rc_decoding { RC_DECODE_GZIP, RC_DECODE_UTF16 };
FILE *rc__decode_open(rc_in *in, enum rc_decoding how, char *msg,
    rc_err *err);
/* What the gzip data b[0..n) decode to, in bytes, counted up to just
 * past limit (then it stops); a damaged stream counts what decodes before
 * the damage (its reader reports that). */
uint64_t rc__gzip_size(const unsigned char *b, size_t n, uint64_t limit);

/* The rest of the input in memory (*buf malloc'ed, *len bytes), growing
 * with what the input really holds. */
int rc__in_slurp(rc_in *in, unsigned char **buf, size_t *len, rc_err *err);
/* Exactly n bytes into a new buffer, allocating no more than about twice
 * what the input holds; "truncated" if it holds fewer. */
int rc__in_read_exact(rc_in *in, size_t n, unsigned char **buf, rc_err *err);

/* Readers of whole files held in memory: every channel into s. */
int rc__gwy_read(const unsigned char *buf, size_t len, rc_chanset *s,
    rc_err *err);
int rc__x3p_read(const unsigned char *buf, size_t len, rc_chanset *s,
    rc_err *err);
/* 0 if the HDF5 file image buf names no other file (external links,
 * external storage, virtual data sets); lib: libnetcdf's dlopen handle.
 * io_h5check.c. */
int rc__h5_self_contained(void *lib, const unsigned char *buf, size_t len,
    rc_err *err);
/* netCDF: o gives the cell size when the file has none. */
int rc__nc_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err);
rc_grid *rc__sdf_read(rc_in *in, const rc_read_opts *o, rc_err *err);
/* Any other format: Gwyddion converts the len bytes at buf (spooled to a
 * file alone in a private temporary directory; name, the file's name or
 * NULL, gives its extension) to .gwy, which rc__gwy_read reads.  Formats
 * whose data are in another file are refused (io_gwyddion.c). */
int rc__gwyddion_read(const char *name, const unsigned char *buf, size_t len,
    rc_chanset *s, rc_err *err);
/* The NaN values of g its missing points (g->valid), as a reader that
 * lists channels must say before rc_grid_read_finish does. */
int rc__io_nan_missing(rc_grid *g, rc_err *err);
/* Instrument formats of other vendors read here, each from its bytes in
 * memory: _is says whether the first n bytes (the whole file for NMS,
 * which has no magic) are of the format; _read puts every channel into s
 * (o unused; the signature of io.c's readers of whole files). */
int rc__tmd_is(const unsigned char *p, size_t n);
int rc__tmd_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err);
int rc__opdx_is(const unsigned char *p, size_t n);
int rc__opdx_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err);
int rc__nms_is(const unsigned char *buf, size_t len);
int rc__nms_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err);
int rc__mnt_is(const unsigned char *p, size_t n);
int rc__mnt_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err);
int rc__x3p_write(const rc_grid *g, FILE *fp, rc_err *err);

/* Zip containers held in memory (io_zip.c): open one (what names the
 * format in messages; zip_discard closes it), and read entry name into a
 * new buffer, exactly want bytes or (want 0) at most limit, never
 * allocating much more than decompression really gives. */
struct zip;
struct zip *rc__zip_open_mem(const unsigned char *buf, size_t len,
    const char *what, rc_err *err);
int rc__zip_entry(struct zip *za, const char *what, const char *name,
    uint64_t want, uint64_t limit, unsigned char **buf, size_t *len,
    rc_err *err);
/* An Excel workbook (io_xlsx.c): a Mitutoyo SurfTest export's profile,
 * else the first sheet as a table of columns (io_txt.c's reading). */
int rc__xlsx_read(const unsigned char *buf, size_t len,
    const rc_read_opts *o, rc_chanset *s, rc_err *err);
/* A reader of every channel of bytes in memory at a nesting depth, as
 * rc__read_member below. */
typedef int (*rc__member_reader)(const unsigned char *b, size_t n,
    const rc_read_opts *o, rc_chanset *s, int depth, rc_err *err);
/* A contact.engineering container (io_ce.c): one channel per
 * measurement meta.yml lists, each member read by read_member (io.c's
 * rc__read_member, passed down so that the container's reader does not
 * call back into the file that calls it: tests/e2e/callgraph.sh). */
int rc__ce_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, int depth, rc__member_reader read_member, rc_err *err);
/* Every channel of the bytes b[0..n) (io.c), read as a file of unknown
 * name at nesting depth (a member of a container is at depth 1: no
 * container nests in it). */
int rc__read_member(const unsigned char *b, size_t n, const rc_read_opts *o,
    rc_chanset *s, int depth, rc_err *err);
/* Text (io_txt.c) held in memory: the columns of a table a reader
 * made, read as a text file. */
rc_grid *rc__txt_read_mem(const char *text, size_t len,
    const rc_read_opts *o, rc_err *err);
int rc__nc_write(const rc_grid *g, FILE *fp, rc_err *err);

#endif
