// Tests of the d3plot family writer/reader (common/plot_database.*).
#include "common/plot_database.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <csignal>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;
using impact3d::PlotGeometry;
using impact3d::PlotReader;
using impact3d::PlotState;
using impact3d::PlotWriter;

namespace {

// 12 nodes on a 3x2x2 grid, 2 hexes in 2 materials (same model as shared/tools/write_tiny_d3plot.py).
PlotGeometry tiny_geometry() {
    PlotGeometry g;
    g.title = "tiny impact3d plot test";
    g.num_materials = 2;
    auto nid = [](int i, int j, int k) { return i + 3 * j + 6 * k; };  // 0-based
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 3; ++i) {
                g.x0.push_back(i);
                g.x0.push_back(j);
                g.x0.push_back(k);
            }
    for (int e = 0; e < 2; ++e) {
        const int n[8] = {nid(e, 0, 0), nid(e + 1, 0, 0), nid(e + 1, 1, 0), nid(e, 1, 0),
                          nid(e, 0, 1), nid(e + 1, 0, 1), nid(e + 1, 1, 1), nid(e, 1, 1)};
        g.hex_nodes.insert(g.hex_nodes.end(), n, n + 8);
        g.hex_material.push_back(e + 1);
        g.hex_user_ids.push_back(1001 + e);
    }
    for (int n = 0; n < 12; ++n) g.node_user_ids.push_back(101 + n);
    g.part_titles = {"steel block", "aluminium block"};
    g.part_user_ids = {10, 20};
    return g;
}

// Synthetic but non-trivial values (not exactly representable in float, so the 4-byte test
// really checks rounding).
PlotState tiny_state(int s, const PlotGeometry& g, bool last = false) {
    PlotState st;
    const double t = s * 1.0e-3 + 1.0e-7;
    const double a = 50.3;
    st.time = t;
    st.kinetic_energy = 0.5 * s + 0.1;
    st.internal_energy = 1.0 * s + 0.2;
    st.total_energy = st.kinetic_energy + st.internal_energy;
    st.velocity = {1.1 * s, -2.2 * s, 3.3};
    const int nm = g.num_materials;
    for (int p = 0; p < nm; ++p) {
        st.mat_internal_energy.push_back(0.3 * s + p);
        st.mat_kinetic_energy.push_back(0.7 * s + p);
        for (int k = 0; k < 3; ++k) st.mat_velocity.push_back(0.11 * s * (k + 1) + p);
        st.mat_mass.push_back(7.85e-3 * (p + 1));
        st.mat_hourglass_energy.push_back(1.0e-4 * s * (p + 1));
    }
    const int nn = g.num_nodes();
    for (int n = 0; n < nn; ++n) {
        const double X = g.x0[3 * n], Y = g.x0[3 * n + 1], Z = g.x0[3 * n + 2];
        st.coords.insert(st.coords.end(), {X * (1 + a * t), Y + 0.01 * t, Z - 0.02 * t});
        st.vel.insert(st.vel.end(), {a * X, 0.01, -0.02 * n});
        st.acc.insert(st.acc.end(), {0.5 * n, -0.25 * s, 1.0 / 3.0});
    }
    for (int e = 0; e < g.num_hexes(); ++e) {
        for (int k = 0; k < 6; ++k) st.stress.push_back((e + 1) * 1000.3 * a * t * (k + 1) - k);
        st.eps.push_back(0.01 * s * (e + 1) + 1.0 / 7.0);
        st.alive.push_back(last && e == 1 ? 0 : 1);
    }
    return st;
}

std::string test_dir(const std::string& name) {
    const fs::path p = fs::path(IMPACT3D_BINARY_DIR) / "test_plot_database" / name;
    fs::remove_all(p);
    fs::create_directories(p);
    return p.string();
}

// Writes a database with n states; returns the root path.
std::string write_db(const std::string& dir, int ws, int nstates,
                     std::int64_t limit = PlotWriter::kDefaultMemberSizeLimitWords) {
    const PlotGeometry g = tiny_geometry();
    PlotWriter w;
    const std::string root = dir + "/d3plot";
    w.open(root, g, ws, limit);
    for (int s = 0; s < nstates; ++s) w.write_state(tiny_state(s, g, s == nstates - 1));
    w.close();
    return root;
}

