/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fft.c - FFTW plans, threads, wave numbers. */
#include "fft.h"

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "atomic.h"
#include "clock.h"
#include "threads.h"
#ifdef _OPENMP
#include <omp.h>
#endif

/* OMP_NUM_THREADS as OpenMP reads it: a positive number, or a list of
 * them (nested levels), whose first entry applies here; else 0. */
static int
env_threads(void)
{
	const char *s = getenv("OMP_NUM_THREADS");
	char *end;
	long n;

	if (s == NULL)
		return 0;
	errno = 0;
	n = strtol(s, &end, 10);
	if (end == s || (*end != '\0' && *end != ',') || errno == ERANGE ||
	    n < 1 || n > 4096)
		return 0;
	return (int)n;
}

int
rc_fft_thread_count(int n)
{
#ifdef _OPENMP
	if (n <= 0)
		n = env_threads();
	if (n <= 0)
		n = rc_threads_auto();
	return n;
#else
	(void)n;
	(void)env_threads;
	return 1;
#endif
}

int
rc_fft_set_threads(int n)
{
#ifdef _OPENMP
	static int initialised;	/* FFTW's own global state: init once */
	n = rc_fft_thread_count(n);
	if (!initialised) {
		fftw_init_threads();
		initialised = 1;
	}
	omp_set_num_threads(n);
	fftw_plan_with_nthreads(n);
	return n;
#else
	return rc_fft_thread_count(n);
#endif
}

static const char *effort_names[] = { "estimate", "measure", "patient", "wisdom" };

const char *
rc_fft_effort_name(enum rc_fft_effort e)
{
	return (unsigned)e < sizeof(effort_names) / sizeof(effort_names[0]) ?
	    effort_names[e] : "unknown";
}

int
rc_fft_effort_parse(const char *name)
{
	for (size_t e = 0; e < sizeof(effort_names) / sizeof(effort_names[0]); e++)
		if (strcmp(name, effort_names[e]) == 0)
			return (int)e;
	return -1;
}

enum rc_fft_effort
rc_fft_effort_auto(size_t nx, size_t ny, double pairs)
{
	if (nx * ny < RC_FFT_MEASURE_POINTS)
		return RC_FFT_ESTIMATE;
	return pairs >= RC_FFT_MEASURE_PAIRS ? RC_FFT_MEASURE : RC_FFT_WISDOM;
}

double
rc_fft_plan_limit(size_t nx, size_t ny, double pairs)
{
	rc_fft f;
	rc_err err;
	double t0, pair;

	if (rc_fft_init(&f, nx, ny, RC_FFT_ESTIMATE, &err) != 0)
		return -1;
	/* The first pair touches the buffers' pages: time the second. */
	rc_fft_forward(&f);
	rc_fft_backward(&f);
	t0 = rc_clock();
	rc_fft_forward(&f);
	rc_fft_backward(&f);
	pair = rc_clock() - t0;
	rc_fft_free(&f);
	return RC_FFT_PLAN_SHARE * pairs * pair / RC_FFT_PLAN_CALLS;
}

void
rc_fft_set_plan_limit(double seconds)
{
	fftw_set_timelimit(seconds >= 0 ? seconds : FFTW_NO_TIMELIMIT);
}

static unsigned
effort_flags(enum rc_fft_effort e)
{
	switch (e) {
	case RC_FFT_MEASURE:
		return FFTW_MEASURE;
	case RC_FFT_PATIENT:
		return FFTW_PATIENT;
	case RC_FFT_WISDOM:
		return FFTW_MEASURE | FFTW_WISDOM_ONLY;
	default:
		return FFTW_ESTIMATE;
	}
}

