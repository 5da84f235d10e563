/* SPDX-License-Identifier: GPL-3.0-or-later */
/* surfgen (MPI build) - a surface made by all ranks and written to a .surf
 * file with MPI-IO.  Self-affine: each rank fills its rows of the
 * half-complex spectrum (the modes are a function of the seed and the wave
 * vector, lib/synth.c), one Allreduce gives the normalisation and one
 * distributed c2r (FFTW-MPI) its rows of heights.  The other types are
 * pointwise: each rank computes its rows; a normalisation to an rms height
 * or gradient takes Allreduce'd sums (the gradient one distributed r2c).
 * The options are surfgen(1)'s. */
#include <complex.h>
#include <fftw3-mpi.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common.h"
#include "mpi/decomp.h"
#include "mpi/dspectral.h"
#include "mpitool.h"
#include "surfgen_opts.h"

static const struct option longopts[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	SURFGEN_LONGOPTS,
	{ NULL, 0, NULL, 0 }
};

static void
usage(void)
{
	printf(
"usage: mpirun -np N surfgen [-n NX[xNY]] [-L LX[xLY]] [-H H] [--lambda-r L]\n"
"           [--lambda-s L] [--rolloff] [--peklenik G] [--seed S]\n"
"           [--rms-gradient G | --rms-height S] [--gaussian-amplitudes]\n"
"           [--type selfaffine|harmonic|sine|eggbox|flat] [--exponent N]\n"
"           [--radius R] [--wavelength W] [--amplitude A] [-j N] [-q]\n"
"           -o FILE.surf\n"
"The MPI build of surfgen(1): the same surface as the serial tool up to\n"
"round-off, written with MPI-IO to a .surf file.  The options mean what\n"
"they mean in surfgen(1); -j N: threads per rank (default\n"
"OMP_NUM_THREADS, else 1).  Not in this build: --png, --json, --wisdom,\n"
"--fft-effort, standard output.\n");
}

/* A harmonic, sine, egg-box or flat surface: rows, then the normalisation
 * of lib/synth.c (rms about the mean, or spectral rms gradient). */
static int
pointwise(const struct tool *t, const rc_synth_params *p)
{
	size_t rows, j0, alloc, n;
	double *z, scale = 1, now = 0, sums[2] = { 0, 0 }, points;
	rc_grid *head;
	rc_err err;

	rc_mpi_rows(p->nx, p->ny, &rows, &j0, &alloc);
	n = rows * p->nx;
	points = (double)p->nx * (double)p->ny;
	if ((z = fftw_alloc_real(n + 1)) == NULL)
		tool_fail(t, "out of memory (asked for %zu bytes)", n * sizeof(double));
	if (rc_synth_pointwise_rows(p, z, j0, rows, &err) != 0)
		tool_fail(t, "%s", err.msg);
	if (p->rms_gradient > 0) {
		if (rc_mpi_rms_gradient(z, p->nx, p->ny, p->lx, p->ly, &now, &err) != 0)
			tool_fail(t, "%s", err.msg);
	} else if (p->rms_height > 0) {
		for (size_t k = 0; k < n; k++)
			sums[0] += z[k];
		rc_mpi_sum(sums, 1);
		sums[0] /= points;
		for (size_t k = 0; k < n; k++)
			sums[1] += (z[k] - sums[0]) * (z[k] - sums[0]);
		rc_mpi_sum(sums + 1, 1);
		now = sqrt(sums[1] / points);
	}
	if (p->rms_gradient > 0 || p->rms_height > 0) {
		if (!(now > 0))
			tool_fail(t, "the surface has zero rms %s; it cannot be normalised",
			    p->rms_gradient > 0 ? "gradient" : "height");
		scale = (p->rms_gradient > 0 ? p->rms_gradient : p->rms_height) / now;
		for (size_t k = 0; k < n; k++)
			z[k] *= scale;
	}
	if ((head = rc_grid_new(p->nx, 1, p->lx, p->ly, &err)) == NULL ||
	    rc_synth_meta(p, head, scale, &err) != 0 ||
	    rc_grid_history_add(head, t->cmdline, &err) != 0)
		tool_fail(t, "%s", err.msg);
	if (rc_mpi_surf_write(head, p->ny, z, t->out, &err) != 0)
		tool_fail(t, "%s", err.msg);
	rc_grid_free(head);
	fftw_free(z);
	return tool_exit(t, 0);
}

