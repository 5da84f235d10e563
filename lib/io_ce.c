/* SPDX-License-Identifier: GPL-3.0-or-later */
/* io_ce.c - contact.engineering containers: a zip of measurements and
 * meta.yml (YAML, read with libyaml), as SurfaceTopography's CEReader
 * reads them.  meta.yml:
 *   surfaces: - topographies: - name, datafile: {original: FILE,
 *               squeezed-netcdf: FILE}, data_source (the member's
 *               channel, from 0), size: [LX] or [LX, LY], unit,
 *               is_periodic, height_scale, detrend_mode, ...
 * Each topography is one channel, titled by its name, read from the
 * member "original" (else "squeezed-netcdf") by the readers of a file of
 * unknown name (io.c: by content; never another file).  What meta.yml
 * says completes what the member lacks, as CEReader does: the unit when
 * the member has none (lengths and heights), the size when the member's
 * differs and it has no unit (a size the member gives in a unit must
 * agree to 1e-4, else the container is refused), the periodic flag.
 * height_scale multiplies heights only when the member's reader gave
 * them no unit (raw numbers); a unit means the file's own scale is
 * applied already (a Bruker file's height_scale is its Zsens times its Z
 * scale, which its reader applies).  detrend_mode is kept as metadata,
 * not applied (surfwarp --detrend does that).  A non-uniform line scan's
 * size is its x span (n - 1 steps), resampled (--uniform) or read as
 * it is (rc_read_opts.nonuniform: then its positions follow the size).
 *
 * Memory: meta.yml is at most CE_META_MAX bytes, all members together
 * unpack to at most CE_TOTAL_MAX (io_zip.c's bound; a gzip-compressed
 * member is charged what it unzips to plus what it decodes to), and no
 * container nests in a member.
 */
#include "io_internal.h"
#include "units.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <yaml.h>
#include <zip.h>
#include "io_dl_internal.h"

#define CE_META_MAX ((uint64_t)16 << 20)
#define CE_TOTAL_MAX ((uint64_t)1 << 30)

/* The value of key in mapping node m, or NULL. */
static yaml_node_t *
get(yaml_document_t *d, yaml_node_t *m, const char *key)
{
	if (m == NULL || m->type != YAML_MAPPING_NODE)
		return NULL;
	for (yaml_node_pair_t *p = m->data.mapping.pairs.start;
	    p < m->data.mapping.pairs.top; p++) {
		yaml_node_t *k = yaml_document_get_node(d, p->key);

		if (k != NULL && k->type == YAML_SCALAR_NODE &&
		    strlen(key) == k->data.scalar.length &&
		    memcmp(k->data.scalar.value, key, k->data.scalar.length) == 0)
			return yaml_document_get_node(d, p->value);
	}
	return NULL;
}

/* A scalar's text into buf; 0 if n is no scalar or too long. */
static int
scalar(const yaml_node_t *n, char *buf, size_t len)
{
	if (n == NULL || n->type != YAML_SCALAR_NODE ||
	    n->data.scalar.length >= len)
		return 0;
	memcpy(buf, n->data.scalar.value, n->data.scalar.length);
	buf[n->data.scalar.length] = '\0';
	return 1;
}

/* Item k of sequence n, or NULL. */
static yaml_node_t *
item(yaml_document_t *d, const yaml_node_t *n, size_t k)
{
	if (n == NULL || n->type != YAML_SEQUENCE_NODE ||
	    k >= (size_t)(n->data.sequence.items.top -
	    n->data.sequence.items.start))
		return NULL;
	return yaml_document_get_node(d, n->data.sequence.items.start[k]);
}

struct topo {
	char name[128], file[512], unit[32], detrend[32];
	int squeezed, have_unit, periodic, nsize;
	long source;
	double size[2], height_scale;
};

static int
number(yaml_node_t *n, const char *what, const char *name, double *v,
    rc_err *err)
{
	char buf[64];

	if (!scalar(n, buf, sizeof(buf)) || rc__parse_double(buf, v) != 0 ||
	    !isfinite(*v))
		return rc_seterr(err, "contact.engineering container: meta.yml: "
		    "%s of '%s' is not a number", what, name);
	return 0;
}

