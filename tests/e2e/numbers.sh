# SPDX-License-Identifier: GPL-3.0-or-later
# numbers.sh - no wrong number passes silently: unconverged rows are
# refused by contact-stats, non-finite results never leave a tool with
# exit 0, option messages name the option that is wrong.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
export OMP_WAIT_POLICY=passive

# ---- convergence: rows carry their tolerance, contact-stats checks it ----
surfgen -n 32 --seed 3 --lambda-s 0.0625 -o s32.surf
surfgen -n 64 --seed 3 --lambda-s 0.0625 -o s64.surf
gfmd-solve -q -p 0.05 -o c32.tsv s32.surf
gfmd-solve -q -p 0.05 -o c64.tsv s64.surf
gfmd-solve -q -p 0.05 --max-iter 3 -o u64.tsv s64.surf 2>/dev/null
check "gfmd-solve rows carry tol = --tol (default 1e-6)" [ "$(col c32.tsv tol)" = 1e-06 ]
gfmd-solve -q -p 0.05 --tol 1e-4 -o t.tsv s32.surf
check "gfmd-solve rows carry tol = --tol 1e-4" [ "$(col t.tsv tol)" = 0.0001 ]
check_status "converged rows are accepted" 0 contact-stats c32.tsv c64.tsv
check_status "--max-iter 3 rows are refused" 1 contact-stats c32.tsv u64.tsv
check "... naming the file and line" grep -q "u64.tsv:2: residual .* exceeds the row's tolerance" "$T_TMP/stderr"
check_status "--allow-unconverged uses them" 0 contact-stats --allow-unconverged -o allow.tsv c32.tsv u64.tsv
check "... with a warning" grep -q "1 row from unconverged solves" "$T_TMP/stderr"
# The unconverged a_r differs from the converged one (it is why they are
# refused): the extrapolation from it is not the converged answer.
contact-stats -o conv.tsv c32.tsv c64.tsv
check "the unconverged rows change a_r" [ "$(col allow.tsv a_r)" != "$(col conv.tsv a_r)" ]
# Older rows without tol: held to residual <= 1e-3.
awk -F'\t' -v OFS='\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "tol") k = i }
    { out = ""; for (i = 1; i <= NF; i++) if (i != k) out = out (out == "" ? "" : OFS) $i; print out }' \
    u64.tsv > old-unconv.tsv
awk -F'\t' -v OFS='\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "tol") k = i }
    { out = ""; for (i = 1; i <= NF; i++) if (i != k) out = out (out == "" ? "" : OFS) $i; print out }' \
    c64.tsv > old-conv.tsv
check_status "rows without tol, residual > 1e-3: refused" 1 contact-stats c32.tsv old-unconv.tsv
check "... saying why" grep -q "old-unconv.tsv:2: residual .* exceeds 0.001 (the row has no tol column)" "$T_TMP/stderr"
check_status "rows without tol, converged: accepted" 0 contact-stats c32.tsv old-conv.tsv
check_status "--lenient skips an unconverged row (then too few grids)" 1 contact-stats --lenient c32.tsv u64.tsv
# A killed run: its last row cut short, then another run appended with cat.
head -c "$(($(wc -c < c64.tsv) - 30))" c64.tsv > killed.tsv
cat killed.tsv c32.tsv > joined.tsv
check_status "a killed run's cut row, concatenated: refused" 1 contact-stats joined.tsv
check "... naming the line" grep -q "joined.tsv:2:" "$T_TMP/stderr"

