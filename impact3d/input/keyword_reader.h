#pragma once
// LS-DYNA keyword-deck reader: *KEYWORD decks (fixed 10-column fields, comma free format,
// long and I10 formats, *INCLUDE) read into the same Model as the DYNA3D fixed-format reader.
// The supported keywords and the mapping onto the Model are listed in README.md ("Keyword
// decks").  Every other keyword is an error (1301) listing each one with its file and line, or a
// warning (2007) with KeywordOptions::lenient.

#include <string>

#include "common/cards.h"
#include "common/messages.h"
#include "impact3d/model/model.h"

namespace impact3d {

struct KeywordOptions {
  bool lenient = false;  // unsupported keywords are warnings (2007) instead of errors (1301)
  int case_id = 0;       // *CASE: the case to read (0: the base case, every case block left out)
};

// True if the deck is an LS-DYNA keyword deck: its first line that is neither blank nor a '$'
// comment starts with *KEYWORD, or any line starts with '*' followed by a letter.  DYNA3D
// fixed-format decks only have '*' comment lines followed by a blank, '-', '*' or '='.
bool is_keyword_deck(const DeckFile& deck);

// Reads a keyword deck into model (nodes and solids renumbered 1..N in increasing id order;
// the deck ids are kept in model.node_user_id / hex_user_id when they are not 1..N already).
// *INCLUDE files are looked up relative to the including file, then the main deck, then the
// working directory.  Returns false if any error was reported.
bool read_keyword_deck(DeckFile& deck, Model& model, Diagnostics& diag,
                       const KeywordOptions& options = {});

}  // namespace impact3d
