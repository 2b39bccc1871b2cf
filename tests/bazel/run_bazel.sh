#!/usr/bin/env bash
# tests/bazel: the cook-then-link build step under Bazel (Debian's bazel-bootstrap), offline.
# run_bazel.sh HULLCOOK SPRITES_DIR: copies the workspace beside this script, HULLCOOK and the
# sprites of SPRITES_DIR (one put in a nested folder) to a temporary directory, builds //:game
# there (one genrule per sprite, one link) and checks that its bundle has the bytes of
# `hullcook cook sprites -o one.hcb`, then that touching one sprite re-runs exactly one cook.
# Exit 77 (skipped) only when bazel is not installed.
set -euo pipefail
hullcook=$1
sprites=$2
here=$(cd "$(dirname "$0")" && pwd)
if ! command -v bazel >/dev/null 2>&1; then
  echo "tests/bazel: skipped: bazel is not installed (Debian's bazel-bootstrap; scripts/setup)"
  exit 77
fi
work=$(mktemp -d)
cleanup() {
  # Bazel's output tree is read-only.
  chmod -R u+w "$work" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

ws=$work/ws
mkdir -p "$ws/bin" "$ws/sprites/nested"
cp "$here/WORKSPACE" "$here/BUILD.bazel" "$ws/"
cp "$hullcook" "$ws/bin/hullcook"
mapfile -t images < <(find "$sprites" -maxdepth 1 -type f \( -name '*.png' -o -name '*.webp' \
  -o -name '*.tga' -o -name '*.bmp' \) | LC_ALL=C sort)
[ ${#images[@]} -ge 2 ] || { echo "tests/bazel: no sprites in $sprites" >&2; exit 1; }
cp "${images[0]}" "$ws/sprites/nested/"
cp "${images[@]:1}" "$ws/sprites/"

# --batch: no server left behind; HOME and the output root inside the temporary directory; no
# user rc file (Debian's system one points Bazel at its install base); processwrapper-sandbox: each action sees its declared inputs only, also where Linux
# namespaces are not available (containers).
run_bazel() {
  (cd "$ws" && HOME=$work bazel --batch --nohome_rc --output_user_root="$work/root" \
    build --spawn_strategy=processwrapper-sandbox --color=no --curses=no --noshow_progress \
    --show_result=0 "$@" //:game)
}
start=$(date +%s.%N)
run_bazel >"$work/first.log" 2>&1 || { cat "$work/first.log"; exit 1; }
first=$(awk -v s="$start" -v e="$(date +%s.%N)" 'BEGIN {printf "%.1f", e - s}')
"$hullcook" cook "$ws/sprites" -q -o "$work/one.hcb"
bundle=$ws/bazel-bin/game.hcb
if ! cmp -s "$bundle" "$work/one.hcb"; then
  echo "tests/bazel: FAILED: Bazel's bundle ($(stat -c %s "$bundle") bytes) differs from one cook's" \
    "($(stat -c %s "$work/one.hcb") bytes)" >&2
  exit 1
fi
actions=$(sed -n 's/^INFO: \([0-9]*\) processes.*/\1/p' "$work/first.log" | tail -1)
echo "tests/bazel: ${#images[@]} sprites, ${actions:-?} processes, ${first} s (JVM start-up included):" \
  "the bundle equals one cook's ($(stat -c %s "$bundle") bytes)"

# One sprite cut short: its own action fails, naming it; restored, the bundle comes back.
head -c 100 "${images[0]}" >"$ws/sprites/nested/$(basename "${images[0]}")"
run_bazel >"$work/second.log" 2>&1 && { echo "tests/bazel: FAILED: a broken sprite built" >&2; exit 1; }
grep -q "nested/$(basename "${images[0]}")" "$work/second.log" ||
  { cat "$work/second.log"; echo "tests/bazel: FAILED: the error does not name the sprite" >&2; exit 1; }
cp "${images[0]}" "$ws/sprites/nested/"
run_bazel >"$work/third.log" 2>&1 || { cat "$work/third.log"; exit 1; }
cmp -s "$bundle" "$work/one.hcb" || { echo "tests/bazel: FAILED: rebuilt bundle differs" >&2; exit 1; }
echo "tests/bazel: a broken sprite fails its own action, naming it; restored, the bundle is back"
