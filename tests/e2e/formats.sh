# SPDX-License-Identifier: GPL-3.0-or-later
# formats.sh - the measured-data formats against real clients: Gwyddion
# opens the x3p we write and its .gwy comes back as our grid; Gwyddion's
# own .gwy files (one and two channels) read with the right channel, size
# and units; a vendor format (NRRD, which Gwyddion reads and we do not)
# opens through Gwyddion from a path and from a pipe, leaving no temporary
# file; without Gwyddion the message names the package; the netCDF
# library's ncgen writes a file in the contact.engineering convention
# that we read, and ncdump shows ours has that convention's layout; the
# titles of single-channel files (GSF Title, Gwyddion's '# Channel:');
# a contact.engineering container (a zip, no x3p) refused by name.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
mkdir -p spool
export TMPDIR=$T_TMP/spool

# stats FILE [OPTIONS]: nx ny lx ly mean hrms hmin hmax, to 17 digits
stats() {
	f=$1; shift
	surfstat "$@" "$f" | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		{ print $c["nx"], $c["ny"], $c["lx"], $c["ly"], $c["mean"], $c["hrms"], $c["hmin"], $c["hmax"] }'
}
# chan FILE N COLUMN: a column of surfstat --channels
chan() {
	surfstat --channels "$1" | awk -F'\t' -v n="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		NR == n + 1 { print $c[name] }'
}

surfgen -q -n 24x16 -L 3e-6x2e-6 --seed 5 -o a.x3p
surfgen -q -n 24x16 -L 3e-6x2e-6 --seed 5 -o a.nc
surfgen -q -n 24x16 -L 3e-6x2e-6 --seed 5 -o a.surf
want=$(stats a.surf)
check "x3p read back: same grid as .surf" [ "$(stats a.x3p)" = "$want" ]
check "nc read back: same grid as .surf" [ "$(stats a.nc)" = "$want" ]
# ncdump: the contact.engineering layout
if command -v ncdump >/dev/null 2>&1; then
	ncdump -h a.nc > a.cdl
	check "nc: heights(x, y)" grep -q 'double heights(x, y)' a.cdl
	check "nc: x:length" grep -q 'x:length = 3\.*e-06' a.cdl
	check "nc: y:periodic (surfgen: periodic)" grep -q 'y:periodic = 1' a.cdl
else
	skip 3 "ncdump not installed: the netCDF layout (apt-get install netcdf-bin)"
fi

if command -v gwyddion >/dev/null 2>&1 && command -v python3 >/dev/null 2>&1; then
	# Gwyddion as a client of our x3p.
	check "gwyddion converts our x3p" gwyddion --convert-to-gwy=a.gwy a.x3p
	check "x3p via Gwyddion's .gwy: same grid" [ "$(stats a.gwy)" = "$want" ]
	check "x3p via Gwyddion: lateral unit m" [ "$(chan a.gwy 1 unit)" = m ]
	check "x3p via Gwyddion: height unit m" [ "$(chan a.gwy 1 z_unit)" = m ]

	# Missing points: an x3p with a validity file (point 4 invalid), as
	# the standard lays it out; Gwyddion turns it into a mask, which we
	# read back as missing points.
	python3 - <<'PY'
import hashlib, struct, zipfile
nx, ny = 4, 3
data = struct.pack("<12d", *[1e-9 * k for k in range(12)])
valid = bytes([0xEF, 0x0F])
xml = """<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
<Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>
<CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-06</Increment><Offset>0</Offset></CX>
<CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2e-06</Increment><Offset>0</Offset></CY>
<CZ><AxisType>A</AxisType><DataType>D</DataType><Increment>1</Increment><Offset>0</Offset></CZ>
</Axes></Record1>
<Record3><MatrixDimension><SizeX>4</SizeX><SizeY>3</SizeY><SizeZ>1</SizeZ></MatrixDimension>
<DataLink><PointDataLink>bindata/data.bin</PointDataLink><MD5ChecksumPointData>%s</MD5ChecksumPointData>
<ValidPointsLink>bindata/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>%s</MD5ChecksumValidPoints></DataLink></Record3>
</p:ISO5436_2>
""" % (hashlib.md5(data).hexdigest(), hashlib.md5(valid).hexdigest())
with zipfile.ZipFile("m.x3p", "w") as z:
    z.writestr("main.xml", xml)
    z.writestr("bindata/data.bin", data)
    z.writestr("bindata/valid.bin", valid)
