# SPDX-License-Identifier: GPL-3.0-or-later
# text.sh - text exports through the tools, against what SurfaceTopography's
# tests expect of the same files (tests/data/st_*, see st_text.README):
# its German Gwyddion export (12.34 um by 5678.9 nm, heights as in the
# file), its UTF-16 CSV with an index column (8 points), its one-column
# profile (heights 1..9, length from -L); gzip and UTF-16 through a pipe;
# its Mitutoyo workbook mocks and non-uniform xy-2.txt (as they are, or
# --uniform);
# an HDF5 file that is not in the contact.engineering layout is named so.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
D=$RC_TOP/tests/data

# refused DESC PATTERN CMD...: exit 1 and a message matching PATTERN (grep -E)
refused() {
	d=$1; pat=$2; shift 2
	"$@" >/dev/null 2>"$T_TMP/err"; got=$?
	if [ "$got" = 1 ] && grep -Eq "$pat" "$T_TMP/err"; then
		pass "$d"
	else
		fail "$d: exit $got, message '$(head -c 300 "$T_TMP/err")'"
	fi
}
# chan FILE COLUMN: a column of surfstat --channels (first channel)
chan() {
	surfstat --channels "$1" | awk -F'\t' -v name="$2" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
		NR == 2 { print $c[name] }'
}

g=$D/st_gwyddion-export-german.txt
check "German export: 3 x 4" [ "$(chan "$g" nx) $(chan "$g" ny)" = "3 4" ]
check "German export: Breite 12.34 um" [ "$(chan "$g" lx)" = 12.34 ]
check "German export: Hoehe 5678.9 nm = 5.6789 um" [ "$(chan "$g" ly)" = 5.6789 ]
check "German export: channel 'My Channel Name'" [ "$(chan "$g" title)" = "My Channel Name" ]
surfwarp -q --unit m "$g" -o g.txt
check "German export: the heights of the file in m, row by row" \
	[ "$(grep -v '^#' g.txt | tr '\n' ' ')" = "1 1.5 3 -2 -3 -6 0 0 0 9 9 9 " ]

c=$D/st_csv-2.csv
check "UTF-16 CSV with an index column: 8 points" [ "$(chan "$c" nx) $(chan "$c" ny)" = "8 1" ]
check "UTF-16 CSV: x in um" [ "$(chan "$c" unit) $(chan "$c" z_unit)" = "um um" ]
check "UTF-16 CSV: the same through gzip and a pipe" \
	[ "$(gzip -c "$c" | surfstat --channels -)" = "$(surfstat --channels "$c")" ]

s=$D/st_single_column.txt
surfwarp -q -L 2.3 "$s" -o s.txt
check "one column: a profile of 9 points" [ "$(chan s.txt nx) $(chan s.txt ny)" = "9 1" ]
check "one column: -L 2.3 is its length" [ "$(chan s.txt lx)" = 2.3 ]
check "one column: heights 1..9" [ "$(grep -v '^#' s.txt | tr '\n' ' ')" = "1 2 3 4 5 6 7 8 9 " ]

# SurfaceTopography's Mitutoyo SurfTest mock (test/io/test_mitutoyo.py):
# 960 points, 480 um, heights in um of rms 0.16866328079293708 (about
# their mean: surfstat's Sq); the non-uniform mock and xy-2.txt read
# by surfstat as they are (its rms 0.1371261153644389 um), by the tools
# that need a grid only with --uniform.
m=$D/st_mitutoyo_mock.xlsx
check "Mitutoyo workbook: 960 x 1 points" [ "$(chan "$m" nx) $(chan "$m" ny)" = "960 1" ]
check "Mitutoyo workbook: 0.48 mm, heights in um" [ "$(chan "$m" lx) $(chan "$m" unit) $(chan "$m" z_unit)" = "0.48 mm um" ]
surfstat -q --unit um --iso "$m" >m.tsv
check_rel "Mitutoyo workbook: Sq = SurfaceTopography's rms" "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } { print $c["Sq"] }' m.tsv)" 0.16866328079293708 1e-12
refused "Mitutoyo non-uniform mock: gfmd-solve refuses it naming --uniform" 'x is not uniformly spaced.*--uniform' gfmd-solve -p 0.01 "$D/st_mitutoyo_nonuniform_mock.xlsx"
check_rel "... surfstat's hrms as it is: SurfaceTopography's 0.1371261153644389 um" "$(surfstat -q --unit um "$D/st_mitutoyo_nonuniform_mock.xlsx" | awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } { print $c["hrms"] }')" 0.1371261153644389 1e-12
check "... read with --uniform: 960 points over 0.48 mm" [ "$(surfstat --uniform --channels "$D/st_mitutoyo_nonuniform_mock.xlsx" | awk -F'\t' 'NR == 2 { print $3, $5 }')" = "960 0.48" ]
refused "xy-2.txt (x-z in um, not uniform): gfmd-solve refuses it naming --uniform" '[-]-uniform resamples' gfmd-solve -p 0.01 "$D/st_xy-2.txt"
check "... with --uniform: 24 points, in um" [ "$(surfstat --uniform --channels "$D/st_xy-2.txt" | awk -F'\t' 'NR == 2 { print $3, $7 }')" = "24 um" ]

