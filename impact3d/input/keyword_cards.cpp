// The keyword card tables (keyword_cards.h).  One entry a keyword (or keywords with the same
// cards); the position, blank value and checks of a field are written here and nowhere else.

#include "impact3d/input/keyword_cards.h"

#include <cmath>
#include <deque>
#include <iterator>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>
#include <stdexcept>

#include "common/messages.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr FieldKind I = FieldKind::integer;
constexpr FieldKind E = FieldKind::real;
constexpr CheckOrder per_field = CheckOrder::per_field;
constexpr CheckOrder after_card = CheckOrder::after_card;

// v < a
KeywordCheck below(double a, int id, const char* detail = nullptr) {
  return {KeywordCheck::outside, a, kInf, false, false, id, detail};
}
// v outside [lo, hi], an end excluded where open
KeywordCheck outside(double lo, double hi, int id, const char* detail = nullptr, bool lo_open = false, bool hi_open = false) {
  return {KeywordCheck::outside, lo, hi, lo_open, hi_open, id, detail};
}
// v in [lo, hi]
KeywordCheck inside(double lo, double hi, int id, const char* detail) { return {KeywordCheck::inside, lo, hi, false, false, id, detail}; }
KeywordCheck nonzero(int id, const char* detail) { return outside(0, 0, id, detail); }
// v not a whole number in [lo, hi]
KeywordCheck not_whole(double lo, double hi, int id, const char* detail) { return {KeywordCheck::not_whole, lo, hi, false, false, id, detail}; }
// checked once the field at `point` is read (instead of right after this one)
KeywordField checked_after(KeywordField f, int point) {
  f.checked_after = point;
  return f;
}
KeywordCheck neither(double a, double b, int id, const char* detail) { return {KeywordCheck::neither, a, b, false, false, id, detail}; }

// A field read and given no check: its value is only checked to be a number.
KeywordField plain(const char* name, int index, FieldKind kind, const char* meaning = "read, no effect here") {
  return {name, index, kind, 0, false, {}, meaning};
}

// *DATABASE_BINARY_D3PLOT and the like: DT, and LCDT refused.
KeywordSpec binary_database(const char* name, const char* lcdt_feature, const char* dt_meaning) {
  return {{name}, KeywordFamily::control_database, true,
          {{"card 1", 5, 10, per_field, {
              {"DT", 0, E, 0, false, {below(0, 1221)}, dt_meaning},
              {"LCDT", 1, I, 0, false, {nonzero(1102, lcdt_feature)}, "interval from a load curve"},
          }, ""}},
          ""};
}

// Keywords read and ignored (warning 2008, with the reason): they change nothing in
// IMPACT-3D's physics or output.  A name ending in '*' is a prefix.
KeywordSpec ignored(const char* name, const char* why, std::vector<KeywordCardLayout> cards = {}) {
  return {{name}, KeywordFamily::ignored, false, std::move(cards), why};
}

// *SECTION_SHELL and *SECTION_BEAM SHRF: 0 and blank are 1.
KeywordField shear_factor(const char* detail) {
  return {"SHRF", 2, E, 1.0, true, {outside(0, 1, 1003, detail, true)}, "shear factor"};
}

// An id read by the family's reader and checked where it says (after the element's other
// cards): below 1 is error 1201.
KeywordField positive_id(const char* name, const char* detail, const char* meaning) {
  return {name, 0, I, 0, false, {below(1, 1201, detail)}, meaning, kByReader};
}
// Fields of a card with no check but its numbers: node ids N<first>..N<last> at index0...
std::vector<KeywordField> node_fields(int first, int last, int index0, std::vector<KeywordCheck> checks = {},
                                      const char* meaning = "node") {
  static const char* const names[] = {"N1", "N2", "N3", "N4", "N5", "N6", "N7", "N8", "N9", "N10"};
  std::vector<KeywordField> f;
  for (int n = first; n <= last; ++n) f.push_back({names[n - 1], index0 + n - first, I, 0, false, checks, meaning});
  return f;
}
template <class... More>
std::vector<KeywordField> fields_of(std::vector<KeywordField> a, const More&... more) {
  (a.insert(a.end(), more.begin(), more.end()), ...);
  return a;
}

// The keywords that shape the deck itself (keyword_include.cpp, keyword_parameters.cpp,
// keyword_cases.cpp): read in the reader's first pass, before any family, and with no
// *PARAMETER reference replaced in their cards.
KeywordField file_name(const char* meaning) { return {"FILENAME", 0, FieldKind::text, 0, false, {}, meaning}; }
constexpr const char* kFileLookup =
    "the line, right blanks dropped (any length); looked up next to the including file, next to the main deck, in the working directory, then in the *INCLUDE_PATH directories "
    "(not found: error 1306; more than 20 levels, or a file that includes itself: error 1307); a name ending in \" +\" continues on the next line";
std::vector<KeywordSpec> deck_specs() {
  const KeywordFamily F = KeywordFamily::deck;
  constexpr FieldKind A = FieldKind::text;
  std::vector<KeywordSpec> t;
  t.push_back({{"KEYWORD"}, F, false,
               {{"options", 6, 0, per_field, {
                   {"LONG", 0, A, 0, false, {}, "LONG=Y: every keyword in long format (fields of 20 columns); LONG=S or LONG=N: standard format"},
                   {"I10", 1, A, 0, false, {}, "I10=Y: I10 format (the 8-column ids have 10); I10=N: not"},
                   {"NCPU", 2, I, 0, false, {}, "NCPU=n: the thread count when the command line has no ncpu= (1 <= abs(n) <= 1024; "
                                                "negative, LS-DYNA's consistent mode: the same, IMPACT-3D's results never depend on the thread count)"},
                   {"MEMORY", 3, A, 0, false, {}, "MEMORY=...: warning 2008 (memory is allocated as the model needs it)"},
                   {"MEMORY2", 4, A, 0, false, {}, "MEMORY2=...: warning 2008, as MEMORY"},
                   {"size", 5, A, 0, false, {}, "a memory size (digits, M): ignored"},
               }, "on the *KEYWORD line after the keyword, in any order; any other word: error 1312", {}, false, true}},
               "the first line of the deck (after blank and $ lines; else warning 2009); LONG= and I10= hold for the keywords after it "
               "that have no format suffix of their own (+ long, - standard, % I10)"});
  t.push_back({{"INCLUDE"}, F, false,
               {{"file card", 1, 80, per_field, {file_name(kFileLookup)}, "each card: one file, read in place of the card", {}, true}},
               "the file's keywords are read as if they stood here; $ lines and blank cards between the names are skipped"});
  t.push_back({{"INCLUDE_PATH", "INCLUDE_PATH_RELATIVE"}, F, false,
               {{"directory card", 1, 80, per_field, {{"PATH", 0, A, 0, false, {}, "a directory searched for *INCLUDE files after the including "
                                                        "file's; relative: to the main deck's directory (and, without _RELATIVE, to the working directory too)"}},
                 "each card: one directory", {}, true}},
               ""});
  t.push_back({{"INCLUDE_TRANSFORM"}, F, false,
               {{"card 1", 1, 80, per_field, {file_name(kFileLookup)}, "the first card that is not blank; missing: error 1316", {}, true},
                {"card 2", 8, 10, after_card, {
                   {"IDNOFF", 0, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "added to every node id the file's cards define or name (0 stays 0)"},
                   {"IDEOFF", 1, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "element ids"},
                   {"IDPOFF", 2, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "part ids"},
                   {"IDMOFF", 3, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "material ids"},
                   {"IDSOFF", 4, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "set ids"},
                   {"IDFOFF", 5, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "curve ids"},
                   {"IDDOFF", 6, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "box, coordinate system and vector ids"},
               }, "when given"},
                {"card 3", 8, 10, per_field, {
                   {"IDROFF", 0, I, 0, false, {below(0, 1003, "id offsets must not be negative")}, "section, hourglass and EOS ids"},
               }, "when given"},
                {"card 4", 8, 10, per_field, {
                   {"FCTMAS", 0, E, 1, false, {neither(0, 1, 1102, "unit conversion of the included data (mass)")}, "mass unit factor", kByReader},
                   {"FCTTIM", 1, E, 1, false, {neither(0, 1, 1102, "unit conversion of the included data (time)")}, "time unit factor", kByReader},
                   {"FCTLEN", 2, E, 1, true, {outside(0, kInf, 1003, "must be positive", true)},
                    "length unit factor: the coordinates are scaled (materials and curves in the file with FCTLEN other than 1: error 1102); "
                    "checked after FCTTEM", kByReader},
                   {"FCTTEM", 3, E, 1, false, {neither(0, 1, 1102, "unit conversion of the included data (temperature)")}, "temperature unit factor", kByReader},
                   plain("INCOUT1", 4, I),
               }, "when given"},
                {"card 5", 8, 10, per_field, {
                   {"TRANID", 0, I, 0, false, {}, "*DEFINE_TRANSFORMATION applied after FCTLEN (0: none; not defined: error 1310); initial velocities in a "
                                                  "moved file, a box in a turned one: error 1102"},
               }, "when given"}},
               "the file is read as an *INCLUDE (files it includes inherit the transform); its records get the offsets and their coordinates the "
               "map once the deck is read"});
  t.push_back({{"PARAMETER"}, F, false,
               {{"", 8, 10, per_field, {
                   {"PRMR", 0, A, 0, false, {}, "R (real), I (integer) or C (text), then the name (else error 1006; defined twice, here or by "
                                                "*PARAMETER_EXPRESSION: error 1200); blank: no parameter"},
                   {"VAL", 1, E, 0, false, {}, "the value, read as PRMR's letter says: I an integer, R a real, C text as written"},
                   {"PRMR", 2, A, 0, false, {}, ""}, {"VAL", 3, E, 0, false, {}, ""},
                   {"PRMR", 4, A, 0, false, {}, ""}, {"VAL", 5, E, 0, false, {}, ""},
                   {"PRMR", 6, A, 0, false, {}, ""}, {"VAL", 7, E, 0, false, {}, ""},
               }, "each card; blank cards skipped"}},
               "read before every other keyword: &name or -&name in a numeric field of any other keyword takes the value, wherever it is "
               "defined (names case-insensitive; not defined, or text: error 1310)"});
  t.push_back({{"PARAMETER_EXPRESSION"}, F, false,
               {{"", 2, 10, per_field, {
                   {"PRMR", 0, A, 0, false, {}, "R or I, then the name (else error 1006; defined twice: error 1200); a comma within these columns: "
                                                "PRMR up to it, the expression after it"},
                   {"EXPRESSION", 1, A, 0, false, {}, "the rest of the line after PRMR, any length (blank: error 1317); errors name the column of the "
                                                      "offending character: error 1317, an undefined or text parameter 1310"},
               }, "each card; blank cards skipped", {10, 70}}},
               "one parameter a card, evaluated after the *PARAMETER values in any order (docs/keyword-decks.md); an I parameter takes the value "
               "truncated toward zero"});
  t.push_back({{"CASE"}, F, false,
               {{"card 1", 2, 0, per_field, {
                   {"CASEID", 0, I, 0, false, {}, "the first word: the case id (not a positive integer: error 1001; defined twice: error 1200)"},
                   {"JOBID", 1, A, 0, false, {}, "the second word: the job name (case=CASEID's output name; blank: caseCASEID)"},
               }, "the first card that is not blank; missing: error 1316", {}, false, true},
                {"command card", 1, 0, per_field, {
                   {"COMMANDS", 0, A, 0, false, {}, "command-line options for the case: warning 2006 when it runs (give them on impact3d's command line)"},
               }, "each later card with a word that is not an integer", {}, false, true},
                {"child case card", 1, 0, per_field, {
                   {"SCID", 0, I, 0, false, {}, "child case ids, any number on a card (0: none)"},
               }, "each later card of integers only", {}, false, true}},
               "a master case (impact3d case=CASEID runs the main model and these children); keywords between *CASE_BEGIN_n and *CASE_END_n, or "
               "with CID=n on their line, belong to child case n (docs/keyword-decks.md)"});
  return t;
}

