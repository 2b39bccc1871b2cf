// hullcook_stress: the long run of the stress generators (scripts/stress N). Generates N polygons
// with holes (spread over the families), decomposes each under every measure and tolerance asked
// for and cooks it as a .poly file (engine limits included) at each tolerance above 0, cooks
// drawn sprites, judges every output with the independent checker, and prints per
// family the cases, failures and time. With --input FILE it judges given files instead: a .poly
// decomposed and cooked like a generated case, an image cooked like a drawn one (replaying a
// saved failure through the checker). Exit 0 when everything passed, 1 on a usage error, 2 when
// a case failed.
#include "stress_runner.h"

#include "hullcook/core/poly_io.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace hullcook::stress {
namespace {

struct Options {
  std::size_t cases = 600;            // generated polygons, over all families
  std::optional<std::size_t> images;  // drawn images per image family (default cases / 20)
  std::uint64_t seed = 1;
  std::vector<Family> families = all_families();
  std::vector<ImageFamily> image_families = all_image_families();
  std::vector<Measure> measures{Measure::sl, Measure::sp, Measure::h1, Measure::h2};
  std::vector<double> taus{0.0, 0.5, 1.0, 4.0};
  std::filesystem::path out = "stress-failures";
  std::size_t show = 5;  // failure messages printed per family
  bool progress = false;
  bool measures_given = false;
  std::vector<std::filesystem::path> inputs;  // judge these files instead of generated cases
};

[[noreturn]] void usage(const std::string& problem) {
  // The families from their lists, so that a new one is never missing here.
  std::string polygons, images;
  for (Family family : all_families()) polygons += std::string(family_name(family)) + " ";
  for (ImageFamily family : all_image_families())
    images += std::string(image_family_name(family)) + " ";
  std::fprintf(
      stderr,
      "%s\nusage: hullcook_stress [--cases N] [--images N] [--seed S] [--family F]... "
      "[--measure M]... [--tau T]... [--out DIR] [--show N] [--progress] [--input FILE]...\n"
      "families: %s(polygons), %s(images)\n",
      problem.c_str(), polygons.c_str(), images.c_str());
  std::exit(1);
}

Options parse(int argc, char** argv) {
  Options options;
  bool families_given = false, taus_given = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(arg + " needs a value");
      return argv[++i];
    };
    auto count = [&]() {
      const std::string text = value();
      char* end = nullptr;
      const unsigned long long n = std::strtoull(text.c_str(), &end, 10);
      if (text.empty() || *end) usage(arg + ": '" + text + "' is not a whole number");
      return static_cast<std::size_t>(n);
    };
    if (arg == "--cases") {
      options.cases = count();
    } else if (arg == "--images") {
      options.images = count();
    } else if (arg == "--seed") {
      options.seed = count();
    } else if (arg == "--family") {
      if (!families_given) options.families.clear(), options.image_families.clear();
      families_given = true;
      const std::string name = value();
      if (auto family = parse_family(name)) {
        options.families.push_back(*family);
      } else if (auto image = parse_image_family(name)) {
        options.image_families.push_back(*image);
      } else {
        usage("--family: unknown family '" + name + "'");
      }
    } else if (arg == "--measure") {
      if (!options.measures_given) options.measures.clear();
      options.measures_given = true;
      const std::string name = value();
      const std::optional<Measure> measure = parse_measure(name);
      if (!measure) usage("--measure: '" + name + "' is not one of sl, sp, h1, h2");
      options.measures.push_back(*measure);
    } else if (arg == "--tau") {
      if (!taus_given) options.taus.clear();
      taus_given = true;
      const std::string text = value();
      char* end = nullptr;
      const double tau = std::strtod(text.c_str(), &end);
      if (text.empty() || *end || !(tau >= 0)) usage("--tau: '" + text + "' is not a tolerance");
      options.taus.push_back(tau);
    } else if (arg == "--out") {
      options.out = value();
    } else if (arg == "--show") {
      options.show = count();
    } else if (arg == "--input") {
      options.inputs.emplace_back(value());
    } else if (arg == "--progress") {
      options.progress = true;
    } else if (arg == "-h" || arg == "--help") {
      usage("hullcook_stress: stress tests of the decomposer and the cooker");
    } else {
      usage("unknown option '" + arg + "'");
    }
  }
  return options;
}

