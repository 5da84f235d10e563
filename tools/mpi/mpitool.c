/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mpitool.c - start-up and checks shared by the MPI tools (mpitool.h). */
#include "mpitool.h"

#include <complex.h>
#include <fftw3-mpi.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void
finish(void)
{
	int done = 0;

	MPI_Finalized(&done);
	if (!done) {
		fflush(stdout);
		fftw_mpi_cleanup();
		MPI_Finalize();
	}
}

void
mpitool_init(int *argc, char ***argv)
{
	int rank;

	MPI_Init(argc, argv);
	/* FFTW's threads must be set up before its MPI layer. */
	fftw_init_threads();
	fftw_mpi_init();
	atexit(finish);
	MPI_Comm_rank(MPI_COMM_WORLD, &rank);
	if (rank != 0) {
		if (freopen("/dev/null", "w", stderr) == NULL)
			fclose(stderr);
		if (freopen("/dev/null", "w", stdout) == NULL)
			fclose(stdout);
	}
}

void
mpitool_threads(const struct tool *t)
{
	if (t->threads > 0)
		rc_fft_set_threads(t->threads);
	else
		rc_fft_set_threads(getenv("OMP_NUM_THREADS") != NULL ? 0 : 1);
}

void
mpitool_check_surf(struct tool *t, const char *opt, const char *path)
{
	size_t n = path != NULL ? strlen(path) : 0;

	if (path == NULL || n < 5 || strcmp(path + n - 5, ".surf") != 0)
		tool_bad(t, "%s %s: the MPI build writes .surf files only (MPI-IO "
		    "at the format's data offset)", opt, path ? path : "(standard output)");
}