double round_ws(double v, int ws) { return ws == 4 ? static_cast<double>(static_cast<float>(v)) : v; }

void expect_vec(const std::vector<double>& got, const std::vector<double>& want, int ws, const char* what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t k = 0; k < want.size(); ++k) EXPECT_EQ(got[k], round_ws(want[k], ws)) << what << "[" << k << "]";
}

void expect_state(const PlotState& got, const PlotState& want, int ws) {
    EXPECT_EQ(got.time, round_ws(want.time, ws));
    EXPECT_EQ(got.kinetic_energy, round_ws(want.kinetic_energy, ws));
    EXPECT_EQ(got.internal_energy, round_ws(want.internal_energy, ws));
    EXPECT_EQ(got.total_energy, round_ws(want.total_energy, ws));
    for (int k = 0; k < 3; ++k) EXPECT_EQ(got.velocity[k], round_ws(want.velocity[k], ws));
    expect_vec(got.mat_internal_energy, want.mat_internal_energy, ws, "mat_internal_energy");
    expect_vec(got.mat_kinetic_energy, want.mat_kinetic_energy, ws, "mat_kinetic_energy");
    expect_vec(got.mat_velocity, want.mat_velocity, ws, "mat_velocity");
    expect_vec(got.mat_mass, want.mat_mass, ws, "mat_mass");
    expect_vec(got.mat_hourglass_energy, want.mat_hourglass_energy, ws, "mat_hourglass_energy");
    expect_vec(got.coords, want.coords, ws, "coords");
    expect_vec(got.vel, want.vel, ws, "vel");
    expect_vec(got.acc, want.acc, ws, "acc");
    expect_vec(got.stress, want.stress, ws, "stress");
    expect_vec(got.eps, want.eps, ws, "eps");
    EXPECT_EQ(got.alive, want.alive);
}

void expect_geometry(const PlotGeometry& got, const PlotGeometry& want, int ws) {
    EXPECT_EQ(got.title, want.title);
    EXPECT_EQ(got.num_materials, want.num_materials);
    expect_vec(got.x0, want.x0, ws, "x0");
    EXPECT_EQ(got.node_user_ids, want.node_user_ids);
    EXPECT_EQ(got.hex_nodes, want.hex_nodes);
    EXPECT_EQ(got.hex_material, want.hex_material);
    EXPECT_EQ(got.hex_user_ids, want.hex_user_ids);
    EXPECT_EQ(got.part_titles, want.part_titles);
    EXPECT_EQ(got.part_user_ids, want.part_user_ids);
}

std::vector<char> slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
void spit(const std::string& path, const std::vector<char>& d) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(d.data(), static_cast<std::streamsize>(d.size()));
}

double last_word(const std::string& path, int ws) {
    const auto d = slurp(path);
    if (d.size() < static_cast<std::size_t>(ws)) return 0.0;
    if (ws == 4) {
        float f;
        std::memcpy(&f, d.data() + d.size() - 4, 4);
        return f;
    }
    double v;
    std::memcpy(&v, d.data() + d.size() - 8, 8);
    return v;
}

// Reads everything; returns the number of states.  Lets std::runtime_error through.
int read_all(const std::string& root) {
    PlotReader r;
    r.open(root);
    for (int i = 0; i < r.num_states(); ++i) (void)r.state(i);
    return r.num_states();
}

}  // namespace

// ---------------------------------------------------------------------------------------------

class PlotRoundTrip : public ::testing::TestWithParam<int> {};

