// bench_cook: a cook measured against the speed of decoding (issue 17), printed in one run with
// the targets beside the figures:
//   1. process start-up: `hullcook --version` and a cook of one 64x64 sprite beside /bin/true;
//   2. the decode floor (libpng's png_read_image / libwebp's decoder alone, file read included)
//      and hullcook's own decoding against it;
//   3. each stage after decoding (trace, decompose, clean, engine limits, contract check,
//      writing) and its ratio to the decode floor, one thread;
//   4. the whole cook with 1 and 2 threads (and of the heaviest image alone, which its threads
//      split per region and per piece), and the peak memory of the cooking process;
//   5. the tracer's and cleaner's cost against the outline's length (the fitted exponent);
//   6. the engine limits' cost against a regular polygon's vertex count (the fitted exponent).
// On samples/sprites and on a synthetic set written here (many sizes, holes, many blobs).
// Options: --runs N (repetitions, default 5), --quick (fewer and smaller images),
// --write-synthetic DIR (only write the synthetic set into DIR, to profile a cook of it),
// --write-docs DIR (also put this run's report in DIR/benchmarks.md, between its markers),
// --sprites DIR (also measure the PNG and WebP images under DIR, recursively: a game's own
// sprites, side by side with their decode floor; images the cook refuses alone are left out and
// counted, and images of one file name in several folders are all measured); any other option
// (scripts/bench passes Google Benchmark's) is ignored.
#include "bench_support.h"
#include "hullcook/cook/cook.h"
#include "hullcook/core/clean.h"
#include "hullcook/core/poly_io.h"
#include "hullcook/trace/trace.h"

#include <fcntl.h>
#include <png.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <webp/decode.h>
#include <webp/encode.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <csetjmp>
#include <cstdarg>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <numeric>
#include <optional>
#include <random>
#include <string>
#include <vector>

extern char** environ;

namespace fs = std::filesystem;
using namespace hullcook;

namespace {

// Everything the run prints, also kept for --write-docs.
std::string g_report;

__attribute__((format(printf, 1, 2))) void report(const char* format, ...) {
  va_list arguments, again;
  va_start(arguments, format);
  va_copy(again, arguments);
  const int size = std::vsnprintf(nullptr, 0, format, arguments);
  va_end(arguments);
  std::string text(static_cast<std::size_t>(std::max(size, 0)), '\0');
  std::vsnprintf(text.data(), text.size() + 1, format, again);
  va_end(again);
  std::fputs(text.c_str(), stdout);
  g_report += text;
}

// Puts this run's report in DIR/benchmarks.md, between bench_cook's markers.
void write_docs(const fs::path& directory) {
  const fs::path page = directory / "benchmarks.md";
  const std::time_t now = std::time(nullptr);
  char date[16];
  std::strftime(date, sizeof date, "%Y-%m-%d", std::gmtime(&now));
  const std::string generated = "\nMeasured " + std::string(date) +
                                " by one run of `bench_cook` (`scripts/bench --write-docs`):\n\n"
                                "```text\n" +
                                g_report + "```\n\n";
  if (!bench::replace_generated_section(page, "bench_cook", generated)) {
    std::fprintf(stderr, "bench_cook: %s has no bench_cook markers\n", page.string().c_str());
    std::exit(1);
  }
}

using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> values) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}
double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(std::lround(q * (values.size() - 1)))];
}

std::string read_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

// ---- Images written for the benchmark -----------------------------------------------------------

struct Rgba {
  int width, height;
  std::vector<std::uint8_t> pixels;
};

void append(png_structp png, png_bytep data, png_size_t size) {
  static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), size);
}

// The PNG forms games ship, for the decode floor: RGBA and grey + alpha at 8 and 16 bits, and
// palette + tRNS (the alpha quantised to 256 entries: palette entry i is grey i, alpha i).
enum class PngForm { rgba8, rgba16, grey_alpha8, grey_alpha16, palette };

bool write_png_rows(png_structp png, png_infop info, std::string& out, int width, int height,
                    PngForm form, std::vector<png_bytep>& rows, std::vector<png_color>& palette,
                    std::vector<png_byte>& alphas) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_write_fn(png, &out, append, nullptr);
  const bool sixteen = form == PngForm::rgba16 || form == PngForm::grey_alpha16;
  const int type = form == PngForm::palette ? PNG_COLOR_TYPE_PALETTE
                   : form == PngForm::grey_alpha8 || form == PngForm::grey_alpha16
                       ? PNG_COLOR_TYPE_GRAY_ALPHA
                       : PNG_COLOR_TYPE_RGB_ALPHA;
  png_set_IHDR(png, info, width, height, sixteen ? 16 : 8, type, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  if (form == PngForm::palette) {
    png_set_PLTE(png, info, palette.data(), static_cast<int>(palette.size()));
    png_set_tRNS(png, info, alphas.data(), static_cast<int>(alphas.size()), nullptr);
  }
  png_write_info(png, info);
  png_write_image(png, rows.data());
  png_write_end(png, nullptr);
  return true;
}

