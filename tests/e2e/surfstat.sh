#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# surfstat.sh - surfstat end to end: scalar row on exact surfaces, the
# spectrum's sum rule, masks, tables, side outputs, exit codes.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

# A cosine of amplitude 0.2, wavelength 1/4: phi6 = phi7 = phi9 = 1 exactly.
surfgen --type sine -n 64x32 --wavelength 0.25 --amplitude 0.2 -o sine.surf
surfstat sine.surf > s.tsv
check_rel "sine hrms = A/sqrt2" "$(col s.tsv hrms)" 0.14142135623730950 1e-12
check_rel "sine gbar = A k/sqrt2" "$(col s.tsv gbar)" "$(awk 'BEGIN { printf "%.17g", 0.2 * 8 * 3.14159265358979324 / sqrt(2) }')" 1e-12
check_rel "sine phi6" "$(col s.tsv phi6)" 1 1e-10
check_rel "sine phi7" "$(col s.tsv phi7)" 1 1e-10
check_rel "sine phi9" "$(col s.tsv phi9)" 1 1e-10
check_rel "sine nayak" "$(col s.tsv nayak)" 1 1e-10
check "derivatives column says spectral" [ "$(col s.tsv derivatives)" = spectral ]
surfstat --fd sine.surf > fd.tsv
check "--fd says finite-difference" [ "$(col fd.tsv derivatives)" = finite-difference ]
# gbar_fd: forward differences, rms 2 sin(k dx/2)/dx A/sqrt2, k dx = pi/8.
check_rel "gbar_fd" "$(col s.tsv gbar_fd)" "$(awk 'BEGIN { printf "%.17g", 0.2 * 2 * sin(3.14159265358979324 / 16) * 64 / sqrt(2) }')" 1e-10

# A random surface: phi1 = phi2, phi4 = phi5 (band-limited, alias free).
surfgen -n 128 --lambda-r 0.25 --lambda-s 0.0625 --seed 5 -o r.surf
surfstat --json r.surf > r.json
check "json output" grep -q '"phi9"' r.json
surfstat r.surf > r.tsv
check_rel "phi1 = phi2" "$(col r.tsv phi1)" "$(col r.tsv phi2)" 1e-9
check_rel "phi4 = phi5" "$(col r.tsv phi4)" "$(col r.tsv phi5)" 1e-9
check_range "phi3 = 0" "$(col r.tsv phi3)" -1e-12 1e-12
check "metadata columns carried" [ "$(col r.tsv seed)" = 5 ]
# Sum rule: sum over bins C n_modes dq^2 = hrms^2 (dq = 2 pi for L = 1).
surfstat --psd r.surf > psd.tsv
sum=$(awk -F'\t' 'NR > 1 { s += $2 * $3 } END { printf "%.17g", s * 4 * 3.14159265358979324^2 }' psd.tsv)
check_rel "sum C n dq^2 = hrms^2" "$sum" "$(awk -v h="$(col r.tsv hrms)" 'BEGIN { printf "%.17g", h * h }')" 1e-10
check "psd header" [ "$(head -n 1 psd.tsv)" = "$(printf 'q\tC\tn_modes\tstderr')" ]
surfstat --psd2d p2.surf --gnuplot c.gp r.surf > /dev/null
check "psd2d is a spectrum grid" grep -aq 'kind = spectrum' p2.surf
check "gnuplot script has a data block" grep -q 'EOD' c.gp
if command -v gnuplot >/dev/null 2>&1; then
	check "gnuplot runs the script" gnuplot c.gp
	check "gnuplot wrote the PNG" [ -s c.png ]
else
	skip 2 "gnuplot not installed: the --gnuplot script is not run (apt-get install gnuplot-nox)"
