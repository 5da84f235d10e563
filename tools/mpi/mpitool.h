/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mpitool.h - what the MPI tools (make MPI=1) share: start-up, so that
 * every rank runs the same tools/common.h code but only rank 0 speaks, and
 * the check that a field path is .surf (MPI-IO writes only that format). */
#ifndef RC_MPITOOL_H
#define RC_MPITOOL_H

#include "common.h"

/* MPI_Init, fftw_mpi_init, MPI_Finalize at exit; ranks other than 0 get
 * stderr on /dev/null (every message is agreed on all ranks, so rank 0's
 * copy is the one shown). */
void mpitool_init(int *argc, char ***argv);
/* Threads per rank: -j N, else OMP_NUM_THREADS, else 1 (ranks usually
 * fill the cores already). */
void mpitool_threads(const struct tool *t);
/* tool_bad unless path ends in .surf. */
void mpitool_check_surf(struct tool *t, const char *opt, const char *path);

#endif
