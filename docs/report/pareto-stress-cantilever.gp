set terminal pngcairo noenhanced size 1000,640 font "Sans,10"
set output "pareto-stress-cantilever.png"
set title "stress on cantilever: time against error, Pareto front dashed and labelled in bold\npoint labels: knob (fragments, r = fem-lite resolution; slabs, cg = CG tolerance or iteration cap)"
set logscale xy
set format y "%.0e"
set grid
set key outside right top
set xlabel "time (ms, median of the repetitions)"
set ylabel "error (relative, against the reference)"
set offsets graph 0.05, graph 0.15, graph 0.1, graph 0.1
set linetype 1 lc rgb "#4e79a7" pt 7
set linetype 2 lc rgb "#e15759" pt 5
set linetype 3 lc rgb "#59a14f" pt 9
set linetype 4 lc rgb "#b07aa1" pt 11
set linetype 5 lc rgb "#f28e2b" pt 13
plot \
  "pareto-stress-cantilever.dat" index 0 using 1:2 with points lt 1 ps 1.6 title "tresca", \
  "pareto-stress-cantilever.dat" index 1 using 1:2 with points lt 2 ps 1.6 title "von-mises", \
  "pareto-stress-cantilever.dat" index 0 using 1:2:3 with labels left offset 0.7,-0.5 font "Sans,7" tc rgb "#777777" notitle, \
  "pareto-stress-cantilever.dat" index 1 using 1:2:3 with labels left offset 0.7,-0.5 font "Sans,7" tc rgb "#777777" notitle, \
  "pareto-stress-cantilever.dat" index 2 using 1:2 with steps lc rgb "black" dt 2 lw 1.5 title "Pareto front", \
  "pareto-stress-cantilever.dat" index 2 using 4:5:3 with labels left font "Sans Bold,8" notitle