void write_png(const fs::path& path, const Rgba& image, PngForm form = PngForm::rgba8) {
  const bool sixteen = form == PngForm::rgba16 || form == PngForm::grey_alpha16;
  const int channels = form == PngForm::palette                                        ? 1
                       : form == PngForm::grey_alpha8 || form == PngForm::grey_alpha16 ? 2
                                                                                       : 4;
  const std::size_t row_bytes = std::size_t(image.width) * channels * (sixteen ? 2 : 1);
  std::vector<png_byte> samples(row_bytes * image.height);
  std::vector<png_bytep> rows;
  for (int y = 0; y < image.height; ++y) {
    png_byte* row = samples.data() + row_bytes * y;
    rows.push_back(row);
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixels.data() + (std::size_t(y) * image.width + x) * 4;
      const std::uint8_t grey = static_cast<std::uint8_t>((p[0] + p[1] + p[2]) / 3);
      const std::uint8_t values[4] = {p[0], p[1], p[2], p[3]};
      const std::uint8_t grey_alpha[2] = {grey, p[3]};
      const std::uint8_t* v = channels == 2 ? grey_alpha : values;
      if (form == PngForm::palette) {
        row[x] = p[3];
        continue;
      }
      for (int c = 0; c < channels; ++c) {
        if (sixteen) {
          row[(x * channels + c) * 2] = v[c];
          row[(x * channels + c) * 2 + 1] = static_cast<png_byte>(v[c] ^ (x & 0x5a));
        } else {
          row[x * channels + c] = v[c];
        }
      }
    }
  }
  std::vector<png_color> palette(256);
  std::vector<png_byte> alphas(256);
  for (int i = 0; i < 256; ++i) {
    const auto v = static_cast<png_byte>(i);
    palette[i] = {v, v, v};
    alphas[i] = v;
  }
  std::string out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  const bool ok =
      write_png_rows(png, info, out, image.width, image.height, form, rows, palette, alphas);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error("cannot write " + path.string());
  std::ofstream(path, std::ios::binary).write(out.data(), static_cast<std::streamsize>(out.size()));
}

void write_webp(const fs::path& path, const Rgba& image) {
  std::uint8_t* out = nullptr;
  const std::size_t size =
      WebPEncodeLosslessRGBA(image.pixels.data(), image.width, image.height, image.width * 4, &out);
  std::ofstream(path, std::ios::binary)
      .write(reinterpret_cast<const char*>(out), static_cast<std::streamsize>(size));
  WebPFree(out);
}

// Solid where field(x, y) > 0, with an anti-aliased edge of about a pixel and some colour.
Rgba draw(int width, int height, const std::function<double(double, double)>& field) {
  Rgba image{width, height, std::vector<std::uint8_t>(std::size_t(width) * height * 4)};
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const double f = field(x + 0.5, y + 0.5);
      std::uint8_t* p = image.pixels.data() + (std::size_t(y) * width + x) * 4;
      p[0] = static_cast<std::uint8_t>(x * 255 / std::max(1, width - 1));
      p[1] = static_cast<std::uint8_t>(y * 255 / std::max(1, height - 1));
      p[2] = 128;
      p[3] = static_cast<std::uint8_t>(std::clamp(std::lround(127.5 + 255 * f), 0L, 255L));
    }
  }
  return image;
}

// Discs of radius r on a grid of the given spacing, with wavy edges; every third has a hole.
double blobs(double x, double y, double spacing, double r) {
  const double cx = (std::floor(x / spacing) + 0.5) * spacing;
  const double cy = (std::floor(y / spacing) + 0.5) * spacing;
  const double dx = x - cx, dy = y - cy, d = std::hypot(dx, dy);
  const double wave = 0.12 * r * std::sin(7 * std::atan2(dy, dx) + cx * 0.37 + cy * 0.11);
  double f = r + wave - d;
  const long cell = std::lround(cx / spacing) * 31 + std::lround(cy / spacing);
  if (cell % 3 == 0) f = std::min(f, d - 0.35 * r);
  return f;
}

