# SPDX-License-Identifier: GPL-3.0-or-later
# Bad input everywhere: every grid reader (surfwarp, surfstat, gfmd-solve,
# surfstat --mask, gfmd-solve --init, surfwarp --carve) fed broken files,
# from a path and from a pipe; every tool fed out-of-range options; the
# contact-stats row parser fed broken tables.
#
# A broken input must give exit 1 and exactly one line on stderr, of the
# form "tool: NAME: reason" naming the input; a pre-existing output must be
# left byte for byte as it was and no temporary file may remain.  A bad
# option must give exit 2 with one line per problem (all of them at once)
# plus the "N usage problems" line, and create no output.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
D=$T_TMP/in
W=$T_TMP/work
mkdir -p "$D" "$W"
n_bad=0

surfgen -q -n 16 --seed 3 -o "$D/good.surf"
surfgen -q -n 16 --seed 3 -o "$D/good.npy"
surfgen -q -n 16 --seed 3 -o "$D/good.gsf"
surfgen -q -n 4 --seed 3 -o "$D/good.txt"
gfmd-solve -q -j 1 -p 0.1 --contact "$D/mask.surf" -o /dev/null "$D/good.surf"
surfgen -q -n 8 --seed 3 -o "$D/small.surf"
gfmd-solve -q -j 1 -p 0.1 --contact "$D/mask8.surf" -o /dev/null "$D/small.surf"

# The data of good.surf start at data_offset (a multiple of 8).
off=$(awk '/^data_offset = / { print $3; exit }' "$D/good.surf")
head_of() { head -c "$off" "$D/good.surf"; }
data_of() { tail -c +"$((off + 1))" "$D/good.surf"; }
# surf_header KEY=VALUE...: good.surf's header with keys replaced (a value
# "DELETE" drops the key), data_offset dropped so the lie is what is tested.
surf_header() {
	awk -v subs="$*" 'BEGIN { n = split(subs, s, " "); for (i = 1; i <= n; i++) {
		k = substr(s[i], 1, index(s[i], "=") - 1); v[k] = substr(s[i], index(s[i], "=") + 1) } }
		/^data_offset = / { next }
		{ k = $1 } k in v { if (v[k] != "DELETE") print k " = " v[k]; next }
		/^end_header/ { print "end_header"; exit } { print }' "$D/good.surf"
}

# --- broken grid files ------------------------------------------------------
B=$D/bad
mkdir -p "$B"
: >"$B/empty"
head -c 1000 "$D/good.surf" >"$B/truncated-data.surf"
head -c 100 "$D/good.surf" >"$B/truncated-header.surf"
head -c "$off" "$D/good.surf" >"$B/header-only.surf"
{ cat "$D/good.surf"; printf 'x'; } >"$B/trailing-byte.surf"
sed '1s/.*/#surf 2/' "$D/good.surf" >"$B/version2.surf"
sed '1s/.*/#surX 1/' "$D/good.surf" >"$B/wrong-magic.surf"
printf '\177ELF\002\001\001\000\000\000\000\000\000\000\000\000' >"$B/elf-binary"
for lie in nx=17 ny=15 nx=0 ny=-4 nx=1e3 nx=16.5 nx= \
    nx=99999999999999999999999 nx=4294967296:ny=4294967296 nx=16777217 \
    lx=-1 lx=0 lx=nan ly=inf lx=1e999 kind=wobble encoding=float32-le \
    nx=DELETE lx=DELETE; do
	name=$(printf '%s' "$lie" | tr ':=' '_-')
	{ surf_header $(printf '%s' "$lie" | tr ':' ' '); data_of; } >"$B/lie-$name.surf"
