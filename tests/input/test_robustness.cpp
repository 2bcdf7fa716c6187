// Robustness of the input phase: pseudo-random mutations of valid decks (byte flips,
// truncations, duplicated and deleted lines, random digits) must never crash, hang or throw;
// every run either succeeds or reports at least one error.

#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;

namespace {

struct Rng {  // deterministic: the same mutations on every machine
  std::uint64_t s;
  explicit Rng(std::uint64_t seed) : s(seed) {}
  std::uint64_t next() {
    s ^= s << 13;
    s ^= s >> 7;
    s ^= s << 17;
    return s;
  }
  std::size_t below(std::size_t n) { return n ? std::size_t(next() % n) : 0; }
};

std::vector<std::string> split_lines(const std::string& t) {
  std::vector<std::string> v;
  std::size_t p = 0;
  while (p < t.size()) {
    std::size_t q = t.find('\n', p);
    if (q == std::string::npos) q = t.size();
    v.push_back(t.substr(p, q - p));
    p = q + 1;
  }
  return v;
}

std::string join_lines(const std::vector<std::string>& v) {
  std::string t;
  for (const auto& l : v) t += l + "\n";
  return t;
}

std::string mutate(const std::string& base, Rng& r) {
  std::string t = base;
  int count = 1 + int(r.below(3));
  for (int k = 0; k < count && !t.empty(); ++k) {
    switch (r.below(6)) {
      case 0: {  // byte flip: any byte value
        t[r.below(t.size())] = char(r.below(256));
        break;
      }
      case 1: {  // truncation
        t.resize(r.below(t.size()));
        break;
      }
      case 2: {  // duplicated line
        auto v = split_lines(t);
        if (v.empty()) break;
        std::size_t i = r.below(v.size());
        v.insert(v.begin() + long(i), v[i]);
        t = join_lines(v);
        break;
      }
      case 3: {  // deleted line
        auto v = split_lines(t);
        if (v.empty()) break;
        v.erase(v.begin() + long(r.below(v.size())));
        t = join_lines(v);
        break;
      }
      case 4: {  // random digit replacing a digit or a blank (counts, ids, exponents)
        for (int tries = 0; tries < 50; ++tries) {
          std::size_t i = r.below(t.size());
          if ((t[i] >= '0' && t[i] <= '9') || t[i] == ' ') {
            t[i] = char('0' + r.below(10));
            break;
          }
        }
        break;
      }
      default: {  // a sign or letter in place of a character of a number
        const char repl[] = "-+.eEdD9";
        t[r.below(t.size())] = repl[r.below(sizeof repl - 1)];
        break;
      }
    }
  }
  return t;
}

// Feeds n mutations of the bases (alternating) to read; every deck must either read clean or
// be refused with at least one error, with no exception and every message in the catalog.
struct MutationCounts {
  int accepted = 0, refused = 0;
};
template <class Read>
MutationCounts run_mutations(const std::vector<std::string>& bases, std::uint64_t seed, int n,
                             Read read) {
  Rng rng(seed);
  MutationCounts c;
  for (int k = 0; k < n; ++k) {
    const std::string text = mutate(bases[std::size_t(k) % bases.size()], rng);
    Diagnostics diag;
    bool ok = false;
    try {
      ok = read(text, diag);
    } catch (const std::exception& e) {
      ADD_FAILURE() << "mutation " << k << " threw " << e.what() << "\n" << text;
      continue;
    } catch (...) {
      ADD_FAILURE() << "mutation " << k << " threw\n" << text;
      continue;
    }
    if (ok) {
      ++c.accepted;
      EXPECT_EQ(diag.error_count(), 0) << "mutation " << k;
    } else {
      ++c.refused;
      EXPECT_GE(diag.error_count(), 1) << "mutation " << k << " refused without an error\n" << text;
    }
    for (const auto& d : diag.all()) {
      EXPECT_GE(d.where.line, 0);
      EXPECT_LE(d.where.line, int(text.size()) + 1);
      render(d);  // never aborts: every message number is in the catalog
    }
  }
  return c;
}

}  // namespace

TEST(Robustness, TwoThousandMutatedDecks) {
  std::string tiny = tiny_deck();
  ASSERT_FALSE(tiny.empty());
  auto taylor_lines = split_lines(read_text(source_path("decks/taylor_bar.dyn")));
  ASSERT_GE(taylor_lines.size(), 200u);
  taylor_lines.resize(200);
  const std::string taylor = join_lines(taylor_lines);

  auto start = std::chrono::steady_clock::now();
  const MutationCounts c =
      run_mutations({tiny, taylor}, 0x1A2B3C4D5E6F7788ULL, 2000, [](const std::string& text, Diagnostics& diag) {
        Model m;
        DeckFile deck;
        deck.load_from_string("mutant.dyn", text);
        bool ok = read_dyna3d_deck(deck, m, diag);
        if (m.num_nodes() == m.control.numnp && m.num_hexes() == m.control.numelh &&
            !diag.has(1004) && !diag.has(1013))
          ok = check_model(m, diag) && ok;
        return ok;
      });
  double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(c.accepted + c.refused, 2000);
  EXPECT_GT(c.refused, 1000);  // the truncated Taylor bar alone is always refused
#if defined(__SANITIZE_ADDRESS__)
  const double limit = 100.0;  // tools/test.sh --sanitize: ASan + UBSan run it about 5x slower
#else
  const double limit = 10.0;
#endif
  EXPECT_LT(seconds, limit);   // a hang guard, not a speed claim
  std::printf("robustness: %d accepted, %d refused, %.2f s\n", c.accepted, c.refused, seconds);
}

// The same for the LS-DYNA keyword reader (picked by content through read_deck): a small
// sparse-id deck and the first 300 lines of the keyword Taylor bar.
TEST(Robustness, TwoThousandMutatedKeywordDecks) {
  const std::string small = read_text(source_path("tests/output/sparse_ids.k"));
  ASSERT_FALSE(small.empty());
  auto taylor_lines = split_lines(read_text(source_path("decks/keyword/taylor_bar.k")));
  ASSERT_GE(taylor_lines.size(), 300u);
  taylor_lines.resize(300);
  const std::string taylor = join_lines(taylor_lines);

  const MutationCounts c =
      run_mutations({small, taylor}, 0x5EED0F1234ABCDEFULL, 2000, [](const std::string& text, Diagnostics& diag) {
        Model m;
        DeckFile deck;
        deck.load_from_string("mutant.k", text);
        bool ok = read_deck(deck, m, diag, InputOptions{});
        if (ok) ok = check_model(m, diag);
        return ok;
      });
  EXPECT_EQ(c.accepted + c.refused, 2000);
  EXPECT_GT(c.refused, 1000);  // the truncated Taylor bar has no *END and misses most nodes' elements
  std::printf("keyword robustness: %d accepted, %d refused\n", c.accepted, c.refused);
}
