/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_stats.c - Phi1..Phi9, moments, masks, height bins, C(q), ACF.
 *
 * Exact tests on cosines and egg-boxes; identities and invariances on
 * band-limited random-phase surfaces; ensemble tests against expectations
 * computed exactly from the mode amplitudes; Peklenik surfaces from
 * rc_synth against the closed form of Phi9.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_rng.h>

#include "fft.h"
#include "grid.h"
#include "psd.h"
#include "spectral.h"
#include "stats.h"
#include "synth.h"
#include "testlib.h"

/* Round-off tolerance for exact identities on grids of a few thousand
 * points: sums of O(N) terms of size O(1) lose ~N eps ~ 1e-12. */
#define EXACT 1e-10

/* h = amp cos(kx x + ky y), mx, my integer wave numbers of the cell. */
static rc_grid *
cosine(size_t nx, size_t ny, double lx, double ly, int mx, int my, double amp)
{
	rc_grid *g = test_new_grid(nx, ny, lx, ly);
	double kx = 2 * M_PI * mx / lx, ky = 2 * M_PI * my / ly;

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			g->z[j * nx + i] = amp * cos(kx * lx * (double)i / (double)nx +
			    ky * ly * (double)j / (double)ny);
	return g;
}

static void
stats_of(const rc_grid *g, const rc_grid *mask, enum rc_deriv_method m,
    rc_stats *s)
{
	rc_err err;

	if (rc_stats_compute(g, mask, m, s, &err) != 0) {
		fprintf(stderr, "test_stats: %s\n", err.msg);
		exit(1);
	}
}

static void
test_cosine(void)
{
	double amp = 0.3, lx = 2, ly = 1;
	int m = 3;
	double k = 2 * M_PI * m / lx;
	rc_grid *g = cosine(64, 32, lx, ly, m, 0, amp);
	rc_stats s;
	rc_err err;
	double gbar;

	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	test_rel(s.hrms, amp / sqrt(2), EXACT, "cosine hrms");
	test_rel(s.gbar, amp * k / sqrt(2), EXACT, "cosine gbar (field)");
	rc_rms_gradient(g, NULL, &gbar, &err);
	test_rel(gbar, amp * k / sqrt(2), EXACT, "cosine gbar (spectrum, Eq. 7)");
	test_rel(s.rms_laplacian, amp * k * k / sqrt(2), EXACT, "cosine rms laplacian");
	test_rel(s.kurtosis, 1.5, EXACT, "cosine kurtosis <cos^4>/<cos^2>^2 = 3/2");
	test_abs(s.skewness, 0, EXACT, "cosine skewness");
	test_rel(s.hmax - s.hmin, 2 * amp, EXACT, "cosine range");
	test_rel(s.phi[6], 1, EXACT, "cosine phi6 = 1");
	test_rel(s.phi[7], 1, EXACT, "cosine phi7 = 1");
	test_rel(s.phi[9], 1, EXACT, "cosine phi9 = 1 (one direction)");
	test_rel(s.phi[4], 0.5, EXACT, "cosine phi4 = <cos^2 sin^2>/(<cos^2><sin^2>) = 1/2");
	test_rel(s.phi[5], 0.5, EXACT, "cosine phi5 = phi4");
	test_rel(s.phi[8], -1.5, EXACT, "cosine phi8 = (3/8 - 1/4 - 1/2)/(1/4)");
	test_abs(s.phi[1], 0, EXACT, "cosine phi1 = 0");
	test_abs(s.phi[2], 0, EXACT, "cosine phi2 = 0");
	test_abs(s.phi[3], 0, EXACT, "cosine phi3 = 0");
	test_rel(s.nayak, 1, EXACT, "cosine nayak = 1");
	/* Finite differences: forward rms 2 sin(k dx/2)/dx, central sin(k dx)/dx. */
	double dx = lx / 64;
	test_rel(rc_gbar_forward(g), amp * 2 * sin(k * dx / 2) / dx / sqrt(2), EXACT,
	    "cosine gbar_fd (forward differences)");
	stats_of(g, NULL, RC_DERIV_FD, &s);
	test_rel(s.gbar, amp * sin(k * dx) / dx / sqrt(2), EXACT,
	    "cosine gbar with central differences");
	test_rel(s.phi[9], 1, EXACT, "cosine phi9 = 1 with finite differences");
	test_abs(s.phi[3], 0, EXACT, "phi3 = 0 with the 5-point Laplacian");
	rc_grid_free(g);

	/* Oblique wave: M has an off-diagonal part, still rank one. */
	g = cosine(48, 48, 1, 1, 2, 3, 1.7);
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	test_rel(s.phi[9], 1, EXACT, "oblique cosine phi9 = 1");
	test_rel(s.phi[6], 1, EXACT, "oblique cosine phi6 = 1");
	test_rel(s.phi[7], 1, EXACT, "oblique cosine phi7 = 1");
	test_rel(s.phi[8], -1.5, EXACT, "oblique cosine phi8 = -3/2");
	rc_grid_free(g);

	/* A wave along y has no x slope: Nayak of x profiles is undefined. */
	g = cosine(16, 16, 1, 1, 0, 2, 1);
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	test_true(isnan(s.nayak), "x-profile nayak of a y wave is NaN");
	test_rel(s.phi[9], 1, EXACT, "y wave phi9 = 1");
	rc_grid_free(g);

	/* Flat: every normalised quantity NaN, no crash. */
	g = test_new_grid(8, 8, 1, 1);
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	test_true(isnan(s.phi[1]) && isnan(s.phi[9]) && isnan(s.skewness) &&
	    s.gbar == 0 && s.hrms == 0, "flat surface: phi NaN, gbar = hrms = 0");
	rc_grid_free(g);
}

