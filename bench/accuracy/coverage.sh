#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# coverage.sh - are contact-stats' error bars calibrated?
#
# For SEEDS independent surfaces (H 0.8, lambda_r/L = 1/2, lambda_s/L =
# 1/16) at three pressures, each estimate of a_r and kappa that
# contact-stats makes from the coarse grids eps_c = 1/4, 1/8, 1/16 (64^2
# ... 256^2) is compared with a reference extrapolated from eps_c = 1/32,
# 1/64, 1/128 (512^2 ... 2048^2, fitted order, independent of the
# estimates).  Coverage is the fraction of estimates whose interval
# estimate +- err contains the reference: a calibrated one-sigma error
# covers about 68%.  Per surface (--per-seed: the extrapolation error
# alone) and per ensemble of GROUP seeds (seed error and extrapolation
# error combined, against the mean of the references).
#   sh coverage.sh [BIN=dir] (environment: BIN, OUT, SEEDS, GROUP)
# Prints a table; writes $OUT/coverage.tsv.
set -eu
BIN=${BIN:-$(cd "$(dirname "$0")/../.." && pwd)/bin}
OUT=${OUT:-out-coverage}
SEEDS=${SEEDS:-$(seq 1 16)}
GROUP=${GROUP:-4}
P=0.1,0.05,0.025
mkdir -p "$OUT/surf" "$OUT/sol"

# Surfaces and solutions, skipped when present (re-runs are cheap).
for s in $SEEDS; do
	for n in 64 128 256 512 1024 2048; do
		f=n${n}_seed$s
		[ -s "$OUT/sol/$f.tsv" ] && continue
		"$BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.5 --lambda-s 0.0625 \
		    --seed "$s" -o "$OUT/surf/$f.surf"
		"$BIN/gfmd-solve" -q -j 1 -p "$P" -o "$OUT/sol/$f.tsv.part" \
		    "$OUT/surf/$f.surf"
		mv "$OUT/sol/$f.tsv.part" "$OUT/sol/$f.tsv"
		rm -f "$OUT/surf/$f.surf"
	done
done

sols() {	# sols SEEDS... with grid sizes in $GRIDS
	for s in "$@"; do for n in $GRIDS; do printf '%s ' "$OUT/sol/n${n}_seed$s.tsv"; done; done
}
# seed, p_star, a_r, a_r_err, kappa, kappa_err of a contact-stats table
cols='FNR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
	{ print $c["seed"], $c["p_star"], $c["a_r"], $c["a_r_err"], $c["kappa"], $c["kappa_err"] }'

GRIDS="512 1024 2048"
# shellcheck disable=SC2046
"$BIN/contact-stats" -q --per-seed --order auto $(sols $SEEDS) -o "$OUT/ref.tsv"
awk -F'\t' "$cols" "$OUT/ref.tsv" >"$OUT/ref.txt"

: >"$OUT/est.txt"
for est in "64 128" "128 256" "64 128 256"; do
	GRIDS=$est
	name=$(echo "$est" | sed 's/64/1\/4/; s/128/1\/8/; s/256/1\/16/; s/ /,/g')
	# shellcheck disable=SC2046
	"$BIN/contact-stats" -q --per-seed $(sols $SEEDS) -o "$OUT/est.tsv"
	awk -F'\t' "$cols" "$OUT/est.tsv" |
	    awk -v e="$name" '{ print e, "surface", $0 }' >>"$OUT/est.txt"
	set -- $SEEDS
	g=0
	while [ $# -ge "$GROUP" ]; do
		grp=""
		i=0
		while [ $i -lt "$GROUP" ]; do grp="$grp $1"; shift; i=$((i + 1)); done
		g=$((g + 1))
		# shellcheck disable=SC2046,SC2086
		"$BIN/contact-stats" -q $(sols $grp) -o "$OUT/est.tsv"
		ids=$(echo $grp | tr ' ' ',')
		awk -F'\t' -v e="$name" -v id="g$g:$ids" \
		    'FNR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		    { print e, "ensemble", id, $c["p_star"], $c["a_r"], $c["a_r_err"], $c["kappa"], $c["kappa_err"] }' \
		    "$OUT/est.tsv" >>"$OUT/est.txt"
	done
done

# Coverage: per surface against the reference of that seed (the
# extrapolation error alone; the reference's own error is 10-50x below
# the estimates' and is neglected).  Per ensemble against the mean
# reference of all the OTHER seeds, an independent sample of the same
# population: the interval is then +- sqrt(err^2 + se_others^2), with
# se_others the standard error of that mean.
awk '
	FILENAME ~ /ref.txt$/ {
		ra[$1 " " $2] = $3; rk[$1 " " $2] = $5
		if (!($1 in seen)) { seen[$1] = 1; seeds[++ns] = $1 }
		next
	}
	{
		e = $1; lvl = $2; p = $4; extra_a = extra_k = 0
		if (lvl == "surface") { key = $3 " " p; ref_a = ra[key]; ref_k = rk[key] }
		else {
			delete in_grp
			split(substr($3, index($3, ":") + 1), sd, ",")
			for (i in sd) in_grp[sd[i]] = 1
			sa = sa2 = sk = sk2 = m = 0
			for (i = 1; i <= ns; i++) {
				if (seeds[i] in in_grp) continue
				va = ra[seeds[i] " " p]; vk = rk[seeds[i] " " p]
				sa += va; sa2 += va * va; sk += vk; sk2 += vk * vk; m++
			}
			ref_a = sa / m; ref_k = sk / m
			extra_a = m > 1 ? (sa2 - m * ref_a * ref_a) / (m - 1) / m : 0
			extra_k = m > 1 ? (sk2 - m * ref_k * ref_k) / (m - 1) / m : 0
		}
		ea = sqrt($6 * $6 + extra_a); ek = sqrt($8 * $8 + extra_k)
		id = e " " lvl
		n[id]++
		da = $5 - ref_a; if (da < 0) da = -da
		dk = $7 - ref_k; if (dk < 0) dk = -dk
		if (da <= ea) ca[id]++
		if (dk <= ek) ck[id]++
		ra_sum[id] += da / ref_a; re_sum[id] += ea / ref_a
		z[id] = z[id] " " (ea > 0 ? da / ea : 1e9)
		order[id] = ++k
	}
	END {
		print "eps_c\tlevel\tn\tcoverage_a_r\tcoverage_kappa\tmean_abs_err_rel\tmean_interval_rel\tmedian_err_over_interval"
		for (id in n) {
			m = split(z[id], v, " ")
			for (i = 1; i <= m; i++) for (j = i + 1; j <= m; j++) if (v[j] < v[i]) { t = v[i]; v[i] = v[j]; v[j] = t }
			med = m % 2 ? v[(m + 1) / 2] : (v[m / 2] + v[m / 2 + 1]) / 2
			split(id, w, " ")
			printf "%s\t%s\t%d\t%.2f\t%.2f\t%.3g\t%.3g\t%.3g\n", w[1], w[2], n[id],
			    ca[id] / n[id], ck[id] / n[id], ra_sum[id] / n[id], re_sum[id] / n[id], med
		}
	}' "$OUT/ref.txt" "$OUT/est.txt" >"$OUT/coverage.tmp"
{ head -n 1 "$OUT/coverage.tmp"; tail -n +2 "$OUT/coverage.tmp" | sort -k2,2r -k1,1; } >"$OUT/coverage.tsv"
rm -f "$OUT/coverage.tmp"
column -t -s "$(printf '\t')" "$OUT/coverage.tsv"
