// `--html report.html`: a page to look at a cook, one card per asset, usable offline.
#pragma once

#include "hullcook/cook/cook.h"

#include <string>

namespace hullcook {

// A self-contained HTML page (nothing loaded from elsewhere): one card per asset, in the result's
// order, each with the sprite as the cook saw it (re-read from asset.cutout: a whole PNG file
// embedded as its own bytes, a --grid cell, a sheet frame, a colour-keyed or TGA, BMP or WebP
// image decoded and encoded as PNG, in a data: URI) under its traced outline, cuts and hulls (the
// preview's inline SVG), and its figures: vertices traced, pieces, hulls, hull vertices, τ, the
// max concavity measured and the milliseconds it took. An inline script sorts the cards by
// name, pieces or time, as the address's hash says (#sort=name|pieces|time; the page's links set
// it). The result needs its regions and pieces (Settings::keep_outlines) and its hulls.
// Every byte is the same from run to run but the times'. Throws InputError naming an image that
// can no longer be read, or no longer holds the asset's pixels.
std::string html_report(const CookResult& result);

}  // namespace hullcook
