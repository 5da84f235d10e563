/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_patches.c - lib/patches.c: patch counts and sum of squared sizes
 * on constructed masks (one blob, two blobs, a patch across the periodic
 * edge counted once there and twice on a finite patch, diagonal
 * neighbours apart: 4-neighbourhood as patches.h states), and on random
 * masks against an independent point-by-point flood fill; the slab pieces
 * the MPI build joins give the whole-grid answer. */
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "patches.h"
#include "testlib.h"

/* Mask from a picture: '#' contact, anything else not; rows top first. */
static unsigned char *
mask(const char *const *rows, size_t nx, size_t ny)
{
	unsigned char *m = malloc(nx * ny);

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			m[j * nx + i] = rows[j][i] == '#';
	return m;
}

/* Both variants on one picture: periodic and open counts, sum_sq. */
static void
check(const char *name, const char *const *rows, size_t nx, size_t ny,
    size_t want_periodic, double sq_periodic, size_t want_open,
    double sq_open)
{
	unsigned char *m = mask(rows, nx, ny);
	size_t n = 999;
	double sq = -1;
	rc_err err;

	test_int(rc_contact_patches(m, nx, ny, &n, &sq, &err), 0, "%s: periodic",
	    name);
	test_int((long long)n, (long long)want_periodic, "%s: periodic count",
	    name);
	test_abs(sq, sq_periodic, 0, "%s: periodic sum of squared sizes", name);
	test_int(rc_contact_patches_open(m, nx, ny, &n, &sq, &err), 0,
	    "%s: open", name);
	test_int((long long)n, (long long)want_open, "%s: open count", name);
	test_abs(sq, sq_open, 0, "%s: open sum of squared sizes", name);
	free(m);
}

static void
constructed(void)
{
	static const char *const empty[] = { "......", "......", "......",
	    "......" };
	static const char *const blob[] = { "......", ".###..", ".####.",
	    "..#..." };
	static const char *const two[] = { "##....", "##..#.", "....#.",
	    "......" };
	/* One patch across the x edge: columns 0 and 5 of row 1. */
	static const char *const wrap_x[] = { "......", "#....#", "......",
	    "......" };
	/* One patch across the y edge: rows 0 and 3 of column 2. */
	static const char *const wrap_y[] = { "..#...", "......", "......",
	    "..#..." };
	/* The four corners touch each other only through both edges. */
	static const char *const corners[] = { "#....#", "......", "......",
	    "#....#" };
	/* Diagonal neighbours only: a checkerboard of 3 points per row. */
	static const char *const diag[] = { "#.#.#.", ".#.#.#", "#.#.#.",
	    ".#.#.#" };
	static const char *const full[] = { "######", "######", "######",
	    "######" };
	/* A ring round the torus in x: one row of contact. */
	static const char *const ring[] = { "......", "######", "......",
	    "......" };

	check("empty", empty, 6, 4, 0, 0, 0, 0);
	check("one blob of 8", blob, 6, 4, 1, 64, 1, 64);
	check("blobs of 4 and 2", two, 6, 4, 2, 16 + 4, 2, 16 + 4);
	check("across x", wrap_x, 6, 4, 1, 4, 2, 1 + 1);
	check("across y", wrap_y, 6, 4, 1, 4, 2, 1 + 1);
	check("four corners", corners, 6, 4, 1, 16, 4, 4);
	/* 12 isolated points: no two share an edge, even across the
	 * periodic edges (6 and 4 are even, so the pattern continues). */
	check("checkerboard", diag, 6, 4, 12, 12, 12, 12);
	check("full", full, 6, 4, 1, 576, 1, 576);
	check("ring", ring, 6, 4, 1, 36, 1, 36);
	/* A line contact (ny = 1): the y join is a self-join. */
	{
		static const char *const line[] = { "##..##.#" };

		check("line nx x 1", line, 8, 1, 2, 9 + 4, 3, 4 + 4 + 1);
	}
}

/* Independent method: flood fill point by point with an explicit stack,
 * 4 neighbours, periodic or not. */