/* What meta.yml says of one topography. */
static int
describe(yaml_document_t *d, yaml_node_t *t, size_t idx, struct topo *p,
    rc_err *err)
{
	yaml_node_t *df = get(d, t, "datafile"), *n;
	char buf[64];

	memset(p, 0, sizeof(*p));
	p->height_scale = 1;
	if (!scalar(get(d, t, "name"), p->name, sizeof(p->name)))
		snprintf(p->name, sizeof(p->name), "measurement %zu", idx + 1);
	if (scalar(get(d, df, "original"), p->file, sizeof(p->file)))
		p->squeezed = 0;
	else if (scalar(get(d, df, "squeezed-netcdf"), p->file, sizeof(p->file)))
		p->squeezed = 1;
	else
		return rc_seterr(err, "contact.engineering container: meta.yml: "
		    "'%s' names no data file (datafile: original or "
		    "squeezed-netcdf)", p->name);
	if ((n = get(d, t, "data_source")) != NULL) {
		double v;

		if (number(n, "data_source", p->name, &v, err) != 0)
			return -1;
		if (v < 0 || v != floor(v) || v > 1e6)
			return rc_seterr(err, "contact.engineering container: "
			    "meta.yml: data_source %g of '%s' is not a channel index",
			    v, p->name);
		p->source = (long)v;
	}
	if ((n = get(d, t, "unit")) != NULL) {
		if (!scalar(n, buf, sizeof(buf)) ||
		    !rc_unit_is_length(rc_unit_canonical(buf)))
			return rc_seterr(err, "contact.engineering container: "
			    "meta.yml: the unit of '%s' is not a length unit", p->name);
		snprintf(p->unit, sizeof(p->unit), "%s", rc_unit_canonical(buf));
		p->have_unit = 1;
	}
	if ((n = get(d, t, "size")) != NULL) {
		for (; p->nsize < 3 && item(d, n, (size_t)p->nsize); p->nsize++)
			if (p->nsize < 2 && number(item(d, n, (size_t)p->nsize), "size",
			    p->name, &p->size[p->nsize], err) != 0)
				return -1;
		if (p->nsize < 1 || p->nsize > 2 || !(p->size[0] > 0) ||
		    (p->nsize == 2 && !(p->size[1] > 0)))
			return rc_seterr(err, "contact.engineering container: "
			    "meta.yml: size of '%s' is not one or two positive "
			    "lengths", p->name);
	}
	if (scalar(get(d, t, "is_periodic"), buf, sizeof(buf)))
		p->periodic = strcasecmp(buf, "true") == 0 ||
		    strcasecmp(buf, "yes") == 0;
	if ((n = get(d, t, "height_scale")) != NULL &&
	    (number(n, "height_scale", p->name, &p->height_scale, err) != 0 ||
	    p->height_scale == 0))
		return p->height_scale == 0 ? rc_seterr(err, "contact.engineering "
		    "container: meta.yml: height_scale of '%s' is 0", p->name) : -1;
	scalar(get(d, t, "detrend_mode"), p->detrend, sizeof(p->detrend));
	return 0;
}

