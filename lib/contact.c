/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact.c - contact fraction, contact line, masked gradients and the
 * analysis gfmd-solve reports; the patches are in patches.c.
 */
#include "contact.h"
#include "contact_internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "gradient.h"
#include "kappa.h"
#include "spectral.h"

void
rc_contact_defaults(rc_contact_opts *o)
{
	memset(o, 0, sizeof(*o));
	o->flags = RC_CONTACT_ALL;
	o->alpha = RC_YASTREBOV_ALPHA;
	o->modulus = 1;
}

size_t
rc_contact_count(const unsigned char *contact, size_t n)
{
	size_t n_c = 0;

	#pragma omp parallel for reduction(+:n_c) schedule(static)
	for (size_t i = 0; i < n; i++)
		n_c += contact[i] != 0;
	return n_c;
}

/* The bisection's test pow(1 - m, 1.5) > r sqrt(m), decided without pow
 * or sqrt where the sides are far apart: for r >= 0 it is a^3 > r^2 m
 * (a = 1 - m), whose computed sides are within 2.3e-16 of theirs
 * (relative; two roundings each) as glibc's pow is within 1 ulp of a^1.5,
 * so a gap of over 1e-14 decides as the pows would; past r ~ 1e154 r^2
 * is inf and the test false, as it is.  pow only near the root (1.1 of
 * the 50 steps on average, r in 1e-2 ... 1e2): the same answer bit for
 * bit.  Cost: a step the cubic decides is a dependent chain of about 30
 * cycles, one with a pow several times that; edge_fraction runs only the
 * last 6 steps on average (edge_start; all 50 were about 85% of
 * rc_contact_subpixel at 512^2, p* = 0.05). */
static inline int
edge_above(double m, double r, double r2)
{
	double a = 1 - m, lhs = a * a * a, rhs = r2 * m;

	if (r >= 0) {
		if (lhs - rhs > 1e-14 * lhs)
			return 1;
		if (rhs - lhs > 1e-14 * lhs)
			return 0;
	}
	return pow(a, 1.5) > r * sqrt(m);
}

/* Highest set bit of v > 0, v < 2^53 (exact as a double). */
static int
highest_bit(uint64_t v)
{
	double d = (double)v;
	uint64_t bits;

	memcpy(&bits, &d, sizeof(bits));
	return (int)((bits >> 52) & 0x7ff) - 1023;
}

