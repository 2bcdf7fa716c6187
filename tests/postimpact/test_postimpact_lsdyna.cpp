// POST-IMPACT on plot databases written by LS-DYNA (tests/data/lsdyna): every element family in
// one numbering, shells drawn as surfaces and beams as lines, fringes at a chosen surface,
// deleted elements hidden, histories of shells and nodes, summary.
//
// Expected values: the raw float32 words of the files (the reader's own test checks those
// against VTK 9.1 and the LS-DYNA database manual), and von Mises / means computed here by hand
// from them; tolerances 1e-9 relative (sums and square roots of float32 values in double).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/plot_database.h"
#include "postimpact/compare.h"
#include "postimpact/database.h"
#include "postimpact/elements.h"
#include "postimpact/fringe.h"
#include "postimpact/history.h"
#include "postimpact/mesh_surface.h"
#include "postimpact/picture.h"
#include "postimpact/quantities.h"
#include "postimpact/summary.h"

namespace fs = std::filesystem;
using namespace postimpact;

namespace {

std::string lsdyna(const std::string& name) {
    return std::string(IMPACT3D_SOURCE_DIR) + "/tests/data/lsdyna/" + name + "/d3plot";
}

Quantity quantity(const std::string& key) {
    Quantity q;
    EXPECT_TRUE(find_quantity(key, q)) << key;
    return q;
}

double vm(const double* s) {
    const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
    return std::sqrt((a * a + b * b + c * c) / 2 + 3 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

bool has_color(const Image& img, Rgb c, int x0, int x1) {
    for (int y = 0; y < img.height; ++y)
        for (int x = x0; x < x1; ++x)
            if (img.get(x, y) == c) return true;
    return false;
}

// a clearly red (red) or clearly blue (!red) pixel
bool has_hue(const Image& img, int x0, int x1, bool red) {
    for (int y = 0; y < img.height; ++y)
        for (int x = x0; x < x1; ++x) {
            const Rgb c = img.get(x, y);
            if (red ? (c.r > 120 && c.g < 60 && c.b < 60) : (c.b > 120 && c.r < 60 && c.g < 60)) return true;
        }
    return false;
}

void spit_file(const std::string& path, const std::vector<char>& d) {
    std::ofstream f(path, std::ios::binary);
    f.write(d.data(), static_cast<std::streamsize>(d.size()));
}

double coverage(const Image& img, int x1) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < x1; ++x)
            if (!(img.get(x, y) == Rgb{255, 255, 255})) ++n;
    return static_cast<double>(n) / (static_cast<double>(img.height) * x1);
}

}  // namespace

TEST(LsDyna, OneElementNumberingOverAllFamilies) {
    Database db(lsdyna("d3plot_solid_int"));
    const auto& g = db.geometry();
    ASSERT_EQ(num_elements(g), 32);
    EXPECT_EQ(family_offset(g, Family::Shell), 16);
    // shell 17 is the first shell; solid 1 the first solid
    EXPECT_EQ(db.element_index(17), 16);
    EXPECT_EQ(element_ref(g, 16).family, Family::Shell);
    EXPECT_EQ(db.element_id(16), 17);
    EXPECT_EQ(db.element_index(1), 0);
    EXPECT_EQ(element_material(g, 16), 3);
    EXPECT_EQ(db.part_name(3), "shell_mat_1");
    int count = 0;
    element_nodes(g, 16, count);
    EXPECT_EQ(count, 4);
}

TEST(LsDyna, ShellsAreSurfacesBeamsAreLines) {
    {
        Database db(lsdyna("simple_d3plot"));
        const auto faces = model_faces(db.geometry(), db.state(0));
        EXPECT_EQ(faces.size(), 4696u);  // every shell, nothing else
        for (const auto& f : faces) EXPECT_GE(f.count, 3);
    }
    {
        Database db(lsdyna("d3plot_beamip"));
        const auto faces = model_faces(db.geometry(), db.state(1));
        ASSERT_EQ(faces.size(), 1u);
        EXPECT_EQ(faces[0].count, 2);
        EXPECT_EQ(faces[0].nodes[0], 0);
        EXPECT_EQ(faces[0].nodes[1], 1);
    }
    {
        // 16 solids (exterior faces only) and 16 shells
        Database db(lsdyna("d3plot_solid_int"));
        const auto& g = db.geometry();
        const auto faces = model_faces(g, db.state(21));
        int shells = 0;
        for (const auto& f : faces) shells += element_ref(g, f.element).family == Family::Shell;
        EXPECT_EQ(shells, 16);
        EXPECT_EQ(faces.size() - 16, exterior_faces(g).size());
    }
}

