/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_synth.c - surface synthesis: the spectrum of Eq. 2, normalisation,
 * phase determinism (grid refinement, lambda_s), Peklenik anisotropy,
 * harmonic/sine/egg-box values, parameter checks, metadata. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fft.h"
#include "grid.h"
#include "spectral.h"
#include "synth.h"
#include "testlib.h"

static rc_grid *
make(const rc_synth_params *p)
{
	rc_err err;
	rc_grid *g = rc_synth(p, &err);

	if (g == NULL) {
		fprintf(stderr, "rc_synth: %s\n", err.msg);
		exit(1);
	}
	return g;
}

/* The grid's mode amplitudes a_k = H_k / N (h = sum_k a_k e^{iqr}). */
static fftw_complex *
modes(const rc_grid *g)
{
	rc_fft f;
	rc_err err;
	size_t n = g->nx * g->ny, ns = (g->nx / 2 + 1) * g->ny;
	fftw_complex *a = fftw_alloc_complex(ns);

	if (rc_fft_init(&f, g->nx, g->ny, RC_FFT_ESTIMATE, &err) != 0) {
		fprintf(stderr, "%s\n", err.msg);
		exit(1);
	}
	memcpy(f.real, g->z, n * sizeof(double));
	rc_fft_forward(&f);
	for (size_t k = 0; k < ns; k++)
		a[k] = f.spec[k] / (double)n;
	rc_fft_free(&f);
	return a;
}

static double
hrms(const rc_grid *g)
{
	double rms;

	rc_mean_rms(g->z, rc_grid_size(g), NULL, &rms);
	return rms;
}

/* Eq. 2 on a 1024^2 grid: the radially averaged spectrum has slope
 * -2(1+H) between q_r and q_s, is zero outside without roll-off and flat at
 * C(q_r) below q_r with it. */
static void
test_spectrum(int gaussian, double hurst, int rolloff)
{
	rc_synth_params p;
	rc_grid *g;
	fftw_complex *a;
	size_t nxc;
	enum { NB = 12 };
	double qr, qs, lq0, lq1, sc[NB] = {0}, sq[NB] = {0}, cnt[NB] = {0};
	double outside = 0, peak = 0, flat_err = 0, c_qr;
	double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0, slope;

	rc_synth_defaults(&p);
	p.nx = p.ny = 1024;
	p.hurst = hurst;
	p.lambda_r = 1.0 / 8;
	p.lambda_s = 1.0 / 256;
	p.rolloff = rolloff;
	p.gaussian_amplitudes = gaussian;
	p.seed = 42;
	g = make(&p);
	a = modes(g);
	nxc = p.nx / 2 + 1;
	qr = 2 * M_PI / p.lambda_r;
	qs = 2 * M_PI / p.lambda_s;
	c_qr = 0;
	/* sqrt amplitudes: |a|^2 = c * (q/q_r)^(-2(1+H)) exactly, so the
	 * mode at q = q_r (k = (8, 0)) gives the constant. */
	c_qr = creal(a[8] * conj(a[8]));
	lq0 = log(qr);
	lq1 = log(qs);
	for (size_t j = 0; j < p.ny; j++) {
		double qy = rc_wavenumber(j, p.ny, p.ly);
		for (size_t i = 0; i < nxc; i++) {
			double qx = rc_wavenumber(i, p.nx, p.lx);
			double q = hypot(qx, qy), c = creal(a[j * nxc + i] * conj(a[j * nxc + i]));
			if (c > peak)
				peak = c;
			if (q >= qs * (1 - 1e-9) || q == 0 || (!rolloff && q < qr * (1 - 1e-9))) {
				if (c > outside)
					outside = c;
				continue;
			}
			if (q < qr * (1 - 1e-9)) {
				if (!gaussian && fabs(c / c_qr - 1) > flat_err)
					flat_err = fabs(c / c_qr - 1);
				continue;
			}
			int b = (int)((log(q) - lq0) / (lq1 - lq0) * NB);
			if (b >= NB)
				b = NB - 1;
			sc[b] += c;
			sq[b] += log(q);
			cnt[b]++;
		}
	}
	for (int b = 0; b < NB; b++) {
		if (cnt[b] == 0)
			continue;
		double x = sq[b] / cnt[b], y = log(sc[b] / cnt[b]);
		sx += x; sy += y; sxx += x * x; sxy += x * y; m++;
	}
	slope = (m * sxy - sx * sy) / (m * sxx - sx * sx);
	/* Issue tolerance 0.05; with sqrt amplitudes the only error is the
	 * curvature of the power law inside a log bin (tiny), with Rayleigh
	 * moduli the sampling noise of ~1e5 modes per decade. */
	test_abs(slope, -2 * (1 + hurst), 0.05,
	    "spectrum slope H=%g gaussian=%d rolloff=%d", hurst, gaussian, rolloff);
	/* "Zero" outside the band: exactly zero in the input, here FFT
	 * round-off of a unit-scale field, < 1e-28 of the peak. */
	test_range(outside / peak, 0, 1e-28,
	    "no power outside the band (H=%g gaussian=%d rolloff=%d)", hurst,
	    gaussian, rolloff);
	if (rolloff && !gaussian)
		test_abs(flat_err, 0, 1e-9, "roll-off: C(q < q_r) = C(q_r)");
	fftw_free(a);
	rc_grid_free(g);
}

