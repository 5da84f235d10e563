/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_core.c - grid metadata, number formatting, wave numbers, FFT
 * normalisation, atomic writes, tables. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <stdint.h>
#include <sys/stat.h>

#include "atomic.h"
#include "fft.h"
#include "grid.h"
#include "io.h"
#include "spectral.h"
#include "table_write.h"
#include "testlib.h"

static void
test_grid(void)
{
	rc_err err;
	rc_grid *g = rc_grid_new(4, 3, 2.0, 1.5, &err), *c;
	double v;

	test_true(g != NULL, "grid_new 4x3");
	test_true(rc_grid_new(0, 3, 1, 1, &err) == NULL, "grid_new rejects nx = 0");
	test_true(rc_grid_new(1u << 25, 1, 1, 1, &err) == NULL, "grid_new rejects nx > max");
	test_true(rc_grid_new(1u << 24, 1u << 24, 1, 1, &err) == NULL,
	    "grid_new rejects too many points");
	test_true(rc_grid_new(3, 3, -1, 1, &err) == NULL, "grid_new rejects negative L");
	test_true(rc_grid_new(3, 3, NAN, 1, &err) == NULL, "grid_new rejects NaN L");
	rc_grid_meta_setd(g, "H", 0.8, &err);
	rc_grid_meta_set(g, "type", "selfaffine", &err);
	rc_grid_meta_setd(g, "H", 0.3, &err);
	test_int((long long)g->nmeta, 2, "meta set replaces an existing key");
	test_true(rc_grid_meta_getd(g, "H", &v) && v == 0.3, "meta getd reads back");
	test_true(!rc_grid_meta_getd(g, "type", &v), "meta getd refuses text");
	test_true(rc_grid_meta_set(g, "bad key", "x", &err) != 0, "meta rejects a key with a space");
	test_true(rc_grid_meta_set(g, "k", "a\nb", &err) != 0, "meta rejects a newline in a value");
	g->z[5] = 3.25;
	rc_grid_history_add(g, "surfgen -n 4x3", &err);
	c = rc_grid_clone(g, 1, &err);
	test_true(c && c->z[5] == 3.25 && c->nhistory == 1 && c->nmeta == 2 &&
	    strcmp(rc_grid_meta_get(c, "type"), "selfaffine") == 0, "clone copies everything");
	rc_grid_free(c);
	rc_grid_free(g);
}

static void
test_format(void)
{
	double vals[] = { 0.05, 1.0 / 3, 1e-300, -2.5e17, M_PI, 0.1 + 0.2 };
	char buf[64];

	for (size_t i = 0; i < sizeof(vals) / sizeof(vals[0]); i++) {
		rc_format_double(buf, sizeof(buf), vals[i]);
		test_true(strtod(buf, NULL) == vals[i], "format_double %s round trips", buf);
	}
	rc_format_double(buf, sizeof(buf), 0.05);
	test_true(strcmp(buf, "0.05") == 0, "format_double 0.05 is short (%s)", buf);
}

static void
test_wavenumbers(void)
{
	test_rel(rc_wavenumber(3, 8, 2.0), 2 * M_PI * 3 / 2.0, 1e-15, "q(3) on 8 points");
	test_rel(rc_wavenumber(5, 8, 2.0), -2 * M_PI * 3 / 2.0, 1e-15, "q(5) on 8 points is negative");
	test_rel(rc_wavenumber(4, 8, 1.0), 2 * M_PI * 4, 1e-15, "Nyquist q on 8 points");
	test_true(rc_is_nyquist(4, 8) && !rc_is_nyquist(3, 7) && !rc_is_nyquist(4, 9),
	    "Nyquist only on even axes");
	test_abs(rc_deriv_wavenumber(4, 8, 1.0), 0, 0, "derivative zeroes Nyquist");
	test_rel(rc_wavenumber(4, 9, 1.0), 2 * M_PI * 4, 1e-15, "q(4) on 9 points");
	test_rel(rc_wavenumber(5, 9, 1.0), -2 * M_PI * 4, 1e-15, "q(5) on 9 points");
}

