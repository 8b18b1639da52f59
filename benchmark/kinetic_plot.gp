# Plots benchmark/kinetic_benchmark.cpp's CSV into doc/kinetic_cloth.png:
#   gnuplot -e "csv='kinetic_benchmark.csv'; out='doc/kinetic_cloth.png'" benchmark/kinetic_plot.gp
# Left: total BV updates over the animation vs cloth triangles (kinetic bound changes are the same
# at every query rate; kinetic nodes changed per frame at 30 Hz for comparison). Middle: median
# processor time per frame (update + the table overlap query) vs query rate (wall-clock time is in
# column 15). Third: the same with ray casts ("+rays" rows) instead of the overlap query. Fourth:
# time per frame kinetic / refit, overlap and rays, flightplans evaluated or the frame's positions
# given ("+given" rows), with the 0.8 target. Fifth (when the CSV has "+box<f>" rows): kinetic /
# refit for range queries with boxes over the table's edge, whose answers are a small part of the
# cloth: the query's footprint decides who wins.
if (!exists("csv")) csv = 'kinetic_benchmark.csv'
if (!exists("out")) out = 'kinetic_cloth.png'
set terminal pngcairo size 3500,600 font ",11"
set output out
set datafile separator ","
set multiplot layout 1,5 title "Kinetic AABB tree vs bottom-up refit vs rebuild: cloth falling on a table (4 s)"

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
set logscale xy
set xlabel "query rate (Hz)"
set ylabel "median processor ms per frame (update + overlap query)"
set key top right
set xtics (30, 60, 120, 240, 480, 960)
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

# kinetic / refit per size and rate: join the two methods' rows on (triangles, rate).
ratio(kin, ref, tri) = sprintf("< awk -F, -v k='%s' -v r='%s' -v n=%d '$2==n && $8==k {a[$5]=$22} $2==n && $8==r {b[$5]=$22} END {for (h in a) if (h in b) print h\",\"a[h]/b[h]}' %s | sort -t, -k1 -n", kin, ref, tri, csv)
unset logscale y
set ylabel "processor time per frame, kinetic / bottom-up refit"
set yrange [0:*]
set key top right
plot for [i=1:n] ratio("kinetic", "bottom_up", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 7 lc i \
         title sprintf("overlap, %s tris", word(sizes, i)), \
     for [i=1:n] ratio("kinetic+rays", "bottom_up+rays", word(sizes, i)+0) using 1:2 with linespoints lw 2 pt 5 dt 2 lc i \
         title sprintf("64 rays, %s tris", word(sizes, i)), \
     for [i=1:n] ratio("kinetic+rays+given", "bottom_up+rays+given", word(sizes, i)+0) using 1:2 with linespoints lw 1 pt 4 dt 3 lc i \
         title sprintf("64 rays, positions given, %s tris", word(sizes, i)), \
     0.8 with lines lw 2 lc rgb "black" dt 4 title "target 0.8"

fracs = system(sprintf("awk -F, 'NR>1 && $8 ~ /^kinetic[+]box/ && !seen[$8]++ {print substr($8, 12)}' %s", csv))
m = words(fracs)
if (m > 0) {
    set ylabel "kinetic / bottom-up refit, box query over the table's edge"
    plot for [i=1:n] for [j=1:m] ratio("kinetic+box".word(fracs, j), "bottom_up+box".word(fracs, j), word(sizes, i)+0) \
             using 1:2 with linespoints lw 2 pt 7 lc i dt j title sprintf("box %s, %s tris", word(fracs, j), word(sizes, i)), \
         0.8 with lines lw 2 lc rgb "black" dt 4 title "target 0.8"
}
unset multiplot
