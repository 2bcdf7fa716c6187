// Tests of POST-IMPACT (postimpact/): exterior surface, mirror, quantities, ticks and units,
// rendering (size, coverage, legend, byte-identical output), time histories, compare, the
// command language and the default picture set.  The databases are small blocks written with
// PlotWriter into a temporary directory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/plot_database.h"
#include "postimpact/camera.h"
#include "postimpact/command_file.h"
#include "postimpact/compare.h"
#include "postimpact/database.h"
#include "postimpact/fringe.h"
#include "postimpact/history.h"
#include "postimpact/image.h"
#include "postimpact/mesh_surface.h"
#include "postimpact/picture.h"
#include "postimpact/plot2d.h"
#include "postimpact/png_io.h"
#include "postimpact/quantities.h"
#include "postimpact/summary.h"

namespace fs = std::filesystem;
using namespace postimpact;
using impact3d::PlotGeometry;
using impact3d::PlotState;

namespace {

// nx x ny x nz unit-size block of hexahedra in [0,nx]x[0,ny]x[0,nz] (scaled by h), LS-DYNA order.
PlotGeometry block(int nx, int ny, int nz, double h = 1.0) {
    PlotGeometry g;
    g.title = "test block";
    g.num_materials = 1;
    auto nid = [&](int i, int j, int k) { return i + (nx + 1) * (j + (ny + 1) * k); };
    for (int k = 0; k <= nz; ++k)
        for (int j = 0; j <= ny; ++j)
            for (int i = 0; i <= nx; ++i) g.x0.insert(g.x0.end(), {i * h, j * h, k * h});
    for (int k = 0; k < nz; ++k)
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i) {
                const int n[8] = {nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                                  nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)};
                g.hex_nodes.insert(g.hex_nodes.end(), n, n + 8);
                g.hex_material.push_back(1);
            }
    return g;
}

// A little "Taylor bar": the block shortens and bulges near z = 0, plastic strain highest at
// z = 0, state s of n.
PlotState bar_state(const PlotGeometry& g, int s, int n) {
    PlotState st;
    const double f = static_cast<double>(s) / std::max(n - 1, 1);
    st.time = 1e-5 * s;
    const int nn = g.num_nodes(), ne = g.num_hexes();
    double zmax = 0;
    for (int i = 0; i < nn; ++i) zmax = std::max(zmax, g.x0[3 * i + 2]);
    for (int i = 0; i < nn; ++i) {
        const double x = g.x0[3 * i], y = g.x0[3 * i + 1], z = g.x0[3 * i + 2];
        const double bulge = 1.0 + 0.6 * f * std::exp(-3.0 * z / zmax);
        st.coords.insert(st.coords.end(), {x * bulge, y * bulge, z * (1.0 - 0.3 * f)});
        st.vel.insert(st.vel.end(), {0.0, 0.0, -100.0 * (1.0 - f)});
    }
    for (int e = 0; e < ne; ++e) {
        double zc = 0;
        for (int k = 0; k < 8; ++k) zc += g.x0[3 * g.hex_nodes[8 * e + k] + 2] / 8.0;
        const double eps = 2.0 * f * std::exp(-3.0 * zc / zmax);
        st.eps.push_back(eps);
        const double szz = -3e8 * f * (1.0 - zc / zmax);
        st.stress.insert(st.stress.end(), {-1e7, -1e7, szz, 0.0, 0.0, 0.0});
    }
    st.kinetic_energy = 50.0 * (1 - f) * (1 - f);
    st.internal_energy = 50.0 - st.kinetic_energy;
    st.total_energy = 50.0;
    return st;
}

