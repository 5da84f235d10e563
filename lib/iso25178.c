/* SPDX-License-Identifier: GPL-3.0-or-later */
/* iso25178.c - ISO 25178-2 height, hybrid, spatial and material-ratio
 * parameters (definitions in iso25178.h). */
#include "iso25178.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "gradient.h"

static int
ok(const rc_grid *g, size_t k)
{
	return g->valid == NULL || g->valid[k];
}

static int
cmp_desc(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;

	return (x < y) - (x > y);
}

/* Valid heights about their mean, sorted from the highest. */
static double *
sorted_heights(const rc_grid *g, double *mean, size_t *n, rc_err *err)
{
	size_t np = rc_grid_size(g), m = 0;
	double *z, s = 0;

	for (size_t k = 0; k < np; k++)
		if (ok(g, k)) {
			s += g->z[k];
			m++;
		}
	if (m == 0) {
		rc_seterr(err, "no valid point: every height is missing (NaN)");
		return NULL;
	}
	if ((z = rc_malloc(m * sizeof(double), err)) == NULL)
		return NULL;
	*mean = s / (double)m;
	m = 0;
	for (size_t k = 0; k < np; k++)
		if (ok(g, k))
			z[m++] = g->z[k] - *mean;
	qsort(z, m, sizeof(double), cmp_desc);
	*n = m;
	return z;
}

/* c(mr): sorted z[k] sits at mr = (k + 1/2)/n; linear in between, the
 * end values beyond. */
static double
height_at(const double *z, size_t n, double mr)
{
	double x = mr * (double)n - 0.5;
	size_t k;

	if (x <= 0)
		return z[0];
	if (x >= (double)(n - 1))
		return z[n - 1];
	k = (size_t)x;
	return z[k] + (x - (double)k) * (z[k + 1] - z[k]);
}

static void
core(const double *z, size_t n, rc_iso *iso)
{
	const int steps = 1000;
	double best = INFINITY, top = 0, bot = 0, a1 = 0, a2 = 0;
	size_t above = 0, below = 0;

	for (int s = 0; s <= 600; s++) {
		double a = (double)s / steps;
		double slope = (height_at(z, n, a) - height_at(z, n, a + 0.4)) / 0.4;
		if (slope < best) {
			best = slope;
			top = height_at(z, n, a) + slope * a;
			bot = height_at(z, n, a) - slope * (1 - a);
		}
	}
	for (size_t k = 0; k < n; k++) {
		if (z[k] > top) {
			a1 += z[k] - top;
			above++;
		}
		if (z[k] < bot) {
			a2 += bot - z[k];
			below++;
		}
	}
	iso->Sk = top - bot;
	iso->Smr1 = (double)above / (double)n;
	iso->Smr2 = 1 - (double)below / (double)n;
	a1 /= (double)n;
	a2 /= (double)n;
	iso->Spk = iso->Smr1 > 0 ? 2 * a1 / iso->Smr1 : 0;
	iso->Svk = iso->Smr2 < 1 ? 2 * a2 / (1 - iso->Smr2) : 0;
}

static void
gradients(const rc_grid *g, rc_iso *iso)
{
	size_t nx = g->nx, ny = g->ny, m = 0;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny, s2 = 0, sr = 0;

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			size_t k = j * nx + i, ip, jp;
			double gx = 0, gy = 0;
			if (!ok(g, k))
				continue;
			if (nx > 1) {
				if (i + 1 == nx && !g->periodic)
					continue;
				ip = j * nx + (i + 1) % nx;
				if (!ok(g, ip))
					continue;
				gx = rc_deriv_forward(g->z[k], g->z[ip], 0, dx);
			}
			if (ny > 1) {
				if (j + 1 == ny && !g->periodic)
					continue;
				jp = ((j + 1) % ny) * nx + i;
				if (!ok(g, jp))
					continue;
				gy = rc_deriv_forward(g->z[k], g->z[jp], 0, dy);
			}
			s2 += gx * gx + gy * gy;
			sr += sqrt(1 + gx * gx + gy * gy) - 1;
			m++;
		}
	iso->Sdq = m > 0 ? sqrt(s2 / (double)m) : NAN;
	iso->Sdr = m > 0 ? sr / (double)m : NAN;
}

/* f(t) at lag (tx, ty) in lattice units, bilinear between lags. */
static double
acf_at(const double *f, size_t px, size_t py, double tx, double ty)
{
	double fx = floor(tx), fy = floor(ty), ax = tx - fx, ay = ty - fy, v = 0;

	for (int b = 0; b < 2; b++)
		for (int a = 0; a < 2; a++) {
			long i = (long)fx + a, j = (long)fy + b;
			double w = (a ? ax : 1 - ax) * (b ? ay : 1 - ay);
			size_t ii = (size_t)((i % (long)px + (long)px) % (long)px);
			size_t jj = (size_t)((j % (long)py + (long)py) % (long)py);
			if (w != 0)
				v += w * f[jj * px + ii];
		}
	return v;
}

