#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# check.sh - the MPI builds (make MPI=1) against the serial tools, with 1, 2
# and 3 ranks (make check-mpi).   tests/mpi/check.sh SERIAL_BIN MPI_BIN
# Ends with "N passed, N failed".
RC_BIN=$(cd "$1" && pwd); export RC_BIN
MPI_BIN=$(cd "$2" && pwd)
RC_TOP=$(cd "$(dirname "$0")/../.." && pwd)
. "$RC_TOP/tests/e2e/lib.sh"
# A hung collective must fail the test, not the CI run.
MPIRUN="timeout 120 mpirun --oversubscribe --allow-run-as-root"
# Containers often forbid the ptrace-based single-copy transfer of
# OpenMPI's shared-memory transport; the copy-in/copy-out path always works.
OMPI_MCA_btl_vader_single_copy_mechanism=none; export OMPI_MCA_btl_vader_single_copy_mechanism
cd "$T_TMP" || exit 1

# The values of a .surf file, one per line (od prints the shortest
# representation that reads back to the same double).
values() {
	off=$(head -c 65536 "$1" | grep -a '^data_offset = ' | sed 's/^data_offset = //')
	od -A n -t f8 -v -j "$off" "$1" | tr -s ' ' '\n' | sed '/^$/d'
}

# maxdiff A B: max |a - b| / rms(a) over the values; 1e300 (a failure for
# every tolerance) if the counts differ or there are none.
maxdiff() {
	values "$1" >a.txt
	values "$2" >b.txt
	if [ "$(wc -l <a.txt)" != "$(wc -l <b.txt)" ] || [ ! -s a.txt ]; then
		echo 1e300
		return
	fi
	paste a.txt b.txt | awk '{ d = $1 - $2; if (d < 0) d = -d; if (d > m) m = d;
		s += $1 * $1 } END { r = sqrt(s / NR); if (r == 0) r = 1e-300; printf "%.3g\n", m / r }'
}

# ndiffer A B: how many values differ (contact masks)
ndiffer() {
	values "$1" >a.txt
	values "$2" >b.txt
	paste a.txt b.txt | awk '$1 != $2 { n++ } END { print n + 0 }'
}

# Self-affine surfaces: the modes are a function of (seed, kx, ky), so each
# rank's slab is the serial spectrum's rows; what differs is the order of
# the normalisation sum (one Allreduce) and FFTW-MPI's transform, round-off
# of order 1e-16 of the rms height.  Allowed: 1e-12 of the rms height.
# Grids: even, odd nx (97), ny = 64 not divisible by 3, and 32x4, where
# with 3 ranks FFTW's blocks of ceil(4/3) = 2 rows leave rank 2 none.
# The pointwise types compute the same formula per row; their
# normalisation sums (rms about the mean, spectral rms gradient) are
# Allreduce'd: again round-off only.  A flat surface has rms 0: maxdiff
# then compares absolute differences, which must be exactly 0.
for spec in "64x48 -H 0.7 --seed 5" "97x64 -H 0.3 --seed 11 --rolloff --lambda-r 0.5" \
    "97x64 --seed 3 --peklenik 2 --gaussian-amplitudes --rms-height 0.01" \
    "32x4 --seed 2" "64x48 --type harmonic --exponent 1.5 --rms-gradient 0.5" \
    "97x64 --type sine --wavelength 0.5 --rms-height 2" \
    "32x4 --type eggbox --rms-gradient 0.1" "97x64 --type flat"; do
	set -- $spec
	size=$1; shift
	surfgen -n "$size" "$@" -o ser.surf
	for np in 1 2 3; do
		$MPIRUN -np $np "$MPI_BIN/surfgen" -n "$size" "$@" -o mpi.surf
		check_status "surfgen $spec np=$np runs" 0 test -f mpi.surf
		check_range "surfgen $spec np=$np equals serial" "$(maxdiff ser.surf mpi.surf)" 0 1e-12
		check "surfgen $spec np=$np header" sh -c "head -c 300 mpi.surf | \
		    grep -aq '^ny = ${size#*x}\$'"
		# The header but for the history (the command lines differ) and
		# the scaled amplitude of a sine (normalisation round-off), which also
		# change the padding of the end_header line.
		head -c 4096 ser.surf | sed 's/ *$//; /^end_header/q' >hs.txt
		head -c 4096 mpi.surf | sed 's/ *$//; /^end_header/q' >hm.txt
		check "surfgen $spec np=$np same header" sh -c "grep -av \
		    '^history\|^data_offset\|^meta.amplitude' hs.txt >hs2.txt; grep -av \
		    '^history\|^data_offset\|^meta.amplitude' hm.txt | cmp -s - hs2.txt"
		if grep -aq '^meta.amplitude = ' hs.txt; then
			check_rel "surfgen $spec np=$np amplitude" \
			    "$(sed -n 's/^meta.amplitude = //p' hm.txt)" \
			    "$(sed -n 's/^meta.amplitude = //p' hs.txt)" 1e-12
		fi
		rm -f mpi.surf
	done
