// The keyword reader's generic card reader (keyword_blocks.h): one card of a block read by its
// table (keyword_cards.h) into named values, with the table's checks.

#include "impact3d/input/keyword_blocks.h"

#include <stdexcept>

namespace impact3d::kw {

KeywordValues::KeywordValues(const Block& b, std::size_t k, const KeywordCardLayout& layout, Diagnostics& diag,
                             const ParamTable* params, const std::string* label)
    : layout_(layout),
      card_(b.data[k], b.keyword + (label ? " " + *label : layout.card[0] ? std::string(" ") + layout.card : std::string()),
            layout.columns(b.long_fmt, b.i10), diag) {
  card_.set_params(params);
  const std::size_t n = layout.fields.size();
  values_.assign(n, 0.0);
  read_.assign(n, 0);
  passed_.assign(n, 1);
}

double KeywordValues::value(std::size_t k) {
  if (read_[k]) return values_[k];
  read_[k] = 1;
  const KeywordField& f = layout_.fields[k];
  if (f.kind == FieldKind::text) return values_[k] = 0;  // read as text (KeywordValues::text)
  double v = f.kind == FieldKind::real ? card_.r(f.index, f.name, f.blank)
                                       : double(card_.i(f.index, f.name, static_cast<long long>(f.blank)));
  if (f.zero_is_blank && v == 0) v = f.blank;
  values_[k] = v;
  for (std::size_t j = 0; j < layout_.fields.size(); ++j)
    if (read_[j] && layout_.check_point(layout_.fields[j]) == f.index) check_field(j);
  const int point = layout_.check_point(f);  // read after its check point: checked now
  if (point != f.index)
    for (std::size_t j = 0; j < layout_.fields.size(); ++j)
      if (layout_.fields[j].index == point && read_[j]) check_field(k);
  return v;
}

KeywordValues& KeywordValues::rest() {
  for (std::size_t k = 0; k < layout_.fields.size(); ++k) value(k);
  return *this;
}

bool KeywordValues::check(std::string_view name) {
  const std::size_t k = index(name);
  value(k);
  check_field(k);
  return passed_[k] != 0;
}

void KeywordValues::check_field(std::size_t k) {
  const KeywordField& f = layout_.fields[k];
  for (const KeywordCheck& c : f.checks) {
    if (!c.fires(values_[k])) continue;
    if (c.id == 0) return;  // accepted
    passed_[k] = 0;
    std::string detail = c.detail ? c.detail : "";
    if (const std::size_t p = detail.find("%v"); p != std::string::npos)
      detail.replace(p, 2, std::to_string(static_cast<long long>(values_[k])));
    card_.error(c.id, f.index, f.name, std::move(detail));
    return;
  }
}

std::size_t KeywordValues::index(std::string_view name) const {
  for (std::size_t k = 0; k < layout_.fields.size(); ++k)
    if (name == layout_.fields[k].name) return k;
  throw std::logic_error("keyword card table: " + std::string(layout_.card) + " has no field " + std::string(name));
}

void KeywordValues::error(int id, std::string_view name, std::string detail) {
  const KeywordField& f = layout_.fields[index(name)];
  card_.error(id, f.index, f.name, std::move(detail));
}

void KeywordContext::once(const Block& b) {
  auto it = seen_once.find(b.name);
  if (it != seen_once.end()) {
    Location loc;
    loc.file = b.kw.file->name();
    loc.line = b.kw.line->number;
    loc.card = b.keyword;
    diag.add(2010, loc, "also given at " + at(it->second));
  }
  Ref r;
  r.file = b.kw.file;
  r.line = b.kw.line;
  seen_once[b.name] = r;
}

void KeywordContext::missing_card(const Block& b, const char* what) {
  Location loc;
  loc.file = b.kw.file->name();
  loc.line = b.kw.line->number;
  loc.card = b.keyword;
  diag.add(1316, loc, std::string("missing: ") + what);
}

}  // namespace impact3d::kw
