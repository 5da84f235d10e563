# SPDX-License-Identifier: GPL-3.0-or-later
# contact-stats on synthetic result rows with known limits: grouping by
# resolution and by seed, the three estimators, kappa and its error, the
# fractal and thermodynamic limits, --schedule, --json, bad input.
. "$RC_TOP/tests/e2e/lib.sh"
cd "$T_TMP" || exit 1

# rows SEEDS NXS PSTARS [LAMBDA_S] [LX] [EXPONENT] [H]: gfmd-solve-shaped rows with
#   a_r = a0 + 0.02 eps_c^EXPONENT, a0 = 0.1 p*/0.05 + 0.001 seed + 0.05 eps_f,
#   eps_c = (LX/nx)/LAMBDA_S, eps_f = LAMBDA_S/0.5, lambda_r = 0.5;
#   n_cl = 0.3 n_c; gbar = 1, gbar_c = 1.2.
rows() {
	awk -v seeds="$1" -v nxs="$2" -v ps="$3" -v ls="${4:-0.0625}" -v lx="${5:-1}" \
	    -v ex="${6:-1}" -v H="${7:-0.8}" 'BEGIN {
		OFS = "\t"
		print "p_star", "p", "a_r", "n_c", "n_cl", "n_tot", "a_yastrebov", "gbar",
		    "gbar_c", "gbar_c_prime", "kappa", "kappa_c", "mean_gap",
		    "elastic_energy", "n_patches", "patch_size_char", "iterations",
		    "residual", "seconds", "method", "nx", "ny", "lx", "ly", "type", "H",
		    "lambda_r", "lambda_s", "seed"
		ns = split(seeds, S, ","); nn = split(nxs, N, ","); np = split(ps, P, ",")
		for (i = 1; i <= ns; i++) for (k = 1; k <= np; k++) for (j = 1; j <= nn; j++) {
			nx = N[j]; eps = (lx / nx) / ls
			a = 0.1 * P[k] / 0.05 + 0.001 * S[i] + 0.05 * ls / 0.5 + 0.02 * eps ^ ex
			ntot = nx * nx; nc = a * ntot; ncl = 0.3 * nc
			printf "%s\t%s\t%.17g\t%.17g\t%.17g\t%d\t0\t1\t1.2\t1.1\t0\t0\t0.1\t0.01\t10\t5\t100\t1e-9\t0.1\tfire\t%d\t%d\t%s\t%s\tselfaffine\t%s\t0.5\t%s\t%s\n",
			    P[k], P[k], a, nc, ncl, ntot, nx, nx, lx, lx, H, ls, S[i]
		}
	}'
}

# erf by its Taylor series (converges fast for the x < 1 used here).
erf_awk='function erf(x,   s, t, n) { s = 0; t = x; for (n = 0; n < 60; n++) { s += t / (2 * n + 1); t *= -x * x / (n + 1) } return 2 / sqrt(3.141592653589793) * s }'

