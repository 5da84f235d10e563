/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_contact.c - contact analysis: counts, contact line, periodic
 * patches, A_c, Yastrebov's estimate, gradients over the contact, kappa. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "contact_internal.h"
#include "grid.h"
#include "kappa.h"
#include "spectral.h"
#include "testlib.h"

/* Mask from a picture: rows top to bottom are j = 0, 1, ...; 'X' is contact. */
static unsigned char *
mask_from(const char *const *rows, size_t nx, size_t ny)
{
	unsigned char *m = calloc(nx * ny, 1);

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++)
			m[j * nx + i] = rows[j][i] == 'X';
	return m;
}

static void
check_mask(const char *name, const unsigned char *m, size_t nx, size_t ny,
    size_t n_c, size_t n_cl, size_t n_patches, double sum_sq)
{
	size_t np;
	double sq;
	rc_err err;

	test_int((long long)rc_contact_count(m, nx * ny), (long long)n_c, "%s: n_c", name);
	test_int((long long)rc_contact_line(m, nx, ny), (long long)n_cl, "%s: n_cl", name);
	test_true(rc_contact_patches(m, nx, ny, &np, &sq, &err) == 0, "%s: patches run", name);
	test_int((long long)np, (long long)n_patches, "%s: n_patches", name);
	test_abs(sq, sum_sq, 0, "%s: sum of squared patch sizes", name);
}

static void
test_hand_made(void)
{
	static const char *const single[] = {
		"........", "........", "...X....", "........", "........", "........" };
	static const char *const block3[] = {
		"........", ".XXX....", ".XXX....", ".XXX....", "......X.", "........" };
	/* The four corners touch across both boundaries: one patch. */
	static const char *const corners[] = {
		"X......X", "........", "........", "........", "........", "X......X" };
	/* A band crossing the x boundary and a column crossing the y one. */
	static const char *const wrap[] = {
		"....X...", "XX..X.XX", "....X...", "........", "....X...", "....X..." };
	/* A U whose arms are labelled apart until the bottom row joins them. */
	static const char *const u_shape[] = {
		"X.X..", "X.X..", "X.X..", "XXX..", "....." };
	/* Checkerboard on an odd width: (4, j) and (0, j) touch across x. */
	static const char *const checker5[] = {
		"X.X.X", ".X.X.", "X.X.X", ".X.X." };
	static const char *const full[] = { "XXX", "XXX" };
	static const char *const empty[] = { "...", "..." };
	unsigned char *m;

	m = mask_from(single, 8, 6);
	check_mask("single point", m, 8, 6, 1, 1, 1, 1);
	free(m);
	/* 3x3 block: only its centre has four contact neighbours. */
	m = mask_from(block3, 8, 6);
	check_mask("3x3 block + point", m, 8, 6, 10, 9, 2, 81 + 1);
	free(m);
	m = mask_from(corners, 8, 6);
	check_mask("corners across both boundaries", m, 8, 6, 4, 4, 1, 16);
	free(m);
	m = mask_from(wrap, 8, 6);
	/* The band's runs {0,1} and {6,7} join across x (4 points); column 4
	 * (rows 0-2 and 4-5) joins across y (5 points), not touching the band
	 * since columns 3 and 5 of row 1 are empty. */
	check_mask("wrap-around band and column", m, 8, 6, 9, 9, 2, 25 + 16);
	free(m);
	/* Every point of the U borders an empty column, row 4, or wraps to one. */
	m = mask_from(u_shape, 5, 5);
	check_mask("U shape merged late", m, 5, 5, 9, 9, 1, 81);
	free(m);
	/* Rows 0 and 2: {0,4} (joined across x) and {2}; rows 1 and 3: {1},{3}.
	 * Sizes 2,1,1,1,2,1,1,1. */
	m = mask_from(checker5, 5, 4);
	check_mask("odd checkerboard", m, 5, 4, 10, 10, 8, 14);
	free(m);
	/* Even checkerboard: every point isolated. */
	m = calloc(64, 1);
	for (size_t j = 0; j < 8; j++)
		for (size_t i = 0; i < 8; i++)
			m[j * 8 + i] = (i + j) % 2 == 0;
	check_mask("even checkerboard", m, 8, 8, 32, 32, 32, 32);
	free(m);
	m = mask_from(full, 3, 2);
	check_mask("full contact", m, 3, 2, 6, 0, 1, 36);
	free(m);
	m = mask_from(empty, 3, 2);
	check_mask("no contact", m, 3, 2, 0, 0, 0, 0);
	free(m);
	/* Line grid nx x 1: only the two x neighbours; 1 1 0 1 is one patch
	 * across the boundary, points 1 and 3 border the gap. */
	{
		unsigned char line[4] = { 1, 1, 0, 1 };
		check_mask("line 1101", line, 4, 1, 3, 2, 1, 9);
		unsigned char col[4] = { 1, 0, 1, 0 };
		check_mask("column 1 x 4 1010", col, 1, 4, 2, 2, 2, 2);
		unsigned char one[1] = { 1 };
		check_mask("1 x 1 grid", one, 1, 1, 1, 0, 1, 1);
	}
}