done

# gfmd-solve: the same FIRE iteration on slabs; the sums (Allreduce) and
# transforms differ in round-off from the serial tool's, so the two runs
# are two solves of one problem to --tol 1e-9.  The contact set is then
# the same (a_r equal or within one point); continuous columns agree to
# 1e-6 relative (tolerance 1e-9 on the residual, times a condition number
# of the contact problem well below 1e3 on these grids); n_patches must
# be equal when the contact sets are.
cols="a_yastrebov gbar gbar_c gbar_c_prime kappa kappa_c mean_gap elastic_energy patch_size_char"
for spec in "64x48 -H 0.7 --seed 5 --lambda-s 0.1" "97x64 -H 0.8 --seed 7"; do
	set -- $spec
	size=$1; shift
	surfgen -n "$size" "$@" -o h.surf
	gfmd-solve --tol 1e-9 -p 0.02,0.1,0.3 h.surf --gap gap.surf \
	    --pressure sig.surf --contact mask.surf --displacement u.surf >ser.tsv
	for np in 1 2 3; do
		$MPIRUN -np $np "$MPI_BIN/gfmd-solve" --tol 1e-9 -p 0.02,0.1,0.3 h.surf \
		    --gap mgap.surf --pressure msig.surf --contact mmask.surf \
		    --displacement mu.surf >mpi.tsv
		check_status "gfmd-solve $size np=$np runs" 0 test -s mpi.tsv
		for r in 1 2 3; do
			nc_s=$(col ser.tsv n_c $r)
			nc_m=$(col mpi.tsv n_c $r)
			# a missing column or a pretty table must fail this
			# check, not abort the script in $((...))
			case "$nc_m$nc_s" in
			*[!0-9]* | "") d=1e300 ;;
			*) d=$((nc_m - nc_s)) ;;
			esac
			check_range "gfmd-solve $size np=$np row $r n_c $nc_m vs $nc_s" \
			    "$d" -1 1
			check_rel "gfmd-solve $size np=$np row $r n_tot" \
			    "$(col mpi.tsv n_tot $r)" "$(col ser.tsv n_tot $r)" 0
			if [ "$nc_m" = "$nc_s" ]; then
				check_rel "gfmd-solve $size np=$np row $r n_patches" \
				    "$(col mpi.tsv n_patches $r)" "$(col ser.tsv n_patches $r)" 0
				check_rel "gfmd-solve $size np=$np row $r n_cl" \
				    "$(col mpi.tsv n_cl $r)" "$(col ser.tsv n_cl $r)" 0
			fi
			for c in $cols; do
				s=$(col ser.tsv $c $r)
				m=$(col mpi.tsv $c $r)
				if [ "$s" = nan ]; then
					check "gfmd-solve $size np=$np row $r $c nan" [ "$m" = nan ]
				else
					check_rel "gfmd-solve $size np=$np row $r $c" "$m" "$s" 1e-6
				fi
			done
			check_range "gfmd-solve $size np=$np row $r residual" \
			    "$(col mpi.tsv residual $r)" 0 1e-9
		done
		# Fields of the last pressure: u and the gap to 1e-6 of their
		# rms, sigma likewise, the mask within one point.
		check_range "gfmd-solve $size np=$np --displacement" "$(maxdiff u.surf mu.surf)" 0 1e-6
		check_range "gfmd-solve $size np=$np --gap" "$(maxdiff gap.surf mgap.surf)" 0 1e-6
		check_range "gfmd-solve $size np=$np --pressure" "$(maxdiff sig.surf msig.surf)" 0 1e-6
		check_range "gfmd-solve $size np=$np --contact" "$(ndiffer mask.surf mmask.surf)" 0 1
		rm -f mpi.tsv mu.surf mgap.surf msig.surf mmask.surf
	done
done

# A rank without rows (32x4 on 3 ranks) takes part in every collective.
surfgen -n 32x4 --seed 2 -o t.surf
gfmd-solve --tol 1e-9 -p 0.1 t.surf >ser.tsv
$MPIRUN -np 3 "$MPI_BIN/gfmd-solve" --tol 1e-9 -p 0.1 t.surf >mpi.tsv
check_rel "gfmd-solve 32x4 np=3 (a rank with no rows) n_c" \
    "$(col mpi.tsv n_c)" "$(col ser.tsv n_c)" 0
check_rel "gfmd-solve 32x4 np=3 mean_gap" "$(col mpi.tsv mean_gap)" \
    "$(col ser.tsv mean_gap)" 1e-6
check_rel "gfmd-solve 32x4 np=3 n_patches" "$(col mpi.tsv n_patches)" \
    "$(col ser.tsv n_patches)" 0
