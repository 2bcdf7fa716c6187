#include "postimpact/fringe.h"

#include <algorithm>
#include <cmath>

#include "postimpact/elements.h"

namespace postimpact {

Rgb colormap(double t) {
    t = std::clamp(t, 0.0, 1.0);
    // piecewise linear through blue, cyan, green, yellow, red
    static const double k[5][3] = {{0, 0, 255}, {0, 255, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}};
    const double s = t * 4.0;
    const int i = std::min(3, static_cast<int>(s));
    const double f = s - i;
    auto c = [&](int j) { return static_cast<std::uint8_t>(std::lround(k[i][j] + f * (k[i + 1][j] - k[i][j]))); };
    return {c(0), c(1), c(2)};
}

Rgb band_color(int i, int n) {
    if (n <= 1) return colormap(1.0);
    return colormap(static_cast<double>(i) / (n - 1));
}

std::vector<double> nodal_fringe(const Quantity& q, const impact3d::PlotGeometry& g,
                                 const impact3d::PlotState& s, const impact3d::PlotLayout& L) {
    if (q.where == Quantity::Where::Node) return node_values(q, g, s);
    const std::vector<double> ev = element_values(q, g, L, s);
    const int nn = g.num_nodes(), ne = num_elements(g);
    std::vector<double> sum(nn, 0.0);
    std::vector<int> cnt(nn, 0);
    for (int e = 0; e < ne; ++e) {
        if (!element_alive(s, g, e)) continue;
        int count = 0;
        const int* hn = element_nodes(g, e, count);
        for (int k = 0; k < count; ++k) {
            bool dup = false;  // a degenerate element counts once per node
            for (int j = 0; j < k; ++j) dup = dup || hn[j] == hn[k];
            if (dup) continue;
            sum[hn[k]] += ev[e];
            ++cnt[hn[k]];
        }
    }
    double lo = 0;
    bool have = false;
    for (int i = 0; i < nn; ++i)
        if (cnt[i]) {
            sum[i] /= cnt[i];
            lo = have ? std::min(lo, sum[i]) : sum[i];
            have = true;
        }
    for (int i = 0; i < nn; ++i)
        if (!cnt[i]) sum[i] = lo;
    return sum;
}

void extend_range(FringeRange& r, bool& have, const std::vector<SurfaceFace>& faces,
                  const std::vector<double>& node_vals, const std::vector<double>& elem_vals) {
    auto add = [&](double v) {
        if (!std::isfinite(v)) return;
        if (!have) { r.lo = r.hi = v; have = true; }
        r.lo = std::min(r.lo, v);
        r.hi = std::max(r.hi, v);
    };
    for (const auto& f : faces) {
        if (!elem_vals.empty()) add(elem_vals[f.element]);
        else
            for (int k = 0; k < f.count; ++k) add(node_vals[f.nodes[k]]);
    }
}

double fringe_coord(double v, const FringeRange& r) {
    const double d = r.hi - r.lo;
    if (!(d > 0)) return 0.5;
    return std::clamp((v - r.lo) / d, 0.0, 1.0);
}

}  // namespace postimpact
