// inspect_gltf (hullcook inspect on a glTF): reads back what write_gltf wrote, and refuses bad
// files with exit code 2 and a message naming the file.
#include "sample_assets.h"

#include "hullcook/cook/gltf_writer.h"
#include "hullcook/cook/output_file.h"
#include "inspect.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

namespace hullcook {
namespace {

using json = nlohmann::json;

struct InspectRun {
  int code;
  std::string out, err;
};

InspectRun inspect(const std::filesystem::path& path, bool json_output) {
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  int code = cli::inspect_gltf(path, json_output);
  std::string out = testing::internal::GetCapturedStdout();
  return {code, out, testing::internal::GetCapturedStderr()};
}

class GltfInspect : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ =
        std::filesystem::path(HULLCOOK_BINARY_DIR) / "tests" / "gltf" /
        ("inspect_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(directory_);
    std::filesystem::create_directories(directory_);
  }
  std::filesystem::path write(const std::string& name, const std::string& bytes) {
    std::filesystem::path path = directory_ / name;
    write_file_atomically(path, bytes);
    return path;
  }
  std::filesystem::path directory_;
};

// How inspect --json's vertices match the cooked ones.
enum class Precision {
  exact,     // version 1: the doubles themselves
  as_float,  // version 2: the floats of the doubles
  on_grid,   // version 2 with --meshopt: within half the asset's grid step
};

void expect_hulls(const json& root, const std::vector<CookedAsset>& assets, Precision precision) {
  EXPECT_EQ(root["hullcook"], 1);
  ASSERT_EQ(root["assets"].size(), assets.size());
  for (std::size_t a = 0; a < assets.size(); ++a) {
    const json& written = root["assets"][a];
    EXPECT_EQ(written["name"], assets[a].name);
    EXPECT_EQ(written["measure"], assets[a].measure);
    EXPECT_EQ(written["tau"].get<double>(), assets[a].tau);
    ASSERT_EQ(written["levels"].size(), assets[a].levels.size());
    for (std::size_t l = 0; l < assets[a].levels.size(); ++l) {
      const CookedLevel& level = assets[a].levels[l];
      EXPECT_EQ(written["levels"][l]["tau"].get<double>(), level.tau);
      ASSERT_EQ(written["levels"][l]["hulls"].size(), level.hulls.size());
      for (std::size_t h = 0; h < level.hulls.size(); ++h) {
        const json& hull = written["levels"][l]["hulls"][h];
        ASSERT_EQ(hull.size(), level.hulls[h].size());
        for (std::size_t v = 0; v < hull.size(); ++v) {
          const Vec2 p{hull[v][0].get<double>(), hull[v][1].get<double>()};
          const Vec2 q = level.hulls[h][v];
          if (precision == Precision::exact) {
            EXPECT_EQ(p.x, q.x);
            EXPECT_EQ(p.y, q.y);
          } else if (precision == Precision::on_grid) {
            const double half_step = 0.5 * test::largest_meshopt_step(assets[a]) * (1 + 1e-9);
            EXPECT_LE(std::abs(p.x - q.x), half_step);
            EXPECT_LE(std::abs(p.y - q.y), half_step);
          } else {
            EXPECT_EQ(static_cast<float>(p.x), static_cast<float>(q.x));
            EXPECT_EQ(static_cast<float>(p.y), static_cast<float>(q.y));
          }
        }
      }
    }
    EXPECT_EQ(written["pieces"].size(), assets[a].levels[0].hulls.size());
    EXPECT_EQ(written.contains("physics"), assets[a].physics.has_value());
    if (assets[a].physics) {
      EXPECT_EQ(written["physics"]["friction"].get<float>(), assets[a].physics->friction);
      EXPECT_EQ(written["physics"]["mask_bits"], assets[a].physics->mask_bits);
    }
  }
}

// --json gives back every level's hulls (as floats, or on the grid of --meshopt), for text and
// binary files, plain, Draco and meshopt.
TEST_F(GltfInspect, JsonReproducesTheHulls) {
  const std::vector<CookedAsset> assets = test::all_sample_assets();
  for (bool binary : {false, true}) {
    for (const std::string compression : {"", "_draco", "_meshopt"}) {
      const GltfOptions options{
          .binary = binary, .draco = compression == "_draco", .meshopt = compression == "_meshopt"};
      auto path =
          write("samples" + compression + (binary ? ".glb" : ".gltf"), write_gltf(assets, options));
      InspectRun run = inspect(path, true);
      ASSERT_EQ(run.code, 0) << run.err;
      expect_hulls(json::parse(run.out), assets,
                   options.meshopt ? Precision::on_grid : Precision::as_float);
    }
  }
}

// Files of version 1 (hulls as JSON numbers, a prism mesh per hull), written by the version 1
// writer (commit ec9da2f) from the assets below, are still read, exactly.
TEST_F(GltfInspect, Version1FilesAreStillRead) {
  const std::vector<CookedAsset> assets = {test::box_asset(), test::physics_asset(),
                                           test::sensor_asset(), test::empty_asset()};
  for (const char* name : {"v1.gltf", "v1_draco.glb"}) {
    InspectRun run =
        inspect(std::filesystem::path(HULLCOOK_SOURCE_DIR) / "tests/gltf/data" / name, true);
    ASSERT_EQ(run.code, 0) << run.err;
    expect_hulls(json::parse(run.out), assets, Precision::exact);
  }
}

TEST_F(GltfInspect, TextListsAssetsLevelsAndHulls) {
  auto path = write("box.glb", write_gltf({test::box_asset()}, {.binary = true}));
  InspectRun run = inspect(path, false);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_NE(run.out.find("1 asset, 2 hulls, 7 hull vertices"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("bytes per vertex"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("asset \"box\""), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("level 1: tau 0.5, 1 hull, 3 vertices"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("(0.33333334, -0.5)"), std::string::npos) << run.out;
}

// Stop 55: inspect of a --meshopt file did not say how far its grid moved the vertices, which
// inspect of a bundle prints: half a step per coordinate, step/sqrt(2) in distance. A file
// without --meshopt has no grid and no such figure.
TEST_F(GltfInspect, Stop55_MeshoptFilesPrintTheirGridsErrorBound) {
  const CookedAsset box = test::box_asset();
  const std::string meshopt = write_gltf({box}, {.meshopt = true});
  const double step = json::parse(meshopt)["nodes"][0]["scale"][0];
  InspectRun run = inspect(write("box_meshopt.gltf", meshopt), false);
  ASSERT_EQ(run.code, 0) << run.err;
  // shortest_text prints the fewest digits that read back as the double: compare as numbers.
  const std::size_t at = run.out.find("quantization error <= ");
  ASSERT_NE(at, std::string::npos) << run.out;
  EXPECT_DOUBLE_EQ(std::stod(run.out.substr(at + 22)), step / std::sqrt(2.0)) << run.out;
  InspectRun json_run = inspect(write("box_meshopt2.gltf", meshopt), true);
  ASSERT_EQ(json_run.code, 0) << json_run.err;
  EXPECT_DOUBLE_EQ(json::parse(json_run.out)["assets"][0]["quantization_error"].get<double>(),
                   step / std::sqrt(2.0));
  InspectRun plain = inspect(write("box_plain.glb", write_gltf({box}, {.binary = true})), false);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("quantization error"), std::string::npos) << plain.out;
}

TEST_F(GltfInspect, DocumentWithoutAssetsHasNoAssets) {
  auto path = write("nothing.glb", write_gltf({}, {.binary = true}));
  InspectRun run = inspect(path, true);
  ASSERT_EQ(run.code, 0) << run.err;
  EXPECT_EQ(json::parse(run.out)["assets"], json::array());
}

// Every truncated prefix, and a few classic wrong files, give exit code 2 and the file's name;
// never a crash.
TEST_F(GltfInspect, BadFilesAreRefusedWithExitCode2) {
  const std::string glb = write_gltf({test::physics_asset()}, {.binary = true});
  const std::string gltf = write_gltf({test::physics_asset()}, {});
  std::vector<std::pair<std::string, std::string>> bad = {
      {"empty.gltf", ""},
      {"garbage.glb", "glTF\x02\x00\x00\x00garbage"},
      {"text.gltf", "hello"},
      {"array.gltf", "[1, 2]"},
      {"version1.gltf", R"({"asset": {"version": "1.0"}})"},
      {"plain.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"name": "cube"}]})"},
      {"future.gltf",
       R"({"asset": {"version": "2.0"}, "nodes": [{"extras": {"hullcook": {"version": 3}}}]})"},
      {"odd.gltf", R"({"asset": {"version": "2.0"}, "nodes": [{"extras": {"hullcook": {
          "version": 1, "source": "", "image_size": [0, 0], "pixels_per_unit": 1,
          "pivot": [0, 0], "transform": {"scale": 1, "origin": [0, 0], "flip_y": false},
          "tau": 0, "measure": "h1", "levels": [{"tau": 0, "hulls": [[0, 0, 1]]}]}}}]})"},
  };
  for (std::size_t length = 0; length < glb.size(); length += 1 + length / 16) {
    bad.emplace_back("prefix" + std::to_string(length) + ".glb", glb.substr(0, length));
  }
  for (std::size_t length = 0; length < gltf.size(); length += 1 + length / 16) {
    bad.emplace_back("prefix" + std::to_string(length) + ".gltf", gltf.substr(0, length));
  }
  // Version 2 files whose accessors point where they must not.
  const json good = json::parse(gltf);
  auto broken = [&](const std::string& name, auto&& change) {
    json copy = good;
    change(copy);
    bad.emplace_back(name, copy.dump());
  };
  broken("no_accessor.gltf",
         [](json& root) { root["nodes"][0]["extras"]["hullcook"]["levels"][0]["counts"] = 999; });
  broken("counts_float.gltf", [](json& root) {
    root["nodes"][0]["extras"]["hullcook"]["levels"][0]["counts"] =
        root["nodes"][0]["extras"]["hullcook"]["levels"][0]["vertices"];
  });
  broken("too_many.gltf", [](json& root) {
    const int vertices = root["nodes"][0]["extras"]["hullcook"]["levels"][0]["vertices"];
    root["accessors"][vertices]["count"] = 100000;
  });
  broken("mismatch.gltf", [](json& root) {
    const int vertices = root["nodes"][0]["extras"]["hullcook"]["levels"][0]["vertices"];
    root["accessors"][vertices]["count"] = 1;
  });
  broken("short_buffer.gltf", [](json& root) { root["buffers"][0]["byteLength"] = 1 << 20; });
  broken("view_past_end.gltf", [](json& root) { root["bufferViews"][0]["byteOffset"] = 1 << 20; });
  broken("external.gltf", [](json& root) { root["buffers"][0]["uri"] = "hulls.bin"; });
  broken("sparse.gltf", [](json& root) {
    const int counts = root["nodes"][0]["extras"]["hullcook"]["levels"][0]["counts"];
    root["accessors"][counts]["sparse"] = json::object();
  });
  for (const auto& [name, bytes] : bad) {
    auto path = write(name, bytes);
    InspectRun run = inspect(path, false);
    EXPECT_EQ(run.code, 2) << name;
    EXPECT_NE(run.err.find(name), std::string::npos) << name << ": " << run.err;
    EXPECT_EQ(run.out, "") << name;
  }
  // A meshopt file whose compressed data is cut short.
  json meshopt = json::parse(write_gltf({test::physics_asset()}, {.meshopt = true}));
  meshopt["bufferViews"][0]["extensions"]["EXT_meshopt_compression"]["byteLength"] = 5;
  InspectRun cut = inspect(write("meshopt_cut.gltf", meshopt.dump()), false);
  EXPECT_EQ(cut.code, 2);
  EXPECT_NE(cut.err.find("meshopt_cut.gltf"), std::string::npos) << cut.err;
  EXPECT_NE(cut.err.find("does not decode"), std::string::npos) << cut.err;
  InspectRun missing = inspect(directory_ / "missing.glb", true);
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("missing.glb"), std::string::npos);
}

