# Figures of the experiments of benchmark/Delaunay_from_prediction/experiment_prediction_quality.cpp,
# drawn from its CSV files. Run by scripts/experiments.sh; by hand:
#   gnuplot -e "results='benchmark/Delaunay_from_prediction/results'; figdir='doc/Delaunay_from_prediction/fig'" \
#           scripts/plot_experiments.gnuplot
# Variables: results (CSV folder), figdir (output folder), fmt ('svg', default, or 'png').
# Times plotted are the minimum over the repetitions (least disturbed by other load); the CSV
# files also have the medians.

if (!exists("results")) results = 'benchmark/Delaunay_from_prediction/results'
if (!exists("figdir")) figdir = 'doc/Delaunay_from_prediction/fig'
if (!exists("fmt")) fmt = 'svg'

set encoding utf8
set datafile separator ','
set datafile columnheaders
set datafile missing ''
set fit quiet
set fit nologfile

A = results.'/exp_a_time_vs_n.csv'
B = results.'/exp_b_time_vs_D.csv'
C = results.'/exp_c_time_vs_rho.csv'
D = results.'/exp_d_measures.csv'
exists_file(f) = system("test -f '".f."' && echo 1 || echo 0") + 0

# The file of a figure, from its name without extension.
output_name(name) = figdir.'/'.name.'.'.fmt
if (fmt eq 'png') {
  set terminal png size 900,600 enhanced font 'DejaVu Sans,11' background rgb 'white'
} else {
  set terminal svg size 900,600 dynamic enhanced font 'sans,13' background rgb 'white'
}

set grid lc rgb '#dddddd'
set key below box
set style line 1 lc rgb '#000000' lw 2 pt 7  ps 0.9   # CGAL
set style line 2 lc rgb '#777777' lw 2 pt 6  ps 0.9 dt 2 # CGAL with info
set style line 3 lc rgb '#0060c0' lw 2 pt 5  ps 0.9   # delaunay_from_prediction, default
set style line 4 lc rgb '#d04000' lw 2 pt 9  ps 1.1   # make_delaunay / unlimited
set style line 5 lc rgb '#008000' lw 2 pt 13 ps 1.1   # third model / fit
set style line 6 lc rgb '#a000a0' lw 2 pt 11 ps 1.1
set style line 7 lc rgb '#909000' lw 2 pt 3  ps 1.0
set style line 9 lc rgb '#0060c0' lw 1 pt 4  ps 2.2   # fallback marker

# ------------------------------------------------------------------------------------------
# (a) D = 0: time per point against n, and time against n (log-log).
if (exists_file(A)) {
set output output_name('exp_a_time_per_point')
set title "(a) Prediction = DT(P) (D = 0), uniform points, shuffled faces: time per point"
set xlabel 'n (number of points)'
set ylabel 'time / n  (ns per point)'
set logscale x
unset logscale y
set yrange [0:*]
set xrange [*:*]
# Where the import starts reordering shuffled input (Statistics::input_reordered), if inside the range.
stats A using 'n' nooutput
n_first = STATS_min
stats A using (column('ours_input_reordered') > 0 ? column('n') : 1e30) nooutput
n_reordered = STATS_min
if (n_reordered > n_first && n_reordered < 1e30) {
  set arrow 1 from n_reordered, graph 0 to n_reordered, graph 1 nohead dt 3 lc rgb '#888888'
  set label 1 sprintf(' from n = %d on, the input is spatially reordered', n_reordered) at n_reordered, graph 0.96 left tc rgb '#666666'
}
plot A using 'n':(column('cgal_min_s')/column('n')*1e9) with linespoints ls 1 title "CGAL from scratch (range insert)", \
     A using 'n':(column('cgal_info_min_s')/column('n')*1e9) with linespoints ls 2 title "CGAL from scratch, vertices with info", \
     A using 'n':(column('ours_min_s')/column('n')*1e9) with linespoints ls 3 title "delaunay\\_from\\_prediction()", \
     A using 'n':(column('make_delaunay_min_s')/column('n')*1e9) with linespoints ls 4 title "make\\_delaunay() on a Delaunay triangulation"
unset arrow 1
unset label 1

set output output_name('exp_a_time_vs_n')
set title "(a) Prediction = DT(P) (D = 0), uniform points, shuffled faces: time"
set ylabel 'time (s)'
set logscale xy
set yrange [*:*]
set format y '10^{%L}'
plot A using 'n':'cgal_min_s' with linespoints ls 1 title "CGAL from scratch (range insert)", \
     A using 'n':'cgal_info_min_s' with linespoints ls 2 title "CGAL from scratch, vertices with info", \
     A using 'n':'ours_min_s' with linespoints ls 3 title "delaunay\\_from\\_prediction()", \
     A using 'n':'make_delaunay_min_s' with linespoints ls 4 title "make\\_delaunay() on a Delaunay triangulation", \
     [1e4:1e6] 0.6e-7*x with lines lc rgb '#bbbbbb' dt 4 title 'slope 1 (linear time)'
set format y '%g'

# ------------------------------------------------------------------------------------------
}