/* sqrt amplitudes: every mode of the band has |a|^2 = C(q) exactly, the
 * kx = 0 column included (a non-Hermitian column would be halved by c2r). */
static void
test_mode_amplitudes(void)
{
	rc_synth_params p;
	rc_grid *g;
	fftw_complex *a;
	size_t nxc;
	double qr, qs, c0, worst = 0;
	long nband = 0;

	rc_synth_defaults(&p);
	p.nx = 128;
	p.ny = 96;
	p.lx = 1.0;
	p.ly = 0.75;
	p.hurst = 0.3;
	p.lambda_r = 0.25;
	p.lambda_s = 0.03;
	g = make(&p);
	a = modes(g);
	nxc = p.nx / 2 + 1;
	qr = 2 * M_PI / p.lambda_r;
	qs = 2 * M_PI / p.lambda_s;
	c0 = creal(a[4] * conj(a[4]));	/* k = (4, 0): q = q_r */
	for (size_t j = 0; j < p.ny; j++) {
		double qy = rc_wavenumber(j, p.ny, p.ly);
		for (size_t i = 0; i < nxc; i++) {
			double q = hypot(rc_wavenumber(i, p.nx, p.lx), qy);
			double c = creal(a[j * nxc + i] * conj(a[j * nxc + i]));
			if (q < qr * (1 - 1e-9) || q >= qs * (1 - 1e-9))
				continue;
			double want = c0 * pow(q / qr, -2 * (1 + p.hurst));
			if (fabs(c / want - 1) > worst)
				worst = fabs(c / want - 1);
			nband++;
		}
	}
	test_true(nband > 100, "band holds modes (%ld)", nband);
	/* Round-off of two 128x96 FFTs: 1e-12 relative on |a|^2 is loose. */
	test_abs(worst, 0, 1e-10, "each mode's |a|^2 = C(q) (non-square cell)");
	fftw_free(a);
	rc_grid_free(g);
}

static void
test_normalisation(void)
{
	rc_synth_params p;
	rc_grid *g;
	rc_err err;
	double gbar, rms, mean;
	double targets[] = { 1.0, 0.05, 7.5 };

	rc_synth_defaults(&p);
	p.nx = 128;
	p.ny = 128;
	for (int k = 0; k < 3; k++) {
		p.rms_gradient = targets[k];
		p.gaussian_amplitudes = k == 1;
		g = make(&p);
		rc_rms_gradient(g, NULL, &gbar, &err);
		rc_mean_rms(g->z, rc_grid_size(g), &mean, NULL);
		/* Both sides are the same sum (Parseval), one through a
		 * forward FFT: round-off only. */
		test_rel(gbar, targets[k], 1e-10, "rms gradient = %g", targets[k]);
		test_abs(mean, 0, 1e-14 * targets[k], "mean height 0");
		rc_grid_free(g);
	}
	/* Default (both zero): rms gradient 1. */
	rc_synth_defaults(&p);
	p.nx = p.ny = 64;
	g = make(&p);
	rc_rms_gradient(g, NULL, &gbar, &err);
	test_rel(gbar, 1.0, 1e-10, "default rms gradient is 1");
	rc_grid_free(g);
	p.rms_height = 0.3;
	g = make(&p);
	rc_mean_rms(g->z, rc_grid_size(g), NULL, &rms);
	test_rel(rms, 0.3, 1e-10, "rms height = 0.3");
	test_true(rc_grid_meta_get(g, "rms_height") != NULL &&
	    rc_grid_meta_get(g, "rms_gradient") == NULL, "metadata names the rms height target");
	rc_grid_free(g);
}

