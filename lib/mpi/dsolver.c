/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dsolver.c - the distributed solver's set-up and contact analysis
 * (lib/mpi/dsolver.h); the iteration itself is lib/solver/solver_fire_loop.c, the
 * serial library's, running on the distributed operator of delastic.c. */
#include "mpi/dsolver.h"

#include <math.h>
#include <mpi.h>
#include <stdlib.h>
#include <string.h>

#include "contact.h"
#include "gradient.h"
#include "kappa.h"
#include "mpi/decomp.h"
#include "mpi/delastic.h"
#include "mpi/dpatches.h"
#include "mpi/dspectral.h"
#include "solver_impl.h"

rc_solver *
rc_mpi_solver_new(const double *height, size_t nx, size_t ny, double lx,
    double ly, const rc_solver_opts *o, rc_err *err)
{
	rc_solver *s;
	size_t rows, j0, alloc, n, k;
	double bad = 0;

	if (o->method != RC_METHOD_FIRE) {
		rc_seterr(err, "the MPI build solves with --method fire only");
		return NULL;
	}
	if (!(o->tol > 0) || !isfinite(o->tol)) {
		rc_seterr(err, "tolerance must be positive and finite");
		return NULL;
	}
	if (o->max_iter < 1) {
		rc_seterr(err, "max_iter must be at least 1");
		return NULL;
	}
	if (rc_grid_check_shape(nx, ny, lx, ly, err) != 0)
		return NULL;
	rc_mpi_rows(nx, ny, &rows, &j0, &alloc);
	n = nx * rows;
	for (k = 0; k < n; k++)
		if (!isfinite(height[k]))
			bad = 1;
	rc_mpi_max(&bad, 1);
	if (bad) {
		rc_seterr(err, "an indenter height is not finite");
		return NULL;
	}
	if ((s = rc_calloc(1, sizeof(*s), err)) == NULL)
		return NULL;
	s->opts = *o;
	s->nx = nx;
	s->ny = rows;
	s->n = n;
	s->lx = lx;
	s->ly = ly;
	if (rc_mpi_elastic_init(&s->el, nx, ny, lx, ly, o->modulus,
	    o->fft_effort == RC_FFT_ESTIMATE ? RC_FFT_ESTIMATE : RC_FFT_MEASURE,
	    err) != 0) {
		free(s);
		return NULL;
	}
	s->k_uniform = HUGE_VAL;	/* a half space: no uniform compression */
	/* One spare point: a rank may own no rows. */
	s->height = fftw_alloc_real(n + 1);
	s->sigma = fftw_alloc_real(n + 1);
	s->contact = calloc(n + 1, 1);
	if (s->height == NULL || s->sigma == NULL || s->contact == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes of solver fields)",
		    n * (2 * sizeof(double) + 1));
		rc_solver_free(s);
		return NULL;
	}
	memcpy(s->height, height, n * sizeof(double));
	memset(s->sigma, 0, (n + 1) * sizeof(double));
	/* max h, the reference of rc_solver_approach */
	s->top = -HUGE_VAL;
	for (size_t i = 0; i < n; i++)
		if (height[i] > s->top)
			s->top = height[i];
	rc_mpi_max(&s->top, 1);
	s->u = fftw_alloc_real(n + 1);
	s->fire_vel = fftw_alloc_real(n + 1);
	if (s->u == NULL || s->fire_vel == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes of FIRE buffers)",
		    2 * n * sizeof(double));
		rc_solver_free(s);
		return NULL;
	}
	return s;
}

/* Which rank owns row j (the FFTW-MPI blocks of every rank). */
static int
owner(const unsigned long long *first, int nranks, size_t j)
{
	int r;

	for (r = nranks - 1; r > 0; r--)
		if (first[2 * r + 1] > 0 && j >= first[2 * r])
			break;
	return r;
}

/* n_cl (contact.c's definition: a contact point with a non-contact
 * neighbour of the four) with a one-row halo from the neighbouring ranks;
 * this rank's count into *n_cl.  Collective. */
static int
contact_line(const rc_solver *s, size_t ny_all, size_t j0, size_t *count,
    rc_err *err)
{
	size_t nx = s->nx, rows = s->ny, n_cl = 0, i, j;
	unsigned long long mine[2] = { j0, rows }, *all;
	unsigned char *below, *above;
	int nranks = rc_mpi_size(), nreq = 0;
	double bad;
	MPI_Request req[4];

	all = malloc(2 * (size_t)nranks * sizeof(*all));
	below = malloc(nx);
	above = malloc(nx);
	bad = all == NULL || below == NULL || above == NULL;
	rc_mpi_max(&bad, 1);
	if (bad) {
		free(all);
		free(below);
		free(above);
		return rc_seterr(err, "out of memory for the contact line halo");
	}
	MPI_Allgather(mine, 2, MPI_UNSIGNED_LONG_LONG, all, 2,
	    MPI_UNSIGNED_LONG_LONG, MPI_COMM_WORLD);
	if (rows > 0) {
		int down = owner(all, nranks, (j0 + ny_all - 1) % ny_all);
		int up = owner(all, nranks, (j0 + rows) % ny_all);

		/* My first row is the row above the last of the rank below. */
		MPI_Irecv(above, (int)nx, MPI_UNSIGNED_CHAR, up, 1, MPI_COMM_WORLD,
		    &req[nreq++]);
		MPI_Irecv(below, (int)nx, MPI_UNSIGNED_CHAR, down, 2, MPI_COMM_WORLD,
		    &req[nreq++]);
		MPI_Isend(s->contact, (int)nx, MPI_UNSIGNED_CHAR, down, 1,
		    MPI_COMM_WORLD, &req[nreq++]);
		MPI_Isend(s->contact + (rows - 1) * nx, (int)nx, MPI_UNSIGNED_CHAR, up,
		    2, MPI_COMM_WORLD, &req[nreq++]);
		MPI_Waitall(nreq, req, MPI_STATUSES_IGNORE);
	}
	for (j = 0; j < rows; j++) {
		const unsigned char *row = s->contact + j * nx;
		const unsigned char *up = j + 1 < rows ? row + nx : above;
		const unsigned char *down = j > 0 ? row - nx : below;

		for (i = 0; i < nx; i++) {
			size_t left = i > 0 ? i - 1 : nx - 1;
			size_t right = i + 1 < nx ? i + 1 : 0;

			if (row[i])
				n_cl += !row[left] || !row[right] || !up[i] || !down[i];
		}
	}
	free(all);
	free(below);
	free(above);
	*count = n_cl;
	return 0;
}

