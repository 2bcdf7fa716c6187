#include "fuzz/harness/fuzz_util.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
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

}  // namespace impact3d_fuzz
