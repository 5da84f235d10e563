/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_txt.c - whitespace matrix: one grid row (fixed j) per line, x fastest
 * along the line, j = 0 first.  Lines starting with '#' are comments (as
 * numpy.loadtxt has them); "# key = value" comments carry what the other
 * formats keep in their headers (nx, ny, lx, ly, unit, z_unit, periodic,
 * kind, meta.KEY, history, filled), so a round trip loses nothing.  Values are
 * printed with %.17g, which reads back exactly; missing points are "nan".
 *
 * Read besides (the header lines are io_txt_head.c's): Gwyddion's ASCII
 * export, SurfaceTopography's "h= w=" matrix, and columns.  Values are
 * separated by blanks, ',' or ';'.  A file of 2 or 3 values per line on 4
 * lines or more, or any file with a line of column names or units, without
 * a matrix header, is x-z (a profile) or x-y-z (a map), never a 2- or
 * 3-column matrix; an index column and a validity flag are set aside; one
 * value per line is a profile whose length -L gives.  Columns must lie on
 * a uniform grid (to 1% of the spacing, or to one unit of the last digit
 * when every coordinate is printed in fixed point); any other set of
 * points is refused, unless the options ask to resample x-z columns
 * (rc_read_opts.uniform): then the n points, in strictly monotonic x,
 * are interpolated linearly (GSL) onto n points of step
 * (x_last - x_first) / (n - 1), a point on the grid keeping its height
 * exactly, and a grid point whose interval touches a missing height is
 * missing; or, when the options ask to keep them as they are
 * (rc_read_opts.nonuniform), read as an n x 1 grid that carries its x
 * positions (grid.h).  Periodic: our own files say (1 when
 * they do not), a plain matrix is periodic, exports and columns
 * (measurements) are not.
 */
#include "io_txt_internal.h"
#include "units.h"

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_interp.h>

#define TOKEN_MAX 128

int
rc__txt_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	char num[64], *filled;
	int bad = 0;

	if (rc__io_filled_text(g, &filled, err) != 0)
		return -1;
	bad |= fprintf(fp, "%s\n# nx = %zu\n# ny = %zu\n", RC_TXT_MAGIC, g->nx, g->ny) < 0;
	rc_format_double(num, sizeof(num), g->lx);
	bad |= fprintf(fp, "# lx = %s\n", num) < 0;
	rc_format_double(num, sizeof(num), g->ly);
	bad |= fprintf(fp, "# ly = %s\n", num) < 0;
	if (g->unit[0] != '\0')
		bad |= fprintf(fp, "# unit = %s\n", g->unit) < 0;
	if (g->z_unit[0] != '\0')
		bad |= fprintf(fp, "# z_unit = %s\n", g->z_unit) < 0;
	bad |= fprintf(fp, "# periodic = %d\n", g->periodic ? 1 : 0) < 0;
	bad |= fprintf(fp, "# kind = %s\n", rc_kind_name(g->kind)) < 0;
	for (size_t i = 0; i < g->nmeta; i++)
		bad |= fprintf(fp, "# meta.%s = %s\n", g->meta[i].key,
		    g->meta[i].val) < 0;
	for (size_t i = 0; i < g->nhistory; i++)
		bad |= fprintf(fp, "# history = %s\n", g->history[i]) < 0;
	if (filled != NULL)
		bad |= fprintf(fp, "# filled = %s\n", filled) < 0;
	free(filled);
	for (size_t j = 0; j < g->ny && !bad; j++) {
		const double *row = g->z + j * g->nx;

		for (size_t i = 0; i < g->nx; i++)
			bad |= fprintf(fp, i ? " %.17g" : "%.17g", row[i]) < 0;
		bad |= putc('\n', fp) == EOF;
	}
	if (bad)
		return rc_seterr(err, "write error");
	return 0;
}


/* Gwyddion's Width and Height (each with its unit) into lx, ly in one
 * unit, which becomes the lateral unit unless the header names one. */
