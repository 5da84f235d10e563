# SPDX-License-Identifier: GPL-3.0-or-later
# estimators.awk - error and cost of each a_r estimator, one row per
# (estimator, eps_c).  Files: ref.tsv (contact-stats --per-seed: the
# reference a_r of each seed), rows.tsv (gfmd-solve rows), pairs.tsv
# (contact-stats --per-seed on neighbouring pairs of grids).
# Error: relative to the seed's reference, rms and mean over seeds.
# Cost: seconds of every gfmd-solve run the estimator needs, mean over seeds.
BEGIN { FS = OFS = "\t"; alpha_y = (atan2(0, -1) - 1 + log(2)) / 24 }
FNR == 1 { file++; delete c; for (i = 1; i <= NF; i++) c[$i] = i; next }
function v(name) { if (!(name in c)) { print "estimators.awk: no column " name > "/dev/stderr"; exit 1 } return $c[name] }
function eps_of() { return sprintf("%.6g", v("lx") / v("nx") / v("lambda_s")) }
file == 1 { ref[v("seed")] = v("a_r"); next }
file == 2 {
	s = v("seed"); e = eps_of()
	t[s, e] = v("seconds"); eps[e] = 1
	add("raw", e, s, v("a_r"), t[s, e])
	add("yastrebov_0.118", e, s, (v("n_c") - alpha_y * v("n_cl")) / v("n_tot"), t[s, e])
	add("yastrebov_0.11", e, s, (v("n_c") - 0.11 * v("n_cl")) / v("n_tot"), t[s, e])
	next
}
file == 3 {
	s = v("seed"); split(v("eps_c"), pe, ",")
	fine = sprintf("%.6g", pe[1] < pe[2] ? pe[1] : pe[2])
	coarse = sprintf("%.6g", pe[1] < pe[2] ? pe[2] : pe[1])
	if (!((s, fine) in t) || !((s, coarse) in t)) { print "estimators.awk: pair without rows" > "/dev/stderr"; exit 1 }
	cost = t[s, fine] + t[s, coarse]
	add("richardson_pair", fine, s, v("a_richardson"), cost)
	add("yastrebov_mod_pair", fine, s, v("a_yastrebov_mod"), cost)
}
function add(est, e, s, a, sec,   r) {
	if (!(s in ref)) { print "estimators.awk: no reference for seed " s > "/dev/stderr"; exit 1 }
	r = a / ref[s] - 1
	k = est SUBSEP e
	keys[k] = 1; n[k]++; sum[k] += r; sum2[k] += r * r; secs[k] += sec; asum[k] += a
}
END {
	print "estimator", "eps_c", "seconds", "rel_err_rms", "rel_err_mean", "a_r_mean", "n_seeds"
	for (k in keys) {
		split(k, p, SUBSEP)
		printf "%s\t%s\t%.4g\t%.3e\t%.3e\t%.6f\t%d\n", p[1], p[2], secs[k] / n[k],
		    sqrt(sum2[k] / n[k]), sum[k] / n[k], asum[k] / n[k], n[k] | "sort -t'\t' -k1,1 -k2,2gr"
	}
}
