// LS-DYNA keyword-deck reader, the orchestrator.  Three passes: the deck and its *INCLUDE files
// are cut into keyword blocks (keyword_include.cpp: keyword line + data lines, '$' comments
// dropped; the *CASE to read selected, keyword_cases.cpp), every block goes to the family
// that reads it by its tables into records (keyword_<family>.cpp; *PARAMETER first,
// keyword_parameters.cpp), and the families' resolve
// steps turn the records into the Model in their order (keyword_include_transform.cpp, then
// keyword_<family>_resolve.cpp, sharing a ResolveContext): ids renumbered 1..N, parts ->
// materials, sets -> nodes and segments, contacts -> sliding interfaces.  Every problem is
// reported, with file, line, keyword/card, field and columns, through the message catalog.
// docs/keyword-decks.md lists the keywords and fields.

#include "impact3d/input/keyword_reader.h"
#include "impact3d/input/keyword_resolve.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/coordinate_systems.h"

#include <algorithm>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace impact3d {

namespace {

using namespace kw;

class KeywordReader {
 public:
  KeywordReader(DeckFile& deck, Model& m, Diagnostics& diag, const KeywordOptions& opt)
      : main_(deck), m_(m), diag_(diag), opt_(opt) {}

  void read() {
    scan_deck(main_, ctx_, m_, deck_);  // keyword_include.cpp
    select_case(deck_.blocks, deck_.cases, opt_.case_id, main_.name(), ctx_, m_);  // keyword_cases.cpp
    read_parameters(deck_.blocks, params_, diag_);  // keyword_parameters.cpp
    parse_blocks();
    ResolveContext rc{m_, diag_, main_.name(), me_, ps_, mt_, sb_, ld_, ctl_, contacts_, refused_};
    apply_include_transforms(rc, deck_.transforms);  // keyword_include_transform.cpp
    report_unsupported();
    for (Block& b : deck_.blocks) release(b.data);  // read: the lines are not needed by block any more
    resolve(rc);
  }

 private:
  DeckFile& main_;
  Model& m_;
  Diagnostics& diag_;
  KeywordOptions opt_;
  ScannedDeck deck_;  // the blocks of the deck and its *INCLUDE files (keyword_include.cpp)
  ParamTable params_;  // *PARAMETER values

  // the families' records (keyword_families.h)
  KeywordMesh me_;        // nodes and elements (keyword_nodes_elements.cpp)
  KeywordParts ps_;       // parts, sections, hourglass (keyword_parts_sections.cpp)
  KeywordMaterials mt_;   // materials, equations of state, erosion (keyword_materials.cpp)
  KeywordSetsBoxes sb_;   // sets, boxes, coordinate systems (keyword_sets_boxes.cpp)
  KeywordLoads ld_;       // loads, prescribed motions, damping, initial conditions, constraints (keyword_loads_bcs.cpp)
  KeywordControls ctl_;   // control and database cards, histories, *TITLE, *COMMENT (keyword_control_database.cpp)
  std::vector<RContact> contacts_;  // (keyword_contacts.cpp)
  std::vector<const Block*> unsupported_;  // blocks no family reads
  RefusedKeywords refused_;  // what they define (keyword_resolve.h)

  // the families' shared state; ids they define get their file's *INCLUDE_TRANSFORM offset by
  // kind: n nodes, e elements, p parts, m materials, s sets, f curves, d boxes and systems,
  // r sections, hourglass and EOS
  KeywordContext ctx_{diag_, params_, {}, [this](int id, const Block& b, char kind) {
                        return xid(id, b, kind == 'n' ? &IncludeTransform::idnoff : kind == 'e' ? &IncludeTransform::ideoff
                                            : kind == 'p' ? &IncludeTransform::idpoff : kind == 'm' ? &IncludeTransform::idmoff
                                            : kind == 's' ? &IncludeTransform::idsoff : kind == 'f' ? &IncludeTransform::idfoff
                                            : kind == 'd' ? &IncludeTransform::iddoff : &IncludeTransform::idroff);
                      }};

