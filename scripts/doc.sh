#!/usr/bin/env bash
# Builds the user manual and reference (HTML) into build/doc/html/ with doxygen, formulas
# rendered by MathJax 2 from Debian's libjs-mathjax, copied into build/doc/html/mathjax/ so
# that the pages read offline and the folder can be moved. Installs doxygen and
# libjs-mathjax with apt-get if they are missing (sudo when not root).
# Usage: scripts/doc.sh   (from any directory; then open build/doc/html/index.html)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."

scripts/install_dependencies.sh doxygen libjs-mathjax

mathjax=/usr/share/javascript/mathjax
[ -f "$mathjax/MathJax.js" ] || { echo "doc.sh: $mathjax/MathJax.js not found" >&2; exit 1; }

html=build/doc/html
rm -rf "$html"
mkdir -p build/doc
# Doxyfile: OUTPUT_DIRECTORY build/doc, WARN_AS_ERROR FAIL_ON_WARNINGS (any warning fails).
doxygen doc/Doxyfile
# MATHJAX_RELPATH = mathjax: the pages load mathjax/MathJax.js. A copy, not a link
# (-L follows Debian's links to the fonts), so the folder can be moved or archived.
cp -rL "$mathjax" "$html/mathjax"
echo "Manual: $(pwd)/$html/index.html"
