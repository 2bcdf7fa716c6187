#include "postimpact/mesh_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

namespace postimpact {

namespace {

// LS-DYNA hexahedron node order: 1-4 bottom, 5-8 top; faces listed with outward orientation for
// a positively oriented element.
constexpr int kHexFaces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                 {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};

struct Key {
    std::array<int, 4> n;
    bool operator==(const Key&) const = default;
};
struct KeyHash {
    std::size_t operator()(const Key& k) const {
        std::size_t h = 1469598103934665603ull;
        for (int v : k.n) h = (h ^ static_cast<std::size_t>(static_cast<unsigned>(v))) * 1099511628211ull;
        return h;
    }
};

}  // namespace

std::vector<SurfaceFace> exterior_faces(const impact3d::PlotGeometry& g,
                                        const std::vector<unsigned char>& alive) {
    const int ne = g.num_hexes();
    const auto& x = g.x0;
    struct Cand { SurfaceFace f; Key key; };
    std::vector<Cand> cands;
    cands.reserve(static_cast<std::size_t>(ne) * 6);
    std::unordered_map<Key, int, KeyHash> count;
    count.reserve(static_cast<std::size_t>(ne) * 6);
    for (int e = 0; e < ne; ++e) {
        if (!alive.empty() && !alive[e]) continue;
        const int* hn = &g.hex_nodes[8 * static_cast<std::size_t>(e)];
        double c[3] = {0, 0, 0};
        for (int k = 0; k < 8; ++k)
            for (int d = 0; d < 3; ++d) c[d] += x[3 * hn[k] + d] / 8.0;
        for (const auto& fd : kHexFaces) {
            // distinct nodes in cyclic order
            std::array<int, 4> v{};
            int m = 0;
            for (int k = 0; k < 4; ++k) {
                const int node = hn[fd[k]];
                bool dup = false;
                for (int j = 0; j < m; ++j) dup = dup || v[j] == node;
                if (!dup) v[m++] = node;
            }
            if (m < 3) continue;  // collapsed face of a degenerate element
            Key key{{-1, -1, -1, -1}};
            std::copy(v.begin(), v.begin() + m, key.n.begin());
            for (int a = 1; a < m; ++a)  // insertion sort of the (up to 4) node numbers
                for (int b = a; b > 0 && key.n[b - 1] > key.n[b]; --b) std::swap(key.n[b - 1], key.n[b]);
            // outward orientation: the face normal points away from the element centroid
            double fc[3] = {0, 0, 0};
            for (int k = 0; k < m; ++k)
                for (int d = 0; d < 3; ++d) fc[d] += x[3 * v[k] + d] / m;
            double nrm[3] = {0, 0, 0};
            for (int k = 0; k < m; ++k) {
                const double* a = &x[3 * v[k]];
                const double* b = &x[3 * v[(k + 1) % m]];
                nrm[0] += (a[1] - b[1]) * (a[2] + b[2]);
                nrm[1] += (a[2] - b[2]) * (a[0] + b[0]);
                nrm[2] += (a[0] - b[0]) * (a[1] + b[1]);
            }
            const double dot = nrm[0] * (fc[0] - c[0]) + nrm[1] * (fc[1] - c[1]) + nrm[2] * (fc[2] - c[2]);
            if (dot < 0) std::reverse(v.begin(), v.begin() + m);
            if (m == 3) v[3] = v[2];
            cands.push_back({SurfaceFace{v, m, e}, key});
            ++count[key];
        }
    }
    std::vector<SurfaceFace> out;
    for (const auto& c : cands)
        if (count[c.key] == 1) out.push_back(c.f);
    return out;
}

Mirror parse_mirror(const std::string& s) {
    Mirror m;
    if (s == "none" || s == "off" || s.empty()) return m;
    for (char c : s) {
        if (c == 'x' || c == 'X') m.axis[0] = true;
        else if (c == 'y' || c == 'Y') m.axis[1] = true;
        else if (c == 'z' || c == 'Z') m.axis[2] = true;
        else if (c == ',' || c == ' ') continue;
        else throw std::invalid_argument("mirror: expected none or letters x, y, z, found '" + s + "'");
    }
    return m;
}

std::string mirror_name(const Mirror& m) {
    std::string s;
    if (m.axis[0]) s += 'x';
    if (m.axis[1]) s += 'y';
    if (m.axis[2]) s += 'z';
    return s.empty() ? "none" : s;
}

std::vector<std::array<double, 3>> mirror_copies(const Mirror& m) {
    std::vector<std::array<double, 3>> out{{1.0, 1.0, 1.0}};
    for (int a = 0; a < 3; ++a) {
        if (!m.axis[a]) continue;
        const std::size_t n = out.size();
        for (std::size_t i = 0; i < n; ++i) {
            auto s = out[i];
            s[a] = -1.0;
            out.push_back(s);
        }
    }
    return out;
}

std::vector<SurfaceFace> drop_symmetry_faces(const std::vector<SurfaceFace>& faces,
                                             const impact3d::PlotGeometry& g, const Mirror& m,
                                             double tol) {
    if (!m.any()) return faces;
    if (tol <= 0) {
        double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
        for (std::size_t i = 0; i + 2 < g.x0.size(); i += 3)
            for (int d = 0; d < 3; ++d) {
                lo[d] = std::min(lo[d], g.x0[i + d]);
                hi[d] = std::max(hi[d], g.x0[i + d]);
            }
        double size = 0;
        for (int d = 0; d < 3; ++d) size = std::max(size, hi[d] - lo[d]);
        tol = 1e-6 * (size > 0 ? size : 1.0);
    }
    std::vector<SurfaceFace> out;
    out.reserve(faces.size());
    for (const auto& f : faces) {
        bool on_plane = false;
        for (int a = 0; a < 3 && !on_plane; ++a) {
            if (!m.axis[a]) continue;
            bool all = true;
            for (int k = 0; k < f.count; ++k) all = all && std::fabs(g.x0[3 * f.nodes[k] + a]) <= tol;
            on_plane = all;
        }
        if (!on_plane) out.push_back(f);
    }
    return out;
}

}  // namespace postimpact