# (b) time against D: k random flips.
if (exists_file(B)) {
stats B using 'n' nooutput
nb = STATS_max
set output output_name('exp_b_time_vs_D')
set title sprintf("(b) k random flips of DT(P), n = %d uniform points: time against D", nb)
set xlabel 'D / n  (measured number of wrong edges, divided by n)'
set ylabel 'time (ms)'
unset logscale xy
set xrange [0:*]
set yrange [0:*]
plot B using 'D_over_n':(column('cgal_min_s')*1e3) with linespoints ls 1 title 'CGAL from scratch', \
     B using 'D_over_n':(column('default_min_s')*1e3) with linespoints ls 3 title 'delaunay\_from\_prediction(), default (flip budget 3n/4 + 64)', \
     B using 'D_over_n':(column('default_fell_back') > 0 ? column('default_min_s')*1e3 : NaN) with points ls 9 title '   ... fell back to a rebuild (Lawson flips > budget)', \
     B using 'D_over_n':(column('unlimited_min_s')*1e3) with linespoints ls 4 title 'no flip budget, no screen (pure Lawson)'

# ------------------------------------------------------------------------------------------
}

# (c) time against rho, one panel per model.
if (exists_file(C)) {
stats C using 'n' nooutput
nc = STATS_max
set output output_name('exp_c_time_vs_rho')
if (fmt eq 'png') {
  set terminal png size 1500,620 enhanced font 'DejaVu Sans,11' background rgb 'white'
} else {
  set terminal svg size 1500,620 dynamic enhanced font 'sans,13' background rgb 'white'
}
set output output_name('exp_c_time_vs_rho')
set multiplot layout 1,3 title sprintf("(c) Time against 1/ρ, n = %d uniform points (generation not timed); fit: c (n log_2 log_2 n + n log_2(1/ρ)), one c per model", nc)
set logscale x
unset logscale y
set xrange [0.9:25]
set xtics (1, 1.4, 2, 3.3, 5, 10, 20) nomirror
set x2tics ('ρ = 1' 1, '0.7' 1/0.7, '0.5' 2, '0.3' 1/0.3, '0.2' 5, '0.1' 10, '0.05' 20)
set x2range [0.9:25]
set logscale x2
set yrange [0:*]
set xlabel '1/ρ'
set ylabel 'time (ms)'
do for [m in "rho_adversarial rho_random random_flip"] {
  if (m eq 'rho_adversarial') { set title "ρ model, adversarial completion" }
  if (m eq 'rho_random') { set title "ρ model, random completion" }
  if (m eq 'random_flip') { set title "random-flip model (Lemma 6.5)" }
  plot C using 'inv_rho':(strcol('model') eq m ? column('cgal_min_s')*1e3 : NaN) with linespoints ls 1 title 'CGAL from scratch', \
       C using 'inv_rho':(strcol('model') eq m ? column('default_min_s')*1e3 : NaN) with linespoints ls 3 title 'default', \
       C using 'inv_rho':(strcol('model') eq m && column('default_fell_back') > 0 ? column('default_min_s')*1e3 : NaN) with points ls 9 title '   ... fell back', \
       C using 'inv_rho':(strcol('model') eq m ? column('unlimited_min_s')*1e3 : NaN) with linespoints ls 4 title 'pure Lawson (no budget)', \
       C using 'inv_rho':(strcol('model') eq m ? column('paper_fit_s')*1e3 : NaN) with lines ls 5 dt 2 title 'fit of the paper''s shape'
}
unset multiplot
if (fmt eq 'png') {
  set terminal png size 900,600 enhanced font 'DejaVu Sans,11' background rgb 'white'
} else {
  set terminal svg size 900,600 dynamic enhanced font 'sans,13' background rgb 'white'
}
set xtics autofreq mirror
unset x2tics
unset logscale x2
set title

# ------------------------------------------------------------------------------------------
}

