/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_elastic.c - lib/elastic/elastic.c and lib/elastic/elastic_free.c
 * against closed forms: a single Fourier mode q of the periodic half space
 * has stiffness k_q = |q| E* / 2 (K cos = k_q cos, G cos = cos/k_q), the
 * elastic energy is (1/2) sum k_q |u_q|^2 = (1/2) <u K u>, and the
 * free-boundary compliance of one loaded pixel is Love's closed form at its
 * centre and Boussinesq's point load d^2/(pi E* r) far from it.  The pixel
 * kernel (elastic.h) against the same Love compliance summed over the
 * periodic images in real space, and its limits and symmetries. */
#include <math.h>
#include <stdlib.h>

#include "elastic.h"
#include "elastic_free.h"
#include "testlib.h"

/* The FFT round-off: a transform pair of N points gives a relative
 * error of a few eps log2(N) (FFTW's own accuracy, about 1e-15 here);
 * 1e-12 leaves room for the scaling and any plan FFTW picks while still
 * failing at once for a wrong factor 2, pi, a swapped lx/ly or a
 * Nyquist mode mishandled (all O(1) errors). */
#define FFT_TOL 1e-12

/* u = cos(2 pi (m x/lx + n y/ly) + phase) on the grid's points. */
static void
mode(double *u, size_t nx, size_t ny, long m, long n, double phase)
{
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			u[j * nx + i] = cos(2 * M_PI * ((double)m * (double)i / (double)nx +
			    (double)n * (double)j / (double)ny) + phase);
}

static long
alias(long m, size_t n)
{
	long a = ((m % (long)n) + (long)n) % (long)n;

	return 2 * a > (long)n ? a - (long)n : a;
}

static void
single_modes(size_t nx, size_t ny, double lx, double ly, double modulus)
{
	/* (m, n): low, mixed, negative, and the Nyquist indices. */
	const long mn[][2] = { { 1, 0 }, { 0, 1 }, { 3, 5 }, { -4, 2 },
	    { (long)nx / 2, 0 }, { 0, (long)ny / 2 }, { (long)nx / 2, (long)ny / 2 },
	    { 2, (long)ny / 2 } };
	size_t n = nx * ny;
	double *u = fftw_alloc_real(n), *f = fftw_alloc_real(n);
	rc_elastic e;
	rc_err err;

	test_int(rc_elastic_init(&e, nx, ny, lx, ly, modulus, RC_FFT_ESTIMATE,
	    &err), 0, "init %zux%zu", nx, ny);
	for (size_t t = 0; t < sizeof(mn) / sizeof(mn[0]); t++) {
		long m = mn[t][0], q = ny == 1 ? 0 : mn[t][1];
		/* On the grid, index m is the wave number of its alias in
		 * (-n/2, n/2] (5 on 9 points is -4). */
		long ma = alias(m, nx), qa = alias(q, ny);
		double qx = 2 * M_PI * (double)ma / lx, qy = 2 * M_PI * (double)qa / ly;
		double k = 0.5 * modulus * hypot(qx, qy), werr = 0, gerr = 0;
		/* Every non-zero component at Nyquist: the mode is +-1 at every
		 * point (<cos^2> = 1) and its sine vanishes on the grid, so no
		 * phase; else a phase exercises the imaginary parts too. */
		int nyq = (ma == 0 || 2 * labs(ma) == (long)nx) &&
		    (qa == 0 || 2 * labs(qa) == (long)ny);
		double phase = nyq ? 0 : 0.3;

		if (m == 0 && q == 0)
			continue;	/* a line contact has no qy */

		mode(u, nx, ny, m, q, phase);
		rc_elastic_force(&e, u, f);
		for (size_t p = 0; p < n; p++)
			werr = fmax(werr, fabs(f[p] - k * u[p]));
		test_abs(werr / k, 0, FFT_TOL, "%zux%zu, mode (%ld, %ld): K cos = "
		    "|q| E*/2 cos", nx, ny, m, q);
		mode(u, nx, ny, m, q, phase);
		rc_elastic_displacement(&e, u, f);
		for (size_t p = 0; p < n; p++)
			gerr = fmax(gerr, fabs(f[p] * k - u[p]));
		test_abs(gerr, 0, FFT_TOL, "%zux%zu, mode (%ld, %ld): G cos = "
		    "cos / k_q", nx, ny, m, q);
		/* Energy per unit area of A cos: k A^2 <cos^2>, <cos^2> = 1/2,
		 * or 1 for a Nyquist mode (cos(pi i) = +-1 at every point). */
		mode(u, nx, ny, m, q, phase);
		for (size_t p = 0; p < n; p++)
			u[p] *= 0.25;
		rc_elastic_r2c(&e, u, e.fft.spec);
		test_rel(rc_elastic_energy_spec(&e, e.fft.spec),
		    0.5 * k * 0.0625 * (nyq ? 1 : 0.5), FFT_TOL,
		    "%zux%zu, mode (%ld, %ld): energy = k A^2 <cos^2> / 2", nx, ny,
		    m, q);
	}
	/* The smallest and largest stiffness of the table. */
	test_rel(e.k_min, 0.5 * modulus * 2 * M_PI / fmax(lx, ny == 1 ? 0 : ly),
	    1e-15, "%zux%zu: k_min = E* pi / max(lx, ly)", nx, ny);
	test_rel(e.k_max, 0.5 * modulus * hypot(M_PI * (double)(nx / 2) * 2 / lx,
	    ny == 1 ? 0 : M_PI * (double)(ny / 2) * 2 / ly), 1e-15,
	    "%zux%zu: k_max at the Nyquist corner", nx, ny);
	rc_elastic_free(&e);
	fftw_free(u);
	fftw_free(f);
}

