#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# free.sh - gfmd-solve --boundary free and --approach end to end: Hertz
# without periodic images, load and displacement control as inverses,
# both methods, the rows, the refusals, and a pipeline into contact-stats.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP
pi=3.14159265358979324

# --- Hertz: h = -r^2/(2R), R = 1, on a 64^2 grid of a 1 x 1 cell, peak on
# pixel (32, 32).  At the load F = 4 E* a^3 / (3R), a = 1/4 (cell area 1,
# so p = F): delta = a^2/R.  tests/test_free.c measures the approach error
# -8.3e-5 at this grid (tolerance 2e-4 here) and the contact radius within
# dx/10 (a_r is checked to within a pixel of the radius).
n=64
awk -v n=$n 'BEGIN { print "# nx = " n; print "# ny = " n; print "# lx = 1"; print "# ly = 1";
	for (j = 0; j < n; j++) { l = ""; for (i = 0; i < n; i++) { x = (i - n / 2) / n; y = (j - n / 2) / n;
	l = l sprintf("%.17g ", -(x * x + y * y) / 2) } print l } }' > "$T/hertz.txt"
F=$(awk 'BEGIN { printf "%.17g\n", 4 * 0.25 ^ 3 / 3 }')
for m in fire cg; do
	gfmd-solve -q -j 1 --boundary free --method $m --pressure-abs "$F" "$T/hertz.txt" > "$T/hz_$m.tsv"
	check "Hertz free $m converges" test $? -eq 0
	check_rel "Hertz free $m: approach = a^2/R" "$(col "$T/hz_$m.tsv" approach)" 0.0625 2e-4
	check_range "Hertz free $m: a_r = pi a^2 within a pixel" "$(col "$T/hz_$m.tsv" a_r)" \
	    "$(awk -v pi=$pi -v n=$n 'BEGIN { print pi * ((0.25 - 1 / n) ^ 2) }')" \
	    "$(awk -v pi=$pi -v n=$n 'BEGIN { print pi * ((0.25 + 1 / n) ^ 2) }')"
	check "Hertz free $m: boundary is free" test "$(col "$T/hz_$m.tsv" boundary)" = free
	check_rel "Hertz free $m: one patch" "$(col "$T/hz_$m.tsv" n_patches)" 1 0
	# Displacement control at the approach load control gave: the same
	# load (the root find stops at tol * delta in the approach; the load
	# then agrees to ~1e-6).
	delta=$(col "$T/hz_$m.tsv" approach)
	gfmd-solve -q -j 1 --boundary free --method $m --approach "$delta" "$T/hertz.txt" > "$T/hzd_$m.tsv"
	check "Hertz free $m --approach converges" test $? -eq 0
	check_rel "Hertz free $m: --approach gives the load back" "$(col "$T/hzd_$m.tsv" p)" "$F" 1e-5
	check_rel "Hertz free $m: --approach reached" "$(col "$T/hzd_$m.tsv" approach)" "$delta" 1e-6
	check_rel "Hertz free $m: same contact" "$(col "$T/hzd_$m.tsv" n_c)" "$(col "$T/hz_$m.tsv" n_c)" 0
done
check_rel "Hertz free: fire and cg agree on a_r" "$(col "$T/hz_fire.tsv" a_r)" "$(col "$T/hz_cg.tsv" a_r)" 0
# The periodic solve of the same grid feels its images: its approach
# (against the mean surface height, gfmd-solve(1)) is 40% below a^2/R.
gfmd-solve -q -j 1 --pressure-abs "$F" "$T/hertz.txt" > "$T/hz_per.tsv"
check "periodic is the default for a periodic grid" test "$(col "$T/hz_per.tsv" boundary)" = periodic
check_range "Hertz periodic: approach far from a^2/R" "$(col "$T/hz_per.tsv" approach)" 0 0.05
# The fields of a free solve describe an isolated patch: periodic = 0 in
# their headers although the indenter is periodic; a periodic solve's
# fields stay periodic.
gfmd-solve -q -j 1 --boundary free --pressure-abs "$F" --gap "$T/fg.surf" \
    --pressure "$T/fp.surf" --contact "$T/fc.surf" --displacement "$T/fu.surf" \
    "$T/hertz.txt" > /dev/null
check "free fields written" test $? -eq 0
for field in fg fp fc fu; do
	check "free field $field: periodic = 0" grep -aq '^periodic = 0$' "$T/$field.surf"
done
gfmd-solve -q -j 1 --pressure-abs "$F" --gap "$T/pg.surf" "$T/hertz.txt" > /dev/null
check "periodic field: periodic = 1" grep -aq '^periodic = 1$' "$T/pg.surf"

