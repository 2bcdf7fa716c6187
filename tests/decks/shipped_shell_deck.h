#pragma once
// A shipped shell benchmark deck (decks/keyword/NAME) with its *SECTION_SHELL ELFORM 2 replaced
// by another shell formulation, read and checked: the Scordelis-Lo roof and pinched-cylinder
// tests run the same deck with ELFORM 2 and 16.

#include <fstream>
#include <sstream>
#include <string>

#include "common/cards.h"
#include "impact3d/input/deck_reader.h"

namespace test_support {

inline bool read_shipped_shell_deck(const std::string& name, int elform, impact3d::Model& m, impact3d::Diagnostics& d) {
  std::ifstream in(std::string(IMPACT3D_SOURCE_DIR) + "/decks/keyword/" + name);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string card = "         1         2 0.8333333         2\n";
  const std::size_t at = text.find(card);
  if (at == std::string::npos) return false;
  text.replace(at, card.size(), "         1" + std::string(elform < 10 ? 9 : 8, ' ') + std::to_string(elform) + " 0.8333333         2\n");
  impact3d::DeckFile deck;
  deck.load_from_string(name, text);
  return impact3d::read_deck(deck, m, d, impact3d::InputOptions{}) && impact3d::check_model(m, d);
}

}  // namespace test_support
