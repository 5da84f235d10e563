# SPDX-License-Identifier: GPL-3.0-or-later
# tolerance.awk - error and cost of gfmd-solve's --tol, per method.
# Files: ref.tsv (reference a_r per seed and pressure), then one gfmd-solve row per
# (seed, method, tol); tol_ref (-v) names the tightest tolerance, whose
# a_r is the converged value at that grid.
# solver_err: |a_r(tol) / a_r(tol_ref) - 1|, the share of the solver;
# total_err: |a_r(tol) / reference - 1|, discretisation included.
BEGIN { FS = OFS = "\t" }
FNR == 1 { file++; delete c; for (i = 1; i <= NF; i++) c[$i] = i; next }
function v(name) { if (!(name in c)) { print "tolerance.awk: no column " name > "/dev/stderr"; exit 1 } return $c[name] }
file == 1 { ref[v("seed"), sprintf("%.6g", v("p_star"))] = v("a_r"); next }
{
	# the tolerance is in the file name (…__tolT.tsv), the row does not carry it
	tol = FILENAME; sub(/.*__tol/, "", tol); sub(/\.tsv$/, "", tol)
	s = v("seed"); m = v("method"); pr[s] = sprintf("%.6g", v("p_star"))
	a[s, m, tol] = v("a_r"); sec[s, m, tol] = v("seconds"); it[s, m, tol] = v("iterations")
	seeds[s] = 1; meth[m] = 1; tols[tol] = 1
	eps = sprintf("%.6g", v("lx") / v("nx") / v("lambda_s"))
}
END {
	print "method", "tol", "eps_c", "seconds", "iterations", "solver_err_rms", "total_err_rms", "n_seeds"
	for (m in meth) for (tol in tols) {
		n = 0; ss = st = 0; se = 0; si = 0
		for (s in seeds) {
			if (!((s, m, tol) in a)) continue
			if (!((s, m, tol_ref) in a)) { print "tolerance.awk: no tol " tol_ref " row" > "/dev/stderr"; exit 1 }
			r = a[s, m, tol] / a[s, m, tol_ref] - 1; ss += r * r
			r = a[s, m, tol] / ref[s, pr[s]] - 1; st += r * r
			se += sec[s, m, tol]; si += it[s, m, tol]; n++
		}
		printf "%s\t%s\t%s\t%.4g\t%.1f\t%.3e\t%.3e\t%d\n", m, tol, eps, se / n, si / n,
		    sqrt(ss / n), sqrt(st / n), n | "sort -t'\t' -k1,1 -k2,2gr"
	}
}
