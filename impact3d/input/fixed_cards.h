#pragma once
// The DYNA3D fixed-format cards as data: each card is a table of fields (name, columns, kind,
// blank value, meaning, and the feature a nonzero value would ask for where IMPACT-3D refuses
// it), per vintage of the layout.  The reader (dyna3d_reader.cpp), the converter
// (deck_writer.cpp) and the README's card tables (impact3d --card-tables) all come from these
// tables, so a card's columns are written down once.
//
// Two vintages, told apart from the deck itself (control card 4, see detect_fixed_vintage):
//  - dyna3d_88: DYNA3D 88 as LLNL's INGRID wrote it: control card 4 opens with the DYNA3D-JOY
//    node count (I5) before the sliding boundary planes (I5), and the coordinate format ends it;
//  - dyna3d_later: the later layout (TrueGrid 2.2 and later, and IMPACT-3D's own writer): control
//    card 4 opens with the sliding boundary planes (I10), and control cards 2, 3, 9 carry more
//    fields (columns blank in 88 decks read as their blank values).
// The layouts were learned from real LLNL decks (docs/dyna3d-decks.md); where a field's meaning
// is not known from them, its name says so and a nonzero value is refused or ignored as the
// table states.

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "common/cards.h"

namespace impact3d {

enum class FixedVintage { dyna3d_88, dyna3d_later };
const char* vintage_name(FixedVintage v);

// integer: an integer, or a real with an integral value ("7.", as INGRID writes codes and counts);
// strict_integer: an integer only (ids and labels: "7." is refused, 1001).
enum class FieldKind { integer, real, text, strict_integer };
inline bool is_integer(FieldKind k) { return k == FieldKind::integer || k == FieldKind::strict_integer; }

// What a nonzero value of a field does.
enum class FieldUse {
  read,      // read; the reader gives it meaning
  ignored,   // read and checked; changes nothing here (listed once as ignored when nonzero)
  refused,   // nonzero: error 1102 naming `feature`
};

struct FixedField {
  const char* name;     // the name in messages and in the README
  int c1, c2;           // columns (1-based, inclusive)
  FieldKind kind;
  double blank;         // the value of a blank field
  FieldUse use;
  const char* feature;  // refused: the feature named in 1102; ignored: what it would do
  const char* meaning;  // one line for the README
};

struct FixedCardLayout {
  const char* id;        // "control card 2", "pressure card", ...
  const char* vintages;  // "88 later" (both), "88", "later"
  std::vector<FixedField> fields;
  const FixedField& field(std::string_view name) const;  // every name a reader asks for exists
};

// The layout of a card in a vintage (a logic_error if the table has none: a programming error).
const FixedCardLayout& fixed_card_layout(std::string_view id, FixedVintage v);
// Every layout, in deck order, for the README tables.
const std::vector<FixedCardLayout>& all_fixed_card_layouts();
// The README's card tables, in Markdown (impact3d --card-tables prints them).
std::string fixed_card_tables_markdown();

// Control card 4: columns 1-5 hold the DYNA3D-JOY node count (88 vintage) or are the high
// digits of the I10 sliding-plane count (later vintage, blank in every real deck).
FixedVintage detect_fixed_vintage(std::string_view control_card_4);

// The values of one card read by its table: every field read (1001/1002 for bad text), blank
// fields take their blank value, refused fields with a nonzero value give 1102 naming the
// feature, ignored ones are collected for the reader's one listing.
class FixedValues {
 public:
  // name_by_first: the card's name once its first field (its own number) is read ("node card for
  // node 417"), so that the messages about the other fields name it.
  using NameByFirst = std::function<std::string(long long)>;
  FixedValues(Card& card, const FixedCardLayout& layout, const NameByFirst& name_by_first = {});
  double operator[](std::string_view name) const;
  long long integer(std::string_view name) const { return static_cast<long long>((*this)[name]); }
  const std::string& text(std::string_view name) const;
  bool blank(std::string_view name) const;
  // An error about one field, with its columns from the table.
  void error(int id, std::string_view name, std::string detail = {}) const;
  // A 0/1 field: whether it is 1; another value is message 1006 with `choices` as its detail.
  bool flag01(std::string_view name, std::string choices) const;
  Location where(std::string_view name) const;
  const FixedField& field(std::string_view name) const { return layout_.field(name); }
  // Fields with FieldUse::ignored that hold a nonzero value ("name (cols a-b)").
  const std::vector<std::string>& ignored() const { return ignored_; }
  Card& card() const { return card_; }

 private:
  std::size_t index(std::string_view name) const;
  void read_field(std::size_t k);
  bool integral_real(const FixedField& f, double& v) const;
  Card& card_;
  const FixedCardLayout& layout_;
  std::vector<double> values_;
  std::vector<std::string> texts_;
  std::vector<char> blank_;
  std::vector<std::string> ignored_;
};

}  // namespace impact3d
