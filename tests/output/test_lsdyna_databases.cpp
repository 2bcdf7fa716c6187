// PlotReader on plot databases written by LS-DYNA (tests/data/lsdyna, lasso-python's test data):
// header values, counts, coordinates of given nodes and state values against the numbers an
// independent reader gives.
//
// Where the reference numbers come from:
//  * d3plot_beamip, d3plot_node_temperature, simple_d3plot: VTK 9.1.0's vtkLSDynaReader
//    (Debian python3-vtk9, DeformedMesh off, deleted cells as ghosts), run at development time;
//    its node order is its own, so nodes are found by their initial coordinates.
//  * d3plot_solid_int: VTK 9.1 crashes on it (EXTRA 64, 8-point solids), so its numbers are the
//    raw float32 words at the offsets of the LS-DYNA database manual (a Python struct script at
//    development time), and three checks that do not depend on this reader's layout logic: the
//    deletion flags, the last words of each state, equal the element material numbers (LS-DYNA
//    writes the material number for a live element), so every block before them has the
//    right length; total energy = kinetic + internal; state 0 coordinates = initial ones.
// Tolerances: values are float32 on disk and compared after widening to double, so equality is
// exact; sums (means over integration points) get 1e-6 relative (float32 rounding of the
// addends, summed in double).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/plot_database.h"

namespace fs = std::filesystem;
using impact3d::PlotGeometry;
using impact3d::PlotReader;
using impact3d::PlotState;