# --- Refusals.
check_status "--boundary bogus" 2 gfmd-solve --boundary bogus -p 0.1 "$T/hertz.txt"
check_status "--approach 0" 2 gfmd-solve --approach 0 "$T/hertz.txt"
check_status "--approach with -p" 2 gfmd-solve --approach 0.01 -p 0.1 "$T/hertz.txt"
check_status "--approach with --checkpoint" 2 gfmd-solve --approach 0.01 --checkpoint "$T/ck.surf" "$T/hertz.txt"
surfgen --type sine -n 64x1 --wavelength 1 --amplitude 0.01 -o "$T/line.surf"
check_status "free boundaries on a line grid" 1 gfmd-solve --boundary free -p 0.1 "$T/line.surf"
check "free line: the message says why" grep -q "line contact" "$T/stderr"
# max h - <h> of the paraboloid is about 1/12: full contact comes first.
check_status "periodic approach beyond full contact" 1 gfmd-solve --approach 1 "$T/hertz.txt"
check "beyond full contact: the message says why" grep -q "full contact" "$T/stderr"

# --- A rough map as an isolated patch, three resolutions of one surface,
# into contact-stats: the rows group into one problem (boundary is a key,
# approach is an output) extrapolated over the three discretisations.  The
# free answer differs from the periodic one (the edges are free).
for k in 32 64 128; do
	surfgen -n $k --seed 4 --lambda-s 0.125 -o "$T/r$k.surf"
	gfmd-solve -q -j 1 --boundary free -p 0.05,0.1 "$T/r$k.surf" > "$T/f$k.tsv"
done
gfmd-solve -q -j 1 -p 0.05 "$T/r128.surf" > "$T/p128.tsv"
check "rough free vs periodic: a_r differs" test "$(col "$T/f128.tsv" a_r)" != "$(col "$T/p128.tsv" a_r)"
contact-stats -q -o "$T/cs.tsv" "$T/f32.tsv" "$T/f64.tsv" "$T/f128.tsv"
check "contact-stats over free rows" test $? -eq 0
check "contact-stats: boundary carried as a key" test "$(col "$T/cs.tsv" boundary)" = free
check_rel "contact-stats: three discretisations in one group" "$(col "$T/cs.tsv" n_disc)" 3 0
check_rel "contact-stats: two pressures" "$(awk 'END { print NR - 1 }' "$T/cs.tsv")" 2 0
# --- A measured map end to end: a tilted, non-periodic map (a Gwyddion
# ASCII export, which carries no periodic flag: read as a finite patch)
# -> surfwarp --detrend plane -> gfmd-solve (free boundaries by default,
# from the periodic = 0 the detrend writes) -> contact-stats.  The map is
# a levelled surface plus a plane of slope 0.5, so detrending gives that
# surface back to round-off and the contact must be the same.
surfgen -q -n 64 --seed 11 -o "$T/m.surf"
surfwarp -q --detrend plane -o "$T/level0.txt" "$T/m.surf"
{
	echo "# Channel: Height"
	echo "# Width: 1.000 m"
	echo "# Height: 1.000 m"
	echo "# Value units: m"
	awk '!/^#/ { for (i = 1; i <= NF; i++) printf "%.17g%s", $i + 0.5 * (i - 1) / NF + 0.25 * (NR - 1) / 64, i < NF ? " " : "\n" }' "$T/level0.txt"
} >"$T/measured.txt"
surfwarp -q --detrend plane -o "$T/levelled.surf" "$T/measured.txt"
check "detrended measured map is marked non-periodic" grep -aq '^periodic = 0$' "$T/levelled.surf"
gfmd-solve -q -j 1 -p 0.05 -o "$T/meas.tsv" "$T/levelled.surf"
check "a non-periodic map is solved with free boundaries by default" \
    test "$(col "$T/meas.tsv" boundary)" = free
gfmd-solve -q -j 1 --boundary free -p 0.05 -o "$T/orig.tsv" "$T/level0.txt"
check_rel "levelled tilted map: the same a_r as the untilted surface" \
    "$(col "$T/meas.tsv" a_r)" "$(col "$T/orig.tsv" a_r)" 1e-9
gfmd-solve -q -j 1 --boundary periodic -p 0.05 -o "$T/raw.tsv" "$T/measured.txt" 2>"$T/stderr"
check "the tilted map as if periodic warns about the wrap-around step" \
    grep -q "step across its edges" "$T/stderr"
check "... and gives another a_r" test "$(col "$T/raw.tsv" a_r)" != "$(col "$T/meas.tsv" a_r)"
contact-stats -q --no-extrapolate -o "$T/mcs.tsv" "$T/meas.tsv"
check "contact-stats takes the measured rows" test "$(col "$T/mcs.tsv" boundary)" = free
summary
