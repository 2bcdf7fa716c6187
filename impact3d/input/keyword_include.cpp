// The keyword deck cut into blocks, the first of the reader's three passes (the include
// family; keyword_reader.cpp): the main deck and the files its *INCLUDE, *INCLUDE_TRANSFORM
// cards name (looked up next to the including file, the main deck, in the working directory,
// then in the *INCLUDE_PATH directories; 20 levels at most, a file never includes itself) are
// read line by line into keyword blocks ('$' comments dropped), each with its format (long '+',
// standard '-', I10 '%', *KEYWORD LONG= and I10=) and the *CASE sections it stands in
// (keyword_cases.cpp).  *INCLUDE_TRANSFORM's cards are read here; its offsets are applied once
// the deck is parsed (keyword_include_transform.cpp).

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/input/keyword_resolve.h"

namespace impact3d::kw {

namespace {

class DeckScanner {
 public:
  DeckScanner(const DeckFile& main, KeywordContext& ctx, Model& m, ScannedDeck& out)
      : main_(main), m_(m), diag_(ctx.diag), ctx_(ctx), includes_(out.includes), blocks_(out.blocks),
        transforms_(out.transforms), cases_(out.cases) {}

  void run() {
    std::vector<std::string> stack;
    check_first_line();
    scan(main_, 0, stack);
  }

 private:
  const DeckFile& main_;
  Model& m_;
  Diagnostics& diag_;
  KeywordContext& ctx_;
  std::deque<std::unique_ptr<DeckFile>>& includes_;
  std::vector<Block>& blocks_;
  IncludeTransforms& transforms_;
  CaseSections& cases_;  // *CASE_BEGIN_n ... *CASE_END_n sections open while scanning
  bool global_long_ = false, global_i10_ = false;

  void check_first_line() {
    for (const auto& l : main_.lines()) {
      if (is_blank(l.text) || l.text[0] == '$') continue;
      if (upper(l.text).rfind("*KEYWORD", 0) != 0) {
        Location loc;
        loc.file = main_.name();
        loc.line = l.number;
        diag_.add(2009, loc, "LS-DYNA requires *KEYWORD as the first line; read anyway");
      }
      return;
    }
  }

  void scan(const DeckFile& f, int depth, std::vector<std::string>& stack) {
    long cur = -1;
    bool reported_orphan = false;
    for (const DeckLine& l : f.lines()) {
      const std::string_view t = l.text;
      if (!t.empty() && t[0] == '$') continue;
      if (is_keyword_line(t)) {
        close_block(cur, depth, stack);
        cur = -1;
        Block b;
        std::string first(t.substr(1, t.find_first_of(" \t,", 1) == std::string::npos ? std::string::npos : t.find_first_of(" \t,", 1) - 1));
        b.keyword = "*" + rtrim(first);
        std::string name = upper(rtrim(first));
        bool lng = global_long_, i10 = global_i10_;
        while (!name.empty() && (name.back() == '+' || name.back() == '-' || name.back() == '%')) {
          if (name.back() == '+') lng = true;
          if (name.back() == '-') lng = false;
          if (name.back() == '%') i10 = true;
          name.pop_back();
        }
        // the suffix may also stand apart: "*NODE +"
        for (std::size_t p = t.find_first_of(" \t"); p != std::string::npos && p < t.size();) {
          std::size_t s = t.find_first_not_of(" \t", p);
          if (s == std::string::npos) break;
          std::size_t e = t.find_first_of(" \t", s);
          std::string_view tok = t.substr(s, e == std::string::npos ? std::string::npos : e - s);
          if (tok == "+") lng = true;
          if (tok == "-") lng = false;
          if (tok == "%") i10 = true;
          p = e;
        }
        b.name = name;
        b.kw = {&f, &l};
        if (name == "END") return;  // the rest of this file is not read
        if (cases_.marker(name, f, l, diag_)) continue;  // *CASE_BEGIN_n / *CASE_END_n: no block
        b.cases = cases_.open;
        if (const int cid = keyword_case_option(t); cid > 0 && std::find(b.cases.begin(), b.cases.end(), cid) == b.cases.end())
          b.cases.push_back(cid);
        if (name == "KEYWORD") keyword_options(t, f, l);
        b.long_fmt = name == "KEYWORD" ? global_long_ : lng;
        b.i10 = name == "KEYWORD" ? global_i10_ : i10;
        blocks_.push_back(std::move(b));
        cur = long(blocks_.size()) - 1;
        continue;
      }
      if (!t.empty() && t[0] == '*') continue;  // '*' not followed by a letter: comment
      if (cur < 0) {
        if (!is_blank(t) && !reported_orphan) {
          Location loc;
          loc.file = f.name();
          loc.line = l.number;
          loc.found = t;
          loc.show_found = true;
          diag_.add(1305, loc);
          reported_orphan = true;
        }
        continue;
      }
      blocks_[std::size_t(cur)].data.push_back({&f, &l});
    }
    close_block(cur, depth, stack);
  }

