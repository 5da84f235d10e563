/* SPDX-License-Identifier: GPL-3.0-or-later */
/* md5.h - the MD5 message digest (RFC 1321), for the checksums that ISO
 * 25178-72 (x3p) containers carry.  Not for security. */
#ifndef RC_MD5_H
#define RC_MD5_H

#include <stddef.h>
#include <stdint.h>

typedef struct rc_md5 {
	uint32_t h[4];
	uint64_t len;		/* bytes so far */
	unsigned char buf[64];
	size_t nbuf;
} rc_md5;

void rc_md5_init(rc_md5 *m);
void rc_md5_update(rc_md5 *m, const void *p, size_t n);
/* The 16-byte digest; m is spent. */
void rc_md5_final(rc_md5 *m, unsigned char out[16]);
/* Digest of one buffer as 32 lower-case hex digits and a NUL. */
void rc_md5_hex(const void *p, size_t n, char hex[33]);

#endif