static int
gwy_size(struct txt_header *h, double *lx, double *ly, rc_err *err)
{
	*lx = h->width;
	*ly = h->height;
	if (strcmp(h->wunit, h->hunit) != 0) {
		if (!rc_unit_is_length(h->wunit) || !rc_unit_is_length(h->hunit))
			return rc_seterr(err, "Gwyddion header: Width in '%s', Height "
			    "in '%s': not one length unit", h->wunit, h->hunit);
		*ly = rc_unit_convert(h->height, h->hunit, h->wunit);
	}
	if (h->unit[0] == '\0')
		strcpy(h->unit, h->wunit);
	else if (strcmp(h->unit, h->wunit) != 0 && h->wunit[0] != '\0') {
		if (!rc_unit_is_length(h->wunit) || !rc_unit_is_length(h->unit))
			return rc_seterr(err, "Gwyddion header: Width in '%s', "
			    "lateral units '%s'", h->wunit, h->unit);
		*lx = rc_unit_convert(*lx, h->wunit, h->unit);
		*ly = rc_unit_convert(*ly, h->wunit, h->unit);
	}
	return 0;
}

/* Does a coordinate lie on the uniform grid a0 + k d, to 1% of d or to
 * ulp, the unit in the last printed digit of the coordinates?  A printed
 * coordinate is within ulp/2 of the grid it was rounded from, and the
 * grid through the first and last printed ones within ulp/2 of that
 * grid, so ulp bounds the distance (Dektak prints 0.15625 um steps as
 * 0.0, 0.2, 0.3, 0.5: 0.094 off a grid through 0 and 1499.8).  Only for
 * coordinates all printed in fixed point with the same decimals
 * (read_values) and a step of at least ulp. */
static int
on_grid(double a, double a0, double d, size_t k, double ulp)
{
	double tol = ulp <= fabs(d) ? ulp : 0;

	return fabs(a - (a0 + (double)k * d)) <= fmax(0.01 * fabs(d), tol);
}

/* The n x-z points (v: x, z pairs) into x and z in increasing x (a
 * profile written backwards is turned round); x must be strictly
 * monotonic ("what" says what needs it). */
static int
profile_in_order(const double *v, size_t n, double *x, double *z,
    const char *what, rc_err *err)
{
	int down = v[2] < v[0];

	for (size_t k = 0; k < n; k++) {
		size_t src = down ? n - 1 - k : k;

		x[k] = v[2 * src];
		z[k] = v[2 * src + 1];
		if (!isfinite(x[k]) || (k > 0 && !(x[k] > x[k - 1])))
			return rc_seterr(err, "%zu x-z points: x is not strictly "
			    "monotonic (line %zu of the data: x = %g): %s needs the "
			    "points in order of x, each x once", n, src + 1, x[k],
			    what);
	}
	return 0;
}

/* n x-z points (v: x, z pairs) in strictly monotonic, not uniformly
 * spaced x, interpolated linearly onto n points of a uniform step (the
 * header comment says how). */
