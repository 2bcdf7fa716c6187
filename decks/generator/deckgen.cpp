// impact3d_deckgen: writes the shipped IMPACT-3D decks (fixed format, "88 large", SI units).
//
//   impact3d_deckgen OUTDIR [--refine N]          all decks into OUTDIR
//   impact3d_deckgen --deck NAME [--refine N]     one deck (NAME or NAME.dyn) to stdout
//   impact3d_deckgen --taylor-bar NHEX             a Taylor bar of about NHEX hexahedra to stdout
//   ... --keyword                                  the deck as an LS-DYNA keyword deck instead
//
// The layout written is the one of README.md (Deck format).  Every number is printed with a fixed
// printf format, so the output is byte-for-byte deterministic.  --refine N multiplies every
// division of each body's logical grid by N (N^3 times the elements).
//
// Standard library only.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

struct Vec {
  double x = 0.0, y = 0.0, z = 0.0;
};

Vec operator-(const Vec& a, const Vec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec operator+(const Vec& a, const Vec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
Vec operator*(double s, const Vec& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const Vec& a, const Vec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec cross(const Vec& a, const Vec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

// ---------------------------------------------------------------------------------------------
// Formatting
// ---------------------------------------------------------------------------------------------

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string fmti(const char* f, long long v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

// E10 field: as many digits as fit in 10 columns.
std::string e10(double v) {
  if (v == 0.0) v = 0.0;  // no "-0"
  std::string s = (v >= 0.0) ? fmt("%10.4e", v) : fmt("%10.3e", v);
  if (s.size() != 10) throw std::runtime_error("E10 field overflow: " + s);
  return s;
}

// E20 field (node coordinates).
std::string e20(double v) {
  if (v == 0.0) v = 0.0;
  std::string s = fmt("%20.12e", v);
  if (s.size() != 20) throw std::runtime_error("E20 field overflow: " + s);
  return s;
}

std::string i5(long long v) { return fmti("%5lld", v); }
std::string i8(long long v) { return fmti("%8lld", v); }
std::string i10(long long v) { return fmti("%10lld", v); }
std::string blank(int n) { return std::string(static_cast<std::size_t>(n), ' '); }

// ---------------------------------------------------------------------------------------------
// Deck model
// ---------------------------------------------------------------------------------------------

struct Material {
  int type = 1;                 // 1 elastic, 3 elastic-plastic
  double rho = 0.0;
  bool seed_viscosity = false;  // hourglass 1 / 0.02, bulk Q1 1.2, Q2 0.06 (else fields blank)
  double E = 0.0, nu = 0.0, sigy = 0.0, etan = 0.0, beta = 0.0;
  bool initially_elastic = false;  // type 3, card 8 = 1.0
  std::string title;
};

struct Wall {
  Vec tail, head;
  double fric = 0.0;
};

struct InitVel {
  int first = 0;  // 0 = all nodes
  int last = 0;   // 0 = blank
  Vec v;
};

struct Interface {
  std::vector<std::array<int, 4>> slave, master;
  int stiffness = 1;  // 1 IMPACT-3D maximum stable
  int one_pass = 0;   // 0 symmetric (two-pass)
};

struct Curve {  // load curve: points (t, f), values already rounded to what E10 holds
  std::vector<double> t, f;
};

struct Pressure {  // pressure on a face: curve (1-based), nodes n1-n4, pressure scale
  int curve = 1;
  std::array<int, 4> nodes{};
  double scale = 1.0;
};

struct Deck {
  std::string name;   // file name without .dyn
  std::string title;  // <= 72 chars
  std::vector<std::string> notes;  // comment lines (without the leading "* ")
  std::vector<Material> mats;
  std::vector<Vec> X;
  std::vector<int> bc;
  std::vector<std::array<int, 8>> hex;
  std::vector<int> hex_mat;
  std::vector<std::array<int, 2>> node_th, solid_th;
  std::vector<Wall> walls;
  std::vector<InitVel> vel;
  std::vector<Interface> sis;
  std::vector<Curve> curves;
  std::vector<Pressure> pressures;
  double t_end = 0.0, dt_th = 0.0, dt_plot = 0.0, tssf = 0.9;
};

// ---------------------------------------------------------------------------------------------
// Circular sections: a core rectangle plus an outer ring (an "O-grid" / butterfly mesh)
// ---------------------------------------------------------------------------------------------
//
// Quarter circle (half = false): core square [0,a]x[0,a], nc x nc cells; the core boundary
// x = a, then y = a, has M = 2 nc edges, mapped to the arc of radius r (angles 0..90 degrees,
// equally spaced).  Half circle (half = true): core [-a,a]x[0,a], 2nc x nc cells; boundary
// x = a, y = a, x = -a has M = 4 nc edges, mapped to angles 0..180 degrees.  The ring has nr
// radial cells; ring nodes are interpolated linearly from the core boundary to the arc.
//
// Local node numbering: core nodes row by row (i along s fastest, then t), then ring level
// k = 1..nr, boundary index j = 0..M.  Cell numbering: core cells row by row, then ring cells
// level k = 0..nr-1 (inner to outer), j = 0..M-1.  All cells are counter-clockwise in (s,t).
struct Section {
  bool half = false;
  int nc = 0, nr = 0, M = 0, ni = 0;  // ni = core nodes along s
  std::vector<std::array<double, 2>> p;
  std::vector<std::array<int, 4>> cells;
  std::vector<int> boundary;  // core node index of boundary point j (ring level 0)

  int core_node(int i, int j) const { return j * ni + i; }
  int ring_node(int j, int k) const {
    if (k == 0) return boundary[static_cast<std::size_t>(j)];
    return ni * (nc + 1) + (k - 1) * (M + 1) + j;
  }
  int core_cells() const { return (ni - 1) * nc; }
  int ring_cell(int j, int k) const { return core_cells() + k * M + j; }
};

Section make_section(bool half, int nc, int nr, double r, double a) {
  Section s;
  s.half = half;
  s.nc = nc;
  s.nr = nr;
  s.M = half ? 4 * nc : 2 * nc;
  s.ni = half ? 2 * nc + 1 : nc + 1;
  const double h = a / nc;
  for (int j = 0; j <= nc; ++j)
    for (int i = 0; i < s.ni; ++i) {
      const double x = half ? (i == nc ? 0.0 : -a + i * h) : i * h;
      s.p.push_back({x, j * h});
    }
  // boundary of the core, counter-clockwise from (a,0)
  for (int j = 0; j <= s.M; ++j) {
    int node = 0;
    if (!half) {
      node = (j <= nc) ? s.core_node(nc, j) : s.core_node(2 * nc - j, nc);
    } else {
      if (j <= nc)
        node = s.core_node(2 * nc, j);
      else if (j <= 3 * nc)
        node = s.core_node(3 * nc - j, nc);
      else
        node = s.core_node(0, 4 * nc - j);
    }
    s.boundary.push_back(node);
  }
  // ring nodes
  const double span = half ? kPi : 0.5 * kPi;
  for (int k = 1; k <= nr; ++k)
    for (int j = 0; j <= s.M; ++j) {
      std::array<double, 2> q;  // point on the arc, exact on the axes
      if (j == 0)
        q = {r, 0.0};
      else if (!half && j == s.M)
        q = {0.0, r};
      else if (half && 2 * j == s.M)
        q = {0.0, r};
      else if (half && j == s.M)
        q = {-r, 0.0};
      else {
        const double th = span * j / s.M;
        q = {r * std::cos(th), r * std::sin(th)};
      }
      const auto& b = s.p[static_cast<std::size_t>(s.boundary[static_cast<std::size_t>(j)])];
      if (k == nr) {
        s.p.push_back(q);
      } else {
        const double f = static_cast<double>(k) / nr;
        s.p.push_back({b[0] + f * (q[0] - b[0]), b[1] + f * (q[1] - b[1])});
      }
    }
  for (int j = 0; j < nc; ++j)
    for (int i = 0; i + 1 < s.ni; ++i)
      s.cells.push_back({s.core_node(i, j), s.core_node(i + 1, j), s.core_node(i + 1, j + 1),
                         s.core_node(i, j + 1)});
  for (int k = 0; k < nr; ++k)
    for (int j = 0; j < s.M; ++j)
      s.cells.push_back({s.ring_node(j, k), s.ring_node(j, k + 1), s.ring_node(j + 1, k + 1),
                         s.ring_node(j + 1, k)});
  return s;
}

// Rectangular section [x0,x0+w]x[y0,y0+w'] with nx x ny cells (same numbering rules).
Section make_rect(int nx, int ny, double x0, double y0, double wx, double wy) {
  Section s;
  s.nc = ny;
  s.ni = nx + 1;
  s.M = 0;
  s.nr = 0;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) s.p.push_back({x0 + wx * i / nx, y0 + wy * j / ny});
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s.cells.push_back({s.core_node(i, j), s.core_node(i + 1, j), s.core_node(i + 1, j + 1),
                         s.core_node(i, j + 1)});
  return s;
}

struct Body {
  int node_base = 0;  // node id = node_base + layer * nps + local + 1
  int elem_base = 0;  // element id = elem_base + layer * nes + local + 1 (before renumbering)
  int nps = 0, nes = 0, layers = 0;
  bool reflected = false;
  int node(int layer, int local) const { return node_base + layer * nps + local + 1; }
  int elem(int layer, int local) const { return elem_base + layer * nes + local + 1; }
};

using Map = std::function<Vec(double s, double t, double w)>;

// Extrudes a section along w (positions w[0..layers]) through the affine map (s,t,w) -> x.
Body extrude(Deck& d, const Section& sec, const std::vector<double>& w, const Map& map,
             int mat) {
  Body b;
  b.node_base = static_cast<int>(d.X.size());
  b.elem_base = static_cast<int>(d.hex.size());
  b.nps = static_cast<int>(sec.p.size());
  b.nes = static_cast<int>(sec.cells.size());
  b.layers = static_cast<int>(w.size()) - 1;
  const Vec o = map(0, 0, 0);
  const double det = dot(cross(map(1, 0, 0) - o, map(0, 1, 0) - o), map(0, 0, 1) - o);
  b.reflected = det < 0.0;
  for (double wl : w)
    for (const auto& p : sec.p) {
      d.X.push_back(map(p[0], p[1], wl));
      d.bc.push_back(0);
    }
  for (int l = 0; l < b.layers; ++l)
    for (const auto& c : sec.cells) {
      std::array<int, 8> h{};
      const int lo = b.reflected ? l + 1 : l, hi = b.reflected ? l : l + 1;
      for (int q = 0; q < 4; ++q) {
        h[static_cast<std::size_t>(q)] = b.node(lo, c[static_cast<std::size_t>(q)]);
        h[static_cast<std::size_t>(q + 4)] = b.node(hi, c[static_cast<std::size_t>(q)]);
      }
      d.hex.push_back(h);
      d.hex_mat.push_back(mat);
    }
  return b;
}

std::vector<double> layers(double w0, double len, int n) {
  std::vector<double> w;
  for (int l = 0; l <= n; ++l) w.push_back(l == n ? w0 + len : w0 + len * l / n);
  return w;
}

const Vec& X(const Deck& d, int id) { return d.X[static_cast<std::size_t>(id - 1)]; }

// Orders a quadrilateral face so that its right-hand normal points away from point inside.
std::array<int, 4> outward(const Deck& d, std::array<int, 4> f, const Vec& inside) {
  const Vec n = cross(X(d, f[2]) - X(d, f[0]), X(d, f[3]) - X(d, f[1]));
  const Vec c = 0.25 * (X(d, f[0]) + X(d, f[1]) + X(d, f[2]) + X(d, f[3]));
  if (dot(n, c - inside) < 0.0) std::swap(f[1], f[3]);
  return f;
}

Vec hex_centroid(const Deck& d, int elem) {
  Vec c;
  for (int n : d.hex[static_cast<std::size_t>(elem - 1)]) c = c + X(d, n);
  return 0.125 * c;
}

// Outer (curved) faces of a circular body: one segment per outer ring cell and layer.
std::vector<std::array<int, 4>> curved_faces(const Deck& d, const Section& sec, const Body& b) {
  std::vector<std::array<int, 4>> segs;
  const int k = sec.nr;
  for (int l = 0; l < b.layers; ++l)
    for (int j = 0; j < sec.M; ++j) {
      std::array<int, 4> f = {b.node(l, sec.ring_node(j, k)), b.node(l, sec.ring_node(j + 1, k)),
                              b.node(l + 1, sec.ring_node(j + 1, k)),
                              b.node(l + 1, sec.ring_node(j, k))};
      segs.push_back(outward(d, f, hex_centroid(d, b.elem(l, sec.ring_cell(j, k - 1)))));
    }
  return segs;
}

// End faces (layer l = 0 or l = layers) of a body.
std::vector<std::array<int, 4>> end_faces(const Deck& d, const Section& sec, const Body& b,
                                          bool top) {
  std::vector<std::array<int, 4>> segs;
  const int l = top ? b.layers : 0, le = top ? b.layers - 1 : 0;
  for (std::size_t c = 0; c < sec.cells.size(); ++c) {
    const auto& q = sec.cells[c];
    std::array<int, 4> f = {b.node(l, q[0]), b.node(l, q[1]), b.node(l, q[2]), b.node(l, q[3])};
    segs.push_back(outward(d, f, hex_centroid(d, b.elem(le, static_cast<int>(c)))));
  }
  return segs;
}

// Symmetry-plane BC codes: x = 0 -> 1, y = 0 -> 2, both -> 4 (exact zeros by construction).
void symmetry_bc(Deck& d, bool plane_x, bool plane_y) {
  for (std::size_t n = 0; n < d.X.size(); ++n) {
    const bool ox = plane_x && d.X[n].x == 0.0, oy = plane_y && d.X[n].y == 0.0;
    d.bc[n] = (ox && oy) ? 4 : ox ? 1 : oy ? 2 : 0;
  }
}

// Moves element `first` to the front (id 1); the others keep their order.
void make_element_first(Deck& d, int first) {
  const auto i = static_cast<std::ptrdiff_t>(first - 1);
  std::rotate(d.hex.begin(), d.hex.begin() + i, d.hex.begin() + i + 1);
  std::rotate(d.hex_mat.begin(), d.hex_mat.begin() + i, d.hex_mat.begin() + i + 1);
}

Material copper(int type) {
  Material m;
  m.type = type;
  m.rho = 8930.0;
  m.E = 117.0e9;
  m.nu = 0.35;
  if (type == 3) {
    m.sigy = 0.4e9;
    m.etan = 0.1e9;
    m.beta = 1.0;
  }
  return m;
}

std::string mm(double v) { return fmt("%.4g", v * 1000.0) + " mm"; }

// ---------------------------------------------------------------------------------------------
// The decks
// ---------------------------------------------------------------------------------------------

// The Taylor bar with nc x nc core cells, nr radial ring cells and nl axial layers
// (nc (nc + 2 nr) nl hexahedra); the shipped deck is nc = nr = 3 N, nl = 36 N.
Deck taylor_bar_grid(int nc, int nr, int nl) {
  Deck d;
  d.name = "taylor_bar";
  d.title = "Taylor bar, copper, 227 m/s, quarter model, SI units (m kg s Pa)";
  const double r = 3.2e-3, L = 32.4e-3, a = 0.45 * r;
  const Section sec = make_section(false, nc, nr, r, a);
  Material m = copper(3);
  m.seed_viscosity = true;
  m.title = "copper, elastic-plastic, linear isotropic hardening";
  d.mats.push_back(m);
  const Body b = extrude(d, sec, layers(0.0, L, nl), [](double s, double t, double w) {
    return Vec{s, t, w};
  }, 1);
  symmetry_bc(d, true, true);
  d.vel.push_back({0, 0, {0.0, 0.0, -227.0}});
  d.walls.push_back({{0, 0, 0}, {0, 0, 1}, 0.0});
  d.t_end = 80.0e-6;
  d.dt_th = 1.0e-6;
  d.dt_plot = 4.0e-6;
  d.tssf = 0.9;
  const int top = b.node(nl, sec.core_node(0, 0));
  d.node_th = {{1, 1}, {top, top}};
  d.solid_th = {{1, 1}};
  d.notes = {
      "Seed example 1 (1987 paper, fig. 9-11): copper cylinder, radius " + mm(r) + ",",
      "length " + mm(L) + ", impacting a rigid wall at 227 m/s.",
      "  Quarter model: symmetry planes x = 0 (BC 1),",
      "y = 0 (BC 2), axis x = y = 0 (BC 4).  Axis along z, impact end z = 0, top z = L.",
      "",
      "Section: quarter circle, core square [0," + mm(a) + "]^2 of " + std::to_string(nc) + "x" +
          std::to_string(nc) + " cells, outer ring",
      std::to_string(2 * nc) + " circumferential x " + std::to_string(nr) +
          " radial cells (arc points equally spaced in angle,",
      "ring nodes linear between the core boundary and the arc); " + std::to_string(nl) +
          " equal axial layers.",
      "Counts: " + std::to_string(d.X.size()) + " nodes, " + std::to_string(d.hex.size()) +
          " hexahedra (" + std::to_string(b.nps) + " nodes per section).",
      "Numbering: node id = layer*" + std::to_string(b.nps) +
          " + local + 1, layer 0 at z = 0; element 1 is the",
      "impact-end element on the axis; node 1 is the impact-end axis node, node " +
          std::to_string(top) + " the top one.",
      "",
      "Stonewall z = 0, normal +z, frictionless; all nodes start with vz = -227 m/s.",
      "Viscosities as in the seed: hourglass 0.02, bulk quadratic 1.2, linear 0.06.",
      "80 us: the rigid-body velocity changes sign (rebound starts); 21 plot states."};
  return d;
}

Deck taylor_bar(int N) { return taylor_bar_grid(3 * N, 3 * N, 36 * N); }

// A Taylor bar of about nhex hexahedra (--taylor-bar NHEX), for input-phase tests at scale:
// nc = nr = n core and ring cells, nl layers, n = cbrt(nhex / 36) as in the shipped deck's
// proportions, nl = nhex / (3 n^2).  The node coordinates are rounded to 10 significant digits,
// so that the fixed-format deck (E20) and the keyword deck (E16) hold the same numbers.
Deck taylor_bar_hexes(long nhex) {
  const int n = std::max(1, static_cast<int>(std::lround(std::cbrt(static_cast<double>(nhex) / 36.0))));
  const int nl = std::max(1, static_cast<int>(std::lround(static_cast<double>(nhex) / (3.0 * n * n))));
  Deck d = taylor_bar_grid(n, n, nl);
  d.name = "taylor_bar_" + std::to_string(d.hex.size());
  const auto round10 = [](double v) { return std::strtod(fmt("%.9e", v).c_str(), nullptr); };
  for (auto& p : d.X) p = {round10(p.x), round10(p.y), round10(p.z)};
  return d;
}

Deck oblique_rod(int N) {
  Deck d;
  d.name = "oblique_rod";
  d.title = "oblique rod, aluminium, 201.7 m/s, 10 deg wall, SI units (m kg s Pa)";
  const double r = 0.5 * 6.38e-3, L = 0.305, a = 0.45 * r, gap = 1.0e-5;
  const double th = 10.0 * kPi / 180.0;
  const int nc = 2 * N, nr = 2 * N, nl = 145 * N;
  const Section sec = make_section(true, nc, nr, r, a);
  const double G = 26.5e9, K = 57.5e9;
  Material m;
  m.type = 3;
  m.rho = 2700.0;
  m.E = 9.0 * K * G / (3.0 * K + G);
  m.nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G));
  m.sigy = 0.29e9;
  m.etan = 0.055e9;
  m.beta = 1.0;
  m.seed_viscosity = true;
  m.title = "aluminium, elastic-plastic (G 26.5 GPa, K 57.5 GPa), isotropic hardening";
  d.mats.push_back(m);
  // Rod vertical (axis z), its bottom edge point (-r, 0, z0) a gap above the wall plane
  // sin(th) x + cos(th) z = 0 through the origin.
  const double z0 = r * std::tan(th) + gap;
  const Body b = extrude(d, sec, layers(z0, L, nl), [](double s, double t, double w) {
    return Vec{s, t, w};
  }, 1);
  symmetry_bc(d, false, true);
  d.vel.push_back({0, 0, {0.0, 0.0, -201.7}});
  d.walls.push_back({{0, 0, 0}, {std::sin(th), 0.0, std::cos(th)}, 0.0});
  d.t_end = 2600.0e-6;
  d.dt_th = 5.0e-6;
  d.dt_plot = 100.0e-6;
  d.tssf = 0.9;
  const int lead = b.node(0, sec.ring_node(sec.M, nr));
  const int top = b.node(nl, sec.core_node(nc, 0));
  const int lead_el = b.elem(0, sec.ring_cell(sec.M - 1, nr - 1));
  d.node_th = {{lead, lead}, {top, top}};
  d.solid_th = {{lead_el, lead_el}};
  d.notes = {
      "Seed example 2 (1987 paper, fig. 12-14): aluminium rod, diameter 6.38 mm, length",
      "30.5 cm, falling vertically at 201.7 m/s onto a rigid wall inclined 10 degrees to the",
      "horizontal.  LENGTH UNIT: the paper gives \"30.5\" without unit.  Taken as 30.5 cm",
      "(0.305 m): at 201.7 m/s a 30.5 mm rod covers its own length in ~150 us and would",
      "be spent long before the 2600 us the paper ran, while a 30.5 cm rod is still",
      "deforming then.  With 30.5 cm the 145 layers are 2.1 mm long, of the order of the",
      "section elements (30.5 mm would give 0.21 mm slices, 4-8x thinner than the section",
      "elements), and the stable step of the thinnest section element (~0.6 mm, dilatational",
      "speed 5860 m/s) gives ~30000 cycles for 2600 us, near the ~40000 the paper reports",
      "(30.5 mm slices would need ~80000).",
      "",
      "Half model: symmetry plane y = 0 (BC 2).  Rod axis along z, bottom at z0, top z0+L.",
      "Wall: plane sin(10) x + cos(10) z = 0 (tail at the origin, head = unit normal, tilted",
      "toward +x), frictionless stonewall.  The rod's lowest edge point (x = -r, y = 0) sits",
      "0.01 mm above the wall: z0 = r tan(10 deg) + 1e-5 m.",
      "",
      "Section: half circle, core [-" + mm(a) + "," + mm(a) + "]x[0," + mm(a) + "] of " +
          std::to_string(2 * nc) + "x" + std::to_string(nc) + " cells, ring " +
          std::to_string(4 * nc) + "x" + std::to_string(nr) + ";",
      std::to_string(nl) + " equal axial layers.  Counts: " + std::to_string(d.X.size()) +
          " nodes, " + std::to_string(d.hex.size()) + " hexahedra.",
      "E = 9KG/(3K+G), nu = (3K-2G)/(2(3K+G)).  Seed viscosities 0.02 / 1.2 / 0.06.",
      "Time histories: node " + std::to_string(lead) + " (first contact), node " +
          std::to_string(top) + " (top, axis), element " + std::to_string(lead_el) +
          " (first contact)."};
  return d;
}

Deck crossed_cylinders(int N) {
  Deck d;
  d.name = "crossed_cylinders";
  d.title = "crossed half-cylinders, copper, +-50 m/s, SI units (m kg s Pa)";
  const double r = 3.2e-3, H = 14.4e-3, a = 0.45 * r, gap = 1.0e-5;
  const int nc = 2 * N, nr = 2 * N, nl = 18 * N;
  const Section sec = make_section(false, nc, nr, r, a);
  for (int i = 0; i < 2; ++i) {
    Material m = copper(3);
    m.seed_viscosity = true;
    m.initially_elastic = true;
    m.title = std::string("copper, initially elastic, body ") + (i == 0 ? "1 (lower)" : "2 (upper)");
    d.mats.push_back(m);
  }
  const double zc1 = -0.5 * gap - r, zc2 = 0.5 * gap + r;
  // body 1: axis along x, flat face z = zc1, curved face up, section (t = y, s = z - zc1)
  const Body b1 = extrude(d, sec, layers(0.0, 0.5 * H, nl), [zc1](double s, double t, double w) {
    return Vec{w, t, zc1 + s};
  }, 1);
  // body 2: axis along y, flat face z = zc2, curved face down, section (t = x, s = zc2 - z)
  const Body b2 = extrude(d, sec, layers(0.0, 0.5 * H, nl), [zc2](double s, double t, double w) {
    return Vec{t, w, zc2 - s};
  }, 2);
  symmetry_bc(d, true, true);
  Interface si;
  si.slave = curved_faces(d, sec, b1);
  si.master = curved_faces(d, sec, b2);
  si.stiffness = 1;
  si.one_pass = 0;
  d.sis.push_back(si);
  const int c1 = b1.node(0, sec.ring_node(0, nr)), c2 = b2.node(0, sec.ring_node(0, nr));
  const int e1 = b1.elem(0, sec.ring_cell(0, nr - 1));
  make_element_first(d, e1);
  d.vel.push_back({b1.node(0, 0), b1.node(nl, b1.nps - 1), {0.0, 0.0, 50.0}});
  d.vel.push_back({b2.node(0, 0), b2.node(nl, b2.nps - 1), {0.0, 0.0, -50.0}});
  d.t_end = 50.0e-6;
  d.dt_th = 0.2e-6;
  d.dt_plot = 2.0e-6;
  d.tssf = 0.9;
  d.node_th = {{c1, c1}, {c2, c2}};
  d.solid_th = {{1, 1}};
  d.notes = {
      "Seed example 3 (1987 paper, fig. 15-17): two copper half-cylinders, radius 3.2 mm,",
      "length 14.4 mm, axes perpendicular, colliding at +50 / -50 m/s (toward each other).",
      "",
      "A half-cylinder is a cylinder cut by a plane through its axis (half-disc section).",
      "Body 1 (material 1, nodes " + std::to_string(b1.node(0, 0)) + "-" +
          std::to_string(b1.node(nl, b1.nps - 1)) + "): axis along x, flat face at z = " +
          fmt("%.4g", zc1 * 1000) + " mm,",
      "curved face up, top line z = -0.005 mm; moves +z at 50 m/s.",
      "",
      "Body 2 (material 2, nodes " + std::to_string(b2.node(0, 0)) + "-" +
          std::to_string(b2.node(nl, b2.nps - 1)) + "): axis along y, flat face at z = " +
          fmt("%.4g", zc2 * 1000) + " mm,",
      "curved face down, bottom line z = +0.005 mm; moves -z at 50 m/s.",
      "",
      "The curved surfaces would touch at the origin; an initial gap of 0.01 mm keeps",
      "everything unpenetrated at t = 0.",
      "",
      "Symmetry planes: x = 0 (mid-length of body 1, through the axis of body 2) and y = 0",
      "(through the axis of body 1, mid-length of body 2): BC 1 on x = 0, 2 on y = 0, 4 on",
      "both.  Modelled: x >= 0, y >= 0, so each body is a quarter-disc section x half",
      "length (" + mm(0.5 * H) + ", " + std::to_string(nl) + " layers); section core " +
          std::to_string(nc) + "x" + std::to_string(nc) + " cells of half-side " + mm(a) +
          ", ring " + std::to_string(2 * nc) + "x" + std::to_string(nr) + ".",
      "Counts: " + std::to_string(d.X.size()) + " nodes, " + std::to_string(d.hex.size()) +
          " hexahedra (" + std::to_string(b1.nps * (nl + 1)) + " / " +
          std::to_string(b1.nes * nl) + " per body).",
      "",
      "Sliding interface type 3: slave = curved faces of body 1, master = curved faces of",
      "body 2, stiffness choice 1 (IMPACT-3D maximum stable), symmetric treatment.",
      "Element 1 = point 1 of the seed: body 1's element at the contact point (outer ring,",
      "on y = 0 and x = 0).  Contact nodes: " + std::to_string(c1) + " (body 1), " +
          std::to_string(c2) + " (body 2).",
      "",
      "End 50 us: the bodies have separated by then (contact ends at about 41 us in",
      "IMPACT-3D with either penalty stiffness; plasticity makes it much longer than the",
      "elastic Hertz estimate of ~11 us)."};
  return d;
}

Deck one_hex(int N) {
  Deck d;
  d.name = "one_hex";
  d.title = "one steel hex (1 mm cube), rigid translation, SI units (m kg s Pa)";
  Material m;
  m.type = 1;
  m.rho = 7850.0;
  m.E = 210.0e9;
  m.nu = 0.3;
  m.title = "steel, elastic";
  d.mats.push_back(m);
  const double h = 1.0e-3;
  const Section sec = make_rect(N, N, 0.0, 0.0, h, h);
  extrude(d, sec, layers(0.0, h, N), [](double s, double t, double w) { return Vec{s, t, w}; },
          1);
  d.vel.push_back({0, 0, {1.0, 0.0, 0.0}});
  d.t_end = 1.0e-5;
  d.dt_th = 1.0e-7;
  d.dt_plot = 1.0e-6;
  // A lone free hexahedron's volumetric mode has omega = 2 c / l * sqrt(3K / (K + 4G/3))
  // (2.73 c/l at nu = 0.3): it is stable only for dt < 0.73 l / c, below the usual 0.9 l / c
  // that holds for elements inside a mesh.  Round-off seeds that mode, so use 0.67.
  d.tssf = 0.67;
  d.node_th = {{1, static_cast<int>(d.X.size())}};
  d.solid_th = {{1, static_cast<int>(d.hex.size())}};
  d.notes = {"Verification: one 1 mm cube of elastic steel, no loads, no constraints, every",
             "node starts with vx = 1 m/s.  A rigid translation: velocities stay exactly 1 m/s,",
             "stresses stay zero, x displacement = t (10 um at the end), energy constant.",
             "Time-step factor 0.67: a lone free hexahedron's volumetric mode needs < 0.73.",
             "Counts: " + std::to_string(d.X.size()) + " nodes, " +
                 std::to_string(d.hex.size()) + " hexahedron(s)."};
  return d;
}

double c0_copper() { return std::sqrt(117.0e9 / 8930.0); }

Deck bar_wall_elastic(int N) {
  Deck d;
  d.name = "bar_wall_elastic";
  d.title = "elastic copper bar 5 m/s on a rigid wall, SI units (m kg s Pa)";
  const double w = 2.0e-3, L = 20.0e-3, v = 5.0;
  Material m = copper(1);
  m.title = "copper, elastic";
  d.mats.push_back(m);
  const Section sec = make_rect(2 * N, 2 * N, -0.5 * w, -0.5 * w, w, w);
  const int nl = 40 * N;
  const Body b = extrude(d, sec, layers(0.0, L, nl),
                         [](double s, double t, double z) { return Vec{s, t, z}; }, 1);
  d.vel.push_back({0, 0, {0.0, 0.0, -v}});
  d.walls.push_back({{0, 0, 0}, {0, 0, 1}, 0.0});
  const double c0 = c0_copper();
  d.t_end = 2.5 * 2.0 * L / c0;
  d.dt_th = 0.1e-6;
  d.dt_plot = 1.0e-6;
  const int centre = sec.core_node(N, N);
  const int bot = b.node(0, centre), top = b.node(nl, centre);
  const int mid = b.elem(nl / 2, 0);
  d.node_th = {{bot, bot}, {top, top}};
  d.solid_th = {{1, 1}, {mid, mid}};
  d.notes = {
      "Verification: elastic copper bar, 2 mm x 2 mm section, length 20 mm along z,",
      "impact end z = 0, hitting a frictionless stonewall z = 0 at 5 m/s; lateral faces free",
      "(uniaxial stress).  Bar wave speed c0 = sqrt(E/rho) = " + fmt("%.1f", c0) +
          " m/s; contact stress",
      "rho c0 v = " + fmt("%.4g", 8930.0 * c0 * v / 1.0e6) +
          " MPa; contact lasts 2L/c0 = " + fmt("%.4g", 2.0 * L / c0 * 1.0e6) +
          " us, then the bar leaves at 5 m/s.",
      "End time 2.5 * 2L/c0.  Section " + std::to_string(2 * N) + "x" + std::to_string(2 * N) +
          ", " + std::to_string(nl) + " layers: " + std::to_string(d.X.size()) + " nodes, " +
          std::to_string(d.hex.size()) + " hexahedra.",
      "Default hourglass and bulk viscosity.  Nodes " + std::to_string(bot) + " / " +
          std::to_string(top) + ": impact end / top, on the axis."};
  return d;
}

Deck two_bars(int N) {
  Deck d;
  d.name = "two_bars";
  d.title = "two elastic copper bars +-5 m/s, sliding interface, SI units (m kg s Pa)";
  const double w = 2.0e-3, L = 20.0e-3, v = 5.0, gap = 1.0e-5;
  for (int i = 0; i < 2; ++i) {
    Material m = copper(1);
    m.title = std::string("copper, elastic, bar ") + (i == 0 ? "1 (lower)" : "2 (upper)");
    d.mats.push_back(m);
  }
  const Section sec = make_rect(2 * N, 2 * N, -0.5 * w, -0.5 * w, w, w);
  const int nl = 40 * N;
  const auto id = [](double s, double t, double z) { return Vec{s, t, z}; };
  const Body b1 = extrude(d, sec, layers(-0.5 * gap - L, L, nl), id, 1);
  const Body b2 = extrude(d, sec, layers(0.5 * gap, L, nl), id, 2);
  Interface si;
  si.slave = end_faces(d, sec, b1, true);
  si.master = end_faces(d, sec, b2, false);
  si.stiffness = 1;
  si.one_pass = 0;
  d.sis.push_back(si);
  d.vel.push_back({b1.node(0, 0), b1.node(nl, b1.nps - 1), {0.0, 0.0, v}});
  d.vel.push_back({b2.node(0, 0), b2.node(nl, b2.nps - 1), {0.0, 0.0, -v}});
  const double c0 = c0_copper();
  d.t_end = 2.5 * 2.0 * L / c0;
  d.dt_th = 0.1e-6;
  d.dt_plot = 1.0e-6;
  const int centre = sec.core_node(N, N);
  const int n1 = b1.node(nl, centre), n2 = b2.node(0, centre);
  const int e1 = b1.elem(nl - 1, 0), e2 = b2.elem(0, 0);
  d.node_th = {{n1, n1}, {n2, n2}};
  d.solid_th = {{e1, e1}, {e2, e2}};
  d.notes = {
      "Verification: two identical elastic copper bars (2 mm x 2 mm, 20 mm, along z) with",
      "a 0.01 mm gap at z = 0, bar 1 below moving +5 m/s, bar 2 above moving -5 m/s.",
      "Sliding interface type 3 between the end faces (slave = top of bar 1, master =",
      "bottom of bar 2), stiffness choice 1, symmetric.  Exact answer: contact stress",
      "rho c0 v = " + fmt("%.4g", 8930.0 * c0 * v / 1.0e6) + " MPa for 2L/c0 = " +
          fmt("%.4g", 2.0 * L / c0 * 1.0e6) +
          " us, then the bars separate with reversed velocities.",
      "End time 2.5 * 2L/c0.  Counts: " + std::to_string(d.X.size()) + " nodes, " +
          std::to_string(d.hex.size()) + " hexahedra.  Default viscosities.",
      "Nodes " + std::to_string(n1) + " / " + std::to_string(n2) +
          ": contact-face centres of bar 1 / bar 2."};
  return d;
}

Deck column_uniaxial_strain(int N) {
  Deck d;
  d.name = "column_uniaxial_strain";
  d.title = "copper column, uniaxial strain, 50 m/s, SI units (m kg s Pa)";
  const double w = 1.0e-3, L = 40.0e-3, v = 50.0;
  Material m = copper(3);
  m.title = "copper, elastic-plastic, linear isotropic hardening";
  d.mats.push_back(m);
  const Section sec = make_rect(N, N, 0.0, 0.0, w, w);
  const int nl = 40 * N;
  const Body b = extrude(d, sec, layers(0.0, L, nl),
                         [](double s, double t, double z) { return Vec{s, t, z}; }, 1);
  for (auto& c : d.bc) c = 4;
  d.vel.push_back({0, 0, {0.0, 0.0, -v}});
  d.walls.push_back({{0, 0, 0}, {0, 0, 1}, 0.0});
  const double E = m.E, nu = m.nu;
  const double Mc = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double cd = std::sqrt(Mc / m.rho);
  d.t_end = 0.75 * L / cd;
  d.dt_th = 0.05e-6;
  d.dt_plot = 0.5e-6;
  const int mid = b.elem(nl / 4, 0);
  d.node_th = {{1, 1}, {b.node(nl, 0), b.node(nl, 0)}};
  d.solid_th = {{1, 1}, {mid, mid}};
  const double hel = m.sigy * (1.0 - nu) / (1.0 - 2.0 * nu);
  d.notes = {
      "Verification: elastic-plastic copper column, 1 mm x 1 mm section, 40 mm long along z,",
      "every node on lateral rollers (BC 4: x and y fixed) so the strain is uniaxial,",
      "hitting a frictionless stonewall z = 0 at 50 m/s.",
      "Elastic precursor speed sqrt((K+4G/3)/rho) = " + fmt("%.1f", cd) +
          " m/s; Hugoniot elastic limit",
      "sigma_y (1-nu)/(1-2nu) = " + fmt("%.4g", hel / 1.0e6) + " MPa; elastic impact stress " +
          fmt("%.4g", m.rho * cd * v / 1.0e6) + " MPa > HEL: a two-wave",
      "structure.  End time 0.75 L / c_d: the precursor reaches 3/4 of the column.",
      "Counts: " + std::to_string(d.X.size()) + " nodes, " + std::to_string(d.hex.size()) +
          " hexahedra.  Default viscosities."};
  return d;
}

// A thick cylinder under internal pressure, plane strain (Lame's problem): a quarter of the
// annulus a <= r <= b (symmetry planes x = 0 and y = 0), nr x nt polar cells and nz layers
// with every node's z fixed.  The pressure rises smoothly ((1 - cos) / 2, 16 linear pieces)
// over t_ramp, 12 periods of the breathing mode, then is held: the response stays close to
// the static one without damping (the fixed format has no damping card).
Deck thick_cylinder(int N) {
  Deck d;
  d.name = "thick_cylinder";
  d.title = "thick cylinder, internal pressure, plane strain, SI units (m kg s Pa)";
  const double a = 0.01, b = 0.02, p = 1.0e7, h = 2.5e-3;
  Material m;
  m.type = 1;
  m.rho = 7800.0;
  m.E = 200.0e9;
  m.nu = 0.3;
  m.title = "steel, elastic";
  d.mats.push_back(m);
  const int nr = 4 * N, nt = 8 * N, nz = N;
  const double pi = std::acos(-1.0);
  const auto round10 = [](double v) { return std::strtod(fmt("%.9e", v).c_str(), nullptr); };
  const auto node = [&](int i, int j, int k) { return 1 + i + (nr + 1) * (j + (nt + 1) * k); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= nt; ++j)
      for (int i = 0; i <= nr; ++i) {
        const double r = a + (b - a) * i / nr, th = 0.5 * pi * j / nt;
        const double x = j == nt ? 0.0 : r * std::cos(th), y = j == 0 ? 0.0 : r * std::sin(th);
        d.X.push_back({round10(x), round10(y), round10(h * k / nz)});
        d.bc.push_back(j == 0 ? 5 : j == nt ? 6 : 3);  // y+z, z+x, z
      }
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nt; ++j)
      for (int i = 0; i < nr; ++i) {
        d.hex.push_back({node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                         node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1),
                         node(i, j + 1, k + 1)});
        d.hex_mat.push_back(1);
      }
  // inner faces, counter-clockwise seen from the bore: a positive pressure pushes outward
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < nt; ++j)
      d.pressures.push_back({1, {node(0, j, k), node(0, j, k + 1), node(0, j + 1, k + 1), node(0, j + 1, k)}, p});
  const double E = m.E, nu = m.nu;
  const double t_ramp = 200.0e-6, t_hold = 40.0e-6;
  Curve c;
  for (int q = 0; q <= 16; ++q) {
    c.t.push_back(round10(t_ramp * q / 16));
    c.f.push_back(std::strtod(e10(0.5 * (1.0 - std::cos(pi * q / 16))).c_str(), nullptr));
  }
  c.t.push_back(t_ramp + t_hold);
  c.f.push_back(1.0);
  d.curves.push_back(c);
  d.t_end = t_ramp + t_hold;
  d.dt_th = 1.0e-6;
  d.dt_plot = d.t_end / 12;
  d.node_th = {{node(0, 0, 0), node(0, 0, 0)}, {node(nr, 0, 0), node(nr, 0, 0)}};
  d.solid_th = {{1, 1}};
  const auto u = [&](double r) {
    return (1 + nu) * p * a * a / (E * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r);
  };
  const double rc = a + 0.5 * (b - a) / nr;
  const double sth = p * a * a * (b * b + rc * rc) / (rc * rc * (b * b - a * a));
  d.notes = {
      "Verification (Lame): a long elastic steel cylinder, inner radius 10 mm, outer 20 mm,",
      "in plane strain (every node's z fixed), internal pressure p = 10 MPa.  Quarter model:",
      "symmetry planes x = 0 (BC 6) and y = 0 (BC 5).  The pressure (curve 1, times the",
      "multipliers) rises as (1 - cos(pi t / 200 us)) / 2, sampled at 17 points, then is held",
      "40 us: the ramp is about 12 periods of the breathing mode (17 us), so the response",
      "at the end is static to a fraction of a percent, with no damping.",
      "Lame: u(r) = (1+nu) p a^2 / (E (b^2-a^2)) ((1-2nu) r + b^2/r): u(a) = " +
          fmt("%.5g", u(a) * 1e6) + " um, u(b) = " + fmt("%.5g", u(b) * 1e6) + " um;",
      "sigma_theta(r) = p a^2 (b^2+r^2) / (r^2 (b^2-a^2)) = " + fmt("%.5g", sth / 1e6) +
          " MPa at the centre of the first ring, r = " + fmt("%.5g", rc * 1e3) + " mm.",
      "Mesh: " + std::to_string(nr) + " radial x " + std::to_string(nt) + " hoop cells, " +
          std::to_string(nz) + " layer(s) of " + fmt("%.4g", h / nz * 1e3) + " mm: " +
          std::to_string(d.X.size()) + " nodes, " + std::to_string(d.hex.size()) +
          " hexahedra, " + std::to_string(d.pressures.size()) + " pressure faces.",
      "Nodes " + std::to_string(node(0, 0, 0)) + " / " + std::to_string(node(nr, 0, 0)) +
          ": r = a / r = b on y = 0; element 1: first ring, on y = 0.",
      "Tests: tests/solve/test_thick_cylinder.cpp."};
  return d;
}