/* Where the 50-step bisection of edge_fraction (lo = 0, hi = 1; m = (lo
 * + hi) / 2; lo = m if edge_above(m) else hi = m) stands after its first
 * K steps, found without running them: an approximate root f_a picks a
 * dyadic interval [lo, hi] = [j, j + 1] 2^-K around it, two strict cubic
 * tests at lo and hi certify that the bisection reaches exactly that
 * interval after K steps, and edge_fraction goes on from there.  Returns
 * K, 0 (lo = 0, hi = 1) where the certificate does not hold or is not
 * proved (r outside 1e-100 ... 1e100, not finite).  f_a only decides how
 * often the certificate holds and how large K is, never the answer.
 *
 * Proof.  Let s = r2 (the double, r > 0, 1e-200 <= s <= 1e200) and g(m)
 * = s m / (1 - m)^3, increasing on (0, 1); edge_above's cubic tests
 * compare g with 1.  For m a multiple of 2^-50 in (0, 1) (every midpoint
 * is) a = 1 - m is exact, and a^3 >= 2^-150, s m >= 1e-216, 1e-14 a^3
 * are normal: the computed lhs = a^3 (1 + t1), |t1| <= 2.3e-16, rhs = s m
 * (1 + t2), |t2| <= 1.2e-16, and a difference or product rounds once
 * more (1.2e-16; doubles rounded one operation at a time: no x87, no
 * fused multiply-add, -ffp-contract=off).
 * (i) If lhs - rhs > 2e-14 lhs (computed) at lo, then g(lo) < 1 - 1.9e-14;
 * at a midpoint m <= lo, g(m) <= g(lo) and lhs - rhs >= a^3 (1 - g(m) -
 * 3.5e-16) (1 - 1.2e-16) > 1.8e-14 a^3, above the computed 1e-14 lhs <
 * 1.01e-14 a^3: edge_above(m) = 1.
 * (ii) If rhs - lhs > 2e-14 lhs at hi, then g(hi) > 1 + 1.9e-14; at a
 * midpoint m >= hi, lhs < rhs (the first test fails) and rhs - lhs >=
 * a^3 ((g(m) - 1) (1 - 1.2e-16) - 3.5e-16) (1 - 1.2e-16) > 1.8e-14 a^3:
 * edge_above(m) = 0.
 * (iii) While the bisection's interval (width 2^-k, k < K) contains
 * [lo, hi], its midpoint, a multiple of 2^-(k+1) and so of 2^-K, is not
 * inside (lo, hi): it is at most lo (then lo > 0 and by (i) it becomes
 * the new lower end) or at least hi (hi < 1, by (ii) the new upper end),
 * and the next interval contains [lo, hi] again.  After K steps the
 * interval contains [lo, hi] and has its width: it is [lo, hi].
 *
 * f_a: with a = 1 - f the root solves a^3 + s a - s = 0; Cardano's w =
 * cbrt(s (1/2 + sqrt(1/4 + s/27))), v = s / (3 w) give a = w - v = s /
 * (w^2 + w v + v^2) (w^3 - v^3 = s, w v = s/3), that is 3 q / (1 + q +
 * q^2) with q = v / w = s / (3 w^2) in (0, 1): no cancellation, within a
 * few ulps, so f_a is within about 1e-15 of the root.  [lo, hi] is the
 * smallest aligned dyadic interval holding (N - 32 ... N + 32) 2^-52, N =
 * floor(f_a 2^52): the ends are at least 7.1e-15 from f_a, and as d ln g
 * / dm = 1/m + 3/(1 - m) >= (1 + sqrt(3))^2 = 7.46, g differs from 1 by
 * over 4e-14 there: the certificate holds (never failed in the tests), K
 * <= 45, and 50 - K is 6 steps on average (5 to 8 mostly; fewer are
 * skipped where the root is within 7e-15 of a coarse dyadic). */
#define EDGE_START_HALF 32	/* units of 2^-52 */

static int
edge_start(double r, double r2, double *lo, double *hi)
{
	double w, q, f;
	uint64_t n, x, y, lo_n, width;
	int b, k;

	*lo = 0;
	*hi = 1;
	if (!(r > 0 && r2 >= 1e-200 && r2 <= 1e200))
		return 0;
	w = cbrt(r2 * (0.5 + sqrt(0.25 + r2 * (1.0 / 27))));
	q = r2 / (3 * w * w);
	f = 1 - 3 * q / (1 + q + q * q);
	if (!(f > -1 && f < 2))
		return 0;
	n = f <= 0 ? 0 : f < 1 ? (uint64_t)(f * 0x1p52) :
	    ((uint64_t)1 << 52) - 1;
	x = n >= EDGE_START_HALF ? n - EDGE_START_HALF : 0;
	y = n + EDGE_START_HALF < ((uint64_t)1 << 52) ?
	    n + EDGE_START_HALF : ((uint64_t)1 << 52) - 1;
	b = highest_bit(x ^ y);
	k = 51 - b;
	if (k < 1 || k > 50)
		return 0;
	width = (uint64_t)1 << (b + 1);
	lo_n = n & ~(width - 1);
	{
		double l = (double)lo_n * 0x1p-52, h = (double)(lo_n + width) *
		    0x1p-52, al = 1 - l, ah = 1 - h;
		double lhs_l = al * al * al, rhs_l = r2 * l;
		double lhs_h = ah * ah * ah, rhs_h = r2 * h;

		if (!((l == 0 || lhs_l - rhs_l > 2e-14 * lhs_l) &&
		    (h == 1 || rhs_h - lhs_h > 2e-14 * lhs_h)))
			return 0;
		*lo = l;
		*hi = h;
	}
	return k;
}

