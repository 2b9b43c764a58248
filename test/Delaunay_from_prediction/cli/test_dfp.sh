#!/usr/bin/env bash
# The command-line tool on files, as a user runs it. Usage: test_dfp.sh PATH/TO/dfp
# Checks, in a throw-away folder:
#  - every point format (.node from 0 and from 1, OFF, plain text with comments, commas and a z
#    column) and every output (.ele, .off, .edge); --check (CGAL's own build) passes on each;
#  - a written triangulation read back as the prediction is certified face for face (so what
#    was written is the triangulation), from .ele, OFF and .edge files;
#  - .ele indices follow the .node numbering; collinear points give edges and no triangle;
#    duplicate points; a wrong prediction (random faces) still gives CGAL's triangulation;
#  - --threads 2 and every --strategy give the same triangles as the default;
#  - malformed files: exit status 1 and a message "file:line: ..." naming the right line;
#    a wrong command line: exit status 2;
#  - kinetic: frames repaired one after another, each equal to CGAL's build (--check), one
#    output per frame with '{}', points that meet and part again (rebuilt), that meet and
#    stay equal (in place), --cgal, a frame of another size;
#  - --periodic: triangulate and kinetic on the torus, each result CGAL's periodic triangulation
#    (--check), offsets written as six .ele attributes and read back as a prediction certified
#    face for face, --threads 2, --cgal, another domain, few points (9-sheeted), points that meet
#    and part, and the errors (a point outside the domain, a domain not square, an edge
#    prediction, an output not .ele).
set -uo pipefail

dfp=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
failures=0

fail() {
  echo "FAILED: $*"
  failures=$((failures + 1))
}

# Runs dfp with the given arguments; fails unless the exit status is $1.
expect_status() {
  local want=$1
  shift
  "$dfp" "$@" > out.txt 2> err.txt
  local got=$?
  [ "$got" -eq "$want" ] || fail "dfp $* exited with $got, expected $want: $(cat err.txt)"
}

# Fails unless err.txt contains the fixed string $1.
expect_message() {
  grep -qF -- "$1" err.txt || fail "expected the message '$1', got: $(cat err.txt)"
}

# The value of 'name: value' in out.txt (the --stats output).
stat() {
  awk -v key="$1:" '$1 == key { print $2 }' out.txt
}

# The triangles of a .ele file, each rotated to start at its smallest index, sorted.
triangles_of() {
  awk 'NR > 1 && NF >= 4 { a = $2; b = $3; c = $4;
         if(b < a && b < c) { t = a; a = b; b = c; c = t } else if(c < a && c < b) { t = c; c = b; b = a; a = t }
         print a, b, c }' "$1" | sort
}

# Points: n uniform random points in the unit square, as .node numbered from $2.
random_node() {
  awk -v n="$1" -v first="$2" -v seed="$3" 'BEGIN { srand(seed); print n, 2, 0, 0;
    for(i = 0; i < n; ++i) printf "%d %.17g %.17g\n", i + first, rand(), rand() }'
}

# --- formats, --check, round trips --------------------------------------------------------
random_node 3000 1 11 > a.node
expect_status 0 triangulate a.node -o a.ele --check --stats
expect_message "the result is CGAL's Delaunay triangulation"
[ "$(stat faces_in)" = 0 ] || fail "no prediction: faces_in $(stat faces_in)"
triangles=$(stat triangles)
[ "$(head -1 a.ele | awk '{ print $1, $2 }')" = "$triangles 3" ] || fail "a.ele header: $(head -1 a.ele)"
[ "$(sed -n 2p a.ele | awk '{ print $1 }')" = 1 ] || fail "a.ele is not numbered from 1 as a.node is"
awk 'NR > 1 { for(k = 2; k <= 4; ++k) if($k < 1 || $k > 3000) bad = 1 } END { exit bad }' a.ele ||
  fail "a.ele has an index outside 1..3000"

expect_status 0 triangulate a.node --prediction a.ele -o b.off --check --stats
[ "$(stat faces_certified)" = "$triangles" ] && [ "$(stat faces_in)" = "$triangles" ] ||
  fail ".ele read back: $(stat faces_certified) of $(stat faces_in) faces certified, expected $triangles"
[ "$(stat fell_back)" = false ] || fail ".ele read back fell back"

