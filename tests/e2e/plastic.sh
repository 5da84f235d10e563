#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# plastic.sh - gfmd-solve --hardness end to end, both methods: a flat
# indenter reaches the plastic limit at p = H, full plasticity gives
# a_r = p/H, a huge H gives the elastic answer, FIRE agrees with the CG
# (both boundaries, and with a layer), --approach gives the load back,
# the rows, the refusals, and contact-stats keeping hardness as a key.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP

# --- A flat indenter in full contact carries sigma = p everywhere: no
# point at H below p = H, every point at H at p = H.
surfgen -q -n 16 --type flat -o "$T/flat.surf"
for m in cg fire; do
	gfmd-solve -q -j 1 --method $m --hardness 0.5 --pressure-abs 0.25,0.5 "$T/flat.surf" > "$T/flat.tsv" 2>/dev/null
	check "$m flat: converges" test $? -eq 0
	check_rel "$m flat p = H/2: a_r = 1" "$(col "$T/flat.tsv" a_r 1)" 1 0
	check_rel "$m flat p = H/2: no plastic point" "$(col "$T/flat.tsv" a_plastic 1)" 0 0
	check_rel "$m flat p = H: every point plastic" "$(col "$T/flat.tsv" a_plastic 2)" 1 0
	check_rel "$m flat: hardness recorded" "$(col "$T/flat.tsv" hardness 1)" 0.5 0
done

# --- Full plasticity on a rough surface (H = 0.01 E*, p = H/2, H/10):
# a_plastic <= p/H <= a_r exactly, and the band between them is the few
# elastic edge points (tests/test_plastic.c: ~1e-3; tolerance 0.01).
surfgen -q -n 64 --seed 3 -o "$T/r.surf"
for m in cg fire; do
	gfmd-solve -q -j 1 --method $m --hardness 0.01 --pressure-abs 0.005,0.001 "$T/r.surf" > "$T/full.tsv"
	check "$m full plasticity: converges" test $? -eq 0
	for r in 1 2; do
		f=$(awk -v r=$r 'BEGIN { print r == 1 ? 0.5 : 0.1 }')
		check_range "$m full plasticity p/H = $f: a_plastic <= p/H" "$(col "$T/full.tsv" a_plastic $r)" 0 "$f"
		check_range "$m full plasticity p/H = $f: a_r >= p/H, within 0.01" "$(col "$T/full.tsv" a_r $r)" "$f" "$(awk -v f=$f 'BEGIN { print f + 0.01 }')"
	done
done

# --- H = 1e6 p never binds: the same contact as the elastic solve of the
# same method, and the approach within the tolerance's effect on it
# (1e-6 relative).
for m in cg fire; do
	gfmd-solve -q -j 1 --method $m --pressure-abs 0.05 "$T/r.surf" > "$T/el.tsv"
	gfmd-solve -q -j 1 --method $m --hardness 5e4 --pressure-abs 0.05 "$T/r.surf" > "$T/big.tsv"
	check_rel "$m H = 1e6 p: same n_c as elastic" "$(col "$T/big.tsv" n_c)" "$(col "$T/el.tsv" n_c)" 0
	check_rel "$m H = 1e6 p: same approach" "$(col "$T/big.tsv" approach)" "$(col "$T/el.tsv" approach)" 1e-6
	check_rel "$m H = 1e6 p: no plastic point" "$(col "$T/big.tsv" a_plastic)" 0 0
done
check_rel "without --hardness: hardness 0 (no cap)" "$(col "$T/el.tsv" hardness)" 0 0
check_rel "without --hardness: a_plastic 0" "$(col "$T/el.tsv" a_plastic)" 0 0