/* (1 - f)^(3/2) / f^(1/2) = r for f in (0, 1): decreasing from +inf to 0;
 * bisection to 2^-50, its first steps taken by edge_start. */
static double
edge_fraction(double r)
{
	double lo, hi, r2 = r * r;

	for (int k = edge_start(r, r2, &lo, &hi); k < 50; k++) {
		double m = 0.5 * (lo + hi);

		if (edge_above(m, r, r2))
			lo = m;
		else
			hi = m;
	}
	return 0.5 * (lo + hi);
}

int
rc__edge_above(double m, double r, double r2)
{
	return edge_above(m, r, r2);
}

int
rc__edge_start(double r, double *lo, double *hi)
{
	return edge_start(r, r * r, lo, hi);
}

double
rc__edge_fraction(double r)
{
	return edge_fraction(r);
}

#define SUBPIXEL_C_MIN 0.1

#define GAP(ii, jj) (u[(jj) * nx + (ii)] - h[(jj) * nx + (ii)])

/* f - 1/2 of the bond from a contact point (pressure sigma_k) to its
 * neighbour (ii, jj), out of contact with gap g > 0, along x or y (d
 * its spacing); rc_contact_subpixel's formulas (contact.h), hypot once. */
static double
bond_shift(const double *u, const double *h, size_t nx, size_t ny,
    size_t ii, size_t jj, double g, int along_x, double sigma_k, double dx,
    double dy, double modulus)
{
	double gx, gy, norm, c, d = along_x ? dx : dy;

	gx = nx > 1 ? (GAP(ii + 1 < nx ? ii + 1 : 0, jj) -
	    GAP(ii > 0 ? ii - 1 : nx - 1, jj)) / dx : 0;
	gy = ny > 1 ? (GAP(ii, jj + 1 < ny ? jj + 1 : 0) -
	    GAP(ii, jj > 0 ? jj - 1 : ny - 1)) / dy : 0;
	norm = hypot(gx, gy);
	c = norm > 0 ? fabs(along_x ? gx : gy) / norm : 1;
	if (c < SUBPIXEL_C_MIN)
		c = SUBPIXEL_C_MIN;
	return edge_fraction(3 * modulus * g / (4 * sigma_k * d * c)) - 0.5;
}

double
rc_contact_subpixel(const double *u, const double *h, const double *sigma,
    const unsigned char *contact, size_t nx, size_t ny, double lx, double ly,
    double modulus)
{
	size_t i, j, n = nx * ny, n_c = 0;
	double dx = lx / (double)nx, dy = ly / (double)ny;
	double sum_x = 0, sum_y = 0, bonds_x = 0, bonds_y = 0;

	/* The neighbours in the order right, left, up, down (each axis's sum
	 * adds its bonds in that order); an axis of one point has none.  Most
	 * points are out of contact: 8 of them are skipped at a time. */
#pragma omp parallel for private(i) reduction(+:sum_x, sum_y, bonds_x, bonds_y, n_c) schedule(static)
	for (j = 0; j < ny; j++) {
		const unsigned char *row = contact + j * nx;
		size_t nb_j[4] = { j, j, j + 1 < ny ? j + 1 : 0,
		    j > 0 ? j - 1 : ny - 1 };

		for (i = 0; i < nx; i++) {
			size_t k = j * nx + i;
			uint64_t eight;

			if (i % 8 == 0 && i + 8 <= nx) {
				memcpy(&eight, row + i, sizeof(eight));
				if (eight == 0) {
					i += 7;
					continue;
				}
			}
			if (!row[i])
				continue;
			n_c++;
			if (!(sigma[k] > 0))
				continue;
			for (int b = nx < 2 ? 2 : 0; b < (ny < 2 ? 2 : 4); b++) {
				size_t ii = b == 0 ? (i + 1 < nx ? i + 1 : 0) :
				    b == 1 ? (i > 0 ? i - 1 : nx - 1) : i;
				size_t jj = nb_j[b];
				double g;

				if (contact[jj * nx + ii] || !((g = GAP(ii, jj)) > 0))
					continue;
				g = bond_shift(u, h, nx, ny, ii, jj, g, b < 2,
				    sigma[k], dx, dy, modulus);
				if (b < 2) {
					sum_x += g;
					bonds_x++;
				} else {
					sum_y += g;
					bonds_y++;
				}
			}
		}
	}
#undef GAP
	if (n == 0)
		return NAN;
	if (bonds_x + bonds_y == 0)
		return (double)n_c / (double)n;
	/* Each axis's sum is the whole correction; weighted by its bonds. */
	return ((double)n_c + (bonds_x * sum_x + bonds_y * sum_y) /
	    (bonds_x + bonds_y)) / (double)n;
}

