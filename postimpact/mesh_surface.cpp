#include "postimpact/mesh_surface.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "postimpact/elements.h"

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

std::vector<SurfaceFace> model_faces(const impact3d::PlotGeometry& g, const impact3d::PlotState& s) {
    std::vector<SurfaceFace> faces = exterior_faces(g, s.alive);
    if (g.num_tshells() > 0) {
        impact3d::PlotGeometry t;  // the thick shells as a hexahedron mesh of their own
        t.x0 = g.x0;
        t.hex_nodes = g.tshell_nodes;
        t.hex_material = g.tshell_material;
        const int off = family_offset(g, Family::ThickShell);
        for (SurfaceFace f : exterior_faces(t, s.tshell_alive)) {
            f.element += off;
            faces.push_back(f);
        }
    }
    const int nb = g.num_beams(), boff = family_offset(g, Family::Beam);
    for (int b = 0; b < nb; ++b) {
        if (!element_alive(s, g, boff + b)) continue;
        SurfaceFace f;
        f.nodes = {g.beam_nodes[2 * static_cast<std::size_t>(b)], g.beam_nodes[2 * static_cast<std::size_t>(b) + 1], -1, -1};
        f.count = 2;
        f.element = boff + b;
        faces.push_back(f);
    }
    const int ns = g.num_shells(), soff = family_offset(g, Family::Shell);
    for (int e = 0; e < ns; ++e) {
        if (!element_alive(s, g, soff + e)) continue;
        const int* n = &g.shell_nodes[4 * static_cast<std::size_t>(e)];
        SurfaceFace f;
        f.nodes = {n[0], n[1], n[2], n[3]};
        f.count = n[3] == n[2] ? 3 : 4;
        f.element = soff + e;
        faces.push_back(f);
    }
    return faces;
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
    const int volume_elements = family_offset(g, Family::Beam);  // solids and thick shells
    for (const auto& f : faces) {
        bool on_plane = false;
        for (int a = 0; a < 3 && !on_plane && f.element < volume_elements; ++a) {
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