/* h = amp cos kx cos ky: <h^2> = amp^2/4, M = diag(1,1) amp^2 k^2/4,
 * lap = -2k^2 h, <h^4> = (3/8)^2 amp^4, <|grad h|^4> = (5/16) amp^4 k^4. */
static void
test_eggbox(void)
{
	size_t n = 32;
	rc_grid *g = test_new_grid(n, n, 1, 1);
	rc_stats s;

	for (size_t j = 0; j < n; j++)
		for (size_t i = 0; i < n; i++)
			g->z[j * n + i] = 2 * cos(2 * M_PI * 2 * (double)i / n) *
			    cos(2 * M_PI * 2 * (double)j / n);
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	test_rel(s.phi[6], 1, EXACT, "eggbox phi6 = 1");
	test_rel(s.phi[7], 1.5, EXACT, "eggbox phi7 = (2/3) 4 (9/64) 4 = 3/2");
	test_rel(s.phi[4], 0.75, EXACT, "eggbox phi4 = 3/4");
	test_rel(s.phi[8], -0.75, EXACT, "eggbox phi8 = (5/16 - 1/4 - 1/4)/(1/4)");
	test_abs(s.phi[9], 0, EXACT, "eggbox phi9 = 0 (isotropic gradient tensor)");
	test_rel(s.nayak, 1, EXACT, "eggbox nayak = 1");
	rc_grid_free(g);
}

/* Random-phase surface with integer wave vectors kmin <= |k| <= kmax and
 * amplitude |k|^-(1+H) (the self-affine C ~ q^-2(1+H)), built directly in
 * the half-complex spectrum.  Also returns, for the exact ensemble
 * expectations, sum a^2, sum a^2 q^2, sum a^4 q^2, sum a^4 q^4 over the
 * half-plane modes, a the cosine amplitudes. */
struct modesums {
	double a2, a2q2, a4q2, a4q4;
};

