#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# demo.sh - the built-in default example (make demo): one self-affine
# surface at two resolutions, its statistics, its contact at three
# pressures, and a_r and kappa extrapolated to the continuum limit.
# Writes into demo-out/ (or $DEMO_OUT); takes a few seconds.
set -eu
: "${RC_BIN:=bin}"
PATH="$RC_BIN:$PATH"
out=${DEMO_OUT:-demo-out}
mkdir -p "$out"

# columns NAME... of a TSV, by name, aligned
cols() {
	f=$1; shift
	awk -F'\t' -v want="$*" 'NR == 1 { n = split(want, w, " ")
		for (i = 1; i <= NF; i++) idx[$i] = i }
	    { line = ""; for (k = 1; k <= n; k++) {
		v = (NR == 1) ? w[k] : $(idx[w[k]])
		if (NR > 1 && v ~ /^-?[0-9.]+(e[-+]?[0-9]+)?$/) v = sprintf("%.6g", v)
		line = line sprintf("%-13s", v) }
	      print "   " line }' "$f"
}

echo "== surfgen: self-affine surface, H = 0.8, lambda_r = L/2, lambda_s = L/32, gbar = 1"
for n in 128 256; do
	surfgen -n $n -H 0.8 --lambda-r 0.5 --lambda-s 0.03125 --seed 1 \
	    -o "$out/surface-$n.surf"
done
surfgen -n 256 -H 0.8 --lambda-r 0.5 --lambda-s 0.03125 --seed 1 \
    --png "$out/surface.png" -o /dev/null
echo "   wrote $out/surface-128.surf, $out/surface-256.surf (the same surface), $out/surface.png"
sed -n '1,20p' "$out/surface-256.surf" | grep -a -v '^end_header' | sed 's/^/   | /'

echo "== surfstat: whole-surface statistics (256x256)"
surfstat -o "$out/stats.tsv" "$out/surface-256.surf"
cols "$out/stats.tsv" hrms gbar gbar_fd nayak phi4 phi6 phi8 phi9 skewness

echo "== gfmd-solve: p* = 0.02, 0.05, 0.1 with FIRE-GFMD, at both resolutions"
for n in 128 256; do
	gfmd-solve -q -p 0.02,0.05,0.1 --contact "$out/contact-$n.surf" \
	    -o "$out/rows-$n.tsv" "$out/surface-$n.surf"
done
surfgen -n 256 -H 0.8 --lambda-r 0.5 --lambda-s 0.03125 --seed 1 |
    gfmd-solve -q -p 0.05 --png "$out/contact.png" -o /dev/null
cols "$out/rows-256.tsv" p_star a_r n_c kappa kappa_c gbar_c iterations residual seconds
echo "   wrote $out/rows-128.tsv, $out/rows-256.tsv, $out/contact-*.surf, $out/contact.png"

echo "== contact-stats: Richardson extrapolation dx/lambda_s -> 0 from the two grids"
contact-stats -o "$out/kappa.tsv" "$out/rows-128.tsv" "$out/rows-256.tsv"
cols "$out/kappa.tsv" p_star a_r a_r_err kappa kappa_err kappa_c
echo "   wrote $out/kappa.tsv"
