#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# readers_corpus.sh - do our readers read a corpus of instrument files as
# Gwyddion does?  For every row of MANIFEST (tab-separated: file
# gwyddion_reads channel title nx ny lx ly xy_unit z_unit masked rms, one
# row per channel Gwyddion reads) whose gwyddion_reads is "yes", reads the
# channel with `surfstat --channels` (size, physical size, units) and
# `surfwarp --channel K` to text (missing points, and the rms about the
# mean of the others, computed here) and prints
#   file channel right | wrong FIELD(ours!=theirs)... | refused REASON
# then per format (file extension) the counts right, wrong, refused.
# A channel whose values are not lengths (deg, V, none) is read with
# --z-unit m so that its rms is computed in its own unit; our z_unit "1"
# (unitless) matches the manifest's empty one.  Sizes compare
# exactly, lengths and rms (in double precision)  to a relative 1e-6.
#   RC_BIN=bin sh bench/readers_corpus.sh DIR MANIFEST
set -u
: "${RC_BIN:?RC_BIN not set}"
DIR=${1:?usage: readers_corpus.sh DIR MANIFEST}
MAN=${2:?usage: readers_corpus.sh DIR MANIFEST}
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rccorpus.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

# The manifest with "-" for an empty field ("read" would merge tabs).
tail -n +2 "$MAN" | awk -F'\t' -v OFS='\t' '{ for (k = 1; k <= 12; k++)
	if ($k == "") $k = "-"; print }' > "$TMP/man"
: > "$TMP/results"
tab=$(printf '\t')
while IFS="$tab" read -r file reads ch title nx ny lx ly xyu zu masked rms; do
	[ "$reads" = yes ] || continue
	f="$DIR/$file"
	case "$zu" in
	m) zopt="" ;;
	-) zopt=""; [ "$xyu" != - ] && zopt="--z-unit m" ;;
	*) zopt="--z-unit m" ;;
	esac
	if ! "$RC_BIN/surfstat" --channels "$f" > "$TMP/ch" 2> "$TMP/err"; then
		verdict="refused $(head -n 1 "$TMP/err" | sed "s|$DIR/||")"
	# shellcheck disable=SC2086
	elif ! "$RC_BIN/surfwarp" -q --channel "$ch" $zopt "$f" -o "$TMP/c.txt" \
	    2> "$TMP/err"; then
		verdict="refused $(head -n 1 "$TMP/err" | sed "s|$DIR/||")"
	else
		verdict=$(awk -v ch="$ch" -v nx="$nx" -v ny="$ny" -v lx="$lx" \
		    -v ly="$ly" -v xyu="$xyu" -v zu="$zu" -v masked="$masked" \
		    -v rms="$rms" '
		function rel(a, b) { if (a == b) return 0; d = a - b; if (d < 0) d = -d;
			if (b < 0) b = -b; return b == 0 ? d : d / b }
		FILENAME == ARGV[1] && FNR > 1 && split($0, c, "\t") && c[1] == ch {
			cnx = c[3]; cny = c[4]; clx = c[5]; cly = c[6]; cu = c[7]; cz = c[8] }
		FILENAME == ARGV[1] { next }
		FILENAME == ARGV[2] && /^#/ { next }
		FILENAME == ARGV[2] { for (k = 1; k <= NF; k++)
			if ($k == "nan") nm++; else { v[++n] = $k; s += $k } }
		END {
			if (cu == "") cu = "-"; if (cz == "") cz = "-"
			m = s / n; for (k = 1; k <= n; k++) q += (v[k] - m) ^ 2
			h = sprintf("%.17g", sqrt(q / n))
			w = ""
			if (cnx != nx || cny != ny) w = w " size(" cnx "x" cny "!=" nx "x" ny ")"
			if (rel(clx, lx) > 1e-6 || rel(cly, ly) > 1e-6)
				w = w " lx,ly(" clx "," cly "!=" lx "," ly ")"
			if (cu != xyu) w = w " unit(" cu "!=" xyu ")"
			if (cz != zu && !(cz == "1" && zu == "-")) w = w " z_unit(" cz "!=" zu ")"
			if (nm + 0 != masked + 0) w = w " masked(" nm + 0 "!=" masked ")"
			if (rms != "nan" && rel(h, rms) > 1e-6) w = w " rms(" h "!=" rms ")"
			print w == "" ? "right" : "wrong" w
		}' "$TMP/ch" "$TMP/c.txt")
	fi
	printf '%s\t%s\t%s\n' "$file" "$ch" "$verdict"
	printf '%s\t%s\n' "${file##*.}" "${verdict%% *}" >> "$TMP/results"
done < "$TMP/man"
printf '\nformat\tright\twrong\trefused\n'
awk -F'\t' '{ n[$1, $2]++; f[$1] = 1 }
END { for (k in f) printf "%s\t%d\t%d\t%d\n", k, n[k, "right"], n[k, "wrong"], n[k, "refused"] }' \
    "$TMP/results" | sort
awk -F'\t' '{ n[$2]++ } END { printf "total\t%d\t%d\t%d\n", n["right"], n["wrong"], n["refused"] }' "$TMP/results"
