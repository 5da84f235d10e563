# SPDX-License-Identifier: GPL-3.0-or-later
# verdict.awk - the cheapest estimator reaching each accuracy target, the
# Pareto front, and the paper's alpha = 0.11.  Files: table.tsv,
# tolerance.tsv.  Error: rms over seeds and the pressures (p_star "all");
# cost: mean wall time.  -v ref_eps=E: the coarsest eps_c of the
# reference's (continuum) grids; a continuum estimate that uses a grid
# that fine shares data with the reference, so its error is not an
# independent measurement and it is not eligible (a pixel-kernel solve on
# that grid is a different solution: eligible).
BEGIN { FS = "\t"; ntarget = split("0.03 0.01 0.003 0.001", target, " ") }
FNR == 1 { file++; delete c; for (i = 1; i <= NF; i++) c[$i] = i; next }
file == 1 && $c["p_star"] == "all" && ($c["kernel"] != "continuum" || $c["eps_c"] + 0 > ref_eps * (1 + 1e-9)) {
	cand[++n] = $c["estimator"] " (" $c["kernel"] " kernel) at eps_c = " $c["eps_c"]
	sec[n] = $c["seconds"]; err[n] = $c["rel_err_rms"]; kerr[n] = $c["kappa_err_rms"]
	if ($c["estimator"] == "yastrebov_0.11") y11[$c["kernel"]] = y11[$c["kernel"]] sprintf(" %.2g%% at %s;", 100 * err[n], $c["eps_c"])
	if ($c["estimator"] == "raw") aex[$c["kernel"]] = aex[$c["kernel"]] sprintf(" %s at %s;", $c["alpha_exact"], $c["eps_c"])
}
file == 2 { solver[$1, $2] = $6; stime[$1, $2] = $4; meth[$1] = 1; tols[$2] = 1; eps_tol = $3 }
END {
	for (k = 1; k <= ntarget; k++) {
		best = 0
		for (i = 1; i <= n; i++)
			if (err[i] <= target[k] && (!best || sec[i] < sec[best])) best = i
		if (best)
			printf "for %g%% accuracy of a_r use %s (%.3g s, measured rms error %.2g%%, kappa %.2g%%)\n",
			    100 * target[k], cand[best], sec[best], 100 * err[best], 100 * kerr[best]
		else
			printf "for %g%% accuracy of a_r: no estimator independent of the reference reaches it\n", 100 * target[k]
	}
	# Pareto front: no other candidate is both cheaper and more accurate
	print "Pareto front (seconds, rms error of a_r over seeds and pressures):"
	for (i = 1; i <= n; i++) {
		dom = 0
		for (j = 1; j <= n; j++)
			if (j != i && sec[j] <= sec[i] && err[j] <= err[i] && (sec[j] < sec[i] || err[j] < err[i])) dom = 1
		if (!dom) printf "  %.3g s  %.3g%%  %s\n", sec[i], 100 * err[i], cand[i] | "sort -g"
	}
	close("sort -g")
	for (k in y11) printf "alpha = 0.11 (Eq. 23: within about 0.1%%), %s kernel:%s\n", k, y11[k]
	for (k in aex) printf "alpha that would be exact, %s kernel:%s\n", k, aex[k]
	# the loosest tolerance whose solver error is 10x below 0.1%
	for (m in meth) {
		bt = ""
		for (t in tols) if (solver[m, t] <= 1e-4 && (bt == "" || t + 0 > bt + 0)) bt = t
		if (bt != "")
			printf "solver %s: --tol %s already keeps its own error below 1e-4 relative at eps_c = %s (%.3g s per solve)\n", m, bt, eps_tol, stime[m, bt]
	}
}
