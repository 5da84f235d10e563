/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd-solve (MPI build) - gfmd-solve(1) on many ranks: the indenter is
 * read from a .surf file with MPI-IO, each rank solves its rows with the
 * library's FIRE-GFMD (lib/solver_fire.c compiled with -DRC_MPI: FFTW-MPI
 * transforms, Allreduce'd sums), rank 0 writes the table, and the fields
 * go to .surf files with MPI-IO.  Options not listed in usage() are the
 * serial tool's that this build does not have; they are refused. */
#include <getopt.h>
#include <math.h>
#include <mpi.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic.h"
#include "common.h"
#include "contact.h"
#include "gfmd_opts.h"
#include "gfmd_row.h"
#include "mpi/decomp.h"
#include "mpi/dsolver.h"
#include "mpitool.h"
#include "solver.h"
#include "table_write.h"

static void
usage(void)
{
	printf(
"usage: mpirun -np N gfmd-solve (-p P[,P...] | --pressure-abs P[,P...])\n"
"           [-E MODULUS] [--method fire] [--tol TOL] [--max-iter N]\n"
"           [--alpha A] [--init FILE.surf] [--contact FILE.surf]\n"
"           [--gap FILE.surf] [--pressure FILE.surf]\n"
"           [--displacement FILE.surf] [-o FILE] [--json] [--pretty]\n"
"           [-j N] [-q] FILE.surf\n"
"The MPI build of gfmd-solve(1): the same rows, solved on all ranks with\n"
"FIRE-GFMD; input and fields are .surf files read and written with MPI-IO.\n"
"Not in this build: --method cg, --fd, --png, --checkpoint,\n"
"--checkpoint-every, --resume, -L, standard input.\n"
"  -j N                 threads per rank (default OMP_NUM_THREADS, else 1)\n");
}

/* A failure seen by rank 0 alone (the table): end every rank. */
static void
fail0(const struct tool *t, rc_atomic *out, const char *what, const char *why)
{
	rc_atomic_abort(out);
	tool_warn(t, "%s: %s", what, why);
	MPI_Abort(MPI_COMM_WORLD, 1);
	exit(1);
}

/* Write one field of the last pressure (rows local) to path. */
static void
write_field(const struct tool *t, const rc_grid *h, size_t ny,
    enum rc_kind kind, double p, double p_star, double modulus,
    const double *local, const char *path)
{
	rc_err err;
	rc_grid *g = rc_grid_clone(h, 0, &err);

	if (g == NULL)
		tool_fail(t, "%s", err.msg);
	g->kind = kind;
	g->periodic = 1;	/* as the solve (periodic only), like the serial tool */
	if (rc_grid_meta_setd(g, "p", p, &err) != 0 ||
	    rc_grid_meta_setd(g, "p_star", p_star, &err) != 0 ||
	    rc_grid_meta_setd(g, "E", modulus, &err) != 0 ||
	    rc_grid_meta_set(g, "method", "fire", &err) != 0 ||
	    rc_grid_history_add(g, t->cmdline, &err) != 0)
		tool_fail(t, "%s", err.msg);
	if (rc_mpi_surf_write(g, ny, local, path, &err) != 0)
		tool_fail_at(t, path, err.msg);
	rc_grid_free(g);
}