TEST(LsDyna, ShellStressAtAChosenSurface) {
    Database db(lsdyna("d3plot_solid_int"));
    const auto& g = db.geometry();
    const auto& L = db.layout();
    const impact3d::PlotState& s = db.state(21);
    ASSERT_EQ(L.layers, 5);
    const int e = db.element_index(17);
    const double* rec = &s.shell_vars[0];  // shell 17 is shell 0
    // the database manual's order: block 1 the mid surface (raw words 0..7), 2 the inner
    // (bottom), 3 the outer (top) surface, 4 and 5 the further points
    EXPECT_NEAR(element_value(quantity("vm"), g, L, s, e), vm(rec), 1e-9 * vm(rec));
    EXPECT_NEAR(element_value(quantity("vm@bottom"), g, L, s, e), vm(rec + 8), 1e-9 * vm(rec + 8));
    EXPECT_NEAR(element_value(quantity("vm@top"), g, L, s, e), vm(rec + 16), 1e-9 * vm(rec + 16));
    EXPECT_EQ(element_value(quantity("sxx@ip5"), g, L, s, e), rec[32]);
    EXPECT_EQ(element_value(quantity("sxx@ip2"), g, L, s, e), rec[8]);
    EXPECT_EQ(element_value(quantity("eps@mid"), g, L, s, e), 0.0031102055218070745);
    EXPECT_EQ(element_value(quantity("szz"), g, L, s, e), 19.926589965820312);
    EXPECT_EQ(element_value(quantity("thickness"), g, L, s, e), 10.0);
    EXPECT_EQ(quantity("vm@top").label, "Von Mises stress (top surface)");
    Quantity q;
    EXPECT_FALSE(find_quantity("vm@side", q));
    EXPECT_FALSE(find_quantity("temp@top", q));
    // solids: the mean over the 8 points by default, one point with @ipK
    EXPECT_EQ(element_value(quantity("sxx@ip1"), g, L, s, 0), 213.20840454101562);
    EXPECT_EQ(element_value(quantity("sxx@ip8"), g, L, s, 0), 230.7303924560547);
    EXPECT_NEAR(element_value(quantity("sxx"), g, L, s, 0), 190.72930526733398, 1e-6 * 190.7);
    EXPECT_EQ(element_value(quantity("sxx@ip9"), g, L, s, 0), 0.0);  // no such point
    // extra history values: solid 1's NEIPH value at point 1; shell 17's NEIPS value, layer 1
    EXPECT_EQ(element_value(quantity("hist1@ip1"), g, L, s, 0), 0.16481825709342957);
    EXPECT_EQ(element_value(quantity("hist1@mid"), g, L, s, e), rec[7]);
    EXPECT_EQ(element_value(quantity("hist2"), g, L, s, e), 0.0);  // NEIPS 1: none
}

TEST(LsDyna, BeamQuantitiesAndTemperatures) {
    {
        Database db(lsdyna("d3plot_beamip"));
        const impact3d::PlotState& s = db.state(1);
        EXPECT_EQ(element_value(quantity("axial_force"), db.geometry(), db.layout(), s, 0), 4.797982323945238e-12);
    }
    Database db(lsdyna("d3plot_node_temperature"));
    const auto& g = db.geometry();
    const impact3d::PlotState& s = db.state(22);
    const auto t = node_values(quantity("temp"), g, s);
    ASSERT_EQ(t.size(), 2185u);
    EXPECT_EQ(t, s.temperature);
    EXPECT_EQ(node_values(quantity("disp"), g, s)[0], 0.0);  // IU 0: no displacement written
    EXPECT_EQ(node_values(quantity("x"), g, s)[0], g.x0[0]);
}

