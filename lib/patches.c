/* SPDX-License-Identifier: GPL-3.0-or-later */
/* patches.c - contact patches, labelled run by run (Hoshen-Kopelman on
 * row runs): a union-find over the runs of contact in each row, runs
 * joined when they share a column with a run of the row before, the last
 * run of a row joined to its first across the x boundary, and the last
 * row joined to the first across the y boundary (neither join for a
 * finite patch, rc_contact_patches_open).  Memory is one
 * union-find entry per run, far below one per point except on
 * pathological masks.
 */
#include "patches.h"

#include <stdlib.h>
#include <string.h>

#include "contact.h"

int
rc_uf_add(rc_uf *u, size_t size, size_t *label, rc_err *err)
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

size_t
rc_uf_find(rc_uf *u, size_t a)
{
	while (u->parent[a] != a) {
		u->parent[a] = u->parent[u->parent[a]];	/* path halving */
		a = u->parent[a];
	}
	return a;
}

void
rc_uf_union(rc_uf *u, size_t a, size_t b)
{
	a = rc_uf_find(u, a);
	b = rc_uf_find(u, b);
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

void
rc_uf_free(rc_uf *u)
{
	free(u->parent);
	free(u->size);
	memset(u, 0, sizeof(*u));
}

void
rc_uf_components(const rc_uf *u, size_t *count, double *sum_sq)
{
	*count = 0;
	*sum_sq = 0;
	for (size_t k = 0; k < u->n; k++)
		if (u->parent[k] == k) {
			(*count)++;
			*sum_sq += (double)u->size[k] * (double)u->size[k];
		}
}

void
rc_runs_join(rc_uf *u, const rc_run *a, size_t na, const rc_run *b,
    size_t nb)
{
	size_t i = 0, k = 0;

	while (i < na && k < nb) {
		if (a[i].start < b[k].end && b[k].start < a[i].end)
			rc_uf_union(u, a[i].label, b[k].label);
		if (a[i].end < b[k].end)
			i++;
		else
			k++;
	}
}

static int
slab(const unsigned char *contact, size_t nx, size_t ny, int wrap_x,
    rc_uf *u, rc_run *first, size_t *nfirst, rc_run *last, size_t *nlast,
    rc_err *err)
{
	rc_run *buf, *prev, *cur, *t;
	size_t maxruns = nx / 2 + 1, nprev = 0, ncur = 0;

	*nfirst = *nlast = 0;
	if ((buf = rc_calloc(2 * maxruns, sizeof(*buf), err)) == NULL)
		return -1;
	prev = buf;
	cur = buf + maxruns;
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
			if (rc_uf_add(u, i - s, &cur[ncur].label, err) != 0) {
				free(buf);
				return -1;
			}
			ncur++;
		}
		if (wrap_x && ncur >= 2 && cur[0].start == 0 &&
		    cur[ncur - 1].end == nx)
			rc_uf_union(u, cur[0].label, cur[ncur - 1].label);
		if (j > 0)
			rc_runs_join(u, prev, nprev, cur, ncur);
		if (j == 0) {
			memcpy(first, cur, ncur * sizeof(*cur));
			*nfirst = ncur;
		}
		t = prev;
		prev = cur;
		cur = t;
		nprev = ncur;
	}
	memcpy(last, prev, nprev * sizeof(*prev));
	*nlast = nprev;
	free(buf);
	return 0;
}

int
rc_patches_slab(const unsigned char *contact, size_t nx, size_t ny,
    rc_uf *u, rc_run *first, size_t *nfirst, rc_run *last, size_t *nlast,
    rc_err *err)
{
	return slab(contact, nx, ny, 1, u, first, nfirst, last, nlast, err);
}

/* Patches of the whole grid: periodic joins runs across both boundaries,
 * else (a finite patch, free boundaries) there is no wrap-around. */
static int
patches(const unsigned char *contact, size_t nx, size_t ny, int periodic,
    size_t *n_patches, double *sum_sq, rc_err *err)
{
	rc_uf u = { NULL, NULL, 0, 0 };
	rc_run *ends;
	size_t maxruns = nx / 2 + 1, nfirst, nlast;
	int rv = -1;

	if ((ends = rc_calloc(2 * maxruns, sizeof(*ends), err)) == NULL)
		return -1;
	if (slab(contact, nx, ny, periodic, &u, ends, &nfirst, ends + maxruns,
	    &nlast, err) == 0) {
		/* Across the y boundary (a self-join when ny = 1, which is
		 * harmless). */
		if (periodic)
			rc_runs_join(&u, ends + maxruns, nlast, ends, nfirst);
		rc_uf_components(&u, n_patches, sum_sq);
		rv = 0;
	}
	rc_uf_free(&u);
	free(ends);
	return rv;
}

int
rc_contact_patches_open(const unsigned char *contact, size_t nx, size_t ny,
    size_t *n_patches, double *sum_sq, rc_err *err)
{
	return patches(contact, nx, ny, 0, n_patches, sum_sq, err);
}

int
rc_contact_patches(const unsigned char *contact, size_t nx, size_t ny,
    size_t *n_patches, double *sum_sq, rc_err *err)
{
	return patches(contact, nx, ny, 1, n_patches, sum_sq, err);
}