  // ---------------------------------------------------------------- pass 1: blocks
  // keyword_include.cpp (scan_deck), keyword_cases.cpp (select_case), keyword_parameters.cpp
  // (read_parameters: *PARAMETER and *PARAMETER_EXPRESSION first, so that a reference may come
  // before or after its definition)

  // ---------------------------------------------------------------- pass 2: parse blocks
  // Field widths for a card of n fields of width w (standard), 20 in long format.
  static std::vector<int> W(const Block& b, int n, int w = 10) { return std::vector<int>(std::size_t(n), b.long_fmt ? 20 : w); }

  // Strips the _TITLE / _ID options the supported keywords know.
  static std::string base_name(const std::string& n, bool& title, bool& id) {
    auto ends = [&](const char* s) {
      std::size_t k = std::char_traits<char>::length(s);
      return n.size() > k && n.compare(n.size() - k, k, s) == 0;
    };
    static const std::set<std::string> titled = {
        "SECTION_SOLID", "SECTION_SHELL", "SECTION_BEAM", "HOURGLASS", "DEFINE_CURVE", "SET_NODE_LIST", "SET_NODE", "SET_PART_LIST",
        "SET_PART", "SET_SEGMENT", "SET_NODE_LIST_GENERATE", "CONTACT_SURFACE_TO_SURFACE",
        "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE", "CONTACT_NODES_TO_SURFACE", "CONTACT_FORCE_TRANSDUCER_PENALTY",
        "CONTACT_AUTOMATIC_SINGLE_SURFACE", "CONTACT_AUTOMATIC_NODES_TO_SURFACE", "CONTACT_ERODING_SURFACE_TO_SURFACE",
        "CONTACT_ERODING_NODES_TO_SURFACE", "CONTACT_ERODING_SINGLE_SURFACE", "CONTACT_SPOTWELD", "CONTACT_SPOTWELD_WITH_TORSION", "CONTACT_TIED_NODES_TO_SURFACE", "CONTACT_TIED_SURFACE_TO_SURFACE", "CONTACT_TIED_SHELL_EDGE_TO_SURFACE",
        "CONTACT_TIED_NODES_TO_SURFACE_OFFSET", "CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET", "CONTACT_TIED_NODES_TO_SURFACE_CONSTRAINED_OFFSET", "CONTACT_TIED_SURFACE_TO_SURFACE_CONSTRAINED_OFFSET",
        "CONTACT_SINGLE_SURFACE", "CONTACT_ONE_WAY_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE",
        "CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE",
        // issue 16: sets, boxes, coordinate systems
        "SET_NODE_ADD", "SET_NODE_GENERAL", "SET_NODE_LIST_GENERATE_INCREMENT", "SET_PART_ADD",
        "SET_PART_LIST_GENERATE", "SET_PART_LIST_GENERATE_INCREMENT", "SET_SOLID", "SET_SOLID_LIST",
        "SET_SOLID_GENERATE", "SET_SOLID_LIST_GENERATE", "SET_SOLID_GENERATE_INCREMENT", "SET_SOLID_ADD",
        "SET_SOLID_GENERAL", "SET_SHELL", "SET_SHELL_LIST", "SET_SHELL_GENERATE", "SET_SHELL_LIST_GENERATE",
        "SET_SHELL_GENERATE_INCREMENT", "SET_SHELL_ADD", "SET_SHELL_GENERAL", "SET_SEGMENT_ADD", "SET_SEGMENT_GENERAL", "DEFINE_BOX",
        "DEFINE_COORDINATE_SYSTEM", "DEFINE_COORDINATE_NODES", "DEFINE_COORDINATE_VECTOR", "DEFINE_VECTOR",
        "DEFINE_VECTOR_NODES", "DEFINE_TRANSFORMATION", "MAT_ADD_EROSION"};
    static const std::set<std::string> with_id = {
        "RIGIDWALL_PLANAR", "RIGIDWALL_PLANAR_MOVING", "CONTACT_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_SURFACE_TO_SURFACE",
        "CONTACT_NODES_TO_SURFACE", "CONTACT_FORCE_TRANSDUCER_PENALTY", "CONTACT_AUTOMATIC_SINGLE_SURFACE",
        "CONTACT_AUTOMATIC_NODES_TO_SURFACE", "CONTACT_ERODING_SURFACE_TO_SURFACE", "CONTACT_ERODING_NODES_TO_SURFACE",
        "CONTACT_ERODING_SINGLE_SURFACE", "CONTACT_SPOTWELD", "CONTACT_SPOTWELD_WITH_TORSION", "CONTACT_TIED_NODES_TO_SURFACE", "CONTACT_TIED_SURFACE_TO_SURFACE", "CONTACT_TIED_SHELL_EDGE_TO_SURFACE",
        "CONTACT_TIED_NODES_TO_SURFACE_OFFSET", "CONTACT_TIED_SURFACE_TO_SURFACE_OFFSET", "CONTACT_TIED_NODES_TO_SURFACE_CONSTRAINED_OFFSET", "CONTACT_TIED_SURFACE_TO_SURFACE_CONSTRAINED_OFFSET", "CONTACT_SINGLE_SURFACE",
        "CONTACT_ONE_WAY_SURFACE_TO_SURFACE", "CONTACT_AUTOMATIC_ONE_WAY_SURFACE_TO_SURFACE",
        "CONTACT_FORMING_ONE_WAY_SURFACE_TO_SURFACE", "BOUNDARY_SPC_NODE", "BOUNDARY_SPC_SET", "BOUNDARY_SPC_NODE_BIRTH_DEATH",
        "BOUNDARY_SPC_SET_BIRTH_DEATH", "RIGIDWALL_GEOMETRIC_CYLINDER", "RIGIDWALL_GEOMETRIC_CYLINDER_DISPLAY",
        "RIGIDWALL_GEOMETRIC_CYLINDER_MOTION", "RIGIDWALL_GEOMETRIC_CYLINDER_MOTION_DISPLAY", "BOUNDARY_PRESCRIBED_MOTION_NODE", "BOUNDARY_PRESCRIBED_MOTION_SET", "BOUNDARY_PRESCRIBED_MOTION_RIGID",
        "LOAD_SEGMENT", "LOAD_SEGMENT_SET", "CONSTRAINED_SPOTWELD", "CONSTRAINED_GENERALIZED_WELD_SPOT"};
    if (ends("_TITLE") && (titled.count(n.substr(0, n.size() - 6)) || find_material_type_by_keyword(n.substr(0, n.size() - 6)) ||
                           find_eos_form_by_keyword(n.substr(0, n.size() - 6)))) {
      title = true;
      return n.substr(0, n.size() - 6);
    }
    for (const char* spc : {"BOUNDARY_SPC_NODE_ID_BIRTH_DEATH", "BOUNDARY_SPC_SET_ID_BIRTH_DEATH"})
      if (n == spc) {  // LS-DYNA's option order NODE|SET, ID, BIRTH_DEATH (_BIRTH_DEATH_ID also reads)
        id = true;
        return n.substr(0, n.size() - 15) + "_BIRTH_DEATH";
      }
    if (ends("_ID") && with_id.count(n.substr(0, n.size() - 3))) {
      id = true;
      return n.substr(0, n.size() - 3);
    }
    return n;
  }

