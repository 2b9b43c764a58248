#!/usr/bin/env bash
# Builds (Release, in build/ at the repository root) and runs the experiments of
# benchmark/Delaunay_from_prediction/experiment_prediction_quality.cpp: time against n at D = 0,
# time against D (k random flips), time against rho (rho model and random-flip model), and the
# relations between the measures of Table 1 of the paper. Writes the CSV files (and the
# program's log) to benchmark/Delaunay_from_prediction/results/ and draws the figures with
# gnuplot (scripts/plot_experiments.gnuplot) into doc/Delaunay_from_prediction/fig/. Also draws the
# manual's figure of a carved prediction, doc/Delaunay_from_prediction/fig/carved_prediction.svg
# (benchmark/Delaunay_from_prediction/figure_carved_prediction.cpp).
# Installs the build dependencies and gnuplot-nox with apt-get if they are missing.
#
# Usage: scripts/experiments.sh [--large] [--png] [program options]
#   --large   larger n ((a) up to 5e6, (b) 1e6, (c) 5e5, (d) up to 3e4); results and figures go
#             to the large/ subfolders instead. Same as EXPERIMENTS_LARGE=1.
#   --png     PNG figures (gnuplot's libgd png terminal) instead of SVG.
#   program options, e.g. --experiments a,b --reps 5: see
#             build/benchmark/Delaunay_from_prediction/experiment_prediction_quality --help
# The default run takes about 3.5 minutes on 2 cores (plus the build); --large about 18.
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

large=${EXPERIMENTS_LARGE:-0}
fmt=svg
args=()
for a in "$@"; do
  case "$a" in
    --large) large=1 ;;
    --png) fmt=png ;;
    *) args+=("$a") ;;
  esac
done

scripts/install_dependencies.sh
status=$(dpkg-query -W -f='${Status}' gnuplot-nox 2>/dev/null || true)
if [ "$status" != "install ok installed" ] && ! command -v gnuplot >/dev/null; then
  echo "Installing: gnuplot-nox"
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends gnuplot-nox
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DDFP_BUILD_BENCHMARKS=ON
cmake --build build -j2 --target experiment_prediction_quality
cmake --build build -j2 --target figure_carved_prediction

results=benchmark/Delaunay_from_prediction/results
figures=doc/Delaunay_from_prediction/fig
if [ "$large" = 1 ]; then
  results=$results/large
  figures=$figures/large
  args=(--large "${args[@]}")
fi
mkdir -p "$results" "$figures"

start=$(date +%s)
rc=0
build/benchmark/Delaunay_from_prediction/experiment_prediction_quality --out "$results" "${args[@]}" \
  | tee "$results/experiments_log.txt" || rc=$?
gnuplot -e "results='$results'; figdir='$figures'; fmt='$fmt'" scripts/plot_experiments.gnuplot
# The manual's figure of a carved prediction (an SVG the program draws itself; same with --large
# and --png). It prints make_delaunay's statistics and fails if the result is not CGAL's.
build/benchmark/Delaunay_from_prediction/figure_carved_prediction \
  doc/Delaunay_from_prediction/fig/carved_prediction.svg --n 400 --sigma 0.1 --seed 7 || rc=$?
echo "experiments and figures: $(( $(date +%s) - start )) s; CSV files in $results/, figures in $figures/"
exit $rc