double
rc_mpi_gbar(rc_solver *s)
{
	rc_elastic *e = &s->el;
	size_t rows, j0, alloc, ny = e->fft.ny;
	double sum;

	rc_mpi_rows(s->nx, ny, &rows, &j0, &alloc);
	rc_elastic_r2c(e, s->height, e->fft.spec);
	sum = rc_mpi_gradient_sum(e->fft.spec, s->nx, ny, s->lx, s->ly, j0, rows);
	rc_mpi_sum(&sum, 1);
	return sqrt(sum) / (double)e->n;
}

/* The spectral derivative d of the indenter (gradient.h), from its
 * spectrum spec0, into out (the rank's rows). */
static void
deriv(rc_solver *s, const fftw_complex *spec0, enum rc_deriv d, double *out)
{
	rc_elastic *e = &s->el;
	size_t rows, j0, alloc, ny = e->fft.ny;

	rc_mpi_rows(s->nx, ny, &rows, &j0, &alloc);
	rc_deriv_spectral(e->fft.spec, spec0, d, s->nx, ny, s->lx, s->ly, j0,
	    rows);
	rc_elastic_c2r(e, e->fft.spec, out);
}

/* Patches from every rank's rows (lib/mpi/dpatches.c: the mask is never
 * gathered). */
static int
patches(rc_solver *s, rc_contact_stats *st, rc_err *err)
{
	double sum_sq, cell = s->lx / (double)s->nx *
	    (s->ly / (double)s->el.fft.ny);

	if (rc_mpi_patches(s->contact, s->nx, s->ny, &st->n_patches, &sum_sq,
	    err) != 0)
		return -1;
	st->patch_size_char = st->n_c ? sum_sq / (double)st->n_c * cell : NAN;
	return 0;
}

int
rc_mpi_contact_analyse(rc_solver *s, double alpha, double pressure,
    double *gbar, rc_contact_stats *st, rc_err *err)
{
	rc_elastic *e = &s->el;
	size_t rows, j0, alloc, n = s->n, k, nc = e->nxc * e->ny, line = 0;
	double sums[3] = { 0, 0, 0 }, hbar, modulus = s->opts.modulus;
	fftw_complex *spec0;
	double *f;

	rc_mpi_rows(s->nx, e->fft.ny, &rows, &j0, &alloc);
	*gbar = rc_mpi_gbar(s);
	memset(st, 0, sizeof(*st));
	st->n_tot = e->n;
	st->patch_size_char = st->gbar_c = st->gbar_c_prime = NAN;
	st->kappa = st->kappa_c = NAN;
	err->msg[0] = '\0';
	for (k = 0; k < n; k++)
		if (s->contact[k]) {
			sums[0] += 1;
			sums[1] += s->height[k];
		}
	if (contact_line(s, e->fft.ny, j0, &line, err) != 0)
		return -1;
	sums[2] = (double)line;
	rc_mpi_sum(sums, 3);
	st->n_c = (size_t)sums[0];
	st->n_cl = (size_t)sums[2];
	st->a_r = sums[0] / (double)e->n;
	st->a_yastrebov = (sums[0] - alpha * sums[2]) / (double)e->n;
	if (modulus > 0 && *gbar > 0)
		st->kappa = rc_kappa(st->a_r, pressure / (modulus * *gbar));
	if (patches(s, st, err) != 0)
		return -1;
	if (st->n_c == 0)
		return 0;
	hbar = sums[1] / sums[0];
	spec0 = fftw_alloc_complex(nc + 1);
	f = fftw_alloc_real(n + 1);
	if (spec0 == NULL || f == NULL) {
		fftw_free(spec0);
		fftw_free(f);
		return rc_seterr(err, "out of memory (asked for %zu bytes)",
		    (2 * nc + n) * sizeof(double));
	}
	rc_elastic_r2c(e, s->height, e->fft.spec);
	memcpy(spec0, e->fft.spec, nc * sizeof(fftw_complex));
	sums[0] = sums[1] = 0;
	for (int d = RC_DERIV_X; d <= RC_DERIV_LAPLACIAN; d++) {
		double g, l;

		deriv(s, spec0, (enum rc_deriv)d, f);
		rc_field_sums(s->height, d == RC_DERIV_X ? f : NULL,
		    d == RC_DERIV_Y ? f : NULL, d == RC_DERIV_LAPLACIAN ? f : NULL,
		    s->contact, n, hbar, &g, &l);
		sums[0] += g;
		sums[1] += l;
	}
	rc_mpi_sum(sums, 2);
	fftw_free(spec0);
	fftw_free(f);
	st->gbar_c = sqrt(sums[0] / (double)st->n_c);
	sums[1] = -sums[1] / (double)st->n_c;
	st->gbar_c_prime = rc_signed_root(sums[1]);
	if (modulus > 0 && st->gbar_c > 0)
		st->kappa_c = rc_kappa(st->a_r, pressure / (modulus * st->gbar_c));
	return 0;
}