rows 1,2,3 64,128,256 0.05,0.1 >a.tsv
check_status "three seeds, three resolutions, two pressures" 0 contact-stats -o out.tsv a.tsv
check_rel "two rows (one per pressure)" "$(($(wc -l <out.tsv) - 1))" 2 0
# Exactly linear in eps_c: Richardson is exact up to round-off; mean over
# seeds 1..3 of 0.1 + 0.001 s + 0.05/8 = 0.10825.
check_rel "a_r at p*=0.05 is the seed mean of a0" "$(col out.tsv a_r 1)" 0.10825 1e-13
check_rel "a_r at p*=0.1" "$(col out.tsv a_r 2)" 0.20825 1e-13
check_rel "a_r_sd = sd of 0.001 s" "$(col out.tsv a_r_sd 1)" 0.001 1e-9
# Extrapolation error ~ 0, so a_r_err is the standard error sd/sqrt(3)
# and the mean counting floor (a_r_floor, lib/cstats.h; exact values in
# tests/test_cstats.c) in quadrature.
check "a_r_floor positive" awk -v f="$(col out.tsv a_r_floor 1)" 'BEGIN { exit !(f > 0) }'
check_rel "a_r_err = hypot(standard error, floor)" "$(col out.tsv a_r_err 1)" "$(awk -v f="$(col out.tsv a_r_floor 1)" 'BEGIN { printf "%.17g", sqrt(0.001 ^ 2 / 3 + f * f) }')" 1e-9
check_rel "n_seeds" "$(col out.tsv n_seeds 1)" 3 0
check_rel "n_disc" "$(col out.tsv n_disc 1)" 3 0
check "eps_c values listed" test "$(col out.tsv eps_c 1)" = "0.0625,0.125,0.25"
check "method column" test "$(col out.tsv method 1)" = "richardson(1)+ensemble"
check "H key carried" test "$(col out.tsv H 1)" = "0.8"
check "seed is averaged out" test "$(col out.tsv seed 1)" = "missing-column-seed"
check "gfmd-solve's method column kept as key_method" test "$(col out.tsv key_method 1)" = fire
# kappa through Eq. 24: erf(sqrt(pi) kappa p*/2) must give a_r back.
k=$(col out.tsv kappa 1)
check_rel "Eq. 24 round trip" "$(awk -v k="$k" "$erf_awk"' BEGIN { printf "%.17g", erf(sqrt(3.141592653589793) * k * 0.05 / 2) }')" 0.10825 1e-12
# kappa_err = exp(x^2) a_r_err / p*, x = erfinv(a_r) = sqrt(pi) kappa p*/2.
check_rel "kappa_err by the derivative of erfinv" "$(col out.tsv kappa_err 1)" \
    "$(awk -v k="$k" -v e="$(col out.tsv a_r_err 1)" 'BEGIN { x = sqrt(3.141592653589793) * k * 0.05 / 2; printf "%.17g", exp(x * x) * e / 0.05 }')" 1e-9
check_rel "kappa_c = kappa gbar_c/gbar" "$(col out.tsv kappa_c 1)" "$(awk -v k="$k" 'BEGIN { printf "%.17g", 1.2 * k }')" 1e-12
check_rel "a_over_p" "$(col out.tsv a_over_p 1)" "$(awk 'BEGIN { printf "%.17g", 0.10825 / 0.05 }')" 1e-12
# Yastrebov at the finest grid (nx = 256): (n_c - alpha n_cl)/n_tot = a (1 - 0.3 alpha)
# with a the raw finest a_r, averaged over seeds.
check_rel "Yastrebov estimate, Eq. 22" "$(col out.tsv a_yastrebov 1)" \
    "$(awk 'BEGIN { al = (3.141592653589793 - 1 + log(2)) / 24; a = 0.10825 + 0.02 * 0.0625; printf "%.17g", a * (1 - 0.3 * al) }')" 1e-12
# Modified Yastrebov: n_c/N = a0 + 0.02 eps, n_cl/N = 0.3 (a0 + 0.02 eps):
# alpha = (n_c1/N1 - n_c2/N2)/(n_cl1/N1 - n_cl2/N2) = 1/0.3.
check_rel "modified-Yastrebov alpha" "$(col out.tsv alpha_mod 1)" "$(awk 'BEGIN { printf "%.17g", 1 / 0.3 }')" 1e-9

# Per seed: three rows per pressure, each with its seed.
check_status "--per-seed" 0 contact-stats --per-seed -o ps.tsv a.tsv
check_rel "--per-seed rows" "$(($(wc -l <ps.tsv) - 1))" 6 0
check_rel "seed 2 at p*=0.05" "$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next } $c["seed"] == 2 && $c["p_star"] == 0.05 { print $c["a_r"] }' ps.tsv)" 0.10825 1e-13

