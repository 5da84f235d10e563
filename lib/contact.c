/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact.c - contact fraction, contact line, masked gradients and the
 * analysis gfmd-solve reports; the patches are in patches.c.
 */
#include "contact.h"

#include <math.h>
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
 * is inf and the test false, as it is.  pow only near the root (the last
 * 4 or 5 of the 50 steps): the same answer bit for bit, in a quarter of
 * the time (the pows were 4% of a one-pressure gfmd-solve at 512^2). */
static int
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

/* (1 - f)^(3/2) / f^(1/2) = r for f in (0, 1): decreasing from +inf to 0;
 * bisection to 2^-50. */
static double
edge_fraction(double r)
{
	double lo = 0, hi = 1, r2 = r * r;

	for (int k = 0; k < 50; k++) {
		double m = 0.5 * (lo + hi);

		if (edge_above(m, r, r2))
			lo = m;
		else
			hi = m;
	}
	return 0.5 * (lo + hi);
}

#define SUBPIXEL_C_MIN 0.1

double
rc_contact_subpixel(const double *u, const double *h, const double *sigma,
    const unsigned char *contact, size_t nx, size_t ny, double lx, double ly,
    double modulus)
{
	size_t i, j, n = nx * ny, n_c = 0;
	double dx = lx / (double)nx, dy = ly / (double)ny;
	double sum_x = 0, sum_y = 0, bonds_x = 0, bonds_y = 0;

#define GAP(ii, jj) (u[(jj) * nx + (ii)] - h[(jj) * nx + (ii)])
#pragma omp parallel for private(i) reduction(+:sum_x, sum_y, bonds_x, bonds_y, n_c) schedule(static)
	for (j = 0; j < ny; j++)
		for (i = 0; i < nx; i++) {
			size_t k = j * nx + i;

			if (!contact[k])
				continue;
			n_c++;
			if (!(sigma[k] > 0))
				continue;
			for (int b = 0; b < 4; b++) {
				int along_x = b < 2;
				size_t ii = i, jj = j, n_axis = along_x ? nx : ny;
				double g, gx, gy, c, d = along_x ? dx : dy;

				if (n_axis < 2)
					continue;
				if (along_x)
					ii = b == 0 ? (i + 1) % nx : (i + nx - 1) % nx;
				else
					jj = b == 2 ? (j + 1) % ny : (j + ny - 1) % ny;
				if (contact[jj * nx + ii] || !((g = GAP(ii, jj)) > 0))
					continue;
				gx = nx > 1 ? (GAP((ii + 1) % nx, jj) -
				    GAP((ii + nx - 1) % nx, jj)) / dx : 0;
				gy = ny > 1 ? (GAP(ii, (jj + 1) % ny) -
				    GAP(ii, (jj + ny - 1) % ny)) / dy : 0;
				c = hypot(gx, gy) > 0 ? fabs(along_x ? gx : gy) /
				    hypot(gx, gy) : 1;
				if (c < SUBPIXEL_C_MIN)
					c = SUBPIXEL_C_MIN;
				g = edge_fraction(3 * modulus * g /
				    (4 * sigma[k] * d * c)) - 0.5;
				if (along_x) {
					sum_x += g;
					bonds_x++;
				} else {
					sum_y += g;
					bonds_y++;
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
