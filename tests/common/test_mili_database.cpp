// The Mili reader (common/mili_database) on databases of our own making (tests/support/
// mili_writer.h): both directory versions, both byte orders, file versions 2 (state maps in
// the A file) and 3 (T file), two state files; read back exactly.  Corrupt and truncated
// databases give clear errors, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <unistd.h>

#include "common/mili_database.h"
#include "tests/support/mili_writer.h"

namespace {

namespace fs = std::filesystem;
using impact3d::MiliReader;
using impact3d::PlotGeometry;
using impact3d::PlotState;

// A folder of this process (in memory where /dev/shm exists: the corruption test writes the
// A file thousands of times), removed at exit.
const fs::path& scratch_root() {
    static const struct Root {
        fs::path p;
        Root() {
            std::error_code ec;
            const fs::path base = fs::is_directory("/dev/shm", ec) ? fs::path("/dev/shm") : fs::temp_directory_path();
            p = base / ("impact3d_mili_" + std::to_string(::getpid()));
        }
        ~Root() {
            std::error_code ec;
            fs::remove_all(p, ec);
        }
    } root;
    return root.p;
}

fs::path scratch(const std::string& name) {
    const fs::path d = scratch_root() / name;
    fs::remove_all(d);
    fs::create_directories(d);
    return d;
}

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}
void spit(const fs::path& p, const std::string& s) {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f.write(s.data(), static_cast<std::streamsize>(s.size()));
}

struct Written {
    std::string base;
    PlotGeometry g;
    std::vector<PlotState> states;
};

Written write(const std::string& name, mili_test::Options o, int nstates = 3) {
    Written w;
    w.base = (scratch(name) / "db.plt").string();
    mili_test::sample_model(w.g, w.states, nstates);
    mili_test::Writer(o).write(w.base, w.g, w.states);
    return w;
}

void expect_same_state(const PlotState& a, const PlotState& b) {
    EXPECT_EQ(a.time, b.time);
    EXPECT_EQ(a.kinetic_energy, b.kinetic_energy);
    EXPECT_EQ(a.internal_energy, b.internal_energy);
    EXPECT_EQ(a.total_energy, b.total_energy);
    EXPECT_EQ(a.velocity, b.velocity);
    EXPECT_EQ(a.coords, b.coords);
    EXPECT_EQ(a.vel, b.vel);  // double precision in the file
    EXPECT_EQ(a.acc, b.acc);
    EXPECT_EQ(a.stress, b.stress);
    EXPECT_EQ(a.eps, b.eps);
    EXPECT_EQ(a.alive, b.alive);
    EXPECT_EQ(a.beam_vars, b.beam_vars);
    EXPECT_EQ(a.beam_alive, b.beam_alive);
    EXPECT_EQ(a.shell_vars, b.shell_vars);
    EXPECT_EQ(a.shell_alive, b.shell_alive);
    EXPECT_EQ(a.mat_internal_energy, b.mat_internal_energy);
    EXPECT_EQ(a.mat_kinetic_energy, b.mat_kinetic_energy);
}

class MiliRoundTrip : public ::testing::TestWithParam<std::tuple<int, int, bool>> {};

