# SPDX-License-Identifier: GPL-3.0-or-later
# estimators.awk - error and cost of each a_r (and kappa) estimator, one
# row per (estimator, kernel, p_star, eps_c), and one per (estimator,
# kernel, eps_c) over all pressures (p_star "all").  Files: ref.tsv
# (contact-stats --per-seed: the reference a_r and kappa of each seed and
# pressure), rows.tsv (gfmd-solve rows), pairs.tsv (contact-stats
# --per-seed on neighbouring pairs of grids of one kernel).
# Error: relative to the reference of the seed and pressure; rms and mean
# over seeds (and, for "all", over seeds and pressures).  kappa of an
# estimate a: 2 erfinv(a) / (sqrt(pi) p*), as gfmd-solve and contact-stats
# compute it (lib/kappa.h).  alpha_exact (Yastrebov rows' own row: the
# raw one): the contact-line weight that would make (n_c - alpha n_cl)/N
# equal the reference, mean over the samples.
# subpixel: gfmd-solve's a_subpixel (lib/contact.h); its pair: 2 a(fine) -
# a(coarse), the linear Richardson step of two grids a factor 2 apart.
# Cost: seconds of every gfmd-solve run the estimator needs, mean.
BEGIN { FS = OFS = "\t"; pi = atan2(0, -1); alpha_y = (pi - 1 + log(2)) / 24 }
FNR == 1 { file++; delete c; for (i = 1; i <= NF; i++) c[$i] = i; next }
function v(name) { if (!(name in c)) { print "estimators.awk: no column " name > "/dev/stderr"; exit 1 } return $c[name] }
function eps_of() { return sprintf("%.6g", v("lx") / v("nx") / v("lambda_s")) }
function pkey() { return sprintf("%.6g", v("p_star")) }
# erf by its Taylor series (|x| < 3 here: a_r < 0.9999), erfinv by Newton
function erf(x,   s, t, n) {
	s = t = x
	for (n = 1; n < 200 && (t > 1e-17 * s || -t > 1e-17 * s); n++) {
		t *= -x * x / n
		s += t / (2 * n + 1)
	}
	return 2 / sqrt(pi) * s
}
function erfinv(y,   x, i) {
	x = y * sqrt(pi) / 2
	for (i = 0; i < 60; i++) x -= (erf(x) - y) / (2 / sqrt(pi) * exp(-x * x))
	return x
}
function kappa(a, ps) { return 2 * erfinv(a) / (sqrt(pi) * ps) }
file == 1 { ref[v("seed"), pkey()] = v("a_r"); refk[v("seed"), pkey()] = v("kappa"); next }
file == 2 {
	s = v("seed"); e = eps_of(); p = pkey(); k = v("kernel")
	t[k, s, p, e] = v("seconds")
	add("raw", k, p, e, s, v("a_r"), t[k, s, p, e], (v("n_c") - ref[s, p] * v("n_tot")) / v("n_cl"))
	add("yastrebov_0.118", k, p, e, s, (v("n_c") - alpha_y * v("n_cl")) / v("n_tot"), t[k, s, p, e], "")
	add("yastrebov_0.11", k, p, e, s, (v("n_c") - 0.11 * v("n_cl")) / v("n_tot"), t[k, s, p, e], "")
	if ("a_subpixel" in c) {
		sub_a[k, s, p, e] = v("a_subpixel"); sub_seen[k, s, p, e] = 1
		add("subpixel", k, p, e, s, v("a_subpixel"), t[k, s, p, e], "")
	}
	next
}
file == 3 {
	s = v("seed"); p = pkey(); k = v("kernel"); split(v("eps_c"), pe, ",")
	fine = sprintf("%.6g", pe[1] < pe[2] ? pe[1] : pe[2])
	coarse = sprintf("%.6g", pe[1] < pe[2] ? pe[2] : pe[1])
	if (!((k, s, p, fine) in t) || !((k, s, p, coarse) in t)) { print "estimators.awk: pair without rows" > "/dev/stderr"; exit 1 }
	cost = t[k, s, p, fine] + t[k, s, p, coarse]
	add("richardson_pair", k, p, fine, s, v("a_richardson"), cost, "")
	add("yastrebov_mod_pair", k, p, fine, s, v("a_yastrebov_mod"), cost, "")
}
function add1(key, r, rk, sec, a, al) {
	keys[key] = 1; n[key]++; sum[key] += r; sum2[key] += r * r; secs[key] += sec; asum[key] += a
	ksum[key] += rk; ksum2[key] += rk * rk
	if (al != "") { alsum[key] += al; aln[key]++ }
}
function add(est, k, p, e, s, a, sec, al,   r, rk) {
	if (!((s, p) in ref)) { print "estimators.awk: no reference for seed " s ", p* " p > "/dev/stderr"; exit 1 }
	r = a / ref[s, p] - 1
	rk = kappa(a, p) / refk[s, p] - 1
	add1(est SUBSEP k SUBSEP p SUBSEP e, r, rk, sec, a, al)
	add1(est SUBSEP k SUBSEP "all" SUBSEP e, r, rk, sec, a, al)
}
END {
	# Richardson (linear, grids halving) of a_subpixel from neighbouring grids
	for (q4 in sub_seen) {
		split(q4, w, SUBSEP); e2 = sprintf("%.6g", w[4] / 2)
		if ((w[1], w[2], w[3], e2) in sub_seen)
			add("subpixel_richardson_pair", w[1], w[3], e2, w[2],
			    2 * sub_a[w[1], w[2], w[3], e2] - sub_a[q4],
			    t[w[1], w[2], w[3], e2] + t[q4], "")
	}
	print "estimator", "kernel", "p_star", "eps_c", "seconds", "rel_err_rms", "rel_err_mean",
	    "kappa_err_rms", "kappa_err_mean", "alpha_exact", "a_r_mean", "n"
	for (key in keys) {
		split(key, q, SUBSEP)
		printf "%s\t%s\t%s\t%s\t%.4g\t%.3e\t%.3e\t%.3e\t%.3e\t%s\t%.6f\t%d\n", q[1], q[2], q[3], q[4],
		    secs[key] / n[key], sqrt(sum2[key] / n[key]), sum[key] / n[key],
		    sqrt(ksum2[key] / n[key]), ksum[key] / n[key],
		    aln[key] ? sprintf("%.4f", alsum[key] / aln[key]) : "-",
		    asum[key] / n[key], n[key] | "sort -t'\t' -k1,1 -k2,2 -k3,3 -k4,4gr"
	}
}