static rc_grid *
rpa_surface(size_t n, double l, int kmin, int kmax, double hurst,
    unsigned long seed, int gaussian, struct modesums *ms)
{
	rc_fft f;
	rc_err err;
	rc_grid *g = test_new_grid(n, n, l, l);
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	size_t nxc = n / 2 + 1;

	gsl_rng_set(rng, seed);
	rc_fft_init(&f, n, n, RC_FFT_ESTIMATE, &err);
	memset(f.spec, 0, nxc * n * sizeof(*f.spec));
	if (ms)
		memset(ms, 0, sizeof(*ms));
	for (int ky = -kmax; ky <= kmax; ky++)
		for (int kx = 0; kx <= kmax; kx++) {
			double k = hypot(kx, ky), amp, phase, q;
			/* canonical half plane: each conjugate pair once */
			if (kx == 0 && ky <= 0)
				continue;
			if (k < kmin || k > kmax)
				continue;
			amp = pow(k, -(1 + hurst));
			phase = 2 * M_PI * gsl_rng_uniform(rng);
			if (gaussian)
				amp *= sqrt(-log(1 - gsl_rng_uniform(rng)));
			size_t j = ky >= 0 ? (size_t)ky : n - (size_t)(-ky);
			double complex c = 0.5 * amp * cexp(I * phase);
			f.spec[j * nxc + (size_t)kx] = c;
			if (kx == 0)
				f.spec[(n - j) * nxc] = conj(c);
			q = 2 * M_PI * k / l;
			if (ms) {
				ms->a2 += amp * amp;
				ms->a2q2 += amp * amp * q * q;
				ms->a4q2 += pow(amp, 4) * q * q;
				ms->a4q4 += pow(amp, 4) * pow(q, 4);
			}
		}
	rc_fft_backward(&f);
	memcpy(g->z, f.real, n * n * sizeof(double));
	rc_fft_free(&f);
	gsl_rng_free(rng);
	return g;
}

/* Products of up to four fields of a surface with |k| <= kmax < n/4 have
 * no aliasing, so the summation-by-parts identities hold to round-off. */
static void
test_identities_and_invariance(void)
{
	rc_grid *g = rpa_surface(64, 1, 2, 14, 0.8, 7, 0, NULL);
	rc_stats a, b;
	double s = 3.7, t = 0.013, h0 = 5.25;

	stats_of(g, NULL, RC_DERIV_SPECTRAL, &a);
	test_abs(a.phi[1] - a.phi[2], 0, EXACT, "periodic: phi1 = phi2 (%g)", a.phi[1]);
	test_abs(a.phi[4] - a.phi[5], 0, EXACT, "periodic: phi4 = phi5 (%g)", a.phi[4]);
	test_abs(a.phi[3], 0, EXACT, "periodic: phi3 = 0");
	test_rel(a.gbar_prime, a.gbar, EXACT, "periodic: -<dh lap h> = gbar^2");
	/* r -> s r, z -> t z, h -> h + h0 */
	g->lx *= s;
	g->ly *= s;
	for (size_t k = 0; k < 64 * 64; k++)
		g->z[k] = t * g->z[k] + h0;
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &b);
	for (int i = 1; i <= 9; i++)
		test_abs(b.phi[i], a.phi[i], EXACT * (1 + fabs(a.phi[i])),
		    "phi%d invariant under r->sr, z->tz, h->h+h0", i);
	test_rel(b.nayak, a.nayak, EXACT, "nayak invariant");
	test_rel(b.skewness, a.skewness, 1e-9, "skewness invariant");
	test_rel(b.gbar, a.gbar * t / s, EXACT, "gbar scales as t/s");
	/* Finite differences: same invariance (lengths cancel in each Phi). */
	stats_of(g, NULL, RC_DERIV_FD, &b);
	g->lx /= s;
	g->ly /= s;
	stats_of(g, NULL, RC_DERIV_FD, &a);
	for (int i = 1; i <= 9; i++)
		test_abs(b.phi[i], a.phi[i], EXACT * (1 + fabs(a.phi[i])),
		    "FD phi%d invariant under r->sr", i);
	rc_grid_free(g);
}

/* Ensemble over phases with fixed amplitudes.  Second-order averages do
 * not depend on the phases, so E[Phi] = E[numerator]/denominator, and for
 * independent uniform phases (cosine amplitudes a_k, wave vectors q_k)
 *   E<dh^2 |grad h|^2> = <dh^2> gbar^2 - sum a^4 q^2 / 8,
 *   E[<|grad h|^4> - (tr M)^2 - 2 tr M^2] = -(3/8) sum a^4 q^4,
 *   E<dh |grad h|^2> = 0 (h -> -h is a phase shift by pi),
 * and Phi9 = 0 exactly on the square lattice (M is phase independent and
 * the mode set is symmetric under qx <-> qy, qy -> -qy). */
