#pragma once
// The input phase ("starter"): read a deck into a Model and check it, reporting every error in
// one pass through the message catalog.

#include <string>

#include "common/cards.h"
#include "common/messages.h"
#include "impact3d/model/model.h"

namespace impact3d {

// Reads a DYNA3D fixed-format deck (title card, control cards 2-9, materials, nodes, solids,
// time-history blocks, load curves, stonewalls, initial velocities, sliding interfaces).
// Field-level checks are done while reading; returns false if any error was reported.
bool read_dyna3d_deck(DeckFile& deck, Model& model, Diagnostics& diag);

// Cross-reference and geometry checks on a model that read without errors: element volumes,
// interface segments on element faces, unused materials and nodes.  Returns false on error.
bool check_model(const Model& model, Diagnostics& diag);

// Sliding-interface segments on the exterior face of one solid take that face's outward
// orientation: a segment given clockwise (seen from outside) is reversed, warning 2013; one
// whose nodes do not go around the face in order (criss-crossed) is error 1225.  Segments that
// are not element faces are left to check_model (1218).  read_and_check_deck calls it.
void orient_interface_segments(Model& model, Diagnostics& diag);

// Reads and checks a deck file: load + read + check.  Returns false on any error.
bool read_and_check_deck(const std::string& path, Model& model, Diagnostics& diag);

// Input options (command line).
struct InputOptions {
  bool lenient_keywords = false;  // unsupported LS-DYNA keywords are warnings, not errors
  int case_id = 0;                // keyword decks: the *CASE to read (0: the base case)
};
bool read_and_check_deck(const std::string& path, Model& model, Diagnostics& diag,
                         const InputOptions& options);

// Reads a loaded deck with the reader its content calls for: an LS-DYNA keyword deck
// (is_keyword_deck in keyword_reader.h) or a DYNA3D fixed-format deck.  No model checks.
bool read_deck(DeckFile& deck, Model& model, Diagnostics& diag, const InputOptions& options = {});

}  // namespace impact3d