int
rc_fft_wisdom_import(const char *path, rc_err *err)
{
	FILE *fp;
	char *text = NULL, *grown;
	size_t len = 0, cap = 0, got;
	int ok;

	if ((fp = fopen(path, "r")) == NULL) {
		if (errno == ENOENT)
			return 0;
		return rc_seterr(err, "%s", strerror(errno));
	}
	/* Read it whole, at most RC_FFT_WISDOM_MAX_BYTES of text: FFTW's own
	 * reader reads until its closing parenthesis, which a device such as
	 * /dev/zero never gives (it read forever). */
	do {
		if (len + 1 >= cap) {
			cap = cap ? 2 * cap : 65536;
			if (cap > RC_FFT_WISDOM_MAX_BYTES + 1)
				cap = RC_FFT_WISDOM_MAX_BYTES + 1;
			if (len + 1 >= cap) {
				free(text);
				fclose(fp);
				return rc_seterr(err, "not FFTW wisdom (%d MiB or more)",
				    RC_FFT_WISDOM_MAX_BYTES >> 20);
			}
			if ((grown = realloc(text, cap)) == NULL) {
				free(text);
				fclose(fp);
				return rc_seterr(err, "out of memory");
			}
			text = grown;
		}
		got = fread(text + len, 1, cap - 1 - len, fp);
		if (memchr(text + len, '\0', got) != NULL) {
			free(text);
			fclose(fp);
			return rc_seterr(err, "not FFTW wisdom (binary data)");
		}
		len += got;
	} while (got > 0);
	ok = !ferror(fp);
	fclose(fp);
	if (!ok) {
		free(text);
		return rc_seterr(err, "read error");
	}
	/* Empty (a new file, /dev/null): no wisdom yet, like a missing one. */
	if (len == 0) {
		free(text);
		return 0;
	}
	text[len] = '\0';
	ok = fftw_import_wisdom_from_string(text);
	free(text);
	if (!ok)
		return rc_seterr(err, "not FFTW wisdom (or from another FFTW "
		    "version); remove it or name another file");
	return 1;
}

int
rc_fft_wisdom_export(const char *path, rc_err *err)
{
	rc_atomic a;

	if (rc_is_stdio(path))
		return rc_seterr(err, "wisdom needs a file name, not standard output");
	if (rc_atomic_open(&a, path, err) != 0)
		return -1;
	fftw_export_wisdom_to_file(a.fp);
	if (ferror(a.fp)) {
		rc_atomic_abort(&a);
		return rc_seterr(err, "write error");
	}
	if (rc_atomic_commit(&a, err) != 0) {
		rc_atomic_abort(&a);
		return -1;
	}
	return 0;
}

/* Room FFTW needs beyond the two buffers, with a wide margin (measured:
 * 3.2 MB in all for planning and executing a 4096^2 pair). */
#define FFTW_HEADROOM(nx, ny) (((size_t)16 << 20) + 64 * ((nx) + (ny)) * \
	sizeof(fftw_complex))

fftw_plan
rc_fft_plan_c2r_inplace(size_t nx, size_t ny, fftw_complex *buf,
    enum rc_fft_effort effort, double *plan_seconds, enum rc_fft_effort *used,
    rc_err *err)
{
	double t0;
	fftw_plan p;
	void *probe;

	if (nx > (size_t)INT32_MAX || ny > (size_t)INT32_MAX) {
		rc_seterr(err, "grid %zux%zu too large for FFTW's int sizes", nx, ny);
		return NULL;
	}
	/* FFTW aborts when its own allocations fail (see rc_fft_init). */
	if ((probe = malloc(FFTW_HEADROOM(nx, ny))) == NULL) {
		rc_seterr(err, "out of memory (asked for %zu bytes of FFTW workspace)",
		    FFTW_HEADROOM(nx, ny));
		return NULL;
	}
	free(probe);
	t0 = rc_clock();
	p = fftw_plan_dft_c2r_2d((int)ny, (int)nx, buf, (double *)buf,
	    effort_flags(effort));
	if (p == NULL && effort == RC_FFT_WISDOM) {
		effort = RC_FFT_ESTIMATE;
		p = fftw_plan_dft_c2r_2d((int)ny, (int)nx, buf, (double *)buf,
		    FFTW_ESTIMATE);
	} else if (effort == RC_FFT_WISDOM)
		effort = RC_FFT_MEASURE;
	if (plan_seconds != NULL)
		*plan_seconds = rc_clock() - t0;
	if (used != NULL)
		*used = effort;
	if (p == NULL)
		rc_seterr(err, "FFTW could not plan a %zux%zu transform", nx, ny);
	return p;
}