// *NODE and *ELEMENT_...: the bulk of a deck.  Their ids are 8 columns (10 in I10 format, 20 in
// long format); a card that is plain and passes every check is read by a fast path with the
// same columns (keyword_nodes_elements.cpp).
std::vector<KeywordSpec> nodes_elements_specs() {
  const KeywordFamily F = KeywordFamily::nodes_elements;
  const char* const eid = "element id (the card is then named \"element EID\" in messages); < 1: error 1201 once the element's cards are read";
  std::vector<KeywordSpec> t;
  t.push_back({{"NODE"}, F, false,
               {{"", 6, 16, after_card, {
                   {"NID", 0, I, 0, false, {below(1, 1201, "node ids must be positive")},
                    "node id (the card is then named \"node NID\" in messages); < 1: error 1201 and the card's other checks are not made", kByReader},
                   {"X", 1, E, 0, false, {}, "coordinates"},
                   {"Y", 2, E, 0, false, {}, ""},
                   {"Z", 3, E, 0, false, {}, ""},
                   {"TC", 4, I, 0, false, {outside(0, 7, 1216)}, "translational constraint 0-7 (as a DYNA3D boundary code; out of range: none)", kByReader},
                   {"RC", 5, I, 0, false, {outside(0, 7, 1216)}, "rotational constraint 0-7 (shell and beam nodes)", kByReader},
               }, "one card a node; blank cards skipped", {8, 16, 16, 16, 8, 8}}},
               "I10 format: NID, TC and RC have 10 columns"});
  t.push_back({{"ELEMENT_SOLID"}, F, false,
               {{"", 10, 8, per_field, fields_of(std::vector<KeywordField>{
                   positive_id("EID", "element ids must be positive", eid),
                   {"PID", 1, I, 0, false, {}, "part"}}, node_fields(1, 8, 2)),
                 "one-line form"},
                {"", 2, 8, per_field, {
                   positive_id("EID", "element ids must be positive", eid),
                   {"PID", 1, I, 0, false, {}, "part"},
                 }, "two-line form"},
                {"node card", 10, 8, per_field, fields_of(node_fields(1, 8, 0),
                   node_fields(9, 10, 8, {}, "10-node tetrahedra: error 1102 once for all of them (the first named)")),
                 "two-line form, named \"element EID node card\"; missing: error 1316"}},
               "one card an element when the first card is longer than two ids (comma format: two commas or more), else "
               "EID PID and the node card; N5-N8 blank after N4 (a tetrahedron written with 4 nodes): N4 repeated"});
  t.push_back({{"ELEMENT_SHELL", "ELEMENT_SHELL_THICKNESS"}, F, false,
               {{"", 10, 8, per_field, fields_of(std::vector<KeywordField>{
                   positive_id("EID", "element ids must be positive", eid),
                   {"PID", 1, I, 0, false, {}, "part"}}, node_fields(1, 4, 2, {}, "node (N4 0: N3, a triangle)"),
                   node_fields(5, 8, 6, {nonzero(1102, "8-node shells")}, "8-node shells")),
                 ""},
                {"thickness card", 5, 16, per_field, {
                   {"THIC1", 0, E, 0, false, {below(0, 1241)}, "thickness at node 1 (0: the section's)"},
                   {"THIC2", 1, E, 0, false, {below(0, 1241)}, "at node 2"},
                   {"THIC3", 2, E, 0, false, {below(0, 1241)}, "at node 3"},
                   {"THIC4", 3, E, 0, false, {below(0, 1241)}, "at node 4"},
                   {"BETA", 4, E, 0, false, {nonzero(1102, "material angles (orthotropic materials)")}, "material angle"},
                 }, "_THICKNESS, named \"element EID thickness card\"; missing: error 1316"}},
               "an element with a refused field is left out"});
  t.push_back({{"ELEMENT_BEAM", "ELEMENT_BEAM_THICKNESS", "ELEMENT_BEAM_ORIENTATION", "ELEMENT_BEAM_THICKNESS_ORIENTATION"}, F, false,
               {{"", 10, 8, per_field, fields_of(std::vector<KeywordField>{
                   positive_id("EID", "element ids must be positive", eid),
                   {"PID", 1, I, 0, false, {}, "part"}}, node_fields(1, 2, 2),
                   std::vector<KeywordField>{
                   {"N3", 4, I, 0, false, {}, "orientation node (0: none)"},
                   {"RT1", 5, I, 0, false, {nonzero(1102, "beam end releases")}, "end releases"},
                   {"RR1", 6, I, 0, false, {nonzero(1102, "beam end releases")}, ""},
                   {"RT2", 7, I, 0, false, {nonzero(1102, "beam end releases")}, ""},
                   {"RR2", 8, I, 0, false, {nonzero(1102, "beam end releases")}, ""},
                   {"LOCAL", 9, I, 0, false, {outside(0, 2, 1003, "1 global, 2 local (0: 2)")}, "release coordinates"}}),
                 ""},
                {"thickness card", 5, 16, per_field, {
                   {"PARM1", 0, E, 0, false, {below(0, 1251)}, "TS1 of this element (0: the section's)"},
                   {"PARM2", 1, E, 0, false, {below(0, 1251)}, "TS2"},
                   {"PARM3", 2, E, 0, false, {below(0, 1251)}, "TT1"},
                   {"PARM4", 3, E, 0, false, {below(0, 1251)}, "TT2"},
                   plain("PARM5", 4, E),
                 }, "_THICKNESS, named \"element EID thickness card\"; missing: error 1316"},
                {"orientation card", 3, 16, per_field, {
                   {"VX", 0, E, 0, false, {}, "orientation vector from N1 (N3 0), x"},
                   {"VY", 1, E, 0, false, {}, "y"},
                   {"VZ", 2, E, 0, false, {}, "z"},
                 }, "_ORIENTATION (after the thickness card), named \"element EID orientation card\"; missing: error 1316"}},
               "an element with a refused field is left out"});
  return t;
}

// The labels of a keyword's cards in messages and tables ("card 1", ...).
const char* card_label(std::size_t k) {
  static const char* const labels[] = {"card 1", "card 2", "card 3", "card 4", "card 5", "card 6", "card 7", "card 8",
                                       "card 9", "card 10", "card 11", "card 12", "card 13", "card 14", "card 15", "card 16"};
  if (k >= std::size(labels)) throw std::logic_error("keyword card table: more than 16 cards");
  return labels[k];
}

// A material parameter's check (material_types.h ParamCheck) as the tables write it; it is
// made by the material table once every card is read (check_material_params, the fixed
// format's too), so the field is checked where its reader says.
std::vector<KeywordCheck> param_checks(const MaterialParam& p) {
  const char* d = p.detail && p.detail[0] ? p.detail : nullptr;
  switch (p.check) {
    case ParamCheck::none: return {};
    case ParamCheck::positive: return {outside(0, kInf, p.msg, d, true)};
    case ParamCheck::non_negative: return {below(0, p.msg, d)};
    case ParamCheck::fraction: return {outside(0, 1, p.msg, d)};
    case ParamCheck::poisson: return {outside(0, 0.5, p.msg, d, false, true)};
    case ParamCheck::below_E: return {below(0, p.msg, d)};  // and below E (the meaning says)
    case ParamCheck::flag01: return {neither(0, 1, p.msg, d)};
    case ParamCheck::integer:
    case ParamCheck::curve: return {not_whole(0, 999999999, p.msg, d)};
    case ParamCheck::unsupported: return {nonzero(1102, d)};
    case ParamCheck::ignored: return {nonzero(2006, d)};
  }
  return {};
}

// *MAT_...: the cards of each type of the material table (material_types.h): card 1 MID RO
// and the type's parameters, by card in the table's order.
KeywordSpec material_spec(const MaterialType& t) {
  static std::deque<std::string> texts;  // meanings and notes built here (the tables keep pointers)
  KeywordSpec s{t.keywords, KeywordFamily::materials, false, {}, ""};
  for (int k = 0; k < t.keyword_cards; ++k) s.cards.push_back({card_label(std::size_t(k)), 8, 10, per_field, {}, k ? "when given" : ""});
  s.cards[0].fields.push_back({"MID", 0, I, 0, false, {}, "material id (the cards are then named \"material MID\"; defined twice: error 1200)"});
  s.cards[0].fields.push_back({"RO", 1, E, 0, false, {outside(0, kInf, 1207, nullptr, true)}, "mass density"});
  for (const MaterialParam& p : t.params) {
    if (p.kcard < 0 || p.kcard >= t.keyword_cards) continue;
    const char* meaning = p.label ? p.label : p.field == &MaterialData::E ? "Young's modulus" : p.field == &MaterialData::nu ? "Poisson's ratio"
                                            : p.fname ? p.fname : "";
    if (p.check == ParamCheck::below_E) meaning = texts.emplace_back(std::string(meaning) + " (must be below E)").c_str();
    if (p.check == ParamCheck::curve) meaning = texts.emplace_back(std::string(meaning[0] ? meaning : "load curve") + " (0: none)").c_str();
    s.cards[std::size_t(p.kcard)].fields.push_back({p.key, p.kfield, E, p.def, false, param_checks(p), meaning, kByReader});
  }
  std::string note = std::string("type ") + std::to_string(t.number) + ", " + t.name +
                     "; the parameters are checked once the cards are read (the material table's checks, those of the fixed format too)";
  if (t.extra_card_feature) note += std::string("; a card after these: error 1102 (") + t.extra_card_feature + ")";
  s.note = texts.emplace_back(note).c_str();
  return s;
}

// *EOS_...: the cards of each form of the EOS table (material/eos.h).
KeywordSpec eos_spec(const EosForm& f) {
  static std::deque<std::string> texts;
  KeywordSpec s{{f.keyword}, KeywordFamily::materials, false, {}, ""};
  for (std::size_t k = 0; k < f.widths.size(); ++k)
    s.cards.push_back({card_label(k), eos_card_fields(f, int(k)), f.widths[k], per_field, {}, k ? "when given" : ""});
  s.cards[0].fields.push_back({"EOSID", 0, I, 0, false, {}, "equation of state id (the cards are then named by it; defined twice: error 1200)"});
  for (const EosParam& p : f.params) {
    if (std::size_t(p.kcard) >= s.cards.size()) continue;
    if (p.slot < 0) s.cards[std::size_t(p.kcard)].fields.push_back({p.key, p.kfield, E, 0, false, {nonzero(1102, p.unsupported)}, "not supported"});
    else s.cards[std::size_t(p.kcard)].fields.push_back({p.key, p.kfield, E, p.slot == kEosSlotV0 ? 1.0 : 0.0, false, {}, ""});
  }
  s.note = texts.emplace_back(std::string("form ") + std::to_string(f.form) + ", " + f.name +
                              "; the constants are checked once the cards are read (material/eos.h)").c_str();
  return s;
}

std::vector<KeywordSpec> materials_specs() {
  std::vector<KeywordSpec> t;
  for (const MaterialType* m : material_types()) t.push_back(material_spec(*m));
  for (const EosForm* f : eos_forms()) t.push_back(eos_spec(*f));
  t.push_back({{"MAT_ADD_EROSION"}, KeywordFamily::materials, false,
               {{"card 1", 8, 10, per_field, {
                   {"MID", 0, I, 0, false, {}, "the material (the cards are then named \"material MID\"; given twice: error 1200)"},
                   {"EXCL", 1, E, 0, false, {}, "a criterion equal to it is not used"},
                   {"MXPRES", 2, E, 0, false, {}, "maximum pressure"},
                   {"MNEPS", 3, E, 0, false, {}, "minimum principal strain"},
                   {"EFFEPS", 4, E, 0, false, {}, "maximum effective strain"},
                   {"VOLEPS", 5, E, 0, false, {}, "volumetric strain"},
                   plain("NUMFIP", 6, E, "read, no effect (one integration point per solid)"),
                   {"NCS", 7, I, 1, false, {outside(0, 6, 1003, "the number of criteria that must hold at once, 1-6 (0: 1)")},
                    "criteria that must hold at once (0: 1)"},
               }, ""},
                {"card 2", 8, 10, per_field, {
                   {"MNPRES", 0, E, 0, false, {}, "minimum pressure"},
                   {"SIGP1", 1, E, 0, false, {}, "maximum principal stress"},
                   {"SIGVM", 2, E, 0, false, {}, "equivalent stress"},
                   {"MXEPS", 3, E, 0, false, {}, "maximum principal strain"},
                   {"EPSSH", 4, E, 0, false, {}, "shear strain"},
                   {"SIGTH", 5, E, 0, false, {}, "Tuler-Butcher erosion: not blank, 0 or EXCL: error 1102"},
                   {"IMPULSE", 6, E, 0, false, {}, "Tuler-Butcher erosion: not blank, 0 or EXCL: error 1102"},
                   {"FAILTM", 7, E, 0, false, {}, "failure time"},
               }, "when given"},
                {"card 3", 8, 10, per_field, {
                   {"IDAM", 0, E, 0, false, {}, "damage models: not blank, 0 or EXCL: error 1102"},
               }, "when given"}},
               "erosion criteria of a material (0: not used)"});
  return t;
}

