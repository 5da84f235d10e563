# SPDX-License-Identifier: GPL-3.0-or-later
# plot.gp - error of a_r against wall time, each estimator with each
# elastic kernel (rms over seeds and the pressures: table rows p_star "all");
#   gnuplot -e "table='…'; tolerance='…'; out='…'; ref_eps=E" plot.gp
# ref_eps: the coarsest eps_c of the reference's grids.  A continuum
# estimate that uses a grid that fine (eps_c <= ref_eps: for a pair, its
# finer grid) shares data with the reference, so its error is not an
# independent measurement: such points are ringed in red (as verdict.awk
# leaves them out).
set terminal pngcairo size 1100,750 noenhanced
set output out
set logscale xy
set format y "%.0e"
set xlabel "wall time of the solves an estimate needs [s]"
set ylabel "rms relative error of a_r (over seeds and p* = 0.02, 0.05, 0.1)"
set key below horizontal maxcols 4 samplen 2
set grid
set datafile separator "\t"
set title "a_r, H = 0.8: error vs cost, continuum (solid) and pixel (dashed) kernels\n(labels: eps_c = dx/lambda_s; tolerance curves: total error at p* = 0.05)"
ests = "raw yastrebov_0.118 yastrebov_0.11 richardson_pair yastrebov_mod_pair subpixel subpixel_richardson_pair"
sel(e, k) = sprintf("< awk -F'\\t' '$1 == \"%s\" && $2 == \"%s\" && $3 == \"all\"' %s | sort -g -k5,5", e, k, table)
# Pareto front over the estimates (all rows), an awk pass
front = sprintf("< awk -F'\\t' 'FNR>1 && $3 == \"all\" {print $5\"\\t\"$6}' %s | sort -g -k1,1 -k2,2 | awk -F'\\t' 'NR==1 || $2 < best {print; best = $2}'", table)
plot for [i=1:words(ests)] sel(word(ests, i), "continuum") using 5:6 with linespoints lc i dt 1 title word(ests, i)." continuum", \
     for [i=1:words(ests)] sel(word(ests, i), "pixel") using 5:6 with linespoints lc i dt 2 pt 6 title word(ests, i)." pixel", \
     for [i=1:words(ests)] sel(word(ests, i), "continuum") using 5:6:4 with labels offset 1.5,0.5 font ",7" notitle, \
     sprintf("< awk -F'\\t' '$1 == \"fire\"' %s | sort -g -k4,4", tolerance) using 4:7 with linespoints dt 3 lc rgb "gray40" title "FIRE, --tol sweep", \
     sprintf("< awk -F'\\t' '$1 == \"cg\"' %s | sort -g -k4,4", tolerance) using 4:7 with linespoints dt 3 lc rgb "gray70" title "CG, --tol sweep", \
     front using 1:2 with steps lw 3 lc rgb "black" title "Pareto front", \
     front using 1:2 with points pt 6 ps 2.5 lc rgb "black" notitle, \
     sprintf("< awk -F'\\t' 'NR > 1 && $2 == \"continuum\" && $3 == \"all\" && $4 <= %.10g' %s", ref_eps * (1 + 1e-9), table) \
	using 5:6 with points pt 4 ps 3 lw 2 lc rgb "red" \
	title "shares a grid with the reference"
