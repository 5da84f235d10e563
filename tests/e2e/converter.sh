# SPDX-License-Identifier: GPL-3.0-or-later
# converter.sh - Gwyddion's converter as a reader: a text-headed
# instrument file our text reader refuses (WSxM .stp) reaches Gwyddion
# and reads as Gwyddion's own .gwy of it; the message of a file nobody
# reads names the readers tried; a unitless channel is no height unless
# --z-unit says so.  Security: a file never makes a tool read another
# one (NRRD with a detached 'data file' naming /etc/passwd, a FIFO or
# /dev/zero is refused, quickly); the conversion has a time limit; a
# SIGTERM during it leaves no temporary directory.  The slow converter
# is a script named by RC_GWYDDION.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
mkdir -p spool
export TMPDIR=$T_TMP/spool

# grid FILE: the grid as text, without its history line
grid() { surfwarp -q "$1" -o grid.txt 2>/dev/null && grep -v "^# history" grid.txt; }

# A binary NRRD (a NUL byte makes it no text) whose data are another file.
detached() {
	printf 'NRRD0004\ntype: uint8\ndimension: 2\nsizes: 16 4\nencoding: raw\ndata file: %s\n\n\0' "$1"
}
detached /etc/passwd > passwd.nrrd
# The same as text (no NUL): it reached Gwyddion only through the text
# reader's refusal.
detached /etc/passwd | tr -d '\000' > passwd-text.nrrd
# Gwyddion also takes the key in other case and spacing.
detached /etc/passwd | sed 's/^data file:/Data File :/' > spaced.nrrd
mkfifo fifo
detached "$T_TMP/fifo" > fifo.nrrd
printf 'NRRD0004\ntype: double\ndimension: 2\nsizes: 100000 100000\nencoding: raw\ndatafile: /dev/zero\n\n\0' > zero.nrrd
for f in passwd.nrrd passwd-text.nrrd spaced.nrrd fifo.nrrd zero.nrrd; do
	rm -f out.txt
	check_status "$f: refused" 1 surfwarp -q "$f" -o out.txt
	check "$f: the message says why" grep -q "detached data file" "$T_TMP/stderr"
	check "$f: nothing written" [ ! -e out.txt ]
done
check "no temporary directory left" [ -z "$(ls spool)" ]

# A slow converter is stopped after RC_GWYDDION_TIMEOUT seconds.
printf '#!/bin/sh\nsleep 60\n' > slow.sh
chmod +x slow.sh
head -c 64 /dev/urandom > noise.bin
printf '\0' >> noise.bin
RC_GWYDDION=$T_TMP/slow.sh RC_GWYDDION_TIMEOUT=0.5 check_status \
    "a converter past its time limit: exit 1" 1 surfstat noise.bin
check "the message says it took too long" grep -q "took longer than 0.5 s" "$T_TMP/stderr"
check "no temporary directory left after the timeout" [ -z "$(ls spool)" ]

# SIGTERM during the conversion: the tool ends, its directory is removed.
RC_GWYDDION=$T_TMP/slow.sh surfstat noise.bin > /dev/null 2>&1 &
pid=$!
n=0
while [ -z "$(ls spool)" ] && [ "$n" -lt 100 ]; do sleep 0.1; n=$((n + 1)); done
check "the conversion's directory exists while it runs" [ -n "$(ls spool)" ]
kill -TERM "$pid"
wait "$pid"
st=$?
check "SIGTERM ends the tool (exit $st)" [ "$st" -eq 143 ]
check "no temporary directory left after SIGTERM" [ -z "$(ls spool)" ]

if command -v gwyddion >/dev/null 2>&1; then
	# A WSxM image: a text header (which the text reader refuses), then
	# 4 x 3 doubles; Gwyddion reads it.
	/usr/bin/python3 - <<'PY'
import struct
nx, ny = 4, 3
body = ("[Control]\r\n\r\n    X Amplitude: 8 nm\r\n    Y Amplitude: 6 nm\r\n\r\n"
        "[General Info]\r\n\r\n    Image Data Type: double\r\n    Number of columns: %d\r\n"
        "    Number of rows: %d\r\n    Z Amplitude: 4 nm\r\n\r\n[Header end]\r\n" % (nx, ny))
def hdr(size):
    return "WSxM file copyright UAM\r\nSxM Image file\r\nImage header size: %d\r\n\r\n" % size + body
size = len(hdr(len(hdr(0))))
vals = [float((k * 7) % 5 - 2) for k in range(nx * ny)]
open("w.stp", "wb").write(hdr(size).encode() + struct.pack("<%dd" % (nx * ny), *vals))
PY
	gwyddion --convert-to-gwy=w.gwy w.stp
	check "WSxM (text header) reads through Gwyddion" [ "$(grid w.stp)" = "$(grid w.gwy)" ]
	check "WSxM: 4 x 3 points over 8 nm x 6 nm" [ "$(surfstat --channels w.stp | awk -F'\t' 'NR == 2 { print $3, $4, $5, $6, $7 }')" = "4 3 7.999999999999999e-09 5.999999999999999e-09 m" ]
	check "no temporary directory left" [ -z "$(ls spool)" ]
	printf 'This is no surface\n' > words.txt
	check_status "text nobody reads: exit 1" 1 surfstat words.txt
	check "the message names the text reader" grep -q "(read as text)" "$T_TMP/stderr"
	check "the message names Gwyddion's converter" grep -q "Gwyddion's converter: Gwyddion does not read it either" "$T_TMP/stderr"
	RC_GWYDDION=/nonexistent/gwyddion check_status "without Gwyddion: exit 1" 1 surfstat words.txt
	check "without Gwyddion: the package is named" grep -q "Debian package gwyddion" "$T_TMP/stderr"

	# NRRD with lateral units and none for its values: unitless values.
	/usr/bin/python3 - <<'PY'
import struct
open("u.nrrd", "wb").write(b'NRRD0004\ntype: double\ndimension: 2\nsizes: 5 3\nendian: little\n'
    b'encoding: raw\nspacings: 2e-07 3e-07\nunits: "m" "m"\n\n' + struct.pack("<15d", *range(15)))
PY
	check "a unitless channel lists z_unit 1" [ "$(surfstat --channels u.nrrd | awk -F'\t' 'NR == 2 { print $8 }')" = 1 ]
	check_status "a unitless channel is no height: exit 1" 1 surfstat u.nrrd
	check "the message says unitless and --z-unit" grep -q "values are unitless.*--z-unit" "$T_TMP/stderr"
	check "with --z-unit nm it is read in nm (hrms of 0..14: sqrt(56/3) nm)" \
	    [ "$(surfstat -q --z-unit nm u.nrrd | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i } NR == 2 { printf "%.6e", $c["hrms"] }')" = "$(awk 'BEGIN { printf "%.6e", sqrt(56 / 3) * 1e-9 }')" ]
else
	skip 11 "gwyddion not installed: the converter's reading tests (Debian package gwyddion)"
fi
summary
