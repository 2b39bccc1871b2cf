#!/usr/bin/env bash
# The Blender test: cooks the sample sprites to a plain .glb, prints them with `hullcook inspect
# --json`, and has Debian's Blender import the .glb headless (blender_import.py). Exit 77 (ctest
# SKIP_RETURN_CODE) only when blender is not installed (scripts/setup installs it); any other
# failure fails the test.
set -euo pipefail
hullcook=$1 sprites=$2 work_dir=$3 script=$4

if ! command -v blender >/dev/null 2>&1; then
  echo "######################################################################" >&2
  echo "## SKIPPED: blender not found: Blender did NOT import hullcook's .glb." >&2
  echo "######################################################################" >&2
  exit 77
fi

rm -rf "$work_dir"
mkdir -p "$work_dir"
"$hullcook" cook "$sprites" --tau 2 --ppu 32 -q -o "$work_dir/sprites.glb"
"$hullcook" inspect --json "$work_dir/sprites.glb" >"$work_dir/sprites.json"
# Blender exits 0 even when a --python script raises: the script's own exit code and its
# final line are both checked.
log="$work_dir/blender.log"
status=0
HOME="$work_dir" blender -b --factory-startup --python "$script" -- \
  "$work_dir/sprites.glb" "$work_dir/sprites.json" >"$log" 2>&1 || status=$?
grep '^blender:' "$log" || true
if [[ $status -ne 0 ]] || ! grep -q '^blender: Blender imports every asset' "$log"; then
  echo "Blender's output:" >&2
  tail -n 40 "$log" >&2
  exit 1
fi