static void
test_rpa_ensemble(void)
{
	enum { SEEDS = 24 };
	double p1[SEEDS], p4[SEEDS], p8[SEEDS], e4 = 0, e8 = 0;
	struct modesums ms;

	for (int k = 0; k < SEEDS; k++) {
		rc_grid *g = rpa_surface(64, 1, 2, 14, 0.8, 100 + k, 0, &ms);
		rc_stats s;
		stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
		p1[k] = s.phi[1];
		p4[k] = s.phi[4];
		p8[k] = s.phi[8];
		test_abs(s.phi[9], 0, 1e-12, "rpa square lattice phi9 = 0 (seed %d)", k);
		rc_grid_free(g);
	}
	e4 = 1 - (ms.a4q2 / 8) / ((ms.a2 / 2) * (ms.a2q2 / 2));
	e8 = -(3.0 / 8) * ms.a4q4 / ((ms.a2q2 / 2) * (ms.a2q2 / 2));
	double *v[3] = { p1, p4, p8 }, want[3] = { 0, e4, e8 };
	const char *name[3] = { "phi1", "phi4", "phi8" };
	for (int m = 0; m < 3; m++) {
		double mean = 0, var = 0;
		for (int k = 0; k < SEEDS; k++)
			mean += v[m][k] / SEEDS;
		for (int k = 0; k < SEEDS; k++)
			var += (v[m][k] - mean) * (v[m][k] - mean) / (SEEDS - 1);
		/* 4 standard errors: a false failure has probability ~1e-4. */
		test_abs(mean, want[m], 4 * sqrt(var / SEEDS),
		    "rpa ensemble mean %s = %g within 4 s.e. (sd %g)", name[m],
		    want[m], sqrt(var));
	}
	test_range(e4, 0.9, 1, "expected phi4 of the rpa ensemble near 1 (%g)", e4);
	test_range(e8, -0.1, 0, "expected phi8 of the rpa ensemble near 0 (%g)", e8);
}

/* Nayak from real-space fields vs from the spectrum's moments, and the
 * isotropic relation phi6 = 2 alpha / 3. */
static void
test_nayak(void)
{
	rc_grid *g = rpa_surface(128, 2, 4, 30, 0.8, 3, 0, NULL);
	rc_stats s;
	rc_err err;
	double m0, m2, m4;

	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	test_true(rc_psd_moments_x(g, NULL, &m0, &m2, &m4, &err) == 0, "moments");
	test_rel(s.nayak, m0 * m4 / (m2 * m2), EXACT, "nayak: fields vs spectral moments");
	test_rel(s.hrms * s.hrms, m0, EXACT, "m0 = <dh^2>");
	test_rel(2 * m2, s.gbar * s.gbar, EXACT, "isotropic lattice: m2 = gbar^2/2");
	/* <h_xx^2> = (3/8) <(lap h)^2> holds for a continuous isotropic spectrum;
	 * the lattice's ring of 4 <= |k| <= 30 averages cos^4 to within ~1%. */
	test_rel(s.phi[6], 2 * s.nayak / 3, 0.01, "isotropic: phi6 = 2 nayak / 3");
	rc_grid_free(g);
}

