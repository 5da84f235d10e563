/* SPDX-License-Identifier: GPL-3.0-or-later */
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

#include <getopt.h>
#include <stddef.h>
#include <stdio.h>
#include "fft.h"
#include "grid.h"
#include "io.h"
#include "table_write.h"

#define RC_VERSION "0.1.0"

/* Long-option codes shared by the tools (short options are their letters). */
enum {
	OPT_JSON = 1000,
	OPT_PNG,
	OPT_VERSION,
	OPT_WISDOM,
	OPT_FFT_EFFORT,
	OPT_PRETTY,
	OPT_UNIT,
	OPT_Z_UNIT,
	OPT_PERIODIC,
	OPT_NO_PERIODIC,
	OPT_NPY_ORDER,
	OPT_CHANNEL,
	OPT_UNIFORM,
	OPT_TOOL_FIRST = 1100	/* a tool's own long-only options start here */
};

struct tool {
	const char *name;	/* program name in messages */
	char *cmdline;		/* the command line, for the history */
	const char *out;	/* -o FILE, NULL for standard output */
	const char *png;	/* --png FILE */
	int quiet;		/* -q */
	int threads;		/* -j N (at most the cores), 0 = all cores */
	int json;		/* --json */
	int pretty;		/* --pretty: aligned table even when not a terminal */
	int pretty_on_terminal;	/* the aligned table when the output is a
				 * terminal; 0 under mpirun, whose ranks write
				 * to a pseudo-terminal whatever mpirun's own
				 * output is */
	double lx, ly;		/* -L, cell size for inputs that have none */
	int have_l;
	int nbad;		/* usage problems reported so far */
	int nstdout;		/* outputs bound for standard output */
	const char *wisdom;	/* --wisdom FILE, else $RC_WISDOM, else NULL */
	int fft_effort;		/* --fft-effort, -1 for the policy */
	int fft_measured;	/* a plan was asked for with MEASURE or more */
	/* how input grids are read (TOOL_GRID_LONGOPTS) */
	const char *unit;	/* --unit: the length unit of the work and output */
	const char *z_unit;	/* --z-unit: the unit of the input's values */
	int periodic;		/* --periodic, --no-periodic (enum rc_periodic_opt) */
	int npy_xy;		/* --npy-order xy */
	int uniform;		/* --uniform: resample non-uniform x-z profiles */
	int nonuniform;		/* the tool analyses non-uniform x-z profiles
				 * as they are (rc_read_opts.nonuniform) */
	int accept_missing;	/* the tool can use grids with missing points */
	const char *channel;	/* --channel N|NAME of the main input, or NULL */
	struct tool_file *files;	/* inputs and outputs (tool_input, tool_output) */
	size_t nfiles;
	const char *(*may_replace)[2];	/* (output, input) option pairs */
	size_t nmay_replace;
	char **argv;		/* main's arguments as given (getopt reorders
				 * main's array), for rc_threads_wait_passively */
};

/* A file of the run, declared so that tool_usage_check can find two that
 * are the same file. */
struct tool_file {
	const char *opt;	/* the option that names it, for messages */
	const char *path;	/* NULL for standard input */
	int output;
};

/* --channel N|NAME, for the tools that read a height map. */
#define TOOL_CHANNEL_LONGOPT \
	{ "channel", required_argument, NULL, OPT_CHANNEL }

/* The FFT options of the tools that plan transforms; put them in the
 * tool's struct option table. */
#define TOOL_FFT_LONGOPTS \
	{ "wisdom", required_argument, NULL, OPT_WISDOM }, \
	{ "fft-effort", required_argument, NULL, OPT_FFT_EFFORT }

/* The options of the tools that read grids: units, periodicity, npy axis
 * order, resampling of non-uniform profiles (handled by
 * tool_common_option). */
#define TOOL_GRID_LONGOPTS \
	{ "unit", required_argument, NULL, OPT_UNIT }, \
	{ "z-unit", required_argument, NULL, OPT_Z_UNIT }, \
	{ "periodic", no_argument, NULL, OPT_PERIODIC }, \
	{ "no-periodic", no_argument, NULL, OPT_NO_PERIODIC }, \
	{ "npy-order", required_argument, NULL, OPT_NPY_ORDER }, \
	{ "uniform", no_argument, NULL, OPT_UNIFORM }

/* Also installs tool_on_signal for SIGINT, SIGTERM and SIGHUP (unless
 * the signal is ignored, as under nohup). */
void tool_init(struct tool *t, const char *name, int argc, char **argv);
/* The handler: removes the temporary files of unfinished outputs
 * (rc_atomic_unlink_pending), says so on stderr and dies of the signal.
 * A tool with its own handler calls it for the signal it cannot handle. */
void tool_on_signal(int sig);

/* Messages: "tool: what: why" on stderr.  tool_fail exits 1. */
void tool_warn(const struct tool *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
void tool_fail(const struct tool *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3), noreturn));
/* tool_fail with "tool: what: why"; "what: " is left out when why, a
 * library message, starts with it already (most name their file); what
 * NULL is "standard output" (an output path not given). */
void tool_fail_at(const struct tool *t, const char *what, const char *why)
	__attribute__((noreturn));
