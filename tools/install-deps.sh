#!/usr/bin/env bash
# Installs the Debian 12 packages sweeptrace needs; installs only what is missing, so on a
# prepared machine it costs a second. Needs root (as CI and fresh machines run).
#   --render  what `sweeptrace render` builds with: the compiler and the libraries it links
#   --test    (the default) those and the test extras: Catch2, Chromium for the diff report
#             test, Slurm + munge for the farm test, clang + its runtime for the fuzzers,
#             matplotlib for the chart tools
# A newcomer's first command takes --render only (README), so the first picture does not wait
# for Chromium, Slurm and clang, which only the tests use.
set -euo pipefail
mode=test
for arg in "$@"; do
  case "$arg" in
    --render) mode=render ;;
    --test) mode=test ;;
    -h|--help) sed -n '2,9p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "install-deps: unknown option '$arg' (use --render or --test)" >&2; exit 2 ;;
  esac
done
packages=(build-essential cmake libglm-dev libembree-dev libstb-dev nlohmann-json3-dev
          libtinyobjloader-dev libcli11-dev libtbb-dev libopenexr-dev libjpeg-dev
          zlib1g-dev   # gzip: pbrt-v4 scenes' .ply.gz meshes and .pbrt.gz Includes
          libopenvdb-dev libnanovdb-dev)  # media's .vdb and pbrt-v4's .nvdb density grids
if [ "$mode" = test ]; then
  packages+=(catch2 python3 python3-matplotlib
             ccache         # cached objects: a rebuild after a pull compiles only what changed
             chromium       # the diff HTML report test renders the page headless
             slurm-wlm munge  # the farm test's single-node Slurm (tools/slurm/)
             clang libclang-rt-14-dev  # clang + its runtime: the libFuzzer harnesses (tests/fuzz)
             python3-openvdb)  # tests/bad_input/generate.py writes the corpus's .vdb files
fi
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
