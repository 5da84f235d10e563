/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_dl.c - loading libzip, libxml2 and libyaml on first use
 * (io_dl_internal.h). */
#define RC_IO_DL_C
#include "io_dl_internal.h"

#include <dlfcn.h>
#include <pthread.h>
#include <stddef.h>

/* The shared libraries to load: their sonames, found by the Makefile;
 * else Debian 12's (those of the packages the errors name, not the -dev
 * packages' libzip.so symlinks). */
#ifndef RC_ZIP_SONAME
#define RC_ZIP_SONAME "libzip.so.4"
#endif
#ifndef RC_XML_SONAME
#define RC_XML_SONAME "libxml2.so.2"
#endif
#ifndef RC_YAML_SONAME
#define RC_YAML_SONAME "libyaml-0.so.2"
#endif

struct rc__dl_zip_api rc__dl_zip_api;
struct rc__dl_xml_api rc__dl_xml_api;
struct rc__dl_yaml_api rc__dl_yaml_api;

static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

/* Each table's members resolved by name (the POSIX idiom: a pointer
 * written through void *): zip_resolve, xml_resolve, yaml_resolve return
 * the first name not found, or NULL. */
#define RC_DL_RESOLVE(f) \
	if ((*(void **)&api->f = dlsym(h, #f)) == NULL && missing == NULL) \
		missing = #f;
#define RC_DL_RESOLVER(lib, FUNCS) \
static const char * \
lib##_resolve(void *h) \
{ \
	struct rc__dl_##lib##_api *api = &rc__dl_##lib##_api; \
	const char *missing = NULL; \
\
	FUNCS(RC_DL_RESOLVE) \
	return missing; \
}
RC_DL_RESOLVER(zip, RC_DL_ZIP_FUNCS)
RC_DL_RESOLVER(xml, RC_DL_XML_FUNCS)
RC_DL_RESOLVER(yaml, RC_DL_YAML_FUNCS)
#undef RC_DL_RESOLVER
#undef RC_DL_RESOLVE

/* One library: its soname, the Debian package that has it, how its table
 * is filled, whether it is. */
struct lib {
	const char *soname, *package;
	const char *(*resolve)(void *handle);
	int loaded;
};

static struct lib zip_lib = { RC_ZIP_SONAME, "libzip4", zip_resolve, 0 };
static struct lib xml_lib = { RC_XML_SONAME, "libxml2", xml_resolve, 0 };
static struct lib yaml_lib = { RC_YAML_SONAME, "libyaml-0-2", yaml_resolve,
	0 };

static int
load(struct lib *l, rc_err *err)
{
	const char *missing;
	void *h;
	int r = 0;

	pthread_mutex_lock(&lock);
	if (l->loaded)
		goto out;
	/* RTLD_NODELETE: never unloaded, so the addresses stay valid */
	if ((h = dlopen(l->soname, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE)) ==
	    NULL) {
		r = rc_seterr(err, "cannot load %s (%s); install the Debian "
		    "package %s", l->soname, dlerror(), l->package);
		goto out;
	}
	if ((missing = l->resolve(h)) != NULL) {
		r = rc_seterr(err, "%s has no %s (install the Debian package "
		    "%s)", l->soname, missing, l->package);
		dlclose(h);
		goto out;
	}
	l->loaded = 1;
out:
	pthread_mutex_unlock(&lock);
	return r;
}

int
rc__dl_zip(rc_err *err)
{
	return load(&zip_lib, err);
}

int
rc__dl_xml(rc_err *err)
{
	return load(&xml_lib, err);
}

int
rc__dl_yaml(rc_err *err)
{
	return load(&yaml_lib, err);
}
