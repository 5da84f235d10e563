/* surfgen (MPI build) - a surface made by all ranks and written to a .surf
 * file with MPI-IO.  Self-affine: each rank fills its rows of the
 * half-complex spectrum (the modes are a function of the seed and the wave
 * vector, lib/synth.c), one Allreduce gives the normalisation and one
 * distributed c2r (FFTW-MPI) its rows of heights.  The other types are
 * pointwise: each rank computes its rows; a normalisation to an rms height
 * or gradient takes Allreduce'd sums (the gradient one distributed r2c).
 * The options are surfgen(1)'s. */
#include <complex.h>
#include <errno.h>
#include <fftw3-mpi.h>
#include <getopt.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common.h"
#include "mpi/decomp.h"
#include "mpi/dspectral.h"
#include "mpitool.h"
#include "synth.h"

enum {
	OPT_LAMBDA_R = OPT_TOOL_FIRST,
	OPT_LAMBDA_S,
	OPT_ROLLOFF,
	OPT_PEKLENIK,
	OPT_SEED,
	OPT_RMS_GRADIENT,
	OPT_RMS_HEIGHT,
	OPT_GAUSSIAN,
	OPT_TYPE,
	OPT_EXPONENT,
	OPT_RADIUS,
	OPT_WAVELENGTH,
	OPT_AMPLITUDE
};

