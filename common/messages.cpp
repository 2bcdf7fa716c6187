#include "common/messages.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace impact3d {

namespace {
using S = Severity;
const std::vector<MessageDef> kCatalog = {
    // 1000-1099: card reading
    {1001, S::error, "not an integer"},
    {1002, S::error, "not a real number"},
    {1003, S::error, "value out of range"},
    {1004, S::error, "unexpected end of file"},
    {1005, S::error, "cards left over after the last section (do the control-card counts match the cards?)"},
    {1006, S::error, "not a valid choice"},
    {1010, S::error, "text beyond column 80"},
    {1011, S::error, "tab character (columns would be ambiguous; use blanks)"},
    {1012, S::error, "non-printable character"},
    {1013, S::error, "too many errors; the rest of the deck was not checked"},
    // 1100-1199: unsupported features
    {1101, S::error, "deck format not supported"},
    {1102, S::error, "feature not supported by IMPACT-3D"},
    {1103, S::error, "material type not supported"},
    {1104, S::error, "sliding interface type not supported"},
    // 1200-1299: model checks
    {1200, S::error, "duplicate number"},
    {1201, S::error, "number outside the allowed range"},
    {1202, S::error, "reference to an undefined node"},
    {1203, S::error, "reference to an undefined material"},
    {1204, S::error, "missing definition"},
    {1205, S::error, "count does not match the cards read"},
    {1206, S::error, "non-positive element volume (inverted or badly numbered element)"},
    {1207, S::error, "density must be positive"},
    {1208, S::error, "Young's modulus must be positive"},
    {1209, S::error, "Poisson's ratio must be in [0, 0.5)"},
    {1210, S::error, "tangent modulus must be in [0, E)"},
    {1211, S::error, "yield stress must not be negative"},
    {1212, S::error, "hardening parameter beta must be in [0, 1]"},
    {1213, S::error, "rigid-wall normal has zero length (tail and head coincide)"},
    {1214, S::error, "termination time must be positive"},
    {1215, S::error, "time-step scale factor must be in (0, 1]"},
    {1216, S::error, "boundary-condition code must be 0-7"},
    {1217, S::error, "load-curve times must increase"},
    {1218, S::error, "segment is not a face of any solid element nor a shell"},
    {1219, S::error, "friction coefficient must be in [0, 1] or stick (1)"},
    {1220, S::error, "viscosity or hourglass coefficient must not be negative"},
    {1221, S::error, "output interval must not be negative"},
    {1222, S::error, "element repeats a node in a way that is neither a wedge nor a tetrahedron"},
    {1223, S::error, "initial-velocity node range is empty"},
    {1224, S::error, "rigid-body material used together with a non-rigid material in one element set"},
    {1225, S::error, "segment nodes do not go around the element face in order (criss-crossed)"},
    {1226, S::error, "prescribed motion on a node of a rigid body"},
    {1240, S::error, "non-positive shell area (collinear or badly numbered nodes)"},
    {1241, S::error, "shell thickness must be positive"},
    {1250, S::error, "beam has no length or its orientation node lies on its axis"},
    {1251, S::error, "beam section size must be positive"},
    {1252, S::error, "spot weld nodes coincide and no coordinate system gives the weld's normal direction"},
    {1253, S::error, "spot weld node is already constrained (another spot weld or a rigid body)"},
    {1254, S::error, "spot weld has no mass (its nodes belong to no element)"},
    {1255, S::error, "beam-to-beam contact is not supported: beams take part in contact as slave nodes only, against solid faces or shells"},
    {1256, S::error, "tied-contact node is already constrained (tied twice, a master node of a tie, on a rigid body or spot weld, or with SPC or a prescribed motion)"},
    // 1300-1399: LS-DYNA keyword decks
    {1301, S::error, "keyword not supported by IMPACT-3D (impact3d --lenient-keywords turns this into a warning)"},
    {1305, S::error, "data line before the first keyword"},
    {1306, S::error, "include file cannot be read"},
    {1307, S::error, "include files nested too deeply or including themselves"},
    {1308, S::error, "reference to an undefined part"},
    {1309, S::error, "reference to an undefined set"},
    {1310, S::error, "reference to an undefined definition"},
    {1311, S::error, "required keyword missing"},
    {1312, S::error, "keyword option not supported"},
    {1314, S::error, "set or contact surface is empty"},
    {1316, S::error, "the keyword ends before a required card"},
    {1317, S::error, "expression cannot be evaluated"},
    // 2000-2099: input warnings
    {2001, S::warning, "material parameters read as packed (8 per card) from card 3"},
    {2002, S::warning, "material not used by any element"},
    {2003, S::warning, "node not used by any element: it has no mass and is not moved"},
    {2004, S::warning, "load curve not used"},
    {2005, S::warning, "rotational boundary code ignored (solids have no rotations)"},
    {2006, S::warning, "field ignored by IMPACT-3D"},
    {2007, S::warning, "keyword not supported by IMPACT-3D: ignored (--lenient-keywords)"},
    {2008, S::warning, "keyword read but ignored (no effect in IMPACT-3D)"},
    {2009, S::warning, "the deck does not start with *KEYWORD"},
    {2010, S::warning, "keyword given more than once: the last one is used"},
    {2011, S::warning, "part without solid elements ignored"},
    {2012, S::warning, "stonewalls do not act on rigid-body nodes (use a sliding interface for a rigid body)"},
    {2013, S::warning, "segment node order reversed so that its normal points out of its solid element"},
    {2014, S::warning, "initial velocities on the nodes of a rigid body are not a rigid motion: the body keeps their momentum and angular momentum, and its nodes start with that rigid motion"},
    {2015, S::warning, "tied-contact slave nodes within reach of no master segment are not tied"},
    {2020, S::warning, "columns that are not read hold something: ignored"},
    {2040, S::warning, "DYNA3D fields and free-format options read but without effect in IMPACT-3D"},
    {2041, S::warning, "card in IMPACT-3D's old fixed layout: read as such (DYNA3D's own layout differs)"},
    // 3000-3099: command line and files
    {3001, S::error, "unknown command-line argument"},
    {3002, S::error, "no input deck given (use i=deck)"},
    {3003, S::error, "cannot open file for reading"},
    {3004, S::error, "cannot write file"},
    {3005, S::error, "bad command-line value"},
    {3006, S::error, "input file is too large"},
    {3007, S::error, "the deck uses what a distributed run (mpirun with more than one rank) does not carry yet: run it on one rank"},
    {3008, S::error, "launched as several processes (mpirun) but this build has no MPI: build with IMPACT3D_MPI (docs/cluster.md)"},
    // 4000-4099: run-time errors (error termination)
    {4001, S::error, "negative volume"},
    {4002, S::error, "non-finite value"},
    {4003, S::error, "time step below the minimum"},
    {4004, S::error, "plot database write failed"},
    {4005, S::error, "restart dump is invalid"},
    {4006, S::error, "output files do not match the restart dump (cannot continue them)"},
    {4007, S::error, "the run diverged: its energy grew without a source"},
    // 5000-5099: run-time information
    {5001, S::info, "stop requested by signal (sense switch sw1): dump and plot state written"},
    {5002, S::info, "status requested (sense switch sw2)"},
    {5003, S::info, "plot state requested (sense switch sw4)"},
    {5004, S::info, "solid element failed and is deleted"},
    {5005, S::info, "beam element failed and is deleted"},
    {5006, S::info, "spot weld failed and is released"},
    {5101, S::warning, "hourglass energy of a part is large against its internal energy"},
    {5102, S::warning, "energy ratio outside its band: the energy balance does not hold"},
    {5103, S::warning, "contact energy is negative beyond its limit (contact forces put energy in)"},
    {5104, S::warning, "added mass (mass scaling) beyond its limit"},
    {5105, S::warning, "nodes not caught by contact"},
    {5106, S::warning, "energy ratio swings outside its band while the time-centred balance holds: energy in modes near the step's limit"},
    {5110, S::info, "run verdict"},
};
}  // namespace

