# docs/performance.md's scaling plot: nanoseconds per eye ray (intersection only, one
# thread) against the number of primitives, for each generated scene and accel.
# Input: the file `prism bench --data` writes. Run through bench/plot-scaling.sh.
#   gnuplot -e "data='scaling.dat'; out='docs/scaling.png'" bench/scaling.gp
set terminal pngcairo size 800,500 font ",11"
set output out
set title "Cost of an eye ray as scenes grow (intersection only, one thread)"
set xlabel "primitives"
set ylabel "ns per eye ray"
set logscale xy
set grid
set key top right
set format x "10^{%L}"
set xrange [500:2000000]
# One series per scene and accel, picked out by awk (gnuplot's NaN filter
# would break the lines).
series(g, a) = sprintf("< awk '$1 == \"%s\" && $3 == \"%s\"' %s", g, a, data)
plot \
  series("soup", "bvh") using 2:6 with linespoints lw 2 pt 7 lc 1 title "polygon soup, bvh", \
  series("soup", "groups") using 2:6 with linespoints lw 2 pt 5 lc 2 title "polygon soup, groups", \
  series("soup", "none") using 2:6 with linespoints lw 2 pt 9 lc 3 title "polygon soup, none", \
  series("scaled-soup", "bvh") using 2:6 with linespoints lw 2 pt 7 lc 1 dt 3 title "scaled soup, bvh", \
  series("scaled-soup", "groups") using 2:6 with linespoints lw 2 pt 5 lc 2 dt 3 title "scaled soup, groups", \
  series("scaled-soup", "none") using 2:6 with linespoints lw 2 pt 9 lc 3 dt 3 title "scaled soup, none", \
  series("sphereflake", "bvh") using 2:6 with linespoints lw 2 pt 7 lc 1 dt 2 title "sphereflake, bvh", \
  series("sphereflake", "groups") using 2:6 with linespoints lw 2 pt 5 lc 2 dt 2 title "sphereflake, groups", \
  series("sphereflake", "none") using 2:6 with linespoints lw 2 pt 9 lc 3 dt 2 title "sphereflake, none"