# ---- option messages name the option as typed (one helper, every tool) ----
# msg DESC WANT CMD...: exit 2 and the first stderr line is exactly WANT
msg() {
	d=$1; want=$2; shift 2
	"$@" >/dev/null 2>err.txt; st=$?
	got=$(head -n 1 err.txt)
	if [ "$st" = 2 ] && [ "$got" = "$want" ]; then pass "$d"; else fail "$d: exit $st, '$got', expected '$want'"; fi
}
msg "surfgen --lambda-r without a value" "surfgen: --lambda-r: needs a value" surfgen --lambda-r
msg "surfstat --mask without a value" "surfstat: --mask: needs a value" surfstat --mask
msg "surfwarp --flip=1" "surfwarp: --flip: takes no value (given '1')" surfwarp --flip=1 s32.surf
msg "surfwarp -w without a value" "surfwarp: -w: needs a value" surfwarp -w
msg "surfwarp -qz: the unknown letter" "surfwarp: -z: unknown option" surfwarp -qz s32.surf
msg "gfmd-solve --tol without a value" "gfmd-solve: --tol: needs a value" gfmd-solve -p 0.1 s32.surf --tol
msg "gfmd-solve abbreviation --tol without a value" "gfmd-solve: --tol: needs a value" gfmd-solve -p 0.1 s32.surf --to
msg "gfmd-solve --wisdom without a value" "gfmd-solve: --wisdom: needs a value" gfmd-solve -p 0.1 s32.surf --wisdom
msg "surfgen ambiguous --lambda" "surfgen: --lambda: ambiguous: --lambda-r, --lambda-s" surfgen --lambda 0.5
msg "contact-stats --lenient=1" "contact-stats: --lenient: takes no value (given '1')" contact-stats --lenient=1 c32.tsv
msg "contact-stats unknown -x" "contact-stats: -x: unknown option" contact-stats -x c32.tsv
# A file the library names is named once.
# (refused before any work, as a usage problem: exit 2)
check_status "surfgen -o into a missing directory" 2 surfgen -n 8 -o nodir/a.surf
check "... names the path once" [ "$(grep -o 'nodir/a.surf' "$T_TMP/stderr" | wc -l)" -eq 1 ]
check_status "gfmd-solve -o into a missing directory" 2 gfmd-solve -q -p 0.1 -o nodir/a.tsv s32.surf
check "... names the path once" [ "$(grep -o 'nodir/a.tsv' "$T_TMP/stderr" | wc -l)" -eq 1 ]
check_status "surfstat --gnuplot into a missing directory" 2 surfstat --gnuplot nodir/a.gp s32.surf
check "... names the path once" [ "$(grep -o 'nodir/a.gp' "$T_TMP/stderr" | wc -l)" -eq 1 ]

# ---- --json is valid JSON for every value ----
# A surface whose metadata strtod reads as numbers JSON does not have
# (Infinity, +5, 0x10, NaN, 1e999), bytes that are not UTF-8, quotes and
# backslashes: the header rewritten with its data offset recomputed.
hostile() {
	python3 - "$1" "$2" <<'PY'
import sys
data = open(sys.argv[1], 'rb').read()
hdr = data[:data.index(b'end_header')].decode()
off = int([l for l in hdr.splitlines() if l.startswith('data_offset')][0].split('=')[1])
keep = [l.encode() for l in hdr.splitlines() if not l.startswith(('data_offset', 'history'))]
meta = [b'meta.inf = Infinity', b'meta.plus = +5', b'meta.hex = 0x10', b'meta.nanv = NaN',
        b'meta.big = 1e999', b'meta.bad = \xff\xfe caf\xc3\xa9', b'meta.quote = say "hi" \\ back']
build = lambda o: b'\n'.join(keep + [b'data_offset = %d' % o] + meta + [b'end_header']) + b'\n'
n = len(build(0))
while len(build(n)) != n:
	n = len(build(n))
open(sys.argv[2], 'wb').write(build(n) + data[off:])
PY
}
# json_ok FILE [KEY=VALUE...]: python's strict parser reads FILE (no NaN or
# Infinity constants) and its first row has these string values (VALUE a
# python literal)
json_ok() {
	python3 -c 'import ast, json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"), parse_constant=lambda c: sys.exit("constant " + c))
for kv in sys.argv[2:]:
	k, v = kv.split("=", 1)
	if d[0].get(k) != ast.literal_eval(v):
		sys.exit("%s: %s, expected %s" % (k, ascii(d[0].get(k)), v))' "$@"
}
if command -v python3 >/dev/null 2>&1; then
	hostile s32.surf hostile.surf
	check_status "surfstat reads the hostile metadata" 0 surfstat --json -o h-stat.json hostile.surf
	check "surfstat --json is valid JSON" json_ok h-stat.json
	check "... non-JSON numbers are strings, bad bytes U+FFFD" json_ok h-stat.json \
	    "inf='Infinity'" "plus='+5'" "hex='0x10'" "nanv='NaN'" "big='1e999'" \
	    "bad='\\ufffd\\ufffd caf\\xe9'" "quote='say \"hi\" \\\\ back'" "H=0.8"
	gfmd-solve -q --json -p 0.05 -o h-gfmd.json hostile.surf
	check "gfmd-solve --json is valid JSON, the same strings" json_ok h-gfmd.json \
	    "inf='Infinity'" "big='1e999'" "bad='\\ufffd\\ufffd caf\\xe9'"
	# Control characters in a key column reach contact-stats' JSON escaped.
	for n in 32 64; do
		awk -F'\t' -v OFS='\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "amplitudes") k = i; print; next }
		    { $k = "sq\001rt\177\"\\"; print }' c$n.tsv > k$n.tsv
	done
	contact-stats --json -o k.json k32.tsv k64.tsv
	check "contact-stats --json with control characters is valid JSON and keeps them" \
	    json_ok k.json "amplitudes='sq\\x01rt\\x7f\"\\\\'"