std::vector<KeywordSpec> parts_sections_specs() {
  const KeywordFamily F = KeywordFamily::parts_sections;
  std::vector<KeywordSpec> t;
  t.push_back({{"PART"}, F, false,
               {{"card 2", 8, 10, per_field, {
                   {"PID", 0, I, 0, false, {}, "part id (the card is then named \"part PID\" in messages)"},
                   {"SECID", 1, I, 0, false, {}, "section"},
                   {"MID", 2, I, 0, false, {}, "material"},
                   {"EOSID", 3, I, 0, false, {}, "equation of state (0: none)"},
                   {"HGID", 4, I, 0, false, {}, "*HOURGLASS (0: the control values)"},
                   {"GRAV", 5, I, 0, false, {nonzero(1102, "body forces")}, "body forces"},
                   plain("ADPOPT", 6, I),
                   {"TMID", 7, I, 0, false, {nonzero(1102, "thermal materials")}, "thermal material"},
               }, "after each heading card"}},
               "pairs of cards: a heading (80 columns), then card 2; card 2 missing after a heading that is not blank: error 1316"});
  t.push_back({{"SECTION_SOLID"}, F, false,
               {{"", 3, 10, per_field, {
                   {"SECID", 0, I, 0, false, {}, "section id (defined twice: error 1200)"},
                   {"ELFORM", 1, I, 1, false, {}, "element formulation (solids: 0/1 the one-point hexahedron, 2 the fully integrated selective-reduced one; others: error 1102 for a part that uses it)"},
                   {"AET", 2, I, 0, false, {nonzero(1102, "ambient element types")}, "ambient element type"},
               }, ""}},
               "one card (the cards of other ELFORMs after it are not read)"});
  t.push_back({{"SECTION_SHELL"}, F, false,
               {{"card 1", 8, 10, per_field, {
                   {"SECID", 0, I, 0, false, {}, "section id (the cards are then named by it in messages; defined twice: error 1200)"},
                   {"ELFORM", 1, I, 2, false, {inside(16, 16, 0, nullptr), neither(0, 2, 1102, "shell formulation %v; only ELFORM 2 (Belytschko-Tsay) and 16 (fully integrated)")}, "shell formulation (0/2 Belytschko-Tsay, 16 fully integrated)"},
                   shear_factor("shear factor in (0, 1] (5/6 for isotropic shells)"),
                   {"NIP", 3, E, 2, true, {not_whole(0, kInf, 1003, "integration points 1-10"),
                                           outside(-kInf, 10, 1102, "more than 10 Gauss points (user-defined integration rules)")}, "through-thickness Gauss points"},
                   plain("PROPT", 4, E),
                   {"QR/IRID", 5, E, 0, false, {nonzero(1102, "user-defined and trapezoidal integration rules (Gauss only)")}, "integration rule"},
                   {"ICOMP", 6, I, 0, false, {nonzero(1102, "composite layups")}, "composite layup"},
                   plain("SETYP", 7, E),
               }, ""},
                {"card 2", 8, 10, per_field, {
                   checked_after({"T1", 0, E, 0, false, {below(0, 1241)}, "thickness at node 1"}, 3),
                   {"T2", 1, E, 0, false, {}, "thickness at node 2 (0: T1)"},
                   {"T3", 2, E, 0, false, {}, "thickness at node 3 (0: T1)"},
                   {"T4", 3, E, 0, false, {}, "thickness at node 4 (0: T1)"},
                   {"NLOC", 4, E, 0, false, {nonzero(1102, "reference-surface offsets")}, "reference surface"},
                   {"MAREA", 5, E, 0, false, {nonzero(1102, "non-structural mass")}, "non-structural mass"},
                   {"IDOF", 6, E, 0, false, {nonzero(1102, "thickness-stretch degrees of freedom")}, "thickness stretch"},
                   {"EDGSET", 7, E, 0, false, {nonzero(1102, "edge sets")}, "edge set"},
               }, "named by SECID; missing: error 1316"}},
               ""});
  t.push_back({{"SECTION_BEAM"}, F, false,
               {{"card 1", 8, 10, per_field, {
                   {"SECID", 0, I, 0, false, {}, "section id (the cards are then named by it in messages; defined twice: error 1200)"},
                   {"ELFORM", 1, I, 1, true, {inside(9, 9, 0, nullptr),
                                              outside(1, 3, 1102, "beam formulation %v; only ELFORM 1 (Hughes-Liu), 2 (Belytschko-Schwer), 3 (truss) and 9 (spot-weld beam)")},
                    "beam formulation (9: spot-weld beam, run as 1)"},
                   shear_factor("shear factor in (0, 1] (5/6 for a rectangle)"),
                   {"QR/IRID", 3, E, 2, true, {below(0, 1102, "user-defined integration rules (*INTEGRATION_BEAM); rules 1-5"),
                                               not_whole(-kInf, 5, 1003, "quadrature rule 1-5")}, "quadrature rule"},
                   {"CST", 4, I, 0, false, {outside(0, 1, 1102, "cross section %v; only 0 (rectangular) and 1 (tubular)")}, "cross section: 0 rectangular, 1 tubular"},
                   {"SCOOR", 5, E, 0, false, {nonzero(1102, "cross-section location options")}, "cross-section location"},
                   {"NSM", 6, E, 0, false, {nonzero(1102, "non-structural mass")}, "non-structural mass"},
               }, ""},
                {"card 2", 8, 10, per_field, {
                   checked_after({"TS1", 0, E, 0, false, {below(0, 1251)}, "s thickness or diameter at node 1"}, 3),
                   {"TS2", 1, E, 0, false, {}, "at node 2 (0: TS1)"},
                   checked_after({"TT1", 2, E, 0, false, {below(0, 1251)}, "t thickness or diameter at node 1"}, 3),
                   {"TT2", 3, E, 0, false, {}, "at node 2 (0: TT1)"},
                   {"NSLOC", 4, E, 0, false, {nonzero(1102, "reference-axis offsets")}, "reference axis"},
                   {"NTLOC", 5, E, 0, false, {nonzero(1102, "reference-axis offsets")}, "reference axis"},
               }, "ELFORM 1"},
                {"card 2", 8, 10, per_field, {
                   checked_after({"A", 0, E, 0, false, {outside(0, kInf, 1251, "the area must be positive", true)}, "area"}, 4),
                   checked_after({"ISS", 1, E, 0, false, {outside(0, kInf, 1251, nullptr, true)}, "moment of inertia about s"}, 4),
                   checked_after({"ITT", 2, E, 0, false, {outside(0, kInf, 1251, nullptr, true)}, "moment of inertia about t"}, 4),
                   checked_after({"J", 3, E, 0, false, {below(0, 1251)}, "torsional constant"}, 4),
                   {"SA", 4, E, 0, false, {}, "shear area"},
                   {"IST", 5, E, 0, false, {nonzero(1102, "a product of inertia (unsymmetric sections)")}, "product of inertia"},
               }, "ELFORM 2"},
                {"card 2", 8, 10, per_field, {
                   {"A", 0, E, 0, false, {outside(0, kInf, 1251, "the truss area must be positive", true)}, "area"},
                   {"RAMPT", 1, E, 0, false, {nonzero(1102, "initial stress ramps")}, "stress ramp time"},
                   {"STRESS", 2, E, 0, false, {nonzero(1102, "initial stress")}, "initial stress"},
               }, "ELFORM 3"},
                {"card 2", 8, 10, per_field, {
                   checked_after({"TS1", 0, E, 0, false, {below(0, 1251)}, "diameter (CST 1) or s thickness at node 1"}, 3),
                   {"TS2", 1, E, 0, false, {}, "at node 2 (0: TS1)"},
                   checked_after({"TT1", 2, E, 0, false, {below(0, 1251)}, "inner diameter (CST 1; 0: solid) or t thickness at node 1"}, 3),
                   {"TT2", 3, E, 0, false, {}, "at node 2 (0: TT1)"},
                   {"PRINT", 4, E, 0, false, {}, "SWFORC output flag (read; no SWFORC file is written)"},
                   plain("UNUSED", 5, E),
                   {"ITOFF", 6, E, 0, false, {nonzero(1102, "torsion-free spot-weld beams (ITOFF 1)")}, "0: torsional stiffness active"},
               }, "ELFORM 9"}},
               "card 2 by ELFORM (another ELFORM: as 1), named by SECID; missing: error 1316"});
  t.push_back({{"HOURGLASS"}, F, false,
               {{"", 8, 10, per_field, {
                   {"HGID", 0, I, 0, false, {}, "hourglass id (the card is then named by it in messages; defined twice: error 1200)"},
                   checked_after({"IHQ", 1, I, 0, false, {inside(6, 10, 1102, "hourglass type %v (IMPACT-3D has 0 control default, 1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness)"),
                                                          outside(0, 5, 1006, "0 (control default), 1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness")}, "hourglass type (0: the control value)"}, 5),
                   checked_after({"QM", 2, E, 0.1, false, {below(0, 1220)}, "hourglass coefficient (0: the control value)"}, 5),
                   plain("IBQ", 3, I),
                   checked_after({"Q1", 4, E, 1.5, false, {below(0, 1220)}, "quadratic bulk viscosity (blank: *CONTROL_BULK_VISCOSITY)"}, 5),
                   {"Q2", 5, E, 0.06, false, {below(0, 1220)}, "linear bulk viscosity (blank: *CONTROL_BULK_VISCOSITY)"},
               }, ""}},
               "one card"});
  return t;
}

// LCID of a load: required (a load without a curve does nothing).
KeywordField load_curve(int index) {
  return {"LCID", index, I, 0, false, {inside(0, 0, 1003, "a load curve (*DEFINE_CURVE) is required")}, "load curve"};
}
KeywordField scale_factor(int index) { return {"SF", index, E, 1.0, false, {}, "scale factor of the curve"}; }

// *LOAD_NODE_POINT / _SET, *LOAD_RIGID_BODY: ID DOF LCID SF CID M1 M2 M3
KeywordSpec load_node(const char* name, const char* id, const char* id_meaning) {
  return {{name}, KeywordFamily::loads_bcs, false,
          {{"", 8, 10, per_field, {
              {id, 0, I, 0, false, {}, id_meaning},
              {"DOF", 1, I, 0, false, {inside(4, 4, 1102, "follower forces"), inside(8, 8, 1102, "follower moments"),
                                       inside(5, 7, 1102, "moments (solid nodes have no rotations)"), outside(1, 8, 1006, "1 x, 2 y, 3 z")},
               "1 x, 2 y, 3 z (along the axes of CID)"},
              load_curve(2),
              scale_factor(3),
              {"CID", 4, I, 0, false, {}, "coordinate system of DOF (0: global)"},
              plain("M1/M2/M3", 5, I), plain("M1/M2/M3", 6, I), plain("M1/M2/M3", 7, I),
          }, "each card ([ID card] with _ID)"}},
          ""};
}

// *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET / _RIGID: ID DOF VAD LCID SF VID DEATH BIRTH; with
// |DOF| 9-11 or VAD 4 LS-DYNA's card 2 (OFFSET1 OFFSET2 LRB NODE1 NODE2) follows.  Nodes take DOF
// 1-3, 4 / -4 (along VID), 5-7 and 8 / -8 (rotations of shell and beam nodes) and 9-11 (turning
// about an axis through OFFSET1, OFFSET2); rigid bodies DOF 1-3, 4 / -4, 5-7 (rotations about x
// y z) and 8 / -8 (about VID).
KeywordSpec prescribed_motion(const char* name, const char* id, bool rigid) {
  std::vector<KeywordCheck> dof;
  if (rigid) {
    dof.push_back(inside(9, 11, 1102, "DOF 9-11 (nodes rotating about an axis; LS-DYNA: not for rigid bodies; its card 2 is skipped)"));
    dof.push_back(inside(-11, -9, 1102, "DOF -11 to -9 (nodes rotating about an axis; LS-DYNA: not for rigid bodies; its card 2 is skipped)"));
    dof.push_back(inside(-8, -8, 0, nullptr));  // about VID, the other rotations held
    dof.push_back(inside(-4, -4, 0, nullptr));  // along VID, the normal plane held
    dof.push_back(outside(1, 8, 1006, "1-3 x y z, 4 / -4 along VID, 5-7 rotations about x y z, 8 / -8 about VID"));
  } else {
    dof.push_back(inside(-11, -9, 0, nullptr));  // turning about an axis, its distance from it free
    dof.push_back(inside(-8, -8, 0, nullptr));  // about VID, the other rotations held
    dof.push_back(inside(-4, -4, 0, nullptr));  // along VID, the normal plane held
    dof.push_back(outside(1, 11, 1006, "1-3 x y z, 4 / -4 along VID, 5-7 rotations about x y z, 8 / -8 about VID, 9-11 turning about an axis along x y z"));
  }
  const char* dof_text = rigid ? "1-3 x y z, 4 along VID (-4: normal plane held), 5-7 rotation about x y z, 8 about VID (-8: other rotations held)"
                               : "1-3 x y z, 4 along VID (-4: normal plane held), 5-7 rotation about x y z and 8 about VID (-8: other rotations held) of a shell or beam node, 9-11 turning about an axis along x y z through OFFSET1, OFFSET2 (-11 to -9: its distance from the axis free)";
  std::vector<KeywordCardLayout> cards = {
      {"", 8, 10, per_field, {
          {id, 0, I, 0, false, {}, rigid ? "part (a *MAT_RIGID part)" : "node or node set"},
          {"DOF", 1, I, 0, false, std::move(dof), dof_text},
          {"VAD", 2, I, 0, false, {inside(3, 3, 1102, "velocity as a function of displacement"), inside(4, 4, 1102, "relative displacement"),
                                   outside(0, 2, 1006, "0 velocity, 1 acceleration, 2 displacement")}, "0 velocity, 1 acceleration, 2 displacement"},
          load_curve(3),
          scale_factor(4),
          {"VID", 5, I, 0, false, {}, "*DEFINE_VECTOR of DOF 4, 8 (required with them: error 1003)"},
          {"DEATH", 6, E, 0, false, {}, "death time (0: none; before BIRTH: error 1003)"},
          {"BIRTH", 7, E, 0, false, {}, "birth time"},
      }, "each motion ([ID card] with _ID; card 2 after it with |DOF| 9-11 or VAD 4, missing: error 1316)"}};
  if (!rigid)
    cards.push_back({"card 2", 5, 10, per_field, {
        {"OFFSET1", 0, E, 0, false, {}, "DOF 9, 10, 11: the axis's y, z, x coordinate"},
        {"OFFSET2", 1, E, 0, false, {}, "DOF 9, 10, 11: the axis's z, x, y coordinate"},
        {"LRB", 2, I, 0, false, {outside(0, 0, 1102, "0 (a load curve of the motion's radius is not implemented)")}, "not 0: error 1102"},
        {"NODE1", 3, I, 0, false, {outside(0, 0, 1102, "0 (motions relative to nodes are not implemented)")}, "not 0: error 1102"},
        {"NODE2", 4, I, 0, false, {outside(0, 0, 1102, "0 (motions relative to nodes are not implemented)")}, "not 0: error 1102"},
    }, "DOF 9-11 (with a refused DOF or VAD 4 skipped)"});
  return {{name}, KeywordFamily::loads_bcs, false, std::move(cards), ""};
}

