# outputs.sh - at most one output goes to standard output, binary never to
# a terminal; the refusal is a usage error (exit 2) that writes nothing.
# An output may be its input where it is the same kind of thing (surfwarp
# -o in.surf in.surf); an output of another kind that names an input (a
# table over the surface, a PNG over rows) is refused, also through another
# path to the same file, and the input is left as it was.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1
surfgen -n 16 -o s.surf
check_status "surfgen --png - with the grid on stdout" 2 surfgen -n 16 --png -
check_status "surfwarp --png - with the grid on stdout" 2 surfwarp --png - s.surf
check_status "surfstat --psd2d - with the table on stdout" 2 surfstat --psd2d - s.surf
check_status "surfstat --gnuplot - with the table on stdout" 2 surfstat --psd --gnuplot - s.surf
check_status "contact-stats --gnuplot - with the table on stdout" 2 contact-stats --gnuplot - /dev/null
# One of them on stdout is fine: a real PNG comes out.
surfgen -n 16 --png - -o t.surf > p.png
check "surfgen --png - alone writes a PNG" [ "$(head -c 4 p.png | od -An -c | tr -d ' ')" = "211PNG" ]
# Binary to a terminal is refused (script(1) gives the tool a terminal).
if command -v script >/dev/null 2>&1; then
	script -qec "surfgen -n 8 --png - -o u.surf" /dev/null > tty.out 2>&1
	check "surfgen --png - to a terminal is refused" grep -q "terminal; refusing" tty.out
	check "nothing written when refused" [ ! -e u.surf ]
fi

# --- outputs against inputs ------------------------------------------------
surfgen -n 32 --seed 4 -o h.surf
cp h.surf keep.surf
surfwarp -w 2 -o w.surf h.surf
cp h.surf inplace.surf
surfwarp -w 2 -o inplace.surf inplace.surf
# the 32 x 32 float64 values (the headers differ in their history lines)
tail -c 8192 w.surf > fresh.bin
tail -c 8192 inplace.surf > inplace.bin
check "surfwarp -o equal to its input: the same heights as a fresh output" \
    cmp -s fresh.bin inplace.bin
check_status "surfstat -o the input" 2 surfstat -o h.surf h.surf
check_status "surfstat --psd2d the input, through ./" 2 surfstat --psd2d ./h.surf h.surf
check_status "surfstat -o the mask" 2 surfstat -o keep.surf --mask keep.surf h.surf
check_status "gfmd-solve -o the indenter" 2 gfmd-solve -p 0.1 -o h.surf h.surf
check_status "gfmd-solve --gap the indenter" 2 gfmd-solve -p 0.1 --gap h.surf h.surf
check_status "gfmd-solve --checkpoint the indenter" 2 gfmd-solve -p 0.1 --checkpoint h.surf h.surf
check_status "surfwarp --png the input" 2 surfwarp -w 1 --png h.surf h.surf
check "every refusal left the input as it was" cmp -s h.surf keep.surf
gfmd-solve -q -p 0.1 -o rows.tsv h.surf
cp rows.tsv rows.keep
check_status "contact-stats -o an input" 2 contact-stats --no-extrapolate -o rows.tsv rows.tsv
check "contact-stats left its input as it was" cmp -s rows.tsv rows.keep
summary
