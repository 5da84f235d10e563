#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# threads.sh - results do not depend on the thread count: every tool run
# with -j 1 and -j 2 (and OMP_NUM_THREADS instead of -j) must agree.
#   surfgen: bit for bit (its reductions are summed in a fixed order and
#     its FFT plan, ESTIMATE, does the same arithmetic for any thread count).
#   surfstat: every statistic to 1e-12 relative (OpenMP reductions add in
#     an order that depends on the thread count; 1e-12 is 10^4 times the
#     round-off of a sum of 10^4 terms of one sign, and far below any
#     digit anyone reads).
#   gfmd-solve (FIRE and CG): the contact area identical or within one
#     contact point (a point at the contact threshold may flip on
#     round-off); the gap field within 1e-6 of its maximum, the order of
#     the solver tolerance (the two methods themselves agree to 1.3e-7 here,
#     thread counts to 3e-14).
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

# data values of a .txt grid, one per line
values() { grep -v '^#' "$1" | tr -s ' \t' '\n\n' | grep -v '^$'; }

# max |a - b| of two .txt grids, relative to max |a|
field_diff() {
	values "$1" >a.val; values "$2" >b.val
	paste a.val b.val | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > md) md = d
		m = $1 < 0 ? -$1 : $1; if (m > mx) mx = m }
		END { print (mx > 0 ? md / mx : md) }'
}

# every numeric column of two one-header TSV tables agrees to REL, except
# the timing columns
tables_agree() {
	awk -F'\t' -v rel="$3" 'NR == FNR { if (FNR == 1) for (i = 1; i <= NF; i++) h[i] = $i
			else a[FNR, 0] = NF
			for (i = 1; i <= NF; i++) a[FNR, i] = $i; next }
		FNR == 1 { next }
		{ for (i = 1; i <= NF; i++) {
			if (h[i] ~ /seconds/) continue
			x = a[FNR, i]; y = $i
			if (x == y) continue
			if (x + 0 != x || y + 0 != y) { bad++; print h[i] ": " x " vs " y; continue }
			s = x < 0 ? -x : x; d = x - y; if (d < 0) d = -d
			if (d > rel * s) { bad++; print h[i] ": " x " vs " y }
		} }
		END { exit bad > 0 }' "$1" "$2"
}

# --- surfgen: bit for bit --------------------------------------------------
for args in "-n 256x192 --seed 7" "-n 200 -H 0.5 --peklenik 2 --rolloff" \
    "-n 128 --type harmonic --rms-gradient 0.3" "-n 96 --type eggbox --wavelength 0.25 --rms-height 1"; do
	surfgen -j 1 $args -o s1.npy && surfgen -j 2 $args -o s2.npy &&
	    OMP_NUM_THREADS=2 surfgen $args -o s3.npy
	check "surfgen $args: -j 1 and -j 2 bit for bit" cmp -s s1.npy s2.npy
	check "surfgen $args: OMP_NUM_THREADS=2 bit for bit" cmp -s s1.npy s3.npy
done

# --- surfstat: to 1e-12 ----------------------------------------------------
surfgen -n 256 --seed 3 -H 0.7 -o s.surf
surfgen -n 256 --type harmonic -o mask_src.surf
for opt in "" "--fd" "--psd" "--acf" "--by-height 8"; do
	surfstat -j 1 $opt -o t1.tsv s.surf && surfstat -j 2 $opt -o t2.tsv s.surf
	check "surfstat $opt: -j 1 and -j 2 agree to 1e-12" tables_agree t1.tsv t2.tsv 1e-12
done
# the scalars carry the planning and compute times separately
surfstat -q -o t.tsv s.surf
check_range "surfstat: plan_seconds column" "$(col t.tsv plan_seconds)" 0 1e9
check_range "surfstat: seconds column" "$(col t.tsv seconds)" 0 1e9
# gfmd-solve: the set-up (planning) time once per process, the same on
# every row, apart from each solve's own time
surfgen -n 64 --seed 2 | gfmd-solve -q -p 0.02,0.05 -o t.tsv
check_rel "gfmd-solve: one plan_seconds for every row" \
    "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "plan_seconds") c = i; next }
	{ v[$c] = 1 } END { for (x in v) n++; print n }' t.tsv)" 1 0
