// Tests of the deck generator (decks/generator/deckgen.cpp) and of the committed decks.
//
// - The built generator reproduces every committed decks/*.dyn byte for byte.
// - Each deck follows the fixed-format layout (80 columns, no tabs, "88 large" title) and its
//   card counts match control card 2; the seed decks have the paper's node/element counts.
// - Every hexahedron has positive volume: each of the 6 tetrahedra of the decomposition about
//   the n1-n7 diagonal is positive (computed here, independent of the solver).
// - Symmetry-plane nodes carry the right BC codes; sliding-interface segments are faces of
//   their body with outward normals; all nodes start on the positive side of the stonewalls.
//
// The parser here is deliberately independent of the solver's reader; one test also reads every
// committed deck with the solver's reader and checker (no errors allowed).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/deck_writer.h"

namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kDecks = {"taylor_bar",       "oblique_rod",
                                         "crossed_cylinders", "one_hex",
                                         "bar_wall_elastic",  "two_bars",
                                         "column_uniaxial_strain", "thick_cylinder"};

std::string generator() { return std::string(IMPACT3D_BINARY_DIR) + "/impact3d_deckgen"; }
fs::path committed(const std::string& name) {
  return fs::path(IMPACT3D_SOURCE_DIR) / "decks" / (name + ".dyn");
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// A fresh temporary directory, removed at the end of the test.
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& tag) {
    path = fs::temp_directory_path() /
           ("impact3d_deckgen_" + tag + "_" + std::to_string(static_cast<long>(::getpid())));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
};

int run(const std::string& cmd) { return std::system(cmd.c_str()); }