  void parse_blocks() {
    for (Block& b : deck_.blocks) {
      if (b.name == "PARAMETER" || b.name == "PARAMETER_EXPRESSION") continue;  // read first (read_parameters)
      std::string n = base_name(b.name, b.title_opt, b.id_opt);
      if (n == "RIGIDWALL_PLANAR_MOVING") {
        n = "RIGIDWALL_PLANAR";
        b.moving_opt = true;
      }
      b.name = n;
      if (n == "KEYWORD" || n == "INCLUDE" || n == "INCLUDE_PATH" || n == "INCLUDE_PATH_RELATIVE" || n == "INCLUDE_TRANSFORM" || n == "CASE") continue;
      if (read_sets_boxes(b, ctx_, sb_)) continue;          // keyword_sets_boxes.cpp
      if (read_control_database(b, ctx_, ctl_)) continue;  // keyword_control_database.cpp
      if (read_parts_sections(b, ctx_, ps_)) continue;      // keyword_parts_sections.cpp
      if (read_loads_bcs(b, ctx_, ld_)) continue;           // keyword_loads_bcs.cpp
      if (read_nodes_elements(b, ctx_, me_)) continue;      // keyword_nodes_elements.cpp
      if (read_materials(b, ctx_, mt_)) continue;           // keyword_materials.cpp
      if (read_contacts(b, ctx_, contacts_)) continue;      // keyword_contacts.cpp
      note_unsupported(b);  // read by no family
    }
  }

