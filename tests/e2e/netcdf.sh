# SPDX-License-Identifier: GPL-3.0-or-later
# netcdf.sh - netCDF in SurfaceTopography's layout (the library behind
# contact.engineering), files written by the netCDF library's ncgen: the
# attribute unit on x, y and heights (a 5 nm patch with --unit m is 5e-9
# m, not 5), length_unit of older files, the mask variable (a masked 999
# is missing), the 1D line-scan layout, netCDF's default fill (a point
# never written is missing), character heights refused by name; and what
# we write carries, by ncdump, what SurfaceTopography reads back: unit on
# x, y and heights, the periodic flag, the sizes, NaN and mask = 1 at
# missing points, a line scan in the 1D layout.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

if ! command -v ncgen >/dev/null 2>&1 || ! command -v ncdump >/dev/null 2>&1; then
	skip 39 "ncgen/ncdump not installed (Debian package netcdf-bin)"
	summary
	exit 0
fi

# col FILE NAME: column NAME of the first row of a table
col_of() {
	awk -F'\t' -v name="$2" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		NR == 2 { print $c[name] }' "$1"
}
# values FILE: a text grid's values, one line
values() { grep -v '^#' "$1" | tr '\n' ' ' | sed 's/ *$//'; }

# 2 x 2 map of 5 nm x 5 nm, heights +-1 nm (hrms 1 nm), unit "nm".
cat > nm.cdl <<'CDL'
netcdf nm {
dimensions:
	x = 2 ;
	y = 2 ;
variables:
	double x(x) ;
		x:length = 5. ;
		x:periodic = 0 ;
		x:unit = "nm" ;
	double y(y) ;
		y:length = 5. ;
		y:periodic = 0 ;
		y:unit = "nm" ;
	double heights(x, y) ;
		heights:unit = "nm" ;
data:
	heights = 1, -1, -1, 1 ;
}
CDL
ncgen -k nc6 -o nm.nc nm.cdl
surfstat -q --unit m nm.nc > nm.tsv 2>/dev/null
check "unit nm: lx in m is 5e-9" [ "$(col_of nm.tsv lx)" = 5e-09 ]
check "unit nm: hrms in m is 1e-9" [ "$(col_of nm.tsv hrms)" = 1e-09 ]
check "unit nm: listed as nm" [ "$(surfstat --channels nm.nc | awk -F'\t' 'NR == 2 { print $7 "," $8 }')" = nm,nm ]
# the same with length_unit only (older files)
sed 's/:unit = /:length_unit = /' nm.cdl | sed '/heights:length_unit/d' > old.cdl
ncgen -k nc6 -o old.nc old.cdl
surfstat -q --unit m old.nc > old.tsv 2>/dev/null
check "length_unit nm: hrms in m is 1e-9" [ "$(col_of old.tsv hrms)" = 1e-09 ]

# mask: the 999 at x = 1, y = 1 (file index [1][1]) is missing
cat > mask.cdl <<'CDL'
netcdf mask {
dimensions:
	x = 3 ;
	y = 2 ;
variables:
	double x(x) ;
		x:length = 6. ;
		x:unit = "um" ;
	double y(y) ;
		y:length = 4. ;
		y:unit = "um" ;
	double heights(x, y) ;
		heights:unit = "um" ;
	byte mask(x, y) ;
data:
	heights = 1, 2, 3, 999, 5, 6 ;
	mask = 0, 0, 0, 1, 0, 0 ;
}
CDL
ncgen -k nc6 -o mask.nc mask.cdl
surfwarp mask.nc -o mask.txt
check "mask: the masked 999 is missing (rows are y)" [ "$(values mask.txt)" = "1 3 5 2 nan 6" ]

# default fill: heights(1, 0) never written ('_' in CDL), no _FillValue
cat > fill.cdl <<'CDL'
netcdf fill {
dimensions:
	x = 2 ;
	y = 2 ;
variables:
	double heights(x, y) ;
data:
	heights = 1, _, 3, 4 ;
}
CDL
ncgen -k nc6 -o fill.nc fill.cdl
surfwarp fill.nc -o fill.txt
check "default fill: the point never written is missing" [ "$(values fill.txt)" = "1 3 nan 4" ]