// A big blob with holes: a wavy disc minus a ring of smaller wavy discs.
double swiss(double x, double y, double size) {
  const double c = size / 2, r = 0.45 * size;
  const double dx = x - c, dy = y - c;
  double f = r + 0.04 * size * std::sin(11 * std::atan2(dy, dx)) - std::hypot(dx, dy);
  for (int k = 0; k < 9; ++k) {
    const double a = k * 0.698, hx = c + 0.25 * size * std::cos(a),
                 hy = c + 0.25 * size * std::sin(a);
    f = std::min(f, std::hypot(x - hx, y - hy) - 0.06 * size);
  }
  return f;
}

std::vector<fs::path> write_synthetic_set(const fs::path& dir, bool quick) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::vector<fs::path> files;
  auto add_png = [&](const std::string& name, const Rgba& image) {
    files.push_back(dir / name);
    write_png(files.back(), image);
  };
  const std::vector<int> sizes =
      quick ? std::vector<int>{48, 160, 512} : std::vector<int>{32, 64, 128, 256, 512, 1024, 2048};
  for (int size : sizes) {
    add_png("swiss_" + std::to_string(size) + ".png",
            draw(size, size, [&](double x, double y) { return swiss(x, y, size); }));
    add_png("blobs_" + std::to_string(size) + ".png",
            draw(size, size / 2, [&](double x, double y) { return blobs(x, y, 24, 9); }));
  }
  // One sprite in every PNG form, for the decode floor of each.
  const int form_size = quick ? 256 : 768;
  const Rgba form_image =
      draw(form_size, form_size, [&](double x, double y) { return swiss(x, y, form_size); });
  const std::pair<const char*, PngForm> forms[] = {{"form_rgba16.png", PngForm::rgba16},
                                                   {"form_grey_alpha8.png", PngForm::grey_alpha8},
                                                   {"form_grey_alpha16.png", PngForm::grey_alpha16},
                                                   {"form_palette_trns.png", PngForm::palette}};
  for (const auto& [name, form] : forms) {
    files.push_back(dir / name);
    write_png(files.back(), form_image, form);
  }
  const int sheet = quick ? 256 : 1024;
  const Rgba webp = draw(sheet, sheet, [&](double x, double y) { return blobs(x, y, 40, 15); });
  files.push_back(dir / ("sheet_" + std::to_string(sheet) + ".webp"));
  write_webp(files.back(), webp);
  std::sort(files.begin(), files.end());
  return files;
}

// ---- 1. Process start-up ------------------------------------------------------------------------

struct ProcessRun {
  double wall_ms;
  double max_rss_mb;
};

// Runs argv with stdout and stderr on /dev/null and waits for it, timing it from this process.
ProcessRun spawn_and_wait(const std::vector<std::string>& argv) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  const auto start = Clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, args[0], &actions, nullptr, args.data(), environ) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    return {-1, 0};
  }
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  const double wall = ms_since(start);
  posix_spawn_file_actions_destroy(&actions);
  return {wall, usage.ru_maxrss / 1024.0};
}

// The commands are started by a small process forked before the benchmark holds any images: a
// child's peak RSS (ru_maxrss) starts at its parent's resident memory at the fork (Linux keeps
// the old memory's high-water mark across exec), so spawned from the benchmark itself a cook
// would be charged the benchmark's hundred megabytes of decoded images.
class Spawner {
 public:
  Spawner() {
    int requests[2], answers[2];
    if (pipe(requests) != 0 || pipe(answers) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      close(requests[1]), close(answers[0]);
      serve(requests[0], answers[1]);
      _exit(0);
    }
    close(requests[0]), close(answers[1]);
    to_ = requests[1], from_ = answers[0];
  }
  ~Spawner() {
    if (to_ >= 0) close(to_);
    if (from_ >= 0) close(from_);
    if (pid_ > 0) waitpid(pid_, nullptr, 0);
  }
  Spawner(const Spawner&) = delete;
  Spawner& operator=(const Spawner&) = delete;

  ProcessRun run(const std::vector<std::string>& argv) {
    if (pid_ <= 0) return spawn_and_wait(argv);  // no fork: measured from here, inflated
    std::string request;
    for (const std::string& a : argv) request += a, request += '\0';
    const std::uint64_t size = request.size();
    ProcessRun run{-1, 0};
    if (!write_all(to_, &size, sizeof size) || !write_all(to_, request.data(), request.size()) ||
        !read_all(from_, &run, sizeof run))
      return {-1, 0};
    return run;
  }