expect_status 0 triangulate b.off --prediction b.off -o c.edge --check --stats
[ "$(stat faces_certified)" = "$triangles" ] || fail "OFF read back: $(stat faces_certified) faces certified"
edges=$(head -1 c.edge | awk '{ print $1 }')
[ "$edges" -eq $((triangles + 3000 - 1)) ] || fail "c.edge has $edges edges, Euler says $((triangles + 2999))"

expect_status 0 triangulate a.node --prediction c.edge -o d.ele --check --stats
[ "$(stat fell_back)" = false ] || fail ".edge prediction fell back"
[ "$(triangles_of d.ele)" = "$(triangles_of a.ele)" ] || fail "the .edge prediction gave other triangles"

# The same points as plain text: comments, a comma, a z column; numbered from 0 on output.
awk 'NR == 1 { print "# x y z"; next } { if(NR % 2) print $2 ", " $3; else print $2, $3, 0.5 }' a.node > a.xyz
echo "   # a comment line, then a blank one" >> a.xyz
echo "" >> a.xyz
expect_status 0 triangulate a.xyz -o e.ele --check --stats
[ "$(sed -n 2p e.ele | awk '{ print $1 }')" = 0 ] || fail "e.ele is not numbered from 0"
[ "$(awk 'NR == 1 { print; next } { print $1 + 1, $2 + 1, $3 + 1, $4 + 1 }' e.ele | triangles_of /dev/stdin)" = "$(triangles_of a.ele)" ] ||
  fail "the plain-text points gave other triangles than the .node"

# A node file numbered from 0, with an attribute and a boundary marker.
awk 'NR == 1 { print $1, 2, 1, 1; next } { print $1 - 1, $2, $3, 7.5, 1 }' a.node > z.node
expect_status 0 triangulate z.node -o z.ele --check
[ "$(awk 'NR == 1 { print; next } { print $1 + 1, $2 + 1, $3 + 1, $4 + 1 }' z.ele | triangles_of /dev/stdin)" = "$(triangles_of a.ele)" ] ||
  fail "the .node numbered from 0 gave other triangles"

# --threads and the strategies: the same triangles.
expect_status 0 triangulate a.node --prediction a.ele -o t.ele --threads 2 --check
[ "$(triangles_of t.ele)" = "$(triangles_of a.ele)" ] || fail "--threads 2 gave other triangles"
for s in automatic flips carve t_division regions rebuild spanning_tree section_3 theorem_4_1 theorem_5_4; do
  expect_status 0 triangulate a.node --prediction a.ele -o s.ele --strategy $s --check
  [ "$(triangles_of s.ele)" = "$(triangles_of a.ele)" ] || fail "--strategy $s gave other triangles"
done
expect_status 0 triangulate a.node -o g.ele --cgal
[ "$(triangles_of g.ele)" = "$(triangles_of a.ele)" ] || fail "--cgal gave other triangles"

# A wrong prediction: random faces.
awk 'BEGIN { srand(5); print 2000, 3, 0; for(i = 1; i <= 2000; ++i) {
       a = 1 + int(3000 * rand()); b = 1 + (a % 3000); c = 1 + ((a + 17) % 3000); print i, a, b, c } }' > r.ele
expect_status 0 triangulate a.node --prediction r.ele -o rr.ele --check
[ "$(triangles_of rr.ele)" = "$(triangles_of a.ele)" ] || fail "random faces gave other triangles"

# Degenerate points: collinear (edges, no triangle), a co-circular grid with duplicates.
awk 'BEGIN { print 50, 2, 0, 0; for(i = 0; i < 50; ++i) print i, 3 * i, 2 * i + 1 }' > line.node
expect_status 0 triangulate line.node -o line.edge --check
[ "$(head -1 line.edge | awk '{ print $1 }')" = 49 ] || fail "collinear points: $(head -1 line.edge) edges, expected 49"
expect_status 0 triangulate line.node -o line.ele --check
[ "$(head -1 line.ele | awk '{ print $1 }')" = 0 ] || fail "collinear points gave triangles"
awk 'BEGIN { for(i = 0; i < 20; ++i) for(j = 0; j < 20; ++j) print i, j; for(i = 0; i < 20; ++i) print i, 3 }' > grid.xyz
expect_status 0 triangulate grid.xyz -o grid.off --check --stats
[ "$(stat duplicate_points)" = 20 ] || fail "grid: $(stat duplicate_points) duplicate points, expected 20"
expect_status 0 triangulate grid.xyz --prediction grid.off -o grid2.off --check --stats
[ "$(stat fell_back)" = false ] || fail "grid read back fell back"