// *LOAD_NODE, *LOAD_SEGMENT, *LOAD_BODY: the loads.
void add_load_specs(std::vector<KeywordSpec>& t) {
  const KeywordFamily F = KeywordFamily::loads_bcs;
  t.push_back(load_node("LOAD_NODE_POINT", "NID", "node"));
  t.push_back(load_node("LOAD_NODE_SET", "NSID", "node set"));
  t.push_back(load_node("LOAD_RIGID_BODY", "PID", "part (a *MAT_RIGID part)"));
  t.push_back({{"LOAD_SEGMENT"}, F, false,
               {{"", 8, 10, per_field, {
                   load_curve(0),
                   scale_factor(1),
                   {"AT", 2, E, 0, false, {}, "arrival time (the pressure acts from AT on)"},
                   {"N1", 3, I, 0, false, {}, "segment nodes (N4 0: a triangle)"},
                   {"N2", 4, I, 0, false, {}, ""},
                   {"N3", 5, I, 0, false, {}, ""},
                   {"N4", 6, I, 0, false, {}, ""},
                   {"N5", 7, I, 0, false, {nonzero(1102, "higher-order (8-node) segments")}, "higher-order segments"},
               }, "each card ([ID card] with _ID)"}},
               ""});
  t.push_back({{"LOAD_SEGMENT_SET"}, F, false,
               {{"", 8, 10, per_field, {
                   {"SSID", 0, I, 0, false, {}, "segment set"},
                   load_curve(1),
                   scale_factor(2),
                   {"AT", 3, E, 0, false, {}, "arrival time"},
                   {"DT", 4, E, 0, false, {}, "death time (0: none)"},
               }, "each card ([ID card] with _ID)"}},
               ""});
  const KeywordCardLayout body_card1{"card 1", 8, 10, per_field, {
      load_curve(0),
      scale_factor(1),
      {"LCIDDR", 2, I, 0, false, {nonzero(2006, "no dynamic relaxation")}, "dynamic relaxation curve"},
      plain("XC/YC/ZC", 3, E), plain("XC/YC/ZC", 4, E), plain("XC/YC/ZC", 5, E),
      {"CID", 6, I, 0, false, {}, "coordinate system of the direction (0: global)"},
  }, "required (missing: error 1316)"};
  t.push_back({{"LOAD_BODY_X", "LOAD_BODY_Y", "LOAD_BODY_Z"}, F, false, {body_card1}, ""});
  t.push_back({{"LOAD_BODY_VECTOR"}, F, false,
               {body_card1,
                {"card 2", 8, 10, per_field, {
                   {"V1", 0, E, 0, false, {}, "direction (normalised; zero: error 1003)"},
                   {"V2", 1, E, 0, false, {}, ""},
                   {"V3", 2, E, 0, false, {}, ""},
               }, "required (missing: error 1316)"}},
               ""});
  t.push_back({{"LOAD_BODY_PARTS"}, F, true,
               {{"card 1", 1, 10, per_field, {
                   {"PSID", 0, I, 0, false, {}, "part set the body loads act on"},
               }, "when given"}},
               ""});
}

// *DAMPING_GLOBAL and *BOUNDARY_SPC (with _BIRTH_DEATH).
void add_damping_and_spc_specs(std::vector<KeywordSpec>& t) {
  const KeywordFamily F = KeywordFamily::loads_bcs;
  t.push_back({{"DAMPING_GLOBAL"}, F, true,
               {{"card 1", 8, 10, per_field, {
                   {"LCID", 0, I, 0, false, {}, "curve of the damping constant (0: VALDMP)"},
                   {"VALDMP", 1, E, 0, false, {below(0, 1003, "the damping constant must not be negative")}, "damping constant"},
                   {"STX", 2, E, 0, false, {below(0, 1003, "a scale factor must not be negative")}, "factors per axis (all six 0: all 1)"},
                   {"STY", 3, E, 0, false, {below(0, 1003, "a scale factor must not be negative")}, ""},
                   {"STZ", 4, E, 0, false, {below(0, 1003, "a scale factor must not be negative")}, ""},
                   {"SRX", 5, E, 0, false, {below(0, 1003, "a scale factor must not be negative")}, "rotations (shells: not damped, warning 2006)"},
                   {"SRY", 6, E, 0, false, {below(0, 1003, "a scale factor must not be negative")}, ""},
                   {"SRZ", 7, E, 0, false, {below(0, 1003, "a scale factor must not be negative")}, ""},
               }, "when given"}},
               ""});
  for (const auto& [name, id] : {std::pair{"BOUNDARY_SPC_NODE", "NID"}, std::pair{"BOUNDARY_SPC_SET", "NSID"}}) {
    KeywordCardLayout c{"", 8, 10, per_field, {
        {id, 0, I, 0, false, {}, id[1] == 'I' ? "node" : "node set"},
        {"CID", 1, I, 0, false, {}, "coordinate system of the DOFs (0: global)"},
    }, "each card (ID cards with _ID)"};
    static const char* const dofs[6] = {"DOFX", "DOFY", "DOFZ", "DOFRX", "DOFRY", "DOFRZ"};
    for (int k = 0; k < 6; ++k)
      c.fields.push_back({dofs[k], 2 + k, I, 0, false, {outside(0, 1, 1006, "0 free or 1 fixed")}, k == 0 ? "1: fixed (rotations: shell and beam nodes)" : ""});
    t.push_back({{name}, F, false, {c}, ""});
    // _BIRTH_DEATH: the same card 1, then card 2 BIRTH DEATH (each pair: the constraint holds
    // from BIRTH to DEATH, a zero velocity prescribed in each fixed direction)
    KeywordCardLayout c1 = c;
    c1.card = "card 1";
    c1.when = "each constraint (ID cards with _ID)";
    c1.fields[2].meaning = "1: fixed from BIRTH to DEATH (rotations: shell and beam nodes)";
    t.push_back({{name == std::string("BOUNDARY_SPC_NODE") ? "BOUNDARY_SPC_NODE_BIRTH_DEATH" : "BOUNDARY_SPC_SET_BIRTH_DEATH"}, F, false,
                 {c1,
                  {"card 2", 2, 10, per_field, {
                      {"BIRTH", 0, E, 0, false, {}, "time the constraint starts to act"},
                      {"DEATH", 1, E, 1e20, true, {}, "time it is removed (0: 1e20, never; before BIRTH: error 1003)"},
                  }, "after each card 1 (missing: error 1316)"}},
                 "pairs of cards; LS-DYNA's *BOUNDARY_SPC_..._ID_BIRTH_DEATH and _BIRTH_DEATH_ID both read"});
  }
}

// *RIGIDWALL_GEOMETRIC_CYLINDER and *CONSTRAINED_GLOBAL.
void add_wall_and_constraint_specs(std::vector<KeywordSpec>& t) {
  const KeywordFamily F = KeywordFamily::loads_bcs;
  t.push_back({{"RIGIDWALL_GEOMETRIC_CYLINDER", "RIGIDWALL_GEOMETRIC_CYLINDER_DISPLAY", "RIGIDWALL_GEOMETRIC_CYLINDER_MOTION",
                "RIGIDWALL_GEOMETRIC_CYLINDER_MOTION_DISPLAY"}, F, false,
               {{"card 1", 5, 10, per_field, {
                   {"NSID", 0, I, 0, false, {}, "node set the wall acts on (0: all nodes)"},
                   {"NSIDEX", 1, I, 0, false, {}, "node set exempted"},
                   {"BOXID", 2, I, 0, false, {}, "only the nodes in this box"},
                   {"BIRTH", 3, E, 0, false, {nonzero(1102, "wall birth time")}, "birth time"},
                   {"DEATH", 4, E, 0, false, {}, "death time (0 or >= 1e20: none; other: error 1102)"},
               }, "each wall (after its ID card with _ID)"},
                {"card 2", 7, 10, per_field, {
                   {"XT", 0, E, 0, false, {}, "tail of the axis (a point on it)"}, {"YT", 1, E, 0, false, {}, ""}, {"ZT", 2, E, 0, false, {}, ""},
                   {"XH", 3, E, 0, false, {}, "head: the axis runs from the tail toward it (tail = head: error 1213)"}, {"YH", 4, E, 0, false, {}, ""},
                   {"ZH", 5, E, 0, false, {}, ""},
                   {"FRIC", 6, E, 0, false, {outside(0, 1, 1219)}, "0 frictionless, 1 stick, between Coulomb"},
               }, "required (missing: error 1316)"},
                {"card 3", 3, 10, per_field, {
                   {"RADCYL", 0, E, 0, false, {outside(0, kInf, 1003, "the cylinder's radius must be positive", true)}, "radius"},
                   {"LENCYL", 1, E, 0, false, {below(0, 1003, "the cylinder's length must not be negative")}, "length from the tail along the axis (0: infinite; a node past an end is free)"},
                   {"NSEGS", 2, I, 0, false, {nonzero(1102, "cylinders of varying radius (NSEGS)")}, "subsections of varying radius"},
               }, "required (missing: error 1316)"},
                {"card 4", 4, 10, per_field, {
                   plain("PID", 0, I, "display part: read, no effect (no display shells are written)"),
                   plain("RO", 1, E), plain("E", 2, E), plain("PR", 3, E),
               }, "with _DISPLAY"}},
               "a fixed rigid cylinder: the nodes are kept outside it (no rebound, friction as *RIGIDWALL_PLANAR); _MOTION: error 1312"});
  t.push_back({{"CONSTRAINED_GLOBAL"}, F, false,
               {{"", 7, 10, per_field, {
                   {"TC", 0, I, 0, false, {outside(0, 7, 1006, "0 none, 1 x, 2 y, 3 z, 4 x and y, 5 y and z, 6 z and x, 7 all")},
                    "translations held: 0 none, 1 x, 2 y, 3 z, 4 x and y, 5 y and z, 6 z and x, 7 all"},
                   {"RC", 1, I, 0, false, {outside(0, 7, 1006, "0 none, 1 x, 2 y, 3 z, 4 x and y, 5 y and z, 6 z and x, 7 all")},
                    "rotations held, coded as TC (shell and beam nodes; solid nodes have none)"},
                   {"DIR", 2, I, 0, false, {outside(1, 3, 1006, "1 x, 2 y, 3 z")}, "normal of the plane: 1 x, 2 y, 3 z"},
                   {"X", 3, E, 0, false, {}, "a point of the plane (the coordinate along DIR counts)"},
                   {"Y", 4, E, 0, false, {}, ""},
                   {"Z", 5, E, 0, false, {}, ""},
                   {"TOL", 6, E, 0, false, {below(0, 1003, "the tolerance must not be negative")},
                    "nodes within TOL of the plane are held (0: 1e-3 of the model's shortest element edge)"},
               }, "each card (one plane)"}},
               "every node (of any element, or of none) within TOL of the plane"});
}

// *RIGIDWALL_PLANAR (_MOVING) (_ID): card 1 the nodes and the refused options, card 2 the
// plane, card 3 the moving wall's mass and velocity.
void add_planar_wall_specs(std::vector<KeywordSpec>& t) {
  t.push_back({{"RIGIDWALL_PLANAR"}, KeywordFamily::loads_bcs, false,
               {{"ID card", 1, 10, per_field, {{"RWID", 0, I, 0, false, {}, "wall id and heading: not read"}}, "with _ID, before each wall"},
                {"card 1", 7, 10, per_field, {
                   {"NSID", 0, I, 0, false, {}, "node set the wall acts on (0: all nodes)"},
                   {"NSIDEX", 1, I, 0, false, {}, "node set exempted"},
                   {"BOXID", 2, I, 0, false, {}, "only the nodes in this box"},
                   {"OFFSET", 3, E, 0, false, {nonzero(1102, "wall offset")}, "offset of the wall"},
                   {"BIRTH", 4, E, 0, false, {nonzero(1102, "wall birth time")}, "birth time"},
                   {"DEATH", 5, E, 0, false, {inside(0, 0, 0, nullptr), below(1e20, 1102, "wall death time")}, "death time (0 or >= 1e20: none)"},
                   plain("RWKSF", 6, E),
               }, "each wall; it and card 2 missing: error 1316"},
                {"card 2", 8, 10, per_field, {
                   {"XT", 0, E, 0, false, {}, "tail of the normal (a point of the wall)"}, {"YT", 1, E, 0, false, {}, ""}, {"ZT", 2, E, 0, false, {}, ""},
                   {"XH", 3, E, 0, false, {}, "head: the normal points from the tail toward it, into the model (tail = head: error 1213, named XT-ZH)"},
                   {"YH", 4, E, 0, false, {}, ""}, {"ZH", 5, E, 0, false, {}, ""},
                   {"FRIC", 6, E, 0, false, {outside(0, 1, 1219)}, "0 frictionless, 1 stick, between Coulomb (checked after the normal)", kByReader},
                   {"WVEL", 7, E, 0, false, {nonzero(2006, "critical velocity for stick (IMPACT-3D sticks for FRIC = 1)")}, "critical velocity for stick"},
               }, "after card 1"},
                {"card 3", 2, 10, per_field, {
                   checked_after({"MASS", 0, E, 0, false, {outside(0, kInf, 1003, "a moving wall needs a positive mass", true)}, "mass of the wall"}, 1),
                   {"V0", 1, E, 0, false, {}, "initial velocity along the normal"},
               }, "with _MOVING (missing: error 1316)"}},
               "one wall a pair of cards (three with _MOVING), several walls a keyword; *RIGIDWALL_PLANAR_MOVING (_ID) is this "
               "entry with card 3"});
}

