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
summary
