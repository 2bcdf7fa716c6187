#include "postimpact/history.h"

#include "postimpact/elements.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace postimpact {

namespace {

// A whole-word integer that fits an int (ids: larger ones are "does not exist", not a crash).
bool is_int(const std::string& s) {
    if (s.empty()) return false;
    std::size_t i = (s[0] == '-' || s[0] == '+') ? 1 : 0;
    if (i == s.size() || s.size() - i > 9) return false;  // at most 9 digits: fits an int
    for (; i < s.size(); ++i)
        if (s[i] < '0' || s[i] > '9') return false;
    return true;
}

const char* kGlobalVars[] = {"ke", "ie", "te", "vx", "vy", "vz"};
const char* kMaterialVars[] = {"ie", "ke", "hg", "mass", "mx", "my", "mz", "vx", "vy", "vz"};
const char* kWallVars[] = {"fn"};
const char* kInterfaceVars[] = {"fx", "fy", "fz", "fm"};

template <std::size_t N>
bool in(const std::string& w, const char* const (&list)[N]) {
    return std::any_of(std::begin(list), std::end(list), [&](const char* s) { return w == s; });
}

std::string var_label(const HistoryCurve& c, const Database& db) {
    static const std::pair<const char*, const char*> names[] = {
        {"ke", "kinetic energy"}, {"ie", "internal energy"}, {"te", "total energy"},
        {"hg", "hourglass energy"}, {"mass", "mass"}, {"mx", "momentum x"}, {"my", "momentum y"},
        {"mz", "momentum z"}, {"vx", "velocity x"}, {"vy", "velocity y"}, {"vz", "velocity z"},
        {"fn", "normal force"}, {"fx", "force x"}, {"fy", "force y"}, {"fz", "force z"}, {"fm", "force"}};
    std::string v = c.var;
    if (c.kind != HistoryCurve::Kind::Node && c.kind != HistoryCurve::Kind::Element)
        for (const auto& [k, n] : names)
            if (v == k) v = n;
    switch (c.kind) {
        case HistoryCurve::Kind::Global: {
            std::string s = v;
            s[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(s[0])));
            return s;
        }
        case HistoryCurve::Kind::Material: return v + ", " + db.part_name(c.id);
        case HistoryCurve::Kind::Node: return "node " + std::to_string(c.id) + " " + v;
        case HistoryCurve::Kind::Element:
            return (c.family < 0 ? std::string("elem") : std::string(family_name(static_cast<Family>(c.family)))) + " " +
                   std::to_string(c.id) + " " + v;
        case HistoryCurve::Kind::Wall: return "wall " + std::to_string(c.id) + " " + v;
        case HistoryCurve::Kind::Interface: return "interface " + std::to_string(c.id) + " " + v;
        case HistoryCurve::Kind::Mili: {
            const auto bar = v.find('|');
            return v.substr(0, bar) + " " + std::to_string(c.id) + " " + v.substr(bar + 1);
        }
    }
    return v;
}

Dim var_dim(const HistoryCurve& c) {
    if (c.kind == HistoryCurve::Kind::Mili) return Dim::None;
    if (c.kind == HistoryCurve::Kind::Node || c.kind == HistoryCurve::Kind::Element) {
        Quantity q;
        find_quantity(c.var, q);
        return q.dim;
    }
    if (c.kind == HistoryCurve::Kind::Wall || c.kind == HistoryCurve::Kind::Interface) return Dim::Force;
    if (c.var == "vx" || c.var == "vy" || c.var == "vz") return Dim::Velocity;
    if (c.var == "mass") return Dim::Mass;
    if (c.var == "mx" || c.var == "my" || c.var == "mz") return Dim::Momentum;
    return Dim::Energy;
}

double at(const std::vector<double>& v, std::size_t i) { return i < v.size() ? v[i] : 0.0; }

