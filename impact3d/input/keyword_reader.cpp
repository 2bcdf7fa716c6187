// LS-DYNA keyword-deck reader.  Two passes: the deck and its *INCLUDE files are cut into
// keyword blocks (keyword line + data lines, '$' comments dropped), every supported block is
// parsed into raw records by fields (fixed columns, long/I10 widths, or comma free format), and
// the records are then resolved into the Model: ids renumbered 1..N, parts -> materials, sets
// -> nodes and segments, contacts -> sliding interfaces.  Every problem is reported, with file,
// line, keyword/card, field and columns, through the message catalog.  README.md ("Keyword
// decks") lists the keywords and fields.

#include "impact3d/input/keyword_reader.h"
#include "impact3d/input/keyword_families.h"
#include "impact3d/init/beam_init.h"
#include "impact3d/init/shell_init.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/coordinate_systems.h"
#include "impact3d/input/element_shapes.h"
#include "impact3d/contact/tied_nodes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace impact3d {

namespace {

using namespace kw;

// Fixed translational components (bit 0 x, bit 1 y, bit 2 z) -> boundary code 0-7 (bc_bits).
int bc_code(int bits) {
  static const int code[8] = {0, 1, 2, 4, 3, 6, 5, 7};  // index = bits: x=1, y=2, z=4
  return code[bits & 7];
}

// Raw records, before resolution (the families' records are in keyword_families.h).


// Faces of the hexahedron (0-based local nodes), counter-clockwise seen from outside.
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

class KeywordReader {
 public:
  KeywordReader(DeckFile& deck, Model& m, Diagnostics& diag, const KeywordOptions& opt)
      : main_(deck), m_(m), diag_(diag), opt_(opt) {}

  void read() {
    std::vector<std::string> stack;
    check_first_line();
    scan(main_, 0, stack);
    select_case();
    collect_parameters();
    parse_blocks();
    apply_include_transforms();
    report_unsupported();
    for (Block& b : blocks_) release(b.data);  // read: the lines are not needed by block any more
    resolve();
  }

 private:
  DeckFile& main_;
  Model& m_;
  Diagnostics& diag_;
  KeywordOptions opt_;
  std::deque<std::unique_ptr<DeckFile>> includes_;
  std::vector<Block> blocks_;
  bool global_long_ = false, global_i10_ = false;

  // raw records
  KeywordSetsBoxes sb_;  // sets, boxes, coordinate systems (keyword_sets_boxes.cpp)
  KeywordLoads ld_;  // loads, prescribed motions, damping, initial conditions, constraints (keyword_loads_bcs.cpp)
  KeywordMesh me_;  // nodes and elements (keyword_nodes_elements.cpp)
  std::vector<RNode, HugePageAllocator<RNode>>& nodes_ = me_.nodes;
  std::vector<RElem, HugePageAllocator<RElem>>& elems_ = me_.elems;
  KeywordParts ps_;  // parts, sections, hourglass (keyword_parts_sections.cpp)
  std::vector<RPart>& parts_ = ps_.parts;
  std::map<int, RSection>& sections_ = ps_.sections;
  std::map<int, RShellSection>& shell_sections_ = ps_.shell_sections;
  std::vector<RShell>& shells_ = me_.shells;
  std::vector<std::vector<int>> part_shells_;  // per part: its shells (indices into Model::shell_nodes)
  std::map<int, RBeamSection>& beam_sections_ = ps_.beam_sections;
  std::vector<RBeam>& beams_ = me_.beams;
  std::vector<std::vector<int>> part_beams_;  // per part: its beams (indices into Model::beam_nodes)
  std::vector<std::pair<int, int>>& node_rc_ = me_.node_rc;
  KeywordMaterials mt_;  // materials, equations of state, erosion (keyword_materials.cpp)
  std::map<int, RMat>& mats_ = mt_.mats;
  std::map<int, std::pair<ErosionData, Ref>>& erosion_ = mt_.erosion;
  std::map<int, RHourglass>& hourglasses_ = ps_.hourglasses;
  std::map<int, REos>& eos_ = mt_.eos;
  std::map<int, std::string> unsupported_eosids_;  // EOSID -> the refused *EOS keyword, line
  std::map<int, RIdList>& node_sets_ = sb_.node_sets;
  std::map<int, RIdList>& part_sets_ = sb_.part_sets;
  ParamTable params_;                    // *PARAMETER values
  std::map<int, RSegSet>& seg_sets_ = sb_.seg_sets;
  std::vector<RContact> contacts_;
  std::vector<RWall>& walls_ = ld_.walls;
  std::vector<RVelocity>& velocities_ = ld_.velocities;
  std::vector<RTemperature>& temperatures_ = ld_.temperatures;
  std::vector<RSpc>& spcs_ = ld_.spcs;
  std::vector<RWeld>& welds_ = ld_.welds;
  std::vector<RLoad>& loads_ = ld_.loads;
  RLoad& damping_ = ld_.damping;
  bool& damping_given_ = ld_.damping_given;
  bool& damping_rotations_ = ld_.damping_rotations;
  int& body_parts_psid_ = ld_.body_parts_psid;
  Ref& body_parts_ref_ = ld_.body_parts_ref;
  std::map<int, RIdList>& solid_sets_ = sb_.solid_sets;
  std::map<int, RIdList>& shell_sets_ = sb_.shell_sets;
  std::map<int, RBox>& boxes_ = sb_.boxes;
  std::vector<RCoordSystem>& coord_defs_ = sb_.systems;
  CoordinateTable coords_;
  long long& tet10_count_ = me_.tet10_count;
  std::pair<Ref, int>& tet10_first_ = me_.tet10_first;
  std::vector<LoadCurve>& curves_ = ld_.curves;
  std::vector<Ref>& curve_refs_ = ld_.curve_refs;
  std::map<int, int> curve_index_;       // LCID -> index in curves_ (= Model::load_curves)
  std::vector<char> curve_used_;
  std::vector<const Block*> unsupported_;
  std::map<int, std::string> unsupported_mids_, unsupported_secids_;  // id -> keyword, line
  // sets and parts that refused keywords define (*SET_NODE_GENERAL, *PART_COMPOSITE, ...):
  // kind ('N' node set, 'P' part set, 'S' segment set, 'p' part) and id -> keyword, line
  std::map<std::pair<char, int>, std::string> refused_defs_;

  // "; SET is defined by *KEYWORD at FILE:LINE, which is not supported" when a refused keyword
  // defines what a reference names.
  std::string refused_note(char kind, int id) const {
    auto it = refused_defs_.find({kind, id});
    if (it == refused_defs_.end()) return {};
    return " (it is defined by " + it->second + ", a keyword IMPACT-3D does not support)";
  }
  int rotational_spc_ = 0;
  std::vector<Ref>& rot_refs_ = ld_.rot_refs;
  Ref& w_ref_ = ld_.w_ref;
  std::vector<char> shell_node_;  // per node: used by a shell
  Ref rotational_ref_;

  // the families' shared state; ids they define get their file's *INCLUDE_TRANSFORM offset by
  // kind: n nodes, e elements, p parts, m materials, s sets, f curves, d boxes and systems,
  // r sections, hourglass and EOS
  KeywordContext ctx_{diag_, params_, {}, [this](int id, const Block& b, char kind) {
                        return xid(id, b, kind == 'n' ? &IncludeTransform::idnoff : kind == 'e' ? &IncludeTransform::ideoff
                                            : kind == 'p' ? &IncludeTransform::idpoff : kind == 'm' ? &IncludeTransform::idmoff
                                            : kind == 's' ? &IncludeTransform::idsoff : kind == 'f' ? &IncludeTransform::idfoff
                                            : kind == 'd' ? &IncludeTransform::iddoff : &IncludeTransform::idroff);
                      }};
  KeywordControls ctl_;  // control and database cards, histories, *TITLE, *COMMENT
  std::vector<RHistory>& histories_ = ctl_.histories;
  std::set<int>& initially_elastic_ = ctl_.initially_elastic;  // part ids

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
        if (case_marker(name, f, l)) continue;  // *CASE_BEGIN_n / *CASE_END_n: no block
        b.cases = open_cases_;
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
      } else if (tok.rfind("MEMORY=", 0) == 0 || tok.rfind("MEMORY2=", 0) == 0) {
        // LS-DYNA's memory options: read and listed as ignored
        Location loc;
        loc.file = f.name();
        loc.line = l.number;
        loc.card = "*KEYWORD";
        loc.found = tok;
        loc.show_found = true;
        diag_.add(2008, loc, "memory is allocated as the model needs it");
      } else {
        Location loc;
        loc.file = f.name();
        loc.line = l.number;
        loc.card = "*KEYWORD";
        loc.found = tok;
        loc.show_found = true;
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

  // *INCLUDE_TRANSFORM: FILENAME; IDNOFF IDEOFF IDPOFF IDMOFF IDSOFF IDFOFF IDDOFF; IDROFF;
  // FCTMAS FCTTIM FCTLEN FCTTEM INCOUT1; TRANID.  The file is read as an *INCLUDE, and its
  // records are renumbered and moved once the deck is parsed (apply_include_transforms).
  struct IncludeTransform {
    long long idnoff = 0, ideoff = 0, idpoff = 0, idmoff = 0, idsoff = 0, idfoff = 0, iddoff = 0, idroff = 0;
    double fctlen = 1;
    int tranid = 0;
    Ref tranid_ref;
    AffineMap map;  // FCTLEN scaling, then *DEFINE_TRANSFORMATION TRANID
    bool moves = false;
  };
  std::deque<IncludeTransform> transforms_;
  std::map<const DeckFile*, const IncludeTransform*> file_transform_;
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
    transforms_.push_back(x);
    pending_transform_ = &transforms_.back();
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
    if (pending_transform_) file_transform_[df.get()] = pending_transform_;
    else if (auto t = file_transform_.find(where.file); t != file_transform_.end()) file_transform_[df.get()] = t->second;
    pending_transform_ = nullptr;
    includes_.push_back(std::move(df));
    stack.push_back(canon);
    scan(*includes_.back(), depth + 1, stack);
    stack.pop_back();
  }


  // ---------------------------------------------------------------- *CASE
  // *CASE_BEGIN_n ... *CASE_END_n sections (nested or not) and the CID=n option of a keyword
  // line put keywords in child case n; a master *CASE (CASEID JOBID; a line of command-line
  // options; lines of child case ids SCID) runs the main model and its children.  Without a
  // master *CASE each child n is case n.  The base case (case_id 0) leaves every child out.
  std::vector<int> open_cases_;
  struct RCase {
    int id = 0;
    std::string job;
    std::vector<int> children;
    std::vector<KLine> commands;  // command-line options for the case: warned when it runs
    Ref ref;
  };
  std::vector<RCase> master_cases_;

  bool case_marker(const std::string& name, const DeckFile& f, const DeckLine& l) {
    for (const bool begin : {true, false}) {
      const std::string p = begin ? "CASE_BEGIN_" : "CASE_END_";
      if (name.rfind(p, 0) != 0) continue;
      long long n = 0;
      Location loc;
      loc.file = f.name();
      loc.line = l.number;
      loc.card = "*" + name;
      if (parse_fortran_int(name.substr(p.size()), n) != FieldStatus::ok || n < 1) {
        diag_.add(1006, loc, "*" + p + "n takes a positive case number n");
        return true;
      }
      auto it = std::find(open_cases_.begin(), open_cases_.end(), int(n));
      if (begin) {
        if (it == open_cases_.end()) open_cases_.push_back(int(n));
      } else if (it == open_cases_.end()) {
        diag_.add(1006, loc, "no *CASE_BEGIN_" + std::to_string(n) + " before it");
      } else {
        open_cases_.erase(it);
      }
      return true;
    }
    return false;
  }

  // CID=n on a keyword line (after the keyword name): the keyword belongs to child case n.
  static int keyword_case_option(std::string_view t) {
    const std::string u = upper(t);
    const std::size_t sp = u.find_first_of(" \t");
    if (sp == std::string::npos) return 0;
    const std::size_t p = u.find("CID=", sp);
    if (p == std::string::npos || (p > 0 && u[p - 1] != ' ' && u[p - 1] != '\t')) return 0;
    long long n = 0;
    const std::size_t e = u.find_first_of(" \t", p);
    if (parse_fortran_int(u.substr(p + 4, e == std::string::npos ? std::string::npos : e - p - 4), n) != FieldStatus::ok) return 0;
    return int(n);
  }

  void read_master_cases() {
    for (const Block& b : blocks_) {
      if (b.name != "CASE") continue;
      RCase c;
      c.ref.file = b.kw.file;
      c.ref.line = b.kw.line;
      std::size_t k = 0;
      while (k < b.data.size() && is_blank(b.data[k].line->text)) ++k;
      if (k >= b.data.size()) { ctx_.missing_card(b, "card 1 (CASEID JOBID)"); continue; }
      // card 1: CASEID and JOBID, written in columns or separated by blanks
      std::istringstream first(std::string(b.data[k].line->text));
      std::string id_text;
      first >> id_text >> c.job;
      long long id = 0;
      if (parse_fortran_int(id_text, id) != FieldStatus::ok || id < 1) {
        Location loc;
        loc.file = b.data[k].file->name();
        loc.line = b.data[k].line->number;
        loc.card = b.keyword;
        loc.field = "CASEID";
        loc.found = id_text;
        loc.show_found = true;
        diag_.add(1001, loc, "a positive case id");
        continue;
      }
      c.id = int(id);
      // then command-line lines (any text) and lines of child case ids (integers only)
      for (++k; k < b.data.size(); ++k) {
        std::istringstream line(std::string(b.data[k].line->text));
        std::vector<int> ids;
        std::string tok;
        bool all_ints = true;
        while (line >> tok) {
          long long v = 0;
          if (parse_fortran_int(tok, v) == FieldStatus::ok) ids.push_back(int(v));
          else all_ints = false;
        }
        if (all_ints) {
          for (int v : ids)
            if (v != 0) c.children.push_back(v);
        } else {
          c.commands.push_back(b.data[k]);
        }
      }
      for (const RCase& o : master_cases_)
        if (o.id == c.id) diag_.add(1200, loc_of(c.ref, b.keyword, nullptr, false), "case " + std::to_string(c.id) + " also defined at " + at(o.ref));
      master_cases_.push_back(std::move(c));
    }
  }

