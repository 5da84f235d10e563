/* SPDX-License-Identifier: GPL-3.0-or-later */
/* surfgen_opts.c - surfgen's surface options (see surfgen_opts.h). */
#include "surfgen_opts.h"

#include <errno.h>
#include <stdlib.h>

void
surfgen_opts_init(struct surfgen_opts *o)
{
	rc_synth_defaults(&o->p);
	o->selfaffine_given = o->harmonic_given = o->periodic_given = 0;
}

/* A positive option value into *v; a bad one is reported and leaves *v
 * at its default, so the library's cross checks still see sane values. */
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

static void
parse_seed(struct tool *t, const char *arg, uint64_t *seed)
{
	char *end;
	unsigned long long s;

	if (arg[0] < '0' || arg[0] > '9') {
		tool_bad(t, "--seed %s: want an integer 0 to 2^64-1", arg);
		return;
	}
	errno = 0;
	s = strtoull(arg, &end, 10);
	if (*end != '\0' || errno == ERANGE)
		tool_bad(t, "--seed %s: want an integer 0 to 2^64-1", arg);
	else
		*seed = (uint64_t)s;
}

int
surfgen_option(struct tool *t, struct surfgen_opts *o, int opt, const char *arg)
{
	rc_synth_params *p = &o->p;
	double v;
	int type;

	switch (opt) {
	case 'n':
		tool_size_pair(t, "-n", arg, &p->nx, &p->ny);
		return 1;
	case 'L':
		tool_length_pair(t, "-L", arg, &p->lx, &p->ly);
		return 1;
	case OPT_RMS_GRADIENT:
		positive(t, "--rms-gradient", arg, &p->rms_gradient);
		return 1;
	case OPT_RMS_HEIGHT:
		positive(t, "--rms-height", arg, &p->rms_height);
		return 1;
	case OPT_TYPE:
		if ((type = rc_surface_type_parse(arg)) < 0)
			tool_bad(t, "--type %s: want selfaffine, harmonic, sine, "
			    "eggbox or flat", arg);
		else
			p->type = (enum rc_surface_type)type;
		return 1;
	case 'H':
		if (tool_double(t, "-H", arg, &v) != 0)
			;
		else if (!(v > 0 && v < 1))
			tool_bad(t, "-H %s: the Hurst exponent must be in (0, 1)", arg);
		else
			p->hurst = v;
		break;
	case OPT_LAMBDA_R:
		positive(t, "--lambda-r", arg, &p->lambda_r);
		break;
	case OPT_LAMBDA_S:
		positive(t, "--lambda-s", arg, &p->lambda_s);
		break;
	case OPT_ROLLOFF:
		p->rolloff = 1;
		break;
	case OPT_PEKLENIK:
		positive(t, "--peklenik", arg, &p->peklenik);
		break;
	case OPT_SEED:
		parse_seed(t, arg, &p->seed);
		break;
	case OPT_GAUSSIAN:
		p->gaussian_amplitudes = 1;
		break;
	case OPT_EXPONENT:
		positive(t, "--exponent", arg, &p->exponent);
		o->harmonic_given = 1;
		return 1;
	case OPT_RADIUS:
		positive(t, "--radius", arg, &p->radius);
		o->harmonic_given = 1;
		return 1;
	case OPT_WAVELENGTH:
		positive(t, "--wavelength", arg, &p->wavelength);
		o->periodic_given = 1;
		return 1;
	case OPT_AMPLITUDE:
		if (tool_double(t, "--amplitude", arg, &v) == 0)
			p->amplitude = v;
		o->periodic_given = 1;
		return 1;
	default:
		return 0;
	}
	o->selfaffine_given = 1;	/* the cases that break out of the switch */
	return 1;
}

void
surfgen_opts_check(struct tool *t, struct surfgen_opts *o)
{
	rc_synth_params *p = &o->p;
	rc_err err;

	if (p->rms_gradient > 0 && p->rms_height > 0)
		tool_bad(t, "--rms-gradient and --rms-height: give one, not both");
	if (p->type != RC_SURF_SELFAFFINE && o->selfaffine_given)
		tool_bad(t, "-H, --lambda-r, --lambda-s, --rolloff, --peklenik, "
		    "--seed, --gaussian-amplitudes: only for --type selfaffine, "
		    "not %s", rc_surface_type_name(p->type));
	if (p->type != RC_SURF_HARMONIC && o->harmonic_given)
		tool_bad(t, "--exponent, --radius: only for --type harmonic");
	if (p->type != RC_SURF_SINE && p->type != RC_SURF_EGGBOX &&
	    o->periodic_given)
		tool_bad(t, "--wavelength, --amplitude: only for --type sine or eggbox");
	/* The library's check catches the cross conditions (lambda_s against
	 * the grid, lambda_r > lambda_s, wavelengths that must divide the
	 * cell); values reported above are still at their defaults here. */
	if (!(p->rms_gradient > 0 && p->rms_height > 0) &&
	    rc_synth_check(p, &err) != 0)
		tool_bad(t, "%s", err.msg);
}
