# SPDX-License-Identifier: GPL-3.0-or-later
# thought.gp - what carving and flipping do to a_r and the Nayak parameter
set terminal pngcairo size 800,500 noenhanced
set output out
set datafile separator "\t"
set logscale y
set grid
set key outside right
set xlabel "seed"
set ylabel "modified / original"
set title "thought experiments: carving (non-contact zone lowered) and flipping (h -> -h)"
set offsets 0.5, 0.5, 0, 0
plot data using 1:($3/$2) every ::1 with points pt 7 ps 1.5 title "a_r, carved", \
     data using 1:($7/$6) every ::1 with points pt 5 ps 1.5 title "Nayak, carved", \
     data using 1:($8/$2) every ::1 with points pt 9 ps 1.5 title "a_r, flipped", \
     data using 1:($9/$6) every ::1 with points pt 4 ps 1.5 title "Nayak, flipped"
