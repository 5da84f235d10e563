/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd-solve (MPI build) - gfmd-solve(1) on many ranks: the indenter is
 * read from a .surf file with MPI-IO, each rank solves its rows with the
 * library's FIRE-GFMD (lib/solver/solver_fire.c on the distributed operator of
 * lib/mpi/delastic.c: FFTW-MPI transforms, Allreduce'd sums), rank 0
 * writes the table (the serial tool's rows and steps, tools/gfmd_row.c),
 * and the fields go to .surf files with MPI-IO.  Options not listed in
 * usage() are the serial tool's that this build does not have; they are
 * refused. */
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

/* Everything one run holds, so that main reads as the run's steps (the
 * serial tool's struct run without what this build does not have). */
struct run {
	struct tool t;
	struct gfmd_opts o;
	const char *input;
	int rank;
	rc_grid *h;			/* the indenter's header (nx x 1) */
	size_t ny;			/* its rows */
	double *height;			/* this rank's rows of it */
	double gbar;			/* its rms gradient */
	rc_solver *solver;
	double plan_seconds;
	size_t npressures, nunconverged;
	double last_p, last_p_star;
	rc_atomic out;			/* rank 0 */
	rc_table_out table;		/* rank 0 */
	rc_row row;
};

/* Options into r->o, checked together, what this build does not have
 * refused; 1 after --help. */
static int
parse_options(struct run *r, int argc, char **argv)
{
	static const struct option longopts[] = {
		GFMD_LONGOPTS,
		{ NULL, 0, NULL, 0 }
	};
	struct tool *t = &r->t;
	struct gfmd_opts *o = &r->o;
	int c;

	tool_init(t, "gfmd-solve", argc, argv);
	t->pretty_on_terminal = 0;
	gfmd_opts_init(o);
	opterr = 0;
	while ((c = getopt_long(argc, argv, GFMD_OPTSTRING, longopts, NULL)) != -1) {
		if (c == 'h') {
			usage();
			return 1;
		}
		gfmd_option(t, o, c, optarg, argv);
	}
	gfmd_opts_check(t, o, argc, argv);
	/* What this build does not have is refused, never ignored. */
	if (o->so.method != RC_METHOD_FIRE)
		tool_bad(t, "--method %s: the MPI build has FIRE only (--method "
		    "fire; use the serial gfmd-solve for cg)",
		    rc_method_name(o->so.method));
	if (o->given_layer)
		tool_bad(t, "--thickness: not in the MPI build (an elastic "
		    "layer is solved by the serial gfmd-solve)");
	if (o->so.kernel != RC_KERNEL_CONTINUUM)
		tool_bad(t, "--kernel %s: not in the MPI build (the pixel "
		    "kernel is solved by the serial gfmd-solve)",
		    rc_kernel_name(o->so.kernel));
	if (o->given_hardness)
		tool_bad(t, "--hardness: not in the MPI build (perfect "
		    "plasticity is solved by the serial gfmd-solve)");
	if (o->given_adhesion)
		tool_bad(t, "--adhesion: not in the MPI build (adhesion is "
		    "solved by the serial gfmd-solve)");
	if (o->boundary == RC_BOUNDARY_FREE || o->napproach)
		tool_bad(t, "--boundary free, --approach: not in the MPI build "
		    "(periodic boundaries under load control only; use the serial "
		    "gfmd-solve)");
	if (o->fd || o->ck_path != NULL || o->ck_every > 0 ||
	    o->resume_path != NULL || t->png != NULL || t->have_l)
		tool_bad(t, "--fd, --checkpoint, --checkpoint-every, --resume, "
		    "--png, -L: not in the MPI build (use the serial gfmd-solve)");
	if (argc - optind != 1)
		tool_bad(t, "give one input FILE.surf (the MPI build reads no "
		    "standard input)");
	else
		mpitool_check_surf(t, "input", argv[optind]);
	if (o->init != NULL)
		mpitool_check_surf(t, "--init", o->init);
	for (int k = 0; k < GFMD_NFIELDS; k++)
		if (o->field[k] != NULL)
			mpitool_check_surf(t, gfmd_field_option[k], o->field[k]);
	tool_usage_check(t);
	r->input = argv[optind];
	r->npressures = o->nreduced ? o->nreduced : o->nabsolute;
	return 0;
}

/* The indenter's rows read, the solver planned and timed (the slowest
 * rank's), the rms gradient gbar (the unit of p*) checked. */
static void
solver_setup(struct run *r)
{
	struct gfmd_opts *o = &r->o;
	rc_err err;

	if ((r->h = rc_mpi_surf_read(r->input, &r->ny, &r->height, &err)) == NULL)
		tool_fail_at(&r->t, r->input, err.msg);
	if (!r->h->periodic && o->boundary != RC_BOUNDARY_PERIODIC)
		tool_fail(&r->t, "%s: a finite patch (not periodic) needs free "
		    "boundaries, which the MPI build does not have (use the serial "
		    "gfmd-solve, or --boundary periodic to treat it as one period)",
		    r->input);
	o->so.modulus = o->modulus;
	/* The serial policy (fft.h): big grids are worth FFTW_MEASURE over the
	 * hundreds of transform pairs of a solve. */
	o->so.fft_effort = rc_fft_effort_auto(r->h->nx, r->ny,
	    RC_FFT_MEASURE_PAIRS) == RC_FFT_MEASURE ? RC_FFT_MEASURE :
	    RC_FFT_ESTIMATE;
	r->plan_seconds = MPI_Wtime();
	if ((r->solver = rc_mpi_solver_new(r->height, r->h->nx, r->ny,
	    r->h->lx, r->h->ly, &o->so, &err)) == NULL)
		tool_fail(&r->t, "%s", err.msg);
	r->plan_seconds = MPI_Wtime() - r->plan_seconds;
	rc_mpi_max(&r->plan_seconds, 1);
	r->gbar = rc_mpi_gbar(r->solver);
	gfmd_check_scale(&r->t, r->input, NAN, r->gbar);
	if (o->nreduced && !(r->gbar > 0))
		tool_fail(&r->t, "%s: the indenter is flat (rms gradient 0), so the "
		    "reduced pressure p* = p/(E* gbar) is undefined; use --pressure-abs",
		    r->input);
}

/* --init: start from this elastic surface height (every rank its rows). */
static void
initial_displacement(struct run *r)
{
	const char *path = r->o.init;
	size_t init_ny;
	double *u, bad;
	rc_err err;
	rc_grid *uh;

	if (path == NULL)
		return;
	if ((uh = rc_mpi_surf_read(path, &init_ny, &u, &err)) == NULL)
		tool_fail_at(&r->t, path, err.msg);
	if (uh->nx != r->h->nx || init_ny != r->ny)
		tool_fail(&r->t, "%s: %zux%zu grid, the indenter is %zux%zu", path,
		    uh->nx, init_ny, r->h->nx, r->ny);
	bad = rc_solver_set_displacement(r->solver, u, &err) != 0;
	rc_mpi_max(&bad, 1);
	if (bad)
		tool_fail(&r->t, "%s: an initial displacement is not finite", path);
	fftw_free(u);
	rc_grid_free(uh);
}

/* Solve pressure k and write its row (rank 0). */
static void
solve_pressure(struct run *r, size_t k)
{
	struct gfmd_opts *o = &r->o;
	rc_solve_result res;
	rc_contact_stats st;
	double p, p_star, seconds, t0 = MPI_Wtime();
	rc_err err;
	int w;

	gfmd_pressure(o, k, r->gbar, &p, &p_star);
	if (rc_solver_solve(r->solver, p, &res, &err) < 0)
		tool_fail(&r->t, "p = %g: %s", p, err.msg);
	/* The slowest rank's wall time is the run's. */
	seconds = MPI_Wtime() - t0;
	rc_mpi_max(&seconds, 1);
	if (rc_mpi_contact_analyse(r->solver, o->alpha, p, &r->gbar, &st,
	    &err) != 0)
		tool_fail(&r->t, "p = %g: %s", p, err.msg);
	{
		struct gfmd_row in = { .p_star = p_star, .p = p, .gbar = r->gbar,
		    .stats = &st, .mean_gap = rc_solver_mean_gap(r->solver),
		    .a_subpixel = NAN,
		    .elastic_energy = rc_solver_elastic_energy(r->solver),
		    .iterations = res.iterations, .residual = res.residual,
		    .tol = o->so.tol,
		    .seconds = seconds, .plan_seconds = r->plan_seconds,
		    .method = "fire", .boundary = "periodic",
		    .approach = rc_solver_approach(r->solver),
		    .hardness = 0, .a_plastic = 0,
		    .stalled = res.stalled ? o->so.stall_window : 0,
		    .indenter = r->h, .nx = r->h->nx, .ny = r->ny };

		w = gfmd_emit_row(&r->t, &in, res.converged, &r->row, &r->table,
		    r->rank == 0 ? r->out.fp : NULL, &r->nunconverged, &err);
	}
	if (w == GFMD_ROW_NOMEM)
		tool_fail(&r->t, "out of memory");
	if (w != 0)
		fail0(&r->t, &r->out, r->t.out ? r->t.out : "standard output",
		    "write failed");
	r->last_p = p;
	r->last_p_star = p_star;
}

/* Fields of the last pressure, only those asked for. */
static void
write_fields(struct run *r)
{
	const struct gfmd_opts *o = &r->o;
	const rc_grid *h = r->h;
	rc_solver *solver = r->solver;
	size_t rows, j0, alloc;

	rc_mpi_rows(h->nx, r->ny, &rows, &j0, &alloc);
	if (o->field[GFMD_CONTACT] != NULL || o->field[GFMD_GAP] != NULL) {
		const double *u = rc_solver_displacement(solver);
		const unsigned char *mask = rc_solver_contact(solver);
		double *f = malloc((rows * h->nx + 1) * sizeof(double));

		if (f == NULL)
			tool_fail(&r->t, "out of memory");
		if (o->field[GFMD_CONTACT] != NULL) {
			for (size_t k = 0; k < rows * h->nx; k++)
				f[k] = mask[k] != 0;
			write_field(&r->t, h, r->ny, RC_KIND_MASK, r->last_p,
			    r->last_p_star, o->modulus, f, o->field[GFMD_CONTACT]);
		}
		if (o->field[GFMD_GAP] != NULL) {
			for (size_t k = 0; k < rows * h->nx; k++)
				f[k] = u[k] - r->height[k];
			write_field(&r->t, h, r->ny, RC_KIND_GAP, r->last_p,
			    r->last_p_star, o->modulus, f, o->field[GFMD_GAP]);
		}
		free(f);
	}
	if (o->field[GFMD_PRESSURE] != NULL)
		write_field(&r->t, h, r->ny, RC_KIND_PRESSURE, r->last_p,
		    r->last_p_star, o->modulus, rc_solver_pressure(solver),
		    o->field[GFMD_PRESSURE]);
	if (o->field[GFMD_DISPLACEMENT] != NULL)
		write_field(&r->t, h, r->ny, RC_KIND_DISPLACEMENT, r->last_p,
		    r->last_p_star, o->modulus, rc_solver_displacement(solver),
		    o->field[GFMD_DISPLACEMENT]);
}

/* The exit status (1 if a pressure did not converge); everything freed. */
static int
finish(struct run *r)
{
	int status = 0;

	if (r->nunconverged) {
		tool_warn(&r->t, "%zu of %zu pressures did not converge",
		    r->nunconverged, r->npressures);
		status = 1;
	}
	rc_solver_free(r->solver);
	fftw_free(r->height);
	rc_grid_free(r->h);
	gfmd_opts_free(&r->o);
	return tool_exit(&r->t, status);
}

int
main(int argc, char **argv)
{
	struct run r;
	rc_err err;

	memset(&r, 0, sizeof(r));
	mpitool_init(&argc, &argv);
	r.rank = rc_mpi_rank();
	if (parse_options(&r, argc, argv))
		return tool_exit(&r.t, 0);
	mpitool_threads(&r.t);
	solver_setup(&r);
	initial_displacement(&r);
	if (r.rank == 0 && rc_atomic_open(&r.out, r.t.out, &err) != 0)
		fail0(&r.t, &r.out, r.t.out, err.msg);
	if (r.rank == 0)
		tool_table_begin(&r.t, &r.table, r.out.fp);
	rc_row_init(&r.row);
	for (size_t k = 0; k < r.npressures; k++)
		solve_pressure(&r, k);
	rc_row_free(&r.row);
	if (r.rank == 0 && (rc_table_end(&r.table, &err) != 0 ||
	    rc_atomic_commit(&r.out, &err) != 0))
		fail0(&r.t, &r.out, r.t.out ? r.t.out : "standard output", err.msg);
	write_fields(&r);
	return finish(&r);
}
