#!/usr/bin/env bash
# The HTML report rendered for real: cooks a few sample sprites (one renamed with <, &, quotes)
# and a tileset cut by --grid, each with --html and --report, has Debian's Chromium render each
# page headless (--dump-dom, after the page's script sorted the cards as the address's hash asks)
# and checks the rendered DOM against the report with html_dom_check.py. Exit 77 (ctest
# SKIP_RETURN_CODE) only when chromium is not installed (scripts/setup installs it); any other
# failure fails the test.
set -euo pipefail
hullcook=$1 sprites=$2 work_dir=$3 checker=$4

chromium=$(command -v chromium || true)
if [[ -z $chromium ]]; then
  echo "######################################################################" >&2
  echo "## SKIPPED: chromium not found: the HTML report was NOT rendered." >&2
  echo "######################################################################" >&2
  exit 77
fi

rm -rf "$work_dir"
mkdir -p "$work_dir/sprites"
for sprite in frozen-bubble__balls__bubble-1-mini.png pingus__traps__spike.png \
  teeworlds__emoticons.png pingus__hotspots__space__engine.png; do
  cp "$sprites/$sprite" "$work_dir/sprites/"
done
cp "$sprites/pingus__pingus__player0__walker.png" "$work_dir/sprites/a<b&\"c'.png"

# Renders page#hash and checks the DOM; a page that Chromium cannot render leaves an empty DOM.
render_and_check() {
  local page=$1 hash=$2 report=$3
  shift 3
  HOME="$work_dir" timeout 120 "$chromium" --headless --no-sandbox --disable-gpu \
    --user-data-dir="$work_dir/chromium" --dump-dom "file://$page#$hash" \
    >"$page.dom" 2>"$page.chromium.log" || {
    echo "chromium failed on $page:" >&2
    tail -n 20 "$page.chromium.log" >&2
    return 1
  }
  python3 "$checker" "$page.dom" "$report" "${hash#sort=}" "$@"
}

"$hullcook" cook "$work_dir/sprites" -q -o "$work_dir/sprites.hcb" \
  --report "$work_dir/sprites.json" --html "$work_dir/sprites.html"
render_and_check "$work_dir/sprites.html" sort=pieces "$work_dir/sprites.json"

"$hullcook" cook "$sprites/teeworlds__mapres__grass_main.png" --grid 64x64 -q \
  -o "$work_dir/tiles.hcb" --report "$work_dir/tiles.json" --html "$work_dir/tiles.html"
render_and_check "$work_dir/tiles.html" sort=time "$work_dir/tiles.json" 64x64