/* Report a usage problem; parsing goes on so all are reported at once. */
void tool_bad(struct tool *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* After getopt_long returned '?' (with opterr = 0): report, with tool_bad,
 * the option as the user typed it and what is wrong with it: unknown (or
 * an ambiguous abbreviation), lacking its value, or given a value it does
 * not take.  optstring and longopts are the ones given to getopt_long. */
void tool_bad_option(struct tool *t, const char *optstring,
    const struct option *longopts, char **argv);
/* After validation: check the declared files against each other (below);
 * if any problem was reported, hint at --help, exit 2. */
void tool_usage_check(struct tool *t);
/* After the options, when -h was among them: 1 to print the help (exit
 * 0); with a bad option anywhere beside it, the problems are counted and
 * the tool exits 2 as tool_usage_check does (a script that passes a
 * wrong option learns so even with --help). */
int tool_help_check(struct tool *t);

/* The shared options: -o -j -q -L --json --png --version.  Returns 1 if
 * opt was one of them (handled), 0 otherwise. */
int tool_common_option(struct tool *t, int opt, const char *arg);

/* The threads alone (tool_fft_setup's first step): the restart for
 * passive waiting (threads.h), the transforms' threads, and the
 * restart's marker removed so that a program the tool runs (the
 * Gwyddion converter) does not take it for its own. */
void tool_threads_setup(struct tool *t);
/* FFT set-up, after tool_usage_check and before any plan: threads (-j,
 * else OMP_NUM_THREADS, else all cores) and FFTW wisdom from --wisdom FILE
 * or the file named by $RC_WISDOM (a missing file is fine; an unreadable or
 * foreign one is an error, exit 1, so it is never overwritten). */
void tool_fft_setup(struct tool *t);
/* The effort for a plan of nx x ny that will run about `pairs` transform
 * pairs: --fft-effort if given; else rc_fft_effort_auto, except that a
 * one-shot plan of a big grid is measured when a wisdom file is in use
 * (the first run pays, later runs load it).  When the policy picks
 * MEASURE, the planning is bounded (rc_fft_plan_limit). */
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

/* Read a grid (path "-" or NULL: stdin); on failure "tool: path: why", exit 1.
 * The grid is brought to one length unit (--unit, else its own lateral
 * unit: rc_grid_to_common_unit); one with missing points is refused,
 * naming surfwarp --fill, unless t->accept_missing. */
rc_grid *tool_read_grid(const struct tool *t, const char *path);
/* Bring g (read from path) to the length unit of another grid (an --init
 * field to its indenter's); exits 1 if it cannot be. */
void tool_grid_to_unit(const struct tool *t, rc_grid *g, const char *path,
    const char *unit);
/* For a tool that treats g as periodic: one warning on stderr when the
 * step across its edges is far above the steps inside (rc_grid_wrap_ratio
 * above RC_WRAP_RATIO_WARN), saying what to do: on a grid read as
 * periodic, which option or rule made it so and how to say it is not;
 * on a patch, what takes it as one period (use, subject and verb:
 * "--boundary periodic solves it") and what to do instead (a sentence).  Levelling is advised
 * only if a plane fit brings the ratio below the threshold. */
void tool_check_wrap(const struct tool *t, const rc_grid *g, const char *path,
    const char *use, const char *instead);
/* The same for the main input, whose channel --channel chooses. */
rc_grid *tool_read_input(const struct tool *t, const char *path);
/* surfstat --channels: one line per channel of the file (tab-separated
 * index, title, nx, ny, lx, ly, unit, z_unit, mask); exits. */
void tool_list_channels(const struct tool *t, const char *path)
	__attribute__((noreturn));
/* Append the command line to the history and write atomically; the format
 * follows the extension.  Refuses binary output to a terminal.  Exits 1 on
 * failure. */
void tool_write_grid(const struct tool *t, rc_grid *g, const char *path);
/* Declare an output (path NULL: not requested; "-": standard output).  A
 * second output bound for standard output is a usage problem, and so is
 * binary data (binary != 0) bound for a terminal, an empty name, and a
 * file that could not be written now (rc_atomic_check: a directory, a
 * missing or read-only directory), so that no work is lost at the end. */
void tool_output(struct tool *t, const char *opt, const char *path, int binary);
/* Declare an input (path NULL or "-": standard input, whatever file it was
 * redirected from); opt names it in messages ("the input", "--mask").  tool_usage_check refuses an output that is the same
 * file (device and inode; for files that do not exist yet, directory and
 * name) as another output or as an input, unless tool_may_replace allowed
 * that pair.  Only regular and new files count: two outputs to /dev/null
 * are fine. */
void tool_input(struct tool *t, const char *opt, const char *path);
/* Output out_opt may be the input in_opt: a result of the same kind that
 * replaces it atomically after it was read in full (surfwarp -o IN IN). */
void tool_may_replace(struct tool *t, const char *out_opt, const char *in_opt);
/* Check an output path's extension up front (tool_bad if unknown). */
void tool_check_grid_path(struct tool *t, const char *opt, const char *path);

/* rc_table_begin on fp, in the pretty view (rc_table_pretty, as wide as
 * the terminal) when the table is TSV and fp is a terminal or --pretty
 * was given; exits 1 if out of memory. */
void tool_table_begin(const struct tool *t, rc_table_out *tab, FILE *fp);

/* Flush stdout and turn a write error into exit status 1. */
int tool_exit(const struct tool *t, int status);

#endif