/* Central differences damp mode q by sin(q dx)/(q dx) (the derivative of
 * e^{iqx} becomes i sin(q dx)/dx e^{iqx}), so by Parseval
 *   gbar_fd^2 = sum_k |a_k|^2 [sin^2(qx dx)/dx^2 + sin^2(qy dy)/dy^2].
 * The real-space estimate must equal this to round-off, and lie below the
 * spectral gbar by at most (q_s dx)^2/3 relative (sin^2 x >= x^2 (1 - x^2/3)). */
static void
test_finite_differences(void)
{
	rc_synth_params p;
	rc_grid *g;
	fftw_complex *a;
	double dx, dy, s = 0, pred = 0, fd, qs;
	size_t nx, ny, nxc;

	rc_synth_defaults(&p);
	p.nx = 256;
	p.ny = 128;
	p.lx = 2.0;
	p.ly = 1.0;
	p.lambda_r = 0.5;
	p.lambda_s = 0.05;
	g = make(&p);
	nx = p.nx;
	ny = p.ny;
	dx = p.lx / nx;
	dy = p.ly / ny;
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double gx = (g->z[j * nx + (i + 1) % nx] - g->z[j * nx + (i + nx - 1) % nx]) / (2 * dx);
			double gy = (g->z[((j + 1) % ny) * nx + i] - g->z[((j + ny - 1) % ny) * nx + i]) / (2 * dy);
			s += gx * gx + gy * gy;
		}
	fd = sqrt(s / (double)(nx * ny));
	a = modes(g);
	nxc = nx / 2 + 1;
	for (size_t j = 0; j < ny; j++) {
		double qy = rc_wavenumber(j, ny, p.ly);
		for (size_t i = 0; i < nxc; i++) {
			double qx = rc_wavenumber(i, nx, p.lx);
			double c = creal(a[j * nxc + i] * conj(a[j * nxc + i]));
			double sx = sin(qx * dx) / dx, sy = sin(qy * dy) / dy;
			pred += rc_fft_weight(i, nx) * c * (sx * sx + sy * sy);
		}
	}
	pred = sqrt(pred);
	test_rel(fd, pred, 1e-10, "finite-difference gbar = damped spectral sum");
	qs = 2 * M_PI / p.lambda_s;
	test_range(fd, 1.0 - (qs * dx) * (qs * dx) / 3, 1.0,
	    "finite-difference gbar %.6f below spectral 1 by at most (q_s dx)^2/3", fd);
	fftw_free(a);
	rc_grid_free(g);
}

/* Same seed and lengths at two resolutions: the coarse grid is every
 * second point of the fine one, because both hold exactly the same modes
 * (lambda_s = 2 coarse spacings and the band is open at q_s). */
static void
test_refinement(int gaussian, double peklenik, size_t nx, size_t ny, double lx,
    double ly)
{
	rc_synth_params p;
	rc_grid *c, *f;
	double worst = 0, rms;

	rc_synth_defaults(&p);
	p.nx = nx;
	p.ny = ny;
	p.lx = lx;
	p.ly = ly;
	p.hurst = 0.8;
	p.lambda_r = lx / 2;
	p.lambda_s = 2 * fmax(lx / nx / peklenik, ly / ny * peklenik);
	p.peklenik = peklenik;
	p.gaussian_amplitudes = gaussian;
	p.seed = 12345;
	c = make(&p);
	p.nx = 2 * nx;
	p.ny = 2 * ny;
	f = make(&p);
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double d = fabs(c->z[j * nx + i] - f->z[2 * j * 2 * nx + 2 * i]);
			if (d > worst)
				worst = d;
		}
	rms = hrms(c);
	/* Two FFTs of different sizes over identical modes: round-off. */
	test_abs(worst / rms, 0, 1e-12,
	    "coarse = every 2nd point of fine (%zux%zu, gaussian=%d, peklenik=%g)",
	    nx, ny, gaussian, peklenik);
	rc_grid_free(c);
	rc_grid_free(f);
}