PY
	check "x3p validity file: a mask" [ "$(chan m.x3p 1 mask)" = yes ]
	surfwarp -o m.txt m.x3p
	check "x3p validity bits: least significant first (point 4 = row 1, x 0)" \
	    [ "$(grep -v '^#' m.txt | awk 'NR == 2 { print $1 }')" = nan ]
	check "x3p: size from the increments" [ "$(chan m.x3p 1 lx) $(chan m.x3p 1 ly)" = "4e-06 6e-06" ]
	check "gwyddion converts the masked x3p" gwyddion --convert-to-gwy=m.gwy m.x3p
	check "masked x3p via Gwyddion: still a mask" [ "$(chan m.gwy 1 mask)" = yes ]

	# Two channels: Gwyddion merges two GSF files into one .gwy.  The
	# first is a phase map (ZUnits deg); the default is the height.
	python3 - <<'PY'
import struct
def gsf(path, zunit, scale):
    nx, ny = 6, 4
    head = ("Gwyddion Simple Field 1.0\nXRes = %d\nYRes = %d\nXReal = 6e-06\n"
            "YReal = 4e-06\nXYUnits = m\nZUnits = %s\nTitle = %s\n" % (nx, ny, zunit, zunit))
    b = head.encode()
    b += b"\0" * (4 - len(b) % 4)
    b += struct.pack("<%df" % (nx * ny), *[scale * ((k * 5) % 11 - 5) for k in range(nx * ny)])
    open(path, "wb").write(b)
gsf("phase.gsf", "deg", 0.5)
gsf("height.gsf", "m", 1e-9)
PY
	check "gwyddion merges two GSF" gwyddion --convert-to-gwy=two.gwy phase.gsf height.gsf
	check "two channels listed" [ "$(surfstat --channels two.gwy | wc -l)" -eq 3 ]
	check "channel 1 is in deg" [ "$(chan two.gwy 1 z_unit)" = deg ]
	check "channel 2 is in m" [ "$(chan two.gwy 2 z_unit)" = m ]
	hgt=$(stats height.gsf)
	check "default channel: the first length (2)" [ "$(stats two.gwy)" = "$hgt" ]
	check "--channel 2 is the height" [ "$(stats two.gwy --channel 2)" = "$hgt" ]
	check "--channel 1 is the phase" [ "$(stats two.gwy --channel 1)" = "$(stats phase.gsf)" ]
	check_status "--channel 3: no such channel" 1 surfstat --channel 3 two.gwy
	check "the message says how many there are" grep -q 'no channel 3: the file has 2' "$T_TMP/stderr"

	# A vendor format we do not read: NRRD (text header, raw doubles).
	python3 - <<'PY'
import struct
nx, ny = 5, 3
v = [0.001 * (k * k % 7) - 0.002 for k in range(nx * ny)]
open("v.nrrd", "wb").write(b"NRRD0004\ntype: double\ndimension: 2\nsizes: 5 3\n"
    b"endian: little\nencoding: raw\nspacings: 2e-07 3e-07\n\n" + struct.pack("<15d", *v))
open("v.txt", "w").write("\n".join(" ".join(repr(v[j * nx + i]) for i in range(nx)) for j in range(ny)) + "\n")
PY
	txt=$(stats v.txt | cut -d' ' -f5-)
	check "NRRD through Gwyddion: the values" [ "$(stats v.nrrd | cut -d' ' -f5-)" = "$txt" ]
	check "NRRD through Gwyddion: the size" [ "$(stats v.nrrd | cut -d' ' -f1-4)" = "5 3 1e-06 9e-07" ]
	check "NRRD from a pipe" [ "$(cat v.nrrd | surfstat | wc -l)" -eq 2 ]
	check "no temporary file left" [ -z "$(ls spool)" ]
	RC_GWYDDION=/nonexistent/gwyddion check_status "without Gwyddion: exit 1" 1 surfstat v.nrrd
	check "without Gwyddion: names the package" grep -q 'Debian package gwyddion' "$T_TMP/stderr"
else
	skip 24 "gwyddion or python3 not installed: the Gwyddion client tests (apt-get install gwyddion python3)"
fi

# netCDF written by the netCDF library (ncgen) in SurfaceTopography's
# convention: heights(x, y), so the file's rows are our columns.
cat > st.cdl <<'CDL'
netcdf st {
dimensions:
	x = 3 ;
	y = 2 ;
variables:
	double x(x) ;
		x:length = 6. ;
		x:periodic = 1 ;
		x:length_unit = "um" ;
	double y(y) ;
		y:length = 4. ;
		y:periodic = 1 ;
		y:length_unit = "um" ;
	double heights(x, y) ;
data:
 heights = 1, 2, 3, 4, 5, 6 ;
}
CDL
if command -v ncgen >/dev/null 2>&1; then
	ncgen -o st.nc st.cdl
	check "ncgen file: the grid (transposed: heights[i][j] at x=i)" \
	    [ "$(stats st.nc | cut -d' ' -f1-4,7,8)" = "3 2 6 4 1 6" ]
	check "ncgen file: unit um" [ "$(chan st.nc 1 unit)" = um ]
	surfwarp -o got.txt st.nc
	check "ncgen file: values where they belong (rows y, x along)" \
	    [ "$(grep -v '^#' got.txt | tr '\n' ' ')" = "1 3 5 2 4 6 " ]
