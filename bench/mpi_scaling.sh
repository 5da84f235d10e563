#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# mpi_scaling.sh - the MPI build's gfmd-solve (make MPI=1) on 1 and 2 ranks
# of this machine: wall seconds per FIRE iteration on an N^2 grid (default
# 1024^2; BENCH_MPI_N to change), the same bounded number of iterations
# (--max-iter; exit 1, "not converged", is expected), one thread per rank;
# speedup is relative to 1 rank.  No --oversubscribe: with it OpenMPI
# runs in its oversubscribed mode (a waiting rank yields its core), and 2
# ranks on 2 cores took twice as long as 1 (measured: 0.150 against 0.074 s
# per iteration).  Needs 2 cores.
# Prints a table; never fails on time.  Skipped (exit 0) when the MPI build
# or mpirun is missing.  Run by make bench, or by hand:
#   RC_BIN=bin sh bench/mpi_scaling.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
N=${BENCH_MPI_N:-1024}
ITER=${BENCH_MPI_ITER:-40}
MPI_BIN=${RC_MPI_BIN:-build/mpi/bin}
if [ ! -x "$MPI_BIN/gfmd-solve" ] || ! command -v mpirun >/dev/null 2>&1; then
	echo "mpi_scaling: $MPI_BIN/gfmd-solve or mpirun missing (make MPI=1); skipped"
	exit 0
fi
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcmpi.XXXXXX")
trap 'rm -rf "$TMP"' EXIT
"$RC_BIN/surfgen" -n "$N" --seed 1 --lambda-r 0.5 -o "$TMP/h.surf" || exit 1
[ -r /proc/loadavg ] && echo "# load average $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc 2>/dev/null || echo ?) cores"
# The serial tool with one thread first, for reference (row "serial").
printf 'ranks\tpoints\titerations\tseconds\ts_per_iter\tspeedup\n'
base=
for np in serial 1 2; do
	if [ $np = serial ]; then
		"$RC_BIN/gfmd-solve" -j 1 -q --tol 1e-12 --max-iter "$ITER" -p 0.05 \
		    "$TMP/h.surf" >"$TMP/r.tsv" 2>/dev/null
	else
		OMP_NUM_THREADS=1 mpirun --allow-run-as-root -np $np \
		    "$MPI_BIN/gfmd-solve" -q --tol 1e-12 --max-iter "$ITER" -p 0.05 \
		    "$TMP/h.surf" >"$TMP/r.tsv" 2>/dev/null
	fi
	line=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		{ print $c["iterations"], $c["seconds"] }' "$TMP/r.tsv")
	if [ -z "$line" ]; then
		echo "$np: no result (mpirun failed: fewer cores than ranks?)"
		continue
	fi
	set -- $line
	per=$(awk -v s="$2" -v i="$1" 'BEGIN { printf "%.4g", s / i }')
	[ -n "$base" ] || [ $np = serial ] || base=$per
	printf '%s\t%s\t%s\t%.3f\t%s\t%s\n' $np $((N * N)) "$1" "$2" "$per" \
	    "$(awk -v b="$base" -v p="$per" 'BEGIN { if (b == "") print "-"; else printf "%.2f", b / p }')"
done