struct Tally {
  std::size_t cases = 0, rejected = 0, runs = 0, failed_runs = 0, failed_cases = 0;
  std::size_t stored_only_near_origin = 0;  // runs whose bundle needs finer floats (not failures)
  double run_ms = 0, check_ms = 0;
  std::map<std::string, std::size_t> rules;  // failed runs per rule broken
  std::size_t shown = 0;
};

void record(Tally& tally, const CaseOutcome& outcome, const Options& options, bool& case_failed) {
  ++tally.runs;
  tally.run_ms += outcome.run_ms;
  tally.check_ms += outcome.check_ms;
  tally.stored_only_near_origin += outcome.stored_only_near_origin;
  if (options.progress) {
    std::printf("  %s: %zu pieces, %.1f ms, check %.1f ms\n", outcome.label.c_str(), outcome.pieces,
                outcome.run_ms, outcome.check_ms);
  }
  if (outcome.ok()) return;
  ++tally.failed_runs;
  case_failed = true;
  const std::string kind = outcome.cooked ? "cook: " : "decompose: ";
  if (!outcome.error.empty()) ++tally.rules[kind + "threw"];
  for (const auto& [rule, count] : outcome.report.counts) ++tally.rules[kind + rule];
  if (tally.shown++ < options.show) std::printf("FAIL %s\n", outcome.message().c_str());
}

void print_tally(const std::string& family, const Tally& tally) {
  std::printf(
      "%-16s %6zu cases %4zu rejected %7zu runs %6zu failed runs %5zu failed cases "
      "%9.1f s decompose/cook %7.1f s check\n",
      family.c_str(), tally.cases, tally.rejected, tally.runs, tally.failed_runs,
      tally.failed_cases, tally.run_ms / 1000, tally.check_ms / 1000);
  if (tally.stored_only_near_origin > 0) {
    std::printf("%-16s   %-36s %zu runs\n", "", "bundle stored only nearer the origin",
                tally.stored_only_near_origin);
  }
  for (const auto& [rule, count] : tally.rules) {
    std::printf("%-16s   %-36s %zu runs\n", "", rule.c_str(), count);
  }
}

// The cooks images are judged under, at the measures given (else H1).
std::vector<CookCase> image_cooks(const Options& options,
                                  std::optional<ImageFamily> family = std::nullopt) {
  return image_cooks(options.measures_given ? options.measures : std::vector{Measure::h1}, family);
}

// Decomposes regions under every measure and tau, and cooks file at every tau (polygon_cook)
// that cooks_at allows.
template <typename Decompose, typename Cook, typename CooksAt>
void run_polygon(Tally& tally, const Options& options, Decompose decompose, Cook cook,
                 CooksAt cooks_at, bool& failed) {
  for (Measure measure : options.measures) {
    for (double tau : options.taus) {
      record(tally, decompose(measure, tau), options, failed);
      if (cooks_at(tau)) record(tally, cook(polygon_cook(tau, measure)), options, failed);
    }
  }
}

bool run_inputs(const Options& options, Tally& tally) {
  bool any_failed = false;
  for (const std::filesystem::path& input : options.inputs) {
    ++tally.cases;
    bool failed = false;
    if (input.extension() == ".poly") {
      const std::vector<Region> regions = read_poly_file(input);
      run_polygon(
          tally, options,
          [&](Measure measure, double tau) {
            return run_polygon_case(input.stem().string(), regions, input.string(), measure, tau,
                                    options.out);
          },
          [&](const CookCase& cook) { return run_sprite_case(input, cook); },
          [](double) { return true; }, failed);
    } else {
      for (const CookCase& cook : image_cooks(options)) {
        record(tally, run_sprite_case(input, cook), options, failed);
      }
    }
    tally.failed_cases += failed;
    any_failed = any_failed || failed;
  }
  return any_failed;
}