static void
flood(const unsigned char *m, size_t nx, size_t ny, int periodic,
    size_t *count, double *sum_sq)
{
	size_t n = nx * ny, *stack = malloc(n * sizeof(size_t));
	unsigned char *seen = calloc(n, 1);

	*count = 0;
	*sum_sq = 0;
	for (size_t s = 0; s < n; s++) {
		size_t top = 0, size = 0;

		if (!m[s] || seen[s])
			continue;
		seen[s] = 1;
		stack[top++] = s;
		while (top > 0) {
			size_t k = stack[--top], i = k % nx, j = k / nx;
			long nb[4][2] = { { (long)i - 1, (long)j }, { (long)i + 1, (long)j },
			    { (long)i, (long)j - 1 }, { (long)i, (long)j + 1 } };

			size++;
			for (int d = 0; d < 4; d++) {
				long a = nb[d][0], b = nb[d][1];

				if (periodic) {
					a = (a + (long)nx) % (long)nx;
					b = (b + (long)ny) % (long)ny;
				} else if (a < 0 || b < 0 || a >= (long)nx || b >= (long)ny)
					continue;
				size_t q = (size_t)b * nx + (size_t)a;
				if (m[q] && !seen[q]) {
					seen[q] = 1;
					stack[top++] = q;
				}
			}
		}
		(*count)++;
		*sum_sq += (double)size * (double)size;
	}
	free(stack);
	free(seen);
}

/* Random masks at fill fractions round the percolation threshold (0.59
 * on the square lattice), where patches are largest and most tangled. */
static void
random_masks(void)
{
	static const size_t dims[][2] = { { 37, 23 }, { 64, 64 }, { 5, 80 },
	    { 1, 9 }, { 2, 2 } };
	static const double fill[] = { 0.2, 0.5, 0.59, 0.7 };
	unsigned long seed = 12345;
	int bad_p = 0, bad_o = 0, ok = 0, differ = 0;

	for (size_t d = 0; d < sizeof(dims) / sizeof(dims[0]); d++)
		for (size_t f = 0; f < sizeof(fill) / sizeof(fill[0]); f++) {
			size_t nx = dims[d][0], ny = dims[d][1], n1, n2;
			unsigned char *m = malloc(nx * ny);
			double s1, s2;
			rc_err err;

			for (size_t k = 0; k < nx * ny; k++) {
				/* 64-bit LCG (Knuth's MMIX constants), top bits */
				seed = seed * 6364136223846793005UL + 1442695040888963407UL;
				m[k] = (double)(seed >> 11) / 9007199254740992.0 < fill[f];
			}
			ok += rc_contact_patches(m, nx, ny, &n1, &s1, &err) == 0;
			flood(m, nx, ny, 1, &n2, &s2);
			bad_p += n1 != n2 || s1 != s2;
			ok += rc_contact_patches_open(m, nx, ny, &n1, &s1, &err) == 0;
			differ += n1 != n2;	/* n2 still the periodic count */
			flood(m, nx, ny, 0, &n2, &s2);
			bad_o += n1 != n2 || s1 != s2;
			free(m);
		}
	test_int(ok, 40, "random masks: every call succeeds");
	test_int(bad_p, 0, "random masks: periodic = flood fill (count, sum_sq)");
	test_int(bad_o, 0, "random masks: open = flood fill (count, sum_sq)");
	/* Else the two comparisons above could not tell the variants apart. */
	test_true(differ >= 10, "random masks: periodic and open counts differ "
	    "on %d of 20 masks", differ);
}

/* The MPI seam: three slabs labelled apart, joined at their edges (and
 * the last to the first across y), give the whole grid's patches. */
static void
slabs(void)
{
	enum { NX = 24, NY = 18 };
	static const size_t cut[] = { 0, 5, 11, NY };
	unsigned char m[NX * NY];
	rc_run first[3][NX / 2 + 1], last[3][NX / 2 + 1];
	size_t nfirst[3], nlast[3], n1, n2;
	double s1, s2;
	rc_uf u = { NULL, NULL, 0, 0 };
	unsigned long seed = 99;
	rc_err err;
	int ok = 1;

	for (size_t k = 0; k < NX * NY; k++) {
		seed = seed * 6364136223846793005UL + 1442695040888963407UL;
		m[k] = (seed >> 40) % 100 < 55;
	}
	for (int s = 0; s < 3; s++)
		ok &= rc_patches_slab(m + cut[s] * NX, NX, cut[s + 1] - cut[s], &u,
		    first[s], &nfirst[s], last[s], &nlast[s], &err) == 0;
	for (int s = 0; s < 3; s++)
		rc_runs_join(&u, last[s], nlast[s], first[(s + 1) % 3],
		    nfirst[(s + 1) % 3]);
	rc_uf_components(&u, &n1, &s1);
	rc_uf_free(&u);
	rc_contact_patches(m, NX, NY, &n2, &s2, &err);
	test_true(ok, "slabs labelled");
	test_int((long long)n1, (long long)n2, "three slabs joined: patch count "
	    "of the whole grid");
	test_abs(s1, s2, 0, "three slabs joined: sum of squared sizes");
	test_true(n2 > 1, "the slab mask has several patches (%zu)", n2);
}

int
main(void)
{
	constructed();
	random_masks();
	slabs();
	return test_summary();
}
