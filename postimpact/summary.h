// postimpact summary DB: a few numbers that characterise a run (final length and radius, the
// largest plastic strain, the final energies, the cycle count), as "key value" lines; and
// postimpact compare-summary A B: the comparison of two such files with the tolerances of
// postimpact compare (docs/regression-suites.md, "Regression suite").
#pragma once

#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "postimpact/compare.h"

namespace postimpact {

// One summary: keys in print order, values as text (numbers in %.17g, round-trip exact).
struct Summary {
    std::vector<std::pair<std::string, std::string>> items;
    const std::string* find(const std::string& key) const;
};

// Summary of the plot database ROOT.  `printed` is the printed output file (o=) the cycle count
// is read from; empty: DIR/d3hsp next to ROOT when it exists (no cycle count otherwise).
// Throws std::runtime_error when the database cannot be read.
Summary summarize(const std::string& root, const std::string& printed);

void write_summary(const Summary& s, std::ostream& out);
Summary read_summary(const std::string& path);  // throws std::runtime_error

// The tolerance field a summary key is compared with ("" = informational, not compared;
// "exact" = must be equal).
std::string summary_field(const std::string& key);

// A key's tolerance is the file's most specific line: summary.KEY, summary.FIELD (FIELD from
// summary_field), FIELD, default.
// 0: every compared key within tolerance, 1: different (or a key missing on one side).
int compare_summaries(const Summary& a, const Summary& b, const Tolerances& tol, std::ostream& out,
                      const std::string& name_a = "A", const std::string& name_b = "B");

}  // namespace postimpact
