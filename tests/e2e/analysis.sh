#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# analysis.sh - measured-data analysis end to end: levelling steps in
# order, the periodic flag in the header, crop/transpose/resample
# identities, 1D spectra of profiles independent of the strip width, the
# window default, ISO parameters of a plane, fit -> surfgen --like ->
# fit, the filled points kept in the output, and the usage errors of the
# new options.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

# A tilted plane as a plain matrix: detrend plane leaves round-off.
awk 'BEGIN { for (j = 0; j < 24; j++) { s = ""; for (i = 0; i < 32; i++)
	s = s sprintf("%s%.17g", i ? " " : "", 0.5 + 0.01 * i - 0.02 * j); print s } }' > plane.txt
surfwarp -L 3.2x2.4 --detrend plane plane.txt -o d.surf
check "detrended grid says periodic = 0" grep -aq '^periodic = 0$' d.surf
surfstat --iso d.surf > iso.tsv
check_range "detrend plane: Sq at round-off" "$(col iso.tsv Sq)" 0 1e-14
check "periodic column 0 after reading back" [ "$(col iso.tsv periodic)" = 0 ]
# (a crop of all but the last row and column: a finite patch, no wrap)
surfwarp -L 3.2x2.4 --crop 0:31,0:23 plane.txt -o p.surf
surfstat --iso p.surf > isop.tsv
# slope along x 0.01 per 0.1 = 0.1, along y -0.02 per 0.1 = -0.2
check_rel "Sdq of the plane" "$(col isop.tsv Sdq)" "$(awk 'BEGIN { printf "%.17g", sqrt(0.05) }')" 1e-12
check_rel "Sdr of the plane" "$(col isop.tsv Sdr)" "$(awk 'BEGIN { printf "%.17g", sqrt(1.05) - 1 }')" 1e-12
surfwarp --detrend mean -L 3.2x2.4 plane.txt -o m.surf
check "mean removal keeps the grid periodic" grep -aq '^periodic = 1$' m.surf

# Order: crop then transpose differs from transpose then crop.
surfgen -n 32x16 -L 2x1 --seed 4 -o s.surf
surfwarp --crop 0:8,0:4 --transpose s.surf -o ct.surf
surfwarp --transpose --crop 0:8,0:4 s.surf -o tc.surf
check "crop then transpose is 4x8" grep -aq '^nx = 4$' ct.surf
check "transpose then crop is 8x4" grep -aq '^nx = 8$' tc.surf
surfwarp --transpose --transpose s.surf -o tt.txt
surfwarp s.surf -o s.txt
grep -v '^#' s.txt > s.val
grep -v '^#' tt.txt > tt.val
check "transpose twice is the identity" cmp -s s.val tt.val
# Spectral resampling of a periodic grid: up and back down exactly.
surfwarp --resample 0.03125 s.surf -o up.surf
check "resample 1/32: 64 points" grep -aq '^nx = 64$' up.surf
surfwarp --resample 0.0625 up.surf -o down.txt
grep -v '^#' down.txt > down.val
check "spectral resampling up and down returns the grid" awk '
	NR == FNR { for (i = 1; i <= NF; i++) a[FNR, i] = $i; next }
	{ for (i = 1; i <= NF; i++) { d = $i - a[FNR, i]; if (d < 0) d = -d; if (d > 1e-13) bad = 1 } }
	END { exit bad }' s.val down.val
surfwarp --fill --filled-mask fm.surf s.surf -o f.surf 2>/dev/null
check "fill of a complete grid records 0 filled points" grep -aq '^meta.filled_points = 0$' f.surf
check "filled mask is a mask" grep -aq '^kind = mask$' fm.surf

