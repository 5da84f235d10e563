#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# surfwarp.sh - surfwarp end to end: identity, direction of w, header,
# flip, carve, renormalisation, pipelines, exit codes.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

surfgen -n 128 --lambda-r 0.25 --lambda-s 0.03 --seed 2 -o s.surf
surfwarp -w 0 s.surf -o w0.surf
check "w = 0 leaves the heights bit for bit" cmp -s \
    "$(tail -c 131072 s.surf > a.bin; echo a.bin)" "$(tail -c 131072 w0.surf > b.bin; echo b.bin)"
surfstat s.surf > s0.tsv
surfwarp -w 2 s.surf | surfstat > s2.tsv
surfwarp -w -2 s.surf | surfstat > sm.tsv
check_range "w = 2: negative skewness (blunted peaks)" "$(col s2.tsv skewness)" -10 -0.2
check_range "w = -2: positive skewness (sharp peaks)" "$(col sm.tsv skewness)" 0.2 10
surfwarp -w 2 s.surf -o w2.surf
check "header records warp" grep -aq '^meta.warp = 2$' w2.surf
check "header records warp_hmin" grep -aq '^meta.warp_hmin = ' w2.surf
check "history appended" grep -aq '^history = surfwarp -w 2' w2.surf
surfwarp -w 20 s.surf | surfstat > s20.tsv
check_range "w = 20: finite statistics" "$(col s20.tsv hrms)" 1e-12 1
check "w = 20: no nan" sh -c "! grep -q nan s20.tsv"
surfwarp -w 2 --rms-gradient 1 s.surf | surfstat > r.tsv
check_rel "--rms-gradient renormalises" "$(col r.tsv gbar)" 1 1e-12
surfwarp --flip s.surf | surfstat > f.tsv
check_rel "flip negates skewness" "$(col f.tsv skewness)" "-$(col s0.tsv skewness)" 1e-10
check_rel "flip keeps nayak" "$(col f.tsv nayak)" "$(col s0.tsv nayak)" 1e-12
check_rel "flip negates phi1" "$(col f.tsv phi1)" "$(awk -v p="$(col s0.tsv phi1)" 'BEGIN { printf "%.17g", -p }')" 1e-10

# Carve: contact = the top heights; those keep their values, nothing rises.
surfwarp -w 0 s.surf -o s.txt
awk '/^#/ { next } { l = ""; for (i = 1; i <= NF; i++) l = l (i > 1 ? " " : "") ($i > 0.03 ? 1 : 0); print l }' s.txt > mask.txt
surfwarp --carve mask.txt 0.1 s.surf -o c.txt
# (.txt files start with '#' header lines; rows follow.)
check "carve keeps contact heights, lowers the rest" awk '
	FNR == 1 { f++; r = 0 }
	/^#/ { next }
	{ r++ }
	f == 1 { for (i = 1; i <= NF; i++) m[r, i] = $i; next }
	f == 2 { for (i = 1; i <= NF; i++) h[r, i] = $i; next }
	{ for (i = 1; i <= NF; i++) { if (m[r, i] == 1 && $i != h[r, i]) bad++; if ($i > h[r, i]) bad++ } }
	END { exit !(bad == 0 && r == 128) }' mask.txt s.txt c.txt
surfwarp --carve mask.txt 0.1 --carve-width 0.01 s.surf | surfstat > c.tsv
check_range "carving changes Nayak by over 20% (contact unchanged)" "$(awk -v a="$(col c.tsv nayak)" -v b="$(col s0.tsv nayak)" 'BEGIN { r = a / b; print (r > 1 ? r - 1 : 1 - r) }')" 0.2 1e9

check_status "hmin above min h: exit 1" 1 surfwarp -w 1 --hmin 0 s.surf -o x.surf
check_status "non-finite w: exit 2" 2 surfwarp -w nan s.surf
check_status "--hmin without -w: exit 2" 2 surfwarp --hmin -1 s.surf
check_status "--carve without depth: exit 2" 2 surfwarp --carve mask.txt
check_status "negative carve depth: exit 2" 2 surfwarp --carve mask.txt -1 s.surf
awk 'BEGIN { print "1 0"; print "0 1" }' > small.txt
check_status "wrong-size carve mask: exit 1" 1 surfwarp --carve small.txt 0.1 s.surf -o x.surf
check "failed run leaves no output" [ ! -e x.surf ]
check_status "--help: exit 0" 0 surfwarp --help
summary
