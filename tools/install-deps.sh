#!/usr/bin/env bash
# Installs the Debian 12 packages sweeptrace builds and tests with; installs only what is missing,
# so on a prepared machine it costs a second. Needs root (as CI and fresh machines run).
set -euo pipefail
packages=(build-essential cmake libglm-dev libembree-dev libstb-dev catch2 nlohmann-json3-dev
          libtinyobjloader-dev libcli11-dev libtbb-dev libopenexr-dev libjpeg-dev python3 python3-matplotlib
          chromium       # the diff HTML report test renders the page headless
          slurm-wlm munge  # the farm test's single-node Slurm (tools/slurm/)
          clang libclang-rt-14-dev)  # clang + its runtime: the libFuzzer harnesses (tests/fuzz)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "install-deps: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