  // A keyword no family reads: refused (or ignored with --lenient-keywords) once the deck is
  // read; the ids it defines are remembered, so that a reference to one names the keyword.
  void note_unsupported(const Block& b) {
    const std::string& n = b.name;
    unsupported_.push_back(&b);
    // remember the ids that unsupported material and section keywords define, so that a
    // part using one gets a clear message
    if ((n.rfind("MAT_", 0) == 0 || n.rfind("SECTION_", 0) == 0 || n.rfind("EOS_", 0) == 0) && !b.data.empty()) {
      std::size_t k = 0;
      if (n.size() > 6 && n.compare(n.size() - 6, 6, "_TITLE") == 0) k = 1;
      if (k < b.data.size()) {
        Diagnostics quiet;
        KCard c(b.data[k], b.keyword, W(b, 1), quiet);
        long long id = c.i(0, "id", 0);
        (n[0] == 'M' ? refused_.mids : n[0] == 'E' ? refused_.eosids : refused_.secids)[int(id)] =
            b.keyword + " at " + b.kw.file->name() + ":" + std::to_string(b.kw.line->number);
      }
    }
    // and the sets and parts they define, so that a reference to one names the keyword
    char kind = n.rfind("SET_NODE", 0) == 0      ? 'N'
                : n.rfind("SET_PART", 0) == 0    ? 'P'
                : n.rfind("SET_SEGMENT", 0) == 0 ? 'S'
                : n.rfind("SET_SOLID", 0) == 0   ? 'H'
                : n.rfind("DEFINE_BOX", 0) == 0  ? 'B'
                : n.rfind("PART", 0) == 0        ? 'p'
                                                 : 0;
    if (kind) {
      const bool titled = n.size() > 6 && n.compare(n.size() - 6, 6, "_TITLE") == 0;
      std::size_t k = kind == 'p' ? 1 : titled ? 1 : 0;  // *PART_...: heading card first
      if (k < b.data.size()) {
        Diagnostics quiet;
        KCard c(b.data[k], b.keyword, W(b, 1), quiet);
        long long id = c.i(0, "id", 0);
        if (quiet.error_count() == 0 && id != 0)
          refused_.defs.emplace(std::make_pair(kind, int(id)),
                                upper(b.keyword) + " at " + b.kw.file->name() + ":" + std::to_string(b.kw.line->number));
      }
    }
  }


  // An id a keyword of this block defines, with its *INCLUDE_TRANSFORM offset (applied while
  // parsing, so that a file included twice with offsets defines no duplicates).
  int xid(int id, const Block& b, long long IncludeTransform::*field) const {
    const IncludeTransform* t = id != 0 ? deck_.transforms.of(b.kw.file) : nullptr;
    return t ? int(id + t->*field) : id;
  }

  // Keywords whose absence changes what the rest of the deck means: --lenient-keywords cannot
  // ignore them (*CASE blocks select cards per case; ignoring them applied every case's cards
  // at once).
  static bool changes_meaning(const std::string& name) { return name == "CASE" || name.rfind("CASE_", 0) == 0; }

  void report_tet10() {
    if (me_.tet10_count == 0) return;
    diag_.add(1102, loc_of(me_.tet10_first.first, "*ELEMENT_SOLID element " + std::to_string(me_.tet10_first.second), "N9"),
              std::to_string(me_.tet10_count) + " element(s) are 10-node tetrahedra (N9, N10 not 0; this is the first): IMPACT-3D has 8-node solids "
              "(4-node tetrahedra as degenerate hexahedra: N1 N2 N3 N4 N4 N4 N4 N4)");
  }

