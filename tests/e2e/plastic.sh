#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# plastic.sh - gfmd-solve --hardness end to end: a flat indenter reaches
# the plastic limit at p = H, full plasticity gives a_r = p/H, a huge H
# gives the elastic answer, the rows, the refusals, and contact-stats
# keeping hardness as a key.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP

# --- A flat indenter in full contact carries sigma = p everywhere: no
# point at H below p = H, every point at H at p = H.
surfgen -q -n 16 --type flat -o "$T/flat.surf"
gfmd-solve -q -j 1 --method cg --hardness 0.5 --pressure-abs 0.25,0.5 "$T/flat.surf" > "$T/flat.tsv" 2>/dev/null
check "flat: converges" test $? -eq 0
check_rel "flat p = H/2: a_r = 1" "$(col "$T/flat.tsv" a_r 1)" 1 0
check_rel "flat p = H/2: no plastic point" "$(col "$T/flat.tsv" a_plastic 1)" 0 0
check_rel "flat p = H: every point plastic" "$(col "$T/flat.tsv" a_plastic 2)" 1 0
check_rel "flat: hardness recorded" "$(col "$T/flat.tsv" hardness 1)" 0.5 0

# --- Full plasticity on a rough surface (H = 0.01 E*, p = H/2, H/10):
# a_plastic <= p/H <= a_r exactly, and the band between them is the few
# elastic edge points (tests/test_plastic.c: ~1e-3; tolerance 0.01).
surfgen -q -n 64 --seed 3 -o "$T/r.surf"
gfmd-solve -q -j 1 --method cg --hardness 0.01 --pressure-abs 0.005,0.001 "$T/r.surf" > "$T/full.tsv"
check "full plasticity: converges" test $? -eq 0
for r in 1 2; do
	f=$(awk -v r=$r 'BEGIN { print r == 1 ? 0.5 : 0.1 }')
	check_range "full plasticity p/H = $f: a_plastic <= p/H" "$(col "$T/full.tsv" a_plastic $r)" 0 "$f"
	check_range "full plasticity p/H = $f: a_r >= p/H, within 0.01" "$(col "$T/full.tsv" a_r $r)" "$f" "$(awk -v f=$f 'BEGIN { print f + 0.01 }')"
done

# --- H = 1e6 p never binds: the same contact as the elastic CG, and the
# approach within the tolerance's effect on it (1e-6 relative).
gfmd-solve -q -j 1 --method cg --pressure-abs 0.05 "$T/r.surf" > "$T/el.tsv"
gfmd-solve -q -j 1 --method cg --hardness 5e4 --pressure-abs 0.05 "$T/r.surf" > "$T/big.tsv"
check_rel "H = 1e6 p: same n_c as elastic" "$(col "$T/big.tsv" n_c)" "$(col "$T/el.tsv" n_c)" 0
check_rel "H = 1e6 p: same approach" "$(col "$T/big.tsv" approach)" "$(col "$T/el.tsv" approach)" 1e-6
check_rel "H = 1e6 p: no plastic point" "$(col "$T/big.tsv" a_plastic)" 0 0
check_rel "without --hardness: hardness 0 (no cap)" "$(col "$T/el.tsv" hardness)" 0 0
check_rel "without --hardness: a_plastic 0" "$(col "$T/el.tsv" a_plastic)" 0 0

# --- Refusals.
check_status "--hardness with FIRE (the default)" 2 gfmd-solve --hardness 1 -p 0.1 "$T/r.surf"
check "--hardness with FIRE: the message names --method cg" grep -q -- "--method cg" "$T/stderr"
check_status "--hardness with --method fire" 2 gfmd-solve --method fire --hardness 1 -p 0.1 "$T/r.surf"
check_status "--hardness 0" 2 gfmd-solve --method cg --hardness 0 -p 0.1 "$T/r.surf"
check_status "--hardness -1" 2 gfmd-solve --method cg --hardness -1 -p 0.1 "$T/r.surf"
check_status "--hardness with --approach" 2 gfmd-solve --method cg --hardness 1 --approach 0.01 "$T/r.surf"
check_status "--hardness with --checkpoint: accepted (recorded)" 0 gfmd-solve -q --method cg --hardness 1 --checkpoint "$T/ck.surf" -p 0.1 "$T/r.surf"
check_status "p > H" 1 gfmd-solve --method cg --hardness 0.01 --pressure-abs 0.02 "$T/r.surf"
check "p > H: the message says why" grep -q "exceeds the hardness" "$T/stderr"

# --- contact-stats: hardness is a key (two hardnesses, two groups) and
# a_plastic a result.
gfmd-solve -q -j 1 --method cg --hardness 0.5 --pressure-abs 0.05 "$T/r.surf" > "$T/h1.tsv"
gfmd-solve -q -j 1 --method cg --hardness 0.2 --pressure-abs 0.05 "$T/r.surf" > "$T/h2.tsv"
contact-stats -q --no-extrapolate -o "$T/cs.tsv" "$T/h1.tsv" "$T/h2.tsv"
check "contact-stats over plastic rows" test $? -eq 0
check_rel "contact-stats: one group per hardness" "$(awk 'END { print NR - 1 }' "$T/cs.tsv")" 2 0
check "contact-stats: hardness carried as a key" test "$(col "$T/cs.tsv" hardness 1) $(col "$T/cs.tsv" hardness 2)" = "0.5 0.2" -o "$(col "$T/cs.tsv" hardness 1) $(col "$T/cs.tsv" hardness 2)" = "0.2 0.5"
summary
