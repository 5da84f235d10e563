# SPDX-License-Identifier: GPL-3.0-or-later
# thought.sh - the paper's first thought experiment through the tools:
# carving and roughening the non-contact zone (surfwarp --carve ...
# --carve-rough) leaves the contact of the original surface at the same
# load unchanged, while the Nayak parameter changes by about an order of
# magnitude.  Exact claims: contact points keep their heights bit for bit
# and no point rises, so the original solution stays feasible and optimal
# and the solver finds the identical contact set.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
surfgen -n 128 --lambda-s 0.05 --seed 4 -o a.surf
gfmd-solve -q --method cg -p 0.05 --contact c.surf -o orig.tsv a.surf
surfwarp -o a.txt a.surf			# no operation: a text dump
nayak() { surfstat "$1" | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "nayak") c = i; next } { print $c }'; }
n0=$(nayak a.surf)
nc0=$(col orig.tsv n_c)
check "original solved: n_c = $nc0" [ -n "$nc0" ] && [ "$nc0" -gt 100 ]
for spec in "0.01 0.01" "0.01 1"; do
	set -- $spec
	surfwarp --carve c.surf "$1" --carve-rough "$2" --carve-seed 7 -o k.surf a.surf
	surfwarp -o k.txt k.surf
	surfwarp -o mask.txt c.surf
	# On contact (mask 1) the height is unchanged; elsewhere it never rises.
	for f in a k mask; do grep -v '^#' $f.txt > $f.dat; done
	verdict=$(paste -d' ' a.dat k.dat mask.dat | awk '
	    { n = NF / 3; rows++; for (i = 1; i <= n; i++) {
	        h = $i; k = $(i + n); m = $(i + 2 * n)
	        if (m == 1 && k != h) moved++; if (k > h) up++ } }
	    END { print rows + 0, moved + 0, up + 0 }')
	check "carve $spec: 128 rows, contact unchanged, nothing raised ($verdict)" [ "$verdict" = "128 0 0" ]
	gfmd-solve -q --method cg --pressure-abs 0.05 -o carved.tsv k.surf
	nc=$(col carved.tsv n_c)
	check "carve $spec: identical contact count ($nc0 vs $nc)" [ -n "$nc" ] && [ "$nc" = "$nc0" ]
	nk=$(nayak k.surf)
	ratio=$(awk -v a="$n0" -v b="$nk" 'BEGIN { if (a <= 0 || b <= 0) { print 0; exit } r = a / b; if (r < 1) r = 1 / r; print r }')
	check_range "carve $spec: nayak $n0 -> $nk changes by at least 5x" "$ratio" 5 1e9
done
# gbar_c and gbar_c_prime: gfmd-solve (lib/contact.c) and surfstat --mask
# (lib/stats.c) are two implementations; they agree to round-off.
surfstat --mask c.surf -o masked.tsv a.surf
check_rel "gbar_c: gfmd-solve = surfstat --mask" "$(col orig.tsv gbar_c)" "$(col masked.tsv gbar_c)" 1e-12
check_rel "gbar_c_prime: gfmd-solve = surfstat --mask" "$(col orig.tsv gbar_c_prime)" "$(col masked.tsv gbar_c_prime)" 1e-12
check "gbar_c_prime is a number" awk -v v="$(col orig.tsv gbar_c_prime)" 'BEGIN { exit !(v == v + 0) }'
summary
