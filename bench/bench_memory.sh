#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_memory.sh - peak resident memory per grid point of surfgen, surfstat
# and gfmd-solve (FIRE and CG), at 512^2, 1024^2 and 2048^2, measured with
# bench/peakrss (wait4's ru_maxrss).  Prints a table; never fails on size.
#   raw_B_per_pt  peak RSS / points
#   B_per_pt      (peak RSS - the same command's peak on a 32^2 grid) / points:
#                 what the grid costs, without the program's fixed part
#                 (libraries, FFTW's and OpenMP's start-up)
# gfmd-solve runs a bounded number of iterations (--max-iter; exit 1, "not
# converged", is expected): its buffers are all allocated before the first
# iteration, so the peak is reached; s_per_iter_pt is its solve time per
# iteration per grid point (wall time, all threads).
# BENCH_BIG=1 adds a 16384^2 surfgen and gfmd-solve (--max-iter 3): about
# 2.7e8 points, several GB and minutes; never run by make check.  Their
# address space is capped at the memory available now less 1 GB, so a run
# that does not fit fails with "out of memory" (exit 1) instead of waking
# the kernel's OOM killer on other processes.
# Run by make bench (RC_BIN, RC_BENCH_BIN set), or by hand:
#   RC_BIN=bin RC_BENCH_BIN=build/bench sh bench/bench_memory.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
: "${RC_BENCH_BIN:?RC_BENCH_BIN not set (the directory holding peakrss)}"
PEAKRSS=$RC_BENCH_BIN/peakrss
[ -x "$PEAKRSS" ] || { echo "bench_memory: $PEAKRSS: not built (make bench)" >&2; exit 1; }
SIZES=${BENCH_SIZES:-512 1024 2048}
ITER=${BENCH_ITER:-20}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcmem.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

# peak NAME N CMD...: run CMD under peakrss, print its peak bytes
# (and exit status in $TMP/NAME.status)
peak() {
	name=$1; shift
	"$PEAKRSS" -o "$TMP/$name.rss" "$@" >/dev/null 2>"$TMP/$name.err"
	read -r bytes status <"$TMP/$name.rss"
	echo "$status" >"$TMP/$name.status"
	echo "$bytes"
}

# The commands of one tool on the grid in $1 (an N^2 surface file) or N.
run_tool() {
	tool=$1 n=$2 surf=$3
	case $tool in
	surfgen) peak "$tool" "$RC_BIN/surfgen" -q -n "$n" -o "$TMP/gen.surf" ;;
	surfstat) peak "$tool" "$RC_BIN/surfstat" -q -o "$TMP/st.tsv" "$surf" ;;
	surfstat-psd) peak "$tool" "$RC_BIN/surfstat" -q --psd -o "$TMP/st.tsv" "$surf" ;;
	gfmd-fire|gfmd-cg)
		peak "$tool" "$RC_BIN/gfmd-solve" -q --method "${tool#gfmd-}" -p 0.05 \
		    --max-iter "$ITER" -o "$TMP/$tool.tsv" "$surf" ;;
	esac
}

col() {
	awk -F'\t' -v n="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == n) c = i; next }
		NR == 2 { print (c ? $c : "nan"); exit }' "$1"
}

TOOLS="surfgen surfstat surfstat-psd gfmd-fire gfmd-cg"
echo "threads: ${OMP_NUM_THREADS:-all $(getconf _NPROCESSORS_ONLN 2>/dev/null) cores}"
printf 'tool\tn\tpoints\tpeak_MB\traw_B_per_pt\tB_per_pt\texit\ts_per_iter_pt\n'
"$RC_BIN/surfgen" -q -n 32 -o "$TMP/s32.surf" || exit 1
for tool in $TOOLS; do
	base=$(run_tool "$tool" 32 "$TMP/s32.surf")
	for n in $SIZES; do
		"$RC_BIN/surfgen" -q -n "$n" -o "$TMP/s.surf" || exit 1
		bytes=$(run_tool "$tool" "$n" "$TMP/s.surf")
		st=$(cat "$TMP/$tool.status")
		spi=-
		case $tool in gfmd-*)
			[ -s "$TMP/$tool.tsv" ] && spi=$(awk -v s="$(col "$TMP/$tool.tsv" seconds)" \
			    -v i="$(col "$TMP/$tool.tsv" iterations)" -v n="$n" \
			    'BEGIN { if (i > 0) printf "%.3g", s / i / (n * n); else print "-" }') ;;
		esac
		awk -v t="$tool" -v n="$n" -v b="$bytes" -v z="$base" -v st="$st" -v spi="$spi" \
		    'BEGIN { p = n * n; printf "%s\t%d\t%d\t%.1f\t%.1f\t%.1f\t%s\t%s\n",
			t, n, p, b / 1048576, b / p, (b - z) / p, st, spi }'
	done
done

if [ "${BENCH_BIG:-0}" = 1 ]; then
	n=16384
	avail=$(awk '/MemAvailable/ { print $2 }' /proc/meminfo)
	echo "BENCH_BIG: $n^2, memory available $(awk -v a="$avail" 'BEGIN { printf "%.1f GB", a / 1048576 }'), cap $(awk -v a="$avail" 'BEGIN { printf "%.1f GB", a / 1048576 - 1 }')"
	for tool in surfgen gfmd-fire gfmd-cg; do
		base=$(run_tool "$tool" 32 "$TMP/s32.surf")
		[ -f "$TMP/big.surf" ] || { "$RC_BIN/surfgen" -q -n $n -o "$TMP/big.surf" || exit 1; }
		start=$(date +%s)
		case $tool in
		surfgen) bytes=$(ulimit -v $((avail - 1048576)); peak big "$RC_BIN/surfgen" -q \
		    -n $n -o "$TMP/big2.surf") ;;
		*) bytes=$(ulimit -v $((avail - 1048576)); peak big "$RC_BIN/gfmd-solve" -q \
		    --method "${tool#gfmd-}" -p 0.05 --max-iter 3 -o "$TMP/big.tsv" "$TMP/big.surf") ;;
		esac
		[ -s "$TMP/big.err" ] && sed 's/^/  /' "$TMP/big.err"
		[ -s "$TMP/big.tsv" ] && [ "$tool" != surfgen ] &&
		    echo "  $tool: $(col "$TMP/big.tsv" iterations) iterations in $(col "$TMP/big.tsv" seconds) s"
		rm -f "$TMP/big.tsv"
		rm -f "$TMP/big2.surf"
		awk -v t="$tool" -v n="$n" -v b="$bytes" -v z="$base" -v st="$(cat "$TMP/big.status")" \
		    -v s="$(( $(date +%s) - start ))" \
		    'BEGIN { p = n * n; printf "%s\t%d\t%d\t%.1f\t%.1f\t%.1f\t%s\twall %d s\n",
			t, n, p, b / 1048576, b / p, (b - z) / p, st, s }'
	done
fi