TEST_P(PlotRoundTrip, WriteThreeStatesReadBackEqual) {
    const int ws = GetParam();
    const std::string dir = test_dir("roundtrip" + std::to_string(ws));
    const std::string root = write_db(dir, ws, 3);
    const PlotGeometry g = tiny_geometry();

    // Layout: root holds no states and ends with a marker; one state member with 3 states + marker.
    EXPECT_EQ(last_word(root, ws), -999999.0);
    ASSERT_TRUE(fs::exists(dir + "/d3plot01"));
    EXPECT_FALSE(fs::exists(dir + "/d3plot02"));
    const std::int64_t state_words = 1 + (6 + 7 * 2) + 9 * 12 + 8 * 2;
    EXPECT_EQ(static_cast<std::int64_t>(fs::file_size(dir + "/d3plot01")), (3 * state_words + 1) * ws);
    EXPECT_EQ(last_word(dir + "/d3plot01", ws), -999999.0);

    PlotReader r;
    r.open(root);
    EXPECT_EQ(r.control().word_size, ws);
    EXPECT_EQ(r.control().numnp, 12);
    EXPECT_EQ(r.control().nel8, 2);
    EXPECT_EQ(r.control().nglbv, 6 + 7 * 2);
    EXPECT_EQ(r.control().maxint, -10003);
    EXPECT_EQ(r.control().nmmat, 2);
    EXPECT_EQ(r.num_members(), 1);
    expect_geometry(r.geometry(), g, ws);
    ASSERT_EQ(r.num_states(), 3);
    for (int s = 0; s < 3; ++s) {
        SCOPED_TRACE("state " + std::to_string(s));
        EXPECT_EQ(r.time(s), round_ws(tiny_state(s, g).time, ws));
        expect_state(r.state(s), tiny_state(s, g, s == 2), ws);
    }
    EXPECT_THROW((void)r.state(3), std::out_of_range);
}

INSTANTIATE_TEST_SUITE_P(WordSizes, PlotRoundTrip, ::testing::Values(4, 8));

TEST(PlotDatabase, EmptyOptionalVectorsWriteZerosAndInitialCoordinates) {
    const std::string dir = test_dir("defaults");
    const PlotGeometry g = tiny_geometry();
    PlotWriter w;
    w.open(dir + "/d3plot", g, 8);
    PlotState s;
    s.time = 0.5;
    w.write_state(s);
    w.close();
    PlotReader r;
    r.open(dir + "/d3plot");
    ASSERT_EQ(r.num_states(), 1);
    const PlotState got = r.state(0);
    EXPECT_EQ(got.time, 0.5);
    EXPECT_EQ(got.coords, g.x0);
    EXPECT_EQ(got.vel, std::vector<double>(36, 0.0));
    EXPECT_EQ(got.mat_mass, std::vector<double>(2, 0.0));
    EXPECT_EQ(got.alive, std::vector<unsigned char>(2, 1));
}

TEST(PlotDatabase, InvalidInputIsRejected) {
    const std::string dir = test_dir("invalid");
    PlotGeometry g = tiny_geometry();
    PlotWriter w;
    EXPECT_THROW(w.open(dir + "/d3plot", g, 6), std::invalid_argument);
    g.hex_material[1] = 3;  // only 2 materials: VTK would crash on this
    EXPECT_THROW(w.open(dir + "/d3plot", g, 4), std::invalid_argument);
    g = tiny_geometry();
    g.hex_nodes[5] = 12;
    EXPECT_THROW(w.open(dir + "/d3plot", g, 4), std::invalid_argument);
    g = tiny_geometry();
    EXPECT_THROW(w.write_state(tiny_state(0, g)), std::logic_error);
    w.open(dir + "/d3plot", g, 4);
    PlotState s = tiny_state(0, g);
    s.coords.pop_back();
    EXPECT_THROW(w.write_state(s), std::invalid_argument);
    EXPECT_EQ(w.num_states_written(), 0);
}