static rc_grid *
resample_profile(const double *v, size_t n, rc_err *err)
{
	double *x = NULL, *z = NULL, dx;
	gsl_interp *ip = NULL;
	gsl_interp_accel *acc = NULL;
	rc_grid *g = NULL;

	if ((x = rc_malloc(n * sizeof(*x), err)) == NULL ||
	    (z = rc_malloc(n * sizeof(*z), err)) == NULL ||
	    profile_in_order(v, n, x, z, "resampling", err) != 0)
		goto out;
	dx = (x[n - 1] - x[0]) / (double)(n - 1);
	if ((ip = gsl_interp_alloc(gsl_interp_linear, n)) == NULL ||
	    (acc = gsl_interp_accel_alloc()) == NULL) {
		rc_seterr(err, "out of memory");
		goto out;
	}
	gsl_interp_init(ip, x, z, n);	/* x checked increasing above */
	if ((g = rc__io_grid_alloc(n, 1, (double)n * dx, dx, err)) == NULL)
		goto out;
	for (size_t i = 0; i < n; i++) {
		double xg = i + 1 < n ? x[0] + (double)i * dx : x[n - 1];
		size_t k = gsl_interp_bsearch(x, xg, 0, n - 1);

		if (isfinite(z[k]) && isfinite(z[k + 1]))
			gsl_interp_eval_e(ip, x, z, xg, acc, &g->z[i]);
		else if (xg == x[k])
			g->z[i] = z[k];
		else if (xg == x[k + 1])
			g->z[i] = z[k + 1];
		else
			g->z[i] = NAN;
	}
	g->periodic = 0;
	if (rc_grid_meta_setf(g, "resampled", err, "linearly from %zu x "
	    "positions not uniformly spaced", n) != 0) {
		rc_grid_free(g);
		g = NULL;
	}
out:
	gsl_interp_accel_free(acc);
	if (ip != NULL)
		gsl_interp_free(ip);
	free(x);
	free(z);
	return g;
}

/* n x-z points (v: x, z pairs) in strictly monotonic, not uniformly
 * spaced x, as they are (rc_read_opts.nonuniform): an n x 1 grid with
 * its positions in g->x (grid.h), a measurement (not periodic). */
static rc_grid *
nonuniform_profile(const double *v, size_t n, rc_err *err)
{
	double *x = NULL, *z = NULL, lx;
	rc_grid *g = NULL;

	if ((x = rc_malloc(n * sizeof(*x), err)) == NULL ||
	    (z = rc_malloc(n * sizeof(*z), err)) == NULL ||
	    profile_in_order(v, n, x, z, "a non-uniform profile", err) != 0)
		goto out;
	lx = x[n - 1] - x[0];
	if ((g = rc__io_grid_alloc(n, 1, lx, lx / (double)(n - 1), err)) == NULL)
		goto out;
	memcpy(g->z, z, n * sizeof(*z));
	g->x = x;
	x = NULL;
	g->periodic = 0;
out:
	free(x);
	free(z);
	return g;
}

/* x-z (ncol 2) or x-y-z (ncol 3) columns of n points on a uniform grid:
 * a profile of n x 1 points, or the map they cover.  Points are taken in
 * the order of the file, along x first or along y first; either axis may
 * run backwards. */
