#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_cstats_perseed.sh - contact-stats --per-seed against the number of
# input rows (S seeds x 3 grids x 2 pressures): one output group per seed
# and pressure, so the run should grow as n log n (the output ordering
# and the curve labels compared every group with every other: 9,000,
# 18,000 and 99,996 of these rows took 2.05, 9.94 and 249 s of CPU, now
# 0.25, 0.45 and 1.98 s; issue 27).  Prints rows, CPU seconds with and without
# --per-seed and the CPU seconds per 1000 rows; never fails on time.
#   RC_BIN=bin sh bench/bench_cstats_perseed.sh   (BENCH_ROWS="9000 ...")
set -u
: "${RC_BIN:?RC_BIN not set}"
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcperseed.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

# cpu CMD...: user + system seconds of CMD (wall time on a shared machine
# says more about the neighbours)
cpu() {
	( "$@" || exit 1; times ) | awk 'NR == 2 { for (i = 1; i <= 2; i++) {
		split($i, a, "m"); s += a[1] * 60 + a[2] } print s }'
}

printf '%-8s %-12s %-12s %s\n' rows per_seed_s ensemble_s per_seed_s_per_1000
for n in ${BENCH_ROWS:-9000 18000 100000}; do
	awk -v seeds=$((n / 6)) 'BEGIN { OFS = "\t"
		print "p_star", "a_r", "nx", "ny", "lx", "ly", "lambda_s", "seed"
		for (s = 1; s <= seeds; s++) for (k = 1; k <= 2; k++)
			for (j = 0; j < 3; j++) { nx = 64 * 2 ^ j
				print 0.05 * k, 0.1 * k + 0.001 * (s % 97) + 0.02 * 16 / nx,
				    nx, nx, 1, 1, 0.0625, s } }' > "$TMP/rows.tsv"
	rows=$(($(wc -l < "$TMP/rows.tsv") - 1))
	ps=$(cpu "$RC_BIN/contact-stats" -q --per-seed -o "$TMP/out.tsv" "$TMP/rows.tsv") || exit 1
	ens=$(cpu "$RC_BIN/contact-stats" -q -o "$TMP/out.tsv" "$TMP/rows.tsv") || exit 1
	awk -v r="$rows" -v p="$ps" -v e="$ens" 'BEGIN {
		printf "%-8d %-12.3f %-12.3f %.4f\n", r, p, e, p / r * 1000 }'
done