  void report_unsupported() {
    report_tet10();
    if (unsupported_.empty()) return;
    std::map<std::string, int> ignorable, refused;  // keyword as written, upper case -> blocks
    int n_ignorable = 0, n_refused = 0;
    for (const Block* b : unsupported_) {
      const bool refuse = !opt_.lenient || changes_meaning(b->name);
      ++(refuse ? refused : ignorable)[upper(b->keyword.substr(1))];
      ++(refuse ? n_refused : n_ignorable);
      Location loc;
      loc.file = b->kw.file->name();
      loc.line = b->kw.line->number;
      loc.card = b->keyword;
      diag_.add(refuse ? 1301 : 2007, loc,
                opt_.lenient && refuse ? "the cards of every case would apply at once: a deck with *CASE is refused even with --lenient-keywords" : "");
    }
    auto summary = [&](int id, int blocks, const std::map<std::string, int>& count) {
      if (count.empty()) return;
      std::string list;
      for (const auto& [n, c] : count) list += (list.empty() ? "*" : ", *") + n + (c > 1 ? " (" + std::to_string(c) + "x)" : "");
      Location loc;
      loc.file = main_.name();
      diag_.add_summary(id, loc, std::to_string(blocks) + " keyword block(s): " + list);
    };
    summary(2007, n_ignorable, ignorable);
    summary(1301, n_refused, refused);
  }

  // ---------------------------------------------------------------- pass 3: resolve
  // The families' builders turn the records into the Model (keyword_*_resolve.cpp), in this
  // order: each step may use what the earlier ones resolved (ResolveContext).
  void resolve(ResolveContext& rc) {
    resolve_nodes(rc);
    resolve_coordinate_systems(rc);
    resolve_parts_and_elements(rc);
    resolve_shells(rc);
    resolve_beams(rc);
    resolve_materials(rc);
    resolve_shell_materials(rc);
    resolve_beam_materials(rc);
    build_controls(ctl_, main_.name(), m_, diag_);
    resolve_spc(rc);
    resolve_spot_welds(rc);
    resolve_history(rc);
    resolve_curves(rc);
    resolve_walls(rc);
    resolve_velocities(rc);
    resolve_temperatures(rc);
    resolve_contacts(rc);
    resolve_loads(rc);
    resolve_timed_spc(rc);
  }
};

}  // namespace

// A keyword deck opens with a keyword (*KEYWORD, or any keyword line, after blank and $
// lines).  A deck that opens with a title card is a DYNA3D fixed-format deck when the title
// carries the format flag ("large" in columns 76-80) or no line is an upper-case keyword: a
// commented-out option such as "*basename ..." inside a fixed-format deck is a comment there.
bool is_keyword_deck(const DeckFile& deck) {
  const DeckLine* first = nullptr;
  for (const auto& l : deck.lines()) {
    if (is_blank(l.text) || l.text[0] == '$') continue;
    first = &l;
    break;
  }
  if (!first) return false;
  if (upper(first->text.substr(0, 8)) == "*KEYWORD" || is_keyword_line(first->text)) return true;
  std::string flag = upper(std::string(card_columns(first->text, 76, 80)));
  if (flag.find("LARGE") != std::string::npos) return false;
  for (const auto& l : deck.lines()) {
    if (!is_keyword_line(l.text)) continue;
    std::size_t e = 1;
    while (e < l.text.size() && l.text[e] != ' ' && l.text[e] != '\r') ++e;
    const std::string_view word = l.text.substr(1, e - 1);
    bool upper_case = true;
    for (char ch : word) upper_case = upper_case && !(ch >= 'a' && ch <= 'z');
    if (upper_case) return true;
  }
  return false;
}

bool read_keyword_deck(DeckFile& deck, Model& model, Diagnostics& diag, const KeywordOptions& options) {
  model.deck_file = deck.name();
  model.large_format = true;
  model.keyword_deck = true;
  const int before = diag.error_count();
  KeywordReader r(deck, model, diag, options);
  r.read();
  return diag.error_count() == before;
}

bool read_deck(DeckFile& deck, Model& model, Diagnostics& diag, const InputOptions& options) {
  if (is_keyword_deck(deck)) {
    KeywordOptions ko;
    ko.lenient = options.lenient_keywords;
    ko.case_id = options.case_id;
    return read_keyword_deck(deck, model, diag, ko);
  }
  return read_dyna3d_deck(deck, model, diag);
}

}  // namespace impact3d
