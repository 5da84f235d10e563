/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solver_approach.c - displacement control: the mean pressure at which the
 * approach (rc_solver_approach, solver.h) takes a prescribed value.
 *
 * The approach grows monotonically with the load, so p is found by a 1-D
 * root find on f(x) = approach(e^x) - delta, x = log p: the root is first
 * bracketed (p multiplied or divided by 4 from a start), then narrowed by
 * regula falsi with the Illinois modification (the retained end's value
 * halved when the same end is kept twice), which converges superlinearly
 * and, unlike GSL's Brent, never re-evaluates an end: each evaluation is a
 * full contact solve, warm-started from the one before, so the state left
 * in the solver is always that of the last (accepted) pressure.  Stop when
 * |approach - delta| <= tol delta, tol the solver's tolerance.
 *
 * Serial only (the MPI build refuses --approach).  A periodic half space
 * cannot be pressed past full contact at a finite load; a layer can (its
 * uniform compression p / k_0 keeps growing).
 *
 * Start: the last solved pressure, or p = E* delta / sqrt(lx ly) (a flat
 * punch of a quarter the cell's width, F = 2 a E* delta, spread over the
 * cell) when there is none.
 *
 * A hardness H (perfect plasticity) bounds the load: p <= H, and at p = H
 * the whole area flows and the rigid level is free (any approach from
 * the one reached as p -> H up is that state).  So the bracket never
 * steps past H: upwards p goes to min(4 p, H - (H - p) / 4), closing in on
 * H geometrically, and the start is H/2 when the guess is not below H.
 * An approach beyond that reached as p -> H (to round-off of H) is an
 * error that says so; regula falsi between two ends below H stays below.
 * That limit is finite: the last points below H are the lowest of h,
 * which fix the level, so it is about max h - min h plus the elastic
 * deflection (measured: 0.2396 periodic, 0.4433 free, against max h -
 * min h = 0.24, on the 128^2 surfgen map of gfmd-solve(1) PLASTICITY
 * at H = 0.2).  With a hardness the periodic body is pressed past full
 * contact (max h - <h>) by flattening, so that bound is not applied.
 */
#include "solver_impl.h"

#include <float.h>
#include <math.h>
#include <string.h>

#include "clock.h"

#define MAX_BRACKET	60
#define MAX_NARROW	100

struct trial {
	rc_solver *s;
	rc_solve_result *total;
	double delta;
	int status;	/* worst inner status (0 or 1) */
};

/* Solve at p = e^x; *f = approach - delta.  -1 on an error, 1 on a stop. */
static int
eval(struct trial *tr, double x, double *f, rc_err *err)
{
	rc_solve_result r;
	int st = rc_solver_solve(tr->s, exp(x), &r, err);

	if (st < 0)
		return -1;
	tr->total->iterations += r.iterations;
	tr->total->fft_pairs += r.fft_pairs;
	tr->total->seconds += r.seconds;
	tr->total->residual = r.residual;
	if (st > 0)
		tr->status = 1;
	*f = rc_solver_approach(tr->s) - tr->delta;
	/* a stalled trial ends the search as a stop does */
	if (r.stalled)
		tr->total->stalled = 1;
	return (tr->s->opts.stop && *tr->s->opts.stop) || r.stalled ? 1 : 0;
}

/* Adhesion: FIRE with the mean height held (solver_fire_adh.c; a half
 * space not past full contact) or, a periodic layer, with its substrate
 * held at delta (the mean mode on the spring k_0: the approach moves with
 * p / k_0, and a layer is pressed past full contact by its compression). */
static int
adhesive_approach(rc_solver *s, double delta, double *pressure,
    rc_solve_result *res, rc_err *err)
{
	double t0 = rc_clock(), sum = 0, p = s->last_pressure;
	unsigned long transforms = s->el.n_r2c + s->el.n_c2r;
	int r, layer = !s->free_bc && isfinite(s->k_uniform);

	if (!isfinite(delta))
		return rc_seterr(err, "approach must be finite");
	for (size_t i = 0; i < s->n; i++)
		sum += s->height[i];
	if (!s->free_bc && !layer && !(delta < s->top - sum / (double)s->n))
		return rc_seterr(err, "approach %g reaches full contact "
		    "(max h - <h> = %g)", delta, s->top - sum / (double)s->n);
	s->watch.stalled = 0;
	if ((r = rc__fire_adh_solve(s, layer ? RC__ADH_SUBSTRATE :
	    RC__ADH_LEVEL, &p, delta, res, err)) < 0)
		return -1;
	s->last_pressure = *pressure = p;
	res->seconds = rc_clock() - t0;
	res->fft_pairs = 0.5 * (double)(s->el.n_r2c + s->el.n_c2r - transforms);
	res->converged = r == 0;
	res->stalled = r == 1 && s->watch.stalled;
	return r;
}