/* Independent reference: flood fill with an explicit stack over points,
 * and the contact line by brute force. */
static void
reference(const unsigned char *m, size_t nx, size_t ny, size_t *n_cl,
    size_t *n_patches, double *sum_sq)
{
	size_t n = nx * ny, *stack = malloc(n * sizeof(*stack));
	unsigned char *seen = calloc(n, 1);

	*n_cl = *n_patches = 0;
	*sum_sq = 0;
	for (size_t p = 0; p < n; p++) {
		size_t i = p % nx, j = p / nx;
		size_t nb[4] = { j * nx + (i + 1) % nx, j * nx + (i + nx - 1) % nx,
		    ((j + 1) % ny) * nx + i, ((j + ny - 1) % ny) * nx + i };
		if (m[p] && (!m[nb[0]] || !m[nb[1]] || !m[nb[2]] || !m[nb[3]]))
			(*n_cl)++;
		if (!m[p] || seen[p])
			continue;
		size_t top = 0, size = 0;
		stack[top++] = p;
		seen[p] = 1;
		while (top) {
			size_t q = stack[--top], qi = q % nx, qj = q / nx;
			size_t qn[4] = { qj * nx + (qi + 1) % nx, qj * nx + (qi + nx - 1) % nx,
			    ((qj + 1) % ny) * nx + qi, ((qj + ny - 1) % ny) * nx + qi };
			size++;
			for (int k = 0; k < 4; k++)
				if (m[qn[k]] && !seen[qn[k]]) {
					seen[qn[k]] = 1;
					stack[top++] = qn[k];
				}
		}
		(*n_patches)++;
		*sum_sq += (double)size * (double)size;
	}
	free(stack);
	free(seen);
}

static void
test_random_masks(void)
{
	static const size_t shapes[][2] = {
		{ 17, 13 }, { 64, 64 }, { 1, 31 }, { 31, 1 }, { 2, 2 }, { 3, 50 }, { 97, 5 } };
	static const double density[] = { 0.1, 0.4, 0.5, 0.6, 0.9 };
	unsigned long long state = 12345;

	for (size_t s = 0; s < sizeof(shapes) / sizeof(shapes[0]); s++) {
		size_t nx = shapes[s][0], ny = shapes[s][1], n = nx * ny;
		unsigned char *m = malloc(n);
		for (size_t d = 0; d < sizeof(density) / sizeof(density[0]); d++) {
			size_t n_cl, np, rnp;
			double sq, rsq;
			rc_err err;
			for (size_t p = 0; p < n; p++) {
				state = state * 6364136223846793005ULL + 1442695040888963407ULL;
				m[p] = (double)(state >> 11) / 9007199254740992.0 < density[d];
			}
			reference(m, nx, ny, &n_cl, &rnp, &rsq);
			test_int((long long)rc_contact_line(m, nx, ny), (long long)n_cl,
			    "random %zux%zu density %g: n_cl vs brute force", nx, ny, density[d]);
			rc_contact_patches(m, nx, ny, &np, &sq, &err);
			test_int((long long)np, (long long)rnp,
			    "random %zux%zu density %g: patches vs flood fill", nx, ny, density[d]);
			test_abs(sq, rsq, 0,
			    "random %zux%zu density %g: sum s^2 vs flood fill", nx, ny, density[d]);
		}
		free(m);
	}
}

