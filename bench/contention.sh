#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# contention.sh - gfmd-solve and surfstat while one other busy process
# competes for the cores: wall seconds of a 512^2 FIRE solve (p* = 0.05)
# and of surfstat on the same surface, with libgomp's default spinning
# wait (GOMP_SPINCOUNT=300000, libgomp's count when no policy is set: how
# the tools ran before they waited passively), with the tools' default (passive waiting: lib/threads.h) and with -j 1;
# each run has its own competitor (a shell loop, started before and killed
# after it, bounded by timeout), the rounds interleave the variants, and
# the table holds medians.  BENCH_ROUNDS rounds (default 5).  Run outside
# make -j (there the default is one thread).  Prints a table; never fails
# on time.  Run by make bench, or by hand:
#   RC_BIN=bin sh bench/contention.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
ROUNDS=${BENCH_ROUNDS:-5}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rccont.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
"$RC_BIN/surfgen" -q -n 512 --seed 1 -H 0.8 -o "$TMP/h.surf" || exit 1
[ -r /proc/loadavg ] && echo "# load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc 2>/dev/null || echo ?) cores"

# one timed run with a competitor: label, then the command
run() {
	label=$1
	shift
	timeout 300 sh -c 'while :; do :; done' &
	spinner=$!
	t0=$(date +%s.%N)
	env -u MAKEFLAGS "$@" >/dev/null 2>&1
	t1=$(date +%s.%N)
	kill "$spinner"
	wait "$spinner" 2>/dev/null
	echo "$label $t0 $t1" | awk '{ printf "%s %.4f\n", $1, $3 - $2 }' >>"$TMP/times"
}
: >"$TMP/times"
r=0
while [ $r -lt "$ROUNDS" ]; do
	for tool in gfmd-solve surfstat; do
		if [ $tool = gfmd-solve ]; then args="-q -p 0.05 -o /dev/null"; else args="-q -o /dev/null"; fi
		run "$tool:spinning" -u OMP_WAIT_POLICY GOMP_SPINCOUNT=300000 "$RC_BIN/$tool" $args "$TMP/h.surf"
		run "$tool:default" -u OMP_WAIT_POLICY "$RC_BIN/$tool" $args "$TMP/h.surf"
		run "$tool:j1" -u OMP_WAIT_POLICY "$RC_BIN/$tool" -j 1 $args "$TMP/h.surf"
	done
	r=$((r + 1))
done
printf 'tool\tspinning\tdefault\tj1\tdefault_over_j1\n'
sort -k1,1 -k2g "$TMP/times" | awk '
	{ split($1, k, ":"); n[$1]++; v[$1, n[$1]] = $2; tools[k[1]] = 1 }
	function med(key) { c = n[key]; return c % 2 ? v[key, (c + 1) / 2] : (v[key, c / 2] + v[key, c / 2 + 1]) / 2 }
	END { for (t in tools) printf "%s\t%.3f\t%.3f\t%.3f\t%.2f\n", t,
		med(t ":spinning"), med(t ":default"), med(t ":j1"), med(t ":default") / med(t ":j1") }'
