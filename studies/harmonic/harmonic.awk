# SPDX-License-Identifier: GPL-3.0-or-later
# harmonic.awk - gfmd-solve rows of harmonic indenters -> kappa_c against
# Eq. 28, kappa_c(n) = sqrt(pi/n) Gamma(n/2 + 3/2) / Gamma(n/2 + 1), and the
# a_r that Eq. 8 predicts with it: erf(sqrt(pi) kappa_c(n) p_c*/2),
# p_c* = p*(gbar/gbar_c) the pressure reduced with the rms gradient over
# the contact.
BEGIN { FS = OFS = "\t"; pi = atan2(0, -1) }
# log Gamma by Lanczos (g = 7, 9 terms; relative error ~1e-15 for x > 0.5)
function lgamma(x,   a, t, i, s) {
	split("0.99999999999980993 676.5203681218851 -1259.1392167224028 771.32342877765313 -176.61503916999185 12.507343278686905 -0.13857109526572012 9.9843695780195716e-6 1.5056327351493116e-7", a, " ")
	x -= 1; s = a[1]
	for (i = 1; i < 9; i++) s += a[i + 1] / (x + i)
	t = x + 7.5
	return 0.5 * log(2 * pi) + (x + 0.5) * log(t) - t + log(s)
}
# erf by the continued-fraction-free series/asymptotic pair is overkill:
# Abramowitz-Stegun 7.1.26 has 1.5e-7 absolute error, far below the errors
# studied here (percent).
function erf(x,   t, y, s) {
	s = x < 0 ? -1 : 1; x = s * x
	t = 1 / (1 + 0.3275911 * x)
	y = 1 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t * exp(-x * x)
	return s * y
}
NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i
	print "exponent", "p_star", "a_r", "kappa_c", "kappa_c_eq28", "kappa_c_rel_err", "a_r_eq28", "a_r_rel_err", "nx"; next }
{
	n = $c["exponent"]
	k28 = sqrt(pi / n) * exp(lgamma(n / 2 + 1.5) - lgamma(n / 2 + 1))
	pc = $c["p_star"] * $c["gbar"] / $c["gbar_c"]
	a28 = erf(sqrt(pi) * k28 * pc / 2)
	print n, $c["p_star"], $c["a_r"], $c["kappa_c"], k28, $c["kappa_c"] / k28 - 1, a28, a28 / $c["a_r"] - 1, $c["nx"] | "sort -t'\t' -k1,1g -k2,2g"
}
