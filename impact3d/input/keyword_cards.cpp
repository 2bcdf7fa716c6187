// The keyword card tables (keyword_cards.h).  One entry a keyword (or keywords with the same
// cards); the position, blank value and checks of a field are written here and nowhere else.

#include "impact3d/input/keyword_cards.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "common/messages.h"

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

std::vector<KeywordSpec> control_database_specs() {
  std::vector<KeywordSpec> t;
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
  }
  return {};
}

const KeywordField& KeywordCardLayout::field(std::string_view name) const {
  for (const KeywordField& f : fields)
    if (name == f.name) return f;
  throw std::logic_error("keyword card table: no field " + std::string(name));
}

const KeywordCardLayout& KeywordSpec::card(std::string_view label) const {
  for (const KeywordCardLayout& c : cards)
    if (label == c.card) return c;
  throw std::logic_error(std::string("keyword card table: ") + names.front() + " has no " + std::string(label));
}

const std::vector<KeywordSpec>& all_keyword_specs() {
  static const std::vector<KeywordSpec> t = control_database_specs();
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
      os << "**" << (c.card[0] ? c.card : "card 1") << "**" << (c.when[0] ? std::string(" (") + c.when + ")" : std::string())
         << ": " << c.count << " fields of " << c.width << " columns (20 in long format)";
      if (c.order == CheckOrder::after_card) os << "; checked once the card is read";
      os << "\n\n| field | columns | kind | blank | meaning | checks |\n|---|---|---|---|---|---|\n";
      for (const KeywordField& f : c.fields) {
        const int c1 = 1 + f.index * c.width;
        os << "| " << f.name << " | " << c1 << "-" << c1 + c.width - 1 << " | " << (f.kind == FieldKind::real ? "E" : "I")
           << " | " << number(f.blank) << (f.zero_is_blank ? " (also for 0)" : "") << " | " << f.meaning << " | ";
        for (std::size_t k = 0; k < f.checks.size(); ++k) {
          const KeywordCheck& ch = f.checks[k];
          const MessageDef& m = message_def(ch.id);
          os << (k ? "; " : "") << ch.text() << ": " << (m.severity == Severity::error ? "error " : "warning ") << ch.id;
          if (ch.detail) os << " (" << ch.detail << ")";
        }
        os << " |\n";
      }
      os << "\n";
    }
  }
  return os.str();
}

}  // namespace impact3d
