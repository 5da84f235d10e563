#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_process.sh - the whole gfmd-solve process against its solve: one
# pressure (p* = 0.05) on bench_gfmd's surface (H = 0.8, lambda_r = L/2,
# lambda_s = L/64), no wisdom file (RC_WISDOM unset), periodic FIRE.
# Columns, medians of ROUNDS interleaved runs: iterations, solve_seconds
# (the row's seconds), plan_seconds (the row's: making the solver, its FFT
# plans included), whole_seconds (the process, wall clock: reading,
# planning, the solve, the contact analysis, writing) and whole_over_solve
# (goal at most 1.5, issue 29), each the median of its own column.  Prints a table; never fails on time.
#   BENCH_PROCESS_SIZES  grid sizes (default 512 1024 2048)
#   BENCH_PROCESS_ROUNDS rounds (default 3)
# Run by make bench, or by hand:
#   RC_BIN=bin sh bench/bench_process.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
SIZES=${BENCH_PROCESS_SIZES:-512 1024 2048}
ROUNDS=${BENCH_PROCESS_ROUNDS:-3}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcproc.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
unset RC_WISDOM

now() { date +%s.%N; }
for n in $SIZES; do
	"$RC_BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.5 --lambda-s 0.015625 \
	    -o "$TMP/s$n.surf" || exit 1
done
echo "threads: ${OMP_NUM_THREADS:-all $(getconf _NPROCESSORS_ONLN 2>/dev/null) cores}"
r=1
while [ "$r" -le "$ROUNDS" ]; do
	for n in $SIZES; do
		t0=$(now)
		"$RC_BIN/gfmd-solve" -q -p 0.05 -o "$TMP/r.tsv" "$TMP/s$n.surf" || exit 1
		t1=$(now)
		awk -F'\t' -v n="$n" -v w="$(echo "$t1 $t0" | awk '{ print $1 - $2 }')" '
		    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		    { print n, $c["iterations"], $c["seconds"], $c["plan_seconds"], w,
			w / $c["seconds"] }' \
		    "$TMP/r.tsv" >>"$TMP/runs"
	done
	r=$((r + 1))
done
# median N COLUMN: the median of that column of size N's runs
median() {
	awk -v n="$1" '$1 == n' "$TMP/runs" | cut -d ' ' -f "$2" | sort -g |
	    awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
printf 'n\titerations\tsolve_seconds\tplan_seconds\twhole_seconds\twhole_over_solve\n'
for n in $SIZES; do
	printf '%d\t%d\t%.3f\t%.3f\t%.3f\t%.2f\n' "$n" "$(median "$n" 2)" \
	    "$(median "$n" 3)" "$(median "$n" 4)" "$(median "$n" 5)" "$(median "$n" 6)"
done
