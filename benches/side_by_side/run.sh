#!/bin/sh
# Side by side with Rabbit Ear's layer solver (Robby Kraft, npm package `rabbit-ear`, MIT),
# on this machine. Rabbit Ear is installed into a scratch directory, never into the project.
#
#   benches/side_by_side/run.sh [SCRATCH_DIR] [TIMEOUT_SECONDS] [EVERY_NTH]
#
# Prints, per design of ../shared/testdata/flat-folder (grids and instagram, every Nth file),
# "file states seconds" from Rabbit Ear (or TIMEOUT / error). Compare with the per-file times of
# `cargo run --release --example flat_folder_set` on the same machine.
set -e
HERE=$(cd "$(dirname "$0")" && pwd)
SCRATCH=${1:-/tmp/foldcam-rabbit-ear}
LIMIT=${2:-30}
EVERY=${3:-1}
DATA="$HERE/../../../shared/testdata/flat-folder"
mkdir -p "$SCRATCH"
if [ ! -d "$SCRATCH/node_modules/rabbit-ear" ]; then
  (cd "$SCRATCH" && npm init -y >/dev/null && npm install --silent rabbit-ear@0.9.32 >/dev/null)
fi
cp "$HERE/count.js" "$SCRATCH/count.js"
i=0
for f in "$DATA"/grids/*.fold "$DATA"/instagram/*.fold "$DATA"/unsatisfiable/*; do
  i=$((i + 1))
  [ $((i % EVERY)) -eq 0 ] || continue
  out=$(cd "$SCRATCH" && timeout "$LIMIT" node count.js "$f" 2>/dev/null | tail -1) || out="TIMEOUT"
  [ -n "$out" ] || out="TIMEOUT"
  echo "$(basename "$f") $out"
done
