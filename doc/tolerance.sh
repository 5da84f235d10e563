#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# tolerance.sh - what gfmd-solve --tol buys: bench_gfmd's surface (256^2,
# H = 0.8, lambda_r = L/2, lambda_s = L/64, seed 1) at p* = 0.05, solved
# by FIRE and CG at each tolerance; a_r against a FIRE solve at 1e-13, in
# contact points (a_r n_tot).  Prints a table (make doc, doc/validation.md).
#   RC_BIN=bin sh doc/tolerance.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rctol.XXXXXX") || exit 1
trap 'rm -rf "$TMP"' EXIT
n=${TOL_N:-256}
"$RC_BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.5 --lambda-s 0.015625 \
    --seed 1 -o "$TMP/s.surf" || exit 1
# row FILE COLUMN: the first row's value of a column
col() {
	awk -F'\t' -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == c) k = i; next }
	    NR == 2 { print $k; exit }' "$1"
}
solve() {	# METHOD TOL: the row in $TMP/METHOD-TOL.tsv
	"$RC_BIN/gfmd-solve" -q -j 1 --method "$1" --tol "$2" -p 0.05 \
	    -o "$TMP/$1-$2.tsv" "$TMP/s.surf" || exit 1
}
solve fire 1e-13
ref=$(col "$TMP/fire-1e-13.tsv" n_c)
printf '# %d^2, p* = 0.05, one thread; a_r error in contact points against FIRE at 1e-13 (n_c %s)\n' "$n" "$ref"
printf 'tol\tfire_iterations\tfire_n_c_error\tcg_iterations\tcg_n_c_error\n'
for tol in 1e-3 1e-4 1e-6 1e-9; do
	solve fire "$tol"; solve cg "$tol"
	printf '%s\t%s\t%s\t%s\t%s\n' "$tol" \
	    "$(col "$TMP/fire-$tol.tsv" iterations)" \
	    "$(( $(col "$TMP/fire-$tol.tsv" n_c) - ref ))" \
	    "$(col "$TMP/cg-$tol.tsv" iterations)" \
	    "$(( $(col "$TMP/cg-$tol.tsv" n_c) - ref ))"
done
