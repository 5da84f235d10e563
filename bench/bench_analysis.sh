#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_analysis.sh - surfstat on a finite patch (a detrended self-affine
# surface, so windowed by default): --psd (Hann), --psd1d x, --fit, and
# the periodic --psd without a window, each next to one bare FFTW r2c
# transform of the same size (bench_fftpair).  Wall seconds (the whole
# command, reading the file included) and peak resident bytes per grid
# point (bench/peakrss).  Prints a table; never fails on time.
#   BENCH_ANALYSIS_SIZES  grid sizes (default 4096)
# Run by make bench, or by hand:
#   RC_BIN=bin RC_BENCH_BIN=build/bench sh bench/bench_analysis.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
: "${RC_BENCH_BIN:?RC_BENCH_BIN not set (the directory holding peakrss)}"
PEAKRSS=$RC_BENCH_BIN/peakrss
FFT=$RC_BENCH_BIN/bench_fftpair
for x in "$PEAKRSS" "$FFT"; do
	[ -x "$x" ] || { echo "bench_analysis: $x: not built (make bench)" >&2; exit 1; }
done
SIZES=${BENCH_ANALYSIS_SIZES:-4096}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcana.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

now() { date +%s.%N; }
# run NAME N CMD...: one row
run() {
	name=$1 n=$2; shift 2
	t0=$(now)
	"$PEAKRSS" -o "$TMP/rss" "$@" >"$TMP/out" 2>"$TMP/err"
	t1=$(now)
	read -r bytes status <"$TMP/rss"
	awk -v name="$name" -v n="$n" -v t0="$t0" -v t1="$t1" -v b="$bytes" -v s="$status" \
	    -v extra="${EXTRA:-}" 'BEGIN { printf "%s\t%d\t%.3f\t%.1f\t%d\t%s\n", name, n,
	    t1 - t0, b / (n * n), s, extra }'
}

echo "threads: ${OMP_NUM_THREADS:-all $(getconf _NPROCESSORS_ONLN 2>/dev/null) cores}"
printf 'command\tn\tseconds\tB_per_pt\texit\tnote\n'
for n in $SIZES; do
	"$RC_BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.25 --rolloff -o "$TMP/s.surf"
	"$RC_BIN/surfwarp" -q --detrend plane "$TMP/s.surf" -o "$TMP/p.surf"
	EXTRA="r2c only: $("$FFT" "$n" | cut -f 2) s" run bare-r2c-fft "$n" "$FFT" "$n"
	EXTRA= run "surfstat --psd (periodic)" "$n" "$RC_BIN/surfstat" -q --psd "$TMP/s.surf"
	EXTRA= run "surfstat --psd (hann)" "$n" "$RC_BIN/surfstat" -q --psd "$TMP/p.surf"
	EXTRA= run "surfstat --psd1d x (hann)" "$n" "$RC_BIN/surfstat" -q --psd1d x "$TMP/p.surf"
	EXTRA="fits surfgen's H = 0.8" run "surfstat --fit (hann)" "$n" "$RC_BIN/surfstat" -q --fit \
	    -o "$TMP/fit.tsv" "$TMP/p.surf"
	echo "# fit at $n: H = $(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "H") c = i; next }
	    { print $c }' "$TMP/fit.tsv")"
	rm -f "$TMP/s.surf" "$TMP/p.surf"
done
