#!/usr/bin/env bash
# The version is written once, in project(VERSION) of the root CMakeLists.txt: cosim --version and every
# model description the build makes must carry that one.
# Arguments: VERSION COSIM_EXE FMU_DIR
set -euo pipefail
version=$1 cosim=$2 fmu_dir=$3
[ "$("$cosim" --version)" = "cosim $version" ] || { echo "cosim --version: $("$cosim" --version), not $version"; exit 1; }
count=0
for fmu in "$fmu_dir"/*.fmu; do
  unzip -p "$fmu" modelDescription.xml | grep '<fmiModelDescription' | grep -q " version=\"$version\"" ||
    { echo "$fmu: its modelDescription.xml does not carry version=\"$version\""; exit 1; }
  count=$((count + 1))
done
[ "$count" -gt 0 ] || { echo "no .fmu in $fmu_dir"; exit 1; }
echo "cosim and $count FMUs carry version $version"