/* A smaller lambda_s adds modes; the shared ones keep their phases and are
 * all scaled by one factor (the rms-gradient normalisation). */
static void
test_lambda_s(void)
{
	rc_synth_params p;
	rc_grid *g1, *g2;
	fftw_complex *a1, *a2;
	size_t ns;
	double complex num = 0;
	double den = 0, worst = 0, amax = 0, factor;
	long shared = 0, added = 0;

	rc_synth_defaults(&p);
	p.nx = p.ny = 256;
	p.lambda_r = 0.25;
	p.lambda_s = 1.0 / 16;
	p.seed = 7;
	g1 = make(&p);
	p.lambda_s = 1.0 / 64;
	g2 = make(&p);
	a1 = modes(g1);
	a2 = modes(g2);
	ns = (p.nx / 2 + 1) * p.ny;
	for (size_t k = 0; k < ns; k++) {
		double m = cabs(a1[k]);
		if (m > amax)
			amax = m;
	}
	for (size_t k = 0; k < ns; k++)
		if (cabs(a1[k]) > 1e-9 * amax) {
			num += a2[k] * conj(a1[k]);
			den += creal(a1[k] * conj(a1[k]));
			shared++;
		} else if (cabs(a2[k]) > 1e-9 * amax)
			added++;
	factor = creal(num) / den;
	for (size_t k = 0; k < ns; k++)
		if (cabs(a1[k]) > 1e-9 * amax) {
			double d = cabs(a2[k] - factor * a1[k]) / cabs(a1[k]);
			if (d > worst)
				worst = d;
		}
	test_true(shared > 50 && added > 500, "modes shared %ld, added %ld", shared, added);
	test_abs(cimag(num) / den, 0, 1e-12, "common factor is real (phases kept)");
	test_range(factor, 0.01, 0.99, "more modes at the same gbar: factor %g < 1", factor);
	/* Each shared mode equals factor * its old value to FFT round-off. */
	test_abs(worst, 0, 1e-9, "shared modes scaled by one common factor");
	fftw_free(a1);
	fftw_free(a2);
	rc_grid_free(g1);
	rc_grid_free(g2);
}

static void
test_seeds(void)
{
	rc_synth_params p;
	rc_grid *g1, *g2, *g3;
	double s = 0, r1, same = 0;

	rc_synth_defaults(&p);
	p.nx = p.ny = 128;
	p.lambda_r = 0.25;
	p.seed = 1;
	g1 = make(&p);
	g3 = make(&p);
	p.seed = 2;
	g2 = make(&p);
	for (size_t k = 0; k < 128 * 128; k++) {
		s += (g1->z[k] - g2->z[k]) * (g1->z[k] - g2->z[k]);
		same += fabs(g1->z[k] - g3->z[k]);
	}
	r1 = hrms(g1);
	test_true(same == 0, "same seed, same surface bit for bit");
	/* Independent phases: rms(h1 - h2) = sqrt(2(1 - rho)) hrms with a
	 * correlation rho of a few 0.1 at most for ~1e4 modes. */
	test_range(sqrt(s / (128 * 128)) / r1, 0.7, 2.0, "different seeds differ");
	test_true(rc_synth_mode_key(1, 3, 4) != rc_synth_mode_key(1, 4, 3) &&
	    rc_synth_mode_key(1, 3, 4) != rc_synth_mode_key(2, 3, 4) &&
	    rc_synth_mode_key(0, 0, 1) != rc_synth_mode_key(0, 1, 0),
	    "mode keys differ for swapped wave vectors and seeds");
	rc_grid_free(g1);
	rc_grid_free(g2);
	rc_grid_free(g3);
}

/* Thread count: each mode is independent and the normalisation sum is
 * added in row order, so any -j gives the same bits. */
static void
test_threads(void)
{
	rc_synth_params p;
	rc_grid *g1, *g2;
	int same = 1;

	rc_synth_defaults(&p);
	p.nx = p.ny = 128;
	rc_fft_set_threads(1);
	g1 = make(&p);
	rc_fft_set_threads(2);
	g2 = make(&p);
	for (size_t k = 0; k < 128 * 128; k++)
		same &= g1->z[k] == g2->z[k];
	test_true(same, "1 and 2 threads give identical surfaces");
	rc_fft_set_threads(1);
	rc_grid_free(g1);
	rc_grid_free(g2);
}

