# SPDX-License-Identifier: GPL-3.0-or-later
# kappa.gp - kappa and kappa_c vs p* with error bars, one curve per
# "curve" value; gnuplot -e "data='…'; out='…'; curves='…'; title='…'" kappa.gp
set terminal pngcairo size 1100,500 noenhanced
set output out
set datafile separator "\t"
set logscale x
set xlabel "p*"
set key top right font ",8"
set grid
set multiplot layout 1,2 title title
sel(c) = sprintf("< awk -F'\\t' '$1 == \"%s\"' %s | sort -g -k2,2", c, data)
set ylabel "kappa (Eq. 24)"
plot for [c in curves] sel(c) using 2:3:4 with yerrorlines title c
set ylabel "kappa_c (Eq. 8, gbar over contact)"
plot for [c in curves] sel(c) using 2:5:6 with yerrorlines title c
unset multiplot
