// Fuzz harness of the Mili reader (common/mili_database) and of POST-IMPACT's use of it: the
// input is cut at lines "$$FUZZ-FILE$$" into the A file, the state files NAME00 and NAME01 and
// the T file.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

#include "common/mili_database.h"
#include "fuzz/harness/fuzz_util.h"
#include "fuzz/harness/targets.h"
#include "postimpact/compare.h"
#include "postimpact/database.h"
#include "postimpact/history.h"
#include "postimpact/summary.h"

namespace impact3d_fuzz {

int fuzz_mili_database(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  static const fs::path dir = scratch_dir() / "mili";
  static const bool made = fs::create_directories(dir);
  (void)made;
  const auto parts = split_parts(as_text(data, size), "$$FUZZ-FILE$$\n", 4);
  const char* names[4] = {"db.pltA", "db.plt00", "db.plt01", "db.pltT"};
  for (std::size_t k = 0; k < 4; ++k) {
    std::error_code ec;
    if (k < parts.size()) write_file(dir / names[k], parts[k]);
    else fs::remove(dir / names[k], ec);
  }
  impact3d::MiliReader r;
  try {
    r.open((dir / "db.pltA").string());
  } catch (const std::runtime_error&) {
    return 0;
  }
  const int n = std::min(r.num_states(), 4);
  for (int i = 0; i < n; ++i) {
    try {
      r.time(i);
      r.state(i);
      std::vector<double> v;
      for (int c = 0; c < static_cast<int>(r.classes().size()) && c < 8; ++c)
        for (const char* leaf : {"ux", "sx", "axf", "ke"}) r.result(i, c, leaf, v);
    } catch (const std::runtime_error&) {
    }
  }
  // POST-IMPACT on it: histories of the first node and element, a raw variable, summary,
  // compare with itself (by time)
  const std::string a = (dir / "db.pltA").string();
  try {
    postimpact::Database db(a);
    if (db.num_states() > 0 && db.geometry().num_nodes() > 0) {
      std::vector<std::string> words = {"energy", "node", std::to_string(db.node_id(0)), "disp", "az"};
      if (db.geometry().num_hexes() > 0) words.insert(words.end(), {"element", std::to_string(db.element_id(0)), "vm"});
      words.insert(words.end(), {"mili", "node", std::to_string(db.node_id(0)), "ux"});
      try {
        postimpact::extract_history(db, postimpact::parse_history(words, db));
      } catch (const std::invalid_argument&) {
      }
    }
  } catch (const std::runtime_error&) {
    return 0;
  }
  std::ostringstream sink;
  try {
    postimpact::write_summary(postimpact::summarize(a, ""), sink);
  } catch (const std::runtime_error&) {
  }
  postimpact::compare_databases(a, a, postimpact::CompareOptions{}, sink);
  return 0;
}

}  // namespace impact3d_fuzz