 private:
  static bool write_all(int fd, const void* data, std::size_t size) {
    const char* bytes = static_cast<const char*>(data);
    while (size > 0) {
      const ssize_t n = write(fd, bytes, size);
      if (n <= 0) return false;
      bytes += n, size -= std::size_t(n);
    }
    return true;
  }
  static bool read_all(int fd, void* data, std::size_t size) {
    char* bytes = static_cast<char*>(data);
    while (size > 0) {
      const ssize_t n = read(fd, bytes, size);
      if (n <= 0) return false;
      bytes += n, size -= std::size_t(n);
    }
    return true;
  }
  static void serve(int requests, int answers) {
    std::uint64_t size = 0;
    while (read_all(requests, &size, sizeof size)) {
      std::string request(size, '\0');
      if (!read_all(requests, request.data(), size)) return;
      std::vector<std::string> argv;
      for (std::size_t at = 0; at < request.size();) {
        const std::size_t end = request.find('\0', at);
        argv.push_back(request.substr(at, end - at));
        at = end + 1;
      }
      const ProcessRun run = spawn_and_wait(argv);
      if (!write_all(answers, &run, sizeof run)) return;
    }
  }

  pid_t pid_ = -1;
  int to_ = -1, from_ = -1;
};

Spawner* g_spawner = nullptr;

ProcessRun run_process(const std::vector<std::string>& argv) { return g_spawner->run(argv); }

void print_startup(const fs::path& scratch, int runs) {
  const fs::path sprite = scratch / "sprite64.png";
  write_png(sprite, draw(64, 64, [](double x, double y) { return blobs(x, y, 64, 26); }));
  const std::string exe = HULLCOOK_EXE;
  const std::vector<std::vector<std::string>> commands{
      {"/bin/true"},
      {exe, "--version"},
      {exe, "cook", sprite.string(), "-o", (scratch / "sprite64.hcb").string(), "-q"}};
  std::vector<std::vector<double>> times(commands.size());
  std::vector<double> rss(commands.size());
  for (const auto& command : commands) run_process(command);  // warm-up
  for (int r = 0; r < runs * 8; ++r) {
    for (std::size_t c = 0; c < commands.size(); ++c) {
      const ProcessRun run = run_process(commands[c]);
      times[c].push_back(run.wall_ms);
      rss[c] = std::max(rss[c], run.max_rss_mb);
    }
  }
  report("\n1. Process start-up (%d runs each, interleaved; wall ms: median [p10 .. p90])\n",
         runs * 8);
  const double base = median(times[0]);
  const char* names[] = {"/bin/true", "hullcook --version", "hullcook cook 64x64 -> .hcb"};
  const char* targets[] = {"", "<= 15 ms above /bin/true", "<= 25 ms above /bin/true"};
  for (std::size_t c = 0; c < commands.size(); ++c) {
    report("   %-30s %7.2f [%6.2f .. %6.2f]  above true %+7.2f  peak RSS %5.1f MB  %s\n", names[c],
           median(times[c]), quantile(times[c], 0.1), quantile(times[c], 0.9),
           median(times[c]) - base, rss[c], targets[c]);
  }
}

// ---- 2. The decode floor ------------------------------------------------------------------------

bool libpng_read(png_structp png, png_infop info, std::vector<png_byte>& pixels,
                 std::vector<png_bytep>& rows, const std::string* bytes, std::size_t* at) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_set_read_fn(png, at, [](png_structp p, png_bytep out, png_size_t size) {
    auto* cursor = static_cast<std::size_t*>(png_get_io_ptr(p));
    const std::string* source = reinterpret_cast<const std::string*>(cursor[1]);
    if (cursor[0] + size > source->size()) png_error(p, "short");
    std::memcpy(out, source->data() + cursor[0], size);
    cursor[0] += size;
  });
  (void)bytes;
  png_read_info(png, info);
  png_set_interlace_handling(png);
  png_read_update_info(png, info);
  const std::size_t row_bytes = png_get_rowbytes(png, info);
  const std::size_t height = png_get_image_height(png, info);
  pixels.resize(row_bytes * height);
  rows.resize(height);
  for (std::size_t y = 0; y < height; ++y) rows[y] = pixels.data() + row_bytes * y;
  png_read_image(png, rows.data());
  png_read_end(png, nullptr);
  return true;
}