// ---------------------------------------------------------------------------------------------
// Writer
// ---------------------------------------------------------------------------------------------

void line(std::string& out, const std::string& s) {
  if (s.size() > 80) throw std::runtime_error("card longer than 80 columns: " + s);
  if (s.find('\t') != std::string::npos) throw std::runtime_error("tab in card");
  std::string t = s;
  while (!t.empty() && t.back() == ' ') t.pop_back();
  out += t;
  out += '\n';
}

// Notes: consecutive entries are joined into one paragraph ("" ends a paragraph) and wrapped
// into "* " comment lines of at most 78 columns ("$ " lines in keyword decks).
void comment_block(std::string& out, const std::vector<std::string>& notes, char mark = '*') {
  const std::string m(1, mark);
  std::vector<std::string> paragraphs(1);
  for (const auto& n : notes) {
    if (n.empty()) {
      paragraphs.emplace_back();
    } else {
      if (!paragraphs.back().empty()) paragraphs.back() += ' ';
      paragraphs.back() += n;
    }
  }
  for (const auto& p : paragraphs) {
    line(out, m);
    std::string cur;
    std::size_t i = 0;
    while (i < p.size()) {
      const std::size_t j = std::min(p.find(' ', i), p.size());
      const std::string word = p.substr(i, j - i);
      if (!word.empty()) {
        if (!cur.empty() && cur.size() + 1 + word.size() > 76) {
          line(out, m + " " + cur);
          cur.clear();
        }
        cur += (cur.empty() ? "" : " ") + word;
      }
      i = j + 1;
    }
    if (!cur.empty()) line(out, m + " " + cur);
  }
  line(out, m);
}

