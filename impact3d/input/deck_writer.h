#pragma once
// Deck writers: any Model that was read (from either format) written back as an LS-DYNA keyword
// deck or as a DYNA3D fixed-format deck (docs/deck-format.md "Deck format" and "Keyword decks"), so that
// reading the written deck gives the same model.  Real values are written in their shortest
// exact form; a keyword card whose values do not fit its columns is written in comma free
// format, so the keyword deck is always exact.  The fixed format has fixed widths (E10, E20):
// a value that does not fit is rounded and noted.

#include <ostream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/model/model.h"

namespace impact3d {

// notes (optional) receives one line for each thing the target format cannot hold exactly.
void write_keyword_deck(std::ostream& os, const Model& m, std::vector<std::string>* notes = nullptr);
void write_fixed_deck(std::ostream& os, const Model& m, std::vector<std::string>* notes = nullptr);

// Writes path (keyword if keyword, else fixed format); reports 3004 if the file cannot be
// written.  Returns false on failure.
bool write_deck_file(const std::string& path, const Model& m, bool keyword, Diagnostics& diag,
                     std::vector<std::string>* notes = nullptr);

// impact3d --write-keyword=FILE / --write-fixed=FILE: writes the decks that are named (empty =
// not written), one line per deck and per note on log.  Returns an exit code (0, or 4 when a
// file cannot be written).
int write_converted_decks(const Model& m, const std::string& keyword_path, const std::string& fixed_path,
                          std::ostream& log);

// The differences between two models in everything a run depends on (not the deck file name,
// deck line numbers or how the cards were laid out), bitwise for reals; empty = same model.
// At most max_lines lines.
std::vector<std::string> model_differences(const Model& a, const Model& b, int max_lines = 20);

}  // namespace impact3d
