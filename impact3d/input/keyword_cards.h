#pragma once
// LS-DYNA keyword cards as data: each keyword the schema-driven families read is an entry of
// its cards, and each card a table of fields (name, position, kind, blank value, what a 0
// means, the checks on the value and the message each gives), in the same form as the
// DYNA3D fixed-format card tables (fixed_cards.h).  The reader (KeywordValues in
// keyword_blocks.h) and docs/keyword-tables.md (impact3d --keyword-tables) both come from these
// tables, so a field's position, default and checks are written down once.
//
// Columns: a card of `count` fields of `width` columns (LS-DYNA's 8 fields of 10; 20 columns
// each in long format, "+" after the keyword or *KEYWORD LONG=Y), or the fields at its commas
// (free format) when the line has one.

#include <string>
#include <string_view>
#include <vector>

#include "impact3d/input/fixed_cards.h"

namespace impact3d {

// A check on a field's value (blank and 0 already replaced as the field says): when it holds,
// message `id` names the field, with `detail` ("%v" in it: the value, as an integer); id 0:
// the value is accepted (the checks after it are not tried).
struct KeywordCheck {
  enum Test {
    outside,   // v not in the interval [lo, hi] (lo_open / hi_open: that end excluded)
    inside,    // v in [lo, hi] (a refused range of values)
    neither,   // v is neither lo nor hi
    not_whole, // v is not a whole number in [lo, hi]
  };
  Test test;
  double lo, hi;
  bool lo_open, hi_open;
  int id;
  const char* detail;  // nullptr: the message's text alone
  bool fires(double v) const;
  std::string text() const;  // "< 0", "not in (0, 1]", "6 to 10", ... (for the tables)
};

struct KeywordField {
  const char* name;    // LS-DYNA's field name (in messages and tables)
  int index;           // position on the card, 0-based (columns 1 + index * width ...)
  FieldKind kind;      // integer (an integral real such as "1." also reads) or real
  double blank;        // the value of a blank field
  bool zero_is_blank;  // 0 stands for the blank value (LS-DYNA's "0: default")
  std::vector<KeywordCheck> checks;  // the first that holds gives its message
  const char* meaning;               // one line for the tables
  int checked_after = -1;            // the checks run once the field at this position is read
                                     // (-1: this field; the card's CheckOrder; kByReader: when
                                     // the family's reader asks, KeywordValues::check)
};
// KeywordField::checked_after: the checks run where the family's reader says (e.g. an element
// id once its node card is read too).
constexpr int kByReader = -2;

// When the checks of a card run: each right after its field is read, or all after every
// field of the card is read (as the reader has always reported them: the message order).
enum class CheckOrder { per_field, after_card };

struct KeywordCardLayout {
  const char* card;   // "card 1", ... as messages name it after the keyword ("" none)
  int count;          // fields on the card in fixed columns
  int width;          // columns of a field in standard format (20 in long format)
  CheckOrder order;
  std::vector<KeywordField> fields;
  const char* when;   // when the card is read ("" always; else e.g. "when given", "ELFORM 2")
  std::vector<int> widths = {};  // columns of each field in standard format when they differ
                                 // (*NODE: 8 16 16 16 8 8); empty: `count` fields of `width`
  bool fixed = false;  // the same columns in long and I10 format (a heading card: *TITLE, the
                       // _ID cards of *DATABASE_HISTORY_...)
  bool words = false;  // the fields are words separated by blanks, not columns (the *KEYWORD
                       // line's options, *CASE's cards); `count` and `width` unused
  const KeywordField& field(std::string_view name) const;  // every name a reader asks for exists
  // The columns of each field: standard format, I10 format (a field of 8 columns has 10: the
  // ids of *NODE and *ELEMENT_...) or long format (20 each).
  std::vector<int> columns(bool long_fmt, bool i10) const;
  // The position after whose reading the checks of field f run.
  int check_point(const KeywordField& f) const;
};

// The families of keywords (one reader file each, keyword_<family>.cpp).
enum class KeywordFamily {
  deck,              // *KEYWORD, *INCLUDE..., *PARAMETER..., *CASE: read in the reader's first pass, before
                     // any family and with no *PARAMETER reference replaced (keyword_include.cpp,
                     // keyword_parameters.cpp, keyword_cases.cpp)
  nodes_elements,    // *NODE, *ELEMENT_SOLID / _SHELL / _BEAM (keyword_nodes_elements.cpp)
  materials,         // *MAT_..., *EOS_..., *MAT_ADD_EROSION (keyword_materials.cpp; the cards from the material and EOS tables)
  parts_sections,    // *PART, *SECTION_..., *HOURGLASS (keyword_parts_sections.cpp)
  sets_boxes,        // *DEFINE_BOX (keyword_sets_boxes.cpp)
  loads_bcs,         // *LOAD_..., *BOUNDARY_..., *INITIAL_..., *DAMPING_GLOBAL (keyword_loads_bcs.cpp)
  contacts,          // *CONTACT_... (keyword_contacts.cpp)
  control_database,  // *CONTROL_..., *DATABASE_..., *TITLE, *COMMENT (keyword_control_database.cpp)
  ignored,           // read and ignored, warning 2008 with the note (keyword_control_database.cpp)
};

struct KeywordSpec {
  std::vector<const char*> names;  // upper case, without '*' (several: the same cards)
  KeywordFamily family;
  bool once;                       // given again: warning 2010, the last one is used
  std::vector<KeywordCardLayout> cards;
  const char* note;                // one line for the page ("" none)
  const KeywordCardLayout& card(std::string_view label, std::string_view when = {}) const;
};

// The entry of a keyword (upper case, options stripped), or nullptr if no table has it.
const KeywordSpec* find_keyword_spec(std::string_view name);
const std::vector<KeywordSpec>& all_keyword_specs();
// docs/keyword-tables.md, in Markdown (impact3d --keyword-tables prints it).
std::string keyword_tables_markdown();

}  // namespace impact3d