void banner(std::string& out, const std::string& what) { line(out, "*----- " + what + " -----*"); }

std::string write_deck(const Deck& d) {
  std::string out;
  if (d.title.size() > 72) throw std::runtime_error("title too long: " + d.title);
  line(out, d.title + blank(72 - static_cast<int>(d.title.size())) + "88 large");
  line(out, "*");
  line(out, "* " + d.name + ".dyn: written by impact3d_deckgen (decks/generator).");
  line(out, "* Units: SI (m, kg, s, Pa).  Layout: README.md (Deck format), 88 large.");
  comment_block(out, d.notes);

  banner(out, "CONTROL CARD #2: counts");
  line(out, i5(static_cast<long long>(d.mats.size())) + i10(static_cast<long long>(d.X.size())) +
                i10(static_cast<long long>(d.hex.size())) + i10(0) + i10(0) + i10(0) + i10(0));
  banner(out, "CONTROL CARD #3: time-history blocks, printing");
  line(out, i5(static_cast<long long>(d.node_th.size())) +
                i5(static_cast<long long>(d.solid_th.size())) + i5(0) + i5(0) + i5(0) + i5(100) +
                i5(0) + i5(0) + i5(0));
  banner(out, "CONTROL CARD #4");
  line(out, i10(0) + i5(0) + i5(0) + i5(0) + i5(0) + "e20.0" + i5(0));
  banner(out, "CONTROL CARD #5: loads and conditions");
  {
    std::string c = i5(static_cast<long long>(d.curves.size())) + i5(0) +
                    i5(static_cast<long long>(d.pressures.size())) + i5(0) +
                    i5(static_cast<long long>(d.walls.size())) +
                    i5(0) + i5(static_cast<long long>(d.vel.size())) +
                    i5(static_cast<long long>(d.sis.size()));
    for (int i = 0; i < 8; ++i) c += i5(0);
    line(out, c);
  }
  banner(out, "CONTROL CARD #6: times");
  line(out, e10(d.t_end) + e10(d.dt_th) + e10(d.dt_plot) + i5(0) + i5(0) + blank(10) +
                blank(10) + i5(0) + i5(0) + e10(d.tssf));
  banner(out, "CONTROL CARD #7");
  {
    std::string c;
    for (int i = 0; i < 15; ++i) c += i5(0);
    line(out, c);
  }
  banner(out, "CONTROL CARD #8");
  line(out, i5(0) + i5(0));
  banner(out, "CONTROL CARD #9");
  line(out, i5(0) + i5(0) + i5(0) + i5(0));

  banner(out, "MATERIAL CARDS");
  for (std::size_t i = 0; i < d.mats.size(); ++i) {
    const Material& m = d.mats[i];
    std::string c = i5(static_cast<long long>(i + 1)) + i5(m.type) + e10(m.rho) + i5(0);
    if (m.seed_viscosity)
      c += i5(1) + e10(0.02) + i5(1) + e10(1.2) + e10(0.06);
    else
      c += blank(5) + blank(10) + blank(5) + blank(10) + blank(10);
    c += i5(0) + blank(5) + i5(0);
    line(out, c);
    line(out, m.title);
    line(out, e10(m.E));
    line(out, e10(m.nu));
    if (m.type == 3) {
      line(out, e10(m.sigy));
      line(out, e10(m.etan));
      line(out, e10(m.beta));
      line(out, m.initially_elastic ? e10(1.0) : std::string());
    } else {
      for (int k = 0; k < 4; ++k) line(out, "");
    }
  }

  banner(out, "NODE DEFINITIONS: id, BC code, x, y, z");
  for (std::size_t n = 0; n < d.X.size(); ++n)
    line(out, i8(static_cast<long long>(n + 1)) + i5(d.bc[n]) + e20(d.X[n].x) + e20(d.X[n].y) +
                  e20(d.X[n].z));

  banner(out, "ELEMENT CARDS FOR SOLID ELEMENTS: id, material, n1..n8");
  for (std::size_t e = 0; e < d.hex.size(); ++e) {
    std::string c = i8(static_cast<long long>(e + 1)) + i5(d.hex_mat[e]);
    for (int n : d.hex[e]) c += i8(n);
    line(out, c);
  }

  // time-history blocks: five (first, last) pairs a card, as DYNA3D reads them
  auto th_cards = [&](const auto& blocks) {
    for (std::size_t k = 0; k < blocks.size(); k += 5) {
      std::string c;
      for (std::size_t j = k; j < std::min(k + 5, blocks.size()); ++j) c += i8(blocks[j][0]) + i8(blocks[j][1]);
      line(out, c);
    }
  };
  if (!d.node_th.empty()) {
    banner(out, "NODE TIME-HISTORY BLOCKS: first, last (five a card)");
    th_cards(d.node_th);
  }
  if (!d.solid_th.empty()) {
    banner(out, "SOLID TIME-HISTORY BLOCKS: first, last (five a card)");
    th_cards(d.solid_th);
  }
  if (!d.curves.empty()) {
    banner(out, "LOAD CURVES: number, points; time, value");
    for (std::size_t k = 0; k < d.curves.size(); ++k) {
      const Curve& c = d.curves[k];
      line(out, i5(static_cast<long long>(k + 1)) + i5(static_cast<long long>(c.t.size())));
      for (std::size_t q = 0; q < c.t.size(); ++q) line(out, e10(c.t[q]) + e10(c.f[q]));
    }
  }
  if (!d.pressures.empty()) {
    banner(out, "PRESSURE CARDS: load curve, n1..n4, multipliers");
    for (const auto& pr : d.pressures) {
      std::string c = i5(pr.curve);
      for (int n : pr.nodes) c += i8(n);
      line(out, c + e10(pr.scale) + e10(pr.scale) + e10(pr.scale) + e10(pr.scale));
    }
  }
  if (!d.walls.empty()) {
    banner(out, "STONEWALLS: nsn, -, tail xyz, head xyz, friction");
    for (const auto& w : d.walls)
      line(out, i5(0) + blank(5) + e10(w.tail.x) + e10(w.tail.y) + e10(w.tail.z) +
                    e10(w.head.x) + e10(w.head.y) + e10(w.head.z) + e10(w.fric));
  }
  if (!d.vel.empty()) {
    banner(out, "INITIAL VELOCITIES: first (0 = all), vx, vy, vz, last, inc");
    for (const auto& v : d.vel) {
      std::string c = i8(v.first) + e10(v.v.x) + e10(v.v.y) + e10(v.v.z);
      if (v.first != 0) c += i8(v.last) + i5(1);
      line(out, c);
    }
  }
  if (!d.sis.empty()) {
    banner(out, "SLIDING INTERFACES: nss nms type fs fd decay stiff pass");
    for (const auto& s : d.sis)
      line(out, i8(static_cast<long long>(s.slave.size())) +
                    i8(static_cast<long long>(s.master.size())) + i5(3) + e10(0.0) +
                    e10(0.0) + e10(0.0) + i5(s.stiffness) + i5(s.one_pass));
    for (std::size_t k = 0; k < d.sis.size(); ++k) {
      const auto& s = d.sis[k];
      banner(out, "INTERFACE " + std::to_string(k + 1) + " SLAVE SEGMENTS: id, n1..n4");
      for (std::size_t i = 0; i < s.slave.size(); ++i) {
        std::string c = i8(static_cast<long long>(i + 1));
        for (int n : s.slave[i]) c += i8(n);
        line(out, c);
      }
      banner(out, "INTERFACE " + std::to_string(k + 1) + " MASTER SEGMENTS: id, n1..n4");
      for (std::size_t i = 0; i < s.master.size(); ++i) {
        std::string c = i8(static_cast<long long>(i + 1));
        for (int n : s.master[i]) c += i8(n);
        line(out, c);
      }
    }
  }
  line(out, "*----- END OF DECK -----*");
  return out;
}

