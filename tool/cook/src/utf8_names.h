// Asset names in the JSON text of glTF and the debug JSON. Names come from file names, which need
// not be UTF-8; JSON text must be.
#pragma once

#include "hullcook/cook/asset.h"

#include <string>
#include <string_view>
#include <vector>

namespace hullcook {

// text with each byte that does not start a valid UTF-8 sequence (shortest form, no surrogates,
// at most U+10FFFF) replaced by U+FFFD.
std::string valid_utf8(const std::string& text);

// Throws OutputError when two assets' names differ but their valid_utf8 texts do not (x\xff and
// x\xfe are both x\uFFFD): a format of UTF-8 names would hold two assets of one name, which a
// game could not tell apart. format names it in the message ("glTF"). Asked before an output of
// such a format is written (write_output.cpp), not by its writers: `inspect --json` prints a
// bundle's names, which keeps the bytes, with the debug JSON's writer.
void refuse_names_alike_in_utf8(const std::vector<CookedAsset>& assets, std::string_view format);

}  // namespace hullcook