else
	skip 5 "python3 not installed: JSON checked by a strict parser (apt-get install python3)"
fi
# Concatenated --json outputs read like concatenated TSV.
gfmd-solve -q --json -p 0.05 -o c32.json s32.surf
gfmd-solve -q --json -p 0.05 -o c64.json s64.surf
cat c32.json c64.json > both.json
cat c32.tsv c64.tsv > both.tsv
check_status "contact-stats reads concatenated JSON" 0 contact-stats -o both-json.out both.json
contact-stats -o both-tsv.out both.tsv
check "... with the result of the concatenated TSV" [ "$(col both-json.out a_r)" = "$(col both-tsv.out a_r)" ]
check_rel "... which is the a_r of the two files" "$(col both-json.out a_r)" "$(col conv.tsv a_r)" 0
printf '[]\n{"x": 1}\n' > notarray.json
check_status "an object after the arrays is still an error" 1 contact-stats notarray.json

# ---- a wide table (20000 carried key columns, 0.56 MB) ----
# Column names are looked up by hash: the reader and the key building are
# linear in the table's size (bench/bench_cstats_wide.sh has the figures).
awk -v n=20000 'BEGIN { h = "p_star\ta_r\tnx\tny\tlx"
	for (i = 1; i <= n; i++) h = h "\tc" i; print h
	for (r = 0; r < 4; r++) { nx = r % 2 ? 64 : 32
		# a_r = 0.1 + eps_c, eps_c = 1/nx (no lambda_s): limit 0.1
		l = 0.05 * (1 + int(r / 2)) "\t" 0.1 + 1 / nx "\t" nx "\t" nx "\t1"
		for (i = 1; i <= n; i++) l = l "\t" i; print l } }' > wide.tsv
check_status "a table of 20000 columns" 0 contact-stats -q -o wide.out wide.tsv
check_rel "... extrapolates a_r = 0.1 + 1/nx to 0.1" "$(col wide.out a_r 1)" 0.1 1e-12
check "... and carries the last key column" [ "$(col wide.out c20000 2)" = 20000 ]
printf 'a\tb\tc\tb\n1\t2\t3\t4\n' > dupcol.tsv
check_status "a duplicate column name is still an error" 1 contact-stats dupcol.tsv
check "... naming both fields" grep -q "header fields 2 and 4: duplicate column name 'b'" "$T_TMP/stderr"

# ---- -j above the core count is clamped, with a note ----
cores=$(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN)
check_status "gfmd-solve -j 4096" 0 gfmd-solve -q -j 4096 -p 0.05 -o j4096.tsv s32.surf
check "... says it uses the $cores cores" grep -q -- "-j 4096: more threads than the $cores core.* available; using $cores\$" "$T_TMP/stderr"
check "... once (not again after the re-execution for passive waiting)" \
    [ "$(grep -c -- "-j 4096: more threads" "$T_TMP/stderr")" = 1 ]
gfmd-solve -q -j 1 -p 0.05 -o j1.tsv s32.surf
check "... and finds the contact of -j 1" [ "$(col j4096.tsv n_c)" = "$(col j1.tsv n_c)" ]
check_status "surfgen -j $cores: no note" 0 surfgen -j "$cores" -n 8 -o j.surf
check "... (stderr empty)" [ ! -s "$T_TMP/stderr" ]

