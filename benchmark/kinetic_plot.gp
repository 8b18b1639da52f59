# Plots benchmark/kinetic_benchmark.cpp's CSV into doc/kinetic_cloth.png:
#   gnuplot -e "csv='kinetic_benchmark.csv'; out='doc/kinetic_cloth.png'" benchmark/kinetic_plot.gp
# Left: total BV updates over the animation vs cloth triangles (kinetic bound changes are the same
# at every query rate; kinetic nodes changed per frame at 30 Hz for comparison). Middle: median
# processor time per frame (update + the table overlap query) vs query rate (wall-clock time is in
# column 15). Right: the same with ray casts ("+rays" rows) instead of the overlap query.
if (!exists("csv")) csv = 'kinetic_benchmark.csv'
if (!exists("out")) out = 'kinetic_cloth.png'
set terminal pngcairo size 2100,560 font ",11"
set output out
set datafile separator ","
set multiplot layout 1,3 title "Kinetic AABB tree vs bottom-up refit vs rebuild: cloth falling on a table (4 s)"

rows(method, hz) = sprintf("< awk -F, '$8==\"%s\" && $5==%d {print $2\",\"$9\",\"$19}' %s", method, hz, csv)
set logscale y
set xlabel "cloth triangles"
set ylabel "BV updates over the whole animation"
set key top left
set grid
plot rows("kinetic", 30) using 1:2 with linespoints lw 2 pt 7 title "kinetic bound changes (any query rate)", \
     rows("kinetic", 30) using 1:3 with linespoints lw 2 pt 6 dt 2 title "kinetic nodes changed per frame, 30 Hz", \
     rows("bottom_up", 30) using 1:2 with linespoints lw 2 pt 5 title "bottom-up, 30 Hz", \
     rows("bottom_up", 60) using 1:2 with linespoints lw 2 pt 5 title "bottom-up, 60 Hz", \
     rows("bottom_up", 120) using 1:2 with linespoints lw 2 pt 5 title "bottom-up, 120 Hz"

unset logscale y
set logscale y
set xlabel "query rate (Hz)"
set ylabel "median processor ms per frame (update + overlap query)"
set key top right
set xtics (30, 60, 120)
per_rate(method, tri) = sprintf("< awk -F, '$8==\"%s\" && $2==%d {print $5\",\"$22}' %s", method, tri, csv)
sizes = system(sprintf("awk -F, 'NR>1 && !seen[$2]++ {print $2}' %s", csv))
n = words(sizes)
plot for [i=1:n] per_rate("kinetic", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 7 lc i \
         title sprintf("kinetic, %s tris", word(sizes, i)), \
     for [i=1:n] per_rate("bottom_up", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 5 dt 2 lc i \
         title sprintf("bottom-up refit, %s tris", word(sizes, i)), \
     for [i=1:n] per_rate("rebuild", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 9 dt 3 lc i \
         title sprintf("rebuild, %s tris", word(sizes, i))

set ylabel "median processor ms per frame (update + ray casts)"
plot for [i=1:n] per_rate("kinetic+rays", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 7 lc i \
         title sprintf("kinetic, %s tris", word(sizes, i)), \
     for [i=1:n] per_rate("bottom_up+rays", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 5 dt 2 lc i \
         title sprintf("bottom-up refit, %s tris", word(sizes, i)), \
     for [i=1:n] per_rate("rebuild+rays", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 9 dt 3 lc i \
         title sprintf("rebuild, %s tris", word(sizes, i))
unset multiplot
