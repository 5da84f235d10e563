#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# coverage.sh - do contact-stats' error bars cover what they claim, on
# surfaces their calibration never saw?
#
# Scene: H 0.8, lambda_r/L = 1/2, lambda_s/L = 1/16, p* = 0.1, 0.05,
# 0.025.  Each seed is solved on 64^2 ... 1024^2 (eps_c = 1/4 ... 1/64;
# gfmd-solve defaults, one thread).  The estimate of a surface is what
# contact-stats --per-seed makes from 64^2, 128^2 and 256^2 (eps_c = 1/4,
# 1/8, 1/16), with a_r_err and kappa_err; its reference is the Richardson
# value of 512^2 and 1024^2 (eps_c = 1/32, 1/64; the 256^2 grid enters
# only the reference's own error bar, through the same model).
#
# Two sets of seeds: CAL_SEEDS calibrate the floor constant
# RC_CSTATS_FLOOR_C (lib/cstats.h): the constant that makes the bar
# a_r_err = sqrt(err^2 + (C noise)^2) cover 68% of them; TEST_SEEDS, never
# used for that, check it.  For each set and pressure: coverage (the
# fraction of surfaces with |a_r - reference| <= a_r_err; a one-sigma bar
# covers 68%) with its binomial standard error sqrt(c (1 - c)/n), the
# same with the reference's own bar added in quadrature, kappa's
# coverage, the median |error|/a_r_err (0.674 for a calibrated Gaussian
# bar), and the smallest bar relative to its floor (never below 1).
#
#   sh coverage.sh   (environment: BIN, OUT, CAL_SEEDS, TEST_SEEDS, NICE)
# Defaults: CAL_SEEDS 5001-5016 and 6001-6016, TEST_SEEDS 7001-7048 (the
# first round, CAL_SEEDS 6001-6016 against TEST_SEEDS 5001-5016, is in
# README.md).
# Solutions are cached per seed and grid in $OUT/sol (a rerun solves
# only what is missing; about 1 min of one core per seed on an idle
# machine).  Prints the table; writes $OUT/coverage.tsv.
set -eu
HERE=$(cd "$(dirname "$0")" && pwd)
BIN=${BIN:-$HERE/../../bin}
OUT=${OUT:-out-coverage}
CAL_SEEDS=${CAL_SEEDS:-$(seq 5001 5016) $(seq 6001 6016)}
TEST_SEEDS=${TEST_SEEDS:-$(seq 7001 7048)}
NICE=${NICE:-5}
P=0.1,0.05,0.025
mkdir -p "$OUT/surf" "$OUT/sol"

for s in $CAL_SEEDS $TEST_SEEDS; do
	for n in 64 128 256 512 1024; do
		f=n${n}_seed$s
		[ -s "$OUT/sol/$f.tsv" ] && continue
		"$BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.5 --lambda-s 0.0625 \
		    --seed "$s" -o "$OUT/surf/$f.surf"
		nice -n "$NICE" "$BIN/gfmd-solve" -q -j 1 -p "$P" \
		    -o "$OUT/sol/$f.tsv.part" "$OUT/surf/$f.surf"
		mv "$OUT/sol/$f.tsv.part" "$OUT/sol/$f.tsv"
		rm -f "$OUT/surf/$f.surf"
	done
done

# The constant the estimates were made with.
C=$(awk '$1 == "#define" && $2 == "RC_CSTATS_FLOOR_C" { print $3 }' \
    "$HERE/../../lib/cstats.h")
sols() {	# sols GRIDS SEEDS...
	g=$1
	shift
	for s in "$@"; do for n in $g; do printf '%s ' "$OUT/sol/n${n}_seed$s.tsv"; done; done
}
# set, seed, p_star, a_r, a_r_err, a_r_floor, kappa, kappa_err
cols='FNR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
	{ print set, $c["seed"], $c["p_star"], $c["a_r"], $c["a_r_err"],
	    $c["a_r_floor"], $c["kappa"], $c["kappa_err"] }'
: >"$OUT/est.txt"
: >"$OUT/ref.txt"
for set in cal test; do
	if [ $set = cal ]; then seeds=$CAL_SEEDS; else seeds=$TEST_SEEDS; fi
	# shellcheck disable=SC2046,SC2086
	"$BIN/contact-stats" -q --per-seed $(sols "64 128 256" $seeds) \
	    -o "$OUT/est-$set.tsv"
	# shellcheck disable=SC2046,SC2086
	"$BIN/contact-stats" -q --per-seed $(sols "256 512 1024" $seeds) \
	    -o "$OUT/ref-$set.tsv"
	awk -F'\t' -v set=$set "$cols" "$OUT/est-$set.tsv" >>"$OUT/est.txt"
	awk -F'\t' -v set=$set "$cols" "$OUT/ref-$set.tsv" >>"$OUT/ref.txt"
