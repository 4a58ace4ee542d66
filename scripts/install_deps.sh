#!/usr/bin/env bash
# Installs the Debian 12 packages ringid builds with, and any packages named
# as arguments (scripts/fuzz.sh adds clang), if any is missing. gnuplot draws
# the report's figures; chromium renders its pages in the tests, which fail
# without them when CI is set. pybind11 and python3-dev build the Python
# module (python/), numpy and scipy its tests and benchmark.
set -euo pipefail
packages=(g++ cmake make ninja-build libceres-dev libeigen3-dev libgoogle-glog-dev libgflags-dev
          libgtest-dev libbenchmark-dev nlohmann-json3-dev libssl-dev libboost-dev gnuplot-nox chromium
          pybind11-dev python3-pybind11 python3-dev python3-numpy python3-scipy "$@")
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "installing: ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi
