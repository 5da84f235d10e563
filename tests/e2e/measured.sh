#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# measured.sh - measured data through the tools: units converted before
# any gradient (a um x nm map gives the gbar and a_r of the same map in
# metres), non-length channels refused, the wrap-around warning, missing
# points refused by name, arrays numpy writes in either axis order,
# columns and the flags kept by the formats; surfstat --fit and surfgen
# --like keep a map's unit (a um map has a um twin).
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

# A python3 with numpy, if any (pyenv shims may hide the system's).
PY=""
for p in python3 /usr/bin/python3; do
	if "$p" -c 'import numpy' 2>/dev/null; then PY=$p; break; fi
done

# --- units ------------------------------------------------------------------
# The same surface as L = 10 um with heights in nm, and as L = 1e-5 m with
# heights in m: surfgen's (L = 1, unitless) scaled by 10 um.
surfgen -q -n 32 --lambda-r 0.5 --seed 3 -o s.txt
scaled() {	# scaled LX UNIT ZUNIT FACTOR
	awk -v lx="$1" -v u="$2" -v zu="$3" -v f="$4" '
		NR == 1 { print "# nx = 32"; print "# ny = 32"; print "# lx = " lx; print "# ly = " lx
			print "# unit = " u; print "# z_unit = " zu }
		/^#/ { next } { for (i = 1; i <= NF; i++) printf "%s%.17g", (i > 1 ? " " : ""), $i * f; print "" }' s.txt
}
scaled 10 um nm 1e4 >umnm.txt
scaled 1e-5 m m 1e-5 >m.txt
surfstat -q s.txt >s.tsv
surfstat -q umnm.txt >umnm.tsv
surfstat -q m.txt >m.tsv
check_rel "gbar: um x nm = m x m" "$(col umnm.tsv gbar)" "$(col m.tsv gbar)" 1e-12
check_rel "gbar: um x nm = unitless original" "$(col umnm.tsv gbar)" "$(col s.tsv gbar)" 1e-12
check_rel "gbar_fd: um x nm = m x m" "$(col umnm.tsv gbar_fd)" "$(col m.tsv gbar_fd)" 1e-12
check_rel "hrms of the um x nm map is in um" "$(col umnm.tsv hrms)" "$(awk -v h="$(col s.tsv hrms)" 'BEGIN { printf "%.17g", 10 * h }')" 1e-12
surfstat -q --unit nm umnm.txt >nm.tsv
check_rel "--unit nm: hrms in nm" "$(col nm.tsv hrms)" "$(awk -v h="$(col s.tsv hrms)" 'BEGIN { printf "%.17g", 1e4 * h }')" 1e-12
check_rel "--unit nm: lx in nm" "$(col nm.tsv lx)" 10000 0
check "--unit nm: the row says nm" [ "$(col nm.tsv unit)" = nm ]
check "the um x nm map's row says um" [ "$(col umnm.tsv unit)" = um ]
check_rel "--unit nm: gbar unchanged" "$(col nm.tsv gbar)" "$(col s.tsv gbar)" 1e-12
# At an absolute pressure: a_r at a given p* would not see a wrong height
# scale, a_r at a given p does.  The two indenters differ by round-off
# (1e-16): the same contact, a_r equal to far below the solver tolerance.
gfmd-solve -q -j 1 --pressure-abs 0.1 umnm.txt >umnm-rows.tsv
gfmd-solve -q -j 1 --pressure-abs 0.1 m.txt >m-rows.tsv
check_rel "gfmd-solve a_r: um x nm = m x m" "$(col umnm-rows.tsv a_r)" "$(col m-rows.tsv a_r)" 1e-9
check_rel "gfmd-solve gbar: um x nm = m x m" "$(col umnm-rows.tsv gbar)" "$(col m-rows.tsv gbar)" 1e-12
check_range "... a contact neither empty nor full" "$(col m-rows.tsv a_r)" 0.01 0.99
gfmd-solve -q -j 1 -p 0.1 --unit nm --gap gap.txt umnm.txt >/dev/null
check "gfmd-solve --unit nm: the gap field is in nm" grep -q '^# unit = nm' gap.txt
# A plain matrix takes --unit as its unit, --z-unit as its heights'.
awk '/^#/ { next } { print }' umnm.txt >plain.txt
surfstat -q -L 10 --unit um --z-unit nm plain.txt >plain.tsv
check_rel "plain matrix, -L 10 --unit um --z-unit nm" "$(col plain.tsv gbar)" "$(col s.tsv gbar)" 1e-12