/* Contact points with a neighbour out of contact; without periodic a
 * point on the edge of the patch counts too, and the wrapped neighbours
 * are then read only where they are the plain ones.  On a periodic axis
 * of length 1 the neighbour is the point itself, which is in contact, so
 * line grids need no special case. */
static size_t
line(const unsigned char *contact, size_t nx, size_t ny, int periodic)
{
	size_t n_cl = 0;

	#pragma omp parallel for reduction(+:n_cl) schedule(static)
	for (size_t j = 0; j < ny; j++) {
		const unsigned char *row = contact + j * nx;
		const unsigned char *up = contact + (j + 1 < ny ? j + 1 : 0) * nx;
		const unsigned char *down = contact + (j > 0 ? j - 1 : ny - 1) * nx;
		for (size_t i = 0; i < nx; i++) {
			if (!row[i])
				continue;
			size_t left = i > 0 ? i - 1 : nx - 1;
			size_t right = i + 1 < nx ? i + 1 : 0;
			int edge = !periodic && (i == 0 || i + 1 == nx || j == 0 ||
			    j + 1 == ny);
			n_cl += edge || !row[left] || !row[right] || !up[i] ||
			    !down[i];
		}
	}
	return n_cl;
}

size_t
rc_contact_line(const unsigned char *contact, size_t nx, size_t ny)
{
	return line(contact, nx, ny, 1);
}

size_t
rc_contact_line_open(const unsigned char *contact, size_t nx, size_t ny)
{
	return line(contact, nx, ny, 0);
}

/* The mean height over the contact; rows are summed first so round-off
 * grows with nx + ny rather than nx * ny. */
static double
contact_mean(const double *h, const unsigned char *contact, size_t nx,
    size_t ny, size_t n_c)
{
	double sum = 0;

	#pragma omp parallel for reduction(+:sum) schedule(static)
	for (size_t j = 0; j < ny; j++) {
		double row = 0;
		for (size_t i = j * nx; i < (j + 1) * nx; i++)
			if (contact[i])
				row += h[i];
		sum += row;
	}
	return sum / (double)n_c;
}

/* The sums of rc_field_sums from spectral fields, one at a time in the
 * plan's buffer. */
