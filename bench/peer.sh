#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# peer.sh - gfmd-solve against the public Python peer, ContactMechanics
# (Polonsky-Keer CG, PeriodicFFTElasticHalfSpace), on the same periodic
# surface and load: for n = 256 ... 2048 (PEER_SIZES), bench_gfmd's
# surface (H = 0.8, lambda_r = L/2, lambda_s = L/64, gbar = 1, E* = 1) at
# p* = 0.05, each solved once by each program as a process of its own.
# Columns: n, program, iterations, solve_seconds (the solve alone: the
# row's seconds; the peer's minimize_proxy call), whole_seconds (the
# process, wall clock: start, reading, planning, solve, analysis,
# writing), peak_bytes (peak resident size, bench/peakrss), a_r,
# mask_diff (the points where the two contact masks differ: gfmd-solve's
# --contact against the peer's positive forces; 0, identical masks) and
# diff_p_max (the largest pressure over the mean pressure at those
# points, of the program that has them in contact: a difference of
# tolerance has tiny pressures there; the peer's over the mean of its
# forces, so no unit enters).  Then the
# ratios peer / gfmd-solve of solve and whole seconds (goals, issue 29:
# 40x at 512^2 and 100x at 2048^2 in solve time, 30x at 1024^2 whole).
# Skips with a message (exit 0) when ContactMechanics is not importable
# by PEER_PYTHON (default /usr/bin/python3, which has numpy).  Prints
# only; never fails on time.
#   RC_BIN=bin RC_BENCH_BIN=build/bench sh bench/peer.sh
set -u
: "${RC_BIN:?RC_BIN not set}"
: "${RC_BENCH_BIN:?RC_BENCH_BIN not set (the directory holding peakrss)}"
PY=${PEER_PYTHON:-/usr/bin/python3}
SIZES=${PEER_SIZES:-256 512 1024 2048}
PEAKRSS=$RC_BENCH_BIN/peakrss
if ! "$PY" -c 'import numpy, ContactMechanics, SurfaceTopography' 2>/dev/null; then
	echo "peer.sh: SKIP: ContactMechanics (with SurfaceTopography and numpy) is not importable by $PY (pip install ContactMechanics; PEER_PYTHON names another python)"
	exit 0
fi
[ -x "$PEAKRSS" ] || { echo "peer.sh: $PEAKRSS: not built (make bench)" >&2; exit 1; }
TMP=$(mktemp -d "${TMPDIR:-/tmp}/rcpeer.XXXXXX")
trap 'rm -rf "$TMP"' EXIT

# The peer's solve of FILE (.npy heights, shape (n, n), cell 1 x 1) at
# mean pressure P: prints iterations, solve seconds and whether it
# converged; saves its forces (positive on contact).
cat >"$TMP/peer.py" <<'EOF'
import sys, time
import numpy as np
from ContactMechanics import PeriodicFFTElasticHalfSpace
from SurfaceTopography import Topography
try:
    from ContactMechanics.Systems import NonSmoothContactSystem
except ImportError:  # older releases: the factory
    from ContactMechanics import make_system as NonSmoothContactSystem

heights, p, forces_out = np.load(sys.argv[1]), float(sys.argv[2]), sys.argv[3]
n = heights.shape
topo = Topography(heights, physical_sizes=(1.0, 1.0), periodic=True)
# young is the contact modulus E* in ContactMechanics
substrate = PeriodicFFTElasticHalfSpace(n, 1.0, physical_sizes=(1.0, 1.0))
system = NonSmoothContactSystem(substrate, topo)
t0 = time.perf_counter()
sol = system.minimize_proxy(external_force=p * 1.0 * 1.0)
seconds = time.perf_counter() - t0
np.save(forces_out, np.asarray(sol.jac, dtype=float))
print(sol.nit, seconds, int(sol.success))
EOF

now() { date +%s.%N; }
printf 'n\tprogram\titerations\tsolve_seconds\twhole_seconds\tpeak_bytes\ta_r\tmask_diff\tdiff_p_max\n'
for n in $SIZES; do
	"$RC_BIN/surfgen" -q -n "$n" -H 0.8 --lambda-r 0.5 --lambda-s 0.015625 \
	    -o "$TMP/s.npy" || exit 1
	# E* = 1, gbar = 1 (surfgen's, spectral): the same absolute pressure
	t0=$(now)
	"$PEAKRSS" -o "$TMP/ours.rss" "$RC_BIN/gfmd-solve" -q --pressure-abs 0.05 \
	    --contact "$TMP/ours_mask.npy" --pressure "$TMP/ours_p.npy" \
	    -o "$TMP/ours.tsv" "$TMP/s.npy"
	t1=$(now)
	read -r ours_bytes ours_status <"$TMP/ours.rss"
	t2=$(now)
	"$PEAKRSS" -o "$TMP/peer.rss" "$PY" "$TMP/peer.py" "$TMP/s.npy" 0.05 \
	    "$TMP/peer_forces.npy" >"$TMP/peer.out"
	t3=$(now)
	read -r peer_bytes peer_status <"$TMP/peer.rss"
	if [ "$ours_status" != 0 ] || [ "$peer_status" != 0 ]; then
		echo "peer.sh: $n: gfmd-solve exit $ours_status, peer exit $peer_status" >&2
		exit 1
	fi
	"$PY" - "$n" "$t0" "$t1" "$t2" "$t3" "$ours_bytes" "$peer_bytes" "$TMP" <<'EOF'
import sys, csv
import numpy as np
n, t0, t1, t2, t3 = int(sys.argv[1]), *map(float, sys.argv[2:6])
ours_bytes, peer_bytes, tmp = int(sys.argv[6]), int(sys.argv[7]), sys.argv[8]
row = next(csv.DictReader(open(tmp + "/ours.tsv"), delimiter="\t"))
nit, peer_seconds, ok = open(tmp + "/peer.out").read().split()
a = np.load(tmp + "/ours_mask.npy") > 0
forces = np.load(tmp + "/peer_forces.npy")
b = forces > 0
if a.shape != b.shape:
    sys.exit(f"peer.sh: {n}: masks of shapes {a.shape} and {b.shape}")
differ = a != b
ours_rel = np.load(tmp + "/ours_p.npy") / float(row["p"])
peer_rel = forces / forces.mean()
rel = np.where(a, ours_rel, peer_rel)[differ]
diff, diff_p = int(differ.sum()), (rel.max() if rel.size else 0.0)
ours_solve, peer_solve = float(row["seconds"]), float(peer_seconds)
print(f"{n}\tgfmd-solve\t{row['iterations']}\t{ours_solve:.3f}\t{t1 - t0:.3f}\t"
      f"{ours_bytes}\t{float(row['a_r']):.6f}\t{diff}\t{diff_p:.3g}")
print(f"{n}\tContactMechanics\t{nit}\t{peer_solve:.3f}\t{t3 - t2:.3f}\t"
      f"{peer_bytes}\t{b.mean():.6f}\t{diff}\t{diff_p:.3g}"
      f"{'' if ok == '1' else ' (not converged)'}")
print(f"# {n}: peer / gfmd-solve: solve {peer_solve / ours_solve:.1f}x, "
      f"whole {(t3 - t2) / (t1 - t0):.1f}x")
EOF
done