/* Parseval and the inverse on an odd x even grid. */
static void
test_fft(void)
{
	rc_fft f;
	rc_err err;
	size_t nx = 7, ny = 6, n = nx * ny;
	double orig[42], e_real = 0, e_spec = 0, maxerr = 0;

	test_true(rc_fft_init(&f, nx, ny, RC_FFT_ESTIMATE, &err) == 0, "fft_init 7x6");
	for (size_t k = 0; k < n; k++)
		orig[k] = f.real[k] = sin(1.0 + 3.7 * k) + 0.1 * k;
	for (size_t k = 0; k < n; k++)
		e_real += orig[k] * orig[k];
	rc_fft_forward(&f);
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < f.nxc; i++) {
			double m = cabs(f.spec[j * f.nxc + i]);
			e_spec += rc_fft_weight(i, nx) * m * m;
		}
	test_rel(e_spec / n, e_real, 1e-13, "Parseval with half-complex weights");
	rc_fft_backward(&f);
	for (size_t k = 0; k < n; k++)
		maxerr = fmax(maxerr, fabs(f.real[k] / n - orig[k]));
	test_abs(maxerr, 0, 1e-14, "backward(forward(x)) = N x");
	rc_fft_free(&f);
}

static void
test_atomic(void)
{
	char path[512], buf[64];
	rc_atomic a;
	rc_err err;
	FILE *fp;
	struct stat st;

	snprintf(path, sizeof(path), "%s/out.txt", test_tmpdir());
	fp = fopen(path, "w");
	fputs("old\n", fp);
	fclose(fp);
	test_true(rc_atomic_open(&a, path, &err) == 0, "atomic open");
	fputs("new\n", a.fp);
	fp = fopen(path, "r");
	test_true(fgets(buf, sizeof(buf), fp) && strcmp(buf, "old\n") == 0,
	    "target untouched before commit");
	fclose(fp);
	rc_atomic_abort(&a);
	fp = fopen(path, "r");
	test_true(fgets(buf, sizeof(buf), fp) && strcmp(buf, "old\n") == 0,
	    "target untouched after abort");
	fclose(fp);
	test_true(rc_atomic_open(&a, path, &err) == 0, "atomic open again");
	fputs("new\n", a.fp);
	test_true(rc_atomic_commit(&a, &err) == 0, "atomic commit");
	fp = fopen(path, "r");
	test_true(fgets(buf, sizeof(buf), fp) && strcmp(buf, "new\n") == 0,
	    "target replaced after commit");
	fclose(fp);
	test_true(stat(path, &st) == 0 && (st.st_mode & 0444) != 0, "committed file is readable");
	test_true(rc_atomic_open(&a, test_tmpdir(), &err) != 0, "a directory is refused");
	snprintf(path, sizeof(path), "%s/no/such/dir/x", test_tmpdir());
	test_true(rc_atomic_open(&a, path, &err) != 0, "a missing directory is refused");
}

static void
test_tables(void)
{
	rc_row r;
	rc_table_out t;
	rc_err err;
	char *buf = NULL;
	size_t len = 0;
	FILE *fp = open_memstream(&buf, &len);

	rc_row_init(&r);
	rc_table_begin(&t, fp, 0);
	rc_row_num(&r, "p_star", 0.05);
	rc_row_int(&r, "n_c", 12);
	rc_row_str(&r, "method", "fire");
	rc_table_write(&t, &r, &err);
	rc_row_clear(&r);
	rc_row_num(&r, "p_star", NAN);
	rc_row_int(&r, "n_c", 3);
	rc_row_str(&r, "method", "cg");
	rc_table_write(&t, &r, &err);
	rc_row_clear(&r);
	rc_row_num(&r, "other", 1);
	rc_row_int(&r, "n_c", 3);
	rc_row_str(&r, "method", "cg");
	test_true(rc_table_write(&t, &r, &err) != 0, "table refuses a row with other columns");
	rc_table_end(&t, &err);
	fflush(fp);
	test_true(strcmp(buf, "p_star\tn_c\tmethod\n0.05\t12\tfire\nnan\t3\tcg\n") == 0,
	    "TSV table text");
	fclose(fp);
	free(buf);

	fp = open_memstream(&buf, &len);
	rc_table_begin(&t, fp, 1);
	rc_row_clear(&r);
	rc_row_num(&r, "a", INFINITY);
	rc_row_str(&r, "s", "q\"t");
	rc_table_write(&t, &r, &err);
	rc_table_end(&t, &err);
	fflush(fp);
	test_true(strcmp(buf, "[\n  {\"a\": null, \"s\": \"q\\\"t\"}\n]\n") == 0,
	    "JSON table text");
	fclose(fp);
	free(buf);
	rc_row_free(&r);
}

/* Spectral derivatives of h = a cos(kx x + ky y) + b sin(2 kx' x) are exact;
 * a Nyquist column contributes nothing to the gradient. */