// A beam's integration-point block in LS-DYNA's order (database manual; IMPACT-3D writes it
// so): shear stress rs, shear stress tr, axial stress, plastic strain, axial strain.  The beam
// quantities take the axial stress as sxx, the shears as sxy and szx (means over the points,
// or one point with @ipK).
TEST(LsDyna, BeamPointWordsAreShearShearAxialStrainStrain) {
    impact3d::PlotGeometry g;
    g.x0 = {0, 0, 0, 1, 0, 0};
    g.beam_nodes = {0, 1};
    g.beam_material = {1};
    g.beam_user_ids = {7};
    g.num_materials = 1;
    impact3d::PlotLayout L;
    L.beam_points = 2;
    impact3d::PlotState s;
    s.coords = g.x0;
    s.beam_vars = {-50, 1, 2, 3, 4, 5, /* point 1 */ 1, 2, 300, 0.1, -0.01, /* point 2 */ 3, 4, 100, 0.3, 0.02};
    EXPECT_EQ(element_value(quantity("sxx"), g, L, s, 0), 200.0);
    EXPECT_EQ(element_value(quantity("sxy"), g, L, s, 0), 2.0);
    EXPECT_EQ(element_value(quantity("szx"), g, L, s, 0), 3.0);
    EXPECT_NEAR(element_value(quantity("eps"), g, L, s, 0), 0.2, 1e-15);
    EXPECT_EQ(element_value(quantity("sxx@ip1"), g, L, s, 0), 300.0);
    EXPECT_EQ(element_value(quantity("szx@ip2"), g, L, s, 0), 4.0);
    EXPECT_NEAR(element_value(quantity("vm"), g, L, s, 0), std::sqrt(200.0 * 200.0 + 3 * (2.0 * 2.0 + 3.0 * 3.0)), 1e-9);
    EXPECT_EQ(element_value(quantity("axial_force"), g, L, s, 0), -50.0);
}