const std::vector<MessageDef>& message_catalog() { return kCatalog; }

const MessageDef& message_def(int id) {
  auto it = std::lower_bound(kCatalog.begin(), kCatalog.end(), id,
                             [](const MessageDef& m, int v) { return m.id < v; });
  if (it == kCatalog.end() || it->id != id) {
    std::fprintf(stderr, "impact3d: internal error: unknown message number %d\n", id);
    std::abort();
  }
  return *it;
}

static const char* severity_word(Severity s) {
  switch (s) {
    case Severity::info: return "info";
    case Severity::warning: return "warning";
    case Severity::error: return "error";
  }
  return "?";
}

std::string render(const Diagnostic& d) {
  std::string s;
  const Location& w = d.where;
  if (!w.file.empty()) {
    s += w.file;
    if (w.line > 0) s += ":" + std::to_string(w.line);
    s += ": ";
  }
  s += severity_word(d.severity);
  s += " " + std::to_string(d.id) + ": ";
  bool any = false;
  if (!w.card.empty()) { s += w.card; any = true; }
  if (!w.field.empty()) {
    s += any ? ", field " : "field ";
    s += "\"" + w.field + "\"";
    any = true;
  }
  if (w.col_first > 0) {
    s += " (cols " + std::to_string(w.col_first) + "-" + std::to_string(w.col_last) + ")";
    any = true;
  }
  if (any) s += ": ";
  s += message_def(d.id).text;
  if (!d.detail.empty()) s += ": " + d.detail;
  if (w.show_found) {
    std::string f = w.found;
    bool cut = f.size() > 40;
    if (cut) f.resize(40);
    // Control and non-ASCII bytes (tabs, binary garbage) are shown as \xNN so that the message
    // stays one printable line.
    std::string shown;
    for (char ch : f) {
      unsigned char c = static_cast<unsigned char>(ch);
      if (c < 32 || c >= 127) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\x%02X", c);
        shown += buf;
      } else {
        shown += ch;
      }
    }
    if (cut) shown += "...";
    s += " [found \"" + shown + "\"]";
  }
  return s;
}