# surfwarp's warp_hmin/warp_hmax follow the sampled heights and differ
# between grids: not keys, so the sets stay together.
awk -F'\t' -v OFS='\t' 'NR == 1 { print $0, "warp", "warp_hmin"; next } { print $0, 2, -1 - 1 / $21 }' a.tsv >w.tsv
check_status "warp_hmin differs per grid" 0 contact-stats -o w-out.tsv w.tsv
check_rel "warp_hmin is not a key: still one row per pressure" "$(($(wc -l <w-out.tsv) - 1))" 2 0
check "warp is a key" test "$(col w-out.tsv warp 1)" = 2
check_status "--group-by warp_hmin splits the sets (one grid each)" 1 contact-stats --group-by warp_hmin w.tsv
check_status "--ignore H" 0 contact-stats --ignore H,type -o ig.tsv a.tsv
check "--ignore drops the key column" test "$(col ig.tsv H 1)" = missing-column-H

# Different Hurst exponents are different groups.
rows 1,2 64,128 0.05 0.0625 1 1 0.3 >h3.tsv
check_status "two files" 0 contact-stats -o two.tsv a.tsv h3.tsv
check_rel "H=0.3 adds one group" "$(($(wc -l <two.tsv) - 1))" 3 0
check "curves in input order, H=0.3 last" test "$(col two.tsv H 3)" = 0.3
# Standard input, cat-joined files (repeated header) and JSON give the same.
cat a.tsv h3.tsv | contact-stats - >cat.tsv 2>/dev/null
check "stdin with a repeated header = two files" cmp -s cat.tsv two.tsv
awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) h[i] = $i; n = NF; print "["; next }
	{ printf "%s  {", (NR > 2 ? ",\n" : ""); for (i = 1; i <= n; i++) printf "%s\"%s\": %s", (i > 1 ? ", " : ""), h[i], ($i ~ /^[-0-9.e]+$/ ? $i : "\"" $i "\""); printf "}" }
	END { print "\n]" }' a.tsv >a.json
contact-stats a.json h3.tsv >json-in.tsv 2>/dev/null
check "JSON input = TSV input" cmp -s json-in.tsv two.tsv
check_status "--json output" 0 contact-stats --json -o out.json a.tsv
check "--json has two objects with kappa" test "$(grep -c '"kappa":' out.json)" = 2
check "--json is an array" test "$(head -c 1 out.json)" = "["

# Order auto: a_r = a0 + 0.02 eps^1.5 at three resolutions.
rows 1 64,128,256 0.05 0.0625 1 1.5 >o15.tsv
check_status "--order auto" 0 contact-stats --order auto -o auto.tsv o15.tsv
check_rel "fitted exponent 1.5" "$(col auto.tsv order 1)" 1.5 1e-9
check_rel "auto recovers a0" "$(col auto.tsv a_r 1)" 0.10725 1e-10
# The linear two-point formula leaves 0.02 (2 e1^1.5 - e2^1.5), e = 1/16, 1/8.
contact-stats -o lin.tsv o15.tsv 2>/dev/null
check_rel "linear model leaves the closed-form remainder" "$(col lin.tsv a_r 1)" \
    "$(awk 'BEGIN { printf "%.17g", 0.10725 + 0.02 * (2 * 0.0625 ^ 1.5 - 0.125 ^ 1.5) }')" 1e-12

# Fractal limit: lambda_s = 1/16 and 1/32 at lambda_r = 0.5 (eps_f = 1/8,
# 1/16): a0 contains 0.05 eps_f, so eps_f -> 0 gives 0.1 + 0.001 seed.
rows 1,2 64,128 0.05 0.0625 >f1.tsv
rows 1,2 128,256 0.05 0.03125 >f2.tsv
check_status "--fractal" 0 contact-stats --fractal -o frac.tsv f1.tsv f2.tsv
check_rel "fractal: one row" "$(($(wc -l <frac.tsv) - 1))" 1 0
check_rel "fractal limit" "$(col frac.tsv a_r 1)" 0.1015 1e-12
check "lambda_s shown as limit" test "$(col frac.tsv lambda_s 1)" = limit
check "eps_f values listed" test "$(col frac.tsv eps_f 1)" = "0.0625,0.125"
check_status "--fractal with one eps_f fails" 1 contact-stats --fractal f1.tsv
# Thermodynamic limit: lx = 1 and 2 (eps_t = 0.5, 0.25) at the same
# eps_c grid; these rows do not depend on lx, so the limit is the value.
rows 1,2 64,128 0.05 0.0625 2 >t2.tsv
check_status "--thermo" 0 contact-stats --thermo -o th.tsv f1.tsv t2.tsv
check_rel "thermo limit of lx-independent rows" "$(col th.tsv a_r 1)" 0.10775 1e-12
check "lx shown as limit" test "$(col th.tsv lx 1)" = limit

