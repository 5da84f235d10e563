/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_txt_head.c - the lines of a text file before its numbers: our
 * "# key = value" comments, Gwyddion's export header ("# Width: 10 um",
 * also with German labels "# Breite:", "# H\xc3\xb6he:", "# Kanal:", and
 * decimal commas), SurfaceTopography's matrix header ("h=650 w=650",
 * "pixel size=3.7e-07 m", "data unit=rad", "height conversion factor
 * (-> m)=6.3e-08"), Bruker Dektak's CSV export (the "Scan Parameters"
 * block up to "Scan Data"), a line of column names ("x in um,y in um",
 * "X_(microns),y1", HFM's "X;Y;valid"), a line of units ("um um",
 * "[mm];[mm];[1/0]") and a line giving the number of points.  Any other
 * text before the numbers is refused, naming what is read: a header that
 * is not understood would lose what it says (a scale, a unit).
 *
 * Lines of numbers are never held whole (a row may be longer than any
 * header): a line is looked at in the input buffer and left unread when
 * it starts with a number.
 */
#include "io_txt_internal.h"
#include "units.h"

#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

static int
push(char ***v, size_t n, const char *s)
{
	char **p = realloc(*v, (n + 1) * sizeof(**v));

	if (p == NULL)
		return -1;
	*v = p;
	return (p[n] = strdup(s)) == NULL ? -1 : 0;
}

/* A unit of at most 31 bytes into dst. */
static int
unit_copy(char *dst, const char *s, size_t lineno, rc_err *err)
{
	if (strlen(s) >= 32)
		return rc_seterr(err, "line %zu: unit longer than 31 characters", lineno);
	strcpy(dst, s);
	return 0;
}

/* Gwyddion's "# Key: value" header lines (English labels); anything else
 * is a free comment.  Width and Height are "NUMBER UNIT". */
static int
gwy_comment(struct txt_header *h, char *label, size_t lineno, rc_err *err)
{
	char *colon = strstr(label, ": "), *val, *e, q[64];
	const char *key = label;

	if (colon == NULL)
		return 0;
	*colon = '\0';
	for (val = colon + 2; *val == ' ' || *val == '\t'; val++)
		;
	for (e = val + strlen(val); e > val && isspace((unsigned char)e[-1]); e--)
		;
	*e = '\0';
	/* Gwyddion in a German locale (it keeps "Value units"); H\xc3\xb6he in
	 * UTF-8 or Latin-1. */
	if (strcmp(key, "Breite") == 0)
		key = "Width";
	else if (strcmp(key, "H\xc3\xb6he") == 0 || strcmp(key, "H\xf6he") == 0)
		key = "Height";
	else if (strcmp(key, "Kanal") == 0)
		key = "Channel";
	if (strcmp(key, "Width") == 0 || strcmp(key, "Height") == 0) {
		int w = key[0] == 'W';
		double *v = w ? &h->width : &h->height;
		char *end, *comma;

		/* a decimal comma (Gwyddion writes the locale's) */
		if ((comma = strchr(val, ',')) != NULL && comma > val &&
		    isdigit((unsigned char)comma[-1]) &&
		    isdigit((unsigned char)comma[1]))
			*comma = '.';
		*v = strtod(val, &end);
		if (end == val || !(*v > 0) || !isfinite(*v) ||
		    (*end != '\0' && *end != ' ' && *end != '\t'))
			return rc_seterr(err, "line %zu: %s '%s' is not a positive "
			    "length", lineno, key, rc__io_quote(q, sizeof(q), val,
			    strlen(val)));
		while (*end == ' ' || *end == '\t')
			end++;
		if (unit_copy(w ? h->wunit : h->hunit, end, lineno, err) != 0)
			return -1;
		*(w ? &h->have_width : &h->have_height) = 1;
		h->gwy = 1;
	} else if (strcmp(key, "Value units") == 0) {
		if (unit_copy(h->z_unit, val, lineno, err) != 0)
			return -1;
		h->gwy = 1;
	} else if (strcmp(key, "Lateral units") == 0) {
		if (unit_copy(h->unit, val, lineno, err) != 0)
			return -1;
		h->gwy = 1;
	} else if (strcmp(key, "Channel") == 0) {
		if (push(&h->mkey, h->nmeta, "channel") != 0)
			return rc_seterr(err, "out of memory");
		if (push(&h->mval, h->nmeta, val) != 0) {
			free(h->mkey[h->nmeta]);
			return rc_seterr(err, "out of memory");
		}
		h->nmeta++;
		h->gwy = 1;
	}
	return 0;
}