// LEAF[:CONTAINER][@POINT] -> its parts (point 0-based, -1 when not given); false if malformed
bool split_mili_var(const std::string& v, std::string& leaf, std::string& container, int& point) {
    std::string rest = v;
    point = -1;
    if (const auto at_ = rest.find('@'); at_ != std::string::npos) {
        const std::string p = rest.substr(at_ + 1);
        if (!is_int(p) || std::stoi(p) < 1) return false;
        point = std::stoi(p) - 1;
        rest.erase(at_);
    }
    container.clear();
    if (const auto c = rest.find(':'); c != std::string::npos) {
        container = rest.substr(c + 1);
        rest.erase(c);
    }
    leaf = rest;
    return !leaf.empty();
}


}  // namespace

std::vector<HistoryCurve> parse_history(const std::vector<std::string>& w, const Database& db) {
    std::vector<HistoryCurve> out;
    const int nmat = db.geometry().num_materials;
    std::size_t i = 0;
    while (i < w.size()) {
        const std::string& g = w[i];
        if (g == "energy" || g == "energies") {
            for (const char* v : {"ke", "ie", "te"}) out.push_back({HistoryCurve::Kind::Global, 0, v});
            for (int m = 1; m <= nmat; ++m) {
                if (nmat > 1) {
                    out.push_back({HistoryCurve::Kind::Material, m, "ie"});
                    out.push_back({HistoryCurve::Kind::Material, m, "ke"});
                }
                out.push_back({HistoryCurve::Kind::Material, m, "hg"});
            }
            ++i;
        } else if (g == "global") {
            ++i;
            const std::size_t first = i;
            while (i < w.size() && in(w[i], kGlobalVars)) out.push_back({HistoryCurve::Kind::Global, 0, w[i++]});
            if (i == first) throw std::invalid_argument("global: expected ke ie te vx vy vz" + (i < w.size() ? ", found '" + w[i] + "'" : std::string()));
        } else if (g == "wall" || g == "interface") {
            const bool wall = g == "wall";
            const int n = wall ? db.geometry().num_rigid_walls : db.geometry().num_interfaces;
            if (i + 1 >= w.size() || !is_int(w[i + 1]))
                throw std::invalid_argument(g + ": expected a number" + (i + 1 < w.size() ? ", found '" + w[i + 1] + "'" : std::string()));
            const int id = std::stoi(w[i + 1]);
            if (id < 1 || id > n)
                throw std::invalid_argument(g + " " + std::to_string(id) + " does not exist in this database (" +
                                            (n > 0 ? "1.." + std::to_string(n) : std::string("it has none")) + ")");
            i += 2;
            const HistoryCurve::Kind kind = wall ? HistoryCurve::Kind::Wall : HistoryCurve::Kind::Interface;
            const std::size_t first = i;
            while (i < w.size() && (wall ? in(w[i], kWallVars) : in(w[i], kInterfaceVars))) out.push_back({kind, id, w[i++]});
            if (i == first)
                throw std::invalid_argument(g + " " + std::to_string(id) + ": expected " + (wall ? "fn" : "fx fy fz fm") +
                                            (i < w.size() ? ", found '" + w[i] + "'" : std::string()));
        } else if (g == "material" || g == "node" || g == "element" || g == "elem" || g == "solid" || g == "tshell" ||
                   g == "beam" || g == "shell") {
            const int family = g == "solid"    ? static_cast<int>(Family::Solid)
                               : g == "tshell" ? static_cast<int>(Family::ThickShell)
                               : g == "beam"   ? static_cast<int>(Family::Beam)
                               : g == "shell"  ? static_cast<int>(Family::Shell)
                                               : -1;
            if (i + 1 >= w.size() || !is_int(w[i + 1]))
                throw std::invalid_argument(g + ": expected an id" + (i + 1 < w.size() ? ", found '" + w[i + 1] + "'" : std::string()));
            const int id = std::stoi(w[i + 1]);
            i += 2;
            HistoryCurve::Kind kind = g == "material" ? HistoryCurve::Kind::Material
                                      : g == "node"   ? HistoryCurve::Kind::Node
                                                      : HistoryCurve::Kind::Element;
            if (kind == HistoryCurve::Kind::Material && (id < 1 || id > nmat))
                throw std::invalid_argument("material " + std::to_string(id) + " does not exist (1.." + std::to_string(nmat) + ")");
            if (kind == HistoryCurve::Kind::Node && db.node_index(id) < 0)
                throw std::invalid_argument("node " + std::to_string(id) + " does not exist");
            if (kind == HistoryCurve::Kind::Element && (family < 0 ? db.element_index(id) : db.element_index(id, family)) < 0)
                throw std::invalid_argument((family < 0 ? std::string("element") : g) + " " + std::to_string(id) + " does not exist");
            const std::size_t first = i;
            while (i < w.size()) {
                const std::string& v = w[i];
                if (kind == HistoryCurve::Kind::Material) {
                    if (!in(v, kMaterialVars)) break;
                    out.push_back({kind, id, v});
                } else {
                    Quantity q;
                    if (!find_quantity(v, q)) break;
                    const bool want_elem = kind == HistoryCurve::Kind::Element;
                    if ((q.where == Quantity::Where::Element) != want_elem)
                        throw std::invalid_argument("'" + v + "' is " + (want_elem ? "a node" : "an element") + " quantity");
                    // the normalized key, with its "@surface" / "@ipK" suffix
                    out.push_back({kind, id, q.key + (v.find('@') != std::string::npos ? v.substr(v.find('@')) : std::string()), family});
                }
                ++i;
            }
            if (i == first)
                throw std::invalid_argument(g + " " + std::to_string(id) + ": expected a variable" +
                                            (i < w.size() ? ", found '" + w[i] + "'" : std::string()));
        } else if (g == "mili") {
            const impact3d::MiliDatabase* r = db.mili();
            if (!r) throw std::invalid_argument("mili: the database is not a Mili database");
            if (i + 2 >= w.size() || !is_int(w[i + 2]))
                throw std::invalid_argument("mili: expected a class name and a label, then variables");
            const std::string cls_name = w[i + 1];
            const int id = std::stoi(w[i + 2]);
            if (!r->has_object(cls_name, id))
                throw std::invalid_argument("mili: " + cls_name + " " + std::to_string(id) + " does not exist");
            i += 3;
            const std::size_t first = i;
            static const char* const groups[] = {"energy", "energies", "global", "wall", "interface", "material", "node",
                                                 "element", "elem", "solid", "tshell", "beam", "shell", "mili"};
            while (i < w.size() && !in(w[i], groups)) {
                std::string leaf, container;
                int point = -1;
                if (!split_mili_var(w[i], leaf, container, point) || !r->has_result(cls_name, leaf, container, point))
                    throw std::invalid_argument("mili " + cls_name + " " + std::to_string(id) + ": no variable '" + w[i] +
                                                "' in its subrecords (LEAF[:CONTAINER][@POINT])");
                out.push_back({HistoryCurve::Kind::Mili, id, cls_name + "|" + w[i], -1});
                ++i;
            }
            if (i == first) throw std::invalid_argument("mili " + cls_name + " " + std::to_string(id) + ": expected a variable");
        } else {
            throw std::invalid_argument("history: expected energy, global, material, node, element (solid, tshell, beam, shell), wall, interface or mili, found '" + g + "'");
        }
    }
    if (out.empty()) throw std::invalid_argument("history: no curve");
    return out;
}

