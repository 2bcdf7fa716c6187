// Fringe colour map (blue - cyan - green - yellow - red, in discrete bands as LS-PrePost and
// GRIZ draw them) and the mapping of values to the [0, 1] fringe coordinate.
#pragma once

#include <vector>

#include "common/plot_database.h"
#include "postimpact/image.h"
#include "postimpact/mesh_surface.h"
#include "postimpact/quantities.h"

namespace postimpact {

// Continuous map of t in [0, 1].
Rgb colormap(double t);
// Colour of band i of n (the band's mid value).
Rgb band_color(int i, int n);

struct FringeRange {
    double lo = 0, hi = 1;
};

// Fringe values on the nodes: node quantities directly; element quantities averaged over the
// live elements around each node (smooth fringes).  Nodes with no live element get the
// smallest value.
// Elements of every family count (elements.h); L: the database's record layout.
std::vector<double> nodal_fringe(const Quantity& q, const impact3d::PlotGeometry& g,
                                 const impact3d::PlotState& s,
                                 const impact3d::PlotLayout& L = impact3d::PlotLayout{});
// Range of the values shown on the given faces: node values (smooth) or element values (flat).
void extend_range(FringeRange& r, bool& have, const std::vector<SurfaceFace>& faces,
                  const std::vector<double>& node_vals, const std::vector<double>& elem_vals);
// Fringe coordinate of a value: (v - lo)/(hi - lo), clamped to [0, 1].
double fringe_coord(double v, const FringeRange& r);

}  // namespace postimpact
