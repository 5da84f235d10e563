/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rc_err.h - how the library reports errors.
 *
 * Every fallible library function takes an rc_err * as its last argument,
 * returns 0 (or a non-NULL pointer) on success and -1 (or NULL) on failure,
 * having written a one-line reason into err->msg.  The library never prints
 * and never exits; the tools decide what to do with the message.
 */
#ifndef RC_ERR_H
#define RC_ERR_H

#include <stddef.h>

#define RC_ERRLEN 512

typedef struct rc_err {
	char msg[RC_ERRLEN];
} rc_err;

/* printf-style; a NULL err is allowed and ignored. Returns -1 for tail calls. */
int rc_seterr(rc_err *err, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));

/* Overflow-checked a*b; returns 0 on overflow (which is never a valid size
 * for our purposes since callers pass non-zero factors). */
size_t rc_mul_size(size_t a, size_t b);

/* malloc/calloc that report the size asked for on failure. */
void *rc_malloc(size_t n, rc_err *err);
void *rc_calloc(size_t count, size_t size, rc_err *err);

#endif