/* The next end of the bracket from x = log p: p times or over 4, but
 * upwards never past a hardness H (see the top); NAN when p is H to
 * round-off.  That test is on the distance to H and on progress in x:
 * exp and log lose a few ulps each way, so for some H (0.05) p stalled
 * a few ulps below H and the bracket ran its MAX_BRACKET solves at
 * p = H before a vaguer message. */
static double
bracket_step(const rc_solver *s, double x, int up)
{
	double p = exp(x), H = s->opts.hardness, next;

	if (!up)
		return x - log(4.0);
	if (!rc_solver_opts_plastic(&s->opts) || 4 * p < H)
		return x + log(4.0);
	p = H - 0.25 * (H - p);
	next = log(p);
	return H - p > 64 * DBL_EPSILON * H && next > x ? next : NAN;
}

/* Long: the full-contact check, the bracket and the Illinois steps share
 * the trial state and its early exits. */
int
rc_solver_solve_approach(rc_solver *s, double delta, double *pressure,
    rc_solve_result *res, rc_err *err)
{
	struct trial tr = { s, res, delta, 0 };
	double a, b, fa, fb, x, fx, p0, tol = s->opts.tol * delta;
	int k, r;

	memset(res, 0, sizeof(*res));
	*pressure = NAN;
	if (rc_solver_opts_adhesive(&s->opts))
		return adhesive_approach(s, delta, pressure, res, err);
	if (!(delta > 0) || !isfinite(delta))
		return rc_seterr(err, "approach must be positive and finite");
	/* A hardness (its flattening) and a compressible layer (its
	 * uniform compression) take the approach past full contact (a
	 * hardness up to the bound of the top of this file). */
	if (!s->free_bc && !isfinite(s->k_uniform) &&
	    !rc_solver_opts_plastic(&s->opts)) {
		double sum = 0, full;

		for (size_t i = 0; i < s->n; i++)
			sum += s->height[i];
		full = s->top - sum / (double)s->n;
		if (!(delta < full))
			return rc_seterr(err, "approach %g reaches full contact "
			    "(max h - <h> = %g): a periodic body cannot be pressed "
			    "further at a finite load", delta, full);
	}
	p0 = s->last_pressure > 0 ? s->last_pressure :
	    s->opts.modulus * delta / sqrt(s->lx * s->ly);
	if (rc_solver_opts_plastic(&s->opts) && !(p0 < s->opts.hardness))
		p0 = 0.5 * s->opts.hardness;
	b = log(p0);
	if ((r = eval(&tr, b, &fb, err)) != 0)
		goto done;
	if (fabs(fb) <= tol)
		goto done;
	/* Bracket: a the other end, f(a) of the opposite sign. */
	for (k = 0, a = b, fa = fb; k < MAX_BRACKET && (fa < 0) == (fb < 0); k++) {
		b = a;
		fb = fa;
		a = bracket_step(s, b, fb < 0);
		if (isnan(a)) {
			r = -1;
			rc_seterr(err, "approach %g not reached below the hardness "
			    "%g (approach %g at p = %.17g): at p = H the whole "
			    "area flows", delta, s->opts.hardness,
			    fb + delta, exp(b));
			goto done;
		}
		if ((r = eval(&tr, a, &fa, err)) != 0)
			goto done;
		if (fabs(fa) <= tol)
			goto done;
	}
	if ((fa < 0) == (fb < 0)) {
		r = -1;
		rc_seterr(err, "approach %g not bracketed between p = %g and %g",
		    delta, exp(a < b ? a : b), exp(a < b ? b : a));
		goto done;
	}
	/* Illinois, b the last point evaluated. */
	{
		double t = a, ft = fa;

		a = b;
		fa = fb;
		b = t;
		fb = ft;
	}
	for (k = 0; k < MAX_NARROW; k++) {
		x = b - fb * (b - a) / (fb - fa);
		if ((r = eval(&tr, x, &fx, err)) != 0)
			goto done;
		if (fabs(fx) <= tol)
			break;
		if (fabs(b - a) < 1e-14) {
			tr.status = 1;	/* the inner solves' noise exceeds tol */
			break;
		}
		if ((fx < 0) != (fb < 0)) {
			a = b;
			fa = fb;
		} else
			fa *= 0.5;
		b = x;
		fb = fx;
	}
	if (k == MAX_NARROW)
		tr.status = 1;
done:
	res->converged = r == 0 && tr.status == 0;
	*pressure = s->last_pressure;
	if (r < 0)
		return -1;
	return r > 0 ? 1 : tr.status;
}
