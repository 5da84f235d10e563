/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dpatches.c - contact patches of a row-distributed mask.
 *
 * Each rank labels its own rows (lib/patches.c: periodic in x, joined
 * between its rows).  A component touching neither the rank's first nor
 * its last row is complete: it is counted where it lies.  The others go
 * to rank 0 as sizes, together with the runs of the two edge rows, O(nx)
 * numbers per rank: rank 0 joins each rank's last row to the first row of
 * the next rank that has rows (cyclically, which is the y boundary) and
 * counts the joined components.  So the mask is never gathered, and the
 * result equals the serial labelling of the whole mask exactly (integer
 * sizes; sums of squares below 2^53).
 *
 * Message of one rank (unsigned long long): rows, nb, nfirst, nlast, the
 * nb edge component sizes, then (start, end, id) of each run of the
 * first row and of the last row, id in [0, nb).
 */
#include "mpi/dpatches.h"

#include <mpi.h>
#include <stdint.h>
#include <stdlib.h>

#include "mpi/decomp.h"
#include "patches.h"

#define HEAD 4

/* This rank's message and its complete components' count and sum of
 * squared sizes (done[0], done[1]). */
static int
local_part(const unsigned char *contact, size_t nx, size_t rows,
    unsigned long long **msg, size_t *len, double done[2], rc_err *err)
{
	size_t maxruns = nx / 2 + 1, nfirst, nlast, nb = 0, k, i;
	rc_uf u = { NULL, NULL, 0, 0 };
	rc_run *ends, *last;
	size_t *edge_id = NULL;
	unsigned long long *m = NULL;
	int rv = -1;

	*msg = NULL;
	if ((ends = rc_calloc(2 * maxruns, sizeof(*ends), err)) == NULL)
		return -1;
	last = ends + maxruns;
	if (rc_patches_slab(contact, nx, rows, &u, ends, &nfirst, last, &nlast,
	    err) != 0)
		goto out;
	if ((edge_id = rc_calloc(u.n + 1, sizeof(*edge_id), err)) == NULL)
		goto out;
	for (k = 0; k < u.n; k++)
		edge_id[k] = SIZE_MAX;
	for (i = 0; i < nfirst + nlast; i++) {
		size_t r = rc_uf_find(&u, (i < nfirst ? ends[i] :
		    last[i - nfirst]).label);

		if (edge_id[r] == SIZE_MAX)
			edge_id[r] = nb++;
	}
	*len = HEAD + nb + 3 * (nfirst + nlast);
	if ((m = rc_calloc(*len, sizeof(*m), err)) == NULL)
		goto out;
	m[0] = rows;
	m[1] = nb;
	m[2] = nfirst;
	m[3] = nlast;
	done[0] = done[1] = 0;
	for (k = 0; k < u.n; k++) {
		if (u.parent[k] != k)
			continue;
		if (edge_id[k] != SIZE_MAX)
			m[HEAD + edge_id[k]] = u.size[k];
		else {
			done[0] += 1;
			done[1] += (double)u.size[k] * (double)u.size[k];
		}
	}
	for (i = 0; i < nfirst + nlast; i++) {
		const rc_run *run = i < nfirst ? &ends[i] : &last[i - nfirst];
		unsigned long long *t = m + HEAD + nb + 3 * i;

		t[0] = run->start;
		t[1] = run->end;
		t[2] = edge_id[rc_uf_find(&u, run->label)];
	}
	*msg = m;
	m = NULL;
	rv = 0;
out:
	rc_uf_free(&u);
	free(ends);
	free(edge_id);
	free(m);
	return rv;
}

/* Runs of one row of a rank's message (which = 0 first, 1 last) with
 * their ids offset into rank 0's union-find. */
static size_t
decode_runs(const unsigned long long *m, int which, size_t offset,
    rc_run *out)
{
	size_t nb = m[1], nfirst = m[2], n = which ? m[3] : nfirst;
	const unsigned long long *t = m + HEAD + nb + (which ? 3 * nfirst : 0);

	for (size_t i = 0; i < n; i++) {
		out[i].start = t[3 * i];
		out[i].end = t[3 * i + 1];
		out[i].label = offset + t[3 * i + 2];
	}
	return n;
}

