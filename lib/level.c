/* SPDX-License-Identifier: GPL-3.0-or-later */
/* level.c - detrending, scan-line alignment, harmonic filling, cropping
 * and transposing (conventions in level.h). */
#include "level.h"

#include <gsl/gsl_multilarge.h>
#include <gsl/gsl_statistics_double.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *detrend_names[] = { "mean", "plane", "quadratic" };
static const char *align_names[] = { "median", "mean", "plane" };

int
rc_detrend_parse(const char *name)
{
	for (int k = 0; k < 3; k++)
		if (strcmp(name, detrend_names[k]) == 0)
			return k;
	return -1;
}

const char *
rc_detrend_name(enum rc_detrend d)
{
	return (unsigned)d < 3 ? detrend_names[d] : "unknown";
}

int
rc_align_parse(const char *name)
{
	for (int k = 0; k < 3; k++)
		if (strcmp(name, align_names[k]) == 0)
			return k;
	return -1;
}

const char *
rc_align_name(enum rc_align a)
{
	return (unsigned)a < 3 ? align_names[a] : "unknown";
}

static int
is_valid(const rc_grid *g, size_t k)
{
	return g->valid == NULL || g->valid[k];
}

/* Basis functions at (u, v), the coordinates centred on the grid and
 * divided by the cell size (so every column is of order one and the least
 * squares problem is well conditioned). */
static void
basis(double u, double v, const int *cols, size_t p, double *row)
{
	double b[6] = { 1, u, v, u * u, u * v, v * v };

	for (size_t m = 0; m < p; m++)
		row[m] = b[cols[m]];
}

/* The columns of the model (indices into 1, u, v, u^2, uv, v^2); an
 * axis of one point has no slope or curvature to fit. */
static size_t
model_columns(const rc_grid *g, enum rc_detrend kind, int *cols)
{
	static const int deg[6] = { 0, 1, 1, 2, 2, 2 };
	static const int usex[6] = { 0, 1, 0, 1, 1, 0 };
	static const int usey[6] = { 0, 0, 1, 0, 1, 1 };
	int maxdeg = kind == RC_DETREND_MEAN ? 0 : kind == RC_DETREND_PLANE ? 1 : 2;
	size_t p = 0;

	for (int m = 0; m < 6; m++)
		if (deg[m] <= maxdeg && !(usex[m] && g->nx < 2) && !(usey[m] && g->ny < 2))
			cols[p++] = m;
	return p;
}

static int
all_finite(const gsl_vector *c)
{
	for (size_t m = 0; m < c->size; m++)
		if (!isfinite(gsl_vector_get(c, m)))
			return 0;
	return 1;
}

/* Rows of the design matrix go to GSL's large least-squares solver
 * (TSQR: a running QR factorisation), a block at a time, so the memory is
 * a block, not six values per point. */
#define BLOCK 4096

/* Long: the design matrix is streamed to GSL in blocks: its assembly and
 * the solve share the workspace. */