/* A_c in area units and Yastrebov's estimate through rc_contact_analyse. */
static void
test_analyse(void)
{
	static const char *const block3[] = {
		"........", ".XXX....", ".XXX....", ".XXX....", "......X.", "........" };
	rc_contact_opts o;
	rc_contact_stats st;
	rc_err err;
	rc_grid *h = rc_grid_new(8, 6, 2.0, 3.0, &err);
	unsigned char *m = mask_from(block3, 8, 6);
	double cell = (2.0 / 8) * (3.0 / 6);

	rc_contact_defaults(&o);
	o.flags = RC_CONTACT_COUNT | RC_CONTACT_LINE | RC_CONTACT_PATCHES;
	test_true(rc_contact_analyse(h, m, &o, &st, &err) == 0, "analyse runs");
	test_rel(st.a_r, 10.0 / 48, 1e-15, "a_r = n_c/n_tot");
	/* Patches of 9 and 1 points: A_c = (81 + 1)/10 points. */
	test_rel(st.patch_size_char, 8.2 * cell, 1e-15, "A_c = sum s^2/sum s in area units");
	test_rel(RC_YASTREBOV_ALPHA, (M_PI - 1 + M_LN2) / 24, 1e-15,
	    "alpha = (pi - 1 + ln 2)/24");
	test_rel(RC_YASTREBOV_ALPHA, 0.11811, 5e-5, "alpha as printed, 0.11811");
	test_rel(st.a_yastrebov, (10 - RC_YASTREBOV_ALPHA * 9) / 48, 1e-15,
	    "Yastrebov Eq. 22 with the default alpha");
	o.alpha = 0.25;
	rc_contact_analyse(h, m, &o, &st, &err);
	test_rel(st.a_yastrebov, (10 - 0.25 * 9) / 48, 1e-15, "Yastrebov with alpha 0.25");
	test_true(isnan(st.gbar_c) && isnan(st.kappa), "gradients not computed unless asked");
	o.flags = RC_CONTACT_COUNT;
	rc_contact_analyse(h, m, &o, &st, &err);
	test_true(st.n_cl == 0 && st.n_patches == 0 && isnan(st.a_yastrebov),
	    "only the count when only the count is asked");
	memset(m, 0, 48);
	o.flags = RC_CONTACT_ALL;
	rc_contact_analyse(h, m, &o, &st, &err);
	test_true(st.n_c == 0 && isnan(st.gbar_c) && isnan(st.patch_size_char),
	    "no contact: averages are NaN");
	free(m);
	rc_grid_free(h);
}

/* h = A cos(k x) with k = 2 pi m / lx, contact where cos(k x) > 0.  With
 * points per period N = 4M + 2 the mask covers exactly (-lambda/4,
 * lambda/4) in the midpoint sense, so the discrete averages approach the
 * integrals with the midpoint rule's O((dx/lambda)^2) error:
 *   gbar_c^2 = A^2 k^2 / 2,  gbar_c'^2 = A^2 k^2 (1/2 - 4/pi^2).
 * The discrete averages are also checked exactly against the analytic
 * derivatives summed at the mask points (spectral derivatives are exact
 * for a band-limited cosine). */