/* Rank 0: join the edges of all ranks' messages. */
static int
join_edges(const unsigned long long *all, const int *displs, int nranks,
    size_t nx, size_t *n_joined, double *sq_joined, rc_err *err)
{
	rc_uf u = { NULL, NULL, 0, 0 };
	size_t maxruns = nx / 2 + 1, *offset, label, na, nb;
	rc_run *a = NULL, *b;
	int r, first = -1, prev = -1, rv = -1;

	if ((offset = rc_calloc((size_t)nranks, sizeof(*offset), err)) == NULL)
		return -1;
	if ((a = rc_calloc(2 * maxruns, sizeof(*a), err)) == NULL)
		goto out;
	b = a + maxruns;
	for (r = 0; r < nranks; r++) {
		const unsigned long long *m = all + displs[r];

		offset[r] = u.n;
		for (size_t i = 0; i < m[1]; i++)
			if (rc_uf_add(&u, m[HEAD + i], &label, err) != 0)
				goto out;
	}
	/* last row of each rank with rows to the first row of the next */
	for (r = 0; r < nranks; r++) {
		if (all[displs[r]] == 0)
			continue;
		if (first < 0)
			first = r;
		if (prev >= 0) {
			na = decode_runs(all + displs[prev], 1, offset[prev], a);
			nb = decode_runs(all + displs[r], 0, offset[r], b);
			rc_runs_join(&u, a, na, b, nb);
		}
		prev = r;
	}
	if (prev >= 0) {
		na = decode_runs(all + displs[prev], 1, offset[prev], a);
		nb = decode_runs(all + displs[first], 0, offset[first], b);
		rc_runs_join(&u, a, na, b, nb);
	}
	rc_uf_components(&u, n_joined, sq_joined);
	rv = 0;
out:
	rc_uf_free(&u);
	free(offset);
	free(a);
	return rv;
}

/* Long: the local labelling, the label exchange with neighbouring ranks
 * and the global union share the label arrays. */
int
rc_mpi_patches(const unsigned char *contact, size_t nx, size_t rows,
    size_t *n_patches, double *sum_sq, rc_err *err)
{
	int nranks = rc_mpi_size(), rank = rc_mpi_rank(), st = 0, len_i, r;
	int *counts = NULL, *displs = NULL;
	unsigned long long *msg = NULL, *all = NULL;
	size_t len = 0, total = 0, n_joined = 0;
	double done[2] = { 0, 0 }, done_all[2] = { 0, 0 }, out[2] = { 0, 0 };
	double sq_joined = 0;

	err->msg[0] = '\0';
	if (local_part(contact, nx, rows, &msg, &len, done, err) != 0)
		st = -1;
	else if (len > INT32_MAX)
		st = rc_seterr(err, "patch statistics: %zu edge numbers on one "
		    "rank (more than an MPI count)", len);
	len_i = st ? 0 : (int)len;
	if (rank == 0 &&
	    ((counts = rc_calloc((size_t)nranks, sizeof(int), err)) == NULL ||
	    (displs = rc_calloc((size_t)nranks, sizeof(int), err)) == NULL))
		st = -1;
	MPI_Allreduce(MPI_IN_PLACE, &st, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
	if (st != 0)
		goto fail;
	MPI_Reduce(done, done_all, 2, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
	MPI_Gather(&len_i, 1, MPI_INT, counts, 1, MPI_INT, 0, MPI_COMM_WORLD);
	if (rank == 0) {
		for (r = 0; r < nranks; r++) {
			if (total + (size_t)counts[r] > INT32_MAX) {
				st = rc_seterr(err, "patch statistics: more edge "
				    "numbers than an MPI count");
				break;
			}
			displs[r] = (int)total;
			total += (size_t)counts[r];
		}
		if (st == 0 &&
		    (all = rc_calloc(total, sizeof(*all), err)) == NULL)
			st = -1;
	}
	MPI_Bcast(&st, 1, MPI_INT, 0, MPI_COMM_WORLD);
	if (st != 0)
		goto fail;
	MPI_Gatherv(msg, len_i, MPI_UNSIGNED_LONG_LONG, all, counts, displs,
	    MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
	if (rank == 0) {
		if (join_edges(all, displs, nranks, nx, &n_joined, &sq_joined,
		    err) != 0)
			st = -1;
		out[0] = done_all[0] + (double)n_joined;
		out[1] = done_all[1] + sq_joined;
	}
	MPI_Bcast(&st, 1, MPI_INT, 0, MPI_COMM_WORLD);
	if (st != 0)
		goto fail;
	MPI_Bcast(out, 2, MPI_DOUBLE, 0, MPI_COMM_WORLD);
	*n_patches = (size_t)out[0];
	*sum_sq = out[1];
	free(msg);
	free(all);
	free(counts);
	free(displs);
	return 0;
fail:
	/* the first message of any rank that has one, on every rank */
	{
		int mine = err->msg[0] != '\0' ? rank : nranks, from;

		MPI_Allreduce(&mine, &from, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
		if (from < nranks)
			MPI_Bcast(err->msg, (int)sizeof(err->msg), MPI_CHAR, from,
			    MPI_COMM_WORLD);
		else
			rc_seterr(err, "out of memory for the patch statistics");
	}
	free(msg);
	free(all);
	free(counts);
	free(displs);
	return -1;
}
