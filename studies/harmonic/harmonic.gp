# SPDX-License-Identifier: GPL-3.0-or-later
# harmonic.gp - kappa_c vs p* against Eq. 28; a_r error of the prediction
set terminal pngcairo size 1100,500 noenhanced
set output out
set datafile separator "\t"
set logscale x
set grid
set key bottom left
set xlabel "p*"
set multiplot layout 1,2 title "periodically repeated harmonic indenters (Eq. 5) vs Eq. 28"
sel(n) = sprintf("< awk -F'\\t' 'NR > 1 && $1 == \"%s\"' %s", n, data)
set ylabel "kappa_c"
# Each exponent in its own colour, measured (points) and Eq. 28 (dashed,
# same colour); the key names both.
plot for [k = 1:words(exponents)] sel(word(exponents, k)) using 2:4 \
         with linespoints lc k lw 2 title "n = ".word(exponents, k), \
     for [k = 1:words(exponents)] sel(word(exponents, k)) using 2:5 \
         with lines dt 2 lc k lw 2 notitle, \
     NaN with lines dt 2 lc rgb "black" lw 2 title "Eq. 28 (dashed)"
set ylabel "a_r(Eq. 8 + 28) / a_r - 1"
set xlabel "a_r"
unset logscale x
set yrange [-0.55:0.4]
set key bottom right
plot for [k = 1:words(exponents)] sel(word(exponents, k)) using 3:8 \
         with linespoints lc k lw 2 title "n = ".word(exponents, k), \
     0.25 with lines dt 2 lc rgb "red" title "+-25%", -0.25 with lines dt 2 lc rgb "red" notitle
unset multiplot