/* A "# key = value" comment we know; anything else is a free comment. */
static int
comment(struct txt_header *h, char *line, size_t lineno, rc_err *err)
{
	char *key, *eq, *val, *e, q[64];
	int r;

	if (strcmp(line, RC_TXT_MAGIC) == 0)
		h->own = 1;
	for (key = line + 1; *key == ' ' || *key == '\t'; key++)
		;
	if ((eq = strstr(key, " = ")) == NULL)
		return gwy_comment(h, key, lineno, err);
	*eq = '\0';
	val = eq + 3;
	for (e = val + strlen(val); e > val && isspace((unsigned char)e[-1]); e--)
		;
	*e = '\0';
	if (strcmp(key, "nx") == 0 || strcmp(key, "ny") == 0) {
		size_t *v = key[1] == 'x' ? &h->nx : &h->ny;
		int *have = key[1] == 'x' ? &h->have_nx : &h->have_ny;

		if (*have)
			return rc_seterr(err, "line %zu: %s given twice", lineno, key);
		if (rc__parse_size(val, v) != 0)
			return rc_seterr(err, "line %zu: %s = '%s' is not a size",
			    lineno, key, rc__io_quote(q, sizeof(q), val, strlen(val)));
		*have = 1;
	} else if (strcmp(key, "lx") == 0 || strcmp(key, "ly") == 0) {
		double *v = key[1] == 'x' ? &h->lx : &h->ly;
		int *have = key[1] == 'x' ? &h->have_lx : &h->have_ly;

		if (*have)
			return rc_seterr(err, "line %zu: %s given twice", lineno, key);
		if (rc__parse_double(val, v) != 0)
			return rc_seterr(err, "line %zu: %s = '%s' is not a number",
			    lineno, key, rc__io_quote(q, sizeof(q), val, strlen(val)));
		*have = 1;
	} else if (strcmp(key, "unit") == 0) {
		if (strlen(val) >= sizeof(h->unit))
			return rc_seterr(err, "line %zu: unit longer than %zu characters",
			    lineno, sizeof(h->unit) - 1);
		strcpy(h->unit, val);
	} else if (strcmp(key, "z_unit") == 0) {
		if (strlen(val) >= sizeof(h->z_unit))
			return rc_seterr(err, "line %zu: z_unit longer than %zu characters",
			    lineno, sizeof(h->z_unit) - 1);
		strcpy(h->z_unit, val);
	} else if (strcmp(key, "periodic") == 0) {
		if (strcmp(val, "0") != 0 && strcmp(val, "1") != 0)
			return rc_seterr(err, "line %zu: periodic = '%s': want 0 or 1",
			    lineno, rc__io_quote(q, sizeof(q), val, strlen(val)));
		h->periodic = val[0] == '1';
	} else if (strcmp(key, "kind") == 0) {
		if ((r = rc_kind_parse(val)) < 0)
			return rc_seterr(err, "line %zu: unknown kind '%s'", lineno,
			    rc__io_quote(q, sizeof(q), val, strlen(val)));
		h->kind = r;
	} else if (strncmp(key, "meta.", 5) == 0 && key[5] != '\0') {
		if (push(&h->mkey, h->nmeta, key + 5) != 0)
			return rc_seterr(err, "out of memory");
		if (push(&h->mval, h->nmeta, val) != 0) {
			free(h->mkey[h->nmeta]);
			return rc_seterr(err, "out of memory");
		}
		h->nmeta++;
	} else if (strcmp(key, "history") == 0) {
		if (push(&h->hist, h->nhist, val) != 0)
			return rc_seterr(err, "out of memory");
		h->nhist++;
	} else if (strcmp(key, "filled") == 0) {
		if (h->filled != NULL)
			return rc_seterr(err, "line %zu: filled given twice", lineno);
		if ((h->filled = strdup(val)) == NULL)
			return rc_seterr(err, "out of memory");
	}
	return 0;
}

/* Blanks, and the comma and semicolon of CSV, separate values. */
static int
is_sep(int c)
{
	return c == ',' || c == ';' || c == ' ' || c == '\t' || c == '\r' ||
	    c == '\v' || c == '\f';
}

/* Does the line p[0..n) (no newline) start with a number?  *ntok its
 * fields, *one_integer whether it is one unsigned integer alone. */