static void
test_mask(void)
{
	size_t nx = 40, ny = 10;
	double amp = 0.5, lx = 1, k = 2 * M_PI * 2 / lx;
	rc_grid *g = cosine(nx, ny, lx, 1, 2, 0, amp), *mask = test_new_grid(nx, ny, 1, 1);
	rc_stats s, full;
	rc_err err;
	double mean = 0, c = 0, gx2 = 0, m2 = 0, dlap = 0, lap = 0;

	/* Contact where cos(kx) > 0.3: the upper parts of the wave. */
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double x = lx * (double)i / (double)nx;
			mask->z[j * nx + i] = cos(k * x) > 0.3;
		}
	mask->kind = RC_KIND_MASK;
	stats_of(g, mask, RC_DERIV_SPECTRAL, &s);
	/* Direct sums with the analytic derivatives h_x = -amp k sin(kx),
	 * lap h = -k^2 h. */
	for (int pass = 0; pass < 2; pass++) {
		for (size_t j = 0; j < ny; j++)
			for (size_t i = 0; i < nx; i++) {
				double x = lx * (double)i / (double)nx, h = amp * cos(k * x);
				if (mask->z[j * nx + i] != 1)
					continue;
				if (pass == 0) {
					mean += h;
					c++;
					continue;
				}
				double d = h - mean;
				gx2 += amp * amp * k * k * sin(k * x) * sin(k * x) / c;
				m2 += d * d / c;
				dlap += d * (-k * k * h) / c;
				lap += -k * k * h / c;
			}
		if (pass == 0)
			mean /= c;
	}
	test_int((long long)s.n_avg, (long long)c, "mask count");
	test_rel(s.fraction, c / (double)(nx * ny), EXACT, "contact fraction");
	test_rel(s.mean, mean, EXACT, "masked mean");
	test_rel(s.gbar, sqrt(gx2), EXACT, "gbar_c");
	test_rel(s.gbar_prime, sqrt(-dlap), EXACT, "gbar_c_prime (Eq. 9)");
	test_rel(s.hrms, sqrt(m2), EXACT, "masked hrms");
	test_rel(s.phi[3], -m2 * lap / (2 * sqrt(m2) * gx2), EXACT,
	    "phi3 over contact: nonzero, curvature negative (%g)", s.phi[3]);
	test_true(s.phi[3] > 0, "phi3 > 0 over contact at the tops");
	/* All ones: the same as no mask. */
	for (size_t p = 0; p < nx * ny; p++)
		mask->z[p] = 1;
	stats_of(g, mask, RC_DERIV_SPECTRAL, &s);
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &full);
	for (int i = 1; i <= 9; i++)
		test_true(s.phi[i] == full.phi[i] || (isnan(s.phi[i]) && isnan(full.phi[i])),
		    "all-ones mask gives the unmasked phi%d", i);
	/* Errors. */
	mask->z[3] = 0.5;
	test_true(rc_stats_compute(g, mask, RC_DERIV_SPECTRAL, &s, &err) != 0 &&
	    strstr(err.msg, "0 or 1"), "mask value 0.5 rejected (%s)", err.msg);
	memset(mask->z, 0, nx * ny * sizeof(double));
	test_true(rc_stats_compute(g, mask, RC_DERIV_SPECTRAL, &s, &err) != 0 &&
	    strstr(err.msg, "no point"), "empty mask rejected (%s)", err.msg);
	rc_grid_free(mask);
	mask = test_new_grid(nx, ny + 1, 1, 1);
	test_true(rc_stats_compute(g, mask, RC_DERIV_SPECTRAL, &s, &err) != 0 &&
	    strstr(err.msg, "40x11"), "wrong-size mask rejected (%s)", err.msg);
	rc_grid_free(mask);
	rc_grid_free(g);
}

static void
test_by_height(void)
{
	size_t n = 48, nb = 6;
	double amp = 0.4, k = 2 * M_PI * 3;
	rc_grid *g = cosine(n, n, 1, 1, 3, 0, amp);
	rc_height_bin bins[6];
	rc_stats s;
	rc_err err;
	size_t total = 0;
	double g2 = 0;

	test_true(rc_stats_by_height(g, NULL, RC_DERIV_SPECTRAL, nb, bins, &err) == 0,
	    "by height runs");
	stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
	for (size_t b = 0; b < nb; b++) {
		/* h_x^2 = k^2 (amp^2 - h^2) at every point of the wave. */
		double want = 0;
		size_t cnt = 0;
		for (size_t p = 0; p < n * n; p++) {
			double h = g->z[p];
			size_t bb = (size_t)((h - s.hmin) / ((s.hmax - s.hmin) / nb));
			if (bb >= nb)
				bb = nb - 1;
			if (bb == b) {
				want += k * k * (amp * amp - h * h);
				cnt++;
			}
		}
		test_int((long long)bins[b].n, (long long)cnt, "bin %zu count", b);
		if (cnt)
			test_rel(bins[b].mxx, want / (double)cnt, EXACT,
			    "bin %zu <h_x^2> = k^2 (amp^2 - <h^2>)", b);
		test_abs(bins[b].myy, 0, EXACT, "bin %zu <h_y^2> = 0", b);
		total += bins[b].n;
		g2 += (double)bins[b].n * bins[b].gbar * bins[b].gbar;
	}
	test_int((long long)total, (long long)(n * n), "bins hold every point");
	test_rel(sqrt(g2 / (double)(n * n)), s.gbar, EXACT, "bins recombine to gbar");
	test_true(bins[0].gbar < bins[nb / 2].gbar,
	    "rms gradient smaller at the wave's extremes");
	rc_grid_free(g);
}

