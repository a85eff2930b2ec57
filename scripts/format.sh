#!/usr/bin/env bash
# Formats every tracked C and C++ file with the repository's .clang-format, or with --check reports
# (and fails on) any file that is not formatted. CI runs the check from scripts/test.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=(-i)
if [[ "${1:-}" == "--check" ]]; then mode=(--dry-run -Werror); fi
git ls-files -z '*.c' '*.h' '*.cpp' '*.hpp' | xargs -0 clang-format --style=file "${mode[@]}"