# ---- with stderr closed, warnings never land in the result table ----
gfmd-solve -q --max-iter 3 -p 0.05,0.1 -o closed.tsv s32.surf 2>&-
check "gfmd-solve 2>&-: the table holds the header and two rows only" [ "$(wc -l < closed.tsv)" -eq 3 ]
check "... no warning text in it" [ "$(grep -c 'not converged' closed.tsv)" -eq 0 ]
contact-stats --allow-unconverged -o closed-cs.tsv c32.tsv u64.tsv 2>&-
check "contact-stats 2>&-: no warning in its table" [ "$(grep -c 'unconverged' closed-cs.tsv)" -eq 0 ]
check_status "stdout closed: the table's write fails (exit 1), not lost silently" 1 sh -c 'surfstat s32.surf >&-'

# ---- non-finite values never leave a tool with exit 0 ----
# finite_surf FILE: surfstat reads it (it refuses NaN and infinities)
finite_surf() { surfstat "$1" > /dev/null 2>&1; }
check_status "surfwarp --hmin -1e308 --hmax 1e308: refused" 1 surfwarp -w 2 --hmin -1e308 --hmax 1e308 -o w1.surf s32.surf
check "... naming the bounds" grep -q "hmax - hmin = 1e+308 - (-1e+308) overflows" "$T_TMP/stderr"
check "... and writing nothing" [ ! -e w1.surf ]
surfwarp -w 2 --hmin -1e307 --hmax 1e307 -o w2.surf s32.surf
check "surfwarp with bounds 1e307 apart: finite heights" finite_surf w2.surf
gfmd-solve -q -p 0.05 --contact c32.surf -o /dev/null s32.surf
check_status "surfwarp --carve-width 1e-300: finite" 0 surfwarp --carve c32.surf 1 --carve-width 1e-300 -o w3.surf s32.surf
check "... heights" finite_surf w3.surf
# A width far below the grid spacing is a step: depth 1 everywhere off contact.
check_rel "... a step of the depth: range grows by 1" \
    "$(surfstat w3.surf | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "hmin") k = i } NR == 2 { print $k }')" \
    "$(surfstat s32.surf | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "hmin") k = i } NR == 2 { printf "%.17g", $k - 1 }')" 1e-12
check_status "surfwarp --carve 1e308 deep with 1e308 roughness: refused" 1 surfwarp --carve c32.surf 1e308 --carve-rough 1e308 -o w4.surf s32.surf
check "... saying it overflows" grep -q "overflows the height" "$T_TMP/stderr"
# Harmonic: z = -r^2/(2 R); at the cell corner r^2 = 1/2, so hmin = -1/(4 R).
check_status "surfgen harmonic --radius 1e-300" 0 surfgen --type harmonic -n 16 --radius 1e-300 -o hr.surf
check "... finite" finite_surf hr.surf
check_rel "... hmin = -1/(4 R) = -2.5e299" "$(surfstat hr.surf | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "hmin") k = i } NR == 2 { print $k }')" -2.5e299 1e-12
check_status "surfgen harmonic --radius 1e-300 --exponent 4: refused" 1 surfgen --type harmonic -n 16 --radius 1e-300 --exponent 4 -o hr4.surf
check "... naming the radius" grep -q "overflows: a larger --radius" "$T_TMP/stderr"
# surfstat near 1e150: the same statistics as the unscaled surface (the
# scale-free ones equal, the others times 1e150), to round-off.
surfgen -n 32 --seed 3 --lambda-s 0.0625 --rms-height 1e150 -o big.surf
surfgen -n 32 --seed 3 --lambda-s 0.0625 --rms-height 1 -o one.surf
surfstat -o big.tsv big.surf
surfstat -o one.tsv one.surf
for c in skewness kurtosis nayak phi1 phi4 phi6 phi8; do
	check_rel "surfstat at 1e150: $c as at 1" "$(col big.tsv $c)" "$(col one.tsv $c)" 1e-9