# One discretisation: an error naming the group and the row; allowed raw.
rows 1 128 0.05 >one.tsv
check_status "one discretisation fails" 1 contact-stats one.tsv
contact-stats one.tsv 2>err.txt
check "the message names the group and file:line" grep -q "group p_star=0.05 .*seed=1.*one.tsv:2.*1 discretisation" err.txt
check_status "--no-extrapolate" 0 contact-stats --no-extrapolate -o raw.tsv one.tsv
check_rel "--no-extrapolate gives the raw value" "$(col raw.tsv a_r 1)" "$(awk 'BEGIN { printf "%.17g", 0.1 + 0.001 + 0.00625 + 0.02 / 128 / 0.0625 }')" 1e-13
# --order auto where a set has two grids: linear there, order_err nan.
check_status "--order auto with two discretisations" 0 contact-stats --order auto -o a2.tsv h3.tsv
check "two grids: linear fallback" test "$(col a2.tsv order 1)/$(col a2.tsv order_err 1)" = "1/nan"
check_rel "two grids: the linear value" "$(col a2.tsv a_r 1)" 0.10775 1e-12

# a_r = 1 (full contact) gives kappa = inf (JSON null); a_r = 0 gives 0.
awk -F'\t' -v OFS='\t' 'NR == 1 || $1 == 0.05 { if (NR > 1) $3 = 1; print }' a.tsv >full.tsv
check_status "full contact" 0 contact-stats -o full-out.tsv full.tsv
check "a_r = 1: kappa = inf" test "$(col full-out.tsv a_r 1)/$(col full-out.tsv kappa 1)" = "1/inf"
check "a_r = 1: JSON null" grep -q '"kappa": null' "$(contact-stats --json -o full.json full.tsv; echo full.json)"
awk -F'\t' -v OFS='\t' 'NR == 1 || $1 == 0.05 { if (NR > 1) $3 = 0; print }' a.tsv >none.tsv
contact-stats -o none-out.tsv none.tsv
check "a_r = 0: kappa = 0" test "$(col none-out.tsv kappa 1)" = 0
# A linear extrapolation below zero is clamped to 0, with a warning.
awk -F'\t' -v OFS='\t' 'NR == 1 || $1 == 0.05 { if (NR > 1) $3 = $21 == 64 ? 0.02 : ($21 == 128 ? 0.005 : 0.001); print }' a.tsv >neg.tsv
contact-stats -o neg-out.tsv neg.tsv 2>err.txt
check "negative extrapolation clamped" test "$(col neg-out.tsv a_r 1)" = 0
check "... with a warning" grep -q "left \[0, 1\]; clamped" err.txt

