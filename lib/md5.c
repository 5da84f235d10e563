/* SPDX-License-Identifier: GPL-3.0-or-later */
/* md5.c - MD5 as specified in RFC 1321, written from the specification. */
#include "md5.h"

#include <string.h>

/* Per-step left rotations, four per round. */
static const unsigned char shift[4][4] = {
	{ 7, 12, 17, 22 }, { 5, 9, 14, 20 }, { 4, 11, 16, 23 }, { 6, 10, 15, 21 }
};

/* The sine table of RFC 1321 section 3.4: T[i] = floor(2^32 |sin(i + 1)|). */
static const uint32_t sine[64] = {
	0xd76aa478, 0xe8c7b756, 0x242070db, 0xc1bdceee, 0xf57c0faf, 0x4787c62a,
	0xa8304613, 0xfd469501, 0x698098d8, 0x8b44f7af, 0xffff5bb1, 0x895cd7be,
	0x6b901122, 0xfd987193, 0xa679438e, 0x49b40821, 0xf61e2562, 0xc040b340,
	0x265e5a51, 0xe9b6c7aa, 0xd62f105d, 0x02441453, 0xd8a1e681, 0xe7d3fbc8,
	0x21e1cde6, 0xc33707d6, 0xf4d50d87, 0x455a14ed, 0xa9e3e905, 0xfcefa3f8,
	0x676f02d9, 0x8d2a4c8a, 0xfffa3942, 0x8771f681, 0x6d9d6122, 0xfde5380c,
	0xa4beea44, 0x4bdecfa9, 0xf6bb4b60, 0xbebfbc70, 0x289b7ec6, 0xeaa127fa,
	0xd4ef3085, 0x04881d05, 0xd9d4d039, 0xe6db99e5, 0x1fa27cf8, 0xc4ac5665,
	0xf4292244, 0x432aff97, 0xab9423a7, 0xfc93a039, 0x655b59c3, 0x8f0ccc92,
	0xffeff47d, 0x85845dd1, 0x6fa87e4f, 0xfe2ce6e0, 0xa3014314, 0x4e0811a1,
	0xf7537e82, 0xbd3af235, 0x2ad7d2bb, 0xeb86d391
};

static uint32_t
rotl(uint32_t x, unsigned s)
{
	return x << s | x >> (32 - s);
}

static void
block(uint32_t h[4], const unsigned char *p)
{
	uint32_t w[16], a = h[0], b = h[1], c = h[2], d = h[3];

	for (int i = 0; i < 16; i++)
		w[i] = (uint32_t)p[4 * i] | (uint32_t)p[4 * i + 1] << 8 |
		    (uint32_t)p[4 * i + 2] << 16 | (uint32_t)p[4 * i + 3] << 24;
	for (int i = 0; i < 64; i++) {
		uint32_t f, t;
		int k, round = i / 16;

		switch (round) {
		case 0: f = (b & c) | (~b & d); k = i; break;
		case 1: f = (b & d) | (c & ~d); k = (5 * i + 1) % 16; break;
		case 2: f = b ^ c ^ d; k = (3 * i + 5) % 16; break;
		default: f = c ^ (b | ~d); k = (7 * i) % 16; break;
		}
		t = d;
		d = c;
		c = b;
		b = b + rotl(a + f + sine[i] + w[k], shift[round][i % 4]);
		a = t;
	}
	h[0] += a;
	h[1] += b;
	h[2] += c;
	h[3] += d;
}

void
rc_md5_init(rc_md5 *m)
{
	m->h[0] = 0x67452301;
	m->h[1] = 0xefcdab89;
	m->h[2] = 0x98badcfe;
	m->h[3] = 0x10325476;
	m->len = 0;
	m->nbuf = 0;
}

void
rc_md5_update(rc_md5 *m, const void *data, size_t n)
{
	const unsigned char *p = data;

	m->len += n;
	if (m->nbuf > 0) {
		size_t take = 64 - m->nbuf < n ? 64 - m->nbuf : n;

		memcpy(m->buf + m->nbuf, p, take);
		m->nbuf += take;
		p += take;
		n -= take;
		if (m->nbuf < 64)
			return;
		block(m->h, m->buf);
		m->nbuf = 0;
	}
	for (; n >= 64; p += 64, n -= 64)
		block(m->h, p);
	memcpy(m->buf, p, n);
	m->nbuf = n;
}

void
rc_md5_final(rc_md5 *m, unsigned char out[16])
{
	uint64_t bits = m->len * 8;
	unsigned char pad[72] = { 0x80 };
	size_t npad = (m->nbuf < 56 ? 56 : 120) - m->nbuf;

	for (int k = 0; k < 8; k++)
		pad[npad + k] = (unsigned char)(bits >> (8 * k));
	rc_md5_update(m, pad, npad + 8);
	for (int i = 0; i < 4; i++)
		for (int k = 0; k < 4; k++)
			out[4 * i + k] = (unsigned char)(m->h[i] >> (8 * k));
}

void
rc_md5_hex(const void *p, size_t n, char hex[33])
{
	static const char digit[] = "0123456789abcdef";
	unsigned char d[16];
	rc_md5 m;

	rc_md5_init(&m);
	rc_md5_update(&m, p, n);
	rc_md5_final(&m, d);
	for (int k = 0; k < 16; k++) {
		hex[2 * k] = digit[d[k] >> 4];
		hex[2 * k + 1] = digit[d[k] & 15];
	}
	hex[32] = '\0';
}