struct Vec {
  double x, y, z;
};
Vec sub(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec cross(const Vec& a, const Vec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

bool is_comment(const std::string& l) {
  if (l.empty()) return false;
  if (l[0] == '$') return true;
  return l[0] == '*' && (l.size() == 1 || l[1] == ' ' || l[1] == '-' || l[1] == '*');
}

std::string field(const std::string& card, std::size_t col, std::size_t width) {
  if (card.size() < col) return std::string();
  return card.substr(col - 1, width);
}
bool blank(const std::string& s) { return s.find_first_not_of(' ') == std::string::npos; }
long long ival(const std::string& card, std::size_t col, std::size_t width) {
  const std::string f = field(card, col, width);
  if (blank(f)) return 0;
  return std::stoll(f);
}
double rval(const std::string& card, std::size_t col, std::size_t width) {
  const std::string f = field(card, col, width);
  if (blank(f)) return 0.0;
  return std::stod(f);
}

struct Wall {
  Vec tail, head;
};
struct Deck {
  std::string title;
  std::vector<std::string> raw;  // every line
  int nmat = 0, numnp = 0, numelh = 0;
  int node_blocks = 0, solid_blocks = 0, nrw = 0, nvel = 0, nsi = 0;
  double t_end = 0.0;
  std::vector<Vec> X;
  std::vector<int> bc;
  std::vector<std::array<int, 8>> hex;
  std::vector<int> mat;
  std::vector<std::array<int, 2>> node_th, solid_th;
  std::vector<Wall> walls;
  std::vector<std::array<double, 3>> vel;
  std::vector<std::vector<std::array<int, 4>>> slave, master;
  std::vector<std::array<int, 4>> pressure;  // pressure-card nodes
  std::size_t node_cards = 0, element_cards = 0, extra_cards = 0;
  const Vec& x(int id) const { return X.at(static_cast<std::size_t>(id - 1)); }
};

// Parses a deck with the layout of docs/deck-format.md "Deck format" (large format, the sections our
// generator writes).  Failures are reported through gtest.
Deck parse(const std::string& text) {
  Deck d;
  std::vector<std::string> cards;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) {
    d.raw.push_back(l);
    if (!is_comment(l)) cards.push_back(l);
  }
  std::size_t k = 0;
  auto next = [&]() -> std::string {
    if (k >= cards.size()) {
      ADD_FAILURE() << "deck ends early";
      return std::string();
    }
    return cards[k++];
  };
  d.title = next();
  const std::string c2 = next(), c3 = next(), c4 = next(), c5 = next(), c6 = next();
  next();
  next();
  next();
  d.nmat = static_cast<int>(ival(c2, 1, 5));
  d.numnp = static_cast<int>(ival(c2, 6, 10));
  d.numelh = static_cast<int>(ival(c2, 16, 10));
  d.node_blocks = static_cast<int>(ival(c3, 1, 5));
  d.solid_blocks = static_cast<int>(ival(c3, 6, 5));
  EXPECT_EQ(field(c4, 31, 5), "e20.0");
  const int numlc = static_cast<int>(ival(c5, 1, 5));
  const int npressure = static_cast<int>(ival(c5, 11, 5));
  d.nrw = static_cast<int>(ival(c5, 21, 5));
  d.nvel = static_cast<int>(ival(c5, 31, 5));
  d.nsi = static_cast<int>(ival(c5, 36, 5));
  d.t_end = rval(c6, 1, 10);
  for (int m = 0; m < d.nmat; ++m) {
    const std::string c = next();
    EXPECT_EQ(ival(c, 1, 5), m + 1);
    for (int i = 0; i < 7; ++i) next();
  }
  for (int n = 0; n < d.numnp && k < cards.size(); ++n) {
    const std::string c = next();
    ++d.node_cards;
    EXPECT_EQ(ival(c, 1, 8), n + 1) << c;
    d.bc.push_back(static_cast<int>(ival(c, 9, 5)));
    d.X.push_back({rval(c, 14, 20), rval(c, 34, 20), rval(c, 54, 20)});
  }
  for (int e = 0; e < d.numelh && k < cards.size(); ++e) {
    const std::string c = next();
    ++d.element_cards;
    EXPECT_EQ(ival(c, 1, 8), e + 1) << c;
    d.mat.push_back(static_cast<int>(ival(c, 9, 5)));
    std::array<int, 8> h{};
    for (std::size_t i = 0; i < 8; ++i) h[i] = static_cast<int>(ival(c, 14 + 8 * i, 8));
    d.hex.push_back(h);
  }
  // time-history blocks: five (first, last) pairs a card, as DYNA3D reads them
  auto blocks = [&](int n, std::vector<std::array<int, 2>>& out) {
    for (int b = 0; b < n; b += 5) {
      const std::string c = next();
      for (int j = 0; j < 5 && b + j < n; ++j)
        out.push_back({static_cast<int>(ival(c, 1 + 16 * j, 8)), static_cast<int>(ival(c, 9 + 16 * j, 8))});
    }
  };
  blocks(d.node_blocks, d.node_th);
  blocks(d.solid_blocks, d.solid_th);
  for (int lc = 0; lc < numlc; ++lc) {
    const long long npts = ival(next(), 6, 5);
    for (long long p = 0; p < npts; ++p) next();
  }
  for (int p = 0; p < npressure; ++p) {  // one card: curve, nodes, multipliers (38-77)
    const std::string c = next();
    std::array<int, 4> q{};
    for (std::size_t j = 0; j < 4; ++j) q[j] = static_cast<int>(ival(c, 6 + 8 * j, 8));
    EXPECT_GT(rval(c, 38, 10), 0.0) << c;
    d.pressure.push_back(q);
  }
  for (int w = 0; w < d.nrw; ++w) {
    const std::string c = next();
    const long long nsn = ival(c, 1, 5);
    d.walls.push_back({{rval(c, 11, 10), rval(c, 21, 10), rval(c, 31, 10)},
                       {rval(c, 41, 10), rval(c, 51, 10), rval(c, 61, 10)}});
    for (long long i = 0; i < (nsn + 9) / 10; ++i) next();
  }
  for (int v = 0; v < d.nvel; ++v) {
    const std::string c = next();
    const long long first = ival(c, 1, 8);
    long long last = ival(c, 39, 8), inc = ival(c, 47, 5);
    const std::array<double, 3> vv = {rval(c, 9, 10), rval(c, 19, 10), rval(c, 29, 10)};
    if (d.vel.empty()) d.vel.assign(static_cast<std::size_t>(d.numnp), {0.0, 0.0, 0.0});
    if (first == 0) {
      for (auto& u : d.vel) u = vv;
    } else {
      if (last == 0) last = first;
      if (inc == 0) inc = 1;
      for (long long n = first; n <= last; n += inc) d.vel.at(static_cast<std::size_t>(n - 1)) = vv;
    }
  }
  std::vector<std::array<long long, 2>> counts;
  for (int s = 0; s < d.nsi; ++s) {
    const std::string c = next();
    counts.push_back({ival(c, 1, 8), ival(c, 9, 8)});
    EXPECT_EQ(ival(c, 17, 5), 3);
  }
  for (int s = 0; s < d.nsi; ++s) {
    for (int side = 0; side < 2; ++side) {
      std::vector<std::array<int, 4>> segs;
      for (long long i = 0; i < counts[static_cast<std::size_t>(s)][static_cast<std::size_t>(side)]; ++i) {
        const std::string c = next();
        EXPECT_EQ(ival(c, 1, 8), i + 1);
        std::array<int, 4> q{};
        for (std::size_t j = 0; j < 4; ++j) q[j] = static_cast<int>(ival(c, 9 + 8 * j, 8));
        segs.push_back(q);
      }
      (side == 0 ? d.slave : d.master).push_back(segs);
    }
  }
  d.extra_cards = cards.size() - k;
  return d;
}

double tet(const Vec& a, const Vec& b, const Vec& c, const Vec& e) {
  return dot(cross(sub(b, a), sub(c, a)), sub(e, a)) / 6.0;
}

// The 6 tetrahedra about the n1-n7 diagonal (0-based corners).
const int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                         {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};

struct Generated {
  TempDir dir{"all"};
  int rc = -1;
  Generated() { rc = run(generator() + " " + dir.path.string()); }
};

Generated& generated() {
  static Generated g;
  return g;
}

Deck load(const std::string& name) {
  return parse(slurp(generated().dir.path / (name + ".dyn")));
}

// ---------------------------------------------------------------------------------------------

TEST(DeckGen, GeneratorRuns) {
  ASSERT_TRUE(fs::exists(generator())) << generator();
  EXPECT_EQ(generated().rc, 0);
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(generated().dir.path))
    names.insert(e.path().filename().string());
  std::set<std::string> expected;
  for (const auto& n : kDecks) expected.insert(n + ".dyn");
  EXPECT_EQ(names, expected);
}