static void
test_cosine(void)
{
	size_t periods = 2, per = 4 * 31 + 2, nx = periods * per, ny = 3;
	double lx = 1.5, amp = 0.3, k = 2 * M_PI * (double)periods / lx;
	double s_grad = 0, s_h = 0, s_lap = 0, n_c = 0;
	rc_contact_opts o;
	rc_contact_stats st;
	rc_err err;
	rc_grid *h = rc_grid_new(nx, ny, lx, 0.7, &err);
	unsigned char *m = malloc(nx * ny);

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double x = lx * (double)i / (double)nx;
			h->z[j * nx + i] = amp * cos(k * x);
			m[j * nx + i] = cos(k * x) > 0;
		}
	for (size_t i = 0; i < nx; i++) {
		double x = lx * (double)i / (double)nx;
		if (!m[i])
			continue;
		n_c++;
		s_grad += pow(amp * k * sin(k * x), 2);
		s_h += amp * cos(k * x);
	}
	for (size_t i = 0; i < nx; i++) {
		double x = lx * (double)i / (double)nx;
		if (m[i])
			s_lap += (amp * cos(k * x) - s_h / n_c) * amp * k * k * cos(k * x);
	}
	rc_contact_defaults(&o);
	o.flags = RC_CONTACT_GRADIENT;
	test_true(rc_contact_analyse(h, m, &o, &st, &err) == 0, "cosine analyse");
	test_rel(st.gbar_c, sqrt(s_grad / n_c), 1e-12, "cosine gbar_c vs pointwise sum");
	test_rel(st.gbar_c_prime, sqrt(s_lap / n_c), 1e-12,
	    "cosine gbar_c' vs pointwise sum");
	/* Midpoint rule on N = 126 points per period: relative error of the
	 * averages O((1/N)^2) = O(6e-5) times a constant of a few; observed:
	 * gbar_c exact (the sin^2 sum is), gbar_c' 4.4e-4. */
	test_rel(st.gbar_c, amp * k / sqrt(2), 1e-3, "cosine gbar_c vs integral");
	test_rel(st.gbar_c_prime, amp * k * sqrt(0.5 - 4 / (M_PI * M_PI)), 1e-3,
	    "cosine gbar_c' vs integral");
	/* Central differences on a cosine are the exact derivatives times
	 * sin(k dx)/(k dx) (gradient) and (2 - 2 cos(k dx))/(k dx)^2
	 * (Laplacian), at every point: exact identities. */
	{
		double kdx = k * lx / (double)nx;
		double grad_factor = sin(kdx) / kdx;
		double lap_factor = (2 - 2 * cos(kdx)) / (kdx * kdx);
		o.fd = 1;
		rc_contact_analyse(h, m, &o, &st, &err);
		test_rel(st.gbar_c, grad_factor * sqrt(s_grad / n_c), 1e-12,
		    "cosine gbar_c by central differences");
		test_rel(st.gbar_c_prime, sqrt(lap_factor * s_lap / n_c), 1e-12,
		    "cosine gbar_c' by the 5-point Laplacian");
		test_rel(rc_gbar_central(h), grad_factor * amp * k / sqrt(2), 1e-12,
		    "central-difference rms gradient of the whole cosine");
	}
	free(m);
	rc_grid_free(h);
}

/* Full contact: gbar_c = rc_rms_gradient and, on an odd grid (no Nyquist
 * mode, where the gradient and Laplacian differ), gbar_c' = gbar_c by
 * summation by parts, exactly up to round-off.  Also kappa round trip. */
