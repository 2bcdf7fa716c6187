#include "postimpact/quantities.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "postimpact/elements.h"

namespace postimpact {

namespace {

struct Entry { const char* key; const char* label; Quantity::Where where; Dim dim; };
const Entry kTable[] = {
    {"eps", "Effective plastic strain", Quantity::Where::Element, Dim::Strain},
    {"vm", "Von Mises stress", Quantity::Where::Element, Dim::Stress},
    {"pressure", "Pressure", Quantity::Where::Element, Dim::Stress},
    {"sxx", "Stress xx", Quantity::Where::Element, Dim::Stress},
    {"syy", "Stress yy", Quantity::Where::Element, Dim::Stress},
    {"szz", "Stress zz", Quantity::Where::Element, Dim::Stress},
    {"sxy", "Stress xy", Quantity::Where::Element, Dim::Stress},
    {"syz", "Stress yz", Quantity::Where::Element, Dim::Stress},
    {"szx", "Stress zx", Quantity::Where::Element, Dim::Stress},
    {"disp", "Displacement magnitude", Quantity::Where::Node, Dim::Length},
    {"dx", "Displacement x", Quantity::Where::Node, Dim::Length},
    {"dy", "Displacement y", Quantity::Where::Node, Dim::Length},
    {"dz", "Displacement z", Quantity::Where::Node, Dim::Length},
    {"vel", "Velocity magnitude", Quantity::Where::Node, Dim::Velocity},
    {"vx", "Velocity x", Quantity::Where::Node, Dim::Velocity},
    {"vy", "Velocity y", Quantity::Where::Node, Dim::Velocity},
    {"vz", "Velocity z", Quantity::Where::Node, Dim::Velocity},
    {"ax", "Acceleration x", Quantity::Where::Node, Dim::Acceleration},
    {"ay", "Acceleration y", Quantity::Where::Node, Dim::Acceleration},
    {"az", "Acceleration z", Quantity::Where::Node, Dim::Acceleration},
    {"x", "Coordinate x", Quantity::Where::Node, Dim::Length},
    {"y", "Coordinate y", Quantity::Where::Node, Dim::Length},
    {"z", "Coordinate z", Quantity::Where::Node, Dim::Length},
    {"temp", "Temperature", Quantity::Where::Node, Dim::None},
    {"thickness", "Shell thickness", Quantity::Where::Element, Dim::Length},
    {"axial_force", "Beam axial force", Quantity::Where::Element, Dim::Force},
};
const std::map<std::string, std::string> kAliases = {
    {"plastic_strain", "eps"}, {"effective_plastic_strain", "eps"}, {"von_mises", "vm"},
    {"vonmises", "vm"}, {"mises", "vm"}, {"p", "pressure"}, {"displacement", "disp"},
    {"velocity", "vel"}, {"sx", "sxx"}, {"sy", "syy"}, {"sz", "szz"}, {"sxz", "szx"},
    {"szy", "syz"}, {"syx", "sxy"}};

int stress_component(const std::string& k) {
    if (k == "sxx") return 0;
    if (k == "syy") return 1;
    if (k == "szz") return 2;
    if (k == "sxy") return 3;
    if (k == "syz") return 4;
    if (k == "szx") return 5;
    return -1;
}

double get(const std::vector<double>& v, std::size_t i) { return i < v.size() ? v[i] : 0.0; }

}  // namespace

bool find_quantity(const std::string& key0, Quantity& q) {
    std::string key = key0;
    int point = Quantity::kMid;
    std::string where;
    if (const auto at = key.find('@'); at != std::string::npos) {
        const std::string p = key.substr(at + 1);
        key = key.substr(0, at);
        if (p == "top" || p == "outer") point = Quantity::kTop, where = " (top surface)";
        else if (p == "bottom" || p == "inner") point = Quantity::kBottom, where = " (bottom surface)";
        else if (p == "mid" || p == "middle") point = Quantity::kMid, where = " (middle surface)";
        else if (p.size() > 2 && p.compare(0, 2, "ip") == 0 && p.find_first_not_of("0123456789", 2) == std::string::npos &&
                 p.size() < 7 && std::stoi(p.substr(2)) >= 1) {
            point = std::stoi(p.substr(2)) - 1;
            where = " (integration point " + p.substr(2) + ")";
        } else {
            return false;
        }
    }
    if (auto it = kAliases.find(key); it != kAliases.end()) key = it->second;
    if (key.size() > 4 && key.size() < 9 && key.compare(0, 4, "hist") == 0 &&
        key.find_first_not_of("0123456789", 4) == std::string::npos && std::stoi(key.substr(4)) >= 1) {
        // extra history value K (NEIPH of solids, NEIPS of shell layers)
        q = Quantity{"hist" + std::to_string(std::stoi(key.substr(4))), "History variable " + key.substr(4) + where,
                     Quantity::Where::Element, Dim::None};
        q.point = point;
        return true;
    }
    for (const auto& e : kTable)
        if (key == e.key) {
            if (!where.empty() && e.where == Quantity::Where::Node) return false;
            q = Quantity{e.key, e.label + where, e.where, e.dim};
            q.point = point;
            return true;
        }
    return false;
}

std::string quantity_keys() {
    std::string s;
    for (const auto& e : kTable) s += (s.empty() ? "" : " ") + std::string(e.key);
    return s + " histK";
}

double von_mises(const double* s) {
    const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
    return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

double pressure(const double* s) { return -(s[0] + s[1] + s[2]) / 3.0; }

std::vector<double> element_values(const Quantity& q, const impact3d::PlotState& s) {
    const std::size_t ne = s.eps.size() ? s.eps.size() : s.stress.size() / 6;
    std::vector<double> out(ne, 0.0);
    const int comp = stress_component(q.key);
    for (std::size_t e = 0; e < ne; ++e) {
        const double* st = s.stress.size() >= 6 * (e + 1) ? &s.stress[6 * e] : nullptr;
        if (q.key == "eps") out[e] = get(s.eps, e);
        else if (!st) out[e] = 0.0;
        else if (q.key == "vm") out[e] = von_mises(st);
        else if (q.key == "pressure") out[e] = pressure(st);
        else if (comp >= 0) out[e] = st[comp];
    }
    return out;
}

double point_value(const Quantity& q, const impact3d::PlotGeometry& g, const impact3d::PlotState& s,
                   int i) {
    if (q.where == Quantity::Where::Element) {
        const std::size_t e = static_cast<std::size_t>(i);
        if (q.key == "eps") return get(s.eps, e);
        if (s.stress.size() < 6 * (e + 1)) return 0.0;
        const double* st = &s.stress[6 * e];
        if (q.key == "vm") return von_mises(st);
        if (q.key == "pressure") return pressure(st);
        const int comp = stress_component(q.key);
        return comp >= 0 ? st[comp] : 0.0;
    }
    const std::size_t b = 3 * static_cast<std::size_t>(i);
    // no current coordinates in the database (IU 0): the initial shape
    auto pos = [&](std::size_t j) { return s.coords.empty() ? get(g.x0, j) : get(s.coords, j); };
    auto d = [&](int k) { return pos(b + k) - get(g.x0, b + k); };
    const std::string& k = q.key;
    if (k == "disp") return std::sqrt(d(0) * d(0) + d(1) * d(1) + d(2) * d(2));
    if (k == "dx") return d(0);
    if (k == "dy") return d(1);
    if (k == "dz") return d(2);
    if (k == "vel") {
        const double a = get(s.vel, b), c = get(s.vel, b + 1), e = get(s.vel, b + 2);
        return std::sqrt(a * a + c * c + e * e);
    }
    if (k == "vx") return get(s.vel, b);
    if (k == "vy") return get(s.vel, b + 1);
    if (k == "vz") return get(s.vel, b + 2);
    if (k == "ax") return get(s.acc, b);
    if (k == "ay") return get(s.acc, b + 1);
    if (k == "az") return get(s.acc, b + 2);
    if (k == "x") return pos(b);
    if (k == "y") return pos(b + 1);
    if (k == "z") return pos(b + 2);
    if (k == "temp") return get(s.temperature, static_cast<std::size_t>(i));
    return 0.0;
}

namespace {

// A stress-type quantity from 6 stresses (xx yy zz xy yz zx) and the EPS.
double from_stress(const std::string& key, const double* st, double eps) {
    if (key == "eps") return eps;
    if (key == "vm") return von_mises(st);
    if (key == "pressure") return pressure(st);
    const int comp = stress_component(key);
    return comp >= 0 ? st[comp] : 0.0;
}

// Integration points selected by `point` among n: their indices (empty: none there).
std::vector<int> chosen_points(int point, int n, bool through_thickness) {
    if (n <= 0) return {};
    if (point >= 0) return point < n ? std::vector<int>{point} : std::vector<int>{};
    if (!through_thickness) {  // solids, beams: all (the mean)
        std::vector<int> all(static_cast<std::size_t>(n));
        for (int k = 0; k < n; ++k) all[static_cast<std::size_t>(k)] = k;
        return all;
    }
    // LS-DYNA's order (database manual, shell and thick-shell data): mid, inner, outer surface
    if (point == Quantity::kTop) return {std::min(2, n - 1)};
    if (point == Quantity::kBottom) return {std::min(1, n - 1)};
    return {0};
}

// History value number k (1-based) of key "histK", or 0 for other keys.
int history_number(const std::string& key) {
    return key.size() > 4 && key.compare(0, 4, "hist") == 0 ? std::stoi(key.substr(4)) : 0;
}

// Shell or thick-shell record: the quantity at the chosen layer(s) (stresses averaged first).
double layered_value(const Quantity& q, const impact3d::PlotLayout& L, const double* rec) {
    const std::vector<int> pts = chosen_points(q.point, L.layers, true);
    if (pts.empty()) return 0.0;
    if (const int h = history_number(q.key); h > 0) {
        if (L.layer_history < 0 || h > L.layer_words - L.layer_history) return 0.0;
        double v = 0;
        for (int p : pts) v += rec[static_cast<std::ptrdiff_t>(p) * L.layer_words + L.layer_history + h - 1] / pts.size();
        return v;
    }
    double st[6] = {0, 0, 0, 0, 0, 0}, eps = 0;
    for (int p : pts) {
        const double* v = rec + static_cast<std::ptrdiff_t>(p) * L.layer_words;
        if (L.layer_stress >= 0)
            for (int k = 0; k < 6; ++k) st[k] += v[L.layer_stress + k] / pts.size();
        if (L.layer_eps >= 0) eps += v[L.layer_eps] / pts.size();
    }
    return from_stress(q.key, st, eps);
}

}  // namespace

double element_value(const Quantity& q, const impact3d::PlotGeometry& g, const impact3d::PlotLayout& L,
                     const impact3d::PlotState& s, int e) {
    const ElementRef r = element_ref(g, e);
    const std::size_t i = static_cast<std::size_t>(r.index);
    switch (r.family) {
        case Family::Solid: {
            if (q.key == "thickness" || q.key == "axial_force") return 0.0;
            const std::size_t nv = static_cast<std::size_t>(L.solid_points) * L.solid_point_words;
            if (const int h = history_number(q.key); h > 0) {
                if (h > L.solid_history || s.solid_vars.size() < nv * (i + 1)) return 0.0;
                const std::vector<int> pts = chosen_points(q.point, L.solid_points, false);
                double v = 0;
                for (int p : pts) v += s.solid_vars[nv * i + static_cast<std::size_t>(p) * L.solid_point_words + 6 + h] / pts.size();
                return v;
            }
            if (q.point < 0 || s.solid_vars.size() < nv * (i + 1)) {
                if (q.point > 0) return 0.0;  // a single point: only point 1 is there
                if (s.stress.size() < 6 * (i + 1)) return q.key == "eps" ? get(s.eps, i) : 0.0;
                return from_stress(q.key, &s.stress[6 * i], get(s.eps, i));
            }
            if (q.point >= L.solid_points) return 0.0;
            const double* v = &s.solid_vars[nv * i + static_cast<std::size_t>(q.point) * L.solid_point_words];
            return from_stress(q.key, v, v[6]);
        }
        case Family::ThickShell: {
            const std::size_t nv = s.tshell_vars.size() / std::max<std::size_t>(1, g.tshell_material.size());
            if (nv == 0 || q.key == "thickness" || q.key == "axial_force") return 0.0;
            return layered_value(q, L, &s.tshell_vars[nv * i]);
        }
        case Family::Shell: {
            const std::size_t nv = s.shell_vars.size() / std::max<std::size_t>(1, g.shell_material.size());
            if (nv == 0 || q.key == "axial_force") return 0.0;
            const double* rec = &s.shell_vars[nv * i];
            if (q.key == "thickness") return L.shell_thickness >= 0 ? rec[L.shell_thickness] : 0.0;
            return layered_value(q, L, rec);
        }
        case Family::Beam: {
            const std::size_t nv = s.beam_vars.size() / std::max<std::size_t>(1, g.beam_material.size());
            if (nv == 0 || q.key == "thickness") return 0.0;
            const double* rec = &s.beam_vars[nv * i];
            if (q.key == "axial_force") return rec[0];
            const std::vector<int> pts = chosen_points(q.point, L.beam_points, false);
            if (pts.empty()) return 0.0;
            // a point's words in LS-DYNA's order: shear stresses rs and tr, axial stress,
            // plastic strain, axial strain
            double ax = 0, t1 = 0, t2 = 0, eps = 0;
            for (int p : pts) {
                const double* v = rec + 6 + 5 * p;
                t1 += v[0] / pts.size();
                t2 += v[1] / pts.size();
                ax += v[2] / pts.size();
                eps += v[3] / pts.size();
            }
            const double st[6] = {ax, 0, 0, t1, 0, t2};
            return from_stress(q.key, st, eps);
        }
    }
    return 0.0;
}

std::vector<double> element_values(const Quantity& q, const impact3d::PlotGeometry& g,
                                   const impact3d::PlotLayout& L, const impact3d::PlotState& s) {
    const int ne = num_elements(g);
    std::vector<double> out(static_cast<std::size_t>(ne));
    for (int e = 0; e < ne; ++e) out[static_cast<std::size_t>(e)] = element_value(q, g, L, s, e);
    return out;
}

std::vector<double> node_values(const Quantity& q, const impact3d::PlotGeometry& g,
                                const impact3d::PlotState& s) {
    const int nn = g.num_nodes();
    std::vector<double> out(nn);
    for (int i = 0; i < nn; ++i) out[i] = point_value(q, g, s, i);
    return out;
}

std::string base_unit_name(Dim d, const Units& u) {
    if (!u.si) return "";
    switch (d) {
        case Dim::Time: return "s";
        case Dim::Length: return "m";
        case Dim::Velocity: return "m/s";
        case Dim::Acceleration: return "m/s²";
        case Dim::Stress: return "Pa";
        case Dim::Energy: return "J";
        case Dim::Mass: return "kg";
        case Dim::Momentum: return "kg m/s";
        case Dim::Force: return "N";
        case Dim::Strain:
        case Dim::None: return "";
    }
    return "";
}

DisplayUnit display_unit(Dim d, double max_abs, const Units& u) {
    DisplayUnit du;
    du.name = base_unit_name(d, u);
    if (!u.si) return du;
    const bool prefixable = d == Dim::Time || d == Dim::Length || d == Dim::Stress || d == Dim::Energy || d == Dim::Force;
    if (!prefixable || !(max_abs > 0) || !std::isfinite(max_abs)) return du;
    struct P { double f; const char* p; };
    static const P kPrefix[] = {{1e-9, "G"}, {1e-6, "M"}, {1e-3, "k"}, {1.0, ""},
                                {1e3, "m"}, {1e6, "µ"}, {1e9, "n"}};
    for (const auto& p : kPrefix) {
        if (d == Dim::Length && (p.f < 1.0 || p.f > 1e3)) continue;  // m or mm
        if (d == Dim::Time && p.f < 1.0) continue;                   // s, ms, µs, ns
        if (d == Dim::Stress && p.f > 1.0) continue;                 // Pa, kPa, MPa, GPa
        if (d == Dim::Force && p.f > 1.0) continue;                  // N, kN, MN, GN
        const double v = max_abs * p.f;
        if (v >= 1.0 && v < 1000.0) {
            du.factor = p.f;
            du.name = std::string(p.p) + du.name;
            return du;
        }
    }
    // outside the prefix range: the smallest/largest admissible prefix
    if (d == Dim::Length && max_abs < 1.0) { du.factor = 1e3; du.name = "mm"; }
    if (d == Dim::Time && max_abs < 1e-9) { du.factor = 1e9; du.name = "ns"; }
    return du;
}

std::string format_number(double v, double step) {
    char buf[64];
    step = std::fabs(step);
    if (v == 0.0) return "0";
    const double av = std::fabs(v);
    if (!(step > 0)) step = av;
    if (av >= 1e6 || (av < 1e-3 && step < 1e-3)) {
        std::snprintf(buf, sizeof buf, "%.3e", v);
        return buf;
    }
    int dec = static_cast<int>(2 - std::floor(std::log10(step) + 1e-9));
    dec = std::max(0, std::min(dec, 6));
    if (std::fabs(v) < 0.5 * std::pow(10.0, -dec)) v = 0.0;  // no "-0.00"
    std::snprintf(buf, sizeof buf, "%.*f", dec, v);
    return buf;
}

std::string format_tick(double v, double step) {
    char buf[64];
    step = std::fabs(step);
    if (v == 0.0 || !(step > 0)) return "0";
    if (step >= 1e6 || step < 1e-4) {
        std::snprintf(buf, sizeof buf, "%.3g", v);
        return buf;
    }
    int dec = static_cast<int>(-std::floor(std::log10(step) + 1e-9));
    dec = std::max(0, std::min(dec, 6));
    if (std::fabs(v) < 0.5 * std::pow(10.0, -dec)) v = 0.0;
    std::snprintf(buf, sizeof buf, "%.*f", dec, v);
    return buf;
}

std::string format_time(double t, double t_max, const Units& u) {
    const DisplayUnit du = display_unit(Dim::Time, std::max(std::fabs(t_max), std::fabs(t)), u);
    char buf[64];
    const double v = t * du.factor;
    if (!u.si) {
        std::snprintf(buf, sizeof buf, "%.4g", t);
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%.1f %s", v, du.name.c_str());
    return buf;
}

}  // namespace postimpact