fi
# The gnuplot spectrum names the units: C(q) in unit^4, L in the unit.
surfwarp -q --unit um -o r-um.surf r.surf
surfstat --psd --gnuplot cu.gp r-um.surf > /dev/null
check "gnuplot: C(q) axis carries its unit" grep -q "set ylabel 'C(q) (um^4)'" cu.gp
check "gnuplot: the title its lengths' unit" grep -q "set title '.*L = 1x1 um'" cu.gp
# --png with a spectrum table draws the spectrum (an 800x600 plot), not
# the map (r.surf is 64 wide: its preview is narrower).
pngw() { od -An -tu1 -j 16 -N 4 "$1" | awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4 }'; }
surfstat --psd --png psd.png r.surf > /dev/null
check "surfstat --psd --png: the spectrum plot, 800 wide" [ "$(pngw psd.png)" = 800 ]
surfgen -q -n 64 --seed 5 -o wide.surf
surfstat --fit --png fitp.png wide.surf > /dev/null
check "surfstat --fit --png: the spectrum plot" [ "$(pngw fitp.png)" = 800 ]
surfstat --png map.png r.surf > /dev/null
check "surfstat --png alone: the map" [ "$(pngw map.png)" != 800 ]
surfstat --acf r.surf > acf.tsv
check "acf has x, y, radial" [ "$(cut -f1 acf.tsv | sort -u | tr '\n' ' ')" = "direction radial x y " ]
surfstat --by-height 7 r.surf > bh.tsv
check "by-height rows" [ "$(awk 'END { print NR }' bh.tsv)" = 8 ]
check "by-height counts add up" [ "$(awk -F'\t' 'NR > 1 { s += $4 } END { print s }' bh.tsv)" = 16384 ]

# Masks: all ones = no mask; a mask made from the surface itself.
awk 'BEGIN { for (j = 0; j < 32; j++) { l = ""; for (i = 0; i < 64; i++) l = l (i ? " " : "") 1; print l } }' > ones.txt
surfstat --mask ones.txt sine.surf > m.tsv
check_rel "all-ones mask: phi7 as unmasked" "$(col m.tsv phi7)" 1 1e-10
check_rel "all-ones mask: contact_fraction 1" "$(col m.tsv contact_fraction)" 1 0
check_rel "all-ones mask: gbar_c = gbar" "$(col m.tsv gbar_c)" "$(col m.tsv gbar)" 1e-12
check_rel "all-ones mask: gbar_c_prime = gbar" "$(col m.tsv gbar_c_prime)" "$(col m.tsv gbar)" 1e-12
awk 'BEGIN { for (j = 0; j < 32; j++) { l = ""; for (i = 0; i < 64; i++) l = l (i ? " " : "") (i % 16 < 4 ? 1 : 0); print l } }' > half.txt
surfstat --mask half.txt sine.surf > h.tsv
check_rel "mask contact_fraction" "$(col h.tsv contact_fraction)" 0.25 0
awk 'BEGIN { print "1 0"; print "0 1" }' > small.txt
check_status "wrong-size mask: exit 1" 1 surfstat --mask small.txt sine.surf
awk 'BEGIN { for (j = 0; j < 32; j++) { l = ""; for (i = 0; i < 64; i++) l = l (i ? " " : "") 0; print l } }' > zero.txt
check_status "empty mask: exit 1" 1 surfstat --mask zero.txt sine.surf

# Usage and input errors.
check_status "two tables: exit 2" 2 surfstat --psd --acf r.surf
check_status "--mask with --psd: exit 2" 2 surfstat --psd --mask ones.txt r.surf
check_status "bad --by-height: exit 2" 2 surfstat --by-height 0 r.surf
check_status "unknown option: exit 2" 2 surfstat --bogus r.surf
check_status "missing file: exit 1" 1 surfstat nonexistent.surf
check_status "--help: exit 0" 0 surfstat --help
head -c 300 r.surf > trunc.surf
check_status "truncated input: exit 1" 1 surfstat trunc.surf
# Issue 27: the grid of a surface refused for missing points was leaked
# (valgrind: definitely lost); valgrind is optional.
printf '1 2 3\n4 nan 6\n7 8 9\n' > miss.txt
if command -v valgrind >/dev/null 2>&1; then
	OMP_NUM_THREADS=1 valgrind -q --leak-check=full \
	    --show-leak-kinds=definite,indirect \
	    --errors-for-leak-kinds=definite,indirect --error-exitcode=99 \
	    "$RC_BIN/surfstat" -j 1 miss.txt > /dev/null 2> vg.txt
	check_rel "missing points refused, nothing leaked ($(grep -m 1 'lost' vg.txt))" $? 1 0
else
	skip 1 "valgrind not installed: the leak check of a refused surface (apt-get install valgrind)"
fi
summary
