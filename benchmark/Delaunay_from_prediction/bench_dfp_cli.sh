#!/usr/bin/env bash
# The command-line tool end to end (parse, triangulate, write), against CGAL's build of the
# same files by the same tool (`dfp triangulate --cgal`: the same parser and writer around
# CGAL's Delaunay_triangulation_2 range insertion).
# Usage: bench_dfp_cli.sh PATH/TO/dfp [n (default 1000000)] [repetitions (default 5)]
# Inputs, in a throw-away folder: n uniform points in the unit square (.node), the same points
# moved by up to 5% of the mean spacing in each coordinate, and the Delaunay triangulation of
# the unmoved points (.ele, written by dfp). The cases, run one after another in each
# repetition (interleaved, so that the machine's drift touches them alike):
#   exact      dfp triangulate points.node --prediction dt.ele        (D = 0)
#   moved      dfp triangulate moved.node  --prediction dt.ele        (the previous frame)
#   none       dfp triangulate moved.node                              (the package's rebuild)
#   cgal       dfp triangulate moved.node --cgal                       (CGAL's build)
# For each: the medians of the wall time and of the stages the tool reports (--stats), and the
# median over repetitions of the ratio CGAL's wall time / this wall time (above 1: faster).
set -euo pipefail

dfp=$(realpath "$1")
n=${2:-1000000}
reps=${3:-5}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

echo "# bench_dfp_cli.sh $* (n = $n, $reps repetitions; $(nproc) cores; $(date -u +%Y-%m-%d))"
awk -v n="$n" 'BEGIN { srand(1); print n, 2, 0, 0; for(i = 0; i < n; ++i) printf "%d %.17g %.17g\n", i, rand(), rand() }' > points.node
awk -v n="$n" 'BEGIN { srand(2); step = 0.05 / sqrt(n) }
  NR == 1 { print; next } { printf "%d %.17g %.17g\n", $1, $2 + step * (2 * rand() - 1), $3 + step * (2 * rand() - 1) }' points.node > moved.node
"$dfp" triangulate points.node -o dt.ele --quiet
echo "# points.node $(du -h points.node | cut -f1), dt.ele $(du -h dt.ele | cut -f1)"

cases=(exact moved none cgal)
declare -A args=(
  [exact]="points.node --prediction dt.ele"
  [moved]="moved.node --prediction dt.ele"
  [none]="moved.node"
  [cgal]="moved.node --cgal"
)

# One run: prints "wall read triangulate write".
run() {
  local start end
  start=$(date +%s.%N)
  # shellcheck disable=SC2086
  "$dfp" triangulate ${args[$1]} -o out.ele --stats --quiet > stats.txt
  end=$(date +%s.%N)
  awk -v start="$start" -v end="$end" '
    $1 == "time_read_s:" { r = $2 } $1 == "time_triangulate_s:" { t = $2 } $1 == "time_write_s:" { w = $2 }
    END { printf "%.4f %.4f %.4f %.4f\n", end - start, r, t, w }' stats.txt
}

for ((rep = 0; rep < reps; ++rep)); do
  for c in "${cases[@]}"; do
    run "$c" >> "times_$c.txt"
  done
done

median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

printf "%-7s %9s %9s %12s %9s %15s %21s\n" case wall_s read_s triangulate_s write_s "cgal/this wall" "cgal/this triangulate"
for c in "${cases[@]}"; do
  wall=$(cut -d' ' -f1 "times_$c.txt" | median)
  read_s=$(cut -d' ' -f2 "times_$c.txt" | median)
  tri=$(cut -d' ' -f3 "times_$c.txt" | median)
  write_s=$(cut -d' ' -f4 "times_$c.txt" | median)
  ratio=$(paste -d' ' times_cgal.txt "times_$c.txt" | awk '{ print $1 / $5 }' | median)
  ratio_t=$(paste -d' ' times_cgal.txt "times_$c.txt" | awk '{ print $3 / $7 }' | median)
  printf "%-7s %9.3f %9.3f %12.3f %9.3f %15.2f %21.2f\n" "$c" "$wall" "$read_s" "$tri" "$write_s" "$ratio" "$ratio_t"
done
