#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# tsv.sh - a benchmark's output as Markdown: each "# comment" line (and
# any other line without a tab) as a paragraph, each run of tab-separated
# lines as a table, its first line the header; with ERE, only the data
# rows that match it (headers and comments are kept).
#   COMMAND | sh doc/tsv.sh [ERE]
pat=${1:-}
awk -v pat="$pat" '
function endtable() { intable = 0 }
/\t/ {
	if (!intable) {
		intable = 1; n = split($0, h, "\t")
		print ""; line = "|"; sep = "|"
		for (i = 1; i <= n; i++) { line = line " " h[i] " |"; sep = sep "---|" }
		print line; print sep; next
	}
	if (pat != "" && $0 !~ pat) next
	gsub(/\t/, " | "); print "| " $0 " |"; next
}
/^[ \t]*$/ { endtable(); next }
{ endtable(); sub(/^# */, ""); print ""; print $0 }
'