/* <h_x^2>/<h_y^2> = gamma^-4: substituting u = gamma qx, v = qy/gamma in
 * the integrals of qx^2 C(q_P) and qy^2 C(q_P) (Jacobian 1).  On the grid
 * the integrals are lattice sums over an elliptical band, so the ratio is
 * checked two ways: (1) the spectral derivatives of the surface equal the
 * lattice sums of the spectrum to round-off; (2) the lattice sums equal
 * gamma^-4 within the discreteness of the band, a few per cent here where
 * the narrow axis of the band spans only 4 to 24 lattice steps. */
static void
test_peklenik(void)
{
	double gammas[] = { 0.5, 2.0, 4.0 };
	rc_synth_params p;
	rc_err err;

	for (int t = 0; t < 3; t++) {
		double gam = gammas[t], g2 = gam * gam, sx = 0, sy = 0, lx = 0, ly = 0;
		double qr, qs;
		double *hx, *hy;
		rc_grid *g;
		size_t n;

		rc_synth_defaults(&p);
		p.nx = p.ny = 512;
		p.hurst = 0.8;
		p.lambda_r = 1.0 / 8;
		p.lambda_s = 1.0 / 64;
		p.peklenik = gam;
		p.seed = 3;
		g = make(&p);
		n = rc_grid_size(g);
		hx = malloc(n * sizeof(double));
		hy = malloc(n * sizeof(double));
		rc_spectral_derivs(g, NULL, hx, hy, NULL, &err);
		for (size_t k = 0; k < n; k++) {
			sx += hx[k] * hx[k];
			sy += hy[k] * hy[k];
		}
		qr = 2 * M_PI / p.lambda_r;
		qs = 2 * M_PI / p.lambda_s;
		for (long ky = -255; ky <= 255; ky++)
			for (long kx = -255; kx <= 255; kx++) {
				double qx = 2 * M_PI * kx, qy = 2 * M_PI * ky;
				double qp = sqrt(g2 * qx * qx + qy * qy / g2);
				if (qp < qr * (1 - 1e-9) || qp >= qs * (1 - 1e-9))
					continue;
				double c = pow(qp / qr, -2 * 1.8);
				lx += qx * qx * c;
				ly += qy * qy * c;
			}
		test_rel(sx / sy, lx / ly, 1e-9,
		    "Peklenik %g: surface <h_x^2>/<h_y^2> = lattice sum", gam);
		test_rel(sx / sy, pow(gam, -4), 0.05,
		    "Peklenik %g: <h_x^2>/<h_y^2> = gamma^-4 (%g)", gam, sx / sy);
		free(hx);
		free(hy);
		rc_grid_free(g);
	}
}

static void
test_harmonic(void)
{
	rc_synth_params p;
	rc_grid *g;
	size_t nx = 64;

	rc_synth_defaults(&p);
	p.type = RC_SURF_HARMONIC;
	p.nx = p.ny = nx;
	p.exponent = 2;
	p.radius = 1;
	g = make(&p);
	/* Apex at the cell centre (32, 32), h = 0 there, below elsewhere. */
	test_abs(g->z[32 * nx + 32], 0, 0, "harmonic apex h = 0 at the centre");
	/* r = 0.5 at the cell edge: -(1/2) 0.5^2. */
	test_rel(g->z[32 * nx + 0], -0.125, 1e-15, "harmonic n=2 at r = 0.5");
	/* The corner: r = sqrt(0.5), the farthest point. */
	test_rel(g->z[0], -0.25, 1e-15, "harmonic n=2 at the corner");
	/* Nearest periodic image: i = 1 and i = 63 are at the same distance. */
	test_rel(g->z[32 * nx + 1], g->z[32 * nx + 63], 1e-15, "periodic images");
	rc_grid_free(g);

	p.exponent = 1.5;
	p.radius = 2;
	p.lx = p.ly = 4;
	g = make(&p);
	/* (48, 32) on a 4x4 cell: r = 1: -(R/n)(r/R)^n = -(2/1.5) 0.5^1.5. */
	test_rel(g->z[32 * nx + 48], -(2 / 1.5) * pow(0.5, 1.5), 1e-14,
	    "harmonic n=1.5 R=2 at r = 1");
	/* (40, 38): r = hypot(0.5, 0.375) = 0.625. */
	test_rel(g->z[38 * nx + 40], -(2 / 1.5) * pow(0.625 / 2, 1.5), 1e-14,
	    "harmonic n=1.5 off axis");
	test_true(strcmp(rc_grid_meta_get(g, "type"), "harmonic") == 0 &&
	    rc_grid_meta_get(g, "exponent") && rc_grid_meta_get(g, "radius") &&
	    !rc_grid_meta_get(g, "H") && !rc_grid_meta_get(g, "seed"),
	    "harmonic metadata: exponent, radius, no self-affine keys");
	rc_grid_free(g);
}

