# outputs.sh - at most one output goes to standard output, binary never to
# a terminal; the refusal is a usage error (exit 2) that writes nothing.
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
summary
