#include "common/cards.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <limits>
#include <memory>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace impact3d {

namespace {
constexpr std::size_t kBulkBytes = std::size_t(4) << 20;  // blocks mapped on their own from here
}

void advise_huge_pages(void* p, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  if (!p || bytes < kBulkBytes) return;
  const std::uintptr_t b = (reinterpret_cast<std::uintptr_t>(p) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t e = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(kHuge - 1);
  if (e > b) (void)::madvise(reinterpret_cast<void*>(b), e - b, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

void* allocate_bulk(std::size_t bytes) {
#if defined(__linux__)
  if (bytes >= kBulkBytes) {
    void* p = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED) throw std::bad_alloc();
    advise_huge_pages(p, bytes);
    return p;
  }
#endif
  return ::operator new(bytes == 0 ? 1 : bytes);
}

void free_bulk(void* p, std::size_t bytes) {
  if (!p) return;
#if defined(__linux__)
  if (bytes >= kBulkBytes) {
    (void)::munmap(p, bytes);
    return;
  }
#endif
  ::operator delete(p);
}

namespace {
std::string_view trim(std::string_view s) {
  std::size_t b = 0, e = s.size();
  while (b < e && s[b] == ' ') ++b;
  while (e > b && s[e - 1] == ' ') --e;
  return s.substr(b, e - b);
}
bool is_digit(char c) { return c >= '0' && c <= '9'; }
}  // namespace

FieldStatus parse_fortran_int(std::string_view text, long long& value) {
  std::string_view s = trim(text);
  if (s.empty()) return FieldStatus::blank;
  std::size_t p = 0;
  bool neg = false;
  if (s[p] == '+' || s[p] == '-') { neg = s[p] == '-'; ++p; }
  if (p >= s.size()) return FieldStatus::bad;
  long long v = 0;
  for (; p < s.size(); ++p) {
    if (!is_digit(s[p])) return FieldStatus::bad;
    if (v > (std::numeric_limits<long long>::max() - 9) / 10) return FieldStatus::bad;
    v = v * 10 + (s[p] - '0');
  }
  if (v > std::numeric_limits<int>::max()) return FieldStatus::bad;
  value = neg ? -v : v;
  return FieldStatus::ok;
}

FieldStatus parse_fortran_real(std::string_view text, double& value) {
  std::string_view s = trim(text);
  if (s.empty()) return FieldStatus::blank;
  // The number is checked and rewritten into C form ([-]digits[.digits][e[sign]digits]) in a
  // buffer on the stack; a longer field (free format) goes through a std::string.
  char stack_buf[72];
  std::string heap_buf;
  char* norm = stack_buf;
  if (s.size() + 2 > sizeof stack_buf) {
    heap_buf.resize(s.size() + 2);
    norm = heap_buf.data();
  }
  std::size_t n = 0;
  std::size_t p = 0;
  if (s[p] == '+' || s[p] == '-') {
    if (s[p] == '-') norm[n++] = '-';  // from_chars takes no '+'; strtod gives the same without
    ++p;
  }
  int mant_digits = 0;
  while (p < s.size() && is_digit(s[p])) { norm[n++] = s[p++]; ++mant_digits; }
  if (p < s.size() && s[p] == '.') {
    norm[n++] = s[p++];
    while (p < s.size() && is_digit(s[p])) { norm[n++] = s[p++]; ++mant_digits; }
  }
  if (mant_digits == 0) return FieldStatus::bad;
  if (p < s.size()) {
    // exponent: letter (e, E, d, D) with optional sign, or a bare sign (Fortran 1.0-5)
    char c = s[p];
    if (c == 'e' || c == 'E' || c == 'd' || c == 'D') {
      ++p;
    } else if (c != '+' && c != '-') {
      return FieldStatus::bad;
    }
    norm[n++] = 'e';
    if (p < s.size() && (s[p] == '+' || s[p] == '-')) norm[n++] = s[p++];
    int exp_digits = 0;
    while (p < s.size() && is_digit(s[p])) { norm[n++] = s[p++]; ++exp_digits; }
    if (exp_digits == 0 || exp_digits > 4 || p != s.size()) return FieldStatus::bad;
  }
  // from_chars and strtod both give the correctly rounded double (round to nearest), so the
  // bits are the same; what from_chars reports out of range (overflow, underflow) is left to
  // the strtod rules: overflow is bad, an underflow gives strtod's tiny value or zero.
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(norm, norm + n, v);
  if (ec == std::errc() && ptr == norm + n && std::isfinite(v)) {
    value = v;
    return FieldStatus::ok;
  }
  norm[n] = '\0';
  errno = 0;
  char* end = nullptr;
  v = std::strtod(norm, &end);
  if (end != norm + n) return FieldStatus::bad;
  if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0)) return FieldStatus::bad;
  value = v;
  return FieldStatus::ok;
}