static rc_grid *
columns(const double *v, size_t ncol, size_t n, const double *ulp,
    const rc_read_opts *o, rc_err *err)
{
	size_t nxg = n, nyg = 1, run, bad = n;
	double x0 = v[0], y0 = 0, dx, dy, lx, ly;
	int x_fast = 1;
	rc_grid *g;

	/* one point has no spacing to give the cell size (a line that
	 * starts with '#', as Excel's #N/A, is a comment: the rest can be
	 * a single line) */
	if (n < 2) {
		rc_seterr(err, "one point in %s columns: no spacing gives the "
		    "cell size (the other lines are comments or blank?)",
		    ncol == 3 ? "x-y-z" : "x-z");
		return NULL;
	}
	if (ncol == 3) {
		y0 = v[1];
		/* the length of the first run of equal y (or equal x) */
		x_fast = v[ncol] != x0;
		for (run = 1; run < n && v[run * ncol + (x_fast ? 1 : 0)] ==
		    (x_fast ? y0 : x0); run++)
			;
		if (n % run != 0) {
			rc_seterr(err, "%zu x-y-z points (3 values per line): the first "
			    "line of equal %s holds %zu points, which does not divide "
			    "%zu, so they do not form a grid; resample them to a grid, "
			    "or add a '# nx = 3' line to read a 3-column height matrix",
			    n, x_fast ? "y" : "x", run, n);
			return NULL;
		}
		nxg = x_fast ? run : n / run;
		nyg = x_fast ? n / run : run;
	}
	dx = nxg > 1 ? (v[(x_fast ? nxg - 1 : (nxg - 1) * nyg) * ncol] - x0) /
	    (double)(nxg - 1) : 0;
	dy = nyg > 1 ? (v[(x_fast ? (nyg - 1) * nxg : nyg - 1) * ncol + 1] - y0) /
	    (double)(nyg - 1) : 0;
	if (nxg > 1 && dx == 0)
		bad = 0;
	if (nyg > 1 && dy == 0)
		bad = 0;
	for (size_t k = 0; k < n && bad == n; k++) {
		size_t i = x_fast ? k % nxg : k / nyg, j = x_fast ? k / nxg : k % nyg;

		if (!on_grid(v[k * ncol], x0, dx, i, ulp[0]) ||
		    (ncol == 3 && !on_grid(v[k * ncol + 1], y0, dy, j, ulp[1])))
			bad = k;
	}
	if (bad < n && ncol == 2 && o != NULL && o->uniform)
		return resample_profile(v, n, err);
	if (bad < n && ncol == 2 && o != NULL && o->nonuniform)
		return nonuniform_profile(v, n, err);
	if (bad < n) {
		if (ncol == 2)
			rc_seterr(err, "%zu x-z points (2 values per line): x is not "
			    "uniformly spaced (line %zu of the data: x = %g, a uniform "
			    "step would give %g); --uniform resamples the profile "
			    "linearly onto %zu points of a uniform step, or add a "
			    "'# nx = 2' line to read a 2-column height matrix", n,
			    bad + 1, v[bad * ncol], x0 + (double)bad * dx, n);
		else
			rc_seterr(err, "%zu x-y-z points (3 values per line) do not "
			    "form a uniform %zux%zu grid (line %zu of the data is off "
			    "it); resample them to a grid (--uniform resamples x-z "
			    "profiles only), or add a '# nx = 3' line to read a "
			    "3-column height matrix", n, nxg, nyg, bad + 1);
		return NULL;
	}
	/* A line has the spacing of its one axis both ways. */
	if (nxg == 1)
		dx = dy;
	if (nyg == 1)
		dy = dx;
	lx = (double)nxg * fabs(dx);
	ly = (double)nyg * fabs(dy);
	if ((g = rc__io_grid_alloc(nxg, nyg, lx, ly, err)) == NULL)
		return NULL;
	for (size_t k = 0; k < n; k++) {
		size_t i = x_fast ? k % nxg : k / nyg, j = x_fast ? k / nxg : k % nyg;

		if (dx < 0)
			i = nxg - 1 - i;
		if (dy < 0)
			j = nyg - 1 - j;
		g->z[j * nxg + i] = v[k * ncol + ncol - 1];
	}
	g->periodic = 0;	/* a measurement */
	return g;
}

/* Decimals of a number printed in fixed point ("0.0386": 4); -1 for
 * any other form (an integer, an exponent, nan), whose last digit says
 * nothing of the precision (%g drops trailing zeros). */
static int
decimals(const char *tok)
{
	const char *dot = strchr(tok, '.');
	size_t n;

	if (dot == NULL || strpbrk(tok, "eEnNiI") != NULL)
		return -1;
	n = strspn(dot + 1, "0123456789");
	return dot[1 + n] == '\0' && n > 0 && n < 300 ? (int)n : -1;
}

/* The values of a text file: whitespace, ',' or ';' between them (',' a
 * decimal comma in Gwyddion's export, which never separates with it),
 * '#' to the end of a line a comment (at the start of a token: inside
 * one it is part of it), trailing empty fields (Dektak's
 * "0.0,-0.00933,,") dropped.  Every row must have as many values as the
 * first.  ulp[k]: 10^-d if every value of column k < TXT_MAXCOL is
 * printed in fixed point with d decimals, else 0.
 * One pass over characters: no line is ever held whole, so a long row
 * costs nothing beyond its values. */