TEST(LsDyna, DeletedShellIsHiddenAndLeftOutOfTheFringe) {
    const fs::path dir = fs::temp_directory_path() / ("impact3d_pi_lsdyna_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& f : fs::directory_iterator(fs::path(lsdyna("d3plot_solid_int")).parent_path()))
        fs::copy_file(f.path(), dir / f.path().filename());
    fs::permissions(dir / "d3plot22", fs::perms::owner_write, fs::perm_options::add);
    {
        // the deletion flag of shell 17 (after the 16 solid flags) in the last state: 0 = deleted
        std::fstream f(dir / "d3plot22", std::ios::in | std::ios::out | std::ios::binary);
        const float zero = 0.0f;
        f.seekp(4 * (2983 - 16));
        f.write(reinterpret_cast<const char*>(&zero), 4);
    }
    Database db((dir / "d3plot").string());
    const auto& g = db.geometry();
    const impact3d::PlotState& s = db.state(21);
    EXPECT_FALSE(element_alive(s, g, 16));
    EXPECT_TRUE(element_alive(s, g, 17));
    const auto faces = model_faces(g, s);
    for (const auto& f : faces) EXPECT_NE(f.element, 16);
    EXPECT_EQ(faces.size(), model_faces(g, db.state(20)).size() - 1);
    // a node only shell 17 holds gets no value from it: the thickness fringe there is the
    // smallest value (nodes without a live element), not 10
    const auto th = nodal_fringe(quantity("thickness"), g, s, db.layout());
    int count = 0;
    const int* n = element_nodes(g, 16, count);
    bool lone = false;
    for (int k = 0; k < count; ++k) {
        int users = 0;
        for (int e = 0; e < num_elements(g); ++e) {
            int c = 0;
            const int* m = element_nodes(g, e, c);
            for (int j = 0; j < c; ++j) users += m[j] == n[k];
        }
        if (users == 1) {
            lone = true;
            EXPECT_EQ(th[n[k]], 0.0);  // solids have no thickness: the smallest value is 0
        }
    }
    EXPECT_TRUE(lone);
    Summary sum = summarize((dir / "d3plot").string(), "");
    ASSERT_NE(sum.find("failed_other_elements"), nullptr);
    EXPECT_EQ(*sum.find("failed_other_elements"), "1");
    fs::remove_all(dir);
}

TEST(LsDyna, HistoriesOfShellsAndNodes) {
    Database db(lsdyna("d3plot_node_temperature"));
    const auto curves = parse_history({"node", "100001", "temp", "vx"}, db);
    ASSERT_EQ(curves.size(), 2u);
    const HistoryData h = extract_history(db, curves);
    ASSERT_EQ(h.time.size(), 23u);
    // VTK: node at (-400.001, -70.0002, 0) (user id 100001): T 1423.1499 at t = 0, 1297.0785 at t = 20
    EXPECT_EQ(h.series[0].y[0], 1423.14990234375);
    EXPECT_EQ(h.series[0].y[22], 1297.0784912109375);
    EXPECT_EQ(h.series[1].y[22], -117.86971282958984);

    Database sdb(lsdyna("d3plot_solid_int"));
    const auto sc = parse_history({"element", "17", "eps@mid", "thickness"}, sdb);
    const HistoryData sh = extract_history(sdb, sc);
    ASSERT_EQ(sh.time.size(), 22u);
    EXPECT_EQ(sh.series[0].y[21], 0.0031102055218070745);
    EXPECT_EQ(sh.series[0].y[0], 0.0);
    EXPECT_EQ(sh.series[1].y[21], 10.0);
    // a family named: shell 17, solid 1 (the two families number their elements apart)
    const auto fc = parse_history({"shell", "17", "eps", "solid", "1", "sxx@ip1"}, sdb);
    ASSERT_EQ(fc.size(), 2u);
    const HistoryData fh = extract_history(sdb, fc);
    EXPECT_EQ(fh.series[0].y[21], 0.0031102055218070745);
    EXPECT_EQ(fh.series[1].y[21], 213.20840454101562);
    EXPECT_THROW(parse_history({"shell", "1", "vm"}, sdb), std::invalid_argument);  // solid 1 is no shell
    EXPECT_THROW(parse_history({"beam", "17", "vm"}, sdb), std::invalid_argument);
}

TEST(LsDyna, Summary) {
    const Summary s = summarize(lsdyna("d3plot_node_temperature"), "");
    ASSERT_NE(s.find("shells"), nullptr);
    EXPECT_EQ(*s.find("shells"), "2075");
    EXPECT_EQ(*s.find("states"), "23");
    EXPECT_EQ(*s.find("nodes"), "2185");
    EXPECT_EQ(s.find("beams"), nullptr);
    // IU 0: the extents are those of the initial shape (finite)
    EXPECT_TRUE(std::isfinite(std::stod(*s.find("xmin"))));
    const Summary b = summarize(lsdyna("d3plot_beamip"), "");
    EXPECT_EQ(*b.find("beams"), "1");
    EXPECT_EQ(*b.find("xmax"), "1000");
}

TEST(LsDyna, PicturesOfShellsAndBeams) {
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 640;
    ps.height = 480;
    ps.units.si = false;
    {
        Database db(lsdyna("d3plot_node_temperature"));
        ps.fringe = "temp";
        const Image img = make_picture(db, {22}, ps, r, font);
        EXPECT_GT(coverage(img, 500), 0.03);
        // the legend's scale, and on the shells both ends of it: hot (red) inside, cool (blue)
        // at the corners (shading darkens the band colours, so hues are tested)
        EXPECT_TRUE(has_color(img, band_color(0, ps.bands), 500, 640));
        EXPECT_TRUE(has_color(img, band_color(ps.bands - 1, ps.bands), 500, 640));
        EXPECT_TRUE(has_hue(img, 0, 500, true));
        EXPECT_TRUE(has_hue(img, 0, 500, false));
    }
    {
        Database db(lsdyna("d3plot_solid_int"));
        ps.fringe = "vm@top";
        const Image img = make_picture(db, {21}, ps, r, font);
        EXPECT_GT(coverage(img, 500), 0.03);
        ps.fringe = "material";
        EXPECT_NO_THROW(make_picture(db, {21}, ps, r, font));
    }
    {
        Database db(lsdyna("d3plot_beamip"));
        ps.fringe = "none";
        const Image img = make_picture(db, {1}, ps, r, font);
        EXPECT_GT(coverage(img, 500), 0.001);  // the beam's line
    }
}

namespace {

// Two hexahedra side by side (12 nodes, user ids 101.. and 11, 12), in the node order `perm`
// (perm[k] = the node stored at index k); node 1's z is shifted by dz in the last state.
std::string write_pair(const std::string& root, const std::vector<int>& perm, double dz) {
    const double x[12][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1},
                             {1, 1, 1}, {0, 1, 1}, {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}};
    const int hex[2][8] = {{0, 1, 2, 3, 4, 5, 6, 7}, {1, 8, 9, 2, 5, 10, 11, 6}};
    std::vector<int> where(12);
    for (int k = 0; k < 12; ++k) where[static_cast<std::size_t>(perm[static_cast<std::size_t>(k)])] = k;
    impact3d::PlotGeometry g;
    g.num_materials = 1;
    for (int k = 0; k < 12; ++k) {
        const int n = perm[static_cast<std::size_t>(k)];
        for (int d = 0; d < 3; ++d) g.x0.push_back(x[n][d]);
        g.node_user_ids.push_back(101 + n);
    }
    for (int e = 0; e < 2; ++e) {
        for (int k = 0; k < 8; ++k) g.hex_nodes.push_back(where[static_cast<std::size_t>(hex[e][k])]);
        g.hex_material.push_back(1);
        g.hex_user_ids.push_back(11 + e);
    }
    impact3d::PlotWriter w;
    w.open(root, g);
    for (int st = 0; st < 2; ++st) {
        impact3d::PlotState s;
        s.time = 1e-3 * st;
        s.coords = g.x0;
        if (st == 1) s.coords[3 * static_cast<std::size_t>(where[1]) + 2] += dz;
        s.stress = {1e6, 0, 0, 0, 0, 0, 2e6, 0, 0, 0, 0, 0};
        s.eps = {0.01, 0.02};
        w.write_state(s);
    }
    return root;
}

}  // namespace