int
rc_fft_bytes(size_t a, size_t b, size_t size, size_t *bytes)
{
	*bytes = 0;
	if (b != 0 && a > SIZE_MAX / b)
		return -1;
	if (size != 0 && a * b > SIZE_MAX / size)
		return -1;
	*bytes = a * b * size;
	return 0;
}

void
rc_fft_huge_free(void *x, void *block)
{
	fftw_free(block != NULL ? block : x);
}

void *
rc_fft_huge(size_t n, void **block)
{
	const size_t page = (size_t)2 << 20;
	size_t len = n;
	uintptr_t at;

	if (n < RC_FFT_HUGE_MIN || n > SIZE_MAX - 2 * page)
		return *block = fftw_malloc(n);
	/* A rest of half a huge page or more goes on one: its 256 and more
	 * small pages cost more in faults (3.3 ms at 1 MB) than the huge
	 * page's unused part costs in memory (at most 1 MB). */
	if (n % page >= RC_FFT_HUGE_MIN)
		len = n / page * page + page;
	if ((*block = fftw_malloc(len + page)) == NULL)
		return NULL;
	at = ((uintptr_t)*block + page - 1) & ~(uintptr_t)(page - 1);
#ifdef MADV_HUGEPAGE
	/* Advice, failure changes nothing.  A shorter rest past the last
	 * whole 2 MB stays on small pages (glibc's hugetlb tunable advises
	 * whole mappings): a huge page there would hold over 1 MB unused. */
	uintptr_t whole = at + len / page * page;
	uintptr_t end = ((uintptr_t)*block + len + page) & ~(uintptr_t)4095;

	/* Small pages already there (heap memory malloc reused: its
	 * contents are not the caller's yet) would keep the range on small
	 * pages: gfmd-solve's 1 MB stiffness table at 512^2 took 257 faults
	 * instead of 1 in about half its runs without this. */
	(void)madvise((void *)at, whole - at, MADV_DONTNEED);
	(void)madvise((void *)at, whole - at, MADV_HUGEPAGE);
	if (end > whole)
		(void)madvise((void *)whole, end - whole, MADV_NOHUGEPAGE);
	/* The block's parts around the values, up to 2 MB, stay resident
	 * when the heap held data there before: given back (the pages that
	 * hold malloc's own headers excepted, so whole pages inside the
	 * block only).  gfmd-solve's peak at 512^2 FIRE, with its u, v and
	 * mass table here: 37.3 MB without this, 26.2 to 27.4 with (31.1
	 * before they came here).  Not kept: every block a mapping of its
	 * own, 25.0 MB, but then every block is new memory for the kernel
	 * to clear: 74 ms of system time more at 1024^2 on this VM. */
	uintptr_t head = ((uintptr_t)*block + 4095) & ~(uintptr_t)4095;
	uintptr_t tail = (at + n + 4095) & ~(uintptr_t)4095;

	if (tail < whole)
		tail = whole;
	if (at > head)
		(void)madvise((void *)head, at - head, MADV_DONTNEED);
	if (end > tail)
		(void)madvise((void *)tail, end - tail, MADV_DONTNEED);
#endif
	return (void *)at;
}

