#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# kernel.sh - gfmd-solve --kernel end to end: the default row says
# continuum and is unchanged by --kernel continuum; a sine in full
# contact carries p + k_q A cos with the pixel kernel's k_q (1/G_q of
# lib/elastic/elastic.h, summed here by awk over 201^2 images, independent of the
# library's truncation) with both methods; free boundaries write pixel;
# the refusals; a_subpixel; contact-stats groups by kernel.
. "$RC_TOP/tests/e2e/lib.sh"
T=$T_TMP

surfgen -q -n 64 -H 0.8 --lambda-r 0.5 --lambda-s 0.125 --seed 3 -o "$T/r.surf"
gfmd-solve -q -j 1 -p 0.05 "$T/r.surf" > "$T/d.tsv"
gfmd-solve -q -j 1 -p 0.05 --kernel continuum "$T/r.surf" > "$T/c.tsv"
check "default kernel column: continuum" test "$(col "$T/d.tsv" kernel)" = continuum
check "--kernel continuum: the default's contact" test "$(col "$T/c.tsv" n_c)" = "$(col "$T/d.tsv" n_c)"
gfmd-solve -q -j 1 -p 0.05 --kernel pixel "$T/r.surf" > "$T/p.tsv"
check "--kernel pixel: kernel column pixel" test "$(col "$T/p.tsv" kernel)" = pixel
gfmd-solve -q -j 1 -p 0.05 --kernel pixel --method cg "$T/r.surf" > "$T/pc.tsv"
check "--kernel pixel: FIRE and CG find the same contact" test "$(col "$T/p.tsv" n_c)" = "$(col "$T/pc.tsv" n_c)"

# A sine of wavelength 8 dx (q dx = pi/4) along x in full contact: the
# pressure amplitude is k_q A, k_q the pixel kernel's (qy = 0: only the
# my = 0 images survive; their sum converges like 1/m^2, to 1e-6 at
# |m| <= 100).
kqa() {
	awk -v A="$1" 'BEGIN { pi = 3.14159265358979324; dx = 1 / 64; q = 2 * pi / 8 / dx
		for (m = -100; m <= 100; m++) { x = q * dx / 2 + pi * m
			g += 2 / (2 * (x < 0 ? -x : x) / dx) * sin(x) / x }
		printf "%.17g\n", A / g }'
}
surfgen -q -n 64x4 --type sine --wavelength 0.125 --amplitude 0.001 -o "$T/sine.surf"
for m in fire cg; do
	gfmd-solve -q -j 1 --method $m --kernel pixel --pressure-abs 1 \
	    --pressure "$T/sp.surf" "$T/sine.surf" > "$T/s.tsv"
	check_rel "pixel kernel, $m: full contact of a sine carries k_q A" \
	    "$(amplitude "$T/sp.surf")" "$(kqa 0.001)" 1e-5
done
gfmd-solve -q -j 1 --pressure-abs 1 --pressure "$T/sc.surf" "$T/sine.surf" > "$T/s.tsv"
check_rel "continuum kernel: the same sine carries |q| A E*/2" \
    "$(amplitude "$T/sc.surf")" "$(awk 'BEGIN { printf "%.17g\n", 3.14159265358979324 * 8 * 0.001 }')" 1e-9

# Free boundaries solve with Love's pixel compliance.
surfgen -q -n 32 --seed 2 | surfwarp --detrend plane -o "$T/np.surf"
gfmd-solve -q -j 1 -p 0.1 "$T/np.surf" > "$T/f.tsv"
check "free boundaries: kernel column pixel" test "$(col "$T/f.tsv" kernel)" = pixel
gfmd-solve -q -j 1 -p 0.1 --kernel pixel --boundary free "$T/r.surf" > "$T/f2.tsv"
check "--kernel pixel --boundary free: accepted (what is solved anyway)" test "$(col "$T/f2.tsv" kernel)" = pixel

check_status "--kernel bem" 2 gfmd-solve --kernel bem -p 0.1 "$T/r.surf"
check "--kernel bem: names the kernels" grep -q "continuum or pixel" "$T/stderr"
check_status "--kernel continuum --boundary free" 2 gfmd-solve --kernel continuum --boundary free -p 0.1 "$T/r.surf"
check "--kernel continuum --boundary free: says Love's pixel compliance" grep -q "Love" "$T/stderr"
check_status "--kernel continuum on a non-periodic map" 1 gfmd-solve -q --kernel continuum -p 0.1 "$T/np.surf"
check_status "--kernel pixel with --thickness" 2 gfmd-solve --kernel pixel --thickness 0.1 --poisson 0.3 -p 0.1 "$T/r.surf"
check_status "--kernel pixel with --checkpoint: accepted (recorded)" 0 gfmd-solve -q --kernel pixel --checkpoint "$T/ck.surf" -p 0.1 "$T/r.surf"

# a_subpixel (lib/contact.h): below the raw count, which overshoots, and
# above Yastrebov's weight 1/2 on every contact-line point; nan when free.
for f in d p; do
	check "a_subpixel ($f): within [(n_c - n_cl/2)/n_tot, a_r)" awk -F'\t' '
	    NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
	    { exit !($c["a_subpixel"] < $c["a_r"] && $c["a_subpixel"] > ($c["n_c"] - $c["n_cl"] / 2) / $c["n_tot"]) }' "$T/$f.tsv"
done
check "free boundaries: a_subpixel nan" test "$(col "$T/f.tsv" a_subpixel)" = nan

contact-stats -q --no-extrapolate -o "$T/cs.tsv" "$T/d.tsv" "$T/p.tsv"
check_rel "contact-stats: one group per kernel" "$(awk 'END { print NR - 1 }' "$T/cs.tsv")" 2 0
summary
