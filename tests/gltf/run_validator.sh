#!/usr/bin/env bash
# The Khronos glTF validator test: writes the sample files, installs the validator from npm under
# the build tree on first use (later runs reuse it, no network), and validates every file.
# Exit 77 (ctest SKIP_RETURN_CODE) only when node or npm is absent.
set -euo pipefail
samples_exe=$1 validator_dir=$2 samples_dir=$3 script=$4
version=2.0.0-dev.3.10

if ! command -v node >/dev/null 2>&1 || ! command -v npm >/dev/null 2>&1; then
  echo "######################################################################" >&2
  echo "## SKIPPED: node/npm not found: the Khronos glTF validator did NOT run." >&2
  echo "## Install nodejs and npm to check the glTF writer's output." >&2
  echo "######################################################################" >&2
  exit 77
fi

package="$validator_dir/node_modules/gltf-validator/package.json"
if [[ -f "$package" ]] && grep -q "\"version\": \"$version\"" "$package"; then
  echo "using the cached gltf-validator $version in $validator_dir"
else
  echo "installing gltf-validator $version into $validator_dir (npm)"
  mkdir -p "$validator_dir"
  npm install --prefix "$validator_dir" --no-audit --no-fund --loglevel=error \
    "gltf-validator@$version"
fi

rm -rf "$samples_dir"
"$samples_exe" "$samples_dir"
node "$script" "$validator_dir" "$samples_dir"
