# Filter error and its 3-sigma bound over an orbit, with the single-frame error beside them, from a trace
# written by filter_stats.py --trace (columns: time, filter error, bound, single-frame error, lit).
#   gnuplot -e "trace='trace.txt'; out='filter_leo_orbit.svg'" attitude_estimator/study/filter_plot.gp
set terminal svg size 900,420 font "sans,11"
set output out
set xlabel "time (s)"
set ylabel "attitude error (deg)"
set logscale y
set yrange [0.01:100]
set key top left
set grid
plot trace using 1:($5 < 0.5 ? 50 : 1/0) with points pt 7 ps 0.3 lc rgb "#999999" title "eclipse", \
     trace using 1:4 with points pt 7 ps 0.2 lc rgb "#e08000" title "single-frame (cones)", \
     trace using 1:2 with lines lc rgb "#0050c0" title "filter", \
     trace using 1:3 with lines lc rgb "#c00000" dt 2 title "filter 3-sigma bound"