else
	skip 3 "ncgen not installed: netCDF written by the netCDF library (apt-get install netcdf-bin)"
fi

# Titles of single-channel files: a GSF's Title field and the '# Channel:'
# line of Gwyddion's text export, as --channels lists them and
# --channel NAME picks them; a grid converted from them keeps the title.
if command -v python3 >/dev/null 2>&1; then
	python3 - <<'PY'
import struct
b = ("Gwyddion Simple Field 1.0\nXRes = 2\nYRes = 2\nXReal = 2e-06\n"
     "YReal = 2e-06\nXYUnits = m\nZUnits = m\nTitle = Height (fwd)\n").encode()
b += b"\0" * (4 - len(b) % 4) + struct.pack("<4f", 1e-9, 2e-9, 3e-9, 4e-9)
open("titled.gsf", "wb").write(b)
PY
	check "GSF Title is the channel's title" [ "$(chan titled.gsf 1 title)" = "Height (fwd)" ]
	check_status "--channel NAME picks a GSF by its Title" 0 surfstat --channel 'height (FWD)' titled.gsf
else
	skip 2 "python3 not installed: a GSF with a Title (apt-get install python3)"
fi
printf '# Channel: Topography\n# Width: 2.000 um\n# Height: 2.000 um\n# Value units: m\n1e-9 2e-9\n3e-9 4e-9\n' > titled.txt
check "Gwyddion text export: '# Channel:' is the title" [ "$(chan titled.txt 1 title)" = Topography ]
check_status "--channel NAME: another title is refused" 1 surfstat --channel Phase titled.txt
surfwarp -o titled.surf titled.txt
check "a .surf converted from the export keeps the title" [ "$(chan titled.surf 1 title)" = Topography ]
check "a grid without a title lists '-'" [ "$(chan a.surf 1 title)" = - ]

# A zip that is no x3p: contact.engineering's container (meta.yml) of
# two measurements, one without units (meta.yml's nm) and one x-z
# profile not uniformly spaced (read with --uniform, by surfstat as it
# is); one with no
# measurement is refused saying so (tests/test_zipped.c has the rest).
if command -v python3 >/dev/null 2>&1; then
	printf '0 1\n1 2\n2 3\n3 5\n' >m1.txt
	printf '0 1\n1 2\n3 3\n4 5\n' >m2.txt
	printf 'surfaces:\n- topographies:\n  - name: flat one\n    datafile: {original: m1.txt}\n    unit: nm\n  - name: uneven\n    datafile: {original: m2.txt}\n    unit: um\n' >meta.yml
	python3 -c 'import zipfile; z = zipfile.ZipFile("ce2.zip", "w"); [z.write(f) for f in ("meta.yml", "m1.txt", "m2.txt")]; z.close()'
	check_status "a container with a non-uniform profile: surfwarp refuses it (exit 1)" 1 surfwarp -q --channel uneven -o un.txt ce2.zip
	check "... naming the measurement and --uniform" grep -q "'uneven' (m2.txt): .*--uniform" "$T_TMP/stderr"
	check "surfstat lists it as it is: 4 points over the x span, 4 um" [ "$(surfstat --channels ce2.zip | awk -F'\t' 'NR == 3 { print $3, $5, $7 }')" = "4 4 um" ]
	surfstat --uniform --channels ce2.zip >ce2.tsv
	check "--channels lists the two measurements by name" [ "$(cut -f2 ce2.tsv | tr '\n' ,)" = "title,flat one,uneven," ]
	check "... in meta.yml's units" [ "$(cut -f7 ce2.tsv | tr '\n' ,)" = "unit,nm,um," ]
	check_status "--channel NAME reads one" 0 surfwarp -q --uniform --channel uneven -o un.txt ce2.zip
	check "... its 4 points resampled at x 0 4/3 8/3 4: 1, 2 + 1/6, 2 + 5/6, 5" [ "$(grep -v '^#' un.txt | tr '\n' ' ')" = "1 2.1666666666666665 2.833333333333333 5 " ]
	python3 -c 'import zipfile; z = zipfile.ZipFile("ce.zip", "w"); z.writestr("meta.yml", "datasets: []\n"); z.close()'
	check_status "a container listing no measurement: exit 1" 1 surfstat ce.zip
	check "the message says so" grep -q "contact.engineering container: meta.yml lists no topographies" "$T_TMP/stderr"
else
	skip 9 "python3 not installed: containers zipped by python's zipfile (apt-get install python3)"
fi
summary