// The spot welds' failure fields SN SS N M (the same columns in both keywords); N and M are
// checked against SN and SS by the family's reader.
std::vector<KeywordField> weld_failure_fields() {
  return {checked_after({"SN", 2, E, 0, false, {below(0, 1003, "must not be negative (0: no failure by the normal force)")},
                         "normal force at failure (0: none)"}, 5),
          checked_after({"SS", 3, E, 0, false, {below(0, 1003, "must not be negative (0: no failure by the shear force)")},
                         "shear force at failure (0: none)"}, 5),
          {"N", 4, E, 0, false, {}, "exponent of the normal force (SN given: not positive error 1003)"},
          {"M", 5, E, 0, false, {}, "exponent of the shear force (SS given: not positive error 1003)"}};
}
KeywordField ductile_failure(const char* name, int index) {
  return {name, index, E, 1e20, false,
          {below(0, 1003, "must not be negative (0 or >= 1e19: no ductile failure)")},
          "effective plastic strain at a weld node at which the weld fails (0 or >= 1e19: none)"};
}

// *CONSTRAINED_SPOTWELD and *CONSTRAINED_GENERALIZED_WELD_SPOT (_ID: an ID card before a weld).
void add_spot_weld_specs(std::vector<KeywordSpec>& t) {
  const KeywordCardLayout id{"ID card", 1, 10, per_field, {{"WID", 0, I, 0, false, {}, "weld id (the weld is then named \"WID n\")"}},
                             "with _ID: the first card and any card of an id and a heading (or blank) before a weld"};
  t.push_back({{"CONSTRAINED_SPOTWELD"}, KeywordFamily::loads_bcs, false,
               {id,
                {"", 8, 10, per_field, fields_of(std::vector<KeywordField>{
                   {"N1", 0, I, 0, false, {}, "first node"},
                   {"N2", 1, I, 0, false, {}, "second node"}}, weld_failure_fields(), std::vector<KeywordField>{
                   {"TF", 6, E, 1e20, false, {}, "failure time"},
                   ductile_failure("EP", 7)}),
                 "each weld (blank cards skipped)"}},
               "a rigid link between two shell nodes, failing by force or time"});
  t.push_back({{"CONSTRAINED_GENERALIZED_WELD_SPOT"}, KeywordFamily::loads_bcs, false,
               {id,
                {"card 1", 5, 10, per_field, {
                   {"NSID", 0, I, 0, false, {}, "node set of the weld"},
                   {"CID", 1, I, 0, false, {}, "coordinate system of the forces"},
                   {"FILTER", 2, I, 0, false, {inside(2, kInf, 1102, "filtering of the weld forces")}, "force filter"},
                   {"WINDOW", 3, E, 0, false, {nonzero(1102, "filtering of the weld forces")}, "filter window"},
                   {"NPRT", 4, I, 0, false, {inside(1, 1, 2006, "the weld forces are not printed (no rbdout)")}, "print flag"},
               }, "each weld (blank cards skipped)"},
                {"card 2", 6, 10, per_field, fields_of(std::vector<KeywordField>{
                   {"TFAIL", 0, E, 1e20, false, {}, "failure time"},
                   ductile_failure("EPSF", 1)}, weld_failure_fields()),
                 "after card 1 (missing: error 1316)"}},
               "a rigid link among the nodes of a set, failing by force or time"});
}

// *INITIAL_TEMPERATURE and *INITIAL_VELOCITY: the initial conditions.
void add_initial_condition_specs(std::vector<KeywordSpec>& t) {
  const KeywordFamily F = KeywordFamily::loads_bcs;
  for (const auto& [name, id] : {std::pair{"INITIAL_TEMPERATURE_NODE", "NID"}, std::pair{"INITIAL_TEMPERATURE_SET", "NSID"}})
    t.push_back({{name}, F, false,
                 {{"", 3, 10, per_field, {
                     {id, 0, I, 0, false, {}, id[1] == 'I' ? "node" : "node set (0: every node)"},
                     {"TEMP", 1, E, 0, false, {}, "temperature (a later card wins)"},
                     {"LOC", 2, I, 0, false, {nonzero(2006, "a shell surface: the temperature holds through the thickness")}, "shell surface"},
                 }, "each card"}},
                 ""});
  t.push_back({{"INITIAL_VELOCITY_NODE"}, F, false,
               {{"", 8, 10, per_field, {
                   {"NID", 0, I, 0, false, {}, "node"},
                   {"VX", 1, E, 0, false, {}, "velocity"}, {"VY", 2, E, 0, false, {}, ""}, {"VZ", 3, E, 0, false, {}, ""},
                   {"VXR", 4, E, 0, false, {}, "rotational velocity (shell nodes)"}, {"VYR", 5, E, 0, false, {}, ""}, {"VZR", 6, E, 0, false, {}, ""},
                   {"ICID", 7, I, 0, false, {}, "coordinate system of the velocities (0: global)"},
               }, "each card"}},
               ""});
  t.push_back({{"INITIAL_VELOCITY"}, F, false,
               {{"card 1", 5, 10, per_field, {
                   {"NSID", 0, I, 0, false, {}, "node set (0: every node)"},
                   {"NSIDEX", 1, I, 0, false, {}, "node set exempted (< 0: error 1003); they take card 3's velocity"},
                   {"BOXID", 2, I, 0, false, {}, "only the nodes in this box"},
                   plain("IRIGID", 3, I),
                   {"ICID", 4, I, 0, false, {}, "coordinate system of the velocities (0: global)"},
               }, "each definition"},
                {"card 2", 6, 10, per_field, {
                   {"VX", 0, E, 0, false, {}, "velocity"}, {"VY", 1, E, 0, false, {}, ""}, {"VZ", 2, E, 0, false, {}, ""},
                   {"VXR", 3, E, 0, false, {}, "rotational velocity (shell nodes)"}, {"VYR", 4, E, 0, false, {}, ""}, {"VZR", 5, E, 0, false, {}, ""},
               }, "required (missing: error 1316)"},
                {"card 3", 6, 10, per_field, {
                   {"VXE", 0, E, 0, false, {}, "velocity of the exempted nodes"}, {"VYE", 1, E, 0, false, {}, ""}, {"VZE", 2, E, 0, false, {}, ""},
                   {"VRE", 3, E, 0, false, {}, "VXRE-VZRE (solid nodes have no rotations: the first nonzero is warning 2006, the rest not read)"},
                   {"VRE", 4, E, 0, false, {}, ""}, {"VRE", 5, E, 0, false, {}, ""},
               }, "with NSIDEX > 0 (missing: error 1316)"}},
               "pairs (with NSIDEX, triples) of cards"});
  t.push_back({{"INITIAL_VELOCITY_GENERATION"}, F, false,
               {{"card 1", 8, 10, per_field, {
                   {"ID", 0, I, 0, false, {}, "part set, part or node set"},
                   {"STYP", 1, I, 0, false, {outside(1, 3, 1006, "1 part set, 2 part, 3 node set")}, "1 part set, 2 part, 3 node set"},
                   {"OMEGA", 2, E, 0, false, {}, "angular velocity about the axis of card 2 (needs it: error 1316)"},
                   {"VX", 3, E, 0, false, {}, "velocity"}, {"VY", 4, E, 0, false, {}, ""}, {"VZ", 5, E, 0, false, {}, ""},
                   {"IVATN", 6, I, 0, false, {nonzero(1102, "slave parts of rigid bodies")}, "slave parts of rigid bodies"},
                   {"ICID", 7, I, 0, false, {}, "coordinate system of the velocities (0: global)"},
               }, "each definition"},
                {"card 2", 8, 10, per_field, {
                   {"XC", 0, E, 0, false, {}, "a point on the axis"}, {"YC", 1, E, 0, false, {}, ""}, {"ZC", 2, E, 0, false, {}, ""},
                   {"NX", 3, E, 0, false, {}, "the axis (normalised; zero with OMEGA: error 1003)"}, {"NY", 4, E, 0, false, {}, ""}, {"NZ", 5, E, 0, false, {}, ""},
                   {"PHASE", 6, E, 0, false, {nonzero(2006, "no dynamic relaxation: velocities apply at time 0")}, "dynamic relaxation phase"},
                   plain("IRIGID", 7, I),
               }, "when given"}},
               "pairs of cards"});
  t.push_back({{"DEFINE_CURVE"}, F, false,
               {{"card 1", 8, 10, per_field, {
                   {"LCID", 0, I, 0, false, {}, "curve id (the cards are then named by it in messages; defined twice: error 1200)"},
                   {"SIDR", 1, I, 0, false, {nonzero(2006, "dynamic relaxation")}, "dynamic relaxation"},
                   {"SFA", 2, E, 1.0, true, {}, "abscissa scale factor"},
                   {"SFO", 3, E, 1.0, true, {}, "ordinate scale factor"},
                   {"OFFA", 4, E, 0, false, {}, "abscissa offset"},
                   {"OFFO", 5, E, 0, false, {}, "ordinate offset"},
                   plain("DATTYP", 6, I),
               }, "after the _TITLE card (missing: error 1316)"},
                {"point", 2, 20, per_field, {
                   {"A", 0, E, 0, false, {}, "abscissa: A x SFA + OFFA, increasing (else error 1217)"},
                   {"O", 1, E, 0, false, {}, "ordinate: O x SFO + OFFO"},
               }, "each card after card 1 (named \"curve LCID point\"; 20 columns in either format)"}},
               ""});
  t.push_back(prescribed_motion("BOUNDARY_PRESCRIBED_MOTION_NODE", "NID", false));
  t.push_back(prescribed_motion("BOUNDARY_PRESCRIBED_MOTION_SET", "NSID", false));
  t.push_back(prescribed_motion("BOUNDARY_PRESCRIBED_MOTION_RIGID", "PID", true));
}

// The loads and boundary conditions family: loads, damping and constraints, walls, initial conditions.
std::vector<KeywordSpec> loads_bcs_specs() {
  std::vector<KeywordSpec> t;
  add_load_specs(t);
  add_damping_and_spc_specs(t);
  add_wall_and_constraint_specs(t);
  add_planar_wall_specs(t);
  add_spot_weld_specs(t);
  add_initial_condition_specs(t);
  return t;
}

// A coordinate system's or vector's id: below 1 (after an *INCLUDE_TRANSFORM's offset): error
// 1201; defined twice: error 1200.
KeywordField system_id(const char* name) {
  return {name, 0, I, 0, false, {}, "id (the card is then named by it; < 1 after the *INCLUDE_TRANSFORM offset: error 1201; defined twice: error 1200)"};
}
std::vector<KeywordField> reals(std::initializer_list<const char*> names, int index0, const char* meaning) {
  std::vector<KeywordField> f;
  for (const char* n : names) f.push_back({n, index0++, E, 0, false, {}, f.empty() ? meaning : ""});
  return f;
}

// n integer fields named `name` from index0 on (ids 8 a card, 0: none).
std::vector<KeywordField> ids(const char* name, int n, int index0, const char* meaning) {
  std::vector<KeywordField> f;
  for (int k = 0; k < n; ++k) f.push_back({name, index0 + k, I, 0, false, {}, k ? "" : meaning});
  return f;
}