# A phase channel (ZUnits = deg) is not a height unless the user says so.
printf 'Gwyddion Simple Field 1.0\nXRes = 2\nYRes = 2\nXReal = 1e-06\nYReal = 1e-06\nXYUnits = m\nZUnits = deg\n' >phase.gsf
n=$(wc -c <phase.gsf); head -c $((4 - n % 4)) /dev/zero >>phase.gsf
printf '\000\000\200\077\000\000\000\100\000\000\100\100\000\000\200\100' >>phase.gsf
check_status "surfstat refuses a deg channel" 1 surfstat -q phase.gsf
check "... naming deg and --z-unit" grep -q "phase.gsf: values are in 'deg'.*--z-unit" "$T_TMP/stderr"
check_status "surfstat --z-unit nm reads it" 0 surfstat -q --z-unit nm phase.gsf
check_status "--unit furlong is a usage error" 2 surfstat -q --unit furlong s.txt

# Gwyddion, a real client, opens our .gsf of the um x nm map with its size
# and heights in metres (float32: 2^-24 relative).
if command -v gwyddion >/dev/null 2>&1 && command -v python3 >/dev/null 2>&1; then
	surfwarp -q -w 0 -o umnm.gsf umnm.txt
	surfwarp -q -w 0 -o umnm-um.txt umnm.txt
	if gwyddion --convert-to-gwy=umnm.gwy umnm.gsf >/dev/null 2>&1; then
		# xreal, the lateral unit string and the first value of the .gwy
		python3 -c '
import struct, sys
d = open("umnm.gwy", "rb").read()
i = d.find(b"xreal\0d") + 7
j = d.find(b"si_unit_xy")
u = d.find(b"unitstr\0s", j) + 9
k = d.find(b"data\0D") + 10
print(struct.unpack("<d", d[i:i + 8])[0], d[u:d.find(b"\0", u)].decode(),
    struct.unpack("<d", d[k:k + 8])[0])' >gwy.txt
		first=$(awk '!/^#/ { print $1; exit }' umnm-um.txt)
		check_rel "Gwyddion reads XReal of our .gsf: 10 um = 1e-5 m" "$(awk '{ print $1 }' gwy.txt)" 1e-5 1e-15
		check "... in m" [ "$(awk '{ print $2 }' gwy.txt)" = m ]
		check_rel "... and the first height in m" "$(awk '{ print $3 }' gwy.txt)" "$(awk -v z="$first" 'BEGIN { printf "%.17g", z * 1e-6 }')" 1.2e-7
	else
		skip 2 "gwyddion --convert-to-gwy failed here: Gwyddion client check"
	fi
else
	skip 3 "gwyddion or python3 not installed: Gwyddion client check (apt-get install gwyddion python3)"
fi

# --- a twin in the map's unit ----------------------------------------------------
# A 10 um map (Rayleigh amplitudes, as a measurement's) in netCDF, which
# carries the unit: surfstat --fit says um, surfgen --like makes its twin
# in um, and the twin's fitted H and hrms agree with the map's within the
# two fits' errors added in quadrature (over seeds 1-8 the largest
# deviation was 0.45 of that: the twin has exact amplitudes and its own
# error is small).
surfgen -q -n 128 -L 10 -H 0.7 --lambda-r 2.5 --rolloff --rms-height 0.05 \
    --gaussian-amplitudes --seed 4 -o twin-src.surf
