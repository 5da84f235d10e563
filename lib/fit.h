/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit.h - the self-affine model of Eq. 2 of Wang & Mueser (2020), as
 * surfgen makes it (synth.h), fitted to the spectrum of a surface:
 *   C(q) = C_r (q / q_r)^(-2 - 2H)   for q_r <= q < q_s,
 *   C(q) = C_r (roll-off) or 0       for q < q_r,      0 for q >= q_s,
 * so that hrms^2 = int d^2q C(q) = 2 pi C_r q_r^2 [ f_roll / 2
 *   + (1 - (q_s/q_r)^(-2H)) / (2H) ].
 *
 * The method (piecewise, each step stated):
 * 1. The 2D spectrum (windowed like surfstat --psd: Hann by default on a
 *    finite patch) restricted to the fit range q_min <= |q| <= q_max.  A
 *    mode holds power if C > 1e-20 max C (below that is FFT round-off).  If
 *    modes without power lie above every mode with power, the spectrum has
 *    a sharp cutoff: q_s is the midpoint between the last mode with power
 *    and the first without, its error half that gap (q_s_from = cutoff).
 *    Otherwise q_s is the upper end of the range (q_s_from = range): a
 *    measurement's spectrum runs on to its resolution, and the fit can
 *    only say the power law holds that far.  Likewise at the low end: modes
 *    without power below every mode with power fix q_r the same way and
 *    mean no roll-off (C = 0 below q_r).
 * 2. The radial C(q) (log bins) inside the range, without the bins within
 *    a bin width of a detected cutoff (they average across the edge).
 * 3. ln C against ln q: without a low cutoff, a hinge (plateau below q_r,
 *    power law above) is searched over 200 positions between the first
 *    and last bin by linear least squares, then refined with GSL's
 *    nonlinear least squares (gsl_multifit_nlinear, trust region) for
 *    ln C_r, H and ln q_r; the plateau is accepted (rolloff = 1,
 *    q_r_from = fit) if it halves the residual sum of squares of a pure
 *    power law and has at least 2 bins on each side.  Otherwise a straight
 *    line (gsl_multifit_linear) gives ln C_r and H, with q_r from the low
 *    cutoff, or, if there is none, the lowest q of the range (q_r_from =
 *    range, rolloff = 0: the roll-off lies below what was measured).
 *    Every bin is weighted by its number of modes (the variance of ln C
 *    of a bin of independent modes falls as 1/modes).  Standard errors
 *    are the covariance of the fit scaled by the residual variance;
 *    hrms's by propagation through the formula above.
 * 4. Self-affine or not: the power-law bins (above q_r with a plateau)
 *    are split into a lower and an upper half in ln q, each fitted by a
 *    line alone.  C(q) is called self-affine on the range if 0 < H < 1
 *    and the halves' H differ by less than 3 standard errors (each from
 *    its own scatter: the fit's own statistics) or by less than
 *    RC_FIT_BEND_TOL (a bend that small is within the scatter of H
 *    between measurements of one surface).  If it is not, the widest run
 *    of bins spanning at least a decade that is (same tests) is found,
 *    for rc_fit_advice.
 * Short wavelengths measured by a scanning probe are often unreliable
 * (tip convolution, noise): q_max = 2 pi / (the shortest reliable
 * wavelength) excludes them; see surfstat(1).  On a finite patch q_max
 * defaults to pi / (2 max(dx, dy)), wavelengths of 4 spacings and more
 * (the window's leakage, and the transfer function of most instruments,
 * make the last octave unreliable); on a periodic grid to no bound.
 */
#ifndef RC_FIT_H
#define RC_FIT_H
/* (surfgen --like turns a fit into surfgen's parameters: H, lambda_r =
 * 2 pi / q_r, lambda_s = 2 pi / q_s, rolloff and rms height hrms.) */

#include <stddef.h>
#include "fft.h"
#include "grid.h"
#include "psd.h"

