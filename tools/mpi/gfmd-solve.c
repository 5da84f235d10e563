/* gfmd-solve (MPI build) - gfmd-solve(1) on many ranks: the indenter is
 * read from a .surf file with MPI-IO, each rank solves its rows with the
 * library's FIRE-GFMD (lib/fire.c compiled with -DRC_MPI: FFTW-MPI
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
#include "mpi/decomp.h"
#include "mpi/dsolver.h"
#include "mpitool.h"
#include "solver.h"
#include "table.h"

enum {
	OPT_PRESSURE_ABS = OPT_TOOL_FIRST,
	OPT_METHOD,
	OPT_TOL,
	OPT_MAX_ITER,
	OPT_ALPHA,
	OPT_INIT,
	OPT_CONTACT,
	OPT_GAP,
	OPT_PRESSURE_FIELD,
	OPT_DISPLACEMENT,
	OPT_UNSUPPORTED
};

static void
usage(void)
{
	printf(
"usage: mpirun -np N gfmd-solve (-p P[,P...] | --pressure-abs P[,P...])\n"
"           [-E MODULUS] [--method fire] [--tol TOL] [--max-iter N]\n"
"           [--alpha A] [--init FILE.surf] [--contact FILE.surf]\n"
"           [--gap FILE.surf] [--pressure FILE.surf]\n"
"           [--displacement FILE.surf] [-o FILE] [--json] [-j N] [-q]\n"
"           FILE.surf\n"
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
	if (rc_grid_meta_setd(g, "p", p, &err) != 0 ||
	    rc_grid_meta_setd(g, "p_star", p_star, &err) != 0 ||
	    rc_grid_meta_setd(g, "E", modulus, &err) != 0 ||
	    rc_grid_meta_set(g, "method", "fire", &err) != 0 ||
	    rc_grid_history_add(g, t->cmdline, &err) != 0)
		tool_fail(t, "%s", err.msg);
	if (rc_mpi_surf_write(g, ny, local, path, &err) != 0)
		tool_fail(t, "%s: %s", path, err.msg);
	rc_grid_free(g);
}

int
main(int argc, char **argv)
{
	static const struct option longopts[] = {
		{ "pressure-abs", required_argument, NULL, OPT_PRESSURE_ABS },
		{ "method", required_argument, NULL, OPT_METHOD },
		{ "tol", required_argument, NULL, OPT_TOL },
		{ "max-iter", required_argument, NULL, OPT_MAX_ITER },
		{ "alpha", required_argument, NULL, OPT_ALPHA },
		{ "init", required_argument, NULL, OPT_INIT },
		{ "contact", required_argument, NULL, OPT_CONTACT },
		{ "gap", required_argument, NULL, OPT_GAP },
		{ "pressure", required_argument, NULL, OPT_PRESSURE_FIELD },
		{ "displacement", required_argument, NULL, OPT_DISPLACEMENT },
		{ "fd", no_argument, NULL, OPT_UNSUPPORTED },
		{ "checkpoint", required_argument, NULL, OPT_UNSUPPORTED },
		{ "checkpoint-every", required_argument, NULL, OPT_UNSUPPORTED },
		{ "resume", required_argument, NULL, OPT_UNSUPPORTED },
		{ "json", no_argument, NULL, OPT_JSON },
		{ "png", required_argument, NULL, OPT_PNG },
		{ "version", no_argument, NULL, OPT_VERSION },
		{ "help", no_argument, NULL, 'h' },
		{ NULL, 0, NULL, 0 }
	};
	static const char optstring[] = "p:E:o:j:qL:h";
	struct tool t;
	rc_solver_opts so;
	rc_solver *solver;
	rc_grid *h;
	rc_err err;
	rc_atomic out;
	rc_table_out table;
	rc_row row;
	double *reduced = NULL, *absolute = NULL, *height, gbar = 0, modulus = 1;
	double alpha = RC_YASTREBOV_ALPHA, last_p = 0, last_p_star = 0;
	size_t npressures, nreduced = 0, nabsolute = 0, nunconverged = 0, ny;
	size_t rows, j0, alloc;
	const char *init = NULL, *fields[4] = { NULL, NULL, NULL, NULL };
	static const char *field_opts[4] = { "--contact", "--gap", "--pressure",
	    "--displacement" };
	long n;
	int c, rank, status = 0;

	mpitool_init(&argc, &argv);
	rank = rc_mpi_rank();
	tool_init(&t, "gfmd-solve", argc, argv);
	rc_solver_defaults(&so);
	opterr = 0;
	while ((c = getopt_long(argc, argv, optstring, longopts, NULL)) != -1) {
		switch (c) {
		case 'p':
			free(reduced);
			tool_double_list(&t, "-p", optarg, &reduced, &nreduced);
			break;
		case OPT_PRESSURE_ABS:
			free(absolute);
			tool_double_list(&t, "--pressure-abs", optarg, &absolute, &nabsolute);
			break;
		case 'E':
			if (tool_double(&t, "-E", optarg, &modulus) == 0 && !(modulus > 0))
				tool_bad(&t, "-E %s: the contact modulus must be positive", optarg);
			break;
		case OPT_METHOD:
			if (strcmp(optarg, "fire") != 0)
				tool_bad(&t, "--method %s: the MPI build has FIRE only "
				    "(--method fire; use the serial gfmd-solve for cg)", optarg);
			break;
		case OPT_TOL:
			if (tool_double(&t, "--tol", optarg, &so.tol) == 0 &&
			    !(so.tol > 0 && so.tol < 1))
				tool_bad(&t, "--tol %s: want a tolerance in (0, 1)", optarg);
			break;
		case OPT_MAX_ITER:
			if (tool_long(&t, "--max-iter", optarg, &n) == 0) {
				if (n < 1)
					tool_bad(&t, "--max-iter %s: want at least 1", optarg);
				else
					so.max_iter = n;
			}
			break;
		case OPT_ALPHA:
			if (tool_double(&t, "--alpha", optarg, &alpha) == 0 &&
			    !(alpha >= 0 && alpha <= 1))
				tool_bad(&t, "--alpha %s: want a weight in [0, 1]", optarg);
			break;
		case OPT_INIT:
			init = optarg;
			break;
		case OPT_CONTACT:
		case OPT_GAP:
		case OPT_PRESSURE_FIELD:
		case OPT_DISPLACEMENT:
			fields[c - OPT_CONTACT] = optarg;
			break;
		case OPT_UNSUPPORTED:
			tool_bad(&t, "%s: not in the MPI build (use the serial gfmd-solve)",
			    argv[optind - 1]);
			break;
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case '?':
			if (optopt > 0 && optopt < 128 && strchr(optstring, optopt))
				tool_bad(&t, "-%c: missing argument", optopt);
			else if (optopt > 0 && optopt < 128)
				tool_bad(&t, "-%c: unknown option", optopt);
			else if (optopt != 0)
				tool_bad(&t, "%s: missing argument", argv[optind - 1]);
			else
				tool_bad(&t, "%s: unknown option", argv[optind - 1]);
			break;
		default:
			tool_common_option(&t, c, optarg);
		}
	}
	for (size_t k = 0; k < nreduced + nabsolute; k++)
		if (!((k < nreduced ? reduced[k] : absolute[k - nreduced]) > 0)) {
			tool_bad(&t, "-p, --pressure-abs: pressures must be positive");
			break;
		}
	if (nreduced && nabsolute)
		tool_bad(&t, "-p and --pressure-abs: give one of them, not both");
	else if (!nreduced && !nabsolute && t.nbad == 0)
		tool_bad(&t, "no pressure: give -p P[,P...] or --pressure-abs P[,P...]");
	if (t.png != NULL || t.have_l)
		tool_bad(&t, "--png, -L: not in the MPI build");
	if (argc - optind != 1)
		tool_bad(&t, "give one input FILE.surf (the MPI build reads no "
		    "standard input)");
	else
		mpitool_check_surf(&t, "input", argv[optind]);
	if (init != NULL)
		mpitool_check_surf(&t, "--init", init);
	for (int k = 0; k < 4; k++)
		if (fields[k] != NULL)
			mpitool_check_surf(&t, field_opts[k], fields[k]);
	tool_usage_check(&t);
	npressures = nreduced ? nreduced : nabsolute;
	mpitool_threads(&t);

	if ((h = rc_mpi_surf_read(argv[optind], &ny, &height, &err)) == NULL)
		tool_fail(&t, "%s: %s", argv[optind], err.msg);
	so.modulus = modulus;
	/* The serial policy (fft.h): big grids are worth FFTW_MEASURE over the
	 * hundreds of transform pairs of a solve. */
	so.measure = rc_fft_effort_auto(h->nx, ny, RC_FFT_MEASURE_PAIRS) ==
	    RC_FFT_MEASURE;
	if ((solver = rc_mpi_solver_new(height, h->nx, ny, h->lx, h->ly, &so,
	    &err)) == NULL)
		tool_fail(&t, "%s", err.msg);
	rc_mpi_rows(h->nx, ny, &rows, &j0, &alloc);
	gbar = rc_mpi_gbar(solver);
	if (nreduced && !(gbar > 0))
		tool_fail(&t, "%s: the indenter is flat (rms gradient 0), so the "
		    "reduced pressure p* = p/(E* gbar) is undefined; use --pressure-abs",
		    argv[optind]);
	if (init != NULL) {
		size_t init_ny;
		double *u;
		rc_grid *uh = rc_mpi_surf_read(init, &init_ny, &u, &err);

		if (uh == NULL)
			tool_fail(&t, "%s: %s", init, err.msg);
		if (uh->nx != h->nx || init_ny != ny)
			tool_fail(&t, "%s: %zux%zu grid, the indenter is %zux%zu", init,
			    uh->nx, init_ny, h->nx, ny);
		if (rc_solver_set_displacement(solver, u, &err) != 0)
			status = -1;
		{
			double bad = status != 0;

			rc_mpi_max(&bad, 1);
			if (bad)
				tool_fail(&t, "%s: an initial displacement is not finite",
				    init);
		}
		fftw_free(u);
		rc_grid_free(uh);
	}
	if (rank == 0 && rc_atomic_open(&out, t.out, &err) != 0)
		fail0(&t, &out, t.out, err.msg);
	if (rank == 0)
		rc_table_begin(&table, out.fp, t.json);
	rc_row_init(&row);
	for (size_t k = 0; k < npressures; k++) {
		rc_solve_result res;
		rc_contact_stats st;
		double p = nreduced ? reduced[k] * modulus * gbar : absolute[k];
		double p_star = nreduced ? reduced[k] :
		    gbar > 0 ? p / (modulus * gbar) : NAN, mean_gap, seconds;
		double t0 = MPI_Wtime();
		int r;

		r = rc_solver_solve(solver, p, &res, &err);
		if (r < 0)
			tool_fail(&t, "p = %g: %s", p, err.msg);
		/* The slowest rank's wall time is the run's. */
		seconds = MPI_Wtime() - t0;
		rc_mpi_max(&seconds, 1);
		if (rc_mpi_contact_analyse(solver, alpha, p, &gbar, &st, &err) != 0)
			tool_fail(&t, "p = %g: %s", p, err.msg);
		mean_gap = rc_solver_mean_gap(solver);
		rc_row_clear(&row);
		if (rc_row_num(&row, "p_star", p_star) ||
		    rc_row_num(&row, "p", p) ||
		    rc_row_num(&row, "a_r", st.a_r) ||
		    rc_row_int(&row, "n_c", (long long)st.n_c) ||
		    rc_row_int(&row, "n_cl", (long long)st.n_cl) ||
		    rc_row_int(&row, "n_tot", (long long)st.n_tot) ||
		    rc_row_num(&row, "a_yastrebov", st.a_yastrebov) ||
		    rc_row_num(&row, "gbar", gbar) ||
		    rc_row_num(&row, "gbar_c", st.gbar_c) ||
		    rc_row_num(&row, "gbar_c_prime", st.gbar_c_prime) ||
		    rc_row_num(&row, "kappa", st.kappa) ||
		    rc_row_num(&row, "kappa_c", st.kappa_c) ||
		    rc_row_num(&row, "mean_gap", mean_gap) ||
		    rc_row_num(&row, "elastic_energy",
		    rc_solver_elastic_energy(solver)) ||
		    rc_row_int(&row, "n_patches", (long long)st.n_patches) ||
		    rc_row_num(&row, "patch_size_char", st.patch_size_char) ||
		    rc_row_int(&row, "iterations", res.iterations) ||
		    rc_row_num(&row, "residual", res.residual) ||
		    rc_row_num(&row, "seconds", seconds) ||
		    rc_row_str(&row, "method", "fire") ||
		    rc_row_int(&row, "nx", (long long)h->nx) ||
		    rc_row_int(&row, "ny", (long long)ny) ||
		    rc_row_num(&row, "lx", h->lx) ||
		    rc_row_num(&row, "ly", h->ly) ||
		    rc_row_meta(&row, h))
			tool_fail(&t, "out of memory");
		if (rank == 0 && (rc_table_write(&table, &row, &err) != 0 ||
		    fflush(out.fp) != 0))
			fail0(&t, &out, t.out ? t.out : "standard output",
			    "write failed");
		if (!res.converged) {
			nunconverged++;
			tool_warn(&t, "p = %g: not converged after %ld iterations "
			    "(residual %.3g, tolerance %.3g); row written, going on",
			    p, res.iterations, res.residual, so.tol);
		}
		last_p = p;
		last_p_star = p_star;
	}
	rc_row_free(&row);
	if (rank == 0 && (rc_table_end(&table, &err) != 0 ||
	    rc_atomic_commit(&out, &err) != 0))
		fail0(&t, &out, t.out ? t.out : "standard output", err.msg);

	/* Fields of the last pressure, only those asked for. */
	if (fields[0] != NULL || fields[1] != NULL) {
		const double *u = rc_solver_displacement(solver);
		const unsigned char *mask = rc_solver_contact(solver);
		double *f = malloc((rows * h->nx + 1) * sizeof(double));

		if (f == NULL)
			tool_fail(&t, "out of memory");
		if (fields[0] != NULL) {
			for (size_t k = 0; k < rows * h->nx; k++)
				f[k] = mask[k] != 0;
			write_field(&t, h, ny, RC_KIND_MASK, last_p, last_p_star,
			    modulus, f, fields[0]);
		}
		if (fields[1] != NULL) {
			for (size_t k = 0; k < rows * h->nx; k++)
				f[k] = u[k] - height[k];
			write_field(&t, h, ny, RC_KIND_GAP, last_p, last_p_star,
			    modulus, f, fields[1]);
		}
		free(f);
	}
	if (fields[2] != NULL)
		write_field(&t, h, ny, RC_KIND_PRESSURE, last_p, last_p_star, modulus,
		    rc_solver_pressure(solver), fields[2]);
	if (fields[3] != NULL)
		write_field(&t, h, ny, RC_KIND_DISPLACEMENT, last_p, last_p_star,
		    modulus, rc_solver_displacement(solver), fields[3]);
	if (nunconverged) {
		tool_warn(&t, "%zu of %zu pressures did not converge", nunconverged,
		    npressures);
		status = 1;
	}
	rc_solver_free(solver);
	fftw_free(height);
	rc_grid_free(h);
	free(reduced);
	free(absolute);
	return tool_exit(&t, status);
}