TEST(LsDyna, CompareMatchesNodesAndElementsByUserId) {
    const fs::path dir = fs::temp_directory_path() / ("impact3d_pi_cmp_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "a");
    fs::create_directories(dir / "b");
    fs::create_directories(dir / "c");
    std::vector<int> id(12), rev(12);
    for (int k = 0; k < 12; ++k) id[static_cast<std::size_t>(k)] = k, rev[static_cast<std::size_t>(k)] = 11 - k;
    const std::string a = write_pair((dir / "a" / "d3plot").string(), id, 0.0);
    const std::string b = write_pair((dir / "b" / "d3plot").string(), rev, 0.0);     // other node order
    const std::string c = write_pair((dir / "c" / "d3plot").string(), rev, 1e-3);    // and node 102 moved
    std::ostringstream o1;
    EXPECT_EQ(compare_databases(a, b, {}, o1), 0) << o1.str();
    EXPECT_EQ(o1.str().find("connectivities differ"), std::string::npos) << o1.str();
    std::ostringstream o2;
    EXPECT_EQ(compare_databases(a, c, {}, o2), 1) << o2.str();
    EXPECT_NE(o2.str().find("node 102 z"), std::string::npos) << o2.str();
    fs::remove_all(dir);
}

TEST(LsDyna, CompareShellsBeamsAndTemperatures) {
    for (const char* name : {"d3plot_solid_int", "d3plot_beamip", "d3plot_node_temperature"}) {
        std::ostringstream o;
        EXPECT_EQ(compare_databases(lsdyna(name), lsdyna(name), {}, o), 0) << o.str();
    }
    // one stress word of shell 17 (block 1, the mid surface) changed in the last state
    const fs::path dir = fs::temp_directory_path() / ("impact3d_pi_cmp2_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& f : fs::directory_iterator(fs::path(lsdyna("d3plot_solid_int")).parent_path()))
        fs::copy_file(f.path(), dir / f.path().filename());
    fs::permissions(dir / "d3plot22", fs::perms::owner_write, fs::perm_options::add);
    {
        std::fstream f(dir / "d3plot22", std::ios::in | std::ios::out | std::ios::binary);
        const float v = 12345.0f;
        f.seekp(4 * (1 + 34 + 106 * 10 + 16 * 64));  // shell 17's mid-surface sxx
        f.write(reinterpret_cast<const char*>(&v), 4);
    }
    std::ostringstream o;
    EXPECT_EQ(compare_databases(lsdyna("d3plot_solid_int"), (dir / "d3plot").string(), {}, o), 1) << o.str();
    EXPECT_NE(o.str().find("shell 17 sxx"), std::string::npos) << o.str();
    // different models are not comparable
    std::ostringstream o3;
    EXPECT_EQ(compare_databases(lsdyna("d3plot_solid_int"), lsdyna("d3plot_beamip"), {}, o3), 2) << o3.str();
    fs::remove_all(dir);
}

// A thick shell (no LS-DYNA sample has one): a 4-byte database written here word by word in
// the manual's layout (IXT after IX8, NV3DT = 3 layers x (6 stresses + EPS), element deletion
// flags), read back and drawn by its exterior.  (VTK 9.1 reads this file with the same stress
// at its "Stress" (mid) and "StressOuterSurf" EPS, but takes the three 6-stress blocks as
// contiguous, without the EPS between them, unlike the manual and lasso-python.)
TEST(LsDyna, ThickShellReadAndDrawn) {
    const fs::path dir = fs::temp_directory_path() / ("impact3d_pi_tshell_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    auto put_i = [](std::vector<char>& b, std::int32_t v) { b.insert(b.end(), reinterpret_cast<char*>(&v), reinterpret_cast<char*>(&v) + 4); };
    auto put_f = [](std::vector<char>& b, float v) { b.insert(b.end(), reinterpret_cast<char*>(&v), reinterpret_cast<char*>(&v) + 4); };
    std::vector<char> root;
    for (int k = 0; k < 40; ++k) root.push_back(k < 7 ? "tshell "[k] : ' ');
    std::int32_t w[64] = {};
    w[11] = 1;                                   // FILETYPE
    w[15] = 4; w[16] = 8; w[17] = 6; w[18] = 13;  // NDIM NUMNP ICODE NGLBV
    w[20] = 1;                                   // IU
    w[36] = -10003;                              // MAXINT: 3 layers, element deletion
    w[40] = 1; w[41] = 1; w[42] = 21;            // NELT NUMMATT NV3DT
    w[43] = w[44] = w[45] = w[46] = 1000;        // IOSHL
    w[51] = 1;                                   // NMMAT
    for (int k = 10; k < 64; ++k) {
        if (k == 13) { root.insert(root.end(), {'R', '9', '6', '0'}); continue; }
        if (k == 14) { put_f(root, 960.0f); continue; }
        put_i(root, w[k]);
    }
    const float x[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0.1f}, {1, 0, 0.1f}, {1, 1, 0.1f}, {0, 1, 0.1f}};
    for (const auto& p : x)
        for (float c : p) put_f(root, c);
    for (int k = 1; k <= 8; ++k) put_i(root, k);
    put_i(root, 1);        // material
    put_f(root, -999999.0f);
    spit_file((dir / "d3plot").string(), root);
    std::vector<char> st;
    put_f(st, 0.5f);                                    // time
    for (int k = 0; k < 13; ++k) put_f(st, 0.0f);       // globals
    for (const auto& p : x)
        for (float c : p) put_f(st, c);
    for (int layer = 0; layer < 3; ++layer)             // mid, inner, outer: sxx = 100 (layer + 1), EPS 0.1 layer
        for (int k = 0; k < 7; ++k) put_f(st, k == 0 ? 100.0f * (layer + 1) : (k == 6 ? 0.1f * layer : 0.0f));
    put_f(st, 1.0f);                                    // alive
    put_f(st, -999999.0f);
    spit_file((dir / "d3plot01").string(), st);

    Database db((dir / "d3plot").string());
    const auto& g = db.geometry();
    ASSERT_EQ(g.num_tshells(), 1);
    EXPECT_EQ(g.num_hexes() + g.num_shells() + g.num_beams(), 0);
    ASSERT_EQ(db.num_states(), 1);
    EXPECT_EQ(db.layout().layers, 3);
    const impact3d::PlotState& s = db.state(0);
    ASSERT_EQ(s.tshell_vars.size(), 21u);
    // blocks: mid, inner, outer surface (the manual's thick-shell order)
    EXPECT_EQ(element_value(quantity("sxx@top"), g, db.layout(), s, 0), 300.0);
    EXPECT_EQ(element_value(quantity("sxx@bottom"), g, db.layout(), s, 0), 200.0);
    EXPECT_EQ(element_value(quantity("sxx"), g, db.layout(), s, 0), 100.0);
    EXPECT_NEAR(element_value(quantity("eps@top"), g, db.layout(), s, 0), 0.2, 1e-7);  // float32 0.2
    EXPECT_EQ(model_faces(g, s).size(), 6u);
    EXPECT_EQ(db.element_index(1, static_cast<int>(Family::ThickShell)), 0);
    fs::remove_all(dir);
}

// Damaged LS-DYNA databases (random bytes in the control words, anywhere in the root file, or
// in the first state member) are read or refused with an exception, never a crash; what is
// read is drawn and fringed.
TEST(LsDyna, RandomCorruptionNeverCrashes) {
    std::mt19937 rng(2024);
    for (const char* name : {"d3plot_beamip", "d3plot_solid_int", "d3plot_node_temperature"}) {
        const fs::path dir = fs::temp_directory_path() / (std::string("impact3d_pi_corrupt_") + name + "_" + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        for (const auto& f : fs::directory_iterator(fs::path(lsdyna(name)).parent_path()))
            fs::copy_file(f.path(), dir / f.path().filename());
        for (const auto& f : fs::directory_iterator(dir))
            fs::permissions(f.path(), fs::perms::owner_write, fs::perm_options::add);
        auto slurp = [](const fs::path& p) {
            std::ifstream f(p, std::ios::binary);
            return std::vector<char>(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
        };
        const auto root0 = slurp(dir / "d3plot"), m0 = slurp(dir / "d3plot01");
        int ok = 0, refused = 0;
        const int iterations = std::string(name) == "d3plot_node_temperature" ? 150 : 600;
        for (int it = 0; it < iterations; ++it) {
            auto root = root0;
            auto m1 = m0;
            const int mode = it % 3;
            for (int k = 0, n = 1 + static_cast<int>(rng() % 4); k < n; ++k) {
                if (mode == 0) root[rng() % (128 * 4)] = static_cast<char>(rng());
                else if (mode == 1) root[rng() % root.size()] = static_cast<char>(rng());
                else m1[rng() % m1.size()] = static_cast<char>(rng());
            }
            spit_file((dir / "d3plot").string(), root);
            spit_file((dir / "d3plot01").string(), m1);
            try {
                Database db((dir / "d3plot").string());
                const auto& g = db.geometry();
                if (db.num_states() > 0) {
                    const impact3d::PlotState& s = db.state(0);
                    model_faces(g, s);
                    for (const char* k : {"vm@top", "eps", "thickness", "axial_force", "hist1@ip2", "sxx@ip8"})
                        element_values(quantity(k), g, db.layout(), s);
                    nodal_fringe(quantity("vm"), g, s, db.layout());
                    node_values(quantity("temp"), g, s);
                }
                ++ok;
            } catch (const std::exception&) {
                ++refused;
            }
        }
        EXPECT_GT(ok, 0) << name;
        EXPECT_GT(refused, 0) << name;
        fs::remove_all(dir);
    }
}
