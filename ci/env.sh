# shellcheck shell=bash
# Environment for building and running crashsim in CI and in the scripts under ci/.
# Source it (`. ci/env.sh`); it only exports variables and never exits.

# cargo/rustc from rustup, when the calling shell has not put them on PATH yet.
if ! command -v cargo >/dev/null 2>&1 && [ -f "${HOME:-/root}/.cargo/env" ]; then
    # shellcheck source=/dev/null
    . "${HOME:-/root}/.cargo/env"
fi

# Open MPI 4.1 refuses to start as root unless both of these are set
# (CI containers run as root).
if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1
    export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi

# Shared-memory transport: the default single-copy mechanism (CMA,
# process_vm_readv) needs ptrace rights between ranks, which many containers
# (docker's default seccomp / no CAP_SYS_PTRACE) deny; ranks then die on the
# first large message. "none" falls back to copy-in/copy-out through the shared
# segment: always works, negligible cost at our message sizes.
export OMPI_MCA_btl_vader_single_copy_mechanism=none

# Do not pin ranks to cores. cargo test runs several mpirun tests at once; with
# the default binding every one of them pins its rank 0 to core 0, rank 1 to
# core 1, ... and they all pile onto the same few cores.
export OMPI_MCA_hwloc_base_binding_policy=none

# HDF5: nothing to set. hdf5-metno-sys asks pkg-config for "hdf5"; on Debian
# with libhdf5-openmpi-dev that is the Open MPI flavour
# (/usr/include/hdf5/openmpi, /usr/lib/<triplet>/hdf5/openmpi), which ci/setup
# checks. HDF5_DIR would not help: it expects a <root>/include, <root>/lib layout.
