/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gradient.c - the derivative stencils and the rms gradients built on
 * them (gradient.h). */
#include "gradient.h"

#include <complex.h>

/* Reductions are deterministic for any thread count: the rows are cut
 * into NPART fixed parts (depending on the size only), threads sum the
 * parts, and one thread adds the partial sums in order. */
#define NPART 64

static size_t
part_start(long p, size_t n)
{
	return (size_t)p * n / NPART;
}

/* Columns a block at a time: the factor of each column (for the
 * Laplacian its qx^2) made once for all rows, not once a point (two
 * calls and two divisions a point were 8M of the 27M instructions of
 * one spectral derivative at 512^2, callgrind).  Each factor is the same
 * expression as a point's was, so the values are the same bit for bit. */
#define DERIV_COLS 1024

void
rc_deriv_spectral(fftw_complex *out, const fftw_complex *in,
    enum rc_deriv which, size_t nx, size_t ny, double lx, double ly,
    size_t j0, size_t rows)
{
	size_t nxc = nx / 2 + 1;
	double n = (double)(nx * ny);
	long nrows = (long)rows;
	double complex col[DERIV_COLS];
	double qx2[DERIV_COLS];

	for (size_t i0 = 0; i0 < nxc; i0 += DERIV_COLS) {
		size_t ncol = nxc - i0 < DERIV_COLS ? nxc - i0 : DERIV_COLS;

		for (size_t c = 0; c < ncol; c++) {
			double qx = rc_wavenumber(i0 + c, nx, lx);
			double complex factor;

			qx2[c] = qx * qx;
			switch (which) {
			case RC_DERIV_X:
				factor = I * rc_deriv_wavenumber(i0 + c, nx, lx);
				break;
			case RC_DERIV_Y:
			case RC_DERIV_LAPLACIAN:	/* per row, below */
				factor = 0;
				break;
			default:	/* RC_DERIV_XX */
				factor = -qx * qx;
				break;
			}
			col[c] = factor / n;
		}
		#pragma omp parallel for schedule(static)
		for (long jl = 0; jl < nrows; jl++) {
			size_t j = (size_t)jl;
			double qy = rc_wavenumber(j0 + j, ny, ly);
			double complex fy = I * rc_deriv_wavenumber(j0 + j, ny, ly);
			double complex row = fy / n;
			const fftw_complex *a = in + j * nxc + i0;
			fftw_complex *b = out + j * nxc + i0;

			switch (which) {
			case RC_DERIV_Y:
				for (size_t c = 0; c < ncol; c++)
					b[c] = a[c] * row;
				break;
			case RC_DERIV_LAPLACIAN:
				for (size_t c = 0; c < ncol; c++) {
					double complex factor =
					    -(qx2[c] + qy * qy);

					b[c] = a[c] * (factor / n);
				}
				break;
			default:	/* the columns' factors */
				for (size_t c = 0; c < ncol; c++)
					b[c] = a[c] * col[c];
				break;
			}
		}
	}
}

/* Index of the centre of the 3-point second difference at i on n points
 * without wrap-around (n >= 3). */
static size_t
interior(size_t i, size_t n)
{
	return i == 0 ? 1 : i + 1 == n ? n - 2 : i;
}

void
rc_deriv_open(const double *z, size_t nx, size_t ny, size_t i, size_t j,
    double dx, double dy, double d[4])
{
	size_t up = j + 1 < ny ? j + 1 : j, down = j > 0 ? j - 1 : j;
	size_t right = i + 1 < nx ? i + 1 : i, left = i > 0 ? i - 1 : i;

	d[RC_D_X] = d[RC_D_Y] = d[RC_D_XX] = d[RC_D_YY] = 0;
	if (right > left)
		d[RC_D_X] = (z[j * nx + right] - z[j * nx + left]) /
		    ((double)(right - left) * dx);
	if (up > down)
		d[RC_D_Y] = (z[up * nx + i] - z[down * nx + i]) /
		    ((double)(up - down) * dy);
	if (nx >= 3) {
		const double *c = z + j * nx + interior(i, nx);

		d[RC_D_XX] = (c[1] - 2 * c[0] + c[-1]) / (dx * dx);
	}
	if (ny >= 3) {
		const double *c = z + interior(j, ny) * nx + i;

		d[RC_D_YY] = (c[nx] - 2 * c[0] + c[-(ptrdiff_t)nx]) / (dy * dy);
	}
}