# a line scan: heights(x) only, 4 points over 8 um, periodic
cat > line.cdl <<'CDL'
netcdf line {
dimensions:
	x = 4 ;
variables:
	double x(x) ;
		x:length = 8. ;
		x:periodic = 1 ;
		x:unit = "um" ;
	double heights(x) ;
		heights:unit = "um" ;
data:
	heights = 1, 2, 4, 1 ;
}
CDL
ncgen -k nc6 -o line.nc line.cdl
check "line scan: read as 4 x 1 over 8 um" [ "$(surfstat --channels line.nc | awk -F'\t' 'NR == 2 { print $3, $4, $5, $7 }')" = "4 1 8 um" ]
surfwarp line.nc -o line.txt
check "line scan: the heights" [ "$(values line.txt)" = "1 2 4 1" ]
check "line scan: periodic" grep -q '^# periodic = 1' line.txt

# character heights: refused by name
cat > char.cdl <<'CDL'
netcdf char {
dimensions:
	x = 2 ;
	y = 2 ;
variables:
	char heights(x, y) ;
data:
	heights = "ab", "cd" ;
}
CDL
ncgen -k nc6 -o char.nc char.cdl
check_status "character heights: exit 1" 1 surfstat char.nc
check "character heights: the message says so" grep -q "heights holds characters, not numbers" "$T_TMP/stderr"

# What we write: a map with a missing point, in nm, periodic.
surfwarp mask.nc -o m.nc
ncdump m.nc > m.cdl
for v in x y heights; do
	check "written: $v:unit = \"um\"" grep -q "^		$v:unit = \"um\" ;" m.cdl
