/* SPDX-License-Identifier: GPL-3.0-or-later */
/* decomp.c - slab decomposition, reductions and MPI-IO of .surf files for
 * the MPI build (decomp.h). */
#include "decomp.h"

#include <complex.h>
#include <errno.h>
#include <fftw3-mpi.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "io_internal.h"
#include "units.h"

void
rc_mpi_rows(size_t nx, size_t ny, size_t *rows, size_t *j0,
    size_t *alloc_complex)
{
	ptrdiff_t local_n0, local_0_start, alloc;

	alloc = fftw_mpi_local_size_2d((ptrdiff_t)ny, (ptrdiff_t)(nx / 2 + 1),
	    MPI_COMM_WORLD, &local_n0, &local_0_start);
	*rows = (size_t)local_n0;
	*j0 = (size_t)local_0_start;
	*alloc_complex = alloc > 0 ? (size_t)alloc : 1;
}

int
rc_mpi_rank(void)
{
	int r;

	MPI_Comm_rank(MPI_COMM_WORLD, &r);
	return r;
}

int
rc_mpi_size(void)
{
	int r;

	MPI_Comm_size(MPI_COMM_WORLD, &r);
	return r;
}

void
rc_mpi_sum(double *v, int count)
{
	MPI_Allreduce(MPI_IN_PLACE, v, count, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
}

void
rc_mpi_max(double *v, int count)
{
	MPI_Allreduce(MPI_IN_PLACE, v, count, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
}

/* The .surf values are float64 little-endian; MPI-IO moves raw bytes. */
static int
little_endian(void)
{
	const unsigned one = 1;

	return *(const unsigned char *)&one == 1;
}

/* Rank 0's status and message to every rank: 0 on all or -1 on all. */
static int
agree(int status, rc_err *err)
{
	int bad = status != 0;

	MPI_Bcast(&bad, 1, MPI_INT, 0, MPI_COMM_WORLD);
	if (bad)
		MPI_Bcast(err->msg, (int)sizeof(err->msg), MPI_CHAR, 0, MPI_COMM_WORLD);
	return bad ? -1 : 0;
}

/* Any rank's failure (its message) to every rank. */
static int
agree_any(int status, rc_err *err)
{
	int mine = status != 0 ? rc_mpi_rank() : rc_mpi_size(), first;

	MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
	if (first == rc_mpi_size())
		return 0;
	MPI_Bcast(err->msg, (int)sizeof(err->msg), MPI_CHAR, first, MPI_COMM_WORLD);
	return -1;
}

/* The header grid (rank 0's) to every rank: rank 0 writes it as a .surf
 * header into memory and the others parse the same bytes. */
static rc_grid *
share_header(rc_grid *head, size_t *ny, rc_err *err)
{
	char *text = NULL;
	size_t len = 0, off;
	unsigned long long meta[2] = { 0, 0 };
	int st = 0;

	if (rc_mpi_rank() == 0) {
		FILE *fp = open_memstream(&text, &len);

		if (fp == NULL || rc__surf_write_header(head, *ny, fp, err) != 0)
			st = -1;
		if (fp != NULL && fclose(fp) != 0 && st == 0)
			st = rc_seterr(err, "out of memory");
		meta[0] = len;
	}
	if (agree(st, err) != 0) {
		free(text);
		return NULL;
	}
	MPI_Bcast(meta, 2, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
	if (rc_mpi_rank() != 0 && (text = malloc(meta[0] + 1)) == NULL)
		st = rc_seterr(err, "out of memory");
	if (agree_any(st, err) != 0) {
		free(text);
		return NULL;
	}
	MPI_Bcast(text, (int)meta[0], MPI_CHAR, 0, MPI_COMM_WORLD);
	if (rc_mpi_rank() != 0) {
		FILE *fp = fmemopen(text, meta[0], "r");

		head = fp != NULL ? rc__surf_read_header(fp, ny, &off, err) : NULL;
		if (fp == NULL)
			rc_seterr(err, "fmemopen: %s", strerror(errno));
		else
			fclose(fp);
		st = head == NULL ? -1 : 0;
	}
	free(text);
	if (agree_any(st, err) != 0) {
		if (rc_mpi_rank() != 0)
			rc_grid_free(head);
		return NULL;
	}
	return head;
}

/* Heights in another length unit than the sizes (a um x nm map) into the
 * lateral unit, as the serial tools read them (rc_grid_to_common_unit);
 * every rank does the same to its rows. */
static int
heights_to_lateral_unit(rc_grid *head, double *local, size_t n, rc_err *err)
{
	if (!rc_kind_is_length(head->kind) || head->z_unit[0] == '\0')
		return 0;
	if (!rc_unit_is_length(head->z_unit))
		return rc_seterr(err, "values are in '%s', not a length: not a %s",
		    head->z_unit, rc_kind_name(head->kind));
	if (head->unit[0] == '\0') {
		strcpy(head->unit, head->z_unit);
		return 0;
	}
	if (!rc_unit_is_length(head->unit))
		return rc_seterr(err, "lateral unit '%s' is not a length", head->unit);
	for (size_t k = 0; k < n; k++)
		local[k] = rc_unit_convert(local[k], head->z_unit, head->unit);
	strcpy(head->z_unit, head->unit);
	return 0;
}

rc_grid *
rc_mpi_surf_read(const char *path, size_t *ny, double **local, rc_err *err)
{
	rc_grid *head = NULL;
	unsigned long long hdr[2] = { 0, 0 };
	size_t rows, j0, alloc, offset = 0;
	MPI_File fh;
	MPI_Status status;
	int st = 0, rc;

	*local = NULL;
	if (rc_mpi_rank() == 0) {
		FILE *fp = fopen(path, "rb");

		if (!little_endian())
			st = rc_seterr(err, "MPI-IO of .surf needs a little-endian host");
		else if (fp == NULL)
			st = rc_seterr(err, "%s: %s", path, strerror(errno));
		else if ((head = rc__surf_read_header(fp, ny, &offset, err)) == NULL)
			st = -1;
		if (fp != NULL)
			fclose(fp);
		hdr[0] = *ny;
		hdr[1] = offset;
	}
	if (agree(st, err) != 0)
		return NULL;
	if ((head = share_header(head, ny, err)) == NULL)
		return NULL;
	MPI_Bcast(hdr, 2, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
	*ny = hdr[0];
	offset = hdr[1];
	rc_mpi_rows(head->nx, *ny, &rows, &j0, &alloc);
	if ((*local = fftw_alloc_real(rows * head->nx + 1)) == NULL)
		st = rc_seterr(err, "out of memory (asked for %zu bytes)",
		    (rows * head->nx + 1) * sizeof(double));
	if (agree_any(st, err) != 0)
		goto fail;
	rc = MPI_File_open(MPI_COMM_WORLD, path, MPI_MODE_RDONLY, MPI_INFO_NULL, &fh);
	if (rc != MPI_SUCCESS) {
		rc_seterr(err, "%s: MPI_File_open failed", path);
		goto fail;
	}
	MPI_Offset size;
	MPI_File_get_size(fh, &size);
	if ((unsigned long long)size < offset + (unsigned long long)head->nx * *ny * 8) {
		MPI_File_close(&fh);
		rc_seterr(err, "%s: truncated: %zu x %zu values need %llu bytes, the "
		    "file has %lld", path, head->nx, *ny,
		    (unsigned long long)(offset + head->nx * *ny * 8), (long long)size);
		goto fail;
	}
	/* One collective read per rank, counted in rows (an MPI count is an
	 * int; a row type keeps it far from 2^31). */
	MPI_Datatype row;

	MPI_Type_contiguous((int)head->nx, MPI_DOUBLE, &row);
	MPI_Type_commit(&row);
	rc = MPI_File_read_at_all(fh, (MPI_Offset)(offset + j0 * head->nx * 8), *local,
	    (int)rows, row, &status);
	MPI_Type_free(&row);
	MPI_File_close(&fh);
	if (agree_any(rc == MPI_SUCCESS ? 0 : rc_seterr(err, "%s: MPI-IO read failed",
	    path), err) != 0)
		goto fail;
	if (heights_to_lateral_unit(head, *local, rows * head->nx, err) != 0) {
		char msg[RC_ERRLEN];

		snprintf(msg, sizeof(msg), "%s", err->msg);
		rc_seterr(err, "%s: %s", path, msg);
		goto fail;
	}
	return head;
fail:
	fftw_free(*local);
	*local = NULL;
	rc_grid_free(head);
	return NULL;
}

int
rc_mpi_surf_write(const rc_grid *head, size_t ny, const double *local,
    const char *path, rc_err *err)
{
	char *text = NULL, *part = NULL;
	size_t len = 0, rows, j0, alloc;
	unsigned long long offset = 0;
	MPI_File fh;
	MPI_Status status;
	int st = 0, rc;

	if ((part = malloc(strlen(path) + 16)) == NULL)
		st = rc_seterr(err, "out of memory");
	else
		sprintf(part, "%s.mpi-part", path);
	if (rc_mpi_rank() == 0 && st == 0) {
		FILE *fp = open_memstream(&text, &len);

		if (!little_endian())
			st = rc_seterr(err, "MPI-IO of .surf needs a little-endian host");
		else if (fp == NULL || rc__surf_write_header(head, ny, fp, err) != 0)
			st = -1;
		if (fp != NULL && fclose(fp) != 0 && st == 0)
			st = rc_seterr(err, "out of memory");
		offset = len;
	}
	if (agree_any(st, err) != 0)
		goto out;
	MPI_Bcast(&offset, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
	rc = MPI_File_open(MPI_COMM_WORLD, part, MPI_MODE_WRONLY | MPI_MODE_CREATE,
	    MPI_INFO_NULL, &fh);
	if (rc != MPI_SUCCESS) {
		st = rc_seterr(err, "%s: cannot create", part);
		goto out;
	}
	MPI_File_set_size(fh, (MPI_Offset)(offset + head->nx * ny * 8));
	rc = MPI_SUCCESS;
	if (rc_mpi_rank() == 0)
		rc = MPI_File_write_at(fh, 0, text, (int)len, MPI_CHAR, &status);
	rc_mpi_rows(head->nx, ny, &rows, &j0, &alloc);
	MPI_Datatype row;

	MPI_Type_contiguous((int)head->nx, MPI_DOUBLE, &row);
	MPI_Type_commit(&row);
	if (rc == MPI_SUCCESS)
		rc = MPI_File_write_at_all(fh, (MPI_Offset)(offset + j0 * head->nx * 8),
		    local, (int)rows, row, &status);
	else
		MPI_File_write_at_all(fh, 0, local, 0, row, &status);
	MPI_Type_free(&row);
	rc = MPI_File_close(&fh) == MPI_SUCCESS ? rc : !MPI_SUCCESS;
	st = agree_any(rc == MPI_SUCCESS ? 0 : rc_seterr(err, "%s: MPI-IO write "
	    "failed", part), err);
	if (st == 0 && rc_mpi_rank() == 0 && rename(part, path) != 0)
		st = rc_seterr(err, "%s: rename: %s", path, strerror(errno));
	st = agree(st, err);
	if (st != 0 && rc_mpi_rank() == 0)
		remove(part);
out:
	free(text);
	free(part);
	return st;
}
