# SPDX-License-Identifier: GPL-3.0-or-later
# nayak.gp - kappa vs Nayak parameter per H and spectrum type
set terminal pngcairo size 800,550 noenhanced
set output out
set datafile separator "\t"
set logscale x
set grid
set key bottom right
set xlabel "Nayak parameter m0 m4 / m2^2"
set ylabel "kappa at p* = 0.05 (continuum-extrapolated, seed mean)"
set title "kappa vs Nayak parameter (labels: eps_f)"
sel(h, s) = sprintf("< awk -F'\\t' 'NR > 1 && $1 == \"%s\" && $2 == \"%s\"' %s | sort -g -k4,4", h, s, data)
plot for [h in "0.3 0.8"] for [s in "cutoff rolloff"] sel(h, s) using 4:6:7 with yerrorlines title "H = ".h.", ".s, \
     for [h in "0.3 0.8"] for [s in "cutoff rolloff"] sel(h, s) using 4:6:3 with labels offset 0,1 font ",7" notitle
