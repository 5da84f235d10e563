/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rc_err.c - error messages and checked allocation. */
#include "rc_err.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

int
rc_seterr(rc_err *err, const char *fmt, ...)
{
	va_list ap;

	if (err == NULL)
		return -1;
	va_start(ap, fmt);
	vsnprintf(err->msg, sizeof(err->msg), fmt, ap);
	va_end(ap);
	return -1;
}

size_t
rc_mul_size(size_t a, size_t b)
{
	if (a != 0 && b > SIZE_MAX / a)
		return 0;
	return a * b;
}

void *
rc_malloc(size_t n, rc_err *err)
{
	void *p = malloc(n ? n : 1);

	if (p == NULL)
		rc_seterr(err, "out of memory (asked for %zu bytes)", n);
	return p;
}

void *
rc_calloc(size_t count, size_t size, rc_err *err)
{
	void *p;

	if (count != 0 && rc_mul_size(count, size) == 0) {
		rc_seterr(err, "allocation size overflows (%zu x %zu bytes)",
		    count, size);
		return NULL;
	}
	p = calloc(count ? count : 1, size ? size : 1);
	if (p == NULL)
		rc_seterr(err, "out of memory (asked for %zu x %zu bytes)",
		    count, size);
	return p;
}