static void
test_full_contact(void)
{
	size_t nx = 15, ny = 9, n = nx * ny;
	unsigned long long state = 99;
	double gbar;
	rc_contact_opts o;
	rc_contact_stats st;
	rc_err err;
	rc_grid *h = rc_grid_new(nx, ny, 1.0, 0.6, &err);
	unsigned char *m = malloc(n);
	rc_fft fft;

	for (size_t p = 0; p < n; p++) {
		state = state * 6364136223846793005ULL + 1442695040888963407ULL;
		h->z[p] = (double)(state >> 11) / 9007199254740992.0 - 0.5;
		m[p] = 1;
	}
	rc_fft_init(&fft, nx, ny, RC_FFT_ESTIMATE, &err);
	rc_rms_gradient(h, &fft, &gbar, &err);
	rc_contact_defaults(&o);
	o.fft = &fft;
	o.pressure = 0.01;
	o.modulus = 2;
	o.gbar = gbar;
	rc_contact_analyse(h, m, &o, &st, &err);
	test_rel(st.gbar_c, gbar, 1e-12, "full contact: gbar_c = gbar");
	test_rel(st.gbar_c_prime, gbar, 1e-12, "full contact, odd grid: gbar_c' = gbar_c");
	test_true(isinf(st.kappa), "full contact: kappa = inf");
	/* Partial contact: erf(sqrt(pi) kappa p* / 2) gives a_r back. */
	for (size_t p = 0; p < n; p++)
		m[p] = h->z[p] > 0.2;
	rc_contact_analyse(h, m, &o, &st, &err);
	test_rel(erf(sqrt(M_PI) * st.kappa * o.pressure / (o.modulus * gbar) / 2), st.a_r,
	    1e-12, "kappa inverts Eq. 24");
	test_rel(erf(sqrt(M_PI) * st.kappa_c * o.pressure / (o.modulus * st.gbar_c) / 2),
	    st.a_r, 1e-12, "kappa_c inverts Eq. 8");
	test_range(st.gbar_c_prime, 0, 1e3, "gbar_c' finite on a random mask");
	rc_fft_free(&fft);
	free(m);
	rc_grid_free(h);
}


/* rc_contact_subpixel on the edges of a 2D Hertz contact (a cylinder of
 * radius R on a half space, E* = 1, contact |x| < a): the pressure
 * (1/(2R)) sqrt(a^2 - x^2) inside, the gap (1/(2R)) [|x| sqrt(x^2 - a^2)
 * - a^2 acosh(|x|/a)] outside, sampled on a line of nx points, and the
 * same profile uniform along y on an nx x 8 grid (no column crosses the
 * edge: the rows' estimate alone must count).  The edge asymptotics the
 * estimate inverts are this solution's leading terms, so what is left is
 * their next order.  Measured over 20 contact widths a/dx = 6.3 ...
 * 25.3: the largest error of the area is 0.0047 dx per edge (the raw
 * count's: 0.30 dx); tolerance 0.02 dx, 4 times the measured error and
 * 15 times below the raw count's.  The whole cell is 1 (lx = 1) and holds the contact
 * once (the profile is the isolated cylinder's, which is what the local
 * estimate sees). */
static void
test_subpixel_hertz(void)
{
	const size_t nx = 128;
	const double dx = 1.0 / nx, R = 1;
	double worst = 0, worst_raw = 0, worst2 = 0;

	for (int t = 0; t < 20; t++) {
		double a = (6.3 + t) * dx;
		size_t ny = 8;
		double *u = malloc(nx * ny * sizeof(double));
		double *h = calloc(nx * ny, sizeof(double));
		double *sg = malloc(nx * ny * sizeof(double));
		unsigned char *c = malloc(nx * ny);
		size_t n_c = 0;
		double est, est2;

		for (size_t i = 0; i < nx; i++) {
			double x = ((double)i - nx / 2.0 + 0.5) * dx, ax = fabs(x);

			c[i] = ax < a;
			n_c += c[i];
			sg[i] = c[i] ? sqrt(a * a - x * x) / (2 * R) : 0;
			u[i] = c[i] ? 0 : (ax * sqrt(x * x - a * a) -
			    a * a * acosh(ax / a)) / (2 * R);
		}
		for (size_t j = 1; j < ny; j++) {
			memcpy(u + j * nx, u, nx * sizeof(double));
			memcpy(sg + j * nx, sg, nx * sizeof(double));
			memcpy(c + j * nx, c, nx);
		}
		est = rc_contact_subpixel(u, h, sg, c, nx, 1, 1.0, 1.0, 1.0);
		est2 = rc_contact_subpixel(u, h, sg, c, nx, ny, 1.0, 0.5, 1.0);
		worst = fmax(worst, fabs(est - 2 * a) / 2 / dx);
		worst2 = fmax(worst2, fabs(est2 - 2 * a) / 2 / dx);
		worst_raw = fmax(worst_raw, fabs((double)n_c * dx - 2 * a) / 2 / dx);
		free(u);
		free(h);
		free(sg);
		free(c);
	}
	test_range(worst, 0, 0.02, "a_subpixel of a 2D Hertz contact, line grid: "
	    "error per edge in units of dx (the raw count's: %.3f)", worst_raw);
	test_range(worst2, 0, 0.02, "a_subpixel of the same contact uniform "
	    "along y on an nx x 8 grid: the rows' estimate counts");
}

