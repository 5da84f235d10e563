/* contact.c - contact fraction, contact line, patches, masked gradients.
 *
 * Patches are labelled run by run (Hoshen-Kopelman on row runs): a
 * union-find over the runs of contact in each row, runs joined when they
 * share a column with a run of the row before, the last run of a row
 * joined to its first across the x boundary, and the last row joined to
 * the first across the y boundary.  Memory is one union-find entry per
 * run, which is far below one per point except on pathological masks.
 */
#include "contact.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "kappa.h"
#include "spectral.h"

/* Eq. 9's (gbar_c')^2 = -<dh lap h>_c can be negative over a partial
 * contact (dh about the contact mean): return its signed square root,
 * sign(x) sqrt(|x|), so the column is never NaN and squares back to x. */
static double
signed_root(double x)
{
	return x == 0 ? 0 : copysign(sqrt(fabs(x)), x);
}

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

/* On an axis of length 1 the periodic neighbour is the point itself, which
 * is in contact, so line grids need no special case. */
size_t
rc_contact_line(const unsigned char *contact, size_t nx, size_t ny)
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
			n_cl += !row[left] || !row[right] || !up[i] || !down[i];
		}
	}
	return n_cl;
}

struct run {
	size_t start, end;	/* columns [start, end) */
	size_t label;
};

struct uf {
	size_t *parent, *size;
	size_t n, cap;
};

static int
uf_add(struct uf *u, size_t size, size_t *label, rc_err *err)
{
	if (u->n == u->cap) {
		size_t cap = u->cap ? 2 * u->cap : 1024;
		size_t *p = realloc(u->parent, cap * sizeof(*p));
		if (p == NULL)
			return rc_seterr(err, "out of memory (asked for %zu bytes)",
			    cap * sizeof(*p));
		u->parent = p;
		p = realloc(u->size, cap * sizeof(*p));
		if (p == NULL)
			return rc_seterr(err, "out of memory (asked for %zu bytes)",
			    cap * sizeof(*p));
		u->size = p;
		u->cap = cap;
	}
	u->parent[u->n] = u->n;
	u->size[u->n] = size;
	*label = u->n++;
	return 0;
}

static size_t
uf_find(struct uf *u, size_t a)
{
	while (u->parent[a] != a) {
		u->parent[a] = u->parent[u->parent[a]];	/* path halving */
		a = u->parent[a];
	}
	return a;
}

static void
uf_union(struct uf *u, size_t a, size_t b)
{
	a = uf_find(u, a);
	b = uf_find(u, b);
	if (a == b)
		return;
	if (u->size[a] < u->size[b]) {
		size_t t = a;
		a = b;
		b = t;
	}
	u->parent[b] = a;
	u->size[a] += u->size[b];
}

/* Join runs of two adjacent rows that share a column (both sorted). */
static void
join_rows(struct uf *u, const struct run *a, size_t na, const struct run *b,
    size_t nb)
{
	size_t i = 0, k = 0;

	while (i < na && k < nb) {
		if (a[i].start < b[k].end && b[k].start < a[i].end)
			uf_union(u, a[i].label, b[k].label);
		if (a[i].end < b[k].end)
			i++;
		else
			k++;
	}
}

int
rc_contact_patches(const unsigned char *contact, size_t nx, size_t ny,
    size_t *n_patches, double *sum_sq, rc_err *err)
{
	struct uf u = { NULL, NULL, 0, 0 };
	struct run *buf, *first, *prev, *cur, *t;
	size_t maxruns = nx / 2 + 1, nfirst = 0, nprev = 0, ncur;
	int rv = -1;

	if ((buf = rc_calloc(3 * maxruns, sizeof(*buf), err)) == NULL)
		return -1;
	first = buf;
	prev = buf + maxruns;
	cur = buf + 2 * maxruns;
	for (size_t j = 0; j < ny; j++) {
		const unsigned char *row = contact + j * nx;
		ncur = 0;
		for (size_t i = 0; i < nx;) {
			if (!row[i]) {
				i++;
				continue;
			}
			size_t s = i;
			while (i < nx && row[i])
				i++;
			cur[ncur].start = s;
			cur[ncur].end = i;
			if (uf_add(&u, i - s, &cur[ncur].label, err) != 0)
				goto out;
			ncur++;
		}
		if (ncur >= 2 && cur[0].start == 0 && cur[ncur - 1].end == nx)
			uf_union(&u, cur[0].label, cur[ncur - 1].label);
		if (j > 0)
			join_rows(&u, prev, nprev, cur, ncur);
		if (j == 0) {
			memcpy(first, cur, ncur * sizeof(*cur));
			nfirst = ncur;
		}
		t = prev;
		prev = cur;
		cur = t;
		nprev = ncur;
	}
	/* Across the y boundary (a self-join when ny = 1, which is harmless). */
	join_rows(&u, prev, nprev, first, nfirst);
	*n_patches = 0;
	*sum_sq = 0;
	for (size_t k = 0; k < u.n; k++) {
		if (u.parent[k] != k)
			continue;
		(*n_patches)++;
		*sum_sq += (double)u.size[k] * (double)u.size[k];
	}
	rv = 0;
out:
	free(u.parent);
	free(u.size);
	free(buf);
	return rv;
}

/* Masked sums of fft->real (squared or times (h - hbar_c)); rows are summed
 * first so round-off grows with nx + ny rather than nx * ny. */
