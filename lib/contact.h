/* SPDX-License-Identifier: GPL-3.0-or-later */
/* contact.h - analysis of a contact field: contact fraction, contact
 * line, patches, and the indenter's gradients averaged over the contact.
 *
 * Input: the indenter heights h (a periodic grid, or a finite patch: see
 * opts.nonperiodic below) and a contact mask of
 * nx*ny bytes, 1 where the point is in contact.  Everything is O(N) and
 * only what the flags ask for is computed.  Neighbours are the four
 * nearest ones with periodic wrap-around; on a line grid (ny = 1, or
 * nx = 1) only the two neighbours along the line exist, and a 1 x 1 grid
 * has none.  Quantities (Wang & Mueser 2020):
 *   a_r             n_c / n_tot
 *   n_cl            contact points with at least one non-contact neighbour
 *   a_yastrebov     (n_c - alpha n_cl) / n_tot                     (Eq. 22)
 *   n_patches       periodic connected components of the contact
 *   patch_size_char A_c = sum_i s_i^2 / sum_i s_i, s_i the patch areas:
 *                   the expected area of the patch that a randomly picked
 *                   contact point belongs to (length^2)
 *   gbar_c          sqrt(<|grad h|^2>_c)                          (Eq. 8)
 *   gbar_c_prime    sign(x) sqrt(|x|), x = -<dh lap h>_c, dh = h - <h>_c
 *                   (Eq. 9; x can be negative over a partial contact)
 *   kappa, kappa_c  from a_r = erf(sqrt(pi) kappa p* / 2) with
 *                   p* = p/(E* gbar) and p*_c = p/(E* gbar_c)  (Eqs. 24, 8)
 * Derivatives are taken on the whole periodic indenter, then averaged
 * over the mask: spectral by default (spectral.h; exact for band-limited
 * heights), one field at a time; or, with opts.fd, central differences
 * h_x = (h[i+1] - h[i-1]) / 2dx and the 5-point Laplacian, which need no
 * buffer and suit indenters with kinks (a kink makes the spectral
 * derivatives ring over the whole cell).  Averages over an empty contact are NaN.
 *
 * A finite patch (opts.nonperiodic, free boundaries in gfmd-solve) has no
 * wrap-around: outside the grid there is no contact, so a contact point
 * on the edge is on the contact line; patches are not joined across the
 * edges; and the derivatives are central differences with the neighbours
 * inside the grid only (h_x = (h[i+1] - h[i]) / dx at i = 0, the second
 * difference of the nearest interior point at the edges; an axis of
 * fewer than 3 points has no second derivative), whatever opts.fd says:
 * spectral derivatives would see the step between opposite edges.
 */
#ifndef RC_CONTACT_H
#define RC_CONTACT_H

#include <stddef.h>
#include "fft.h"
#include "grid.h"

/* Yastrebov et al.'s (2017) contact-line weight, (pi - 1 + ln 2)/24. */
#define RC_YASTREBOV_ALPHA ((3.14159265358979323846 - 1 + \
	0.69314718055994530942) / 24)

enum {
	RC_CONTACT_COUNT = 1 << 0,	/* n_c, n_tot, a_r */
	RC_CONTACT_LINE = 1 << 1,	/* n_cl, a_yastrebov */
	RC_CONTACT_PATCHES = 1 << 2,	/* n_patches, patch_size_char */
	RC_CONTACT_GRADIENT = 1 << 3,	/* gbar_c, gbar_c_prime */
	RC_CONTACT_KAPPA = 1 << 4,	/* kappa, kappa_c (implies the above) */
	RC_CONTACT_ALL = (1 << 5) - 1
};

typedef struct rc_contact_opts {
	unsigned flags;
	double alpha;		/* Eq. 22 weight (RC_YASTREBOV_ALPHA) */
	/* For RC_CONTACT_KAPPA: the applied mean pressure, the contact
	 * modulus E* and the rms gradient of the whole indenter. */
	double pressure, modulus, gbar;
	/* A plan of the grid's size to reuse for the gradients, or NULL to
	 * make one for this call; its buffers are overwritten. */
	rc_fft *fft;
	int fd;			/* central differences instead of spectral */
	int nonperiodic;	/* a finite patch: no wrap-around (above) */
} rc_contact_opts;

