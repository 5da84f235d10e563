#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# bench_readers.sh - how long opening a file takes against reading its
# bytes: each format's reader (surfstat --channels, which reads every
# channel and computes nothing) on one 2048^2 surface, against
# `cat FILE > /dev/null`, best of BENCH_REPEAT (default 3) runs each.
# Prints format, file bytes, wall seconds (reader, cat, ratio) and CPU
# seconds (reader, cat, ratio).
# .gwy comes from Gwyddion (skipped without it); "vendor" is an NRRD file,
# which goes through Gwyddion's converter, so its time is Gwyddion's.
# Never fails on time.
#   RC_BIN=bin sh bench/bench_readers.sh    (BENCH_N=512 for a quick look)
set -u
: "${RC_BIN:?RC_BIN not set}"
N=${BENCH_N:-2048}
REPEAT=${BENCH_REPEAT:-3}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcread.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

# best CMD...: "WALL CPU" seconds, each the least of REPEAT runs; CPU is
# user + system time (GNU time), which a loaded machine disturbs less
# than the wall time, or "-" without /usr/bin/time.
best() {
	bw="" bc=""
	r=0
	while [ "$r" -lt "$REPEAT" ]; do
		if [ -x /usr/bin/time ]; then
			/usr/bin/time -f '%e %U %S' -o "$TMP/time" "$@" >/dev/null 2>&1
			w=$(awk '{ print $1 }' "$TMP/time")
			c=$(awk '{ print $2 + $3 }' "$TMP/time")
		else
			t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N)
			w=$(awk -v a="$t0" -v z="$t1" 'BEGIN { print z - a }')
			c=-
		fi
		bw=$(awk -v d="$w" -v b="$bw" 'BEGIN { print (b == "" || d < b) ? d : b }')
		bc=$(awk -v d="$c" -v b="$bc" 'BEGIN { print (d == "-" ? "-" : (b == "" || d < b) ? d : b) }')
		r=$((r + 1))
	done
	echo "$bw $bc"
}

"$RC_BIN/surfgen" -q -n "$N" --seed 1 -o "$TMP/s.surf"
for ext in npy gsf txt x3p nc; do
	"$RC_BIN/surfgen" -q -n "$N" --seed 1 -o "$TMP/s.$ext"
done
python3 - "$TMP" "$N" <<'PY'
import struct, sys
d, n = sys.argv[1], int(sys.argv[2])
raw = open(d + "/s.surf", "rb").read()
off = int([l for l in raw[:4096].split(b"\n") if l.startswith(b"data_offset")][0].split()[2])
data = raw[off:off + 8 * n * n]
hdr = struct.pack("<10s12s12sHH4d3B", b"bench", b"010120200000", b"010120200000",
    n, n, 1.0 / n, 1.0 / n, 1.0, -1, 0, 7, 0) if n < 65536 else None
open(d + "/s.sdf", "wb").write(b"bISO-1.0" + hdr + data)
open(d + "/s.nrrd", "wb").write(("NRRD0004\ntype: double\ndimension: 2\nsizes: %d %d\n"
    "endian: little\nencoding: raw\n\n" % (n, n)).encode() + data)
PY
formats="surf npy gsf txt x3p nc sdf"
if command -v gwyddion >/dev/null 2>&1; then
	gwyddion --convert-to-gwy="$TMP/s.gwy" "$TMP/s.gsf" >/dev/null 2>&1 &&
	    formats="$formats gwy"
	formats="$formats nrrd"
fi
printf 'format\tbytes\tread_wall_s\tcat_wall_s\twall_ratio\tread_cpu_s\tcat_cpu_s\tcpu_ratio\n'
for f in $formats; do
	file=$TMP/s.$f
	set -- $(best "$RC_BIN/surfstat" --channels "$file")
	rw=$1 rc=$2
	set -- $(best sh -c "cat '$file' > /dev/null")
	cw=$1 cc=$2
	printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$f" "$(wc -c < "$file")" \
	    "$rw" "$cw" "$(awk -v r="$rw" -v c="$cw" 'BEGIN { printf "%.1f", (c > 0 ? r / c : 0) }')" \
	    "$rc" "$cc" "$(awk -v r="$rc" -v c="$cc" 'BEGIN { printf "%.1f", (c > 0 ? r / c : 0) }')"
done
