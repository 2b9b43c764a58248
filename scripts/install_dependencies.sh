#!/usr/bin/env bash
# Installs the Debian packages the project builds with, only those missing (apt-get, with
# sudo when not root). Sourced by demo.sh and test.sh.
set -euo pipefail

packages=(cmake g++ libcgal-dev libboost-dev libgmp-dev libmpfr-dev libtbb-dev)
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
