#!/usr/bin/env bash
# The lecture's gallery in N shards on one machine with GNU parallel (Debian's `parallel`),
# then merged: docs/scale-out.md. Usage: parallel.sh OUTDIR [SHARDS] [GALLERY OPTIONS...]
set -euo pipefail
out=${1:?usage: parallel.sh OUTDIR [SHARDS] [GALLERY OPTIONS...]}
shards=${2:-4}
shift $(($# < 2 ? $# : 2))
parallel --halt now,fail=1 shadelab gallery "$out" --shard {}/"$shards" "$@" ::: $(seq "$shards")
shadelab merge "$out"