TEST(PlotDatabase, FamilyRolloverNoStraddlingAllStatesInOrder) {
    for (int ws : {4, 8}) {
        SCOPED_TRACE("word size " + std::to_string(ws));
        const PlotGeometry g = tiny_geometry();
        const std::int64_t sw = 1 + (6 + 7 * 2) + 9 * 12 + 8 * 2;
        struct Case { std::int64_t limit; int per_member; };
        // 2 states + marker fit exactly; 3 states do not.  Limit 1 word: one (oversized) state per member.
        for (const Case c : {Case{2 * sw + 1, 2}, Case{3 * sw, 2}, Case{1, 1}, Case{sw + 1, 1}}) {
            SCOPED_TRACE("limit " + std::to_string(c.limit));
            const std::string dir = test_dir("rollover" + std::to_string(ws));
            const int nstates = 7;
            const std::string root = write_db(dir, ws, nstates, c.limit);
            const int members = (nstates + c.per_member - 1) / c.per_member;
            for (int m = 1; m <= members; ++m) {
                const std::string name = PlotWriter::member_name(root, m);
                ASSERT_TRUE(fs::exists(name)) << name;
                const int k = std::min(c.per_member, nstates - (m - 1) * c.per_member);
                EXPECT_EQ(static_cast<std::int64_t>(fs::file_size(name)), (k * sw + 1) * ws) << name;
                EXPECT_EQ(last_word(name, ws), -999999.0) << name;
            }
            EXPECT_FALSE(fs::exists(PlotWriter::member_name(root, members + 1)));
            for (const auto& e : fs::directory_iterator(dir))
                EXPECT_EQ(e.path().extension(), "") << "left over " << e.path();
            PlotReader r;
            r.open(root);
            EXPECT_EQ(r.num_members(), members);
            ASSERT_EQ(r.num_states(), nstates);
            for (int s = 0; s < nstates; ++s) {
                SCOPED_TRACE("state " + std::to_string(s));
                expect_state(r.state(s), tiny_state(s, g, s == nstates - 1), ws);
            }
        }
    }
}

TEST(PlotDatabase, ReopenRemovesStaleMembersOfEarlierRun) {
    const std::string dir = test_dir("stale");
    write_db(dir, 4, 6, 1);  // d3plot01..06
    spit(dir + "/d3plot07.tmp", {'x'});
    ASSERT_TRUE(fs::exists(dir + "/d3plot06"));
    const std::string root = write_db(dir, 4, 2, 1);
    EXPECT_TRUE(fs::exists(dir + "/d3plot02"));
    EXPECT_FALSE(fs::exists(dir + "/d3plot03"));
    EXPECT_FALSE(fs::exists(dir + "/d3plot06"));
    EXPECT_FALSE(fs::exists(dir + "/d3plot07.tmp"));
    EXPECT_EQ(read_all(root), 2);
}

// A restart appends only to a family written for the same model: a root file with other
// control words, geometry, ids or titles (another deck run in the same folder, or a database
// of an older layout) is refused, and nothing is changed.
TEST(PlotDatabase, ResumeRefusesAFamilyOfAnotherModel) {
    const std::string dir = test_dir("resume_other");
    const std::string root = write_db(dir, 4, 3, 1);
    const auto before = slurp(dir + "/d3plot03");
    PlotGeometry other = tiny_geometry();
    other.num_rigid_walls = 1;  // one more global word per state
    {
        PlotWriter w;
        try {
            w.resume(root, other, 4, 1, 2);
            FAIL() << "resumed a family of another model";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find("does not belong to this model"), std::string::npos) << e.what();
        }
    }
    EXPECT_EQ(slurp(dir + "/d3plot03"), before);  // untouched
    EXPECT_EQ(read_all(root), 3);
    other = tiny_geometry();
    other.title = "another title";
    PlotWriter w2;
    EXPECT_THROW(w2.resume(root, other, 4, 1, 2), std::runtime_error);
    // the same model resumes (the run-time word may differ)
    PlotWriter w3;
    w3.resume(root, tiny_geometry(), 4, 1, 2);
    w3.close();
    EXPECT_EQ(read_all(root), 2);
}