/* The bisection rc_contact_subpixel inverts the edge asymptotics with,
 * as written before its test skipped most pows (contact.c, edge_above). */
static double
edge_fraction_pow(double r)
{
	double lo = 0, hi = 1;

	for (int k = 0; k < 50; k++) {
		double m = 0.5 * (lo + hi);

		if (pow(1 - m, 1.5) > r * sqrt(m))
			lo = m;
		else
			hi = m;
	}
	return 0.5 * (lo + hi);
}

/* rc_contact_subpixel bit for bit against that bisection: a line of 4
 * points, h = 0, u = (g0, 0, g2, g3), point 1 in contact with pressure
 * s, so its two bonds have gaps g2 and g0, |cos| = 1 and r = 3 g /
 * (4 s dx); a_subpixel = (1 + (2 (e(r2) - 1/2 + e(r0) - 1/2)) / 2) / 4.
 * 20000 random states with r over 1e-8 ... 1e8 (each bisection takes
 * both of edge_above's ways: far from the root and near it), 20000 with
 * r over 1e-200 ... 1e200 (r^2 underflows and overflows). */
static void
test_subpixel_bits(void)
{
	const double dx = 0.25;
	unsigned long long x = 88172645463325252ULL;
	size_t bad = 0;

	for (int t = 0; t < 40000; t++) {
		double decades = t < 20000 ? 4 : 100;
		double u[4], h[4] = { 0, 0, 0, 0 }, sg[4] = { 0, 0, 0, 0 };
		unsigned char c[4] = { 0, 1, 0, 0 };
		double e[2], sum = 0, want, got;

		for (int k = 0; k < 3; k++) {	/* xorshift: log10 uniform */
			x ^= x << 13;
			x ^= x >> 7;
			x ^= x << 17;
			e[k % 2] = pow(10, decades * (2 * (double)(x >> 11) /
			    9007199254740992.0 - 1));
			if (k == 2)
				sg[1] = e[0];
			else if (k == 0)
				u[0] = e[0];
			else
				u[2] = e[1];
		}
		u[1] = 0;
		u[3] = 0.5 * (u[0] + u[2]) + 1e-3;
		sum += edge_fraction_pow(3 * u[2] / (4 * sg[1] * dx)) - 0.5;
		sum += edge_fraction_pow(3 * u[0] / (4 * sg[1] * dx)) - 0.5;
		want = (1.0 + (2.0 * sum) / 2.0) / 4.0;
		got = rc_contact_subpixel(u, h, sg, c, 4, 1, 1.0, 1.0, 1.0);
		bad += memcmp(&got, &want, sizeof(got)) != 0;
	}
	test_true(bad == 0, "a_subpixel bit for bit as with a pow at every "
	    "bisection step: %zu of 40000 differ", bad);
}

/* The bisection rc_contact_subpixel ran before its first steps were
 * taken by rc__edge_start: 50 steps from [0, 1] with the library's test;
 * *lo, *hi: the interval after `at` steps. */