check_rel "gfmd-solve 32x4 np=3 patch_size_char" \
    "$(col mpi.tsv patch_size_char)" "$(col ser.tsv patch_size_char)" 1e-12

# Patches across rank boundaries and across y = 0, which no rank holds
# whole (lib/mpi/dpatches.c joins the ranks' edge rows).  Egg box
# h = cos(kx) cos(ky) with 4 periods on 64^2: at small load one patch
# around each of the 2 * 4^2 = 32 maxima, centred on rows 0, 8, ..., 56
# (row 0's patch wraps in y; on 2 and 3 ranks others straddle the slab
# edges); at p* = 0.5 the contact is one network around 32 holes, whose
# patch_size_char is then the contact area a_r L^2 itself.
surfgen -n 64 --type eggbox --wavelength 0.25 -o egg.surf
for np in 1 2 3; do
	$MPIRUN -np $np "$MPI_BIN/gfmd-solve" -p 0.02,0.1,0.5 egg.surf >mpi.tsv
	check_rel "egg box np=$np p*=0.02: 32 patches" "$(col mpi.tsv n_patches 1)" 32 0
	check_rel "egg box np=$np p*=0.1: 32 patches" "$(col mpi.tsv n_patches 2)" 32 0
	check_rel "egg box np=$np p*=0.5: one patch" "$(col mpi.tsv n_patches 3)" 1 0
	check_rel "egg box np=$np p*=0.5: patch_size_char = a_r L^2" \
	    "$(col mpi.tsv patch_size_char 3)" "$(col mpi.tsv a_r 3)" 1e-15
done

# What the MPI build does not have is refused with a message, exit 2; a
# missing input fails on every rank alike, exit 1, without hanging.
for bad in "--method cg" "--fd" "--png x.png" "--checkpoint c.surf" "--gap g.npy" "--boundary free" "--thickness 0.1 --poisson 0.3" "--method cg --hardness 1"; do
	check_status "gfmd-solve MPI refuses $bad" 2 $MPIRUN -np 2 \
	    "$MPI_BIN/gfmd-solve" -p 0.1 $bad t.surf
done
check_status "gfmd-solve MPI refuses --adhesion" 2 $MPIRUN -np 2 \
    "$MPI_BIN/gfmd-solve" -p 0.1 --adhesion 0.01 --range 0.1 t.surf
$MPIRUN -np 2 "$MPI_BIN/gfmd-solve" -p 0.1 --method cg t.surf 2>err.txt
check "gfmd-solve MPI --method cg message" grep -q "FIRE only" err.txt
check_status "gfmd-solve MPI refuses --approach" 2 $MPIRUN -np 2 \
    "$MPI_BIN/gfmd-solve" --approach 0.01 t.surf
$MPIRUN -np 2 "$MPI_BIN/gfmd-solve" --approach 0.01 t.surf 2>err.txt
check "gfmd-solve MPI --approach message" grep -q "not in the MPI build" err.txt
check_status "gfmd-solve MPI non-.surf input" 2 $MPIRUN -np 2 \
    "$MPI_BIN/gfmd-solve" -p 0.1 t.npy
check_status "gfmd-solve MPI missing input" 1 $MPIRUN -np 2 \
    "$MPI_BIN/gfmd-solve" -p 0.1 missing.surf
# A um x nm map: the heights are brought to um as the serial tool does
# (the same a_r as the serial run on the same file; at an absolute
# pressure, since a_r at a given p* does not depend on the height scale).
surfgen -n 32 --seed 3 -L 10 -o base.surf
awk '/^data_offset/ { next } /^kind = / { print "unit = um"; print "z_unit = nm" }
	{ print } /^end_header/ { exit }' base.surf | sed 's/ *$//' >umnm.surf
off=$(awk '/^data_offset = / { print $3; exit }' base.surf)
tail -c +"$((off + 1))" base.surf >>umnm.surf
gfmd-solve -q -j 1 --pressure-abs 1e-4 umnm.surf >ser-umnm.tsv
$MPIRUN -np 2 "$MPI_BIN/gfmd-solve" -q --pressure-abs 1e-4 umnm.surf >mpi-umnm.tsv
check_rel "gfmd-solve MPI, um x nm map: a_r as serial" "$(col mpi-umnm.tsv a_r)" "$(col ser-umnm.tsv a_r)" 1e-9
check_status "surfgen MPI refuses --png" 2 $MPIRUN -np 2 \
    "$MPI_BIN/surfgen" --png s.png -o s.surf
check_status "surfgen MPI refuses -H with --type sine" 2 $MPIRUN -np 2 \
    "$MPI_BIN/surfgen" --type sine -H 0.5 -o s.surf
check_status "surfgen MPI refuses standard output" 2 $MPIRUN -np 2 \
    "$MPI_BIN/surfgen" -n 16
summary
