#pragma once
// Fixed-column card reading for DYNA3D-style decks: the deck as numbered lines, comment lines,
// Fortran integer and real fields read by columns (never by splitting on blanks), and card
// views that report every bad field through the message catalog with file, line, card, field
// and columns.

#include <cstdint>
#include <memory>
#include <new>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/messages.h"

namespace impact3d {

enum class FieldStatus { blank, ok, bad };

// Memory for the bulk arrays of the input phase.  A large block (from 4 MiB) is mapped on its
// own (mmap) and asks for transparent huge pages: reading a big deck touches hundreds of MB
// once, 2 MiB pages save most of the page faults (Linux's THP setting "madvise" needs the ask),
// and the block goes back to the system as soon as it is freed (malloc would keep it in its
// heap once its mmap threshold has grown).  Smaller blocks come from operator new.
void* allocate_bulk(std::size_t bytes);
void free_bulk(void* p, std::size_t bytes);
// Asks for huge pages on a block that is not written yet (see allocate_bulk; from 4 MiB).
void advise_huge_pages(void* p, std::size_t bytes);

template <class T>
struct HugePageAllocator {
  using value_type = T;
  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}
  T* allocate(std::size_t n) {
    if (n > std::size_t(-1) / sizeof(T)) throw std::bad_alloc();
    return static_cast<T*>(allocate_bulk(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t n) { free_bulk(p, n * sizeof(T)); }
  template <class U>
  bool operator==(const HugePageAllocator<U>&) const { return true; }
};

// Makes v hold n default elements in storage advised for huge pages (a fresh block when it
// must grow), for the bulk arrays of a model.
template <class V>
void assign_huge(V& v, std::size_t n, const typename V::value_type& value) {
  if (v.capacity() < n) {
    V().swap(v);
    v.reserve(n);
    advise_huge_pages(v.data(), n * sizeof(typename V::value_type));
  }
  v.assign(n, value);
}

// Fortran I-format: optional sign and digits, surrounding blanks allowed, blank = default.
FieldStatus parse_fortran_int(std::string_view text, long long& value);
// Fortran E/F/D-format: 1.5, 1.5e3, 1.5E+03, 2.5D-3, 1.0-5, 15, .5; blank = default.
// Infinite/NaN/overflowing values are bad.  The value is the correctly rounded double of the
// decimal number (std::from_chars; strtod for what from_chars leaves out of range).
FieldStatus parse_fortran_real(std::string_view text, double& value);

// The text of columns [c1, c2] (1-based, inclusive) that lies within the line: shorter than
// the columns, or empty, where the line ends first (the rest counts as blanks).
inline std::string_view card_columns(std::string_view line, int c1, int c2) {
  const std::size_t b = static_cast<std::size_t>(c1 - 1);
  if (b >= line.size()) return {};
  return line.substr(b, static_cast<std::size_t>(c2 - c1 + 1));
}
// True if Card would report nothing about the line itself: printable ASCII only (no tab, no
// control byte) and nothing but blanks beyond column 80.  The readers' fast paths (cards read
// without a Card, messages impossible) take only such lines.
bool is_plain_fixed_card(std::string_view line);

// DYNA3D comment line: '*' in column 1 followed by blank, '-', '*' or end of line; or '$'.
bool is_comment_line(std::string_view line);
// LS-DYNA keyword line: '*' followed by a letter.
bool is_keyword_line(std::string_view line);

struct DeckLine {
  int number = 0;          // 1-based line number in the file
  std::string_view text;   // without the line terminator (\n or \r\n), in the DeckFile's text
};

// A whole deck file: its text in one block, read in one go, and the lines as views into it
// (no copy per line).  Reading is bounded (max_bytes) so no input can exhaust memory.  The
// lines stay valid while the DeckFile lives (also when it is moved); it cannot be copied.
class DeckFile {
 public:
  static constexpr std::size_t kMaxBytes = std::size_t(1) << 30;
  DeckFile() = default;
  DeckFile(const DeckFile&) = delete;
  DeckFile& operator=(const DeckFile&) = delete;
  DeckFile(DeckFile&&) = default;
  DeckFile& operator=(DeckFile&&) = default;

  // Returns false (and reports 3003/3006) when the file cannot be read.
  bool load(const std::string& path, Diagnostics& diag);
  void load_from_string(const std::string& name, std::string_view content);

  const std::string& name() const { return name_; }
  using Lines = std::vector<DeckLine, HugePageAllocator<DeckLine>>;
  const Lines& lines() const { return lines_; }
  // The whole text as loaded.
  std::string_view text() const { return {text_.p, size_}; }

  // Sequential access to cards (comment lines skipped).
  const DeckLine* next_card();
  const DeckLine* peek_card();
  bool at_end();
  int last_line_number() const { return lines_.empty() ? 0 : lines_.back().number; }
  // Cards (lines that are not comments) from the next card to the end of the file.
  long cards_left() const { return cards_total_ - cards_read_; }
  // DYNA3D fixed format: every line with '*' in column 1 is a comment ("*basename ...", a
  // commented-out option line, is not a keyword there).  Off: is_comment_line alone.
  void set_star_comments(bool on);
  // Moves back to the line with this number (the readers' look-ahead for optional cards).
  void rewind_to_line(int number) {
    while (pos_ > 0 && lines_[pos_ - 1].number >= number) {
      --pos_;
      if (!is_comment(lines_[pos_].text)) --cards_read_;
    }
  }

 private:
  void split_lines();

  std::string name_;
  struct Text {  // the file's text, from allocate_bulk
    char* p = nullptr;
    std::size_t bytes = 0;
    Text() = default;
    explicit Text(std::size_t n) : p(static_cast<char*>(allocate_bulk(n))), bytes(n) {}
    Text(Text&& o) noexcept : p(o.p), bytes(o.bytes) { o.p = nullptr; o.bytes = 0; }
    Text& operator=(Text&& o) noexcept {
      std::swap(p, o.p);
      std::swap(bytes, o.bytes);
      return *this;
    }
    ~Text() { if (p) free_bulk(p, bytes); }
  };
  Text text_;
  std::size_t size_ = 0;
  Lines lines_;
  bool is_comment(std::string_view line) const;
  std::size_t pos_ = 0;
  long cards_total_ = 0, cards_read_ = 0;
  bool star_comments_ = false;
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
  // The columns' text within the line (card_columns): no padding, no copy.
  std::string_view columns(int c1, int c2) const { return card_columns(line_->text, c1, c2); }
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
  // i and e: the field parsed by parse (blank: def; bad: message id, def).
  template <class T, class Parse>
  T number(int c1, int c2, const char* field, T def, Parse parse, int id);
};

}  // namespace impact3d
