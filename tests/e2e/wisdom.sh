#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# wisdom.sh - FFT planning options: --fft-effort, --wisdom FILE, RC_WISDOM.
# A measured plan computes the same transform as the estimated one, so the
# surfaces agree to round-off (1e-12 of the largest height: a 64^2
# transform adds ~10^2 terms per output, each rounded at 1e-16); the
# wisdom file is FFTW's text format; a file that is not wisdom is refused
# (exit 1) and left untouched, never overwritten.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

values() { grep -v '^#' "$1" | tr -s ' \t' '\n\n' | grep -v '^$'; }
max_rel_diff() {
	values "$1" >a.val; values "$2" >b.val
	paste a.val b.val | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > md) md = d
		m = $1 < 0 ? -$1 : $1; if (m > mx) mx = m } END { print md / mx }'
}

check_status "surfgen --fft-effort measure --wisdom" 0 \
    surfgen -q -n 64 --fft-effort measure --wisdom w.wis -o m.txt
check "the wisdom file is FFTW wisdom" grep -q '^(fftw-3' w.wis
surfgen -q -n 64 -o e.txt
check_range "measured and estimated plans agree" "$(max_rel_diff m.txt e.txt)" 0 1e-12
cp w.wis w0.wis
check_status "RC_WISDOM names the file" 0 env RC_WISDOM=w.wis surfgen -q -n 64 \
    --fft-effort measure -o m2.txt
values m.txt >m.val; values m2.txt >m2.val
check "wisdom reused: the same plan, the same values" cmp -s m.val m2.val
check_status "surfstat --wisdom" 0 surfstat -q --fft-effort measure --wisdom w.wis \
    -o st.tsv m.txt
check "surfstat added its plans to the wisdom" sh -c '! cmp -s w.wis w0.wis'
# not wisdom: refused and left alone
cp m.txt notwisdom.txt
check_status "a non-wisdom file is refused" 1 surfgen -q -n 64 --wisdom notwisdom.txt \
    -o x.txt
check "and left untouched" cmp -s m.txt notwisdom.txt
check_status "RC_WISDOM naming a non-wisdom file is refused" 1 \
    env RC_WISDOM=notwisdom.txt surfstat -q -o x.tsv m.txt
check_status "--fft-effort bogus: usage" 2 surfgen -n 8 --fft-effort bogus -o x.txt
check_status "--fft-effort wisdom is internal: usage" 2 surfstat --fft-effort wisdom m.txt
check_status "--wisdom -: usage" 2 surfgen -n 8 --wisdom - -o x.txt
# a missing wisdom file is created only when something was measured
check_status "estimate with --wisdom" 0 surfgen -q -n 64 --wisdom new.wis -o x.txt
check "no measured plan, no wisdom file" test ! -e new.wis
# a device that never ends (it was read forever): refused, any tool
for dev in /dev/zero /dev/full; do
	[ -r "$dev" ] || { skip 1 "$dev not readable"; continue; }
	check_status "--wisdom $dev is refused" 1 timeout 60 surfgen -q -n 8 \
	    --wisdom "$dev" -o x.txt
	check_status "RC_WISDOM=$dev is refused" 1 env RC_WISDOM="$dev" \
	    timeout 60 surfstat -q -o x.tsv m.txt
done
check_status "--wisdom /dev/null: no wisdom yet, like an empty file" 0 \
    surfgen -q -n 8 --wisdom /dev/null -o x.txt
summary
