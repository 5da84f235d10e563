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
summary