// The same model as an LS-DYNA keyword deck (README.md, "Keyword decks"): one *PART per
// material, *NODE as I8 3E16 I8 I8, *ELEMENT_SOLID in the one-line form (10 I8), reals in the
// E10 / E16 forms above, so that it reads as the same model as write_deck's.  Decks with
// sliding interfaces are not written in this form.
std::string keyword_e16(double v) {
  if (v == 0.0) v = 0.0;
  std::string s = fmt("%16.9e", v);
  if (s.size() != 16) throw std::runtime_error("E16 field overflow: " + s);
  return s;
}

std::string write_keyword_deck(const Deck& d) {
  if (!d.sis.empty()) throw std::runtime_error("--keyword: decks with sliding interfaces are not written as keyword decks");
  std::string out;
  line(out, "*KEYWORD");
  line(out, "$ " + d.name + ".k: written by impact3d_deckgen --keyword (decks/generator).");
  line(out, "$ Units: SI (m, kg, s, Pa).  Layout: README.md (Keyword decks).");
  comment_block(out, d.notes, '$');
  line(out, "*TITLE");
  line(out, d.title);
  line(out, "*CONTROL_TERMINATION");
  line(out, "$#  endtim");
  line(out, e10(d.t_end));
  line(out, "*CONTROL_TIMESTEP");
  line(out, "$#  dtinit    tssfac");
  line(out, blank(10) + e10(d.tssf));
  line(out, "*DATABASE_BINARY_D3PLOT");
  line(out, "$#      dt");
  line(out, e10(d.dt_plot));
  line(out, "*DATABASE_NODOUT");
  line(out, "$#      dt");
  line(out, e10(d.dt_th));
  for (int solid = 0; solid < 2; ++solid)
    for (const auto& b : solid ? d.solid_th : d.node_th) {
      line(out, solid ? "*DATABASE_HISTORY_SOLID" : "*DATABASE_HISTORY_NODE");
      std::string c;
      for (int id = b[0]; id <= b[1]; ++id) {
        c += i10(id);
        if (c.size() == 80) {
          line(out, c);
          c.clear();
        }
      }
      if (!c.empty()) line(out, c);
    }
  line(out, "*SECTION_SOLID");
  line(out, "$#   secid    elform");
  line(out, i10(1) + i10(1));
  for (std::size_t i = 0; i < d.mats.size(); ++i) {
    const Material& m = d.mats[i];
    const long long id = static_cast<long long>(i + 1);
    if (m.type != 1 && m.type != 3) throw std::runtime_error("--keyword: material type not written");
    line(out, "*PART");
    line(out, m.title);
    line(out, "$#     pid     secid       mid     eosid      hgid");
    line(out, i10(id) + i10(1) + i10(id) + i10(0) + i10(m.seed_viscosity ? id : 0));
    if (m.type == 3) {
      line(out, "*MAT_PLASTIC_KINEMATIC");
      line(out, "$#     mid        ro         e        pr      sigy      etan      beta");
      line(out, i10(id) + e10(m.rho) + e10(m.E) + e10(m.nu) + e10(m.sigy) + e10(m.etan) + e10(m.beta));
      if (m.initially_elastic) {
        line(out, "*COMMENT");
        line(out, "IMPACT-3D INITIALLY_ELASTIC PART " + std::to_string(id));
      }
    } else {
      line(out, "*MAT_ELASTIC");
      line(out, "$#     mid        ro         e        pr");
      line(out, i10(id) + e10(m.rho) + e10(m.E) + e10(m.nu));
    }
    if (m.seed_viscosity) {
      line(out, "*HOURGLASS");
      line(out, "$#    hgid       ihq        qm       ibq        q1        q2");
      line(out, i10(id) + i10(1) + e10(0.02) + i10(0) + e10(1.2) + e10(0.06));
    }
  }
  line(out, "*NODE");
  line(out, "$#   nid               x               y               z      tc      rc");
  for (std::size_t n = 0; n < d.X.size(); ++n)
    line(out, i8(static_cast<long long>(n + 1)) + keyword_e16(d.X[n].x) + keyword_e16(d.X[n].y) +
                  keyword_e16(d.X[n].z) + i8(d.bc[n]) + i8(0));
  line(out, "*ELEMENT_SOLID");
  line(out, "$#   eid     pid      n1      n2      n3      n4      n5      n6      n7      n8");
  for (std::size_t e = 0; e < d.hex.size(); ++e) {
    std::string c = i8(static_cast<long long>(e + 1)) + i8(d.hex_mat[e]);
    for (int n : d.hex[e]) c += i8(n);
    line(out, c);
  }
  for (const auto& w : d.walls) {
    line(out, "*RIGIDWALL_PLANAR");
    line(out, "$#    nsid");
    line(out, i10(0));
    line(out, "$#      xt        yt        zt        xh        yh        zh      fric");
    line(out, e10(w.tail.x) + e10(w.tail.y) + e10(w.tail.z) + e10(w.head.x) + e10(w.head.y) +
                  e10(w.head.z) + e10(w.fric));
  }
  for (const auto& v : d.vel) {
    if (v.first == 0) {
      line(out, "*INITIAL_VELOCITY");
      line(out, "$#    nsid");
      line(out, i10(0));
      line(out, "$#      vx        vy        vz");
      line(out, e10(v.v.x) + e10(v.v.y) + e10(v.v.z));
    } else {
      line(out, "*INITIAL_VELOCITY_NODE");
      for (int id = v.first; id <= (v.last ? v.last : v.first); ++id)
        line(out, i10(id) + e10(v.v.x) + e10(v.v.y) + e10(v.v.z));
    }
  }
  for (std::size_t k = 0; k < d.curves.size(); ++k) {
    const Curve& c = d.curves[k];
    line(out, "*DEFINE_CURVE");
    line(out, "$#    lcid");
    line(out, i10(static_cast<long long>(k + 1)));
    line(out, "$#                a1                  o1");
    for (std::size_t q = 0; q < c.t.size(); ++q) line(out, blank(10) + e10(c.t[q]) + blank(10) + e10(c.f[q]));
  }
  if (!d.pressures.empty()) {
    line(out, "*LOAD_SEGMENT");
    line(out, "$#    lcid        sf        at        n1        n2        n3        n4");
    for (const auto& pr : d.pressures) {
      std::string c = i10(pr.curve) + e10(pr.scale) + e10(0.0);
      for (int n : pr.nodes) c += i10(n);
      line(out, c);
    }
  }
  line(out, "*END");
  return out;
}

