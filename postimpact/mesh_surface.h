// Exterior surface of a hexahedron mesh: the faces of live elements that no other live element
// shares (degenerate hexahedra -- wedges, tetrahedra with repeated nodes -- give triangles or no
// face), oriented outward; and the reflected copies that show a symmetric part model whole.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "common/plot_database.h"

namespace postimpact {

struct SurfaceFace {
    std::array<int, 4> nodes{};  // 0-based node indices, counter-clockwise seen from outside
    int count = 4;               // 3 (triangle) or 4; 2: a beam, drawn as a line
    int element = 0;             // 0-based element index (model_faces: elements.h numbering)
};

// alive: per element 1/0, or empty (all alive).  Faces come out in a fixed order (element order,
// then face order), so the result is deterministic.
std::vector<SurfaceFace> exterior_faces(const impact3d::PlotGeometry& g,
                                        const std::vector<unsigned char>& alive = {});

// What a picture shows of every element family of state s, live elements only, element indices
// in the numbering of elements.h: the exterior faces of the solids and of the thick shells,
// every shell (a quadrilateral, or a triangle when n3 == n4) and every beam (a line, count 2).
std::vector<SurfaceFace> model_faces(const impact3d::PlotGeometry& g, const impact3d::PlotState& s);

// Reflection across coordinate planes: axis k set = reflect across the plane x_k = 0.
struct Mirror {
    std::array<bool, 3> axis{false, false, false};
    bool any() const { return axis[0] || axis[1] || axis[2]; }
};
// "none", or letters of the reflected coordinates: "x", "xy", "xyz", ...  Throws
// std::invalid_argument.
Mirror parse_mirror(const std::string& s);
std::string mirror_name(const Mirror& m);
// Sign vectors of all copies (the original first): 2^(number of axes) entries.
std::vector<std::array<double, 3>> mirror_copies(const Mirror& m);
// Drops the faces that lie on a reflection plane (all nodes within tol of it in the initial
// coordinates x0): after reflection they are interior.  tol <= 0: 1e-6 of the model size.
std::vector<SurfaceFace> drop_symmetry_faces(const std::vector<SurfaceFace>& faces,
                                             const impact3d::PlotGeometry& g, const Mirror& m,
                                             double tol = 0.0);

}  // namespace postimpact
