# Plots the per-frame CSV of `pccd kinetic-bench --scene bunny-contact --csv FILE` into
# doc/deforming_contact.png:
#   gnuplot -e "csv='deforming_contact.csv'; out='doc/deforming_contact.png'" benchmark/deforming_contact_plot.gp
# Left: processor time per frame of the deforming object (update + do_intersect) and of the rebuild
# reference (Point_cloud_object from the frame's points + do_intersect), log scale. Right: the
# verdicts per frame (exact, rebuild, deforming object; offset for legibility), grazing frames
# marked, and the largest edge stretch of the frame.
if (!exists("csv")) csv = 'deforming_contact.csv'
if (!exists("out")) out = 'deforming_contact.png'
set terminal pngcairo size 1800,600 font ",11"
set output out
set datafile separator ","
set multiplot layout 1,2 title "Deforming bunny cloud against a rigid sphere cloud: the deforming object vs a rebuild per frame"

set logscale y
set xlabel "animation time (s)"
set ylabel "processor time per frame (ms)"
set key top right
set grid
set key center right
plot csv skip 1 using 2:12 with linespoints lw 2 pt 5 ps 0.6 title "rebuild + query", \
     csv skip 1 using 2:9 with linespoints lw 2 pt 7 ps 0.6 title "deforming object: update + query"

unset logscale y
set ylabel "verdict (1 = contact), stretch"
set yrange [-0.1:1.6]
set key top right
plot csv skip 1 using 2:($5 * 1.0) with steps lw 3 title "exact (mesh vs sphere)", \
     csv skip 1 using 2:($4 * 0.96) with steps lw 2 title "rebuild", \
     csv skip 1 using 2:($3 * 0.92) with steps lw 2 dt 2 title "deforming object", \
     csv skip 1 using 2:($6 > 0 ? 0.5 : 1/0) with points pt 2 ps 1 title "grazing frame", \
     csv skip 1 using 2:14 with lines lw 1 title "largest edge stretch"
unset multiplot