typedef struct rc_fit_opts {
	double q_min, q_max;	/* fit range; 0 = the default (below) */
	double bins_per_decade;	/* radial bins (default 10) */
	enum rc_window window;	/* RC_WINDOW_AUTO as surfstat --psd */
} rc_fit_opts;

typedef struct rc_selfaffine_fit {
	double H, H_err;
	double q_r, q_r_err;
	double q_s, q_s_err;
	double c_r;		/* C(q_r) */
	double hrms, hrms_err;	/* of the fitted model */
	int rolloff;
	const char *q_r_from, *q_s_from;	/* "fit", "cutoff", "range" */
	double fit_q_min, fit_q_max;	/* the bins used */
	size_t n_bins;
	double rms_residual;	/* of ln C, weighted by the bins' modes */
	/* Step 4: is C(q) self-affine on the bins fitted? */
	int selfaffine;		/* 0 < H < 1 and the halves' slopes agree */
	double h_lo, h_lo_err, h_hi, h_hi_err;	/* the halves; NAN if < 8 bins */
	double q_mid;		/* where the halves meet */
	/* the widest run of bins of at least a decade that is self-affine
	 * (good_H NAN if none): ln q of its end bins, bounds half a bin
	 * outside them (0 where the run reaches the end of the range), H */
	double good_lo, good_hi, good_q_min, good_q_max, good_H, good_H_err;
	/* The length unit of every length of the fit (q in its inverse, C
	 * in its fourth power): the grid's lateral unit, "" if it has none.
	 * The fit reads the heights as lengths in it; the tools bring every
	 * grid to one length unit first (units.h). */
	char unit[32];
} rc_selfaffine_fit;

/* A wavelength bound as given on the command line: a bare number is in
 * the map's length unit; with the suffix L a fraction of the scan (L =
 * the longer side, lx or ly: 0.05L); with a length unit (units.h: 5um,
 * 0.2mm, 50nm) in that unit.  Parse checks the text; resolve gives the
 * length in g's unit, failing when a unit is given for a map without one
 * or the result is not positive and finite. */
typedef struct rc_fit_length {
	double value;
	int scan;		/* value is a fraction of the scan */
	char unit[16];		/* a length unit, or "" */
} rc_fit_length;
int rc_fit_length_parse(const char *text, rc_fit_length *l, rc_err *err);
int rc_fit_length_resolve(const rc_fit_length *l, const rc_grid *g,
    double *out, rc_err *err);

void rc_fit_opts_default(rc_fit_opts *o);
int rc_fit_selfaffine(const rc_grid *g, rc_fft *fft, const rc_fit_opts *o,
    rc_selfaffine_fit *fit, rc_err *err);
/* Halves whose H differ by less than this are not a bend (step 4). */
#define RC_FIT_BEND_TOL 0.1
/* 0 if the fit is self-affine; else 1 and, in buf, which range of q is
 * not, why (H outside 0 < H < 1, the slope bends, flat or steep at which
 * end) and what to try: the self-affine sub-range as --min-wavelength,
 * --max-wavelength fractions of the scan L, or that none spans a decade. */
int rc_fit_advice(const rc_selfaffine_fit *fit, double L, char *buf,
    size_t len);
/* hrms of the model (formula above). */
double rc_fit_model_hrms(double c_r, double hurst, double q_r, double q_s,
    int rolloff);

#endif

/* A fit as surfstat --fit writes it (TSV: a header line, one row), read
 * back: the columns nx ny lx ly H q_r q_s hrms rolloff are required; a
 * unit column, which surfstat writes when the grid has a unit, must name
 * a length unit (units.h) and goes into fit->unit.  Returns 1 and fills fit, nx, ny, lx, ly if the text is such a table; 0
 * if it is not one (no lambda_r column in the first line: something
 * else, e.g. a grid); -1 with err set if it is one but broken. */
int rc_fit_table_parse(const char *text, rc_selfaffine_fit *fit, size_t *nx, size_t *ny,
    double *lx, double *ly, rc_err *err);
