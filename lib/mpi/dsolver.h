/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dsolver.h - the contact solver on this rank's rows (make MPI=1).
 *
 * rc_mpi_solver_new is rc_solver_new for a distributed indenter: height
 * holds this rank's rows (rc_mpi_rows) of an nx x ny grid.  The solve and
 * the accessors are the serial library's (lib/solver/solver.c, solver_fire.c)
 * on the distributed operator of delastic.h, which completes their sums
 * over all ranks (fields are the local rows; elastic energy, mean gap
 * and approach are global).  FIRE only. */
#ifndef RC_MPI_DSOLVER_H
#define RC_MPI_DSOLVER_H

#include "solver.h"

rc_solver *rc_mpi_solver_new(const double *height, size_t nx, size_t ny,
    double lx, double ly, const rc_solver_opts *o, rc_err *err);

/* Contact statistics of the current solution, over the whole grid: every
 * field of rc_contact_stats as rc_contact_analyse gives them with
 * RC_CONTACT_ALL and spectral gradients (the patches from every rank's
 * rows, lib/mpi/dpatches.c); *gbar the spectral rms gradient of the whole
 * indenter.  Collective. */
struct rc_contact_stats;
int rc_mpi_contact_analyse(rc_solver *s, double alpha, double pressure,
    double *gbar, struct rc_contact_stats *st, rc_err *err);
/* The spectral rms gradient of the indenter alone.  Collective. */
double rc_mpi_gbar(rc_solver *s);

#endif