void
rc_deriv_sums(const rc_grid *h, const unsigned char *mask, double hbar,
    int open, double *grad2, double *dh_lap)
{
	size_t nx = h->nx, ny = h->ny;
	double dx = h->lx / (double)nx, dy = h->ly / (double)ny;
	double sum_g = 0, sum_l = 0;
	const double *z = h->z;

	/* Rows are summed first so round-off grows with nx + ny rather
	 * than nx * ny. */
	#pragma omp parallel for reduction(+:sum_g, sum_l) schedule(static)
	for (size_t j = 0; j < ny; j++) {
		double row_g = 0, row_l = 0;

		for (size_t i = 0; i < nx; i++) {
			size_t k = j * nx + i;
			double d[4];

			if (mask != NULL && !mask[k])
				continue;
			if (open)
				rc_deriv_open(z, nx, ny, i, j, dx, dy, d);
			else
				rc_deriv_central(z, nx, ny, i, j, dx, dy, d);
			row_g += d[RC_D_X] * d[RC_D_X] + d[RC_D_Y] * d[RC_D_Y];
			row_l += (z[k] - hbar) * (d[RC_D_XX] + d[RC_D_YY]);
		}
		sum_g += row_g;
		sum_l += row_l;
	}
	*grad2 = sum_g;
	*dh_lap = sum_l;
}

void
rc_field_sums(const double *h, const double *hx, const double *hy,
    const double *lap, const unsigned char *set, size_t n, double hbar,
    double *grad2, double *dh_lap)
{
	double part[NPART][2];

	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double g = 0, l = 0;

		for (size_t k = part_start(p, n); k < part_start(p + 1, n); k++) {
			if (set != NULL && !set[k])
				continue;
			if (hx != NULL)
				g += hx[k] * hx[k];
			if (hy != NULL)
				g += hy[k] * hy[k];
			if (lap != NULL)
				l += (h[k] - hbar) * lap[k];
		}
		part[p][0] = g;
		part[p][1] = l;
	}
	*grad2 = *dh_lap = 0;
	for (int p = 0; p < NPART; p++) {
		*grad2 += part[p][0];
		*dh_lap += part[p][1];
	}
}

double
rc_gbar_central(const rc_grid *g)
{
	double grad2, dh_lap;

	rc_deriv_sums(g, NULL, 0, 0, &grad2, &dh_lap);
	return sqrt(grad2 / (double)rc_grid_size(g));
}

double
rc_gbar_open(const rc_grid *g)
{
	double grad2, dh_lap;

	rc_deriv_sums(g, NULL, 0, 1, &grad2, &dh_lap);
	return sqrt(grad2 / (double)rc_grid_size(g));
}

double
rc_gbar_forward(const rc_grid *g)
{
	size_t nx = g->nx, ny = g->ny;
	double dx = g->lx / (double)nx, dy = g->ly / (double)ny, sum = 0, zmax = 0;
	double part[NPART];
	const double *h = g->z;
	int e;

	/* Differences scaled by a power of two near the largest height, so
	 * that their squares neither overflow nor underflow (exact). */
	for (size_t k = 0; k < nx * ny; k++)
		if (isfinite(h[k]))
			zmax = fmax(zmax, fabs(h[k]));
	e = zmax > 0 ? ilogb(zmax) : 0;

	#pragma omp parallel for schedule(static)
	for (long p = 0; p < NPART; p++) {
		double acc = 0;
		for (size_t j = part_start(p, ny); j < part_start(p + 1, ny); j++) {
			size_t jp = (j + 1) % ny;
			for (size_t i = 0; i < nx; i++) {
				size_t ip = (i + 1) % nx;
				double a = rc_deriv_forward(h[j * nx + i],
				    h[j * nx + ip], e, dx);
				double b = rc_deriv_forward(h[j * nx + i],
				    h[jp * nx + i], e, dy);
				acc += a * a + b * b;
			}
		}
		part[p] = acc;
	}
	for (int p = 0; p < NPART; p++)
		sum += part[p];
	return ldexp(sqrt(sum / (double)(nx * ny)), e);
}