/* Parseval: the spectral energy (1/2) sum k |U_q|^2 / N^2 equals the
 * real-space (1/2N) sum_i u_i (K u)_i for any field (random here, with a
 * mean, which carries no energy). */
static void
energy_identity(void)
{
	const size_t nx = 30, ny = 20, n = nx * ny;
	double *u = fftw_alloc_real(n), *f = fftw_alloc_real(n);
	double direct = 0, spec, shifted;
	unsigned long seed = 7;
	rc_elastic e;
	rc_err err;

	test_int(rc_elastic_init(&e, nx, ny, 3, 2, 1.7, RC_FFT_ESTIMATE, &err),
	    0, "init 30x20");
	for (size_t p = 0; p < n; p++) {
		seed = seed * 6364136223846793005UL + 1442695040888963407UL;
		u[p] = (double)(seed >> 11) / 9007199254740992.0 - 0.2;
	}
	rc_elastic_force(&e, u, f);
	for (size_t p = 0; p < n; p++)
		direct += u[p] * f[p];
	direct *= 0.5 / (double)n;
	rc_elastic_r2c(&e, u, e.fft.spec);
	spec = rc_elastic_energy_spec(&e, e.fft.spec);
	test_rel(spec, direct, FFT_TOL, "energy: (1/2) sum k |u_q|^2 = "
	    "(1/2) <u K u> (Parseval)");
	test_true(spec > 0, "energy of a random field is positive (%g)", spec);
	for (size_t p = 0; p < n; p++)
		u[p] += 5;
	rc_elastic_r2c(&e, u, e.fft.spec);
	shifted = rc_elastic_energy_spec(&e, e.fft.spec);
	test_rel(shifted, spec, FFT_TOL, "energy: a rigid shift adds none");
	rc_elastic_free(&e);
	fftw_free(u);
	fftw_free(f);
}

/* Unit pressure on pixel (i0, j0) of an nx x ny area (pixels dx x dy);
 * returns w at pixel (i, j). */
static void
one_pixel(rc_halfspace *h, size_t i0, size_t j0, double *w)
{
	for (size_t p = 0; p < h->n; p++)
		w[p] = 0;
	w[j0 * h->nx + i0] = 1;
	rc_halfspace_apply(h, w, w);
}