done

# Per surface: error e = |a_r - ref|, bar b = a_r_err, the pair part
# d = sqrt(b^2 - floor^2) and the noise n = floor / C; the constant that
# would just cover it is c = sqrt(e^2 - d^2)/n (0 if d alone covers).
# Calibration: Ccal = the 68th percentile of c over CAL_SEEDS; TEST is
# then scored with Ccal (the out-of-sample check) and every set with the
# compiled C (what contact-stats writes).
awk -v C="$C" '
	function sort(s, v,   m, i, j, t) {
		m = split(s, v, " ")
		for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
		return m
	}
	function median(s,   v, m) { m = sort(s, v); return m % 2 ? v[(m + 1) / 2] : (v[m / 2] + v[m / 2 + 1]) / 2 }
	function quantile(s, q,   v, m, k) { m = sort(s, v); k = int(q * m + 0.999999); return v[k < 1 ? 1 : k] }
	FILENAME ~ /ref.txt$/ { ra[$1 " " $2 " " $3] = $4; re[$1 " " $2 " " $3] = $5
		rk[$1 " " $2 " " $3] = $7; rke[$1 " " $2 " " $3] = $8; next }
	{
		key = $1 " " $2 " " $3
		e = $4 - ra[key]; if (e < 0) e = -e
		ek = $7 - rk[key]; if (ek < 0) ek = -ek
		b = $5; f = $6
		d2 = b * b - f * f; if (d2 < 0) d2 = 0
		need = e * e - d2
		c = need <= 0 ? 0 : (f > 0 ? sqrt(need) / (f / C) : 1e9)
		if ($1 == "cal") cs = cs " " c
		nr++; S[nr] = $1; PS[nr] = $3; E[nr] = e; D2[nr] = d2; NS[nr] = f / C
		for (k = 0; k < 2; k++) {
			id = $1 " " (k ? "all" : $3)
			n[id]++
			if (e <= b) cov[id]++
			if (e <= sqrt(b * b + re[key] * re[key])) covr[id]++
			if (ek <= $8) covk[id]++
			z[id] = z[id] " " (b > 0 ? e / b : 1e9)
			rel[id] = rel[id] " " (f > 0 ? b / f : 1e9)
			sa[id] += e / ra[key]; sb[id] += b / ra[key]
			if (!(id in seen)) { seen[id] = 1; ids[++nid] = id }
		}
	}
	END {
		ccal = quantile(cs, 0.68)
		for (i = 1; i <= nr; i++) {
			if (S[i] != "test") continue
			for (k = 0; k < 2; k++) {
				id = k ? "all" : PS[i]
				tn[id]++
				if (E[i] <= sqrt(D2[i] + ccal * ccal * NS[i] * NS[i])) tc[id]++
			}
		}
		printf "# C calibrated on CAL (68th percentile of the constant each surface needs): %.3f; compiled RC_CSTATS_FLOOR_C: %s\n", ccal, C
		printf "# TEST scored with the calibrated %.3f:", ccal
		for (id in tn) { p = tc[id] / tn[id]; printf " p* %s %.1f%% +- %.1f%% (n %d);", id, 100 * p, 100 * sqrt(p * (1 - p) / tn[id]), tn[id] }
		printf "\n"
		print "set\tp_star\tn\tcoverage_a_r\tse\tcoverage_with_ref_err\tcoverage_kappa\tmedian_err_over_bar\tmin_bar_over_floor\tmean_abs_err_rel\tmean_bar_rel"
		for (i = 1; i <= nid; i++) {
			id = ids[i]; split(id, w, " ")
			p = cov[id] / n[id]
			printf "%s\t%s\t%d\t%.1f%%\t%.1f%%\t%.1f%%\t%.1f%%\t%.3f\t%.3f\t%.3g%%\t%.3g%%\n",
			    w[1], w[2], n[id], 100 * p, 100 * sqrt(p * (1 - p) / n[id]),
			    100 * covr[id] / n[id], 100 * covk[id] / n[id], median(z[id]),
			    quantile(rel[id], 0), 100 * sa[id] / n[id], 100 * sb[id] / n[id]
		}
	}' "$OUT/ref.txt" "$OUT/est.txt" >"$OUT/coverage.tsv"
grep '^#' "$OUT/coverage.tsv"
grep -v '^#' "$OUT/coverage.tsv" | column -t -s "$(printf '\t')"
