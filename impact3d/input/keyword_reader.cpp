// LS-DYNA keyword-deck reader, the orchestrator.  Three passes: the deck and its *INCLUDE files
// are cut into keyword blocks (keyword line + data lines, '$' comments dropped; the *CASE to
// read selected, keyword_cases.cpp), every block goes to the family that reads it by its
// tables into records (keyword_<family>.cpp; *PARAMETER first), and the families' resolve
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
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
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
    std::vector<std::string> stack;
    check_first_line();
    scan(main_, 0, stack);
    select_case(blocks_, cases_, opt_.case_id, main_.name(), ctx_, m_);  // keyword_cases.cpp
    collect_parameters();
    parse_blocks();
    ResolveContext rc{m_, diag_, main_.name(), me_, ps_, mt_, sb_, ld_, ctl_, contacts_, refused_};
    apply_include_transforms(rc, transforms_);  // keyword_include_transform.cpp
    report_unsupported();
    for (Block& b : blocks_) release(b.data);  // read: the lines are not needed by block any more
    resolve(rc);
  }

 private:
  DeckFile& main_;
  Model& m_;
  Diagnostics& diag_;
  KeywordOptions opt_;
  std::deque<std::unique_ptr<DeckFile>> includes_;
  std::vector<Block> blocks_;
  bool global_long_ = false, global_i10_ = false;
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
  void check_first_line() {
    for (const auto& l : main_.lines()) {
      if (is_blank(l.text) || l.text[0] == '$') continue;
      if (upper(l.text).rfind("*KEYWORD", 0) != 0) {
        Location loc;
        loc.file = main_.name();
        loc.line = l.number;
        diag_.add(2009, loc, "LS-DYNA requires *KEYWORD as the first line; read anyway");
      }
      return;
    }
  }

  void scan(const DeckFile& f, int depth, std::vector<std::string>& stack) {
    long cur = -1;
    bool reported_orphan = false;
    for (const DeckLine& l : f.lines()) {
      const std::string_view t = l.text;
      if (!t.empty() && t[0] == '$') continue;
      if (is_keyword_line(t)) {
        close_block(cur, depth, stack);
        cur = -1;
        Block b;
        std::string first(t.substr(1, t.find_first_of(" \t,", 1) == std::string::npos ? std::string::npos : t.find_first_of(" \t,", 1) - 1));
        b.keyword = "*" + rtrim(first);
        std::string name = upper(rtrim(first));
        bool lng = global_long_, i10 = global_i10_;
        while (!name.empty() && (name.back() == '+' || name.back() == '-' || name.back() == '%')) {
          if (name.back() == '+') lng = true;
          if (name.back() == '-') lng = false;
          if (name.back() == '%') i10 = true;
          name.pop_back();
        }
        // the suffix may also stand apart: "*NODE +"
        for (std::size_t p = t.find_first_of(" \t"); p != std::string::npos && p < t.size();) {
          std::size_t s = t.find_first_not_of(" \t", p);
          if (s == std::string::npos) break;
          std::size_t e = t.find_first_of(" \t", s);
          std::string_view tok = t.substr(s, e == std::string::npos ? std::string::npos : e - s);
          if (tok == "+") lng = true;
          if (tok == "-") lng = false;
          if (tok == "%") i10 = true;
          p = e;
        }
        b.name = name;
        b.kw = {&f, &l};
        if (name == "END") return;  // the rest of this file is not read
        if (cases_.marker(name, f, l, diag_)) continue;  // *CASE_BEGIN_n / *CASE_END_n: no block
        b.cases = cases_.open;
        if (const int cid = keyword_case_option(t); cid > 0 && std::find(b.cases.begin(), b.cases.end(), cid) == b.cases.end())
          b.cases.push_back(cid);
        if (name == "KEYWORD") keyword_options(t, f, l);
        b.long_fmt = name == "KEYWORD" ? global_long_ : lng;
        b.i10 = name == "KEYWORD" ? global_i10_ : i10;
        blocks_.push_back(std::move(b));
        cur = long(blocks_.size()) - 1;
        continue;
      }
      if (!t.empty() && t[0] == '*') continue;  // '*' not followed by a letter: comment
      if (cur < 0) {
        if (!is_blank(t) && !reported_orphan) {
          Location loc;
          loc.file = f.name();
          loc.line = l.number;
          loc.found = t;
          loc.show_found = true;
          diag_.add(1305, loc);
          reported_orphan = true;
        }
        continue;
      }
      blocks_[std::size_t(cur)].data.push_back({&f, &l});
    }
    close_block(cur, depth, stack);
  }

  void keyword_options(std::string_view t, const DeckFile& f, const DeckLine& l) {
    std::string u = upper(t);
    std::size_t p = u.find_first_of(" \t");
    while (p != std::string::npos && p < u.size()) {
      std::size_t b = u.find_first_not_of(" \t", p);
      if (b == std::string::npos) break;
      std::size_t e = u.find_first_of(" \t", b);
      std::string tok = u.substr(b, e == std::string::npos ? std::string::npos : e - b);
      p = e;
      if (tok == "LONG=Y") global_long_ = true;
      else if (tok == "LONG=S" || tok == "LONG=N") global_long_ = false;
      else if (tok == "I10=Y") global_i10_ = true;
      else if (tok == "I10=N") global_i10_ = false;
      else if (!tok.empty() && std::all_of(tok.begin(), tok.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == 'M'; })) {
        // memory size: ignored
      } else if (long long n = 0; tok.rfind("NCPU=", 0) == 0 && parse_fortran_int(tok.substr(5), n) == FieldStatus::ok &&
                                    n != 0 && std::llabs(n) <= 1024) {
        // the thread count when the command line has no ncpu= (negative: LS-DYNA's consistent
        // mode; IMPACT-3D's results never depend on the thread count)
        m_.deck_threads = int(std::llabs(n));
      } else {
        Location loc;
        loc.file = f.name();
        loc.line = l.number;
        loc.card = "*KEYWORD";
        loc.found = tok;
        loc.show_found = true;
        if (tok.rfind("MEMORY=", 0) == 0 || tok.rfind("MEMORY2=", 0) == 0)  // LS-DYNA's memory options: read and listed as ignored
          diag_.add(2008, loc, "memory is allocated as the model needs it");
        else
          diag_.add(1312, loc, "supported: LONG=Y, LONG=S, I10=Y, I10=N, MEMORY=, MEMORY2=, NCPU=n (1 <= |n| <= 1024) and a memory size");
      }
    }
  }

  // *INCLUDE_PATH: directories searched for include files (one per line), after the including
  // file's; _RELATIVE: relative to the main deck's directory.
  std::vector<std::string> include_paths_;
  void add_include_paths(const Block& b) {
    namespace fs = std::filesystem;
    const bool relative = b.name == "INCLUDE_PATH_RELATIVE";
    for (const KLine& kl : b.data) {
      std::string t(trim_sv(kl.line->text));
      if (t.empty()) continue;
      fs::path p(t);
      if (relative || p.is_relative()) p = fs::path(main_.name()).parent_path() / p;
      include_paths_.push_back(p.string());
      if (!relative && fs::path(t).is_relative()) include_paths_.push_back(t);  // the working directory
    }
  }

  // *INCLUDE_TRANSFORM: the file is read as an *INCLUDE, and its records are renumbered and
  // moved once the deck is parsed (apply_include_transforms, keyword_include_transform.cpp).
  IncludeTransforms transforms_;
  const IncludeTransform* pending_transform_ = nullptr;  // for the include being opened

  void include_transform(const Block& b, int depth, std::vector<std::string>& stack) {
    const auto& data = b.data;
    std::size_t k = 0;
    while (k < data.size() && is_blank(data[k].line->text)) ++k;
    if (k >= data.size()) { ctx_.missing_card(b, "card 1 (FILENAME)"); return; }
    std::string name;
    const KLine first = data[k];
    for (; k < data.size(); ++k) {
      std::string t = rtrim(data[k].line->text);
      if (t.size() >= 2 && t.compare(t.size() - 2, 2, " +") == 0) { name += t.substr(0, t.size() - 2); continue; }
      name += t;
      ++k;
      break;
    }
    IncludeTransform x;
    const auto card = [&](std::size_t j, const char* what) { return KCard(data[j], b.keyword + " " + what, W(b, 8), diag_); };
    if (k < data.size()) {
      KCard c = card(k++, "card 2");
      x.idnoff = c.i(0, "IDNOFF"), x.ideoff = c.i(1, "IDEOFF"), x.idpoff = c.i(2, "IDPOFF"), x.idmoff = c.i(3, "IDMOFF");
      x.idsoff = c.i(4, "IDSOFF"), x.idfoff = c.i(5, "IDFOFF"), x.iddoff = c.i(6, "IDDOFF");
      for (int f = 0; f < 7; ++f)
        if (c.i(f, "offset") < 0) c.error(1003, f, "offset", "id offsets must not be negative");
    }
    if (k < data.size()) {
      KCard c = card(k++, "card 3");
      x.idroff = c.i(0, "IDROFF");
      if (x.idroff < 0) c.error(1003, 0, "IDROFF", "id offsets must not be negative");
    }
    if (k < data.size()) {
      KCard c = card(k++, "card 4");
      const double fctmas = c.r(0, "FCTMAS", 1), fcttim = c.r(1, "FCTTIM", 1);
      x.fctlen = c.r(2, "FCTLEN", 1);
      const double fcttem = c.r(3, "FCTTEM", 1);
      if (x.fctlen == 0) x.fctlen = 1;
      if (fctmas != 0 && fctmas != 1) c.error(1102, 0, "FCTMAS", "unit conversion of the included data (mass)");
      if (fcttim != 0 && fcttim != 1) c.error(1102, 1, "FCTTIM", "unit conversion of the included data (time)");
      if (fcttem != 0 && fcttem != 1) c.error(1102, 3, "FCTTEM", "unit conversion of the included data (temperature)");
      if (!(x.fctlen > 0)) c.error(1003, 2, "FCTLEN", "must be positive");
      c.i(4, "INCOUT1");
    }
    if (k < data.size()) {
      KCard c = card(k++, "card 5");
      x.tranid = int(c.i(0, "TRANID"));
      x.tranid_ref = c.ref(0);
    }
    transforms_.list.push_back(x);
    pending_transform_ = &transforms_.list.back();
    include(std::string(trim_sv(name)), first, depth, stack);
    pending_transform_ = nullptr;
  }

  void close_block(long cur, int depth, std::vector<std::string>& stack) {
    if (cur >= 0 && (blocks_[std::size_t(cur)].name == "INCLUDE_PATH" || blocks_[std::size_t(cur)].name == "INCLUDE_PATH_RELATIVE"))
      add_include_paths(blocks_[std::size_t(cur)]);
    if (cur >= 0 && blocks_[std::size_t(cur)].name == "INCLUDE_TRANSFORM") {
      const Block b = blocks_[std::size_t(cur)];  // copy: including appends to blocks_
      include_transform(b, depth, stack);
      return;
    }
    if (cur < 0 || blocks_[std::size_t(cur)].name != "INCLUDE") return;
    // copy: including appends to blocks_
    const auto data = blocks_[std::size_t(cur)].data;
    std::string name;
    KLine first{};
    for (const KLine& kl : data) {
      std::string t = rtrim(kl.line->text);
      if (t.empty() && name.empty()) continue;
      if (name.empty()) first = kl;
      // a file name longer than one line continues on the next after " +"
      if (t.size() >= 2 && t.compare(t.size() - 2, 2, " +") == 0) {
        name += t.substr(0, t.size() - 2);
        continue;
      }
      name += t;
      include(std::string(trim_sv(name)), first, depth, stack);
      name.clear();
    }
  }

  void include(const std::string& name, const KLine& where, int depth, std::vector<std::string>& stack) {
    namespace fs = std::filesystem;
    Location loc;
    loc.file = where.file->name();
    loc.line = where.line->number;
    loc.card = "*INCLUDE";
    loc.field = "FILENAME";
    loc.found = name;
    loc.show_found = true;
    std::vector<fs::path> candidates;
    fs::path p(name);
    if (p.is_absolute()) {
      candidates.push_back(p);
    } else {
      candidates.push_back(fs::path(where.file->name()).parent_path() / p);
      candidates.push_back(fs::path(main_.name()).parent_path() / p);
      candidates.push_back(p);
      for (const std::string& d : include_paths_) candidates.push_back(fs::path(d) / p);
    }
    fs::path found;
    std::error_code ec;
    for (const auto& c : candidates)
      if (fs::is_regular_file(c, ec)) { found = c; break; }
    if (found.empty()) {
      diag_.add(1306, loc, "not found next to " + where.file->name() + ", the main deck, in the working directory or in an *INCLUDE_PATH directory");
      return;
    }
    std::string canon = fs::weakly_canonical(found, ec).string();
    if (depth >= 20 || std::find(stack.begin(), stack.end(), canon) != stack.end() ||
        canon == fs::weakly_canonical(main_.name(), ec).string()) {
      diag_.add(1307, loc, depth >= 20 ? "more than 20 levels" : "the file includes itself");
      return;
    }
    auto df = std::make_unique<DeckFile>();
    Diagnostics local;
    if (!df->load(found.string(), local)) {
      diag_.add(1306, loc, local.all().empty() ? std::string() : local.all().front().detail);
      return;
    }
    // the records of a transformed include (and of the files it includes) are renumbered and moved
    if (pending_transform_) transforms_.of_file[df.get()] = pending_transform_;
    else if (auto t = transforms_.of_file.find(where.file); t != transforms_.of_file.end()) transforms_.of_file[df.get()] = t->second;
    pending_transform_ = nullptr;
    includes_.push_back(std::move(df));
    stack.push_back(canon);
    scan(*includes_.back(), depth + 1, stack);
    stack.pop_back();
  }

  // *CASE_BEGIN_n ... *CASE_END_n sections open while scanning (keyword_cases.cpp)
  CaseSections cases_;

  // ---------------------------------------------------------------- pass 2: parse blocks
  // Field widths for a card of n fields of width w (standard), 20 in long format.
  static std::vector<int> W(const Block& b, int n, int w = 10) { return std::vector<int>(std::size_t(n), b.long_fmt ? 20 : w); }

  // *PARAMETER: cards of four pairs PRMR (10 columns: type R, I or C, then the name) and VAL
  // (10 columns), then *PARAMETER_EXPRESSION.  Read before every other keyword, so a reference
  // may come before or after its definition; a name defined twice is error 1200.
  void collect_parameters() {
    for (Block& b : blocks_) {
      if (b.name != "PARAMETER") continue;
      for (std::size_t k = 0; k < b.data.size(); ++k) {
        if (is_blank(b.data[k].line->text)) continue;
        KCard c(b.data[k], b.keyword, W(b, 8), diag_);  // no substitution inside *PARAMETER
        for (int f = 0; f + 1 < 8; f += 2) {
          std::string pr = c.literal(f);
          if (pr.empty()) continue;
          const char type = char(std::toupper(static_cast<unsigned char>(pr[0])));
          std::string name = pr.substr(1);
          const std::size_t s = name.find_first_not_of(' ');
          name = s == std::string::npos ? std::string() : name.substr(s);
          for (char& ch : name) ch = char(std::toupper(static_cast<unsigned char>(ch)));
          if ((type != 'R' && type != 'I' && type != 'C') || name.empty() || name.find(' ') != std::string::npos) {
            c.error(1006, f, "PRMR", "a type letter R, I or C followed by the parameter name");
            continue;
          }
          Param p;
          p.type = type;
          if (type == 'C') {
            p.text = c.literal(f + 1);
          } else if (type == 'I') {
            p.value = double(c.i(f + 1, "VAL"));
          } else {
            p.value = c.r(f + 1, "VAL");
          }
          if (!params_.emplace(name, p).second) c.error(1200, f, "PRMR", "parameter " + name + " is defined twice");
        }
      }
    }
    read_parameter_expressions(blocks_, params_, diag_);  // (keyword_parameters.cpp)
  }

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
        "CONTACT_ERODING_NODES_TO_SURFACE", "CONTACT_ERODING_SINGLE_SURFACE", "CONTACT_SPOTWELD", "CONTACT_TIED_NODES_TO_SURFACE",
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
        "CONTACT_ERODING_SINGLE_SURFACE", "CONTACT_SPOTWELD", "CONTACT_TIED_NODES_TO_SURFACE", "CONTACT_SINGLE_SURFACE",
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
    for (Block& b : blocks_) {
      if (b.name == "PARAMETER" || b.name == "PARAMETER_EXPRESSION") continue;  // read first (collect_parameters)
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
    const IncludeTransform* t = id != 0 ? transforms_.of(b.kw.file) : nullptr;
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