// A run killed in the middle of an append leaves the new state's body after the old end marker
// (the commit word not yet written).  Both this reader and VTK must see only the committed states.
TEST(PlotDatabase, UncommittedAppendIsInvisible) {
    const std::string dir = test_dir("uncommitted");
    const std::string root = write_db(dir, 4, 2);
    auto d = slurp(dir + "/d3plot01");
    const std::size_t state_bytes = (1 + 20 + 108 + 16) * 4;
    for (std::size_t k = 0; k < state_bytes / 2; ++k) d.push_back(static_cast<char>(k * 7 + 1));
    spit(dir + "/d3plot01", d);
    EXPECT_EQ(read_all(root), 2);
}

// The sync interval: with 0 every appended state is fsync'ed twice (body, then the commit word);
// with a long interval only a new member (before its rename) and sync() are, and a process killed
// (SIGKILL, no close) without any sync still leaves every state it wrote readable, with the
// values written: the write order alone makes them readable after the process dies.
TEST(PlotDatabase, SyncIntervalAndKilledWriterKeepsEveryState) {
    const PlotGeometry g = tiny_geometry();
    {
        const std::string dir = test_dir("sync_every");
        PlotWriter w;
        w.open(dir + "/d3plot", g, 4);
        for (int k = 0; k < 4; ++k) w.write_state(tiny_state(k, g));
        EXPECT_EQ(w.num_syncs(), 1 + 2 * 3);  // the first member, then two per append
        w.sync();
        EXPECT_EQ(w.num_syncs(), 7);          // nothing left to make durable
    }
    const std::string dir = test_dir("sync_killed");
    const std::string root = dir + "/d3plot";
    const std::int64_t sw = 1 + 20 + 108 + 16;
    std::fflush(nullptr);
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        PlotWriter w;
        w.set_sync_interval(3600);
        w.open(root, g, 4, 3 * sw + 1);  // three states a member: members 1 and 2
        for (int k = 0; k < 5; ++k) w.write_state(tiny_state(k, g));
        // member 1 (fsync'ed at its start), its two appends not, then member 2's start: the
        // member before it synced first, then the new one
        if (w.num_syncs() != 3) _exit(5);
        w.write_state(tiny_state(5, g));
        if (w.num_syncs() != 3) _exit(6);
        std::raise(SIGKILL);
        _exit(7);
    }
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status)) << "child exit " << WEXITSTATUS(status);
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
    PlotReader r;
    r.open(root);
    ASSERT_EQ(r.num_states(), 6);
    for (int k = 0; k < 6; ++k) {
        const PlotState got = r.state(k), want = tiny_state(k, g);
        EXPECT_EQ(float(got.time), float(want.time)) << k;
        ASSERT_EQ(got.coords.size(), want.coords.size());
        for (std::size_t i = 0; i < want.coords.size(); ++i)
            EXPECT_EQ(float(got.coords[i]), float(want.coords[i])) << k << " " << i;
    }
}

TEST(PlotDatabase, TruncatedLastMemberAtEveryLength) {
    for (int ws : {4, 8}) {
        for (int two_members : {0, 1}) {
            SCOPED_TRACE("ws " + std::to_string(ws) + " two members " + std::to_string(two_members));
            const std::string dir = test_dir("trunc" + std::to_string(ws));
            const PlotGeometry g = tiny_geometry();
            const std::int64_t sw = 1 + 20 + 108 + 16;
            // one member with 3 states, or member 1 with 3 states and member 2 with 2
            const int nstates = two_members ? 5 : 3;
            const std::string root = write_db(dir, ws, nstates, two_members ? 3 * sw + 1 : 100 * sw);
            const int first_in_last = two_members ? 3 : 0;
            const std::string last = PlotWriter::member_name(root, two_members ? 2 : 1);
            ASSERT_TRUE(fs::exists(last));
            ASSERT_FALSE(fs::exists(PlotWriter::member_name(root, two_members ? 3 : 2)));
            const auto full = fs::file_size(last);
            std::vector<PlotState> want;
            for (int s = 0; s < nstates; ++s) want.push_back(tiny_state(s, g, s == nstates - 1));
            int errors = 0;
            for (std::int64_t len = static_cast<std::int64_t>(full); len >= 0; --len) {
                fs::resize_file(last, static_cast<std::uintmax_t>(len));
                try {
                    PlotReader r;
                    r.open(root);
                    const int complete =
                        static_cast<int>(std::min<std::int64_t>(nstates - first_in_last, len / (sw * ws)));
                    ASSERT_EQ(r.num_states(), first_in_last + complete) << "length " << len;
                    for (int s = 0; s < r.num_states(); ++s) {
                        const PlotState st = r.state(s);
                        ASSERT_EQ(st.time, round_ws(want[s].time, ws));
                        ASSERT_EQ(st.stress, [&] {
                            std::vector<double> v;
                            for (double x : want[s].stress) v.push_back(round_ws(x, ws));
                            return v;
                        }());
                        ASSERT_EQ(st.alive, want[s].alive);
                    }
                } catch (const std::runtime_error& e) {
                    ++errors;
                    EXPECT_NE(std::string(e.what()).find("d3plot"), std::string::npos) << e.what();
                }
            }
            EXPECT_EQ(errors, 0) << "a truncated last member should just lose its incomplete state";
        }
    }
}