HistoryData extract_history(Database& db, const std::vector<HistoryCurve>& curves) {
    HistoryData h;
    const int ns = db.num_states();
    const auto& g = db.geometry();
    for (const auto& c : curves) {
        Series s;
        s.name = var_label(c, db);
        h.series.push_back(s);
        h.dims.push_back(var_dim(c));
    }
    for (int i = 0; i < ns; ++i) {
        const impact3d::PlotState& st = db.state(i);
        h.time.push_back(st.time);
        for (std::size_t k = 0; k < curves.size(); ++k) {
            const HistoryCurve& c = curves[k];
            double v = 0.0;
            const std::size_t m = static_cast<std::size_t>(c.id - 1);
            switch (c.kind) {
                case HistoryCurve::Kind::Global:
                    if (c.var == "ke") v = st.kinetic_energy;
                    else if (c.var == "ie") v = st.internal_energy;
                    else if (c.var == "te") v = st.total_energy;
                    else if (c.var == "vx") v = st.velocity[0];
                    else if (c.var == "vy") v = st.velocity[1];
                    else if (c.var == "vz") v = st.velocity[2];
                    break;
                case HistoryCurve::Kind::Material:
                    if (c.var == "ie") v = at(st.mat_internal_energy, m);
                    else if (c.var == "ke") v = at(st.mat_kinetic_energy, m);
                    else if (c.var == "hg") v = at(st.mat_hourglass_energy, m);
                    else if (c.var == "mass") v = at(st.mat_mass, m);
                    else if (c.var == "mx") v = at(st.mat_mass, m) * at(st.mat_velocity, 3 * m);
                    else if (c.var == "my") v = at(st.mat_mass, m) * at(st.mat_velocity, 3 * m + 1);
                    else if (c.var == "mz") v = at(st.mat_mass, m) * at(st.mat_velocity, 3 * m + 2);
                    else if (c.var == "vx") v = at(st.mat_velocity, 3 * m);
                    else if (c.var == "vy") v = at(st.mat_velocity, 3 * m + 1);
                    else if (c.var == "vz") v = at(st.mat_velocity, 3 * m + 2);
                    break;
                case HistoryCurve::Kind::Wall:
                    v = at(st.rigid_wall_forces, m);
                    break;
                case HistoryCurve::Kind::Interface: {
                    const double f[3] = {at(st.interface_forces, 3 * m), at(st.interface_forces, 3 * m + 1),
                                         at(st.interface_forces, 3 * m + 2)};
                    if (c.var == "fx") v = f[0];
                    else if (c.var == "fy") v = f[1];
                    else if (c.var == "fz") v = f[2];
                    else v = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
                    break;
                }
                case HistoryCurve::Kind::Mili: {
                    const impact3d::MiliDatabase* r = db.mili();
                    std::string leaf, container;
                    int point = -1;
                    const auto bar = c.var.find('|');
                    if (!r || bar == std::string::npos || !split_mili_var(c.var.substr(bar + 1), leaf, container, point) ||
                        !r->result(i, c.var.substr(0, bar), c.id, leaf, v, container, point))
                        v = 0.0;
                    break;
                }
                case HistoryCurve::Kind::Node:
                case HistoryCurve::Kind::Element: {
                    Quantity q;
                    find_quantity(c.var, q);
                    const int idx = c.kind == HistoryCurve::Kind::Node ? db.node_index(c.id)
                                    : c.family >= 0                      ? db.element_index(c.id, c.family)
                                                                         : db.element_index(c.id);
                    v = c.kind == HistoryCurve::Kind::Element && q.where == Quantity::Where::Element
                            ? element_value(q, g, db.layout(), st, idx)
                            : point_value(q, g, st, idx);
                    break;
                }
            }
            h.series[k].x.push_back(st.time);
            h.series[k].y.push_back(v);
        }
    }
    return h;
}

