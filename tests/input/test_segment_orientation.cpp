// Sliding-interface segments take the outward orientation of the solid face they lie on
// (decks/two_bars.dyn): master segments given clockwise are reversed with warning 2013 and
// give the same model as the shipped deck; criss-crossed node orders are error 1225 naming the
// line and card; the warnings come in one pass, one per segment.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/deck_writer.h"
#include "tests/input/input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

// two_bars.dyn with each master segment card rewritten by `edit` (fields of 8 columns:
// id, n1, n2, n3, n4)
std::string two_bars_with(void (*edit)(std::vector<std::string>&)) {
  const std::string text = read_text(source_path("decks/two_bars.dyn"));
  std::string out, line;
  std::istringstream in(text);
  bool master = false;
  while (std::getline(in, line)) {
    if (line.rfind("*", 0) == 0) master = line.find("MASTER SEGMENTS") != std::string::npos;
    else if (master && line.size() >= 40) {
      std::vector<std::string> f;
      for (std::size_t k = 0; k + 8 <= line.size(); k += 8) f.push_back(line.substr(k, 8));
      edit(f);
      line.clear();
      for (const auto& x : f) line += x;
    }
    out += line + "\n";
  }
  return out;
}

bool read_file_text(const std::string& name, const std::string& text, Model& m, Diagnostics& d) {
  const std::string path = std::string(IMPACT3D_BINARY_DIR) + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return read_and_check_deck(path, m, d);
}

int count(const Diagnostics& d, int id) { return d.count(id); }

}  // namespace

TEST(SegmentOrientation, ClockwiseSegmentsAreReversedToTheOutwardNormal) {
  Model shipped;
  Diagnostics ds;
  ASSERT_TRUE(read_and_check_deck(source_path("decks/two_bars.dyn"), shipped, ds));
  EXPECT_EQ(count(ds, 2013), 0);
  Model rev;
  Diagnostics dr;
  ASSERT_TRUE(read_file_text("segments_reversed.dyn",
                             two_bars_with([](std::vector<std::string>& f) { std::swap(f[2], f[4]); }), rev, dr))
      << all_messages(dr);
  EXPECT_EQ(count(dr, 2013), int(shipped.interfaces[0].master.size())) << all_messages(dr);
  EXPECT_NE(all_messages(dr).find("master segment 1"), std::string::npos);
  // the same segments as the shipped deck's, up to the starting node
  ASSERT_EQ(shipped.interfaces[0].master.size(), rev.interfaces[0].master.size());
  for (std::size_t s = 0; s < shipped.interfaces[0].master.size(); ++s) {
    const auto a = shipped.interfaces[0].master[s], b = rev.interfaces[0].master[s];
    bool rotated = false;
    for (int r = 0; r < 4; ++r)
      rotated = rotated || (a[0] == b[std::size_t(r)] && a[1] == b[std::size_t((r + 1) % 4)] &&
                            a[2] == b[std::size_t((r + 2) % 4)] && a[3] == b[std::size_t((r + 3) % 4)]);
    EXPECT_TRUE(rotated) << "segment " << s + 1;
  }
}

TEST(SegmentOrientation, CrissCrossedSegmentsAreErrors) {
  Model m;
  Diagnostics d;
  EXPECT_FALSE(read_file_text("segments_crossed.dyn",
                              two_bars_with([](std::vector<std::string>& f) { std::swap(f[2], f[3]); }), m, d));
  EXPECT_EQ(count(d, 1225), 4) << all_messages(d);
  const std::string msg = all_messages(d);
  EXPECT_NE(msg.find("segments_crossed.dyn:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sliding interface 1 master segment 1"), std::string::npos) << msg;
}
