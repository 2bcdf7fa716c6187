// Fuzz harnesses of the plot-database reader (common/plot_database) and of POST-IMPACT's use
// of it.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>

#include "common/plot_database.h"
#include "fuzz/harness/fuzz_util.h"
#include "fuzz/harness/targets.h"
#include "postimpact/compare.h"
#include "postimpact/database.h"
#include "postimpact/history.h"
#include "postimpact/mesh_surface.h"
#include "postimpact/quantities.h"
#include "postimpact/summary.h"

namespace impact3d_fuzz {

namespace {

// Writes the family <scratch>/plot/d3plot (+ d3plot01) from the input; returns the root.
std::string write_family(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  static const fs::path dir = scratch_dir() / "plot";
  static const bool made = fs::create_directories(dir);
  (void)made;
  std::string_view root, member;
  split_root_member(as_text(data, size), root, member);
  write_file(dir / "d3plot", root);
  std::error_code ec;
  if (member.empty()) fs::remove(dir / "d3plot01", ec);
  else write_file(dir / "d3plot01", member);
  return (dir / "d3plot").string();
}

}  // namespace

int fuzz_plot_database(const std::uint8_t* data, std::size_t size) {
  const std::string root = write_family(data, size);
  try {
    impact3d::PlotReader::read_control(root);
  } catch (const std::runtime_error&) {
  }
  impact3d::PlotReader r;
  try {
    r.open(root);
  } catch (const std::runtime_error&) {
    return 0;
  }
  const int n = std::min(r.num_states(), 4);
  for (int i = 0; i < n; ++i) {
    try {
      r.time(i);
      r.state(i);
    } catch (const std::runtime_error&) {
    }
  }
  return 0;
}

int fuzz_postimpact_database(const std::uint8_t* data, std::size_t size) {
  const std::string root = write_family(data, size);
  std::ostringstream sink;
  try {
    postimpact::Database db(root);
    const auto& g = db.geometry();
    const int ns = db.num_states();
    for (int i : {0, ns / 2, ns - 1}) {
      if (i < 0 || i >= ns) continue;
      const impact3d::PlotState& s = db.state(i);
      auto faces = postimpact::exterior_faces(g, s.alive);
      postimpact::Mirror m;
      m.axis = {true, true, true};
      faces = postimpact::drop_symmetry_faces(faces, g, m);
      for (const char* key : {"eps", "vm", "pressure", "szx", "disp", "dz", "vel", "vy", "ax", "x"}) {
        postimpact::Quantity q;
        if (!postimpact::find_quantity(key, q)) continue;
        if (q.where == postimpact::Quantity::Where::Element) postimpact::element_values(q, s);
        else postimpact::node_values(q, g, s);
      }
    }
    if (ns > 0) {
      std::vector<std::string> words = {"energy", "global", "ke", "vz"};
      if (g.num_nodes() > 0) words.insert(words.end(), {"node", std::to_string(db.node_id(0)), "disp", "az"});
      if (g.num_hexes() > 0)
        words.insert(words.end(), {"element", std::to_string(db.element_id(g.num_hexes() - 1)), "vm", "eps"});
      if (g.num_materials > 0) words.insert(words.end(), {"material", "1", "ie", "mass", "vx"});
      if (g.num_rigid_walls > 0) words.insert(words.end(), {"wall", "1", "fn"});
      if (g.num_interfaces > 0) words.insert(words.end(), {"interface", "1", "fm"});
      try {
        postimpact::extract_history(db, postimpact::parse_history(words, db));
      } catch (const std::invalid_argument&) {
      }
    }
  } catch (const std::runtime_error&) {
    return 0;
  }
  try {
    postimpact::write_summary(postimpact::summarize(root, ""), sink);
  } catch (const std::runtime_error&) {
  }
  postimpact::CompareOptions opt;
  postimpact::compare_databases(root, root, opt, sink);
  return 0;
}

}  // namespace impact3d_fuzz
