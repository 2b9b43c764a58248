# Figures of benchmark/Delaunay_from_prediction/bench_d_cross.cpp (Sections 5 to 7: the ρ model
# and the process of Corollary 6.6), drawn from the CSV file it writes with --csv:
#   d_cross_time_vs_rho_N.svg     time per point against 1/ρ, one panel per model, every strategy
#                                 and CGAL's build from scratch;
#   d_cross_time_vs_dcross_N.svg  time per point of Lawson's flips against the measured d_cross,
#                                 all models, with the least-squares fit a + b log2(d_cross).
# By hand, from the repository root:
#   build/benchmark/Delaunay_from_prediction/bench_d_cross --n 1e5,1e6 --reps 3 --rhos 0.5,0.2,0.1,0.01 \
#       --csv benchmark/Delaunay_from_prediction/results/d_cross.csv
#   gnuplot -e "results='benchmark/Delaunay_from_prediction/results'; figdir='doc/Delaunay_from_prediction/fig'" \
#           scripts/plot_d_cross.gnuplot
# Variables: results (CSV folder), figdir (output folder), fmt ('svg', default, or 'png'),
# csv (input file, default results.'/d_cross.csv'), nplot (the n drawn, default 1000000;
# when the file has no row with n = nplot, the largest n in the file is drawn instead; N in
# the file names is the n drawn).
# Times plotted are the medians over the repetitions (the only times the CSV file has), per point
# in ns: 1e9 * seconds / n.

if (!exists("results")) results = 'benchmark/Delaunay_from_prediction/results'
if (!exists("figdir")) figdir = 'doc/Delaunay_from_prediction/fig'
if (!exists("fmt")) fmt = 'svg'
if (!exists("csv")) csv = results.'/d_cross.csv'
if (!exists("nplot")) nplot = 1000000

set encoding utf8
set datafile separator ','
set datafile columnheaders
set datafile missing ''
set fit quiet
set fit nologfile

exists_file(f) = system("test -f '".f."' && echo 1 || echo 0") + 0
if (!exists_file(csv)) {
  exit error sprintf("plot_d_cross.gnuplot: no file %s (set csv='...')", csv)
}

# The n drawn: nplot if the file has rows with that n, else the largest n in the file.
stats csv using (column('n') == nplot ? 1 : 0) nooutput
if (STATS_sum == 0) {
  stats csv using 'n' nooutput
  print sprintf("plot_d_cross.gnuplot: no row with n = %d in %s, drawing n = %d", nplot, csv, STATS_max)
  nplot = STATS_max
}

# The file of a figure, from its name without extension.
output_name(name) = figdir.'/'.name.sprintf('_%d', nplot).'.'.fmt
if (fmt eq 'png') {
  set terminal png size 900,600 enhanced font 'DejaVu Sans,11' background rgb 'white'
} else {
  set terminal svg size 900,600 dynamic enhanced font 'sans,13' background rgb 'white'
}

set grid lc rgb '#dddddd'
set key below box
set style line 1 lc rgb '#000000' lw 2 pt 7  ps 0.9   # CGAL
set style line 3 lc rgb '#0060c0' lw 2 pt 5  ps 0.9   # default (Strategy::automatic); random completion
set style line 4 lc rgb '#d04000' lw 2 pt 9  ps 1.1   # Lawson's flips (Strategy::flips, no budget); adversarial completion
set style line 5 lc rgb '#008000' lw 2 pt 13 ps 1.1   # process of Corollary 6.6 (second figure)
set style line 6 lc rgb '#a000a0' lw 2 pt 11 ps 1.1   # Strategy::regions
set style line 7 lc rgb '#909000' lw 2 pt 3  ps 1.0   # Strategy::rebuild
set style line 9 lc rgb '#0060c0' lw 1 pt 4  ps 2.2   # fallback marker

# Time per point (ns) of a column of seconds, on the rows of model m (any model if m is '') at n = nplot.
at_n(m) = column('n') == nplot && (m eq '' || strcol('model') eq m)
ns(m, c) = at_n(m) ? 1e9 * column(c) / column('n') : NaN
models = "adversarial random process"
model_title(m) = m eq 'adversarial' ? "ρ model, adversarial completion" : \
                 m eq 'random' ? "ρ model, random completion" : \
                 m eq 'process' ? "process of Corollary 6.6 ((1 − ρ) m random flips of DT(P))" : m

# ------------------------------------------------------------------------------------------
# Time per point against 1/ρ, one panel per model, one y range for all panels.
stats csv using (column('n') == nplot ? 1 / column('rho') : NaN) nooutput
inv_rho_min = STATS_min
inv_rho_max = STATS_max
ymax = 0
do for [c in "cgal_s flips_s automatic_s regions_s rebuild_s"] {
  stats csv using (ns('', c)) nooutput
  ymax = STATS_max > ymax ? STATS_max : ymax
}

