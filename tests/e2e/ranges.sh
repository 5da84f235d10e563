#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# ranges.sh - values past what the tools can carry are refused up front
# (issue 27): -p, --pressure-abs and --thickness of 1e300 ran 100000
# iterations to "not converged"; -L on a file with its own size was
# ignored without a word; an x3p's unpacked size had no limit.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

surfgen -q -n 32 --seed 4 -o s4.surf
check_status "-p 1e300: exit 2" 2 gfmd-solve -q -p 1e300 s4.surf
check "  a range error" grep -q -- '-p 1e+300: out of range' "$T_TMP/stderr"
check_status "--pressure-abs 1e300: exit 2" 2 gfmd-solve -q --pressure-abs 1e300 s4.surf
check "  a range error" grep -q -- '--pressure-abs 1e+300: out of range' "$T_TMP/stderr"
check_status "--thickness 1e300: exit 2" 2 \
    gfmd-solve -q -p 0.05 --thickness 1e300 --poisson 0.3 s4.surf
check "  a range error" grep -q -- '--thickness 1e+300: out of range' "$T_TMP/stderr"
# The bounds leave the physical range alone: p* = 1e3 is full contact,
# a layer 1e6 sides thick solves.
gfmd-solve -q -p 1000 -o full.tsv s4.surf
check_rel "-p 1000 solves: a_r = 1" "$(col full.tsv a_r)" 1 0
gfmd-solve -q -p 0.05 --thickness 1e6 --poisson 0.3 -o thick.tsv s4.surf
check_rel "--thickness 1e6 solves" $? 0 0

# Strong short-range adhesion: its convergence test was scaled by the
# law's peak stress (1e5 here, 2e6 times the load), so the flat start
# passed after 0 iterations with one point in contact: a_r = 1/1024 at
# --adhesion 1 against 0.199 at 0.01.  More adhesion never gives less
# contact: a_r is non-decreasing in the adhesion and in the range.
ar() { gfmd-solve -q -p 0.05 "$@" s4.surf 2>/dev/null | awk -F'\t' '
	NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } { print $c["a_r"] }'; }
a0=$(ar) a1=$(ar --adhesion 0.01 --range 1e-5) a2=$(ar --adhesion 1 --range 1e-5)
a3=$(ar --adhesion 1 --range 1e-4)
check "a_r non-decreasing in the adhesion: $a0 <= $a1 <= $a2 <= $a3 (range 1e-5, then 1e-4)" \
    awk -v a="$a0" -v b="$a1" -v c="$a2" -v d="$a3" 'BEGIN { exit !(a > 0 && a <= b && b <= c && c <= d) }'
# -L is for formats that carry no size: said when the file has one.
surfstat -q -L 5 -o st.tsv s4.surf 2> err
check "-L on a file with a size: warned ($(head -c 150 err))" \
    grep -q 's4.surf: -L 5,5 ignored: the file gives its size, 1 x 1' err
check_rel "  and its size used" "$(col st.tsv lx)" 1 0
printf '1 2 3\n4 5 6\n7 8 9\n' > t.txt
surfstat -q -L 5 -o st.tsv t.txt 2> err
check "-L on a file without a size: no warning ($(head -c 150 err))" test ! -s err
check_rel "  and -L used" "$(col st.tsv lx)" 5 0

# x3p: the memory a file unpacks to is computed first; past
# RC_X3P_MAX_MB (MiB) it is refused, naming the cost; raised, it reads.
# 1024^2 float64: 8 + 8 + 1 + 1/8 bytes a point = 17.125 MiB.
surfgen -q -n 1024 -o big.x3p
RC_X3P_MAX_MB=16 surfstat -q big.x3p > /dev/null 2> err
check_rel "x3p past RC_X3P_MAX_MB: exit 1" $? 1 0
check "  names the cost and the variable ($(head -c 200 err))" \
    grep -q 'unpack to 18 MiB of memory, past the limit of 16 MiB; to read it, set RC_X3P_MAX_MB=18' err
check_status "  raised, it reads" 0 env RC_X3P_MAX_MB=18 surfstat -q big.x3p
check_status "RC_X3P_MAX_MB not a number: exit 1" 1 env RC_X3P_MAX_MB=lots surfstat -q big.x3p
summary