TEST(PlotDatabase, TruncatedRootFileGivesClearError) {
    for (int ws : {4, 8}) {
        SCOPED_TRACE("ws " + std::to_string(ws));
        const std::string dir = test_dir("trunc_root" + std::to_string(ws));
        const std::string root = write_db(dir, ws, 3);
        const auto full = slurp(root);
        // control words, coordinates, connectivity, NARBS section
        const std::size_t static_end = static_cast<std::size_t>((64 + 36 + 18 + (16 + 12 + 2 + 6)) * ws);
        ASSERT_LT(static_end, full.size());
        for (std::size_t len = 0; len < full.size(); ++len) {
            spit(root, std::vector<char>(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(len)));
            try {
                PlotReader r;
                r.open(root);
                EXPECT_GE(len, static_end) << "a root file without complete geometry was accepted";
                EXPECT_EQ(r.geometry().num_nodes(), 12);
                EXPECT_EQ(r.num_states(), 3);
            } catch (const std::runtime_error& e) {
                const std::string msg = e.what();
                EXPECT_NE(msg.find(root), std::string::npos) << msg;
                EXPECT_NE(msg.find("byte offset"), std::string::npos) << msg;
                if (len == 100) std::printf("  e.g. root truncated to 100 bytes: %s\n", msg.c_str());
            }
        }
        fs::remove(root);
        try {
            PlotReader r;
            r.open(root);
            ADD_FAILURE() << "missing root file accepted";
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(root), std::string::npos) << e.what();
        }
    }
}

TEST(PlotDatabase, RandomCorruptionNeverCrashes) {
    std::mt19937 rng(12345);
    for (int ws : {4, 8}) {
        const std::string dir = test_dir("corrupt" + std::to_string(ws));
        const std::string root = write_db(dir, ws, 4, 2 * (1 + 20 + 108 + 16) + 1);
        const auto orig_root = slurp(root);
        const auto orig_m1 = slurp(dir + "/d3plot01");
        int ok = 0, err = 0;
        for (int it = 0; it < 3000; ++it) {
            auto d = orig_root;
            auto m1 = orig_m1;
            const int mode = it % 3;  // 0: control words, 1: anywhere in root, 2: state member
            const int nflip = 1 + static_cast<int>(rng() % 4);
            for (int k = 0; k < nflip; ++k) {
                if (mode == 0) d[rng() % (64 * ws)] = static_cast<char>(rng());
                else if (mode == 1) d[rng() % d.size()] = static_cast<char>(rng());
                else m1[rng() % m1.size()] = static_cast<char>(rng());
            }
            spit(root, d);
            spit(dir + "/d3plot01", m1);
            try {
                read_all(root);
                ++ok;
            } catch (const std::runtime_error&) {
                ++err;
            }
        }
        std::printf("  ws %d: %d corrupt databases read, %d refused with an error\n", ws, ok, err);
        EXPECT_GT(err, 0);
        EXPECT_GT(ok, 0);
    }
}

