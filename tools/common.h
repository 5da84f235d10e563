/* common.h - what every tool does the same way: messages, the shared
 * options, number parsing with error collection, grid input and output.
 *
 * A tool's main: tool_init, getopt_long with its own options (passing the
 * shared ones to tool_common_option), check everything and report every
 * problem with tool_bad, tool_usage_check (exit 2 if any), do the work
 * through lib/, return tool_exit(status).
 */
#ifndef RC_TOOLS_COMMON_H
#define RC_TOOLS_COMMON_H

#include <stddef.h>
#include <stdio.h>
#include "fft.h"
#include "grid.h"
#include "io.h"

#define RC_VERSION "0.1.0"

/* Long-option codes shared by the tools (short options are their letters). */
enum {
	OPT_JSON = 1000,
	OPT_PNG,
	OPT_VERSION,
	OPT_WISDOM,
	OPT_FFT_EFFORT,
	OPT_TOOL_FIRST = 1100	/* a tool's own long-only options start here */
};

struct tool {
	const char *name;	/* program name in messages */
	char *cmdline;		/* the command line, for the history */
	const char *out;	/* -o FILE, NULL for standard output */
	const char *png;	/* --png FILE */
	int quiet;		/* -q */
	int threads;		/* -j N, 0 = all cores */
	int json;		/* --json */
	double lx, ly;		/* -L, cell size for inputs that have none */
	int have_l;
	int nbad;		/* usage problems reported so far */
	int nstdout;		/* outputs bound for standard output */
	const char *wisdom;	/* --wisdom FILE, else $RC_WISDOM, else NULL */
	int fft_effort;		/* --fft-effort, -1 for the policy */
	int fft_measured;	/* a plan was asked for with MEASURE or more */
	char **argv;		/* main's arguments as given (getopt reorders
				 * main's array), for rc_threads_wait_passively */
};

/* The FFT options of the tools that plan transforms; put them in the
 * tool's struct option table. */
#define TOOL_FFT_LONGOPTS \
	{ "wisdom", required_argument, NULL, OPT_WISDOM }, \
	{ "fft-effort", required_argument, NULL, OPT_FFT_EFFORT }

void tool_init(struct tool *t, const char *name, int argc, char **argv);

/* Messages: "tool: what: why" on stderr.  tool_fail exits 1. */
void tool_warn(const struct tool *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
void tool_fail(const struct tool *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3), noreturn));
/* Report a usage problem; parsing goes on so all are reported at once. */
void tool_bad(struct tool *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* After validation: if any problem was reported, hint at --help, exit 2. */
void tool_usage_check(const struct tool *t);

/* The shared options: -o -j -q -L --json --png --version.  Returns 1 if
 * opt was one of them (handled), 0 otherwise. */
int tool_common_option(struct tool *t, int opt, const char *arg);

/* FFT set-up, after tool_usage_check and before any plan: threads (-j,
 * else OMP_NUM_THREADS, else all cores) and FFTW wisdom from --wisdom FILE
 * or the file named by $RC_WISDOM (a missing file is fine; an unreadable or
 * foreign one is an error, exit 1, so it is never overwritten). */
void tool_fft_setup(struct tool *t);
/* The effort for a plan of nx x ny that will run about `pairs` transform
 * pairs: --fft-effort if given; else rc_fft_effort_auto, except that a
 * one-shot plan of a big grid is measured when a wisdom file is in use
 * (the first run pays, later runs load it). */
enum rc_fft_effort tool_fft_effort(struct tool *t, size_t nx, size_t ny,
    double pairs);
/* Save the wisdom atomically if a file is in use and a plan was measured;
 * a failure is a warning (the results are unaffected). */
void tool_fft_finish(const struct tool *t);

/* Parsers: on a bad value they call tool_bad naming the option and return -1. */
int tool_double(struct tool *t, const char *opt, const char *arg, double *v);
int tool_long(struct tool *t, const char *opt, const char *arg, long *v);
/* "NX" or "NXxNY" positive integers; NY = NX when omitted. */
int tool_size_pair(struct tool *t, const char *opt, const char *arg,
    size_t *nx, size_t *ny);
/* "LX" or "LXxLY" positive lengths; LY = LX when omitted. */
int tool_length_pair(struct tool *t, const char *opt, const char *arg,
    double *lx, double *ly);
/* Comma-separated numbers; *v is malloc'ed. */
int tool_double_list(struct tool *t, const char *opt, const char *arg,
    double **v, size_t *n);

/* Read a grid (path "-" or NULL: stdin); on failure "tool: path: why", exit 1. */
rc_grid *tool_read_grid(const struct tool *t, const char *path);
/* Append the command line to the history and write atomically; the format
 * follows the extension.  Refuses binary output to a terminal.  Exits 1 on
 * failure. */
void tool_write_grid(const struct tool *t, rc_grid *g, const char *path);
/* Declare an output (path NULL: not requested; "-": standard output).  A
 * second output bound for standard output is a usage problem, and so is
 * binary data (binary != 0) bound for a terminal. */
void tool_output(struct tool *t, const char *opt, const char *path, int binary);
/* Check an output path's extension up front (tool_bad if unknown). */
void tool_check_grid_path(struct tool *t, const char *opt, const char *path);

/* Flush stdout and turn a write error into exit status 1. */
int tool_exit(const struct tool *t, int status);
/* tool_bad if the output path names the same file as the input path (an
 * existing file, by device and inode): for outputs of another kind than
 * the input, where writing would replace what the user had (a table over
 * the surface it describes).  Either may be NULL or "-". */
void tool_not_input(struct tool *t, const char *opt, const char *out,
    const char *in);


#endif
