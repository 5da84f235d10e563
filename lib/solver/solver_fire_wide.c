/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_fire_wide.c - the hard wall's update pass (solver_fire.c) on
 * the widest vectors the CPU has: 8 doubles with
 * AVX-512 (x86-64-v4), 4 with AVX2 (x86-64-v3), else none (the callers'
 * two-lane SSE2 and scalar loops do all).  The loops are one template,
 * solver_fire_lanes_impl.h, compiled once per instruction set under `#pragma
 * GCC target'; the choice is made at run time (rc__lanes_best), so the
 * binaries stay x86-64 baseline.
 *
 * Why: the update is element-wise with byte masks that gcc 12 does not
 * vectorise; on two lanes (rc__v2d) it was the costliest pass, 0.33 FFT
 * pairs an iteration at 512^2.  Measured in isolation (one thread, 512^2
 * points in chunks of 8192, this VM's AMD EPYC): 0.33 ms on two lanes,
 * 0.24 on four, 0.15 on eight.  Not kept: the wall's force pass on
 * vectors (its sums added lane by lane, to keep their order): in a solve
 * 8% slower on eight lanes and no faster on four than the branching
 * scalar loop, which is bound by the latency of its chains of additions,
 * as is the loop's mixing pass; only a new order of the sums (new bits)
 * would speed those.
 *
 * Bits: the same operations on each point as the two-lane loop, and no
 * FMA (-ffp-contract=off holds under the target pragma too), so u, v and
 * the mark are its bits (tests/test_fire_wide.c compares them with
 * memcmp, special values included).  Valgrind's CPU has no AVX-512: it
 * runs the AVX2 loop. */
#include "solver_impl.h"

#include <string.h>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    __GNUC__ >= 12
#define HAVE_LANES
#endif

#ifdef HAVE_LANES
#pragma GCC push_options
#pragma GCC target("arch=x86-64-v4")
#define LANES		8
#define LANES_NAME(x)	x##_8
#include "solver_fire_lanes_impl.h"
#undef LANES
#undef LANES_NAME
#pragma GCC pop_options

#pragma GCC push_options
#pragma GCC target("arch=x86-64-v3")
#define LANES		4
#define LANES_NAME(x)	x##_4
#include "solver_fire_lanes_impl.h"
#undef LANES
#undef LANES_NAME
#pragma GCC pop_options
#endif

int
rc__lanes_best(void)
{
#ifdef HAVE_LANES
	__builtin_cpu_init();
	if (__builtin_cpu_supports("x86-64-v4"))
		return RC__LANES_AVX512;
	if (__builtin_cpu_supports("x86-64-v3"))
		return RC__LANES_AVX2;
#endif
	return RC__LANES_BASE;
}

size_t
rc__wall_update_lanes(int lanes, unsigned char *contact, const double *h,
    double *u, double *v, const double *a, const rc__fire_step *st,
    size_t k0, size_t k1)
{
#ifdef HAVE_LANES
	if (lanes == RC__LANES_AVX512)
		return update_8(contact, h, u, v, a, st, k0, k1);
	if (lanes == RC__LANES_AVX2)
		return update_4(contact, h, u, v, a, st, k0, k1);
#else
	(void)lanes, (void)contact, (void)h, (void)u, (void)v, (void)a;
	(void)st, (void)k1;
#endif
	return k0;
}
