// The tied contacts' segment search (impact3d/contact/tied_nodes.*): the grid of segment boxes
// ties every slave node to the same segment, at the same point, as the search over every segment.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "impact3d/contact/tied_nodes.h"

namespace impact3d {
namespace {

// A deterministic pseudo-random number in [0, 1) (a 64-bit LCG; the same on every machine).
struct Lcg {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(s >> 11) * (1.0 / 9007199254740992.0);
  }
};

int add_node(Model& m, double x, double y, double z) {
  m.x.push_back(x), m.y.push_back(y), m.z.push_back(z);
  return int(m.x.size()) - 1;
}

// A wavy sheet of nx x ny segments of size h (nodes perturbed by `jitter` of h), as one contact's
// master side; returns the contact's index.
int add_wavy_sheet(Model& m, int nx, int ny, double h, double jitter, Lcg& r, double wave = 0.3) {
  const int first = int(m.x.size());
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      add_node(m, h * (i + jitter * (r.next() - 0.5)), h * (j + jitter * (r.next() - 0.5)),
               wave * h * std::sin(0.4 * i) * std::cos(0.3 * j));
  TiedContact tc;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int a = first + j * (nx + 1) + i;
      tc.master.push_back({a, a + 1, a + nx + 2, a + nx + 1});
    }
  m.tied_contacts.push_back(tc);
  return int(m.tied_contacts.size()) - 1;
}

// Slave nodes around the sheet: on its nodes and edges (equal distances to neighbouring
// segments), just above and below it, and far from it.
void add_slaves(Model& m, int c, int count, double size, double h, Lcg& r) {
  TiedContact& tc = m.tied_contacts[std::size_t(c)];
  for (int k = 0; k < count; ++k) {
    double x = size * (1.2 * r.next() - 0.1), y = size * (1.2 * r.next() - 0.1);
    if (k % 5 == 0) x = h * std::round(x / h);  // on an edge line of the unperturbed grid
    const double z = 0.3 * h * std::sin(0.4 * x / h) * std::cos(0.3 * y / h) + h * 0.12 * (r.next() - 0.5);
    tc.slave_nodes.push_back(add_node(m, x, y, k % 17 == 0 ? z + 2 * h : z));
  }
}

void expect_same_ties(Model a, Model b, int c, double* tied_share) {
  const std::vector<int> ua = tie_slave_nodes(a, c, TieSearch::grid);
  const std::vector<int> ub = tie_slave_nodes(b, c, TieSearch::every_segment);
  EXPECT_EQ(ua, ub);
  ASSERT_EQ(a.node_ties.size(), b.node_ties.size());
  for (std::size_t i = 0; i < a.node_ties.size(); ++i) {
    EXPECT_EQ(a.node_ties[i].node, b.node_ties[i].node);
    EXPECT_EQ(a.node_ties[i].seg, b.node_ties[i].seg);
    EXPECT_EQ(a.node_ties[i].w, b.node_ties[i].w);  // bit for bit
  }
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_EQ(a.z, b.z);
  EXPECT_EQ(a.tied_contacts[std::size_t(c)].tied, b.tied_contacts[std::size_t(c)].tied);
  *tied_share = double(a.node_ties.size()) / double(a.tied_contacts[std::size_t(c)].slave_nodes.size());
}

TEST(TieSearch, GridTiesAsTheSearchOverEverySegment) {
  for (std::uint64_t seed : {1ULL, 2ULL, 3ULL}) {
    Lcg r{seed};
    Model m;
    const int c = add_wavy_sheet(m, 40, 30, 0.01, 0.3, r);
    add_slaves(m, c, 3000, 0.4, 0.01, r);
    double share = 0;
    expect_same_ties(m, m, c, &share);
    EXPECT_GT(share, 0.2);  // both outcomes are exercised: many tied, many out of reach
    EXPECT_LT(share, 0.9);
  }
}

TEST(TieSearch, GridTiesAsTheSearchOverEverySegmentWithAGivenReach) {
  Lcg r{7};
  Model m;
  const int c = add_wavy_sheet(m, 25, 25, 0.02, 0.2, r);
  m.tied_contacts[std::size_t(c)].tolerance = 0.004;  // |SST|
  add_slaves(m, c, 2000, 0.5, 0.02, r);
  double share = 0;
  expect_same_ties(m, m, c, &share);
  EXPECT_GT(share, 0.2);
}

TEST(TieSearch, SegmentsOfVerySizesFarApart) {
  // a tiny segment far from a flat sheet of large ones: the grid's cells stay few and every tie is
  // the same
  Lcg r{11};
  Model m;
  const int c = add_wavy_sheet(m, 4, 4, 1.0, 0.0, r, 0.0);  // flat
  const int a = add_node(m, 1e6, 1e6, 0), b = add_node(m, 1e6 + 1e-6, 1e6, 0), d = add_node(m, 1e6 + 1e-6, 1e6 + 1e-6, 0),
            e = add_node(m, 1e6, 1e6 + 1e-6, 0);
  TiedContact& tc = m.tied_contacts[std::size_t(c)];
  tc.master.push_back({a, b, d, e});
  tc.slave_nodes.push_back(add_node(m, 1e6 + 5e-7, 1e6 + 5e-7, 1e-9));
  tc.slave_nodes.push_back(add_node(m, 2.5, 2.5, 0.01));
  tc.slave_nodes.push_back(add_node(m, -3.0, 2.5, 0.0));
  double share = 0;
  expect_same_ties(m, m, c, &share);
  Model g = m;
  EXPECT_EQ(tie_slave_nodes(g, c), std::vector<int>{int(g.x.size()) - 1});  // the node off the sheet
  ASSERT_EQ(g.node_ties.size(), 2u);
  EXPECT_EQ(g.node_ties[0].seg, (std::array<int, 4>{a, b, d, e}));
}

TEST(TieSearch, SlaveNodesThatAreMasterNodesTieAsBefore) {
  // slave nodes that are also master nodes move segments as they are tied: the search falls back
  // to every segment, so the result is the reference's
  Lcg r{5};
  Model m;
  const int c = add_wavy_sheet(m, 10, 10, 0.01, 0.3, r);
  add_slaves(m, c, 300, 0.1, 0.01, r);
  TiedContact& tc = m.tied_contacts[std::size_t(c)];
  tc.slave_nodes.push_back(tc.master[55][2]);
  std::sort(tc.slave_nodes.begin(), tc.slave_nodes.end());
  double share = 0;
  expect_same_ties(m, m, c, &share);
}

}  // namespace
}  // namespace impact3d