static const struct option longopts[] = {
	{ "help", no_argument, NULL, 'h' },
	{ "version", no_argument, NULL, OPT_VERSION },
	{ "lambda-r", required_argument, NULL, OPT_LAMBDA_R },
	{ "lambda-s", required_argument, NULL, OPT_LAMBDA_S },
	{ "rolloff", no_argument, NULL, OPT_ROLLOFF },
	{ "peklenik", required_argument, NULL, OPT_PEKLENIK },
	{ "seed", required_argument, NULL, OPT_SEED },
	{ "rms-gradient", required_argument, NULL, OPT_RMS_GRADIENT },
	{ "rms-height", required_argument, NULL, OPT_RMS_HEIGHT },
	{ "gaussian-amplitudes", no_argument, NULL, OPT_GAUSSIAN },
	{ "type", required_argument, NULL, OPT_TYPE },
	{ "exponent", required_argument, NULL, OPT_EXPONENT },
	{ "radius", required_argument, NULL, OPT_RADIUS },
	{ "wavelength", required_argument, NULL, OPT_WAVELENGTH },
	{ "amplitude", required_argument, NULL, OPT_AMPLITUDE },
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

static void
positive(struct tool *t, const char *opt, const char *arg, double *v)
{
	double d;

	if (tool_double(t, opt, arg, &d) != 0)
		return;
	if (!(d > 0))
		tool_bad(t, "%s %s: must be positive", opt, arg);
	else
		*v = d;
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
	rc_synth_params p;
	rc_err err;
	rc_grid *head;
	fftw_complex *spec;
	fftw_plan plan;
	size_t rows, j0, alloc, nxc;
	double *sums, total = 0, target, scale, v, *real;
	unsigned long long seed;
	char *end;
	int opt, type, selfaffine_opt = 0, have_exp = 0, have_rad = 0;
	int have_wave = 0, have_amp = 0;

	mpitool_init(&argc, &argv);
	tool_init(&t, "surfgen", argc, argv);
	rc_synth_defaults(&p);
	opterr = 0;
	while ((opt = getopt_long(argc, argv, "hn:L:H:o:q", longopts, NULL)) != -1) {
		if (opt != 'L' && tool_common_option(&t, opt, optarg))
			continue;
		switch (opt) {
		case 'h':
			usage();
			return tool_exit(&t, 0);
		case 'n':
			tool_size_pair(&t, "-n", optarg, &p.nx, &p.ny);
			break;
		case 'L':
			tool_length_pair(&t, "-L", optarg, &p.lx, &p.ly);
			break;
		case 'H':
			selfaffine_opt = 1;
			if (tool_double(&t, "-H", optarg, &v) == 0) {
				if (!(v > 0 && v < 1))
					tool_bad(&t, "-H %s: the Hurst exponent must be in (0, 1)",
					    optarg);
				else
					p.hurst = v;
			}
			break;
		case OPT_LAMBDA_R:
			selfaffine_opt = 1;
			positive(&t, "--lambda-r", optarg, &p.lambda_r);
			break;
		case OPT_LAMBDA_S:
			selfaffine_opt = 1;
			positive(&t, "--lambda-s", optarg, &p.lambda_s);
			break;
		case OPT_ROLLOFF:
			selfaffine_opt = 1;
			p.rolloff = 1;
			break;
		case OPT_PEKLENIK:
			selfaffine_opt = 1;
			positive(&t, "--peklenik", optarg, &p.peklenik);
			break;
		case OPT_SEED:
			selfaffine_opt = 1;
			errno = 0;
			seed = strtoull(optarg, &end, 10);
			if (optarg[0] < '0' || optarg[0] > '9' || *end != '\0' ||
			    errno == ERANGE)
				tool_bad(&t, "--seed %s: want an integer 0 to 2^64-1", optarg);
			else
				p.seed = (uint64_t)seed;
			break;
		case OPT_RMS_GRADIENT:
			positive(&t, "--rms-gradient", optarg, &p.rms_gradient);
			break;
		case OPT_RMS_HEIGHT:
			positive(&t, "--rms-height", optarg, &p.rms_height);
			break;
		case OPT_GAUSSIAN:
			selfaffine_opt = 1;
			p.gaussian_amplitudes = 1;
			break;
		case OPT_TYPE:
			if ((type = rc_surface_type_parse(optarg)) < 0)
				tool_bad(&t, "--type %s: want selfaffine, harmonic, sine, "
				    "eggbox or flat", optarg);
			else
				p.type = (enum rc_surface_type)type;
			break;
		case OPT_EXPONENT:
			positive(&t, "--exponent", optarg, &p.exponent);
			have_exp = 1;
			break;
		case OPT_RADIUS:
			positive(&t, "--radius", optarg, &p.radius);
			have_rad = 1;
			break;
		case OPT_WAVELENGTH:
			positive(&t, "--wavelength", optarg, &p.wavelength);
			have_wave = 1;
			break;
		case OPT_AMPLITUDE:
			if (tool_double(&t, "--amplitude", optarg, &v) == 0)
				p.amplitude = v;
			have_amp = 1;
			break;
		default:
			tool_bad(&t, "%s: unknown option or missing value", argv[optind - 1]);
			break;
		}
	}
	if (optind < argc)
		tool_bad(&t, "%s: unexpected argument (surfgen reads no input)", argv[optind]);
	if (t.png != NULL || t.json)
		tool_bad(&t, "--png, --json: not in the MPI build");
	if (p.rms_gradient > 0 && p.rms_height > 0)
		tool_bad(&t, "--rms-gradient and --rms-height: give one, not both");
	if (p.type != RC_SURF_SELFAFFINE && selfaffine_opt)
		tool_bad(&t, "-H, --lambda-r, --lambda-s, --rolloff, --peklenik, "
		    "--seed, --gaussian-amplitudes: only for --type selfaffine, not %s",
		    rc_surface_type_name(p.type));
	if (p.type != RC_SURF_HARMONIC && (have_exp || have_rad))
		tool_bad(&t, "--exponent, --radius: only for --type harmonic");
	if (p.type != RC_SURF_SINE && p.type != RC_SURF_EGGBOX && (have_wave || have_amp))
		tool_bad(&t, "--wavelength, --amplitude: only for --type sine or eggbox");
	mpitool_check_surf(&t, "-o", t.out);
	if (!(p.rms_gradient > 0 && p.rms_height > 0) && rc_synth_check(&p, &err) != 0)
		tool_bad(&t, "%s", err.msg);
	tool_usage_check(&t);

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
