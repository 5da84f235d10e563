/* SPDX-License-Identifier: GPL-3.0-or-later */
/* h5links.c - HDF5 files that name other files, for tests/e2e/netcdf.sh
 * (libnetcdf's ncgen cannot write them).  In the working directory:
 * target.h5 (heights, 2 x 3, values 100..105) and secret.raw (the six
 * doubles 200..205), and the files that point at them, each holding
 * one 2 x 3 data set "heights":
 *   extlink.h5   an external link to target.h5:/heights (relative name)
 *   extabs.h5    the same by absolute name (argv[1], the directory)
 *   extgroup.h5  a group /g whose member /g/deep is such a link
 *   extstore.h5  raw data in secret.raw (H5Pset_external)
 *   vds.h5       a virtual data set mapped from target.h5:/heights
 *   softlink.h5  heights of its own (values 1..6) and a soft link
 *                /alias -> /heights: inside the file, allowed
 * Exit 0 if all were written. */
#include <hdf5.h>
#include <stdio.h>

static int
one(const char *name, hid_t dcpl, const double *v)
{
	hsize_t dims[2] = { 2, 3 };
	hid_t f, s, d;
	int bad;

	f = H5Fcreate(name, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
	s = H5Screate_simple(2, dims, NULL);
	d = H5Dcreate2(f, "heights", H5T_IEEE_F64LE, s, H5P_DEFAULT, dcpl,
	    H5P_DEFAULT);
	bad = f < 0 || s < 0 || d < 0 || (v != NULL && H5Dwrite(d,
	    H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) < 0);
	H5Dclose(d);
	H5Sclose(s);
	return H5Fclose(f) < 0 || bad;
}

static int
link_file(const char *name, const char *target, const char *where)
{
	hid_t f, g = -1;
	int bad;

	f = H5Fcreate(name, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
	if (where[0] == 'g')
		g = H5Gcreate2(f, "g", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
	bad = f < 0 || H5Lcreate_external(target, "/heights", f, where,
	    H5P_DEFAULT, H5P_DEFAULT) < 0;
	if (g >= 0)
		H5Gclose(g);
	return H5Fclose(f) < 0 || bad;
}

int
main(int argc, char **argv)
{
	double target[6] = { 100, 101, 102, 103, 104, 105 };
	double secret[6] = { 200, 201, 202, 203, 204, 205 };
	double own[6] = { 1, 2, 3, 4, 5, 6 };
	hsize_t dims[2] = { 2, 3 };
	char abs[4096];
	hid_t dcpl, space, f;
	FILE *fp;
	int bad = 0;

	if (argc != 2 || snprintf(abs, sizeof(abs), "%s/target.h5",
	    argv[1]) >= (int)sizeof(abs)) {
		fprintf(stderr, "usage: h5links ABSOLUTE-DIRECTORY\n");
		return 2;
	}
	if ((fp = fopen("secret.raw", "wb")) == NULL ||
	    fwrite(secret, sizeof(double), 6, fp) != 6 || fclose(fp) != 0)
		return 1;
	bad |= one("target.h5", H5P_DEFAULT, target);
	bad |= link_file("extlink.h5", "target.h5", "heights");
	bad |= link_file("extabs.h5", abs, "heights");
	bad |= link_file("extgroup.h5", abs, "g/deep");
	dcpl = H5Pcreate(H5P_DATASET_CREATE);
	bad |= H5Pset_external(dcpl, "secret.raw", 0, sizeof(secret)) < 0;
	bad |= one("extstore.h5", dcpl, NULL);
	H5Pclose(dcpl);
	dcpl = H5Pcreate(H5P_DATASET_CREATE);
	space = H5Screate_simple(2, dims, NULL);
	bad |= H5Pset_virtual(dcpl, space, "target.h5", "/heights", space) < 0;
	bad |= one("vds.h5", dcpl, NULL);
	H5Sclose(space);
	H5Pclose(dcpl);
	bad |= one("softlink.h5", H5P_DEFAULT, own);
	f = H5Fopen("softlink.h5", H5F_ACC_RDWR, H5P_DEFAULT);
	bad |= f < 0 || H5Lcreate_soft("/heights", f, "alias", H5P_DEFAULT,
	    H5P_DEFAULT) < 0;
	bad |= H5Fclose(f) < 0;
	return bad != 0;
}