TEST(DeckGen, MatchesCommittedDecksByteForByte) {
  ASSERT_EQ(generated().rc, 0);
  for (const auto& n : kDecks) {
    ASSERT_TRUE(fs::exists(committed(n))) << committed(n);
    const std::string a = slurp(generated().dir.path / (n + ".dyn")), b = slurp(committed(n));
    EXPECT_TRUE(a == b) << n << ".dyn differs from the generator's output (regenerate with "
                        << "impact3d_deckgen decks/)";
  }
}

TEST(DeckGen, StdoutModeAndDeterminism) {
  ASSERT_EQ(generated().rc, 0);
  TempDir t("stdout");
  for (const std::string n : {"taylor_bar", "crossed_cylinders"}) {
    const fs::path out = t.path / (n + ".out");
    ASSERT_EQ(run(generator() + " --deck " + n + " > " + out.string()), 0);
    EXPECT_TRUE(slurp(out) == slurp(generated().dir.path / (n + ".dyn"))) << n;
  }
  EXPECT_NE(run(generator() + " --deck no_such_deck > " + (t.path / "x").string() + " 2>&1"),
            0);
}

TEST(DeckGen, CardLayout) {
  for (const auto& n : kDecks) {
    const Deck d = load(n);
    ASSERT_GE(d.raw.size(), 1u);
    for (const auto& l : d.raw) {
      EXPECT_LE(l.size(), 80u) << n << ": " << l;
      EXPECT_EQ(l.find('\t'), std::string::npos) << n;
      EXPECT_EQ(l.find('\r'), std::string::npos) << n;
    }
    ASSERT_GE(d.title.size(), 80u) << n;
    EXPECT_EQ(field(d.title, 73, 2), "88") << n;
    EXPECT_EQ(field(d.title, 75, 1), " ") << n;
    EXPECT_EQ(field(d.title, 76, 5), "large") << n;
    EXPECT_NE(d.title.substr(0, 72).find("SI units (m kg s Pa)"), std::string::npos) << n;
    EXPECT_EQ(d.node_cards, static_cast<std::size_t>(d.numnp)) << n;
    EXPECT_EQ(d.element_cards, static_cast<std::size_t>(d.numelh)) << n;
    EXPECT_EQ(d.extra_cards, 0u) << n;
    EXPECT_GT(d.t_end, 0.0) << n;
    for (int m : d.mat) EXPECT_TRUE(m >= 1 && m <= d.nmat) << n;
    for (const auto& h : d.hex)
      for (int id : h) EXPECT_TRUE(id >= 1 && id <= d.numnp) << n;
    for (const auto& b : d.node_th) EXPECT_TRUE(b[0] >= 1 && b[1] >= b[0] && b[1] <= d.numnp);
    for (const auto& b : d.solid_th) EXPECT_TRUE(b[0] >= 1 && b[1] >= b[0] && b[1] <= d.numelh);
    // every node belongs to an element
    std::vector<char> used(static_cast<std::size_t>(d.numnp), 0);
    for (const auto& h : d.hex)
      for (int id : h) used[static_cast<std::size_t>(id - 1)] = 1;
    for (std::size_t i = 0; i < used.size(); ++i) EXPECT_TRUE(used[i]) << n << " node " << i + 1;
  }
}