static int
read_values(rc_in *in, int decimal_comma, size_t lineno, double **vals,
    size_t *nvals, size_t *ncols, size_t *nrows, double *ulp, rc_err *err)
{
	double *v = NULL;
	size_t nv = 0, cap = 0, nx = 0, rows = 0, first_line = 0, inrow = 0;
	size_t tlen = 0;
	char tok[TOKEN_MAX + 1], q[64];
	int c, in_comment = 0, after_sep = 0, empty = 0, dec[TXT_MAXCOL];

	for (size_t k = 0; k < TXT_MAXCOL; k++)
		dec[k] = -2;	/* no value yet */
	for (;;) {
		c = rc__in_getc(in);
		if (in_comment && c != '\n' && c != EOF)
			continue;
		in_comment = 0;
		if (c == ',' && decimal_comma)
			c = '.';
		if (c == 0) {
			rc_seterr(err, "line %zu: NUL byte: not a text file", lineno);
			goto fail;
		}
		/* '#' starts a comment between values; inside one it is
		 * part of it (1.#QNAN: not a number, not 1 and a comment) */
		if (c != EOF && c != '\n' && (c != '#' || tlen > 0) && c != ',' &&
		    c != ';' && !isspace(c)) {
			if (tlen >= TOKEN_MAX) {
				tok[TOKEN_MAX] = '\0';
				rc_seterr(err, "line %zu: '%s' is not a number", lineno,
				    rc__io_quote(q, sizeof(q), tok, TOKEN_MAX));
				goto fail;
			}
			tok[tlen++] = (char)c;
			continue;
		}
		if (tlen > 0) {
			double d;

			tok[tlen] = '\0';
			if (rc__parse_double(tok, &d) != 0) {
				rc_seterr(err, "line %zu: '%s' is not a number", lineno,
				    rc__io_quote(q, sizeof(q), tok, tlen));
				goto fail;
			}
			if (empty) {
				rc_seterr(err, "line %zu: an empty field before '%s'",
				    lineno, rc__io_quote(q, sizeof(q), tok, tlen));
				goto fail;
			}
			if (nv == cap) {
				size_t ncap = cap ? 2 * cap : 1024;
				double *p;

				if (ncap > RC_GRID_MAX_POINTS)
					ncap = RC_GRID_MAX_POINTS;
				if (nv >= ncap) {
					rc_seterr(err, "line %zu: more than %zu values", lineno,
					    (size_t)RC_GRID_MAX_POINTS);
					goto fail;
				}
				if ((p = realloc(v, ncap * sizeof(*v))) == NULL) {
					rc_seterr(err, "out of memory (asked for %zu bytes)",
					    ncap * sizeof(*v));
					goto fail;
				}
				v = p;
				cap = ncap;
			}
			/* A side longer than any grid may have ends the read now,
			 * not when memory runs out (an endless pipe of "1\n"). */
			if (inrow >= RC_GRID_MAX_DIM) {
				rc_seterr(err, "line %zu: more than %u values in a row",
				    lineno, RC_GRID_MAX_DIM);
				goto fail;
			}
			if (inrow < TXT_MAXCOL && dec[inrow] != -1) {
				int dk = decimals(tok);

				dec[inrow] = dec[inrow] == -2 || dec[inrow] == dk ? dk : -1;
			}
			v[nv++] = d;
			inrow++;
			tlen = 0;
			after_sep = 0;
		}
		if (c == ',' || c == ';') {
			if (after_sep || inrow == 0)
				empty = 1;	/* an error if a value follows */
			after_sep = 1;
		} else if (c == '#')
			in_comment = 1;
		else if (c == '\n' || c == EOF) {
			if (inrow > 0) {
				if (rows == 0) {
					nx = inrow;
					first_line = lineno;
				} else if (inrow != nx) {
					rc_seterr(err, "line %zu has %zu values, line %zu has %zu",
					    lineno, inrow, first_line, nx);
					goto fail;
				} else if (rows >= RC_GRID_MAX_DIM) {
					rc_seterr(err, "line %zu: more than %u rows", lineno,
					    RC_GRID_MAX_DIM);
					goto fail;
				}
				rows++;
				inrow = 0;
			}
			after_sep = empty = 0;
			if (c == EOF)
				break;
			lineno++;
		}
	}
	if (rc__in_check(in, err) != 0)
		goto fail;
	for (size_t k = 0; k < TXT_MAXCOL; k++)
		ulp[k] = dec[k] > 0 ? pow(10, -dec[k]) : 0;
	*vals = v;
	*nvals = nv;
	*ncols = nx;
	*nrows = rows;
	return 0;
fail:
	free(v);
	return -1;
}