// libpng or libwebp alone, as an application would call it: the file read, then every pixel
// decoded (no transform) into one buffer.
double floor_decode_ms(const fs::path& path) {
  const auto start = Clock::now();
  const std::string bytes = read_file(path);
  if (path.extension() == ".webp") {
    int width = 0, height = 0;
    std::uint8_t* pixels = WebPDecodeRGBA(reinterpret_cast<const std::uint8_t*>(bytes.data()),
                                          bytes.size(), &width, &height);
    WebPFree(pixels);
  } else {
    std::vector<png_byte> pixels;
    std::vector<png_bytep> rows;
    std::size_t cursor[2] = {0, reinterpret_cast<std::size_t>(&bytes)};
    // Warnings (e.g. a known incorrect sRGB profile) are not printed, as a game would not.
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr,
                                             [](png_structp, png_const_charp) {});
    png_infop info = png_create_info_struct(png);
    libpng_read(png, info, pixels, rows, &bytes, cursor);
    png_destroy_read_struct(&png, &info, nullptr);
  }
  return ms_since(start);
}

double best_of(int runs, const std::function<double()>& measure) {
  double best = 1e300;
  for (int r = 0; r < runs; ++r) best = std::min(best, measure());
  return best;
}

// ---- 3, 4. Stages, threads, memory
// ---------------------------------------------------------------

Settings cook_settings(unsigned threads) {
  Settings settings;
  settings.tau = Tolerance{1.0, false};
  settings.threads = threads;
  return settings;
}