/* meta.yml's word on the member's grid g (see the header comment). */
static int
complete(rc_grid *g, const struct topo *p, rc_err *err)
{
	int raw_heights = g->z_unit[0] == '\0', sized = g->unit[0] != '\0';
	int resampled = rc_grid_meta_get(g, "resampled") != NULL;
	size_t n = rc_grid_size(g);

	if (p->have_unit) {
		if (!sized)
			strcpy(g->unit, p->unit);
		if (raw_heights)
			strcpy(g->z_unit, p->unit);
	}
	if (p->nsize > 0) {
		double want[2], have[2];
		int agree = 1;

		want[0] = p->size[0];
		want[1] = p->nsize == 2 ? p->size[1] : p->size[0] / (double)g->nx;
		have[0] = resampled ? g->lx * (double)(g->nx - 1) / (double)g->nx :
		    g->lx;
		have[1] = g->ly;
		for (int k = 0; k < 2; k++) {
			double w = p->have_unit && sized ? rc_unit_convert(want[k],
			    p->unit, g->unit) : want[k];

			if (k < p->nsize && fabs(have[k] - w) > 1e-4 * fabs(w))
				agree = 0;
			want[k] = w;
		}
		if (!agree && sized)
			return rc_seterr(err, "contact.engineering container: '%s': "
			    "meta.yml's size %g%s%g %s and the data file's %g x %g %s "
			    "differ", p->name, p->size[0], p->nsize == 2 ? " x " : "",
			    p->nsize == 2 ? p->size[1] : 0.0, p->unit, g->lx, g->ly,
			    g->unit);
		if (!agree) {
			if (resampled)
				want[0] *= (double)g->nx / (double)(g->nx - 1);
			if (p->nsize == 1)
				want[1] = want[0] / (double)g->nx;
			for (size_t i = 0; g->x != NULL && i < g->nx; i++)
				g->x[i] *= want[0] / g->lx;	/* positions too */
			if (g->x != NULL)
				want[1] = want[0] / (double)(g->nx - 1);
			g->lx = want[0];
			g->ly = want[1];
		}
	}
	g->periodic = p->periodic;
	if (p->height_scale != 1) {
		if (raw_heights && !p->squeezed) {
			for (size_t k = 0; k < n; k++)
				g->z[k] *= p->height_scale;
			if (rc_grid_meta_setd(g, "height_scale", p->height_scale,
			    err) != 0)
				return -1;
		} else if (rc_grid_meta_setf(g, "height_scale", err, "%.17g not "
		    "applied: the file's heights have their unit", p->height_scale)
		    != 0)
			return -1;
	}
	if (p->detrend[0] != '\0' && rc_grid_meta_setf(g, "detrend_mode", err,
	    "%s (not applied)", p->detrend) != 0)
		return -1;
	return rc_grid_meta_set(g, "file", p->file, err);
}

/* One topography: its member read, its channel taken, completed. */
static int
read_topo(zip_t *za, const struct topo *p, const rc_read_opts *o,
    uint64_t *budget, rc_chanset *s, rc__member_reader read_member,
    rc_err *err)
{
	rc_read_opts mo;
	rc_chanset ms = { 0 };
	unsigned char *b = NULL;
	size_t len;
	rc_grid *g;
	char inner[sizeof(err->msg)], q[64];
	int r = -1;

	if (rc__zip_entry(za, "zip", p->file, 0, *budget, &b, &len, err) != 0) {
		if (strstr(err->msg, "unpacks to over") == NULL)
			goto fail;
		return rc_seterr(err, "contact.engineering container: its "
		    "measurements unpack to over %zu bytes: unzip it and read "
		    "them one by one", (size_t)CE_TOTAL_MAX);
	}
	*budget -= len;
	if (len >= 2 && b[0] == 0x1f && b[1] == 0x8b) {
		/* gzip-compressed: what it decodes to is charged too */
		uint64_t decoded = rc__gzip_size(b, len, *budget);

		if (decoded > *budget) {
			free(b);
			return rc_seterr(err, "contact.engineering container: "
			    "'%s' (%s): gzip-compressed, its measurements unpack "
			    "to over %zu bytes: unzip it and read them one by one",
			    p->name, rc__io_quote(q, sizeof(q), p->file,
			    strlen(p->file)), (size_t)CE_TOTAL_MAX);
		}
		*budget -= decoded;
	}
	if (o != NULL)
		mo = *o;
	else
		rc_read_opts_init(&mo);
	mo.channel = 0;		/* those choose among the container's */
	mo.channel_name = NULL;
	if (read_member(b, len, &mo, &ms, 1, err) != 0)
		goto fail;
	if ((size_t)p->source >= ms.n) {
		rc_seterr(err, "data_source %ld, but the file has %zu channel%s",
		    p->source, ms.n, ms.n == 1 ? "" : "s");
		goto fail;
	}
	g = ms.c[p->source].g;
	ms.c[p->source].g = NULL;
	if (complete(g, p, err) != 0) {
		rc_grid_free(g);
		goto out;
	}
	r = rc__chanset_add(s, g, p->name, err);
	goto out;
fail:
	snprintf(inner, sizeof(inner), "%s", err->msg);
	rc_seterr(err, "contact.engineering container: '%s' (%s): %s", p->name,
	    rc__io_quote(q, sizeof(q), p->file, strlen(p->file)), inner);
out:
	rc__chanset_free(&ms);
	free(b);
	return r;
}

