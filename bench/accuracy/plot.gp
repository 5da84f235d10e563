# SPDX-License-Identifier: GPL-3.0-or-later
# plot.gp - error of a_r against wall time;
#   gnuplot -e "table='…'; tolerance='…'; out='…'; ref_eps=E" plot.gp
# ref_eps: the coarsest eps_c of the reference's grids.  An estimate that
# uses a grid that fine (eps_c <= ref_eps: for a pair, its finer grid)
# shares data with the reference, so its error is not an independent
# measurement: such points are ringed in red (as verdict.awk leaves them
# out).
set terminal pngcairo size 1000,700 noenhanced
set output out
set logscale xy
set format y "%.0e"
set xlabel "wall time of the solves an estimate needs [s]"
set ylabel "rms relative error of a_r (over seeds)"
set key below horizontal maxcols 3 samplen 2
set grid
set datafile separator "\t"
set title "a_r at p* = 0.05, H = 0.8: error vs cost\n(labels: eps_c = dx/lambda_s; tolerance curves: total error)"
ests = "raw yastrebov_0.118 yastrebov_0.11 richardson_pair yastrebov_mod_pair"
# Pareto front: points no other point beats in both time and error
# (computed by an awk pass over both tables).
front = sprintf("< awk -F'\\t' 'FNR>1 && FILENAME ~ /table/ {print $3\"\\t\"$4} FNR>1 && FILENAME ~ /tolerance/ {print $4\"\\t\"$7}' %s %s | sort -g -k1,1 -k2,2 | awk -F'\\t' 'NR==1 || $2 < best {print; best = $2}'", table, tolerance)
plot for [e in ests] sprintf("< awk -F'\\t' '$1 == \"%s\"' %s | sort -g -k3,3", e, table) \
	using 3:4 with linespoints title e, \
     for [e in ests] sprintf("< awk -F'\\t' '$1 == \"%s\"' %s", e, table) \
	using 3:4:2 with labels offset 1.5,0.5 font ",7" notitle, \
     sprintf("< awk -F'\\t' '$1 == \"fire\"' %s | sort -g -k4,4", tolerance) using 4:7 with linespoints dt 2 title "FIRE, --tol sweep", \
     sprintf("< awk -F'\\t' '$1 == \"cg\"' %s | sort -g -k4,4", tolerance) using 4:7 with linespoints dt 2 title "CG, --tol sweep", \
     front using 1:2 with steps lw 3 lc rgb "black" title "Pareto front", \
     front using 1:2 with points pt 6 ps 2.5 lc rgb "black" notitle, \
     sprintf("< awk -F'\\t' 'NR > 1 && $2 <= %.10g' %s", ref_eps * (1 + 1e-9), table) \
	using 3:4 with points pt 4 ps 3 lw 2 lc rgb "red" \
	title "shares a grid with the reference"