static void
free_boundary(double dx, double dy, const char *what)
{
	const size_t nx = 48, ny = 48, i0 = 3, j0 = 4;
	const double modulus = 2;
	double *w = malloc(nx * ny * sizeof(double));
	rc_halfspace h;
	rc_err err;

	test_int(rc_halfspace_init(&h, nx, ny, nx * dx, ny * dy, modulus,
	    RC_FFT_ESTIMATE, &err), 0, "%s: halfspace init", what);
	one_pixel(&h, i0, j0, w);
	/* Centre: C(0,0) = 4 H(dx/2, dy/2) / (pi E*) with
	 * H(a, b) = a asinh(b/a) + b asinh(a/b). */
	{
		double a = dx / 2, b = dy / 2;
		double c0 = 4 * (a * asinh(b / a) + b * asinh(a / b)) / (M_PI * modulus);

		test_rel(w[j0 * nx + i0], c0, FFT_TOL, "%s: centre of the loaded "
		    "pixel = Love's closed form", what);
	}
	/* Far along x (42 pixels) and along the diagonal (40, 40): the
	 * pixel acts as a point load F = dx dy, w = F / (pi E* r).  The
	 * pixel average of 1/r differs by (dx^2 d_xx + dy^2 d_yy)(1/r)/24
	 * (second moments dx^2/12, dy^2/12), with d_xx(1/r) = (2x^2 - y^2)/r^5:
	 * relative (dx^2 (2x^2 - y^2) + dy^2 (2y^2 - x^2)) / (24 r^4), a
	 * few 1e-5 here; what is left is O((d/r)^4), below 1e-6.  A
	 * periodic image across the padded cell would be off by tens of
	 * per cent. */
	{
		const size_t at[2][2] = { { i0 + 42, j0 }, { i0 + 40, j0 + 40 } };

		for (int t = 0; t < 2; t++) {
			double x = (double)(at[t][0] - i0) * dx;
			double y = (double)(at[t][1] - j0) * dy;
			double r = hypot(x, y), point = dx * dy / (M_PI * modulus * r);
			double corr = (dx * dx * (2 * x * x - y * y) +
			    dy * dy * (2 * y * y - x * x)) / (24 * pow(r, 4));
			double got = w[at[t][1] * nx + at[t][0]];

			test_abs(got / point - 1, corr, 1e-6, "%s: %s: point load "
			    "d^2/(pi E* r) with its second-order correction %.3g",
			    what, t ? "diagonal" : "along x", corr);
			test_true(fabs(got / point - 1) > 0.5 * fabs(corr),
			    "%s: %s: the correction is seen (%.3g vs %.3g)", what,
			    t ? "diagonal" : "along x", got / point - 1, corr);
		}
	}
	rc_halfspace_release(&h);
	free(w);
}