void print_set(const std::string& title, const std::vector<fs::path>& files,
               const fs::path& scratch, int runs) {
  report("\n== %s: %zu images\n", title.c_str(), files.size());
  double floor_ms = 0, decode_ms = 0, largest_image_mb = 0;
  std::string forms;
  for (const fs::path& file : files) {
    const double floor_one = best_of(runs, [&] { return floor_decode_ms(file); });
    const TraceSettings trace;
    AlphaImage alpha;
    const double decode_one = best_of(runs, [&] {
      const auto start = Clock::now();
      alpha = load_alpha(file, trace);
      return ms_since(start);
    });
    floor_ms += floor_one, decode_ms += decode_one;
    largest_image_mb = std::max(largest_image_mb, alpha.width * double(alpha.height) * 4 / 1e6);
    const std::string name = file.filename().string();
    if (name.rfind("form_", 0) == 0 || file.extension() == ".webp") {
      char line[200];
      std::snprintf(line, sizeof line, "     %-26s floor %7.2f ms, hullcook %7.2f ms = %.2fx\n",
                    name.c_str(), floor_one, decode_one, decode_one / floor_one);
      forms += line;
    }
  }
  report("2. Decode floor (libpng/libwebp alone, best of %d): %8.2f ms\n", runs, floor_ms);
  report(
      "   hullcook's decoding (alpha only):          %8.2f ms  = %.2fx the floor"
      "   (target <= 1.2x)\n",
      decode_ms, decode_ms / floor_ms);
  report("%s", forms.c_str());

  // Stages inside cook(), one thread: each asset's best run.
  std::vector<CookedStats> best;
  for (int r = 0; r < runs; ++r) {
    CookResult result = cook(files, cook_settings(1));
    if (best.empty()) {
      CookedStats none;
      none.decode_ms = none.trace_ms = none.decompose_ms = none.contract_ms = none.total_ms = 1e300;
      best.resize(result.assets.size(), none);
    }
    for (std::size_t i = 0; i < result.assets.size(); ++i) {
      const CookedStats& s = result.assets[i].stats;
      best[i].decode_ms = std::min(best[i].decode_ms, s.decode_ms);
      best[i].trace_ms = std::min(best[i].trace_ms, s.trace_ms);
      best[i].decompose_ms = std::min(best[i].decompose_ms, s.decompose_ms);
      best[i].contract_ms = std::min(best[i].contract_ms, s.contract_ms);
      best[i].total_ms = std::min(
          best[i].total_ms, s.total_ms - s.decode_ms - s.trace_ms - s.decompose_ms - s.contract_ms);
    }
  }
  double trace = 0, decompose = 0, contract = 0, rest = 0;
  for (const CookedStats& s : best)
    trace += s.trace_ms, decompose += s.decompose_ms, contract += s.contract_ms, rest += s.total_ms;
  const CookResult result = cook(files, cook_settings(1));
  // The asset that takes longest, for the cook of one huge image alone (section 4).
  fs::path heaviest;
  double heaviest_ms = -1;
  for (std::size_t i = 0; i < best.size(); ++i) {
    const CookedStats& s = best[i];
    const double ms = s.decode_ms + s.trace_ms + s.decompose_ms + s.contract_ms + s.total_ms;
    if (ms > heaviest_ms) heaviest_ms = ms, heaviest = result.assets[i].source;
  }
  const fs::path out = scratch / "bench.hcb";
  const double write = best_of(runs, [&] {
    const auto start = Clock::now();
    write_output(result, out, cook_settings(1));
    return ms_since(start);
  });
  // The cleaner alone, on each asset's regions again (cleaning clean regions does the same
  // checks); the engine limits are the rest.
  double clean = 0;
  for (const CookedAsset& asset : result.assets) {
    clean += best_of(runs, [&] {
      std::vector<Region> regions = asset.regions;
      const auto start = Clock::now();
      if (!regions.empty()) clean_and_validate(std::move(regions), asset.source);
      return ms_since(start);
    });
  }
  rest = std::max(0.0, rest - clean);
  const double after = trace + decompose + clean + rest + contract + write;
  report("3. Stages after decoding, one thread (ms, and x the decode floor):\n");
  report("   trace (march, nesting, simplify)  %8.2f  %5.2fx\n", trace, trace / floor_ms);
  report("   decompose                         %8.2f  %5.2fx\n", decompose, decompose / floor_ms);
  report("   clean (validation)                %8.2f  %5.2fx\n", clean, clean / floor_ms);
  report("   engine limits + other             %8.2f  %5.2fx\n", rest, rest / floor_ms);
  report("   contract check (every level)      %8.2f  %5.2fx\n", contract, contract / floor_ms);
  report("   write .hcb                        %8.2f  %5.2fx\n", write, write / floor_ms);
  report("   all after decoding                %8.2f  %5.2fx   (target <= 1x)\n", after,
         after / floor_ms);

  std::vector<double> one, two;
  for (int r = 0; r < runs; ++r) {
    for (unsigned threads : {1u, 2u}) {
      const auto start = Clock::now();
      cook(files, cook_settings(threads));
      (threads == 1 ? one : two).push_back(ms_since(start));
    }
  }
  report(
      "4. Whole cook in process (median of %d): 1 thread %8.2f ms, 2 threads %8.2f ms:"
      " %.2fx faster (target >= 1.7x); 2 threads = %.2fx the decode floor (target <= 2x)\n",
      runs, median(one), median(two), median(one) / median(two), median(two) / floor_ms);
  // The heaviest image alone: its threads split its work per region and per piece, not per asset.
  // Short, so three times the runs, and the ratio taken pair by pair (these machines drift).
  {
    one.clear(), two.clear();
    std::vector<double> ratios;
    const int alone_runs = 3 * runs;
    for (int r = 0; r < alone_runs; ++r) {
      for (unsigned threads : {1u, 2u}) {
        const auto start = Clock::now();
        cook({heaviest}, cook_settings(threads));
        (threads == 1 ? one : two).push_back(ms_since(start));
      }
      ratios.push_back(one.back() / two.back());
    }
    report(
        "   the heaviest image alone (%s, median of %d): 1 thread %8.2f ms, 2 threads %8.2f ms:"
        " %.2fx faster (paired: %.2fx) (target >= 1.7x)\n",
        heaviest.filename().string().c_str(), alone_runs, median(one), median(two),
        median(one) / median(two), median(ratios));
  }
  for (unsigned threads : {1u, 2u}) {
    std::vector<std::string> command{HULLCOOK_EXE, "cook"};
    for (const fs::path& f : files) command.push_back(f.string());
    command.insert(command.end(),
                   {"--tau", "1", "--threads", std::to_string(threads), "-q", "-o", out.string()});
    std::vector<double> walls;
    double rss = 0;
    for (int r = 0; r < runs; ++r) {
      const ProcessRun run = run_process(command);
      walls.push_back(run.wall_ms);
      rss = std::max(rss, run.max_rss_mb);
    }
    const double output_mb = fs::file_size(out) / 1e6;
    report(
        "   hullcook cook --threads %u as a process: %8.2f ms, peak RSS %6.1f MB;"
        " 4x the largest decoded image (%.1f MB RGBA) + output: %.1f MB\n",
        threads, median(walls), rss, largest_image_mb, 4 * largest_image_mb + output_mb);
  }
}