static int
numbers_line(const unsigned char *p, size_t n, size_t *ntok, int *one_integer)
{
	size_t i = 0, k = 0;
	char tok[64];

	*one_integer = 0;
	while (i < n) {
		size_t s;

		while (i < n && is_sep(p[i]))
			i++;
		if (i == n)
			break;
		for (s = i; i < n && !is_sep(p[i]); i++)
			;
		if (k == 0) {
			double d;

			if (i - s >= sizeof(tok))
				return 0;
			memcpy(tok, p + s, i - s);
			tok[i - s] = '\0';
			if (rc__parse_double(tok, &d) != 0)
				return 0;
			*one_integer = strspn(tok, "0123456789") == i - s;
		}
		k++;
	}
	*ntok = k;
	if (k != 1)
		*one_integer = 0;
	return k > 0;
}

/* Is w the name of a length unit ("um", "µm", "microns", "Micrometer",
 * "mm", ...)?  Its canonical spelling into out. */
static int
unit_word(const char *w, char out[32])
{
	static const struct { const char *name, *unit; } longname[] = {
		{ "microns", "um" }, { "micrometer", "um" }, { "micrometers", "um" },
		{ "micrometre", "um" }, { "micrometres", "um" },
		{ "millimeter", "mm" }, { "millimeters", "mm" },
		{ "millimetre", "mm" }, { "millimetres", "mm" },
		{ "nanometer", "nm" }, { "nanometers", "nm" },
		{ "nanometre", "nm" }, { "nanometres", "nm" },
		{ "meter", "m" }, { "meters", "m" }, { "metre", "m" },
		{ "metres", "m" },
	};
	int e;

	if (strlen(w) >= 32)
		return 0;
	if (rc_unit_length_exp(w, &e)) {
		snprintf(out, 32, "%s", rc_unit_canonical(w));
		return 1;
	}
	for (size_t k = 0; k < sizeof(longname) / sizeof(longname[0]); k++)
		if (strcasecmp(w, longname[k].name) == 0) {
			strcpy(out, longname[k].unit);
			return 1;
		}
	return 0;
}

/* The first word of a column name that is a length unit ("x in µm",
 * "X_(microns)", "Lateral um", "[mm]"); 0 if none. */
int
rc__txt_name_unit(const char *name, char out[32])
{
	const unsigned char *p = (const unsigned char *)name;

	while (*p != '\0') {
		char w[32];
		size_t n = 0;

		while (*p != '\0' && !isalpha(*p) && *p < 0x80)
			p++;
		while (isalpha(*p) || *p >= 0x80) {
			if (n + 1 < sizeof(w))
				w[n++] = (char)*p;
			p++;
		}
		w[n] = '\0';
		if (n > 0 && unit_word(w, out))
			return 1;
	}
	return 0;
}

/* The fields of a header line: split at ',' and ';' if it has one, else
 * at blanks; blanks around a field dropped, trailing empty fields too.
 * Returns their number (at most max are stored, each cut to cap - 1). */
static size_t
fields(const char *t, char (*f)[64], size_t max)
{
	int csv = strpbrk(t, ",;") != NULL;
	size_t n = 0, nonempty = 0;
	const char *p = t;

	for (;;) {
		const char *s, *e;

		if (!csv)
			while (*p == ' ' || *p == '\t')
				p++;
		if (!csv && *p == '\0')
			break;
		s = p;
		while (*p != '\0' && (csv ? (*p != ',' && *p != ';') :
		    (*p != ' ' && *p != '\t')))
			p++;
		for (e = p; e > s && isspace((unsigned char)e[-1]); e--)
			;
		while (s < e && isspace((unsigned char)*s))
			s++;
		if (n < max)
			snprintf(f[n], 64, "%.*s", (int)(e - s > 63 ? 63 : e - s), s);
		n++;
		if (e > s)
			nonempty = n;
		if (*p == '\0')
			break;
		p++;
	}
	return nonempty;
}

/* A line of units, one per column ("um um", "[mm];[mm];[1/0]": a bracket
 * around each is dropped; "1/0" is the unit of a validity flag). */
static int
units_line(struct txt_header *h, const char *t)
{
	char f[TXT_MAXCOL + 1][64], u[TXT_MAXCOL][32];
	size_t n = fields(t, f, TXT_MAXCOL + 1);

	if (n == 0 || n > TXT_MAXCOL)
		return 0;
	for (size_t k = 0; k < n; k++) {
		char *s = f[k];
		size_t len = strlen(s);

		if (len >= 2 && s[0] == '[' && s[len - 1] == ']') {
			s[len - 1] = '\0';
			s++;
		}
		if (strcmp(s, "1/0") == 0)
			strcpy(u[k], "1/0");
		else if (!unit_word(s, u[k]))
			return 0;
	}
	memcpy(h->colunit, u, sizeof(u));
	h->ncolunit = n;
	return 1;
}

