#!/usr/bin/env bash
# The chapter-4 AFS design optimisation (`afsv optimize afs`) on a Slurm cluster:
# `scripts/slurm/optimize.sh afs` (its header documents the loop and the environment).
# Usage:
#   scripts/slurm/afs-optimize.sh [afsv optimize afs OPTIONS...]
set -euo pipefail
exec "$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)/optimize.sh" afs "$@"
