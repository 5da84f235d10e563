#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# convergence.sh - gfmd-solve on measured maps (tests/data/field_bcrf_128
# and field_bcrf_192, their READMEs): the default solve (free boundaries,
# FIRE) converges within 300 iterations per pressure (the 192^2 map at
# p* = 0.01 within 120) and agrees with a second loop; a solve that
# cannot progress ends as stalled, with exit 1 and a message, long before
# --max-iter; no progress line off a terminal.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP
MAP=$RC_TOP/tests/data/field_bcrf_128.surf

# --- The default solve.  Before SIGMA_DT_MAX (solver_fire_free.c) p* =
# 0.01 ran 1000 iterations without converging (a_r 0.35 instead of 0.09).
gfmd-solve -q -j 1 -p 0.01,0.05 "$MAP" > "$T/fire.tsv" 2> "$T/fire.err"
check "measured map, default solve: exit 0" test $? -eq 0
for k in 1 2; do
	it=$(col "$T/fire.tsv" iterations $k)
	check_range "measured map, pressure $k: at most 300 iterations" "$it" 1 300
done
# --- A second loop: the height-space FIRE on the padded grid
# (solver_fire_adh_free.c) with an adhesion too weak to count (sigma_max
# 1e-18 E*, 1e-14 of the pressures).  The same hard-wall problem, so the
# same contact set up to the points whose gap is within the tolerance of
# zero: n_c within 0.5 % (measured: equal, 1479 and 5647 points).
gfmd-solve -q -j 1 -p 0.01,0.05 --adhesion 1e-30 --range 1e-12 "$MAP" > "$T/pad.tsv"
check "measured map, padded height FIRE: exit 0" test $? -eq 0
for k in 1 2; do
	check_rel "measured map, pressure $k: n_c of both loops" \
	    "$(col "$T/pad.tsv" n_c $k)" "$(col "$T/fire.tsv" n_c $k)" 0.005
done
# CG (an independent method): the same contact sets (measured: equal).
# Before its damped steps (solver_cg.c) it cycled at p* = 0.01 (a_r 0.39).
gfmd-solve -q -j 1 -p 0.01,0.05 --method cg "$MAP" > "$T/cg.tsv"
check "measured map, CG: exit 0" test $? -eq 0
for k in 1 2; do
	check_range "measured map, CG, pressure $k: at most 300 iterations" \
	    "$(col "$T/cg.tsv" iterations $k)" 1 300
	check_rel "measured map, pressure $k: n_c of FIRE and CG" \
	    "$(col "$T/cg.tsv" n_c $k)" "$(col "$T/fire.tsv" n_c $k)" 0.005
done

# --- A larger measured map (tests/data/field_bcrf_192, its README): with
# only the fixed largest step SIGMA_DT_MAX (solver_fire_free.c) p* = 0.01
# took 159 iterations, points flip-flopping in and out of the active set;
# with the step rules 90 (the bound: 120).  The same contact sets as CG
# (measured: equal, 4282 and 14940 points).
MAP2=$RC_TOP/tests/data/field_bcrf_192.surf
gfmd-solve -q -j 1 -p 0.01,0.05 "$MAP2" > "$T/fire2.tsv"
check "192^2 measured map, default solve: exit 0" test $? -eq 0
check_range "192^2 measured map, p* = 0.01: at most 120 iterations" \
    "$(col "$T/fire2.tsv" iterations 1)" 1 120
check_range "192^2 measured map, p* = 0.05: at most 300 iterations" \
    "$(col "$T/fire2.tsv" iterations 2)" 1 300
gfmd-solve -q -j 1 -p 0.01,0.05 --method cg "$MAP2" > "$T/cg2.tsv"
check "192^2 measured map, CG: exit 0" test $? -eq 0
for k in 1 2; do
	check_rel "192^2 measured map, pressure $k: n_c of FIRE and CG" \
	    "$(col "$T/cg2.tsv" n_c $k)" "$(col "$T/fire2.tsv" n_c $k)" 0.005
done

# --- A stall: a tolerance below round-off (the residual floors near
# 1e-12).  The solve ends after at most two windows of 300 iterations,
# not at --max-iter, with exit 1 and the reason.
gfmd-solve -j 1 --tol 1e-20 --max-iter 100000 -p 0.01 "$MAP" > "$T/st.tsv" 2> "$T/st.err"
check "tolerance below round-off: exit 1" test $? -eq 1
check_range "stalled within two windows" "$(col "$T/st.tsv" iterations)" 300 600
check "the message says stalled and what to try" grep -q "stalled: .*try --method cg" "$T/st.err"
# stderr is a file here, not a terminal: no progress line
check "no progress line off a terminal" test "$(tr -cd '\r' < "$T/st.err" | wc -c)" -eq 0
gfmd-solve -j 1 --tol 1e-20 -p 0.01 "$MAP" 2>&1 >/dev/null | cat > "$T/pipe.err"
check "no progress line in a pipe" test "$(tr -cd '\r' < "$T/pipe.err" | wc -c)" -eq 0
# --stall 0: no watch, the solve runs to --max-iter
gfmd-solve -q -j 1 --tol 1e-20 --stall 0 --max-iter 700 -p 0.01 "$MAP" > "$T/ns.tsv" 2>/dev/null
check_rel "--stall 0 runs to --max-iter" "$(col "$T/ns.tsv" iterations)" 700 0
check_status "--stall -1 refused" 2 gfmd-solve --stall -1 -p 0.01 "$MAP"

echo "$T_PASS passed, $T_FAIL failed"
[ "$T_FAIL" -eq 0 ]
