# SPDX-License-Identifier: GPL-3.0-or-later
# docs.sh - examples printed in the manual pages are what the tools do.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
# surf(5): the example header is surfgen's, byte for byte, and its sizes.
awk '/^\.Bd -literal/ && !done { on = 1; next } on && /^\.Ed/ { on = 0; done = 1 } on' \
    "$RC_TOP/man/man5/surf.5" > want.txt
surfgen -n 256 -H 0.8 --lambda-r 0.5 --lambda-s 0.015625 --seed 42 -o rough.surf
head -c 1000 rough.surf | sed '/^end_header/q' | sed 's/ *$//' > got.txt
check "surf(5) example header equals surfgen's output" cmp -s want.txt got.txt
size=$(wc -c < rough.surf)
check "surf(5) states the file size ($size bytes)" grep -q "the file has $size" "$RC_TOP/man/man5/surf.5"
# README's pipeline runs as written (its five lines).
awk '/^## A pipeline/ { on = 1; next } on && /^## / { exit } on && /^    / { sub(/^    /, ""); print }' \
    "$RC_TOP/README.md" > pipeline.sh
check "README pipeline has 5 lines" [ "$(wc -l < pipeline.sh)" -eq 5 ]
check "README pipeline runs" sh -e pipeline.sh > pipeline.out 2>&1
# ...for a newcomer whose PATH has no tools: the README says, before the
# pipeline, how to put them there; run its export line from a tree whose
# bin/ holds the tools under test, with a PATH that has none of them.
export_line=$(awk '/^## A pipeline/ { on = 1; next } on && /^    / { exit }
    on' "$RC_TOP/README.md" | grep -o 'export PATH="[^`]*"')
check "README says how the tools get on PATH before the pipeline" [ -n "$export_line" ]
check "README mentions make install PREFIX= before the pipeline" \
    sh -c "awk '/^## A pipeline/ { on = 1; next } on && /^    / { exit } on' '$RC_TOP/README.md' | grep -q 'make install PREFIX='"
mkdir -p newcomer && ln -s "$RC_BIN" newcomer/bin
check "README pipeline runs after its export line, PATH without the tools" \
    sh -c "cd newcomer && PATH=/usr/bin:/bin && $export_line && sh -e ../pipeline.sh" \
    > pipeline2.out 2>&1
check "without it the pipeline fails (command not found)" \
    sh -c "cd newcomer && ! PATH=/usr/bin:/bin sh -e ../pipeline.sh" > /dev/null 2>&1

# Every option --help lists is in the manual page, and every option the
# page describes (.It Fl) is in --help: the two are written together.
for t in surfgen surfwarp surfstat gfmd-solve contact-stats; do
	man="$RC_TOP/man/man1/$t.1"
	"$t" --help 2>&1 | grep -o -- '--[a-z][a-z0-9-]*' | sort -u > help.opts
	grep -o 'Fl -[a-z][a-z0-9-]*' "$man" | sed 's/^Fl -/--/' | sort -u > man.opts
	grep '^\.It Fl -' "$man" | grep -o 'Fl -[a-z][a-z0-9-]*' | sed 's/^Fl -/--/' | sort -u > man.items
	missing=$(comm -23 help.opts man.opts | tr '\n' ' ')
	check "$t: every --help option is in $t(1) (missing: ${missing:-none})" [ -z "$missing" ]
	extra=$(comm -13 help.opts man.items | tr '\n' ' ')
	check "$t: every option $t(1) describes is in --help (extra: ${extra:-none})" [ -z "$extra" ]
done
# Every column of the result tables is in the tool's page, except the
# surface's metadata columns (meta.* in its header), which are carried.
surfgen -n 32 --type harmonic -o h32.surf
surfgen -n 64 --type harmonic -o h64.surf
sed -n 's/^meta\.\([a-z_]*\) =.*/\1/p' h32.surf > meta.cols
gfmd-solve -q -p 0.1,0.2 -o r32.tsv h32.surf
gfmd-solve -q -p 0.1,0.2 -o r64.tsv h64.surf
contact-stats -o cs.tsv r32.tsv r64.tsv
surfstat -o st.tsv h32.surf
surfstat --iso -o iso.tsv h32.surf
surfstat --psd1d x -o p1.tsv h32.surf
surfstat --acf --acf-half -o acf.tsv h32.surf
surfstat --material-ratio 4 -o mr.tsv h32.surf
surfgen -n 64 --lambda-r 0.25 --rolloff -o sa64.surf
surfstat --fit -o fit.tsv sa64.surf
for pair in gfmd-solve:r32.tsv surfstat:st.tsv contact-stats:cs.tsv \
    surfstat:iso.tsv surfstat:p1.tsv surfstat:acf.tsv surfstat:mr.tsv surfstat:fit.tsv; do
	t=${pair%%:*}; f=${pair#*:}
	missing=$(head -n 1 "$f" | tr '\t' '\n' | grep -v -x -F -f meta.cols |
	    while read -r c; do grep -q -w -- "$c" "$RC_TOP/man/man1/$t.1" || printf '%s ' "$c"; done)
	check "$t: every output column is in $t(1) (missing: ${missing:-none})" [ -z "$missing" ]
done
# One citation of the paper everywhere: every reference block to it in the
# manual pages is the same (authors, title, journal, volume, page, year),
# and README and studies/README give the same title.
M=$RC_TOP/man
for f in "$M"/man*/*.[157]; do
	awk '/^\.Rs/ { b = ""; on = 1 } on { b = b $0 "\n" } /^\.Re/ && on { on = 0; if (b ~ /%A A\. Wang\n/) printf "%s", b }' "$f"
done | awk '/^\.Rs/ { n++ } { blk[n] = blk[n] $0 "\n" } END { for (i = 2; i <= n; i++) if (blk[i] != blk[1]) bad++; print n, bad + 0 }' > cite.txt
read -r ncite nbad < cite.txt
check "the paper's reference blocks in the man pages are identical ($ncite blocks, $nbad differ)" \
    sh -c "[ $ncite -ge 6 ] && [ $nbad -eq 0 ]"
title='Effect of Structural Parameters on the Relative Contact Area for Ideal, Anisotropic, and Correlated Random Roughness'
check "the man pages' title is the paper's" grep -q "^\.%T $title\$" "$M/man1/surfgen.1"
check "no other spelling of the first author (L. Wang, Anle Wang)" \
    sh -c "! grep -rq -e '%A L\. Wang' -e 'Anle Wang' '$M'"
check "no other title (On the Structural Parameters ...)" \
    sh -c "! grep -rqi 'On the Structural Parameters Controlling' '$M' '$RC_TOP/README.md'"
for f in README.md studies/README.md; do
	check "$f cites the same title" \
	    sh -c "tr '\n' ' ' < '$RC_TOP/$f' | tr -d '*>' | tr -s ' ' | grep -q '$title'"
done
check "gfmd-solve(1): FIRE-GFMD is Zhou, Moseler, Mueser, Phys. Rev. B 99, 144103 (2019)" \
    sh -c "awk '/^\.Rs/ { b = \"\" } { b = b \$0 \"|\" } /^\.Re/ && b ~ /Moseler/ { print b }' '$M/man1/gfmd-solve.1' |
	grep -q '%A Y. Zhou|.%A M. Moseler|.%A M. H. M.*%J Phys. Rev. B|.%V 99|.%P 144103|.%D 2019'"
# One date on all pages; no up-arrows for superscripts.
check "one .Dd date on every page ($(cat "$M"/man*/*.[157] | grep '^\.Dd' | sort -u | tr '\n' ' '))" \
    [ "$(cat "$M"/man*/*.[157] | grep '^\.Dd' | sort -u | wc -l)" -eq 1 ]
check "no \\(ua (an arrow) used as a superscript" sh -c "! grep -q '\\\\(ua' '$M'/man*/*.[157]"
# One memory figure for gfmd-solve: README, gfmd-solve(1), roughcontact(7).
readme_b=$(tr '\n' ' ' < "$RC_TOP/README.md" | grep -o 'gfmd-solve needs [0-9–-]* bytes per' | grep -o '[0-9–-]*[0-9]')
man1_b=$(tr '\n' ' ' < "$M/man1/gfmd-solve.1" | grep -o 'Memory is about [0-9]* bytes per' | grep -o '[0-9][0-9]*')
man7_b=$(grep '^\.It gfmd-solve (FIRE or CG) Ta' "$M/man7/roughcontact.7" | grep -o '[0-9][0-9]*$')
check "gfmd-solve's bytes per point agree (README $readme_b, gfmd-solve(1) $man1_b, roughcontact(7) $man7_b)" \
    sh -c "[ -n '$readme_b' ] && [ '$readme_b' = '$man1_b' ] && [ '$man1_b' = '$man7_b' ]"
# The manual pages are references: each renders to at most 600 lines
# (80 columns); the measured record is in doc/, made by make doc.
if command -v mandoc >/dev/null 2>&1; then
	long=$(for m in "$M"/man*/*.[1-9]; do
		n=$(MANWIDTH=80 mandoc -Tutf8 "$m" | wc -l)
		[ "$n" -le 600 ] || printf '%s %s ' "$(basename "$m")" "$n"
	done)
	check "every manual page renders to at most 600 lines (over: ${long:-none})" [ -z "$long" ]
else
	skip 1 "mandoc not installed: the pages' rendered length"
fi
# Every document a page or README points to exists, and so does each
# doc/NAME.md of a template; a made document holds every generated
# section of its template, each non-empty and closed, and the rest of it
# is the template's text (a template edited without make doc is caught).
refs=$(cat "$M"/man*/*.[1-9] "$RC_TOP/README.md" | grep -o 'doc/[a-z_-]*\.md' | sort -u)
missing=$(for d in $refs; do [ -f "$RC_TOP/$d" ] || printf '%s ' "$d"; done)
check "the documents the pages and README name exist ($(echo $refs); missing: ${missing:-none})" \
    sh -c "[ -n '$refs' ] && [ -z '$missing' ]"
for in in "$RC_TOP"/doc/*.md.in; do
	md=${in%.in}; name=$(basename "$md")
	check "doc/$name is made (make doc)" [ -f "$md" ]
	[ -f "$md" ] || continue
	nin=$(grep -c '^<!-- generated: .* -->$' "$in")
	awk '/^<!-- generated: .* -->$/ { print; on = 1; n = 0; next }
	    on && /^<!-- end generated -->$/ { on = 0; if (n == 0) print "EMPTY"; next }
	    on { if ($0 != "") n++; next } { print }' "$md" > doc.text
	# the footer (a blank line and the "Generated by" line) is not the template's
	sed -e '$d' doc.text | sed -e '$d' > doc.body
	check "doc/$name: its $nin generated sections are there, each with output" \
	    sh -c "[ $nin -gt 0 ] && [ \$(grep -c '^<!-- end generated -->\$' '$md') -eq $nin ] && ! grep -q '^EMPTY\$' doc.text"
	check "doc/$name: the text outside them is its template's (make doc after editing $name.in)" \
	    cmp -s doc.body "$in"
	check "doc/$name says when and from what it was made" grep -q '^Generated by `make doc` on ' "$md"
done

# The licence: every source, script and build file says it in an SPDX
# line near its top, every manual page has a LICENSE section, and the
# text is in the tree.
check "LICENSE is the GPL version 3" grep -q "GNU GENERAL PUBLIC LICENSE" "$RC_TOP/LICENSE"
missing=$(cd "$RC_TOP" && for f in lib/*.[ch] lib/*/*.[ch] tools/*.[ch] tools/mpi/*.[ch] \
    tests/*.[ch] tests/e2e/*.sh bench/*.c bench/*.sh doc/*.sh Makefile studies/*/Makefile; do
	[ -f "$f" ] || continue
	head -n 3 "$f" | grep -q 'SPDX-License-Identifier: GPL-3.0-or-later' || echo "$f"
done)
check "every source file has an SPDX line (missing: $(echo $missing | head -c 200))" [ -z "$missing" ]
nolic=$(for m in "$M"/man*/*.[1-9]; do grep -q '^\.Sh LICENSE' "$m" || basename "$m"; done)
check "every manual page has a LICENSE section (missing: $(echo $nolic))" [ -z "$nolic" ]
summary