static int
spatial(const rc_grid *g, double mean, double s, rc_iso *iso, rc_err *err)
{
	size_t nx = g->nx, ny = g->ny;
	size_t px = g->periodic || nx == 1 ? nx : 2 * nx;
	size_t py = g->periodic || ny == 1 ? ny : 2 * ny;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny;
	double smin = INFINITY, smax = 0, r0;
	int ndir = (nx > 1 && ny > 1) ? 180 : 1, undecayed = 0;
	rc_fft f;

	if (rc_fft_init(&f, px, py, RC_FFT_ESTIMATE, err) != 0)
		return -1;
	memset(f.real, 0, px * py * sizeof(double));
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			if (ok(g, j * nx + i))
				f.real[j * px + i] = g->z[j * nx + i] - mean;
	rc_fft_forward(&f);
	for (size_t m = 0; m < f.nxc * py; m++)
		f.spec[m] = f.spec[m] * conj(f.spec[m]);
	rc_fft_backward(&f);
	r0 = f.real[0];
	if (!(r0 > 0)) {
		iso->Sal = iso->Str = NAN;
		rc_fft_free(&f);
		return 0;
	}
	for (size_t m = 0; m < px * py; m++)
		f.real[m] /= r0;
	for (int d = 0; d < ndir; d++) {
		double th = M_PI * d / 180.0;
		double ux = nx > 1 ? cos(th) : 0, uy = nx > 1 ? sin(th) : 1;
		double ds = 0.25 * fmin(nx > 1 ? dx : INFINITY, ny > 1 ? dy : INFINITY);
		double prev = 1, r = 0, hit = INFINITY;
		for (;;) {
			double rn = r + ds, tx = rn * ux / dx, ty = rn * uy / dy, v;
			if (fabs(tx) > 0.5 * (double)nx || fabs(ty) > 0.5 * (double)ny)
				break;
			v = acf_at(f.real, px, py, tx, ty);
			if (v <= s) {
				hit = r + ds * (prev - s) / (prev - v);
				break;
			}
			prev = v;
			r = rn;
		}
		if (isinf(hit))
			undecayed = 1;
		else {
			smin = fmin(smin, hit);
			smax = fmax(smax, hit);
		}
	}
	iso->Sal = isinf(smin) ? NAN : smin;
	iso->Str = undecayed || ndir == 1 ? NAN : smin / smax;
	rc_fft_free(&f);
	return 0;
}

int
rc_iso25178(const rc_grid *g, double s, rc_iso *iso, rc_err *err)
{
	double *z, s1 = 0, s2 = 0, s3 = 0, s4 = 0;
	size_t n;

	memset(iso, 0, sizeof(*iso));
	if (!(s > 0 && s < 1))
		return rc_seterr(err, "autocorrelation threshold %g: want 0 < s < 1", s);
	if ((z = sorted_heights(g, &iso->mean, &n, err)) == NULL)
		return -1;
	for (size_t k = 0; k < n; k++) {
		double v = z[k], v2 = v * v;
		s1 += fabs(v);
		s2 += v2;
		s3 += v2 * v;
		s4 += v2 * v2;
	}
	iso->n_valid = n;
	iso->Sq = sqrt(s2 / (double)n);
	iso->Sa = s1 / (double)n;
	iso->Ssk = iso->Sq > 0 ? s3 / (double)n / pow(iso->Sq, 3) : NAN;
	iso->Sku = iso->Sq > 0 ? s4 / (double)n / pow(iso->Sq, 4) : NAN;
	iso->Sp = z[0];
	iso->Sv = 0 - z[n - 1] + 0.0;	/* never -0 */
	iso->Sz = iso->Sp + iso->Sv;
	core(z, n, iso);
	free(z);
	gradients(g, iso);
	return spatial(g, iso->mean, s, iso, err);
}

int
rc_material_ratio(const rc_grid *g, size_t npoints, double *c, double *smr,
    rc_err *err)
{
	double *z, mean;
	size_t n, k = 0;

	if (npoints < 2)
		return rc_seterr(err, "material ratio curve: want at least 2 heights");
	if ((z = sorted_heights(g, &mean, &n, err)) == NULL)
		return -1;
	/* Heights from the top down; k counts the points at or above. */
	for (size_t m = 0; m < npoints; m++) {
		double h = z[0] + (z[n - 1] - z[0]) * (double)m / (double)(npoints - 1);
		if (m == npoints - 1)
			h = z[n - 1];
		while (k < n && z[k] >= h)
			k++;
		c[m] = h + mean;
		smr[m] = (double)k / (double)n;
	}
	free(z);
	return 0;
}
