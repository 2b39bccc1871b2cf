#!/usr/bin/env bash
# The three.js test: installs three and draco3dgltf from npm under the build tree on first use
# (later runs reuse them, no network), then loads the sample sprites' plain, meshopt and Draco .glb
# with GLTFLoader (threejs_load.mjs). Exit 77 (ctest SKIP_RETURN_CODE) only when node or npm is
# absent or npm cannot reach its registry; any other failure fails the test.
set -euo pipefail
hullcook=$1 sprites=$2 modules_dir=$3 work_dir=$4 script=$5
packages=(three@0.170.0 draco3dgltf@1.5.7)

skip() {
  echo "######################################################################" >&2
  echo "## SKIPPED: $1: three.js did NOT load hullcook's glTF files." >&2
  echo "######################################################################" >&2
  exit 77
}

command -v node >/dev/null 2>&1 && command -v npm >/dev/null 2>&1 || skip "node/npm not found"

installed=yes
for package in "${packages[@]}"; do
  name=${package%@*} version=${package##*@}
  grep -qs "\"version\": \"$version\"" "$modules_dir/node_modules/$name/package.json" || installed=no
done
if [[ $installed == yes ]]; then
  echo "using the cached ${packages[*]} in $modules_dir"
else
  echo "installing ${packages[*]} into $modules_dir (npm)"
  mkdir -p "$modules_dir"
  if ! npm install --prefix "$modules_dir" --no-audit --no-fund --loglevel=error "${packages[@]}"; then
    # Only an unreachable registry is a skip; an install that reached it and failed is a failure.
    if ! npm ping >/dev/null 2>&1; then skip "the npm registry is unreachable"; fi
    exit 1
  fi
fi

rm -rf "$work_dir"
mkdir -p "$work_dir"
node "$script" "$hullcook" "$sprites" "$work_dir" "$modules_dir"
