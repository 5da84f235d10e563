# SPDX-License-Identifier: GPL-3.0-or-later
# summary.awk - per exponent: kappa_c at the lowest pressure against Eq. 28,
# the largest |error| of the Eq. 8 + Eq. 28 prediction of a_r, and the
# smallest a_r at which that error exceeds 5% and 25% ("none" if never).
BEGIN { FS = OFS = "\t" }
NR == 1 { next }
{
	n = $1; if (!(n in first)) { first[n] = NR; klow[n] = $4; k28[n] = $5; plow[n] = $2; order[++m] = n }
	e = $8 < 0 ? -$8 : $8
	if (e > emax[n]) { emax[n] = e; amax[n] = $3 }
	if (e > 0.05 && !(n in a5)) a5[n] = $3
	if (e > 0.25 && !(n in a25)) a25[n] = $3
}
END {
	print "exponent", "p_star_lowest", "kappa_c_lowest_p", "kappa_c_eq28", "rel_err_lowest_p", "max_abs_a_r_err", "at_a_r", "a_r_err_over_5pct_from", "a_r_err_over_25pct_from"
	for (i = 1; i <= m; i++) {
		n = order[i]
		printf "%s\t%s\t%.4f\t%.4f\t%+.3f\t%.3f\t%.3f\t%s\t%s\n", n, plow[n], klow[n], k28[n], klow[n] / k28[n] - 1,
		    emax[n], amax[n], (n in a5) ? a5[n] : "none", (n in a25) ? a25[n] : "none"
	}
}
