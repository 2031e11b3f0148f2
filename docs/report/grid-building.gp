set terminal pngcairo noenhanced size 810,650 font "Sans,10"
set output "grid-building.png"
set title "building: worst frame per cell (ms), budget 33.3 ms\n0 of 50 cells over the budget (red, framed, !)"
set xlabel "runtime fragments"
set ylabel "pre-fracture fragments"
set xrange [-0.5:4.5]
set yrange [-0.5:9.5]
set xtics ("5" 0, "10" 1, "15" 2, "20" 3, "25" 4) scale 0
set ytics ("10" 0, "20" 1, "30" 2, "40" 3, "50" 4, "60" 5, "70" 6, "80" 7, "90" 8, "100" 9) scale 0
set cbrange [0:49.95]
set cblabel "worst frame (ms)"
set rmargin 14
set cbtics add ("budget 33.3" 33.3)
set palette defined (0 "#1a9850", 13.32 "#a6d96a", 24.975 "#fee08b", 33.3 "#fdae61", 33.3 "#e34a33", 49.95 "#b30000")
unset key
set tics out
set border lw 1
plot "grid-building.dat" using 1:2:(0.5):(0.5):3 with boxxyerror fillstyle solid 1.0 noborder lc palette, \
     "grid-building.dat" using 1:2:($5 == 0 ? stringcolumn(4) : "") with labels font "Sans,10" tc rgb "black", \
     "grid-building.dat" using 1:2:($5 == 1 ? stringcolumn(4) : "") with labels font "Sans Bold,10" tc rgb "white"