  // The options on the *KEYWORD line (the table's "options" card, keyword_cards.cpp): words in
  // any order; a message names the option (its field in the table) and the word's columns.
  void keyword_options(std::string_view t, const DeckFile& f, const DeckLine& l) {
    const KeywordCardLayout& options = find_keyword_spec("KEYWORD")->card("options");
    const std::string u = upper(t);
    for (std::size_t b = u.find_first_of(" \t"); (b = u.find_first_not_of(" \t", b)) != std::string::npos;) {
      const std::size_t e = std::min(u.find_first_of(" \t", b), u.size());
      const std::string tok = u.substr(b, e - b);
      Location loc;
      loc.file = f.name();
      loc.line = l.number;
      loc.card = "*KEYWORD";
      for (const KeywordField& o : options.fields)
        if (tok.substr(0, tok.find('=')) == o.name) loc.field = o.name;
      loc.col_first = int(b) + 1;
      loc.col_last = int(e);
      loc.found = tok;
      loc.show_found = true;
      b = e;
      if (tok == "LONG=Y") global_long_ = true;
      else if (tok == "LONG=S" || tok == "LONG=N") global_long_ = false;
      else if (tok == "I10=Y") global_i10_ = true;
      else if (tok == "I10=N") global_i10_ = false;
      else if (!tok.empty() && std::all_of(tok.begin(), tok.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)) || c == 'M'; })) {
        // memory size: ignored
      } else if (long long n = 0; tok.rfind("NCPU=", 0) == 0 && parse_fortran_int(tok.substr(5), n) == FieldStatus::ok &&
                                    n != 0 && std::llabs(n) <= 1024) {
        // the thread count when the command line has no ncpu= (negative: LS-DYNA's consistent
        // mode; IMPACT-3D's results never depend on the thread count)
        m_.deck_threads = int(std::llabs(n));
      } else if (tok.rfind("MEMORY=", 0) == 0 || tok.rfind("MEMORY2=", 0) == 0) {  // LS-DYNA's memory options: read and listed as ignored
        diag_.add(2008, loc, "memory is allocated as the model needs it");
      } else {
        diag_.add(1312, loc, "supported: LONG=Y, LONG=S, I10=Y, I10=N, MEMORY=, MEMORY2=, NCPU=n (1 <= |n| <= 1024) and a memory size");
      }
    }
  }

  // *INCLUDE_PATH: directories searched for include files (one per line), after the including
  // file's; _RELATIVE: relative to the main deck's directory.
  std::vector<std::string> include_paths_;
  void add_include_paths(const Block& b) {
    namespace fs = std::filesystem;
    const bool relative = b.name == "INCLUDE_PATH_RELATIVE";
    for (const KLine& kl : b.data) {
      std::string t(trim_sv(kl.line->text));
      if (t.empty()) continue;
      fs::path p(t);
      if (relative || p.is_relative()) p = fs::path(main_.name()).parent_path() / p;
      include_paths_.push_back(p.string());
      if (!relative && fs::path(t).is_relative()) include_paths_.push_back(t);  // the working directory
    }
  }

  // *INCLUDE_TRANSFORM: the file is read as an *INCLUDE, and its records are renumbered and
  // moved once the deck is parsed (apply_include_transforms, keyword_include_transform.cpp).
  const IncludeTransform* pending_transform_ = nullptr;  // for the include being opened

  void include_transform(const Block& b, int depth, std::vector<std::string>& stack) {
    const auto& data = b.data;
    std::size_t k = 0;
    while (k < data.size() && is_blank(data[k].line->text)) ++k;
    if (k >= data.size()) { ctx_.missing_card(b, "card 1 (FILENAME)"); return; }
    std::string name;
    const KLine first = data[k];
    for (; k < data.size(); ++k) {
      std::string t = rtrim(data[k].line->text);
      if (t.size() >= 2 && t.compare(t.size() - 2, 2, " +") == 0) { name += t.substr(0, t.size() - 2); continue; }
      name += t;
      ++k;
      break;
    }
    IncludeTransform x;
    // cards 2-5 by their table (keyword_cards.cpp), read before *PARAMETER: no references replaced
    const KeywordSpec& spec = *find_keyword_spec("INCLUDE_TRANSFORM");
    const auto card = [&](const char* label) { return KeywordValues(b, k++, spec.card(label), diag_, nullptr); };
    if (k < data.size()) {
      KeywordValues v = card("card 2");
      x.idnoff = v.integer("IDNOFF"), x.ideoff = v.integer("IDEOFF"), x.idpoff = v.integer("IDPOFF"), x.idmoff = v.integer("IDMOFF");
      x.idsoff = v.integer("IDSOFF"), x.idfoff = v.integer("IDFOFF"), x.iddoff = v.integer("IDDOFF");
    }
    if (k < data.size()) x.idroff = card("card 3").integer("IDROFF");
    if (k < data.size()) {
      KeywordValues v = card("card 4");
      for (const char* f : {"FCTMAS", "FCTTIM", "FCTLEN", "FCTTEM"}) v[f];  // read in this order, then checked in this:
      for (const char* f : {"FCTMAS", "FCTTIM", "FCTTEM", "FCTLEN"}) v.check(f);
      x.fctlen = v["FCTLEN"];
      v["INCOUT1"];
    }
    if (k < data.size()) {
      KeywordValues v = card("card 5");
      x.tranid = int(v.integer("TRANID"));
      x.tranid_ref = v.ref("TRANID");
    }
    transforms_.list.push_back(x);
    pending_transform_ = &transforms_.list.back();
    include(std::string(trim_sv(name)), first, depth, stack);
    pending_transform_ = nullptr;
  }

  void close_block(long cur, int depth, std::vector<std::string>& stack) {
    if (cur >= 0 && (blocks_[std::size_t(cur)].name == "INCLUDE_PATH" || blocks_[std::size_t(cur)].name == "INCLUDE_PATH_RELATIVE"))
      add_include_paths(blocks_[std::size_t(cur)]);
    if (cur >= 0 && blocks_[std::size_t(cur)].name == "INCLUDE_TRANSFORM") {
      const Block b = blocks_[std::size_t(cur)];  // copy: including appends to blocks_
      include_transform(b, depth, stack);
      return;
    }
    if (cur < 0 || blocks_[std::size_t(cur)].name != "INCLUDE") return;
    // copy: including appends to blocks_
    const auto data = blocks_[std::size_t(cur)].data;
    std::string name;
    KLine first{};
    for (const KLine& kl : data) {
      std::string t = rtrim(kl.line->text);
      if (t.empty() && name.empty()) continue;
      if (name.empty()) first = kl;
      // a file name longer than one line continues on the next after " +"
      if (t.size() >= 2 && t.compare(t.size() - 2, 2, " +") == 0) {
        name += t.substr(0, t.size() - 2);
        continue;
      }
      name += t;
      include(std::string(trim_sv(name)), first, depth, stack);
      name.clear();
    }
  }

  void include(const std::string& name, const KLine& where, int depth, std::vector<std::string>& stack) {
    namespace fs = std::filesystem;
    Location loc;
    loc.file = where.file->name();
    loc.line = where.line->number;
    loc.card = "*INCLUDE";
    loc.field = "FILENAME";
    loc.found = name;
    loc.show_found = true;
    std::vector<fs::path> candidates;
    fs::path p(name);
    if (p.is_absolute()) {
      candidates.push_back(p);
    } else {
      candidates.push_back(fs::path(where.file->name()).parent_path() / p);
      candidates.push_back(fs::path(main_.name()).parent_path() / p);
      candidates.push_back(p);
      for (const std::string& d : include_paths_) candidates.push_back(fs::path(d) / p);
    }
    fs::path found;
    std::error_code ec;
    for (const auto& c : candidates)
      if (fs::is_regular_file(c, ec)) { found = c; break; }
    if (found.empty()) {
      diag_.add(1306, loc, "not found next to " + where.file->name() + ", the main deck, in the working directory or in an *INCLUDE_PATH directory");
      return;
    }
    std::string canon = fs::weakly_canonical(found, ec).string();
    if (depth >= 20 || std::find(stack.begin(), stack.end(), canon) != stack.end() ||
        canon == fs::weakly_canonical(main_.name(), ec).string()) {
      diag_.add(1307, loc, depth >= 20 ? "more than 20 levels" : "the file includes itself");
      return;
    }
    auto df = std::make_unique<DeckFile>();
    Diagnostics local;
    if (!df->load(found.string(), local)) {
      diag_.add(1306, loc, local.all().empty() ? std::string() : local.all().front().detail);
      return;
    }
    // the records of a transformed include (and of the files it includes) are renumbered and moved
    if (pending_transform_) transforms_.of_file[df.get()] = pending_transform_;
    else if (auto t = transforms_.of_file.find(where.file); t != transforms_.of_file.end()) transforms_.of_file[df.get()] = t->second;
    pending_transform_ = nullptr;
    includes_.push_back(std::move(df));
    stack.push_back(canon);
    scan(*includes_.back(), depth + 1, stack);
    stack.pop_back();
  }


};

}  // namespace

void scan_deck(const DeckFile& main, KeywordContext& ctx, Model& m, ScannedDeck& out) { DeckScanner(main, ctx, m, out).run(); }

}  // namespace impact3d::kw
