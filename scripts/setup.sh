#!/usr/bin/env bash
# Installs the Debian packages dpgen needs, if any are missing (as root, or
# through sudo). Everything comes from Debian; nothing is downloaded otherwise.
set -euo pipefail
packages=(
  cmake ninja-build g++ make python3
  clang-19 libclang-19-dev libclang-cpp19-dev llvm-19-dev llvm-19-tools libclang-rt-19-dev
  libomp-19-dev
  libeigen3-dev libfmt-dev doctest-dev liblbfgspp-dev libbenchmark-dev
  # distributed runs (DPGEN_WITH_MPI, DPGEN_WITH_PETSC): OpenMPI 4.1, PETSc 3.18 (with hypre)
  openmpi-bin libopenmpi-dev libpetsc-real-dev pkg-config
  python3-torch libtorch-dev pybind11-dev # the PyTorch ops (DPGEN_WITH_TORCH)
  python3-venv python3-pip python3-setuptools python3-wheel # pip install of dpgen_torch
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
echo "setup: installing ${missing[*]}"
as_root=()
[ "$(id -u)" -eq 0 ] || as_root=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -qq
"${as_root[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
