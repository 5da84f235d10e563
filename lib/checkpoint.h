/* SPDX-License-Identifier: GPL-3.0-or-later */
/* checkpoint.h - the state of an interrupted list of contact solves, so
 * that a run can resume where it stopped (gfmd-solve --checkpoint,
 * --resume).
 *
 * A checkpoint is a native .surf grid (surf(5)) of the elastic surface
 * height u of the solve in progress (or of the last finished one), whose
 * metadata, all under "checkpoint.", say what it belongs to:
 *   version        6
 *   input_sum      FNV-1a 64-bit hash of the indenter (nx, ny, lx, ly, the
 *                  bit patterns of its heights, its metadata, units,
 *                  periodic flag and missing-point mask), 16 hex digits
 *   method, tol, E, alpha, fd, max_iter   the options that decide the rows
 *   stall          --stall (0: never), which decides them too; since
 *                  version 6 (older checkpoints: unrecorded, any --stall
 *                  resumes them)
 *   boundary, kernel, hardness, thickness, substrate, poisson, adhesion,
 *   range          the scene (--boundary, --kernel, the optional effects;
 *                  0 or none where not asked for); since version 3 (a
 *                  version 2 checkpoint is read as the half space with no
 *                  effect, which gfmd-solve then refused with checkpoints,
 *                  and an unrecorded boundary kind)
 *   law            the adhesive law (adhesion.h: exponential or dugdale;
 *                  exponential without adhesion); since version 4 (older
 *                  checkpoints: exponential, the only law then)
 *   pressure_kind  reduced (-p) or absolute (--pressure-abs)
 *   pressures      the full list, comma-separated, exact to the last bit
 *                  (positive; any finite value with adhesion)
 *   next           index (0-based) of the first pressure without a row
 *   unconverged    how many of the finished rows did not converge (the
 *                  resumed run's exit status counts them); since version
 *                  6 (older checkpoints: 0)
 *   state          solving (u is a partial solve of pressures[next]) or
 *                  between (u is the solution of pressures[next - 1])
 *   iterations     iterations already spent on pressures[next]
 *   columns, types the result columns (tab-separated) and, per column,
 *                  n (number) or s (string)
 *   row.K          the finished row K, K < next, values tab-separated with
 *                  '\', tab and space escaped as \\, \t, \s
 *   sum            FNV-1a 64-bit hash of the size, u's bit patterns and
 *                  every checkpoint.* key and value above, 16 hex digits;
 *                  since version 5 (read refuses a checkpoint whose sum
 *                  does not match, and rows whose p_star, or p for an
 *                  absolute list, is not pressures[K])
 * Nothing else is needed to resume: rows already finished are re-emitted
 * from the checkpoint, and u warm-starts the interrupted pressure.
 */
#ifndef RC_CHECKPOINT_H
#define RC_CHECKPOINT_H

#include <stdint.h>
#include "grid.h"
#include "rc_err.h"
#include "table_write.h"

typedef struct rc_checkpoint {
	/* identity of the problem */
	size_t nx, ny;
	double lx, ly;
	uint64_t input_sum;
	/* options that decide the results */
	char method[16];
	double tol, modulus, alpha;
	long max_iter;
	long stall;		/* --stall; -1: unrecorded (version < 6) */
	int fd;
	/* the scene: enum rc_boundary (-1: unrecorded, version 2), enum
	 * rc_kernel, enum rc_substrate; 0 where an effect is off */
	int boundary, kernel, substrate;
	double hardness, thickness, poisson, adhesion, range;
	int law;		/* enum rc_adhesion_law */
	int reduced;		/* 1: pressures are p*, 0: absolute p */
	double *pressures;
	size_t npressures;
	/* progress */
	size_t next;
	size_t unconverged;	/* finished rows that did not converge */
	int solving;		/* 1: u is a partial solve of pressures[next] */
	long iterations;
	/* finished rows, serialised (row.K values) */
	char *columns, *types;
	char **rows;
	size_t nrows;
} rc_checkpoint;

/* FNV-1a over nx, ny, lx, ly, every height's bit pattern (byte order
 * fixed, little-endian), the metadata keys and values, the units, the
 * periodic flag and the missing-point mask, so the same indenter gives the
 * same hash anywhere, and one whose rows would differ (other metadata
 * columns) does not. */
uint64_t rc_checkpoint_hash(const rc_grid *indenter);

/* checkpoint.sum of a checkpoint grid (version 5): FNV-1a over nx, ny,
 * lx, ly, the heights' bit patterns and the checkpoint.* metadata in order
 * but checkpoint.sum itself. */
uint64_t rc_checkpoint_sum(const rc_grid *checkpoint);

/* Fill identity from the indenter and copy the pressure list; rows empty;
 * the scene the half space, periodic, no effect; --stall the default. */
int rc_checkpoint_init(rc_checkpoint *c, const rc_grid *indenter,
    const double *pressures, size_t npressures, rc_err *err);
void rc_checkpoint_free(rc_checkpoint *c);

/* Append a finished row (the first fixes columns and types). */
int rc_checkpoint_add_row(rc_checkpoint *c, const rc_row *row, rc_err *err);
/* Rebuild finished row k into row (cleared first). */
int rc_checkpoint_row(const rc_checkpoint *c, size_t k, rc_row *row,
    rc_err *err);

/* Write atomically as .surf (whatever the name's extension) with u, an
 * nx*ny field. */
int rc_checkpoint_write(const rc_checkpoint *c, const double *u,
    const char *path, rc_err *err);
/* Read a checkpoint; *u receives its displacement grid (caller frees). */
int rc_checkpoint_read(rc_checkpoint *c, rc_grid **u, const char *path,
    rc_err *err);

/* One run per checkpoint: an exclusive flock(2) on ".NAME.lock" beside
 * path, held until rc_checkpoint_unlock (or the process ends; a lock file
 * left by a killed run is harmless and taken over).  Returns the lock's
 * descriptor, -2 when path names an existing device or FIFO (nothing to
 * lock), or -1 with err set when another process holds it.  *lock_path
 * receives the lock file's name (malloc'ed) for the unlock. */
int rc_checkpoint_lock(const char *path, char **lock_path, rc_err *err);
/* Remove the lock file, then release the lock; fd < 0 does nothing. */
void rc_checkpoint_unlock(int fd, char *lock_path);

/* The iteration count of a resumed solve: done (up to LONG_MAX, what a
 * checkpoint may hold) plus more spent since, saturating at LONG_MAX
 * rather than overflowing; both >= 0. */
long rc_checkpoint_iterations_add(long done, long more);

/* 0 if saved belongs to the same indenter and options as now (pressure
 * list, method, tol, E, alpha, fd, max_iter, the scene; the boundary kind
 * only where saved records it), else -1 naming the first difference. */
int rc_checkpoint_match(const rc_checkpoint *saved, const rc_checkpoint *now,
    rc_err *err);

#endif
