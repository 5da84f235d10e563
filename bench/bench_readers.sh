#!/bin/sh
# bench_readers.sh - how long opening a file takes against reading its
# bytes: each format's reader (surfstat --channels, which reads every
# channel and computes nothing) on one 2048^2 surface, against
# `cat FILE > /dev/null`, best of BENCH_REPEAT (default 3) runs each.
# Prints format, file bytes, reader seconds, cat seconds, their ratio.
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

now() { date +%s.%N; }
# best CMD...: the shortest wall time of REPEAT runs, seconds
best() {
	b=""
	r=0
	while [ "$r" -lt "$REPEAT" ]; do
		t0=$(now); "$@" >/dev/null 2>&1; t1=$(now)
		b=$(awk -v a="$t0" -v z="$t1" -v b="$b" 'BEGIN { d = z - a; print (b == "" || d < b) ? d : b }')
		r=$((r + 1))
	done
	echo "$b"
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
printf 'format\tbytes\tread_s\tcat_s\tratio\n'
for f in $formats; do
	file=$TMP/s.$f
	rs=$(best "$RC_BIN/surfstat" --channels "$file")
	cs=$(best sh -c "cat '$file' > /dev/null")
	printf '%s\t%s\t%s\t%s\t%s\n' "$f" "$(wc -c < "$file")" "$rs" "$cs" \
	    "$(awk -v r="$rs" -v c="$cs" 'BEGIN { printf "%.1f", (c > 0 ? r / c : 0) }')"
done