// The sets: card 1 (SID), then cards of members by the form.
KeywordCardLayout set_card1(bool named) {
  return {"card 1", 6, 10, per_field, {{"SID", 0, I, 0, false, {},
          named ? "set id (the cards are then named \"set SID\"; < 1 after the *INCLUDE_TRANSFORM offset: error 1201; defined twice: error 1200)"
                : "set id (defined twice: error 1200)"}}, "after the _TITLE card; missing: error 1316"};
}
// *SET_..._GENERAL cards: OPTION and 7 ids, or (a number or blank first) 8 more ids for the
// option before.
std::vector<KeywordCardLayout> general_set_cards() {
  return {{"option card", 8, 10, per_field, fields_of(std::vector<KeywordField>{
              {"OPTION", 0, FieldKind::text, 0, false, {}, "ALL, NODE, ELEM, PART, BOX, SET_SOLID, SET_SHELL, SET_BEAM, SET_TSHELL, SET_DISCRETE, SET_NODE, SET_PART; "
                                                           "a D before one removes (DNODE, ...); checked when the set is resolved"}},
              ids("E", 7, 1, "ids of the option (0: none)")),
           "a card whose first field is not a number or blank, named \"set SID\""},
          {"continuation card", 8, 10, per_field, ids("E", 8, 0, "more ids of the option before (no option before: error 1006 naming OPTION)"),
           "a card whose first field is a number or blank"}};
}
void add_sets(std::vector<KeywordSpec>& t, const char* kind, const char* member, bool general) {
  static std::deque<std::string> names;
  auto name = [&](const char* form, bool list) { return names.emplace_back(std::string(kind) + (list ? "_LIST" : "") + form).c_str(); };
  const char* each = "each card after card 1, named \"set SID\"";
  t.push_back({{name("", false), name("", true)}, KeywordFamily::sets_boxes, false,
               {set_card1(true), {"id card", 8, 10, per_field, ids(member, 8, 0, "members (0: none)"), each}}, ""});
  std::vector<KeywordField> pairs, triples;
  for (int k = 0; k < 8; k += 2) {
    pairs.push_back({"BBEG", k, I, 0, false, {}, k ? "" : "ranges BBEG..BEND (both 0: none; not 1 <= BBEG <= BEND <= 2147483647: error 1003 naming BEND)"});
    pairs.push_back({"BEND", k + 1, I, 0, false, {}, ""});
  }
  for (int k = 0; k + 2 < 8; k += 3) {
    triples.push_back({"BBEG", k, I, 0, false, {}, k ? "" : "ranges BBEG..BEND by INCR (as _GENERATE)"});
    triples.push_back({"BEND", k + 1, I, 0, false, {}, ""});
    triples.push_back({"INCR", k + 2, I, 1, false, {}, k ? "" : "increment (0: 1; < 0: error 1003)"});
  }
  t.push_back({{name("_GENERATE", false), name("_GENERATE", true)}, KeywordFamily::sets_boxes, false,
               {set_card1(true), {"range card", 8, 10, per_field, pairs, each}}, "ids in a range that no definition has are skipped"});
  t.push_back({{name("_GENERATE_INCREMENT", false), name("_GENERATE_INCREMENT", true)}, KeywordFamily::sets_boxes, false,
               {set_card1(true), {"range card", 8, 10, per_field, triples, each}}, "ids in a range that no definition has are skipped"});
  t.push_back({{name("_ADD", false), name("_ADD", true)}, KeywordFamily::sets_boxes, false,
               {set_card1(true), {"set card", 8, 10, per_field, ids("SID", 8, 0, "member sets (0: none)"), each}}, ""});
  if (!general) return;
  std::vector<KeywordCardLayout> cards = {set_card1(true)};
  for (KeywordCardLayout& c : general_set_cards()) cards.push_back(std::move(c));
  t.push_back({{name("_GENERAL", false), name("_GENERAL", true)}, KeywordFamily::sets_boxes, false, std::move(cards), ""});
}

std::vector<KeywordSpec> sets_boxes_specs() {
  const KeywordFamily F = KeywordFamily::sets_boxes;
  constexpr FieldKind A = FieldKind::text;
  std::vector<KeywordSpec> t;
  add_sets(t, "SET_NODE", "NID", true);
  add_sets(t, "SET_PART", "PID", false);
  add_sets(t, "SET_SOLID", "EID", true);
  add_sets(t, "SET_SHELL", "EID", true);
  t.push_back({{"SET_SEGMENT"}, F, false,
               {set_card1(false), {"segment card", 8, 10, per_field, fields_of(ids("N1", 1, 0, "segment nodes (N4 0: N3, a triangle)"),
                   ids("N2", 1, 1, ""), ids("N3", 1, 2, ""), ids("N4", 1, 3, "")), "each card after card 1, named \"set SID segment\""}},
               ""});
  t.push_back({{"SET_SEGMENT_ADD"}, F, false,
               {set_card1(true), {"set card", 8, 10, per_field, ids("SSID", 8, 0, "member segment sets (0: none)"), "each card after card 1, named \"set SID\""}},
               ""});
  {
    std::vector<KeywordCardLayout> cards = {set_card1(true)};
    for (KeywordCardLayout& c : general_set_cards()) cards.push_back(std::move(c));
    t.push_back({{"SET_SEGMENT_GENERAL"}, F, false, std::move(cards), "the options as for the other _GENERAL sets"});
  }
  t.push_back({{"DEFINE_COORDINATE_SYSTEM"}, F, false,
               {{"card 1", 8, 10, per_field, fields_of(std::vector<KeywordField>{system_id("CID")},
                   reals({"XO", "YO", "ZO"}, 1, "origin"), reals({"XL", "YL", "ZL"}, 4, "a point on the local x axis"),
                   std::vector<KeywordField>{{"CIDL", 7, I, 0, false, {}, "the system the points are given in (0: global)"}}),
                 "each system"},
                {"card 2", 3, 10, per_field, reals({"XP", "YP", "ZP"}, 0, "a point in the local x-y plane"),
                 "after card 1, named \"system CID card 2\"; missing: error 1316"}},
               "several systems may follow the keyword"});
  t.push_back({{"DEFINE_COORDINATE_NODES"}, F, false,
               {{"card 1", 8, 10, per_field, {
                   system_id("CID"),
                   {"N1", 1, I, 0, false, {}, "origin node"},
                   {"N2", 2, I, 0, false, {}, "a node on the local x axis"},
                   {"N3", 3, I, 0, false, {}, "a node in the local x-y plane"},
                   {"FLAG", 4, I, 0, false, {nonzero(2006, "the system is built once, from the initial node positions")}, "update with the nodes"},
                   {"DIR", 5, A, 0, false, {}, "axis along N1-N2: X or 1 (blank: X); another: error 1102"},
               }, "each system"}},
               "several systems may follow the keyword"});
  t.push_back({{"DEFINE_COORDINATE_VECTOR"}, F, false,
               {{"card 1", 8, 10, per_field, fields_of(std::vector<KeywordField>{system_id("CID")},
                   reals({"XX", "YX", "ZX"}, 1, "local x axis"), reals({"XV", "YV", "ZV"}, 4, "a vector in the local x-y plane"),
                   std::vector<KeywordField>{{"NID", 7, I, 0, false, {nonzero(2006, "the system is fixed (it does not turn with a node)")}, "a node the system turns with"}}),
                 "each system"}},
               "several systems may follow the keyword"});
  t.push_back({{"DEFINE_VECTOR"}, F, false,
               {{"card 1", 8, 10, per_field, fields_of(std::vector<KeywordField>{system_id("VID")},
                   reals({"XT", "YT", "ZT"}, 1, "tail"), reals({"XH", "YH", "ZH"}, 4, "head"),
                   std::vector<KeywordField>{{"CID", 7, I, 0, false, {}, "the system the points are given in (0: global)"}}),
                 "each vector"}},
               "several vectors may follow the keyword"});
  t.push_back({{"DEFINE_VECTOR_NODES"}, F, false,
               {{"card 1", 8, 10, per_field, {
                   system_id("VID"),
                   {"NODET", 1, I, 0, false, {}, "tail node"},
                   {"NODEH", 2, I, 0, false, {}, "head node"},
               }, "each vector"}},
               "several vectors may follow the keyword"});
  t.push_back({{"DEFINE_TRANSFORMATION"}, F, false,
               {{"card 1", 1, 10, per_field, {
                   {"TRANID", 0, I, 0, false, {below(1, 1201, "ids must be positive")},
                    "transformation id (the cards are then named by it; defined twice: error 1200)", kByReader},
               }, "the first card that is not blank; missing: error 1316"},
                {"option card", 8, 10, per_field, fields_of(std::vector<KeywordField>{
                   {"OPTION", 0, A, 0, false, {}, "TRANSL (A1-A3), SCALE (A1-A3; 0: 1) or ROTATE (axis A1-A3, zero: error 1003, through A4-A6, angle A7 in degrees); MIRROR, POINT, POS6P, POS6N, ROTATE3NA, ROTATE3NB: error 1102; another: error 1006"}},
                   reals({"A", "A", "A", "A", "A", "A", "A"}, 1, "A1-A7 (named A in messages)")),
                 "each card after card 1, composed in order, named \"transformation TRANID\""}},
               ""});
  t.push_back({{"DEFINE_BOX"}, KeywordFamily::sets_boxes, false,
               {{"", 7, 10, per_field, {
                   {"BOXID", 0, I, 0, false, {}, "box id (> 0, else error 1201; the card is then named by it; defined twice: error 1200)"},
                   {"XMN", 1, E, 0, false, {}, "bounds, a maximum below its minimum: error 1003"},
                   {"XMX", 2, E, 0, false, {}, ""},
                   {"YMN", 3, E, 0, false, {}, ""},
                   {"YMX", 4, E, 0, false, {}, ""},
                   {"ZMN", 5, E, 0, false, {}, ""},
                   {"ZMX", 6, E, 0, false, {}, ""},
               }, "the first card that is not blank (after the _TITLE card)"}},
               "one box per keyword, as in LS-DYNA"});
  return t;
}

// The contacts: *CONTACT_... card 1 (the sides), card 2 (friction, birth and death), card 3
// (penalty scales), the _ERODING_ card, optional cards A and B.  The sides' types depend on the
// keyword: checked by the family's reader (keyword_contacts.cpp).
std::vector<KeywordCardLayout> contact_cards(bool eroding) {
  std::vector<KeywordCardLayout> c = {
      {"ID card", 1, 10, per_field, {{"CID", 0, I, 0, false, {}, "contact id (the heading after it is not read)"}}, "with _ID"},
      {"card 1", 8, 10, per_field, {
          {"SURFA", 0, I, 0, false, {}, "side A: segment set, part set, part or node set by SURFATYP (single surface: 0 all parts)"},
          {"SURFB", 1, I, 0, false, {}, "side B (single surface: not 0 warning 2006, ignored)"},
          {"SURFATYP", 2, I, 0, false, {}, "0 segment set, 2 part set, 3 part; 4 node set (nodes to surface, force transducer); "
                                           "5 all parts (single surface); others: error 1104"},
          {"SURFBTYP", 3, I, 0, false, {}, "0 segment set, 2 part set, 3 part (force transducer: 4 node set too); others: error 1104"},
          {"SABOXID", 4, I, 0, false, {}, "only side A's segments whose centroid is in this box"},
          {"SBBOXID", 5, I, 0, false, {}, "only side B's segments in this box"},
          {"SAPR", 6, I, 0, false, {}, "1: side A in the interface-force database (force transducer: not 0 warning 2006)"},
          {"SBPR", 7, I, 0, false, {}, "1: side B in the interface-force database"},
      }, "after the ID or heading card; missing: error 1316"},
      {"card 2", 8, 10, per_field, {
          checked_after({"FS", 0, E, 0, false, {below(0, 1219)}, "static friction coefficient"}, 2),
          checked_after({"FD", 1, E, 0, false, {below(0, 1219)}, "dynamic friction coefficient"}, 2),
          {"DC", 2, E, 0, false, {below(0, 1003, "must not be negative")}, "exponential decay coefficient"},
          {"VC", 3, E, 0, false, {nonzero(2006, "viscous friction limit")}, "viscous friction limit"},
          {"VDC", 4, E, 0, false, {nonzero(2006, "viscous contact damping")}, "viscous contact damping"},
          plain("PENCHK", 5, I),
          {"BT", 6, E, 0, false, {nonzero(1102, "contact birth time")}, "birth time"},
          {"DT", 7, E, 0, false, {inside(0, 0, 0, nullptr), below(1e20, 1102, "contact death time")}, "death time (0 or >= 1e20: none)"},
      }, "when given"},
      {"card 3", 8, 10, per_field, {
          checked_after({"SFSA", 0, E, 1.0, true, {below(0, 1003, "must be positive")}, "penalty scale factor of both sides"}, 1),
          {"SFSB", 1, E, 1.0, true, {}, "other than SFSA: warning 2006 (one penalty scale per interface: SFSA is used for both sides)"},
      }, "when given"},
      {"optional card A", 8, 10, per_field, {
          {"SOFT", 0, I, 0, false, {}, "0 penalty, 1 soft constraint, 2 segment-based (surface-to-surface and single-surface contacts; nodes to surface: error 1102), -1 maximum stable stiffness (IMPACT-3D); 4, 6: error 1102; others: error 1006"},
          {"SOFSCL", 1, E, 0.1, true, {below(0, 1003, "must be positive")}, "scale factor of the soft constraint (SOFT 1; no effect on SOFT 2, as in LS-DYNA)"},
          {"LCIDAB", 2, I, 0, false, {nonzero(1102, "airbag fabric thickness curve of the soft constraint")}, "airbag thickness curve"},
          {"MAXPAR", 3, E, 0, false, {neither(0, 1.025, 1102, "a parametric search extension other than the default 1.025 (IMPACT-3D extends a segment by 1 %)")},
           "parametric search extension"},
          plain("SBOPT", 4, I, "SOFT 2: 0, 2, 3 (segments as bilinear patches); 1, 4, 5 error 1102; other SOFT: no effect"),
          plain("DEPTH", 5, I, "SOFT 2: 0, 1, 2 (surface penetrations); others (edge-to-edge) error 1102; other SOFT: no effect"),
          plain("BSORT", 6, I, "read, no effect here (IMPACT-3D sorts every cycle)"),
          {"FRCFRQ", 7, I, 0, false, {neither(0, 1, 1102, "contact forces updated every FRCFRQ cycles (IMPACT-3D updates them every cycle)")},
           "cycles between contact force updates"},
      }, eroding ? "after the _ERODING_ card, when given" : "after card 3, when given"},
      {"optional card B", 8, 10, per_field, {
          {"PENMAX", 0, E, 0, false, {nonzero(1102, "a maximum penetration (IMPACT-3D: half the segment's element, README \"Contact\")")}, "maximum penetration"},
          {"THKOPT", 1, I, 0, false, {}, "0 *CONTROL_CONTACT's SHLTHK, 1 SHLTHK of this card, 2 no shell thickness; others: error 1006"},
          {"SHLTHK", 2, I, 0, false, {}, "0 shells at their mid-surface, 1 at +-t/2 except rigid shells, 2 at +-t/2; others: error 1006"},
          {"SNLOG", 3, I, 0, false, {neither(0, 1, 1006, "0 or 1")}, "shooting-node logic (none here: 0 and 1 alike)"},
          {"ISYM", 4, I, 0, false, {neither(0, 1, 1006, "0 off, 1 no solid faces whose nodes are all constrained along the face's normal")},
           "1: a side made of parts (SURFATYP 2, 3, 5) leaves out the solids' faces on a symmetry plane (every node constrained along the face's axis-aligned normal)"},
          {"I2D3D", 5, I, 0, false, {nonzero(1102, "segment search order of shells and solids")}, "search order of shells and solids"},
          {"SLDTHK", 6, E, 0, false, {nonzero(1102, "a contact thickness of solids")}, "contact thickness of solids"},
          {"SLDSTF", 7, E, 0, false, {nonzero(1102, "a contact stiffness of solids")}, "contact stiffness of solids"},
      }, "after optional card A, when given"},
  };
  // card 3's fields 3-8 are read as numbers under one name (as messages have always named them)
  for (int k = 2; k < 8; ++k) c[3].fields.push_back(plain("SAST/SBST/SFSAT/SFSBT/FSF/VSF", k, E, k == 2 ? "SAST, SBST, SFSAT, SFSBT, FSF, VSF: read, no effect here" : ""));
  if (eroding)
    c.insert(c.begin() + 4, {"eroding card", 8, 10, per_field, {
        {"ISYM", 0, I, 0, false, {neither(0, 1, 1006, "0 off, 1 no solid faces whose nodes are all constrained along the face's normal")},
         "1: as optional card B's ISYM (either card's 1 turns it on)"},
        {"EROSOP", 1, I, 0, false, {neither(0, 1, 1006, "0 exterior faces only, 1 faces exposed by failed solids join")},
         "0 exterior faces only, 1 faces exposed by failed solids join the surface"},
        {"IADJ", 2, I, 0, false, {nonzero(2006, "shell edges do not join an eroding surface")}, "adjacent shell edges"},
    }, "after card 3 (missing: error 1316, the contact is dropped)"});
  return c;
}

