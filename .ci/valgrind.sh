#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# .ci/valgrind.sh - one small pipeline under valgrind's memcheck: any
# invalid access, use of uninitialised memory or leak (definite, indirect
# or possible) fails the run.  The tools run single-threaded (-j 1,
# OMP_NUM_THREADS=1): libgomp's thread pool is never freed on purpose and
# would show up as "possibly lost"; .ci/valgrind.supp holds what remains
# of that noise.  Uses the normal build (bin/); needs valgrind.
#   sh .ci/valgrind.sh
set -u
cd "$(dirname "$0")/.." || exit 1
command -v valgrind >/dev/null 2>&1 || { echo "valgrind.sh: valgrind not installed" >&2; exit 1; }
make -s all >/dev/null || exit 1
export OMP_NUM_THREADS=1
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rcvg.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
status=0 n=0

vg() {	# vg NAME TOOL ARGS...: run bin/TOOL under memcheck, stdin/stdout passed on
	name=$1; shift
	valgrind -q --error-exitcode=99 --leak-check=full \
	    --show-leak-kinds=definite,indirect,possible \
	    --errors-for-leak-kinds=definite,indirect,possible \
	    --track-origins=yes --suppressions=.ci/valgrind.supp \
	    --log-file="$tmp/$name.log" "bin/$@"
}

report() {	# report NAME STATUS
	n=$((n + 1))
	if [ "$2" -eq 0 ] && [ ! -s "$tmp/$1.log" ]; then
		printf 'valgrind: %-28s clean\n' "$1"
	else
		status=1
		printf 'valgrind: %-28s FAILED (exit %s)\n' "$1" "$2"
		sed 's/^/    /' "$tmp/$1.log" | head -n 40
	fi
}

# surfgen | surfwarp | surfstat, each stage under valgrind (the statuses of
# the first two stages are kept in files: sh has no pipefail).
{ vg surfgen surfgen -j 1 -n 32 --seed 5; echo $? >"$tmp/st1"; } |
    { vg surfwarp surfwarp -j 1 -w 2; echo $? >"$tmp/st2"; } |
    vg surfstat surfstat -j 1 >"$tmp/stat.tsv"
st3=$?
report surfgen "$(cat "$tmp/st1")"
report surfwarp "$(cat "$tmp/st2")"
report surfstat "$st3"
[ "$(wc -l <"$tmp/stat.tsv")" = 2 ] || { echo "valgrind: surfstat wrote no table row"; status=1; }
bin/surfgen -q -j 1 -n 32 --seed 5 -o "$tmp/s.surf"
vg surfstat-psd surfstat -j 1 --psd -o "$tmp/psd.tsv" "$tmp/s.surf"
report surfstat-psd $?
# A height map is no mask: the failure path (exit 1) must be clean too.
vg surfstat-bad-mask surfstat -j 1 --mask "$tmp/s.surf" -o "$tmp/psd.tsv" "$tmp/s.surf" 2>/dev/null
st=$?; [ "$st" = 1 ] && st=0; report surfstat-bad-mask "$st"
vg gfmd-fire gfmd-solve -q -j 1 -p 0.05,0.1 --contact "$tmp/c.surf" \
    --gap "$tmp/g.surf" --png "$tmp/c.png" -o "$tmp/fire.tsv" "$tmp/s.surf"
report gfmd-fire $?
vg gfmd-cg gfmd-solve -q -j 1 --method cg -p 0.1 -o "$tmp/cg.tsv" "$tmp/s.surf"
report gfmd-cg $?
# adhesion on free boundaries: the padded heights, load and displacement
# control (lib/solver/solver_fire_adh_free.c)
vg gfmd-adh-free gfmd-solve -q -j 1 --boundary free --adhesion 0.001 \
    --range 0.01 --approach 0.02,0.01 --pressure "$tmp/p.surf" \
    -o "$tmp/adh.tsv" "$tmp/s.surf" 2>/dev/null
report gfmd-adh-free $?
vg surfstat-mask surfstat -j 1 --mask "$tmp/c.surf" -o "$tmp/m.tsv" "$tmp/s.surf"
report surfstat-mask $?
# netCDF through the loaded libnetcdf: every byte written is initialised
# (its in-memory file once came back larger than its contents).
vg surfwarp-nc surfwarp -j 1 --detrend plane -o "$tmp/s.nc" "$tmp/s.surf"
report surfwarp-nc $?
vg surfstat-nc surfstat -j 1 -o "$tmp/nc.tsv" "$tmp/s.nc"
report surfstat-nc $?
vg contact-stats contact-stats -q --no-extrapolate -o "$tmp/cs.tsv" "$tmp/fire.tsv"
report contact-stats $?
echo "valgrind: $n runs, $([ "$status" = 0 ] && echo "all clean" || echo "FAILURES")"
exit "$status"
