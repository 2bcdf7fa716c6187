// Result quantities of the plot states (fringe and time-history variables), their names,
// dimensions and display units.
#pragma once

#include <string>
#include <vector>

#include "common/plot_database.h"

namespace postimpact {

enum class Dim { None, Time, Length, Velocity, Acceleration, Stress, Energy, Strain, Mass, Momentum, Force };

struct Quantity {
    std::string key;     // command name: eps, vm, pressure, sxx, ..., disp, dx, vel, vz, ...
    std::string label;   // "Effective plastic strain"
    enum class Where { Element, Node } where = Where::Element;
    Dim dim = Dim::None;
    // Where in the element (key suffix "@top", "@bottom", "@mid", "@ip3"): shells and thick
    // shells: the outer ("top"), inner ("bottom") or mid surface (default) values LS-DYNA
    // writes as the first three through-thickness blocks, or block k in the file's order (1 mid,
    // 2 inner, 3 outer, then the further points); solids: the mean over the integration points
    // (default) or point k; beams: the mean over the points (default) or point k.
    static constexpr int kMid = -1, kTop = -2, kBottom = -3;
    int point = kMid;    // kMid, kTop, kBottom, or a 0-based integration point
};

// Fringe / element / node quantities by key (also accepts a few aliases: "plastic_strain",
// "von_mises", "p", "displacement", "velocity").  Returns false for an unknown key.
bool find_quantity(const std::string& key, Quantity& q);
// All keys, for messages and --help.
std::string quantity_keys();

double von_mises(const double* s);   // s: xx yy zz xy yz zx
double pressure(const double* s);    // -(xx+yy+zz)/3, positive in compression

// Per-element values (numelh) of an element quantity in state s (solids).
std::vector<double> element_values(const Quantity& q, const impact3d::PlotState& s);
// Values of every element of every family (elements.h numbering: solids, thick shells, beams,
// shells), read through the database's record layout.  Shells: stresses in the database's
// (global) axes at the chosen point; beams: sxx the axial stress, sxy/szx the two shear
// stresses, eps the plastic strain, axial_force; thickness: shells.
std::vector<double> element_values(const Quantity& q, const impact3d::PlotGeometry& g,
                                   const impact3d::PlotLayout& L, const impact3d::PlotState& s);
double element_value(const Quantity& q, const impact3d::PlotGeometry& g, const impact3d::PlotLayout& L,
                     const impact3d::PlotState& s, int e);
// Per-node values (numnp) of a node quantity.
std::vector<double> node_values(const Quantity& q, const impact3d::PlotGeometry& g,
                                const impact3d::PlotState& s);
// One value of node or element `index` (0-based).
double point_value(const Quantity& q, const impact3d::PlotGeometry& g, const impact3d::PlotState& s,
                   int index);

// Display units.  SI databases (the IMPACT-3D decks) get unit names and an SI prefix chosen
// from the magnitude of the values (Pa -> MPa, s -> µs); "none" shows raw numbers.
struct Units {
    bool si = true;
};
struct DisplayUnit {
    double factor = 1.0;   // displayed = value * factor
    std::string name;      // "MPa", "µs", "" (dimensionless or unknown)
};
DisplayUnit display_unit(Dim d, double max_abs, const Units& u);
std::string base_unit_name(Dim d, const Units& u);  // "Pa", "s", ... ("" for none)

// Number formatting for labels: enough decimals to resolve `step`.
std::string format_number(double v, double step);
// Tick label: as many decimals as the (1, 2 or 5 x 10^k) tick spacing needs.
std::string format_tick(double v, double step);
// "80.0 µs" style time text.
std::string format_time(double t, double t_max, const Units& u);

}  // namespace postimpact