if (fmt eq 'png') {
  set terminal png size 1500,700 enhanced font 'DejaVu Sans,11' background rgb 'white'
} else {
  set terminal svg size 1500,700 dynamic enhanced font 'sans,13' background rgb 'white'
}
set output output_name('d_cross_time_vs_rho')
set multiplot layout 1,3 title sprintf("Time per point against 1/ρ, n = %d uniform points (generation and measures not timed), median of the repetitions", nplot)
set logscale x 2
set logscale x2 2
unset logscale y
set xrange [inv_rho_min / 1.25 : inv_rho_max * 1.25]
set x2range [inv_rho_min / 1.25 : inv_rho_max * 1.25]
set xtics nomirror
set x2tics ()
set yrange [0 : ymax * 1.08]
set xlabel '1/ρ  (log scale)' offset 0,0.4
set x2label 'ρ'
set ylabel 'time / n  (ns per point)'
do for [m in models] {
  set title model_title(m)
  # The tics are the values of 1/ρ (bottom) and of ρ (top) in the file, read off the first curve
  # (from every row: a row without a label would blank the tic of its value).
  plot csv using (1 / column('rho')):(ns(m, 'cgal_s')):xtic(sprintf('%g', 1 / column('rho'))) \
           with linespoints ls 1 title "CGAL from scratch", \
       csv using (1 / column('rho')):(ns(m, 'cgal_s')):x2tic(sprintf('%g', column('rho'))) \
           axes x2y1 with points lc rgb '#000000' pt -1 notitle, \
       csv using (1 / column('rho')):(ns(m, 'flips_s')) with linespoints ls 4 title "Lawson's flips (no flip budget)", \
       csv using (1 / column('rho')):(ns(m, 'automatic_s')) with linespoints ls 3 title 'default (Strategy::automatic)', \
       csv using (1 / column('rho')):(at_n(m) && column('automatic_fell_back') > 0 ? ns(m, 'automatic_s') : NaN) \
           with points ls 9 title '   ... fell back to a rebuild', \
       csv using (1 / column('rho')):(ns(m, 'regions_s')) with linespoints ls 6 title 'Strategy::regions', \
       csv using (1 / column('rho')):(ns(m, 'rebuild_s')) with linespoints ls 7 title 'Strategy::rebuild'
}
unset multiplot
if (fmt eq 'png') {
  set terminal png size 900,600 enhanced font 'DejaVu Sans,11' background rgb 'white'
} else {
  set terminal svg size 900,600 dynamic enhanced font 'sans,13' background rgb 'white'
}
set xtics autofreq mirror
unset x2tics
unset x2label
unset logscale x2
set title

# ------------------------------------------------------------------------------------------
# Lawson's flips: time per point against d_cross, every model, with one least-squares fit
# a + b log2(d_cross) over all of them.
stats csv using (column('n') == nplot && column('d_cross') > 0 ? column('d_cross') : NaN) nooutput
dc_min = STATS_min
dc_max = STATS_max
log2(x) = log(x) / log(2)
fa = 300; fb = 50
fit fa + fb * x csv using (log2(column('d_cross'))):(column('d_cross') > 0 ? ns('', 'flips_s') : NaN) via fa, fb
# Coefficient of determination: 1 - (residual sum of squares) / (total sum of squares).
stats csv using (column('d_cross') > 0 ? ns('', 'flips_s') : NaN) nooutput
fr2 = STATS_records > 0 && STATS_stddev > 0 ? 1 - FIT_WSSR / (STATS_records * STATS_stddev**2) : NaN
print sprintf("Lawson's flips, n = %d: time per point = %.1f + %.1f log2(d_cross) ns, R^2 = %.2f", nplot, fa, fb, fr2)

set output output_name('d_cross_time_vs_dcross')
set title sprintf("Lawson's flips (no flip budget) against d_{cross}, n = %d uniform points, median of the repetitions", nplot)
set xlabel 'd_{cross}  (most DT edges crossed by one edge of the prediction; log scale)'
set ylabel 'time / n  (ns per point)'
set logscale x 2
unset logscale y
set xrange [dc_min / 1.15 : dc_max * 1.15]
set yrange [0:*]
set xtics (1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96, 128, 192, 256, 384, 512, 768, 1024)
dc(m, c) = column('d_cross') > 0 ? ns(m, c) : NaN
plot csv using 'd_cross':(dc('adversarial', 'flips_s')) with points ls 4 pt 8 ps 1.2 title 'ρ model, adversarial completion', \
     csv using 'd_cross':(dc('random', 'flips_s')) with points ls 3 pt 4 ps 1.1 title 'ρ model, random completion', \
     csv using 'd_cross':(dc('process', 'flips_s')) with points ls 5 pt 12 ps 1.3 title 'process of Corollary 6.6', \
     [dc_min / 1.1 : dc_max * 1.1] fa + fb * log2(x) with lines ls 4 dt 2 lw 1.5 \
         title sprintf('fit: a + b log_2 d_{cross}, a = %.0f ns, b = %.1f ns (R^2 = %.2f)', fa, fb, fr2), \
     csv using 'd_cross':(dc('', 'cgal_s')) with points ls 1 pt 6 ps 0.8 title 'CGAL from scratch (same inputs)'
set xtics autofreq
