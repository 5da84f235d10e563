# harmonic.gp - kappa_c vs p* against Eq. 28; a_r error of the prediction
set terminal pngcairo size 1100,500 noenhanced
set output out
set datafile separator "\t"
set logscale x
set grid
set key top right
set xlabel "p*"
set multiplot layout 1,2 title "periodically repeated harmonic indenters (Eq. 5) vs Eq. 28"
sel(n) = sprintf("< awk -F'\\t' 'NR > 1 && $1 == \"%s\"' %s", n, data)
set ylabel "kappa_c"
plot for [n in exponents] sel(n) using 2:4 with linespoints title "n = ".n, \
     for [n in exponents] sel(n) using 2:5 with lines dt 2 lc rgb "gray" notitle
set ylabel "a_r(Eq. 8 + 28) / a_r - 1"
set xlabel "a_r"
unset logscale x
set yrange [-0.4:0.4]
plot for [n in exponents] sel(n) using 3:8 with linespoints title "n = ".n, \
     0.25 with lines dt 2 lc rgb "red" title "+-25%", -0.25 with lines dt 2 lc rgb "red" notitle
unset multiplot
