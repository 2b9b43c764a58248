#!/usr/bin/env bash
# The Python module installed by pip, the way the README says, offline: in a throw-away venv
# made with `/usr/bin/python3 -m venv --system-site-packages` (Debian's setuptools, pybind11,
# numpy, scipy and pytest come from the system), `python -m pip install --no-build-isolation
# --no-index --no-cache-dir examples/Delaunay_from_prediction/python` (setup.py compiles the
# module: one translation unit; --no-index: pip never reaches the network); then, from a folder
# outside the repository, `import delaunay_from_prediction` must resolve to the venv's
# site-packages, and the pytest suite test/Delaunay_from_prediction/python/ runs against it.
# Prints whether the module links TBB. Installs the build dependencies with apt-get if they are
# missing; leaves nothing in the repository (setup.py builds in a temporary folder).
# Usage: scripts/test_pip_install.sh   (from any directory)
set -euo pipefail

cd "$(dirname "${BASH_SOURCE[0]}")/.."
repo=$(pwd)
start=$(date +%s)
scripts/install_dependencies.sh

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "== venv in $work/venv (/usr/bin/python3, --system-site-packages)"
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
python="$work/venv/bin/python"

echo "== pip install --no-build-isolation --no-index examples/Delaunay_from_prediction/python"
compile_start=$(date +%s)
(cd "$work" && "$python" -m pip install --no-build-isolation --no-index --no-cache-dir \
  -v "$repo/examples/Delaunay_from_prediction/python" > "$work/pip.log" 2>&1) ||
  { tail -n 100 "$work/pip.log"; exit 1; }
compile_time=$(( $(date +%s) - compile_start ))
sed -n 's/^ *\(delaunay_from_prediction: .*\)/\1/p' "$work/pip.log"
echo "pip install: ${compile_time} s"

cd "$work"
export PYTHONDONTWRITEBYTECODE=1
unset PYTHONPATH
"$python" - "$repo" <<'PY'
import os, sys, sysconfig
import delaunay_from_prediction as dfp
repo = os.path.realpath(sys.argv[1])
module = os.path.realpath(dfp.__file__)
site_packages = os.path.realpath(sysconfig.get_paths()["platlib"])
print("module:", dfp.__file__)
if module.startswith(repo + os.sep) or os.sep + "build" + os.sep in module:
    sys.exit("the module comes from the repository or a build folder, not from the venv")
if not module.startswith(site_packages + os.sep) or not module.startswith(os.path.realpath(sys.prefix) + os.sep):
    sys.exit("the module is not in the venv's site-packages " + site_packages)
PY
so=$("$python" -c 'import delaunay_from_prediction as m; print(m.__file__)')
if [[ $(ldd "$so") == *libtbb.so* ]]; then echo "TBB: linked"; else echo "TBB: not linked"; fi

tests=("$repo"/test/Delaunay_from_prediction/python/test_*.py)
echo "== pytest ${tests[*]#"$repo/"} (from $work)"
"$python" -m pytest -q -p no:cacheprovider "${tests[@]}"
echo "scripts/test_pip_install.sh: $(( ($(date +%s) - start) / 60 )) min $(( ($(date +%s) - start) % 60 )) s" \
  "(pip install ${compile_time} s)"