done
for c in gbar gbar_fd rms_laplacian hrms; do
	check_rel "surfstat at 1e150: $c = 1e150 times that at 1" "$(col big.tsv $c)" "$(awk -v v="$(col one.tsv $c)" 'BEGIN { printf "%.17g", v * 1e150 }')" 1e-9
done
surfstat --by-height 3 -o bigh.tsv big.surf
surfstat --by-height 3 -o oneh.tsv one.surf
check_rel "surfstat --by-height at 1e150: gxx = 1e300 times" "$(col bigh.tsv gxx 2)" "$(awk -v v="$(col oneh.tsv gxx 2)" 'BEGIN { printf "%.17g", v * 1e300 }')" 1e-9
# gfmd-solve names the surface, not "p = inf".
check_status "gfmd-solve on heights near 1e150: refused" 1 gfmd-solve -q -p 0.05 big.surf
check "... naming the surface and its scale" grep -q "^gfmd-solve: big.surf: heights spanning .* outside \[1e-100, 1e+100\]" "$T_TMP/stderr"
# The span it names is max - min of the heights (its loop compares, no
# fmin/fmax): surfstat's range, to the 6 digits of %g.
span=$(sed -n 's/^gfmd-solve: big.surf: heights spanning \([^ ]*\) .*/\1/p' "$T_TMP/stderr")
check_rel "... the span is surfstat's range" "$span" "$(col big.tsv range)" 1e-5
# One contact point at a harmonic apex: gbar_c = 0, kappa_c nan, said why.
surfgen --type harmonic -n 64 -o hh.surf
check_status "gfmd-solve: a one-point contact" 0 gfmd-solve -q -p 1e-6 -o one-point.tsv hh.surf
check "... n_c = 1" [ "$(col one-point.tsv n_c)" = 1 ]
check "... kappa_c nan" [ "$(col one-point.tsv kappa_c)" = nan ]
check "... and a warning says why" grep -q "kappa_c written as nan: the rms gradient over the contact, gbar_c, is 0" "$T_TMP/stderr"
# surfstat on degenerate surfaces: the undefined ratios stay nan in the
# table, exit 0, and one warning names the columns and why.  A warp with
# bounds far outside the heights makes them equal to round-off (hrms of
# round-off, gbar exactly 0); a flat surface has hrms = 0 too; a sine
# along y has no slope along x, the Nayak parameter's profiles.
surfgen -q -n 64 --seed 1 | surfwarp -q -w 2 --hmin -1e300 --hmax 1e300 -o warped.surf
check_status "surfstat on a surface warped flat: exit 0" 0 surfstat -o warped.tsv warped.surf
check "... nayak and phi1 .. phi9 nan" [ "$(col warped.tsv nayak) $(col warped.tsv phi1) $(col warped.tsv phi9)" = "nan nan nan" ]
check "... and one warning says which and why ($(head -c 200 "$T_TMP/stderr"))" \
    grep -q "^surfstat: nayak, phi1 .. phi9 written as nan: the rms gradient is 0" "$T_TMP/stderr"
check "... only one line" [ "$(wc -l < "$T_TMP/stderr")" -eq 1 ]
surfgen -q --type flat -n 16 -o flat.surf
check_status "surfstat on a flat surface: exit 0" 0 surfstat -q -o flat.tsv flat.surf
check "... skewness nan" [ "$(col flat.tsv skewness)" = nan ]
check "... warned (also under -q): hrms = 0" grep -q "^surfstat: skewness, kurtosis, nayak, phi1 .. phi9 written as nan: the heights are constant (hrms = 0)" "$T_TMP/stderr"
surfgen -q --type sine -n 32 | surfwarp -q --transpose -o ysine.surf
check_status "surfstat on a sine along y: exit 0" 0 surfstat -o ysine.tsv ysine.surf
check "... nayak nan, phi9 defined" [ "$(col ysine.tsv nayak) $(col ysine.tsv phi9)" = "nan 1" ]
check "... warned: no slope along x" grep -q "^surfstat: nayak written as nan: the rms slope along x is 0" "$T_TMP/stderr"
check_status "surfstat on a rough surface: no warning" 0 surfstat -o one-again.tsv one.surf
check "... stderr empty" [ ! -s "$T_TMP/stderr" ]

summary
