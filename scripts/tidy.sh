#!/usr/bin/env bash
# clang-tidy (.clang-tidy: the checks and why) over every C++ source of a configured and built tree,
# from its compile_commands.json (the top-level CMakeLists.txt always writes one). By hand (about 5 minutes
# on 2 cores, so not part of scripts/test.sh):
#   bash scripts/tidy.sh [build-dir]      # default: build (configured and built: generated headers exist)
# Fails when any file has a finding (WarningsAsErrors), printing every finding of the run.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[ -f "$build/compile_commands.json" ] || { echo "tidy: no $build/compile_commands.json (configure first)" >&2; exit 1; }
# The project's own sources: not the build tree's generated files (IGRF tables, wire tables), and not the
# fuzz targets (another compiler's flags, built in their own tree by scripts/fuzz.sh).
files=$(python3 - "$build/compile_commands.json" "$PWD" <<'PY'
import json, os, sys
root = os.path.realpath(sys.argv[2])
seen = set()
for entry in json.load(open(sys.argv[1])):
    f = os.path.realpath(os.path.join(entry["directory"], entry["file"]))
    rel = os.path.relpath(f, root)
    if rel.startswith("..") or rel.split(os.sep)[0].startswith("build") or rel.startswith("fuzz" + os.sep):
        continue
    if f.endswith((".cpp", ".cc")) and f not in seen:
        seen.add(f)
        print(f)
PY
)
count=$(echo "$files" | wc -l)
echo "tidy: $count files, $(nproc) jobs"
# Four files per clang-tidy process, one process per core; WarningsAsErrors makes a finding fail its process.
echo "$files" | xargs -P "$(nproc)" -n 4 clang-tidy -p "$build" --quiet > "$build/tidy.log" 2>&1 || {
  grep -E "(warning|error):" "$build/tidy.log" | sort -u >&2 || cat "$build/tidy.log" >&2
  echo "tidy: findings above (full log: $build/tidy.log)" >&2
  exit 1
}
echo "tidy: clean"