/* The pixel kernel: small q, symmetry, positivity. */
static void
pixel_limits(void)
{
	const double dx = 0.3, dy = 0.2;
	double prev = 0;
	rc_elastic e, c;
	rc_err err;
	size_t nx = 24, ny = 18, i;
	int pos = 1, sym = 1;

	/* k_q -> |q| E* / 2 with a relative error O((q dx)^2): along x, y and
	 * the diagonal, q dx = 0.04, 0.02, 0.01; each halving of q must cut
	 * the error about four times (3.5 ... 4.5 allows the next order). */
	for (int dir = 0; dir < 3; dir++) {
		for (int h = 0; h < 3; h++) {
			double q = 0.04 / dx / (double)(1 << h);
			double qx = dir == 1 ? 0 : q, qy = dir == 0 ? 0 : q;
			double k = 1 / rc_pixel_compliance(qx, qy, dx, dy);
			double rel = k / (0.5 * hypot(qx, qy)) - 1;

			test_range(fabs(rel), 0, 2 * (q * dx) * (q * dx),
			    "pixel kernel, direction %d, q dx = %g: k_q = |q| E*/2 "
			    "(1 + O((q dx)^2))", dir, q * dx);
			if (h > 0)
				test_range(prev / rel, 3.5, 4.5, "pixel kernel, "
				    "direction %d: the error falls like q^2", dir);
			prev = rel;
		}
	}
	/* Even in qx and qy; for square pixels symmetric in qx <-> qy. */
	for (i = 0; i < 20; i++) {
		double qx = 0.37 * (double)i - 3, qy = 1.3 - 0.21 * (double)i;
		double g = rc_pixel_compliance(qx, qy, dx, dy);

		sym &= fabs(rc_pixel_compliance(-qx, qy, dx, dy) - g) <= 1e-14 * g &&
		    fabs(rc_pixel_compliance(qx, -qy, dx, dy) - g) <= 1e-14 * g &&
		    fabs(rc_pixel_compliance(qy, qx, dx, dx) -
		    rc_pixel_compliance(qx, qy, dx, dx)) <= 1e-14 * g;
	}
	test_true(sym, "pixel kernel: even in qx and qy, symmetric for square "
	    "pixels");
	/* The table: positive for q != 0, 0 at q = 0, continuum at small q,
	 * softer than the continuum at the zone corner (1.29 times for
	 * square pixels, elastic.h). */
	test_int(rc_elastic_init(&e, nx, ny, nx * dx, ny * dy, 2.0,
	    RC_FFT_ESTIMATE, &err), 0, "init for the pixel table");
	test_int(rc_elastic_init(&c, nx, ny, nx * dx, ny * dy, 2.0,
	    RC_FFT_ESTIMATE, &err), 0, "init for the continuum table");
	test_int(rc_elastic_set_kernel(&e, nx * dx, ny * dy, RC_KERNEL_PIXEL,
	    &err), 0, "set the pixel kernel");
	for (i = 1; i < e.nxc * ny; i++)
		pos &= e.stiffness[i] > 0 && isfinite(e.stiffness[i]);
	test_true(pos && e.stiffness[0] == 0, "pixel table: k_q > 0 for q != 0, "
	    "k_0 = 0");
	test_rel(e.stiffness[1], c.stiffness[1], 2 * pow(2 * M_PI / nx, 2),
	    "pixel table: the softest x mode is the continuum's");
	test_true(e.k_max < c.k_max, "pixel table: softer than the continuum "
	    "at the zone's edge (k_max %g < %g)", e.k_max, c.k_max);
	test_rel(rc_pixel_compliance(M_PI / dx, M_PI / dx, dx, dx) /
	    (2 / hypot(M_PI / dx, M_PI / dx)), 1.29, 0.005,
	    "pixel kernel at the corner of the zone, square pixels");
	test_true(rc_elastic_set_layer(&e, nx * dx, ny * dy, 1.0,
	    RC_SUBSTRATE_BONDED, 0.3, &err) != 0, "a layer on the pixel kernel "
	    "is refused");
	rc_elastic_free(&e);
	rc_elastic_free(&c);
}

/* The pixel kernel against Love's pixel compliance summed over periodic
 * images in real space, an independent evaluation (closed form in real
 * space instead of the sinc series in Fourier space): on an nx x ny grid
 * of a square cell L x L,
 *   G(r) = sum_{|n|_inf <= K} C(r + n L) + (dx dy / pi) (r^2 / 4) S_3 + c,
 * S_3 = sum_{|n|_inf > K} 1 / |n L|^3.  The images beyond K act as point
 * loads dx dy / (pi E* |R + r|), whose expansion in r has a constant, a
 * linear term that cancels between n and -n, and the quadrupole
 * (3 (r.R)^2 - r^2 R^2) / (2 R^5), which the square shell averages to
 * r^2 / (4 R^3); the next term falls like K^-3.  S_3 is summed to 4K and
 * the rest taken as the integral 4 sqrt 2 / (s L^3) outside the square of
 * half side s = 4K + 1/2.  The DFT of G over the offsets (minimal images)
 * is G_q for q != 0 (the constant c lands on q = 0).  Measured: the
 * largest relative difference over all modes is 7.5e-6, 3.64e-6,
 * 3.610e-6 and 3.606e-6 at K = 8, 16, 32, 64 (8x8; 8x6: 9.0e-6 ...
 * 3.77e-6): the real-space side has converged to 4e-9 at K = 32, and
 * what is left is the truncation of the Fourier image sum, 3.9e-6 for
 * square and 6.0e-6 for 2:1 pixels (elastic.h).  Tolerance 1e-5: above
 * that bound, and 10^4 times below any error of a factor or a missing
 * image (the continuum kernel differs from it by up to 29%). */