# Bad input: precise messages, exit 1; --lenient skips with a count.
sed '3s/\t0\.1[0-9]*\t/\t1.5\t/' a.tsv >ar.tsv
contact-stats ar.tsv >/dev/null 2>err.txt; st=$?
check "a_r > 1: exit 1" test "$st" = 1
check "a_r > 1: file:line and column" grep -q "ar.tsv:3: column 'a_r': 1.5 is outside" err.txt
sed '4s/^0\.05/abc/' a.tsv >nn.tsv
contact-stats nn.tsv >/dev/null 2>err.txt; st=$?
check "non-numeric p_star: exit 1" test "$st" = 1
check "non-numeric p_star: named" grep -q "nn.tsv:4: column 'p_star': 'abc' is not a finite number" err.txt
cut -f1-2,4- a.tsv >mc.tsv
contact-stats mc.tsv >/dev/null 2>err.txt; st=$?
check "missing a_r column: exit 1" test "$st" = 1
check "missing column named" grep -q "mc.tsv:2: no column 'a_r'" err.txt
{ cat a.tsv; sed -n 2p a.tsv; } >dup.tsv
contact-stats dup.tsv >/dev/null 2>err.txt; st=$?
check "duplicate rows: exit 1" test "$st" = 1
check "duplicate rows: both lines named" grep -q "dup.tsv:2 and dup.tsv:20: duplicate rows" err.txt
printf 'p_star\ta_r\n0.05\n' >short.tsv
check_status "short row" 1 contact-stats short.tsv
check_status "empty input" 1 contact-stats /dev/null
check_status "missing file" 1 contact-stats no-such-file.tsv
contact-stats --lenient -o len.tsv ar.tsv 2>err.txt; st=$?
check "--lenient: exit 0" test "$st" = 0
check "--lenient: the skip is counted" grep -q "skipped 1 bad row" err.txt
check_rel "--lenient: the seed-1 set lost a point, still 3 seeds" "$(col len.tsv n_seeds 1)" 3 0
contact-stats --lenient -o lendup.tsv dup.tsv 2>err.txt; st=$?
check "--lenient duplicate: exit 0, later row dropped" test "$st" = 0
check "--lenient duplicate: counted" grep -q "skipped 1 bad row.*dup.tsv:2 and dup.tsv:20" err.txt
check_rel "--lenient duplicate: result unchanged" "$(col lendup.tsv a_r 1)" "$(col out.tsv a_r 1)" 0
contact-stats -o never.tsv ar.tsv 2>/dev/null
check "failed run leaves no output" test ! -e never.tsv

# Usage errors: exit 2.
check_status "--order bogus" 2 contact-stats --order x a.tsv
check_status "--fit bogus" 2 contact-stats --fit z a.tsv
check_status "--schedule without -p" 2 contact-stats --schedule --eps-ref 0.1 --p-ref 0.2
check_status "-p without --schedule" 2 contact-stats -p 0.1 a.tsv
check_status "--help" 0 contact-stats --help

# Eq. 27 schedule (Figure 4: 1/32 at p* = 0.2 -> 1/64 at p* = 0.0125).
contact-stats --schedule --eps-ref 0.03125 --p-ref 0.2 -p 0.2,0.1,0.0125 >sch.tsv
check_rel "schedule at p_ref" "$(col sch.tsv eps 1)" 0.03125 0
check_rel "schedule at p_ref/2" "$(col sch.tsv eps 2)" "$(awk 'BEGIN { printf "%.17g", 0.03125 * 0.5 ^ 0.25 }')" 1e-15
check_rel "schedule at p_ref/16" "$(col sch.tsv eps 3)" 0.015625 1e-15
check_rel "inverse" "$(col sch.tsv inv_eps 3)" 64 1e-15
check "schedule --json" test "$(contact-stats --schedule --json --eps-ref 1 --p-ref 1 -p 16 | grep -c '"eps": 2')" = 1

# Gnuplot script: written; run when gnuplot is installed.
check_status "--gnuplot" 0 contact-stats --gnuplot k.gp -o /dev/null a.tsv h3.tsv
check "script plots kappa with error bars" grep -q "yerrorlines" k.gp
check "one curve per H" test "$(grep -c '^\$curve[0-9]* << EOD' k.gp)" = 2
# a.tsv has p* 0.05 and 0.1 (h3.tsv 0.05): a labelled tick at each
check "every p* tick labelled: at the two pressures" \
    grep -qx "set xtics ('0.05' 0.05, '0.1' 0.1)" k.gp
