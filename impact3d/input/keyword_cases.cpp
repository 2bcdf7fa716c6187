// Keyword decks, *CASE (the family "include, parameters and cases"): *CASE_BEGIN_n ...
// *CASE_END_n sections (nested or not) and the CID=n option of a keyword line put keywords in
// child case n; a master *CASE (CASEID JOBID; a line of command-line options; lines of child
// case ids SCID) runs the main model and its children.  Without a master *CASE each child n is
// case n.  The base case (case_id 0) leaves every child out.  The reader (keyword_reader.cpp)
// marks each block with its cases while scanning and selects the case before the families read.

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "impact3d/input/keyword_families.h"

namespace impact3d::kw {

namespace {

// A master *CASE: its id and job name, child cases and command-line lines.
struct RCase {
  int id = 0;
  std::string job;
  std::vector<int> children;
  std::vector<KLine> commands;  // command-line options for the case: warned when it runs
  Ref ref;
};

// The deck's cases, for messages: the master *CASE ids, or without one the child cases.
std::string case_list(const std::vector<RCase>& master_cases, const std::set<int>& children) {
  std::string list;
  for (const RCase& c : master_cases) list += (list.empty() ? "" : ", ") + std::to_string(c.id);
  if (master_cases.empty())
    for (int c : children) list += (list.empty() ? "" : ", ") + std::to_string(c);
  return list;
}

}  // namespace

bool CaseSections::marker(const std::string& name, const DeckFile& f, const DeckLine& l, Diagnostics& diag) {
  for (const bool begin : {true, false}) {
    const std::string p = begin ? "CASE_BEGIN_" : "CASE_END_";
    if (name.rfind(p, 0) != 0) continue;
    long long n = 0;
    Location loc;
    loc.file = f.name();
    loc.line = l.number;
    loc.card = "*" + name;
    if (parse_fortran_int(name.substr(p.size()), n) != FieldStatus::ok || n < 1) {
      diag.add(1006, loc, "*" + p + "n takes a positive case number n");
      return true;
    }
    auto it = std::find(open.begin(), open.end(), int(n));
    if (begin) {
      if (it == open.end()) open.push_back(int(n));
    } else if (it == open.end()) {
      diag.add(1006, loc, "no *CASE_BEGIN_" + std::to_string(n) + " before it");
    } else {
      open.erase(it);
    }
    return true;
  }
  return false;
}

// CID=n on a keyword line (after the keyword name): the keyword belongs to child case n.
int keyword_case_option(std::string_view t) {
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

static std::vector<RCase> read_master_cases(const std::vector<Block>& blocks, KeywordContext& ctx) {
  std::vector<RCase> master_cases;
  for (const Block& b : blocks) {
    if (b.name != "CASE") continue;
    RCase c;
    c.ref.file = b.kw.file;
    c.ref.line = b.kw.line;
    std::size_t k = 0;
    while (k < b.data.size() && is_blank(b.data[k].line->text)) ++k;
    if (k >= b.data.size()) { ctx.missing_card(b, "card 1 (CASEID JOBID)"); continue; }
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
      if (const std::size_t c = std::string_view(b.data[k].line->text).find(id_text); !id_text.empty() && c != std::string::npos) {
        loc.col_first = int(c) + 1;  // the word's columns
        loc.col_last = int(c + id_text.size());
      }
      loc.found = id_text;
      loc.show_found = true;
      ctx.diag.add(1001, loc, "a positive case id");
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
    for (const RCase& o : master_cases)
      if (o.id == c.id) ctx.diag.add(1200, loc_of(c.ref, b.keyword, nullptr, false), "case " + std::to_string(c.id) + " also defined at " + at(o.ref));
    master_cases.push_back(std::move(c));
  }
  return master_cases;
}

// Leaves out the keyword blocks of the child cases the selected case does not hold.
void select_case(std::vector<Block>& blocks, const CaseSections& sections, int want, const std::string& main_file, KeywordContext& ctx,
                 Model& m) {
  const std::vector<RCase> master_cases = read_master_cases(blocks, ctx);
  Diagnostics& diag = ctx.diag;
  std::set<int> children, all_children;
  for (const Block& b : blocks) all_children.insert(b.cases.begin(), b.cases.end());
  if (!sections.open.empty()) {
    Location loc;
    loc.file = main_file;
    diag.add(1316, loc, "*CASE_BEGIN_" + std::to_string(sections.open.front()) + " has no *CASE_END_" + std::to_string(sections.open.front()));
  }
  if (want != 0) {
    std::string job;
    bool found = false;
    for (const RCase& c : master_cases)
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
          diag.add(2006, loc, "the command-line options of a case: give them on impact3d's command line");
        }
      }
    if (!found && master_cases.empty() && all_children.count(want)) {  // child n is case n
      found = true;
      children.insert(want);
    }
    if (!found) {
      const std::string list = case_list(master_cases, all_children);
      Location loc;
      loc.file = main_file;
      diag.add(1310, loc, "case=" + std::to_string(want) + ": the deck defines no such case" + (list.empty() ? std::string(" (it has no *CASE)") : " (its cases: " + list + ")"));
    }
    m.case_job = job.empty() ? "case" + std::to_string(want) : job;
  }
  std::size_t dropped = 0;
  std::vector<Block> kept;
  kept.reserve(blocks.size());
  for (Block& b : blocks) {
    bool active = b.cases.empty();
    for (int c : b.cases) active = active || children.count(c) > 0;
    if (active) kept.push_back(std::move(b));
    else ++dropped;
  }
  blocks.swap(kept);
  if (dropped) {
    const std::string list = case_list(master_cases, all_children);
    Location loc;
    loc.file = main_file;
    diag.add(2008, loc, std::to_string(dropped) + " keyword block(s) of *CASE sections left out: " +
                             (want == 0 ? "this is the base case (impact3d case=ID runs case ID; cases " + list + ")"
                                        : "they belong to other cases than " + std::to_string(want)));
  }
}

}  // namespace impact3d::kw
