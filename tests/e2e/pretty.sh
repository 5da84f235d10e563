# SPDX-License-Identifier: GPL-3.0-or-later
# pretty.sh - tables on a terminal: aligned and rounded when standard
# output is a terminal (a pty made by script(1)) or with --pretty; the
# exact TSV when piped, byte for byte what -o writes.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
surfgen -n 32 --seed 5 -o s.surf
gfmd-solve -q -p 0.02,0.05 -o rows.tsv s.surf

# Piped: the TSV of -o, except the timing columns.
drop_times() { awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i ~ /seconds/) skip[i] = 1 }
    { line = ""; for (i = 1; i <= NF; i++) if (!skip[i]) line = line $i "\t"; print line }' "$1"; }
surfstat -o st.tsv s.surf
surfstat s.surf | cat > st-pipe.tsv
drop_times st.tsv > a; drop_times st-pipe.tsv > b
check "surfstat piped: the TSV of -o" cmp -s a b
check "surfstat piped: tab-separated, 2 lines" [ "$(awk -F'\t' 'NF > 30' st-pipe.tsv | wc -l)" -eq 2 ]
contact-stats --no-extrapolate -o cs.tsv rows.tsv
contact-stats --no-extrapolate rows.tsv | cat > cs-pipe.tsv
check "contact-stats piped: the TSV of -o" cmp -s cs.tsv cs-pipe.tsv

if have_pty; then
	# On a terminal: the pretty view (35 columns: transposed, one line
	# per column), hrms rounded to 4 significant digits.
	script -qc "surfstat s.surf" /dev/null | tr -d '\r' > st-tty.txt
	check "surfstat on a terminal: no tabs" sh -c "! grep -q '	' st-tty.txt"
	hrms=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "hrms") c = i } NR == 2 { printf "%.4g", $c }' st.tsv)
	check "surfstat on a terminal: hrms rounded to 4 digits ($hrms)" \
	    grep -Eq "^hrms +$hrms\$" st-tty.txt
	check "surfstat on a terminal: one line per column" \
	    [ "$(wc -l < st-tty.txt)" -eq "$(awk -F'\t' 'NR == 1 { print NF }' st.tsv)" ]
	check "values right-aligned in one column" \
	    [ "$(awk '{ print length($0) }' st-tty.txt | sort -u | wc -l)" -eq 1 ]
	check "integers whole (nx 32)" grep -Eq '^nx +32$' st-tty.txt
else
	skip 5 "script(1) not installed or no pseudo-terminal here (/dev/pts): no pty test (apt-get install bsdutils)"
fi

# --pretty into a pipe, wide enough for columns: every numeric column's
# values end where its header ends (right-aligned), a rule under the header.
COLUMNS=2000 gfmd-solve -q --pretty -p 0.02,0.05 s.surf > pretty.txt
check "--pretty: header, rule, 2 rows" [ "$(wc -l < pretty.txt)" -eq 4 ]
check "--pretty: a rule of dashes under the header" grep -Eq '^-+$' pretty.txt
check "--pretty: no tabs" sh -c "! grep -q '	' pretty.txt"
bad=$(awk 'NR == 1 { h = $0; next } NR == 2 { next }
    { n = split("p_star p a_r n_c kappa iterations", want, " ")
      for (k = 1; k <= n; k++) {
	e = 0
	# the end of the header word want[k], a whole word
	for (s = 1; s <= length(h); s++)
		if (substr(h, s, length(want[k])) == want[k] &&
		    (s == 1 || substr(h, s - 1, 1) == " ") &&
		    substr(h, s + length(want[k]), 1) ~ /^( |)$/) { e = s + length(want[k]) - 1; break }
	if (!e || substr($0, e, 1) == " " || substr($0, e + 1, 1) !~ /^( |)$/) print want[k]
      } }' pretty.txt | sort -u | tr '\n' ' ')
check "--pretty: numeric columns right-aligned under their headers (bad: ${bad:-none})" [ -z "$bad" ]
a_r=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "a_r") c = i } NR == 2 { printf "%.4g", $c }' rows.tsv)
check "--pretty: a_r rounded ($a_r)" grep -q " $a_r " pretty.txt
# Narrow: transposed, both rows side by side.
COLUMNS=60 gfmd-solve -q --pretty -p 0.02,0.05 s.surf > narrow.txt
check "--pretty narrow: transposed, row labels" grep -Eq '^ +row 1 +row 2$' narrow.txt
check "--pretty narrow: no line wider than 60" [ "$(awk '{ if (length($0) > m) m = length($0) } END { print m }' narrow.txt)" -le 60 ]
COLUMNS=22 contact-stats --pretty --no-extrapolate rows.tsv > narrower.txt
check "--pretty narrower than two rows: one row per block" \
    [ "$(grep -c '^ *row [0-9]*$' narrower.txt)" -eq 2 ]
# --json wins over --pretty; JSON is never made pretty.
surfstat --pretty --json s.surf > st.json
check "--pretty --json: JSON" grep -q '^\[' st.json
summary
