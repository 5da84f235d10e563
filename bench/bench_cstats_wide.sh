#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_cstats_wide.sh - contact-stats' time against the number of columns
# of its input (four rows, two surfaces of two grids each, and N carried
# key columns).  The reader indexes column names by hash, so the time per
# megabyte should stay flat as N grows (it grew as N, 51 s for 1.3 MB,
# when names were looked up by scanning).  Prints a table; never fails on
# time.  Run by make bench, or: RC_BIN=bin sh bench/bench_cstats_wide.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcwide.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
printf '%-8s %-8s %-10s %s\n' columns MB cpu_s cpu_s_per_MB
for n in ${BENCH_COLUMNS:-10000 20000 40000 80000}; do
	awk -v n="$n" 'BEGIN { h = "p_star\ta_r\tnx\tny\tlx"
		for (i = 1; i <= n; i++) h = h "\tc" i; print h
		for (r = 0; r < 4; r++) { nx = r % 2 ? 64 : 32
			l = 0.05 * (1 + int(r / 2)) "\t0.1\t" nx "\t" nx "\t1"
			for (i = 1; i <= n; i++) l = l "\t" i; print l } }' > "$TMP/w.tsv"
	bytes=$(wc -c < "$TMP/w.tsv")
	# CPU time (user + system) of the run, from the shell's times: wall
	# time on a shared machine says more about the neighbours
	cpu=$( ( "$RC_BIN/contact-stats" -q -o "$TMP/out.tsv" "$TMP/w.tsv" || exit 1
	    times ) | awk 'NR == 2 { for (i = 1; i <= 2; i++) { split($i, a, "m")
		s += a[1] * 60 + a[2] } print s }') || exit 1
	awk -v n="$n" -v b="$bytes" -v s="$cpu" 'BEGIN {
		mb = b / 1e6; printf "%-8d %-8.2f %-10.3f %.3f\n", n, mb, s, s / mb }'
done