static void
test_psd(void)
{
	double amp = 0.7, lx = 2, ly = 1.5;
	size_t nx = 32, ny = 24;
	rc_grid *g = cosine(nx, ny, lx, ly, 3, 2, amp), *s2;
	rc_err err;
	rc_psd_bin *bins;
	size_t nb;
	double sum = 0, mean, rms;

	/* A constant offset exercises the q = 0 mode. */
	for (size_t p = 0; p < nx * ny; p++)
		g->z[p] += 0.2;
	s2 = rc_psd2d(g, NULL, &err);
	test_true(s2 != NULL && s2->kind == RC_KIND_SPECTRUM, "psd2d grid");
	for (size_t p = 0; p < nx * ny; p++)
		sum += s2->z[p];
	sum *= (2 * M_PI / lx) * (2 * M_PI / ly);
	rc_mean_rms(g->z, nx * ny, &mean, &rms);
	test_rel(sum, mean * mean + rms * rms, EXACT, "sum C dq^2 = <h^2>");
	/* The wave's two modes: C = (amp/2)^2 A / (2 pi)^2 at q = +-(3, 2). */
	size_t i = nx / 2 + 3, j = ny / 2 + 2;
	test_rel(s2->z[j * nx + i], amp * amp / 4 * lx * ly / (4 * M_PI * M_PI),
	    EXACT, "cosine mode C = (amp/2)^2 A/(2pi)^2");
	i = nx / 2 - 3, j = ny / 2 - 2;
	test_rel(s2->z[j * nx + i], amp * amp / 4 * lx * ly / (4 * M_PI * M_PI),
	    EXACT, "mirror mode");
	test_rel(s2->z[(ny / 2) * nx + nx / 2], 0.04 * lx * ly / (4 * M_PI * M_PI),
	    EXACT, "q = 0 mode holds the mean");
	rc_grid_free(s2);
	rc_grid_free(g);

	/* Radial table of a random surface: sum c n dq^2 = variance. */
	g = rpa_surface(64, 1, 2, 20, 0.8, 9, 1, NULL);
	test_true(rc_psd_radial(g, NULL, 10, &bins, &nb, &err) == 0, "radial psd");
	sum = 0;
	size_t modes = 0;
	for (size_t b = 0; b < nb; b++) {
		sum += bins[b].c * (double)bins[b].n_modes * 4 * M_PI * M_PI;
		modes += bins[b].n_modes;
		if (b)
			test_true(bins[b].q > bins[b - 1].q, "bins increase in q");
	}
	rc_mean_rms(g->z, 64 * 64, &mean, &rms);
	test_rel(sum, rms * rms, EXACT, "radial: sum C n_modes dq^2 = <dh^2>");
	test_int((long long)modes, 64 * 64 - 1, "radial bins hold every mode but q = 0");
	free(bins);
	rc_grid_free(g);
}

/* C(q) of rc_synth output is the requested spectrum: with sqrt(C)
 * amplitudes every mode of the 2D spectrum is K (q/q_r)^-2(1+H) inside
 * q_r <= q < q_s and zero outside; the radial table follows it in every
 * bin lying wholly inside the band. */
