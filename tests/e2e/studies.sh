#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# studies.sh - one tiny instance of each study pipeline (studies/*/Makefile):
# each runs end to end into a temporary OUT, its qualitative result holds,
# and a second make has nothing to do.  Grids of 16^2 .. 256x16, one seed.
. "$RC_TOP/tests/e2e/lib.sh"
S=$RC_TOP/studies
# value of column C in the row of TSV F whose column K equals V
pick() { awk -F'\t' -v k="$3" -v v="$4" -v c="$2" 'NR == 1 { for (i = 1; i <= NF; i++) h[$i] = i; next }
	$h[k] == v { print $h[c]; exit }' "$1"; }

# harmonic: kappa_c(1.5) > kappa_c(2) > kappa_c(4) at each pressure (Eq. 28:
# 1.784 > 1.666 > 1.473, gaps of 7% and 12%), and kappa_c(2) near Eq. 28 at
# small load: within 5%, the 64^2 discretisation error (1% at 256^2).
H=harmonic
make -s -j2 -C "$S/$H" BIN="$RC_BIN" OUT="$T_TMP/$H" N=64 PRESSURES="0.02 0.1" >"$T_TMP/h.log" 2>&1
check "harmonic: make runs" test -s "$T_TMP/$H/harmonic.png"
check "harmonic: the key names Eq. 28's curves" grep -q 'title "Eq. 28' "$S/$H/harmonic.gp"
check_status "harmonic: second make has nothing to do" 0 make -q -C "$S/$H" BIN="$RC_BIN" OUT="$T_TMP/$H" N=64 PRESSURES="0.02 0.1"
for p in 0.02 0.1; do
	k15=$(awk -F'\t' -v p=$p '$1 == 1.5 && $2 == p { print $4 }' "$T_TMP/$H/harmonic.tsv")
	k2=$(awk -F'\t' -v p=$p '$1 == 2 && $2 == p { print $4 }' "$T_TMP/$H/harmonic.tsv")
	k4=$(awk -F'\t' -v p=$p '$1 == 4 && $2 == p { print $4 }' "$T_TMP/$H/harmonic.tsv")
	check "harmonic p*=$p: kappa_c(1.5)=$k15 > kappa_c(2)=$k2 > kappa_c(4)=$k4" \
		awk -v a="$k15" -v b="$k2" -v c="$k4" 'BEGIN { exit !(a > b && b > c && c > 0) }'
done
k2=$(awk -F'\t' '$1 == 2 && $2 == 0.02 { print $4 }' "$T_TMP/$H/harmonic.tsv")
check_rel "harmonic: kappa_c(2) at p* = 0.02 vs Eq. 28" "$k2" 1.6661 0.05
# changing one pressure solves only the new pressure (3 exponents)
n=$(make -n -C "$S/$H" BIN="$RC_BIN" OUT="$T_TMP/$H" N=64 PRESSURES="0.02 0.1 0.2" | grep -c gfmd-solve)
check_rel "harmonic: a new pressure solves 3 indenters, nothing else" "$n" 3 0

# thought experiments: carving leaves a_r unchanged (the same contact at the
# same absolute pressure; the solver's own tolerance allows at most a
# point: 1/4096) and changes Nayak; flipping keeps Nayak (exactly: the
# spectral moments are even in h) and changes a_r.
T=thought-experiments
make -s -j2 -C "$S/$T" BIN="$RC_BIN" OUT="$T_TMP/$T" N=64 LS=0.0625 SEEDS=1 >"$T_TMP/t.log" 2>&1
check "thought: make runs" test -s "$T_TMP/$T/thought.png"
check_status "thought: second make has nothing to do" 0 make -q -C "$S/$T" BIN="$RC_BIN" OUT="$T_TMP/$T" N=64 LS=0.0625 SEEDS=1
row=$T_TMP/$T/thought.tsv
check_rel "thought: carving keeps a_r at p*" "$(col "$row" a_r_carved)" "$(col "$row" a_r_base)" 0.003
check_rel "thought: carving keeps a_r at a lower pressure" "$(col "$row" a_r_carved_low)" "$(col "$row" a_r_base_low)" 0.005
check "thought: carving changes Nayak by more than 20%" awk -v a="$(col "$row" nayak_carved)" -v b="$(col "$row" nayak_base)" \
	'BEGIN { exit !(a > 1.2 * b || a < b / 1.2) }'
check_rel "thought: flipping keeps Nayak" "$(col "$row" nayak_flipped)" "$(col "$row" nayak_base)" 1e-9
check "thought: flipping a w = 2 surface lowers a_r by more than 10%" awk -v a="$(col "$row" a_r_flipped)" -v b="$(col "$row" a_r_base)" \
	'BEGIN { exit !(a < 0.9 * b) }'

# kappa-pressure: both schedules on one seed at 32^2 .. 90^2; kappa in the
# wide band of every published value (1.3 .. 4; small grids, one seed);
# adding a pressure solves only its surfaces (2 schedules x 2 grids).
K=kappa-pressure
make -s -j2 -C "$S/$K" BIN="$RC_BIN" OUT="$T_TMP/$K" HS=0.8 PRESSURES="0.2 0.1" SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125 >"$T_TMP/k.log" 2>&1
check "kappa-pressure: make runs" test -s "$T_TMP/$K/kappa.png"
check_status "kappa-pressure: second make has nothing to do" 0 make -q -C "$S/$K" BIN="$RC_BIN" OUT="$T_TMP/$K" HS=0.8 PRESSURES="0.2 0.1" SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125
for c in H0.8+const+w0 H0.8+ft+w0; do
	check_range "kappa-pressure: $c kappa at p* = 0.1" "$(pick "$T_TMP/$K/kappa.tsv" kappa curve "$c")" 1.3 4
done
n=$(make -n -C "$S/$K" BIN="$RC_BIN" OUT="$T_TMP/$K" HS=0.8 PRESSURES="0.2 0.1 0.05" SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125 | grep -c gfmd-solve)
check_rel "kappa-pressure: a new pressure solves 4 surfaces, nothing else" "$n" 4 0

# anisotropy: Peklenik 4 on (n/4) x 4n grids; kappa_c finite and in band.
A=anisotropy
make -s -j2 -C "$S/$A" BIN="$RC_BIN" OUT="$T_TMP/$A" HS=0.8 PRESSURES=0.1 SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125 >"$T_TMP/a.log" 2>&1
check "anisotropy: make runs" test -s "$T_TMP/$A/kappa.png"
check_status "anisotropy: second make has nothing to do" 0 make -q -C "$S/$A" BIN="$RC_BIN" OUT="$T_TMP/$A" HS=0.8 PRESSURES=0.1 SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125
check_range "anisotropy: kappa_c" "$(col "$T_TMP/$A/kappa.tsv" kappa_c)" 1.2 3

# warping: w = 2 (blunt peaks) gives more contact than w = -2 at the same
# p* (the paper's Figure 8 ordering; 20-50% apart, far above one seed's
# scatter at these sizes); the height histogram is a probability (fractions
# add up to 1 to the printed precision).
W=warping
make -s -j2 -C "$S/$W" BIN="$RC_BIN" OUT="$T_TMP/$W" WARPS="-2 2" PRESSURES=0.1 SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125 HIST_N=64 >"$T_TMP/w.log" 2>&1
check "warping: make runs" test -s "$T_TMP/$W/heights.png"
check_status "warping: second make has nothing to do" 0 make -q -C "$S/$W" BIN="$RC_BIN" OUT="$T_TMP/$W" WARPS="-2 2" PRESSURES=0.1 SEEDS=1 EPS_C="0.5 0.25" EF_REF=0.125 HIST_N=64
kp=$(pick "$T_TMP/$W/kappa.tsv" kappa curve H0.8+const+w2)
km=$(pick "$T_TMP/$W/kappa.tsv" kappa curve H0.8+const+w-2)
check "warping: kappa(w=2)=$kp > kappa(w=-2)=$km" awk -v a="$kp" -v b="$km" 'BEGIN { exit !(a > b && b > 0) }'
check_rel "warping: histogram fractions add up to 1" \
	"$(awk -F'\t' '$1 == 2 { s += $6 } END { print s }' "$T_TMP/$W/heights.tsv")" 1 1e-9

# nayak: the Nayak parameter grows as eps_f falls (as eps_f^(-2H)).
N=nayak
make -s -j2 -C "$S/$N" BIN="$RC_BIN" OUT="$T_TMP/$N" HS=0.8 SPECTRA=cutoff EPS_F="0.25 0.125" SEEDS=1 EPS_C="0.5 0.25" >"$T_TMP/n.log" 2>&1
check "nayak: make runs" test -s "$T_TMP/$N/nayak.png"
check_status "nayak: second make has nothing to do" 0 make -q -C "$S/$N" BIN="$RC_BIN" OUT="$T_TMP/$N" HS=0.8 SPECTRA=cutoff EPS_F="0.25 0.125" SEEDS=1 EPS_C="0.5 0.25"
n1=$(pick "$T_TMP/$N/nayak.tsv" nayak eps_f 0.25)
n2=$(pick "$T_TMP/$N/nayak.tsv" nayak eps_f 0.125)
check "nayak: Nayak(eps_f=1/8)=$n2 > Nayak(eps_f=1/4)=$n1" awk -v a="$n2" -v b="$n1" 'BEGIN { exit !(a > b && b > 0) }'
# effects: on the same surface, perfect plasticity raises kappa (a_r >=
# p/H adds flattened area), a thin bonded layer lowers it (stiffer than
# the half space at long wavelengths), and adhesion raises it (the
# contact carries the attraction's tension on top of the load; p_adh < 0).
E=effects
EARGS="LS=0.125 SEEDS=1 PRESSURES=0.1 HARD=0.5 THICK=0.125 ADH=2e-4"
# shellcheck disable=SC2086
make -s -j2 -C "$S/$E" BIN="$RC_BIN" OUT="$T_TMP/$E" $EARGS EPS_C="0.5 0.25" >"$T_TMP/e.log" 2>&1
check "effects: make runs" test -s "$T_TMP/$E/kappa.png" -a -s "$T_TMP/$E/paired.tsv"
# shellcheck disable=SC2086
check_status "effects: second make has nothing to do" 0 make -q -C "$S/$E" BIN="$RC_BIN" OUT="$T_TMP/$E" $EARGS EPS_C="0.5 0.25"
ke=$(pick "$T_TMP/$E/kappa.tsv" kappa curve elastic)
kh=$(pick "$T_TMP/$E/kappa.tsv" kappa curve hard0.5)
kt=$(pick "$T_TMP/$E/kappa.tsv" kappa curve th0.125)
ka=$(pick "$T_TMP/$E/kappa.tsv" kappa curve adh2e-4)
check "effects: kappa plastic $kh > elastic $ke > layer $kt" awk -v h="$kh" -v e="$ke" -v t="$kt" 'BEGIN { exit !(h > e && e > t && t > 0) }'
check "effects: kappa adhesive $ka > elastic $ke" awk -v a="$ka" -v e="$ke" 'BEGIN { exit !(a > e && e > 0) }'
check_range "effects: the paired difference of adhesion is positive" \
    "$(pick "$T_TMP/$E/paired.tsv" dkappa variant adh0.0002)" 0.01 10
summary