TEST(DeckGen, SeedDeckCounts) {
  const std::map<std::string, std::array<int, 2>> expected = {
      {"taylor_bar", {1369, 972}}, {"oblique_rod", {4818, 3480}},
      {"crossed_cylinders", {722, 432}}};
  for (const auto& [n, c] : expected) {
    const Deck d = load(n);
    EXPECT_EQ(d.numnp, c[0]) << n;
    EXPECT_EQ(d.numelh, c[1]) << n;
    EXPECT_EQ(d.node_cards, static_cast<std::size_t>(c[0])) << n;
    EXPECT_EQ(d.element_cards, static_cast<std::size_t>(c[1])) << n;
    // the committed file too
    const Deck f = parse(slurp(committed(n)));
    EXPECT_EQ(f.numnp, c[0]) << n;
    EXPECT_EQ(f.numelh, c[1]) << n;
  }
}

void expect_positive_volumes(const Deck& d, const std::string& n) {
  int bad = 0;
  for (std::size_t e = 0; e < d.hex.size(); ++e) {
    const auto& h = d.hex[e];
    double vol = 0.0, vmin = 1e300;
    for (const auto& t : kTets) {
      const double v = tet(d.x(h[static_cast<std::size_t>(t[0])]), d.x(h[static_cast<std::size_t>(t[1])]),
                           d.x(h[static_cast<std::size_t>(t[2])]), d.x(h[static_cast<std::size_t>(t[3])]));
      vol += v;
      vmin = std::min(vmin, v);
    }
    if (!(vmin > 0.0) && ++bad <= 5) ADD_FAILURE() << n << ": element " << e + 1 << " volume " << vol
                                                   << ", smallest tetrahedron " << vmin;
  }
  EXPECT_EQ(bad, 0) << n;
}

TEST(DeckGen, PositiveHexVolumes) {
  for (const auto& n : kDecks) expect_positive_volumes(load(n), n);
}

// Expected symmetry-plane codes: x = 0 -> 1, y = 0 -> 2, both -> 4, otherwise 0.
void expect_symmetry_bc(const Deck& d, bool px, bool py, const std::string& n) {
  for (std::size_t i = 0; i < d.X.size(); ++i) {
    const bool ox = px && std::fabs(d.X[i].x) < 1e-12, oy = py && std::fabs(d.X[i].y) < 1e-12;
    const int want = (ox && oy) ? 4 : ox ? 1 : oy ? 2 : 0;
    EXPECT_EQ(d.bc[i], want) << n << " node " << i + 1;
  }
}

TEST(DeckGen, BoundaryCodes) {
  expect_symmetry_bc(load("taylor_bar"), true, true, "taylor_bar");
  expect_symmetry_bc(load("crossed_cylinders"), true, true, "crossed_cylinders");
  expect_symmetry_bc(load("oblique_rod"), false, true, "oblique_rod");
  for (const std::string n : {"one_hex", "bar_wall_elastic", "two_bars"})
    expect_symmetry_bc(load(n), false, false, n);
  const Deck c = load("column_uniaxial_strain");
  for (int b : c.bc) EXPECT_EQ(b, 4);
  // the quarter models really are quarter models
  for (const std::string n : {"taylor_bar", "crossed_cylinders"}) {
    const Deck d = load(n);
    int on_x = 0, on_y = 0;
    for (const auto& p : d.X) {
      EXPECT_GE(p.x, 0.0) << n;
      EXPECT_GE(p.y, 0.0) << n;
      on_x += p.x == 0.0;
      on_y += p.y == 0.0;
    }
    EXPECT_GT(on_x, 0) << n;
    EXPECT_GT(on_y, 0) << n;
  }
}