contact-stats --gnuplot k1.gp -o /dev/null h3.tsv
check "one pressure: one labelled tick (none before)" grep -qx "set xtics ('0.05' 0.05)" k1.gp
rows 1 64,128 0.001,0.002,0.003,0.005,0.01,0.02,0.03,0.05,0.1,0.2,0.3 >many.tsv
contact-stats --gnuplot km.gp -o /dev/null many.tsv
check "many pressures: labelled ticks at 1, 2, 5 x 10^k in the range" \
    grep -qx "set xtics ('0.001' 0.001, '0.002' 0.002, '0.005' 0.005, '0.01' 0.01, '0.02' 0.02, '0.05' 0.05, '0.1' 0.1, '0.2' 0.2)" km.gp
persson=$(grep "title 'Persson" k.gp | grep -o "lc rgb '#[0-9a-f]*'")
bgt=$(grep "title 'BGT" k.gp | grep -o "lc rgb '#[0-9a-f]*'")
check "Persson and BGT lines in distinct colours ($persson, $bgt)" \
    [ -n "$persson" ] && [ -n "$bgt" ] && [ "$persson" != "$bgt" ]
check "data curves in neither reference colour" \
    sh -c "! grep yerrorlines k.gp | grep -q -e \"$persson\" -e \"$bgt\""
check "legend above the plot, not beside it" grep -qx "set key above horizontal samplen 2" k.gp
if command -v gnuplot >/dev/null 2>&1; then
	gnuplot k.gp 2>/dev/null
	check "gnuplot makes a PNG" test "$(od -An -tx1 -N4 k.png 2>/dev/null | tr -d ' ')" = 89504e47
else
	skip 1 "gnuplot not installed: the --gnuplot script is not run (apt-get install gnuplot-nox)"
fi
# Review fixes.  Unknown options: one line of ours, no getopt message.
contact-stats --bogus a.tsv >/dev/null 2>err.txt; st=$?
check "--bogus: exit 2" test "$st" = 2
check "--bogus: reported once, as tool: option: why" test "$(grep -c 'bogus' err.txt)/$(head -n 1 err.txt)" = "1/contact-stats: --bogus: unknown option"
# Columns of the review: the used eps_c, both Yastrebov alphas, a_r_se.
check "eps_c_used: the finest pair of three (linear, finest)" test "$(col out.tsv eps_c_used 1)" = "0.0625,0.125"
check_rel "a_r_se = 0.001/sqrt(3)" "$(col out.tsv a_r_se 1)" "$(awk 'BEGIN { printf "%.17g", 0.001 / sqrt(3) }')" 1e-9
check_rel "a_yastrebov_011 (alpha = 0.11, Eq. 23)" "$(col out.tsv a_yastrebov_011 1)" \
    "$(awk 'BEGIN { a = 0.10825 + 0.02 * 0.0625; printf "%.17g", a * (1 - 0.3 * 0.11) }')" 1e-12
contact-stats --alpha 0.2 -o al.tsv a.tsv 2>/dev/null
check_rel "--alpha changes a_yastrebov" "$(col al.tsv a_yastrebov 1)" \
    "$(awk 'BEGIN { a = 0.10825 + 0.02 * 0.0625; printf "%.17g", a * (1 - 0.3 * 0.2) }')" 1e-12
check "--alpha leaves a_yastrebov_011" test "$(col al.tsv a_yastrebov_011 1)" = "$(col out.tsv a_yastrebov_011 1)"
# Forty grids: every eps_c listed in full (no fixed-size buffer), lsq uses all.
rows 1 "$(awk 'BEGIN { for (n = 100; n < 140; n++) printf "%s%d", (n > 100 ? "," : ""), n }')" 0.05 >many.tsv
check_status "forty discretisations, lsq" 0 contact-stats --fit lsq -o many-out.tsv many.tsv
check_rel "all forty eps_c listed" "$(col many-out.tsv eps_c 1 | tr ',' '\n' | wc -l)" 40 0
check "eps_c_used = eps_c for lsq" test "$(col many-out.tsv eps_c_used 1)" = "$(col many-out.tsv eps_c 1)"
check_rel "the exact eps_c of nx = 137 is listed" "$(col many-out.tsv eps_c 1 | tr ',' '\n' | sed -n 3p)" \
    "$(awk 'BEGIN { printf "%.17g", 16 / 137 }')" 1e-16