int
main(int argc, char **argv)
{
	static const struct option longopts[] = {
		GFMD_LONGOPTS,
		{ NULL, 0, NULL, 0 }
	};
	struct tool t;
	struct gfmd_opts o;
	rc_solver *solver;
	rc_grid *h;
	rc_err err;
	rc_atomic out;
	rc_table_out table;
	rc_row row;
	double *height, gbar = 0, last_p = 0, last_p_star = 0, plan_seconds;
	size_t npressures, nunconverged = 0, ny;
	size_t rows, j0, alloc;
	int c, rank, status = 0;

	mpitool_init(&argc, &argv);
	rank = rc_mpi_rank();
	tool_init(&t, "gfmd-solve", argc, argv);
	t.pretty_on_terminal = 0;
	gfmd_opts_init(&o);
	opterr = 0;
	while ((c = getopt_long(argc, argv, GFMD_OPTSTRING, longopts, NULL)) != -1) {
		if (c == 'h') {
			usage();
			return tool_exit(&t, 0);
		}
		gfmd_option(&t, &o, c, optarg, argv);
	}
	gfmd_opts_check(&t, &o, argc, argv);
	/* What this build does not have is refused, never ignored. */
	if (o.so.method != RC_METHOD_FIRE)
		tool_bad(&t, "--method %s: the MPI build has FIRE only (--method "
		    "fire; use the serial gfmd-solve for cg)",
		    rc_method_name(o.so.method));
	if (o.given_layer)
		tool_bad(&t, "--thickness: not in the MPI build (an elastic "
		    "layer is solved by the serial gfmd-solve)");
	if (o.so.kernel != RC_KERNEL_CONTINUUM)
		tool_bad(&t, "--kernel %s: not in the MPI build (the pixel "
		    "kernel is solved by the serial gfmd-solve)",
		    rc_kernel_name(o.so.kernel));
	if (o.given_hardness)
		tool_bad(&t, "--hardness: not in the MPI build (perfect "
		    "plasticity needs the serial gfmd-solve with --method cg)");
	if (o.given_adhesion)
		tool_bad(&t, "--adhesion: not in the MPI build (adhesion is "
		    "solved by the serial gfmd-solve)");
	if (o.boundary == RC_BOUNDARY_FREE || o.napproach)
		tool_bad(&t, "--boundary free, --approach: not in the MPI build "
		    "(periodic boundaries under load control only; use the serial "
		    "gfmd-solve)");
	if (o.fd || o.ck_path != NULL || o.ck_every > 0 || o.resume_path != NULL ||
	    t.png != NULL || t.have_l)
		tool_bad(&t, "--fd, --checkpoint, --checkpoint-every, --resume, "
		    "--png, -L: not in the MPI build (use the serial gfmd-solve)");
	if (argc - optind != 1)
		tool_bad(&t, "give one input FILE.surf (the MPI build reads no "
		    "standard input)");
	else
		mpitool_check_surf(&t, "input", argv[optind]);
	if (o.init != NULL)
		mpitool_check_surf(&t, "--init", o.init);
	for (int k = 0; k < GFMD_NFIELDS; k++)
		if (o.field[k] != NULL)
			mpitool_check_surf(&t, gfmd_field_option[k], o.field[k]);
	tool_usage_check(&t);
	npressures = o.nreduced ? o.nreduced : o.nabsolute;
	mpitool_threads(&t);

	if ((h = rc_mpi_surf_read(argv[optind], &ny, &height, &err)) == NULL)
		tool_fail_at(&t, argv[optind], err.msg);
	if (!h->periodic && o.boundary != RC_BOUNDARY_PERIODIC)
		tool_fail(&t, "%s: a finite patch (not periodic) needs free "
		    "boundaries, which the MPI build does not have (use the serial "
		    "gfmd-solve, or --boundary periodic to treat it as one period)",
		    argv[optind]);
	o.so.modulus = o.modulus;
	/* The serial policy (fft.h): big grids are worth FFTW_MEASURE over the
	 * hundreds of transform pairs of a solve. */
	o.so.fft_effort = rc_fft_effort_auto(h->nx, ny, RC_FFT_MEASURE_PAIRS) ==
	    RC_FFT_MEASURE ? RC_FFT_MEASURE : RC_FFT_ESTIMATE;
	plan_seconds = MPI_Wtime();
	if ((solver = rc_mpi_solver_new(height, h->nx, ny, h->lx, h->ly, &o.so,
	    &err)) == NULL)
		tool_fail(&t, "%s", err.msg);
	plan_seconds = MPI_Wtime() - plan_seconds;
	rc_mpi_max(&plan_seconds, 1);
	rc_mpi_rows(h->nx, ny, &rows, &j0, &alloc);
	gbar = rc_mpi_gbar(solver);
	gfmd_check_scale(&t, argv[optind], NAN, gbar);
	if (o.nreduced && !(gbar > 0))
		tool_fail(&t, "%s: the indenter is flat (rms gradient 0), so the "
		    "reduced pressure p* = p/(E* gbar) is undefined; use --pressure-abs",
		    argv[optind]);
	if (o.init != NULL) {
		size_t init_ny;
		double *u;
		rc_grid *uh = rc_mpi_surf_read(o.init, &init_ny, &u, &err);

		if (uh == NULL)
			tool_fail_at(&t, o.init, err.msg);
		if (uh->nx != h->nx || init_ny != ny)
			tool_fail(&t, "%s: %zux%zu grid, the indenter is %zux%zu", o.init,
			    uh->nx, init_ny, h->nx, ny);
		if (rc_solver_set_displacement(solver, u, &err) != 0)
			status = -1;
		{
			double bad = status != 0;

			rc_mpi_max(&bad, 1);
			if (bad)
				tool_fail(&t, "%s: an initial displacement is not finite",
				    o.init);
		}
		fftw_free(u);
		rc_grid_free(uh);
	}
	if (rank == 0 && rc_atomic_open(&out, t.out, &err) != 0)
		fail0(&t, &out, t.out, err.msg);
	if (rank == 0)
		tool_table_begin(&t, &table, out.fp);
	rc_row_init(&row);
	for (size_t k = 0; k < npressures; k++) {
		rc_solve_result res;
		rc_contact_stats st;
		double p = o.nreduced ? o.reduced[k] * o.modulus * gbar : o.absolute[k];
		double p_star = o.nreduced ? o.reduced[k] :
		    gbar > 0 ? p / (o.modulus * gbar) : NAN, mean_gap, seconds;
		double t0 = MPI_Wtime();
		int r;

		r = rc_solver_solve(solver, p, &res, &err);
		if (r < 0)
			tool_fail(&t, "p = %g: %s", p, err.msg);
		/* The slowest rank's wall time is the run's. */
		seconds = MPI_Wtime() - t0;
		rc_mpi_max(&seconds, 1);
		if (rc_mpi_contact_analyse(solver, o.alpha, p, &gbar, &st, &err) != 0)
			tool_fail(&t, "p = %g: %s", p, err.msg);
		mean_gap = rc_solver_mean_gap(solver);
		{
			struct gfmd_row in = { .p_star = p_star, .p = p, .gbar = gbar,
			    .stats = &st, .mean_gap = mean_gap, .a_subpixel = NAN,
			    .elastic_energy = rc_solver_elastic_energy(solver),
			    .iterations = res.iterations, .residual = res.residual,
			    .tol = o.so.tol,
			    .seconds = seconds, .plan_seconds = plan_seconds,
			    .method = "fire", .boundary = "periodic",
			    .approach = rc_solver_approach(solver),
			    .hardness = 0, .a_plastic = 0,
			    .indenter = h, .nx = h->nx, .ny = ny };

			const char *why = gfmd_kappa_c_why(&in);

			if (why != NULL && rank == 0)
				tool_warn(&t, "p = %g: kappa_c written as nan: %s", p,
				    why);
			if (gfmd_result_row(&row, &in) != 0)
				tool_fail(&t, "out of memory");
		}
		if (rank == 0 && (rc_table_write(&table, &row, &err) != 0 ||
		    fflush(out.fp) != 0))
			fail0(&t, &out, t.out ? t.out : "standard output",
			    "write failed");
		if (!res.converged) {
			nunconverged++;
			tool_warn(&t, "p = %g: not converged after %ld iterations "
			    "(residual %.3g, tolerance %.3g); row written, going on",
			    p, res.iterations, res.residual, o.so.tol);
		}
		last_p = p;
		last_p_star = p_star;
	}
	rc_row_free(&row);
	if (rank == 0 && (rc_table_end(&table, &err) != 0 ||
	    rc_atomic_commit(&out, &err) != 0))
		fail0(&t, &out, t.out ? t.out : "standard output", err.msg);

	/* Fields of the last pressure, only those asked for. */
	if (o.field[GFMD_CONTACT] != NULL || o.field[GFMD_GAP] != NULL) {
		const double *u = rc_solver_displacement(solver);
		const unsigned char *mask = rc_solver_contact(solver);
		double *f = malloc((rows * h->nx + 1) * sizeof(double));

		if (f == NULL)
			tool_fail(&t, "out of memory");
		if (o.field[GFMD_CONTACT] != NULL) {
			for (size_t k = 0; k < rows * h->nx; k++)
				f[k] = mask[k] != 0;
			write_field(&t, h, ny, RC_KIND_MASK, last_p, last_p_star,
			    o.modulus, f, o.field[GFMD_CONTACT]);
		}
		if (o.field[GFMD_GAP] != NULL) {
			for (size_t k = 0; k < rows * h->nx; k++)
				f[k] = u[k] - height[k];
			write_field(&t, h, ny, RC_KIND_GAP, last_p, last_p_star,
			    o.modulus, f, o.field[GFMD_GAP]);
		}
		free(f);
	}
	if (o.field[GFMD_PRESSURE] != NULL)
		write_field(&t, h, ny, RC_KIND_PRESSURE, last_p, last_p_star, o.modulus,
		    rc_solver_pressure(solver), o.field[GFMD_PRESSURE]);
	if (o.field[GFMD_DISPLACEMENT] != NULL)
		write_field(&t, h, ny, RC_KIND_DISPLACEMENT, last_p, last_p_star,
		    o.modulus, rc_solver_displacement(solver), o.field[GFMD_DISPLACEMENT]);
	if (nunconverged) {
		tool_warn(&t, "%zu of %zu pressures did not converge", nunconverged,
		    npressures);
		status = 1;
	}
	rc_solver_free(solver);
	fftw_free(height);
	rc_grid_free(h);
	gfmd_opts_free(&o);
	return tool_exit(&t, status);
}