int
rc_detrend(rc_grid *g, enum rc_detrend kind, double *coef, rc_err *err)
{
	int cols[6];
	size_t p = model_columns(g, kind, cols);
	size_t nx = g->nx, ny = g->ny, n = nx * ny, nvalid = 0, fill = 0;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;
	double xc = 0.5 * (double)(nx - 1) * dx, yc = 0.5 * (double)(ny - 1) * dy;
	gsl_multilarge_linear_workspace *w = NULL;
	gsl_matrix *x = NULL;
	gsl_vector *y = NULL, *c = NULL;
	double rnorm, snorm;
	int rc = -1;

	if ((unsigned)kind > RC_DETREND_QUADRATIC)
		return rc_seterr(err, "internal: unknown detrend %d", (int)kind);
	for (size_t k = 0; k < n; k++)
		nvalid += is_valid(g, k);
	if (nvalid < p)
		return rc_seterr(err, "detrend %s: %zu valid points, need at least %zu",
		    rc_detrend_name(kind), nvalid, p);
	w = gsl_multilarge_linear_alloc(gsl_multilarge_linear_tsqr, p);
	x = gsl_matrix_alloc(BLOCK, p);
	y = gsl_vector_alloc(BLOCK);
	c = gsl_vector_alloc(p);
	if (w == NULL || x == NULL || y == NULL || c == NULL) {
		rc_seterr(err, "out of memory");
		goto out;
	}
	for (size_t k = 0; k <= n; k++) {
		if (k < n && is_valid(g, k)) {
			double u = ((double)(k % nx) * dx - xc) / g->lx;
			double v = ((double)(k / nx) * dy - yc) / g->ly;
			basis(u, v, cols, p, gsl_matrix_ptr(x, fill, 0));
			gsl_vector_set(y, fill, g->z[k]);
			fill++;
		}
		if (fill > 0 && (fill == BLOCK || k == n)) {
			gsl_matrix_view xb = gsl_matrix_submatrix(x, 0, 0, fill, p);
			gsl_vector_view yb = gsl_vector_subvector(y, 0, fill);
			if (gsl_multilarge_linear_accumulate(&xb.matrix, &yb.vector, w) != 0) {
				rc_seterr(err, "detrend: least squares failed");
				goto out;
			}
			fill = 0;
		}
	}
	if (gsl_multilarge_linear_solve(0.0, c, &rnorm, &snorm, w) != 0 ||
	    !all_finite(c)) {
		rc_seterr(err, "detrend %s: singular fit (the valid points are "
		    "collinear or too few)", rc_detrend_name(kind));
		goto out;
	}
	{
		long nl = (long)n;
		const double *cc = c->data;
		#pragma omp parallel for schedule(static)
		for (long k = 0; k < nl; k++) {
			double row[6], u, v, f = 0;
			if (!is_valid(g, (size_t)k))
				continue;
			u = ((double)((size_t)k % nx) * dx - xc) / g->lx;
			v = ((double)((size_t)k / nx) * dy - yc) / g->ly;
			basis(u, v, cols, p, row);
			for (size_t m = 0; m < p; m++)
				f += row[m] * cc[m];
			g->z[k] -= f;
		}
	}
	if (coef != NULL) {
		/* Back to x - xc, y - yc in the grid's length unit; terms of
		 * an axis of one point are 0. */
		double s[6] = { 1, 1 / g->lx, 1 / g->ly, 1 / (g->lx * g->lx),
		    1 / (g->lx * g->ly), 1 / (g->ly * g->ly) };
		size_t full = kind == RC_DETREND_MEAN ? 1 : kind == RC_DETREND_PLANE ? 3 : 6;
		for (size_t m = 0; m < full; m++)
			coef[m] = 0;
		for (size_t m = 0; m < p; m++)
			coef[cols[m]] = gsl_vector_get(c, m) * s[cols[m]];
	}
	if (kind != RC_DETREND_MEAN)
		g->periodic = 0;
	rc = 0;
out:
	gsl_multilarge_linear_free(w);
	gsl_matrix_free(x);
	gsl_vector_free(y);
	gsl_vector_free(c);
	return rc;
}

int
rc_align_rows(rc_grid *g, enum rc_align kind, rc_err *err)
{
	size_t nx = g->nx, ny = g->ny;
	double dx = g->lx / (double)nx;
	double *buf;

	if ((unsigned)kind > RC_ALIGN_PLANE)
		return rc_seterr(err, "internal: unknown alignment %d", (int)kind);
	if ((buf = rc_malloc(nx * sizeof(double), err)) == NULL)
		return -1;
	for (size_t j = 0; j < ny; j++) {
		double *row = g->z + j * nx;
		size_t m = 0;
		for (size_t i = 0; i < nx; i++)
			if (is_valid(g, j * nx + i))
				buf[m++] = row[i];
		if (m == 0)
			continue;
		if (kind == RC_ALIGN_PLANE && m >= 2) {
			/* Least-squares line over the valid x of the row. */
			double sx = 0, sz = 0, sxx = 0, sxz = 0, xm, zm, b;
			for (size_t i = 0; i < nx; i++)
				if (is_valid(g, j * nx + i)) {
					sx += (double)i * dx;
					sz += row[i];
				}
			xm = sx / (double)m;
			zm = sz / (double)m;
			for (size_t i = 0; i < nx; i++)
				if (is_valid(g, j * nx + i)) {
					double ddx = (double)i * dx - xm;
					sxx += ddx * ddx;
					sxz += ddx * (row[i] - zm);
				}
			b = sxx > 0 ? sxz / sxx : 0;
			for (size_t i = 0; i < nx; i++)
				if (is_valid(g, j * nx + i))
					row[i] -= zm + b * ((double)i * dx - xm);
		} else {
			double off = kind == RC_ALIGN_MEDIAN ?
			    gsl_stats_median(buf, 1, m) : gsl_stats_mean(buf, 1, m);
			for (size_t i = 0; i < nx; i++)
				if (is_valid(g, j * nx + i))
					row[i] -= off;
		}
	}
	free(buf);
	if (ny > 1)
		g->periodic = 0;
	return 0;
}

