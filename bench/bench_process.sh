#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_process.sh - the whole gfmd-solve process against its solve: one
# pressure (p* = 0.05) on bench_gfmd's surface (H = 0.8, lambda_r = L/2,
# lambda_s = L/64), no wisdom file (RC_WISDOM unset), periodic FIRE.
# Columns, medians of ROUNDS interleaved runs: iterations, solve_seconds
# (the row's seconds), plan_seconds (the row's: making the solver, its FFT
# plans included), whole_seconds (the process, wall clock: reading,
# planning, the solve, the contact analysis, writing), whole_cpu (its
# user + system CPU seconds, all threads), rest_cpu (the CPU seconds of
# the same process started from the solution with --init: everything but
# the iterations), whole_over_solve (wall over the row's seconds; goal at
# most 1.5, issue 29) and cpu_whole_over_solve (whole_cpu over whole_cpu
# - rest_cpu: the same ratio in CPU time, which the machine's other work
# disturbs far less), each the median of its own column.
# Then bench_gfmd's one-thread rows (BENCH_ITER_ONLY: FIRE iteration in FFT
# pairs, analysis over solve, CPU time) and the issue's ratios from this
# run in one block, with the load average before and after (the machine's
# other work inflates wall times; the iteration rows are CPU time).
# Prints; never fails on time.
#   BENCH_PROCESS_SIZES  grid sizes (default 512 1024 2048)
#   BENCH_PROCESS_BIG=1  also 4096 (memory: about 2 GB; minutes)
#   BENCH_PROCESS_ROUNDS rounds (default 3)
#   RC_BENCH_BIN         where bench_gfmd is (default build/bench); without
#                        it the iteration figures are skipped, saying so
# Run by make bench, or by hand:
#   RC_BIN=bin sh bench/bench_process.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
SIZES=${BENCH_PROCESS_SIZES:-512 1024 2048}
[ -n "${BENCH_PROCESS_BIG:-}" ] && SIZES="$SIZES 4096"
ROUNDS=${BENCH_PROCESS_ROUNDS:-3}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcproc.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
unset RC_WISDOM

now() { date +%s.%N; }
# cpu FILE0 FILE1: the children's user + system CPU seconds between two
# outputs of the shell's times builtin (run in this shell, not a subshell)
cpu() { cat "$1" "$2" | awk 'NR % 2 == 0 { split($1, u, "m"); split($2, s, "m");
	t[NR / 2] = u[1] * 60 + u[2] + s[1] * 60 + s[2] } END { print t[2] - t[1] }'; }
load() { cut -d ' ' -f 1-3 /proc/loadavg 2>/dev/null || echo unknown; }
load_before=$(load)
for n in $SIZES; do
	"$RC_BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.5 --lambda-s 0.015625 \
	    -o "$TMP/s$n.surf" || exit 1
done
echo "threads: ${OMP_NUM_THREADS:-all $(getconf _NPROCESSORS_ONLN 2>/dev/null) cores}"
r=1
while [ "$r" -le "$ROUNDS" ]; do
	for n in $SIZES; do
		t0=$(now)
		times >"$TMP/c0"
		"$RC_BIN/gfmd-solve" -q -p 0.05 -o "$TMP/r.tsv" "$TMP/s$n.surf" || exit 1
		times >"$TMP/c1"
		t1=$(now)
		awk -F'\t' -v n="$n" -v w="$(echo "$t1 $t0" | awk '{ print $1 - $2 }')" \
		    -v c="$(cpu "$TMP/c0" "$TMP/c1")" '
		    NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
		    { print n, $col["iterations"], $col["seconds"],
			$col["plan_seconds"], w, w / $col["seconds"], c }' \
		    "$TMP/r.tsv" >>"$TMP/runs"
		# Everything but the iterations: the same process started from
		# the solution (--init; 0 iterations, the same contact and
		# analysis; it also reads the start field, so it counts a
		# little more than the rest of the full run)
		[ -f "$TMP/u$n.npy" ] || "$RC_BIN/gfmd-solve" -q -p 0.05 \
		    --displacement "$TMP/u$n.npy" -o /dev/null "$TMP/s$n.surf" || exit 1
		times >"$TMP/c0"
		"$RC_BIN/gfmd-solve" -q -p 0.05 --init "$TMP/u$n.npy" -o /dev/null \
		    "$TMP/s$n.surf" || exit 1
		times >"$TMP/c1"
		echo "$n $(cpu "$TMP/c0" "$TMP/c1")" >>"$TMP/rest"
	done
	r=$((r + 1))
done
# median N COLUMN: the median of that column of size N's runs
median() {
	awk -v n="$1" '$1 == n' "$TMP/runs" | cut -d ' ' -f "$2" | sort -g |
	    awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
# rest N: the median CPU seconds of size N's runs from the solution
rest() {
	awk -v n="$1" '$1 == n { print $2 }' "$TMP/rest" | sort -g |
	    awk '{ v[NR] = $1 } END { print NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}
# cpu_ratio N: whole CPU over (whole CPU - the rest's CPU), the solve's
cpu_ratio() {
	echo "$(median "$1" 7) $(rest "$1")" | awk '{ printf "%.2f", ($1 > $2) ? $1 / ($1 - $2) : 0 }'
}
printf 'n\titerations\tsolve_seconds\tplan_seconds\twhole_seconds\twhole_cpu\trest_cpu\twhole_over_solve\tcpu_whole_over_solve\n'
for n in $SIZES; do
	printf '%d\t%d\t%.3f\t%.3f\t%.3f\t%.3f\t%.3f\t%.2f\t%s\n' "$n" \
	    "$(median "$n" 2)" "$(median "$n" 3)" "$(median "$n" 4)" \
	    "$(median "$n" 5)" "$(median "$n" 7)" "$(rest "$n")" \
	    "$(median "$n" 6)" "$(cpu_ratio "$n")"
done

# The one-thread iteration rows (bench_gfmd.c: 256^2-1024^2).
BG=${RC_BENCH_BIN:-build/bench}/bench_gfmd
if [ -x "$BG" ]; then
	echo
	BENCH_ITER_ONLY=1 "$BG" | tee "$TMP/iter"
else
	echo
	echo "SKIP: no $BG (make $BG, or set RC_BENCH_BIN): no iteration figures"
	: >"$TMP/iter"
fi
# iter N COLUMN: that column of bench_gfmd's row of size N, else "-"
iter() {
	awk -F'\t' -v n="$1" -v name="$2" '
	    $1 == "n" { for (i = 1; i <= NF; i++) c[$i] = i; next }
	    $1 == n && (name in c) { v = $c[name] }
	    END { print v == "" ? "-" : v }' "$TMP/iter"
}
echo
echo "# issue 29 ratios from this run (load average before: $load_before, after: $(load))"
printf 'figure\tvalue\tgoal\n'
for n in $SIZES; do
	printf 'whole_over_solve_%d\t%.2f\t1.5\n' "$n" "$(median "$n" 6)"
	printf 'cpu_whole_over_solve_%d\t%s\t1.5\n' "$n" "$(cpu_ratio "$n")"
done
printf 'fire_iter_in_pairs_512\t%s\t3.0\n' "$(iter 512 iter_in_pairs)"
printf 'fire_iter_in_pairs_1024\t%s\t2.3\n' "$(iter 1024 iter_in_pairs)"
printf 'analysis_in_solve_512\t%s\t0.25\n' "$(iter 512 analysis_in_solve)"
printf 'analysis_in_solve_1024\t%s\t0.25\n' "$(iter 1024 analysis_in_solve)"