done
check "written: x:periodic = 0" grep -q '^		x:periodic = 0 ;' m.cdl
check "written: sizes x = 3, y = 2" [ "$(grep -c -E '^	(x = 3|y = 2) ;' m.cdl)" -eq 2 ]
check "written: heights NaN at the missing point" [ "$(sed -n '/^ heights =/,/;/p' m.cdl | tr -d ' \n')" = "heights=1,2,3,NaN,5,6;" ]
check "written: mask 1 at the missing point" [ "$(sed -n '/^ mask =/,/;/p' m.cdl | tr -d ' \n')" = "mask=0,0,0,1,0,0;" ]
surfwarp m.nc -o m.txt
check "written and read back: the same values" [ "$(values m.txt)" = "$(values mask.txt)" ]
surfwarp --periodic nm.nc -o g.nc 2>/dev/null
ncdump -h g.nc > g.cdl
check "written: periodic = 1 on x and y" [ "$(grep -c ':periodic = 1 ;' g.cdl)" -eq 2 ]
check "written: no mask when nothing is missing" [ "$(grep -c 'mask' g.cdl)" -eq 0 ]
check "written: unit nm" grep -q 'x:unit = "nm"' g.cdl
# a line scan goes out in the 1D layout
surfwarp line.nc -o l2.nc
ncdump -h l2.nc > l2.cdl
check "written line scan: only dimension x" [ "$(sed -n '/^dimensions:/,/^variables:/p' l2.cdl | grep -c ' = ')" -eq 1 ]
check "written line scan: heights(x)" grep -q 'double heights(x) ;' l2.cdl
check "written line scan: x:length = 8" grep -q 'x:length = 8. ;' l2.cdl
# Data sets without heights (netCDF-4/HDF5, as multiple_data_sets.h5):
# every 1-D or 2-D numeric variable but a coordinate variable (c(c)) is
# a channel named by the variable, unitless unless an attribute unit or
# units says otherwise, of no physical size (-L or 1, as .npy).
cat > ds.cdl <<'CDL'
netcdf ds {
dimensions:
	a = 2 ;
	b = 3 ;
	c = 4 ;
	d = 2 ;
variables:
	double c(c) ;
	double data1(a, b) ;
	float data2(c, d) ;
data:
	c = 0, 1, 2, 3 ;
	data1 = 1, 2, 3, 4, 5, 6 ;
	data2 = 0.5, -1.25, 2, 0, 3.75, -0.5, 1, 0.25 ;
}
CDL
ncgen -k nc4 -o ds.h5 ds.cdl
surfstat --channels ds.h5 > ds.lst
check "data sets: two channels, c(c) is a coordinate" [ "$(sed 1d ds.lst | wc -l)" -eq 2 ]
check "data sets: data1, 2 x 3, L 1, unitless" [ "$(awk -F'\t' 'NR == 2 { print $2, $3, $4, $5, $6, $7, $8 }' ds.lst)" = "data1 2 3 1 1 - 1" ]
check "data sets: data2, 4 x 2, unitless" [ "$(awk -F'\t' 'NR == 3 { print $2, $3, $4, $8 }' ds.lst)" = "data2 4 2 1" ]
check_status "data sets: unitless values are no heights by default" 1 surfstat ds.h5
check "data sets: the refusal names --z-unit" grep -q "unitless.*--z-unit" "$T_TMP/stderr"
check_status "data sets: nor when picked" 1 surfstat --channel 2 ds.h5
# hrms = sqrt<(h - mean)^2> from the CDL's values
hrms_of() { echo "$1" | tr ',' '\n' | awk '{ h[NR] = $1; s += $1 } END { m = s / NR; for (k = 1; k <= NR; k++) q += (h[k] - m)^2; printf "%.17g\n", sqrt(q / NR) }'; }
surfwarp -q --channel 1 --z-unit nm ds.h5 -o d1.txt
check "data sets: --channel 1 --z-unit nm, the values (rows are y)" [ "$(values d1.txt)" = "1 4 2 5 3 6" ]
surfstat -q --channel data1 --z-unit nm -L 2x3 ds.h5 > d1.tsv
check_rel "data sets: data1 hrms" "$(col_of d1.tsv hrms)" "$(hrms_of 1,2,3,4,5,6)" 1e-12
check "data sets: -L 2x3 is its size" [ "$(col_of d1.tsv lx) $(col_of d1.tsv ly)" = "2 3" ]
surfwarp -q --channel data2 --z-unit um ds.h5 -o d2.txt
check "data sets: --channel data2, the float values" [ "$(values d2.txt)" = "0.5 2 3.75 1 -1.25 0 -0.5 0.25" ]
surfstat -q --channel data2 --z-unit um ds.h5 > d2.tsv
check_rel "data sets: data2 hrms" "$(col_of d2.tsv hrms)" "$(hrms_of 0.5,-1.25,2,0,3.75,-0.5,1,0.25)" 1e-12
# a unit attribute makes data2 heights: the default channel, no --z-unit
sed 's/^	float data2(c, d) ;/&\n		data2:units = "um" ;/' ds.cdl > du.cdl
ncgen -k nc4 -o du.h5 du.cdl
check "data sets: units = um listed" [ "$(surfstat --channels du.h5 | awk -F'\t' 'NR == 3 { print $8 }')" = um ]
surfstat -q du.h5 > du.tsv
check "data sets: the channel in a length unit is the default" [ "$(col_of du.tsv nx) $(col_of du.tsv ny)" = "4 2" ]
check_rel "data sets: its hrms" "$(col_of du.tsv hrms)" "$(col_of d2.tsv hrms)" 0
# HDF5 files that name other files (tests/h5links.c, compiled here
# against libhdf5, which libnetcdf-dev brings): an external link (by a
# relative or absolute name, or deep in a group), external raw storage
# and a virtual data set are refused by name before libnetcdf follows
# them, and no value of the other file (100..105, 200..205) is output;
# a soft link inside the file is allowed.
if ${CC:-cc} $(pkg-config --cflags hdf5 2>/dev/null) -o h5links \
    "$RC_TOP/tests/h5links.c" $(pkg-config --libs hdf5 2>/dev/null) \
    2>h5links.err && ./h5links "$T_TMP"; then
	for c in "extlink:an external link" "extabs:an external link" \
	    "extgroup:an external link" "extstore:stored in external files" \
	    "vds:a virtual data set"; do
		f=${c%%:*}
		check_status "HDF5 $f.h5: refused" 1 surfwarp -q --z-unit nm "$f.h5" -o "$f.txt"
		check "HDF5 $f.h5: the refusal says why" grep -q "refused: /.* is .*${c#*:}" "$T_TMP/stderr"
		check "HDF5 $f.h5: nothing written" [ ! -e "$f.txt" ]
	done
	check_status "HDF5 extgroup.h5: --channels refuses too" 1 surfstat --channels extgroup.h5
	check "HDF5: the link's path is named" grep -q "/g/deep is an external link" "$T_TMP/stderr"
	check_status "HDF5 softlink.h5: a soft link inside the file is read" 0 surfwarp -q --z-unit nm softlink.h5 -o soft.txt
	check "HDF5 softlink.h5: its own values, heights(x, y)" [ "$(values soft.txt)" = "1 4 2 5 3 6" ]
else
	skip 18 "cannot compile tests/h5links.c against libhdf5 (libhdf5-dev): $(head -1 h5links.err)"
fi
summary