# --- malformed files: exit status 1, the file and the line ------------------------------
printf '3 2 0 0\n1 0 0\n2 1 x\n3 0 1\n' > bad1.node
expect_status 1 triangulate bad1.node -o o.ele
expect_message "bad1.node:3: expected the y coordinate, found 'x'"
printf '3 2 0 0\n1 0 0\n2 1 0\n' > bad2.node
expect_status 1 triangulate bad2.node -o o.ele
expect_message "bad2.node:3: the header announces 3 vertices, the file ends after 2"
printf '# points\n0 0\n1 nan\n' > bad3.xyz
expect_status 1 triangulate bad3.xyz -o o.ele
expect_message "bad3.xyz:3: the y coordinate 'nan' is not finite"
printf '0 0\n1 0\n0 1\n1 1e999\n' > bad4.xyz
expect_status 1 triangulate bad4.xyz -o o.ele
expect_message "bad4.xyz:4: the y coordinate '1e999' is not representable as a double"
printf '2 3 0\n1 1 2 3\n2 2 3 3001\n' > bad5.ele
expect_status 1 triangulate a.node --prediction bad5.ele -o o.ele
expect_message "bad5.ele:3: vertex index 3001 is out of range"
printf '1 3 0\n1 1 2 1\n' > bad6.ele
expect_status 1 triangulate a.node --prediction bad6.ele -o o.ele
expect_message "bad6.ele:2: the face repeats an index"
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n' > bad7.off
expect_status 1 triangulate bad7.off --prediction bad7.off -o o.ele
expect_message "bad7.off:6: a face needs at least 3 vertices, not 2"
expect_status 1 triangulate a.node --prediction bad7.off -o o.ele
expect_message "bad7.off:2: the OFF file has 3 vertices, the points are 3000"
printf '1 0\n1 5 -2\n' > bad8.edge
expect_status 1 triangulate a.node --prediction bad8.edge -o o.ele
expect_message "bad8.edge:2: vertex index '-2' is negative"
printf '4 2 0 0\n1 0 0\n2 1 0\n4 0 1\n5 1 1\n' > bad9.node
expect_status 1 triangulate bad9.node -o o.ele
expect_message "bad9.node:4: vertex number 4, expected 3"
expect_status 1 triangulate missing.node -o o.ele
expect_message "missing.node: cannot open the file for reading"
expect_status 1 triangulate a.node -o no/such/folder/o.ele
expect_message "no/such/folder/o.ele: cannot open the file for writing"
[ ! -e o.ele ] || fail "a failed call wrote its output"

# --- wrong command lines: exit status 2 ---------------------------------------------------
expect_status 2 triangulate a.node
expect_message "triangulate needs -o OUT"
expect_status 2 triangulate a.node -o o.ele --strategy fastest
expect_message "unknown strategy 'fastest'"
expect_status 2 triangulate a.node -o o.ele --frobnicate
expect_status 2 triangulate a.node -o o.txt
expect_status 2 triangulate a.node -o o.ele --threads two
expect_status 2 transmogrify a.node
expect_status 0 --help
grep -q "dfp triangulate POINTS" out.txt || fail "--help does not show the usage"

# --- kinetic ------------------------------------------------------------------------------
# Frames: the points of a.node moved a little more each time (frame 3 inverts faces).
for f in 1 2 3; do
  awk -v f=$f 'NR == 1 { print; next } { srand($1 * 7 + f); print $1, $2 + f * f * 0.002 * (rand() - 0.5), $3 + f * f * 0.002 * (rand() - 0.5) }' a.node > frame$f.node
done
expect_status 0 kinetic a.node frame1.node frame2.node frame3.node -o 'k{}.ele' --check --stats
expect_message "every frame is CGAL's Delaunay triangulation"
for f in 0 1 2 3; do
  [ -s k$f.ele ] || fail "kinetic wrote no k$f.ele"