TEST_P(MiliRoundTrip, ReadsBackExactly) {
    mili_test::Options o;
    std::tie(o.file_version, o.dir_version, o.big_endian) = GetParam();
    const Written w = write("rt_" + std::to_string(o.file_version) + std::to_string(o.dir_version) +
                                (o.big_endian ? "b" : "l"), o);
    MiliReader r;
    r.open(w.base + "A");
    EXPECT_EQ(r.file_version(), o.file_version);
    EXPECT_EQ(r.directory_version(), o.dir_version);
    EXPECT_EQ(r.big_endian(), o.big_endian);
    EXPECT_EQ(fs::exists(w.base + "T"), o.file_version == 3);
    ASSERT_EQ(r.state_files().size(), 2u);  // 2 states per file: 00 and 01
    const PlotGeometry& g = r.geometry();
    EXPECT_EQ(g.title, w.g.title);
    EXPECT_EQ(g.num_materials, 3);
    EXPECT_EQ(g.part_titles, w.g.part_titles);
    EXPECT_EQ(g.x0, w.g.x0);
    EXPECT_EQ(g.node_user_ids, w.g.node_user_ids);
    EXPECT_EQ(g.hex_nodes, w.g.hex_nodes);
    EXPECT_EQ(g.hex_material, w.g.hex_material);
    EXPECT_EQ(g.hex_user_ids, w.g.hex_user_ids);
    EXPECT_EQ(g.beam_nodes, w.g.beam_nodes);
    EXPECT_EQ(g.beam_material, w.g.beam_material);
    EXPECT_EQ(g.beam_user_ids, w.g.beam_user_ids);
    EXPECT_EQ(g.shell_nodes, w.g.shell_nodes);  // the contact-segment class is left out
    EXPECT_EQ(g.shell_material, w.g.shell_material);
    EXPECT_EQ(g.shell_user_ids, w.g.shell_user_ids);
    ASSERT_EQ(r.skipped_classes().size(), 1u);
    EXPECT_EQ(r.skipped_classes()[0], "cseg (Contact Segment)");
    ASSERT_EQ(r.num_states(), 3);
    for (int k = 0; k < 3; ++k) {
        SCOPED_TRACE(k);
        EXPECT_EQ(r.time(k), w.states[static_cast<std::size_t>(k)].time);
        expect_same_state(r.state(k), w.states[static_cast<std::size_t>(k)]);
    }
}

INSTANTIATE_TEST_SUITE_P(VersionsAndByteOrders, MiliRoundTrip,
                         ::testing::Combine(::testing::Values(2, 3), ::testing::Values(2, 3), ::testing::Bool()));

TEST(MiliReader, RawResultsByClass) {
    const Written w = write("raw", mili_test::Options{});
    MiliReader r;
    r.open(w.base);  // the base name finds NAMEA
    const int shell = r.find_class("shell"), node = r.find_class("node"), beam = r.find_class("beam");
    ASSERT_GE(shell, 0);
    ASSERT_GE(node, 0);
    ASSERT_GE(beam, 0);
    EXPECT_EQ(r.classes()[static_cast<std::size_t>(beam)].count, 3);
    std::vector<double> v;
    // inner-surface sx of both shells at state 2 = shell word 7
    ASSERT_TRUE(r.result(2, shell, "sx", v, "stress_in"));
    ASSERT_EQ(v.size(), 2u);
    for (int e = 0; e < 2; ++e)
        EXPECT_EQ(v[static_cast<std::size_t>(e)], w.states[2].shell_vars[static_cast<std::size_t>(45 * e + 7)]);
    // outer-surface strain exy = point 2 of the element-set array es_3c
    EXPECT_EQ(r.points(shell, "exy"), 2);
    ASSERT_TRUE(r.result(1, shell, "exy", v, "es_3c", 1));
    EXPECT_EQ(v[1], w.states[1].shell_vars[45 + 39 + 3]);
    // node velocities are double precision in the file
    ASSERT_TRUE(r.result(2, node, "vz", v));
    for (int n = 0; n < 12; ++n) EXPECT_EQ(v[static_cast<std::size_t>(n)], w.states[2].vel[static_cast<std::size_t>(3 * n + 2)]);
    EXPECT_FALSE(r.result(0, node, "no_such_variable", v));
    EXPECT_TRUE(std::isnan(v[0]));
    // beams in two subrecords: torsion of the last one
    ASSERT_TRUE(r.result(1, beam, "tor", v));
    EXPECT_EQ(v[2], w.states[1].beam_vars[2 * 6 + 5]);
    EXPECT_EQ(r.param_string("title"), "mili test model");
}

