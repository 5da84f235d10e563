/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_fire_wide.c - the hard wall's update pass on wide vectors
 * (lib/solver/solver_fire_wide.c) against the scalar update written out
 * here from its rules (solver_fire.c's update_range): u, v and the wall's
 * mark compared with memcmp, on every lane count this CPU runs, with
 * special values (NaN, infinities, signed zeros, subnormals, u == h) among
 * random ones, misaligned starts and ragged ends, and restarts.  A
 * whole solve on the wide lanes is test_solver's (exact solutions), and
 * its rows' bits are tests/rows.sh's against an earlier build. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "solver_impl.h"
#include "testlib.h"

#define POINTS	4099	/* not a multiple of 8: a ragged end */

static uint64_t seed = 20261128;

static double
uniform(void)
{
	seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
	return (double)(seed >> 11) / 9007199254740992.0;
}

/* A value for a field: mostly random of scale `scale', else one of the
 * special values. */
static double
value(double scale)
{
	static const double special[] = { 0.0, -0.0, INFINITY, -INFINITY,
	    4.9e-324, -2.2e-308, 1e300, -1e300 };
	double r = uniform();

	if (r < 0.03)
		return special[(size_t)(uniform() * 8) % 8];
	if (r < 0.035)
		return NAN;
	return scale * (uniform() - 0.5);
}

/* The update's rule, one point at a time (update_range's scalar loop). */
static void
update_scalar(unsigned char *contact, const double *h, double *u,
    double *v, const double *a, const rc__fire_step *st, size_t k0,
    size_t k1)
{
	for (size_t k = k0; k < k1; k++) {
		double ak = contact[k] ? 0 : a[k], vk = st->restart ? 0 : v[k];
		double uk;

		vk = st->mix_v * (vk + st->dt * ak) + st->mix_a * ak;
		uk = u[k] + st->dt * vk;
		if (uk <= h[k]) {
			u[k] = h[k];
			v[k] = 0;
			contact[k] = RC__ON_WALL;
		} else {
			u[k] = uk;
			v[k] = vk;
			contact[k] = 0;
		}
	}
}

static void
test_update(int lanes)
{
	static const rc__fire_step steps[] = {
		{ .dt = 0.7, .restart = 0, .mix_v = 0.93, .mix_a = 0.041 },
		{ .dt = 2.0, .restart = 1, .mix_v = 0.5, .mix_a = 0.5 },
		{ .dt = 1.1, .restart = 0, .mix_v = 1.0, .mix_a = 0.0 },
	};
	size_t n = POINTS + 1;
	double *h = malloc(n * sizeof(*h)), *a = malloc(n * sizeof(*a));
	double *u[2], *v[2];
	unsigned char *c[2];
	int round;

	for (int w = 0; w < 2; w++) {
		u[w] = malloc(n * sizeof(double));
		v[w] = malloc(n * sizeof(double));
		c[w] = malloc(n);
	}
	for (round = 0; round < 12; round++) {
		const rc__fire_step *st = &steps[round % 3];
		/* starts 0 ... 3 (misaligned), ends 0 ... 8 points short */
		size_t k0 = (size_t)round % 4, k1 = n - (size_t)(round * 5) % 9;
		size_t stop, differ = 0;

		for (size_t k = 0; k < n; k++) {
			double r = uniform();

			h[k] = value(1.0);
			a[k] = value(0.1);
			v[0][k] = value(0.1);
			/* a third on the wall (u == h), some just above */
			u[0][k] = r < 0.33 ? h[k] : r < 0.4 ? nextafter(h[k],
			    INFINITY) : value(1.0);
			c[0][k] = r < 0.2 ? RC__ON_WALL : r < 0.5 ? 1 : 0;
		}
		memcpy(u[1], u[0], n * sizeof(double));
		memcpy(v[1], v[0], n * sizeof(double));
		memcpy(c[1], c[0], n);
		update_scalar(c[0], h, u[0], v[0], a, st, k0, k1);
		stop = rc__wall_update_lanes(lanes, c[1], h, u[1], v[1], a, st,
		    k0, k1);
		test_true(stop <= k1 && stop + (size_t)lanes > k1 &&
		    (stop - k0) % (size_t)lanes == 0,
		    "%d lanes, round %d: the wide loop stops at %zu of [%zu, %zu)",
		    lanes, round, stop, k0, k1);
		update_scalar(c[1], h, u[1], v[1], a, st, stop, k1);
		for (size_t k = 0; k < n; k++)
			differ += memcmp(&u[0][k], &u[1][k], sizeof(double)) != 0 ||
			    memcmp(&v[0][k], &v[1][k], sizeof(double)) != 0 ||
			    c[0][k] != c[1][k];
		test_int((long long)differ, 0, "%d lanes, round %d (restart %d): "
		    "points whose u, v or mark differ from the scalar rule's",
		    lanes, round, st->restart);
	}
	for (int w = 0; w < 2; w++) {
		free(u[w]);
		free(v[w]);
		free(c[w]);
	}
	free(h);
	free(a);
}

int
main(void)
{
	int best = rc__lanes_best();

	test_true(best == RC__LANES_BASE || best == RC__LANES_AVX2 ||
	    best == RC__LANES_AVX512, "rc__lanes_best: %d", best);
	test_int((long long)rc__wall_update_lanes(RC__LANES_BASE, NULL, NULL,
	    NULL, NULL, NULL, NULL, 5, 100), 5,
	    "no lanes: the wide loop leaves every point to the scalar one");
	if (best >= RC__LANES_AVX2)
		test_update(RC__LANES_AVX2);
	else
		test_skip(25, "this CPU has no AVX2 (x86-64-v3)");
	if (best >= RC__LANES_AVX512)
		test_update(RC__LANES_AVX512);
	else
		test_skip(25, "this CPU has no AVX-512 (x86-64-v4)");
	return test_summary();
}
