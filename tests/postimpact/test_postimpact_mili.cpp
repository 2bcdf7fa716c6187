// POST-IMPACT on Mili databases (DYNA3D's own; common/mili_database): the database is chosen by
// content, summary, histories of nodes and elements of every family, the default pictures, and
// compare between a Mili database and a d3plot family of the same model (nodes and elements
// matched by label, states by time, B interpolated between its states).  The databases are
// written by the test writers (tests/support/mili_writer.h, PlotWriter).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "common/plot_database.h"
#include "postimpact/command_file.h"
#include "postimpact/compare.h"
#include "postimpact/database.h"
#include "postimpact/history.h"
#include "postimpact/picture.h"
#include "postimpact/render_osmesa.h"
#include "postimpact/summary.h"
#include "postimpact/text_freetype.h"
#include "tests/support/mili_writer.h"

namespace fs = std::filesystem;
using namespace postimpact;
using impact3d::PlotGeometry;
using impact3d::PlotState;

namespace {

struct TempDir {
    fs::path path;
    TempDir() {
        static int n = 0;
        path = fs::temp_directory_path() / ("postimpact_mili_" + std::to_string(::getpid()) + "_" + std::to_string(n++));
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string str(const std::string& name) const { return (path / name).string(); }
};

struct Sample {
    std::string base;  // NAME: the A file is NAME + "A"
    PlotGeometry g;
    std::vector<PlotState> states;
};

Sample write_sample(const TempDir& d, int nstates = 3) {
    Sample s;
    s.base = d.str("run.plt");
    mili_test::sample_model(s.g, s.states, nstates);
    mili_test::Writer(mili_test::Options{}).write(s.base, s.g, s.states);
    return s;
}

TEST(MiliPostimpact, OpensByContentSummarizesAndReadsHistories) {
    TempDir d;
    const Sample s = write_sample(d);
    Database db(s.base + "A");
    EXPECT_TRUE(db.is_mili());
    EXPECT_TRUE(Database(s.base).is_mili());  // the base name finds NAMEA
    EXPECT_EQ(db.num_states(), 3);
    EXPECT_EQ(db.node_id(0), 101);
    EXPECT_EQ(db.element_index(22, 2), 2 + 1);  // beams follow the 2 solids
    const Summary sum = summarize(s.base + "A", "");
    ASSERT_NE(sum.find("states"), nullptr);
    EXPECT_EQ(*sum.find("states"), "3");
    EXPECT_EQ(*sum.find("nodes"), "12");
    EXPECT_EQ(*sum.find("solids"), "2");
    EXPECT_EQ(*sum.find("beams"), "3");
    EXPECT_EQ(*sum.find("shells"), "2");
    // node 104 vz (double precision in the file), solid 12 sxx, beam 22 axial force, shell 31
    // thickness, global kinetic energy
    const auto curves = parse_history({"node", "104", "vz", "solid", "12", "sxx", "beam", "22", "axial_force", "shell",
                                       "31", "thickness", "global", "ke"},
                                      db);
    const HistoryData h = extract_history(db, curves);
    ASSERT_EQ(h.series.size(), 5u);
    for (int k = 0; k < 3; ++k) {
        const PlotState& w = s.states[static_cast<std::size_t>(k)];
        EXPECT_EQ(h.time[static_cast<std::size_t>(k)], w.time);
        EXPECT_EQ(h.series[0].y[static_cast<std::size_t>(k)], w.vel[3 * 3 + 2]);
        EXPECT_EQ(h.series[1].y[static_cast<std::size_t>(k)], w.stress[6]);
        EXPECT_EQ(h.series[2].y[static_cast<std::size_t>(k)], w.beam_vars[6]);
        EXPECT_EQ(h.series[3].y[static_cast<std::size_t>(k)], w.shell_vars[29]);
        EXPECT_EQ(h.series[4].y[static_cast<std::size_t>(k)], w.kinetic_energy);
    }
}

// Any variable of the file by name: mili CLASS LABEL LEAF[:CONTAINER][@POINT]
TEST(MiliPostimpact, HistoriesOfTheFilesOwnVariables) {
    TempDir d;
    const Sample s = write_sample(d);
    Database db(s.base + "A");
    const auto curves = parse_history({"mili", "beam", "23", "tor", "mili", "shell", "32", "exy:es_3c@2", "sx:stress_in",
                                       "mili", "node", "112", "uz", "energy"},
                                      db);
    ASSERT_EQ(curves.size(), 4u + 3u + 9u);  // 4 mili curves; ke ie te; ie ke hg of 3 materials
    const HistoryData h = extract_history(db, curves);
    EXPECT_EQ(h.series[0].name, "beam 23 tor");
    EXPECT_EQ(h.series[1].name, "shell 32 exy:es_3c@2");
    for (int k = 0; k < 3; ++k) {
        const PlotState& w = s.states[static_cast<std::size_t>(k)];
        EXPECT_EQ(h.series[0].y[static_cast<std::size_t>(k)], w.beam_vars[2 * 6 + 5]);
        EXPECT_EQ(h.series[1].y[static_cast<std::size_t>(k)], w.shell_vars[45 + 39 + 3]);  // outer strain xy
        EXPECT_EQ(h.series[2].y[static_cast<std::size_t>(k)], w.shell_vars[45 + 7]);       // inner sx
        EXPECT_EQ(h.series[3].y[static_cast<std::size_t>(k)], w.coords[3 * 11 + 2]);
    }
    EXPECT_THROW(parse_history({"mili", "beam", "23", "nothing"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"mili", "beam", "99", "tor"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"mili", "rod", "23", "tor"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"mili", "shell", "32", "exy:es_3c@3"}, db), std::invalid_argument);
    EXPECT_THROW(parse_history({"mili", "shell", "32", "exy@0"}, db), std::invalid_argument);
}

TEST(MiliPostimpact, DefaultPicturesAndFringes) {
    TempDir d;
    const Sample s = write_sample(d);
    std::ostringstream log;
    Session ses(log);
    ses.execute({"open", s.base + "A"});
    ses.execute({"outdir", d.str("def")});
    ses.execute({"size", "400", "300"});
    ses.default_set();
    for (const char* f : {"eps_first.png", "eps_middle.png", "eps_last.png", "eps_sequence.png", "energies.png", "energies.csv"})
        EXPECT_TRUE(fs::exists(fs::path(d.str("def")) / f)) << f;
    Database db(s.base + "A");
    Renderer r;
    Font font;
    PictureSettings ps;
    ps.width = 400;
    ps.height = 300;
    ps.fringe = "vm";
    const Image img = make_picture(db, {db.num_states() - 1}, ps, r, font);
    EXPECT_EQ(img.width, 400);
}

// Values linear in time, so that B interpolated between two states is A's state at that time.
PlotState linear_state(const PlotGeometry& g, double t) {
    PlotState s;
    s.time = t;
    s.kinetic_energy = 5 + t;
    s.internal_energy = 2 * t;
    s.total_energy = 5 + 3 * t;
    s.velocity = {t, 0.5 * t, -t};
    for (std::size_t i = 0; i < g.x0.size(); ++i) {
        s.coords.push_back(g.x0[i] + 0.01 * t * static_cast<double>(i % 7));
        s.vel.push_back(0.5 * static_cast<double>(i % 5) + 0.25 * t);
        s.acc.push_back(0.125 * static_cast<double>(i % 3));
    }
    for (int e = 0; e < g.num_hexes(); ++e) {
        for (int j = 0; j < 6; ++j) s.stress.push_back(10.0 * (j + 1) * t + e);
        s.eps.push_back(0.01 * t * (e + 1));
    }
    s.alive.assign(static_cast<std::size_t>(g.num_hexes()), 1);
    s.mat_internal_energy = {2 * t};
    s.mat_kinetic_energy = {5 + t};
    return s;
}

// The solids of the sample model as a d3plot family: nodes and solids in reverse order (the
// user labels kept), states at other times than the Mili database's.
void write_d3plot_reversed(const std::string& root, const PlotGeometry& mili_g, const std::vector<double>& times,
                           double perturb = 0.0) {
    PlotGeometry g;
    g.title = mili_g.title;
    g.num_materials = 1;
    const int nn = mili_g.num_nodes(), nh = mili_g.num_hexes();
    auto rn = [nn](int n) { return nn - 1 - n; };
    g.x0.resize(mili_g.x0.size());
    g.node_user_ids.resize(static_cast<std::size_t>(nn));
    for (int n = 0; n < nn; ++n) {
        for (int j = 0; j < 3; ++j) g.x0[3 * static_cast<std::size_t>(rn(n)) + j] = mili_g.x0[3 * static_cast<std::size_t>(n) + j];
        g.node_user_ids[static_cast<std::size_t>(rn(n))] = mili_g.node_user_ids[static_cast<std::size_t>(n)];
    }
    for (int e = nh - 1; e >= 0; --e) {
        for (int j = 0; j < 8; ++j) g.hex_nodes.push_back(rn(mili_g.hex_nodes[static_cast<std::size_t>(8 * e + j)]));
        g.hex_material.push_back(1);
        g.hex_user_ids.push_back(mili_g.hex_user_ids[static_cast<std::size_t>(e)]);
    }
    impact3d::PlotWriter w;
    w.open(root, g);
    for (double t : times) {
        const PlotState m = linear_state(mili_g, t);  // in the Mili numbering
        PlotState s = m;
        for (int n = 0; n < nn; ++n)
            for (int j = 0; j < 3; ++j) {
                const std::size_t a = 3 * static_cast<std::size_t>(rn(n)) + j, b = 3 * static_cast<std::size_t>(n) + j;
                s.coords[a] = m.coords[b];
                s.vel[a] = m.vel[b];
                s.acc[a] = m.acc[b];
            }
        s.coords[3 * static_cast<std::size_t>(rn(5)) + 2] += perturb;  // node 106 z
        for (int e = 0; e < nh; ++e) {
            const std::size_t a = static_cast<std::size_t>(nh - 1 - e), b = static_cast<std::size_t>(e);
            for (int j = 0; j < 6; ++j) s.stress[6 * a + j] = m.stress[6 * b + j];
            s.eps[a] = m.eps[b];
        }
        s.mat_velocity = {0, 0, 0};
        s.mat_mass = {0};
        s.mat_hourglass_energy = {0};
        w.write_state(s);
    }
}

TEST(MiliPostimpact, CompareWithAD3plotFamilyByLabelAndTime) {
    TempDir d;
    // the Mili database: the sample model's solids only, states at t = 0 1 2 3
    PlotGeometry g;
    std::vector<PlotState> unused;
    mili_test::sample_model(g, unused, 0);
    g.beam_nodes.clear(), g.beam_material.clear(), g.beam_user_ids.clear();
    g.shell_nodes.clear(), g.shell_material.clear(), g.shell_user_ids.clear();
    g.num_materials = 1;
    g.part_titles.clear();
    std::vector<PlotState> states;
    for (double t : {0.0, 1.0, 2.0, 3.0}) states.push_back(linear_state(g, t));
    const std::string mili = d.str("dyna.plt");
    mili_test::Writer(mili_test::Options{}).write(mili, g, states);
    // our run: t = 0 0.5 2 2.75 3.5 (0.5 and 2.75 between Mili states, 3.5 after the last)
    const std::vector<double> times = {0.0, 0.5, 2.0, 2.75, 3.5};
    write_d3plot_reversed(d.str("d3plot"), g, times);
    CompareOptions opt;
    opt.tol = Tolerances::parse("default 1e-6 1e-9\n");  // single precision in both files
    std::ostringstream o1;
    EXPECT_EQ(compare_databases(d.str("d3plot"), mili + "A", opt, o1), 0) << o1.str();
    EXPECT_NE(o1.str().find("matched by time: 4 of A's 5 (2 interpolated between two of B's 4); 1 outside B's time span"),
              std::string::npos)
        << o1.str();
    // and the other way round: every Mili state has a d3plot state at or around its time
    std::ostringstream o2;
    EXPECT_EQ(compare_databases(mili + "A", d.str("d3plot"), opt, o2), 0) << o2.str();
    EXPECT_NE(o2.str().find("matched by time: 4 of A's 4 (2 interpolated"), std::string::npos) << o2.str();
    // node 106 moved by 1e-3: found, with its label
    write_d3plot_reversed(d.str("moved"), g, times, 1e-3);
    std::ostringstream o3;
    CompareResult res;
    EXPECT_EQ(compare_databases(d.str("moved"), mili + "A", opt, o3, &res), 1) << o3.str();
    ASSERT_FALSE(res.worst.empty());
    EXPECT_EQ(res.worst[0].field, "coords");
    EXPECT_EQ(res.worst[0].what, "node");
    EXPECT_EQ(res.worst[0].id, 106);
    EXPECT_NEAR(res.worst[0].absd, 1e-3, 1e-6);
    // no overlap in time: not comparable
    write_d3plot_reversed(d.str("late"), g, {5.0, 6.0});
    std::ostringstream o4;
    EXPECT_EQ(compare_databases(d.str("late"), mili + "A", opt, o4), 2) << o4.str();
    // --by-time between two d3plot families
    CompareOptions bt = opt;
    bt.by_time = true;
    write_d3plot_reversed(d.str("other"), g, {0.0, 1.0, 3.0});
    std::ostringstream o5;
    EXPECT_EQ(compare_databases(d.str("other"), d.str("d3plot"), bt, o5), 0) << o5.str();
    std::ostringstream o6;
    EXPECT_EQ(compare_databases(d.str("other"), d.str("d3plot"), opt, o6), 1) << o6.str();  // by number: times differ
}

// A Mili database with shells and beams against a d3plot family with solids only (ours before
// the shell and beam output): the families only one has are left out, with a note.
TEST(MiliPostimpact, CompareLeavesOutFamiliesOnlyOneDatabaseHas) {
    TempDir d;
    const Sample s = write_sample(d, 3);
    PlotGeometry g = s.g;
    g.beam_nodes.clear(), g.beam_material.clear(), g.beam_user_ids.clear();
    g.shell_nodes.clear(), g.shell_material.clear(), g.shell_user_ids.clear();
    g.num_materials = 3;
    impact3d::PlotWriter w;
    w.open(d.str("d3plot"), g);
    for (PlotState st : s.states) {
        st.beam_vars.clear(), st.beam_alive.clear(), st.shell_vars.clear(), st.shell_alive.clear();
        w.write_state(st);
    }
    CompareOptions opt;
    opt.tol = Tolerances::parse("default 1e-6 1e-9\n");
    std::ostringstream o;
    EXPECT_EQ(compare_databases(d.str("d3plot"), s.base + "A", opt, o), 0) << o.str();
    EXPECT_NE(o.str().find("note: B has 3 beams, A none: not compared"), std::string::npos) << o.str();
    EXPECT_NE(o.str().find("note: B has 2 shells, A none: not compared"), std::string::npos) << o.str();
}

// Part of the sample model as one processor of a parallel run: the elements listed, the nodes
// they use (labels kept); the kinetic and total energy and the model velocity written alike by
// every processor, the internal energy and the material values as this processor's share
// (a quarter on the first, three quarters on the second: exact in binary).
void write_processor(const std::string& base, const PlotGeometry& g, const std::vector<PlotState>& states,
                     const std::vector<int>& hexes, const std::vector<int>& beams, const std::vector<int>& shells) {
    PlotGeometry q;
    q.title = g.title;
    q.num_materials = g.num_materials;
    q.part_titles = g.part_titles;
    std::vector<int> used(static_cast<std::size_t>(g.num_nodes()), -1);
    auto node = [&](int n) {
        if (used[static_cast<std::size_t>(n)] < 0) used[static_cast<std::size_t>(n)] = 0;
        return n;
    };
    for (int e : hexes)
        for (int j = 0; j < 8; ++j) node(g.hex_nodes[static_cast<std::size_t>(8 * e + j)]);
    for (int e : beams)
        for (int j = 0; j < 2; ++j) node(g.beam_nodes[static_cast<std::size_t>(2 * e + j)]);
    for (int e : shells)
        for (int j = 0; j < 4; ++j) node(g.shell_nodes[static_cast<std::size_t>(4 * e + j)]);
    std::vector<int> nodes;
    for (int n = 0; n < g.num_nodes(); ++n)
        if (used[static_cast<std::size_t>(n)] == 0) {
            used[static_cast<std::size_t>(n)] = static_cast<int>(nodes.size());
            nodes.push_back(n);
            q.x0.insert(q.x0.end(), g.x0.begin() + 3 * n, g.x0.begin() + 3 * n + 3);
            q.node_user_ids.push_back(g.node_user_ids[static_cast<std::size_t>(n)]);
        }
    auto take = [&](const std::vector<int>& list, const std::vector<int>& gn, const std::vector<int>& gm,
                    const std::vector<int>& gid, int per, std::vector<int>& qn, std::vector<int>& qm, std::vector<int>& qid) {
        for (int e : list) {
            for (int j = 0; j < per; ++j) qn.push_back(used[static_cast<std::size_t>(gn[static_cast<std::size_t>(per * e + j)])]);
            qm.push_back(gm[static_cast<std::size_t>(e)]);
            qid.push_back(gid[static_cast<std::size_t>(e)]);
        }
    };
    take(hexes, g.hex_nodes, g.hex_material, g.hex_user_ids, 8, q.hex_nodes, q.hex_material, q.hex_user_ids);
    take(beams, g.beam_nodes, g.beam_material, g.beam_user_ids, 2, q.beam_nodes, q.beam_material, q.beam_user_ids);
    take(shells, g.shell_nodes, g.shell_material, g.shell_user_ids, 4, q.shell_nodes, q.shell_material, q.shell_user_ids);
    std::vector<PlotState> qs;
    for (const PlotState& s : states) {
        PlotState t;
        t.time = s.time;
        t.kinetic_energy = s.kinetic_energy;
        t.total_energy = s.total_energy;
        t.velocity = s.velocity;
        const double share = base.back() == '0' ? 0.25 : 0.75;
        t.internal_energy = share * s.internal_energy;
        for (double v : s.mat_internal_energy) t.mat_internal_energy.push_back(share * v);
        for (double v : s.mat_kinetic_energy) t.mat_kinetic_energy.push_back(share * v);
        for (int n : nodes)
            for (int j = 0; j < 3; ++j) {
                t.coords.push_back(s.coords[static_cast<std::size_t>(3 * n + j)]);
                t.vel.push_back(s.vel[static_cast<std::size_t>(3 * n + j)]);
                t.acc.push_back(s.acc[static_cast<std::size_t>(3 * n + j)]);
            }
        for (int e : hexes) {
            t.stress.insert(t.stress.end(), s.stress.begin() + 6 * e, s.stress.begin() + 6 * e + 6);
            t.eps.push_back(s.eps[static_cast<std::size_t>(e)]);
            t.alive.push_back(s.alive[static_cast<std::size_t>(e)]);
        }
        for (int e : beams) {
            t.beam_vars.insert(t.beam_vars.end(), s.beam_vars.begin() + 6 * e, s.beam_vars.begin() + 6 * e + 6);
            t.beam_alive.push_back(s.beam_alive[static_cast<std::size_t>(e)]);
        }
        for (int e : shells) {
            t.shell_vars.insert(t.shell_vars.end(), s.shell_vars.begin() + 45 * e, s.shell_vars.begin() + 45 * e + 45);
            t.shell_alive.push_back(s.shell_alive[static_cast<std::size_t>(e)]);
        }
        qs.push_back(std::move(t));
    }
    mili_test::Options o;
    o.big_endian = base.back() == '1';  // the second processor in the other byte order
    mili_test::Writer(o).write(base, q, qs);
}

// A two-processor family (run.plt000A, run.plt001A with their state files), the processors
// sharing the nodes between solid 11 and solid 12, merged by label: the same as the serial
// database of the whole model, value for value.
TEST(MiliPostimpact, TwoProcessorFamilyMergedByLabel) {
    TempDir d;
    PlotGeometry g;
    std::vector<PlotState> states;
    mili_test::sample_model(g, states, 3);
    mili_test::Writer(mili_test::Options{}).write(d.str("serial.plt"), g, states);
    write_processor(d.str("run.plt000"), g, states, {0}, {0, 1}, {});
    write_processor(d.str("run.plt001"), g, states, {1}, {2}, {0, 1});
    impact3d::MiliDatabase m;
    m.open(d.str("run.plt"));
    ASSERT_EQ(m.num_parts(), 2);
    EXPECT_EQ(m.part(0).geometry().num_nodes() + m.part(1).geometry().num_nodes(), 12 + 8);  // 8 on both
    const PlotGeometry& mg = m.geometry();
    EXPECT_EQ(mg.num_nodes(), 12);
    EXPECT_EQ(mg.num_hexes(), 2);
    EXPECT_EQ(mg.num_beams(), 3);
    EXPECT_EQ(mg.num_shells(), 2);
    EXPECT_EQ(mg.num_materials, 3);
    const PlotState s = m.state(2);
    EXPECT_EQ(s.kinetic_energy, states[2].kinetic_energy);    // written alike: the model's
    EXPECT_EQ(s.internal_energy, states[2].internal_energy);  // shares: summed
    EXPECT_EQ(s.mat_kinetic_energy, states[2].mat_kinetic_energy);
    double v = 0;
    ASSERT_TRUE(m.result(1, "shell", 32, "sx", v, "stress_out"));  // on the second processor
    EXPECT_EQ(v, states[1].shell_vars[45 + 14]);
    EXPECT_FALSE(m.has_object("shell", 33));
    // POST-IMPACT: the base name opens the family; compare with the serial database: equal
    Database db(d.str("run.plt"));
    EXPECT_TRUE(db.is_mili());
    std::ostringstream o;
    EXPECT_EQ(compare_databases(d.str("run.plt"), d.str("serial.pltA"), CompareOptions{}, o), 0) << o.str();
    const auto h = extract_history(db, parse_history({"mili", "beam", "23", "tor", "node", "107", "vz"}, db));
    EXPECT_EQ(h.series[0].y[2], states[2].beam_vars[2 * 6 + 5]);
    EXPECT_EQ(h.series[1].y[2], states[2].vel[3 * 6 + 2]);
    // a processor with a different number of states: refused, naming it
    fs::remove(d.str("run.plt00101"));
    write_processor(d.str("run.plt001"), g, {states[0], states[1]}, {1}, {2}, {0, 1});
    EXPECT_THROW(m.open(d.str("run.plt")), std::runtime_error);
}

}  // namespace