static void
test_spectral(void)
{
	rc_err err;
	size_t nx = 16, ny = 12;
	double lx = 2.0, ly = 3.0, kx = 2 * M_PI * 3 / lx, ky = 2 * M_PI * 2 / ly;
	rc_grid *g = rc_grid_new(nx, ny, lx, ly, &err);
	double *hx = malloc(nx * ny * sizeof(double)), *hy = malloc(nx * ny * sizeof(double));
	double *lap = malloc(nx * ny * sizeof(double)), ex = 0, ey = 0, el = 0, gbar, g2 = 0;

	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double x = lx * i / nx, y = ly * j / ny;
			g->z[j * nx + i] = 0.7 * cos(kx * x + ky * y) + (i % 2 ? -0.2 : 0.2);
		}
	test_true(rc_spectral_derivs(g, NULL, hx, hy, lap, &err) == 0, "spectral_derivs");
	for (size_t j = 0; j < ny; j++)
		for (size_t i = 0; i < nx; i++) {
			double x = lx * i / nx, y = ly * j / ny, s = sin(kx * x + ky * y);
			ex = fmax(ex, fabs(hx[j * nx + i] + 0.7 * kx * s));
			ey = fmax(ey, fabs(hy[j * nx + i] + 0.7 * ky * s));
			double nyq = (i % 2 ? -0.2 : 0.2) * pow(M_PI * nx / lx, 2);
			el = fmax(el, fabs(lap[j * nx + i] + (kx * kx + ky * ky) * 0.7 *
			    cos(kx * x + ky * y) + nyq));
			g2 += hx[j * nx + i] * hx[j * nx + i] + hy[j * nx + i] * hy[j * nx + i];
		}
	test_abs(ex, 0, 1e-12, "d/dx of a cosine; Nyquist column dropped");
	test_abs(ey, 0, 1e-12, "d/dy of a cosine");
	test_abs(el, 0, 1e-10, "Laplacian keeps the Nyquist column");
	test_true(rc_rms_gradient(g, NULL, &gbar, &err) == 0, "rms_gradient");
	test_rel(gbar, 0.7 * sqrt((kx * kx + ky * ky) / 2), 1e-13, "rms gradient of a cosine");
	test_rel(gbar, sqrt(g2 / (nx * ny)), 1e-13, "rms gradient = rms of the gradient field");
	free(hx);
	free(hy);
	free(lap);
	rc_grid_free(g);
}

/* A grid's values of 2 MB and more start on a 2 MB boundary (huge pages,
 * rc_grid_values), made or read; smaller ones and adopted ones are
 * fftw_malloc's, and each is freed as it was allocated (ASan). */
static void
test_grid_huge(void)
{
	const size_t huge = (size_t)2 << 20;
	rc_grid *g = rc_grid_new(512, 512, 1, 1, NULL), *small, *r, *a;
	rc_read_opts o;
	rc_err err;
	char path[512];
	double *z = fftw_alloc_real(512 * 512), sum = 0;
	int zero = 1;

	for (size_t k = 0; k < 512 * 512; k++)
		zero &= g->z[k] == 0;
	test_true(zero, "grid_new 512^2: zeroed");
	test_int((long long)((uintptr_t)g->z % huge), 0,
	    "grid_new 512^2: values on a 2 MB boundary");
	test_true(g->z_block != NULL && (char *)g->z_block <= (char *)g->z,
	    "grid_new 512^2: the block it frees holds the values");
	for (size_t k = 0; k < 512 * 512; k++)
		g->z[k] = sin(0.01 * (double)k);
	snprintf(path, sizeof(path), "%s/huge.surf", test_tmpdir());
	test_int(rc_grid_write(g, path, RC_FMT_SURF, &err), 0, "512^2 written");
	rc_read_opts_init(&o);
	r = rc_grid_read(path, &o, &err);
	test_true(r != NULL && (uintptr_t)r->z % huge == 0,
	    "a 512^2 grid read: values on a 2 MB boundary");
	test_true(r != NULL && memcmp(r->z, g->z, 512 * 512 * sizeof(double)) == 0,
	    "a 512^2 grid read: the values written");
	small = rc_grid_new(64, 64, 1, 1, NULL);
	test_true(small->z_block == (void *)small->z,
	    "grid_new 64^2: fftw_malloc's values, as they are");
	for (size_t k = 0; k < 512 * 512; k++)
		sum += z[k] = 1;
	a = rc_grid_adopt(512, 512, 1, 1, z, &err);
	test_true(a != NULL && a->z == z && a->z_block == NULL && sum == 512 * 512,
	    "grid_adopt: the caller's values, freed with fftw_free");
	rc_grid_free(a);
	rc_grid_free(small);
	rc_grid_free(r);
	rc_grid_free(g);
	remove(path);
}

int
main(void)
{
	test_spectral();
	test_grid();
	test_grid_huge();
	test_format();
	test_wavenumbers();
	test_fft();
	test_atomic();
	test_tables();
	return test_summary();
}
