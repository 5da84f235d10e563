# SPDX-License-Identifier: GPL-3.0-or-later
# nonuni.sh - x-z profiles not uniformly spaced through the tools:
# surfstat analyses them as they are (stats_nonuni.h), by hand on
# SurfaceTopography's xy-3.txt (tests/data/st_text.README) and against an
# independent numpy computation of the same formulas on a random profile
# (python3-numpy); what needs a grid (gfmd-solve, surfwarp, surfstat
# --iso) refuses them naming --uniform.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
D=$RC_TOP/tests/data

# xy-3: 0 but 1 at x 4.5, L 9: mean 1/18, hrms sqrt(11)/18, slope 2/3
surfstat -q "$D/st_xy-3.txt" >x3.tsv
check "xy-3: the row says nonuniform" [ "$(col x3.tsv spacing)" = nonuniform ]
check "xy-3: lx is the x span, 9" [ "$(col x3.tsv lx)" = 9 ]
check_rel "xy-3: mean 1/18" "$(col x3.tsv mean)" 0.055555555555555556 1e-15
check_rel "xy-3: hrms sqrt(11)/18" "$(col x3.tsv hrms)" 0.18425693279752226 1e-15
check_rel "xy-3: rms slope 2/3" "$(col x3.tsv rms_slope)" 0.66666666666666667 1e-15
# xy-6: a missing point takes out its two segments, said on stderr
check_status "xy-6 (one height NaN): read" 0 surfstat "$D/st_xy-6.txt"
check "... the left-out segments said" grep -q "1 of 4 points missing: the segments touching them are left out" "$T_TMP/stderr"

check_status "gfmd-solve refuses a non-uniform profile" 1 gfmd-solve -p 0.01 "$D/st_xy-3.txt"
check "... naming --uniform" grep -q "x is not uniformly spaced.*--uniform resamples" "$T_TMP/stderr"
check_status "surfwarp refuses it" 1 surfwarp -q -o o.surf "$D/st_xy-3.txt"
check_status "surfstat --iso refuses it" 1 surfstat --iso "$D/st_xy-3.txt"
check "... naming --iso and --uniform" grep -q "\-\-iso needs a uniform grid: --uniform resamples" "$T_TMP/stderr"
check_status "surfstat --window blackman --psd refuses it" 1 surfstat --psd --window blackman "$D/st_xy-3.txt"
check_status "surfstat --uniform still resamples it" 0 surfstat --uniform "$D/st_xy-3.txt"
check "... to the uniform row" [ "$(surfstat --uniform "$D/st_xy-3.txt" | head -1 | cut -f3)" = derivatives ]

# numpy: the same formulas written independently (vectorised) on 300
# random positions, heights a sum of sines; the spectrum with the Hann
# window at q_k = 2 pi k / L as SurfaceTopography's brute-force algorithm
# (its mean removed first); relative 1e-9 (different summation orders).
PY=""
for p in python3 /usr/bin/python3; do
	if "$p" -c 'import numpy' 2>/dev/null; then PY=$p; break; fi
done
if [ -n "$PY" ]; then
	"$PY" - <<'PY'
import numpy as np
rng = np.random.default_rng(26)
x = np.sort(np.concatenate(([0.0, 7.0], rng.uniform(0, 7, 298))))
h = np.sin(1.3 * x) + 0.3 * np.cos(5.1 * x + 0.4) + 0.1 * rng.standard_normal(x.size)
np.savetxt("r.txt", np.column_stack((x, h)), fmt="%.17g")
dx, L = np.diff(x), x[-1] - x[0]
mean = np.trapz(h, x) / L
d = h - mean
hrms = np.sqrt(np.sum((d[:-1]**2 + d[:-1]*d[1:] + d[1:]**2) * dx) / (3 * L))
slope = np.sqrt(np.sum(np.diff(h)**2 / dx) / L)
dm, dp = x[1:-1] - x[:-2], x[2:] - x[1:-1]
c = 2 * (dm * (h[2:] - h[1:-1]) + dp * (h[:-2] - h[1:-1])) / (dp * dm * (dp + dm))
curv = np.sqrt(np.trapz(c**2, x[1:-1]) / (x[-2] - x[1]))
y = np.sqrt(2 / 3) * (1 - np.cos(2 * np.pi * (x - x[0]) / L)) * d
k = np.arange(1, min(int(L / dx.min()), x.size - 1))
q = 2 * np.pi * k / L
xm, ym, dy = (x[1:] + x[:-1]) / 2, (y[1:] + y[:-1]) / 2, np.diff(y)
u = np.outer(q, dx) / 2
sinc = np.sin(u) / u
dsinc = (np.cos(u) - sinc) / u
H = np.sum(dx * np.exp(-1j * np.outer(q, xm)) * (ym * sinc + 1j * dy * dsinc / 2), axis=1)
C = np.abs(H)**2 / L
with open("want.txt", "w") as f:
    f.write("%.17g %.17g %.17g %.17g\n" % (mean, hrms, slope, curv))
    f.write("%d %.17g %.17g %.17g %.17g\n" % (q.size, q[0], C[0], q[9], C[9]))
    f.write("%.17g\n" % np.sum(C))
PY
	surfstat -q r.txt >r.tsv
	set -- $(sed -n 1p want.txt)
	check_rel "numpy: mean" "$(col r.tsv mean)" "$1" 1e-9
	check_rel "numpy: hrms" "$(col r.tsv hrms)" "$2" 1e-9
	check_rel "numpy: rms slope" "$(col r.tsv rms_slope)" "$3" 1e-9
	check_rel "numpy: rms curvature" "$(col r.tsv rms_curvature)" "$4" 1e-9
	surfstat -q --psd r.txt >p.tsv
	set -- $(sed -n 2p want.txt)
	check "numpy: as many wave vectors ($1)" [ "$(($(wc -l <p.tsv) - 1))" = "$1" ]
	check_rel "numpy: q_1" "$(col p.tsv q 1)" "$2" 1e-12
	check_rel "numpy: C1D_ce(q_1)" "$(col p.tsv C1D_ce 1)" "$3" 1e-9
	check_rel "numpy: C1D_ce(q_10)" "$(col p.tsv C1D_ce 10)" "$5" 1e-9
	check_rel "numpy: sum of C1D_ce over every q" "$(awk -F'\t' 'NR > 1 { s += $3 } END { printf "%.17g", s }' p.tsv)" "$(sed -n 3p want.txt)" 1e-9
else
	skip 9 "python3-numpy not installed: the independent numpy computation (apt-get install python3-numpy)"
fi
summary