// A tied contact's cards: as the others', card 3 field 3 SAST its own (negative: the reach of
// the ties); friction, penalty and thickness have no effect on a tie.
std::vector<KeywordCardLayout> tied_contact_cards() {
  std::vector<KeywordCardLayout> c = contact_cards(false);
  c[3].fields[2] = {"SAST", 2, E, 0, false, {outside(-kInf, 0, 2006, "a positive contact thickness does not change a tie's reach (a negative SAST sets it)")},
                    "negative: its magnitude is how far from a master segment a slave node is tied (0: 5 % of the segment's shorter diagonal)"};
  return c;
}

std::vector<KeywordSpec> contact_specs() {
  const KeywordFamily F = KeywordFamily::contacts;
  return {{{"CONTACT_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", "CONTACT_NODES_TO_SURFACE",
            "CONTACT_AUTOMATIC_NODES_TO_SURFACE", "CONTACT_AUTOMATIC_SINGLE_SURFACE", "CONTACT_FORCE_TRANSDUCER_PENALTY",
            "CONTACT_SINGLE_SURFACE", "CONTACT_ONE_WAY_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE",
            "CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE"},
           F, false, contact_cards(false),
           "one contact a keyword; _ID: the ID card first, _TITLE: a heading card first (not read); automatic, forming and single-surface "
           "contacts take the shells' thickness always (docs/contact.md); *CONTACT_SINGLE_SURFACE reads as the automatic single surface, "
           "the _ONE_WAY_SURFACE_TO_SURFACE forms as nodes-to-surface of the slave surface's nodes"},
          {{"CONTACT_ERODING_SURFACE_TO_SURFACE", "CONTACT_ERODING_NODES_TO_SURFACE", "CONTACT_ERODING_SINGLE_SURFACE"},
           F, false, contact_cards(true),
           "one contact a keyword, as the others with the _ERODING_ card after card 3"},
          {{"CONTACT_SPOTWELD", "CONTACT_SPOTWELD_WITH_TORSION", "CONTACT_TIED_NODES_TO_SURFACE", "CONTACT_TIED_SURFACE_TO_SURFACE",
            "CONTACT_TIED_SHELL_EDGE_TO_SURFACE"}, F, false, tied_contact_cards(),
           "constraint-based ties: each slave node (SURFA: node set, or the nodes of a segment set or parts, beams' too) "
           "projected onto a master segment (SURFB) when read and moved with it; the rotations tied too by the spot welds and "
           "_SHELL_EDGE_TO_SURFACE (translations only: _NODES_, _SURFACE_TO_SURFACE); a spot weld's rotation about the segment's "
           "normal free (_SPOTWELD) or tied to the segment's in-plane spin (_WITH_TORSION) (docs/contact.md \"Tied contacts\")"},
          {{"CONTACT_TIED_NODES_TO_SURFACE_OFFSET", "CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET", "CONTACT_TIED_NODES_TO_SURFACE_CONSTRAINED_OFFSET",
            "CONTACT_TIED_SURFACE_TO_SURFACE_CONSTRAINED_OFFSET"},
           F, false, tied_contact_cards(),
           "ties that keep each slave node's offset (not moved; translations only): _OFFSET a penalty spring holding the offset along "
           "the segment's turning normal, _CONSTRAINED_OFFSET the constraint tie with the offset kept as a fixed vector "
           "(docs/contact.md \"Tied contacts\")"}};
}

// A card of one id and a heading in fixed columns (10 and 70, also in long format).
KeywordCardLayout id_and_heading(const char* name, const char* meaning, const char* when) {
  KeywordCardLayout c{"", 2, 10, per_field, {{name, 0, I, 0, false, {}, meaning},
                                            {"HEADING", 1, FieldKind::text, 0, false, {}, "not read"}}, when, {10, 70}};
  c.fixed = true;
  return c;
}

// *DATABASE_HISTORY_...: the nodes, elements or sets of the time-history databases.
void add_history_specs(std::vector<KeywordSpec>& t) {
  const KeywordFamily F = KeywordFamily::control_database;
  const char* const every = "one or more cards (blank cards skipped)";
  t.push_back({{"DATABASE_HISTORY_NODE"}, F, false, {{"", 8, 10, per_field, ids("NID", 8, 0, "node ids (0: none)"), every}}, ""});
  t.push_back({{"DATABASE_HISTORY_SOLID", "DATABASE_HISTORY_SHELL", "DATABASE_HISTORY_BEAM"}, F, false,
               {{"", 8, 10, per_field, ids("EID", 8, 0, "element ids of the keyword's kind (0: none)"), every}}, ""});
  t.push_back({{"DATABASE_HISTORY_NODE_SET", "DATABASE_HISTORY_SOLID_SET"}, F, false,
               {{"", 8, 10, per_field, ids("ID", 8, 0, "node or solid set ids (0: none)"), every}}, ""});
  t.push_back({{"DATABASE_HISTORY_NODE_ID"}, F, false, {id_and_heading("NID", "node id (0: none)", "one node a card (blank cards skipped)")}, ""});
  t.push_back({{"DATABASE_HISTORY_SOLID_ID", "DATABASE_HISTORY_SHELL_ID", "DATABASE_HISTORY_BEAM_ID"}, F, false,
               {id_and_heading("EID", "element id (0: none)", "one element a card (blank cards skipped)")}, ""});
}

// *TITLE and *COMMENT: read as text, never as fields (no message about their characters).
void add_title_specs(std::vector<KeywordSpec>& t) {
  const KeywordFamily F = KeywordFamily::control_database;
  KeywordCardLayout title{"", 1, 80, per_field, {{"TITLE", 0, FieldKind::text, 0, false, {}, "the problem's title, as written (right blanks dropped)"}},
                          "the first card; the cards after it are not read"};
  title.fixed = true;
  t.push_back({{"TITLE"}, F, false, {title}, "given again: the last one is used"});
  t.push_back({{"COMMENT"}, F, false, {},
               "ignored, as by LS-DYNA, except the lines the converter writes for fields LS-DYNA has no keyword for (upper or lower "
               "case, words between blanks): IMPACT-3D INTERFACE_SEGMENTS n, IMPACT-3D VISCOSITY_FLAG n, IMPACT-3D REACTION_PRINT_FLAG n, "
               "IMPACT-3D INITIALLY_ELASTIC PART pid; any other line that starts with IMPACT-3D: error 1312"});
}