# Two outputs on standard output: refused.
check_status "--gnuplot - with the table on stdout" 2 contact-stats --gnuplot - a.tsv
check_status "--gnuplot - with -o" 0 contact-stats --gnuplot - -o /dev/null a.tsv
check_status "--png - with the table on stdout" 2 contact-stats --png - a.tsv
# -j: checked, no effect (one thread): no note about cores (it said
# "more threads than the 2 cores available; using 2").
contact-stats -j 4096 --no-extrapolate -o /dev/null a.tsv 2>j.err
check "-j 4096: no note about cores ($(head -c 120 j.err))" test ! -s j.err
check_status "-j 0: a usage error" 2 contact-stats -j 0 --no-extrapolate -o /dev/null a.tsv
# --png: gnuplot run on the script, written atomically.
mkdir -p png nobin fakebin
printf '#!/bin/sh\necho "fake gnuplot fails" >&2\nexit 3\n' >fakebin/gnuplot
chmod +x fakebin/gnuplot
PATH="$T_TMP/nobin" "$RC_BIN/contact-stats" --png png/k.png -o png/t.tsv a.tsv 2>err.txt; st=$?
check "--png without gnuplot: exit 1" test "$st" = 1
check "--png without gnuplot: the message" grep -qx "contact-stats: --png: gnuplot not found; use --gnuplot FILE to get the script" err.txt
check "--png without gnuplot: the table is written" test "$(col png/t.tsv a_r 1)" = "$(col out.tsv a_r 1)"
PATH="$T_TMP/fakebin" "$RC_BIN/contact-stats" --png png/k.png -o /dev/null a.tsv 2>err.txt; st=$?
check "--png with a failing gnuplot: exit 1" test "$st" = 1
check "--png with a failing gnuplot: said so" grep -q "gnuplot failed (exit status 3)" err.txt
check "a failed --png leaves nothing beside the target" test "$(ls -A png)" = t.tsv
# A gnuplot that exits 0 but wrote no whole PNG (what a full disk did:
# the old picture replaced by 0 bytes, exit 0): refused, the old file
# kept.  The fake writes the signature and half an IHDR, or, to show the
# check takes a whole file, the signature and the IEND chunk.
mkdir -p halfbin wholebin
cat >halfbin/gnuplot <<'SH'
#!/bin/sh
out=$(sed -n "s/^set output '\(.*\)'.*/\1/p" "$1")
printf '\211PNG\r\n\032\n\0\0\0\rIHDR' >"$out"
SH
cat >wholebin/gnuplot <<'SH'
#!/bin/sh
out=$(sed -n "s/^set output '\(.*\)'.*/\1/p" "$1")
printf '\211PNG\r\n\032\n\0\0\0\0IEND\256B`\202' >"$out"
SH
chmod +x halfbin/gnuplot wholebin/gnuplot
echo old >png/old.png
PATH="$T_TMP/halfbin:$PATH" "$RC_BIN/contact-stats" --png png/old.png -o /dev/null a.tsv 2>err.txt; st=$?
check "--png, gnuplot exits 0 with half a PNG: exit 1" test "$st" = 1
check "--png, half a PNG: said so" grep -q "png/old.png: gnuplot exited 0 but wrote no whole PNG" err.txt
check "--png, half a PNG: the old file kept" test "$(cat png/old.png)" = old
check "--png, half a PNG: nothing left beside it" test "$(ls -A png | tr '\n' ' ')" = "old.png t.tsv "
PATH="$T_TMP/halfbin:$PATH" "$RC_BIN/contact-stats" --png - -o /dev/null a.tsv >png/half.out 2>err.txt; st=$?
check "--png - with half a PNG: exit 1, nothing on stdout" test "$st:$(wc -c <png/half.out)" = "1:0"
PATH="$T_TMP/wholebin:$PATH" "$RC_BIN/contact-stats" --png png/old.png -o /dev/null a.tsv 2>err.txt; st=$?
check "--png, a whole (if tiny) PNG: exit 0, written" test "$st:$(wc -c <png/old.png)" = "0:20"
rm -f png/old.png png/half.out
# Issue 27: --per-seed compared every output group with every other
# (twice: the curve order and the labels), 9,000 rows 19.7 s, 18,000
# rows 79.7 s; n log n now (bench/bench_cstats_perseed.sh, these rows:
# 18,000 took 9.9 s of CPU, 0.33 s now).  60,000 rows under a CPU limit
# of 30 s: about 1.2 s now, some 110 s quadratic (margins of 25 and 4,
# so the load of the machine does not decide).
awk 'BEGIN { OFS = "\t"; print "p_star", "a_r", "nx", "ny", "lx", "ly", "lambda_s", "seed"
	for (s = 1; s <= 10000; s++) for (k = 1; k <= 2; k++) for (j = 0; j < 3; j++) {
		nx = 64 * 2 ^ j
		print 0.05 * k, 0.1 * k + 0.001 * (s % 97) + 0.32 / nx, nx, nx, 1, 1, 0.0625, s } }' > seeds.tsv
