# Time-critical queries: the fraction of undecided and of wrong answers against the time budget,
# per model, from hierarchy_benchmark --budgets ... --budget-csv (rows with distance -1: all poses).
#   gnuplot -e "csv='doc/hierarchy_budget.csv'; out='doc/hierarchy_budget.png'" benchmark/hierarchy_budget.gp
if (!exists("csv")) csv = 'doc/hierarchy_budget.csv'
if (!exists("out")) out = 'doc/hierarchy_budget.png'
set terminal pngcairo size 900,520 font ",11"
set output out
set datafile separator ","
set logscale x
set xlabel "time budget per query (us)"
set ylabel "fraction of the 650 poses (%)"
set key top right
set grid
set title "Time-critical first-hit queries (likelihood walk): undecided and wrong answers vs budget"
set yrange [0:*]
models = "bunny00.off elephant.off eight.off knot1.off"
rows(m) = sprintf("< awk -F, '$1 == \"%s\" && $3 == -1' %s", m, csv)
plot for [m in models] rows(m) using 2:(100.0 * $5 / $4) with linespoints title m." undecided", \
     for [m in models] rows(m) using 2:(100.0 * $6 / $4) with linespoints dashtype 2 title m." wrong (vs FCL)"
