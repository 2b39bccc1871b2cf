// One stress case run end to end: a generated polygon decomposed, or a drawn (or real) sprite
// cooked, then judged by the independent checker; a failing input is saved for replay with the
// `hullcook` command.
#pragma once

#include "generators.h"
#include "images.h"
#include "independent_check.h"

#include "hullcook/cook/asset.h"
#include "hullcook/core/decompose.h"

#include <filesystem>
#include <optional>
#include <string>

namespace hullcook::stress {

struct CaseOutcome {
  bool cooked = false;      // cooked (engine limits included), not only decomposed
  std::string label;        // e.g. "grid seed 17, h1, tau 0.5"
  std::string description;  // the case's parameters
  CheckReport report;
  std::string error;  // what decompose or cook threw, if it did
  std::size_t pieces = 0;
  // The .hcb writer refused a hull that the runtime's floats would flatten where it lies, and
  // stored the same hulls moved to the origin: not a failure.
  bool stored_only_near_origin = false;
  double run_ms = 0;            // decomposing or cooking
  double check_ms = 0;          // the independent check
  std::filesystem::path saved;  // the failing input, saved for replay
  std::string replay;           // the command that replays it

  bool ok() const { return error.empty() && report.ok(); }
  // Everything a reader needs to reproduce a failure: label, parameters, rules broken, replay.
  std::string message() const;
};

// Decomposes every region at tau under measure and checks the pieces. On a failure the regions
// are saved as failure_dir/NAME.poly.
CaseOutcome run_polygon_case(const std::string& name, const std::vector<Region>& regions,
                             const std::string& description, Measure measure, double tau,
                             const std::filesystem::path& failure_dir);

// The same for a generated case, named FAMILY-SEED.
CaseOutcome run_polygon_case(const GeneratedCase& generated, Measure measure, double tau,
                             const std::filesystem::path& failure_dir);

struct CookCase {
  double tau_px = 1.0;  // --tau, in input units (pixels for images)
  double pixels_per_unit = 1.0;
  Measure measure = Measure::h1;
  std::optional<double> weld;      // --weld; default kDefaultWeld
  int alpha = 128;                 // --alpha: opaque where alpha >= this
  std::optional<double> simplify;  // --simplify [px]; default tau / 4
  bool merge = false;              // --merge
  std::size_t max_verts = 8;       // --max-verts
};

// An image's cook at tau_px and pixels per unit, the other settings the cook's defaults.
CookCase image_cook(double tau_px, double pixels_per_unit, Measure measure = Measure::h1);

// The cooks an image is judged under, for each measure: tau 1 and 4 px (with --merge and
// --max-verts 4) at 1 px per unit, tau 1 px at 100; soft edges also at tau 0.25 px unsimplified at
// alpha 1 (the faintest pixel is opaque). Without a family, a given sprite's.
std::vector<CookCase> image_cooks(const std::vector<Measure>& measures,
                                  std::optional<ImageFamily> family = std::nullopt);

// How polygons are cooked at tau: at tau 0 with weld 0 (no engine hull keeps vertices a weld
// apart at a tolerance of 0; the pieces are convex and every vertex stays, however close), below
// tau 1 with --max-verts 3, and from tau 4 on with --merge and --max-verts 4.
CookCase polygon_cook(double tau, Measure measure);

// Whether the stress cooks polygons of family at tau: all but the dense family at τ 0. A side of
// hundreds of nearly collinear vertices leaves pieces along it thinner than the bundle's grid
// (the strips between the notches that rounding leaves there, which τ 0 must cut, or the parts
// of a convex piece split for --max-verts), which the writer refuses (exit 3) or, among slivers
// at the rounding, the constrainer (exit 2): a known limit, in the README's exit codes.
bool cooks_polygon_at(Family family, double tau);

// Writes the case's regions as failure_dir/FAMILY-SEED.poly, cooks that file (with the engine
// limits, as `hullcook cook` does) and checks the cooked asset; the file is kept only when the
// case fails.
CaseOutcome run_polygon_cook_case(const GeneratedCase& generated, const CookCase& settings,
                                  const std::filesystem::path& failure_dir);

// Writes the image as failure_dir/FAMILY-SEED.png, cooks it and checks the cooked asset; the PNG
// is kept only when the case fails.
CaseOutcome run_image_case(const DrawnImage& image, const CookCase& settings,
                           const std::filesystem::path& failure_dir);

// Cooks a file as given (a real sprite, a saved .poly) and checks the cooked asset.
CaseOutcome run_sprite_case(const std::filesystem::path& sprite, const CookCase& settings);

// The contract of a cooked asset's finest level: the regions partitioned by the components, each
// within tau of its hull, the hulls within tau of the outline and within the engine's rules.
CheckReport check_cooked_asset(const CookedAsset& asset, std::size_t max_verts, double weld);

}  // namespace hullcook::stress