/* One SOR update of missing point k; returns |change|. */
static double
relax(rc_grid *g, size_t k, double wx, double wy, double omega)
{
	size_t nx = g->nx, ny = g->ny, i = k % nx, j = k / nx;
	double s = 0, w = 0, z;

	if (nx > 1) {
		if (i > 0 || g->periodic) {
			s += wx * g->z[j * nx + (i + nx - 1) % nx];
			w += wx;
		}
		if (i + 1 < nx || g->periodic) {
			s += wx * g->z[j * nx + (i + 1) % nx];
			w += wx;
		}
	}
	if (ny > 1) {
		if (j > 0 || g->periodic) {
			s += wy * g->z[((j + ny - 1) % ny) * nx + i];
			w += wy;
		}
		if (j + 1 < ny || g->periodic) {
			s += wy * g->z[((j + 1) % ny) * nx + i];
			w += wy;
		}
	}
	z = g->z[k] + omega * (s / w - g->z[k]);
	s = fabs(z - g->z[k]);
	g->z[k] = z;
	return s;
}

/* Long: the relaxation's set-up, sweeps and convergence test share the
 * fill mask and the neighbour weights. */
int
rc_fill_harmonic(rc_grid *g, unsigned char **filled, size_t *nfilled,
    rc_err *err)
{
	size_t n = rc_grid_size(g), nmiss = 0, nvalid = 0, *list = NULL, nlist = 0;
	size_t imin = g->nx, imax = 0, jmin = g->ny, jmax = 0, extent, maxsweep;
	double dx = g->lx / (double)g->nx, dy = g->ly / (double)g->ny;
	double wx = 1 / (dx * dx), wy = 1 / (dy * dy), lo = INFINITY, hi = -INFINITY;
	double mean = 0, omega, tol;
	unsigned char *mask = NULL;

	if (filled != NULL)
		*filled = NULL;
	if (nfilled != NULL)
		*nfilled = 0;
	if (g->valid == NULL)
		/* nothing to fill; an earlier fill's points stay filled */
		return rc_grid_meta_setf(g, "filled_points", err, "%zu",
		    rc_grid_filled_count(g));
	for (size_t k = 0; k < n; k++) {
		if (g->valid[k]) {
			nvalid++;
			mean += g->z[k];
			lo = fmin(lo, g->z[k]);
			hi = fmax(hi, g->z[k]);
		} else {
			size_t i = k % g->nx, j = k / g->nx;
			nmiss++;
			imin = i < imin ? i : imin;
			imax = i > imax ? i : imax;
			jmin = j < jmin ? j : jmin;
			jmax = j > jmax ? j : jmax;
		}
	}
	if (nvalid == 0)
		return rc_seterr(err, "fill: no valid point to fill from");
	mean /= (double)nvalid;
	if (nmiss > 0) {
		if ((list = rc_malloc(nmiss * sizeof(size_t), err)) == NULL)
			return -1;
		/* Red points (i + j even) first, then black: each half sweep
		 * reads only the other colour's latest values. */
		for (int colour = 0; colour < 2; colour++)
			for (size_t k = 0; k < n; k++)
				if (!g->valid[k] && (int)((k % g->nx + k / g->nx) % 2) == colour) {
					list[nlist++] = k;
					g->z[k] = mean;
				}
		extent = imax - imin + 1 > jmax - jmin + 1 ? imax - imin + 1 : jmax - jmin + 1;
		omega = 2 / (1 + sin(M_PI / (double)(extent + 1)));
		tol = fmax(1e-13 * (hi - lo), 1e-300);
		maxsweep = 200 * (g->nx + g->ny) + 1000;
		for (size_t sweep = 0;; sweep++) {
			double change = 0;
			if (sweep == maxsweep) {
				free(list);
				return rc_seterr(err, "fill: no convergence in %zu sweeps", maxsweep);
			}
			for (size_t m = 0; m < nmiss; m++)
				change = fmax(change, relax(g, list[m], wx, wy, omega));
			if (change <= tol)
				break;
		}
		free(list);
	}
	if (filled != NULL && nmiss > 0) {
		if ((mask = rc_malloc(n, err)) == NULL)
			return -1;
		for (size_t k = 0; k < n; k++)
			mask[k] = !g->valid[k];
	}
	/* The grid remembers which points are made up (added to those of
	 * an earlier fill). */
	if (nmiss > 0 && g->filled == NULL &&
	    (g->filled = rc_calloc(n, 1, err)) == NULL) {
		free(mask);
		return -1;
	}
	for (size_t k = 0; k < n && nmiss > 0; k++)
		g->filled[k] |= !g->valid[k];
	free(g->valid);
	g->valid = NULL;
	if (filled != NULL)
		*filled = mask;
	else
		free(mask);
	if (nfilled != NULL)
		*nfilled = nmiss;
	return rc_grid_meta_setf(g, "filled_points", err, "%zu",
	    rc_grid_filled_count(g));
}

