/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gridcheck.c - the wrap-around ratio and missing points (gridcheck.h). */
#include "gridcheck.h"

#include <math.h>

static int
ok(const rc_grid *g, size_t k)
{
	return g->valid == NULL || g->valid[k];
}

/* r_d along x (dx = 1, n = nx, lines ny) or along y (dx = nx, n = ny,
 * lines nx, line stride 1); -1 when the direction has nothing to say. */
static double
ratio(const rc_grid *g, size_t stride, size_t n, size_t lines, size_t lstride)
{
	double edge = 0, inner = 0;
	size_t nedge = 0, ninner = 0;

	if (n < 2)
		return -1;
	for (size_t l = 0; l < lines; l++) {
		const size_t base = l * lstride;

		for (size_t k = 0; k + 1 < n; k++) {
			size_t a = base + k * stride, b = a + stride;

			if (ok(g, a) && ok(g, b)) {
				double d = g->z[b] - g->z[a];

				inner += d * d;
				ninner++;
			}
		}
		size_t first = base, last = base + (n - 1) * stride;

		if (ok(g, first) && ok(g, last)) {
			double d = g->z[first] - g->z[last];

			edge += d * d;
			nedge++;
		}
	}
	if (nedge == 0 || ninner == 0 || (edge == 0 && inner == 0))
		return -1;
	if (inner == 0)
		return INFINITY;
	return sqrt((edge / (double)nedge) / (inner / (double)ninner));
}

double
rc_grid_wrap_ratio(const rc_grid *g)
{
	double rx = ratio(g, 1, g->nx, g->ny, g->nx);
	double ry = ratio(g, g->nx, g->ny, g->nx, 1);
	double r = rx > ry ? rx : ry;

	return r < 0 ? 1 : r;
}

size_t
rc_grid_missing_count(const rc_grid *g)
{
	size_t n = 0, total = rc_grid_size(g);

	if (g->valid == NULL)
		return 0;
	for (size_t k = 0; k < total; k++)
		n += g->valid[k] == 0;
	return n;
}

int
rc_grid_check_uniform(const rc_grid *g, rc_err *err)
{
	if (g->x == NULL)
		return 0;
	return rc_seterr(err, "a line scan not uniformly spaced: this needs a "
	    "uniform step; read it with --uniform to resample it onto one");
}