// DYNA3D writes a beam's integration-point stresses (element set es_1a) in the global axes
// (d3samp6: a column along z shows its axial stress in sz) and the beam's s axis as svec.  The
// reader turns each point into the beam's axes (r from the state's node positions, s = svec
// projected normal to r, t = r x s) and lays it out as a d3plot point block in LS-DYNA's order:
// shear rs, shear tr, axial stress, plastic strain, axial strain (0).
TEST(MiliReader, BeamPointStressesTurnIntoTheBeamsAxes) {
    mili_test::Options o;
    o.beam_points = 2;
    Written w;
    w.base = (scratch("beam_points") / "db.plt").string();
    mili_test::sample_model(w.g, w.states, 3);
    const double g_dir[3] = {0.0, 0.6, 0.8};
    auto axes = [&](const PlotState& s, int b, double r[3], double sa[3], double ta[3]) {
        const int n1 = w.g.beam_nodes[static_cast<std::size_t>(2 * b)], n2 = w.g.beam_nodes[static_cast<std::size_t>(2 * b + 1)];
        double len = 0, c = 0, n = 0;
        for (int a = 0; a < 3; ++a) {
            r[a] = s.coords[static_cast<std::size_t>(3 * n2 + a)] - s.coords[static_cast<std::size_t>(3 * n1 + a)];
            len += r[a] * r[a];
        }
        for (int a = 0; a < 3; ++a) {
            r[a] /= std::sqrt(len);
            c += r[a] * g_dir[a];
        }
        for (int a = 0; a < 3; ++a) {
            sa[a] = g_dir[a] - c * r[a];
            n += sa[a] * sa[a];
        }
        for (int a = 0; a < 3; ++a) sa[a] /= std::sqrt(n);
        ta[0] = r[1] * sa[2] - r[2] * sa[1];
        ta[1] = r[2] * sa[0] - r[0] * sa[2];
        ta[2] = r[0] * sa[1] - r[1] * sa[0];
    };
    // local values of beam b, point p, state k
    auto local = [](int k, int b, int p, double v[4]) {
        v[0] = 7.0 + b - p;          // shear rs
        v[1] = -3.0 - k + 0.5 * p;   // shear tr
        v[2] = 100.0 + 10 * b + k - 50 * p;  // axial
        v[3] = 0.125 * (k + p);      // plastic strain
    };
    for (std::size_t k = 0; k < w.states.size(); ++k) {
        PlotState& s = w.states[k];
        for (int b = 0; b < 3; ++b) {
            double r[3], sa[3], ta[3];
            axes(s, b, r, sa, ta);
            for (int p = 0; p < 2; ++p) {
                double v[4];
                local(static_cast<int>(k), b, p, v);
                double m[3][3];
                for (int i = 0; i < 3; ++i)
                    for (int j = 0; j < 3; ++j)
                        m[i][j] = v[2] * r[i] * r[j] + v[0] * (r[i] * sa[j] + sa[i] * r[j]) + v[1] * (ta[i] * r[j] + r[i] * ta[j]);
                s.beam_vars.insert(s.beam_vars.end(), {m[0][0], m[1][1], m[2][2], m[0][1], m[1][2], m[2][0], v[3]});
            }
            s.beam_vars.insert(s.beam_vars.end(), g_dir, g_dir + 3);
        }
    }
    mili_test::Writer(o).write(w.base, w.g, w.states);
    MiliReader rd;
    rd.open(w.base + "A");
    EXPECT_EQ(rd.layout().beam_points, 2);
    for (int k = 0; k < 3; ++k) {
        SCOPED_TRACE(k);
        const PlotState st = rd.state(k);
        ASSERT_EQ(st.beam_vars.size(), 3u * (6 + 5 * 2));
        for (int b = 0; b < 3; ++b) {
            const double* rec = &st.beam_vars[static_cast<std::size_t>(16 * b)];
            for (int j = 0; j < 6; ++j) EXPECT_EQ(rec[j], w.states[static_cast<std::size_t>(k)].beam_vars[static_cast<std::size_t>(6 * b + j)]);
            for (int p = 0; p < 2; ++p) {
                double v[4];
                local(k, b, p, v);
                const double* q = rec + 6 + 5 * p;
                for (int j = 0; j < 3; ++j) EXPECT_NEAR(q[j], v[j], 1e-4) << "beam " << b << " point " << p << " word " << j;
                EXPECT_EQ(q[3], v[3]);
                EXPECT_EQ(q[4], 0.0);
            }
        }
    }
}

TEST(MiliReader, IsMiliFileByContent) {
    const Written w = write("magic", mili_test::Options{});
    EXPECT_TRUE(MiliReader::is_mili_file(w.base + "A"));
    EXPECT_FALSE(MiliReader::is_mili_file(w.base + "00"));
    EXPECT_FALSE(MiliReader::is_mili_file(w.base + "none"));
}