int
rc_fft_init(rc_fft *f, size_t nx, size_t ny, enum rc_fft_effort effort,
    rc_err *err)
{
	double t0;
	unsigned flags = effort_flags(effort);
	void *probe;
	size_t real_bytes, spec_bytes;

	memset(f, 0, sizeof(*f));
	if (nx > (size_t)INT32_MAX || ny > (size_t)INT32_MAX)
		return rc_seterr(err, "grid %zux%zu too large for FFTW's int sizes", nx, ny);
	/* spec_bytes >= real_bytes: below SIZE_MAX / 3, the sums in the
	 * messages below fit too */
	if (rc_fft_bytes(nx, ny, sizeof(double), &real_bytes) != 0 ||
	    rc_fft_bytes(RC_FFT_SPEC_ROW(nx), ny, sizeof(fftw_complex),
	    &spec_bytes) != 0 || spec_bytes > SIZE_MAX / 3)
		return rc_seterr(err, "grid %zux%zu too large: its FFT buffers' "
		    "size overflows size_t", nx, ny);
	f->nx = nx;
	f->ny = ny;
	f->nxc = nx / 2 + 1;
	f->nxs = RC_FFT_SPEC_ROW(nx);
	f->real = rc_fft_huge(real_bytes, &f->real_block);
	f->spec = rc_fft_huge(spec_bytes, &f->spec_block);
	if (f->real == NULL || f->spec == NULL) {
		rc_fft_free(f);
		return rc_seterr(err, "out of memory (asked for %zu bytes of FFT buffers)",
		    (nx * ny + 2 * f->nxs * ny) * sizeof(double));
	}
	/* FFTW aborts when one of its own allocations (plans, twiddle factors,
	 * buffers: a few MB for a 4096^2 grid) fails: fail cleanly here instead
	 * when not even that much is left. */
	if ((probe = malloc(FFTW_HEADROOM(nx, ny))) == NULL) {
		rc_fft_free(f);
		return rc_seterr(err, "out of memory (asked for %zu bytes of FFT buffers "
		    "and %zu bytes of FFTW workspace)", (nx * ny + 2 * f->nxs * ny) *
		    sizeof(double), FFTW_HEADROOM(nx, ny));
	}
	free(probe);
	t0 = rc_clock();
	f->forward = fftw_plan_dft_r2c_2d((int)ny, (int)nx, f->real, f->spec, flags);
	f->backward = fftw_plan_dft_c2r_2d((int)ny, (int)nx, f->spec, f->real, flags);
	if (effort == RC_FFT_WISDOM) {
		effort = RC_FFT_MEASURE;
		if (f->forward == NULL || f->backward == NULL) {
			/* Not in the wisdom: the instant plan instead. */
			if (f->forward)
				fftw_destroy_plan(f->forward);
			if (f->backward)
				fftw_destroy_plan(f->backward);
			effort = RC_FFT_ESTIMATE;
			f->forward = fftw_plan_dft_r2c_2d((int)ny, (int)nx, f->real,
			    f->spec, FFTW_ESTIMATE);
			f->backward = fftw_plan_dft_c2r_2d((int)ny, (int)nx, f->spec,
			    f->real, FFTW_ESTIMATE);
		}
	}
	f->effort = effort;
	f->plan_seconds = rc_clock() - t0;
	if (f->forward == NULL || f->backward == NULL) {
		rc_fft_free(f);
		return rc_seterr(err, "FFTW could not plan a %zux%zu transform", nx, ny);
	}
	/* MEASURE scribbles on the buffers. */
	memset(f->real, 0, nx * ny * sizeof(double));
	return 0;
}

void
rc_fft_free(rc_fft *f)
{
	if (f->forward)
		fftw_destroy_plan(f->forward);
	if (f->backward)
		fftw_destroy_plan(f->backward);
	for (int what = 0; what < 4; what++) {
		if (f->block[what])
			fftw_destroy_plan(f->block[what]);
		if (f->block_tail[what])
			fftw_destroy_plan(f->block_tail[what]);
	}
	fftw_free(f->column_buf_all);
	rc_fft_huge_free(f->real, f->real_block);
	rc_fft_huge_free(f->spec, f->spec_block);
	memset(f, 0, sizeof(*f));
}

rc_fft *
rc_fft_borrow(rc_fft *given, rc_fft *own, size_t nx, size_t ny, rc_err *err)
{
	memset(own, 0, sizeof(*own));
	if (given == NULL)
		return rc_fft_init(own, nx, ny, RC_FFT_ESTIMATE, err) != 0 ? NULL : own;
	if (given->nx != nx || given->ny != ny) {
		rc_seterr(err, "internal: FFT plan %zux%zu for a %zux%zu grid",
		    given->nx, given->ny, nx, ny);
		return NULL;
	}
	return given;
}

void
rc_fft_forward(rc_fft *f)
{
	fftw_execute(f->forward);
}

void
rc_fft_backward(rc_fft *f)
{
	fftw_execute(f->backward);
}

