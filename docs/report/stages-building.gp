set terminal pngcairo noenhanced size 900,520 font "Sans,10"
set output "stages-building.png"
set title "building cell 100 x 25 (plane-slice, von-mises): time per stage, summed over 300 frames"
set ylabel "time (ms)"
set yrange [0:*]
set grid ytics
set style data histograms
set style histogram rowstacked
set style fill solid 0.85 border -1
set boxwidth 0.6
set key outside right top vertical title "stage (median)"
set xtics scale 0
set linetype 1 lc rgb "#4e79a7"
set linetype 2 lc rgb "#f28e2b"
set linetype 3 lc rgb "#e15759"
set linetype 4 lc rgb "#76b7b2"
set linetype 5 lc rgb "#59a14f"
set linetype 6 lc rgb "#edc948"
set linetype 7 lc rgb "#b07aa1"
set linetype 8 lc rgb "#9c755f"
set linetype 9 lc rgb "#bab0ac"
plot "stages-building.dat" using 2:xtic(1) title "bond_update (0.000461 ms)", \
     "stages-building.dat" using 3 title "colliders (0.588 ms)", \
     "stages-building.dat" using 4 title "falling_clusters (0.00332 ms)", \
     "stages-building.dat" using 5 title "physics (223 ms)", \
     "stages-building.dat" using 6 title "runtime_fracture (2.96 ms)", \
     "stages-building.dat" using 7 title "stress (1.12 ms)"