done
grep -q "^frame 3: .*flips [1-9]" out.txt || fail "kinetic: frame 3 made no flip: $(cat out.txt)"
expect_status 0 triangulate frame3.node -o f3.ele
[ "$(triangles_of k3.ele)" = "$(triangles_of f3.ele)" ] || fail "kinetic frame 3 differs from triangulating it"
expect_status 0 kinetic a.node frame1.node --prediction a.ele -o last.off --threads 2 --check
[ -s last.off ] && [ ! -e k4.ele ] || fail "kinetic without {} should write the last frame only"
# Two points meet in frame 1 and part again in frame 2.
awk 'NR == 1 { print; next } $1 == 2 { print $1, 0.25, 0.75; next } $1 == 1 { print $1, 0.25, 0.75; next } { print }' a.node > meet.node
expect_status 0 kinetic a.node meet.node frame2.node --check --stats
grep -q "^frame 1: .*rebuilt" out.txt || fail "kinetic: points that meet should rebuild: $(cat out.txt)"
grep -q "^frame 2: .*rebuilt" out.txt || fail "kinetic: points that part should rebuild: $(cat out.txt)"
# Points that met and stay equal move in place.
awk 'NR == 1 { print; next } { print $1, $2 + 0.001, $3 - 0.002 }' meet.node > meet_shifted.node
expect_status 0 kinetic a.node meet.node meet_shifted.node --check --stats
if grep -q "^frame 2: .*rebuilt" out.txt; then fail "kinetic: equal points that stay equal should move in place: $(cat out.txt)"; fi
expect_status 0 kinetic a.node frame1.node frame2.node --cgal --check
head -n 100 a.node | awk 'NR == 1 { print 99, 2, 0, 0; next } { print }' > short.node
expect_status 1 kinetic a.node short.node
expect_message "short.node: the frame has 99 points, the first frame 3000"

# --- periodic -----------------------------------------------------------------------------
# The triangles of a periodic .ele file with their offsets: each corner "index:ox,oy", the
# triangle rotated to start at its smallest index (the corners of a 1-sheeted covering differ), sorted.
periodic_triangles_of() {
  awk 'NR > 1 && NF >= 10 { c[0] = $2 ":" $5 "," $6; c[1] = $3 ":" $7 "," $8; c[2] = $4 ":" $9 "," $10;
         k = 0; if($3 < $2 && $3 < $4) k = 1; else if($4 < $2 && $4 < $3) k = 2;
         print c[k], c[(k + 1) % 3], c[(k + 2) % 3] }' "$1" | sort
}
# Moves every point of a .node by up to $2 in x and y, wrapped into [0, 1).
moved_node() {
  awk -v d="$2" -v seed="$3" 'BEGIN { srand(seed) } NR == 1 { print; next } {
         x = $2 + d * (2 * rand() - 1); y = $3 + d * (2 * rand() - 1);
         if(x < 0) x += 1; if(x >= 1) x -= 1; if(y < 0) y += 1; if(y >= 1) y -= 1;
         if(x >= 1) x = 0; if(y >= 1) y = 0;
         printf "%d %.17g %.17g\n", $1, x, y }' "$1"
}
random_node 2000 0 13 > p.node
expect_status 0 triangulate p.node -o p.ele --periodic 0 0 1 1 --check --stats
expect_message "the result is CGAL's periodic Delaunay triangulation"
[ "$(stat covering)" = 1-sheeted ] || fail "periodic: covering $(stat covering)"
[ "$(stat triangles)" = 4000 ] || fail "periodic: $(stat triangles) triangles, the torus has 2n = 4000"
[ "$(head -1 p.ele)" = "4000 3 6" ] || fail "periodic p.ele header: $(head -1 p.ele)"
awk 'NR > 1 { if(NF != 10) bad = 1; for(k = 5; k <= 10; ++k) if($k != 0 && $k != 1) bad = 1 } END { exit bad }' p.ele ||
  fail "p.ele: a line without six offsets of 0 or 1"
awk 'NR > 1 { if($5 + $7 + $9 + $6 + $8 + $10 > 0) crossing = 1 } END { exit !crossing }' p.ele ||
  fail "p.ele: no triangle crosses a side of the domain"
expect_status 0 triangulate p.node --prediction p.ele -o p2.ele --periodic 0 0 1 1 --check --stats
[ "$(stat faces_certified)" = 4000 ] && [ "$(stat fell_back)" = false ] ||
  fail "periodic .ele read back: $(stat faces_certified) faces certified, fell_back $(stat fell_back)"