/* Columns with a line of names or units, or 1-3 unlabelled ones: which
 * column is an index (named "index", or 3 columns whose first counts
 * 0, 1, 2, ... beside a strictly monotonic second: csv-2's "index,x,y"),
 * which a validity flag (named "valid" or in unit "1/0", as HFM's), and
 * the units of the coordinates and heights.  Returns the grid of the
 * rest as a profile (x z, or z alone) or map (x y z). */
static rc_grid *
labelled_columns(const struct txt_header *h, const double *v, size_t ncol,
    size_t rows, const double *ulp, const rc_read_opts *o, rc_err *err)
{
	int idx = -1, valid = -1;
	size_t use[TXT_MAXCOL], m = 0;
	char xu[32] = "", zu[32] = "", yu[32] = "", u[TXT_MAXCOL][32];
	double *w = NULL, ulpw[2] = { 0, 0 };
	rc_grid *g = NULL;

	if (ncol > TXT_MAXCOL) {
		rc_seterr(err, "%zu columns with a line of names or units: read "
		    "are a height column, x-z or x-y-z columns (and an index or "
		    "'valid' column)", ncol);
		return NULL;
	}
	if (h->ncolname > 0 && h->ncolname != ncol) {
		rc_seterr(err, "line %zu: '%s' is neither a header this reader "
		    "knows nor a line of names for the %zu columns of numbers "
		    "(it has %zu fields)", h->colname_line, h->colname_text, ncol,
		    h->ncolname);
		return NULL;
	}
	if (h->ncolunit > 0 && h->ncolunit != ncol) {
		rc_seterr(err, "the line of units has %zu, the numbers %zu "
		    "columns", h->ncolunit, ncol);
		return NULL;
	}
	for (size_t k = 0; k < ncol; k++) {
		u[k][0] = '\0';
		if (h->ncolunit > 0)
			strcpy(u[k], h->colunit[k]);
		else if (h->ncolname > 0 && !rc__txt_name_unit(h->colname[k], u[k]))
			u[k][0] = '\0';
		if (h->ncolname > 0 && strcasecmp(h->colname[k], "index") == 0)
			idx = (int)k;
		if ((h->ncolname > 0 && strcasecmp(h->colname[k], "valid") == 0) ||
		    strcmp(u[k], "1/0") == 0)
			valid = (int)k;
	}
	if (idx < 0 && valid < 0 && ncol == 3 && rows >= 2) {
		size_t r = 0;
		int up = v[4] > v[1];

		while (r < rows && v[r * 3] == v[0] + (double)r &&
		    v[0] == floor(v[0]) && (r == 0 ||
		    (up ? v[r * 3 + 1] > v[r * 3 - 2] : v[r * 3 + 1] < v[r * 3 - 2])))
			r++;
		if (r == rows)
			idx = 0;
	}
	for (size_t k = 0; k < ncol; k++)
		if ((int)k != idx && (int)k != valid)
			use[m++] = k;
	if (m > 3 || m == 0) {
		rc_seterr(err, "%zu columns with a line of names or units, %d "
		    "of them an index or validity flag: read are a height column, "
		    "x-z or x-y-z columns", ncol, (idx >= 0) + (valid >= 0));
		return NULL;
	}
	if ((w = rc_malloc(rows * m * sizeof(*w), err)) == NULL)
		return NULL;
	for (size_t r = 0; r < rows; r++) {
		for (size_t k = 0; k < m; k++)
			w[r * m + k] = v[r * ncol + use[k]];
		if (valid >= 0) {
			double f = v[r * ncol + (size_t)valid];

			if (f != 0 && f != 1) {
				rc_seterr(err, "data line %zu: validity flag %g: want 0 "
				    "or 1", r + 1, f);
				goto out;
			}
			if (f == 0)
				w[r * m + m - 1] = NAN;
		}
	}
	strcpy(xu, u[use[0]]);
	strcpy(zu, u[use[m - 1]]);
	if (m == 3)
		strcpy(yu, u[use[1]]);
	if (m == 1) {
		/* one height column: a profile of unknown step (-L gives it) */
		double lx = o != NULL && o->have_l ? o->lx : 1;

		if ((g = rc__io_grid_alloc(rows, 1, lx, lx / (double)rows, err)) ==
		    NULL)
			goto out;
		memcpy(g->z, w, rows * sizeof(*w));
		g->periodic = 0;
		xu[0] = '\0';
	} else {
		for (size_t k = 0; k + 1 < m; k++)
			ulpw[k] = use[k] < TXT_MAXCOL ? ulp[use[k]] : 0;
		if (m == 3 && strcmp(xu, yu) != 0 && yu[0] != '\0') {
			rc_seterr(err, "x in '%s', y in '%s': give both columns in one "
			    "length unit", xu, yu);
			goto out;
		}
		if ((g = columns(w, m, rows, ulpw, o, err)) == NULL)
			goto out;
	}
	strcpy(g->unit, xu);
	/* heights in the lateral unit unless their column says */
	strcpy(g->z_unit, zu);
out:
	free(w);
	return g;
}