std::vector<KeywordSpec> control_database_specs() {
  std::vector<KeywordSpec> t;
  add_history_specs(t);
  add_title_specs(t);
  t.push_back({{"CONTROL_TERMINATION"}, KeywordFamily::control_database, true,
               {{"", 6, 10, per_field, {
                   {"ENDTIM", 0, E, 0, false, {outside(0, kInf, 1214, nullptr, true)}, "termination time (required)"},
                   {"ENDCYC", 1, I, 0, false, {outside(0, 2147483647.0, 1003, "must be 0 (no limit) or a cycle count")}, "termination cycle (0: none)"},
                   {"DTMIN", 2, E, 0, false, {outside(0, 1, 1003, "must be in [0, 1)", false, true)}, "minimum step factor"},
                   {"ENDENG", 3, E, 0, false, {nonzero(1102, "termination by energy change")}, "energy change limit"},
                   {"ENDMAS", 4, E, 0, false, {below(0, 1003, "must not be negative (0 or blank: no limit)")}, "mass change limit, percent (1e8 or more: none)"},
                   plain("NOSOL", 5, I),
               }, ""}},
               "card 1 missing: error 1316; no *CONTROL_TERMINATION: error 1311"});
  t.push_back({{"CONTROL_TIMESTEP"}, KeywordFamily::control_database, true,
               {{"card 1", 8, 10, per_field, {
                   {"DTINIT", 0, E, 0, false, {below(0, 1003, "must not be negative")}, "initial time step (0: computed)"},
                   {"TSSFAC", 1, E, 0.9, true, {outside(0, 1, 1215, nullptr, true)}, "time-step scale factor"},
                   plain("ISDO", 2, I),
                   {"TSLIMT", 3, E, 0, false, {nonzero(2006, "shell time-step limit")}, "shell time-step limit"},
                   {"DT2MS", 4, E, 0, false, {}, "mass scaling time step"},
                   {"LCTM", 5, I, 0, false, {nonzero(1102, "time-step limit from a load curve")}, "time-step limit curve"},
                   {"ERODE", 6, I, 0, false, {outside(0, 1, 1006, "0 (the run ends below DTMIN) or 1 (solids below DTMIN x the first step are deleted)")}, "1: delete solids below DTMIN x the first step"},
                   {"MS1ST", 7, I, 0, false, {outside(0, 1, 1006, "0 (mass scaling every cycle) or 1 (the first cycle only)")}, "1: mass scaling on the first cycle only"},
               }, ""}},
               ""});
  t.push_back({{"CONTROL_CONTACT"}, KeywordFamily::control_database, true,
               {{"card 1", 8, 10, per_field, {
                   {"SLSFAC", 0, E, 0.1, true, {below(0, 1003, "must be positive")}, "penalty scale factor"},
                   {"SHLTHK", 3, I, 0, false, {outside(0, 2, 1006, "0 shells at their mid-surface, 1 at +-t/2 except rigid shells, 2 at +-t/2")}, "shell thickness in non-automatic contacts"},
                   {"PENOPT", 4, I, 1, true, {inside(4, 5, 1102, "area- or mass-weighted node stiffness (IMPACT-3D has 1 the smaller, 2 the segment's, 3 the node's)"),
                                              outside(1, 5, 1006, "1 the smaller of segment and node stiffness, 2 the segment's, 3 the node's")}, "penalty stiffness"},
               }, "when given"}},
               ""});
  t.push_back({{"CONTROL_OUTPUT"}, KeywordFamily::control_database, true,
               {{"card 1", 8, 10, per_field, {
                   {"IKEDIT", 6, I, 100, true, {below(0, 1003, "must not be negative")}, "run-log interval, cycles"},
               }, "when given"}},
               ""});
  t.push_back({{"CONTROL_HOURGLASS"}, KeywordFamily::control_database, true,
               {{"", 2, 10, after_card, {
                   {"IHQ", 0, I, 0, false, {inside(6, 10, 1102, "hourglass type %v (IMPACT-3D has 0/1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness)"),
                                            inside(-10, -1, 1102, "hourglass type %v (IMPACT-3D has 0/1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness)"),
                                            outside(0, 5, 1006, "0/1 viscous, 2/3 Flanagan-Belytschko viscous, 4/5 stiffness")}, "hourglass type of parts without HGID"},
                   {"QH", 1, E, 0.1, true, {below(0, 1220)}, "hourglass coefficient"},
               }, "when given"}},
               ""});
  t.push_back({{"CONTROL_BULK_VISCOSITY"}, KeywordFamily::control_database, true,
               {{"", 5, 10, after_card, {
                   {"Q1", 0, E, 1.5, false, {below(0, 1220)}, "quadratic coefficient"},
                   {"Q2", 1, E, 0.06, false, {below(0, 1220)}, "linear coefficient"},
                   {"TYPE", 2, I, 1, false, {outside(-2, 1, 1006, "1 standard (-1, -2 differ only for shells)")}, "standard for solids"},
               }, "when given"}},
               ""});
  t.push_back({{"CONTROL_SHELL"}, KeywordFamily::control_database, true,
               {{"card 1", 8, 10, per_field, {
                   plain("WRPANG", 0, E),
                   {"ESORT", 1, I, 0, false, {nonzero(2006, "triangles are always degenerate Belytschko-Tsay quadrilaterals")}, "triangle sorting"},
                   plain("IRNXX", 2, I),
                   {"ISTUPD", 3, I, 0, false, {nonzero(2006, "the shell thickness stays constant")}, "thickness update"},
                   {"THEORY", 4, I, 2, false, {neither(0, 2, 1102, "shell theory %v; only 2 (Belytschko-Tsay)")}, "shell theory"},
                   {"BWC", 5, I, 2, false, {inside(1, 1, 2006, "no warping stiffness for Belytschko-Tsay shells")}, "warping stiffness"},
                   {"MITER", 6, I, 1, false, {inside(3, 3, 2006, "plane-stress plasticity is always iterated to sigma_zz = 0")}, "plane-stress plasticity"},
                   plain("PROJ", 7, I),
               }, "when given"},
                {"card 2", 8, 10, per_field, {
                   {"ROTASCL", 0, E, 1.0, true, {below(0, 1003, "rotary inertia scale factor must be positive")}, "rotary inertia scale factor"},
                   {"INTGRD", 1, I, 0, false, {nonzero(1102, "Lobatto integration through the thickness")}, "through-thickness integration"},
                   plain("LAMSHT", 2, I),
                   plain("CSTYP6", 3, I),
                   plain("TSHELL", 4, I),
               }, "when given"}},
               ""});
  t.push_back(binary_database("DATABASE_BINARY_D3PLOT", "plot interval from a load curve", "plot interval (0: ENDTIM/20)"));
  t.push_back(binary_database("DATABASE_BINARY_D3THDT", "time-history interval from a load curve", "time-history interval (before the ASCII keywords' DT)"));
  t.push_back(binary_database("DATABASE_BINARY_INTFOR", "interface-force interval from a load curve", "interface-force database interval (0: the plot interval)"));
  t.push_back({{"DATABASE_BINARY_D3DUMP", "DATABASE_BINARY_RUNRSF"}, KeywordFamily::control_database, true,
               {{"card 1", 2, 10, per_field, {
                   {"CYCL", 0, E, 0, false, {outside(0, 2e9, 1003, "cycles between dumps, >= 0")}, "cycles between restart dumps"},
               }, "when given"}},
               ""});
  t.push_back({{"DATABASE_GLSTAT", "DATABASE_MATSUM", "DATABASE_NODOUT", "DATABASE_ELOUT", "DATABASE_RCFORC",
                "DATABASE_RWFORC", "DATABASE_SPCFORC", "DATABASE_NCFORC", "DATABASE_SLEOUT", "DATABASE_RBDOUT",
                "DATABASE_BNDOUT", "DATABASE_NODFOR", "DATABASE_DEFORC", "DATABASE_SECFORC", "DATABASE_ABSTAT",
                "DATABASE_JNTFORC", "DATABASE_SBTOUT", "DATABASE_SWFORC", "DATABASE_SPHOUT", "DATABASE_TPRINT"},
               KeywordFamily::control_database, false,
               {{"card 1", 4, 10, per_field, {
                   {"DT", 0, E, 0, false, {below(0, 1221)}, "output interval (NODOUT, ELOUT, GLSTAT: the time-history interval; NCFORC: the interface output; SPCFORC > 0: reactions printed)"},
               }, "when given"}},
               ""});
  t.push_back(ignored("CONTROL_ENERGY", "IMPACT-3D always computes all energies"));
  t.push_back(ignored("KEYWORD_ID", "the model identification (project, number, stage) is not used"));
  t.push_back(ignored("DATABASE_EXTENT_BINARY", "IMPACT-3D writes its fixed set of plot variables"));
  t.push_back(ignored("CONTROL_PARALLEL", "threads are set on the command line (ncpu=); results do not depend on them"));
  t.push_back(ignored("CONTROL_ACCURACY", "no accuracy options for solids here (invariant numbering and objective updates are for shells and fully integrated elements)"));
  t.push_back(ignored("CONTROL_SOLID", "solids are always the one-point hexahedron (degenerate shapes included)"));
  t.push_back(ignored("CONTROL_SOLUTION", "structural analysis only (SOLN 0)",
                      {{"card 1", 8, 10, per_field, {
                          {"SOLN", 0, I, 0, false, {nonzero(1102, "thermal and coupled thermal-structural analysis")}, "analysis type"},
                      }, "when given"}}));
  t.push_back(ignored("DATABASE_FORMAT", "the plot database is always the LS-DYNA binary layout (8-byte words: plotwords=8 on the command line)"));
  t.push_back(ignored("CONTROL_MPP_*", "MPP decomposition controls have no effect on a shared-memory run"));
  t.push_back(ignored("CONTROL_CPU", "no CPU-time limit (CPUTIM): the run ends at its termination time or cycle"));
  t.push_back(ignored("CONTROL_UNITS", "the unit names label the model; IMPACT-3D converts nothing (the deck's numbers are used as they are)"));
  // LS-DYNA's older name (versions 940-950) of *CONTROL_DYNAMIC_RELAXATION: the dynamic
  // relaxation controls, which act only when a curve asks for dynamic relaxation (SIDR, itself
  // warning 2006) or IDRFLG does
  t.push_back(ignored("CONTROL_DAMPING", "the dynamic relaxation controls (LS-DYNA's older name of *CONTROL_DYNAMIC_RELAXATION): IMPACT-3D has no dynamic relaxation phase, and with IDRFLG 0 none is asked for",
                      {{"card 1", 8, 10, per_field, {
                          plain("NRCYCK", 0, I), plain("DRTOL", 1, E), plain("DRFCTR", 2, E), plain("DRTERM", 3, E),
                          plain("TSSFDR", 4, E), plain("IRELAL", 5, I), plain("EDTTL", 6, E),
                          {"IDRFLG", 7, I, 0, false, {nonzero(1102, "dynamic relaxation (IDRFLG): the run starts from the deck's state")}, "dynamic relaxation flag"},
                      }, "when given"}}));
  t.push_back(ignored("DATABASE_NODAL_FORCE_GROUP", "the nodal force group output (nodfor) is not written"));
  return t;
}

bool matches(const char* pattern, std::string_view name) {
  const std::string_view p(pattern);
  if (!p.empty() && p.back() == '*') return name.substr(0, p.size() - 1) == p.substr(0, p.size() - 1);
  return name == p;
}

std::string number(double v) {
  if (v == kInf) return "inf";
  std::ostringstream os;
  os << std::setprecision(12) << v;
  return os.str();
}

}  // namespace

bool KeywordCheck::fires(double v) const {
  switch (test) {
    case outside: return !((lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi));
    case inside: return v >= lo && v <= hi;
    case neither: return v != lo && v != hi;
    case not_whole: return !(v == std::floor(v) && v >= lo && v <= hi);
  }
  return false;
}

std::string KeywordCheck::text() const {
  switch (test) {
    case outside:
      if (hi == kInf && !lo_open) return "< " + number(lo);
      if (hi == kInf) return "<= " + number(lo);
      if (lo == 0 && hi == 0) return "not 0";
      return std::string("not in ") + (lo_open ? "(" : "[") + number(lo) + ", " + number(hi) + (hi_open ? ")" : "]");
    case inside: return lo == hi ? number(lo) : number(lo) + " to " + number(hi);
    case neither: return "not " + number(lo) + " or " + number(hi);
    case not_whole: return lo == -kInf ? "not a whole number <= " + number(hi) : "not a whole number >= " + number(lo);
  }
  return {};
}

const KeywordField& KeywordCardLayout::field(std::string_view name) const {
  for (const KeywordField& f : fields)
    if (name == f.name) return f;
  throw std::logic_error("keyword card table: no field " + std::string(name));
}

std::vector<int> KeywordCardLayout::columns(bool long_fmt, bool i10) const {
  std::vector<int> w = widths.empty() ? std::vector<int>(std::size_t(count), width) : widths;
  if (fixed) return w;
  for (int& c : w) c = long_fmt ? 20 : i10 && c == 8 ? 10 : c;
  return w;
}

int KeywordCardLayout::check_point(const KeywordField& f) const {
  if (f.checked_after >= 0 || f.checked_after == kByReader) return f.checked_after;
  return order == CheckOrder::after_card && !fields.empty() ? fields.back().index : f.index;
}

const KeywordCardLayout& KeywordSpec::card(std::string_view label, std::string_view when) const {
  for (const KeywordCardLayout& c : cards)
    if (label == c.card && (when.empty() || when == c.when)) return c;
  throw std::logic_error(std::string("keyword card table: ") + names.front() + " has no " + std::string(label));
}

const std::vector<KeywordSpec>& all_keyword_specs() {
  static const std::vector<KeywordSpec> t = [] {
    std::vector<KeywordSpec> all = deck_specs();
    for (KeywordSpec& s : nodes_elements_specs()) all.push_back(std::move(s));
    for (KeywordSpec& s : parts_sections_specs()) all.push_back(std::move(s));
    for (KeywordSpec& s : materials_specs()) all.push_back(std::move(s));
    for (KeywordSpec& s : sets_boxes_specs()) all.push_back(std::move(s));
    for (KeywordSpec& s : loads_bcs_specs()) all.push_back(std::move(s));
    for (KeywordSpec& s : contact_specs()) all.push_back(std::move(s));
    for (KeywordSpec& s : control_database_specs()) all.push_back(std::move(s));
    return all;
  }();
  return t;
}

const KeywordSpec* find_keyword_spec(std::string_view name) {
  for (const KeywordSpec& s : all_keyword_specs())
    for (const char* n : s.names)
      if (matches(n, name)) return &s;
  return nullptr;
}

std::string keyword_tables_markdown() {
  std::ostringstream os;
  for (const KeywordSpec& s : all_keyword_specs()) {
    os << "### ";
    for (std::size_t k = 0; k < s.names.size(); ++k) os << (k ? ", " : "") << "`*" << s.names[k] << "`";
    os << "\n\n";
    if (s.family == KeywordFamily::ignored) os << "Read and ignored (warning 2008): " << s.note << ".\n\n";
    else if (s.note[0]) os << s.note << ".\n\n";
    if (s.once) os << "Given more than once: warning 2010, the last one is used.\n\n";
    for (const KeywordCardLayout& c : s.cards) {
      const std::vector<int> w = c.columns(false, false);
      os << "**" << (c.card[0] ? c.card : "card 1") << "**" << (c.when[0] ? std::string(" (") + c.when + ")" : std::string()) << ": ";
      if (c.words) {
        os << "words separated by blanks (in any columns)";
      } else if (c.widths.empty()) {
        os << c.count << (c.count == 1 ? " field of " : " fields of ") << c.width << " columns";
      } else {
        os << c.count << " fields of";
        for (std::size_t k = 0; k < w.size(); ++k) os << (k ? ", " : " ") << w[k];
        os << " columns";
      }
      os << (c.words ? ""
             : c.fixed ? " (the same in long format)"
             : c.width == 8 || (!c.widths.empty() && c.columns(false, true) != w) ? " (8-column fields 10 in I10 format; 20 in long format)"
                                                                                   : " (20 in long format)");
      if (c.order == CheckOrder::after_card) os << "; checked once the card is read";
      os << "\n\n| field | columns | kind | blank | meaning | checks |\n|---|---|---|---|---|---|\n";
      for (const KeywordField& f : c.fields) {
        int c1 = 1;
        for (int k = 0; !c.words && k < f.index; ++k) c1 += w[std::size_t(k)];
        os << "| " << f.name << " | " << (c.words ? std::string("-") : std::to_string(c1) + "-" + std::to_string(c1 + w[std::size_t(f.index)] - 1))
           << " | "
           << (f.kind == FieldKind::real ? "E" : f.kind == FieldKind::text ? "A" : "I")
           << " | " << number(f.blank) << (f.zero_is_blank ? " (also for 0)" : "") << " | " << f.meaning << " | ";
        for (std::size_t k = 0; k < f.checks.size(); ++k) {
          const KeywordCheck& ch = f.checks[k];
          if (ch.id == 0) {
            os << (k ? "; " : "") << ch.text() << ": accepted";
            continue;
          }
          const MessageDef& m = message_def(ch.id);
          os << (k ? "; " : "") << ch.text() << ": " << (m.severity == Severity::error ? "error " : "warning ") << ch.id;
          if (ch.detail) {
            std::string d = ch.detail;
            if (const std::size_t p = d.find("%v"); p != std::string::npos) d.replace(p, 2, "N");
            os << " (" << d << ")";
          }
        }
        os << " |\n";
      }
      os << "\n";
    }
  }
  return os.str();
}

}  // namespace impact3d