// A helper's hunt (stop 60): files that parse but break what the writer promises were printed
// with exit 0. Each is refused now, naming the node and the problem.
TEST_F(GltfInspect, Stop61_FilesThatBreakTheWritersPromisesAreRefused) {
  const json good = json::parse(write_gltf({test::box_asset(), test::physics_asset()}, {}));
  const json meshopt =
      json::parse(write_gltf({test::box_asset(), test::physics_asset()}, {.meshopt = true}));
  ASSERT_EQ(inspect(write("good.gltf", good.dump()), false).code, 0);
  ASSERT_EQ(inspect(write("good_meshopt.gltf", meshopt.dump()), false).code, 0);
  // Version 1 keeps hulls as JSON numbers: the simplest way to give a hull any shape.
  auto version1 = [](const json& hulls) {
    return json{{"asset", {{"version", "2.0"}, {"generator", "hullcook"}}},
                {"nodes",
                 {{{"name", "a"},
                   {"extras",
                    {{"hullcook",
                      {{"version", 1},
                       {"source", "a.png"},
                       {"image_size", {4, 4}},
                       {"pixels_per_unit", 1},
                       {"pivot", {0, 0}},
                       {"transform", {{"scale", 1}, {"origin", {0, 0}}, {"flip_y", false}}},
                       {"tau", 0},
                       {"measure", "h1"},
                       {"levels", {{{"tau", 0}, {"hulls", hulls}}}}}}}}}}}};
  };
  ASSERT_EQ(inspect(write("square.gltf", version1({{0, 0, 1, 0, 1, 1, 0, 1}}).dump()), false).code,
            0);
  struct Case {
    std::string name, expected;
    json document;
  };
  std::vector<Case> cases = {
      {"clockwise.gltf", "levels[0], hull 0: its hull is clockwise",
       version1({{0, 0, 0, 1, 1, 1, 1, 0}})},
      {"reflex.gltf", "levels[0], hull 0: its hull is not convex at its vertex (1, 0.25)",
       version1({{0, 0, 2, 0, 1, 0.25, 2, 2, 0, 2}})},
      {"two_vertices.gltf", "levels[0], hull 0: its hull has 2 vertices", version1({{0, 0, 1, 0}})},
  };
  auto changed = [&](const std::string& name, const std::string& expected, json document,
                     auto&& change) {
    change(document);
    cases.push_back({name, expected, std::move(document)});
  };
  changed("scale_zero.gltf", "levels[0], hull 0: its hull has no area", meshopt, [](json& root) {
    root["nodes"][0]["scale"] = {0, 0, 0};
  });
  changed("mirrored.gltf", "levels[0], hull 0: its hull is clockwise", meshopt, [](json& root) {
    root["nodes"][0]["scale"][0] = -root["nodes"][0]["scale"][0].get<double>();
  });
  changed("levels_out_of_order.gltf", "levels[1]: \"tau\" 0.5 is finer than the previous level's",
          good, [](json& root) {
            json& levels = root["nodes"][0]["extras"]["hullcook"]["levels"];
            levels[0]["tau"] = 1.0;
            levels[1]["tau"] = 0.5;
          });
  changed("negative_ppu.gltf", "\"pixels_per_unit\" is not a positive 32-bit float", good,
          [](json& root) { root["nodes"][1]["extras"]["hullcook"]["pixels_per_unit"] = -32; });
  changed("unknown_measure.gltf", "\"measure\" 'xy' is not one of sl, sp, h1, h2", good,
          [](json& root) { root["nodes"][1]["extras"]["hullcook"]["measure"] = "xy"; });
  changed("twins.gltf", "two asset nodes are named", good,
          [](json& root) { root["nodes"][1]["name"] = root["nodes"][0]["name"]; });
  changed("nameless.gltf", "an asset node without a name", good,
          [](json& root) { root["nodes"][1].erase("name"); });
  changed("nodes_object.gltf", "\"nodes\" is not an array", good, [](json& root) {
    root["nodes"] = json{{"a", 1}};
  });
  changed("stripped.gltf", "node 0 has no extras.hullcook", good, [](json& root) {
    for (json& node : root["nodes"]) node.erase("extras");
  });
  for (const Case& bad : cases) {
    InspectRun run = inspect(write(bad.name, bad.document.dump()), false);
    EXPECT_EQ(run.code, 2) << bad.name << ": " << run.out;
    EXPECT_NE(run.err.find(bad.name), std::string::npos) << bad.name << ": " << run.err;
    EXPECT_NE(run.err.find(bad.expected), std::string::npos) << bad.name << ": " << run.err;
    EXPECT_EQ(run.out, "") << bad.name;
  }
}

}  // namespace
}  // namespace hullcook