/* The value after "key =" at the start of t, or NULL. */
static const char *
after_key(const char *t, const char *key)
{
	size_t n = strlen(key);

	if (strncasecmp(t, key, n) != 0)
		return NULL;
	for (t += n; *t == ' ' || *t == '\t'; t++)
		;
	if (*t != '=')
		return NULL;
	for (t++; *t == ' ' || *t == '\t'; t++)
		;
	return t;
}

/* SurfaceTopography's matrix header: 1 if t is one of its lines, 0 if
 * not, -1 (err set) if it is one with a bad value. */
static int
matrix_line(struct txt_header *h, const char *t, size_t lno, rc_err *err)
{
	const char *v;
	char *end, q[64];
	size_t a, b;
	int pos = -1;

	if (sscanf(t, "h = %zu w = %zu%n", &a, &b, &pos) == 2 && pos > 0 &&
	    t[pos] == '\0' && t[strspn(t, "hw= 0123456789\t")] == '\0') {
		h->have_hw = 1;
		h->h_rows = a;
		h->w_cols = b;
		return 1;
	}
	if ((v = after_key(t, "pixel size")) != NULL) {
		h->pixel = strtod(v, &end);
		while (*end == ' ' || *end == '\t')
			end++;
		if (end == v || !(h->pixel > 0) || !isfinite(h->pixel) ||
		    !unit_word(end, h->pixel_unit))
			return rc_seterr(err, "line %zu: pixel size '%s' is not a "
			    "positive length with its unit", lno,
			    rc__io_quote(q, sizeof(q), v, strlen(v)));
		h->have_pixel = 1;
		return 1;
	}
	if ((v = after_key(t, "data unit")) != NULL) {
		if (strlen(v) >= sizeof(h->data_unit))
			return rc_seterr(err, "line %zu: data unit longer than %zu "
			    "characters", lno, sizeof(h->data_unit) - 1);
		strcpy(h->data_unit, v);
		return 1;
	}
	if (strncasecmp(t, "height conversion factor (->", 28) == 0) {
		const char *u = t + 28, *close;
		char unit[32];

		while (*u == ' ')
			u++;
		if ((close = strchr(u, ')')) == NULL || close - u >= 32)
			return 0;
		snprintf(unit, sizeof(unit), "%.*s", (int)(close - u), u);
		if ((v = after_key(close, ")")) == NULL)
			return 0;
		h->zfac = strtod(v, &end);
		if (end == v || *end != '\0' || !isfinite(h->zfac) ||
		    h->zfac == 0 || !unit_word(unit, h->zfac_unit))
			return rc_seterr(err, "line %zu: height conversion factor "
			    "'%s' is not a number to a length unit", lno,
			    rc__io_quote(q, sizeof(q), t, strlen(t)));
		h->have_zfac = 1;
		return 1;
	}
	return 0;
}

/* The pending text line, which directly precedes the numbers or a line
 * of units, is a line of column names, unless a field of it is a number
 * the reader does not take: one that strtod reads whole (beyond the
 * range of a double: 1e400) or up to a '#' (MSVC's 1.#QNAN, -1.#INF),
 * which as "names" would drop the profile's first point without a word.
 * A name that starts with digits ("2D height") is still a name. */
static int
set_names(struct txt_header *h, const char *t, size_t lno, rc_err *err)
{
	char q[64], *end;

	h->ncolname = fields(t, h->colname, TXT_MAXCOL);
	for (size_t k = 0; k < h->ncolname && k < TXT_MAXCOL; k++) {
		const char *f = h->colname[k];

		(void)strtod(f, &end);
		if (end != f && (*end == '\0' || *end == '#'))
			return rc_seterr(err, "line %zu: '%s' is not a number this "
			    "reader takes (beyond the range of a double, or a "
			    "spelling of NaN or infinity other than nan, inf; a "
			    "missing point is written NaN)", lno,
			    rc__io_quote(q, sizeof(q), f, strlen(f)));
	}
	h->colname_line = lno;
	rc__io_quote(h->colname_text, sizeof(h->colname_text), t, strlen(t));
	return 0;
}

static int
unknown_line(const char *t, size_t lno, rc_err *err)
{
	char q[64];

	return rc_seterr(err, "line %zu: '%s' is a header line this reader "
	    "does not know (it reads Gwyddion's text export, "
	    "SurfaceTopography's 'h= w=' matrix, Dektak's CSV, one line of "
	    "column names and one of units before x-z or x-y-z columns, and "
	    "'# lx = ...' lines as surf(5) describes); make it a '#' comment "
	    "or say what it means with those lines", lno,
	    rc__io_quote(q, sizeof(q), t, strlen(t)));
}