[ "$(periodic_triangles_of p2.ele)" = "$(periodic_triangles_of p.ele)" ] || fail "periodic read back gave other triangles"
expect_status 0 triangulate p.node --prediction p.ele -o p3.ele --periodic 0 0 1 1 --threads 2 --check
[ "$(periodic_triangles_of p3.ele)" = "$(periodic_triangles_of p.ele)" ] || fail "periodic --threads 2 gave other triangles"
expect_status 0 triangulate p.node -o p4.ele --periodic 0 0 1 1 --cgal
[ "$(periodic_triangles_of p4.ele)" = "$(periodic_triangles_of p.ele)" ] || fail "periodic --cgal gave other triangles"
# Another domain: the same points scaled to [-2, 6)^2 give the same triangles.
awk 'NR == 1 { print; next } { printf "%d %.17g %.17g\n", $1, 8 * $2 - 2, 8 * $3 - 2 }' p.node > q.node
expect_status 0 triangulate q.node --prediction p.ele -o q.ele --periodic -2 -2 6 6 --check
[ "$(periodic_triangles_of q.ele)" = "$(periodic_triangles_of p.ele)" ] || fail "periodic [-2, 6)^2 gave other triangles"
# Few points: CGAL's 9-sheeted covering.
random_node 12 0 17 > few.node
expect_status 0 triangulate few.node -o few.ele --periodic 0 0 1 1 --check --stats
[ "$(stat covering)" = 9-sheeted ] || fail "12 points: covering $(stat covering)"
# Kinetic frames: small moves (repaired in place), then moves that cross the sides.
moved_node p.node 0.0003 1 > pf1.node
moved_node pf1.node 0.01 2 > pf2.node
expect_status 0 kinetic p.node pf1.node pf2.node -o 'pk{}.ele' --periodic 0 0 1 1 --check --stats
expect_message "every frame is CGAL's periodic Delaunay triangulation"
grep -q "^frame 1: .*faces_certified" out.txt && ! grep -q "^frame 1: .*rebuilt" out.txt ||
  fail "periodic kinetic: frame 1 should be repaired in place: $(cat out.txt)"
expect_status 0 triangulate pf2.node -o pf2.ele --periodic 0 0 1 1
[ "$(periodic_triangles_of pk2.ele)" = "$(periodic_triangles_of pf2.ele)" ] || fail "periodic kinetic frame 2 differs from triangulating it"
awk 'NR == 1 { print; next } $1 == 7 { print $1, 0.5, 0.5; next } $1 == 8 { print $1, 0.5, 0.5; next } { print }' pf1.node > pmeet.node
expect_status 0 kinetic p.node pmeet.node pf2.node --periodic 0 0 1 1 --check --stats
grep -q "^frame 1: .*rebuilt" out.txt && grep -q "^frame 2: .*rebuilt" out.txt ||
  fail "periodic kinetic: points that meet and part should rebuild: $(cat out.txt)"
expect_status 0 kinetic p.node pf1.node --periodic 0 0 1 1 --cgal --check
# Errors.
awk 'NR == 1 { print; next } $1 == 5 { print $1, 1, 0.5; next } { print }' p.node > pout.node
expect_status 1 triangulate pout.node -o o.ele --periodic 0 0 1 1
expect_message "point 5 (1, 0.5) lies outside the periodic domain [0, 1) x [0, 1)"
expect_status 1 kinetic p.node pout.node --periodic 0 0 1 1
expect_message "point 5 (1, 0.5) lies outside the periodic domain"
expect_status 2 triangulate p.node -o o.ele --periodic 0 0 1 2
expect_message "the domain must be a square"
expect_status 2 triangulate p.node -o o.ele --periodic 0 0 1
expect_status 2 triangulate p.node -o o.ele --periodic 0 0 1 x
expect_message "--periodic needs finite numbers, not 'x'"
expect_status 2 triangulate p.node -o o.off --periodic 0 0 1 1
expect_message "--periodic writes a .ele file"
expect_status 2 triangulate p.node --prediction c.edge -o o.ele --periodic 0 0 1 1
expect_message "--periodic takes a prediction of faces"

if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed"
  exit 1
fi
echo "all dfp checks passed"