static double
masked_sum_sq(const double *f, const unsigned char *contact, size_t nx,
    size_t ny)
{
	double sum = 0;

	#pragma omp parallel for reduction(+:sum) schedule(static)
	for (size_t j = 0; j < ny; j++) {
		double row = 0;
		for (size_t i = j * nx; i < (j + 1) * nx; i++)
			if (contact[i])
				row += f[i] * f[i];
		sum += row;
	}
	return sum;
}

static double
masked_sum_dh(const double *f, const double *h, double hbar,
    const unsigned char *contact, size_t nx, size_t ny)
{
	double sum = 0;

	#pragma omp parallel for reduction(+:sum) schedule(static)
	for (size_t j = 0; j < ny; j++) {
		double row = 0;
		for (size_t i = j * nx; i < (j + 1) * nx; i++)
			if (contact[i])
				row += (f != NULL ? f[i] : 1) * (h[i] - hbar);
		sum += row;
	}
	return sum;
}

/* Central differences at every point (contact NULL) or at the contact
 * points: sum of |grad h|^2 into *grad2 and of (h - hbar) lap h into
 * *dh_lap.  An axis of length 1 has no derivative (the neighbours are the
 * point itself). */
static void
fd_sums(const rc_grid *h, const unsigned char *contact, double hbar,
    double *grad2, double *dh_lap)
{
	size_t nx = h->nx, ny = h->ny;
	double dx = h->lx / (double)nx, dy = h->ly / (double)ny;
	double sum_g = 0, sum_l = 0;
	const double *z = h->z;

	#pragma omp parallel for reduction(+:sum_g, sum_l) schedule(static)
	for (size_t j = 0; j < ny; j++) {
		const double *row = z + j * nx;
		const double *up = z + (j + 1 < ny ? j + 1 : 0) * nx;
		const double *down = z + (j > 0 ? j - 1 : ny - 1) * nx;
		double row_g = 0, row_l = 0;
		for (size_t i = 0; i < nx; i++) {
			if (contact != NULL && !contact[j * nx + i])
				continue;
			size_t left = i > 0 ? i - 1 : nx - 1;
			size_t right = i + 1 < nx ? i + 1 : 0;
			double hx = (row[right] - row[left]) / (2 * dx);
			double hy = (up[i] - down[i]) / (2 * dy);
			double lap = (row[right] - 2 * row[i] + row[left]) / (dx * dx) +
			    (up[i] - 2 * row[i] + down[i]) / (dy * dy);
			row_g += hx * hx + hy * hy;
			row_l += (row[i] - hbar) * lap;
		}
		sum_g += row_g;
		sum_l += row_l;
	}
	*grad2 = sum_g;
	*dh_lap = sum_l;
}

double
rc_contact_gbar_fd(const rc_grid *h)
{
	double grad2, dh_lap;

	fd_sums(h, NULL, 0, &grad2, &dh_lap);
	return sqrt(grad2 / (double)rc_grid_size(h));
}

static int
gradients(const rc_grid *h, const unsigned char *contact, size_t n_c,
    rc_fft *fft, int fd, rc_contact_stats *st, rc_err *err)
{
	rc_fft own;
	size_t nx = h->nx, ny = h->ny;
	double hbar, sum, dh_lap;
	int rv = -1;

	if (n_c == 0)
		return 0;	/* NaN: no contact to average over */
	hbar = masked_sum_dh(NULL, h->z, 0, contact, nx, ny) / (double)n_c;
	if (fd) {
		fd_sums(h, contact, hbar, &sum, &dh_lap);
		st->gbar_c = sqrt(sum / (double)n_c);
		sum = -dh_lap / (double)n_c;
		st->gbar_c_prime = signed_root(sum);
		return 0;
	}
	memset(&own, 0, sizeof(own));
	if (fft == NULL) {
		if (rc_fft_init(&own, nx, ny, RC_FFT_ESTIMATE, err) != 0)
			return -1;
		fft = &own;
	}
	if (rc_spectral_deriv(h, fft, RC_DERIV_X, err) != 0)
		goto out;
	sum = masked_sum_sq(fft->real, contact, nx, ny);
	if (rc_spectral_deriv(h, fft, RC_DERIV_Y, err) != 0)
		goto out;
	sum += masked_sum_sq(fft->real, contact, nx, ny);
	st->gbar_c = sqrt(sum / (double)n_c);
	if (rc_spectral_deriv(h, fft, RC_DERIV_LAPLACIAN, err) != 0)
		goto out;
	sum = -masked_sum_dh(fft->real, h->z, hbar, contact, nx, ny) / (double)n_c;
	st->gbar_c_prime = signed_root(sum);
	rv = 0;
out:
	if (fft == &own)
		rc_fft_free(&own);
	return rv;
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
		st->n_cl = rc_contact_line(contact, nx, ny);
		st->a_yastrebov = ((double)st->n_c - o->alpha * (double)st->n_cl) /
		    (double)n;
	}
	if (flags & RC_CONTACT_PATCHES) {
		double sum_sq, cell = h->lx / (double)nx * (h->ly / (double)ny);
		if (rc_contact_patches(contact, nx, ny, &st->n_patches, &sum_sq,
		    err) != 0)
			return -1;
		st->patch_size_char = st->n_c ? sum_sq / (double)st->n_c * cell : NAN;
	}
	if (flags & RC_CONTACT_GRADIENT &&
	    gradients(h, contact, st->n_c, o->fft, o->fd, st, err) != 0)
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