namespace {
// The id an occurrence is known by in a folded line: the first number in its card ("element 17"
// -> "17"), else its line.
// A card that starts with a keyword ("*CASE_BEGIN_2", "*MAT_020 ...") keeps the keyword as it is.
std::size_t keyword_end(const std::string& c) {
  if (c.empty() || c[0] != '*') return 0;
  std::size_t e = c.find(' ');
  return e == std::string::npos ? c.size() : e;
}

std::string occurrence_id(const Location& w) {
  const std::string& c = w.card;
  for (std::size_t i = keyword_end(c); i < c.size(); ++i) {
    if (c[i] >= '0' && c[i] <= '9') {
      std::size_t j = i;
      while (j < c.size() && c[j] >= '0' && c[j] <= '9') ++j;
      return c.substr(i, j - i);
    }
  }
  return w.line > 0 ? "line " + std::to_string(w.line) : std::string();
}

// Messages of one cause: same number, file, card with its numbers left out, field, detail and
// text found.
std::string cause_key(int id, const Location& w, const std::string& detail) {
  std::string k = std::to_string(id);
  k += '\x1f';
  k += w.file;
  k += '\x1f';
  const std::size_t kw = keyword_end(w.card);
  k.append(w.card, 0, kw);
  bool in_digits = false;
  for (char ch : std::string_view(w.card).substr(kw)) {
    bool dg = ch >= '0' && ch <= '9';
    if (!dg) k += ch;
    else if (!in_digits) k += '#';
    in_digits = dg;
  }
  k += '\x1f';
  k += w.field;
  k += '\x1f';
  k += detail;
  k += '\x1f';
  if (w.show_found) k += w.found;
  return k;
}

}  // namespace

void Diagnostics::add_id(Fold& f, const Location& w) {
  if (static_cast<int>(f.more.size()) >= kFirstIds) return;
  std::string s = occurrence_id(w);
  if (!s.empty()) f.more.push_back(std::move(s));
}

void Diagnostics::add(int id, Location where, std::string detail) {
  const MessageDef& m = message_def(id);
  if (m.severity == Severity::error) ++errors_;
  if (m.severity == Severity::warning) ++warnings_;
  std::string key = cause_key(id, where, detail);
  auto it = index_.find(key);
  if (it != index_.end()) {
    Fold& f = folds_[it->second];
    ++f.count;
    add_id(f, where);
    return;
  }
  int& n = distinct_[id];
  if (n >= kMaxDistinctPerNumber) {
    auto o = overflow_.find(id);
    if (o == overflow_.end()) {
      Fold f;
      add_id(f, where);
      overflow_.emplace(id, std::make_pair(Diagnostic{id, m.severity, std::move(where), {}}, std::move(f)));
    } else {
      ++o->second.second.count;
      add_id(o->second.second, where);
    }
    return;
  }
  ++n;
  index_.emplace(std::move(key), list_.size());
  list_.push_back({id, m.severity, std::move(where), std::move(detail)});
  folds_.emplace_back();
}

void Diagnostics::add_summary(int id, Location where, std::string detail) {
  const MessageDef& m = message_def(id);
  ++distinct_[id];
  list_.push_back({id, m.severity, std::move(where), std::move(detail)});
  folds_.emplace_back();
  folds_.back().summary = true;
}

bool Diagnostics::has(int id) const { return distinct_.count(id) > 0; }

int Diagnostics::count(int id) const {
  int n = 0;
  for (std::size_t k = 0; k < list_.size(); ++k)
    if (list_[k].id == id && !folds_[k].summary) n += folds_[k].count;
  auto o = overflow_.find(id);
  if (o != overflow_.end()) n += o->second.second.count;
  return n;
}

int Diagnostics::summarised() const {
  int n = 0;
  for (const auto& [id, o] : overflow_) n += o.second.count;
  return n;
}

namespace {
std::string id_list(const std::vector<std::string>& ids, int count) {
  std::string s;
  for (const auto& x : ids) s += (s.empty() ? "" : ", ") + x;
  if (count > static_cast<int>(ids.size())) s += ", ...";
  return s;
}
}  // namespace

void Diagnostics::print(std::ostream& os) const {
  for (std::size_t k = 0; k < list_.size(); ++k) {
    os << render(list_[k]);
    const Fold& f = folds_[k];
    if (f.count > 1) {
      os << " (" << f.count << " times";
      if (!f.more.empty()) os << "; also " << id_list(f.more, f.count - 1);
      os << ")";
    }
    os << '\n';
  }
  // one line per number for the different messages past the per-number bound
  for (const auto& [id, o] : overflow_) {
    const Diagnostic& d = o.first;
    const Fold& f = o.second;
    Diagnostic s = d;
    s.where.card.clear();
    s.where.field.clear();
    s.where.col_first = s.where.col_last = 0;
    s.where.show_found = false;
    s.detail = std::to_string(f.count) + " further message(s) of this number, not shown one by one";
    if (!f.more.empty()) s.detail += " (at " + id_list(f.more, f.count) + ")";
    os << render(s) << '\n';
  }
}

}  // namespace impact3d