# --- FIRE against the CG (H = 4 p; periodic, free, and a layer): the
# same contact and plastic sets (the solution is unique; measured: the
# same to the point), the approach within 1e-6 relative (both to the
# default tol 1e-6; measured 5e-11 .. 9e-10).  Then --approach D, D the
# approach of that load, gives it back: the approach within the root
# find's tol D (1e-6 D), p within 1e-5 relative (d ln p / d ln D is
# about 2; measured 7e-7).
for b in periodic free layer; do
	case $b in
	layer) bo="--thickness 0.1 --poisson 0.3" ;;
	*) bo="--boundary $b" ;;
	esac
	for m in cg fire; do
		gfmd-solve -q -j 1 --method $m $bo --hardness 0.2 --pressure-abs 0.05 "$T/r.surf" > "$T/$m.tsv"
		check "$m $b H = 4 p: converges" test $? -eq 0
	done
	check_rel "$b H = 4 p: FIRE n_c = CG n_c" "$(col "$T/fire.tsv" n_c)" "$(col "$T/cg.tsv" n_c)" 0
	check_rel "$b H = 4 p: FIRE a_plastic = CG a_plastic" "$(col "$T/fire.tsv" a_plastic)" "$(col "$T/cg.tsv" a_plastic)" 0
	check_rel "$b H = 4 p: FIRE approach = CG approach" "$(col "$T/fire.tsv" approach)" "$(col "$T/cg.tsv" approach)" 1e-6
	[ $b = layer ] && continue
	for m in cg fire; do
		dd=$(col "$T/$m.tsv" approach)
		gfmd-solve -q -j 1 --method $m $bo --hardness 0.2 --approach "$dd" "$T/r.surf" > "$T/a.tsv"
		check "$m $b --hardness --approach: converges" test $? -eq 0
		check_rel "$m $b --approach D: approach D" "$(col "$T/a.tsv" approach)" "$dd" 1e-6
		check_rel "$m $b --approach D: the load back" "$(col "$T/a.tsv" p)" 0.05 1e-5
	done
done

# --- Refusals.
check_status "--hardness with --adhesion" 2 gfmd-solve --hardness 1 --adhesion 0.01 --range 0.01 -p 0.1 "$T/r.surf"
check "--hardness with --adhesion: the message says why" grep -q "no unloading" "$T/stderr"
check_status "--hardness 0" 2 gfmd-solve --method cg --hardness 0 -p 0.1 "$T/r.surf"
check_status "--hardness -1" 2 gfmd-solve --method cg --hardness -1 -p 0.1 "$T/r.surf"
check_status "--hardness with --checkpoint: accepted (recorded)" 0 gfmd-solve -q --method cg --hardness 1 --checkpoint "$T/ck.surf" -p 0.1 "$T/r.surf"
gfmd-solve -q -j 1 --hardness 0.2 --pressure-abs 0.05,0.1 "$T/r.surf" > "$T/fh1.tsv"
gfmd-solve -q -j 1 --hardness 0.2 --pressure-abs 0.05,0.1 --checkpoint "$T/fck.surf" "$T/r.surf" > "$T/fh2.tsv"
check "FIRE --hardness with --checkpoint: the same rows" test "$(cut -f 1-20 "$T/fh1.tsv")" = "$(cut -f 1-20 "$T/fh2.tsv")"
check_status "p > H" 1 gfmd-solve --hardness 0.01 --pressure-abs 0.02 "$T/r.surf"
check "p > H: the message says why" grep -q "exceeds the hardness" "$T/stderr"
check_status "--approach past the plastic limit" 1 gfmd-solve -q --hardness 0.2 --approach 10 "$T/r.surf"
check "--approach past the plastic limit: the message says why" grep -q "not reached below the hardness" "$T/stderr"
# H = 0.05: exp and log of the bracket once stalled a few ulps below H,
# so the same case ran 60 solves at p = H and ended "not bracketed".
for m in fire cg; do
	check_status "--approach past the plastic limit, H = 0.05, $m" 1 gfmd-solve -q --method $m --hardness 0.05 --approach 1 "$T/r.surf"
	check "--approach past the plastic limit, H = 0.05, $m: names the hardness" grep -q "not reached below the hardness" "$T/stderr"
done

# --- contact-stats: hardness is a key (two hardnesses, two groups) and
# a_plastic a result.
gfmd-solve -q -j 1 --method cg --hardness 0.5 --pressure-abs 0.05 "$T/r.surf" > "$T/h1.tsv"
gfmd-solve -q -j 1 --method cg --hardness 0.2 --pressure-abs 0.05 "$T/r.surf" > "$T/h2.tsv"
contact-stats -q --no-extrapolate -o "$T/cs.tsv" "$T/h1.tsv" "$T/h2.tsv"
check "contact-stats over plastic rows" test $? -eq 0
check_rel "contact-stats: one group per hardness" "$(awk 'END { print NR - 1 }' "$T/cs.tsv")" 2 0
check "contact-stats: hardness carried as a key" test "$(col "$T/cs.tsv" hardness 1) $(col "$T/cs.tsv" hardness 2)" = "0.5 0.2" -o "$(col "$T/cs.tsv" hardness 1) $(col "$T/cs.tsv" hardness 2)" = "0.2 0.5"
summary