TEST(DeckGen, TaylorBarGeometry) {
  const Deck d = load("taylor_bar");
  double zmin = 1e9, zmax = -1e9, rmax = 0.0;
  for (const auto& p : d.X) {
    zmin = std::min(zmin, p.z);
    zmax = std::max(zmax, p.z);
    rmax = std::max(rmax, std::hypot(p.x, p.y));
  }
  EXPECT_DOUBLE_EQ(zmin, 0.0);
  EXPECT_NEAR(zmax, 32.4e-3, 1e-15);
  EXPECT_NEAR(rmax, 3.2e-3, 1e-15);
  ASSERT_EQ(d.node_th.size(), 2u);
  const Vec a = d.x(d.node_th[0][0]), b = d.x(d.node_th[1][0]);
  EXPECT_TRUE(a.x == 0.0 && a.y == 0.0 && a.z == 0.0);
  EXPECT_TRUE(b.x == 0.0 && b.y == 0.0 && std::fabs(b.z - 32.4e-3) < 1e-15);
  ASSERT_EQ(d.solid_th.size(), 1u);
  bool has_axis_node = false;
  for (int id : d.hex.at(static_cast<std::size_t>(d.solid_th[0][0] - 1)))
    has_axis_node |= id == d.node_th[0][0];
  EXPECT_TRUE(has_axis_node);
  for (const auto& v : d.vel) EXPECT_EQ(v[2], -227.0);
  double vol = 0.0;
  for (const auto& h : d.hex)
    for (const auto& t : kTets)
      vol += tet(d.x(h[static_cast<std::size_t>(t[0])]), d.x(h[static_cast<std::size_t>(t[1])]),
                 d.x(h[static_cast<std::size_t>(t[2])]), d.x(h[static_cast<std::size_t>(t[3])]));
  // polygonal section: a little less than the quarter circle
  const double exact = 0.25 * 3.14159265358979 * 3.2e-3 * 3.2e-3 * 32.4e-3;
  EXPECT_LT(vol, exact);
  EXPECT_GT(vol, 0.98 * exact);
}

TEST(DeckGen, StonewallsStartClear) {
  for (const auto& n : kDecks) {
    const Deck d = load(n);
    for (const auto& w : d.walls) {
      const Vec nrm = sub(w.head, w.tail);
      const double len = std::sqrt(dot(nrm, nrm));
      ASSERT_GT(len, 0.0) << n;
      double dmin = 1e300;
      for (const auto& p : d.X) dmin = std::min(dmin, dot(sub(p, w.tail), nrm) / len);
      EXPECT_GE(dmin, 0.0) << n;
      EXPECT_LT(dmin, 2.0e-5) << n;  // the body starts on (or just above) the wall
    }
  }
}