int
main(int argc, char **argv)
{
	struct tool t;
	struct surfgen_opts o;
	rc_synth_params p;
	rc_err err;
	rc_grid *head;
	fftw_complex *spec;
	fftw_plan plan;
	size_t rows, j0, alloc, nxc;
	double *sums, total = 0, target, scale, *real;
	int opt;

	mpitool_init(&argc, &argv);
	tool_init(&t, "surfgen", argc, argv);
	surfgen_opts_init(&o);
	opterr = 0;
	while ((opt = getopt_long(argc, argv, "hn:L:H:o:j:q", longopts, NULL)) != -1) {
		if (opt == 'h') {
			usage();
			return tool_exit(&t, 0);
		}
		if ((opt != 'L' && tool_common_option(&t, opt, optarg)) ||
		    surfgen_option(&t, &o, opt, optarg))
			continue;
		tool_bad_option(&t, "hn:L:H:o:j:q", longopts, argv);
	}
	if (optind < argc)
		tool_bad(&t, "%s: unexpected argument (surfgen reads no input)", argv[optind]);
	if (t.png != NULL || t.json)
		tool_bad(&t, "--png, --json: not in the MPI build");
	surfgen_opts_check(&t, &o);
	mpitool_check_surf(&t, "-o", t.out);
	tool_usage_check(&t);
	p = o.p;

	mpitool_threads(&t);
	if (p.type != RC_SURF_SELFAFFINE)
		return pointwise(&t, &p);
	nxc = p.nx / 2 + 1;
	rc_mpi_rows(p.nx, p.ny, &rows, &j0, &alloc);
	spec = fftw_alloc_complex(alloc);
	sums = calloc(rows + 1, sizeof(double));
	if (spec == NULL || sums == NULL)
		tool_fail(&t, "out of memory (asked for %zu bytes)",
		    alloc * sizeof(fftw_complex));
	real = (double *)spec;
	/* In place: rows of 2 nxc doubles; planned before filling. */
	plan = fftw_mpi_plan_dft_c2r_2d((ptrdiff_t)p.ny, (ptrdiff_t)p.nx, spec, real,
	    MPI_COMM_WORLD, FFTW_ESTIMATE);
	if (plan == NULL)
		tool_fail(&t, "FFTW-MPI could not plan a %zu x %zu transform", p.nx, p.ny);
	rc_synth_selfaffine_rows(&p, spec, j0, rows, sums);
	for (size_t j = 0; j < rows; j++)
		total += sums[j];
	rc_mpi_sum(&total, 1);
	if (!(total > 0))
		tool_fail(&t, "no grid mode lies in the band lambda_s = %g <= lambda < "
		    "lambda_r = %g; enlarge the cell or widen the band",
		    rc_synth_lambda_s(&p), rc_synth_lambda_r(&p));
	target = p.rms_height > 0 ? p.rms_height :
	    p.rms_gradient > 0 ? p.rms_gradient : 1.0;
	scale = target / sqrt(total);
	for (size_t k = 0; k < rows * nxc; k++)
		spec[k] *= scale;
	fftw_mpi_execute_dft_c2r(plan, spec, real);
	fftw_destroy_plan(plan);
	for (size_t j = 1; j < rows; j++)
		memmove(real + j * p.nx, real + j * 2 * nxc, p.nx * sizeof(double));
	if ((head = rc_grid_new(p.nx, 1, p.lx, p.ly, &err)) == NULL ||
	    rc_synth_meta(&p, head, 1, &err) != 0 ||
	    rc_grid_history_add(head, t.cmdline, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	if (rc_mpi_surf_write(head, p.ny, real, t.out, &err) != 0)
		tool_fail(&t, "%s", err.msg);
	rc_grid_free(head);
	fftw_free(spec);
	free(sums);
	return tool_exit(&t, 0);
}
