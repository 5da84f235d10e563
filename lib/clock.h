/* SPDX-License-Identifier: GPL-3.0-or-later */
/* clock.h - the one wall clock of the library, the tools and the
 * benchmarks: monotonic, in seconds from an arbitrary origin. */
#ifndef RC_CLOCK_H
#define RC_CLOCK_H

double rc_clock(void);

#endif