static void
test_waves(void)
{
	rc_synth_params p;
	rc_grid *g;
	rc_err err;
	double worst = 0, gbar;

	/* A line: nx x 1, four periods. */
	rc_synth_defaults(&p);
	p.type = RC_SURF_SINE;
	p.nx = 100;
	p.ny = 1;
	p.lx = 2;
	p.wavelength = 0.5;
	p.amplitude = 0.01;
	g = make(&p);
	for (size_t i = 0; i < 100; i++) {
		double d = fabs(g->z[i] - 0.01 * cos(2 * M_PI * (2.0 * i / 100) / 0.5));
		if (d > worst)
			worst = d;
	}
	test_abs(worst, 0, 1e-16, "sine on a line: amplitude cos(2 pi x / lambda)");
	rc_grid_free(g);

	/* 2D sine: constant along y; normalised to rms gradient 1: the
	 * amplitude becomes lambda / (sqrt(2) pi) / ... exactly. */
	p.nx = 64;
	p.ny = 8;
	p.lx = 1;
	p.ly = 0.125;
	p.wavelength = 0.25;
	p.rms_gradient = 1;
	g = make(&p);
	rc_rms_gradient(g, NULL, &gbar, &err);
	test_rel(gbar, 1, 1e-12, "sine normalised to rms gradient 1");
	/* gbar = A k / sqrt(2) -> A = sqrt(2) / k. */
	double amp = sqrt(2) * 0.25 / (2 * M_PI), amp_meta = 0;
	rc_grid_meta_getd(g, "amplitude", &amp_meta);
	test_rel(amp_meta, amp, 1e-12, "sine metadata holds the scaled amplitude");
	test_abs(g->z[5 * 64 + 3], g->z[3], 0, "sine constant along y");
	test_rel(g->z[0], amp, 1e-12, "sine maximum at x = 0");
	rc_grid_free(g);

	p.type = RC_SURF_EGGBOX;
	p.nx = 48;
	p.ny = 32;
	p.lx = 1.5;
	p.ly = 1;
	p.wavelength = 0.5;
	p.amplitude = 2;
	p.rms_gradient = 0;
	g = make(&p);
	worst = 0;
	for (size_t j = 0; j < 32; j++)
		for (size_t i = 0; i < 48; i++) {
			double x = 1.5 * i / 48, y = 1.0 * j / 32, k = 2 * M_PI / 0.5;
			double d = fabs(g->z[j * 48 + i] - 2 * cos(k * x) * cos(k * y));
			if (d > worst)
				worst = d;
		}
	test_abs(worst, 0, 1e-14, "eggbox = amplitude cos(kx) cos(ky)");
	rc_grid_free(g);

	p.type = RC_SURF_FLAT;
	g = make(&p);
	worst = 0;
	for (size_t k = 0; k < 48 * 32; k++)
		worst = fmax(worst, fabs(g->z[k]));
	test_abs(worst, 0, 0, "flat is zero");
	test_true(g->nmeta == 1, "flat metadata: type only");
	rc_grid_free(g);
}

static void
test_metadata(void)
{
	const char *want[] = { "type", "H", "lambda_r", "lambda_s", "rolloff",
	    "peklenik", "seed", "amplitudes", "rms_gradient" };
	rc_synth_params p;
	rc_grid *g;
	double v;
	int ok = 1;

	rc_synth_defaults(&p);
	p.nx = 64;
	p.ny = 32;
	p.lx = 2;
	p.seed = 18446744073709551615ULL;
	p.gaussian_amplitudes = 1;
	g = make(&p);
	for (size_t k = 0; k < sizeof(want) / sizeof(want[0]); k++)
		ok &= rc_grid_meta_get(g, want[k]) != NULL;
	test_true(ok && g->nmeta == 9, "selfaffine metadata: the nine keys (%zu)", g->nmeta);
	test_true(strcmp(rc_grid_meta_get(g, "seed"), "18446744073709551615") == 0,
	    "seed written as an unsigned 64-bit integer");
	test_true(strcmp(rc_grid_meta_get(g, "amplitudes"), "gaussian") == 0,
	    "amplitudes = gaussian");
	test_true(rc_grid_meta_getd(g, "lambda_s", &v) && v == 2 * 2.0 / 64,
	    "default lambda_s is two grid spacings");
	test_true(rc_grid_meta_getd(g, "lambda_r", &v) && v == 2,
	    "default lambda_r is the longer cell side");
	rc_grid_free(g);
}

