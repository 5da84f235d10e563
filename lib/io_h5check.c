/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_h5check.c - refuse an HDF5 (netCDF-4) file that points outside
 * itself, before libnetcdf reads it.
 *
 * HDF5 lets a file name other files: an external link (a link whose
 * target is an object in another file, H5Lcreate_external), external
 * raw storage (a data set whose values live in named files,
 * H5Pset_external) and a virtual data set (values mapped from data sets
 * of other files, H5Pset_virtual).  libnetcdf follows all three when it
 * reads, so a file from elsewhere could make a tool read any file the
 * user can read (an absolute path, or one relative to the working
 * directory) and put its bytes into a result.  surf(5) promises that a
 * file never makes a tool read another one: every link in the file is
 * visited here (H5Lvisit recurses through hard links only, and reports
 * the others without following them) and the file is refused at the
 * first external or user-defined link, external storage or virtual
 * layout.  Soft links stay inside the file and are allowed.
 *
 * The HDF5 functions are those of the libhdf5 that libnetcdf was loaded
 * with (dlsym on its handle searches its dependencies), typed from the
 * header libnetcdf was compiled against.
 */
#include "io_internal.h"

#include <dlfcn.h>
#include <string.h>
#include <hdf5.h>
#include <hdf5_hl.h>

/* A symbol's name after macro expansion: H5Lvisit is H5Lvisit2 in the
 * headers of HDF5 1.12 and later, the function itself in 1.10. */
#define H5_NAME(f) H5_NAME_(f)
#define H5_NAME_(f) #f

#define H5_FUNCS(X) \
	X(H5LTopen_file_image) X(H5Lvisit) X(H5Oopen) X(H5Oclose) \
	X(H5Iget_type) X(H5Dget_create_plist) X(H5Pget_layout) \
	X(H5Pget_external_count) X(H5Pclose) X(H5Fclose) X(H5Eset_auto2)

struct h5api {
#define H5_MEMBER(f) __typeof__(f) *f##_fn;
	H5_FUNCS(H5_MEMBER)
#undef H5_MEMBER
};

/* What the visit found: the first link that leads outside, and why. */
struct h5visit {
	const struct h5api *api;
	hid_t file;
	const char *why;
	char name[256];
};

static herr_t
visit_link(hid_t group, const char *name, const H5L_info_t *info, void *data)
{
	struct h5visit *v = data;
	const struct h5api *api = v->api;
	hid_t obj, dcpl;

	(void)group;	/* name is relative to the visit's start, the root */
	if (info->type == H5L_TYPE_EXTERNAL)
		v->why = "an external link to another file";
	else if (info->type != H5L_TYPE_HARD && info->type != H5L_TYPE_SOFT)
		v->why = "a user-defined link";
	else if (info->type == H5L_TYPE_HARD) {
		if ((obj = api->H5Oopen_fn(v->file, name, H5P_DEFAULT)) < 0) {
			v->why = "an object that cannot be opened";
		} else {
			if (api->H5Iget_type_fn(obj) == H5I_DATASET) {
				if ((dcpl = api->H5Dget_create_plist_fn(obj)) < 0)
					v->why = "a data set without a creation "
					    "property list";
				else {
					if (api->H5Pget_layout_fn(dcpl) ==
					    H5D_VIRTUAL)
						v->why = "a virtual data set "
						    "mapped from other files";
					else if (api->H5Pget_external_count_fn(
					    dcpl) != 0)
						v->why = "a data set stored in "
						    "external files";
					api->H5Pclose_fn(dcpl);
				}
			}
			api->H5Oclose_fn(obj);
		}
	}
	if (v->why == NULL)
		return 0;
	snprintf(v->name, sizeof(v->name), "%s", name);
	return 1;	/* stop: one reason is enough */
}

int
rc__h5_self_contained(void *lib, const unsigned char *buf, size_t len,
    rc_err *err)
{
	struct h5api api;
	struct h5visit v = { &api, -1, NULL, "" };
	const char *missing = NULL;
	herr_t st;

#define H5_RESOLVE(f) \
	if ((*(void **)&api.f##_fn = dlsym(lib, H5_NAME(f))) == NULL && \
	    missing == NULL) \
		missing = H5_NAME(f);
	H5_FUNCS(H5_RESOLVE)
#undef H5_RESOLVE
	if (missing != NULL)
		return rc_seterr(err, "netCDF-4: the HDF5 library loaded with "
		    "libnetcdf has no %s", missing);
	/* HDF5 prints its error stack to stderr by default; libnetcdf
	 * turns it off too, and an error is reported here instead */
	api.H5Eset_auto2_fn(H5E_DEFAULT, NULL, NULL);
	/* read-only, on our buffer as it is (HDF5 neither copies nor
	 * frees it) */
	v.file = api.H5LTopen_file_image_fn((void *)buf, len,
	    H5LT_FILE_IMAGE_DONT_COPY | H5LT_FILE_IMAGE_DONT_RELEASE);
	if (v.file < 0)
		return rc_seterr(err, "not a readable netCDF file: neither "
		    "classic netCDF nor HDF5 (netCDF-4)");
	st = api.H5Lvisit_fn(v.file, H5_INDEX_NAME, H5_ITER_NATIVE,
	    visit_link, &v);
	api.H5Fclose_fn(v.file);
	if (v.why != NULL)
		return rc_seterr(err, "refused: /%s is %s, and a file is not "
		    "allowed to make this tool read another one (surf(5))",
		    v.name, v.why);
	if (st < 0)
		return rc_seterr(err, "not a readable netCDF file: its HDF5 "
		    "links cannot be listed");
	return 0;
}
