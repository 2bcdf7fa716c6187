// postimpact suite: a user's regression suite (docs/regression-suites.md, "Regression suites for users").
//
// A suite is a folder:
//   decks/NAME.dyn | NAME.k | NAME.key   the decks (fixed format or keyword)
//   reference/NAME/d3plot*               stored plot database of NAME (checked with compare), or
//   summaries/NAME.txt                   its stored summary (checked with compare-summary)
//   tolerances.txt                       tolerance file of every deck (compare's format; none:
//                                        values must be equal)
//   tolerances/NAME.txt                  lines that override tolerances.txt for NAME
//   summary_decks.txt                    further decks (one path a line, from the suite folder),
//                                        checked against summaries/NAME.txt (big decks)
//   options.txt, options/NAME.txt        run options of every deck / of NAME (overriding):
//                                        "timeout SECONDS", "args WORD..." (extra impact3d
//                                        words; KEY=VALUE replaces the default of KEY),
//                                        "reference plot|summary"
// tests/regression is such a folder.  Each deck runs as `impact3d i=DECK o=d3hsp g=d3plot
// ncpu=1 plotwords=8` (plus its args) with SOURCE_DATE_EPOCH=0 in OUT/NAME/run/, killed after
// its timeout (a failure: "timeout after N s"), then its database is compared
// with the reference; the job writes OUT/NAME/result.txt, compare.txt, run.log and pictures.
// The gather step reads every OUT/NAME/result.txt and writes OUT/junit.xml and OUT/report.html.
#pragma once

#include <ostream>
#include <string>
#include <vector>

namespace postimpact {

struct SuiteDeck {
    std::string name;     // file name without extension
    std::string deck;     // absolute path
    std::string ref_dir;  // SUITE/reference/NAME
    std::string summary;  // SUITE/summaries/NAME.txt
    // from summary_decks.txt, options.txt and options/NAME.txt
    bool summary_check = false;      // checked against its summary (also what --update stores)
    double timeout = 0;              // seconds; 0: none
    std::vector<std::string> args;   // extra impact3d words
    bool plot_reference() const;     // ref_dir/d3plot exists
    bool summary_reference() const;  // summary exists
    // "plot" or "summary": summary_check, else a stored summary without a stored database
    std::string mode() const;
    // impact3d's words after the program: the suite's defaults with args on top
    std::vector<std::string> impact3d_args() const;
};

struct SuiteOptions {
    std::string suite;                // the suite folder
    std::string outdir = "suite_out";
    std::string impact3d;             // the solver; empty: found (suite.cpp find_impact3d)
    std::string self;                 // this program, for the parallel jobs
    int jobs = 0;                     // decks run at once; 0: the machine's cores
    bool pictures = true;             // pictures and time-history overlays for the HTML report
    bool update = false;              // store each run as the deck's reference instead of comparing
    std::vector<std::string> decks;   // names selected; empty: all
};

// The suite's decks (decks/ and summary_decks.txt), sorted by name, with their options.  Throws
// std::runtime_error (no such folder, no decks, two decks of one name, a missing deck of
// summary_decks.txt, an error in an options file: FILE:LINE: message).
std::vector<SuiteDeck> list_suite(const std::string& suite);

// One deck: run, compare, pictures, OUT/NAME/result.txt.  Returns 0 pass, 1 fail (outside
// tolerance), 2 error (the run failed, no reference, not comparable).
int run_suite_deck(const SuiteOptions& opt, const SuiteDeck& deck, std::ostream& log);

// Runs the selected decks, `jobs` at a time, each as its own process (`self suite ... --deck
// NAME`), then gathers.  Returns gather's status.
int run_suite(const SuiteOptions& opt, std::ostream& log);

// Reads OUT/NAME/result.txt of every selected deck and writes OUT/junit.xml and
// OUT/report.html.  Returns 0 when every deck passed, 1 when any failed, erred or has no result.
int gather_suite(const SuiteOptions& opt, std::ostream& log);

// XML / HTML text escaping (& < > " ').
std::string xml_escape(const std::string& s);

}  // namespace postimpact