surfwarp -q --unit um -o um.nc twin-src.surf
surfstat -q --fit -o umfit.tsv um.nc
check "the fit table's unit is the map's (um)" [ "$(col umfit.tsv unit)" = um ]
surfstat -q --fit --json -o umfit.json um.nc
check "... in JSON too" grep -q '"unit": "um"' umfit.json
surfgen -q --like umfit.tsv --seed 9 -o twin.surf
check "the twin's header says um" grep -aq '^unit = um$' twin.surf
check_rel "... and lx = 10 (um)" "$(surfstat -q twin.surf | col /dev/stdin lx)" 10 0
surfstat -q --fit -o twinfit.tsv twin.surf
# agree DESC COLUMN: twin and map within their combined error
agree() {
	check_range "$1" "$(col twinfit.tsv "$2")" \
	    "$(awk -v a="$(col umfit.tsv "$2")" -v e="$(col umfit.tsv "$2"_err)" -v f="$(col twinfit.tsv "$2"_err)" 'BEGIN { printf "%.17g", a - sqrt(e * e + f * f) }')" \
	    "$(awk -v a="$(col umfit.tsv "$2")" -v e="$(col umfit.tsv "$2"_err)" -v f="$(col twinfit.tsv "$2"_err)" 'BEGIN { printf "%.17g", a + sqrt(e * e + f * f) }')"
}
agree "the twin's H is the map's within the fits' errors" H
agree "the twin's hrms (um) is the map's within the fits' errors" hrms
surfgen -q --like um.nc --seed 9 -o twin2.surf
check "--like the map itself: the twin is in um too" grep -aq '^unit = um$' twin2.surf
# A map in metres (x3p stores metres): a twin in metres.
surfwarp -q -o m.x3p um.nc
surfgen -q --like m.x3p --seed 9 -o twin-m.surf
check "--like an x3p map: the twin is in m" grep -aq '^unit = m$' twin-m.surf
check_rel "... lx = 1e-5 (m)" "$(surfstat -q twin-m.surf | col /dev/stdin lx)" 1e-5 1e-15
sed '2s/	um	/	V	/' umfit.tsv >badunit.tsv
check_status "a fit table whose unit is not a length: exit 1" 1 surfgen -q --like badunit.tsv
check "... naming the unit" grep -q "unit 'V' is not a length unit" "$T_TMP/stderr"
# A unitless fit (surfgen's own surfaces) makes a unitless twin.
surfstat -q --fit -o nofit.tsv twin-src.surf
check "a unitless map's fit has no unit column" [ "$(col nofit.tsv unit)" = missing-column-unit ]
surfgen -q --like nofit.tsv --seed 9 -o twin-none.surf
check "... and its twin no unit" sh -c '! grep -aq "^unit = " twin-none.surf'

# --- README's measured-data example on a real file -----------------------------
# top-1.top (tests/data/top-1.README): 256^2 AFM map, 600 nm scan, read
# through Gwyddion.  --min-wavelength 0.05L is 5% of the scan; a bare
# 0.05 is 5 cm in the map's metres, which no wavelength of it is below.
if command -v gwyddion >/dev/null 2>&1; then
	surfwarp -q --detrend plane --fill -o lev.surf "$RC_TOP/tests/data/top-1.top"
	surfstat --fit --min-wavelength 0.05L -o fit.tsv lev.surf 2>warn.txt
	check "README: surfstat --fit --min-wavelength 0.05L on a real map" [ -s fit.tsv ]
	check "... H inside (0, 1), no warning" sh -c "[ ! -s warn.txt ] && awk -v h=$(col fit.tsv H) 'BEGIN { exit !(h > 0 && h < 1) }'"
	surfstat -q --fit --min-wavelength 30nm -o fit30.tsv lev.surf
	check "--min-wavelength 30nm is 0.05L of the 600 nm scan" [ "$(col fit30.tsv H)" = "$(col fit.tsv H)" ]
	surfgen -q --like fit.tsv -n 1024 --seed 7 -o twin.surf
	check "README: surfgen --like takes the fit" grep -aq '^unit = m$' twin.surf
	check_status "--min-wavelength 0.05 (metres) on a 600 nm scan: exit 1" 1 surfstat -q --fit --min-wavelength 0.05 lev.surf
	check "... saying it is not below the scan and how to give it" grep -q "0.05 m is not below the scan's length L = 6e-07 m.*0.05L.*5um" "$T_TMP/stderr"
	# the whole range is not one power law: the warning says where and
	# names a range that is; that range then fits without a warning
	surfstat --fit -o full.tsv lev.surf 2>warn.txt
	check "full range: the warning says C(q) is not self-affine and where" grep -q "C(q) is not self-affine on the range fitted, q = .* (wavelengths 9.41 nm to 600 nm): .*below q = .*above" warn.txt
	try=$(sed -n 's/.*try \(--min-wavelength [0-9.e+-]*L\).*/\1/p' warn.txt)
	check "... and names a range to try ($try)" [ -n "$try" ]
	surfstat --fit $try -o try.tsv lev.surf 2>warn.txt
	check "... which fits without a warning" [ ! -s warn.txt ]