(ulimit -t 30; contact-stats -q --per-seed -o seeds.out seeds.tsv) 2>/dev/null
check_rel "--per-seed on 60,000 rows within 30 s of CPU: exit 0" $? 0 0
check_rel "  one row per seed and pressure" "$(($(wc -l < seeds.out 2>/dev/null || echo 0) - 1))" 20000 0
# Issue 27: the gnuplot of a killed contact-stats ran on.  A slow fake
# gnuplot (its pid in a file, then exec sleep: the same process) is
# started; contact-stats is killed (SIGKILL: no handler runs); the fake
# must be gone within a second.  TMPDIR is the test's: the killed run's
# gnuplot script, which no handler can remove, was left in /tmp.
mkdir -p slowbin
printf '#!/bin/sh\necho $$ > "%s/slow.pid"\nexec sleep 30\n' "$T_TMP" >slowbin/gnuplot
chmod +x slowbin/gnuplot
TMPDIR="$T_TMP" PATH="$T_TMP/slowbin:$PATH" "$RC_BIN/contact-stats" --png png/slow.png -o /dev/null a.tsv 2>/dev/null &
cpid=$!
i=0
while [ ! -s slow.pid ] && [ $i -lt 200 ]; do sleep 0.05; i=$((i + 1)); done
kill -KILL $cpid 2>/dev/null; wait $cpid 2>/dev/null
gp=$(cat slow.pid 2>/dev/null)
# alive: not a zombie (a killed orphan waits there for its reaper)
alive() { kill -0 "$1" 2>/dev/null && ! grep -q '^State:.*Z' "/proc/$1/status" 2>/dev/null; }
i=0
while [ -n "$gp" ] && alive "$gp" && [ $i -lt 100 ]; do sleep 0.05; i=$((i + 1)); done
if [ -z "$gp" ]; then
	fail "killed contact-stats: the fake gnuplot never started"
elif alive "$gp"; then
	fail "killed contact-stats: its gnuplot (pid $gp) runs on"
	kill "$gp" 2>/dev/null
else
	pass "killed contact-stats: its gnuplot died too"
fi
rm -f png/.slow.png.* 2>/dev/null
if command -v gnuplot >/dev/null 2>&1; then
	check_status "--png" 0 contact-stats --png png/k.png -o /dev/null a.tsv h3.tsv
	check "--png writes a PNG" test "$(od -An -tx1 -N8 png/k.png | tr -d ' ')" = 89504e470d0a1a0a
	check "--png leaves no temporary file" test "$(ls -A png | tr '\n' ' ')" = "k.png t.tsv "
	contact-stats --png - -o /dev/null a.tsv >png/stdout.png 2>/dev/null
	check "--png - writes the PNG to standard output" test "$(od -An -tx1 -N4 png/stdout.png | tr -d ' ')" = 89504e47
else
	skip 5 "gnuplot not installed: --png output not tested (apt-get install gnuplot-nox)"
fi
summary
