// The tests' one way to read a deck given as text and to run a model in a folder of the build
// tree: what the tests of every folder (keyword, contact, solve, output, decks) share, instead
// of a copy per file.
#pragma once

#include <cstdio>
#include <filesystem>
#include <initializer_list>
#include <sstream>
#include <string>

#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/run.h"

namespace test_support {

// The messages of a read, as the program prints them.
inline std::string messages_of(const impact3d::Diagnostics& d) {
  std::ostringstream os;
  d.print(os);
  return os.str();
}

// A deck read from text: the Model, the messages, and whether the read and the check passed.
struct ReadDeck {
  impact3d::Model m;
  impact3d::Diagnostics d;
  bool ok = false;
  std::string messages() const { return messages_of(d); }
  int count(int id) const { return d.count(id); }
  const impact3d::Diagnostic* first(int id) const {
    for (const auto& x : d.all())
      if (x.id == id) return &x;
    return nullptr;
  }
};

// Reads `text` as the deck `name` (messages name it; the content tells the format) and, when
// that succeeds, checks the model (after orienting the interface segments, as impact3d does,
// when `orient_segments`).
inline ReadDeck read_deck_text(const std::string& text, const std::string& name,
                               const impact3d::InputOptions& options = impact3d::InputOptions{},
                               bool orient_segments = false) {
  ReadDeck r;
  impact3d::DeckFile deck;
  deck.load_from_string(name, text);
  r.ok = impact3d::read_deck(deck, r.m, r.d, options);
  if (r.ok) {
    if (orient_segments) impact3d::orient_interface_segments(r.m, r.d);
    r.ok = impact3d::check_model(r.m, r.d);
  }
  return r;
}

// IMPACT3D_BINARY_DIR/group/name (or /group), emptied (made if missing).
inline std::filesystem::path empty_run_folder(const std::string& group, const std::string& name = "") {
  const std::filesystem::path dir =
      name.empty() ? std::filesystem::path(IMPACT3D_BINARY_DIR) / group : std::filesystem::path(IMPACT3D_BINARY_DIR) / group / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// A quiet run on one thread with its d3hsp, d3plot and d3dump in `dir`.
inline impact3d::RunOptions run_options_in(const std::filesystem::path& dir) {
  impact3d::RunOptions o;
  o.printed = (dir / "d3hsp").string();
  o.plot = (dir / "d3plot").string();
  o.dump = (dir / "d3dump").string();
  o.quiet = true;
  o.threads = 1;
  return o;
}

// A keyword deck's integer field, right-aligned in w columns.
inline std::string I(long v, int w = 10) {
  char b[32];
  std::snprintf(b, sizeof b, "%*ld", w, v);
  return b;
}

// A card: its fields, already formatted, on one line.
inline std::string card(std::initializer_list<std::string> fields) {
  std::string s;
  for (const auto& f : fields) s += f;
  return s + "\n";
}

// A keyword deck's real field in w columns: 6 significant digits in a 10-column field, 12 in a
// wider one.
inline std::string F(double v, int w = 10) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.*g", w, w > 10 ? 12 : 6, v);
  return b;
}

}  // namespace test_support
