#pragma once
// Fixed-column card reading for DYNA3D-style decks: the deck as numbered lines, comment lines,
// Fortran integer and real fields read by columns (never by splitting on blanks), and card
// views that report every bad field through the message catalog with file, line, card, field
// and columns.

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/messages.h"

namespace impact3d {

enum class FieldStatus { blank, ok, bad };

// Fortran I-format: optional sign and digits, surrounding blanks allowed, blank = default.
FieldStatus parse_fortran_int(std::string_view text, long long& value);
// Fortran E/F/D-format: 1.5, 1.5e3, 1.5E+03, 2.5D-3, 1.0-5, 15, .5; blank = default.
// Infinite/NaN/overflowing values are bad.
FieldStatus parse_fortran_real(std::string_view text, double& value);

// DYNA3D comment line: '*' in column 1 followed by blank, '-', '*' or end of line; or '$'.
bool is_comment_line(std::string_view line);
// LS-DYNA keyword line: '*' followed by a letter.
bool is_keyword_line(std::string_view line);

struct DeckLine {
  int number = 0;     // 1-based line number in the file
  std::string text;   // without the line terminator (\n or \r\n)
};

// A whole deck file held as lines.  Reading is bounded (max_bytes) so no input can exhaust
// memory.
class DeckFile {
 public:
  static constexpr std::size_t kMaxBytes = std::size_t(1) << 30;
  // Returns false (and reports 3003/3006) when the file cannot be read.
  bool load(const std::string& path, Diagnostics& diag);
  void load_from_string(const std::string& name, std::string_view content);

  const std::string& name() const { return name_; }
  const std::vector<DeckLine>& lines() const { return lines_; }

  // Sequential access to cards (comment lines skipped).
  const DeckLine* next_card();
  const DeckLine* peek_card();
  bool at_end();
  int last_line_number() const { return lines_.empty() ? 0 : lines_.back().number; }

 private:
  std::string name_;
  std::vector<DeckLine> lines_;
  std::size_t pos_ = 0;
};

// One card being read: names the card in messages and reads its fields.
class Card {
 public:
  Card(const std::string& file, const DeckLine& line, std::string card_name, Diagnostics& diag);

  // Integer in columns [c1, c2]; blank gives def; a bad field reports 1001 and gives def.
  long long i(int c1, int c2, const char* field, long long def = 0);
  // Real in columns [c1, c2]; blank gives def; a bad field reports 1002 and gives def.
  double e(int c1, int c2, const char* field, double def = 0.0);
  // Raw text of the columns (blank-padded beyond the end of the line).
  std::string a(int c1, int c2) const;
  bool blank(int c1, int c2) const;
  // True if a field is bad (for callers that need to know).
  bool had_error() const { return had_error_; }

  Location where(int c1 = 0, int c2 = 0, const char* field = nullptr) const;
  // Reports message id for columns [c1, c2].  A message about a field that already failed to
  // parse (1001/1002 on the same columns) is not reported again.
  void error(int id, int c1, int c2, const char* field, std::string detail = {},
             bool show_found = true);
  int line() const { return line_->number; }
  const std::string& name() const { return card_name_; }
  // Renames the card once its own number is known ("node card for node 417").
  void set_name(std::string name) { card_name_ = std::move(name); }

 private:
  const std::string& file_;
  const DeckLine* line_;
  std::string card_name_;
  Diagnostics& diag_;
  bool had_error_ = false;
  // Columns of the fields that failed to parse (1001/1002): a later check of the same field
  // (range, reference) would only repeat the error about the default value, so it is not shown.
  std::vector<std::pair<int, int>> bad_fields_;
};

}  // namespace impact3d