/* Whether topography idx (from 0) is to be read: every one, unless the
 * options name a channel (select_channel in io.c matches names the same
 * way: exactly, else ignoring case). */
static int
chosen(const rc_read_opts *o, const struct topo *p, size_t idx)
{
	if (o == NULL)
		return 1;
	if (o->channel_name != NULL)
		return strcasecmp(o->channel_name, p->name) == 0;
	if (o->channel > 0)
		return (size_t)o->channel == idx + 1;
	return 1;
}

int
rc__ce_read(const unsigned char *buf, size_t len, const rc_read_opts *o,
    rc_chanset *s, int depth, rc__member_reader read_member, rc_err *err)
{
	yaml_parser_t parser;
	yaml_document_t doc;
	yaml_node_t *root, *surfaces;
	unsigned char *meta = NULL;
	size_t mlen, ntopo = 0;
	uint64_t budget = CE_TOTAL_MAX;
	zip_t *za;
	int have_doc = 0, r = -1;

	if (depth > 0)
		return rc_seterr(err, "a contact.engineering container inside "
		    "another container or a compressed file: unpack the outer "
		    "one first");
	if ((za = rc__zip_open_mem(buf, len, "contact.engineering", err)) == NULL)
		return -1;
	if (rc__dl_yaml(err) != 0) {
		zip_discard(za);
		return -1;
	}
	if (zip_name_locate(za, "meta.yml", 0) < 0) {
		rc_seterr(err, "a zip without main.xml or meta.yml: neither an "
		    "x3p file (ISO 25178-72) nor a contact.engineering container");
		goto out;
	}
	if (rc__zip_entry(za, "contact.engineering container", "meta.yml", 0,
	    CE_META_MAX, &meta, &mlen, err) != 0)
		goto out;
	if (!yaml_parser_initialize(&parser)) {
		rc_seterr(err, "out of memory");
		goto out;
	}
	yaml_parser_set_input_string(&parser, meta, mlen);
	have_doc = yaml_parser_load(&parser, &doc);
	if (!have_doc) {
		rc_seterr(err, "contact.engineering container: meta.yml is not "
		    "YAML (line %zu: %s)", parser.problem_mark.line + 1,
		    parser.problem ? parser.problem : "?");
		yaml_parser_delete(&parser);
		goto out;
	}
	yaml_parser_delete(&parser);
	root = yaml_document_get_root_node(&doc);
	surfaces = get(&doc, root, "surfaces");
	for (size_t i = 0; item(&doc, surfaces, i) != NULL; i++) {
		yaml_node_t *topos = get(&doc, item(&doc, surfaces, i),
		    "topographies");

		for (size_t k = 0; item(&doc, topos, k) != NULL; k++) {
			struct topo p;

			if (describe(&doc, item(&doc, topos, k), ntopo, &p, err) != 0)
				goto out;
			if (!chosen(o, &p, ntopo)) {
				/* Only the channel asked for is read (one
				 * member may need options another refuses);
				 * the others keep their place and title. */
				if (rc__chanset_add(s, NULL, p.name, err) != 0)
					goto out;
			} else if (read_topo(za, &p, o, &budget, s, read_member, err) != 0)
				goto out;
			ntopo++;
		}
	}
	if (ntopo == 0) {
		rc_seterr(err, "contact.engineering container: meta.yml lists "
		    "no topographies (surfaces: - topographies: ...)");
		goto out;
	}
	r = 0;
out:
	if (r != 0)
		rc__chanset_free(s);
	if (have_doc)
		yaml_document_delete(&doc);
	free(meta);
	zip_discard(za);
	return r;
}
