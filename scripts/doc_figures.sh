#!/usr/bin/env bash
# Regenerates the figures the README shows (docs/figures/*.svg) from runs of the bundled systems as
# bundled: the seed scenario (10 s, rows every 10 ms) and one orbit of leo_orbit (rows every 10 s), drawn
# by `cosim plot --format svg`. SVG, as attitude_estimator/docs/filter_leo_orbit.svg: the docs' figures
# are the only generated images kept in the repository, so that the README shows them without a build.
# Usage: bash scripts/doc_figures.sh   (after building cosim and the five FMUs)
set -euo pipefail
cd "$(dirname "$0")/.."
cosim=${COSIM:-build/bin/cosim}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$cosim" run harness/systems/seed_spin.ssd --stop-time 10 --output-interval 0.01 --output "$tmp/seed.csv" > /dev/null
"$cosim" plot "$tmp/seed.csv" --out-dir "$tmp/seed" --format svg > /dev/null
"$cosim" run harness/systems/leo_orbit.ssd --output "$tmp/leo.csv" > /dev/null
"$cosim" plot "$tmp/leo.csv" --out-dir "$tmp/leo" --format svg > /dev/null
mkdir -p docs/figures
cp "$tmp/seed/sun_vector_x.svg" docs/figures/seed_spin_sun_vector_x.svg
cp "$tmp/seed/attitude_error.svg" docs/figures/seed_spin_attitude_error.svg
cp "$tmp/leo/attitude_error.svg" docs/figures/leo_orbit_attitude_error.svg
echo "docs/figures: $(ls docs/figures | tr '\n' ' ')"