// The message of the runtime_error open() throws ("" if none).
std::string open_error(const std::string& path) {
    try {
        MiliReader r;
        r.open(path);
        for (int k = 0; k < r.num_states(); ++k) r.state(k);
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return "";
}

TEST(MiliReader, ClearErrors) {
    const Written w = write("errors", mili_test::Options{});
    const std::string a = slurp(w.base + "A");
    // not a Mili file
    spit(w.base + "A", "taur" + a.substr(4));
    EXPECT_NE(open_error(w.base + "A").find("not a Mili A file"), std::string::npos);
    // footer counting more directory entries than the file holds
    std::string bad = a;
    bad[bad.size() - 5] = '\x7f';
    spit(w.base + "A", bad);
    EXPECT_NE(open_error(w.base + "A").find("directory entries"), std::string::npos);
    // too short
    spit(w.base + "A", a.substr(0, 20));
    EXPECT_NE(open_error(w.base + "A").find("header"), std::string::npos);
    spit(w.base + "A", a);
    EXPECT_EQ(open_error(w.base + "A"), "");
    // the last state cut short: named with its file, offset and size
    const std::string s1 = slurp(w.base + "01");
    spit(w.base + "01", s1.substr(0, s1.size() - 4));
    const std::string e = open_error(w.base + "A");
    EXPECT_NE(e.find("db.plt01"), std::string::npos) << e;
    EXPECT_NE(e.find("state 3"), std::string::npos) << e;
    // a state file missing
    fs::remove(w.base + "01");
    EXPECT_NE(open_error(w.base + "A").find("state file missing"), std::string::npos);
}

// Every single-byte change and every truncation of the A file either reads or throws a
// runtime_error: no crash, no other exception (the fuzz target goes further).
TEST(MiliReader, CorruptAFileNeverCrashes) {
    for (int dv : {2, 3}) {
        mili_test::Options o;
        o.dir_version = dv;
        const Written w = write("corrupt" + std::to_string(dv), o, 2);
        const std::string a = slurp(w.base + "A");
        int refused = 0;
        for (std::size_t k = 0; k < a.size(); ++k) {
            for (char x : {'\xff', '\x40'}) {
                std::string b = a;
                b[k] = static_cast<char>(b[k] ^ x);
                spit(w.base + "A", b);
                refused += !open_error(w.base + "A").empty();
            }
            if (k % 7 == 0) {
                spit(w.base + "A", a.substr(0, k));
                refused += !open_error(w.base + "A").empty();
            }
        }
        EXPECT_GT(refused, static_cast<int>(a.size()) / 2);
    }
}

}  // namespace

namespace {

// The fuzz target's seeds (fuzz/seeds/mili_database/) are this writer's databases: A file,
// state files 00 and 01, T file, cut at "$$FUZZ-FILE$$" lines.  IMPACT3D_UPDATE_SEEDS=1
// rewrites them.
TEST(MiliReader, FuzzSeedsAreTheTestWritersDatabases) {
    struct Seed { const char* name; int fv, dv; bool big; };
    for (const Seed& s : {Seed{"v2_dir2_little", 2, 2, false}, Seed{"v3_dir3_big", 3, 3, true},
                          Seed{"v2_dir3_big", 2, 3, true}}) {
        mili_test::Options o;
        o.file_version = s.fv;
        o.dir_version = s.dv;
        o.big_endian = s.big;
        const Written w = write(std::string("seed_") + s.name, o, 3);
        std::string seed = slurp(w.base + "A");
        for (const char* part : {"00", "01", "T"})
            if (fs::exists(w.base + part)) seed += "$$FUZZ-FILE$$\n" + slurp(w.base + part);
        const fs::path stored = fs::path(IMPACT3D_SOURCE_DIR) / "fuzz/seeds/mili_database" / s.name;
        const char* update = std::getenv("IMPACT3D_UPDATE_SEEDS");
        if (update && std::string(update) == "1") {
            fs::create_directories(stored.parent_path());
            spit(stored, seed);
        }
        EXPECT_EQ(slurp(stored), seed) << stored << " differs from the writer's database (IMPACT3D_UPDATE_SEEDS=1)";
    }
}

}  // namespace