int run(const Options& options) {
  const auto start = std::chrono::steady_clock::now();
  std::map<std::string, Tally> tallies;
  std::vector<std::string> order;
  bool any_failed = false;
  if (!options.inputs.empty()) {
    order.push_back("inputs");
    any_failed = run_inputs(options, tallies["inputs"]);
  }
  const std::size_t families = std::max<std::size_t>(options.families.size(), 1);
  for (std::size_t i = 0; i < options.cases && options.inputs.empty() && !options.families.empty();
       ++i) {
    const Family family = options.families[i % families];
    const std::uint64_t seed = options.seed + i / families;
    const std::string name = family_name(family);
    if (!tallies.count(name)) order.push_back(name);
    Tally& tally = tallies[name];
    ++tally.cases;
    const GeneratedCase generated = generate_case(family, seed);
    if (!generated.rejection.empty()) {
      ++tally.rejected;
      continue;
    }
    if (options.progress)
      std::printf("%s seed %llu: %s\n", name.c_str(), static_cast<unsigned long long>(seed),
                  generated.description.c_str());
    bool case_failed = false;
    run_polygon(
        tally, options,
        [&](Measure measure, double tau) {
          return run_polygon_case(generated, measure, tau, options.out);
        },
        [&](const CookCase& cook) { return run_polygon_cook_case(generated, cook, options.out); },
        [&](double tau) { return cooks_polygon_at(family, tau); }, case_failed);
    tally.failed_cases += case_failed;
    any_failed = any_failed || case_failed;
  }
  const std::size_t images = options.images.value_or(std::max<std::size_t>(1, options.cases / 20));
  for (ImageFamily family :
       options.inputs.empty() ? options.image_families : std::vector<ImageFamily>{}) {
    const std::string name = image_family_name(family);
    order.push_back(name);
    Tally& tally = tallies[name];
    const std::size_t count = images_to_draw(family, images);
    const std::vector<CookCase> cooks = image_cooks(options, family);
    for (std::size_t i = 0; i < count; ++i) {
      const DrawnImage image = draw_image(family, options.seed + i);
      ++tally.cases;
      if (options.progress)
        std::printf("%s seed %llu: %s\n", name.c_str(), static_cast<unsigned long long>(image.seed),
                    image.description.c_str());
      bool case_failed = false;
      for (const CookCase& cook : cooks) {
        record(tally, run_image_case(image, cook, options.out), options, case_failed);
      }
      tally.failed_cases += case_failed;
      any_failed = any_failed || case_failed;
    }
  }
  std::printf("\nhullcook_stress: seed %llu, measures",
              static_cast<unsigned long long>(options.seed));
  for (Measure measure : options.measures) std::printf(" %s", measure_name(measure));
  std::printf(", tau");
  for (double tau : options.taus) std::printf(" %g", tau);
  std::printf(
      "; polygons also cooked at each tau (weld 0 at tau 0, max-verts 3 below tau 1, merge and "
      "max-verts 4 from tau 4); images cooked at tau 1 px, tau 4 px (merge, max-verts 4) and at "
      "tau 1 px with 100 px per unit, soft edges also at tau 0.25 px, alpha 1, simplify 0\n");
  for (const std::string& name : order) print_tally(name, tallies[name]);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("total %.1f s; %s\n", seconds,
              any_failed ? ("FAILED: inputs saved in " + options.out.string()).c_str()
                         : "every output passed the independent check");
  return any_failed ? 2 : 0;
}

}  // namespace
}  // namespace hullcook::stress

int main(int argc, char** argv) {
  try {
    return hullcook::stress::run(hullcook::stress::parse(argc, argv));
  } catch (const std::exception& error) {  // an unreadable --input, an unwritable --out
    std::fprintf(stderr, "hullcook_stress: %s\n", error.what());
    return 1;
  }
}
