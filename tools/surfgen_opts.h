/* SPDX-License-Identifier: GPL-3.0-or-later */
/* surfgen_opts.h - surfgen's surface options, shared by the serial tool and
 * its MPI build so that one command line means one surface in both. */
#ifndef RC_SURFGEN_OPTS_H
#define RC_SURFGEN_OPTS_H

#include <getopt.h>

#include "common.h"
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

/* The long options of the surface, for a tool's option table. */
#define SURFGEN_LONGOPTS \
	{ "lambda-r", required_argument, NULL, OPT_LAMBDA_R }, \
	{ "lambda-s", required_argument, NULL, OPT_LAMBDA_S }, \
	{ "rolloff", no_argument, NULL, OPT_ROLLOFF }, \
	{ "peklenik", required_argument, NULL, OPT_PEKLENIK }, \
	{ "seed", required_argument, NULL, OPT_SEED }, \
	{ "rms-gradient", required_argument, NULL, OPT_RMS_GRADIENT }, \
	{ "rms-height", required_argument, NULL, OPT_RMS_HEIGHT }, \
	{ "gaussian-amplitudes", no_argument, NULL, OPT_GAUSSIAN }, \
	{ "type", required_argument, NULL, OPT_TYPE }, \
	{ "exponent", required_argument, NULL, OPT_EXPONENT }, \
	{ "radius", required_argument, NULL, OPT_RADIUS }, \
	{ "wavelength", required_argument, NULL, OPT_WAVELENGTH }, \
	{ "amplitude", required_argument, NULL, OPT_AMPLITUDE }

/* The surface being described and which type-specific options were given
 * (an option the chosen type would ignore is a mistake). */
struct surfgen_opts {
	rc_synth_params p;
	int selfaffine_given;	/* -H, --lambda-r/-s, --rolloff, ... */
	int harmonic_given;	/* --exponent, --radius */
	int periodic_given;	/* --wavelength, --amplitude */
};

void surfgen_opts_init(struct surfgen_opts *o);
/* One option of the surface (-n, -L, -H or a SURFGEN_LONGOPTS one): 1 if
 * it was one (a bad value is reported through tool_bad), 0 if not. */
int surfgen_option(struct tool *t, struct surfgen_opts *o, int opt,
    const char *arg);
/* The checks between options, after the last one; reported through
 * tool_bad. */
void surfgen_opts_check(struct tool *t, struct surfgen_opts *o);

#endif
