#pragma once
// The one catalog of numbered messages.  Every message a user or a script can see comes from
// here; numbers never change meaning (scripts grep for them).  The catalog itself and the
// rendering rules are documented in README.md ("Messages").
//
//   1000-1099  card reading (fields, columns, files)
//   1100-1199  unsupported features switched on in the deck
//   1200-1299  model checks (ids, references, counts, geometry, materials)
//   1300-1399  LS-DYNA keyword decks (keywords, includes, references between keywords)
//   2000-2099  input warnings
//   3000-3099  command line and files
//   4000-4099  run-time errors (error termination)
//   5000-5099  run-time information (sense switches, output)
//   5100-5109  run checks: warnings about a run's results (impact3d/solve/run_checks.h)
//   5110-5199  run checks: the verdict (information)

#include <string>
#include <string_view>
#include <vector>
#include <map>
#include <unordered_map>
#include <ostream>

namespace impact3d {

enum class Severity { info, warning, error };

struct MessageDef {
  int id;
  Severity severity;
  const char* text;  // short, fixed description
};

// Looks up a message by number; unknown numbers abort (a programming error).
const MessageDef& message_def(int id);
// The whole catalog, sorted by number (for --help-messages and the documentation test).
const std::vector<MessageDef>& message_catalog();

// Where in a deck a message points.  Empty/zero members are left out of the rendered text.
struct Location {
  std::string file;
  int line = 0;            // 1-based line in the file
  std::string card;        // e.g. "control card 6", "material 2 card 3", "node card for node 417"
  std::string field;       // e.g. "termination time"
  int col_first = 0;       // 1-based inclusive columns
  int col_last = 0;
  std::string found;       // the text found in the field (shown quoted), if relevant
  bool show_found = false;
};

struct Diagnostic {
  int id;
  Severity severity;
  Location where;
  std::string detail;  // specifics appended to the catalog text
};

// Renders one diagnostic on one line:
//   FILE:LINE: error 1003: CARD, field FIELD (cols A-B): TEXT: DETAIL [found "X"]
std::string render(const Diagnostic& d);

// Collects diagnostics; the input phase never stops at the first error.  No message is
// dropped: repeats of one cause become one line with a count and the first ids, and past
// kMaxDistinctPerNumber different lines of one number the rest of that number is one summary
// line (count, first place, first ids), so a garbage file cannot use unbounded memory and every
// message number that occurred is printed.
class Diagnostics {
 public:
  void add(int id, Location where, std::string detail = {});
  // A line that sums up messages already added (e.g. "N keyword block(s): ..." after the 1301s
  // it lists): printed with them, but not counted again (error_count, warning_count, count).
  void add_summary(int id, Location where, std::string detail);
  int error_count() const { return errors_; }
  int warning_count() const { return warnings_; }
  // The distinct lines.  Repeats of one cause (same number, file, card with its numbers left
  // out, field, detail and text found) are folded into the first: times(k) is how many there
  // were in all.
  const std::vector<Diagnostic>& all() const { return list_; }
  int times(std::size_t k) const { return folds_[k].count; }
  // Occurrences of a number, repeats and summarised ones included.
  int count(int id) const;
  void print(std::ostream& os) const;
  bool has(int id) const;
  static constexpr int kMaxDistinctPerNumber = 200;
  static constexpr int kFirstIds = 10;
  // Occurrences summarised per number past kMaxDistinctPerNumber (shown as one line each).
  int summarised() const;

 private:
  struct Fold {
    int count = 1;
    std::vector<std::string> more;  // ids of the first repeats (number in the card, or line)
    bool summary = false;           // add_summary: not counted
  };
  std::vector<Diagnostic> list_;
  std::vector<Fold> folds_;                             // parallel to list_
  std::unordered_map<std::string, std::size_t> index_;  // cause key -> index in list_
  std::map<int, int> distinct_;                         // number -> lines in list_
  std::map<int, std::pair<Diagnostic, Fold>> overflow_;  // number -> summary of the rest
  static void add_id(Fold& f, const Location& w);
  int errors_ = 0, warnings_ = 0;
};

// Exit codes of impact3d and postimpact (documented in the README; scripts depend on them).
namespace exit_code {
constexpr int ok = 0;
constexpr int input_error = 2;       // the deck has errors (nothing was run or written to g=)
constexpr int usage_error = 3;       // bad command line
constexpr int file_error = 4;        // a file cannot be opened, read or written
constexpr int error_termination = 5; // the run stopped: negative volume, non-finite value...
constexpr int stopped_by_signal = 6; // SIGINT/SIGTERM: dump written, stopped as asked (sw1)
constexpr int suspect_run = 7;       // --strict: normal termination, but the run checks found it suspect
constexpr int internal_error = 9;    // a bug: please report
}  // namespace exit_code

}  // namespace impact3d
