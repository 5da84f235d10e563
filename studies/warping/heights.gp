# SPDX-License-Identifier: GPL-3.0-or-later
# heights.gp - height histogram and gbar(h) per warp exponent
set terminal pngcairo size 1100,500 noenhanced
set output out
set datafile separator "\t"
set grid
set key top left
set multiplot layout 1,2 title "warped surfaces, rms gradient 1, H = 0.8, one seed"
sel(w) = sprintf("< awk -F'\\t' 'NR > 1 && $1 == \"%s\"' %s", w, data)
set xlabel "h"
set ylabel "probability density"
plot for [w in warps] sel(w) using 4:12 with linespoints title "w = ".w
set ylabel "gbar(h): rms gradient in the height bin"
plot for [w in warps] sel(w) using 4:7 with linespoints title "w = ".w
unset multiplot