/* The assembled grid of a matrix: our header, Gwyddion's, or
 * SurfaceTopography's "h= w=" one. */
static rc_grid *
matrix(struct txt_header *h, double *v, size_t nx, size_t rows,
    const rc_read_opts *o, rc_err *err)
{
	double lx = 1, ly = 1;
	rc_grid *g;

	if (o != NULL && o->have_l) {
		lx = o->lx;
		ly = o->ly;
	}
	if ((h->have_nx && h->nx != nx) || (h->have_ny && h->ny != rows)) {
		rc_seterr(err, "header says %zux%zu, the data are %zux%zu",
		    h->have_nx ? h->nx : nx, h->have_ny ? h->ny : rows, nx, rows);
		return NULL;
	}
	if (h->have_hw && (h->w_cols != nx || h->h_rows != rows)) {
		rc_seterr(err, "header says h=%zu w=%zu (rows, columns), the data "
		    "are %zu rows of %zu", h->h_rows, h->w_cols, rows, nx);
		return NULL;
	}
	if (h->have_lx != h->have_ly) {
		rc_seterr(err, "header gives %s without %s", h->have_lx ? "lx" : "ly",
		    h->have_lx ? "ly" : "lx");
		return NULL;
	}
	if (h->have_lx) {
		lx = h->lx;
		ly = h->ly;
	}
	if (h->have_width != h->have_height) {
		rc_seterr(err, "Gwyddion header gives %s without %s",
		    h->have_width ? "Width" : "Height",
		    h->have_width ? "Height" : "Width");
		return NULL;
	}
	if (h->have_width && gwy_size(h, &lx, &ly, err) != 0)
		return NULL;
	if (h->have_pixel) {
		lx = (double)nx * h->pixel;
		ly = (double)rows * h->pixel;
		strcpy(h->unit, h->pixel_unit);
	}
	if ((g = rc__io_grid_alloc(nx, rows, lx, ly, err)) == NULL)
		return NULL;
	memcpy(g->z, v, nx * rows * sizeof(*v));
	if (h->have_zfac) {
		for (size_t k = 0; k < nx * rows; k++)
			g->z[k] *= h->zfac;
		strcpy(h->z_unit, h->zfac_unit);
	} else if (h->data_unit[0] != '\0' && h->z_unit[0] == '\0')
		strcpy(h->z_unit, h->data_unit);
	/* Our files say; a plain matrix is periodic by rule; Gwyddion's and
	 * SurfaceTopography's exports are measurements. */
	g->periodic = h->periodic >= 0 ? h->periodic :
	    !(h->gwy || h->have_hw || h->have_pixel);
	return g;
}

