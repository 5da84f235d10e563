# SPDX-License-Identifier: GPL-3.0-or-later
# verdict.awk - the cheapest estimator reaching each accuracy target.
# Files: table.tsv, tolerance.tsv.  Cost is the mean wall time over seeds.
# -v ref_eps=E: the coarsest eps_c of the reference's grids; an estimator
# that uses a grid that fine shares data with the reference, so its error
# is not an independent measurement and it is not eligible.
BEGIN { FS = "\t"; ntarget = split("0.03 0.01 0.003 0.001", target, " ") }
FNR == 1 { file++; next }
file == 1 && $2 + 0 > ref_eps * (1 + 1e-9) { cand[++n] = $1 " at eps_c = " $2; sec[n] = $3; err[n] = $4 }
file == 2 { solver[$1, $2] = $6; stime[$1, $2] = $4; meth[$1] = 1; tols[$2] = 1; eps_tol = $3 }
END {
	for (k = 1; k <= ntarget; k++) {
		best = 0
		for (i = 1; i <= n; i++)
			if (err[i] <= target[k] && (!best || sec[i] < sec[best])) best = i
		if (best)
			printf "for %g%% accuracy of a_r use %s (%.3g s, measured error %.2g%%)\n",
			    100 * target[k], cand[best], sec[best], 100 * err[best]
		else
			printf "for %g%% accuracy of a_r: no estimator independent of the reference reaches it (those on grids with eps_c <= %s share data with it)\n", 100 * target[k], ref_eps
	}
	# the loosest tolerance whose solver error is 10x below 0.1%
	for (m in meth) {
		bt = ""
		for (t in tols) if (solver[m, t] <= 1e-4 && (bt == "" || t + 0 > bt + 0)) bt = t
		if (bt != "")
			printf "solver %s: --tol %s already keeps its own error below 1e-4 relative at eps_c = %s (%.3g s per solve)\n", m, bt, eps_tol, stime[m, bt]
	}
}