/* One-thread plans (the stages run one block per thread): `count` rows
 * of the real buffer to spec or back (spec's rows nxs apart, fft.h), or
 * `count` columns in place in a column buffer, each column contiguous.
 * Every block starts at a multiple of RC_FFT_BLOCK rows, 8 doubles or
 * complex values, so at FFTW's alignment of the planned base; every
 * column buffer at fftw_malloc's.
 *
 * Why the columns are gathered: FFTW's ESTIMATE plan for 8 columns in
 * place, nxs apart, is a radix-8 decomposition vectorised across the
 * columns that took 3.3 ms per direction over the 512 columns of a
 * 1024^2 grid (one thread, this project's 2-core machine), the whole
 * column stage (forward, multiplier, backward) 7.7 ms; on the columns
 * gathered contiguous it takes 1.3 ms per direction and the stage,
 * gather and scatter included, 5.0 ms (2048^2: 43 -> 29 ms, 4096^2:
 * 399 -> 184 ms).  A different algorithm, so the values change at the
 * level of rounding (issue 29's note). */
static fftw_plan
plan_block(rc_fft *f, int what, int count, unsigned flags)
{
	int nx = (int)f->nx, ny = (int)f->ny, nxs = (int)f->nxs;
	fftw_plan p;
#ifdef _OPENMP
	int threads = fftw_planner_nthreads();

	fftw_plan_with_nthreads(1);
#endif
	if (what == 0)
		p = fftw_plan_many_dft_r2c(1, &nx, count, f->real, NULL, 1, nx,
		    f->spec, NULL, 1, nxs, flags);
	else if (what == 1)
		p = fftw_plan_many_dft_c2r(1, &nx, count, f->spec, NULL, 1, nxs,
		    f->real, NULL, 1, nx, flags);
	else
		p = fftw_plan_many_dft(1, &ny, count, f->column_buf_all, NULL, 1,
		    (int)f->column_dist, f->column_buf_all, NULL, 1,
		    (int)f->column_dist, what == 2 ?
		    FFTW_FORWARD : FFTW_BACKWARD, flags);
#ifdef _OPENMP
	fftw_plan_with_nthreads(threads);
#endif
	return p;
}

int
rc_fft_conv_init(rc_fft *f, enum rc_fft_effort effort, size_t min_points,
    rc_err *err)
{
	int row_rest = (int)(f->ny % RC_FFT_BLOCK);
	int col_rest = (int)(f->nxc % RC_FFT_BLOCK), ok;
	unsigned flags = effort == RC_FFT_MEASURE || effort == RC_FFT_PATIENT ?
	    effort_flags(effort) : FFTW_ESTIMATE;

	if (f->nx * f->ny < min_points || f->nxc < RC_FFT_BLOCK ||
	    f->ny < RC_FFT_BLOCK)
		return 0;
	/* a column buffer per thread that rc_fft_columns may run; its
	 * columns 8 values more than ny apart: ny apart (a power of two)
	 * they fell on one L1 set and 4 kB-aliased (the multiplier's
	 * stores to one column and loads from the next stalled: 27% of the
	 * stage's own time at 1024^2) */
	f->column_dist = f->ny + RC_FFT_BLOCK;
	f->ncolumn_buf = omp_get_max_threads();
	if (f->ncolumn_buf < 1)
		f->ncolumn_buf = 1;
	if ((f->column_buf_all = fftw_alloc_complex((size_t)f->ncolumn_buf *
	    RC_FFT_BLOCK * f->column_dist)) == NULL)
		return rc_seterr(err, "out of memory (the column buffers, %zu "
		    "bytes)", (size_t)f->ncolumn_buf * RC_FFT_BLOCK * f->column_dist *
		    sizeof(fftw_complex));
	for (int what = 0; what < 4; what++) {
		f->block[what] = plan_block(f, what, RC_FFT_BLOCK, flags);
		if ((what < 2 ? row_rest : col_rest) > 0)
			f->block_tail[what] = plan_block(f, what,
			    what < 2 ? row_rest : col_rest, flags);
	}
	/* MEASURE scribbles on the buffers. */
	memset(f->real, 0, f->nx * f->ny * sizeof(double));
	ok = 1;
	for (int what = 0; what < 4; what++)
		ok = ok && f->block[what] != NULL && ((what < 2 ? row_rest :
		    col_rest) == 0 || f->block_tail[what] != NULL);
	if (!ok)
		return rc_seterr(err, "FFTW could not plan the blocked %zux%zu "
		    "transforms", f->nx, f->ny);
	return 0;
}