bool is_plain_fixed_card(std::string_view line) {
  unsigned bad = 0;  // no early exit: the loop vectorises
  for (char ch : line) bad |= static_cast<unsigned>(static_cast<unsigned char>(ch) - 32u >= 95u);
  if (bad) return false;
  if (line.size() > 80 && !trim(line.substr(80)).empty()) return false;
  return true;
}

bool is_comment_line(std::string_view line) {
  if (line.empty()) return false;
  if (line[0] == '$') return true;
  if (line[0] != '*') return false;
  if (line.size() == 1) return true;
  char c = line[1];
  return c == ' ' || c == '-' || c == '*' || c == '=' || c == '\r';
}

bool is_keyword_line(std::string_view line) {
  return line.size() >= 2 && line[0] == '*' &&
         ((line[1] >= 'A' && line[1] <= 'Z') || (line[1] >= 'a' && line[1] <= 'z'));
}

bool DeckFile::load(const std::string& path, Diagnostics& diag) {
  name_ = path;
  text_ = Text();
  size_ = 0;
  lines_.clear();
  pos_ = 0;
  cards_total_ = cards_read_ = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    Location loc;
    loc.file = path;
    diag.add(3003, loc, std::string("cannot open the input deck: ") + std::strerror(errno));
    return false;
  }
  in.seekg(0, std::ios::end);
  std::streamoff size = in.tellg();
  in.seekg(0, std::ios::beg);
  if (size < 0 || static_cast<std::size_t>(size) > kMaxBytes) {
    Location loc;
    loc.file = path;
    diag.add(3006, loc, "larger than 1 GiB");
    return false;
  }
  // one read into one block, not initialised first
  Text text(static_cast<std::size_t>(size) + 1);
  in.read(text.p, size);
  if (!in) {
    Location loc;
    loc.file = path;
    diag.add(3003, loc, "read error");
    return false;
  }
  text_ = std::move(text);
  size_ = static_cast<std::size_t>(size);
  split_lines();
  return true;
}

void DeckFile::load_from_string(const std::string& name, std::string_view content) {
  name_ = name;
  text_ = Text(content.size() + 1);
  if (!content.empty()) std::memcpy(text_.p, content.data(), content.size());
  size_ = content.size();
  split_lines();
}

void DeckFile::split_lines() {
  lines_.clear();
  pos_ = 0;
  cards_total_ = cards_read_ = 0;
  const char* const text = text_.p;
  const std::string_view content(text, size_);
  // count the lines first: one allocation of the right size
  std::size_t count = 0;
  for (const char* p = text; (p = static_cast<const char*>(std::memchr(p, '\n', size_ - std::size_t(p - text)))); ++p)
    ++count;
  if (size_ > 0 && text[size_ - 1] != '\n') ++count;
  lines_.reserve(count);
  int number = 0;
  std::size_t start = 0;
  while (start < content.size()) {
    const char* nlp = static_cast<const char*>(std::memchr(text + start, '\n', size_ - start));
    std::size_t end = nlp ? std::size_t(nlp - text) : content.size();
    std::string_view l = content.substr(start, end - start);
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    lines_.push_back({++number, l});
    if (!is_comment_line(l)) ++cards_total_;
    if (!nlp) break;
    start = end + 1;
  }
}