else
	skip 11 "no gwyddion: README's example on a real file (apt-get install gwyddion)"
fi
check_status "--min-wavelength 5um on a unitless map: exit 1" 1 surfstat -q --fit --min-wavelength 5um twin-src.surf
check "... saying it has no length unit" grep -q "the map has no length unit; give the wavelength as a fraction of the scan" "$T_TMP/stderr"
check_status "--min-wavelength 5x: usage error" 2 surfstat -q --fit --min-wavelength 5x twin-src.surf
surfstat -q --fit -o fit-l.tsv twin-src.surf
awk -F '\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "H") c = i } NR == 2 { $c = 1.3 } { print }' OFS='\t' fit-l.tsv >steep.tsv
check_status "surfgen --like a fit with H = 1.3: exit 1" 1 surfgen -q --like steep.tsv
check "... saying why and what to do" grep -q "the fit's H = 1.3 is outside 0 < H < 1.*fit a narrower one (surfstat --fit --min-wavelength" "$T_TMP/stderr"

# --- periodicity --------------------------------------------------------------
surfgen -q -n 64 --seed 9 -o rough.surf
surfstat rough.surf >/dev/null 2>warn.txt
check "a surfgen surface gives no wrap-around warning" [ ! -s warn.txt ]
gfmd-solve -q -j 1 -p 0.1 rough.surf >/dev/null 2>warn.txt
check "... nor in gfmd-solve" [ ! -s warn.txt ]
# A tilted plane with noise (a measurement not levelled), as plain text:
# periodic by the format's rule, so the tools warn and name the option.
awk 'BEGIN { srand(4); for (j = 0; j < 32; j++) { for (i = 0; i < 32; i++)
	printf "%s%.17g", (i ? " " : ""), 0.01 * i + 0.003 * j + 0.005 * (rand() - 0.5); print "" } }' >tilt.txt
surfstat tilt.txt >/dev/null 2>warn.txt
check "surfstat warns on a tilted map" grep -q "tilt.txt: read as periodic (the file's flag or its format's rule).*--no-periodic" warn.txt
check "... once" [ "$(wc -l <warn.txt)" -eq 1 ]
check "... and advises levelling, which helps on a tilted map" grep -q "it is tilted: levelled (surfwarp --detrend plane) the ratio is" warn.txt
gfmd-solve -q -j 1 -p 0.1 tilt.txt >/dev/null 2>warn.txt
check "gfmd-solve warns on a tilted map" grep -q "tilt.txt: read as periodic.*--no-periodic" warn.txt
surfstat --periodic tilt.txt >/dev/null 2>warn.txt
check "--periodic given: the warning names it" grep -q "read as periodic (--periodic).*leave out --periodic" warn.txt
surfstat --no-periodic tilt.txt >/dev/null 2>warn.txt
check "--no-periodic: a patch, and the warning says what takes it as a period" grep -q "a patch (not periodic), but the spectral derivatives (gbar, rms_laplacian, nayak, phi1..phi9) take it as one period" warn.txt
check "... without naming options the user did not give" sh -c '! grep -q -e "--periodic\|--boundary" warn.txt'
# A levelled patch whose edges do not meet (a crop of a periodic surface):
# levelling is not advised again, the ways around the wrap are.
surfwarp -q --crop 0:40,0:40 --detrend plane -o crop.surf rough.surf
surfstat crop.surf >/dev/null 2>warn.txt
check "a levelled patch: the warning says levelling does not help" grep -q "levelling does not help (levelled by a plane, [0-9.]*): its edges do not meet" warn.txt
check "... and names --fd and --iso" grep -q -- "--fd takes the derivatives without the wrap.*--iso uses the patch alone" warn.txt
check "... and does not advise surfwarp --detrend" sh -c '! grep -q "surfwarp --detrend" warn.txt'
gfmd-solve -q -j 1 -p 0.1 --boundary periodic crop.surf >/dev/null 2>warn.txt
check "gfmd-solve --boundary periodic on a patch: names the option given" grep -q "but --boundary periodic solves it as one period.*Leave out --boundary periodic" warn.txt
surfwarp -q -w 0 --no-periodic -o tilt.surf tilt.txt
check ".surf keeps periodic = 0" grep -aq '^periodic = 0' tilt.surf
surfwarp -q -w 0 -o tilt.gsf tilt.surf
surfwarp -q -w 0 -o back.txt tilt.gsf
check ".gsf and .txt keep it" grep -q '^# periodic = 0' back.txt