/* A new grid of nx x ny like g, with a missing-point and a filled-point
 * mask where g has them. */
static rc_grid *
like(const rc_grid *g, size_t nx, size_t ny, double lx, double ly, rc_err *err)
{
	rc_grid *c = rc_grid_new_like(g, nx, ny, lx, ly, err);

	if (c != NULL && ((g->valid != NULL &&
	    (c->valid = rc_calloc(nx * ny, 1, err)) == NULL) ||
	    (g->filled != NULL &&
	    (c->filled = rc_calloc(nx * ny, 1, err)) == NULL))) {
		rc_grid_free(c);
		return NULL;
	}
	return c;
}

rc_grid *
rc_crop(const rc_grid *g, size_t x0, size_t x1, size_t y0, size_t y1,
    rc_err *err)
{
	rc_grid *c;
	size_t nx, ny;

	if (!(x0 < x1 && x1 <= g->nx && y0 < y1 && y1 <= g->ny)) {
		rc_seterr(err, "crop %zu:%zu,%zu:%zu: outside the %zux%zu grid or empty "
		    "(want 0 <= X0 < X1 <= %zu, 0 <= Y0 < Y1 <= %zu)", x0, x1, y0, y1,
		    g->nx, g->ny, g->nx, g->ny);
		return NULL;
	}
	nx = x1 - x0;
	ny = y1 - y0;
	c = like(g, nx, ny, g->lx * (double)nx / (double)g->nx,
	    g->ly * (double)ny / (double)g->ny, err);
	if (c == NULL)
		return NULL;
	for (size_t j = 0; j < ny; j++) {
		memcpy(c->z + j * nx, g->z + (j + y0) * g->nx + x0, nx * sizeof(double));
		if (g->valid != NULL)
			memcpy(c->valid + j * nx, g->valid + (j + y0) * g->nx + x0, nx);
		if (g->filled != NULL)
			memcpy(c->filled + j * nx, g->filled + (j + y0) * g->nx + x0, nx);
	}
	if (nx != g->nx || ny != g->ny)
		c->periodic = 0;
	/* filled_points counts the filled points the crop kept */
	if (g->filled != NULL) {
		size_t nf = rc_grid_filled_count(c);

		if (nf == 0) {
			free(c->filled);
			c->filled = NULL;
		}
		if (rc_grid_meta_setf(c, "filled_points", err, "%zu", nf) != 0) {
			rc_grid_free(c);
			return NULL;
		}
	}
	return c;
}

rc_grid *
rc_transpose(const rc_grid *g, rc_err *err)
{
	rc_grid *c = like(g, g->ny, g->nx, g->ly, g->lx, err);

	if (c == NULL)
		return NULL;
	for (size_t j = 0; j < g->ny; j++)
		for (size_t i = 0; i < g->nx; i++) {
			c->z[i * g->ny + j] = g->z[j * g->nx + i];
			if (g->valid != NULL)
				c->valid[i * g->ny + j] = g->valid[j * g->nx + i];
			if (g->filled != NULL)
				c->filled[i * g->ny + j] = g->filled[j * g->nx + i];
		}
	return c;
}
