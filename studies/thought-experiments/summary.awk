# SPDX-License-Identifier: GPL-3.0-or-later
# summary.awk - ratios carved/base and flipped/base over seeds: mean and
# standard error, plus the largest |a_r change| of carving (which should be
# zero up to the solver tolerance).
BEGIN { FS = OFS = "\t" }
NR == 1 { next }
{
	r[1] = $3 / $2; r[2] = $5 / $4; r[3] = $7 / $6; r[4] = $8 / $2; r[5] = $9 / $6
	for (i = 1; i <= 5; i++) { s[i] += r[i]; s2[i] += r[i] * r[i] }
	d = $3 - $2; if (d < 0) d = -d; if (d > dmax) dmax = d
	d = $5 - $4; if (d < 0) d = -d; if (d > dmax) dmax = d
	n++
}
END {
	split("a_r_carved/a_r_base a_r_carved/a_r_base_at_p_low nayak_carved/nayak_base a_r_flipped/a_r_base nayak_flipped/nayak_base", name, " ")
	print "quantity", "mean", "stderr", "n_seeds"
	for (i = 1; i <= 5; i++) {
		m = s[i] / n; v = n > 1 ? (s2[i] - n * m * m) / (n - 1) : 0
		printf "%s\t%.6g\t%.2g\t%d\n", name[i], m, (v > 0 ? sqrt(v / n) : 0), n
	}
	printf "max_abs_a_r_change_by_carving\t%.3g\t0\t%d\n", dmax, n
}
