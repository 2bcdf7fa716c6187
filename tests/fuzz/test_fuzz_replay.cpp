// Every input that made a fuzz target fail (tests/fuzz/TARGET/*, README.md "Fuzzing and
// sanitizers") replayed through the same harness in the normal build: it must now go through
// without a crash (the sanitizer build, tools/test.sh --sanitize, checks for memory errors too).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz/harness/fuzz_util.h"
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

// The plot targets' header mutation (fuzz_util.h) writes only the extreme values, only onto
// count words of the control section, in the word size the file's VERSION word shows.
TEST(FuzzReplay, HeaderCountMutationWritesExtremesOnCountWords) {
  const fs::path p = fs::path(IMPACT3D_SOURCE_DIR) / "tests/fuzz/plot_database/neips_2147483647";
  std::ifstream f(p, std::ios::binary);
  const std::vector<std::uint8_t> orig((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  ASSERT_GT(orig.size(), 4u + 64 * 4);
  const std::int64_t extremes[] = {0, -1, 2147483647LL, 2147483648LL, 9223372036854775807LL};
  int changed = 0;
  for (unsigned seed = 0; seed < 200; ++seed) {
    std::vector<std::uint8_t> d = orig;
    ASSERT_TRUE(impact3d_fuzz::write_extreme_header_count(d.data(), d.size(), seed));
    for (std::size_t b = 0; b < d.size(); ++b) {
      if (d[b] == orig[b]) continue;
      ++changed;
      const std::size_t k = (b - 4) / 4;  // this file has 4-byte words
      EXPECT_TRUE(k >= 16 && k < 68) << "byte " << b;
      std::int32_t v;
      std::memcpy(&v, d.data() + 4 + 4 * k, 4);
      bool extreme = false;
      for (std::int64_t x : extremes) extreme = extreme || v == static_cast<std::int32_t>(static_cast<std::uint32_t>(x));
      EXPECT_TRUE(extreme) << "word " << k << " = " << v;
      break;
    }
  }
  EXPECT_GT(changed, 100);  // most draws change the word (an extreme equal to the old value does not)
}
