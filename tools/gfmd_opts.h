/* SPDX-License-Identifier: GPL-3.0-or-later */
/* gfmd_opts.h - gfmd-solve's options, shared by the serial tool and its MPI
 * build: one table, one parser, one set of checks, so that a command line
 * means the same in both (the MPI build then refuses what it lacks). */
#ifndef RC_GFMD_OPTS_H
#define RC_GFMD_OPTS_H

#include <getopt.h>

#include "common.h"
#include "solver.h"

enum {
	OPT_PRESSURE_ABS = OPT_TOOL_FIRST,
	OPT_METHOD,
	OPT_TOL,
	OPT_MAX_ITER,
	OPT_ALPHA,
	OPT_INIT,
	OPT_CONTACT,		/* the four fields, in gfmd_field order */
	OPT_GAP,
	OPT_PRESSURE_FIELD,
	OPT_DISPLACEMENT,
	OPT_FD,
	OPT_CHECKPOINT,
	OPT_CHECKPOINT_EVERY,
	OPT_RESUME,
	OPT_BOUNDARY,
	OPT_APPROACH,
	OPT_HARDNESS,
	OPT_THICKNESS,
	OPT_SUBSTRATE,
	OPT_POISSON,
	OPT_KERNEL,
	OPT_ADHESION,
	OPT_RANGE,
	OPT_LAW,
	OPT_STALL
};

/* The least --checkpoint-every, in minutes (0.3 s). */
#define GFMD_CHECKPOINT_EVERY_MIN 0.005

#define GFMD_OPTSTRING "p:E:o:j:qL:h"
#define GFMD_LONGOPTS \
	{ "pressure-abs", required_argument, NULL, OPT_PRESSURE_ABS }, \
	{ "method", required_argument, NULL, OPT_METHOD }, \
	{ "tol", required_argument, NULL, OPT_TOL }, \
	{ "max-iter", required_argument, NULL, OPT_MAX_ITER }, \
	{ "stall", required_argument, NULL, OPT_STALL }, \
	{ "alpha", required_argument, NULL, OPT_ALPHA }, \
	{ "init", required_argument, NULL, OPT_INIT }, \
	{ "contact", required_argument, NULL, OPT_CONTACT }, \
	{ "gap", required_argument, NULL, OPT_GAP }, \
	{ "pressure", required_argument, NULL, OPT_PRESSURE_FIELD }, \
	{ "displacement", required_argument, NULL, OPT_DISPLACEMENT }, \
	{ "fd", no_argument, NULL, OPT_FD }, \
	{ "checkpoint", required_argument, NULL, OPT_CHECKPOINT }, \
	{ "checkpoint-every", required_argument, NULL, OPT_CHECKPOINT_EVERY }, \
	{ "resume", required_argument, NULL, OPT_RESUME }, \
	{ "boundary", required_argument, NULL, OPT_BOUNDARY }, \
	{ "approach", required_argument, NULL, OPT_APPROACH }, \
	{ "hardness", required_argument, NULL, OPT_HARDNESS }, \
	{ "thickness", required_argument, NULL, OPT_THICKNESS }, \
	{ "substrate", required_argument, NULL, OPT_SUBSTRATE }, \
	{ "poisson", required_argument, NULL, OPT_POISSON }, \
	{ "kernel", required_argument, NULL, OPT_KERNEL }, \
	{ "adhesion", required_argument, NULL, OPT_ADHESION }, \
	{ "range", required_argument, NULL, OPT_RANGE }, \
	{ "law", required_argument, NULL, OPT_LAW }, \
	{ "json", no_argument, NULL, OPT_JSON }, \
	{ "pretty", no_argument, NULL, OPT_PRETTY }, \
	{ "png", required_argument, NULL, OPT_PNG }, \
	{ "version", no_argument, NULL, OPT_VERSION }, \
	{ "help", no_argument, NULL, 'h' }

enum gfmd_field { GFMD_CONTACT, GFMD_GAP, GFMD_PRESSURE, GFMD_DISPLACEMENT,
	GFMD_NFIELDS };
extern const char *const gfmd_field_option[GFMD_NFIELDS];
/* Why --kernel pixel is refused with a periodic layer. */
extern const char gfmd_pixel_layer_refusal[];

struct gfmd_opts {
	rc_solver_opts so;
	double *reduced, *absolute;	/* -p and --pressure-abs lists */
	size_t nreduced, nabsolute;
	double *approach;		/* --approach list (displacement control) */
	size_t napproach;
	int boundary;			/* an enum rc_boundary, -1: the grid's */
	double modulus, alpha, ck_every;
	int fd;
	const char *init, *ck_path, *resume_path;
	const char *field[GFMD_NFIELDS];
	/* given on the command line (a resumed run takes the rest from its
	 * checkpoint) */
	int given_method, given_tol, given_e, given_alpha, given_fd;
	int given_hardness;
	int given_layer;		/* --thickness, --substrate or --poisson */
	int poisson_given;
	int given_max_iter;
	int given_stall;
	int given_kernel;
	int given_adhesion;		/* --adhesion or --range */
	int given_law;			/* --law */
};

void gfmd_opts_init(struct gfmd_opts *o);
void gfmd_opts_free(struct gfmd_opts *o);
/* One option c of getopt_long (with GFMD_OPTSTRING and GFMD_LONGOPTS) that
 * is not -h: values checked, problems through tool_bad. */
void gfmd_option(struct tool *t, struct gfmd_opts *o, int c, const char *arg,
    char **argv);
/* The checks between options and on the operands argv[optind..argc-1]. */
void gfmd_opts_check(struct tool *t, struct gfmd_opts *o, int argc, char **argv);

/* Refuse (exit 1, naming the input) an indenter whose height range or rms
 * gradient gbar lies outside [GFMD_SCALE_MIN, GFMD_SCALE_MAX]: the solver
 * squares gradients and multiplies pressures by displacements, which
 * overflow or underflow there (a p = inf would be blamed on the pressure).
 * range NaN: not known (skipped); 0 (flat) and gbar 0 are fine. */
#define GFMD_SCALE_MIN 1e-100
#define GFMD_SCALE_MAX 1e100
void gfmd_check_scale(const struct tool *t, const char *input, double range,
    double gbar);

#endif
