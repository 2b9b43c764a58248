#!/usr/bin/env bash
# Compile time of a user's program: compile_time/one_call.cpp (one call of
# delaunay_from_prediction() and one of make_delaunay(), Epick) against compile_time/one_call_cgal.cpp
# (the same program with CGAL's range insertion in place of each call), compiled to an object
# file as a user's build does (g++ -std=c++17 -frounding-math -DNDEBUG, CGAL's flags), the two
# alternating in each repetition. For each case: the median processor time of the compiler
# (user + system: it runs on one core; on a virtual machine whose host is busy, the wall time
# also counts the time the machine waits for a core, which varies by a third from run to run),
# the median wall time, the median peak memory of the compiler (GNU time's maximum resident set
# size), and the median over repetitions of the ratio of processor times, package / CGAL.
# Cases: -O2; -O2 with CGAL_LINKED_WITH_TBB defined (a program linked with CGAL::TBB_support,
# calling without CGAL::Parallel_tag: the parallel code is compiled too, see the manual);
# -O0; delaunay_from_prediction() alone at -O2 (ONE_ENTRY_POINT).
# Usage (from the repository root): benchmark/Delaunay_from_prediction/compile_time.sh [repetitions (default 3)]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/../.."
reps=${1:-3}
cxx=${CXX:-g++}
src=benchmark/Delaunay_from_prediction/compile_time
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

echo "# compile_time.sh $reps repetitions; $($cxx --version | head -1); CGAL $(grep -o 'CGAL_VERSION [0-9.]*' /usr/include/CGAL/version.h | cut -d' ' -f2); $(nproc) cores; $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')"
echo "case | CGAL cpu s | CGAL wall s | CGAL MB | package cpu s | package wall s | package MB | ratio of cpu times (median of package / CGAL)"
run_case() {
  local name=$1
  shift
  local t_c=() t_p=() w_c=() w_p=() m_c=() m_p=() r=()
  for ((k = 0; k < reps; ++k)); do
    /usr/bin/time -f "%U %S %e %M" -o "$work/c" "$cxx" -std=c++17 -frounding-math -DNDEBUG "$@" -c "$src/one_call_cgal.cpp" -o "$work/c.o"
    /usr/bin/time -f "%U %S %e %M" -o "$work/p" "$cxx" -std=c++17 -frounding-math -DNDEBUG -Iinclude "$@" -c "$src/one_call.cpp" -o "$work/p.o"
    read -r uc sc wc mc < <(tail -1 "$work/c")
    read -r up sp wp mp < <(tail -1 "$work/p")
    tc=$(awk -v u="$uc" -v s="$sc" 'BEGIN { printf "%.2f", u + s }')
    tp=$(awk -v u="$up" -v s="$sp" 'BEGIN { printf "%.2f", u + s }')
    t_c+=("$tc"); w_c+=("$wc"); m_c+=("$mc"); t_p+=("$tp"); w_p+=("$wp"); m_p+=("$mp")
    r+=("$(awk -v a="$tp" -v b="$tc" 'BEGIN { printf "%.3f", a / b }')")
  done
  median() { printf '%s\n' "$@" | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
  echo "$name | $(median "${t_c[@]}") | $(median "${w_c[@]}") | $(( $(median "${m_c[@]}" | cut -d. -f1) / 1024 )) | $(median "${t_p[@]}") | $(median "${w_p[@]}") | $(( $(median "${m_p[@]}" | cut -d. -f1) / 1024 )) | $(median "${r[@]}") (each: ${r[*]})"
}
run_case "-O2" -O2
run_case "-O2, CGAL_LINKED_WITH_TBB" -O2 -DCGAL_LINKED_WITH_TBB
run_case "-O0" -O0
run_case "-O2, delaunay_from_prediction() alone" -O2 -DONE_ENTRY_POINT
