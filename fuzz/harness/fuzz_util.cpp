#include "fuzz/harness/fuzz_util.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>

namespace impact3d_fuzz {

namespace {
std::filesystem::path g_scratch;
void remove_scratch() {
  std::error_code ec;
  if (!g_scratch.empty()) std::filesystem::remove_all(g_scratch, ec);
}
}  // namespace

const std::filesystem::path& scratch_dir() {
  if (g_scratch.empty()) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/impact3d-fuzz-XXXXXX";
    if (!mkdtemp(pattern.data())) {
      std::perror("impact3d fuzz: mkdtemp");
      std::abort();
    }
    g_scratch = pattern;
    std::atexit(remove_scratch);
  }
  return g_scratch;
}

void write_file(const std::filesystem::path& path, std::string_view bytes) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  f.close();
  if (!f) {
    std::fprintf(stderr, "impact3d fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
}

std::vector<std::string_view> split_parts(std::string_view in, std::string_view sep, std::size_t max_parts) {
  std::vector<std::string_view> parts;
  while (parts.size() + 1 < max_parts) {
    const std::size_t at = in.find(sep);
    if (at == std::string_view::npos) break;
    parts.push_back(in.substr(0, at));
    in.remove_prefix(at + sep.size());
  }
  parts.push_back(in);
  return parts;
}

void split_root_member(std::string_view in, std::string_view& root, std::string_view& member) {
  if (in.size() < 4) {
    root = in;
    member = {};
    return;
  }
  const auto* u = reinterpret_cast<const unsigned char*>(in.data());
  const std::uint32_t len = std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 |
                            std::uint32_t(u[3]) << 24;
  in.remove_prefix(4);
  const std::size_t n = in.empty() ? 0 : len % (in.size() + 1);
  root = in.substr(0, n);
  member = in.substr(n);
}

namespace {

// The word size of a d3plot root file at `root`: 4 or 8 as its VERSION word (14) reads as a
// float in (900, 1000), else 0.
int version_word_size(const std::uint8_t* root, std::size_t size) {
  if (size >= 15 * 4) {
    float v4;
    std::memcpy(&v4, root + 14 * 4, 4);
    if (v4 > 900 && v4 < 1000) return 4;
  }
  if (size >= 15 * 8) {
    double v8;
    std::memcpy(&v8, root + 14 * 8, 8);
    if (v8 > 900 && v8 < 1000) return 8;
  }
  return 0;
}

}  // namespace

bool write_extreme_header_count(std::uint8_t* data, std::size_t size, unsigned seed) {
  // the count words of the 64 control words (common/plot_database.cpp parse_control), then
  // the first EXTRA words (64: NEL20, 65: NT3D, ..., 67: NEIPB)
  static const int kCountWords[] = {16, 18, 19, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36,
                                    37, 38, 39, 40, 41, 42, 47, 51, 52, 55, 56, 57, 63, 64, 65, 66, 67};
  static const std::int64_t kExtremes[] = {0, -1, 2147483647LL, 2147483648LL, 9223372036854775807LL};
  if (size < 4 + 64 * 4) return false;
  std::uint8_t* root = data + 4;
  const std::size_t root_size = size - 4;
  std::uint64_t r = seed * 0x9E3779B97F4A7C15ULL + 1;
  auto next = [&r] {
    r ^= r >> 33;
    r *= 0xFF51AFD7ED558CCDULL;
    r ^= r >> 29;
    return r;
  };
  int ws = version_word_size(root, root_size);
  if (ws == 0) ws = (next() & 1) ? 8 : 4;
  const int k = kCountWords[next() % (sizeof kCountWords / sizeof kCountWords[0])];
  if (std::size_t(k + 1) * std::size_t(ws) > root_size) return false;
  const std::int64_t v = kExtremes[next() % (sizeof kExtremes / sizeof kExtremes[0])];
  if (ws == 4) {
    const auto v32 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(v));
    std::memcpy(root + 4 * k, &v32, 4);
  } else {
    std::memcpy(root + 8 * k, &v, 8);
  }
  return true;
}

}  // namespace impact3d_fuzz