done
awk '/^data_offset = / { print "data_offset = 400"; next } { print }' "$D/good.surf" >"$B/lie-data-offset.surf"
# units and the periodic flag: a height in deg, a lateral unit that is no
# length, a flag that is neither 0 nor 1
{ surf_header | sed '/^kind = /i z_unit = deg'; data_of; } >"$B/z-unit-deg.surf"
{ surf_header | sed '/^kind = /i unit = furlong'; data_of; } >"$B/unit-furlong.surf"
{ surf_header periodic=2; data_of; } >"$B/lie-periodic-2.surf"
{ head -c 8 "$D/good.surf"; printf 'bogus line without equals\n'; tail -c +9 "$D/good.surf"; } >"$B/not-key-value.surf"
{ head -c 8 "$D/good.surf"; printf 'nx = 16\n'; tail -c +9 "$D/good.surf"; } >"$B/duplicate-key.surf"
{ head -c 8 "$D/good.surf"; printf 'ctl = \001\n'; tail -c +9 "$D/good.surf"; } >"$B/control-char.surf"
{ printf '#surf 1\n'; head -c 1100000 /dev/zero | tr '\0' 'a'; } >"$B/endless-header.surf"
# NaN and +Inf as the first value (little-endian float64).
{ head_of; printf '\000\000\000\000\000\000\370\177'; data_of | tail -c +9; } >"$B/nan.surf"
{ head_of; printf '\000\000\000\000\000\000\360\177'; data_of | tail -c +9; } >"$B/inf.surf"
# A mask with a value that is neither 0 nor 1.
moff=$(awk '/^data_offset = / { print $3; exit }' "$D/mask.surf")
{ head -c "$moff" "$D/mask.surf"; printf '\000\000\000\000\000\000\340\077'; tail -c +"$((moff + 9))" "$D/mask.surf"; } >"$B/mask-half.surf"
# npy
npy() {	# npy HEADER-DICT: version 1.0, header padded to 128 bytes, then data
	h=$1; pad=$((128 - 10 - ${#h} - 1))
	printf '\223NUMPY\001\000\166\000%s%*s\n' "$h" "$pad" ''
}
{ npy "{'descr': '<f8', 'fortran_order': False, 'shape': (16, 17), }"; tail -c 2048 "$D/good.npy"; } >"$B/npy-shape-lie.npy"
{ npy "{'descr': '<i4', 'fortran_order': False, 'shape': (16, 16), }"; tail -c 2048 "$D/good.npy"; } >"$B/npy-int.npy"
{ npy "{'descr': '<f8', 'fortran_order': False, 'shape': (0, 16), }"; } >"$B/npy-zero.npy"
{ npy "{'descr': '<f8', 'fortran_order': False, 'shape': (4294967296, 4294967296), }"; } >"$B/npy-overflow.npy"
{ npy "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2, 2), }"; head -c 64 /dev/zero; } >"$B/npy-3d.npy"
{ npy "{'descr': '<f8', 'shape': (16, 16), }"; tail -c 2048 "$D/good.npy"; } >"$B/npy-no-order.npy"
{ npy "{'descr': '<f8', 'fortran_order': False, 'shape': (16, 16"; tail -c 2048 "$D/good.npy"; } >"$B/npy-unclosed.npy"
printf '\223NUMPY\001\000\377\377' >"$B/npy-header-len.npy"
head -c 500 "$D/good.npy" >"$B/npy-truncated.npy"
# gsf: header lies
sed -e '1,/^YRes/s/^XRes = 16/XRes = 0/' "$D/good.gsf" >"$B/gsf-xres0.gsf"
sed -e '1,/^YRes/s/^XRes = 16/XRes = -16/' "$D/good.gsf" >"$B/gsf-xres-neg.gsf"
sed -e '1,/^YRes/s/^XRes = 16/XRes = 32/' "$D/good.gsf" >"$B/gsf-xres-lie.gsf"
sed -e '1,/^YReal/s/^XReal = 1/XReal = -1/' "$D/good.gsf" >"$B/gsf-xreal-neg.gsf"
head -c 400 "$D/good.gsf" >"$B/gsf-truncated.gsf"
# txt
printf '1 2 3\n4 5\n' >"$B/ragged.txt"
printf '1 2\n3 x\n' >"$B/word.txt"
printf '1 2\n3 nan\n' >"$B/nan.txt"
printf '1 2\n3 1e999\n' >"$B/huge.txt"
printf '# nx = 2\n# only comments\n' >"$B/comments-only.txt"
printf '# nx = 3\n1 2\n3 4\n' >"$B/txt-nx-lie.txt"
printf '1 \000\n3 4\n' >"$B/nul.txt"
printf '\r\n\r\n' >"$B/blank-lines.txt"
# columns that are no grid, and Gwyddion headers that contradict themselves
printf '0 1\n0.5 2\n1.7 3\n2 5\n' >"$B/xz-nonuniform.txt"
printf '0 0 1\n1 0.3 2\n0 1 3\n1 1 4\n' >"$B/xyz-scattered.txt"
printf '0 0 1\n1 0 2\n2 0 3\n0 1 4\n1 1 5\n' >"$B/xyz-incomplete.txt"
printf '# Width: 10 um\n1 2\n3 4\n' >"$B/gwy-width-only.txt"
printf '# Width: 10 um\n# Height: 2 deg\n1 2\n3 4\n' >"$B/gwy-height-deg.txt"
printf '# Width: 10 um\n# Height: 10 um\n# Value units: V\n1 2\n3 4\n' >"$B/gwy-value-volt.txt"
printf '# Width: -3 um\n# Height: 10 um\n1 2\n3 4\n' >"$B/gwy-width-negative.txt"
printf '# periodic = yes\n1 2\n3 4\n' >"$B/txt-periodic-yes.txt"
# x3p, .gwy, netCDF, SDF: broken containers, lying lengths, wrong checksums
surfgen -q -n 16 --seed 3 -o "$D/good.x3p"
surfgen -q -n 16 --seed 3 -o "$D/good.nc"
head -c 300 "$D/good.x3p" >"$B/x3p-truncated.x3p"
head -c 200 "$D/good.nc" >"$B/nc-truncated.nc"
# (python3 writes 13 broken files, 9 checks each; optional)
if ! command -v python3 >/dev/null 2>&1; then
	skip 117 "python3 not installed: 13 hand-broken x3p, gwy, nc and SDF files (apt-get install python3)"
else
python3 - "$D/good.x3p" "$B" <<'PY'
import hashlib, re, struct, sys, zipfile
good, bad = sys.argv[1], sys.argv[2]
z = zipfile.ZipFile(good)
xml, data = z.read("main.xml").decode(), z.read("bindata/data.bin")
def x3p(name, files):
    with zipfile.ZipFile(bad + "/" + name, "w") as o:
        for k, v in files.items():
            o.writestr(k, v)
def with_sum(x):
    return {"main.xml": x, "bindata/data.bin": data,
            "md5checksum.hex": hashlib.md5(x.encode()).hexdigest() + " *main.xml\n"}
x3p("x3p-no-main.x3p", {"bindata/data.bin": data})
x3p("x3p-data-checksum.x3p", with_sum(re.sub("<MD5ChecksumPointData>[0-9a-f]*<",
    "<MD5ChecksumPointData>00000000000000000000000000000000<", xml)))
x3p("x3p-main-checksum.x3p", dict(with_sum(xml), **{"md5checksum.hex": "0" * 32 + " *main.xml\n"}))
x3p("x3p-size-lie.x3p", with_sum(xml.replace("<SizeX>16<", "<SizeX>17<")))
x3p("x3p-not-xml.x3p", with_sum("<ISO5436_2><Record1>"))
x3p("x3p-no-data.x3p", {"main.xml": xml})
# .gwy: a GwyContainer with one 16x16 field, then lies about its lengths
def obj(t, body): return t.encode() + b"\0" + struct.pack("<I", len(body)) + body
def comp(n, t, v): return n.encode() + b"\0" + t.encode() + v
field = (comp("xres", "i", struct.pack("<i", 16)) + comp("yres", "i", struct.pack("<i", 16)) +
         comp("data", "D", struct.pack("<I", 256) + bytes(8 * 256)))
ok = b"GWYP" + obj("GwyContainer", comp("/0/data", "o", obj("GwyDataField", field)))
open(bad + "/gwy-object-size-lie.gwy", "wb").write(ok[:4] + ok[4:17] + struct.pack("<I", 1 << 30) + ok[21:])
open(bad + "/gwy-array-lie.gwy", "wb").write(ok.replace(struct.pack("<I", 256) + bytes(8), struct.pack("<I", 1 << 29) + bytes(8), 1))
open(bad + "/gwy-truncated.gwy", "wb").write(ok[:100])
open(bad + "/gwy-no-data.gwy", "wb").write(b"GWYP" + obj("GwyContainer", comp("/0/meta", "s", b"x\0")))
# SDF
sdf = ("aISO-1.0\nNumPoints = 3\nNumProfiles = 2\nXscale = 1e-6\nYscale = 1e-6\n"
       "Zscale = 1e-9\nDataType = 7\n*\n1 2 3\n4 5\n*\n")
open(bad + "/sdf-count.sdf", "w").write(sdf)
open(bad + "/sdf-zero-scale.sdf", "w").write(sdf.replace("Xscale = 1e-6", "Xscale = 0").replace("4 5", "4 5 6"))
open(bad + "/sdf-binary-truncated.sdf", "wb").write(b"bISO-1.0" + bytes(34) + struct.pack("<HH4d3B", 300, 300, 1e-6, 1e-6, 1e-9, -1, 0, 7, 0) + bytes(64))
PY
fi
if command -v ncgen >/dev/null 2>&1; then
	printf 'netcdf x {\ndimensions:\n\tx = 2 ;\nvariables:\n\tdouble depth(x) ;\ndata:\n depth = 1, 2 ;\n}\n' >"$B/nc.cdl"
	ncgen -o "$B/nc-no-heights.nc" "$B/nc.cdl"
	rm -f "$B/nc.cdl"
else
	skip 9 "ncgen not installed: a netCDF without heights (apt-get install netcdf-bin)"
fi
mkdir "$B/a-directory"
nfiles=$(ls "$B" | wc -l)

# --- the check -------------------------------------------------------------
SENTINEL='an existing output that must survive'
# fresh_work: the work directory holds only sentinel outputs.  The helpers
# loop over "out", never "f": sh has no local variables, and the callers'
# f is the bad file the next reader must get.
fresh_work() {
	rm -rf "$W"; mkdir "$W"
	for out in out.surf out.tsv gap.surf; do printf '%s\n' "$SENTINEL" >"$W/$out"; done
	# a reader run as nobody may write there, and over the sentinels
	# (outputs are checked before the input is read, as a shell's >
	# would: root's 644 files are write-protected for nobody)
	if [ -n "${RUNAS:-}" ]; then chmod 777 "$W"; chmod 666 "$W"/out.* "$W"/gap.surf; fi
}
# expect_fail1 DESC NAME CMD...: run CMD in $W; exit 1, one stderr line
# naming NAME with a reason, outputs intact, no new files.
expect_fail1() {
	d=$1 name=$2; shift 2
	n_bad=$((n_bad + 1))
	fresh_work
	(cd "$W" && "$@") >"$T_TMP/stdout" 2>"$T_TMP/stderr" </dev/null
	st=$?
	why=""
	[ "$st" = 1 ] || why="$why exit $st (want 1);"
	[ "$(wc -l <"$T_TMP/stderr")" = 1 ] || why="$why $(wc -l <"$T_TMP/stderr") stderr lines (want 1);"
	grep -qF -- "$name:" "$T_TMP/stderr" || why="$why message does not name '$name';"
	grep -q ': [^:]*[a-zA-Z][^:]*' "$T_TMP/stderr" || why="$why no reason;"
	for out in out.surf out.tsv gap.surf; do
		[ "$(cat "$W/$out" 2>/dev/null)" = "$SENTINEL" ] || why="$why $out modified;"
	done
	[ "$(ls -A "$W" | wc -l)" = 3 ] || why="$why stray files: $(ls -A "$W" | tr '\n' ' ');"
	if [ -z "$why" ]; then pass "$d"; else fail "$d:$why [$(head -c 300 "$T_TMP/stderr")]"; fi
}
# same, with the input on a pipe (cat FILE | CMD)
expect_fail1_pipe() {
	d=$1 file=$2; shift 2
	n_bad=$((n_bad + 1))
	fresh_work
	(cd "$W" && cat "$file" | "$@") >"$T_TMP/stdout" 2>"$T_TMP/stderr"
	st=$?
	why=""
	[ "$st" = 1 ] || why="$why exit $st (want 1);"
	[ "$(wc -l <"$T_TMP/stderr")" = 1 ] || why="$why $(wc -l <"$T_TMP/stderr") stderr lines;"
	grep -qF -- "standard input: " "$T_TMP/stderr" || why="$why message does not name standard input;"
	for out in out.surf out.tsv gap.surf; do
		[ "$(cat "$W/$out" 2>/dev/null)" = "$SENTINEL" ] || why="$why $out modified;"
	done
	[ "$(ls -A "$W" | wc -l)" = 3 ] || why="$why stray files: $(ls -A "$W" | tr '\n' ' ');"
	if [ -z "$why" ]; then pass "$d"; else fail "$d:$why [$(head -c 300 "$T_TMP/stderr")]"; fi
}

G=$D/good.surf
RUNAS=""	# a command prefix for every reader (see the unreadable case)
readers() {	# readers FILE: every reader on FILE
	f=$1 b=$(basename "$1")
	expect_fail1 "surfwarp $b" "$f" $RUNAS surfwarp -q -w 1 -o out.surf "$f"
	# surfstat analyses an x-z profile not uniformly spaced as it is
	[ "$b" = xz-nonuniform.txt ] ||
	expect_fail1 "surfstat $b" "$f" $RUNAS surfstat -q -o out.tsv "$f"
	expect_fail1 "gfmd-solve $b" "$f" $RUNAS gfmd-solve -q -j 1 -p 0.1 --gap gap.surf -o out.tsv "$f"
	expect_fail1 "surfstat --mask $b" "$f" $RUNAS surfstat -q --mask "$f" -o out.tsv "$G"
	expect_fail1 "gfmd-solve --init $b" "$f" $RUNAS gfmd-solve -q -j 1 -p 0.1 --init "$f" --gap gap.surf -o out.tsv "$G"
	expect_fail1 "surfwarp --carve $b" "$f" $RUNAS surfwarp -q --carve "$f" 0.1 -o out.surf "$G"
}
for f in "$B"/*; do
	readers "$f"
	[ -d "$f" ] && continue
	b=$(basename "$f")
	# NaN is a missing point: surfwarp keeps it unless an operation needs
	# every point (checked below); surfstat and gfmd-solve refuse it.
	case $b in
	nan.*) ;;
	*) expect_fail1_pipe "surfwarp < $b" "$f" surfwarp -q -o out.surf ;;
	esac
	[ "$b" = xz-nonuniform.txt ] ||
	expect_fail1_pipe "surfstat < $b" "$f" surfstat -q -o out.tsv
	expect_fail1_pipe "gfmd-solve < $b" "$f" gfmd-solve -q -j 1 -p 0.1 --gap gap.surf -o out.tsv
done
readers "$D/no-such-file.surf"
check_status "surfstat reads xz-nonuniform.txt as it is" 0 surfstat -q -o "$W/ok.tsv" "$B/xz-nonuniform.txt"
for b in nan.surf nan.txt; do
	expect_fail1_pipe "surfwarp -w 1 < $b (warping needs every point)" "$B/$b" surfwarp -q -w 1 -o out.surf
	check_status "surfwarp < $b passes the missing point through" 0 \
	    sh -c "surfwarp -q -o '$W/nan-kept.surf' < '$B/$b'"
	check "... and keeps it missing" sh -c "surfstat -q --iso '$W/nan-kept.surf' >/dev/null"
done
# Sizes that do not match the indenter (a good file otherwise).
expect_fail1 "surfstat --mask of another size" "$D/mask8.surf" surfstat -q --mask "$D/mask8.surf" -o out.tsv "$G"
expect_fail1 "surfstat --mask with a 0.5" "$B/mask-half.surf" surfstat -q --mask "$B/mask-half.surf" -o out.tsv "$G"
expect_fail1 "surfwarp --carve of another size" "$D/mask8.surf" surfwarp -q --carve "$D/mask8.surf" 0.1 -o out.surf "$G"
expect_fail1 "gfmd-solve --init of another size" "$D/small.surf" gfmd-solve -q -j 1 -p 0.1 --init "$D/small.surf" --gap gap.surf -o out.tsv "$G"
# Empty standard input (no pipe writer at all).
expect_fail1 "surfwarp, empty stdin" "standard input" surfwarp -q -o out.surf
expect_fail1 "surfstat, empty stdin" "standard input" surfstat -q -o out.tsv
expect_fail1 "gfmd-solve, empty stdin" "standard input" gfmd-solve -q -j 1 -p 0.1 -o out.tsv
# An endless text stream stops at the longest side a grid may have
# (16777216 rows or values in a row), not when memory runs out.
expect_fail1 "surfstat < endless rows" "standard input" sh -c 'yes 1 | surfstat -q -o out.tsv'
expect_fail1 "surfwarp < endless row" "standard input" sh -c 'yes 1 | tr "\n" " " | surfwarp -q -o out.surf'
# Unreadable: chmod 000 does not stop root, so as root the readers run as
# user nobody (setpriv), for whom it does.
cp "$G" "$D/unreadable.surf"; chmod 000 "$D/unreadable.surf"
if ! cat "$D/unreadable.surf" >/dev/null 2>&1; then
	readers "$D/unreadable.surf"
elif chmod 755 "$T_TMP" "$D" && command -v setpriv >/dev/null 2>&1 &&
    setpriv --reuid=65534 --regid=65534 --clear-groups -- \
    surfstat -q "$G" >/dev/null 2>&1; then
	RUNAS="setpriv --reuid=65534 --regid=65534 --clear-groups --"
	readers "$D/unreadable.surf"
	RUNAS=""
else
	skip 6 "unreadable-file cases: root, and user nobody cannot run the tools here (no setpriv, or the build is not world-readable)"
fi
chmod 644 "$D/unreadable.surf"
# The same good file still works through every reader (the harness is honest).
check_status "surfwarp reads the good file" 0 surfwarp -q -w 1 -o "$W/ok.surf" "$G"
check_status "surfstat reads the good .npy" 0 surfstat -q -o "$W/ok.tsv" "$D/good.npy"
check_status "surfstat reads the good .gsf" 0 surfstat -q -o "$W/ok.tsv" "$D/good.gsf"
check_status "surfstat reads the good .txt" 0 surfstat -q -o "$W/ok.tsv" "$D/good.txt"
check_status "surfstat --mask reads the good mask" 0 surfstat -q --mask "$D/mask.surf" -o "$W/ok.tsv" "$G"

# --- out of memory ---------------------------------------------------------
# With the address space limited to 200 MB, a grid of 8192^2 (512 MB) cannot
# be made or read, and a 4096^2 grid (128 MB) can be read but not
# transformed (surfgen transforms in place in one 4096^2 buffer, so it is
# limited to 100 MB to fail): a one-line "out of memory" with the size asked for, exit 1,
# outputs intact.  The inputs are sparse files of zeros (no disk, fast).
# AddressSanitizer reserves terabytes of address space: under SANITIZE=1
# the tools cannot start with a limit at all, so these cases are skipped.
expect_oom() {
	d=$1 lim=$2; shift 2
	n_bad=$((n_bad + 1))
	fresh_work
	(cd "$W" && ulimit -v "$lim" && "$@") >"$T_TMP/stdout" 2>"$T_TMP/stderr" </dev/null
	st=$?
	why=""
	[ "$st" = 1 ] || why="$why exit $st (want 1);"
	[ "$(wc -l <"$T_TMP/stderr")" = 1 ] || why="$why $(wc -l <"$T_TMP/stderr") stderr lines (want 1);"
	grep -q 'out of memory (asked for [0-9][0-9]* bytes' "$T_TMP/stderr" || why="$why no 'out of memory (asked for N bytes';"
	for out in out.surf out.tsv gap.surf; do
		[ "$(cat "$W/$out" 2>/dev/null)" = "$SENTINEL" ] || why="$why $out modified;"
	done
	[ "$(ls -A "$W" | wc -l)" = 3 ] || why="$why stray files: $(ls -A "$W" | tr '\n' ' ');"
	if [ -z "$why" ]; then pass "$d"; else fail "$d:$why [$(head -c 300 "$T_TMP/stderr")]"; fi
}
sparse_surf() {	# sparse_surf N FILE: an N x N grid of zeros
	printf '#surf 1\nnx = %d\nny = %d\nlx = 1\nly = 1\nkind = height\nencoding = float64-le\nend_header\n' \
	    "$1" "$1" >"$2"
	truncate -s "$(($(wc -c <"$2") + $1 * $1 * 8))" "$2"
}
if (ulimit -v 200000 && surfgen -q -n 4 -o /dev/null; r=$?; exit $r) >/dev/null 2>&1 &&
    command -v truncate >/dev/null; then
	sparse_surf 8192 "$D/big8192.surf"
	sparse_surf 4096 "$D/big4096.surf"
	expect_oom "surfgen -n 8192 in 200 MB" 200000 surfgen -q -n 8192 -o out.surf
	expect_oom "surfgen -n 4096 in 100 MB (FFT)" 100000 surfgen -q -n 4096 -o out.surf
	expect_oom "surfwarp reading 8192^2 in 200 MB" 200000 surfwarp -q -w 1 -o out.surf "$D/big8192.surf"
	expect_oom "surfstat reading 8192^2 in 200 MB" 200000 surfstat -q -o out.tsv "$D/big8192.surf"
	expect_oom "gfmd-solve reading 8192^2 in 200 MB" 200000 gfmd-solve -q --pressure-abs 0.1 --gap gap.surf -o out.tsv "$D/big8192.surf"
	expect_oom "surfstat --mask 8192^2 in 200 MB" 200000 surfstat -q --mask "$D/big8192.surf" -o out.tsv "$G"
	expect_oom "gfmd-solve --init 8192^2 in 200 MB" 200000 gfmd-solve -q -p 0.1 --init "$D/big8192.surf" -o out.tsv "$G"
	expect_oom "surfwarp 8192^2 from a pipe in 200 MB" 200000 sh -c "head -c 300000000 '$D/big8192.surf' | surfwarp -q -o out.surf"
	expect_oom "surfstat 4096^2 in 200 MB (FFT)" 200000 surfstat -q -o out.tsv "$D/big4096.surf"
	expect_oom "surfstat --psd 4096^2 in 300 MB" 300000 surfstat -q --psd -o out.tsv "$D/big4096.surf"
	expect_oom "gfmd-solve 4096^2 in 300 MB" 300000 gfmd-solve -q --pressure-abs 0.1 --gap gap.surf -o out.tsv "$D/big4096.surf"
	expect_oom "gfmd-solve --method cg 4096^2 in 300 MB" 300000 gfmd-solve -q --method cg --pressure-abs 0.1 --gap gap.surf -o out.tsv "$D/big4096.surf"
	rm -f "$D/big8192.surf" "$D/big4096.surf"
else
	skip 12 "out-of-memory cases: the tools cannot run under ulimit -v (sanitizer build?)"
fi

# --- options ---------------------------------------------------------------
# expect_usage DESC NPROBLEMS CMD...: exit 2, NPROBLEMS problem lines, then
# the summary line counting them; nothing written.
expect_usage() {
	d=$1 want=$2; shift 2
	n_bad=$((n_bad + want))
	fresh_work
	(cd "$W" && "$@") >"$T_TMP/stdout" 2>"$T_TMP/stderr" </dev/null
	st=$?
	why=""
	[ "$st" = 2 ] || why="$why exit $st (want 2);"
	lines=$(grep -cv 'usage problems\{0,1\}; see' "$T_TMP/stderr")
	[ "$lines" = "$want" ] || why="$why $lines problem lines (want $want);"
	grep -q ": $want usage problems\{0,1\}; see" "$T_TMP/stderr" || why="$why no summary counting $want;"
	for out in out.surf out.tsv gap.surf; do
		[ "$(cat "$W/$out" 2>/dev/null)" = "$SENTINEL" ] || why="$why $out modified;"
	done
	[ "$(ls -A "$W" | wc -l)" = 3 ] || why="$why stray files: $(ls -A "$W" | tr '\n' ' ');"
	[ -s "$T_TMP/stdout" ] && why="$why wrote to stdout;"
	if [ -z "$why" ]; then pass "$d"; else fail "$d:$why [$(head -c 400 "$T_TMP/stderr")]"; fi
}
S="-q -o out.surf"
for a in "-H 0" "-H 1" "-H 1.5" "-H -0.2" "-H nan" "-H abc" "-L -1" "-L 0" \
    "-L 1x" "-L 1x-2" "-L inf" "-n 0" "-n -4" "-n 3x" "-n 99999999999" "-n 16x0" \
    "--lambda-s 0.1" "--lambda-s -1" "--lambda-r -1" "--lambda-r 0" \
    "--peklenik 0" "--peklenik -2" "--peklenik inf" "--seed -1" "--seed x" \
    "--rms-gradient -1" "--rms-gradient inf" "--rms-height 0" "--type foo" \
    "--type harmonic --radius -1" "--type harmonic --exponent 0" \
    "--type sine --wavelength 0" "--type sine --amplitude nan" \
    "-j 0" "-j x" "--bogus" "-o out.xyz"; do
	expect_usage "surfgen -n 16 $a" 1 surfgen -n 16 $S $a
done
expect_usage "surfgen: eight problems at once" 8 surfgen $S -H 1.5 -L -1 -n 0 \
    --peklenik 0 --seed x --rms-gradient inf --type foo --bogus
for a in "-w nan" "-w inf" "-w x" "-w" "-w 1 --hmin 1 --hmax 0" "--rms-gradient -1" \
    "--carve-width -1" "--carve-width nan" "-L 0" "-j -1" "--frobnicate" \
    "-o out.bad"; do
	expect_usage "surfwarp $a" 1 surfwarp $S $a "$G"
done
expect_usage "surfwarp: four problems at once" 4 surfwarp $S -w nan --rms-gradient -1 -L 0 --frob "$G"
T="-q -o out.tsv"
for a in "--bins-per-decade 0" "--bins-per-decade -3" "--bins-per-decade x" \
    "--by-height 0" "--by-height -2" "-L -1" "--nope" "-j 0"; do
	expect_usage "surfstat $a" 1 surfstat $T $a "$G"
done
expect_usage "surfstat: three problems at once" 3 surfstat $T --bins-per-decade 0 -L -1 --nope "$G"
for tool in surfstat surfwarp gfmd-solve; do
	for a in "--unit furlong" "--unit deg" "--z-unit V" "--npy-order zz" \
	    "--periodic --no-periodic"; do
		case $tool in
		gfmd-solve) expect_usage "$tool $a" 1 $tool $T -j 1 -p 0.1 $a "$G" ;;
		surfwarp) expect_usage "$tool $a" 1 $tool $S $a "$G" ;;
		*) expect_usage "$tool $a" 1 $tool $T $a "$G" ;;
		esac
	done
done
for a in "-p 0" "-p -0.1" "-p 0.1,,0.2" "-p 0.1,abc" "-p nan" "-p inf" "-p ''" \
    "-p 0.1," "-E 0" "-E -1" "-E nan" "--tol 0" "--tol -1" "--max-iter 0" \
    "--max-iter x" "--method foo" "--alpha nan" "-L 0" "--what"; do
	eval "set -- $a"
	expect_usage "gfmd-solve $a" 1 gfmd-solve $T -j 1 -p 0.1 "$@" "$G"
done
expect_usage "gfmd-solve without -p" 1 gfmd-solve $T -j 1 "$G"
expect_usage "gfmd-solve --pressure-abs -1" 1 gfmd-solve $T -j 1 --pressure-abs -1 "$G"
expect_usage "gfmd-solve -p and --pressure-abs" 1 gfmd-solve $T -j 1 -p 0.1 --pressure-abs 0.1 "$G"
expect_usage "gfmd-solve: five problems at once" 5 gfmd-solve $T -j 1 -p 0 -E -1 --tol 0 --method foo --what "$G"
for a in "--order x" "--order 0" "--fit foo" "--alpha nan" "--alpha-f x" \
    "--alpha-t -1" "--zzz"; do
	expect_usage "contact-stats $a" 1 contact-stats $T $a "$D/rows.tsv"
done
expect_usage "contact-stats --schedule without its parameters" 1 contact-stats -q --schedule
expect_usage "contact-stats --schedule, bad parameters" 3 contact-stats -q --schedule --eps-ref -1 --p-ref 0 -p 0.1,x

# --- contact-stats rows ----------------------------------------------------
R=$D/rows
mkdir -p "$R"
hdr='p_star	a_r	n_c	n_cl	n_tot	gbar	gbar_c	nx	ny	lx	ly	lambda_r	lambda_s	seed	H	type'
row1='0.1	0.2	100	30	500	1	1.2	32	32	1	1	0.5	0.0625	1	0.8	selfaffine'
row2='0.1	0.19	400	120	2048	1	1.2	64	64	1	1	0.5	0.0625	1	0.8	selfaffine'
printf '%s\n%s\n%s\n' "$hdr" "$row1" "$row2" >"$D/rows.tsv"
check_status "contact-stats reads the good rows" 0 contact-stats -q -o "$W/ok.tsv" "$D/rows.tsv"
good_rows() { cat "$D/rows.tsv"; }
good_rows | awk -F'\t' -v OFS='\t' '{ $2 = ""; print }' | sed 's/\t\t/\t/' >"$R/no-a_r-column.tsv"
good_rows | awk -F'\t' -v OFS='\t' '{ $1 = ""; print }' | sed 's/^\t//' >"$R/no-p_star-column.tsv"
good_rows | sed '3s/0\.19/abc/' >"$R/a_r-word.tsv"
good_rows | sed '3s/0\.19/1.5/' >"$R/a_r-above-1.tsv"
good_rows | sed '3s/0\.19/-0.1/' >"$R/a_r-negative.tsv"
good_rows | sed '3s/0\.19/nan/' >"$R/a_r-nan.tsv"
good_rows | sed '3s/0\.19/0x1p-3junk/' >"$R/a_r-trailing.tsv"
good_rows | sed '3s/\t64\t64/\tsixty\t64/' >"$R/nx-word.tsv"
good_rows | sed '3s/\tselfaffine$//' >"$R/short-row.tsv"
good_rows | sed '3s/$/\textra/' >"$R/long-row.tsv"
good_rows | sed '1s/a_r/p_star/' >"$R/duplicate-column.tsv"
printf '\377\376\000\001garbage\000\n\001\002\003\n' >"$R/garbage.bin"
head -c 300 "$D/good.surf" >"$R/a-surface.surf"
: >"$R/empty.tsv"
printf '%s\n' "$hdr" >"$R/header-only.tsv"
printf '[{"p_star": 0.1, "a_r":' >"$R/json-truncated.json"
printf '[{"p_star": 0.1, "a_r": {"x": 1}}]' >"$R/json-nested.json"
printf '[{"p_star": 0.1, "a_r": 0.2}' >"$R/json-unclosed.json"
# A full row in JSON with a_r replaced.
json_row() {
	awk -F'\t' -v ar="$1" 'NR == 1 { for (i = 1; i <= NF; i++) k[i] = $i; next }
		NR == 2 { printf "[{"; for (i = 1; i <= NF; i++) { v = k[i] == "a_r" ? ar : $i
			if (v !~ /^[-0-9.e]+$/ && v != ar) v = "\"" v "\""
			printf "%s\"%s\": %s", (i > 1 ? ", " : ""), k[i], v } print "}]"; exit }' "$D/rows.tsv"
}
json_row 0.2 >"$D/rows.json"
check_status "contact-stats reads a good JSON row" 0 contact-stats -q --no-extrapolate -o "$W/ok.tsv" "$D/rows.json"
json_row 1e999 >"$R/json-overflow.json"
json_row true >"$R/json-a_r-true.json"
printf '[{"p_star": 0.1, "a_r": "0.2\\uZZZZ"}]' >"$R/json-bad-escape.json"
for f in "$R"/*; do
	b=$(basename "$f")
	# JSON files hold one discretisation: no extrapolation.
	case $b in *.json) x=--no-extrapolate ;; *) x=--fit=finest ;; esac
	expect_fail1 "contact-stats $b" "$f" contact-stats -q $x -o out.tsv "$f"
done
expect_fail1 "contact-stats, missing file" "$D/no-rows.tsv" contact-stats -q -o out.tsv "$D/no-rows.tsv"
expect_fail1 "contact-stats, a directory" "$R" contact-stats -q -o out.tsv "$R"
expect_fail1 "contact-stats, empty stdin" "standard input" contact-stats -q -o out.tsv
expect_fail1 "contact-stats, good then bad file" "$R/a_r-word.tsv" contact-stats -q -o out.tsv "$D/rows.tsv" "$R/a_r-word.tsv"

# -h beside a bad option (before or after it): the problem is reported,
# exit 2, as without -h; -h alone prints the help, exit 0.
for t in surfgen surfwarp surfstat gfmd-solve contact-stats; do
	check_status "$t --no-such-option -h: exit 2" 2 $t --no-such-option -h
	check "  names the option" grep -q 'no-such-option' "$T_TMP/stderr"
	check_status "$t -h --no-such-option: exit 2" 2 $t -h --no-such-option
	$t -h > help.txt 2>&1; st=$?
	check "$t -h alone: exit 0, the help" test "$st" = 0 -a "$(grep -c -- '--help\|-h' help.txt)" -ge 1
done
# --min-wavelength >= --max-wavelength of one kind: a usage error (2)
# before any reading; of two kinds (L and a length) it needs the map.
surfgen -q -n 16 -o w16.surf
check_status "--fit, min 0.5L >= max 0.1L: exit 2" 2 surfstat --fit --min-wavelength 0.5L --max-wavelength 0.1L w16.surf
check "  need min < max" grep -q 'min < max' "$T_TMP/stderr"
check_status "--fit, min 5um >= max 1000nm: exit 2" 2 surfstat --fit --min-wavelength 5um --max-wavelength 1000nm w16.surf
surfgen -q -n 16 -L 10 | surfwarp -q --unit um -o w16um.surf
check_status "--fit, min 2um < max 5000nm on a 10 um map: accepted" 0 surfstat --fit --min-wavelength 2um --max-wavelength 5000nm w16um.surf

echo "bad inputs tried: $n_bad ($nfiles broken grid files)"
summary