# The nonsense text of SurfaceTopography's examples, written here.
printf 'This is nonsense. Should raise CannotDetectFileFormat.' > n.txt
refused "prose is not a height file" 'is text and no numbers follow' surfstat n.txt

if command -v ncgen >/dev/null 2>&1; then
	# 2-D data sets are channels (netcdf.sh); a 3-D one alone is not
	printf 'netcdf d {\ndimensions:\n a = 2 ;\n b = 3 ;\n c = 1 ;\nvariables:\n double dataset1(a, b, c) ;\ndata:\n dataset1 = 1, 2, 3, 4, 5, 6 ;\n}\n' > d.cdl
	ncgen -k nc4 -o d.h5 d.cdl
	refused "HDF5 with no 1-D or 2-D data set: said, with h5ls" \
		'an HDF5 file .*h5ls' surfstat d.h5
fi
# --channels says mask "yes" where points are missing as NaN (a read
# turns them into a mask; the listing said "no" for text, .surf, .npy).
printf '1 2\nnan 4\n' >nanpt.txt
printf '1 2\n3 4\n' >nonan.txt
check "--channels: NaN in a text grid is a mask" [ "$(surfstat --channels nanpt.txt | awk -F'\t' 'NR == 2 { print $9 }')" = yes ]
check "--channels: no NaN, no mask" [ "$(surfstat --channels nonan.txt | awk -F'\t' 'NR == 2 { print $9 }')" = no ]
surfwarp -q -o nanpt.surf nanpt.txt
check "--channels: .surf with a missing point is a mask" [ "$(surfstat --channels nanpt.surf | awk -F'\t' 'NR == 2 { print $9 }')" = yes ]
# A value the reader does not take is an error naming it: also on the
# first line of a profile (it was taken for a column name, the first
# point dropped without a word), and 1.#QNAN (MSVC's NaN) was read as 1
# and a comment.
printf '1e400\n2\n3\n4\n' >big1.txt
printf '1.#QNAN\n2\n3\n4\n' >qnan1.txt
printf '1 2\n1.#QNAN 4\n' >qnan2.txt
printf '1 2\n3 4#c\n' >hash.txt
for f in big1:1e400 qnan1:1.#QNAN qnan2:1.#QNAN hash:4#c; do
	check_status "${f%%:*}.txt: refused" 1 surfstat -q "${f%%:*}.txt"
	check "  names '${f#*:}'" grep -qF "'${f#*:}' is not a number" "$T_TMP/stderr"
done
printf '1 2 # a comment\n3 4,# another\n' >cmt.txt
surfwarp -q -o cmt.out.txt cmt.txt
check "a '#' after a blank or separator is a comment" [ "$(grep -v '^#' cmt.out.txt | tr '\n' ' ')" = "1 2 3 4 " ]
# Messages that say what is wrong: one point of x-z columns (the rest
# comments, as a '#N/A' line) said "cell size 0x0"; an all-NaN map's
# --iso said "no valid point" without the file.
printf 'a,b\n1,2\n#N/A,3\n' >na.csv
check_status "x-z columns of one point: refused" 1 surfstat -q na.csv
check "  said so" grep -q "na.csv: one point in x-z columns" "$T_TMP/stderr"
printf 'nan nan\nnan nan\n' >allnan.txt
check_status "--iso of a map without a valid point: exit 1" 1 surfstat -q --iso allnan.txt
check "  names the file" grep -q "allnan.txt: no valid point: every height is missing" "$T_TMP/stderr"
summary
