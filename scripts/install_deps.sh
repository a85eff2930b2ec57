#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need, skipping those already installed.
# Runs apt-get as root (directly, or through sudo for a normal user).
# --firmware adds the Cortex-M cross toolchain and QEMU (the estimator firmware, scripts/pil.sh, the test
# suite): about 420 MB installed, left out of the seed run.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libsundials-dev     # CVODE: Co-Simulation inside each FMU (linked statically), the master's solver
  libeigen3-dev       # small fixed-size linear algebra (Q-method, rotations)
  liberfa-dev         # ERFA (IAU SOFA), at test time: the independent sun, precession and nutation (orbit/, on-board)
  libxml2-dev         # modelDescription.xml writer and parser
  libzip-dev          # .fmu archives in the loader
  libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libfftw3-dev        # spin-rate estimation from the acquired sun vector
  gnuplot-nox         # cosim plot, cosim campaign figures
  graphviz            # cosim info SYSTEM --diagram: the components and connections as a picture (dot)
  libtomlplusplus-dev # cosim campaign specs (TOML)
  libopenmpi-dev openmpi-bin  # cosim campaign over MPI ranks (build option PVATT_MPI)
  zip unzip
  clang-format        # one format for every C++ file (scripts/format.sh --check in scripts/test.sh)
  clang libclang-rt-14-dev   # the test build (scripts/test.sh) and libFuzzer (scripts/fuzz.sh), ASan and UBSan
  clang-tidy          # the static checks of .clang-tidy (scripts/tidy.sh)
  python3-sgp4        # orbit/ tests: the independent SGP4 (Brandon Rhodes' package) run at test time
  python3-numpy       # the Python package python/pvatt (its result columns are numpy arrays)
  python3-pytest      # its tests (ctest Python.Pytest)
  python3-pandas python3-matplotlib  # Result.to_pandas(), examples/python's figures
)

if [ "${1:-}" = "--firmware" ]; then
  packages+=(
    gcc-arm-none-eabi libnewlib-arm-none-eabi  # the firmware: Arm's GCC and newlib (C library and libm)
    libstdc++-arm-none-eabi-dev                # C++ headers only (the firmware links no libstdc++)
    qemu-system-arm                            # mps2-an386, the Cortex-M4F board the firmware runs on
  )
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  as_root=(sudo)
fi
echo "install_deps: installing ${missing[*]}"
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
"${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}"