  // Leaves out the keyword blocks of the child cases the selected case does not hold.
  void select_case() {
    read_master_cases();
    std::set<int> children, all_children;
    for (const Block& b : blocks_) all_children.insert(b.cases.begin(), b.cases.end());
    if (!open_cases_.empty()) {
      Location loc;
      loc.file = main_.name();
      diag_.add(1316, loc, "*CASE_BEGIN_" + std::to_string(open_cases_.front()) + " has no *CASE_END_" + std::to_string(open_cases_.front()));
    }
    const int want = opt_.case_id;
    if (want != 0) {
      std::string job;
      bool found = false;
      for (const RCase& c : master_cases_)
        if (c.id == want) {
          found = true;
          job = c.job;
          children.insert(c.children.begin(), c.children.end());
          for (const KLine& l : c.commands) {
            Location loc;
            loc.file = l.file->name();
            loc.line = l.line->number;
            loc.card = "*CASE " + std::to_string(c.id);
            loc.found = rtrim(l.line->text);
            loc.show_found = true;
            diag_.add(2006, loc, "the command-line options of a case: give them on impact3d's command line");
          }
        }
      if (!found && master_cases_.empty() && all_children.count(want)) {  // child n is case n
        found = true;
        children.insert(want);
      }
      if (!found) {
        std::string list;
        for (const RCase& c : master_cases_) list += (list.empty() ? "" : ", ") + std::to_string(c.id);
        if (master_cases_.empty())
          for (int c : all_children) list += (list.empty() ? "" : ", ") + std::to_string(c);
        Location loc;
        loc.file = main_.name();
        diag_.add(1310, loc, "case=" + std::to_string(want) + ": the deck defines no such case" + (list.empty() ? std::string(" (it has no *CASE)") : " (its cases: " + list + ")"));
      }
      m_.case_job = job.empty() ? "case" + std::to_string(want) : job;
    }
    std::size_t dropped = 0;
    std::vector<Block> kept;
    kept.reserve(blocks_.size());
    for (Block& b : blocks_) {
      bool active = b.cases.empty();
      for (int c : b.cases) active = active || children.count(c) > 0;
      if (active) kept.push_back(std::move(b));
      else ++dropped;
    }
    blocks_.swap(kept);
    if (dropped) {
      std::string list;
      for (const RCase& c : master_cases_) list += (list.empty() ? "" : ", ") + std::to_string(c.id);
      if (master_cases_.empty())
        for (int c : all_children) list += (list.empty() ? "" : ", ") + std::to_string(c);
      Location loc;
      loc.file = main_.name();
      diag_.add(2008, loc, std::to_string(dropped) + " keyword block(s) of *CASE sections left out: " +
                               (want == 0 ? "this is the base case (impact3d case=ID runs case ID; cases " + list + ")"
                                          : "they belong to other cases than " + std::to_string(want)));
    }
  }

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
        "CONTACT_ERODING_SINGLE_SURFACE", "CONTACT_SPOTWELD", "CONTACT_TIED_NODES_TO_SURFACE", "BOUNDARY_SPC_NODE", "BOUNDARY_SPC_SET", "BOUNDARY_SPC_NODE_BIRTH_DEATH",
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
        (n[0] == 'M' ? unsupported_mids_ : n[0] == 'E' ? unsupported_eosids_ : unsupported_secids_)[int(id)] =
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
          refused_defs_.emplace(std::make_pair(kind, int(id)),
                                upper(b.keyword) + " at " + b.kw.file->name() + ":" + std::to_string(b.kw.line->number));
      }
    }
  }

  // A solid part's equation of state (*PART EOSID) into its material: refused for a material
  // that takes none, required by one that needs one (*MAT_NULL).
  void resolve_part_eos(MaterialData& md, const RPart& p, const std::string& card, const MaterialType* t) {
    if (p.eosid == 0) {
      if (t && t->needs_eos)
        err(1204, p.eos_ref.line ? p.eos_ref : p.mid_ref, card, "EOSID",
            std::string("*") + t->keywords.front() + " needs an equation of state (" + supported_eos_keywords() + ")");
      return;
    }
    auto it = eos_.find(p.eosid);
    if (it == eos_.end()) {
      auto u = unsupported_eosids_.find(p.eosid);
      if (u != unsupported_eosids_.end())
        err(1102, p.eos_ref, card, "EOSID", "equation of state " + std::to_string(p.eosid) + " is " + u->second + "; supported: " + supported_eos_keywords());
      else
        err(1310, p.eos_ref, card, "EOSID", "*EOS " + std::to_string(p.eosid) + " is not defined");
      return;
    }
    if (t && !t->accepts_eos) {
      err(1102, p.eos_ref, card, "EOSID", std::string("an equation of state with *") + t->keywords.front() + " (materials that take one: " + eos_material_types() + ")");
      return;
    }
    md.eos = it->second.eos;
    if (const int lc = eos_curve(md.eos); lc > 0) {  // *DEFINE_CURVE id -> the curve's number 1..NUMLC
      std::size_t k = 0;
      while (k < curves_.size() && curves_[k].number != lc) ++k;
      if (k < curves_.size()) md.eos.c[kEosLeakCurve] = double(k + 1);
      else err(1310, it->second.lcid_ref, "*EOS " + std::to_string(p.eosid), "LCID", "*DEFINE_CURVE " + std::to_string(lc) + " is not defined");
    }
  }

  void resolve_temperatures() {
    if (temperatures_.empty()) return;
    m_.node_temperature.assign(std::size_t(m_.num_nodes()), std::nan(""));
    for (const RTemperature& t : temperatures_) {
      const char* kw = t.set ? "*INITIAL_TEMPERATURE_SET" : "*INITIAL_TEMPERATURE_NODE";
      std::vector<int> nodes;
      if (!t.set) {
        const int idx = node_index(t.id);
        if (idx < 0) {
          err(1202, t.ref, kw, "NID", "node " + std::to_string(t.id) + " is not defined by *NODE");
          continue;
        }
        nodes = {idx};
      } else if (t.id == 0) {
        for (int i = 0; i < m_.num_nodes(); ++i) nodes.push_back(i);
      } else if (const RIdList* s = find_node_set(t.id, t.ref, kw, "NSID")) {
        nodes = set_nodes(*s, "*SET_NODE " + std::to_string(t.id));
      }
      for (int n : nodes) m_.node_temperature[std::size_t(n)] = t.temp;
    }
  }

  std::map<int, RTransformation>& transformations_ = sb_.transformations;

  // The records read from a file of an *INCLUDE_TRANSFORM get the id offsets (an id 0, which
  // means "none" or "all", stays 0; the ids that keyed definitions define got theirs while
  // parsing, xid) and their coordinates the map: nodes, the points of walls and coordinate
  // systems, boxes (translation and scaling only).
  const IncludeTransform* transform_of(const DeckFile* f) const {
    auto it = file_transform_.find(f);
    return it == file_transform_.end() ? nullptr : it->second;
  }
  // An id a keyword of this block defines, with its *INCLUDE_TRANSFORM offset (applied while
  // parsing, so that a file included twice with offsets defines no duplicates).
  int xid(int id, const Block& b, long long IncludeTransform::*field) const {
    const IncludeTransform* t = id != 0 ? transform_of(b.kw.file) : nullptr;
    return t ? int(id + t->*field) : id;
  }
  static void offset(int& id, long long off) {
    if (id != 0) id = int(id + off);
  }
  void offset_set_members(RIdList& s, const IncludeTransform& t, long long member_off) {
    for (int& id : s.ids) offset(id, member_off);
    for (auto& r : s.ranges) r[0] += member_off, r[1] += member_off;
    for (RSetTerm& term : s.terms) {
      const long long off = term.option == "NODE" ? t.idnoff : term.option == "ELEM" ? t.ideoff : term.option == "PART" ? t.idpoff
                            : term.option == "BOX" ? t.iddoff : term.option == "SET" || term.option.rfind("SET_", 0) == 0 ? t.idsoff : 0;
      for (int& id : term.ids) offset(id, off);
    }
  }

  void apply_include_transforms() {
    if (transforms_.empty()) return;
    for (IncludeTransform& t : transforms_) {
      t.map = AffineMap::scaling({t.fctlen, t.fctlen, t.fctlen});
      if (t.tranid != 0) {
        auto it = transformations_.find(t.tranid);
        if (it == transformations_.end()) err(1310, t.tranid_ref, "*INCLUDE_TRANSFORM", "TRANID", "*DEFINE_TRANSFORMATION " + std::to_string(t.tranid) + " is not defined");
        else t.map = t.map.then(it->second.map);
      }
      const AffineMap id;
      t.moves = t.map.a != id.a || t.map.t != id.t;
    }
    // FCTLEN converts units: only coordinates are converted here, so data with other
    // length-dimensioned units (materials, curves) in such a file is not supported
    for (auto& [mid, mat] : mats_)
      if (const IncludeTransform* t = transform_of(mat.ref.file); t && t->fctlen != 1)
        err(1102, mat.ref, "*MAT " + std::to_string(mid), "MID", "a material in an *INCLUDE_TRANSFORM file with FCTLEN other than 1 (its units would have to be converted)");
    for (std::size_t k = 0; k < curves_.size(); ++k)
      if (const IncludeTransform* t = transform_of(curve_refs_[k].file); t && t->fctlen != 1)
        err(1102, curve_refs_[k], "*DEFINE_CURVE " + std::to_string(curves_[k].number), "LCID", "a curve in an *INCLUDE_TRANSFORM file with FCTLEN other than 1 (its units would have to be converted)");
    for (RNode& n : nodes_)
      if (const IncludeTransform* t = transform_of(n.card.file)) {
        offset(n.id, t->idnoff);
        const Vec3 p = t->map.apply({n.x, n.y, n.z});
        n.x = p[0], n.y = p[1], n.z = p[2];
      }
    for (RElem& e : elems_)
      if (const IncludeTransform* t = transform_of(e.card.file)) {
        offset(e.id, t->ideoff);
        offset(e.pid, t->idpoff);
        for (int& v : e.n) offset(v, t->idnoff);
      }
    for (RPart& p : parts_)
      if (const IncludeTransform* t = transform_of(p.ref.file)) {
        offset(p.pid, t->idpoff);
        offset(p.mid, t->idmoff);
        offset(p.secid, t->idroff);
        offset(p.hgid, t->idroff);
        offset(p.eosid, t->idroff);
      }
    const std::pair<std::map<int, RIdList>*, long long IncludeTransform::*> sets[] = {
        {&node_sets_, &IncludeTransform::idnoff}, {&part_sets_, &IncludeTransform::idpoff},
        {&solid_sets_, &IncludeTransform::ideoff}, {&shell_sets_, &IncludeTransform::ideoff}};
    for (auto [map, member] : sets) {
      for (auto& [sid, s] : *map)
        if (const IncludeTransform* t = transform_of(s.ref.file)) offset_set_members(s, *t, t->*member);
    }
    for (auto& [sid, s] : seg_sets_)
      if (const IncludeTransform* t = transform_of(s.ref.file)) {
        for (auto& seg : s.segs)
          for (int& v : seg) offset(v, t->idnoff);
        for (RSetTerm& term : s.terms)
          for (int& id : term.ids) offset(id, term.option == "PART" ? t->idpoff : t->idsoff);
      }
    for (RContact& c : contacts_)
      if (const IncludeTransform* t = transform_of(c.ref.file))
        for (RSide* side : {&c.a, &c.b}) {
          offset(side->id, side->type == 3 ? t->idpoff : t->idsoff);
          offset(side->boxid, t->iddoff);
        }
    for (RWall& w : walls_)
      if (const IncludeTransform* t = transform_of(w.nsid_ref.file)) {
        offset(w.nsid, t->idsoff);
        offset(w.nsidex, t->idsoff);
        offset(w.boxid, t->iddoff);
        w.w.tail = t->map.apply(w.w.tail);
        w.w.head = t->map.apply(w.w.head);
      }
    for (RVelocity& v : velocities_)
      if (const IncludeTransform* t = transform_of(v.ref.file)) {
        offset(v.id, v.kind == RVelocity::node ? t->idnoff : v.kind == RVelocity::part ? t->idpoff : t->idsoff);
        offset(v.nsidex, t->idsoff);
        offset(v.boxid, t->iddoff);
        offset(v.icid, t->iddoff);
        if (t->moves && (v.v != Vec3{} || v.omega != 0 || v.ve != Vec3{}))
          err(1102, v.ref, v.keyword, nullptr, "initial velocities in an *INCLUDE_TRANSFORM file that is scaled, turned or moved (the velocities would have to turn with it)");
      }
    for (RSpc& s : spcs_)
      if (const IncludeTransform* t = transform_of(s.ref.file)) {
        offset(s.id, s.set ? t->idsoff : t->idnoff);
        offset(s.cid, t->iddoff);
      }
    for (RWeld& w : welds_)
      if (const IncludeTransform* t = transform_of(w.ref.file)) {
        if (w.generalized) offset(w.nsid, t->idsoff);
        else offset(w.n1, t->idnoff), offset(w.n2, t->idnoff);
        offset(w.cid, t->iddoff);
      }
    for (RHistory& h : histories_)
      for (std::size_t j = 0; j < h.ids.size(); ++j)
        if (const IncludeTransform* t = transform_of(h.refs[j].file)) offset(h.ids[j], h.sets ? t->idsoff : h.solid ? t->ideoff : t->idnoff);
    for (auto& [bid, r] : boxes_)
      if (const IncludeTransform* t = transform_of(r.ref.file)) {
        const auto& a = t->map.a;
        const bool diagonal = a[0][1] == 0 && a[0][2] == 0 && a[1][0] == 0 && a[1][2] == 0 && a[2][0] == 0 && a[2][1] == 0;
        if (!diagonal) {
          err(1102, r.ref, "*DEFINE_BOX " + std::to_string(bid), "BOXID", "a box in a turned *INCLUDE_TRANSFORM file (it would no longer be aligned with the axes)");
          continue;
        }
        const Vec3 lo = t->map.apply(r.box.lo), hi = t->map.apply(r.box.hi);
        for (int q = 0; q < 3; ++q) {
          r.box.lo[std::size_t(q)] = std::min(lo[std::size_t(q)], hi[std::size_t(q)]);
          r.box.hi[std::size_t(q)] = std::max(lo[std::size_t(q)], hi[std::size_t(q)]);
        }
      }
    for (RCoordSystem& r : coord_defs_)
      if (const IncludeTransform* t = transform_of(r.ref.file)) {
        offset(r.cid, t->iddoff);
        for (int& v : r.n) offset(v, t->idnoff);
        if (t->moves && (r.kind == RCoordSystem::points || r.kind == RCoordSystem::vector) && r.n[0] == 0 && r.cid == 0) {
          for (int q = 0; q < 3; ++q) {  // the points move with the mesh
            const Vec3 p = t->map.apply({r.v[std::size_t(3 * q)], r.v[std::size_t(3 * q + 1)], r.v[std::size_t(3 * q + 2)]});
            for (int j = 0; j < 3; ++j) r.v[std::size_t(3 * q + j)] = p[std::size_t(j)];
          }
        } else if (t->moves && r.kind == RCoordSystem::vectors) {
          err(1102, r.ref, r.keyword, nullptr, "*DEFINE_COORDINATE_VECTOR in a turned or moved *INCLUDE_TRANSFORM file");
        }
      }
  }

  // Keywords whose absence changes what the rest of the deck means: --lenient-keywords cannot
  // ignore them (*CASE blocks select cards per case; ignoring them applied every case's cards
  // at once).
  static bool changes_meaning(const std::string& name) { return name == "CASE" || name.rfind("CASE_", 0) == 0; }

  void report_tet10() {
    if (tet10_count_ == 0) return;
    diag_.add(1102, loc_of(tet10_first_.first, "*ELEMENT_SOLID element " + std::to_string(tet10_first_.second), "N9"),
              std::to_string(tet10_count_) + " element(s) are 10-node tetrahedra (N9, N10 not 0; this is the first): IMPACT-3D has 8-node solids "
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
  std::vector<int> node_ids_;  // sorted user ids
  std::vector<int> elem_ids_;
  std::map<int, int> part_index_;      // pid -> index in parts_
  std::vector<int> part_material_;     // part index -> material index or -1
  std::vector<std::vector<int>> part_elems_;  // part index -> element indices

  bool node_ids_identity_ = false;  // node_ids_ is 1..N: the index is id - 1

  int node_index(int id) const {
    if (node_ids_identity_) return id >= 1 && id <= int(node_ids_.size()) ? id - 1 : -1;
    auto it = std::lower_bound(node_ids_.begin(), node_ids_.end(), id);
    return it != node_ids_.end() && *it == id ? int(it - node_ids_.begin()) : -1;
  }

  void err(int id, const Ref& r, const std::string& card, const char* field, std::string detail = {}) {
    diag_.add(id, loc_of(r, card, field), std::move(detail));
  }

  void resolve() {
    resolve_nodes();
    resolve_coordinate_systems();
    resolve_parts_and_elements();
    resolve_shells();
    resolve_beams();
    resolve_materials();
    resolve_shell_materials();
    resolve_beam_materials();
    build_controls(ctl_, main_.name(), m_, diag_);
    resolve_spc();
    resolve_spot_welds();
    resolve_history();
    resolve_curves();
    resolve_walls();
    resolve_velocities();
    resolve_temperatures();
    resolve_contacts();
    resolve_loads();
    resolve_timed_spc();
  }

  void resolve_nodes() {
    std::vector<std::uint32_t> order(nodes_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
    const auto by_id = [&](std::uint32_t a, std::uint32_t b) { return nodes_[a].id < nodes_[b].id; };
    if (!std::is_sorted(order.begin(), order.end(), by_id)) std::stable_sort(order.begin(), order.end(), by_id);
    // the first of each id is kept (order is filtered in place)
    std::size_t nn = 0;
    for (std::size_t q = 0; q < order.size(); ++q) {
      const RNode& n = nodes_[order[q]];
      if (nn > 0 && nodes_[order[nn - 1]].id == n.id) {
        err(1200, n.ref(), "*NODE node " + std::to_string(n.id), "NID", "node " + std::to_string(n.id) + " also defined at " + at(nodes_[order[nn - 1]].ref()));
        continue;
      }
      order[nn++] = order[q];
    }
    const auto kept = [&](std::size_t k) { return &nodes_[order[k]]; };
    assign_huge(m_.x, nn, 0.0);
    assign_huge(m_.y, nn, 0.0);
    assign_huge(m_.z, nn, 0.0);
    assign_huge(m_.bc, nn, 0);
    node_ids_.resize(nn);
    bool identity = true;
    for (std::size_t k = 0; k < nn; ++k) {
      const RNode& n = *kept(k);
      node_ids_[k] = n.id;
      m_.x[k] = n.x;
      m_.y[k] = n.y;
      m_.z[k] = n.z;
      m_.bc[k] = n.tc;
      identity = identity && n.id == int(k) + 1;
    }
    m_.node_user_id.clear();
    if (!identity) m_.node_user_id = node_ids_;
    node_ids_identity_ = identity;
    release(order);
    release(nodes_);  // the raw nodes are not needed any more
    if (nn == 0) {
      Location loc;
      loc.file = main_.name();
      diag_.add(1311, loc, "*NODE: the deck defines no nodes");
    }
  }

  void resolve_parts_and_elements() {
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      auto [it, fresh] = part_index_.emplace(parts_[k].pid, int(k));
      if (!fresh) err(1200, parts_[k].ref, "*PART " + std::to_string(parts_[k].pid), "PID", "also defined at " + at(parts_[it->second].ref));
    }
    part_elems_.assign(parts_.size(), {});
    std::vector<std::uint32_t> order(elems_.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
    const auto by_id = [&](std::uint32_t a, std::uint32_t b) { return elems_[a].id < elems_[b].id; };
    if (!std::is_sorted(order.begin(), order.end(), by_id)) std::stable_sort(order.begin(), order.end(), by_id);
    // the first of each id is kept (order is filtered in place)
    std::size_t ne = 0;
    for (std::size_t q = 0; q < order.size(); ++q) {
      const RElem& e = elems_[order[q]];
      if (ne > 0 && elems_[order[ne - 1]].id == e.id) {
        err(1200, e.ref(), "*ELEMENT_SOLID element " + std::to_string(e.id), "EID", "element " + std::to_string(e.id) + " also defined at " + at(elems_[order[ne - 1]].ref()));
        continue;
      }
      order[ne++] = order[q];
    }
    std::array<int, 8> undefined;
    undefined.fill(-1);
    assign_huge(m_.hex_nodes, ne, undefined);
    assign_huge(m_.hex_material, ne, -1);
    assign_huge(m_.hex_line, ne, 0);
    assign_huge(m_.hex_file, ne, -1);
    elem_ids_.resize(ne);
    bool identity = true;
    const DeckFile* last_file = nullptr;
    int last_file_index = -1;
    int last_pid = 0;
    auto last_part = part_index_.end();
    for (std::size_t k = 0; k < ne; ++k) {
      const RElem& e = elems_[order[k]];
      elem_ids_[k] = e.id;
      identity = identity && e.id == int(k) + 1;
      m_.hex_line[k] = e.card.line ? e.card.line->number : 0;
      if (e.card.file != last_file || !last_file) {
        last_file = e.card.file;
        last_file_index = file_index(e.card.file);
      }
      m_.hex_file[k] = last_file_index;
      const auto card = [&] { return "*ELEMENT_SOLID element " + std::to_string(e.id); };
      bool ok = true;
      std::array<int, 8> n{};
      for (int j = 0; j < 8; ++j) {
        int idx = node_index(e.n[std::size_t(j)]);
        if (idx < 0) {
          std::string f = "N" + std::to_string(j + 1);
          err(1202, e.node_ref(j), card(), f.c_str(), "node " + std::to_string(e.n[std::size_t(j)]) + " is not defined by *NODE");
          ok = false;
        }
        n[std::size_t(j)] = idx;
      }
      if (last_part == part_index_.end() || e.pid != last_pid) {
        last_part = part_index_.find(e.pid);
        last_pid = e.pid;
      }
      auto pit = last_part;
      if (pit == part_index_.end()) {
        err(1308, e.pid_ref(), card(), "PID", "part " + std::to_string(e.pid) + " is not defined by *PART" + refused_note('p', e.pid));
        ok = false;
      } else {
        part_elems_[std::size_t(pit->second)].push_back(int(k));
      }
      if (ok && !is_valid_solid_node_pattern(n)) {
        Ref r = e.node_ref(0);
        r.c2 = e.node_ref(7).c2;
        err(1222, r, card(), "N1-N8");
        ok = false;
      }
      if (ok) {
        make_canonical_solid_node_pattern(n);
        m_.hex_nodes[k] = n;
        m_.hex_material[k] = -2 - pit->second;  // part index, replaced by the material index
      }
    }
    release(order);
    release(elems_);  // the raw elements are not needed any more
    m_.hex_user_id.clear();
    if (!identity) m_.hex_user_id = elem_ids_;
    if (ne == 0 && shells_.empty() && beams_.empty()) {
      Location loc;
      loc.file = main_.name();
      diag_.add(1311, loc, "*ELEMENT_SOLID, *ELEMENT_SHELL, *ELEMENT_BEAM: the deck defines no elements");
    }
  }


  void resolve_materials() {
    for (const auto& [mid, e] : erosion_)
      if (!mats_.count(mid) && !unsupported_mids_.count(mid))
        err(1310, e.second, "*MAT_ADD_EROSION material " + std::to_string(mid), "MID", "material " + std::to_string(mid) + " is not defined by a *MAT keyword");
    part_material_.assign(parts_.size(), -1);
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const RPart& p = parts_[k];
      if (part_index_[p.pid] != int(k)) continue;  // duplicate
      std::string card = "*PART " + std::to_string(p.pid);
      bool used = !part_elems_[k].empty() || !part_shells_[k].empty() || !part_beams_[k].empty();
      if (!part_shells_[k].empty()) {  // a shell part: resolve_shell_materials
        if (!part_elems_[k].empty()) err(1102, p.sec_ref, card, "SECID", "a part of both solids and shells");
        if (!part_beams_[k].empty()) err(1102, p.sec_ref, card, "SECID", "a part of both shells and beams");
        continue;
      }
      if (!part_beams_[k].empty()) {  // a beam part: resolve_beam_materials
        if (!part_elems_[k].empty()) err(1102, p.sec_ref, card, "SECID", "a part of both solids and beams");
        continue;
      }
      auto sit = sections_.find(p.secid);
      auto mit = mats_.find(p.mid);
      if (!used && (sit == sections_.end() || mit == mats_.end())) {
        Location loc = loc_of(p.ref, card, "PID");
        diag_.add(2011, loc, "no *ELEMENT_SOLID uses it and its section or material is not a supported solid one");
        continue;
      }
      MaterialData md;
      md.number = int(m_.materials.size()) + 1;
      md.title = p.title;
      md.line = p.line;
      if (sit == sections_.end()) {
        auto u = unsupported_secids_.find(p.secid);
        if (u != unsupported_secids_.end()) err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is " + u->second + "; solids need *SECTION_SOLID");
        else err(1310, p.sec_ref, card, "SECID", "*SECTION_SOLID " + std::to_string(p.secid) + " is not defined");
      } else if (sit->second.elform != 0 && sit->second.elform != 1 && sit->second.elform != 2) {
        err(1102, sit->second.ref, "*SECTION_SOLID " + std::to_string(p.secid), "ELFORM", "only ELFORM 1 (one-point constant-stress hexahedron) and 2 (fully integrated selective-reduced)");
      }
      if (mit == mats_.end()) {
        auto u = unsupported_mids_.find(p.mid);
        if (u != unsupported_mids_.end()) err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is " + u->second + "; supported: " + supported_material_keywords());
        else err(1310, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is not defined by a *MAT keyword");
      } else {
        const RMat& r = mit->second;
        const MaterialData keep = md;
        md = r.md;
        md.number = keep.number;
        md.title = keep.title;
        md.line = keep.line;
        // the IMPACT-3D comment line INITIALLY_ELASTIC PART sets the type's switch, if it has one
        if (const MaterialParam* ie = find_param(*r.type, "IE")) {
          md.initially_elastic = initially_elastic_.count(p.pid) > 0;
          param_value(md, *ie) = md.initially_elastic ? 1.0 : 0.0;
        }
        resolve_material_curves(md, r, p.mid);
        resolve_rigid_constraints(md, r, p.mid);
        if (auto eit = erosion_.find(p.mid); eit != erosion_.end()) {
          if (r.type->rigid) err(1102, eit->second.second, "*MAT_ADD_EROSION material " + std::to_string(p.mid), "MID", "erosion of a rigid body");
          else md.erosion = eit->second.first;
        }
      }
      resolve_part_eos(md, p, card, mit != mats_.end() ? mit->second.type : nullptr);
      // hourglass and bulk viscosity
      int ihq = ctl_.ihq;
      double qm = ctl_.qh;
      md.q1 = ctl_.q1;
      md.q2 = ctl_.q2;
      if (p.hgid != 0) {
        auto hit = hourglasses_.find(p.hgid);
        if (hit == hourglasses_.end()) {
          err(1310, p.hg_ref, card, "HGID", "*HOURGLASS " + std::to_string(p.hgid) + " is not defined");
        } else {
          const RHourglass& h = hit->second;
          if (h.ihq != 0) ihq = h.ihq;
          if (h.qm > 0) qm = h.qm;
          if (!h.q1_blank) md.q1 = h.q1;
          if (!h.q2_blank) md.q2 = h.q2;
        }
      }
      md.hourglass_type = ihq == 0 ? 1 : ihq;
      md.hourglass_coef = qm > 0 ? qm : 0.10;
      md.bulk_type = ctl_.btype;
      if (sit != sections_.end() && sit->second.elform == 2) {  // no zero-energy modes: LS-DYNA ignores IHQ
        md.solid_elform = 2;
        md.hourglass_coef = 0;
      }
      part_material_[k] = int(m_.materials.size());
      m_.materials.push_back(md);
    }
    for (int& hm : m_.hex_material) {
      if (hm <= -2) {
        int mat = part_material_[std::size_t(-2 - hm)];
        hm = mat;
        if (mat < 0) {
          // the part was refused above
        }
      }
    }
    // elements of a refused part keep -1: mark them undefined so the checks skip them
    for (std::size_t e = 0; e < m_.hex_material.size(); ++e)
      if (m_.hex_material[e] < 0) m_.hex_nodes[e].fill(-1);
  }

  // *ELEMENT_SHELL cards -> Model::shell_* in increasing id order (material: -2 - part index
  // until resolve_shell_materials).
  void resolve_shells() {
    part_shells_.assign(parts_.size(), {});
    std::stable_sort(shells_.begin(), shells_.end(), [](const RShell& a, const RShell& b) { return a.id < b.id; });
    std::vector<int> ids;
    bool identity = true;
    for (std::size_t q = 0; q < shells_.size(); ++q) {
      const RShell& e = shells_[q];
      const std::string card = "*ELEMENT_SHELL element " + std::to_string(e.id);
      if (q > 0 && shells_[q - 1].id == e.id) {
        err(1200, e.ref, card, "EID", "element " + std::to_string(e.id) + " also defined at " + at(shells_[q - 1].ref));
        continue;
      }
      std::array<int, 4> n{};
      bool ok = true;
      for (int j = 0; j < 4; ++j) {
        n[std::size_t(j)] = node_index(e.n[std::size_t(j)]);
        if (n[std::size_t(j)] < 0) {
          const std::string f = "N" + std::to_string(j + 1);
          err(1202, e.node_refs[std::size_t(j)], card, f.c_str(), "node " + std::to_string(e.n[std::size_t(j)]) + " is not defined by *NODE");
          ok = false;
        }
      }
      if (ok && (n[0] == n[1] || n[0] == n[2] || n[1] == n[2] || n[0] == n[3] || n[1] == n[3])) {
        Ref r = e.node_refs[0];
        r.c2 = e.node_refs[3].c2;
        err(1222, r, card, "N1-N4", "a shell is a quadrilateral or a triangle with N3 = N4");
        ok = false;
      }
      auto pit = part_index_.find(e.pid);
      if (pit == part_index_.end()) {
        err(1308, e.pid_ref, card, "PID", "part " + std::to_string(e.pid) + " is not defined by *PART" + refused_note('p', e.pid));
        ok = false;
      }
      const int k = m_.num_shells();
      if (!ok) n.fill(-1);
      m_.shell_nodes.push_back(n);
      m_.shell_material.push_back(ok ? -2 - pit->second : -1);
      m_.shell_thickness.push_back(e.t);
      m_.shell_line.push_back(e.line);
      m_.shell_file.push_back(file_index(e.file));
      ids.push_back(e.id);
      identity = identity && e.id == k + 1;
      if (ok) part_shells_[std::size_t(pit->second)].push_back(k);
    }
    m_.shell_user_id.clear();
    if (!identity) m_.shell_user_id = ids;
    release(shells_);
    m_.shell_rotary_scale = ctl_.rotascl;
  }

  // *ELEMENT_BEAM cards -> Model::beam_* in increasing id order (material: -2 - part index
  // until resolve_beam_materials).
  void resolve_beams() {
    part_beams_.assign(parts_.size(), {});
    std::stable_sort(beams_.begin(), beams_.end(), [](const RBeam& a, const RBeam& b) { return a.id < b.id; });
    std::vector<int> ids;
    bool identity = true;
    for (std::size_t q = 0; q < beams_.size(); ++q) {
      const RBeam& e = beams_[q];
      const std::string card = "*ELEMENT_BEAM element " + std::to_string(e.id);
      if (q > 0 && beams_[q - 1].id == e.id) {
        err(1200, e.ref, card, "EID", "element " + std::to_string(e.id) + " also defined at " + at(beams_[q - 1].ref));
        continue;
      }
      std::array<int, 3> n{-1, -1, -1};
      bool ok = true;
      for (int j = 0; j < 3; ++j) {
        if (j == 2 && e.n[2] == 0) break;  // no orientation node
        n[std::size_t(j)] = node_index(e.n[std::size_t(j)]);
        if (n[std::size_t(j)] < 0) {
          const std::string f = "N" + std::to_string(j + 1);
          err(1202, e.node_refs[std::size_t(j)], card, f.c_str(), "node " + std::to_string(e.n[std::size_t(j)]) + " is not defined by *NODE");
          ok = false;
        }
      }
      if (ok && n[0] == n[1]) {
        Ref r = e.node_refs[0];
        r.c2 = e.node_refs[1].c2;
        err(1250, r, card, "N1-N2", "N1 = N2");
        ok = false;
      }
      auto pit = part_index_.find(e.pid);
      if (pit == part_index_.end()) {
        err(1308, e.pid_ref, card, "PID", "part " + std::to_string(e.pid) + " is not defined by *PART" + refused_note('p', e.pid));
        ok = false;
      }
      const int k = m_.num_beams();
      if (!ok) n.fill(-1);
      m_.beam_nodes.push_back(n);
      m_.beam_material.push_back(ok ? -2 - pit->second : -1);
      m_.beam_thickness.push_back(e.t);
      m_.beam_line.push_back(e.line);
      m_.beam_file.push_back(file_index(e.file));
      ids.push_back(e.id);
      identity = identity && e.id == k + 1;
      if (ok) part_beams_[std::size_t(pit->second)].push_back(k);
    }
    m_.beam_user_id.clear();
    if (!identity) m_.beam_user_id = ids;
    release(beams_);
  }

  // Beam parts: *SECTION_BEAM and material -> MaterialData (beam = true, its beam_section),
  // the beams' material indices.
  void resolve_beam_materials() {
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const RPart& p = parts_[k];
      if (part_index_[p.pid] != int(k) || part_beams_[k].empty() || !part_elems_[k].empty() || !part_shells_[k].empty()) continue;
      const std::string card = "*PART " + std::to_string(p.pid);
      auto sit = beam_sections_.find(p.secid);
      auto mit = mats_.find(p.mid);
      if (sit == beam_sections_.end()) {
        if (sections_.count(p.secid) || shell_sections_.count(p.secid))
          err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is not a *SECTION_BEAM; beams need *SECTION_BEAM");
        else if (auto u = unsupported_secids_.find(p.secid); u != unsupported_secids_.end())
          err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is " + u->second + "; beams need *SECTION_BEAM");
        else err(1310, p.sec_ref, card, "SECID", "*SECTION_BEAM " + std::to_string(p.secid) + " is not defined");
        continue;
      }
      if (mit == mats_.end()) {
        auto u = unsupported_mids_.find(p.mid);
        if (u != unsupported_mids_.end()) err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is " + u->second + "; supported for beams: " + beam_material_keywords());
        else err(1310, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is not defined by a *MAT keyword");
        continue;
      }
      if (p.eosid != 0) err(1102, p.eos_ref, card, "EOSID", "equations of state of beams");
      const RMat& r = mit->second;
      MaterialData md = r.md;
      md.number = int(m_.materials.size()) + 1;
      md.title = p.title;
      md.line = p.line;
      if (!has_beam_kernel(md.type)) {
        err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " (type " + std::to_string(md.type) +
                                              ") has no beam form; supported for beams: " + beam_material_keywords());
        continue;
      }
      resolve_rigid_constraints(md, r, p.mid);
      if (auto eit = erosion_.find(p.mid); eit != erosion_.end())
        err(1102, eit->second.second, "*MAT_ADD_EROSION material " + std::to_string(p.mid), "MID", "erosion (element deletion) of beams");
      md.beam = true;
      md.beam_section = sit->second.sec;
      md.bulk_type = ctl_.btype;
      const int mat = int(m_.materials.size());
      m_.materials.push_back(md);
      for (int e : part_beams_[k]) {
        m_.beam_material[std::size_t(e)] = mat;
        const auto& t = m_.beam_thickness[std::size_t(e)];
        if (md.beam_section.elform == 3 && (t[0] != 0 || t[1] != 0 || t[2] != 0 || t[3] != 0)) {
          Location loc;
          loc.file = m_.file_of(m_.beam_file, std::size_t(e));
          loc.line = m_.beam_line[std::size_t(e)];
          loc.card = "*ELEMENT_BEAM_THICKNESS element " + std::to_string(m_.beam_id(e));
          diag_.add(1102, loc, "per-element truss areas (the section's A applies)");
        }
      }
    }
    // beams of refused parts: undefined (the checks skip them)
    for (std::size_t e = 0; e < m_.beam_material.size(); ++e)
      if (m_.beam_material[e] < 0) {
        m_.beam_material[e] = -1;
        m_.beam_nodes[e].fill(-1);
      }
  }

  // Shell parts: *SECTION_SHELL and material -> MaterialData (shell = true), the shells'
  // material indices and the section's thicknesses where the element card gives none.
  void resolve_shell_materials() {
    for (std::size_t k = 0; k < parts_.size(); ++k) {
      const RPart& p = parts_[k];
      if (part_index_[p.pid] != int(k) || part_shells_[k].empty() || !part_elems_[k].empty()) continue;
      const std::string card = "*PART " + std::to_string(p.pid);
      auto sit = shell_sections_.find(p.secid);
      auto mit = mats_.find(p.mid);
      if (sit == shell_sections_.end()) {
        if (sections_.count(p.secid)) err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is a *SECTION_SOLID; shells need *SECTION_SHELL");
        else if (auto u = unsupported_secids_.find(p.secid); u != unsupported_secids_.end())
          err(1102, p.sec_ref, card, "SECID", "section " + std::to_string(p.secid) + " is " + u->second + "; shells need *SECTION_SHELL");
        else err(1310, p.sec_ref, card, "SECID", "*SECTION_SHELL " + std::to_string(p.secid) + " is not defined");
        continue;
      }
      if (mit == mats_.end()) {
        auto u = unsupported_mids_.find(p.mid);
        if (u != unsupported_mids_.end()) err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is " + u->second + "; supported for shells: " + shell_material_keywords());
        else err(1310, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " is not defined by a *MAT keyword");
        continue;
      }
      if (p.eosid != 0) err(1102, p.eos_ref, card, "EOSID", "equations of state");
      const RMat& r = mit->second;
      MaterialData md = r.md;
      md.number = int(m_.materials.size()) + 1;
      md.title = p.title;
      md.line = p.line;
      if (!has_shell_kernel(md.type)) {
        err(1103, p.mid_ref, card, "MID", "material " + std::to_string(p.mid) + " (type " + std::to_string(md.type) +
                                              ") has no shell form; supported for shells: " + shell_material_keywords());
        continue;
      }
      if (const char* feature = nullptr; const MaterialParam* q = refused_shell_param(md, &feature)) {
        const std::size_t qi = std::size_t(q - r.type->params.data());
        err(1102, qi < r.refs.size() && r.refs[qi].line ? r.refs[qi] : p.mid_ref, "*MAT material " + std::to_string(p.mid), q->key,
            std::string(feature) + " (part " + std::to_string(p.pid) + " is of shells)");
        continue;
      }
      resolve_material_curves(md, r, p.mid);
      resolve_rigid_constraints(md, r, p.mid);
      if (auto eit = erosion_.find(p.mid); eit != erosion_.end())
        err(1102, eit->second.second, "*MAT_ADD_EROSION material " + std::to_string(p.mid), "MID", "erosion (element deletion) of shells");
      md.shell = true;
      md.shell_section.elform = sit->second.elform;
      md.shell_section.nip = sit->second.nip;
      md.shell_section.shrf = sit->second.shrf;
      md.shell_section.t = sit->second.t;
      int ihq = ctl_.ihq;
      double qm = ctl_.qh;
      if (p.hgid != 0) {
        auto hit = hourglasses_.find(p.hgid);
        if (hit == hourglasses_.end()) {
          err(1310, p.hg_ref, card, "HGID", "*HOURGLASS " + std::to_string(p.hgid) + " is not defined");
        } else {
          if (hit->second.ihq != 0) ihq = hit->second.ihq;
          if (hit->second.qm > 0) qm = hit->second.qm;
        }
      }
      md.hourglass_type = ihq == 0 ? 1 : ihq;
      md.hourglass_coef = qm > 0 ? qm : 0.10;
      if (md.shell_section.elform == 16) {  // no hourglass modes: LS-DYNA ignores the part's settings
        md.hourglass_type = 1;
        md.hourglass_coef = 0;
      } else if (md.hourglass_type > 5) {
        err(1102, p.hg_ref.line ? p.hg_ref : p.ref, card, "HGID", "shell hourglass type " + std::to_string(md.hourglass_type) + " (IHQ 1-3 viscous, 4-5 stiffness)");
      }
      md.bulk_type = ctl_.btype;
      const int mat = int(m_.materials.size());
      m_.materials.push_back(md);
      for (int e : part_shells_[k]) {
        m_.shell_material[std::size_t(e)] = mat;
        auto& t = m_.shell_thickness[std::size_t(e)];
        if (t[0] == 0 && t[1] == 0 && t[2] == 0 && t[3] == 0) t = sit->second.t;
        if (!(t[0] > 0)) {
          Location loc;
          loc.file = m_.file_of(m_.shell_file, std::size_t(e));
          loc.line = m_.shell_line[std::size_t(e)];
          loc.card = "*ELEMENT_SHELL element " + std::to_string(m_.shell_id(e));
          diag_.add(1241, loc, "neither the element card nor *SECTION_SHELL " + std::to_string(p.secid) + " (T1) gives a thickness");
        }
      }
    }
    // shells of refused parts: undefined (the checks skip them)
    for (std::size_t e = 0; e < m_.shell_material.size(); ++e)
      if (m_.shell_material[e] < 0) {
        m_.shell_material[e] = -1;
        m_.shell_nodes[e].fill(-1);
      }
  }

  // Indices (into sorted ids) of the ids BBEG..BEND by INC.
  static void ids_in_range(const std::vector<int>& sorted, const std::array<long long, 3>& r, std::vector<int>& out) {
    auto lo = std::lower_bound(sorted.begin(), sorted.end(), r[0]);
    auto hi = std::upper_bound(sorted.begin(), sorted.end(), r[1]);
    for (auto it = lo; it < hi; ++it)
      if ((*it - r[0]) % r[2] == 0) out.push_back(int(it - sorted.begin()));
  }

  // the sets being resolved: a set that contains itself (through _ADD or _GENERAL) is an error
  std::set<const RIdList*> resolving_;
  bool enter_set(const RIdList& s, const Ref& r, const std::string& card) {
    if (!resolving_.insert(&s).second) {
      err(1309, r, card, "SID", "the set contains itself (through *SET_..._ADD or _GENERAL)");
      return false;
    }
    return true;
  }

  const Box* find_box(int id, const Ref& r, const std::string& card, const char* field) {
    auto it = boxes_.find(id);
    if (it == boxes_.end()) {
      err(1310, r, card, field, "*DEFINE_BOX " + std::to_string(id) + " is not defined" + refused_note('B', id));
      return nullptr;
    }
    return &it->second.box;
  }

  int elem_index(int id) const {
    auto it = std::lower_bound(elem_ids_.begin(), elem_ids_.end(), id);
    return it != elem_ids_.end() && *it == id ? int(it - elem_ids_.begin()) : -1;
  }

  const RIdList* find_solid_set(int sid, const Ref& r, const std::string& card, const char* field) {
    auto it = solid_sets_.find(sid);
    if (it == solid_sets_.end()) {
      err(1309, r, card, field, "*SET_SOLID " + std::to_string(sid) + " is not defined" + refused_note('H', sid));
      return nullptr;
    }
    return &it->second;
  }

  // The option of a *SET_..._GENERAL card that IMPACT-3D cannot resolve: error 1102 for the
  // element kinds it does not have, 1006 for anything else.
  void refuse_set_option(const RSetTerm& t, const std::string& card, const char* valid) {
    static const std::set<std::string> other_elements = {"SET_SHELL", "SET_BEAM", "SET_TSHELL", "SET_DISCRETE"};
    if (other_elements.count(t.option)) err(1102, t.ref, card, "OPTION", t.option + ": IMPACT-3D has solid elements only");
    else err(1006, t.ref, card, "OPTION", valid);
  }

  // Node set members as 0-based node indices (undefined nodes reported).  A list keeps its
  // order; a set with _ADD or _GENERAL terms is sorted, each node once.
  std::vector<int> set_nodes(const RIdList& s, const std::string& card) {
    std::vector<int> out;
    for (const auto& r : s.ranges) ids_in_range(node_ids_, r, out);  // _GENERATE
    for (std::size_t j = 0; j < s.ids.size(); ++j) {
      int idx = node_index(s.ids[j]);
      if (idx < 0) {
        err(1202, s.refs[j], card, "NID", "node " + std::to_string(s.ids[j]) + " is not defined by *NODE");
        continue;
      }
      out.push_back(idx);
    }
    if (s.terms.empty() || !enter_set(s, s.ref, card)) return out;
    std::vector<char> mark(std::size_t(m_.num_nodes()), 0);
    for (int v : out) mark[std::size_t(v)] = 1;
    for (const RSetTerm& t : s.terms) {
      const char value = t.remove ? 0 : 1;
      const auto set_all = [&](const std::vector<int>& nodes) {
        for (int v : nodes) mark[std::size_t(v)] = value;
      };
      if (t.option == "ALL") {
        std::fill(mark.begin(), mark.end(), value);
        continue;
      }
      if (t.option != "NODE" && t.option != "PART" && t.option != "BOX" && t.option != "SET_SOLID" && t.option != "SET") {
        refuse_set_option(t, card, "node set options: ALL, NODE, PART, BOX, SET_SOLID (D in front removes: DNODE, DPART, DBOX, ...)");
        continue;
      }
      for (std::size_t j = 0; j < t.ids.size(); ++j) {
        const int id = t.ids[j];
        const Ref& r = t.refs[j];
        if (t.option == "NODE") {
          const int idx = node_index(id);
          if (idx < 0) err(1202, r, card, "E", "node " + std::to_string(id) + " is not defined by *NODE");
          else mark[std::size_t(idx)] = value;
        } else if (t.option == "PART") {
          set_all(nodes_of_parts(parts_of(false, id, r, card, "E")));
        } else if (t.option == "BOX") {
          if (const Box* bx = find_box(id, r, card, "E"))
            for (std::size_t k = 0; k < mark.size(); ++k)
              if (bx->contains(m_.x[k], m_.y[k], m_.z[k])) mark[k] = value;
        } else if (t.option == "SET_SOLID") {
          if (const RIdList* ss = find_solid_set(id, r, card, "E")) set_all(nodes_of_elements(set_solids(*ss, "*SET_SOLID " + std::to_string(id))));
        } else {  // SET: a member of a *SET_NODE_ADD
          if (const RIdList* ns = find_node_set(id, r, card, "NSID")) set_all(set_nodes(*ns, "*SET_NODE " + std::to_string(id)));
        }
      }
    }
    resolving_.erase(&s);
    out.clear();
    for (std::size_t k = 0; k < mark.size(); ++k)
      if (mark[k]) out.push_back(int(k));
    return out;
  }

  // Solid set members as element indices, sorted, each once (undefined elements reported).
  std::vector<int> set_solids(const RIdList& s, const std::string& card) {
    std::vector<char> mark(std::size_t(m_.num_hexes()), 0);
    std::vector<int> in;
    for (const auto& r : s.ranges) ids_in_range(elem_ids_, r, in);
    for (std::size_t j = 0; j < s.ids.size(); ++j) {
      const int idx = elem_index(s.ids[j]);
      if (idx < 0) err(1201, s.refs[j], card, "EID", "element " + std::to_string(s.ids[j]) + " is not defined by *ELEMENT_SOLID");
      else in.push_back(idx);
    }
    for (int e : in) mark[std::size_t(e)] = 1;
    if (!s.terms.empty() && enter_set(s, s.ref, card)) {
      for (const RSetTerm& t : s.terms) {
        const char value = t.remove ? 0 : 1;
        if (t.option == "ALL") {
          std::fill(mark.begin(), mark.end(), value);
          continue;
        }
        if (t.option != "ELEM" && t.option != "PART" && t.option != "BOX" && t.option != "SET") {
          refuse_set_option(t, card, "solid set options: ALL, ELEM, PART, BOX (D in front removes: DELEM, DPART, DBOX)");
          continue;
        }
        for (std::size_t j = 0; j < t.ids.size(); ++j) {
          const int id = t.ids[j];
          const Ref& r = t.refs[j];
          if (t.option == "ELEM") {
            const int idx = elem_index(id);
            if (idx < 0) err(1201, r, card, "E", "element " + std::to_string(id) + " is not defined by *ELEMENT_SOLID");
            else mark[std::size_t(idx)] = value;
          } else if (t.option == "PART") {
            for (int p : parts_of(false, id, r, card, "E"))
              for (int e : part_elems_[std::size_t(p)]) mark[std::size_t(e)] = value;
          } else if (t.option == "BOX") {  // elements whose centroid is in the box
            if (const Box* bx = find_box(id, r, card, "E"))
              for (std::size_t e = 0; e < mark.size(); ++e) {
                const auto& nd = m_.hex_nodes[e];
                if (nd[0] < 0) continue;
                double c[3] = {0, 0, 0};
                for (int v : nd) {
                  c[0] += m_.x[std::size_t(v)] / 8;
                  c[1] += m_.y[std::size_t(v)] / 8;
                  c[2] += m_.z[std::size_t(v)] / 8;
                }
                if (bx->contains(c[0], c[1], c[2])) mark[e] = value;
              }
          } else if (const RIdList* ss = find_solid_set(id, r, card, "SID")) {  // _ADD member
            for (int e : set_solids(*ss, "*SET_SOLID " + std::to_string(id))) mark[std::size_t(e)] = value;
          }
        }
      }
      resolving_.erase(&s);
    }
    std::vector<int> out;
    for (std::size_t e = 0; e < mark.size(); ++e)
      if (mark[e]) out.push_back(int(e));
    return out;
  }

  // The nodes of elements (refused elements skipped), sorted, each once.
  std::vector<int> nodes_of_elements(const std::vector<int>& elems) {
    std::vector<char> mark(std::size_t(m_.num_nodes()), 0);
    for (int e : elems) {
      const auto& n = m_.hex_nodes[std::size_t(e)];
      if (n[0] < 0) continue;
      for (int v : n) mark[std::size_t(v)] = 1;
    }
    std::vector<int> out;
    for (std::size_t k = 0; k < mark.size(); ++k)
      if (mark[k]) out.push_back(int(k));
    return out;
  }

  // *DEFINE_COORDINATE_* and *DEFINE_VECTOR into coords_, once the nodes are known.  A system
  // given in another one (CIDL) or a vector in a system (CID) waits for that system; one that
  // never resolves names the missing system.
  void resolve_coordinate_systems() {
    std::vector<char> done(coord_defs_.size(), 0);
    for (bool progress = true; progress;) {
      progress = false;
      for (std::size_t k = 0; k < coord_defs_.size(); ++k) {
        const RCoordSystem& r = coord_defs_[k];
        if (done[k] || !coords_.has_system(r.cid)) continue;
        done[k] = 1;
        progress = true;
        build_coordinate_system(r);
      }
    }
    for (std::size_t k = 0; k < coord_defs_.size(); ++k)
      if (!done[k]) {
        const RCoordSystem& r = coord_defs_[k];
        err(1310, r.cid_ref, r.keyword + " " + std::to_string(r.id), r.kind == RCoordSystem::vector ? "CID" : "CIDL",
            "coordinate system " + std::to_string(r.cid) + " is not defined (or the systems refer to each other)");
      }
  }

  void build_coordinate_system(const RCoordSystem& r) {
    const std::string card = r.keyword + " " + std::to_string(r.id);
    const CoordinateSystem* in = coords_.system(r.cid);
    auto point = [&](int k) { return in->to_global_point({r.v[std::size_t(3 * k)], r.v[std::size_t(3 * k + 1)], r.v[std::size_t(3 * k + 2)]}); };
    std::array<Vec3, 3> p{};
    const int nodes = r.kind == RCoordSystem::nodes ? 3 : (r.kind == RCoordSystem::vector && r.n[0] != 0) ? 2 : 0;
    for (int j = 0; j < nodes; ++j) {
      const int idx = node_index(r.n[std::size_t(j)]);
      if (idx < 0) {
        err(1202, r.node_refs[std::size_t(j)], card, j == 0 ? "N1" : j == 1 ? "N2" : "N3", "node " + std::to_string(r.n[std::size_t(j)]) + " is not defined by *NODE");
        return;
      }
      p[std::size_t(j)] = {m_.x[std::size_t(idx)], m_.y[std::size_t(idx)], m_.z[std::size_t(idx)]};
    }
    if (r.kind == RCoordSystem::vector) {
      Vec3 t = nodes ? p[0] : point(0), h = nodes ? p[1] : point(1);
      Vec3 d = {h[0] - t[0], h[1] - t[1], h[2] - t[2]};
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(len > 0)) {
        err(1003, r.ref, card, "VID", "the vector has zero length (tail and head coincide)");
        return;
      }
      for (double& a : d) a /= len;
      coords_.add_vector(r.id, d);
      return;
    }
    CoordinateSystem cs;
    bool ok;
    if (r.kind == RCoordSystem::nodes) ok = coordinate_system_from_points(p[0], p[1], p[2], cs);
    else if (r.kind == RCoordSystem::points) ok = coordinate_system_from_points(point(0), point(1), point(2), cs);
    else ok = coordinate_system_from_vectors({r.v[0], r.v[1], r.v[2]}, {r.v[3], r.v[4], r.v[5]}, cs);
    if (!ok) {
      err(1003, r.ref, card, "CID", "the points (or vectors) that define the local x axis and the x-y plane are collinear or coincide");
      return;
    }
    coords_.add_system(r.id, cs);
  }

  // A direction given in system cid (0: global) in global components; false (reported) if cid
  // is not defined.
  bool global_direction(int cid, const Ref& r, const std::string& card, const char* field, std::array<double, 3>& v) {
    if (cid == 0) return true;
    if (!coords_.to_global_direction(cid, v, v)) {
      err(1310, r, card, field, "coordinate system " + std::to_string(cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
      return false;
    }
    return true;
  }

  // *MAT_RIGID CMO = -1: CON1 names a local system, CON2 six digits (x y z translations, x y z
  // rotations in it).  As for *BOUNDARY_SPC: a system whose axes are the global ones (any order
  // and sign) becomes the global codes (CMO = 1, CON1, CON2 0-7); skew axes are not supported
  // unless all or none of the translations (and of the rotations) are fixed.
  // A material's curve references (ParamCheck::curve): *DEFINE_CURVE ids -> the curves'
  // numbers 1..NUMLC, for solid and shell parts alike (an undefined id: 1310).
  void resolve_material_curves(MaterialData& md, const RMat& r, int mid) {
    for (std::size_t i = 0; i < r.type->params.size(); ++i) {
      const MaterialParam& q = r.type->params[i];
      if (q.check != ParamCheck::curve || param_value(md, q) == 0) continue;
      const int id = int(param_value(md, q));
      std::size_t k = 0;
      while (k < curves_.size() && curves_[k].number != id) ++k;
      if (k < curves_.size()) param_value(md, q) = double(k + 1);
      else err(1310, r.refs[i], "*MAT material " + std::to_string(mid), q.key, "*DEFINE_CURVE " + std::to_string(id) + " is not defined");
    }
  }

  void resolve_rigid_constraints(MaterialData& md, const RMat& r, int mid) {
    if (md.type != 20 || md.par.size() < 6 || md.par[3] != -1) return;
    const MaterialParam* con1 = find_param(*r.type, "CON1");
    const Ref& ref = r.refs[std::size_t(con1 - r.type->params.data())];
    const std::string card = "*MAT_RIGID " + std::to_string(mid);
    const int cid = int(md.par[4]);
    const CoordinateSystem* cs = coords_.system(cid);
    if (!cs) {
      err(1310, ref, card, "CON1", "coordinate system " + std::to_string(cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
      return;
    }
    long long digits = (long long)md.par[5];
    unsigned local_t = 0, local_r = 0;
    for (int i = 5; i >= 0; --i, digits /= 10)
      if (digits % 10) (i < 3 ? local_t : local_r) |= 1u << (i % 3);
    std::array<int, 3> axis{{0, 1, 2}}, sign{{1, 1, 1}};
    const bool aligned = cs->axis_aligned(axis, sign);
    auto global_bits = [&](unsigned local) -> unsigned {
      if (local == 0 || local == 7) return local;
      unsigned g = 0;
      for (int i = 0; i < 3; ++i)
        if (local & (1u << i)) g |= 1u << axis[std::size_t(i)];
      return g;
    };
    if (!aligned && ((local_t != 0 && local_t != 7) || (local_r != 0 && local_r != 7))) {
      err(1102, ref, card, "CON1", "rigid-body constraints along skew local axes (the axes of system " + std::to_string(cid) + " are not the global ones)");
      return;
    }
    auto code = [](unsigned b) {  // bits -> the 0-7 code (1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all)
      static const int c[8] = {0, 1, 2, 4, 3, 6, 5, 7};
      return c[b & 7u];
    };
    md.par[3] = 1;
    md.par[4] = code(global_bits(local_t));
    md.par[5] = code(global_bits(local_r));
  }

  // The fixed directions (bits x=1, y=2, z=4) of a *BOUNDARY_SPC in the global system: a local
  // system whose axes are global axes maps each fixed local direction onto its global axis;
  // one with skew axes is not supported unless all or none of the directions are fixed.
  int global_spc_bits(const RSpc& s) {
    if (s.cid == 0 || s.bits == 0 || s.bits == 7) return s.bits;
    const CoordinateSystem* cs = coords_.system(s.cid);
    if (!cs) {
      err(1310, s.cid_ref, s.keyword, "CID", "coordinate system " + std::to_string(s.cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
      return 0;
    }
    std::array<int, 3> axis{}, sign{};
    if (!cs->axis_aligned(axis, sign)) {
      err(1102, s.cid_ref, s.keyword, "CID", "constraints along skew local axes (the axes of system " + std::to_string(s.cid) + " are not the global ones)");
      return 0;
    }
    int bits = 0;
    for (int i = 0; i < 3; ++i)
      if (s.bits & (1 << i)) bits |= 1 << axis[std::size_t(i)];
    return bits;
  }

  const RIdList* find_node_set(int sid, const Ref& r, const std::string& card, const char* field) {
    auto it = node_sets_.find(sid);
    if (it == node_sets_.end()) {
      err(1309, r, card, field, "*SET_NODE_LIST " + std::to_string(sid) + " is not defined" + refused_note('N', sid));
      return nullptr;
    }
    return &it->second;
  }

  // Parts of a part or part set, as part indices.
  std::vector<int> parts_of(bool is_set, int id, const Ref& r, const std::string& card, const char* field) {
    std::vector<int> out;
    if (is_set) {
      auto it = part_sets_.find(id);
      if (it == part_sets_.end()) {
        err(1309, r, card, field, "*SET_PART_LIST " + std::to_string(id) + " is not defined" + refused_note('P', id));
        return out;
      }
      for (std::size_t j = 0; j < it->second.ids.size(); ++j) {
        auto p = part_index_.find(it->second.ids[j]);
        if (p == part_index_.end()) err(1308, it->second.refs[j], "*SET_PART_LIST " + std::to_string(id), "PID", "part " + std::to_string(it->second.ids[j]) + " is not defined" + refused_note('p', it->second.ids[j]));
        else out.push_back(p->second);
      }
      // _GENERATE: the parts whose ids lie in the ranges; _ADD: the parts of the member sets
      for (const auto& rg : it->second.ranges)
        for (auto p = part_index_.lower_bound(int(rg[0])); p != part_index_.end() && p->first <= rg[1]; ++p)
          if ((p->first - rg[0]) % rg[2] == 0) out.push_back(p->second);
      if (!it->second.terms.empty() && enter_set(it->second, it->second.ref, card)) {
        for (const RSetTerm& t : it->second.terms)
          for (std::size_t j = 0; j < t.ids.size(); ++j) {
            std::vector<int> more = parts_of(true, t.ids[j], t.refs[j], it->second.keyword + " " + std::to_string(id), "PSID");
            out.insert(out.end(), more.begin(), more.end());
          }
        resolving_.erase(&it->second);
        std::sort(out.begin(), out.end());
        out.erase(std::unique(out.begin(), out.end()), out.end());
      }
    } else {
      auto p = part_index_.find(id);
      if (p == part_index_.end()) err(1308, r, card, field, "part " + std::to_string(id) + " is not defined" + refused_note('p', id));
      else out.push_back(p->second);
    }
    return out;
  }

  std::vector<int> nodes_of_parts(const std::vector<int>& parts) {
    std::vector<char> mark(std::size_t(m_.num_nodes()), 0);
    for (int p : parts) {
      for (int e : part_elems_[std::size_t(p)]) {
        const auto& n = m_.hex_nodes[std::size_t(e)];
        if (n[0] < 0) continue;
        for (int v : n) mark[std::size_t(v)] = 1;
      }
      for (int e : part_shells_[std::size_t(p)]) {
        const auto& n = m_.shell_nodes[std::size_t(e)];
        if (n[0] < 0) continue;
        for (int v : n) mark[std::size_t(v)] = 1;
      }
    }
    std::vector<int> out;
    for (std::size_t k = 0; k < mark.size(); ++k)
      if (mark[k]) out.push_back(int(k));
    return out;
  }

  // The nodes of a *BOUNDARY_SPC card (its NID or NSID).
  std::vector<int> spc_nodes(const RSpc& s) {
    std::vector<int> nodes;
    const std::string& card = s.keyword;
    if (s.set) {
      if (const RIdList* set = find_node_set(s.id, s.ref, card, "NSID")) nodes = set_nodes(*set, card);
    } else {
      int idx = node_index(s.id);
      if (idx < 0) err(1202, s.ref, card, "NID", "node " + std::to_string(s.id) + " is not defined by *NODE");
      else nodes.push_back(idx);
    }
    return nodes;
  }

  // The shortest element edge of the model (solids, shells, beams; 0 when there is none).
  double shortest_edge() const {
    double h2 = std::numeric_limits<double>::infinity();
    auto edge = [&](int a, int b) {
      if (a < 0 || b < 0 || a == b) return;
      const std::size_t i = std::size_t(a), j = std::size_t(b);
      const double dx = m_.x[i] - m_.x[j], dy = m_.y[i] - m_.y[j], dz = m_.z[i] - m_.z[j];
      const double d2 = dx * dx + dy * dy + dz * dz;
      if (d2 > 0) h2 = std::min(h2, d2);
    };
    static const int hex_edges[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
    for (const auto& n : m_.hex_nodes)
      for (const auto& e : hex_edges) edge(n[std::size_t(e[0])], n[std::size_t(e[1])]);
    for (const auto& n : m_.shell_nodes)
      for (std::size_t k = 0; k < 4; ++k) edge(n[k], n[(k + 1) % 4]);
    for (const auto& n : m_.beam_nodes) edge(n[0], n[1]);
    return std::isfinite(h2) ? std::sqrt(h2) : 0.0;
  }

  // *CONSTRAINED_GLOBAL: every node within TOL of the plane (TOL 0: 1e-3 of the shortest
  // element edge) takes the plane's translational code; nodes with rotations (shells', beams')
  // also its rotational one (solid nodes have no rotations: RC means nothing for them).
  void resolve_constrained_global() {
    if (ld_.globals.empty()) return;
    const double h = shortest_edge();
    for (const RGlobalConstraint& g : ld_.globals) {
      if (g.dir < 1 || g.dir > 3) continue;  // (reported)
      const double tol = g.tol > 0 ? g.tol : 1e-3 * h;
      const std::vector<double>& c = g.dir == 1 ? m_.x : g.dir == 2 ? m_.y : m_.z;
      const int bits = bc_bits(g.tc);
      std::vector<int> rot_nodes;
      for (int n = 0; n < m_.num_nodes(); ++n) {
        if (!(std::fabs(c[std::size_t(n)] - g.at) <= tol)) continue;
        m_.bc[std::size_t(n)] = bc_code(bc_bits(m_.bc[std::size_t(n)]) | bits);
        if (g.rc != 0 && node_has_rotations(n)) rot_nodes.push_back(n);
      }
      if (!rot_nodes.empty()) add_rotational_constraints(rot_nodes, bc_bits(g.rc), g.ref);
    }
  }

  // *BOUNDARY_SPC_..._BIRTH_DEATH: each fixed direction of each node becomes a prescribed zero
  // velocity (a rotational one for rotations of nodes that have them) from BIRTH to DEATH, on a
  // zero curve added after the deck's curves (as LS-DYNA's manual writes the same constraint).
  void resolve_timed_spc() {
    int zero = -1, no_rotations = 0;
    Ref no_rotations_ref;
    for (const RSpc& s : spcs_) {
      if (!s.birth_death) continue;
      const std::vector<int> nodes = spc_nodes(s);
      const int line = s.ref.line ? s.ref.line->number : 0;
      for (int f = 0; f < 6; ++f) {
        if (!((f < 3 ? s.bits : s.rbits) & (1 << (f % 3)))) continue;
        std::array<double, 3> d{};
        d[std::size_t(f % 3)] = 1;
        if (s.cid != 0 && !coords_.to_global_direction(s.cid, d, d)) {
          err(1310, s.cid_ref, s.keyword, "CID", "coordinate system " + std::to_string(s.cid) + " is not defined by *DEFINE_COORDINATE_SYSTEM, _NODES or _VECTOR");
          return;
        }
        if (zero < 0) {
          LoadCurve lc;
          lc.number = int(m_.load_curves.size()) + 1;
          lc.t = {0.0, 1.0};
          lc.f = {0.0, 0.0};
          m_.load_curves.push_back(std::move(lc));
          m_.control.numlc = int(m_.load_curves.size());
          zero = int(m_.load_curves.size()) - 1;
        }
        for (int n : nodes) {
          if (f >= 3 && !node_has_rotations(n)) {
            if (no_rotations++ == 0) no_rotations_ref = s.ref;
            continue;
          }
          PrescribedMotion pm;
          pm.node = n;
          pm.dir = d;
          pm.kind = MotionKind::velocity;
          pm.rotation = f >= 3;
          pm.curve = zero;
          pm.scale = 1;
          pm.birth = s.birth;
          pm.death = s.death;
          pm.line = line;
          m_.prescribed_motions.push_back(pm);
        }
      }
    }
    if (no_rotations)
      diag_.add(2005, loc_of(no_rotations_ref, "", nullptr, false), std::to_string(no_rotations) + " rotational constraint(s) (*BOUNDARY_SPC_..._BIRTH_DEATH DOFR*)");
  }

  void resolve_spc() {
    resolve_constrained_global();
    for (const RSpc& s : spcs_) {
      if (s.birth_death) continue;  // resolve_timed_spc
      std::vector<int> nodes = spc_nodes(s);
      const int bits = global_spc_bits(s);
      for (int n : nodes) m_.bc[std::size_t(n)] = bc_code(bc_bits(m_.bc[std::size_t(n)]) | bits);
      if (s.rbits) add_rotational_constraints(nodes, s.rbits, s.ref);
    }
    for (const auto& [id, bits] : node_rc_) {
      const int idx = node_index(id);
      if (idx >= 0) add_rotational_constraints({idx}, bits, Ref{});
    }
    if (rotational_spc_) {
      Location loc = loc_of(rotational_ref_, "", nullptr, false);
      diag_.add(2005, loc, std::to_string(rotational_spc_) + " rotational constraint(s) (*NODE RC, *BOUNDARY_SPC DOFR*)");
    }
  }

  // Spot welds: their nodes (N1 N2, or the set's) and the normal axis of CID.
  void resolve_spot_welds() {
    for (const RWeld& r : welds_) {
      SpotWeld w;
      const std::string& card = r.keyword;
      if (r.generalized) {
        if (const RIdList* set = find_node_set(r.nsid, r.ref, card, "NSID")) w.nodes = set_nodes(*set, card);
        else continue;
        std::vector<int> sorted = w.nodes;
        std::sort(sorted.begin(), sorted.end());
        if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) remove_repeated_nodes(w.nodes);
        if (w.nodes.size() < 2) {
          err(1314, r.ref, card, "NSID", "a spot weld needs two nodes or more; set " + std::to_string(r.nsid) + " has " + std::to_string(w.nodes.size()));
          continue;
        }
      } else {
        bool ok = true;
        for (int j = 0; j < 2; ++j) {
          const int id = j == 0 ? r.n1 : r.n2;
          const int idx = node_index(id);
          if (idx < 0) {
            err(1202, j == 0 ? r.ref : r.ref2, card, j == 0 ? "N1" : "N2", "node " + std::to_string(id) + " is not defined by *NODE");
            ok = false;
          }
          w.nodes.push_back(idx);
        }
        if (!ok) continue;
        if (w.nodes[0] == w.nodes[1]) {
          Ref rr = r.ref;
          rr.c2 = r.ref2.c2;
          err(1003, rr, card, "N1-N2", "N1 = N2: a weld joins two different nodes");
          continue;
        }
      }
      if (r.cid != 0) {
        std::array<double, 3> z = {0, 0, 1};
        if (!global_direction(r.cid, r.cid_ref, card, "CID", z)) continue;
        w.has_axis = true;
        w.axis = z;
      }
      w.sn = r.sn;
      w.ss = r.ss;
      w.n = r.n;
      w.m = r.m;
      w.tfail = r.tfail > 0 ? r.tfail : 1e20;
      w.epsf = r.epsf;
      w.id = r.wid;
      w.generalized = r.generalized;
      w.line = r.ref.line ? r.ref.line->number : 0;
      w.file = file_index(r.ref.file);
      m_.spot_welds.push_back(std::move(w));
    }
  }

  // Rotational constraints act on the nodes that shells use; on other nodes they are counted
  // for warning 2005 (solids have no rotations).
  bool node_has_rotations(int n) {
    add_rotational_constraints({}, 0, Ref{});  // marks shell_node_
    return shell_node_[std::size_t(n)] != 0;
  }

  void add_rotational_constraints(const std::vector<int>& nodes, int bits, const Ref& r) {
    if (shell_node_.empty()) {
      shell_node_.assign(std::size_t(m_.num_nodes()), 0);
      for (const auto& n : m_.shell_nodes)
        if (n[0] >= 0)
          for (int v : n) shell_node_[std::size_t(v)] = 1;
      for (const auto& n : m_.beam_nodes)  // beam ends have rotations too
        if (n[0] >= 0)
          for (int j = 0; j < 2; ++j) shell_node_[std::size_t(n[std::size_t(j)])] = 1;
    }
    if (nodes.empty()) return;
    if (m_.rot_bc.empty()) m_.rot_bc.assign(std::size_t(m_.num_nodes()), 0);
    for (int n : nodes) {
      if (shell_node_[std::size_t(n)]) m_.rot_bc[std::size_t(n)] |= std::uint8_t(bits);
      else if (rotational_spc_++ == 0) rotational_ref_ = r;
    }
  }

  void resolve_history() {
    for (const RHistory& h : histories_) {
      std::vector<int> idx;
      for (std::size_t j = 0; h.sets && j < h.ids.size(); ++j) {  // _SET: the members, in order
        const std::string card = h.solid ? "*DATABASE_HISTORY_SOLID_SET" : "*DATABASE_HISTORY_NODE_SET";
        if (h.solid) {
          if (const RIdList* s = find_solid_set(h.ids[j], h.refs[j], card, "ID")) {
            std::vector<int> e = set_solids(*s, "*SET_SOLID " + std::to_string(h.ids[j]));
            idx.insert(idx.end(), e.begin(), e.end());
          }
        } else if (const RIdList* s = find_node_set(h.ids[j], h.refs[j], card, "ID")) {
          std::vector<int> n = set_nodes(*s, "*SET_NODE " + std::to_string(h.ids[j]));
          idx.insert(idx.end(), n.begin(), n.end());
        }
      }
      for (std::size_t j = 0; !h.sets && j < h.ids.size(); ++j) {
        int v = -1;
        if (h.beam) {  // beam ids: Model::beam_user_id or 1..N
          const auto& ids = m_.beam_user_id;
          if (ids.empty()) v = h.ids[j] >= 1 && h.ids[j] <= m_.num_beams() ? h.ids[j] - 1 : -1;
          else if (auto it = std::find(ids.begin(), ids.end(), h.ids[j]); it != ids.end()) v = int(it - ids.begin());
          if (v < 0) err(1201, h.refs[j], "*DATABASE_HISTORY_BEAM", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_BEAM");
        } else if (h.shell) {  // shell ids: Model::shell_user_id (increasing) or 1..N
          const auto& ids = m_.shell_user_id;
          if (ids.empty()) v = h.ids[j] >= 1 && h.ids[j] <= m_.num_shells() ? h.ids[j] - 1 : -1;
          else if (auto it = std::lower_bound(ids.begin(), ids.end(), h.ids[j]); it != ids.end() && *it == h.ids[j]) v = int(it - ids.begin());
          if (v < 0) err(1201, h.refs[j], "*DATABASE_HISTORY_SHELL", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_SHELL");
        } else if (h.solid) {
          auto it = std::lower_bound(elem_ids_.begin(), elem_ids_.end(), h.ids[j]);
          if (it != elem_ids_.end() && *it == h.ids[j]) v = int(it - elem_ids_.begin());
          else err(1201, h.refs[j], "*DATABASE_HISTORY_SOLID", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_SOLID");
        } else {
          v = node_index(h.ids[j]);
          if (v < 0) err(1202, h.refs[j], "*DATABASE_HISTORY_NODE", "NID", "node " + std::to_string(h.ids[j]) + " is not defined by *NODE");
        }
        if (v >= 0) idx.push_back(v);
      }
      auto& blocks = h.beam ? m_.beam_th_blocks : h.shell ? m_.shell_th_blocks : h.solid ? m_.solid_th_blocks : m_.node_th_blocks;
      for (std::size_t j = 0; j < idx.size();) {
        std::size_t e = j;
        while (e + 1 < idx.size() && idx[e + 1] == idx[e] + 1) ++e;
        blocks.push_back({idx[j] + 1, idx[e] + 1});
        j = e + 1;
      }
    }
    m_.control.node_th_blocks = int(m_.node_th_blocks.size());
    m_.control.solid_th_blocks = int(m_.solid_th_blocks.size());
  }

  void resolve_curves() {
    // renumbered 1..NUMLC in deck order (the fixed format needs 1..NUMLC)
    curve_used_.assign(curves_.size(), 0);
    for (std::size_t k = 0; k < curves_.size(); ++k) {
      LoadCurve lc = curves_[k];
      const std::string card = "*DEFINE_CURVE " + std::to_string(lc.number);
      if (lc.t.size() < 2) err(1003, curve_refs_[k], card, "LCID", "a curve needs at least 2 points");
      curve_index_.emplace(lc.number, int(k));
      lc.number = int(k) + 1;
      m_.load_curves.push_back(std::move(lc));
      // a curve a material uses (a flow stress curve: the *MAT card still holds the deck's id)
      // is used
      bool used = false;
      for (const auto& [mid, r] : mats_) used = used || material_uses_curve(r.md, curves_[k].number);
      for (const auto& [eid, r] : eos_) used = used || eos_curve(r.eos) == curves_[k].number;  // an EOS energy deposition
      if (used) curve_used_[k] = 1;
    }
    m_.control.numlc = int(m_.load_curves.size());
  }

  // curves no load or motion uses: one warning line (Diagnostics folds the repeats)
  void report_unused_curves() {
    for (std::size_t k = 0; k < curves_.size(); ++k)
      if (!curve_used_[k])
        diag_.add(2004, loc_of(curve_refs_[k], "*DEFINE_CURVE " + std::to_string(curves_[k].number), nullptr, false));
  }

  // 0-based index of the curve a load refers to, or -1 (error 1310)
  int curve_of(const RLoad& l) {
    auto it = curve_index_.find(l.lcid);
    if (it == curve_index_.end()) {
      if (l.lcid != 0) err(1310, l.lc_ref, l.keyword, "LCID", "*DEFINE_CURVE " + std::to_string(l.lcid) + " is not defined");
      return -1;
    }
    curve_used_[std::size_t(it->second)] = 1;
    return it->second;
  }

  std::array<double, 3> axis_direction(int dof) {
    std::array<double, 3> d{};
    if (dof >= 1 && dof <= 3) d[std::size_t(dof - 1)] = 1;
    return d;
  }

  // nodes of a load's NID or NSID
  std::vector<int> load_nodes(const RLoad& l, bool set, const char* field) {
    std::vector<int> nodes;
    if (set) {
      if (const RIdList* st = find_node_set(l.id, l.ref, l.keyword, field)) nodes = set_nodes(*st, l.keyword);
    } else {
      const int idx = node_index(l.id);
      if (idx < 0) err(1202, l.ref, l.keyword, field, "node " + std::to_string(l.id) + " is not defined by *NODE");
      else nodes.push_back(idx);
    }
    return nodes;
  }

  // the rigid material of a part (PID of *LOAD_RIGID_BODY, *BOUNDARY_PRESCRIBED_MOTION_RIGID), or -1
  int rigid_material_of_part(const RLoad& l) {
    auto p = part_index_.find(l.id);
    if (p == part_index_.end()) {
      err(1308, l.ref, l.keyword, "PID", "part " + std::to_string(l.id) + " is not defined" + refused_note('p', l.id));
      return -1;
    }
    const int mt = part_material_[std::size_t(p->second)];
    if (mt < 0) return -1;
    const MaterialType* t = find_material_type(m_.materials[std::size_t(mt)].type);  // (null: its *MAT was refused)
    if (!t || !t->rigid) {
      err(1006, l.ref, l.keyword, "PID", "part " + std::to_string(l.id) + " is not a rigid body (*MAT_RIGID)");
      return -1;
    }
    return mt;
  }

  // The global unit direction of a load or motion: DOF 1-3 along the axes of its system CID
  // (global when 0), DOF 4 along its *DEFINE_VECTOR VID, a body load's direction in its CID; a
  // motion's DOF 5-7 about the axes, 8 (and -4, -8) along or about VID.
  // False (error reported) when the system or vector is undefined.
  bool load_direction(const RLoad& l, std::array<double, 3>& d) {
    if (l.kind == RLoad::body) {
      d = l.dir;
      return global_direction(l.cid, l.cid_ref, l.keyword, "CID", d);
    }
    const bool motion = l.kind == RLoad::motion_node || l.kind == RLoad::motion_set || l.kind == RLoad::motion_rigid;
    if (motion ? motion_along_vector(l.dof) : l.dof == 4) {
      if (l.vid == 0) return false;  // (VID required: reported when read)
      if (!coords_.vector(l.vid, d)) {
        err(1310, l.vid_ref, l.keyword, "VID", "vector " + std::to_string(l.vid) + " is not defined by *DEFINE_VECTOR");
        return false;
      }
      return true;
    }
    d = axis_direction(motion && motion_is_rotation(l.dof) ? l.dof - 4 : l.dof);  // DOF 5-7: about x y z
    return global_direction(l.cid, l.cid_ref, l.keyword, "CID", d);
  }

  void resolve_damping() {
    if (!damping_given_) return;
    GlobalDamping& g = m_.damping;
    g.active = true;
    g.d = damping_.sf;
    g.factor = damping_.dir;
    g.line = damping_.ref.line ? damping_.ref.line->number : 0;
    if (damping_.lcid != 0) {
      g.curve = curve_of(damping_);
      if (g.curve < 0) g.active = false;  // (reported)
    }
    if (damping_rotations_ && m_.num_shells() > 0)
      err(2006, damping_.ref, damping_.keyword, "SRX", "the rotations of shell nodes are not damped (translations only)");
  }

  void resolve_loads() {
    resolve_damping();
    std::vector<char> rigid_node;  // nodes of rigid bodies (prescribed node motions refused there)
    for (const RLoad& l : loads_) {
      int curve = curve_of(l);
      std::array<double, 3> dir{};
      if (!load_direction(l, dir)) curve = -1;  // (reported) nothing of it is kept
      const int line = l.ref.line ? l.ref.line->number : l.lc_ref.line ? l.lc_ref.line->number : 0;
      switch (l.kind) {
        case RLoad::node:
        case RLoad::node_set:
          for (int n : load_nodes(l, l.kind == RLoad::node_set, l.kind == RLoad::node ? "NID" : "NSID")) {
            if (curve < 0) continue;
            m_.nodal_loads.push_back({n, dir, curve, l.sf, line});
          }
          break;
        case RLoad::rigid_body: {
          // the force acts at the body's centre of mass: spread over its nodes by mass (the
          // engine's rigid-body update sums it back into one force, with no moment)
          const int mt = rigid_material_of_part(l);
          if (mt < 0 || curve < 0) break;
          m_.rigid_body_loads.push_back({mt, dir, curve, l.sf, line});
          break;
        }
        case RLoad::segment:
        case RLoad::segment_set: {
          std::vector<std::array<int, 4>> faces;
          if (l.kind == RLoad::segment) {
            std::array<int, 4> f{};
            bool ok = true;
            for (int q = 0; q < 4; ++q) {
              f[std::size_t(q)] = node_index(l.nodes[std::size_t(q)]);
              if (f[std::size_t(q)] < 0) {
                const std::string fn = "N" + std::to_string(q + 1);
                err(1202, l.node_refs[std::size_t(q)], l.keyword, fn.c_str(), "node " + std::to_string(l.nodes[std::size_t(q)]) + " is not defined by *NODE");
                ok = false;
                break;
              }
            }
            if (ok) faces.push_back(f);
          } else {
            auto it = seg_sets_.find(l.id);
            if (it == seg_sets_.end()) {
              err(1309, l.ref, l.keyword, "SSID", "*SET_SEGMENT " + std::to_string(l.id) + " is not defined" + refused_note('S', l.id));
              break;
            }
            for (std::size_t j = 0; j < it->second.segs.size(); ++j) {
              std::array<int, 4> f{};
              bool ok = true;
              for (int q = 0; q < 4 && ok; ++q) {
                f[std::size_t(q)] = node_index(it->second.segs[j][std::size_t(q)]);
                if (f[std::size_t(q)] < 0) {
                  const std::string fn = "N" + std::to_string(q + 1);
                  err(1202, it->second.refs[j][std::size_t(q)], "*SET_SEGMENT " + std::to_string(l.id), fn.c_str(), "node " + std::to_string(it->second.segs[j][std::size_t(q)]) + " is not defined by *NODE");
                  ok = false;
                }
              }
              if (ok) faces.push_back(f);
            }
          }
          if (curve < 0) break;
          for (const auto& f : faces) {
            PressureLoad p;
            p.nodes = f;
            p.curve = curve;
            p.scale = l.sf;
            p.birth = l.birth;
            p.death = l.death;
            p.line = line;
            m_.pressure_loads.push_back(p);
          }
          break;
        }
        case RLoad::body:
          if (curve >= 0) m_.body_loads.push_back({dir, curve, l.sf, line});
          break;
        case RLoad::motion_node:
        case RLoad::motion_set: {
          if (rigid_node.empty()) {
            rigid_node.assign(std::size_t(m_.num_nodes()), 0);
            for (int e = 0; e < m_.num_hexes(); ++e) {
              const int mt = m_.hex_material[std::size_t(e)];
              const MaterialType* t = mt >= 0 ? find_material_type(m_.materials[std::size_t(mt)].type) : nullptr;
              if (t && t->rigid)
                for (int n : m_.hex_nodes[std::size_t(e)]) if (n >= 0) rigid_node[std::size_t(n)] = 1;
            }
          }
          int refused = 0, first = -1;
          for (int n : load_nodes(l, l.kind == RLoad::motion_set, l.kind == RLoad::motion_node ? "NID" : "NSID")) {
            if (rigid_node[std::size_t(n)]) {
              if (refused++ == 0) first = n;
              continue;
            }
            if (curve < 0) continue;
            PrescribedMotion pm;
            pm.node = n;
            pm.dir = dir;
            pm.hold_normal = l.dof < 0;  // DOF -4
            pm.kind = l.vad;
            pm.curve = curve;
            pm.scale = l.sf;
            pm.birth = l.birth;
            pm.death = l.death;
            pm.line = line;
            m_.prescribed_motions.push_back(pm);
          }
          if (refused > 0)
            err(1226, l.ref, l.keyword, l.kind == RLoad::motion_node ? "NID" : "NSID",
                std::to_string(refused) + " node(s) of rigid bodies, the first node " + std::to_string(m_.node_id(first)) +
                    ": prescribe the body's motion with *BOUNDARY_PRESCRIBED_MOTION_RIGID");
          break;
        }
        case RLoad::motion_rigid: {
          const int mt = rigid_material_of_part(l);
          if (mt < 0 || curve < 0) break;
          PrescribedMotion pm;
          pm.rigid_material = mt;
          pm.dir = dir;
          pm.rotation = motion_is_rotation(l.dof);  // about the axis dir through the centre of mass
          pm.hold_normal = l.dof < 0;                // DOF -4, -8
          pm.kind = l.vad;
          pm.curve = curve;
          pm.scale = l.sf;
          pm.birth = l.birth;
          pm.death = l.death;
          pm.line = line;
          m_.prescribed_motions.push_back(pm);
          break;
        }
      }
    }
    if (body_parts_psid_ != 0) {
      for (int p : parts_of(true, body_parts_psid_, body_parts_ref_, "*LOAD_BODY_PARTS", "PSID")) {
        const int mt = part_material_[std::size_t(p)];
        if (mt >= 0) m_.body_load_materials.push_back(mt);
      }
      std::sort(m_.body_load_materials.begin(), m_.body_load_materials.end());
      m_.body_load_materials.erase(std::unique(m_.body_load_materials.begin(), m_.body_load_materials.end()), m_.body_load_materials.end());
    }
    report_unused_curves();
  }

  void resolve_walls() {
    walls_.insert(walls_.end(), ld_.geometric_walls.begin(), ld_.geometric_walls.end());  // after the planar walls
    for (RWall& w : walls_) {
      if (w.nsidex != 0 || w.boxid != 0) {  // the nodes of NSID (0: all) in the box, less NSIDEX
        std::vector<int> nodes;
        if (w.nsid == 0) {
          for (int k = 0; k < m_.num_nodes(); ++k) nodes.push_back(k);
        } else if (const RIdList* s = find_node_set(w.nsid, w.nsid_ref, w.keyword, "NSID")) {
          nodes = set_nodes(*s, "*SET_NODE " + std::to_string(w.nsid));
        }
        std::vector<char> exempt(std::size_t(m_.num_nodes()), 0);
        if (w.nsidex != 0)
          if (const RIdList* s = find_node_set(w.nsidex, w.nsidex_ref, w.keyword, "NSIDEX"))
            for (int n : set_nodes(*s, "*SET_NODE " + std::to_string(w.nsidex))) exempt[std::size_t(n)] = 1;
        const Box* box = w.boxid != 0 ? find_box(w.boxid, w.boxid_ref, w.keyword, "BOXID") : nullptr;
        for (int n : nodes)
          if (!exempt[std::size_t(n)] && (!box || box->contains(m_.x[std::size_t(n)], m_.y[std::size_t(n)], m_.z[std::size_t(n)])))
            w.w.nodes.push_back(n);
        remove_repeated_nodes(w.w.nodes);
        if (w.w.nodes.empty()) err(1314, w.boxid != 0 ? w.boxid_ref : w.nsidex_ref, w.keyword, w.boxid != 0 ? "BOXID" : "NSIDEX", "no node is left for the wall");
      } else if (w.nsid != 0) {
        if (const RIdList* s = find_node_set(w.nsid, w.nsid_ref, w.keyword, "NSID")) {
          w.w.nodes = set_nodes(*s, "*SET_NODE_LIST " + std::to_string(w.nsid));
          remove_repeated_nodes(w.w.nodes);
          if (w.w.nodes.empty()) err(1314, w.nsid_ref, w.keyword, "NSID", "the node set has no nodes (0 = all nodes)");
        }
      }
      m_.walls.push_back(w.w);
    }
    m_.control.num_walls = int(m_.walls.size());
  }

  // Appends the nodes as initial-velocity ranges: arithmetic runs first..last by increment.
  void add_velocity_nodes(const std::vector<int>& nodes, const std::array<double, 3>& v) {
    for (std::size_t j = 0; j < nodes.size();) {
      InitialVelocity iv;
      iv.first = nodes[j] + 1;
      iv.last = iv.first;
      iv.increment = 1;
      iv.v = v;
      std::size_t e = j;
      if (j + 1 < nodes.size() && nodes[j + 1] > nodes[j]) {
        int inc = nodes[j + 1] - nodes[j];
        e = j + 1;
        while (e + 1 < nodes.size() && nodes[e + 1] - nodes[e] == inc) ++e;
        iv.increment = inc;
        iv.last = nodes[e] + 1;
      }
      m_.init_velocities.push_back(iv);
      j = e + 1;
    }
  }

  // translation v.v plus, with OMEGA, the rotation OMEGA n x (x - xc): node by node
  void add_generated_velocities(const std::vector<int>& nodes, const RVelocity& v) {
    if (v.omega == 0) {
      add_velocity_nodes(nodes, v.v);
      return;
    }
    for (int i : nodes) {
      const double r[3] = {m_.x[std::size_t(i)] - v.xc[0], m_.y[std::size_t(i)] - v.xc[1], m_.z[std::size_t(i)] - v.xc[2]};
      const std::array<double, 3> vi = {v.v[0] + v.omega * (v.n[1] * r[2] - v.n[2] * r[1]),
                                        v.v[1] + v.omega * (v.n[2] * r[0] - v.n[0] * r[2]),
                                        v.v[2] + v.omega * (v.n[0] * r[1] - v.n[1] * r[0])};
      add_velocity_nodes({i}, vi);
    }
  }

  // *INITIAL_VELOCITY with BOXID or NSIDEX: the nodes of NSID (all nodes for 0) inside the
  // box take v, except the nodes of NSIDEX, which take ve.
  void add_restricted_velocities(const RVelocity& v) {
    std::vector<int> nodes;
    if (v.id == 0) {
      for (int k = 0; k < m_.num_nodes(); ++k) nodes.push_back(k);
    } else if (const RIdList* s = find_node_set(v.id, v.ref, "*INITIAL_VELOCITY", "NSID")) {
      nodes = set_nodes(*s, "*SET_NODE " + std::to_string(v.id));
    }
    std::vector<char> exempt(std::size_t(m_.num_nodes()), 0);
    std::vector<int> exempted;
    if (v.nsidex > 0)
      if (const RIdList* s = find_node_set(v.nsidex, v.nsidex_ref, "*INITIAL_VELOCITY", "NSIDEX"))
        for (int n : set_nodes(*s, "*SET_NODE " + std::to_string(v.nsidex))) {
          if (!exempt[std::size_t(n)]) exempted.push_back(n);
          exempt[std::size_t(n)] = 1;
        }
    const Box* box = v.boxid != 0 ? find_box(v.boxid, v.boxid_ref, "*INITIAL_VELOCITY", "BOXID") : nullptr;
    std::vector<int> moved;
    for (int n : nodes) {
      if (exempt[std::size_t(n)]) continue;
      if (box && !box->contains(m_.x[std::size_t(n)], m_.y[std::size_t(n)], m_.z[std::size_t(n)])) continue;
      moved.push_back(n);
    }
    add_velocity_nodes(moved, v.v);
    std::sort(exempted.begin(), exempted.end());
    add_velocity_nodes(exempted, v.ve);
  }

  // Rotational initial velocities (VXR VYR VZR, or OMEGA n of *INITIAL_VELOCITY_GENERATION)
  // on the nodes (only shell nodes have rotations; on others they have no effect).
  void set_rotational_velocities(const std::vector<int>& nodes, const RVelocity& v) {
    std::array<double, 3> w = v.w;
    bool any = v.has_w;
    if (v.omega != 0) {
      for (int a = 0; a < 3; ++a) w[std::size_t(a)] = v.omega * v.n[std::size_t(a)];
      any = true;
    }
    if (!any) return;
    if (m_.init_omega.empty()) m_.init_omega.assign(std::size_t(m_.num_nodes()), {0, 0, 0});
    for (int n : nodes) m_.init_omega[std::size_t(n)] = w;
  }

  void resolve_velocities() {
    for (RVelocity v : velocities_) {
      // ICID: the velocities (and the rotation axis) are given in a local system
      const std::string& icid_card = v.keyword;
      if (!global_direction(v.icid, v.icid_ref, icid_card, "ICID", v.v)) continue;
      global_direction(v.icid, v.icid_ref, icid_card, "ICID", v.n);
      global_direction(v.icid, v.icid_ref, icid_card, "ICID", v.ve);
      if (v.nsidex != 0 || v.boxid != 0) {
        add_restricted_velocities(v);
        continue;
      }
      switch (v.kind) {
        case RVelocity::all: {
          InitialVelocity iv;
          iv.first = 0;
          iv.last = 0;
          iv.v = v.v;
          m_.init_velocities.push_back(iv);
          if (v.has_w) {
            std::vector<int> all(std::size_t(m_.num_nodes()));
            for (std::size_t i = 0; i < all.size(); ++i) all[i] = int(i);
            set_rotational_velocities(all, v);
          }
          break;
        }
        case RVelocity::node: {
          int idx = node_index(v.id);
          if (idx < 0) err(1202, v.ref, "*INITIAL_VELOCITY_NODE", "NID", "node " + std::to_string(v.id) + " is not defined by *NODE");
          else {
            add_velocity_nodes({idx}, v.v);
            set_rotational_velocities({idx}, v);
          }
          break;
        }
        case RVelocity::node_set:
          if (const RIdList* s = find_node_set(v.id, v.ref, "*INITIAL_VELOCITY", "NSID")) {
            const std::vector<int> nodes = set_nodes(*s, "*SET_NODE_LIST " + std::to_string(v.id));
            add_generated_velocities(nodes, v);
            set_rotational_velocities(nodes, v);
          }
          break;
        case RVelocity::part:
        case RVelocity::part_set: {
          const std::vector<int> nodes = nodes_of_parts(parts_of(v.kind == RVelocity::part_set, v.id, v.ref, "*INITIAL_VELOCITY_GENERATION", "ID"));
          add_generated_velocities(nodes, v);
          set_rotational_velocities(nodes, v);
          break;
        }
      }
    }
    m_.control.num_init_velocity_cards = int(m_.init_velocities.size());
  }

  // index of a file in Model::source_files (registered on first use)
  int file_index(const DeckFile* f) {
    if (!f) return -1;
    for (std::size_t k = 0; k < m_.source_files.size(); ++k)
      if (m_.source_files[k] == f->name()) return int(k);
    m_.source_files.push_back(f->name());
    return int(m_.source_files.size()) - 1;
  }

  // Exterior faces of a list of elements (faces not shared by two of them).
  void exterior_faces_of_elements(const std::vector<int>& elems, std::vector<std::array<int, 4>>& out, std::vector<int>& lines,
                                  std::vector<int>& files) {
    element_filter_ = &elems;
    exterior_faces({}, nullptr, out, lines, files);
    element_filter_ = nullptr;
  }
  const std::vector<int>* element_filter_ = nullptr;  // exterior_faces of these elements instead of parts'
  bool all_faces_ = false;  // exterior_faces gives every face (an eroding contact's sides), one per solid

  // The shells of the parts (or, with a node filter, every shell whose nodes are all in it) as
  // contact segments, in shell order: n1 n2 n3 n4 (both sides of a shell are used).
  void shell_segments(const std::vector<int>& parts, const std::vector<char>* node_filter,
                      std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files) {
    std::vector<int> shells;
    if (node_filter) {
      for (int k = 0; k < m_.num_shells(); ++k) shells.push_back(k);
    } else {
      for (int p : parts) shells.insert(shells.end(), part_shells_[std::size_t(p)].begin(), part_shells_[std::size_t(p)].end());
      std::sort(shells.begin(), shells.end());
      shells.erase(std::unique(shells.begin(), shells.end()), shells.end());
    }
    for (int k : shells) {
      const auto& n = m_.shell_nodes[std::size_t(k)];
      if (n[0] < 0) continue;
      if (node_filter && !std::all_of(n.begin(), n.end(), [&](int v) { return (*node_filter)[std::size_t(v)] != 0; })) continue;
      out.push_back(n);
      lines.push_back(m_.shell_line[std::size_t(k)]);
      files.push_back(m_.shell_file.empty() ? -1 : m_.shell_file[std::size_t(k)]);
    }
  }

  // Exterior faces of the elements of the parts (faces not shared by two of those elements),
  // in element and face order, outward counter-clockwise; triangles as n1 n2 n3 n3.
  void exterior_faces(const std::vector<int>& parts, const std::vector<char>* node_filter,
                      std::vector<std::array<int, 4>>& out, std::vector<int>& lines, std::vector<int>& files) {
    std::vector<int> elems;
    for (int p : parts) elems.insert(elems.end(), part_elems_[std::size_t(p)].begin(), part_elems_[std::size_t(p)].end());
    if (node_filter) {
      elems.clear();
      for (int e = 0; e < m_.num_hexes(); ++e) elems.push_back(e);
    }
    if (element_filter_) elems = *element_filter_;
    std::sort(elems.begin(), elems.end());
    elems.erase(std::unique(elems.begin(), elems.end()), elems.end());
    std::map<std::array<int, 4>, int> count;
    auto key = [](std::array<int, 4> f) {
      std::sort(f.begin(), f.end());
      auto end = std::unique(f.begin(), f.end());
      for (auto it = end; it != f.end(); ++it) *it = -1;
      return f;
    };
    auto face = [&](int e, int f) {
      const auto& n = m_.hex_nodes[std::size_t(e)];
      return std::array<int, 4>{n[std::size_t(kHexFaces[f][0])], n[std::size_t(kHexFaces[f][1])],
                                n[std::size_t(kHexFaces[f][2])], n[std::size_t(kHexFaces[f][3])]};
    };
    for (int e : elems) {
      if (m_.hex_nodes[std::size_t(e)][0] < 0) continue;
      for (int f = 0; f < 6; ++f) ++count[key(face(e, f))];
    }
    for (int e : elems) {
      if (m_.hex_nodes[std::size_t(e)][0] < 0) continue;
      for (int f = 0; f < 6; ++f) {
        std::array<int, 4> s = face(e, f);
        std::array<int, 4> k = key(s);
        if (k[2] < 0) continue;  // collapsed face (edge or point)
        if (count[k] != 1 && !all_faces_) continue;
        if (k[3] < 0) {
          // triangle: rotate the cycle so that the repeated node is n3 = n4
          for (int r = 0; r < 4 && s[2] != s[3]; ++r) s = {s[1], s[2], s[3], s[0]};
          if (s[2] != s[3]) continue;
        }
        if (node_filter) {
          bool all = true;
          for (int v : s) all = all && (*node_filter)[std::size_t(v)];
          if (!all) continue;
        }
        out.push_back(s);
        lines.push_back(m_.hex_line[std::size_t(e)]);
        files.push_back(m_.hex_file.empty() ? -1 : m_.hex_file[std::size_t(e)]);
      }
    }
  }

  // The segments of a *SET_SEGMENT: its cards, then its _ADD / _GENERAL terms in order (SET:
  // the member sets' segments; PART: the exterior faces of the part's solids, as for a contact
  // side of type 3; SET_SOLID: the exterior faces of the set's solids).
  std::set<const RSegSet*> resolving_segments_;
  void segment_set_segments(const RSegSet& s, int sid, std::vector<std::array<int, 4>>& out, std::vector<int>& lines,
                            std::vector<int>& files) {
    const std::string card = "*SET_SEGMENT " + std::to_string(sid);
    for (std::size_t j = 0; j < s.segs.size(); ++j) {
      std::array<int, 4> seg{};
      bool ok = true;
      for (int q = 0; q < 4; ++q) {
        int idx = node_index(s.segs[j][std::size_t(q)]);
        if (idx < 0) {
          std::string f = "N" + std::to_string(q + 1);
          err(1202, s.refs[j][std::size_t(q)], card, f.c_str(), "node " + std::to_string(s.segs[j][std::size_t(q)]) + " is not defined by *NODE");
          ok = false;
        }
        seg[std::size_t(q)] = idx;
      }
      if (ok) {
        out.push_back(seg);
        lines.push_back(s.refs[j][0].line ? s.refs[j][0].line->number : 0);
        files.push_back(file_index(s.refs[j][0].file));
      }
    }
    if (s.terms.empty()) return;
    if (!resolving_segments_.insert(&s).second) {
      err(1309, s.ref, card, "SID", "the set contains itself (through *SET_SEGMENT_ADD)");
      return;
    }
    for (const RSetTerm& t : s.terms) {
      if (t.remove || (t.option != "SET" && t.option != "PART" && t.option != "SET_SOLID")) {
        err(t.option == "SET_SHELL" || t.option == "BOX" || t.remove ? 1102 : 1006, t.ref, card, "OPTION",
            t.option == "SET_SHELL" || t.option == "BOX" || t.remove ? (t.remove ? "D" : "") + t.option + " in *SET_SEGMENT_GENERAL (IMPACT-3D has PART, SET_SOLID)"
                                                                     : std::string("segment set options: PART, SET_SOLID"));
        continue;
      }
      for (std::size_t j = 0; j < t.ids.size(); ++j) {
        if (t.option == "SET") {
          auto it = seg_sets_.find(t.ids[j]);
          if (it == seg_sets_.end()) err(1309, t.refs[j], card, "SSID", "*SET_SEGMENT " + std::to_string(t.ids[j]) + " is not defined" + refused_note('S', t.ids[j]));
          else segment_set_segments(it->second, t.ids[j], out, lines, files);
        } else if (t.option == "PART") {
          exterior_faces(parts_of(false, t.ids[j], t.refs[j], card, "E"), nullptr, out, lines, files);
        } else if (const RIdList* ss = find_solid_set(t.ids[j], t.refs[j], card, "E")) {
          exterior_faces_of_elements(set_solids(*ss, "*SET_SOLID " + std::to_string(t.ids[j])), out, lines, files);
        }
      }
    }
    resolving_segments_.erase(&s);
  }

  // A side's segments (out, with their cards' lines and files) and its beam nodes (the end
  // nodes of its parts' beams, or the node set's beam end nodes; in SABOXID / SBBOXID's box;
  // sorted, none a node of the side's segments): beams are contact nodes, never segments.
  // can_be_nodes: a side of beam nodes alone is a contact's slave side (else error 1255).
  void resolve_side(const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                    std::vector<int>& lines, std::vector<int>& files, std::vector<int>& beam_nodes,
                    bool can_be_nodes) {
    const int errors_before = diag_.error_count();
    const char* field = slave ? "SURFA" : "SURFB";
    std::vector<char> beam_end(std::size_t(m_.num_nodes()), 0);
    auto mark_beam_ends = [&](int e) {
      const auto& bn = m_.beam_nodes[std::size_t(e)];
      if (bn[0] >= 0 && bn[1] >= 0) beam_end[std::size_t(bn[0])] = beam_end[std::size_t(bn[1])] = 1;
    };
    auto in_set = [&](const std::vector<char>& mark, int e) {
      const auto& bn = m_.beam_nodes[std::size_t(e)];
      return bn[0] >= 0 && bn[1] >= 0 && (mark[std::size_t(bn[0])] || mark[std::size_t(bn[1])]);
    };
    if (side.type == 0) {
      auto it = seg_sets_.find(side.id);
      if (it == seg_sets_.end()) {
        err(1309, side.id_ref, card, field, "*SET_SEGMENT " + std::to_string(side.id) + " is not defined" + refused_note('S', side.id));
        return;
      }
      segment_set_segments(it->second, side.id, out, lines, files);
    } else if (side.type == 2 || side.type == 3 || side.type == 5) {
      // a part's segments: the exterior faces of its solids, then its shells (both sides)
      std::vector<int> parts;
      if (side.type == 5)
        for (std::size_t p = 0; p < parts_.size(); ++p) parts.push_back(int(p));
      else
        parts = parts_of(side.type == 2, side.id, side.id_ref, card, field);
      exterior_faces(parts, nullptr, out, lines, files);
      shell_segments(parts, nullptr, out, lines, files);
      for (int p : parts)
        for (int e : part_beams_[std::size_t(p)]) mark_beam_ends(e);
    } else if (side.type == 4) {
      if (const RIdList* s = find_node_set(side.id, side.id_ref, card, field)) {
        std::vector<char> mark(std::size_t(m_.num_nodes()), 0);
        for (int n : set_nodes(*s, "*SET_NODE_LIST " + std::to_string(side.id))) mark[std::size_t(n)] = 1;
        exterior_faces({}, &mark, out, lines, files);
        shell_segments({}, &mark, out, lines, files);
        for (int e = 0; e < m_.num_beams(); ++e)
          if (in_set(mark, e)) mark_beam_ends(e);
        for (std::size_t n = 0; n < mark.size(); ++n) beam_end[n] = char(beam_end[n] && mark[n]);
      }
    }
    if (side.boxid != 0) keep_segments_in_box(side, slave, card, out, lines, files);
    const auto bit = side.boxid != 0 ? boxes_.find(side.boxid) : boxes_.end();  // (an undefined box: 1310 above)
    const Box* box = bit != boxes_.end() ? &bit->second.box : nullptr;
    for (const auto& sg : out)
      for (int v : sg) beam_end[std::size_t(v)] = 0;
    beam_nodes.clear();
    for (std::size_t n = 0; n < beam_end.size(); ++n)
      if (beam_end[n] && (!box || box->contains(m_.x[n], m_.y[n], m_.z[n]))) beam_nodes.push_back(int(n));
    if (out.empty() && !beam_nodes.empty() && !can_be_nodes && diag_.error_count() == errors_before) {
      err(1255, side.id_ref, card, field,
          std::string(slave ? "the single surface" : "the master side (SURFB)") + " holds beams (" +
              std::to_string(beam_nodes.size()) + " beam nodes) and no solid faces or shells to strike");
      return;
    }
    if (out.empty() && beam_nodes.empty() && diag_.error_count() == errors_before &&
        (side.type == 0 || side.type == 2 || side.type == 3 || side.type == 4 || side.type == 5))
      err(1314, side.boxid != 0 ? side.box_ref : side.id_ref, card, side.boxid != 0 ? (slave ? "SABOXID" : "SBBOXID") : field,
          side.boxid != 0 ? "no segment has its centroid in the box" : "no segments");
  }

  // SABOXID / SBBOXID: the side keeps the segments whose centroid (mean of the corner nodes)
  // is in the box.
  void keep_segments_in_box(const RSide& side, bool slave, const std::string& card, std::vector<std::array<int, 4>>& out,
                            std::vector<int>& lines, std::vector<int>& files) {
    const Box* box = find_box(side.boxid, side.box_ref, card, slave ? "SABOXID" : "SBBOXID");
    if (!box) return;
    std::size_t kept = 0;
    for (std::size_t j = 0; j < out.size(); ++j) {
      double c[3] = {0, 0, 0};
      for (int v : out[j]) {
        c[0] += m_.x[std::size_t(v)] / 4;
        c[1] += m_.y[std::size_t(v)] / 4;
        c[2] += m_.z[std::size_t(v)] / 4;
      }
      if (!box->contains(c[0], c[1], c[2])) continue;
      out[kept] = out[j];
      lines[kept] = lines[j];
      files[kept] = files[j];
      ++kept;
    }
    out.resize(kept);
    lines.resize(kept);
    files.resize(kept);
  }

  // A tied contact (*CONTACT_SPOTWELD, *CONTACT_TIED_NODES_TO_SURFACE): its slave nodes (a node
  // set's nodes; a segment set's or parts' segment and beam nodes) and master segments, then
  // the ties (contact/tied_nodes.h); slave nodes out of every segment's reach warning 2015.
  void resolve_tied_contact(const RContact& c) {
    TiedContact tc;
    tc.spotweld = c.tied == 2;
    tc.id = c.cid;
    tc.line = c.ref.line ? c.ref.line->number : 0;
    tc.tolerance = c.sast < 0 ? -c.sast : 0.0;
    std::vector<int> lines, files, beam_nodes;
    if (c.a.type == 4 && c.a.boxid == 0) {
      if (const RIdList* s = find_node_set(c.a.id, c.a.id_ref, c.keyword, "SURFA"))
        tc.slave_nodes = set_nodes(*s, "*SET_NODE_LIST " + std::to_string(c.a.id));
    } else {
      std::vector<std::array<int, 4>> segs;
      resolve_side(c.a, true, c.keyword, segs, lines, files, beam_nodes, true);
      for (const auto& sg : segs) tc.slave_nodes.insert(tc.slave_nodes.end(), sg.begin(), sg.end());
      tc.slave_nodes.insert(tc.slave_nodes.end(), beam_nodes.begin(), beam_nodes.end());
    }
    std::sort(tc.slave_nodes.begin(), tc.slave_nodes.end());
    tc.slave_nodes.erase(std::unique(tc.slave_nodes.begin(), tc.slave_nodes.end()), tc.slave_nodes.end());
    lines.clear(), files.clear();
    resolve_side(c.b, false, c.keyword, tc.master, lines, files, beam_nodes, false);
    if (tc.slave_nodes.empty() || tc.master.empty()) return;  // (1309 / 1314 / 1255 above)
    m_.tied_contacts.push_back(std::move(tc));
    const std::vector<int> untied = tie_slave_nodes(m_, int(m_.tied_contacts.size()) - 1);
    if (untied.empty()) return;
    std::string ids;
    for (std::size_t k = 0; k < untied.size() && k < 10; ++k) ids += (k ? ", " : "") + std::to_string(m_.node_id(untied[k]));
    if (untied.size() > 10) ids += ", ...";
    diag_.add(2015, loc_of(c.ref, c.keyword, "SURFA"),
              std::to_string(untied.size()) + " slave node(s) lie within reach of no master segment (inside its normal "
              "projection, at most 5 % of its shorter diagonal from it, or |SAST| of a negative SAST) and are not tied: " + ids);
  }

  void resolve_contacts() {
    for (const RContact& c : contacts_) {
      if (c.tied) {
        resolve_tied_contact(c);
        continue;
      }
      if (c.transducer) {
        // side A (and B): the nodes of the segments, or of the node set
        ForceTransducer ft;
        ft.id = c.cid;
        ft.line = c.ref.line ? c.ref.line->number : 0;
        for (int sd = 0; sd < 2; ++sd) {
          const RSide& side = sd == 0 ? c.a : c.b;
          if (sd == 1 && side.id == 0) break;  // no side B: every contact force on A
          std::vector<int>& nodes = sd == 0 ? ft.a_nodes : ft.b_nodes;
          if (side.type == 4 && side.boxid == 0) {
            if (const RIdList* s = find_node_set(side.id, side.id_ref, c.keyword, sd == 0 ? "SURFA" : "SURFB"))
              nodes = set_nodes(*s, "*SET_NODE_LIST " + std::to_string(side.id));
          } else {
            std::vector<std::array<int, 4>> segs;
            std::vector<int> lines, files, beam_nodes;
            resolve_side(side, sd == 0, c.keyword, segs, lines, files, beam_nodes, true);
            for (const auto& sg : segs) nodes.insert(nodes.end(), sg.begin(), sg.end());
            nodes.insert(nodes.end(), beam_nodes.begin(), beam_nodes.end());
          }
          std::sort(nodes.begin(), nodes.end());
          nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
          if (sd == 1) ft.has_b = true;
        }
        m_.force_transducers.push_back(std::move(ft));
        continue;
      }
      SlidingInterface si;
      si.type = c.single ? 4 : 3;
      si.eroding = c.eroding;
      all_faces_ = c.eroding;  // an eroding side holds every face of its solids
      si.fs = c.fs;
      si.fd = c.fd;
      si.decay = c.dc;
      si.penalty_scale = c.sfsa == 1 ? 0 : c.sfsa * ctl_.slsfac;
      // SOFT 0 DYNA3D, 1 LS-DYNA's soft constraint, -1 IMPACT-3D maximum stable
      si.stiffness_method = c.soft == 1 ? 2 : c.soft == -1 ? 1 : 0;
      si.sofscl = c.sofscl;
      si.penopt = ctl_.penopt;
      si.symmetric = c.symmetric;
      si.shell_thickness = c.automatic ? 2 : c.thkopt == 1 ? c.shlthk : c.thkopt == 2 ? 0 : ctl_.shlthk;
      si.intfor_slave = c.sapr;
      si.intfor_master = c.sbpr;
      si.line = c.ref.line ? c.ref.line->number : 0;
      resolve_side(c.a, true, c.keyword, si.slave, si.slave_line, si.slave_file, si.slave_nodes, !c.single);
      if (!c.single) resolve_side(c.b, false, c.keyword, si.master, si.master_line, si.master_file, si.master_nodes, false);
      if (!c.symmetric) si.master_nodes.clear();  // one pass: the master side's nodes search nothing
      all_faces_ = false;
      m_.interfaces.push_back(std::move(si));
    }
    m_.control.num_interfaces = int(m_.interfaces.size());
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