void write_csv(const std::string& path, const HistoryData& h, const Units& u) {
    std::ofstream f(path, std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write " + path);
    const std::string tu = base_unit_name(Dim::Time, u);
    f << "state,time" << (tu.empty() ? "" : " (" + tu + ")");
    for (std::size_t k = 0; k < h.series.size(); ++k) {
        const std::string un = base_unit_name(h.dims[k], u);
        const std::string name = h.series[k].name + (un.empty() ? "" : " (" + un + ")");
        if (name.find_first_of(",\"") == std::string::npos) {
            f << ',' << name;
        } else {  // RFC 4180 quoting
            f << ",\"";
            for (char ch : name) f << (ch == '"' ? "\"\"" : std::string(1, ch));
            f << '"';
        }
    }
    f << '\n';
    char buf[64];
    for (std::size_t i = 0; i < h.time.size(); ++i) {
        std::snprintf(buf, sizeof buf, "%zu,%.9g", i + 1, h.time[i]);
        f << buf;
        for (const auto& s : h.series) {
            std::snprintf(buf, sizeof buf, ",%.9g", s.y[i]);
            f << buf;
        }
        f << '\n';
    }
    if (!f) throw std::runtime_error("cannot write " + path);
}

namespace {

Image plot_group(const HistoryData& h, const std::vector<std::size_t>& idx, const std::string& title,
                 const Units& u, int width, int height, const Font& font) {
    PlotSpec sp;
    sp.title = title;
    sp.width = width;
    sp.height = height;
    double tmax = 0;
    for (double t : h.time) tmax = std::max(tmax, std::fabs(t));
    const DisplayUnit tu = display_unit(Dim::Time, tmax, u);
    sp.xlabel = "Time" + (tu.name.empty() ? std::string() : " (" + tu.name + ")");
    const Dim dim = h.dims[idx[0]];
    double ymax = 0;
    for (std::size_t k : idx)
        for (double v : h.series[k].y)
            if (std::isfinite(v)) ymax = std::max(ymax, std::fabs(v));
    const DisplayUnit yu = display_unit(dim, ymax, u);
    static const std::pair<Dim, const char*> names[] = {
        {Dim::Energy, "Energy"}, {Dim::Stress, "Stress"}, {Dim::Strain, "Strain"},
        {Dim::Length, "Displacement"}, {Dim::Velocity, "Velocity"}, {Dim::Acceleration, "Acceleration"},
        {Dim::Mass, "Mass"}, {Dim::Momentum, "Momentum"}, {Dim::Force, "Force"}, {Dim::Time, "Time"}, {Dim::None, "Value"}};
    sp.ylabel = "Value";
    for (const auto& [d, n] : names)
        if (d == dim) sp.ylabel = n;
    if (!yu.name.empty()) sp.ylabel += " (" + yu.name + ")";
    for (std::size_t k : idx) {
        Series d = h.series[k];
        for (double& x : d.x) x *= tu.factor;
        for (double& y : d.y) y *= yu.factor;
        sp.series.push_back(std::move(d));
    }
    return draw_plot(sp, font);
}

}  // namespace

Image plot_history(const HistoryData& h, const std::string& title, const Units& u, int width,
                   int height, const Font& font) {
    // curves of different dimensions (strain, stress, ...) go to panels stacked vertically
    std::vector<std::vector<std::size_t>> groups;
    std::vector<Dim> gdim;
    for (std::size_t k = 0; k < h.series.size(); ++k) {
        auto it = std::find(gdim.begin(), gdim.end(), h.dims[k]);
        if (it == gdim.end()) { gdim.push_back(h.dims[k]); groups.push_back({k}); }
        else groups[static_cast<std::size_t>(it - gdim.begin())].push_back(k);
    }
    if (groups.size() <= 1) {
        if (groups.empty()) return draw_plot(PlotSpec{title, "", "Time", "Value", {}, width, height}, font);
        return plot_group(h, groups[0], title, u, width, height, font);
    }
    const int ph = std::max(height * 3 / 5, 360);
    Image out(width, ph * static_cast<int>(groups.size()));
    for (std::size_t g = 0; g < groups.size(); ++g)
        out.blit(plot_group(h, groups[g], g == 0 ? title : std::string(), u, width, ph, font), 0, static_cast<int>(g) * ph);
    return out;
}

}  // namespace postimpact