int
rc_fft_conv_blocked(const rc_fft *f)
{
	return f->block[0] != NULL;
}

size_t
rc_fft_row_blocks(const rc_fft *f)
{
	return (f->ny + RC_FFT_BLOCK - 1) / RC_FFT_BLOCK;
}

void
rc_fft_block_rows(const rc_fft *f, size_t b, size_t *j0, size_t *j1)
{
	*j0 = b * RC_FFT_BLOCK;
	*j1 = *j0 + RC_FFT_BLOCK < f->ny ? *j0 + RC_FFT_BLOCK : f->ny;
}

void
rc_fft_rows_r2c(rc_fft *f, const double *in, size_t b)
{
	size_t j0 = b * RC_FFT_BLOCK;
	fftw_plan p = j0 + RC_FFT_BLOCK <= f->ny ? f->block[0] :
	    f->block_tail[0];

	fftw_execute_dft_r2c(p, (double *)in + j0 * f->nx,
	    f->spec + j0 * f->nxs);
}

void
rc_fft_rows_c2r(rc_fft *f, double *out, size_t b)
{
	size_t j0 = b * RC_FFT_BLOCK;
	fftw_plan p = j0 + RC_FFT_BLOCK <= f->ny ? f->block[1] :
	    f->block_tail[1];

	fftw_execute_dft_c2r(p, f->spec + j0 * f->nxs, out + j0 * f->nx);
}

/* How many rows ahead the column stage's strided reads are prefetched. */
#define PREFETCH_ROWS 16

/* The `count` columns of spec from i0 into buf, column c at buf + c dist
 * (dist = f->column_dist), or back.  spec's rows are nxs values apart,
 * past a 4 kB page, where the hardware does not prefetch: software
 * does, PREFETCH_ROWS ahead. */
static void
gather_columns(const rc_fft *f, size_t i0, size_t count, fftw_complex *buf)
{
	const double *s = (const double *)(f->spec + i0);
	double *d = (double *)buf;
	size_t ny = f->ny, nxs = f->nxs, dist = f->column_dist;

	for (size_t j = 0; j < ny; j++, s += 2 * nxs) {
		if (j + PREFETCH_ROWS < ny) {
			__builtin_prefetch(s + 2 * PREFETCH_ROWS * nxs);
			__builtin_prefetch(s + 2 * PREFETCH_ROWS * nxs + 8);
		}
		for (size_t c = 0; c < count; c++) {
			d[2 * (c * dist + j)] = s[2 * c];
			d[2 * (c * dist + j) + 1] = s[2 * c + 1];
		}
	}
}

static void
scatter_columns(rc_fft *f, size_t i0, size_t count, const fftw_complex *buf)
{
	const double *s = (const double *)buf;
	double *d = (double *)(f->spec + i0);
	size_t ny = f->ny, nxs = f->nxs, dist = f->column_dist;

	for (size_t j = 0; j < ny; j++, d += 2 * nxs)
		for (size_t c = 0; c < count; c++) {
			d[2 * c] = s[2 * (c * dist + j)];
			d[2 * c + 1] = s[2 * (c * dist + j) + 1];
		}
}

/* buf's column c *= c_q of column i0 + c, every row: the products and
 * quotients of rc_fft_multiply, value for value.  Row by row, so that
 * each row's `count` values of k (one cache line, nxc values after the
 * last: prefetched) are read once; column by column they cost an L1
 * miss per value, 47% of the column stage's own time at 1024^2.  The
 * fields of *mu are read once (the stores could alias them) and the
 * test of inverse is out of the loops. */
static void
multiply_gathered(const rc_fft *f, const rc_fft_multiplier *mu, size_t i0,
    size_t count, fftw_complex *buf)
{
	const double scale = mu->scale, at_zero = mu->at_zero;
	const int inverse = mu->inverse;
	size_t ny = f->ny, nxc = f->nxc, dist = f->column_dist;
	double *z = (double *)buf;

	for (size_t j = 0; j < ny; j++) {
		const double *k = mu->k + j * nxc + i0;

		if (j + PREFETCH_ROWS < ny)
			__builtin_prefetch(k + PREFETCH_ROWS * nxc);
		if (!inverse)
			for (size_t c = 0; c < count; c++) {
				double q = k[c] * scale;

				z[2 * (c * dist + j)] *= q;
				z[2 * (c * dist + j) + 1] *= q;
			}
		else
			for (size_t c = 0; c < count; c++) {
				double q = k[c] > 0 ? scale / k[c] : at_zero;

				z[2 * (c * dist + j)] *= q;
				z[2 * (c * dist + j) + 1] *= q;
			}
	}
}