// Segments are faces of a hexahedron of one body, with the normal pointing out of it.
TEST(DeckGen, SlidingInterfaceSegments) {
  for (const std::string n : {"crossed_cylinders", "two_bars"}) {
    const Deck d = load(n);
    ASSERT_EQ(d.nsi, 1) << n;
    std::map<std::set<int>, int> face_owner;  // face node set -> element (0-based)
    const int faces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                             {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (std::size_t e = 0; e < d.hex.size(); ++e)
      for (const auto& f : faces) {
        std::set<int> s;
        for (int c : f) s.insert(d.hex[e][static_cast<std::size_t>(c)]);
        face_owner[s] = static_cast<int>(e);
      }
    std::set<int> mats[2];
    for (int side = 0; side < 2; ++side) {
      const auto& segs = side == 0 ? d.slave[0] : d.master[0];
      EXPECT_FALSE(segs.empty()) << n;
      for (const auto& q : segs) {
        const std::set<int> s(q.begin(), q.end());
        ASSERT_EQ(s.size(), 4u) << n;
        const auto it = face_owner.find(s);
        ASSERT_NE(it, face_owner.end()) << n << ": segment is not an element face";
        const auto& h = d.hex[static_cast<std::size_t>(it->second)];
        mats[side].insert(d.mat[static_cast<std::size_t>(it->second)]);
        Vec hc{0, 0, 0}, fc{0, 0, 0};
        for (int id : h) hc = {hc.x + d.x(id).x / 8, hc.y + d.x(id).y / 8, hc.z + d.x(id).z / 8};
        for (int id : q) fc = {fc.x + d.x(id).x / 4, fc.y + d.x(id).y / 4, fc.z + d.x(id).z / 4};
        const Vec nrm = cross(sub(d.x(q[2]), d.x(q[0])), sub(d.x(q[3]), d.x(q[1])));
        EXPECT_GT(dot(nrm, sub(fc, hc)), 0.0) << n << ": segment normal points inward";
      }
    }
    EXPECT_EQ(mats[0].size(), 1u) << n;
    EXPECT_EQ(mats[1].size(), 1u) << n;
    EXPECT_NE(*mats[0].begin(), *mats[1].begin()) << n;
  }
}

TEST(DeckGen, CrossedCylindersSetup) {
  const Deck d = load("crossed_cylinders");
  ASSERT_EQ(d.nmat, 2);
  // bodies separated by the initial gap, approaching each other
  double top1 = -1e9, bot2 = 1e9;
  for (std::size_t i = 0; i < d.X.size(); ++i) {
    const bool body1 = i < 361;
    if (body1) top1 = std::max(top1, d.X[i].z);
    else bot2 = std::min(bot2, d.X[i].z);
    EXPECT_EQ(d.vel.at(i)[2], body1 ? 50.0 : -50.0);
  }
  EXPECT_NEAR(bot2 - top1, 1.0e-5, 1e-12);
  int body1_elements = 0;
  for (std::size_t e = 0; e < d.hex.size(); ++e) {
    int nmax = 0;
    for (int id : d.hex[e]) nmax = std::max(nmax, id);
    EXPECT_EQ(d.mat[e], nmax <= 361 ? 1 : 2);
    body1_elements += nmax <= 361;
  }
  EXPECT_EQ(body1_elements, 216);
  // element 1 (the seed's point 1) touches body 1's contact point; node blocks = contact nodes
  ASSERT_EQ(d.node_th.size(), 2u);
  const Vec c1 = d.x(d.node_th[0][0]), c2 = d.x(d.node_th[1][0]);
  EXPECT_TRUE(c1.x == 0.0 && c1.y == 0.0 && std::fabs(c1.z - top1) < 1e-15);
  EXPECT_TRUE(c2.x == 0.0 && c2.y == 0.0 && std::fabs(c2.z - bot2) < 1e-15);
  ASSERT_EQ(d.solid_th.size(), 1u);
  EXPECT_EQ(d.solid_th[0][0], 1);
  bool touches = false;
  for (int id : d.hex[0]) touches |= id == d.node_th[0][0];
  EXPECT_TRUE(touches);
  EXPECT_EQ(d.mat[0], 1);
}

TEST(DeckGen, ObliqueRodWall) {
  const Deck d = load("oblique_rod");
  ASSERT_EQ(d.walls.size(), 1u);
  const Vec n = sub(d.walls[0].head, d.walls[0].tail);
  const double tilt = std::acos(n.z / std::sqrt(dot(n, n))) * 180.0 / 3.14159265358979;
  EXPECT_NEAR(tilt, 10.0, 1e-3);
  EXPECT_EQ(n.y, 0.0);  // normal in the symmetry plane y = 0
  double zmin = 1e9, zmax = -1e9;
  for (const auto& p : d.X) {
    zmin = std::min(zmin, p.z);
    zmax = std::max(zmax, p.z);
    EXPECT_GE(p.y, 0.0);
  }
  EXPECT_NEAR(zmax - zmin, 0.305, 1e-12);
  for (const auto& v : d.vel) EXPECT_EQ(v[2], -201.7);
}

// The thick cylinder (plane strain, quarter): z fixed everywhere, x = 0 -> z+x (6), y = 0 ->
// y+z (5); one pressure face per bore face, its right-hand normal toward the axis (a positive
// pressure pushes outward), all nodes on r = a.
TEST(DeckGen, ThickCylinderConstraintsAndPressureFaces) {
  const Deck d = load("thick_cylinder");
  for (std::size_t i = 0; i < d.X.size(); ++i) {
    const int want = d.X[i].x == 0.0 ? 6 : d.X[i].y == 0.0 ? 5 : 3;
    EXPECT_EQ(d.bc[i], want) << "node " << i + 1;
  }
  ASSERT_EQ(d.pressure.size(), 8u);
  for (const auto& f : d.pressure) {
    Vec c{0, 0, 0};
    for (int id : f) {
      EXPECT_NEAR(std::hypot(d.x(id).x, d.x(id).y), 0.01, 1e-12);
      c = {c.x + d.x(id).x / 4, c.y + d.x(id).y / 4, c.z + d.x(id).z / 4};
    }
    const Vec n = cross(sub(d.x(f[2]), d.x(f[0])), sub(d.x(f[3]), d.x(f[1])));
    EXPECT_LT(n.x * c.x + n.y * c.y, 0.0);
    EXPECT_NEAR(n.z, 0.0, 1e-15);
  }
}

TEST(DeckGen, SolverReaderAcceptsCommittedDecks) {
  for (const auto& n : kDecks) {
    impact3d::Model model;
    impact3d::Diagnostics diag;
    const bool ok = impact3d::read_and_check_deck(committed(n).string(), model, diag);
    std::ostringstream msgs;
    diag.print(msgs);
    EXPECT_TRUE(ok) << n << ":\n" << msgs.str();
    EXPECT_EQ(diag.error_count(), 0) << n << ":\n" << msgs.str();
    EXPECT_EQ(diag.warning_count(), 0) << n << ":\n" << msgs.str();
    const Deck d = load(n);
    EXPECT_EQ(model.num_nodes(), d.numnp) << n;
    EXPECT_EQ(model.num_hexes(), d.numelh) << n;
    EXPECT_EQ(model.walls.size(), d.walls.size()) << n;
    EXPECT_EQ(model.interfaces.size(), static_cast<std::size_t>(d.nsi)) << n;
  }
}

TEST(DeckGen, RefineMultipliesElementsByEight) {
  TempDir t("refine2");
  ASSERT_EQ(run(generator() + " " + t.path.string() + " --refine 2"), 0);
  for (const auto& n : kDecks) {
    const Deck base = load(n);
    const Deck d = parse(slurp(t.path / (n + ".dyn")));
    EXPECT_EQ(d.numelh, 8 * base.numelh) << n;
    EXPECT_EQ(d.element_cards, static_cast<std::size_t>(d.numelh)) << n;
    EXPECT_EQ(d.node_cards, static_cast<std::size_t>(d.numnp)) << n;
    expect_positive_volumes(d, n + " (refine 2)");
  }
  const Deck tb = parse(slurp(t.path / "taylor_bar.dyn"));
  EXPECT_EQ(tb.numnp, 127 * 73);
  expect_symmetry_bc(tb, true, true, "taylor_bar (refine 2)");
}

// --taylor-bar NHEX: about NHEX hexahedra, positive volumes, symmetry codes; the keyword form
// (--keyword) reads as the same model as the fixed form.
TEST(DeckGen, TaylorBarAtRequestedSizeInBothFormats) {
  TempDir t("taylor_hexes");
  const fs::path fixed = t.path / "bar.dyn", keyword = t.path / "bar.k";
  ASSERT_EQ(run(generator() + " --taylor-bar 5000 > " + fixed.string()), 0);
  ASSERT_EQ(run(generator() + " --taylor-bar 5000 --keyword > " + keyword.string()), 0);
  const Deck d = parse(slurp(fixed));
  EXPECT_GT(d.numelh, 4500);
  EXPECT_LT(d.numelh, 5500);
  expect_positive_volumes(d, "taylor bar 5000");
  expect_symmetry_bc(d, true, true, "taylor bar 5000");
  impact3d::Model a, b;
  impact3d::Diagnostics da, db;
  ASSERT_TRUE(impact3d::read_and_check_deck(fixed.string(), a, da));
  ASSERT_TRUE(impact3d::read_and_check_deck(keyword.string(), b, db));
  EXPECT_EQ(da.warning_count(), 0);
  EXPECT_EQ(db.warning_count(), 0);
  EXPECT_TRUE(b.keyword_deck);
  EXPECT_EQ(a.num_hexes(), d.numelh);
  std::string diffs;
  for (const auto& l : impact3d::model_differences(a, b)) diffs += l + "\n";
  EXPECT_EQ(diffs, "");
  // deterministic, and the shipped decks' options are refused together with it
  const fs::path again = t.path / "again.k";
  ASSERT_EQ(run(generator() + " --taylor-bar 5000 --keyword > " + again.string()), 0);
  EXPECT_TRUE(slurp(again) == slurp(keyword));
  EXPECT_NE(run(generator() + " --taylor-bar 5000 --refine 2 > " + (t.path / "x").string() + " 2>&1"), 0);
  EXPECT_NE(run(generator() + " --taylor-bar 0 > " + (t.path / "x").string() + " 2>&1"), 0);
}

}  // namespace
