#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# surfgen end to end: output files and pipes, header metadata, seeds and
# grid refinement through the tool, PNG, usage errors reported at once.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

# The float64 data of a .surf file, one value per line (%.17g).
values() {
	n=$(awk '/^nx = / { nx = $3 } /^ny = / { ny = $3 } /^end_header/ { print nx * ny; exit }' "$1")
	tail -c $((n * 8)) "$1" | od -A n -v -t f8 | awk '{ for (i = 1; i <= NF; i++) printf "%.17g\n", $i }'
}
meta() { awk -v k="meta.$2" '$1 == k { print $3; exit }' "$1"; }

check_status "surfgen -n 64 -o a.surf" 0 surfgen -n 64 -o a.surf
check "header names the size" grep -q '^nx = 64$' a.surf
check "header: type" [ "$(meta a.surf type)" = selfaffine ]
check "header: H default 0.8" [ "$(meta a.surf H)" = 0.8 ]
check "header: seed" [ "$(meta a.surf seed)" = 1 ]
check "header: lambda_s two spacings" [ "$(meta a.surf lambda_s)" = 0.03125 ]
check "header: rms_gradient" [ "$(meta a.surf rms_gradient)" = 1 ]
check "header: amplitudes" [ "$(meta a.surf amplitudes)" = sqrt ]
check "header: history holds the command" grep -q '^history = surfgen -n 64 -o a.surf$' a.surf
check "no harmonic keys on a selfaffine surface" sh -c '! grep -q "^meta.exponent" a.surf'

# Standard output is the same surface (the history differs, the data not).
surfgen -n 64 | cat >b.surf
values a.surf >a.txt
values b.surf >b.txt
check "stdout pipe gives the same data" cmp -s a.txt b.txt
check_rel "4096 values" "$(wc -l <a.txt)" 4096 0
# Mean zero and rms gradient (finite differences, which sit a few per cent
# below the spectral 1 for a spectrum reaching the grid's Nyquist
# wavelength: each mode is damped by sin(q dx)/(q dx)).
check_range "mean height 0" "$(awk '{ s += $1 } END { printf "%.3g", s / NR }' a.txt)" -1e-15 1e-15
gfd=$(awk '{ z[NR - 1] = $1 } END { n = 64; d = 1 / n; s = 0
	for (j = 0; j < n; j++) for (i = 0; i < n; i++) {
		gx = (z[j * n + (i + 1) % n] - z[j * n + (i + n - 1) % n]) / (2 * d)
		gy = (z[((j + 1) % n) * n + i] - z[((j + n - 1) % n) * n + i]) / (2 * d)
		s += gx * gx + gy * gy }
	printf "%.6f", sqrt(s / (n * n)) }' a.txt)
check_range "finite-difference rms gradient below and near 1" "$gfd" 0.5 1

# Seeds: same seed same surface, another seed another.
surfgen -n 32 --seed 5 -o s5.surf
surfgen -n 32 --seed 5 -o s5b.surf
surfgen -n 32 --seed 6 -o s6.surf
values s5.surf >s5.txt; values s5b.surf >s5b.txt; values s6.surf >s6.txt
check "same seed, same data" cmp -s s5.txt s5b.txt
check "another seed, other data" sh -c '! cmp -s s5.txt s6.txt'

# Refinement: -n 32 is every second point of -n 64 with the same seed and
# lambda_s = two coarse spacings (relative 1e-12 of the rms height).
surfgen -n 32 --lambda-s 0.0625 --seed 9 -o c.surf
surfgen -n 64 --lambda-s 0.0625 --seed 9 -o f.surf
values c.surf >c.txt
values f.surf >f.txt
dev=$(awk 'NR == FNR { c[NR - 1] = $1; s += $1 * $1; next }
	{ k = FNR - 1; i = k % 64; j = int(k / 64)
	  if (i % 2 == 0 && j % 2 == 0) { d = $1 - c[(j / 2) * 32 + i / 2]; if (d < 0) d = -d; if (d > m) m = d } }
	END { printf "%.3g", m / sqrt(s / 1024) }' c.txt f.txt)
check_range "coarse = every second point of fine" "$dev" 0 1e-12

# Other formats by extension.
surfgen -n 16x8 -L 2x1 -o g.npy
check_rel "npy: 128 float64 after a 64-byte aligned header" "$(( ($(wc -c <g.npy) - 1024) % 64 ))" 0 0
check "npy magic" sh -c 'head -c 6 g.npy | grep -q NUMPY'
surfgen -n 16x8 -L 2x1 -o g.txt
check_rel "txt: 8 rows" "$(grep -vc "^#" g.txt)" 8 0
check_rel "txt: 16 columns" "$(awk '!/^#/ { print NF; exit }' g.txt)" 16 0

# Types and their keys.
surfgen -n 64 --type harmonic --exponent 1.5 --radius 2 -o h.surf
check "harmonic: exponent in header" [ "$(meta h.surf exponent)" = 1.5 ]
check "harmonic: no H" sh -c '! grep -q "^meta.H " h.surf'
surfgen -n 64 --type harmonic -o h2.surf
values h2.surf >h2.txt
check_rel "harmonic apex 0 at the centre" "$(sed -n $((32 * 64 + 33))p h2.txt)" 0 0
check_rel "harmonic n=2 at the edge: -1/8" "$(sed -n $((32 * 64 + 1))p h2.txt)" -0.125 1e-15
surfgen -n 40x1 --type sine --wavelength 0.25 --amplitude 0.5 -o w.surf
values w.surf >w.txt
check_rel "sine at x = 0" "$(sed -n 1p w.txt)" 0.5 1e-15
check_rel "sine at x = lambda/2" "$(sed -n 6p w.txt)" -0.5 1e-15
check_status "eggbox" 0 surfgen -n 32 --type eggbox --wavelength 0.5 -o e.surf
check_status "flat" 0 surfgen -n 8 --type flat -o z.surf

# PNG preview.
check_status "png" 0 surfgen -n 64 --png p.png -o p.surf
check "png magic" sh -c 'head -c 8 p.png | od -A n -t x1 | grep -q "89 50 4e 47 0d 0a 1a 0a"'

# Usage errors: exit 2, every problem reported in one run, no output.
echo keep >keep.surf
surfgen -H 1.5 --lambda-r -2 --type cone --seed x -n 0 --bogus -o keep.surf 2>err.txt
check_rel "bad options exit 2" $? 2 0
check_rel "all seven problems reported (six options + the summary line)" "$(grep -c '^surfgen: ' err.txt)" 7 0
check "existing output untouched" grep -qx keep keep.surf
check_status "lambda_s below two spacings" 2 surfgen -n 64 --lambda-s 0.01 -o x.surf
check_status "lambda_r not above lambda_s" 2 surfgen -n 64 --lambda-r 0.1 --lambda-s 0.1 -o x.surf
check_status "both rms targets" 2 surfgen --rms-gradient 1 --rms-height 1 -o x.surf
check_status "wavelength must divide the cell" 2 surfgen --type sine --wavelength 0.3 -o x.surf
check_status "selfaffine options on a sine" 2 surfgen --type sine -H 0.5 -o x.surf
check_status "Peklenik band beyond Nyquist" 2 surfgen -n 64 --peklenik 4 --lambda-s 0.04 -o x.surf
check_status "unknown extension" 2 surfgen -o x.dat
check_status "an input argument" 2 surfgen in.surf
check "no stray output" [ ! -e x.surf ]
check_status "--help" 0 surfgen --help
check "--help prints a synopsis" sh -c 'surfgen --help | grep -q "^usage: surfgen"'
check_status "--version" 0 surfgen --version
summary