// Issue 25 defect 9: a header count is untrusted.  Every count word of the 64 control words
// (and EXTRA) set to 0, -1, 2^31 - 1, 2^31 and 2^63 - 1 (the low 4 bytes of these in a 4-byte
// file) reads or is refused with an error, never past what the family holds; NEIPS = 2^31 - 1
// (which overflowed the layer word count, 7 + NEIPS, in 32 bits) is refused by name.  Run under
// UndefinedBehaviorSanitizer (tools/fuzz.sh builds) this also checks that no sum overflows.
TEST(PlotDatabase, ExtremeHeaderCountsAreRefusedBeforeUse) {
    const std::int64_t extremes[] = {0, -1, 2147483647LL, 2147483648LL, 9223372036854775807LL};
    const int count_words[] = {16, 18, 23, 24, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 39, 40, 41, 42, 51, 57, 63};
    for (int ws : {4, 8}) {
        const std::string dir = test_dir("extreme" + std::to_string(ws));
        const std::string root = write_db(dir, ws, 2);
        const auto orig = slurp(root);
        int read = 0, refused = 0;
        for (int k : count_words)
            for (std::int64_t v : extremes) {
                auto d = orig;
                if (ws == 4) {
                    const auto v32 = static_cast<std::uint32_t>(static_cast<std::uint64_t>(v));
                    std::memcpy(d.data() + 4 * k, &v32, 4);
                } else {
                    std::memcpy(d.data() + 8 * k, &v, 8);
                }
                spit(root, d);
                try {
                    read_all(root);
                    ++read;
                } catch (const std::runtime_error& e) {
                    ++refused;
                    EXPECT_NE(std::string(e.what()).find(root), std::string::npos) << e.what();
                }
            }
        std::printf("  ws %d: %d extreme headers read, %d refused\n", ws, read, refused);
        EXPECT_GT(refused, 0);
        // NEIPS (word 35) = 2^31 - 1: refused by name, before the layout is formed
        auto d = orig;
        const std::int64_t big = 2147483647LL;
        if (ws == 4) {
            const auto v32 = static_cast<std::int32_t>(big);
            std::memcpy(d.data() + 4 * 35, &v32, 4);
        } else {
            std::memcpy(d.data() + 8 * 35, &big, 8);
        }
        spit(root, d);
        try {
            read_all(root);
            ADD_FAILURE() << "NEIPS = 2^31 - 1 accepted";
        } catch (const std::runtime_error& e) {
            const std::string msg = e.what();
            EXPECT_NE(msg.find("NEIPS = 2147483647"), std::string::npos) << msg;
            EXPECT_NE(msg.find("the family holds"), std::string::npos) << msg;
        }
    }
}

// Write errors: EFBIG from RLIMIT_FSIZE (in a child process, so the limit cannot hit the test log)
// must throw std::runtime_error naming the file, and leave the earlier states readable.
TEST(PlotDatabase, WriteErrorThrowsAndKeepsEarlierStates) {
    for (int per_member : {100, 1}) {
        SCOPED_TRACE("states per member " + std::to_string(per_member));
        const std::string dir = test_dir("write_error");
        const std::string root = dir + "/d3plot";
        const std::int64_t sw = 1 + 20 + 108 + 16;
        std::fflush(nullptr);
        const pid_t pid = fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            int rc = 0;
            try {
                const PlotGeometry g = tiny_geometry();
                PlotWriter w;
                w.open(root, g, 4, per_member == 1 ? 1 : 100 * sw);
                w.write_state(tiny_state(0, g));
                w.write_state(tiny_state(1, g));
                std::signal(SIGXFSZ, SIG_IGN);
                rlimit lim{};
                getrlimit(RLIMIT_FSIZE, &lim);
                // per_member 100: d3plot01 already exceeds the limit; 1: a new member cannot hold a state
                lim.rlim_cur = static_cast<rlim_t>(per_member == 1 ? sw * 4 / 2 : sw * 4 * 3 / 2);
                if (setrlimit(RLIMIT_FSIZE, &lim) != 0) _exit(3);
                try {
                    w.write_state(tiny_state(2, g));
                    rc = 4;  // no error
                } catch (const std::runtime_error& e) {
                    const std::string msg = e.what();
                    if (msg.find(dir + "/d3plot0") == std::string::npos || msg.find("too large") == std::string::npos)
                        rc = 5;
                    std::fprintf(stderr, "  write error as reported: %s\n", msg.c_str());
                }
            } catch (...) {
                rc = 6;
            }
            _exit(rc);
        }
        int status = 0;
        ASSERT_EQ(waitpid(pid, &status, 0), pid);
        ASSERT_TRUE(WIFEXITED(status));
        EXPECT_EQ(WEXITSTATUS(status), 0);
        EXPECT_EQ(read_all(root), 2);
        for (const auto& e : fs::directory_iterator(dir))
            EXPECT_EQ(e.path().extension(), "") << "left over " << e.path();
    }
    PlotWriter w;
    try {
        w.open("/nonexistent-dir-impact3d/d3plot", tiny_geometry(), 4);
        ADD_FAILURE() << "open in a missing directory succeeded";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("/nonexistent-dir-impact3d/d3plot"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
    }
}