void
rc_fft_columns(rc_fft *f, const rc_fft_multiplier *mu)
{
	size_t nblocks = (f->nxc + RC_FFT_BLOCK - 1) / RC_FFT_BLOCK;
	int threads = omp_get_max_threads();

	if (threads > f->ncolumn_buf)
		threads = f->ncolumn_buf;
#pragma omp parallel num_threads(threads)
	{
		fftw_complex *buf = f->column_buf_all +
		    (size_t)omp_get_thread_num() * RC_FFT_BLOCK * f->column_dist;

#pragma omp for schedule(static)
		for (size_t b = 0; b < nblocks; b++) {
			size_t i0 = b * RC_FFT_BLOCK;
			int full = i0 + RC_FFT_BLOCK <= f->nxc;
			size_t count = full ? RC_FFT_BLOCK : f->nxc - i0;

			gather_columns(f, i0, count, buf);
			fftw_execute_dft(full ? f->block[2] : f->block_tail[2],
			    buf, buf);
			multiply_gathered(f, mu, i0, count, buf);
			fftw_execute_dft(full ? f->block[3] : f->block_tail[3],
			    buf, buf);
			scatter_columns(f, i0, count, buf);
		}
	}
}

void
rc_fft_multiply(fftw_complex *spec, size_t nm, const rc_fft_multiplier *mu)
{
	double *z = (double *)spec;
	const double *k = mu->k;
	/* Read once: the stores to z could alias *mu, so the compiler
	 * would load these every mode.  SIMD loops: 94 M instructions in
	 * a 512^2 FIRE solve (callgrind) instead of 122 M, the same
	 * products. */
	const double scale = mu->scale, at_zero = mu->at_zero;
	size_t m;

	if (!mu->inverse) {
#pragma omp parallel for simd schedule(static)
		for (m = 0; m < nm; m++) {
			double c = k[m] * scale;

			z[2 * m] *= c;
			z[2 * m + 1] *= c;
		}
	} else {
#pragma omp parallel for simd schedule(static)
		for (m = 0; m < nm; m++) {
			double c = k[m] > 0 ? scale / k[m] : at_zero;

			z[2 * m] *= c;
			z[2 * m + 1] *= c;
		}
	}
}

void
rc_fft_convolve(rc_fft *f, const double *in, double *out,
    const rc_fft_multiplier *mu)
{
	size_t nb = rc_fft_row_blocks(f), b;

	if (rc_fft_conv_blocked(f)) {
#pragma omp parallel for schedule(static)
		for (b = 0; b < nb; b++)
			rc_fft_rows_r2c(f, in, b);
		rc_fft_columns(f, mu);
#pragma omp parallel for schedule(static)
		for (b = 0; b < nb; b++)
			rc_fft_rows_c2r(f, out, b);
		return;
	}
	fftw_execute_dft_r2c(f->forward, (double *)in, f->spec);
	rc_fft_multiply(f->spec, f->nxc * f->ny, mu);
	fftw_execute_dft_c2r(f->backward, f->spec, out);
}

double
rc_wavenumber(size_t k, size_t n, double l)
{
	double kk = k <= n / 2 ? (double)k : (double)k - (double)n;

	return 2 * M_PI * kk / l;
}

int
rc_is_nyquist(size_t k, size_t n)
{
	return n % 2 == 0 && k == n / 2;
}

int
rc_fft_weight(size_t i, size_t nx)
{
	return (i == 0 || rc_is_nyquist(i, nx)) ? 1 : 2;
}

double
rc_deriv_wavenumber(size_t k, size_t n, double l)
{
	return rc_is_nyquist(k, n) ? 0.0 : rc_wavenumber(k, n, l);
}
