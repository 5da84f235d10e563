#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# rows.sh - the rows of gfmd-solve over one case of every solver loop
# (periodic FIRE in heights, FIRE on pressures on free boundaries, CG,
# plastic CG and FIRE, adhesive FIRE periodic and free, the layer bonded
# and slipping, displacement control, 1 and 2 threads, 64^2 to 256^2 and
# a 1024^2 solve on the blocked transforms), written without their timing
# columns, so that a change of the solver's code can be shown to give
# the same rows bit for bit.  Not part of make check (minutes):
#   sh tests/rows.sh BINDIR OUTDIR            write OUTDIR/<case>.tsv
#   sh tests/rows.sh BINDIR OUTDIR REFDIR     and compare with REFDIR
# Exit 1 when a case fails or differs from REFDIR.
set -u
bin=$(cd "$1" && pwd); out=$2; ref=${3:-}
mkdir -p "$out"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/rows.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
gen() { "$bin/surfgen" -q "$@"; }
gen -n 64 --seed 1 -o "$tmp/r64.surf"
gen -n 128 --seed 2 -o "$tmp/r128.surf"
gen -n 256 --seed 3 -o "$tmp/r256.surf"
gen -n 1024 --seed 4 -o "$tmp/r1024.surf"
gen -n 64 --type sine --wavelength 1 --amplitude 0.05 -o "$tmp/sine.surf"
gen -n 64 --seed 5 --rms-height 0.01 -o "$tmp/h64.surf"
ADH="--adhesion 0.0001 --range 0.005"
status=0
# case NAME SURFACE ARGS...: solve, cut the timing columns, compare
case_() {
	name=$1 surf=$2; shift 2
	if ! "$bin/gfmd-solve" -q "$@" "$tmp/$surf.surf" >"$tmp/$name.raw" 2>"$tmp/$name.err"; then
		echo "FAILED: $name: $(head -c 300 "$tmp/$name.err")"; status=1; return
	fi
	awk -F'\t' 'BEGIN { OFS = "\t" }
	NR == 1 { for (i = 1; i <= NF; i++) keep[i] = $i !~ /seconds$/ }
	{ s = ""; for (i = 1; i <= NF; i++) if (keep[i]) s = s (s == "" ? "" : "\t") $i; print s }' \
	    "$tmp/$name.raw" >"$out/$name.tsv"
	if [ -n "$ref" ]; then
		if cmp -s "$out/$name.tsv" "$ref/$name.tsv"; then
			echo "same: $name"
		else
			echo "DIFFERS: $name"; status=1
		fi
	else
		echo "written: $name"
	fi
}
case_ fire64 r64 -j 1 -p 0.01,0.05,0.2
case_ fire64j2 r64 -j 2 -p 0.01,0.05,0.2
case_ fire256 r256 -j 1 -p 0.05
case_ fire256j2 r256 -j 2 -p 0.05
case_ fire128pix r128 -j 1 --kernel pixel -p 0.05
case_ fire1024 r1024 -j 2 -p 0.1 --tol 1e-5
case_ cg128 r128 -j 1 --method cg -p 0.05,0.2
case_ cg128j2 r128 -j 2 --method cg -p 0.05
case_ freefire64 r64 -j 1 --boundary free -p 0.05,0.2
case_ freefire64j2 r64 -j 2 --boundary free -p 0.05
case_ freecg64 r64 -j 1 --boundary free --method cg -p 0.05,0.2
case_ plfire64 r64 -j 1 --hardness 0.5 -p 0.05,0.2
case_ plcg64 r64 -j 1 --method cg --hardness 0.5 -p 0.05,0.2
case_ plfreefire64 r64 -j 1 --boundary free --hardness 0.5 -p 0.05
case_ plfreecg64 r64 -j 1 --boundary free --method cg --hardness 0.5 -p 0.05
case_ plapp64 r64 -j 1 --hardness 0.5 --approach 0.05
case_ adh64 h64 -j 1 $ADH -p 0,0.05
case_ adh64j2 h64 -j 2 $ADH -p 0.05
case_ adhdug64 h64 -j 1 $ADH --law dugdale -p 0.05
case_ adhfree64 h64 -j 1 $ADH --boundary free -p 0.05
case_ adhapp64 h64 -j 1 $ADH --approach 0.01,0
case_ adhfreeapp64 h64 -j 1 $ADH --boundary free --approach 0.01
case_ adhsine sine -j 1 --adhesion 0.00694 --range 0.5 --approach 0.04,0.02
case_ adhlayer64 h64 -j 1 $ADH --thickness 0.2 --poisson 0.3 -p 0.05
case_ layer64 r64 -j 1 --thickness 0.1 --poisson 0.3 -p 0.05,0.2
case_ layerslip64 r64 -j 1 --thickness 0.1 --poisson 0.3 --substrate slip -p 0.05
case_ layercg64 r64 -j 1 --method cg --thickness 0.1 --poisson 0.3 -p 0.05
case_ layerfree64 r64 -j 1 --boundary free --thickness 0.1 --poisson 0.3 -p 0.05
case_ layerfreecg64 r64 -j 1 --boundary free --method cg --thickness 0.1 --poisson 0.3 --substrate slip -p 0.05
case_ layerpl64 r64 -j 1 --thickness 0.1 --poisson 0.3 --hardness 0.5 -p 0.05
case_ app64 r64 -j 1 --approach 0.02,0.05
case_ appcg64 r64 -j 1 --method cg --approach 0.05
case_ appfree64 r64 -j 1 --boundary free --approach 0.05
case_ appfreecg64 r64 -j 1 --boundary free --method cg --approach 0.05
case_ applayer64 r64 -j 1 --thickness 0.1 --poisson 0.3 --approach 0.05
exit $status