// The PNG and WebP images under dir (the decode floor is libpng's or libwebp's) that cook alone
// at the benchmark's settings: a game's folder holds images the cook refuses (no alpha channel,
// nothing opaque), which would stop a cook of the whole set.
// A cook given files names each by its file name and refuses two of one name, which a game's
// folders often hold (the same sprites at 1x, 2x and 3x): such an image is measured through a
// link in links_dir named by its path under dir, as a cook of the directory would name it.
std::vector<fs::path> cookable_images(const fs::path& dir, const fs::path& links_dir) {
  std::vector<fs::path> candidates, files;
  std::size_t refused = 0, other = 0, linked = 0;
  std::error_code error;
  for (auto it = fs::recursive_directory_iterator(dir, error); !error && it != fs::end(it);
       it.increment(error)) {
    if (!it->is_regular_file()) continue;
    std::string extension = it->path().extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".png" || extension == ".webp") {
      candidates.push_back(it->path());
    } else {
      other += is_image_file(it->path());
    }
  }
  if (error)
    report("\nbench_cook: cannot list %s: %s\n", dir.string().c_str(), error.message().c_str());
  std::sort(candidates.begin(), candidates.end());
  std::map<std::string, std::size_t> name_count;
  for (const fs::path& found : candidates) ++name_count[found.filename().string()];
  for (const fs::path& found : candidates) {
    fs::path path = found;
    if (name_count[found.filename().string()] > 1) {
      std::string name = found.lexically_relative(dir).generic_string();
      std::replace(name.begin(), name.end(), '/', '~');
      path = links_dir / name;
      fs::create_directories(links_dir);
      // "a/b~c.png" and "a~b/c.png" would share a link's name: the second is numbered.
      if (fs::exists(fs::symlink_status(path)))
        path = links_dir / (std::to_string(linked) + "~" + name);
      fs::create_symlink(fs::absolute(found), path);
    }
    try {
      cook({path}, cook_settings(1));
      files.push_back(path);
      if (path != found) ++linked;
    } catch (const std::exception&) {
      ++refused;
    }
  }
  const std::string links =
      linked == 0 ? std::string()
                  : " (" + std::to_string(linked) +
                        " of them sharing a file name, measured through links named by their path)";
  report(
      "\nbench_cook: %s: %zu images cook alone%s; left out: %zu the cook refuses, %zu neither "
      "PNG nor WebP\n",
      dir.string().c_str(), files.size(), links.c_str(), refused, other);
  return files;
}

// ---- 5. Scaling of the tracer and the cleaner with the outline's length
// --------------------------

// The slope of the least-squares line through (x[i], y[i]): on logarithms, a fitted exponent.
double least_squares_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / x.size();
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / y.size();
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < y.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
  }
  return sxy / sxx;
}

void print_scaling(int runs, bool quick) {
  report(
      "\n5. Tracer and cleaner against the outline's length (blobs with wavy edges and "
      "holes, best of %d)\n",
      runs);
  report("   %12s %12s %12s %12s %12s\n", "pixels", "vertices", "trace ms", "clean ms",
         "ns/vertex");
  std::vector<double> log_n, log_trace, log_clean;
  const std::vector<int> sides =
      quick ? std::vector<int>{100, 316, 1000} : std::vector<int>{100, 316, 1000, 3162};
  for (int side : sides) {
    const Rgba image = draw(side, side, [](double x, double y) { return blobs(x, y, 20, 7.5); });
    AlphaImage alpha{side, side, {}};
    for (std::size_t i = 3; i < image.pixels.size(); i += 4) alpha.alpha.push_back(image.pixels[i]);
    TraceSettings settings;
    settings.simplify = 0.25;
    TraceResult traced;
    const double trace = best_of(runs, [&] {
      const auto start = Clock::now();
      traced = trace_alpha(alpha, settings);
      return ms_since(start);
    });
    const double clean = best_of(runs, [&] {
      std::vector<Region> regions = traced.regions;
      const auto start = Clock::now();
      clean_and_validate(std::move(regions), "scaling");
      return ms_since(start);
    });
    const double n = static_cast<double>(traced.traced_vertices);
    report("   %12lld %12.0f %12.2f %12.2f %12.1f\n", static_cast<long long>(side) * side, n, trace,
           clean, (trace + clean) * 1e6 / n);
    log_n.push_back(std::log(n));
    log_trace.push_back(std::log(trace));
    log_clean.push_back(std::log(clean));
  }
  auto slope = [&](const std::vector<double>& y) { return least_squares_slope(log_n, y); };
  report(
      "   fitted exponent (time ~ vertices^k): trace k = %.2f, clean k = %.2f"
      "   (target: linear, k ~ 1)\n",
      slope(log_trace), slope(log_clean));
}

// ---- 6. The engine limits against a convex outline's vertex count
// ----------------------------