static void
test_psd_synth(void)
{
	rc_synth_params p;
	rc_err err;
	rc_grid *g, *s2;
	rc_psd_bin *bins;
	size_t nb, n = 128, inside = 0;
	double bpd = 20, ref = NAN;

	rc_synth_defaults(&p);
	p.nx = p.ny = n;
	p.hurst = 0.7;
	p.lambda_r = 0.25;
	p.lambda_s = 1.0 / 32;
	if ((g = rc_synth(&p, &err)) == NULL) {
		test_true(0, "rc_synth: %s", err.msg);
		return;
	}
	double qr = 2 * M_PI / p.lambda_r, qs = 2 * M_PI / p.lambda_s;
	s2 = rc_psd2d(g, NULL, &err);
	int bad_in = 0, bad_out = 0;
	for (size_t j = 0; j < n; j++)
		for (size_t i = 0; i < n; i++) {
			double q = 2 * M_PI * hypot((double)i - n / 2, (double)j - n / 2);
			double c = s2->z[j * n + i];
			if (q >= qr * (1 - 1e-9) && q < qs * (1 - 1e-9)) {
				double want = pow(q / qr, -2 * (1 + p.hurst));
				if (isnan(ref))
					ref = c / want;
				bad_in += fabs(c / want / ref - 1) > EXACT;
				inside++;
			} else
				bad_out += c > 1e-30 * ref;
		}
	test_int(bad_in, 0, "every mode in the band has C = K (q/q_r)^-2(1+H) "
	    "(%zu modes)", inside);
	test_int(bad_out, 0, "every mode outside the band has C = 0");
	rc_grid_free(s2);
	rc_psd_radial(g, NULL, bpd, &bins, &nb, &err);
	for (size_t b = 0; b < nb; b++) {
		double q = bins[b].q, lo = q * pow(10, -0.5 / bpd), hi = q * pow(10, 0.5 / bpd);
		if (lo < qr * 1.01 || hi > qs * 0.99)
			continue;
		/* Within a bin 10^(1/20) wide, q^-3.4 varies by 48%: the bin
		 * mean of C sits within ~15% of C at the bin's mean q. */
		double want = ref * pow(q / qr, -2 * (1 + p.hurst));
		test_rel(bins[b].c, want, 0.15, "radial C(q) at q %g", q);
		test_true(bins[b].std_err > 0 && bins[b].std_err < bins[b].c,
		    "bin standard error positive and below C");
	}
	free(bins);
	rc_grid_free(g);
}

/* Phi9 of Peklenik surfaces.  Continuum: for C(q_P), q_P^2 = gamma^2 qx^2
 * + qy^2/gamma^2, substituting qx = u/gamma, qy = gamma v gives
 * <h_x^2>/<h_y^2> = gamma^-4 and M_xy = 0, so
 * Phi9 = ((1 - gamma^4)/(1 + gamma^4))^2.  On the grid with sqrt(C)
 * amplitudes M is the lattice sum of C q_a q_b, computed here
 * independently; the lattice sum approaches the closed form as the band
 * holds more modes (measured: |error| 5.5e-3, 1.6e-3, 2.8e-3 for gamma =
 * 2, 4, 1/3 at q_r = 4 dq, q_s = 24 dq; 1.4e-3, 3.5e-4, 3e-5 at 8 dq,
 * 128 dq). */
static void
test_peklenik(void)
{
	double gammas[3] = { 2, 4, 1.0 / 3 }, hurst = 0.8, kr = 4, ks = 24;

	for (int k = 0; k < 3; k++) {
		double gm = gammas[k], g4 = pow(gm, 4);
		double want = pow((1 - g4) / (1 + g4), 2);
		enum { SEEDS = 6 };
		double v[SEEDS], mean = 0, var = 0, mxx = 0, myy = 0, mxy = 0;
		int box = (int)ceil(fmax(gm, 1 / gm) * ks) + 1;
		rc_synth_params p;
		rc_err err;
		rc_stats s;

		for (int a = -box; a <= box; a++)
			for (int b = -box; b <= box; b++) {
				double qp = sqrt(gm * gm * a * a + b * b / (gm * gm)), c;
				if (qp < kr * (1 - 1e-9) || qp >= ks * (1 - 1e-9))
					continue;
				c = pow(qp / kr, -2 * (1 + hurst));
				mxx += c * a * a;
				myy += c * b * b;
				mxy += c * a * b;
			}
		double lattice = ((mxx - myy) * (mxx - myy) + 4 * mxy * mxy) /
		    ((mxx + myy) * (mxx + myy));
		rc_synth_defaults(&p);
		p.nx = p.ny = 256;
		p.hurst = hurst;
		p.peklenik = gm;
		p.lambda_r = 1 / kr;
		p.lambda_s = 1 / ks;
		rc_grid *g = rc_synth(&p, &err);
		if (g == NULL) {
			test_true(0, "rc_synth: %s", err.msg);
			return;
		}
		stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
		test_rel(s.phi[9], lattice, EXACT, "peklenik %g: phi9 = lattice sum %g",
		    gm, lattice);
		test_rel(s.mxx / s.myy, mxx / myy, EXACT, "peklenik %g: <h_x^2>/<h_y^2>", gm);
		test_abs(s.phi[9], want, 0.01, "peklenik %g: phi9 %g vs closed form %g",
		    gm, s.phi[9], want);
		rc_grid_free(g);
		/* Rayleigh amplitudes: Phi9 fluctuates; its spread over seeds
		 * sets the tolerance of the mean (plus the lattice error). */
		p.gaussian_amplitudes = 1;
		for (int sd = 0; sd < SEEDS; sd++) {
			p.seed = 11 + (unsigned)sd;
			g = rc_synth(&p, &err);
			stats_of(g, NULL, RC_DERIV_SPECTRAL, &s);
			v[sd] = s.phi[9];
			mean += v[sd] / SEEDS;
			rc_grid_free(g);
		}
		for (int sd = 0; sd < SEEDS; sd++)
			var += (v[sd] - mean) * (v[sd] - mean) / (SEEDS - 1);
		test_abs(mean, want, 4 * sqrt(var / SEEDS) + 0.01,
		    "peklenik %g, Rayleigh amplitudes: mean phi9 %g vs %g (sd %g)",
		    gm, mean, want, sqrt(var));
	}
}

