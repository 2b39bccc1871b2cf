// libFuzzer target: `link`'s fragment reader (.hcf, formats/FRAGMENT.md) on any bytes. Refusing
// them (InputError naming the file) is fine; whatever it accepts must then go on as link takes it:
// into a bundle (or an OutputError naming the asset the bundle cannot store) that the runtime
// opens, and through a fragment written again that reads back to the same assets. A mutated
// fragment almost never keeps its CRC-32, so each input is also read with its checksum recomputed.
#include "fuzz_check.h"

#include "hullcook/cook/bundle_writer.h"
#include "hullcook/cook/fragment.h"
#include "hullcook/core/error.h"
#include "hullcook/format/crc32.h"
#include "hullcook/format/fragment_layout.h"
#include "hullcook/runtime.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

namespace {

using namespace hullcook;

void link_what_is_accepted(std::string_view bytes) {
  Fragment fragment;
  try {
    fragment = parse_fragment(bytes, "fuzz.hcf");
  } catch (const InputError& e) {
    FUZZ_CHECK(std::string_view(e.what()).find("fuzz.hcf") != std::string_view::npos,
               "a refusal names the file");
    return;
  }
  std::string bundle;
  try {
    bundle = write_bundle(fragment.assets);
  } catch (const OutputError& e) {
    FUZZ_CHECK(std::string_view(e.what()).find("bundle") != std::string_view::npos,
               "a bundle the writer cannot store is named");
  }
  if (!bundle.empty()) {
    std::vector<std::uint32_t> aligned((bundle.size() + 3) / 4);
    std::memcpy(aligned.data(), bundle.data(), bundle.size());
    runtime::Bundle opened;
    FUZZ_CHECK(opened.open(aligned.data(), bundle.size()) == runtime::Status::ok,
               "the runtime opens what the writer wrote");
    FUZZ_CHECK(opened.asset_count() == fragment.assets.size(), "every asset is in the bundle");
  }
  // Written again (with default settings: the settings text is only carried), it reads back.
  const std::string again = write_fragment(fragment.assets, Settings{});
  Fragment reread;
  try {
    reread = parse_fragment(again, "again.hcf");
  } catch (const InputError& e) {
    std::fprintf(stderr, "a fragment written again is refused: %s\n", e.what());
    std::abort();
  }
  FUZZ_CHECK(reread.assets.size() == fragment.assets.size(), "written again, the assets stay");
  for (std::size_t i = 0; i < reread.assets.size(); ++i) {
    FUZZ_CHECK(reread.assets[i].name == fragment.assets[i].name, "names stay");
    FUZZ_CHECK(reread.assets[i].levels.size() == fragment.assets[i].levels.size(), "levels stay");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes(reinterpret_cast<const char*>(data), size);
  link_what_is_accepted(bytes);

  using format::FragmentHeader;
  if (size < sizeof(FragmentHeader)) return 0;
  std::memset(bytes.data() + offsetof(FragmentHeader, checksum), 0, 4);
  const std::uint32_t checksum = format::crc32(0, bytes.data(), bytes.size());
  std::memcpy(bytes.data() + offsetof(FragmentHeader, checksum), &checksum, 4);
  link_what_is_accepted(bytes);
  return 0;
}