bool DeckFile::is_comment(std::string_view line) const {
  return is_comment_line(line) || (star_comments_ && !line.empty() && line[0] == '*');
}

void DeckFile::set_star_comments(bool on) {
  star_comments_ = on;
  long total = 0, read = 0;
  for (std::size_t k = 0; k < lines_.size(); ++k)
    if (!is_comment(lines_[k].text)) {
      ++total;
      if (k < pos_) ++read;
    }
  cards_total_ = total;
  cards_read_ = read;
}

const DeckLine* DeckFile::peek_card() {
  while (pos_ < lines_.size() && is_comment(lines_[pos_].text)) ++pos_;
  return pos_ < lines_.size() ? &lines_[pos_] : nullptr;
}

const DeckLine* DeckFile::next_card() {
  const DeckLine* l = peek_card();
  if (l) {
    ++pos_;
    ++cards_read_;
  }
  return l;
}

bool DeckFile::at_end() { return peek_card() == nullptr; }

Card::Card(const std::string& file, const DeckLine& line, std::string card_name,
           Diagnostics& diag)
    : file_(file), line_(&line), card_name_(std::move(card_name)), diag_(diag) {
  const std::string_view t = line.text;
  for (std::size_t k = 0; k < t.size(); ++k) {
    unsigned char c = static_cast<unsigned char>(t[k]);
    if (c == '\t') {
      error(1011, int(k) + 1, int(k) + 1, nullptr, {}, false);
      break;
    }
    if (c < 32 || c >= 127) {
      error(1012, int(k) + 1, int(k) + 1, nullptr, "byte " + std::to_string(int(c)), false);
      break;
    }
  }
  if (t.size() > 80 && !trim(t.substr(80)).empty()) {
    Location loc = where(81, int(t.size()));
    loc.found = std::string(t.substr(80));
    loc.show_found = true;
    diag_.add(1010, loc);
    had_error_ = true;
  }
}

std::string Card::a(int c1, int c2) const {
  if (c2 < c1) return {};
  std::string out(columns(c1, c2));
  out.resize(static_cast<std::size_t>(c2 - c1 + 1), ' ');
  return out;
}

bool Card::blank(int c1, int c2) const { return trim(columns(c1, c2)).empty(); }

Location Card::where(int c1, int c2, const char* field) const {
  Location loc;
  loc.file = file_;
  loc.line = line_->number;
  loc.card = card_name_;
  if (field) loc.field = field;
  loc.col_first = c1;
  loc.col_last = c2;
  return loc;
}

void Card::error(int id, int c1, int c2, const char* field, std::string detail,
                 bool show_found) {
  if (id != 1001 && id != 1002 && c1 > 0) {
    for (const auto& b : bad_fields_) {
      if (b.first == c1 && b.second == c2) {
        if (message_def(id).severity == Severity::error) had_error_ = true;
        return;
      }
    }
  }
  Location loc = where(c1, c2, field);
  if (show_found && c1 > 0) {
    loc.found = std::string(trim(columns(c1, c2)));
    loc.show_found = true;
  }
  diag_.add(id, loc, std::move(detail));
  if (message_def(id).severity == Severity::error) had_error_ = true;
}

template <class T, class Parse>
T Card::number(int c1, int c2, const char* field, T def, Parse parse, int id) {
  T v = def;
  FieldStatus st = parse(columns(c1, c2), v);
  if (st == FieldStatus::blank) return def;
  if (st == FieldStatus::bad) {
    error(id, c1, c2, field);
    bad_fields_.emplace_back(c1, c2);
    return def;
  }
  return v;
}

long long Card::i(int c1, int c2, const char* field, long long def) {
  return number<long long>(c1, c2, field, def, [](std::string_view t, long long& v) { return parse_fortran_int(t, v); }, 1001);
}

double Card::e(int c1, int c2, const char* field, double def) {
  return number<double>(c1, c2, field, def, [](std::string_view t, double& v) { return parse_fortran_real(t, v); }, 1002);
}

}  // namespace impact3d