int
rc__txt_preamble(rc_in *in, struct txt_header *h, size_t *lineno,
    rc_err *err)
{
	char *line, *pending = NULL, q[64];
	size_t lno = 1, pending_line = 0, len;
	int dektak_block = 0, first = 1, r = -1, k;

	if ((line = rc_malloc(RC_HEADER_MAX + 1, err)) == NULL)
		return -1;
	for (;; lno++) {
		const unsigned char *p;
		size_t n = rc__in_peek(in, RC_IN_BUFSIZE, &p), e, b, ntok;
		int one_int;
		char *t;

		if (n == 0)
			break;
		for (e = 0; e < n && p[e] != '\n'; e++)
			;
		for (b = 0; b < e && isspace(p[b]); b++)
			;
		if (!dektak_block && b < e && p[b] != '#' &&
		    numbers_line(p + b, e - b, &ntok, &one_int)) {
			size_t e2, nt2;
			int oi2;

			/* "23" after a line of units, then 23 lines of x z */
			if (!one_int || (pending == NULL && h->ncolunit == 0) ||
			    h->have_count || e == n)
				break;
			for (e2 = e + 1; e2 < n && p[e2] != '\n'; e2++)
				;
			if (!numbers_line(p + e + 1, e2 - e - 1, &nt2, &oi2) ||
			    nt2 < 2 || nt2 > 3)
				break;
			h->have_count = 1;
			h->count = strtoull((const char *)p + b, NULL, 10);
			(void)rc__in_line(in, line, RC_HEADER_MAX + 1, &len);
			continue;
		}
		if (rc__in_line(in, line, RC_HEADER_MAX + 1, &len) < 0) {
			rc_seterr(err, "line %zu: longer than %zu bytes and not "
			    "numbers", lno, RC_HEADER_MAX);
			goto out;
		}
		if (strlen(line) != len) {
			rc_seterr(err, "line %zu: NUL byte: not a text file", lno);
			goto out;
		}
		t = rc__header_trim(line);
		if (*t == '\0')
			continue;
		if (*t == '#') {
			if (comment(h, t, lno, err) != 0)
				goto out;
			continue;
		}
		if (dektak_block) {
			if (strncmp(t, "Scan Data", 9) == 0)
				dektak_block = 0;
			continue;
		}
		if (first && strcmp(t, "Scan Parameters") == 0) {
			h->dektak = dektak_block = 1;
			first = 0;
			continue;
		}
		first = 0;
		if ((k = matrix_line(h, t, lno, err)) < 0)
			goto out;
		if (k > 0)
			continue;
		if (units_line(h, t)) {
			if (pending != NULL) {
				if (set_names(h, pending, pending_line, err) != 0)
					goto out;
				free(pending);
				pending = NULL;
			}
			continue;
		}
		if (pending != NULL) {
			unknown_line(pending, pending_line, err);
			goto out;
		}
		if ((pending = strdup(t)) == NULL) {
			rc_seterr(err, "out of memory");
			goto out;
		}
		pending_line = lno;
	}
	if (rc__in_check(in, err) != 0)
		goto out;
	if (dektak_block) {
		rc_seterr(err, "a Dektak export (first line 'Scan Parameters') "
		    "without its 'Scan Data' line: no profile in it");
		goto out;
	}
	if (pending != NULL) {
		const unsigned char *p;

		if (rc__in_peek(in, 1, &p) == 0) {
			rc_seterr(err, "line %zu: '%s' is text and no numbers "
			    "follow: not a height file (read are number matrices, "
			    "x-z and x-y-z columns with or without a line of column "
			    "names, Gwyddion's and SurfaceTopography's text exports, "
			    "Dektak's CSV)", pending_line, rc__io_quote(q, sizeof(q),
			    pending, strlen(pending)));
			goto out;
		}
		if (set_names(h, pending, pending_line, err) != 0)
			goto out;
	}
	*lineno = lno;
	r = 0;
out:
	free(pending);
	free(line);
	return r;
}

void
rc__txt_header_free(struct txt_header *h)
{
	for (size_t i = 0; i < h->nmeta; i++) {
		free(h->mkey[i]);
		free(h->mval[i]);
	}
	for (size_t i = 0; i < h->nhist; i++)
		free(h->hist[i]);
	free(h->mkey);
	free(h->mval);
	free(h->hist);
	free(h->filled);
}
