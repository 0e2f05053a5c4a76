#!/usr/bin/env bash
# install_deps.sh - installs the Debian packages cdmpm needs to build, test and post-process, if missing.
# Needs root (or sudo) and apt; does nothing when everything is already installed.
set -euo pipefail
pkgs=(build-essential cmake libeigen3-dev nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev
      zlib1g-dev libnetcdf-dev libproj-dev python3-numpy python3-matplotlib python3-netcdf4 python3-xarray
      python3-gdal gdal-bin libopenmpi-dev openmpi-bin)
missing=()
for p in "${pkgs[@]}"; do dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p"); done
if [ ${#missing[@]} -gt 0 ]; then
  echo "cdmpm: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