namespace {

std::string data(const std::string& name) {
    return std::string(IMPACT3D_SOURCE_DIR) + "/tests/data/lsdyna/" + name + "/d3plot";
}

// Node nearest to an initial position (float32 coordinates: within 1e-4 of the model size).
int node_at(const PlotGeometry& g, double x, double y, double z) {
    int best = -1;
    double bd = 1e300;
    for (int n = 0; n < g.num_nodes(); ++n) {
        const double d = std::hypot(g.x0[3 * n] - x, g.x0[3 * n + 1] - y, g.x0[3 * n + 2] - z);
        if (d < bd) { bd = d; best = n; }
    }
    EXPECT_LT(bd, 1e-9) << "no node at (" << x << ", " << y << ", " << z << ")";
    return best;
}

int index_of(const std::vector<int>& ids, int id) {
    for (std::size_t k = 0; k < ids.size(); ++k)
        if (ids[k] == id) return static_cast<int>(k);
    ADD_FAILURE() << "no element with user id " << id;
    return 0;
}

// A private copy of a database's folder (tests damage it).
std::string copy_of(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("impact3d_lsdyna_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& e : fs::directory_iterator(fs::path(data(name)).parent_path()))
        fs::copy_file(e.path(), dir / e.path().filename());
    for (const auto& e : fs::directory_iterator(dir))
        fs::permissions(e.path(), fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::add);
    return (dir / "d3plot").string();
}

void put_word(const std::string& file, int word, std::int32_t value) {
    std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(4 * word);
    f.write(reinterpret_cast<const char*>(&value), 4);
}

std::string open_error(const std::string& root) {
    try {
        PlotReader r;
        r.open(root);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(LsDynaDatabase, BeamWithIntegrationPoints) {
    PlotReader r;
    r.open(data("d3plot_beamip"));
    const auto& c = r.control();
    EXPECT_EQ(c.word_size, 4);
    EXPECT_EQ(c.version, 960.0);
    EXPECT_EQ(c.nel2, 1);
    EXPECT_EQ(c.nv1d, 26);
    EXPECT_EQ(c.maxint, -10003);
    const auto& g = r.geometry();
    ASSERT_EQ(g.num_nodes(), 2);
    ASSERT_EQ(g.num_beams(), 1);
    EXPECT_EQ(g.num_hexes() + g.num_shells() + g.num_tshells(), 0);
    EXPECT_EQ(g.beam_user_ids[0], 1);
    EXPECT_EQ(g.beam_material[0], 1);
    ASSERT_EQ(g.part_titles.size(), 1u);
    EXPECT_EQ(g.part_titles[0], "SECTION_BEAM");  // VTK's part name
    EXPECT_EQ(r.layout().beam_points, 4);         // 26 = 6 resultants + 4 x 5
    // VTK: 2 steps, times 0 and 0.0017400739016011357
    ASSERT_EQ(r.num_states(), 2);
    EXPECT_EQ(r.time(1), 0.0017400739016011357);
    const int n = node_at(g, 1000, 0, 0);
    EXPECT_EQ(g.beam_nodes[1], n);
    const PlotState s = r.state(1);
    // VTK "Deflected Coordinates" of the node at (1000, 0, 0), step 1
    EXPECT_EQ(s.coords[3 * n + 0], 1000.0);
    EXPECT_EQ(s.coords[3 * n + 1], -9.038360615498675e-10);
    EXPECT_EQ(s.coords[3 * n + 2], 1.609819946679636e-06);
    EXPECT_TRUE(s.vel.empty());  // IV 0
    // VTK beam cell arrays, step 1: AxialForce, ShearResultant, BendingResultant, TorsionResultant
    ASSERT_EQ(s.beam_vars.size(), 26u);
    EXPECT_EQ(s.beam_vars[0], 4.797982323945238e-12);
    EXPECT_EQ(s.beam_vars[1], 2.4028277039178647e-06);
    EXPECT_EQ(s.beam_vars[2], 1.8374037608737126e-05);
    EXPECT_EQ(s.beam_vars[3], -0.009219318628311157);
    EXPECT_EQ(s.beam_vars[4], 0.001209799200296402);
    EXPECT_EQ(s.beam_vars[5], 0.0);
    ASSERT_EQ(s.beam_alive.size(), 1u);
    EXPECT_EQ(s.beam_alive[0], 1);
}

TEST(LsDynaDatabase, ShellsWithNodalTemperatures) {
    PlotReader r;
    r.open(data("d3plot_node_temperature"));
    const auto& c = r.control();
    EXPECT_EQ(c.it, 1);
    EXPECT_EQ(c.iu, 0);
    EXPECT_EQ(c.nglbv, 1);
    const auto& g = r.geometry();
    ASSERT_EQ(g.num_nodes(), 2185);
    ASSERT_EQ(g.num_shells(), 2075);
    ASSERT_EQ(g.part_titles.size(), 1u);
    EXPECT_EQ(g.part_titles[0], "Profil_Shells");
    EXPECT_EQ(g.part_user_ids[0], 1000000);
    EXPECT_EQ(g.node_user_ids[0], 100001);
    EXPECT_EQ(g.shell_user_ids[0], 100001);
    // VTK: 23 steps, t[11] = 9.399999618530273, t[22] = 20
    ASSERT_EQ(r.num_states(), 23);
    EXPECT_EQ(r.time(11), 9.399999618530273);
    EXPECT_EQ(r.time(22), 20.0);
    const int a = node_at(g, -400.0010070800781, -70.00019836425781, 0.0);
    const int b = node_at(g, -5.000019550323486, 63.00026321411133, 0.0);
    {
        const PlotState s = r.state(11);
        ASSERT_EQ(s.temperature.size(), 2185u);
        EXPECT_TRUE(s.coords.empty());  // IU 0: the shape is the initial one
        EXPECT_EQ(s.temperature[a], 1334.229736328125);
        EXPECT_EQ(s.temperature[b], 1384.2103271484375);
        EXPECT_EQ(s.vel[3 * a + 0], -120.43283081054688);
        EXPECT_EQ(s.vel[3 * b + 1], 77.6697006225586);
    }
    {
        const PlotState s = r.state(22);
        EXPECT_EQ(s.temperature[a], 1297.0784912109375);
        EXPECT_EQ(s.temperature[b], 1348.854736328125);
        EXPECT_EQ(s.vel[3 * a + 0], -117.86971282958984);
        EXPECT_EQ(s.vel[3 * a + 1], -110.3544921875);
        EXPECT_EQ(s.vel[3 * b + 0], 108.76078796386719);
        EXPECT_EQ(s.vel[3 * b + 1], 92.45828247070312);
        EXPECT_TRUE(s.shell_vars.empty());  // NV2D 0
    }
    EXPECT_EQ(r.state(0).temperature[a], 1423.14990234375);
}

TEST(LsDynaDatabase, ShellsWithLayersResultantsAndStrains) {
    PlotReader r;
    r.open(data("simple_d3plot"));
    const auto& g = r.geometry();
    ASSERT_EQ(g.num_nodes(), 4915);
    ASSERT_EQ(g.num_shells(), 4696);
    EXPECT_EQ(g.part_titles.at(0), "Zugprobe");
    const auto& L = r.layout();
    // NV2D 102 = 3 layers x (6 + 1 + NEIPS 19) + 8 resultants + thickness, 2 words, 12 strains, energy
    EXPECT_EQ(L.layers, 3);
    EXPECT_EQ(L.layer_words, 26);
    EXPECT_EQ(L.shell_forces, 78);
    EXPECT_EQ(L.shell_thickness, 86);
    EXPECT_EQ(L.shell_strain, 89);
    EXPECT_EQ(L.shell_internal_energy, 101);
    ASSERT_EQ(r.num_states(), 1);
    EXPECT_EQ(r.time(0), 0.0);
    // VTK: shell 4696's first two points, shell 1's
    const int e = index_of(g.shell_user_ids, 4696);
    const double* p0 = &g.x0[3 * g.shell_nodes[4 * e]];
    const double* p1 = &g.x0[3 * g.shell_nodes[4 * e + 1]];
    EXPECT_EQ(p0[0], -8.327468872070312);
    EXPECT_EQ(p0[2], -26.908710479736328);
    EXPECT_EQ(p1[0], -7.951408863067627);
    EXPECT_EQ(p1[2], -26.63557243347168);
    const int e1 = index_of(g.shell_user_ids, 1);
    EXPECT_EQ(g.x0[3 * g.shell_nodes[4 * e1] + 0], 4.5);
    EXPECT_EQ(g.x0[3 * g.shell_nodes[4 * e1] + 2], 9.0);
    node_at(g, -7.842541217803955, 0.0, -27.063220977783203);  // VTK's last point
    const PlotState s = r.state(0);
    // VTK "Thickness" of shells 1, 100, 4696 (float32 2.93)
    for (int id : {1, 100, 4696})
        EXPECT_EQ(s.shell_vars[102 * index_of(g.shell_user_ids, id) + 86], 2.930000066757202) << id;
    EXPECT_EQ(s.shell_alive.size(), 4696u);
    EXPECT_EQ(s.coords, g.x0);  // t = 0
}

TEST(LsDynaDatabase, SolidIntegrationPointsAndShellsInAFamily) {
    PlotReader r;
    r.open(data("d3plot_solid_int"));
    const auto& c = r.control();
    EXPECT_EQ(c.title, "50 percent rund");
    EXPECT_EQ(c.extra, 64);
    EXPECT_EQ(c.neipb, 1);
    EXPECT_EQ(c.it, 10);
    const auto& g = r.geometry();
    ASSERT_EQ(g.num_nodes(), 106);
    ASSERT_EQ(g.num_hexes(), 16);
    ASSERT_EQ(g.num_shells(), 16);
    ASSERT_EQ(g.num_materials, 4);
    const std::vector<std::string> titles = {"solid_mat_1", "solid_mat_2", "shell_mat_1", "shell_mat_2"};
    EXPECT_EQ(g.part_titles, titles);
    EXPECT_EQ(g.part_user_ids, (std::vector<int>{1000, 2000, 3000, 4000}));
    EXPECT_EQ(r.layout().solid_points, 8);
    EXPECT_EQ(r.layout().solid_point_words, 8);
    EXPECT_EQ(r.layout().layers, 5);
    EXPECT_EQ(r.num_members(), 22);
    ASSERT_EQ(r.num_states(), 22);
    EXPECT_EQ(r.time(21), 0.10000019520521164);  // word 0 of d3plot22
    EXPECT_EQ(r.state(0).coords, g.x0);
    for (int i : {10, 21}) {
        const PlotState s = r.state(i);
        EXPECT_NEAR(s.total_energy, s.kinetic_energy + s.internal_energy, 1e-6 * s.total_energy) << i;
    }
    const PlotState s = r.state(21);
    // deletion flags: LS-DYNA wrote each element's material number (all alive)
    std::vector<double> flags;
    {
        std::ifstream f(std::string(IMPACT3D_SOURCE_DIR) + "/tests/data/lsdyna/d3plot_solid_int/d3plot22", std::ios::binary);
        std::vector<float> w(2983);
        f.read(reinterpret_cast<char*>(w.data()), 4 * 2983);
        for (int k = 2983 - 32; k < 2983; ++k) flags.push_back(w[k]);
    }
    for (int e = 0; e < 16; ++e) {
        EXPECT_EQ(flags[e], g.hex_material[e]);
        EXPECT_EQ(flags[16 + e], g.shell_material[e]);
        EXPECT_EQ(s.alive[e], 1);
        EXPECT_EQ(s.shell_alive[e], 1);
    }
    // solid 1 (index 0), state 22: integration point 1 and 8 raw, stress and EPS the means
    ASSERT_EQ(s.solid_vars.size(), 16u * 64u);
    EXPECT_EQ(s.solid_vars[0], 213.20840454101562);
    EXPECT_EQ(s.solid_vars[5], 98.97233581542969);
    EXPECT_EQ(s.solid_vars[6], 0.022274183109402657);
    EXPECT_EQ(s.solid_vars[7], 0.16481825709342957);  // NEIPH 1 history value
    EXPECT_EQ(s.solid_vars[56], 230.7303924560547);
    EXPECT_EQ(s.solid_vars[62], 0.03695255517959595);
    EXPECT_NEAR(s.stress[0], 190.72930526733398, 1e-6 * 190.7);
    EXPECT_NEAR(s.eps[0], 0.02022545682848431, 1e-6 * 0.0202);
    // shell 17 (index 0): layer 1 stress and EPS, thickness, internal energy
    ASSERT_EQ(s.shell_vars.size(), 16u * 52u);
    EXPECT_EQ(s.shell_vars[0], -8.985283851623535);
    EXPECT_EQ(s.shell_vars[4], -136.1299285888672);
    EXPECT_EQ(s.shell_vars[6], 0.0031102055218070745);
    EXPECT_EQ(s.shell_vars[r.layout().shell_thickness], 10.0);
    EXPECT_EQ(s.shell_vars[r.layout().shell_internal_energy], 21.137737274169922);
    EXPECT_EQ(g.shell_user_ids[0], 17);
}

// A killed run leaves a partial last state: the complete states are read, the partial one is not.
TEST(LsDynaDatabase, LastStateStopsPartWay) {
    const std::string root = copy_of("d3plot_node_temperature");
    PlotReader full;
    full.open(root);
    ASSERT_EQ(full.num_states(), 23);
    const std::int64_t state_words = 1 + 1 + 2185 * (1 + 3);  // time, NGLBV 1, T + velocity per node
    fs::resize_file(root + "01", 4 * (22 * state_words + state_words / 2));
    PlotReader r;
    r.open(root);
    EXPECT_EQ(r.num_states(), 22);
    EXPECT_EQ(r.time(21), 19.399999618530273);
    EXPECT_EQ(r.state(21).temperature, full.state(21).temperature);
    fs::remove_all(fs::path(root).parent_path());
}

TEST(LsDynaDatabase, RefusedClearly) {
    const std::string root = copy_of("d3plot_beamip");
    put_word(root, 51, 76893465);  // NMMAT as femzip writes it
    std::string msg = open_error(root);
    EXPECT_NE(msg.find(root), std::string::npos) << msg;
    EXPECT_NE(msg.find("femzip"), std::string::npos) << msg;
    put_word(root, 51, 1);
    EXPECT_EQ(open_error(root), "");
    put_word(root, 55, 3);  // NEL48
    msg = open_error(root);
    EXPECT_NE(msg.find("unsupported"), std::string::npos) << msg;
    EXPECT_NE(msg.find("8-node shells (NEL48)"), std::string::npos) << msg;
    put_word(root, 55, 0);
    put_word(root, 30, 27);  // NV1D that is no beam layout
    msg = open_error(root);
    EXPECT_NE(msg.find("NV1D 27"), std::string::npos) << msg;
    fs::remove_all(fs::path(root).parent_path());
}

// The writer writes solids and shells; the families impact3d does not have are refused.
TEST(LsDynaDatabase, WriterRefusesOtherFamilies) {
    PlotGeometry g;
    g.x0 = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    g.num_materials = 1;
    g.tshell_nodes = {0, 1, 2, 3, 0, 1, 2, 3};  // thick shells (beams: written, tests/keyword/test_keyword_beams.cpp)
    g.tshell_material = {1};
    impact3d::PlotWriter w;
    const std::string root = (fs::temp_directory_path() / ("impact3d_shellwrite_" + std::to_string(::getpid()))).string();
    EXPECT_THROW(w.open(root, g), std::invalid_argument);
}

namespace {

// Re-encodes a 4-byte little-endian file word by word: integers and reals widened to 8 bytes
// (int64 / float64) or kept at 4, optionally big-endian; text kept as bytes (the title and
// release words padded with blanks to the wider word, the 72-byte title records unchanged).
enum class Word { Int, Real, Text, WideText };
struct Segment {
    Word type;
    int words;  // 4-byte words in the source; -1: the rest of the file
};

std::vector<char> reencode(const std::vector<char>& in, const std::vector<Segment>& segs, int ws, bool big) {
    std::vector<char> out;
    std::size_t pos = 0;
    auto put = [&](const char* p, int n) {
        if (big) for (int k = n - 1; k >= 0; --k) out.push_back(p[k]);
        else out.insert(out.end(), p, p + n);
    };
    for (const Segment& s : segs) {
        const int n = s.words < 0 ? static_cast<int>((in.size() - pos) / 4) : s.words;
        if (s.type == Word::Text || s.type == Word::WideText) {
            out.insert(out.end(), in.begin() + static_cast<std::ptrdiff_t>(pos), in.begin() + static_cast<std::ptrdiff_t>(pos + 4 * n));
            if (s.type == Word::WideText) out.insert(out.end(), static_cast<std::size_t>(n * (ws - 4)), ' ');
            pos += 4 * static_cast<std::size_t>(n);
            continue;
        }
        for (int k = 0; k < n; ++k, pos += 4) {
            if (s.type == Word::Int) {
                std::int32_t v;
                std::memcpy(&v, &in[pos], 4);
                const std::int64_t w = v;
                if (ws == 4) put(reinterpret_cast<const char*>(&v), 4);
                else put(reinterpret_cast<const char*>(&w), 8);
            } else {
                float v;
                std::memcpy(&v, &in[pos], 4);
                const double w = v;
                if (ws == 4) put(reinterpret_cast<const char*>(&v), 4);
                else put(reinterpret_cast<const char*>(&w), 8);
            }
        }
    }
    return out;
}

std::vector<char> slurp(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

void spit(const std::string& path, const std::vector<char>& d) {
    std::ofstream f(path, std::ios::binary);
    f.write(d.data(), static_cast<std::streamsize>(d.size()));
}

}  // namespace

// The beam database re-encoded with 8-byte words and/or big-endian reads the same values.  (At
// development time VTK 9.1 read the 8-byte big-endian re-encoding too: 2 steps, AxialForce
// 4.797982323945238e-12 at step 1, the same as from the original.)
TEST(LsDynaDatabase, EightByteWordsAndByteSwappedFilesReadTheSame) {
    // d3plot_beamip's root: control words, 2 nodes, 1 beam, NARBS 16, marker, 90001 (1 part,
    // its title), 90000 (model title), marker, padding; d3plot01: 2 states of reals, marker, padding
    const std::vector<Segment> root = {{Word::WideText, 10}, {Word::Int, 3}, {Word::WideText, 1}, {Word::Real, 1},
                                       {Word::Int, 49},      {Word::Real, 6}, {Word::Int, 6},      {Word::Int, 16},
                                       {Word::Real, 1},      {Word::Int, 3},  {Word::Text, 18},    {Word::Int, 1},
                                       {Word::Text, 18},     {Word::Real, 1}, {Word::Int, -1}};
    const std::vector<Segment> states = {{Word::Real, -1}};
    const std::string src = fs::path(data("d3plot_beamip")).parent_path().string();
    PlotReader ref;
    ref.open(data("d3plot_beamip"));
    for (const auto& [ws, big] : {std::pair{8, false}, std::pair{8, true}, std::pair{4, true}}) {
        const fs::path dir = fs::temp_directory_path() / ("impact3d_ws_" + std::to_string(ws) + (big ? "b_" : "l_") + std::to_string(::getpid()));
        fs::remove_all(dir);
        fs::create_directories(dir);
        spit((dir / "d3plot").string(), reencode(slurp(src + "/d3plot"), root, ws, big));
        spit((dir / "d3plot01").string(), reencode(slurp(src + "/d3plot01"), states, ws, big));
        PlotReader r;
        ASSERT_NO_THROW(r.open((dir / "d3plot").string())) << ws << " " << big;
        EXPECT_EQ(r.control().word_size, ws);
        EXPECT_EQ(r.control().byte_swapped, big);
        EXPECT_EQ(r.geometry().x0, ref.geometry().x0);
        EXPECT_EQ(r.geometry().beam_nodes, ref.geometry().beam_nodes);
        EXPECT_EQ(r.geometry().part_titles, ref.geometry().part_titles);
        EXPECT_EQ(r.geometry().node_user_ids, ref.geometry().node_user_ids);
        ASSERT_EQ(r.num_states(), 2);
        const PlotState a = r.state(1), b = ref.state(1);
        EXPECT_EQ(a.time, b.time);
        EXPECT_EQ(a.coords, b.coords);
        EXPECT_EQ(a.beam_vars, b.beam_vars);
        EXPECT_EQ(a.beam_alive, b.beam_alive);
        EXPECT_EQ(a.beam_vars[0], 4.797982323945238e-12);  // VTK's AxialForce
        fs::remove_all(dir);
    }
}

// NDIM 5 (what LS-DYNA writes when parts are rigid): the material-type section after the control
// words, and no state data for the shells of rigid parts (type 20).  Made from d3plot_solid_int
// by declaring part 3 (shell_mat_1) rigid: the section inserted, NDIM 5, and those shells'
// records cut out of every state.  The rigid shells read as zeros, all else as before.
TEST(LsDynaDatabase, RigidShellsOfNdim5HaveNoStateData) {
    const std::string src = fs::path(data("d3plot_solid_int")).parent_path().string();
    PlotReader ref;
    ref.open(src + "/d3plot");
    const auto& g = ref.geometry();
    std::vector<int> rigid;  // shells of part 3
    for (int e = 0; e < g.num_shells(); ++e)
        if (g.shell_material[static_cast<std::size_t>(e)] == 3) rigid.push_back(e);
    ASSERT_FALSE(rigid.empty());
    const fs::path dir = fs::temp_directory_path() / ("impact3d_ndim5_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
        std::vector<char> root = slurp(src + "/d3plot");
        const std::int32_t ndim = 5;
        std::memcpy(&root[4 * 15], &ndim, 4);
        // after the 64 + EXTRA 64 control words: NUMRBE, NMMAT, the 4 material types
        const std::int32_t section[6] = {static_cast<std::int32_t>(rigid.size()), 4, 3, 3, 20, 3};
        root.insert(root.begin() + 4 * 128, reinterpret_cast<const char*>(section), reinterpret_cast<const char*>(section) + 24);
        spit((dir / "d3plot").string(), root);
    }
    const int state_words = 2983, shell_at = 1 + 34 + 106 * 10 + 16 * 64, nv2d = 52;
    for (int m = 1; m <= 22; ++m) {
        char name[16];
        std::snprintf(name, sizeof name, "d3plot%02d", m);
        const std::vector<char> in = slurp(src + "/" + name);
        std::vector<char> out;
        for (int w = 0; w < state_words; ++w) {
            const int shell = (w - shell_at) / nv2d;
            const bool cut = w >= shell_at && w < shell_at + 16 * nv2d &&
                             std::find(rigid.begin(), rigid.end(), shell) != rigid.end();
            if (!cut) out.insert(out.end(), in.begin() + 4 * w, in.begin() + 4 * w + 4);
        }
        out.insert(out.end(), in.begin() + 4 * state_words, in.end());  // marker, padding
        spit((dir / name).string(), out);
    }
    PlotReader r;
    r.open((dir / "d3plot").string());
    EXPECT_EQ(r.control().ndim, 5);
    EXPECT_EQ(r.geometry().part_types, (std::vector<int>{3, 3, 20, 3}));
    ASSERT_EQ(r.num_states(), 22);
    const PlotState a = r.state(21), b = ref.state(21);
    for (int e = 0; e < 16; ++e) {
        const bool is_rigid = std::find(rigid.begin(), rigid.end(), e) != rigid.end();
        for (int k = 0; k < nv2d; ++k)
            EXPECT_EQ(a.shell_vars[static_cast<std::size_t>(nv2d * e + k)],
                      is_rigid ? 0.0 : b.shell_vars[static_cast<std::size_t>(nv2d * e + k)]) << e << " " << k;
    }
    EXPECT_EQ(a.solid_vars, b.solid_vars);
    EXPECT_EQ(a.shell_alive, b.shell_alive);
    EXPECT_EQ(a.coords, b.coords);
    fs::remove_all(dir);
}