check_range "gfmd-solve: plan_seconds column" "$(col t.tsv plan_seconds | head -1)" 0 1e9

# --- gfmd-solve, both methods ----------------------------------------------
surfgen -n 128 --seed 5 -o h.surf
for m in fire cg; do
	for j in 1 2; do
		gfmd-solve -q -j $j --method $m -p 0.02,0.1 --gap g$j.txt -o r$j.tsv h.surf
	done
	for row in 1 2; do
		n1=$(col r1.tsv n_c $row) n2=$(col r2.tsv n_c $row)
		check_range "gfmd-solve $m row $row: n_c -j 1 ($n1) vs -j 2 ($n2) within one point" \
		    "$((n1 - n2))" -1 1
	done
	check_range "gfmd-solve $m: gap fields of -j 1 and -j 2 agree to 1e-6" \
	    "$(field_diff g1.txt g2.txt)" 0 1e-6
done

# --- the wait policy (lib/threads.h) --------------------------------------
# libgomp's spin count at start-up (OMP_DISPLAY_ENV=verbose prints one
# block per start; the last is the program that runs): with two threads
# and no policy set, 0 (passive: the tool executed itself again with
# OMP_WAIT_POLICY=passive); a policy the user set is kept; one thread
# starts once (nothing spins, nothing to change).
spin() { env -u MAKEFLAGS "$@" OMP_DISPLAY_ENV=verbose "$RC_BIN/$tool" $args 2>&1 >/dev/null |
	sed -n "s/.*GOMP_SPINCOUNT = '\([0-9]*\)'.*/\1/p"; }
for tool in surfgen surfwarp surfstat gfmd-solve; do
	case $tool in
	surfgen) args="-q -n 8 -o /dev/null" ;;
	surfwarp) args="-q -w 2 -o /dev/null h.surf" ;;
	surfstat) args="-q h.surf" ;;
	gfmd-solve) args="-q -p 0.1 -o /dev/null h.surf" ;;
	esac
	args="$args -j 2"
	n=$(spin -u OMP_WAIT_POLICY | tail -1)
	check "$tool -j 2: passive waiting by default (spin count $n)" test "$n" = 0
	n=$(spin OMP_WAIT_POLICY=active | tail -1)
	check "$tool -j 2: OMP_WAIT_POLICY=active kept (spin count $n)" test "$n" -gt 0
	args="${args% -j 2} -j 1"
	n=$(spin -u OMP_WAIT_POLICY | wc -l)
	check "$tool -j 1: started once ($n start-ups)" test "$n" -eq 1
done
# The restart's malloc tunable (glibc.malloc.hugetlb=1, threads.h) is the
# tool's alone: a program it runs (here the Gwyddion converter, a script
# that saves its environment) does not inherit it; a GLIBC_TUNABLES the
# user set reaches it unchanged.
printf '#!/bin/sh\nenv > "%s/child.env"\nexit 1\n' "$PWD" >fakegwy
chmod +x fakegwy
printf 'not a height file\n' >junk.xyz
for run in "surfstat -j 2 junk.xyz" \
    "surfwarp -q -w 2 -o /dev/null -j 2 junk.xyz"; do
tool=${run%% *}
for user in "" glibc.malloc.arena_max=2; do
	rm -f child.env
	if [ -n "$user" ]; then
		env -u MAKEFLAGS -u OMP_WAIT_POLICY GLIBC_TUNABLES=$user \
		    RC_GWYDDION="$PWD/fakegwy" "$RC_BIN/"$run \
		    >/dev/null 2>&1
	else
		env -u MAKEFLAGS -u OMP_WAIT_POLICY -u GLIBC_TUNABLES \
		    RC_GWYDDION="$PWD/fakegwy" "$RC_BIN/"$run \
		    >/dev/null 2>&1
	fi
	check "$tool -j 2 restarted before running the converter" \
	    grep -q '^OMP_WAIT_POLICY=passive$' child.env
	got=$(sed -n 's/^GLIBC_TUNABLES=//p' child.env)
	check "$tool: GLIBC_TUNABLES '$user' reaches the converter as set ('$got')" \
	    test "$got" = "$user"
	check "$tool: the restart's marker does not reach the converter" \
	    sh -c '! grep -q "^RC_THREADS_REEXEC=" child.env'
done
done

summary
