// postimpact compare A B: state-by-state comparison of two plot databases with relative and
// absolute tolerances per field.
#pragma once

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace postimpact {

struct Tolerance {
    double rel = 0.0;  // relative to the larger magnitude of the two values
    double abs = 0.0;  // absolute
};

// Fields: time, coords, vel, acc, stress, eps, energy (kinetic, internal, total, and the
// per-material energies), force, mass, temp (nodal temperatures).  A value passes when |a - b| <= abs + rel * max(|a|, |b|).
struct Tolerances {
    std::map<std::string, Tolerance> field;
    Tolerance get(const std::string& f) const;
    // File: one "FIELD REL ABS" (or "FIELD rel=R abs=A") per line, '#' comments, FIELD one of
    // the fields above, "default", or for compare-summary only (summary.h) "cycles",
    // "summary.FIELD" and "summary.KEY" (a summary key).
    // Throws std::runtime_error (file:line: message).
    static Tolerances read(const std::string& path);
    static Tolerances parse(const std::string& text, const std::string& name = "tolerances");
    static const char* const kFields[10];
};

struct CompareOptions {
    Tolerances tol;
    int report = 10;  // largest out-of-tolerance differences listed
    // States matched by time instead of by number: each state of A is compared with B's state
    // at the same time, interpolated linearly between B's two neighbouring states when B has
    // none at that time (states of A outside B's time span are left out and counted).  A family
    // of elements only one of the databases has is left out (noted), and the numbers of
    // materials may differ (the materials both have are compared).  On by itself when either
    // database is a Mili database (DYNA3D's runs against ours: other output times, contact
    // segments, DYNA3D's interface materials).
    bool by_time = false;
};

// What a comparison found, for programs (the suite report, suite.h): one row per field and the
// worst values outside tolerance, worst first (at most CompareOptions::report of them).
struct CompareFinding {
    std::string field;  // time, coords, ...
    int state = 0;      // 1-based
    double time = 0;    // of that state in A
    std::string what;   // "node", "elem", "shell", "material", "wall", "" (a global value)
    int id = 0;         // user id (node, element), material, wall or interface number
    std::string comp;   // x, sxx, kinetic, alive, ...
    double a = 0, b = 0, absd = 0, reld = 0;
    double ratio = 0;   // |a-b| / allowed (inf when nothing is allowed)
};
struct CompareFieldRow {
    std::string field;
    Tolerance tol;
    long long compared = 0, outside = 0;
    double max_abs = 0, max_rel = 0;
};
struct CompareResult {
    int states_a = 0, states_b = 0;
    std::vector<CompareFieldRow> fields;
    std::vector<CompareFinding> worst;
    std::string problem;  // why the databases are not comparable (exit 2), else empty
};

// Nodes and elements are matched by user id (per element family), so two databases of the same
// model written in different orders (ours and LS-DYNA's) compare.  Shells, thick shells and
// beams: the stresses and EPS at the middle surface (beams: axial and shear stresses, plastic
// strain), element deletion flags of every family.
// Returns 0 when every compared value is within tolerance and the databases have the same
// states (by time: every state of A in B's time span), 1 when not, 2 when they cannot be
// compared (unreadable, different node or element user ids, different numbers of parts; by
// time: no state of A in B's time span).
int compare_databases(const std::string& a, const std::string& b, const CompareOptions& opt,
                      std::ostream& out, CompareResult* result = nullptr);

}  // namespace postimpact
