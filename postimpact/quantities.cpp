#include "postimpact/quantities.h"

#include <cmath>
#include <cstdio>
#include <map>

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
    if (auto it = kAliases.find(key); it != kAliases.end()) key = it->second;
    for (const auto& e : kTable)
        if (key == e.key) {
            q = Quantity{e.key, e.label, e.where, e.dim};
            return true;
        }
    return false;
}

std::string quantity_keys() {
    std::string s;
    for (const auto& e : kTable) s += (s.empty() ? "" : " ") + std::string(e.key);
    return s;
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
    auto d = [&](int k) { return get(s.coords, b + k) - get(g.x0, b + k); };
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
    if (k == "x") return get(s.coords, b);
    if (k == "y") return get(s.coords, b + 1);
    if (k == "z") return get(s.coords, b + 2);
    return 0.0;
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
