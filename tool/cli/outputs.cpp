#include "outputs.h"

#include "hullcook/cook/cook.h"
#include "hullcook/cook/output_file.h"
#include "hullcook/core/error.h"

namespace hullcook::cli {

std::vector<std::filesystem::path> checked_outputs(const std::string& command,
                                                   const std::string& output,
                                                   const std::string& json) {
  if (output.empty() && json.empty()) {
    throw UsageError(command + ": give an output with -o OUT.hcb|.gltf|.glb|.json or --json OUT");
  }
  std::vector<std::filesystem::path> outputs;
  if (!output.empty()) outputs.emplace_back(output);
  if (!json.empty()) {
    if (std::filesystem::path(json).extension() != ".json") {
      throw UsageError("--json " + json + ": the debug JSON is written as .json");
    }
    outputs.emplace_back(json);
  }
  for (const std::filesystem::path& path : outputs) check_output_path(path);
  std::error_code error;
  if (outputs.size() == 2 && std::filesystem::weakly_canonical(outputs[0], error) ==
                                 std::filesystem::weakly_canonical(outputs[1], error)) {
    throw UsageError("-o and --json name the same file: " + json);
  }
  return outputs;
}

namespace {

void check_side_output(const std::string& option, const std::filesystem::path& path,
                       const std::vector<std::filesystem::path>& outputs,
                       const std::vector<std::filesystem::path>& inputs) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    throw OutputError(path.string() + ": cannot write: it is a directory");
  }
  check_directory_of(path);
  for (const std::filesystem::path& output : outputs) {
    if (std::filesystem::weakly_canonical(output, error) ==
        std::filesystem::weakly_canonical(path, error)) {
      throw UsageError(option + " " + path.string() + " names another output");
    }
  }
  check_not_an_input(path, inputs);
}

}  // namespace

void check_side_outputs(const std::string& depfile, const std::string& report,
                        std::vector<std::filesystem::path> outputs,
                        const std::vector<std::filesystem::path>& inputs, const std::string& html) {
  if (!depfile.empty()) {
    check_side_output("--depfile", depfile, outputs, inputs);
    outputs.emplace_back(depfile);
  }
  if (!report.empty()) {
    if (std::filesystem::path(report).extension() != ".json") {
      throw UsageError("--report " + report + ": the report is written as .json");
    }
    check_side_output("--report", report, outputs, inputs);
    outputs.emplace_back(report);
  }
  if (!html.empty()) {
    const std::filesystem::path extension = std::filesystem::path(html).extension();
    if (extension != ".html" && extension != ".htm") {
      throw UsageError("--html " + html + ": the page is written as .html");
    }
    check_side_output("--html", html, outputs, inputs);
  }
}

}  // namespace hullcook::cli