rc_grid *
rc__txt_read(rc_in *in, const rc_read_opts *o, rc_err *err)
{
	struct txt_header h = { .periodic = -1 };
	double *v = NULL, ulp[TXT_MAXCOL] = { 0 };
	size_t nv = 0, nx = 0, rows = 0, lineno = 1;
	rc_grid *g = NULL;
	int labelled, plain;

	if (rc__txt_preamble(in, &h, &lineno, err) != 0 ||
	    read_values(in, h.gwy, lineno, &v, &nv, &nx, &rows, ulp, err) != 0)
		goto fail;
	if (rows == 0) {
		rc_seterr(err, "no values (empty input or only comments)");
		goto fail;
	}
	/* the count of points, or of intervals (xy-2.txt's 23 for 24) */
	if (h.have_count && h.count != rows && h.count + 1 != rows) {
		rc_seterr(err, "the header gives %zu points, the data have %zu "
		    "lines", h.count, rows);
		goto fail;
	}
	labelled = h.ncolname > 0 || h.ncolunit > 0;
	plain = !h.own && !h.have_nx && !h.have_ny && !h.have_width && !h.gwy &&
	    !h.have_hw && !h.have_pixel;
	if (plain && (labelled || (nx == 1 && rows >= 2) ||
	    ((nx == 2 || nx == 3) && rows >= 4)))
		g = labelled_columns(&h, v, nx, rows, ulp, o, err);
	else if (labelled) {
		rc_seterr(err, "line %zu: a line of column names or units in a "
		    "file with a matrix header", h.colname_line);
		goto fail;
	} else
		g = matrix(&h, v, nx, rows, o, err);
	if (g == NULL)
		goto fail;
	/* what '#' header lines say has the last word */
	if (h.z_unit[0] != '\0')
		strcpy(g->z_unit, h.z_unit);
	if (h.unit[0] != '\0')
		strcpy(g->unit, h.unit);
	g->kind = (enum rc_kind)h.kind;
	for (size_t i = 0; i < h.nmeta; i++)
		if (rc_grid_meta_set(g, h.mkey[i], h.mval[i], err) != 0)
			goto fail;
	for (size_t i = 0; i < h.nhist; i++)
		if (rc_grid_history_add(g, h.hist[i], err) != 0)
			goto fail;
	if (h.filled != NULL && rc_grid_filled_parse(g, h.filled, err) != 0)
		goto fail;
	goto out;
fail:
	rc_grid_free(g);
	g = NULL;
out:
	rc__txt_header_free(&h);
	free(v);
	return g;
}

rc_grid *
rc__txt_read_mem(const char *text, size_t len, const rc_read_opts *o,
    rc_err *err)
{
	rc_grid *g = NULL;
	rc_in *in;
	FILE *fp;

	if (len == 0) {
		rc_seterr(err, "no values (an empty table)");
		return NULL;
	}
	if ((fp = fmemopen((void *)text, len, "rb")) == NULL) {
		rc_seterr(err, "%s", strerror(errno));
		return NULL;
	}
	if ((in = rc_malloc(sizeof(*in), err)) != NULL) {
		rc__in_init(in, fp);
		g = rc__txt_read(in, o, err);
		free(in);
	}
	fclose(fp);
	return g;
}
