// Fuzz harnesses of the deck readers (fixed format and keyword with *INCLUDE).
#include <filesystem>
#include <sstream>
#include <string>

#include "fuzz/harness/fuzz_util.h"
#include "fuzz/harness/targets.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/input/keyword_reader.h"

namespace impact3d_fuzz {

namespace {

// What impact3d does after reading: the cross checks when the arrays are complete (as
// read_and_check_deck), the messages rendered, and the deck writers on a model that read clean.
void after_read(impact3d::Model& model, impact3d::Diagnostics& diag, bool ok) {
  if (model.num_nodes() == model.control.numnp && model.num_hexes() == model.control.numelh &&
      !diag.has(1004) && !diag.has(1013)) {
    impact3d::orient_interface_segments(model, diag);
    ok = impact3d::check_model(model, diag) && ok;
  }
  std::ostringstream os;
  diag.print(os);
  if (ok && diag.error_count() == 0) {
    std::ostringstream kw, fixed;
    impact3d::write_keyword_deck(kw, model);
    impact3d::write_fixed_deck(fixed, model);
  }
}

}  // namespace

int fuzz_fixed_deck(const std::uint8_t* data, std::size_t size) {
  impact3d::DeckFile deck;
  deck.load_from_string("fuzz.dyn", as_text(data, size));
  impact3d::Model model;
  impact3d::Diagnostics diag;
  const bool ok = impact3d::read_dyna3d_deck(deck, model, diag);
  after_read(model, diag, ok);
  return 0;
}

int fuzz_keyword_deck(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  static const fs::path dir = scratch_dir() / "keyword";
  static const bool made = fs::create_directories(dir);
  (void)made;
  const auto parts = split_parts(as_text(data, size), "$$FUZZ-FILE$$\n", 4);
  const fs::path main = dir / "main.k";
  write_file(main, parts[0]);
  for (std::size_t k = 1; k < 4; ++k) {
    const fs::path inc = dir / ("inc" + std::to_string(k) + ".k");
    if (k < parts.size()) {
      write_file(inc, parts[k]);
    } else {
      std::error_code ec;
      fs::remove(inc, ec);
    }
  }
  impact3d::DeckFile deck;
  impact3d::Diagnostics diag;
  if (!deck.load(main.string(), diag)) return 0;
  impact3d::Model model;
  impact3d::KeywordOptions opt;
  opt.lenient = (size % 2) == 1;  // both modes, fixed per input
  const bool ok = impact3d::read_keyword_deck(deck, model, diag, opt);
  after_read(model, diag, ok);
  return 0;
}

}  // namespace impact3d_fuzz