# Filled points kept in the output.  Holes punched into a 128x96 map: a
# 30x60 rectangle, a whole row, scattered points.
# ranges FILE WHAT: the indices k = j nx + i of the data values of a text
# grid that are nan (WHAT = nan) or 1 (WHAT = 1), as surf(5)'s ranges
ranges() {
	awk -v what="$2" 'BEGIN { k = 0 } !/^#/ { for (i = 1; i <= NF; i++) { if ($i == what) {
		if (n && k == last + 1) { last = k } else { if (n) out = out sep(); first = k; last = k; n = 1 } }
		k++ } }
		function sep() { return (first == last ? first : first "-" last) "," }
		END { if (n) out = out (first == last ? first : first "-" last); print out }' "$1"
}
surfgen -q -n 128x96 -L 12.8x9.6 --seed 2 -o base.txt
awk '/^#/ { print; next } { for (i = 1; i <= NF; i++) if ((i > 10 && i <= 40 && j >= 5 && j < 65) ||
	j == 80 || ((i - 1) * 7 + j * 13) % 101 == 0) $i = "nan"; j++; print }' base.txt > holes.txt
listed=$(ranges holes.txt nan)
surfwarp --fill --filled-mask holes-mask.txt -o filled.surf holes.txt 2>/dev/null
check "the filled points are listed in the header" [ "$(grep -a '^filled = ' filled.surf)" = "filled = $listed" ]
check "... 60 rows of the hole, the row, the dropouts: few ranges" [ "$(printf %s "$listed" | tr ',' '\n' | wc -l)" -lt 200 ]
check "the --filled-mask file marks the same points" [ "$(ranges holes-mask.txt 1)" = "$listed" ]
# The header's first 1000 bytes: text, the grid's description first.
head -c 1000 filled.surf > head.txt
check "head -c 1000: all text" [ "$(LC_ALL=C tr -d '[:print:]\n' < head.txt | wc -c)" -eq 0 ]
check "head -c 1000: the grid first" [ "$(sed -n 3,4p head.txt | tr '\n' ' ')" = "nx = 128 ny = 96 " ]
check_status "the toolkit reads it" 0 surfstat -q filled.surf
# A second operation on the same grid keeps the list; one that changes
# the grid maps it (crop, transpose) or drops it (resample).
surfwarp -q --detrend mean -w 0.5 -o again.surf filled.surf
check "detrend and warp keep the list" [ "$(grep -a '^filled = ' again.surf)" = "filled = $listed" ]
surfwarp -q -o again.txt filled.surf
check ".txt keeps it" grep -q "^# filled = $listed\$" again.txt
surfwarp -q -o again.gsf filled.surf
surfwarp -q -o again2.surf again.gsf
check ".gsf keeps it" [ "$(grep -a '^filled = ' again2.surf)" = "filled = $listed" ]
surfwarp --crop 5:45,10:90 -o crop.surf filled.surf
surfwarp -q --crop 5:45,10:90 -o crop.txt holes.txt
check "a crop keeps the filled points inside it" [ "$(grep -a '^filled = ' crop.surf)" = "filled = $(ranges crop.txt nan)" ]
surfwarp --transpose -o tr.surf filled.surf
surfwarp -q --transpose -o tr.txt holes.txt
check "a transpose moves them with their values" [ "$(grep -a '^filled = ' tr.surf)" = "filled = $(ranges tr.txt nan)" ]
surfwarp --resample 0.15 -o rs.surf filled.surf
check "a resample drops the list" sh -c '! grep -aq "^filled = " rs.surf'
surfwarp -o lost.npy filled.surf 2>lost.err
check "a .npy output says it loses them" grep -q 'lost.npy: the .* filled points are not marked' lost.err

# A profile's spectrum is 1D and does not depend on ly.
surfgen -n 128 --seed 5 -o r.surf
surfwarp --crop 0:128,0:1 r.surf -o prof.txt
surfstat -L 1x1 --psd prof.txt > p1.tsv
surfstat -L 1x5 --psd prof.txt > p5.tsv
check "profile --psd is the 1D table" [ "$(head -n 1 p1.tsv | cut -f 2)" = C1D ]
check "profile spectrum independent of ly" cmp -s p1.tsv p5.tsv
check_rel "C1D_ce = 2 pi C1D" "$(col p1.tsv C1D_ce 3)" \
    "$(awk -v c="$(col p1.tsv C1D 3)" 'BEGIN { printf "%.17g", 2 * 3.14159265358979324 * c }')" 1e-14
