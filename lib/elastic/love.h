/* SPDX-License-Identifier: GPL-3.0-or-later */
/* love.h - Love's (1929) surface displacement of a half space under a
 * pressure uniform on one rectangular pixel: the kernel of the
 * free-boundary compliance (elastic_free.h) and the half-space part of a
 * layer's pixel compliance (elastic_layer_free.h).  With E* = 1,
 *   C(x, y) = (1/pi) [H(x + dx/2, y + dy/2) - H(x - dx/2, y + dy/2)
 *             - H(x + dx/2, y - dy/2) + H(x - dx/2, y - dy/2)],
 *   H(x, y) = x asinh(y/x) + y asinh(x/y), the integral of 1/r over
 * [0, x] x [0, y] (odd in x and in y). */
#ifndef RC_LOVE_H
#define RC_LOVE_H

/* Love's C(x, y) for a dx x dy pixel, per unit pressure, with E* = 1. */
double rc_love_pixel(double x, double y, double dx, double dy);

#endif