// Independent check with VTK's vtkLSDynaReader (the project's script in tests/support).
TEST(PlotDatabase, VtkProbeReadsOurFiles) {
    const std::string probe = std::string(IMPACT3D_SOURCE_DIR) + "/tests/support/vtk_d3plot_check.py";
    if (!fs::exists(probe)) GTEST_SKIP() << "probe script not found: " << probe;
    if (std::system("/usr/bin/python3 -c 'import vtkmodules.vtkIOLSDyna' >/dev/null 2>&1") != 0)
        GTEST_SKIP() << "/usr/bin/python3 cannot import vtkmodules (install python3-vtk9); VTK check skipped";
    struct Case { int ws; int nstates; std::int64_t limit; bool uncommitted_tail; };
    const std::int64_t sw = 1 + 20 + 108 + 16;
    for (const Case c : {Case{4, 3, PlotWriter::kDefaultMemberSizeLimitWords, false},
                         Case{8, 3, PlotWriter::kDefaultMemberSizeLimitWords, false},
                         Case{4, 5, 2 * sw + 1, false}, Case{8, 4, 1, false}, Case{4, 3, 3 * sw, true}}) {
        const std::string dir = test_dir("vtk" + std::to_string(c.ws) + "_" + std::to_string(c.nstates) + "_" +
                                         std::to_string(c.limit) + (c.uncommitted_tail ? "_tail" : ""));
        const std::string root = write_db(dir, c.ws, c.nstates, c.limit);
        int expect_steps = c.nstates;
        if (c.uncommitted_tail) {  // half-written appended state after the last marker
            const std::string last = dir + "/d3plot02";
            auto d = slurp(last);
            for (int k = 0; k < 100; ++k) d.push_back(static_cast<char>(0x40 + k));
            spit(last, d);
        }
        const std::string cmd = "/usr/bin/python3 '" + probe + "' '" + root +
                                "' --node-xyz 2,1,1 --expect-nodes 12 --expect-solids 2 --ghost-deleted --expect-steps " +
                                std::to_string(expect_steps) + " > '" + dir + "/probe.log' 2>&1";
        const int st = std::system(cmd.c_str());
        const auto log = slurp(dir + "/probe.log");
        ASSERT_TRUE(WIFEXITED(st)) << cmd << "\n" << std::string(log.begin(), log.end());
        const std::string text(log.begin(), log.end());
        EXPECT_EQ(WEXITSTATUS(st), 0) << cmd << "\n" << text;
        // part titles, node 12 (initial (2,1,1)) at state 2, deleted solid 2 in the last state
        EXPECT_NE(text.find("parts: ['steel block', 'aluminium block']"), std::string::npos) << text;
        EXPECT_NE(text.find("(2, 1, 1) -> (2.20121, 1.00002, 0.99996)"),
                  std::string::npos) << text;
        EXPECT_NE(text.find("'vtkGhostType': 1"), std::string::npos) << text;
        EXPECT_EQ(read_all(root), expect_steps);
    }
}
