// Every input that made a fuzz target fail (tests/fuzz/TARGET/*, README.md "Fuzzing and
// sanitizers") replayed through the same harness in the normal build: it must now go through
// without a crash (the sanitizer build, tools/test.sh --sanitize, checks for memory errors too).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/harness/targets.h"

namespace {

namespace fs = std::filesystem;
using Harness = int (*)(const std::uint8_t*, std::size_t);

int replay(const std::string& target, Harness h) {
  const fs::path dir = fs::path(IMPACT3D_SOURCE_DIR) / "tests/fuzz" / target;
  int n = 0;
  if (!fs::is_directory(dir)) return 0;
  std::vector<fs::path> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& p : files) {
    std::ifstream f(p, std::ios::binary);
    const std::string data((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
    SCOPED_TRACE(p.string());
    EXPECT_EQ(h(reinterpret_cast<const std::uint8_t*>(data.data()), data.size()), 0);
    ++n;
  }
  return n;
}

}  // namespace

#define REPLAY_TEST(name)                                                             \
  TEST(FuzzReplay, name) {                                                            \
    const int n = replay(#name, impact3d_fuzz::fuzz_##name);                          \
    RecordProperty("inputs", n);                                                      \
  }

REPLAY_TEST(fixed_deck)
REPLAY_TEST(keyword_deck)
REPLAY_TEST(plot_database)
REPLAY_TEST(postimpact_database)
REPLAY_TEST(restart_dump)
REPLAY_TEST(command_file)
REPLAY_TEST(tolerances)
REPLAY_TEST(mili_database)