typedef struct rc_contact_stats {
	size_t n_tot, n_c, n_cl, n_patches;
	double a_r, a_yastrebov;
	double patch_size_char;	/* A_c, in the square of the length unit */
	double gbar_c, gbar_c_prime;
	double kappa, kappa_c;
} rc_contact_stats;

void rc_contact_defaults(rc_contact_opts *o);

/* Fields not asked for are set to NaN (sizes to 0).  Returns -1 only on
 * an allocation failure or a plan of the wrong size. */
int rc_contact_analyse(const rc_grid *h, const unsigned char *contact,
    const rc_contact_opts *o, rc_contact_stats *st, rc_err *err);

/* The rms gradient of the whole grid by the central and open stencils:
 * rc_gbar_central and rc_gbar_open (gradient.h). */

/* Sub-pixel contact area from a solution (periodic grids), a fraction
 * of the cell.  The raw count n_c puts the contact line on the midpoint
 * of every bond between a contact point i and a non-contact neighbour j.
 * Near a straight contact edge the pressure inside and the gap outside
 * follow the edge asymptotics of a half space (locally plane strain; the
 * 2D Hertz solution expanded at its edge):
 *   sigma(s) = C s^(1/2),   g(t) = (4 C / (3 E*)) t^(3/2),
 * s and t the normal distances into and out of the contact.  A bond of
 * spacing d (dx or dy) crossing the edge at distance x from i along the
 * bond has s = c x, t = c (d - x), c = |n . e| the cosine between the
 * edge normal and the bond, so
 *   3 E* g_j / (4 sigma_i d c) = (1 - f)^(3/2) / f^(1/2),  f = x / d,
 * monotonic in f in (0, 1), solved by a 50-step bisection (to 2^-50),
 * whose first steps (44 or 45 typically) are read off the root of the cubic
 * (1 - f)^3 = r^2 f in closed form and certified by two tests, so that f
 * is the plain bisection's bit for bit (contact.c).  The normal is that of
 * the gap's gradient at j (central differences, wrap-around); c is
 * floored at 0.1 (a bond along the edge carries no information on where
 * it crosses).  The edge then lies (f - 1/2) d beyond the bond's
 * midpoint; summed over the bonds of one axis, S_x = sum (f - 1/2),
 * this is the area (in pixels) that the rows miss, exact for a straight
 * edge that crosses them (the length in contact is linear across a row,
 * so the row centre's is its mean), and the same for the columns, S_y.
 * The two are weighted by their bond counts b_x, b_y (an edge along y
 * crosses no column, and the columns' estimate is then the raw one):
 *   a_subpixel = (n_c + (b_x S_x + b_y S_y) / (b_x + b_y)) / n_tot.
 * Bonds with sigma_i = 0 or g_j = 0 are
 * skipped.  Chosen among seven variants (how the normal is estimated,
 * its floor) on two seeds at eps_c = 1/4 and 1/8 (bench/accuracy,
 * README.md: its measured error).  u, h, sigma: nx*ny values. */
double rc_contact_subpixel(const double *u, const double *h,
    const double *sigma, const unsigned char *contact, size_t nx, size_t ny,
    double lx, double ly, double modulus);

/* The pieces, for callers that need only one. */
size_t rc_contact_count(const unsigned char *contact, size_t n);
size_t rc_contact_line(const unsigned char *contact, size_t nx, size_t ny);
/* Patch count and sum of squared patch sizes in points (sum s_i^2). */
int rc_contact_patches(const unsigned char *contact, size_t nx, size_t ny,
    size_t *n_patches, double *sum_sq, rc_err *err);
/* The same on a finite patch: no wrap-around. */
size_t rc_contact_line_open(const unsigned char *contact, size_t nx, size_t ny);
int rc_contact_patches_open(const unsigned char *contact, size_t nx, size_t ny,
    size_t *n_patches, double *sum_sq, rc_err *err);

#endif