// A regular polygon (a CAD circle): every vertex is nearly collinear with its neighbours, so the
// hull fitter mends thousands of vertices one edge at a time before it fits hulls of 8. Each
// removal once cost a pass over the hull (stop 55: 5,000 vertices 4.2 s, 20,000 65 s).
void print_regular_polygons(const fs::path& scratch, int runs, bool quick) {
  report(
      "\n6. Engine limits against the vertex count of a regular polygon (radius 100, default "
      "settings, --max-verts 8, one thread, best of %d)\n",
      runs);
  report("   %12s %8s %12s %12s\n", "vertices", "hulls", "cook ms", "us/vertex");
  std::vector<double> log_n, log_ms;
  const std::vector<int> counts =
      quick ? std::vector<int>{1250, 2500, 5000} : std::vector<int>{1250, 2500, 5000, 10000};
  for (int n : counts) {
    const fs::path file = scratch / ("regular_" + std::to_string(n) + ".poly");
    {
      Ring circle;
      for (int i = 0; i < n; ++i) {
        const double angle = 2 * std::acos(-1.0) * i / n;
        circle.push_back(100.0 * Vec2{std::cos(angle), std::sin(angle)});
      }
      std::ofstream(file) << format_poly({Region{circle, {}}});
    }
    Settings settings;
    settings.threads = 1;
    std::size_t hulls = 0;
    const double ms = best_of(n >= 5000 ? 1 : runs, [&] {
      const auto start = Clock::now();
      const CookResult result = cook({file}, settings);
      const double elapsed = ms_since(start);
      hulls = 0;
      for (const CookedAsset& asset : result.assets) hulls += asset.stats.hulls;
      return elapsed;
    });
    report("   %12d %8zu %12.1f %12.1f\n", n, hulls, ms, ms * 1e3 / n);
    log_n.push_back(std::log(n));
    log_ms.push_back(std::log(ms));
  }
  report("   fitted exponent (time ~ vertices^k): k = %.2f   (stop 55: k ~ 2)\n",
         least_squares_slope(log_n, log_ms));
}

}  // namespace

int main(int argc, char** argv) {
  int runs = 5;
  bool quick = false;
  std::optional<fs::path> docs;
  std::vector<fs::path> sprite_dirs;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--sprites") == 0 && i + 1 < argc) sprite_dirs.push_back(argv[++i]);
    if (std::strcmp(argv[i], "--runs") == 0 && i + 1 < argc)
      runs = std::max(1, std::atoi(argv[++i]));
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    if (std::strcmp(argv[i], "--write-docs") == 0 && i + 1 < argc) docs = argv[++i];
    if (std::strcmp(argv[i], "--write-synthetic") == 0 && i + 1 < argc) {
      const std::vector<fs::path> files = write_synthetic_set(argv[i + 1], quick);
      std::printf("bench_cook: %zu synthetic images in %s\n", files.size(), argv[i + 1]);
      return 0;
    }
  }
  Spawner spawner;  // first, while this process is small
  g_spawner = &spawner;
  const fs::path scratch =
      fs::temp_directory_path() / ("hullcook_bench_cook_" + std::to_string(getpid()));
  fs::create_directories(scratch);
  report(
      "bench_cook: whole-process and in-process figures of one run (hullcook %s); "
      "machine load average at start: ",
      HULLCOOK_EXE);
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) == 3) report("%.2f %.2f %.2f\n", load[0], load[1], load[2]);
  print_startup(scratch, runs);
  std::vector<fs::path> samples;
  for (const auto& entry :
       fs::directory_iterator(fs::path(HULLCOOK_SOURCE_DIR) / "samples/sprites")) {
    if (is_image_file(entry.path())) samples.push_back(entry.path());
  }
  std::sort(samples.begin(), samples.end());
  print_set("samples/sprites", samples, scratch, runs);
  print_set("synthetic set", write_synthetic_set(scratch / "synthetic", quick), scratch, runs);
  for (std::size_t d = 0; d < sprite_dirs.size(); ++d) {
    const fs::path& dir = sprite_dirs[d];
    const std::vector<fs::path> files =
        cookable_images(dir, scratch / ("sprite-links-" + std::to_string(d)));
    if (!files.empty()) print_set(dir.string(), files, scratch, runs);
  }
  print_scaling(std::min(runs, 3), quick);
  print_regular_polygons(scratch, std::min(runs, 3), quick);
  fs::remove_all(scratch);
  if (docs) write_docs(*docs);
  return 0;
}