# (d) relations between the measures, every triangulation of every model.
if (exists_file(D)) {
stats D using 'n' nooutput
nd = STATS_max
set output output_name('exp_d_measures')
set title sprintf("(d) D_{local} <= D <= Lawson flips <= D_{cross}: every triangulation of every model, n <= %d", nd)
set xlabel 'D (wrong edges)'
set ylabel 'measure'
set logscale xy
set xrange [*:*]
set yrange [*:*]
set format xy '10^{%L}'
tri(c) = (column('is_triangulation') > 0 && column(c) > 0) ? column(c) : NaN
plot D using 'D':(tri('D_cross')) with points ls 4 pt 6 ps 0.6 title 'D_{cross}', \
     D using 'D':(tri('lawson_flips')) with points ls 3 pt 7 ps 0.5 title 'Lawson flips (>= D_{flip})', \
     D using 'D':(tri('D_local')) with points ls 5 pt 2 ps 0.6 title 'D_{local}', \
     x with lines lc rgb '#000000' dt 2 title 'y = D'

set output output_name('exp_d_dcross_vs_dvio2')
set title sprintf("(d) d_{cross} against d_{vio}^2 (Section 7: d_{cross} = O(d_{vio}^2)), every triangulation, n <= %d", nd)
set xlabel 'd_{vio}^2  (d_{vio}: most points inside one circumcircle of G)'
set ylabel 'd_{cross} (most DT edges crossed by one edge of G)'
family(m) = (m eq 'rho_adversarial' || m eq 'rho_random' || m eq 'random_flip') ? 1 : \
            (m eq 'k_flips') ? 2 : (m eq 'capped_flips') ? 3 : (m eq 'moved_points') ? 4 : 5
fam(f) = (column('is_triangulation') > 0 && column('d_cross') > 0 && family(strcol('model')) == f) ? column('d_cross') : NaN
plot D using 'd_vio_squared':(fam(1)) with points ls 4 pt 6 ps 0.6 title 'ρ models, random-flip model', \
     D using 'd_vio_squared':(fam(2)) with points ls 3 pt 4 ps 0.8 title 'k random flips', \
     D using 'd_vio_squared':(fam(3)) with points ls 5 pt 7 ps 0.7 title 'k flips with circumradius <= cap (small d_{vio})', \
     D using 'd_vio_squared':(fam(4)) with points ls 6 pt 9 ps 0.9 title 'moved points (the few that are triangulations)', \
     D using 'd_vio_squared':(fam(5)) with points ls 7 pt 3 ps 0.9 title 'merging lists, sorting', \
     x with lines lc rgb '#000000' dt 2 title 'y = x'

set output output_name('exp_d_dcross_vs_rho_log_n')
set title sprintf("(d) d_{cross} against (1/ρ) ln n (Lemmas 6.1 and 6.5), uniform points and jittered grids, n = 1000 ... %d", nd)
set xlabel '(1/ρ) ln n'
set ylabel 'd_{cross}'
set xrange [5:300]
set yrange [1:*]
set format xy '%g'
rho(m) = (strcol('model') eq m && column('is_triangulation') > 0 && column('d_cross') > 0) ? column('d_cross') : NaN
# Power law a x^b fitted to the logarithms, one per model.
do for [i = 1:3] {
  m = word("rho_adversarial rho_random random_flip", i)
  la = 0.1; b = 0.5
  fit [*:*] [*:*] la + b * x D using (log(column('inv_rho_ln_n'))):(log(rho(m))) via la, b
  if (i == 1) { a1 = exp(la); b1 = b }
  if (i == 2) { a2 = exp(la); b2 = b }
  if (i == 3) { a3 = exp(la); b3 = b }
}
print sprintf("d_cross power-law fits: rho_adversarial %.2f x^%.2f, rho_random %.2f x^%.2f, random_flip %.2f x^%.2f", a1, b1, a2, b2, a3, b3)
plot D using 'inv_rho_ln_n':(rho('rho_adversarial')) with points ls 4 pt 6 ps 0.7 title 'ρ model, adversarial completion', \
     D using 'inv_rho_ln_n':(rho('rho_random')) with points ls 3 pt 4 ps 0.7 title 'ρ model, random completion', \
     D using 'inv_rho_ln_n':(rho('random_flip')) with points ls 5 pt 8 ps 0.7 title 'random-flip model', \
     [5:250] a1 * x**b1 with lines ls 4 dt 2 lw 1 title sprintf('fit %.2f x^{%.2f}', a1, b1), \
     [5:250] a2 * x**b2 with lines ls 3 dt 2 lw 1 title sprintf('fit %.2f x^{%.2f}', a2, b2), \
     [5:250] a3 * x**b3 with lines ls 5 dt 2 lw 1 title sprintf('fit %.2f x^{%.2f}', a3, b3), \
     [5:250] x with lines lc rgb '#000000' dt 3 title 'y = x'
}
