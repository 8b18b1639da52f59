# Plots benchmark/intersection_benchmark.cpp's CSVs into WSCG05's figures (doc/benchmarks.md):
#   gnuplot -e "dir='doc'" benchmark/intersection_plots.gp
# reads <dir>/intersection_fig7.csv, intersection_fig10_11.csv and intersection_fig9.csv and writes
# <dir>/intersection_fig7.png (error rate vs distance per sample count n), intersection_fig10.png
# (query time per distance), intersection_fig11.png (f evaluations per distance) and
# intersection_fig9.png (mean and median time and mean f evaluations vs cloud size, with ln ln N
# for comparison).
# A missing CSV skips its figure.
if (!exists("dir")) dir = 'doc'
set datafile separator ","
set datafile missing "nan"
set grid
file_exists(f) = system(sprintf("test -f '%s' && echo 1 || echo 0", f)) + 0

# Line styles shared by the figures: isearch solid, RST dashed; object boxes circles, leaf boxes
# squares; the baselines grey and black.
set style line 1 lc rgb "#1f77b4" lw 2 pt 7 dt 1   # isearch, object boxes
set style line 2 lc rgb "#2ca02c" lw 2 pt 5 dt 1   # isearch, leaf boxes
set style line 3 lc rgb "#d62728" lw 2 pt 7 dt 2   # rst, object boxes
set style line 4 lc rgb "#ff7f0e" lw 2 pt 5 dt 2   # rst, leaf boxes
set style line 5 lc rgb "#555555" lw 2 pt 9 dt 4   # FCL
set style line 6 lc rgb "#000000" lw 2 pt 11 dt 3  # threshold test

fig10 = dir.'/intersection_fig10_11.csv'
if (file_exists(fig10)) {
    set terminal pngcairo size 1400,640 font ",11"
    set output dir.'/intersection_fig10.png'
    set multiplot layout 1,2 title "WSCG05 Fig. 10: first-hit query time per distance, two bunnies (37,706 points), one thread"
    set logscale y
    set xlabel "distance d of the two copies"
    set key below font ",10"
    set xrange [-0.1:3.1]
    do for [stat in "mean median"] {
        set ylabel sprintf("%s query time (µs), log scale", stat)
        set title sprintf("%s over the poses of each distance", stat)
        plot fig10 using "distance":"isearch_object_".stat."_us" with linespoints ls 1 title "isearch, object boxes (WSCG05)", \
             ''    using "distance":"isearch_leaf_".stat."_us" with linespoints ls 2 title "isearch, leaf boxes (default)", \
             ''    using "distance":"rst_object_".stat."_us" with linespoints ls 3 title "RST, object boxes (WSCG05)", \
             ''    using "distance":"rst_leaf_".stat."_us" with linespoints ls 4 title "RST, leaf boxes", \
             ''    using "distance":"fcl_".stat."_us" with linespoints ls 5 title "FCL OBBRSS (mesh)", \
             ''    using "distance":"threshold_".stat."_us" with linespoints ls 6 title "threshold test (1 spacing)"
    }
    unset multiplot

    set terminal pngcairo size 900,640 font ",11"
    set output dir.'/intersection_fig11.png'
    set title "WSCG05 Fig. 11: mean f evaluations per first-hit query"
    set ylabel "mean f evaluations, log scale (0 not drawn)"
    plot fig10 using "distance":"isearch_object_mean_f" with linespoints ls 1 title "isearch, object boxes (WSCG05)", \
         ''    using "distance":"isearch_leaf_mean_f" with linespoints ls 2 title "isearch, leaf boxes (default)", \
         ''    using "distance":"rst_object_mean_f" with linespoints ls 3 title "RST, object boxes (WSCG05)", \
         ''    using "distance":"rst_leaf_mean_f" with linespoints ls 4 title "RST, leaf boxes"
    unset title
    unset logscale y
    unset xrange
}

fig7 = dir.'/intersection_fig7.csv'
if (file_exists(fig7)) {
    set terminal pngcairo size 1400,640 font ",11"
    set output dir.'/intersection_fig7.png'
    set multiplot layout 1,2 title "WSCG05 Fig. 7: error rate of the interpolation search with n samples per role (non-grazing poses)"
    set xlabel "distance d of the two copies"
    set ylabel "(false negatives + false positives) / non-grazing poses (%)"
    set key inside top right font ",10"
    set xrange [-0.1:3.1]
    set yrange [0:5]
    do for [region in "object leaf"] {
        set title (region eq "object" ? "object boxes (WSCG05's setting)" : "leaf boxes (PCCD's default)")
        plot for [n in "20 50 100 150 200 default"] fig7 using "distance":(100 * column(region."_n".n."_error_rate")) \
             with linespoints lw 2 title (n eq "default" ? "n from the covering (default)" : "n = ".n)
    }
    unset multiplot
    unset title
    unset xrange
    unset yrange
}

fig9 = dir.'/intersection_fig9.csv'
if (file_exists(fig9)) {
    set terminal pngcairo size 1800,640 font ",11"
    set output dir.'/intersection_fig9.png'
    set tmargin 2.5
    set multiplot layout 1,3 title "WSCG05 Fig. 9: first-hit queries vs cloud size (resampled bunny, d in [0, 1.5])"
    set logscale x
    set logscale y
    set xlabel "points per cloud N, log scale"
    set key below font ",10"
    # ln ln N scaled to pass through the first point of the default configuration (isearch, leaf boxes).
    first(col) = real(system(sprintf("awk -F, -v c=%s 'NR==1 {for (i = 1; i <= NF; ++i) if ($i == c) k = i} NR==2 {print $k}' '%s'", col, fig9)))
    loglog0 = first("loglog_n")
    do for [what in "mean_us median_us mean_f"] {
        y0 = first("isearch_leaf_".what)
        set ylabel (what eq "mean_us" ? "mean query time (µs), log scale" : \
                    what eq "median_us" ? "median query time (µs), log scale" : "mean f evaluations, log scale")
        plot fig9 using "points":"isearch_object_".what with linespoints ls 1 title "isearch, object boxes (WSCG05)", \
             ''   using "points":"isearch_leaf_".what with linespoints ls 2 title "isearch, leaf boxes (default)", \
             ''   using "points":"rst_object_".what with linespoints ls 3 title "RST, object boxes (WSCG05)", \
             ''   using "points":"rst_leaf_".what with linespoints ls 4 title "RST, leaf boxes", \
             ''   using "points":(y0 * column("loglog_n") / loglog0) with lines lc rgb "#000000" lw 2 dt 3 \
                  title "∝ ln ln N (through isearch, leaf boxes)"
    }
    unset multiplot
}
