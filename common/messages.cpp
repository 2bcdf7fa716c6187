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
    {1218, S::error, "segment is not a face of any solid element"},
    {1219, S::error, "friction coefficient must be in [0, 1] or stick (1)"},
    {1220, S::error, "viscosity or hourglass coefficient must not be negative"},
    {1221, S::error, "output interval must not be negative"},
    {1222, S::error, "element repeats a node in a way that is neither a wedge nor a tetrahedron"},
    {1223, S::error, "initial-velocity node range is empty"},
    {1224, S::error, "rigid-body material used together with a non-rigid material in one element set"},
    {1225, S::error, "segment nodes do not go around the element face in order (criss-crossed)"},
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
    // 3000-3099: command line and files
    {3001, S::error, "unknown command-line argument"},
    {3002, S::error, "no input deck given (use i=deck)"},
    {3003, S::error, "cannot open file for reading"},
    {3004, S::error, "cannot write file"},
    {3005, S::error, "bad command-line value"},
    {3006, S::error, "input file is too large"},
    // 4000-4099: run-time errors (error termination)
    {4001, S::error, "negative volume"},
    {4002, S::error, "non-finite value"},
    {4003, S::error, "time step below the minimum"},
    {4004, S::error, "plot database write failed"},
    {4005, S::error, "restart dump is invalid"},
    {4006, S::error, "output files do not match the restart dump (cannot continue them)"},
    // 5000-5099: run-time information
    {5001, S::info, "stop requested by signal (sense switch sw1): dump and plot state written"},
    {5002, S::info, "status requested (sense switch sw2)"},
    {5003, S::info, "plot state requested (sense switch sw4)"},
    {5004, S::info, "solid element failed (effective plastic strain reached the failure strain) and is deleted"},
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

void Diagnostics::add(int id, Location where, std::string detail) {
  const MessageDef& m = message_def(id);
  if (m.severity == Severity::error) ++errors_;
  if (m.severity == Severity::warning) ++warnings_;
  if (static_cast<int>(list_.size()) >= kMaxStored) {
    ++suppressed_;
    return;
  }
  list_.push_back({id, m.severity, std::move(where), std::move(detail)});
}

bool Diagnostics::has(int id) const {
  return std::any_of(list_.begin(), list_.end(), [id](const Diagnostic& d) { return d.id == id; });
}

void Diagnostics::print(std::ostream& os) const {
  for (const auto& d : list_) os << render(d) << '\n';
  if (suppressed_ > 0)
    os << "(" << suppressed_ << " further messages not shown)\n";
}

}  // namespace impact3d