check_status "profile has no 2D spectrum" 1 surfstat -L 1x1 --psd2d x.surf prof.txt

# Periodic grid: the default window is none, bit for bit.
surfstat --psd r.surf > a.tsv
surfstat --psd --window none r.surf > b.tsv
check "periodic spectrum unchanged by the window default" cmp -s a.tsv b.tsv
surfwarp --crop 0:120,0:120 r.surf -o c.surf
surfstat --fit c.surf > cf.tsv
check "a finite patch is fitted through a Hann window" [ "$(col cf.tsv window)" = hann ]

# Fit -> surfgen --like -> fit: the statistics come back.
surfgen -n 128 -H 0.7 --lambda-r 0.25 --rolloff --seed 1 -o sa.surf
surfstat --fit -o fit.tsv sa.surf
surfgen -q --like fit.tsv --seed 9 -o twin.surf
check "twin is periodic" grep -aq '^periodic = 1$' twin.surf
surfstat --fit twin.surf > fit2.tsv
# exact amplitudes: H to 0.01, q_r to a bin (26%), hrms to 10%
check_range "twin's H" "$(col fit2.tsv H)" 0.69 0.71
check_rel "twin's q_r" "$(col fit2.tsv q_r)" 25.13 0.26
check_rel "twin's hrms" "$(col fit2.tsv hrms)" "$(col fit.tsv hrms)" 0.1
surfgen -q --like sa.surf --seed 9 -o twin2.txt
surfwarp twin.surf -o twin.txt
grep -v '^#' twin.txt > twin.val
grep -v '^#' twin2.txt > twin2.val
check "--like a surface equals --like its fit table" cmp -s twin.val twin2.val

# Usage and data errors.
check_status "--detrend foo" 2 surfwarp --detrend foo s.surf
check_status "--align-rows foo" 2 surfwarp --align-rows foo s.surf
check_status "--crop 5:3,0:1" 2 surfwarp --crop 5:3,0:1 s.surf
check_status "--crop bad syntax" 2 surfwarp --crop 1:2 s.surf
check_status "--crop outside the grid" 1 surfwarp --crop 0:99,0:4 s.surf -o x.surf
check "no output left by a failed crop" [ ! -e x.surf ]
check_status "--filled-mask without --fill" 2 surfwarp --filled-mask m.surf s.surf
check_status "--resample 0" 2 surfwarp --resample 0 s.surf
check_status "--window on the scalar row" 2 surfstat --window hann s.surf
check_status "--window foo" 2 surfstat --psd --window foo s.surf
check_status "--acf-half without --acf" 2 surfstat --acf-half s.surf
check_status "--min-wavelength without --fit" 2 surfstat --min-wavelength 0.1 s.surf
check_status "two tables" 2 surfstat --iso --fit s.surf
check_status "--like with -H" 2 surfgen --like fit.tsv -H 0.5
check_status "--like a missing file" 1 surfgen --like nothere.tsv
# A broken fit table: refused with the column named, nothing written.
sed '2s/^\([^	]*	[^	]*	[^	]*	[^	]*	\)[^	]*/\1abc/' fit.tsv > badfit.tsv
surfgen --like badfit.tsv -o bad.surf 2>bad.err
check_rel "--like a fit table with H = abc: exit 1" $? 1 0
check "the message names H" grep -q "H = 'abc'" bad.err
check "nothing written" [ ! -e bad.surf ]
head -n 1 fit.tsv > header-only.tsv
check_status "--like a fit table without a row" 1 surfgen --like header-only.tsv
check_status "--fit of a profile" 1 surfstat --fit -L 1x1 prof.txt
# The header key: only 0 or 1.
LC_ALL=C sed 's/^periodic = 0$/periodic = 2/' d.surf > p2.surf
surfstat --iso p2.surf > /dev/null 2>p2.err
check_rel "periodic = 2 refused: exit 1" $? 1 0
check "the message names the key" grep -q "periodic = '2'" p2.err
summary