/* ACF against a brute-force O(N^2) sum. */
static void
test_acf(void)
{
	size_t nx = 12, ny = 10;
	double lx = 1.2, ly = 1;
	rc_grid *g = test_new_grid(nx, ny, lx, ly);
	rc_acf_point *pts;
	size_t np;
	rc_err err;
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	double dx = lx / nx, dy = ly / ny, dr = fmax(dx, dy);

	for (size_t p = 0; p < nx * ny; p++)
		g->z[p] = gsl_rng_uniform(rng) - 0.3;
	gsl_rng_free(rng);
	test_true(rc_acf(g, NULL, &pts, &np, &err) == 0, "acf runs");
	size_t nrad = (size_t)floor(0.5 * fmin(lx, ly) / dr + 0.5) + 1;
	double *want = calloc(nrad, sizeof(double)), *cnt = calloc(nrad, sizeof(double));
	double gx[12], gy[10];
	for (size_t dj = 0; dj < ny; dj++)
		for (size_t di = 0; di < nx; di++) {
			double sum = 0;
			for (size_t j = 0; j < ny; j++)
				for (size_t i = 0; i < nx; i++) {
					double d = g->z[((j + dj) % ny) * nx + (i + di) % nx] -
					    g->z[j * nx + i];
					sum += d * d;
				}
			sum /= (double)(nx * ny);
			if (dj == 0)
				gx[di] = sum;
			if (di == 0)
				gy[dj] = sum;
			double rx = (di <= nx / 2 ? (double)di : (double)di - nx) * dx;
			double ry = (dj <= ny / 2 ? (double)dj : (double)dj - ny) * dy;
			double r = hypot(rx, ry);
			if (r > 0.5 * fmin(lx, ly) * (1 + 1e-12))
				continue;
			size_t b = (size_t)floor(r / dr + 0.5);
			want[b] += sum;
			cnt[b]++;
		}
	size_t b = 0;
	for (size_t p = 0; p < np; p++) {
		if (pts[p].dir == RC_ACF_X)
			test_rel(pts[p].g, gx[(size_t)lround(pts[p].r / dx)], EXACT,
			    "acf x at r %g", pts[p].r);
		else if (pts[p].dir == RC_ACF_Y)
			test_rel(pts[p].g, gy[(size_t)lround(pts[p].r / dy)], EXACT,
			    "acf y at r %g", pts[p].r);
		else {
			while (cnt[b] == 0)
				b++;
			test_rel(pts[p].g, want[b] / cnt[b], EXACT, "acf radial bin %zu", b);
			test_int((long long)pts[p].n, (long long)cnt[b], "radial bin count");
			b++;
		}
	}
	free(want);
	free(cnt);
	free(pts);
	rc_grid_free(g);
}

int
main(void)
{
	test_cosine();
	test_eggbox();
	test_identities_and_invariance();
	test_rpa_ensemble();
	test_nayak();
	test_mask();
	test_by_height();
	test_psd();
	test_psd_synth();
	test_peklenik();
	test_acf();
	return test_summary();
}