static int
spectral_sums(const rc_grid *h, const unsigned char *contact, double hbar,
    rc_fft *fft, double *grad2, double *dh_lap, rc_err *err)
{
	rc_fft own;
	int rv = -1;

	if ((fft = rc_fft_borrow(fft, &own, h->nx, h->ny, err)) == NULL)
		return -1;
	*grad2 = *dh_lap = 0;
	for (int d = RC_DERIV_X; d <= RC_DERIV_LAPLACIAN; d++) {
		const double *f = fft->real;
		double g, l;

		if (rc_spectral_deriv(h, fft, (enum rc_deriv)d, err) != 0)
			goto out;
		rc_field_sums(h->z, d == RC_DERIV_X ? f : NULL,
		    d == RC_DERIV_Y ? f : NULL, d == RC_DERIV_LAPLACIAN ? f : NULL,
		    contact, rc_grid_size(h), hbar, &g, &l);
		*grad2 += g;
		*dh_lap += l;
	}
	rv = 0;
out:
	if (fft == &own)
		rc_fft_free(&own);
	return rv;
}

static int
gradients(const rc_grid *h, const unsigned char *contact, size_t n_c,
    rc_fft *fft, int fd, int nonperiodic, rc_contact_stats *st, rc_err *err)
{
	double hbar, grad2, dh_lap;

	if (n_c == 0)
		return 0;	/* NaN: no contact to average over */
	hbar = contact_mean(h->z, contact, h->nx, h->ny, n_c);
	if (fd || nonperiodic)
		rc_deriv_sums(h, contact, hbar, nonperiodic, &grad2, &dh_lap);
	else if (spectral_sums(h, contact, hbar, fft, &grad2, &dh_lap, err) != 0)
		return -1;
	st->gbar_c = sqrt(grad2 / (double)n_c);
	st->gbar_c_prime = rc_signed_root(-dh_lap / (double)n_c);
	return 0;
}

int
rc_contact_analyse(const rc_grid *h, const unsigned char *contact,
    const rc_contact_opts *o, rc_contact_stats *st, rc_err *err)
{
	size_t nx = h->nx, ny = h->ny, n = rc_grid_size(h);
	unsigned flags = o->flags;

	if (flags & RC_CONTACT_KAPPA)
		flags |= RC_CONTACT_GRADIENT;
	st->n_tot = n;
	st->n_c = st->n_cl = st->n_patches = 0;
	st->a_r = st->a_yastrebov = st->patch_size_char = NAN;
	st->gbar_c = st->gbar_c_prime = st->kappa = st->kappa_c = NAN;
	if (flags & (RC_CONTACT_COUNT | RC_CONTACT_LINE | RC_CONTACT_PATCHES |
	    RC_CONTACT_GRADIENT)) {
		st->n_c = rc_contact_count(contact, n);
		st->a_r = (double)st->n_c / (double)n;
	}
	if (flags & RC_CONTACT_LINE) {
		st->n_cl = o->nonperiodic ? rc_contact_line_open(contact, nx, ny) :
		    rc_contact_line(contact, nx, ny);
		st->a_yastrebov = ((double)st->n_c - o->alpha * (double)st->n_cl) /
		    (double)n;
	}
	if (flags & RC_CONTACT_PATCHES) {
		double sum_sq, cell = h->lx / (double)nx * (h->ly / (double)ny);
		if ((o->nonperiodic ? rc_contact_patches_open(contact, nx, ny,
		    &st->n_patches, &sum_sq, err) : rc_contact_patches(contact, nx,
		    ny, &st->n_patches, &sum_sq, err)) != 0)
			return -1;
		st->patch_size_char = st->n_c ? sum_sq / (double)st->n_c * cell : NAN;
	}
	if (flags & RC_CONTACT_GRADIENT &&
	    gradients(h, contact, st->n_c, o->fft, o->fd, o->nonperiodic, st,
	    err) != 0)
		return -1;
	if (flags & RC_CONTACT_KAPPA) {
		if (o->modulus > 0 && o->gbar > 0)
			st->kappa = rc_kappa(st->a_r, o->pressure / (o->modulus * o->gbar));
		if (o->modulus > 0 && st->gbar_c > 0)
			st->kappa_c = rc_kappa(st->a_r,
			    o->pressure / (o->modulus * st->gbar_c));
	}
	return 0;
}