struct TempDir {
    fs::path path;
    TempDir() {
        path = fs::temp_directory_path() / ("postimpact_test_" + std::to_string(::getpid()) + "_" +
                                            std::to_string(counter()++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    static int& counter() { static int c = 0; return c; }
    std::string str(const std::string& name) const { return (path / name).string(); }
};

// Writes a quarter-bar database (symmetry planes x = 0, y = 0) of n states.
std::string write_bar(const TempDir& d, const std::string& name = "d3plot", int n = 5,
                      double perturb = 0.0, int perturb_node = 4) {
    PlotGeometry g = block(2, 2, 6, 1e-3);
    g.title = "quarter test bar";
    impact3d::PlotWriter w;
    const std::string root = d.str(name);
    w.open(root, g);
    for (int s = 0; s < n; ++s) {
        PlotState st = bar_state(g, s, n);
        if (s == n - 1 && perturb != 0.0) st.coords[3 * perturb_node + 2] += perturb;
        w.write_state(st);
    }
    w.close();
    return root;
}

double dot3(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

bool has_color_in(const Image& img, Rgb c, int x0, int x1, int tol = 0) {
    for (int y = 0; y < img.height; ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, img.width); ++x) {
            const Rgb p = img.get(x, y);
            if (std::abs(p.r - c.r) <= tol && std::abs(p.g - c.g) <= tol && std::abs(p.b - c.b) <= tol) return true;
        }
    return false;
}

}  // namespace

// ------------------------------------------------------------------------------------------
// Exterior surface

TEST(Surface, SingleHexHasSixOutwardFaces) {
    const PlotGeometry g = block(1, 1, 1);
    const auto faces = exterior_faces(g);
    ASSERT_EQ(faces.size(), 6u);
    const double c[3] = {0.5, 0.5, 0.5};
    for (const auto& f : faces) {
        ASSERT_EQ(f.count, 4);
        const double* a = &g.x0[3 * f.nodes[0]];
        const double* b = &g.x0[3 * f.nodes[1]];
        const double* d = &g.x0[3 * f.nodes[2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {d[0] - b[0], d[1] - b[1], d[2] - b[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double out[3] = {a[0] - c[0], a[1] - c[1], a[2] - c[2]};
        EXPECT_GT(dot3(n, out), 0.0);
    }
}

TEST(Surface, InvertedElementStillOutward) {
    PlotGeometry g = block(1, 1, 1);
    // swap bottom and top: a negatively oriented element
    std::rotate(g.hex_nodes.begin(), g.hex_nodes.begin() + 4, g.hex_nodes.end());
    for (const auto& f : exterior_faces(g)) {
        const double* a = &g.x0[3 * f.nodes[0]];
        const double* b = &g.x0[3 * f.nodes[1]];
        const double* d = &g.x0[3 * f.nodes[2]];
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
        const double v[3] = {d[0] - b[0], d[1] - b[1], d[2] - b[2]};
        const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        const double out[3] = {a[0] - 0.5, a[1] - 0.5, a[2] - 0.5};
        EXPECT_GT(dot3(n, out), 0.0);
    }
}

TEST(Surface, BlockFaceCount) {
    const PlotGeometry g = block(2, 3, 4);
    EXPECT_EQ(exterior_faces(g).size(), static_cast<std::size_t>(2 * (2 * 3 + 3 * 4 + 2 * 4)));
}

TEST(Surface, DeletedElementExposesItsNeighbours) {
    const PlotGeometry g = block(3, 3, 3);
    std::vector<unsigned char> alive(27, 1);
    EXPECT_EQ(exterior_faces(g, alive).size(), 54u);
    alive[13] = 0;  // the centre element
    EXPECT_EQ(exterior_faces(g, alive).size(), 60u);
    alive.assign(27, 0);
    EXPECT_TRUE(exterior_faces(g, alive).empty());
}

TEST(Surface, DegenerateWedgeGivesTrianglesAndQuads) {
    PlotGeometry g = block(1, 1, 1);
    // wedge: node 4 = node 3 and node 8 = node 7 (1-based)
    g.hex_nodes[3] = g.hex_nodes[2];
    g.hex_nodes[7] = g.hex_nodes[6];
    const auto faces = exterior_faces(g);
    int tri = 0, quad = 0;
    for (const auto& f : faces) (f.count == 3 ? tri : quad)++;
    EXPECT_EQ(tri, 2);
    EXPECT_EQ(quad, 3);
}

TEST(Surface, MirrorDropsSymmetryPlaneFaces) {
    const PlotGeometry g = block(2, 2, 3);
    const auto faces = exterior_faces(g);
    const Mirror m = parse_mirror("xy");
    EXPECT_EQ(mirror_copies(m).size(), 4u);
    const auto kept = drop_symmetry_faces(faces, g, m);
    // the faces on x = 0 (2x3) and y = 0 (2x3) go
    EXPECT_EQ(kept.size(), faces.size() - 12);
    EXPECT_EQ(mirror_name(parse_mirror("none")), "none");
    EXPECT_EQ(mirror_copies(parse_mirror("xyz")).size(), 8u);
    EXPECT_THROW(parse_mirror("xq"), std::invalid_argument);
}

// ------------------------------------------------------------------------------------------
// Quantities, units, ticks

TEST(Quantities, VonMisesAndPressure) {
    const double uni[6] = {-2e8, 0, 0, 0, 0, 0};
    EXPECT_NEAR(von_mises(uni), 2e8, 1e-6);
    EXPECT_NEAR(pressure(uni), 2e8 / 3.0, 1e-6);
    const double shear[6] = {0, 0, 0, 1e6, 0, 0};
    EXPECT_NEAR(von_mises(shear), std::sqrt(3.0) * 1e6, 1e-6);
    const double hydro[6] = {-5, -5, -5, 0, 0, 0};
    EXPECT_NEAR(von_mises(hydro), 0.0, 1e-12);
    EXPECT_NEAR(pressure(hydro), 5.0, 1e-12);
    Quantity q;
    EXPECT_TRUE(find_quantity("von_mises", q));
    EXPECT_EQ(q.key, "vm");
    EXPECT_FALSE(find_quantity("bogus", q));
}

TEST(Quantities, NodalAveragingAndDisplacement) {
    const PlotGeometry g = block(2, 1, 1);
    PlotState s;
    s.coords = g.x0;
    s.coords[2] += 0.5;  // node 0 moves 0.5 in z
    s.eps = {1.0, 3.0};
    s.stress.assign(12, 0.0);
    Quantity eps, disp;
    ASSERT_TRUE(find_quantity("eps", eps));
    ASSERT_TRUE(find_quantity("disp", disp));
    const auto nv = nodal_fringe(eps, g, s);
    EXPECT_DOUBLE_EQ(nv[0], 1.0);  // corner of element 1 only
    EXPECT_DOUBLE_EQ(nv[1], 2.0);  // shared node
    EXPECT_DOUBLE_EQ(nv[2], 3.0);
    EXPECT_DOUBLE_EQ(node_values(disp, g, s)[0], 0.5);
}

TEST(Units, PrefixesAndFormatting) {
    Units si;
    EXPECT_EQ(display_unit(Dim::Stress, 4e8, si).name, "MPa");
    EXPECT_EQ(display_unit(Dim::Stress, 1.2e9, si).name, "GPa");
    EXPECT_EQ(display_unit(Dim::Time, 8e-5, si).name, "µs");
    EXPECT_EQ(display_unit(Dim::Length, 0.0324, si).name, "mm");
    EXPECT_EQ(display_unit(Dim::Strain, 3.0, si).name, "");
    EXPECT_EQ(display_unit(Dim::Stress, 4e8, Units{false}).name, "");
    EXPECT_EQ(format_time(8e-5, 8e-5, si), "80.0 µs");
    EXPECT_EQ(format_tick(60.0, 10.0), "60");
    EXPECT_EQ(format_tick(0.5, 0.1), "0.5");
    EXPECT_EQ(format_number(0.317, 0.317), "0.317");
}

TEST(Plot2d, NiceTicks) {
    double lo = 0.0, hi = 59.3, step = 0;
    const auto t = nice_ticks(lo, hi, 6, &step);
    EXPECT_DOUBLE_EQ(step, 10.0);
    EXPECT_DOUBLE_EQ(lo, 0.0);
    EXPECT_DOUBLE_EQ(hi, 60.0);
    EXPECT_EQ(t.size(), 7u);
    double a = -227, b = 8.3;
    nice_ticks(a, b, 6, &step);
    EXPECT_DOUBLE_EQ(step, 50.0);
    EXPECT_DOUBLE_EQ(a, -250.0);
    EXPECT_DOUBLE_EQ(b, 50.0);
    double c = 1.0, d = 1.0;  // degenerate range
    EXPECT_FALSE(nice_ticks(c, d, 5, &step).empty());
    EXPECT_LT(c, d);
}

TEST(Camera, NamedViews) {
    View v;
    ASSERT_TRUE(named_view("front", v));
    Camera c = make_camera(v);
    EXPECT_NEAR(c.eye[1], -1.0, 1e-12);  // viewer on -y
    EXPECT_NEAR(c.up[2], 1.0, 1e-12);    // z up
    ASSERT_TRUE(named_view("top", v));
    c = make_camera(v);
    EXPECT_NEAR(c.eye[2], 1.0, 1e-12);
    EXPECT_NEAR(c.right[0], 1.0, 1e-12);
    ASSERT_TRUE(named_view("iso", v));
    c = make_camera(v);
    EXPECT_NEAR(c.eye[0], c.eye[1], 1e-12);
    EXPECT_NEAR(c.eye[0], c.eye[2], 1e-9);  // isometric: equal angles with the three axes
    EXPECT_FALSE(named_view("sideways", v));
}

// ------------------------------------------------------------------------------------------
// Rendering

TEST(Render, OsmesaClearAndReadback) {
    Renderer r;
    RenderStyle st;
    st.background = {10, 20, 30};
    st.supersample = 1;
    const Image img = r.render(16, 16, {}, st);
    ASSERT_EQ(img.width, 16);
    ASSERT_EQ(img.height, 16);
    EXPECT_EQ(img.get(0, 0), (Rgb{10, 20, 30}));
    EXPECT_EQ(img.get(15, 15), (Rgb{10, 20, 30}));
}

TEST(Render, PictureSizeCoverageLegendAndDeterminism) {
    TempDir d;
    Database db(write_bar(d));
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 800;
    ps.height = 600;
    ps.mirror = parse_mirror("xy");
    const Image a = make_picture(db, {db.num_states() - 1}, ps, r, font);
    ASSERT_EQ(a.width, 800);
    ASSERT_EQ(a.height, 600);
    const double frac = non_background_fraction(a);
    EXPECT_GT(frac, 0.05);
    EXPECT_LT(frac, 0.8);
    // legend: the extreme band colours in the right part of the picture
    EXPECT_TRUE(has_color_in(a, band_color(0, ps.bands), 600, 800));
    EXPECT_TRUE(has_color_in(a, band_color(ps.bands - 1, ps.bands), 600, 800));
    // the same input gives the same bytes, also from a fresh renderer
    Renderer r2;
    const Image b = make_picture(db, {db.num_states() - 1}, ps, r2, font);
    EXPECT_EQ(encode_png(a), encode_png(b));
    const std::string p1 = d.str("a.png"), p2 = d.str("b.png");
    write_png(p1, a);
    write_png(p2, b);
    std::ifstream f1(p1, std::ios::binary), f2(p2, std::ios::binary);
    const std::string s1((std::istreambuf_iterator<char>(f1)), {}), s2((std::istreambuf_iterator<char>(f2)), {});
    EXPECT_EQ(s1, s2);
    EXPECT_EQ(s1.find("tIME"), std::string::npos);  // no time chunk
    // round trip through the reader
    const Image back = read_png(p1);
    EXPECT_EQ(back.width, 800);
    EXPECT_EQ(back.get(400, 300), a.get(400, 300));
    // another state gives another picture
    const Image c = make_picture(db, {0}, ps, r, font);
    EXPECT_NE(encode_png(a), encode_png(c));
    // mirroring covers more of the picture than the quarter model from the same view
    PictureSettings quarter = ps;
    quarter.mirror = Mirror{};
    quarter.legend = false;
    PictureSettings whole = ps;
    whole.legend = false;
    ps.legend = false;
    EXPECT_NE(encode_png(make_picture(db, {1}, quarter, r, font)), encode_png(make_picture(db, {1}, whole, r, font)));
}

TEST(Render, PlasticStrainHighestAtTheImpactEnd) {
    // front view of the quarter bar: the band colour of the highest values appears at the
    // bottom of the picture (z = 0), the lowest at the top
    TempDir d;
    Database db(write_bar(d));
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 600;
    ps.height = 600;
    ps.legend = false;
    ps.triad = false;
    ps.edges = false;
    named_view("front", ps.view);
    const Image img = make_picture(db, {db.num_states() - 1}, ps, r, font);
    int top_hot = -1, bottom_hot = -1;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb p = img.get(x, y);
            if (p.r > 150 && p.g < 60 && p.b < 60) {  // red (lit)
                if (top_hot < 0) top_hot = y;
                bottom_hot = y;
            }
        }
    ASSERT_GE(top_hot, 0);
    EXPECT_GT(top_hot, img.height / 2);  // red only in the lower half
    EXPECT_GT(bottom_hot, img.height * 3 / 4);
}

TEST(Render, SequenceAndRangeAndNoFringe) {
    TempDir d;
    Database db(write_bar(d));
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 900;
    ps.height = 400;
    const Image seq = make_picture(db, {0, 2, 4}, ps, r, font);
    EXPECT_EQ(seq.width, 900);
    EXPECT_GT(non_background_fraction(seq), 0.03);
    ps.fringe = "none";
    const Image plain = make_picture(db, {4}, ps, r, font);
    EXPECT_FALSE(has_color_in(plain, {255, 0, 0}, 0, plain.width));
    ps.fringe = "vm";
    ps.range_auto = false;
    ps.range_lo = 0;
    ps.range_hi = 1e9;
    EXPECT_NO_THROW(make_picture(db, {4}, ps, r, font));
    ps.fringe = "nonsense";
    EXPECT_THROW(make_picture(db, {4}, ps, r, font), std::invalid_argument);
}

TEST(Render, MaterialLegendWrapsLongPartNames) {
    // a part title longer than the legend column is wrapped on words, not cut at the edge
    TempDir d;
    PlotGeometry g = block(2, 1, 1, 1e-3);
    g.num_materials = 2;
    g.hex_material = {1, 2};
    g.part_titles = {"copper, initially elastic, body 1 (lower) with a long title",
                     "copper, initially elastic, body 2 (upper) with a long title"};
    impact3d::PlotWriter w;
    w.open(d.str("d3plot"), g);
    w.write_state(bar_state(g, 0, 1));
    w.close();
    Database db(d.str("d3plot"));
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 800;
    ps.height = 600;
    ps.fringe = "material";
    ps.triad = false;
    const Image img = make_picture(db, {0}, ps, r, font);
    const int unit = std::max(8, std::min(ps.width, ps.height * 4 / 3) / 60);
    int text_rows = 0;  // rows with text ink in the legend column, right of the swatches
    for (int y = 0; y < img.height; ++y) {
        bool ink = false;
        for (int x = img.width - ps.width / 6 + unit; x < img.width; ++x) {
            const Rgb p = img.get(x, y);
            if (x >= img.width - unit / 2) {
                EXPECT_EQ(p, (Rgb{255, 255, 255})) << "x " << x << " y " << y;
            }
            ink = ink || (p.r < 128 && p.g < 128 && p.b < 128);
        }
        text_rows += ink;
    }
    EXPECT_GT(text_rows, 4 * (unit * 3 / 4));  // two names of at least two lines each
}

// ------------------------------------------------------------------------------------------
// Time histories

TEST(History, EnergiesNodesElementsAndCsv) {
    TempDir d;
    Database db(write_bar(d));
    const auto curves = parse_history({"energy", "node", "1", "vz", "dz", "element", "1", "eps", "vm", "pressure"}, db);
    ASSERT_EQ(curves.size(), 3u + 1u + 2u + 3u);  // ke ie te, hg of material 1, node, element
    const HistoryData h = extract_history(db, curves);
    ASSERT_EQ(h.time.size(), 5u);
    EXPECT_DOUBLE_EQ(h.series[0].y[0], 50.0);                       // kinetic at t = 0
    EXPECT_NEAR(h.series[4].y[0], -100.0, 1e-4);                    // node 1 vz (float words)
    EXPECT_NEAR(h.series[6].y.back(), 2.0 * std::exp(-3.0 / 12), 1e-5);  // element 1 eps
    const std::string csv = d.str("h.csv");
    write_csv(csv, h, Units{});
    std::ifstream f(csv);
    std::vector<std::string> lines;
    for (std::string l; std::getline(f, l);) lines.push_back(l);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0].rfind("state,time (s),Kinetic energy (J)", 0), 0u);
    Font font;
    const Image img = plot_history(h, "test", Units{}, 600, 400, font);
    EXPECT_EQ(img.width, 600);
    EXPECT_GT(img.height, 400);  // energy, velocity, length, strain and stress panels stacked
    EXPECT_THROW(parse_history({"node", "99999", "vz"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"node", "1", "eps"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"element", "1"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"wobble"}, db), std::invalid_argument);
}

// A bar database with one rigid wall and one sliding interface: the wall pushes with 100 s N
// and the interface carries (3 s, -4 s, 12 s) N at state s (|F| = 13 s).
std::string write_bar_with_forces(const TempDir& d, const std::string& name, double scale = 1.0) {
    PlotGeometry g = block(2, 2, 6, 1e-3);
    g.num_rigid_walls = 1;
    g.num_interfaces = 1;
    impact3d::PlotWriter w;
    const std::string root = d.str(name);
    w.open(root, g);
    for (int s = 0; s < 4; ++s) {
        PlotState st = bar_state(g, s, 4);
        st.rigid_wall_forces = {100.0 * s * scale};
        st.interface_forces = {3.0 * s, -4.0 * s, 12.0 * s};
        w.write_state(st);
    }
    return root;
}

TEST(History, RigidWallAndInterfaceForces) {
    TempDir d;
    Database db(write_bar_with_forces(d, "d3plot"));
    const auto curves = parse_history({"wall", "1", "fn", "interface", "1", "fx", "fy", "fz", "fm"}, db);
    ASSERT_EQ(curves.size(), 5u);
    const HistoryData h = extract_history(db, curves);
    ASSERT_EQ(h.time.size(), 4u);
    EXPECT_EQ(h.series[0].y[3], 300.0);
    EXPECT_EQ(h.series[1].y[2], 6.0);
    EXPECT_EQ(h.series[2].y[2], -8.0);
    EXPECT_EQ(h.series[3].y[2], 24.0);
    EXPECT_DOUBLE_EQ(h.series[4].y[3], 39.0);  // |(9, -12, 36)|
    EXPECT_EQ(h.series[0].name, "wall 1 normal force");
    EXPECT_EQ(h.series[4].name, "interface 1 force");
    const std::string csv = d.str("f.csv");
    write_csv(csv, h, Units{});
    std::ifstream f(csv);
    std::string head;
    std::getline(f, head);
    EXPECT_NE(head.find("wall 1 normal force (N)"), std::string::npos) << head;
    EXPECT_THROW(parse_history({"wall", "2", "fn"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"interface", "1"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"interface", "1", "fn"}, db), std::invalid_argument);
    // the default set adds forces.png / forces.csv when there are walls or interfaces
    std::ostringstream log;
    Session s(log);
    s.execute({"open", d.str("d3plot")});
    s.execute({"outdir", d.str("def")});
    s.execute({"size", "320", "240"});
    s.default_set();
    for (const char* name : {"forces.png", "forces.csv", "energies.csv"})
        EXPECT_TRUE(fs::exists(fs::path(d.str("def")) / name)) << name;
}

// The summary describes the live mesh: a failed (deleted) solid and the nodes only it held
// (here element 1's corner node 1, thrown far away) are out of the extents and max_eps, and
// failed_solids counts them.
TEST(Summary, LeavesOutFailedSolidsAndTheirOrphanNodes) {
    TempDir d;
    PlotGeometry g = block(2, 2, 6, 1e-3);
    impact3d::PlotWriter w;
    w.open(d.str("d3plot"), g);
    PlotState s0 = bar_state(g, 0, 2), s1 = bar_state(g, 1, 2);
    w.write_state(s0);
    PlotState s1dead = s1;
    s1dead.alive.assign(static_cast<std::size_t>(g.num_hexes()), 1);
    s1dead.alive[0] = 0;
    s1dead.coords[0] = 1.0;       // node 1 (only element 1 holds it) far away in x
    s1dead.eps[0] = 99.0;         // and the dead element's strain is out of the maximum
    w.write_state(s1dead);
    w.close();
    impact3d::PlotWriter w2;
    w2.open(d.str("ref"), g);
    w2.write_state(s0);
    w2.write_state(s1);
    w2.close();
    const Summary a = summarize(d.str("d3plot"), ""), b = summarize(d.str("ref"), "");
    ASSERT_TRUE(a.find("failed_solids"));
    EXPECT_EQ(*a.find("failed_solids"), "1");
    EXPECT_FALSE(b.find("failed_solids"));
    EXPECT_EQ(*a.find("xmax"), *b.find("xmax"));
    EXPECT_NE(*a.find("max_eps"), "99");
}

TEST(Compare, ForcesAreComparedAndTheirCountsMustAgree) {
    TempDir d;
    const std::string a = write_bar_with_forces(d, "a"), b = write_bar_with_forces(d, "b", 1.001);
    std::ostringstream o1;
    EXPECT_EQ(compare_databases(a, b, {}, o1), 1) << o1.str();
    EXPECT_NE(o1.str().find("wall 1 normal"), std::string::npos) << o1.str();
    CompareOptions loose;
    loose.tol = Tolerances::parse("force 2e-3 0\ndefault 0 0\n");
    std::ostringstream o2;
    EXPECT_EQ(compare_databases(a, b, loose, o2), 0) << o2.str();
    // a database without the force words is not comparable
    const std::string c = write_bar(d, "c", 4);
    std::ostringstream o3;
    EXPECT_EQ(compare_databases(a, c, {}, o3), 2) << o3.str();
    EXPECT_NE(o3.str().find("global blocks differ"), std::string::npos) << o3.str();
}

// ------------------------------------------------------------------------------------------
// compare

TEST(Compare, SameDifferentAndTolerances) {
    TempDir d;
    const std::string a = write_bar(d, "a"), b = write_bar(d, "b"), c = write_bar(d, "c", 5, 1e-4, 4);
    std::ostringstream o1;
    EXPECT_EQ(compare_databases(a, b, {}, o1), 0) << o1.str();
    EXPECT_NE(o1.str().find("SAME"), std::string::npos);
    std::ostringstream o2;
    EXPECT_EQ(compare_databases(a, c, {}, o2), 1);
    // the perturbed node (index 4, user id 5) at the last state is reported
    EXPECT_NE(o2.str().find("state 5"), std::string::npos) << o2.str();
    EXPECT_NE(o2.str().find("node 5 z"), std::string::npos) << o2.str();
    CompareOptions loose;
    loose.tol = Tolerances::parse("coords 0 1e-3\n# comment\ndefault 0 0\n");
    std::ostringstream o3;
    EXPECT_EQ(compare_databases(a, c, loose, o3), 0) << o3.str();
    CompareOptions rel;
    rel.tol = Tolerances::parse("coords rel=1e-6 abs=1e-9\n");
    std::ostringstream o4;
    EXPECT_EQ(compare_databases(a, c, rel, o4), 1);
    // different numbers of states
    const std::string e = write_bar(d, "e", 4);
    std::ostringstream o5;
    EXPECT_EQ(compare_databases(a, e, {}, o5), 1);
    // different meshes
    {
        impact3d::PlotWriter w;
        w.open(d.str("f"), block(1, 1, 1));
        w.write_state(PlotState{});
    }
    std::ostringstream o6;
    EXPECT_EQ(compare_databases(a, d.str("f"), {}, o6), 2);
    std::ostringstream o7;
    EXPECT_EQ(compare_databases(a, d.str("missing"), {}, o7), 2);
}

TEST(Compare, ToleranceFileErrors) {
    try {
        Tolerances::parse("time 0 0\nspeed 1 1\n", "tol.txt");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("tol.txt:2"), std::string::npos);
    }
    EXPECT_THROW(Tolerances::parse("coords -1\n"), std::runtime_error);
    EXPECT_THROW(Tolerances::parse("coords\n"), std::runtime_error);
    EXPECT_THROW(Tolerances::parse("coords 1 2 3\n"), std::runtime_error);
    EXPECT_NO_THROW(Tolerances::parse("vel 1e-5 1e-3\nstress rel=1e-4\n"));
}

// ------------------------------------------------------------------------------------------
// Command language and the default set

TEST(Commands, Split) {
    EXPECT_EQ(split_command("  picture  a.png  # comment"), (std::vector<std::string>{"picture", "a.png"}));
    EXPECT_EQ(split_command("title \"Taylor bar # 1\" x"), (std::vector<std::string>{"title", "Taylor bar # 1", "x"}));
    EXPECT_TRUE(split_command("# only a comment").empty());
    EXPECT_THROW(split_command("title \"open"), CommandError);
}

TEST(Commands, FileRunsAndReportsErrorsWithLine) {
    TempDir d;
    const std::string db = write_bar(d);
    std::ostringstream log;
    Session s(log);
    const std::string text = "open " + db + "\noutdir " + d.str("out") +
                             "\nsize 320 240\nplotsize 400 300\nmirror xy\nfringe vm\nview 30 20\nstate middle\n"
                             "picture vm_mid\nfringe eps\nsequence seq first 3 last\nframes fr 1:3\n"
                             "history e.png energy\nhistory n.png node 1 vz element 1 eps\n";
    s.run_text(text, "cmds");
    for (const char* f : {"vm_mid.png", "seq.png", "fr0001.png", "fr0002.png", "fr0003.png", "e.png", "e.csv", "n.png", "n.csv"})
        EXPECT_TRUE(fs::exists(fs::path(d.str("out")) / f)) << f;
    EXPECT_EQ(read_png(d.str("out/vm_mid.png")).width, 320);
    EXPECT_EQ(read_png(d.str("out/e.png")).width, 400);
    try {
        s.run_text("size 320 240\n\nview sideways\n", "bad.cmd");
        FAIL();
    } catch (const CommandError& e) {
        EXPECT_NE(std::string(e.what()).find("bad.cmd:3"), std::string::npos) << e.what();
    }
    EXPECT_THROW(s.run_text("state 99\n", "x"), CommandError);
    EXPECT_THROW(s.run_text("frobnicate\n", "x"), CommandError);
    EXPECT_THROW(s.run_text("fringe temperature\n", "x"), CommandError);
    Session empty(log);
    EXPECT_THROW(empty.run_text("picture a.png\n", "x"), CommandError);  // no database
}

TEST(Commands, DefaultSet) {
    TempDir d;
    const std::string db = write_bar(d);
    std::ostringstream log;
    Session s(log);
    s.execute({"open", db});
    s.execute({"outdir", d.str("def")});
    s.execute({"size", "400", "300"});
    s.default_set();
    for (const char* f : {"eps_first.png", "eps_middle.png", "eps_last.png", "eps_sequence.png", "energies.png", "energies.csv"})
        EXPECT_TRUE(fs::exists(fs::path(d.str("def")) / f)) << f;
    EXPECT_NE(log.str().find("eps_last.png"), std::string::npos);
}

// ------------------------------------------------------------------------------------------
// Golden image: a small picture compared with a stored one, with a tolerance for the few
// pixels that another Mesa/FreeType version may shade differently (edges, glyph antialiasing).
// To rewrite the golden image after an intended change of the pictures:
//   IMPACT3D_UPDATE_GOLDEN=1 build/tests/test_postimpact --gtest_filter=Render.GoldenImage
TEST(Render, GoldenImage) {
    TempDir d;
    Database db(write_bar(d));
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 320;
    ps.height = 240;
    ps.mirror = parse_mirror("xy");
    const Image img = make_picture(db, {db.num_states() - 1}, ps, r, font);
    const std::string golden = std::string(IMPACT3D_SOURCE_DIR) + "/tests/postimpact/golden/quarter_bar_eps_320x240.png";
    if (std::getenv("IMPACT3D_UPDATE_GOLDEN")) {
        fs::create_directories(fs::path(golden).parent_path());
        write_png(golden, img);
        GTEST_SKIP() << "golden image rewritten: " << golden;
    }
    ASSERT_TRUE(fs::exists(golden)) << golden;
    const Image ref = read_png(golden);
    ASSERT_EQ(ref.width, img.width);
    ASSERT_EQ(ref.height, img.height);
    // Tolerances: a pixel "differs" when a channel is off by more than 24 (of 255); at most
    // 0.5% of the pixels may differ and the mean absolute channel difference must stay below 1.
    long differ = 0;
    double sum = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const Rgb a = img.get(x, y), b = ref.get(x, y);
            const int dr = std::abs(a.r - b.r), dg = std::abs(a.g - b.g), db2 = std::abs(a.b - b.b);
            sum += dr + dg + db2;
            if (std::max({dr, dg, db2}) > 24) ++differ;
        }
    const double npx = double(img.width) * img.height;
    EXPECT_LE(differ, 0.005 * npx) << differ << " pixels differ from " << golden;
    EXPECT_LT(sum / (3 * npx), 1.0);
}

// Marks (the suite report's worst location): the ring is drawn where the node or element
// centroid projects.  Checked against the drawn mesh itself: one hexahedron (no edges, legend or
// triad; material colour, the only coloured pixels), whose centroid projects to the centre of the
// mesh's bounding box in pixels, and whose rightmost node (from the camera) to the rightmost
// mesh pixel.
TEST(Render, MarkRingsTheProjectedElementCentroidAndNode) {
    TempDir d;
    PlotGeometry g = block(1, 1, 1, 1e-2);
    g.title = "one hex";
    impact3d::PlotWriter w;
    w.open(d.str("d3plot"), g);
    PlotState st;
    st.time = 0;
    st.coords = g.x0;
    st.vel.assign(g.x0.size(), 0.0);
    st.eps.assign(1, 0.0);
    st.stress.assign(6, 0.0);
    w.write_state(st);
    w.close();
    Database db(d.str("d3plot"));
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 800;
    ps.height = 600;
    ps.fringe = "material";
    ps.edges = ps.legend = ps.triad = false;
    ASSERT_TRUE(named_view("iso", ps.view));
    ps.view.azimuth = 30;  // no two corners tie for the rightmost place
    ps.view.elevation = 20;
    const Image plain = make_picture(db, {0}, ps, r, font);
    auto coloured = [](Rgb p) { return std::max({p.r, p.g, p.b}) - std::min({p.r, p.g, p.b}) > 40; };
    auto magenta = [](Rgb p) { return p.r >= 200 && p.g <= 80 && p.b >= 200; };
    int xmin = 1 << 30, xmax = -1, ymin = 1 << 30, ymax = -1;
    for (int y = 0; y < plain.height; ++y)
        for (int x = 0; x < plain.width; ++x) {
            ASSERT_FALSE(magenta(plain.get(x, y))) << x << " " << y;
            if (!coloured(plain.get(x, y))) continue;
            xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
        }
    ASSERT_GT(xmax - xmin, 100);
    // the top of the rightmost mesh pixels (up = z: a vertical edge is rightmost)
    int yr = -1;
    for (int y = ymin; y <= ymax && yr < 0; ++y)
        if (coloured(plain.get(xmax, y))) yr = y;

    // the upper end of the rightmost edge on screen, from the camera
    const Camera cam = make_camera(ps.view);
    int right = 0;
    for (int i = 1; i < 8; ++i) {
        const double dx = cam.sx(&g.x0[3 * i]) - cam.sx(&g.x0[3 * right]);
        if (dx > 1e-12 || (dx > -1e-12 && cam.sy(&g.x0[3 * i]) > cam.sy(&g.x0[3 * right]))) right = i;
    }
    ps.marks = {PictureMark{"elem", 1, "elem 1 szz"}, PictureMark{"node", db.node_id(right), ""}};
    std::vector<MarkSpot> spots;
    const Image marked = make_picture(db, {0}, ps, r, font, {}, &spots);
    ASSERT_EQ(spots.size(), 2u);
    EXPECT_NEAR(spots[0].x, 0.5 * (xmin + xmax), 1.0);
    EXPECT_NEAR(spots[0].y, 0.5 * (ymin + ymax), 1.0);
    EXPECT_NEAR(spots[1].x, xmax, 1.5);
    EXPECT_NEAR(spots[1].y, yr, 2.0);
    // the ring: magenta pixels around each spot (none elsewhere), centred on it
    for (const MarkSpot& s : spots) {
        double sx = 0, sy = 0;
        int n = 0;
        for (int y = static_cast<int>(s.y) - 40; y <= static_cast<int>(s.y) + 40; ++y)
            for (int x = static_cast<int>(s.x) - 40; x <= static_cast<int>(s.x) + 40; ++x)
                if (marked.inside(x, y) && std::hypot(x - s.x, y - s.y) < 32 && magenta(marked.get(x, y)))
                    sx += x, sy += y, ++n;
        EXPECT_GT(n, 60) << "ring pixels";
        EXPECT_NEAR(sx / n, s.x, 1.0);
        EXPECT_NEAR(sy / n, s.y, 1.0);
    }
    // an unknown element is refused
    ps.marks = {PictureMark{"elem", 99, ""}};
    EXPECT_THROW(make_picture(db, {0}, ps, r, font), std::invalid_argument);
}
