// A picture of one cooked asset, so a person can judge the decomposition at a glance.
#pragma once

#include "hullcook/cook/asset.h"
#include "hullcook/trace/trace.h"

#include <filesystem>
#include <string>

namespace hullcook {

// Draws the sprite (scaled up by an integer factor, nearest neighbour, until its long side is at
// least kPreviewMinSize px; over a checkerboard that shows transparency) with, on top of it:
// each piece's hull (asset.pieces[i].hull) filled translucent in its own colour and outlined, the
// components' boundaries (asset.pieces[i].component: the cuts show as yellow lines through the
// sprite) and the traced outline (asset.regions) in red. The asset's geometry is in output units
// and is mapped back to pixels with the inverse of asset.transform.
//
// image may be empty (an asset cooked from a .poly file): the geometry is then drawn on a blank
// canvas framing it. out ends in .png (raster, libpng) or .svg (text; the sprite is embedded as
// a PNG). Written with write_file_atomically(): nothing is left behind on failure.
// Throws InputError if the image cannot be read, UsageError for another extension, OutputError if
// out cannot be written.
void render_preview(const std::filesystem::path& image, const CookedAsset& asset,
                    const std::filesystem::path& out);

// The SVG render_preview writes, of a sprite already decoded (empty: none, as for a .poly asset)
// and cut to the asset's frame: the HTML report draws every asset with it, sheets' frames and grid
// cells included. Its groups are classes (hulls, components, outline), not ids, so that several
// can share a page.
std::string preview_svg(RgbaImage sprite, const CookedAsset& asset);

// preview_svg with the sprite already a data: URI of an image of the asset's image_width x
// image_height px (a PNG file's own bytes, say), which the SVG embeds as it is.
std::string preview_svg_embedding(std::string sprite_uri, const CookedAsset& asset);

// [px] the smallest long side of a preview; smaller sprites are scaled up by an integer factor.
inline constexpr int kPreviewMinSize = 512;

}  // namespace hullcook