# --- missing points -------------------------------------------------------------
printf '1 2 3\n4 nan 6\n7 8 9\n' >holes.txt
check_status "surfstat refuses missing points" 1 surfstat -q holes.txt
check "... naming surfwarp --fill" grep -q "holes.txt: 1 of 9 points are missing (NaN); surfstat needs every point: fill them first with surfwarp --fill" "$T_TMP/stderr"
check_status "gfmd-solve refuses missing points" 1 gfmd-solve -q -j 1 -p 0.1 holes.txt
check "... naming surfwarp --fill" grep -q "surfwarp --fill" "$T_TMP/stderr"

# --- columns --------------------------------------------------------------------
awk 'BEGIN { for (k = 0; k < 50; k++) printf "%.6g %.17g\n", 0.02 * k, sin(k / 3) }' >profile.txt
surfstat -q profile.txt >p.tsv
check "an x-z profile of 50 points is a 50 x 1 grid" [ "$(col p.tsv nx) $(col p.tsv ny)" = "50 1" ]
check_rel "... of length 50 dx" "$(col p.tsv lx)" 1 1e-12
awk 'BEGIN { for (k = 0; k < 50; k++) printf "%.6g %.17g\n", 0.02 * k * k, k }' >nonuniform.txt
check_status "a non-uniform profile is refused where a grid is needed" 1 surfwarp -q -o nu.surf nonuniform.txt
check "... saying why" grep -q "x is not uniformly spaced" "$T_TMP/stderr"

# --- numpy ----------------------------------------------------------------------
if [ -n "$PY" ]; then
	# a[j, i] = 100 j + i, shape (ny, nx) = (3, 4), in several dtypes and
	# orders; and its transpose, shape (nx, ny), read with --npy-order xy.
	"$PY" -c '
import numpy as np
a = np.array([[100 * j + i for i in range(4)] for j in range(3)], dtype=float)
np.save("c8.npy", a)
np.save("c4.npy", a.astype("<f4"))
np.save("b8.npy", a.astype(">f8"))
np.save("f8.npy", np.asfortranarray(a))
np.save("xy.npy", a.T.copy())
np.save("xyf.npy", np.asfortranarray(a.T))
'
	printf '0 1 2 3\n100 101 102 103\n200 201 202 203\n' >want.txt
	for f in c8 c4 b8 f8; do
		surfwarp -q -w 0 -o "$f.txt" "$f.npy"
		grep -v '^#' "$f.txt" >got.txt
		check "numpy $f.npy (ny, nx) read as a[j, i]" cmp -s want.txt got.txt
	done
	for f in xy xyf; do
		surfwarp -q -w 0 --npy-order xy -o "$f.txt" "$f.npy"
		grep -v '^#' "$f.txt" >got.txt
		check "numpy $f.npy (nx, ny) with --npy-order xy" cmp -s want.txt got.txt
	done
	surfstat --channels --npy-order xy xy.npy >ch.tsv
	check "--channels honours --npy-order xy: nx 4, ny 3" \
	    [ "$(awk -F '\t' 'NR == 2 { print $3 " " $4 }' ch.tsv)" = "4 3" ]
	"$PY" -c '
import numpy as np
a = np.ones((4, 4)); a[1, 2] = np.nan
np.save("nan.npy", a)
'
	check_status "a NaN in a numpy array is a missing point" 1 surfstat -q nan.npy
	check "... 1 of 16" grep -q "1 of 16 points are missing" "$T_TMP/stderr"
else
	skip 9 "no python3 with numpy: arrays numpy writes (apt-get install python3-numpy)"
fi

summary
