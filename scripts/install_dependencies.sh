#!/usr/bin/env bash
# Installs the Debian packages the project builds with, only those missing (apt-get, with
# sudo when not root). Called by the scripts that build (test.sh, demo.sh, ...); with package names as
# arguments it installs those instead (doc.sh: doxygen and libjs-mathjax).
set -euo pipefail

# pybind11-dev, python3-dev, python3-numpy: the Python module; python3-scipy, python3-pytest: its tests.
# python3-pybind11, python3-setuptools, python3-pip, python3-venv: the module built and installed by
# pip with no download (--no-build-isolation: setuptools and pybind11's setup_helpers from Debian),
# also into a venv made with --system-site-packages (scripts/test_pip_install.sh).
packages=(cmake g++ libcgal-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev
          pybind11-dev python3-dev python3-numpy python3-scipy python3-pytest
          python3-pybind11 python3-setuptools python3-pip python3-venv)
if (($#)); then
  packages=("$@")
fi
missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "Installing: ${missing[*]}"
  sudo=()
  [ "$(id -u)" -eq 0 ] || sudo=(sudo)
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
fi