static double
edge_fraction_plain(double r, int at, double *lo_at, double *hi_at)
{
	double lo = 0, hi = 1, r2 = r * r;

	for (int k = 0; k < 50; k++) {
		double m = 0.5 * (lo + hi);

		if (k == at) {
			*lo_at = lo;
			*hi_at = hi;
		}
		if (rc__edge_above(m, r, r2))
			lo = m;
		else
			hi = m;
	}
	return 0.5 * (lo + hi);
}

struct edge_tally {
	size_t n, bad, bad_start, bad_pow, in_range, uncertified, short_start;
	double sum_k;
};

/* One r: rc__edge_fraction bit for bit as the plain bisection (and, with
 * pow_too, as the bisection with a pow at every step), and the plain
 * bisection's interval after rc__edge_start's K steps is its [lo, hi].
 * Returns K. */
static int
edge_check(struct edge_tally *t, double r, int pow_too)
{
	double lo, hi, plo = 0, phi = 1, want, got;
	int k = rc__edge_start(r, &lo, &hi);

	want = edge_fraction_plain(r, k, &plo, &phi);
	got = rc__edge_fraction(r);
	t->n++;
	t->bad += memcmp(&got, &want, sizeof(got)) != 0;
	t->bad_start += memcmp(&lo, &plo, sizeof(lo)) != 0 ||
	    memcmp(&hi, &phi, sizeof(hi)) != 0;
	if (pow_too) {
		want = edge_fraction_pow(r);
		t->bad_pow += memcmp(&got, &want, sizeof(got)) != 0;
	}
	if (r >= 1e-100 && r <= 1e100) {
		t->in_range++;
		t->uncertified += k == 0;
		t->sum_k += k;
	}
	return k;
}

static double
xorshift_unit(unsigned long long *x)
{
	*x ^= *x << 13;
	*x ^= *x >> 7;
	*x ^= *x << 17;
	return (double)(*x >> 11) / 9007199254740992.0;
}

/* The first step k whose midpoint, the plain bisection's if it went by
 * the digits of f, lies within tol of f: (floor(f 2^k) + 1/2) 2^-k. */
static int
first_near(double f, double tol)
{
	for (int k = 0; k < 50; k++)
		if (fabs(ldexp(floor(ldexp(f, k)) + 0.5, -k) - f) <= tol)
			return k;
	return 50;
}

static void
edge_report(const struct edge_tally *t, const char *what)
{
	test_true(t->bad == 0 && t->bad_start == 0 && t->bad_pow == 0,
	    "edge fraction from the certified start bit for bit as the plain "
	    "50-step bisection, %s: %zu of %zu differ (%zu starts, %zu against "
	    "the pow bisection)", what, t->bad, t->n, t->bad_start, t->bad_pow);
}

/* rc__edge_fraction (the bisection from rc__edge_start's certified
 * interval, contact.c) against the plain bisection it replaces, on
 * the r where its argument could break: r log-uniform over 1e-300 ...
 * 1e300; around the bounds 1e-100, 1e100 of the certified range (inside
 * the start is taken, outside not); roots f next to the dyadic midpoints
 * the bisection tests (r = (1 - f)^1.5 / f^0.5 for f = j 2^-(k+1) + d,
 * d from 0 over the start's margin 32 2^-52 to 1e-11, r and its
 * neighbours one ulp away; a fifth also against the pow bisection); and
 * 0, negative, denormal, huge, inf and NaN r.  Then: the start is
 * certified for every random r of the range, at 43 steps or more on
 * average (measured: 0 uncertified, 44.0 at r ~ 1 to 45.7 over the
 * range), and a root f next to step k's midpoint starts no earlier than
 * k (rc__edge_start starts at the first midpoint within 33 2^-52 of its
 * f_a, about 1e-15 from f), else edge_fraction is correct but no faster. */
