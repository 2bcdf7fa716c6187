#pragma once
// Helpers shared by the input-phase tests: reading a deck held in a string, finding messages.

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "common/cards.h"
#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/model/model.h"

namespace impact3d::testing {

inline std::string source_path(const std::string& rel) {
  return std::string(IMPACT3D_SOURCE_DIR) + "/" + rel;
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The tiny valid deck of the malformed corpus (12 nodes, 2 hexahedra, 1 material, 1 wall,
// 1 initial-velocity card).
inline std::string tiny_deck() { return read_text(source_path("tests/input/malformed/tiny.dyn")); }

// Reads a deck from a string as read_and_check_deck does from a file.
inline bool read_string(const std::string& text, Model& m, Diagnostics& d,
                        const std::string& name = "test.dyn") {
  DeckFile deck;
  deck.load_from_string(name, text);
  bool ok = read_dyna3d_deck(deck, m, d);
  if (m.num_nodes() == m.control.numnp && m.num_hexes() == m.control.numelh && !d.has(1004) &&
      !d.has(1013))
    ok = check_model(m, d) && ok;
  return ok && d.error_count() == 0;
}

// Reads deck text of either format (chosen by content, as read_and_check_deck does) and checks
// the model; true when there is no error.
inline bool read_any(const std::string& text, Model& m, Diagnostics& d, const std::string& name) {
  DeckFile deck;
  deck.load_from_string(name, text);
  return read_deck(deck, m, d, InputOptions{}) && check_model(m, d) && d.error_count() == 0;
}

inline std::string all_messages(const Diagnostics& d) {
  std::string s;
  for (const auto& x : d.all()) s += render(x) + "\n";
  return s;
}

// Right-justified integer / real (%.4e) of the given width, for writing cards.
inline std::string I(long long v, int w) {
  std::string s = std::to_string(v);
  return std::string(s.size() < std::size_t(w) ? std::size_t(w) - s.size() : 0, ' ') + s;
}
inline std::string E(double v, int w = 10, int prec = 4) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%*.*e", w, prec, v);
  return buf;
}

}  // namespace impact3d::testing
