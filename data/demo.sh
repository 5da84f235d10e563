#!/bin/sh
# demo.sh - the built-in default example (make demo): a self-affine surface,
# its statistics, its contact under three pressures, kappa extrapolated.
# Writes into demo-out/ (or $DEMO_OUT).
set -eu
: "${RC_BIN:=bin}"
PATH="$RC_BIN:$PATH"
out=${DEMO_OUT:-demo-out}
mkdir -p "$out"
echo "== surfgen: 256x256 self-affine surface, H = 0.8, lambda_r = L/2, lambda_s = L/32, gbar = 1"
surfgen -n 256 -H 0.8 --lambda-r 0.5 --lambda-s 0.03125 --seed 1 \
    --png "$out/surface.png" -o "$out/surface.surf"
echo "   wrote $out/surface.surf and $out/surface.png"
head -c 400 "$out/surface.surf" | sed -n '1,12p' | sed 's/^/   | /'
if command -v surfstat >/dev/null 2>&1; then
	echo "== surfstat: scalars"
	surfstat "$out/surface.surf" | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[i] = $i; next }
	    { for (i = 1; i <= NF && i <= 24; i++) printf "   %-16s %s\n", h[i], $i }'
fi
if command -v gfmd-solve >/dev/null 2>&1; then
	echo "== gfmd-solve: p* = 0.02, 0.05, 0.1 (FIRE-GFMD)"
	gfmd-solve -p 0.02,0.05,0.1 --contact "$out/contact.surf" \
	    --png "$out/contact.png" -o "$out/results.tsv" "$out/surface.surf"
	cut -f 1,3,4,11,12,17,18,19 "$out/results.tsv" | sed 's/^/   /'
	echo "   wrote $out/results.tsv, $out/contact.surf, $out/contact.png"
fi
