/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_nc.c - netCDF in the convention of the contact.engineering
 * ecosystem (SurfaceTopography's NC reader and writer).
 *
 * Dimensions x (nx) and y (ny); variable heights(x, y), so the y index
 * runs fastest in the file while our grid runs x fastest (we transpose);
 * heights(x) alone is a line scan (an nx x 1 grid, ly one spacing).
 * Optional coordinate variables x(x) and y(y) (pixel centres) whose
 * attributes carry the physical size (length), the unit (unit, which
 * SurfaceTopography writes and reads on x, y and heights; length_unit, of
 * older files, when unit is absent; one unit for lengths and heights) and
 * the periodic flag (periodic, non-zero = periodic; absent = not
 * periodic).  Missing points: NaN, the heights' _FillValue or
 * missing_value, netCDF's default fill of the type when there is no
 * _FillValue (points never written: 9.97e36 for double), and the points
 * where SurfaceTopography's variable mask (same dimensions) is non-zero.
 * We write unit and length_unit, NaN and mask = 1 at missing points.  We
 * write the classic 64-bit
 * offset format that SurfaceTopography's default writer (scipy) writes
 * and reads; we read any netCDF the library opens (also netCDF-4).
 * Heights are written as stored: when the grid's height unit differs from
 * its lateral one, the lengths are converted to the height unit.
 * A file without heights (netCDF-4 or plain HDF5 data sets) is read as
 * channels, one per 1-D or 2-D numeric variable (read_data_sets).
 *
 * libnetcdf is loaded when a netCDF file is read or written (dlopen), not
 * when a program starts: with HDF5, curl and their TLS and Kerberos
 * libraries it is 40 of the 54 shared libraries a tool would otherwise
 * map and relocate at every start (measured on a loaded 2-core machine:
 * a program that links them all starts in 50-80 ms, without them in
 * 15-30 ms), which every run in a pipeline and every restart for passive
 * waiting (threads.h) would pay.  RTLD_NODELETE keeps it mapped once
 * loaded: HDF5 registers exit handlers.
 */
#include "io_internal.h"

#include <dlfcn.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <netcdf.h>
#include <netcdf_mem.h>

/* The shared library to load: its soname, found by the Makefile, else
 * Debian 12's (that of libnetcdf19, which the error names; not the -dev
 * package's libnetcdf.so symlink). */
#ifndef RC_NETCDF_SONAME
#define RC_NETCDF_SONAME "libnetcdf.so.19"
#endif

/* The functions of libnetcdf used here, typed from its header. */
#define NC_FUNCS(X) \
	X(strerror) X(inq_att) X(get_att_double) X(get_att_text) \
	X(open_mem) X(inq_varid) X(inq_var) X(inq_vardimid) X(inq_dimlen) \
	X(get_var_double) X(close) X(create_mem) X(def_dim) X(def_var) \
	X(put_att_double) X(put_att_int) X(put_att_text) X(_enddef) \
	X(put_var_double) X(close_memio) X(abort) X(put_var_uchar) \
	X(inq_nvars) X(inq_dimname)

struct ncapi {
	void *handle;
#define NC_MEMBER(f) __typeof__(nc_##f) *f;
	NC_FUNCS(NC_MEMBER)
#undef NC_MEMBER
};

static int
ncapi_open(struct ncapi *api, rc_err *err)
{
	const char *missing = NULL;

	api->handle = dlopen(RC_NETCDF_SONAME, RTLD_NOW | RTLD_LOCAL |
	    RTLD_NODELETE);
	if (api->handle == NULL)
		return rc_seterr(err, "netCDF: cannot load %s (%s); install "
		    "the Debian package libnetcdf19", RC_NETCDF_SONAME, dlerror());
	/* the POSIX idiom: a function pointer written through void * */
#define NC_RESOLVE(f) \
	if ((*(void **)&api->f = dlsym(api->handle, "nc_" #f)) == NULL && \
	    missing == NULL) \
		missing = "nc_" #f;
	NC_FUNCS(NC_RESOLVE)
#undef NC_RESOLVE
	if (missing != NULL) {
		dlclose(api->handle);
		api->handle = NULL;
		return rc_seterr(err, "netCDF: %s has no %s", RC_NETCDF_SONAME,
		    missing);
	}
	return 0;
}

static void
ncapi_close(struct ncapi *api)
{
	if (api->handle != NULL)
		dlclose(api->handle);
}

static int
nc_fail(const struct ncapi *api, rc_err *err, const char *what, int status)
{
	return rc_seterr(err, "netCDF: %s: %s", what, api->strerror(status));
}

/* Attribute att of variable name as a number / text; 0 if present. */
static int
att_double(const struct ncapi *api, int nc, int var, const char *att,
    double *v)
{
	size_t len;
	nc_type t;

	if (api->inq_att(nc, var, att, &t, &len) != NC_NOERR || len != 1 ||
	    t == NC_CHAR || t == NC_STRING)
		return -1;
	return api->get_att_double(nc, var, att, v) == NC_NOERR ? 0 : -1;
}

static int
att_text(const struct ncapi *api, int nc, int var, const char *att,
    char *buf, size_t cap)
{
	size_t len;
	nc_type t;

	if (api->inq_att(nc, var, att, &t, &len) != NC_NOERR || t != NC_CHAR ||
	    len >= cap)
		return -1;
	if (api->get_att_text(nc, var, att, buf) != NC_NOERR)
		return -1;
	buf[len] = '\0';
	return 0;
}

/* The classic header (CDF-1, -2, -5) walked before libnetcdf sees it:
 * libnetcdf allocates what the header's counts claim, so every count must
 * be covered by the bytes that follow it (each element takes at least
 * one, or four, bytes).  A header that passes costs no more memory than
 * the file's size. */
struct hcur {
	const unsigned char *p, *end;
	int wide;	/* CDF-5: 64-bit counts */
};

static int
h_count(struct hcur *c, uint64_t *v)
{
	size_t w = c->wide ? 8 : 4;

	if ((size_t)(c->end - c->p) < w)
		return -1;
	*v = 0;
	for (size_t k = 0; k < w; k++)
		*v = *v << 8 | c->p[k];
	c->p += w;
	return 0;
}

static int
h_skip(struct hcur *c, uint64_t n, uint64_t unit)
{
	uint64_t bytes;

	if (unit != 0 && n > (uint64_t)(c->end - c->p) / unit)
		return -1;
	bytes = (n * unit + 3) & ~(uint64_t)3;	/* padded to 4 */
	if (bytes > (uint64_t)(c->end - c->p))
		return -1;
	c->p += bytes;
	return 0;
}

static int
h_u32(struct hcur *c, uint32_t *v)
{
	if (c->end - c->p < 4)
		return -1;
	*v = (uint32_t)c->p[0] << 24 | (uint32_t)c->p[1] << 16 |
	    (uint32_t)c->p[2] << 8 | c->p[3];
	c->p += 4;
	return 0;
}

static int
h_name(struct hcur *c)
{
	uint64_t n;

	return h_count(c, &n) != 0 ? -1 : h_skip(c, n, 1);
}

/* An attribute list (tag already read as 0x0C or ABSENT). */
static int
h_atts(struct hcur *c)
{
	static const unsigned size[13] = { 0, 1, 1, 2, 4, 4, 8, 1, 2, 4, 8, 8 };
	uint32_t tag, type;
	uint64_t n, m;

	if (h_u32(c, &tag) != 0 || h_count(c, &n) != 0)
		return -1;
	if (tag == 0)
		return n == 0 ? 0 : -1;
	if (tag != 0x0C || n > (uint64_t)(c->end - c->p) / 4)
		return -1;
	for (uint64_t k = 0; k < n; k++)
		if (h_name(c) != 0 || h_u32(c, &type) != 0 || type < 1 ||
		    type > 11 || h_count(c, &m) != 0 || h_skip(c, m, size[type]))
			return -1;
	return 0;
}

/* *htype: the type of the variable named heights (0 if none). */
static int
classic_header_ok(const unsigned char *buf, size_t len, uint32_t *htype)
{
	struct hcur c = { buf + 4, buf + len, buf[3] == 5 };
	uint32_t tag, type;
	uint64_t n, m, v;
	const unsigned char *name;

	if (h_count(&c, &v) != 0)	/* numrecs */
		return 0;
	/* Dimensions. */
	if (h_u32(&c, &tag) != 0 || h_count(&c, &n) != 0 ||
	    (tag != 0x0A && !(tag == 0 && n == 0)) ||
	    n > (uint64_t)(c.end - c.p) / 4)
		return 0;
	for (uint64_t k = 0; k < n; k++)
		if (h_name(&c) != 0 || h_count(&c, &v) != 0)
			return 0;
	if (h_atts(&c) != 0)
		return 0;
	/* Variables: name, dimension ids, attributes, type, size, begin. */
	if (h_u32(&c, &tag) != 0 || h_count(&c, &n) != 0 ||
	    (tag != 0x0B && !(tag == 0 && n == 0)) ||
	    n > (uint64_t)(c.end - c.p) / 4)
		return 0;
	*htype = 0;
	for (uint64_t k = 0; k < n; k++) {
		name = c.p;
		if (h_name(&c) != 0 || h_count(&c, &m) != 0 ||
		    h_skip(&c, m, c.wide ? 8 : 4) != 0 || h_atts(&c) != 0 ||
		    h_u32(&c, &type) != 0 || h_count(&c, &v) != 0 ||
		    h_skip(&c, 1, buf[3] == 1 ? 4 : 8) != 0)
			return 0;
		/* the name: its count (4 or 8 bytes), then its bytes */
		if (memcmp(name + (c.wide ? 4 : 0), "\0\0\0\7heights", 11) == 0)
			*htype = type;
	}
	return 1;
}

/* The value netCDF gives a point never written in a variable of type t
 * without _FillValue (NaN for types whose default fill is no marker:
 * bytes, by netCDF's convention, and 64-bit integers, which a double
 * would not hold exactly). */
static double
default_fill(nc_type t)
{
	switch (t) {
	case NC_DOUBLE: return NC_FILL_DOUBLE;
	case NC_FLOAT: return NC_FILL_FLOAT;
	case NC_INT: return NC_FILL_INT;
	case NC_SHORT: return NC_FILL_SHORT;
	case NC_UINT: return NC_FILL_UINT;
	case NC_USHORT: return NC_FILL_USHORT;
	default: return NAN;
	}
}

/* A variable of numbers, 1-D or 2-D: its type and shape (ny = 1 for
 * 1-D), checked against the bytes of the file; name for messages. */
static int
var_shape(const struct ncapi *api, int nc, int v, const char *name,
    size_t len, int classic, nc_type *type, int *ndims, int dims[2],
    size_t *nx, size_t *ny, rc_err *err)
{
	int st;

	if ((st = api->inq_var(nc, v, NULL, type, ndims, NULL, NULL)) != NC_NOERR)
		return nc_fail(api, err, name, st);
	if (*type == NC_CHAR || *type == NC_STRING || *type >= NC_VLEN)
		return rc_seterr(err, "netCDF: %s holds %s, not numbers", name,
		    *type == NC_CHAR ? "characters" : *type == NC_STRING ?
		    "strings" : "a user-defined type");
	if (*ndims != 1 && *ndims != 2)
		return rc_seterr(err, "netCDF: %s has %d dimensions, not 2 (a map) "
		    "or 1 (a line scan)", name, *ndims);
	*ny = 1;
	if ((st = api->inq_vardimid(nc, v, dims)) != NC_NOERR ||
	    (st = api->inq_dimlen(nc, dims[0], nx)) != NC_NOERR ||
	    (*ndims == 2 && (st = api->inq_dimlen(nc, dims[1], ny)) != NC_NOERR))
		return nc_fail(api, err, name, st);
	if (*nx == 0 || *ny == 0)
		return rc_seterr(err, "netCDF: %s has no points (%zu x %zu)", name,
		    *nx, *ny);
	if (rc_grid_check_shape(*nx, *ny, 1, 1, err) != 0)
		return -1;
	/* A classic file stores every value; a netCDF-4 one may compress,
	 * by at most about 1000 (deflate).  Either way a lying header costs
	 * no memory. */
	if (classic ? *nx * *ny > len : *nx * *ny / 1024 > len)
		return rc_seterr(err, "netCDF: %s of %zux%zu cannot fit in %zu "
		    "bytes", name, *nx, *ny, len);
	return 0;
}

/* Variable v (nx x ny in the file, y fastest) into g (x fastest), its
 * _FillValue, missing_value or netCDF's default fill as NaN; t holds
 * nx * ny doubles. */
static int
var_values(const struct ncapi *api, int nc, int v, const char *name,
    nc_type type, double *t, rc_grid *g, rc_err *err)
{
	size_t nx = g->nx, ny = g->ny;
	double fill, missing;
	int st;

	if ((st = api->get_var_double(nc, v, t)) != NC_NOERR)
		return nc_fail(api, err, name, st);
	if (att_double(api, nc, v, "_FillValue", &fill) != 0)
		fill = default_fill(type);
	if (att_double(api, nc, v, "missing_value", &missing) != 0)
		missing = NAN;
	for (size_t i = 0; i < nx; i++)
		for (size_t j = 0; j < ny; j++) {
			double z = t[i * ny + j];

			g->z[j * nx + i] = z == fill || z == missing ? NAN : z;
		}
	return 0;
}

/* NaN points of g missing (valid = 0). */
static int
mark_missing(rc_grid *g, rc_err *err)
{
	size_t n = g->nx * g->ny;

	for (size_t k = 0; k < n; k++)
		if (isnan(g->z[k])) {
			if (g->valid == NULL) {
				if ((g->valid = rc_malloc(n, err)) == NULL)
					return -1;
				memset(g->valid, 1, n);
			}
			g->valid[k] = 0;
		}
	return 0;
}

/* A file without heights (a netCDF-4 or plain HDF5 file of data sets):
 * every 1-D or 2-D numeric variable that is not a coordinate variable
 * (x(x)) is a channel titled by its name, in the file's order.  No
 * physical size (-L or 1, as .npy); the values' unit is the variable's
 * attribute unit or units, else they are unitless ("1"), which no length
 * reading takes for heights unless --z-unit says what they are. */
static int
read_data_sets(const struct ncapi *api, int nc, size_t len, int classic, const rc_read_opts *o, rc_chanset *s,
    rc_err *err)
{
	double lx = o != NULL && o->have_l ? o->lx : 1;
	double ly = o != NULL && o->have_l ? o->ly : 1;
	int nvars, st, ndims, dims[NC_MAX_VAR_DIMS];
	size_t before = s->n, nx, ny;
	char name[NC_MAX_NAME + 1], dname[NC_MAX_NAME + 1], zunit[64];
	nc_type type;

	if ((st = api->inq_nvars(nc, &nvars)) != NC_NOERR)
		return nc_fail(api, err, "variables", st);
	for (int v = 0; v < nvars; v++) {
		double *t;
		rc_grid *g;

		if ((st = api->inq_var(nc, v, name, &type, &ndims, dims, NULL)) !=
		    NC_NOERR)
			return nc_fail(api, err, "variables", st);
		if (type == NC_CHAR || type == NC_STRING || type >= NC_VLEN ||
		    (ndims != 1 && ndims != 2))
			continue;
		if (ndims == 1 && api->inq_dimname(nc, dims[0], dname) == NC_NOERR &&
		    strcmp(dname, name) == 0)
			continue;	/* a coordinate variable */
		if (api->inq_dimlen(nc, dims[0], &nx) == NC_NOERR && (nx == 0 ||
		    (ndims == 2 && api->inq_dimlen(nc, dims[1], &ny) == NC_NOERR &&
		    ny == 0)))
			continue;	/* an unlimited dimension never written */
		if (var_shape(api, nc, v, name, len, classic, &type, &ndims, dims,
		    &nx, &ny, err) != 0)
			return -1;
		if ((t = rc_malloc(nx * ny * sizeof(double), err)) == NULL)
			return -1;
		if ((g = rc__io_grid_alloc(nx, ny, lx, ly, err)) == NULL) {
			free(t);
			return -1;
		}
		if (att_text(api, nc, v, "unit", zunit, sizeof(zunit)) != 0 &&
		    att_text(api, nc, v, "units", zunit, sizeof(zunit)) != 0)
			strcpy(zunit, "1");
		if (rc__io_set_unit(g->z_unit, zunit, err) != 0 ||
		    var_values(api, nc, v, name, type, t, g, err) != 0 ||
		    mark_missing(g, err) != 0) {
			free(t);
			rc_grid_free(g);
			return -1;
		}
		free(t);
		if (rc__chanset_add(s, g, name, err) != 0)
			return -1;
	}
	if (s->n == before)
		return rc_seterr(err, "netCDF file has neither the variable "
		    "'heights' (the contact.engineering convention) nor a 1-D or "
		    "2-D numeric variable");
	return 0;
}

/* Long: the netCDF variables and attributes in the order the library
 * hands them out, each checked where read. */
int
rc__nc_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, rc_err *err)
{
	int nc, hv, xv = -1, yv = -1, mv, ndims, dims[2], st, r = -1;
	size_t nx, ny, n;
	double lx = 1, ly = 1, per = 0, *t = NULL;
	char unit[64] = "", zunit[64] = "";
	int classic = len >= 3 && memcmp(buf, "CDF", 3) == 0;
	nc_type type;
	uint32_t htype = 0;
	rc_grid *g = NULL;
	struct ncapi lib, *api = &lib;

	if (o != NULL && o->have_l) {
		lx = o->lx;
		ly = o->ly;
	}
	if (classic && (len < 4 || !classic_header_ok(buf, len, &htype)))
		return rc_seterr(err, "not a readable netCDF file: corrupt or "
		    "truncated header");
	/* Before libnetcdf, which refuses some such files with a bare
	 * "Operation not permitted". */
	if (classic && htype == NC_CHAR)
		return rc_seterr(err, "netCDF: heights holds characters, not "
		    "numbers");
	if (ncapi_open(api, err) != 0)
		return -1;
	/* netCDF-4 is HDF5, whose links and storage can name other files */
	if (!classic && rc__h5_self_contained(api->handle, buf, len, err) != 0) {
		ncapi_close(api);
		return -1;
	}
	if ((st = api->open_mem("input.nc", NC_NOWRITE, len, (void *)buf, &nc)) !=
	    NC_NOERR) {
		rc_seterr(err, "not a readable netCDF file: %s", api->strerror(st));
		ncapi_close(api);
		return -1;
	}
	if (api->inq_varid(nc, "heights", &hv) != NC_NOERR) {
		r = read_data_sets(api, nc, len, classic, o, s, err);
		goto out;
	}
	if (var_shape(api, nc, hv, "heights", len, classic, &type, &ndims, dims,
	    &nx, &ny, err) != 0)
		goto out;
	n = nx * ny;
	if (api->inq_varid(nc, "x", &xv) == NC_NOERR) {
		if (att_double(api, nc, xv, "length", &lx) == 0 && ndims == 1)
			ly = lx / (double)nx;
		att_double(api, nc, xv, "periodic", &per);
		if (att_text(api, nc, xv, "unit", unit, sizeof(unit)) != 0)
			att_text(api, nc, xv, "length_unit", unit, sizeof(unit));
	}
	if (ndims == 2 && api->inq_varid(nc, "y", &yv) == NC_NOERR)
		att_double(api, nc, yv, "length", &ly);
	if (att_text(api, nc, hv, "unit", zunit, sizeof(zunit)) != 0)
		strcpy(zunit, unit);
	if ((t = rc_malloc(n * sizeof(double), err)) == NULL)
		goto out;
	if ((g = rc__io_grid_alloc(nx, ny, lx, ly, err)) == NULL)
		goto out;
	if ((unit[0] != '\0' && rc__io_set_unit(g->unit, unit, err) != 0) ||
	    (zunit[0] != '\0' && rc__io_set_unit(g->z_unit, zunit, err) != 0))
		goto out;
	g->periodic = per != 0;
	if (var_values(api, nc, hv, "heights", type, t, g, err) != 0)
		goto out;
	/* SurfaceTopography's mask: non-zero where a point is missing. */
	if (api->inq_varid(nc, "mask", &mv) == NC_NOERR) {
		int mdims[2], mnd;

		if ((st = api->inq_var(nc, mv, NULL, NULL, &mnd, NULL, NULL)) !=
		    NC_NOERR)
			goto nc;
		if (mnd != ndims || api->inq_vardimid(nc, mv, mdims) != NC_NOERR ||
		    mdims[0] != dims[0] || (ndims == 2 && mdims[1] != dims[1])) {
			rc_seterr(err, "netCDF: mask does not have the dimensions of "
			    "heights");
			goto out;
		}
		if ((st = api->get_var_double(nc, mv, t)) != NC_NOERR) {
			nc_fail(api, err, "mask", st);
			goto out;
		}
		for (size_t i = 0; i < nx; i++)
			for (size_t j = 0; j < ny; j++)
				if (t[i * ny + j] != 0)
					g->z[j * nx + i] = NAN;
	}
	if (mark_missing(g, err) != 0)
		goto out;
	r = rc__chanset_add(s, g, "heights", err);
	g = NULL;
	goto out;
nc:
	nc_fail(api, err, "heights", st);
out:
	rc_grid_free(g);
	free(t);
	api->close(nc);
	ncapi_close(api);
	return r;
}

/* Long: the netCDF definitions in the order the library needs them
 * (define mode, then data). */
int
rc__nc_write(const rc_grid *g, FILE *fp, rc_err *err)
{
	size_t nx = g->nx, ny = g->ny, n = nx * ny;
	int nc, dx, dy = -1, xv, yv = -1, hv, mv = -1, dims[2], st, nd;
	int per = g->periodic ? 1 : 0;
	size_t missing = 0;
	double lx = g->lx, ly = g->ly, *t = NULL;
	const char *unit = g->unit;
	NC_memio mem = { 0, NULL, 0 };
	int r = -1, open = 0;
	struct ncapi lib, *api = &lib;

	/* One unit for all: the heights' (they stay bit for bit). */
	if (g->z_unit[0] != '\0' && strcmp(g->z_unit, g->unit) != 0) {
		double from = rc__io_per_metre(g->unit), to = rc__io_per_metre(g->z_unit);

		if (from == 0 || to == 0)
			return rc_seterr(err, "netCDF (contact.engineering) holds "
			    "lengths and heights in one length unit; '%s' and '%s' "
			    "are not both lengths", g->unit[0] ? g->unit : "(none)",
			    g->z_unit);
		lx = lx / from * to;
		ly = ly / from * to;
		unit = g->z_unit;
	}
	if (ncapi_open(api, err) != 0)
		return -1;
	if ((t = rc_malloc((n > nx + ny ? n : nx + ny) * sizeof(double), err)) ==
	    NULL) {
		ncapi_close(api);
		return -1;
	}
	/* Initial size 0: the in-memory file then grows to exactly what it
	 * holds; a larger one would be returned whole, its unwritten tail
	 * uninitialised. */
	if ((st = api->create_mem("output.nc", NC_64BIT_OFFSET, 0, &nc))
	    != NC_NOERR) {
		nc_fail(api, err, "create", st);
		free(t);
		ncapi_close(api);
		return -1;
	}
	open = 1;
	/* A line scan (ny = 1) in SurfaceTopography's 1D layout. */
	nd = ny == 1 ? 1 : 2;
	if ((st = api->def_dim(nc, "x", nx, &dx)) != NC_NOERR ||
	    (nd == 2 && (st = api->def_dim(nc, "y", ny, &dy)) != NC_NOERR) ||
	    (st = api->def_var(nc, "x", NC_DOUBLE, 1, &dx, &xv)) != NC_NOERR ||
	    (nd == 2 && (st = api->def_var(nc, "y", NC_DOUBLE, 1, &dy, &yv)) !=
	    NC_NOERR))
		goto nc;
	dims[0] = dx;
	dims[1] = dy;
	if ((st = api->def_var(nc, "heights", NC_DOUBLE, nd, dims, &hv)) != NC_NOERR)
		goto nc;
	for (size_t k = 0; g->valid != NULL && k < n; k++)
		missing += !g->valid[k];
	if (missing > 0 && (st = api->def_var(nc, "mask", NC_BYTE, nd, dims, &mv))
	    != NC_NOERR)
		goto nc;
	for (int k = 0; k < nd; k++) {
		int v = k ? yv : xv;
		double l = k ? ly : lx;

		if ((st = api->put_att_double(nc, v, "length", NC_DOUBLE, 1, &l)) !=
		    NC_NOERR || (st = api->put_att_int(nc, v, "periodic", NC_INT, 1,
		    &per)) != NC_NOERR)
			goto nc;
		/* unit for SurfaceTopography, length_unit for older readers */
		if (unit[0] != '\0' && ((st = api->put_att_text(nc, v, "unit",
		    strlen(unit), unit)) != NC_NOERR || (st = api->put_att_text(nc,
		    v, "length_unit", strlen(unit), unit)) != NC_NOERR))
			goto nc;
	}
	if (unit[0] != '\0' && (st = api->put_att_text(nc, hv, "unit",
	    strlen(unit), unit)) != NC_NOERR)
		goto nc;
	/* No free space after the header or between variables (libnetcdf's
	 * default reserves some, which its in-memory file leaves
	 * uninitialised: the output would differ from run to run). */
	if ((st = api->_enddef(nc, 0, 4, 0, 4)) != NC_NOERR)
		goto nc;
	for (size_t i = 0; i < nx; i++)
		t[i] = ((double)i + 0.5) * lx / (double)nx;
	if ((st = api->put_var_double(nc, xv, t)) != NC_NOERR)
		goto nc;
	for (size_t j = 0; nd == 2 && j < ny; j++)
		t[j] = ((double)j + 0.5) * ly / (double)ny;
	if (nd == 2 && (st = api->put_var_double(nc, yv, t)) != NC_NOERR)
		goto nc;
	for (size_t i = 0; i < nx; i++)
		for (size_t j = 0; j < ny; j++)
			t[i * ny + j] = g->valid && !g->valid[j * nx + i] ? NAN :
			    g->z[j * nx + i];
	if ((st = api->put_var_double(nc, hv, t)) != NC_NOERR)
		goto nc;
	if (missing > 0) {
		unsigned char *m = (unsigned char *)t;	/* n bytes of 8n */

		for (size_t i = 0; i < nx; i++)
			for (size_t j = 0; j < ny; j++)
				m[i * ny + j] = !g->valid[j * nx + i];
		if ((st = api->put_var_uchar(nc, mv, m)) != NC_NOERR)
			goto nc;
	}
	open = 0;
	if ((st = api->close_memio(nc, &mem)) != NC_NOERR)
		goto nc;
	r = rc__io_write(fp, mem.memory, mem.size, err);
	goto out;
nc:
	nc_fail(api, err, "write", st);
out:
	if (open)
		api->abort(nc);
	free(mem.memory);
	free(t);
	ncapi_close(api);
	return r;
}
