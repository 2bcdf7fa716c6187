#include "postimpact/compare.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "postimpact/database.h"
#include "postimpact/elements.h"
#include "postimpact/quantities.h"

namespace postimpact {

const char* const Tolerances::kFields[10] = {"time", "coords", "vel", "acc", "stress", "eps", "energy", "force", "mass", "temp"};

Tolerance Tolerances::get(const std::string& f) const {
    if (auto it = field.find(f); it != field.end()) return it->second;
    if (auto it = field.find("default"); it != field.end()) return it->second;
    return {};
}

Tolerances Tolerances::parse(const std::string& text, const std::string& name) {
    Tolerances t;
    std::istringstream in(text);
    std::string line;
    int ln = 0;
    auto fail = [&](const std::string& msg) {
        throw std::runtime_error(name + ":" + std::to_string(ln) + ": " + msg);
    };
    auto num = [&](const std::string& s) {
        std::size_t pos = 0;
        double v = 0;
        try { v = std::stod(s, &pos); } catch (...) { pos = 0; }
        if (pos != s.size() || !(v >= 0) || !std::isfinite(v)) fail("expected a non-negative number, found '" + s + "'");
        return v;
    };
    while (std::getline(in, line)) {
        ++ln;
        if (auto h = line.find('#'); h != std::string::npos) line.erase(h);
        std::istringstream ls(line);
        std::vector<std::string> w;
        for (std::string s; ls >> s;) w.push_back(s);
        if (w.empty()) continue;
        const std::string& f = w[0];
        auto is_field = [](const std::string& x) {
            return x == "default" || x == "cycles" ||
                   std::any_of(std::begin(kFields), std::end(kFields), [&](const char* k) { return x == k; });
        };
        auto is_key = [](const std::string& x) {
            return !x.empty() && std::all_of(x.begin(), x.end(), [](char c) {
                return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
            });
        };
        const bool known = is_field(f) || (f.rfind("summary.", 0) == 0 && is_key(f.substr(8)));
        if (!known) fail("unknown field '" + f + "' (time coords vel acc stress eps energy force mass temp cycles default, summary.FIELD, summary.KEY)");
        Tolerance tol;
        bool have_rel = false, have_abs = false;
        std::vector<std::string> pos;
        for (std::size_t i = 1; i < w.size(); ++i) {
            const auto eq = w[i].find('=');
            if (eq == std::string::npos) { pos.push_back(w[i]); continue; }
            const std::string k = w[i].substr(0, eq), v = w[i].substr(eq + 1);
            if (k == "rel") { tol.rel = num(v); have_rel = true; }
            else if (k == "abs") { tol.abs = num(v); have_abs = true; }
            else fail("expected rel= or abs=, found '" + w[i] + "'");
        }
        if (!pos.empty() && (have_rel || have_abs)) fail("mixes positional and rel=/abs= values");
        if (pos.size() > 2) fail("too many values (FIELD REL ABS)");
        if (pos.size() >= 1) tol.rel = num(pos[0]);
        if (pos.size() == 2) tol.abs = num(pos[1]);
        if (pos.empty() && !have_rel && !have_abs) fail("no tolerance given for '" + f + "'");
        t.field[f] = tol;
    }
    return t;
}

Tolerances Tolerances::read(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot read tolerance file " + path);
    std::stringstream ss;
    ss << f.rdbuf();
    return parse(ss.str(), path);
}

namespace {

struct Diff {
    double ratio = 0;  // |d| / allowed (inf when allowed = 0)
    double a = 0, b = 0, absd = 0, reld = 0;
    int state = 0;
    int id = 0;        // user id (node / element / material), 0 for scalars
    std::string what;  // "node", "elem", "" ...
    std::string comp;  // "x", "sxx", ...
};

struct FieldStats {
    std::string name;
    Tolerance tol;
    long long compared = 0, outside = 0;
    Diff max_abs, max_rel;
    std::vector<Diff> worst;
};

void add(FieldStats& fs, const Diff& d0, std::size_t keep) {
    Diff d = d0;
    d.absd = std::fabs(d.a - d.b);
    const double mag = std::max(std::fabs(d.a), std::fabs(d.b));
    d.reld = mag > 0 ? d.absd / mag : 0.0;
    const bool nan = std::isnan(d.a) != std::isnan(d.b);
    if (std::isnan(d.a) && std::isnan(d.b)) d.absd = 0, d.reld = 0;
    const double allowed = fs.tol.abs + fs.tol.rel * mag;
    ++fs.compared;
    if (fs.compared == 1 || d.absd > fs.max_abs.absd) fs.max_abs = d;
    if (fs.compared == 1 || d.reld > fs.max_rel.reld) fs.max_rel = d;
    const bool out = nan || d.absd > allowed;
    if (!out) return;
    ++fs.outside;
    d.ratio = nan ? INFINITY : (allowed > 0 ? d.absd / allowed : INFINITY);
    fs.worst.push_back(d);
    if (fs.worst.size() > 4 * keep + 16) {
        std::stable_sort(fs.worst.begin(), fs.worst.end(), [](const Diff& x, const Diff& y) {
            return x.ratio > y.ratio || (x.ratio == y.ratio && x.absd > y.absd);
        });
        fs.worst.resize(keep);
    }
}

std::string g(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

// B's state between states s0 and s1 at weight w (0: s0), every value linear in time; the
// deletion flags of the nearer state.
impact3d::PlotState interpolate(const impact3d::PlotState& s0, const impact3d::PlotState& s1, double w) {
    impact3d::PlotState s = w < 0.5 ? s0 : s1;
    auto lerp = [w](double& out, double a, double b) { out = a + w * (b - a); };
    auto vec = [&](std::vector<double>& out, const std::vector<double>& a, const std::vector<double>& b) {
        if (a.size() != b.size()) return;
        out.resize(a.size());
        for (std::size_t k = 0; k < a.size(); ++k) lerp(out[k], a[k], b[k]);
    };
    lerp(s.time, s0.time, s1.time);
    lerp(s.kinetic_energy, s0.kinetic_energy, s1.kinetic_energy);
    lerp(s.internal_energy, s0.internal_energy, s1.internal_energy);
    lerp(s.total_energy, s0.total_energy, s1.total_energy);
    for (std::size_t k = 0; k < 3; ++k) lerp(s.velocity[k], s0.velocity[k], s1.velocity[k]);
    vec(s.mat_internal_energy, s0.mat_internal_energy, s1.mat_internal_energy);
    vec(s.mat_kinetic_energy, s0.mat_kinetic_energy, s1.mat_kinetic_energy);
    vec(s.mat_velocity, s0.mat_velocity, s1.mat_velocity);
    vec(s.mat_mass, s0.mat_mass, s1.mat_mass);
    vec(s.mat_hourglass_energy, s0.mat_hourglass_energy, s1.mat_hourglass_energy);
    vec(s.rigid_wall_forces, s0.rigid_wall_forces, s1.rigid_wall_forces);
    vec(s.interface_forces, s0.interface_forces, s1.interface_forces);
    vec(s.coords, s0.coords, s1.coords);
    vec(s.vel, s0.vel, s1.vel);
    vec(s.acc, s0.acc, s1.acc);
    vec(s.stress, s0.stress, s1.stress);
    vec(s.eps, s0.eps, s1.eps);
    vec(s.history, s0.history, s1.history);
    vec(s.temperature, s0.temperature, s1.temperature);
    vec(s.solid_vars, s0.solid_vars, s1.solid_vars);
    vec(s.tshell_vars, s0.tshell_vars, s1.tshell_vars);
    vec(s.beam_vars, s0.beam_vars, s1.beam_vars);
    vec(s.shell_vars, s0.shell_vars, s1.shell_vars);
    return s;
}

// The state of B compared with A's state i: (first, second, weight of the second); first < 0
// when A's time lies outside B's time span.
struct StateMatch {
    int a = 0, b0 = -1, b1 = -1;
    double w = 0;
};

std::vector<StateMatch> match_states(Database& A, Database& B, bool by_time) {
    std::vector<StateMatch> m;
    const int na = A.num_states(), nb = B.num_states();
    if (!by_time) {
        for (int i = 0; i < std::min(na, nb); ++i) m.push_back({i, i, i, 0.0});
        return m;
    }
    if (na == 0 || nb == 0) return m;
    // times equal to single precision (Mili writes float times) are the same time
    const double eps = 1e-6 * std::max({std::fabs(A.time(na - 1)), std::fabs(B.time(nb - 1)), 1e-300});
    for (int i = 0; i < na; ++i) {
        const double t = A.time(i);
        int j = 0;
        while (j < nb && B.time(j) < t - eps) ++j;
        if (j == nb) {
            m.push_back({i, -1, -1, 0.0});
        } else if (std::fabs(B.time(j) - t) <= eps) {
            m.push_back({i, j, j, 0.0});
        } else if (j == 0) {
            m.push_back({i, -1, -1, 0.0});
        } else {
            const double t0 = B.time(j - 1), t1 = B.time(j);
            m.push_back({i, j - 1, j, t1 > t0 ? (t - t0) / (t1 - t0) : 0.0});
        }
    }
    return m;
}

std::string where(const Diff& d, Database& db) {
    std::string s = "state " + std::to_string(d.state + 1) + " (t " + g(db.time(d.state)) + ")";
    if (!d.what.empty()) s += " " + d.what + " " + std::to_string(d.id);
    if (!d.comp.empty()) s += " " + d.comp;
    return s;
}

int family_count(const impact3d::PlotGeometry& g, int f) {
    const int n[4] = {g.num_hexes(), g.num_tshells(), g.num_beams(), g.num_shells()};
    return n[f];
}

// A's nodes and elements matched to B's by user id (per family); a family only one database has
// is skipped when matching by time.
struct Matching {
    bool skip_family[4] = {false, false, false, false};
    std::vector<int> node_b, elem_b;  // B's node / element of each of A's (-1: none, or skipped)
};

// The meshes have the same counts (nodes, elements per family, materials when matching by
// state); by time, a family only one database has is noted and skipped. False: not comparable
// (said on out).
bool same_counts(const impact3d::PlotGeometry& ga, const impact3d::PlotGeometry& gb, bool by_time, Matching& mt,
                 std::ostream& out) {
    if (by_time) {
        const char* names[4] = {"solids", "thick shells", "beams", "shells"};
        for (int f = 0; f < 4; ++f) {
            const int ca = family_count(ga, f), cb = family_count(gb, f);
            if ((ca == 0) == (cb == 0)) continue;
            mt.skip_family[f] = true;
            out << "compare: note: " << (ca ? "A" : "B") << " has " << std::max(ca, cb) << " " << names[f] << ", "
                << (ca ? "B" : "A") << " none: not compared\n";
        }
    }
    auto same_count = [&](int f) { return mt.skip_family[f] || family_count(ga, f) == family_count(gb, f); };
    if (ga.num_nodes() != gb.num_nodes() || !same_count(0) || (!by_time && ga.num_materials != gb.num_materials) ||
        !same_count(1) || !same_count(2) || !same_count(3)) {
        out << "compare: the meshes differ: A has " << ga.num_nodes() << " nodes, " << ga.num_hexes()
            << " solids, " << ga.num_materials << " materials; B has " << gb.num_nodes() << ", "
            << gb.num_hexes() << ", " << gb.num_materials;
        if (num_elements(ga) != ga.num_hexes() || num_elements(gb) != gb.num_hexes())
            out << " (thick shells, beams, shells: A " << ga.num_tshells() << ", " << ga.num_beams() << ", "
                << ga.num_shells() << "; B " << gb.num_tshells() << ", " << gb.num_beams() << ", " << gb.num_shells() << ")";
        out << "\nresult: NOT COMPARABLE\n";
        return false;
    }
    return true;
}

// Matches nodes and elements (per family) by user id. False: some of A's are not in B (said).
bool match_by_user_id(Database& A, Database& B, Matching& mt, std::ostream& out) {
    const auto& ga = A.geometry();
    const auto& gb = B.geometry();
    mt.node_b.assign(static_cast<std::size_t>(ga.num_nodes()), 0);
    mt.elem_b.assign(static_cast<std::size_t>(num_elements(ga)), 0);
    std::vector<int> unmatched;
    for (int k = 0; k < ga.num_nodes(); ++k) {
        const int j = B.node_index(A.node_id(k));
        mt.node_b[static_cast<std::size_t>(k)] = j;
        if (j < 0) unmatched.push_back(A.node_id(k));
    }
    std::map<std::pair<int, int>, int> b_elems;  // (family, user id) -> B element
    for (int e = 0; e < num_elements(gb); ++e)
        b_elems.emplace(std::make_pair(static_cast<int>(element_ref(gb, e).family), element_user_id(gb, e)), e);
    std::vector<std::string> unmatched_elems;
    for (int e = 0; e < num_elements(ga); ++e) {
        const ElementRef r = element_ref(ga, e);
        if (mt.skip_family[static_cast<int>(r.family)]) {
            mt.elem_b[static_cast<std::size_t>(e)] = -1;
            continue;
        }
        const auto it = b_elems.find({static_cast<int>(r.family), element_user_id(ga, e)});
        mt.elem_b[static_cast<std::size_t>(e)] = it == b_elems.end() ? -1 : it->second;
        if (it == b_elems.end()) unmatched_elems.push_back(std::string(family_name(r.family)) + " " + std::to_string(element_user_id(ga, e)));
    }
    if (!unmatched.empty() || !unmatched_elems.empty()) {
        out << "compare: the meshes differ: " << unmatched.size() << " node and " << unmatched_elems.size()
            << " element user id(s) of A are not in B (first: "
            << (unmatched.empty() ? unmatched_elems.front() : "node " + std::to_string(unmatched.front()))
            << ")\nresult: NOT COMPARABLE\n";
        return false;
    }
    return true;
}

// The rigid-wall and interface force blocks have the same counts (a Mili database holds none:
// then they are noted and left out). False: not comparable (said).
bool same_global_blocks(Database& A, Database& B, bool by_time, std::ostream& out) {
    const auto& ga = A.geometry();
    const auto& gb = B.geometry();
    if ((ga.num_rigid_walls != gb.num_rigid_walls || ga.num_interfaces != gb.num_interfaces) && by_time &&
        (A.is_mili() || B.is_mili())) {
        // a Mili database holds no rigid-wall or interface-force block: those forces are left out
        out << "compare: note: A has " << ga.num_rigid_walls << " rigid-wall and " << ga.num_interfaces
            << " interface force(s), B " << gb.num_rigid_walls << " and " << gb.num_interfaces
            << " (a Mili database holds none): the forces are not compared\n";
    } else if (ga.num_rigid_walls != gb.num_rigid_walls || ga.num_interfaces != gb.num_interfaces) {
        out << "compare: the global blocks differ: A has " << ga.num_rigid_walls << " rigid-wall and "
            << ga.num_interfaces << " interface force(s); B has " << gb.num_rigid_walls << " and "
            << gb.num_interfaces << "\nresult: NOT COMPARABLE\n";
        return false;
    }
    return true;
}

// Connectivity through the matches: A's element nodes, as B nodes, are B's element nodes (a
// warning when not).
void warn_if_connectivity_differs(const impact3d::PlotGeometry& ga, const impact3d::PlotGeometry& gb, const Matching& mt,
                                  std::ostream& out) {
    bool same = true;
    for (int e = 0; e < num_elements(ga) && same; ++e) {
        if (mt.elem_b[static_cast<std::size_t>(e)] < 0) continue;
        int ca = 0, cb = 0;
        const int* na = element_nodes(ga, e, ca);
        const int* nb = element_nodes(gb, mt.elem_b[static_cast<std::size_t>(e)], cb);
        for (int k = 0; k < ca && same; ++k) same = mt.node_b[static_cast<std::size_t>(na[k])] == nb[k];
    }
    if (!same) out << "compare: warning: the element connectivities differ\n";
}

const char* const kXyz[3] = {"x", "y", "z"};
const char* const kStressComps[6] = {"sxx", "syy", "szz", "sxy", "syz", "szx"};

// The statistics of every field (Tolerances::kFields order), and how many of the largest
// differences each keeps.
struct FieldTable {
    std::vector<FieldStats> fs;
    std::size_t keep = 0;
    FieldStats& operator()(const char* n) {
        for (auto& x : fs)
            if (x.name == n) return x;
        return fs[0];
    }
    void add(const char* field, const Diff& d) { postimpact::add((*this)(field), d, keep); }
};

// Nodal fields (coordinates, velocities, accelerations, temperatures) of state i.
void compare_nodes(Database& A, const impact3d::PlotState& sa, const impact3d::PlotState& sb, int i, const Matching& mt,
                   FieldTable& F) {
    auto nodal = [&](const char* field, const std::vector<double>& a, const std::vector<double>& b, int per) {
        if (a.empty() || b.empty() || a.size() != b.size()) return;
        for (std::size_t k = 0; k < a.size(); ++k) {
            const std::size_t kb = per * static_cast<std::size_t>(mt.node_b[k / per]) + k % per;
            F.add(field, Diff{0, a[k], b[kb], 0, 0, i, A.node_id(static_cast<int>(k / per)), "node", per == 3 ? kXyz[k % 3] : ""});
        }
    };
    nodal("coords", sa.coords, sb.coords, 3);
    nodal("vel", sa.vel, sb.vel, 3);
    nodal("acc", sa.acc, sb.acc, 3);
    nodal("temp", sa.temperature, sb.temperature, 1);
}

// Element fields of state i: solid stresses and EPS; thick shells, beams, shells: middle-surface
// stresses and EPS (beams: mean over the points).
void compare_elements(Database& A, Database& B, const impact3d::PlotState& sa, const impact3d::PlotState& sb, int i,
                      const Matching& mt, FieldTable& F) {
    const auto& ga = A.geometry();
    const auto& gb = B.geometry();
    const std::size_t nh = static_cast<std::size_t>(ga.num_hexes());
    if (sa.stress.size() == sb.stress.size() && !mt.skip_family[0])
        for (std::size_t k = 0; k < sa.stress.size(); ++k)
            F.add("stress", Diff{0, sa.stress[k], sb.stress[6 * static_cast<std::size_t>(mt.elem_b[k / 6]) + k % 6], 0, 0, i,
                                 A.element_id(static_cast<int>(k / 6)), "elem", kStressComps[k % 6]});
    if (sa.eps.size() == sb.eps.size() && !mt.skip_family[0])
        for (std::size_t k = 0; k < sa.eps.size(); ++k)
            F.add("eps", Diff{0, sa.eps[k], sb.eps[static_cast<std::size_t>(mt.elem_b[k])], 0, 0, i, A.element_id(static_cast<int>(k)), "elem", ""});
    for (int e = static_cast<int>(nh); e < num_elements(ga); ++e) {
        const int eb = mt.elem_b[static_cast<std::size_t>(e)];
        if (eb < 0) continue;
        const std::string what = family_name(element_ref(ga, e).family);
        for (int c = 0; c < 7; ++c) {
            Quantity q;
            find_quantity(c < 6 ? kStressComps[c] : "eps", q);
            F.add(c < 6 ? "stress" : "eps",
                  Diff{0, element_value(q, ga, A.layout(), sa, e), element_value(q, gb, B.layout(), sb, eb), 0, 0, i,
                       A.element_id(e), what, c < 6 ? kStressComps[c] : ""});
        }
    }
}

// Global fields of state i: energies (model and per material), the model's and the materials'
// velocities, the materials' masses, rigid-wall and interface forces.
void compare_globals(const impact3d::PlotState& sa, const impact3d::PlotState& sb, int i, FieldTable& F) {
    F.add("energy", Diff{0, sa.kinetic_energy, sb.kinetic_energy, 0, 0, i, 0, "", "kinetic"});
    F.add("energy", Diff{0, sa.internal_energy, sb.internal_energy, 0, 0, i, 0, "", "internal"});
    F.add("energy", Diff{0, sa.total_energy, sb.total_energy, 0, 0, i, 0, "", "total"});
    auto mat = [&](const char* comp, const std::vector<double>& a, const std::vector<double>& b) {
        if (a.size() != b.size()) return;
        for (std::size_t k = 0; k < a.size(); ++k)
            F.add("energy", Diff{0, a[k], b[k], 0, 0, i, static_cast<int>(k + 1), "material", comp});
    };
    mat("internal", sa.mat_internal_energy, sb.mat_internal_energy);
    mat("kinetic", sa.mat_kinetic_energy, sb.mat_kinetic_energy);
    mat("hourglass", sa.mat_hourglass_energy, sb.mat_hourglass_energy);
    // model velocity and per-material mean velocities (field vel), per-material masses
    for (std::size_t k = 0; k < 3; ++k)
        F.add("vel", Diff{0, sa.velocity[k], sb.velocity[k], 0, 0, i, 0, "model", kXyz[k]});
    if (sa.mat_velocity.size() == sb.mat_velocity.size())
        for (std::size_t k = 0; k < sa.mat_velocity.size(); ++k)
            F.add("vel", Diff{0, sa.mat_velocity[k], sb.mat_velocity[k], 0, 0, i, static_cast<int>(k / 3 + 1), "material", kXyz[k % 3]});
    if (sa.mat_mass.size() == sb.mat_mass.size())
        for (std::size_t k = 0; k < sa.mat_mass.size(); ++k)
            F.add("mass", Diff{0, sa.mat_mass[k], sb.mat_mass[k], 0, 0, i, static_cast<int>(k + 1), "material", ""});
    // rigid-wall normal forces and interface resultant forces (the same counts: checked above)
    if (sa.rigid_wall_forces.size() == sb.rigid_wall_forces.size())
        for (std::size_t k = 0; k < sa.rigid_wall_forces.size(); ++k)
            F.add("force", Diff{0, sa.rigid_wall_forces[k], sb.rigid_wall_forces[k], 0, 0, i, static_cast<int>(k + 1), "wall", "normal"});
    if (sa.interface_forces.size() == sb.interface_forces.size())
        for (std::size_t k = 0; k < sa.interface_forces.size(); ++k)
            F.add("force", Diff{0, sa.interface_forces[k], sb.interface_forces[k], 0, 0, i, static_cast<int>(k / 3 + 1), "interface", kXyz[k % 3]});
}

// Element deletion flags of state i must agree (every family).
void compare_deletion(Database& A, Database& B, const impact3d::PlotState& sa, const impact3d::PlotState& sb, int i,
                      const Matching& mt, FieldTable& F) {
    const auto& ga = A.geometry();
    const auto& gb = B.geometry();
    const int nh = ga.num_hexes();
    for (int e = 0; e < num_elements(ga); ++e) {
        if (mt.elem_b[static_cast<std::size_t>(e)] < 0) continue;
        const bool la = element_alive(sa, ga, e), lb = element_alive(sb, gb, mt.elem_b[static_cast<std::size_t>(e)]);
        if (la != lb)
            F.add("eps", Diff{0, la ? 1.0 : 0.0, lb ? 1.0 : 0.0, 0, 0, i, A.element_id(e),
                              e < nh ? std::string("elem") : std::string(family_name(element_ref(ga, e).family)),
                              "alive"});
    }
}

// The matched states compared field by field; counts the states compared, those interpolated
// between two of B's and those outside B's time span.
struct StateCounts {
    int compared = 0, interpolated = 0, outside_span = 0;
};

StateCounts compare_states(Database& A, Database& B, bool by_time, const Matching& mt, FieldTable& F) {
    StateCounts n;
    for (const StateMatch& m : match_states(A, B, by_time)) {
        if (m.b0 < 0) {
            ++n.outside_span;
            continue;
        }
        ++n.compared;
        const int i = m.a;
        const impact3d::PlotState sa = A.state(i);  // copies: the cache may be trimmed
        impact3d::PlotState sb = B.state(m.b0);
        if (m.b1 != m.b0) {
            ++n.interpolated;
            const impact3d::PlotState s1 = B.state(m.b1);
            sb = interpolate(sb, s1, m.w);
        }
        F.add("time", Diff{0, sa.time, sb.time, 0, 0, i, 0, "", ""});
        compare_nodes(A, sa, sb, i, mt, F);
        compare_elements(A, B, sa, sb, i, mt, F);
        compare_globals(sa, sb, i, F);
        compare_deletion(A, B, sa, sb, i, mt, F);
    }
    return n;
}

// The table of fields (tolerances, largest differences, values outside) and the largest
// differences outside tolerance, worst first; kept in res too. Returns the values outside.
long long report_fields(FieldTable& F, Database& A, CompareResult& res, std::ostream& out) {
    const std::size_t keep = F.keep;
    char line[512];
    out << "\n";
    std::snprintf(line, sizeof line, "%-7s %10s %10s  %12s  %12s  %10s  %s\n", "field", "rel tol", "abs tol",
                  "max |a-b|", "max rel", "outside", "largest absolute difference at");
    out << line;
    long long outside = 0;
    std::vector<std::pair<std::string, Diff>> all_worst;
    for (auto& f : F.fs) {
        if (f.compared == 0) {
            if (f.name == "temp") continue;  // (a row only for databases with temperatures)
            std::snprintf(line, sizeof line, "%-7s %10s %10s  %12s  %12s  %10s\n", f.name.c_str(), g(f.tol.rel).c_str(),
                          g(f.tol.abs).c_str(), "-", "-", "-");
            out << line;
            continue;
        }
        outside += f.outside;
        res.fields.push_back(CompareFieldRow{f.name, f.tol, f.compared, f.outside, f.max_abs.absd, f.max_rel.reld});
        std::snprintf(line, sizeof line, "%-7s %10s %10s  %12s  %12s  %10lld  %s\n", f.name.c_str(), g(f.tol.rel).c_str(),
                      g(f.tol.abs).c_str(), g(f.max_abs.absd).c_str(), g(f.max_rel.reld).c_str(), f.outside,
                      f.max_abs.absd > 0 ? where(f.max_abs, A).c_str() : "");
        out << line;
        for (const auto& d : f.worst) all_worst.emplace_back(f.name, d);
    }
    std::stable_sort(all_worst.begin(), all_worst.end(), [](const auto& x, const auto& y) {
        return x.second.ratio > y.second.ratio || (x.second.ratio == y.second.ratio && x.second.absd > y.second.absd);
    });
    for (std::size_t k = 0; k < std::min(keep, all_worst.size()); ++k) {
        const auto& [name, d] = all_worst[k];
        res.worst.push_back(CompareFinding{name, d.state + 1, A.time(d.state), d.what, d.id, d.comp, d.a, d.b,
                                           d.absd, d.reld, d.ratio});
    }
    if (!all_worst.empty() && keep > 0) {
        out << "\nlargest differences outside tolerance (|a-b| / allowed, worst first):\n";
        for (std::size_t k = 0; k < std::min(keep, all_worst.size()); ++k) {
            const auto& [name, d] = all_worst[k];
            std::snprintf(line, sizeof line, "  %-7s %s: a %s  b %s  |a-b| %s  rel %s  x%s\n", name.c_str(),
                          where(d, A).c_str(), g(d.a).c_str(), g(d.b).c_str(), g(d.absd).c_str(), g(d.reld).c_str(),
                          std::isinf(d.ratio) ? "inf" : g(d.ratio).c_str());
            out << line;
        }
    }
    return outside;
}

}  // namespace

int compare_databases(const std::string& pa, const std::string& pb, const CompareOptions& opt,
                      std::ostream& out0, CompareResult* result) {
    // what goes to `out` is also kept, so that `problem` can quote the reason for exit 2
    std::ostringstream out;
    CompareResult scratch;
    CompareResult& res = result ? *result : scratch;
    res = CompareResult{};
    struct Flush {
        std::ostream& to;
        std::ostringstream& from;
        ~Flush() { to << from.str(); }
    } flush{out0, out};
    auto not_comparable = [&]() {
        const std::string text = out.str();
        std::string reason = text;
        if (const auto p = text.rfind("compare: "); p != std::string::npos) reason = text.substr(p + 9);
        if (const auto r = reason.find("\nresult:"); r != std::string::npos) reason.erase(r);
        while (!reason.empty() && reason.back() == '\n') reason.pop_back();
        res.problem = reason;
        return 2;
    };
    std::unique_ptr<Database> A, B;
    try {
        A = std::make_unique<Database>(pa);
        B = std::make_unique<Database>(pb);
    } catch (const std::exception& e) {
        out << "compare: cannot open: " << e.what() << "\n";
        return not_comparable();
    }
    res.states_a = A->num_states();
    res.states_b = B->num_states();
    const bool by_time = opt.by_time || A->is_mili() || B->is_mili();
    out << "compare: A = " << pa << " (" << A->num_states() << " states" << (A->is_mili() ? ", Mili" : "") << ")\n"
        << "         B = " << pb << " (" << B->num_states() << " states" << (B->is_mili() ? ", Mili" : "") << ")\n";
    Matching mt;
    if (!same_counts(A->geometry(), B->geometry(), by_time, mt, out) || !match_by_user_id(*A, *B, mt, out) ||
        !same_global_blocks(*A, *B, by_time, out))
        return not_comparable();
    warn_if_connectivity_differs(A->geometry(), B->geometry(), mt, out);

    FieldTable F;
    F.keep = static_cast<std::size_t>(std::max(opt.report, 0));
    for (const char* f : Tolerances::kFields) F.fs.push_back(FieldStats{f, opt.tol.get(f), 0, 0, {}, {}, {}});
    const StateCounts n = compare_states(*A, *B, by_time, mt, F);
    const long long outside = report_fields(F, *A, res, out);
    const int ns = n.compared;
    int rc = 0;
    out << "\n";
    if (by_time) {
        out << "states: matched by time: " << ns << " of A's " << A->num_states() << " (" << n.interpolated
            << " interpolated between two of B's " << B->num_states() << ")";
        if (n.outside_span > 0) out << "; " << n.outside_span << " outside B's time span, not compared";
        out << "\n";
        if (ns == 0) {
            out << "compare: no state of A lies in B's time span\nresult: NOT COMPARABLE\n";
            return not_comparable();
        }
    } else if (A->num_states() != B->num_states()) {
        out << "states: A has " << A->num_states() << ", B has " << B->num_states() << " (the first " << ns
            << " compared)\n";
        rc = 1;
    }
    if (outside > 0) rc = 1;
    if (rc == 0) out << "result: SAME within tolerance (" << ns << " states)\n";
    else out << "result: DIFFERENT (" << outside << " values outside tolerance)\n";
    return rc;
}

}  // namespace postimpact