static void
pixel_vs_love(size_t nx, size_t ny)
{
	const long K = 32;
	const double L = 1.0, dx = L / nx, dy = L / ny;
	double *g = malloc(nx * ny * sizeof(double)), s3 = 0, worst = 0;
	long kk = 4 * K;

	for (long a = -kk; a <= kk; a++)
		for (long b = -kk; b <= kk; b++)
			if (labs(a) > K || labs(b) > K)
				s3 += pow(hypot((double)a, (double)b), -3);
	s3 = (s3 + 4 * sqrt(2) / ((double)kk + 0.5)) / (L * L * L);
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double x = (2 * i > nx ? (double)i - (double)nx : (double)i) * dx;
			double y = (2 * j > ny ? (double)j - (double)ny : (double)j) * dy;
			double sum = 0;

			for (long a = -K; a <= K; a++)
				for (long b = -K; b <= K; b++)
					sum += rc_love_pixel(x + a * L, y + b * L, dx, dy);
			g[j * nx + i] = sum + dx * dy / M_PI * 0.25 * (x * x + y * y) * s3;
		}
	for (size_t v = 0; v < ny; v++)
		for (size_t u = 0; u < nx; u++) {
			double re = 0, qx, qy, gq;

			if (u == 0 && v == 0)
				continue;
			for (size_t j = 0; j < ny; j++)
				for (size_t i = 0; i < nx; i++)
					re += g[j * nx + i] * cos(2 * M_PI *
					    ((double)(u * i) / nx + (double)(v * j) / ny));
			qx = rc_wavenumber(u, nx, L);
			qy = rc_wavenumber(v, ny, L);
			gq = rc_pixel_compliance(qx, qy, dx, dy);
			worst = fmax(worst, fabs(re / gq - 1));
		}
	test_range(worst, 0, 1e-5, "pixel kernel = Love's pixel compliance "
	    "summed over periodic images, %zux%zu (largest relative "
	    "difference over the modes)", nx, ny);
	free(g);
}

/* The continuum table equals E* |q| / 2 at every entry, bit for bit: the
 * rows above ny/2, copied from their mirror images (elastic.c), included;
 * even and odd row counts, a rectangular cell, one and two rows, and
 * 512x511 on two threads (the rows split between them). */
static void
table_exact(size_t nx, size_t ny, double lx, double ly)
{
	rc_elastic e;
	rc_err err;
	size_t bad = 0;
	double kmin = HUGE_VAL, kmax = 0;

	if (rc_elastic_init(&e, nx, ny, lx, ly, 3.0, RC_FFT_ESTIMATE, &err) != 0) {
		test_true(0, "table %zux%zu: %s", nx, ny, err.msg);
		return;
	}
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < e.nxc; i++) {
			double k = 0.5 * 3.0 * hypot(rc_wavenumber(i, nx, lx),
			    rc_wavenumber(j, ny, ly));

			bad += e.stiffness[j * e.nxc + i] != k;
			kmax = fmax(kmax, k);
			if (k > 0)
				kmin = fmin(kmin, k);
		}
	test_int((long long)bad, 0, "table %zux%zu: entries that differ from "
	    "E* hypot(qx, qy) / 2", nx, ny);
	test_true(e.k_min == kmin && e.k_max == kmax, "table %zux%zu: k_min, "
	    "k_max over all entries", nx, ny);
	rc_elastic_free(&e);
}

int
main(void)
{
	table_exact(16, 12, 1.0, 0.7);
	table_exact(9, 7, 1.3, 2.1);
	table_exact(8, 1, 1.0, 1.0);
	table_exact(6, 2, 1.0, 0.5);
	rc_fft_set_threads(2);
	table_exact(512, 511, 1.0, 1.0);
	single_modes(32, 24, 2.0, 1.5, 3.0);
	single_modes(15, 9, 1.0, 2.5, 0.7);	/* odd: no Nyquist mode */
	single_modes(16, 1, 4.0, 1.0, 1.0);	/* line contact: qy = 0 */
	energy_identity();
	free_boundary(0.025, 0.025, "square pixel");
	free_boundary(0.03, 0.02, "rectangular pixel");
	pixel_limits();
	pixel_vs_love(8, 8);
	pixel_vs_love(8, 6);
	return test_summary();
}
