#include "postimpact/summary.h"

#include "postimpact/elements.h"
#include "postimpact/quantities.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

#include "postimpact/database.h"

namespace postimpact {

namespace {

std::string num(double v) {
    char b[40];
    std::snprintf(b, sizeof b, "%.17g", v);
    return b;
}

std::string g6(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

// The cycle count of the run from its printed output: the last " cycles N, elapsed" line.
long long read_cycles(const std::string& path) {
    std::ifstream f(path);
    long long cycles = -1;
    for (std::string line; std::getline(f, line);) {
        const auto p = line.find_first_not_of(' ');
        if (p == std::string::npos || line.compare(p, 7, "cycles ") != 0) continue;
        long long n = 0;
        if (std::sscanf(line.c_str() + p + 7, "%lld,", &n) == 1 && line.find(", elapsed") != std::string::npos) cycles = n;
    }
    return cycles;
}

}  // namespace

const std::string* Summary::find(const std::string& key) const {
    for (const auto& [k, v] : items)
        if (k == key) return &v;
    return nullptr;
}

Summary summarize(const std::string& root, const std::string& printed) {
    Database db(root);
    const int ns = db.num_states();
    if (ns == 0) throw std::runtime_error(root + ": the database has no state");
    const auto& geo = db.geometry();
    Summary s;
    auto put = [&](const std::string& k, const std::string& v) { s.items.emplace_back(k, v); };
    put("title", geo.title);
    put("states", std::to_string(ns));
    put("nodes", std::to_string(geo.num_nodes()));
    put("solids", std::to_string(geo.num_hexes()));
    // other families only when there are (older summaries lack them)
    if (geo.num_tshells()) put("thick_shells", std::to_string(geo.num_tshells()));
    if (geo.num_beams()) put("beams", std::to_string(geo.num_beams()));
    if (geo.num_shells()) put("shells", std::to_string(geo.num_shells()));
    const impact3d::PlotState first = db.state(0);
    const impact3d::PlotState last = db.state(ns - 1);
    put("time", num(last.time));
    std::string pr = printed;
    if (pr.empty()) {
        const auto cand = std::filesystem::path(root).parent_path() / "d3hsp";
        if (std::filesystem::exists(cand)) pr = cand.string();
    }
    if (!pr.empty()) {
        if (!std::ifstream(pr)) throw std::runtime_error("cannot read the printed file " + pr);
        const long long c = read_cycles(pr);
        if (c >= 0) put("cycles", std::to_string(c));
    }
    // Extents: length along z and radius about the z axis (the Taylor bar's final length and
    // mushroom radius), first and last state; the bounding box of the last state.
    struct Ext {
        double lo[3], hi[3], r;
    };
    // nodes of live solids only: a failed (deleted) solid and the nodes only it held are not
    // part of the shape
    auto live_nodes = [&](const impact3d::PlotState& st) {
        std::vector<char> live(static_cast<std::size_t>(geo.num_nodes()), 0);
        for (int e = 0; e < num_elements(geo); ++e)
            if (element_alive(st, geo, e)) {
                int count = 0;
                const int* n = element_nodes(geo, e, count);
                for (int j = 0; j < count; ++j) live[static_cast<std::size_t>(n[j])] = 1;
            }
        return live;
    };
    auto extents = [&](const impact3d::PlotState& st) {
        const std::vector<double>& c = st.coords.empty() ? geo.x0 : st.coords;  // IU 0: initial shape
        const std::vector<char> live = live_nodes(st);
        Ext e{};
        for (int a = 0; a < 3; ++a) e.lo[a] = INFINITY, e.hi[a] = -INFINITY;
        e.r = 0;
        for (std::size_t i = 0; i + 2 < c.size(); i += 3) {
            if (!live[i / 3]) continue;
            for (int a = 0; a < 3; ++a) e.lo[a] = std::min(e.lo[a], c[i + a]), e.hi[a] = std::max(e.hi[a], c[i + a]);
            e.r = std::max(e.r, std::sqrt(c[i] * c[i] + c[i + 1] * c[i + 1]));
        }
        return e;
    };
    const Ext e0 = extents(first), e1 = extents(last);
    put("length0", num(e0.hi[2] - e0.lo[2]));
    put("length", num(e1.hi[2] - e1.lo[2]));
    put("radius0", num(e0.r));
    put("radius", num(e1.r));
    const char* ax[3] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
        put(std::string(ax[a]) + "min", num(e1.lo[a]));
        put(std::string(ax[a]) + "max", num(e1.hi[a]));
    }
    // Largest effective plastic strain over all states (it never decreases; the last state's).
    double emax = 0;
    int eid = 0;
    int failed = 0;
    for (std::size_t k = 0; k < last.eps.size(); ++k) {
        if (!last.alive.empty() && !last.alive[k]) {
            ++failed;
            continue;
        }
        if (last.eps[k] > emax || eid == 0) emax = last.eps[k], eid = db.element_id(static_cast<int>(k));
    }
    // shells, thick shells, beams: EPS at the middle surface / mean over the beam's points
    int failed_other = 0;
    if (num_elements(geo) > geo.num_hexes()) {
        Quantity eps;
        find_quantity("eps", eps);
        for (int e = geo.num_hexes(); e < num_elements(geo); ++e) {
            if (!element_alive(last, geo, e)) {
                ++failed_other;
                continue;
            }
            const double v = element_value(eps, geo, db.layout(), last, e);
            if (v > emax || eid == 0) emax = v, eid = db.element_id(e);
        }
    }
    put("max_eps", num(emax));
    put("max_eps_element", std::to_string(eid));
    if (failed) put("failed_solids", std::to_string(failed));  // (only when there are: older summaries lack it)
    if (failed_other) put("failed_other_elements", std::to_string(failed_other));
    double hg = 0;
    for (double v : last.mat_hourglass_energy) hg += v;
    put("kinetic_energy", num(last.kinetic_energy));
    put("internal_energy", num(last.internal_energy));
    put("hourglass_energy", num(hg));
    put("total_energy", num(last.total_energy));
    put("initial_total_energy", num(first.total_energy));
    put("energy_ratio", num(first.total_energy != 0 ? last.total_energy / first.total_energy : 0.0));
    return s;
}

void write_summary(const Summary& s, std::ostream& out) {
    for (const auto& [k, v] : s.items) out << k << " " << v << "\n";
}

Summary read_summary(const std::string& path) {
    std::ifstream f(path);
    if (!f) throw std::runtime_error("cannot read summary " + path);
    Summary s;
    int ln = 0;
    std::set<std::string> seen;
    for (std::string line; std::getline(f, line);) {
        ++ln;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const auto p = line.find_first_not_of(' ');
        if (p == std::string::npos || line[p] == '#') continue;
        const auto sp = line.find(' ', p);
        const std::string k = line.substr(p, sp == std::string::npos ? std::string::npos : sp - p);
        const std::string v = sp == std::string::npos ? "" : line.substr(sp + 1);
        if (!seen.insert(k).second)
            throw std::runtime_error(path + ":" + std::to_string(ln) + ": key '" + k + "' given twice");
        s.items.emplace_back(k, v);
    }
    return s;
}

std::string summary_field(const std::string& k) {
    if (k == "title" || k == "max_eps_element") return "";
    if (k == "states" || k == "nodes" || k == "solids" || k == "failed_solids") return "exact";
    if (k == "time") return "time";
    if (k == "cycles") return "cycles";
    if (k == "max_eps") return "eps";
    if (k.find("energy") != std::string::npos) return "energy";  // the energies and energy_ratio
    return "coords";  // length, radius, extents
}

int compare_summaries(const Summary& a, const Summary& b, const Tolerances& tol, std::ostream& out,
                      const std::string& name_a, const std::string& name_b) {
    std::vector<std::string> keys;
    for (const auto& [k, v] : a.items) keys.push_back(k);
    for (const auto& [k, v] : b.items)
        if (!a.find(k)) keys.push_back(k);
    out << "compare-summary: A = " << name_a << "\n                 B = " << name_b << "\n\n";
    char line[512];
    std::snprintf(line, sizeof line, "%-21s %-7s %22s %22s %10s %10s %10s  %s\n", "key", "field", "A", "B", "|a-b|",
                  "rel", "allowed", "");
    out << line;
    int bad = 0;
    for (const auto& k : keys) {
        const std::string* va = a.find(k);
        const std::string* vb = b.find(k);
        const std::string field = summary_field(k);
        if (!va || !vb) {
            std::snprintf(line, sizeof line, "%-21s %-7s %22s %22s %10s %10s %10s  %s\n", k.c_str(), field.c_str(),
                          va ? va->c_str() : "(missing)", vb ? vb->c_str() : "(missing)", "", "", "",
                          field.empty() ? "" : "MISSING");
            out << line;
            if (!field.empty()) ++bad;
            continue;
        }
        if (field.empty()) {
            if (*va != *vb) out << k << ": A \"" << *va << "\", B \"" << *vb << "\" (not compared)\n";
            continue;
        }
        auto parse = [](const std::string& s, double& v) {
            std::size_t pos = 0;
            try { v = std::stod(s, &pos); } catch (...) { return false; }
            return pos == s.size();
        };
        double x = 0, y = 0;
        if (!parse(*va, x) || !parse(*vb, y)) {
            const bool same = *va == *vb;
            out << k << ": A \"" << *va << "\", B \"" << *vb << "\"" << (same ? "\n" : "  DIFFERENT (not numbers)\n");
            if (!same) ++bad;
            continue;
        }
        // The most specific tolerance line: summary.KEY, summary.FIELD, FIELD, default.
        Tolerance t;
        if (field != "exact") {
            if (auto it = tol.field.find("summary." + k); it != tol.field.end()) t = it->second;
            else if (auto it2 = tol.field.find("summary." + field); it2 != tol.field.end()) t = it2->second;
            else t = tol.get(field);
        }
        const double d = std::fabs(x - y), mag = std::max(std::fabs(x), std::fabs(y));
        const double allowed = t.abs + t.rel * mag;
        const bool out_of = std::isnan(x) || std::isnan(y) ? !(std::isnan(x) && std::isnan(y)) : d > allowed;
        if (out_of) ++bad;
        std::snprintf(line, sizeof line, "%-21s %-7s %22s %22s %10s %10s %10s  %s\n", k.c_str(), field.c_str(),
                      va->c_str(), vb->c_str(), g6(d).c_str(), g6(mag > 0 ? d / mag : 0.0).c_str(), g6(allowed).c_str(),
                      out_of ? "OUTSIDE" : "");
        out << line;
    }
    out << "\n";
    if (bad == 0) out << "result: SAME within tolerance (" << keys.size() << " keys)\n";
    else out << "result: DIFFERENT (" << bad << " keys outside tolerance or missing)\n";
    return bad == 0 ? 0 : 1;
}

}  // namespace postimpact