static void
test_checks(void)
{
	rc_synth_params p;
	rc_err err;

#define BAD(desc, stmt) do { \
	rc_synth_defaults(&p); p.nx = p.ny = 64; stmt; \
	test_true(rc_synth_check(&p, &err) != 0 && rc_synth(&p, &err) == NULL, \
	    "rejects %s", desc); } while (0)
	BAD("H = 0", p.hurst = 0);
	BAD("H = 1", p.hurst = 1);
	BAD("H = NaN", p.hurst = NAN);
	BAD("lambda_s below two spacings", p.lambda_s = 1.9 / 64);
	BAD("Peklenik 2 band beyond the y Nyquist", p.peklenik = 2; p.lambda_s = 2.0 / 64);
	BAD("lambda_r = lambda_s", p.lambda_r = 0.1; p.lambda_s = 0.1);
	BAD("negative lambda_r", p.lambda_r = -1);
	BAD("Peklenik 0", p.peklenik = 0);
	BAD("Peklenik Inf", p.peklenik = INFINITY);
	BAD("both rms targets", p.rms_gradient = 1; p.rms_height = 1);
	BAD("negative rms gradient", p.rms_gradient = -1);
	BAD("nx = 0", p.nx = 0);
	BAD("negative length", p.lx = -1);
	BAD("harmonic exponent 0", p.type = RC_SURF_HARMONIC; p.exponent = 0);
	BAD("harmonic radius -1", p.type = RC_SURF_HARMONIC; p.radius = -1);
	BAD("sine wavelength not dividing lx", p.type = RC_SURF_SINE; p.wavelength = 0.3);
	BAD("sine wavelength longer than lx", p.type = RC_SURF_SINE; p.wavelength = 2);
	BAD("eggbox wavelength not dividing ly", p.type = RC_SURF_EGGBOX; p.ly = 0.7;
	    p.wavelength = 0.5);
	BAD("normalising a flat surface", p.type = RC_SURF_FLAT; p.rms_gradient = 1);
	BAD("unknown type", p.type = (enum rc_surface_type)9);
#undef BAD
	/* Legal edge cases. */
	rc_synth_defaults(&p);
	p.nx = p.ny = 64;
	p.lambda_s = 2.0 / 64;
	test_true(rc_synth_check(&p, &err) == 0, "lambda_s = two spacings is legal");
	/* A band with no grid mode: a clear error, not a NaN surface. */
	/* |k| in [1.0101, 1.3333): between the lattice radii 1 and sqrt 2. */
	p.lambda_r = 0.99;
	p.lambda_s = 0.75;
	test_true(rc_synth(&p, &err) == NULL && strstr(err.msg, "no grid mode") != NULL,
	    "empty band is an error (%s)", err.msg);
	test_int(rc_surface_type_parse("eggbox"), RC_SURF_EGGBOX, "type parse");
	test_int(rc_surface_type_parse("cone"), -1, "type parse rejects unknown");
	test_true(strcmp(rc_surface_type_name(RC_SURF_SINE), "sine") == 0, "type name");
}

int
main(void)
{
	test_spectrum(0, 0.8, 0);
	test_spectrum(1, 0.8, 0);
	test_spectrum(0, 0.3, 1);
	test_mode_amplitudes();
	test_normalisation();
	test_finite_differences();
	test_refinement(0, 1, 256, 256, 1, 1);
	test_refinement(1, 1, 256, 256, 1, 1);
	test_refinement(0, 3, 128, 64, 2, 1);
	test_lambda_s();
	test_seeds();
	test_threads();
	test_peklenik();
	test_harmonic();
	test_waves();
	test_metadata();
	test_checks();
	return test_summary();
}