using Builder = Deck (*)(int);
const std::vector<std::pair<std::string, Builder>>& decks() {
  static const std::vector<std::pair<std::string, Builder>> all = {
      {"taylor_bar", taylor_bar},
      {"oblique_rod", oblique_rod},
      {"crossed_cylinders", crossed_cylinders},
      {"one_hex", one_hex},
      {"bar_wall_elastic", bar_wall_elastic},
      {"two_bars", two_bars},
      {"column_uniaxial_strain", column_uniaxial_strain},
      {"thick_cylinder", thick_cylinder}};
  return all;
}

int usage() {
  std::cerr << "usage: impact3d_deckgen OUTDIR [--refine N]\n"
               "       impact3d_deckgen --deck NAME [--refine N] [--keyword] > file\n"
               "       impact3d_deckgen --taylor-bar NHEX [--keyword] > file\n"
               "decks:";
  for (const auto& d : decks()) std::cerr << ' ' << d.first;
  std::cerr << '\n';
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string outdir, deck;
  int refine = 1;
  long taylor_hexes = 0;
  bool keyword = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--refine" && i + 1 < argc) {
      char* end = nullptr;
      const long v = std::strtol(argv[++i], &end, 10);
      if (*end != '\0' || v < 1 || v > 64) return usage();
      refine = static_cast<int>(v);
    } else if (a == "--taylor-bar" && i + 1 < argc) {
      char* end = nullptr;
      const long v = std::strtol(argv[++i], &end, 10);
      if (*end != '\0' || v < 1 || v > 20000000) return usage();
      taylor_hexes = v;
    } else if (a == "--keyword") {
      keyword = true;
    } else if (a == "--deck" && i + 1 < argc) {
      deck = argv[++i];
      if (deck.size() > 4 && deck.substr(deck.size() - 4) == ".dyn")
        deck = deck.substr(0, deck.size() - 4);
    } else if (!a.empty() && a[0] != '-' && outdir.empty()) {
      outdir = a;
    } else {
      return usage();
    }
  }
  if (taylor_hexes > 0 && (!outdir.empty() || !deck.empty() || refine != 1)) return usage();
  if (taylor_hexes == 0 && outdir.empty() == deck.empty()) return usage();
  if (keyword && !outdir.empty()) return usage();
  const auto write = [&](const Deck& d) { return keyword ? write_keyword_deck(d) : write_deck(d); };
  try {
    if (taylor_hexes > 0) {
      const std::string text = write(taylor_bar_hexes(taylor_hexes));
      std::fwrite(text.data(), 1, text.size(), stdout);
      return std::fflush(stdout) == 0 ? 0 : 1;
    }
    if (!deck.empty()) {
      for (const auto& [name, build] : decks())
        if (name == deck) {
          const std::string text = write(build(refine));
          std::fwrite(text.data(), 1, text.size(), stdout);
          return std::fflush(stdout) == 0 ? 0 : 1;
        }
      std::cerr << "impact3d_deckgen: unknown deck " << deck << '\n';
      return usage();
    }
    for (const auto& [name, build] : decks()) {
      const std::string path = outdir + "/" + name + ".dyn";
      const std::string text = write_deck(build(refine));
      std::ofstream f(path, std::ios::binary | std::ios::trunc);
      f.write(text.data(), static_cast<std::streamsize>(text.size()));
      if (!f) {
        std::cerr << "impact3d_deckgen: cannot write " << path << '\n';
        return 1;
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "impact3d_deckgen: " << e.what() << '\n';
    return 1;
  }
  return 0;
}