static void
test_edge_start(void)
{
	static const double offsets[] = { 0, 0x1p-52, 0x2p-52, 0x3p-52,
	    0x5p-52, 0x8p-52, 0x10p-52, 0x1fp-52, 0x20p-52, 0x21p-52, 0x40p-52,
	    0x64p-52, 0x3e8p-52, 1e-13, 1e-12, 1e-11 };
	static const double special[] = { 0.0, -0.0, -1.0, -1e-300, 4.9e-324,
	    1e-320, 1e-310, 2.2250738585072014e-308, 1e-300, 1e-200, 1e-160,
	    1e-154, 1e-101, 1e154, 1.3407807929942596e154, 1.35e154, 1e200,
	    1e300, 1.7976931348623157e308, INFINITY, -INFINITY, NAN };
	unsigned long long x = 0x9E3779B97F4A7C15ULL;
	struct edge_tally wide = { 0 }, bounds = { 0 }, dyadic = { 0 },
	    odd = { 0 };
	double mean_k;

	for (int t = 0; t < 3000000; t++)
		edge_check(&wide, pow(10, 300 * (2 * xorshift_unit(&x) - 1)), 0);
	mean_k = wide.sum_k / (double)wide.in_range;
	for (int side = 0; side < 2; side++) {
		double bound = side ? 1e100 : 1e-100, r = bound;

		for (int t = 0; t < 100000; t++)
			edge_check(&bounds, bound * pow(10, 2 * xorshift_unit(&x) -
			    1), 0);
		for (int t = 0; t < 20000; t++) {	/* ulps up from the bound */
			edge_check(&bounds, r, 0);
			r = nextafter(r, INFINITY);
		}
		r = bound;
		for (int t = 0; t < 20000; t++) {
			r = nextafter(r, 0);
			edge_check(&bounds, r, 0);
		}
	}
	for (int k = 0; k < 50; k++)
		for (int t = 0; t < 200; t++) {
			double step = ldexp(1, -(k + 1));
			double j = 2 * floor(xorshift_unit(&x) * ldexp(1, k)) + 1;

			for (size_t o = 0; o < sizeof(offsets) / sizeof(*offsets);
			    o++)
				for (int sign = -1; sign <= 1; sign += 2) {
					double f = j * step + sign * offsets[o], r;

					if (!(f > 0 && f < 1))
						continue;
					int want_k = first_near(f, 0x1p-45);

					r = pow(1 - f, 1.5) / sqrt(f);
					dyadic.short_start +=
					    edge_check(&dyadic, r, t % 5 == 0) < want_k ||
					    edge_check(&dyadic, nextafter(r, 0), 0) < want_k ||
					    edge_check(&dyadic, nextafter(r, INFINITY), 0) < want_k;
				}
		}
	for (size_t i = 0; i < sizeof(special) / sizeof(*special); i++)
		edge_check(&odd, special[i], 1);

	edge_report(&wide, "r log-uniform over 1e-300 ... 1e300");
	edge_report(&bounds, "r around 1e-100 and 1e100");
	edge_report(&dyadic, "roots next to the bisection's midpoints");
	edge_report(&odd, "0, negative, denormal, huge, inf, NaN r");
	test_int((long long)(wide.uncertified + bounds.uncertified), 0,
	    "edge fraction: the start is certified for every r in 1e-100 ... "
	    "1e100 (of %zu)", wide.in_range + bounds.in_range);
	test_int((long long)dyadic.short_start, 0, "edge fraction: a root "
	    "f starts no earlier than the first step whose midpoint is within "
	    "2^-45 of f (the start's window, 33 2^-52 around f_a, lies inside)");
	test_range(mean_k, 43, 50, "edge fraction: steps the start skips, "
	    "mean over r log-uniform in 1e-100 ... 1e100");
}

int
main(void)
{
	test_hand_made();
	test_random_masks();
	test_analyse();
	test_cosine();
	test_full_contact();
	test_subpixel_hertz();
	test_subpixel_bits();
	test_edge_start();
	return test_summary();
}
