// Time histories from the plot states: global and per-material energies, node displacement /
// velocity / acceleration components, element stresses, plastic strain, pressure, von Mises.
#pragma once

#include <string>
#include <vector>

#include "postimpact/database.h"
#include "postimpact/plot2d.h"
#include "postimpact/quantities.h"

namespace postimpact {

struct HistoryCurve {
    enum class Kind { Global, Material, Node, Element, Wall, Interface, Mili } kind = Kind::Global;
    int id = 0;           // user node / element id, material, rigid-wall or interface number
    std::string var;      // global: ke ie te vx vy vz; material: ie ke hg mass mx my mz;
                          // wall: fn (normal force); interface: fx fy fz fm (slave side);
                          // node / element: a quantity key (quantities.h)
    int family = -1;      // element: an elements.h Family (groups solid, tshell, beam, shell),
                          // -1 (group element): the first family that has the id
                          // Mili: "CLASS|LEAF[:CONTAINER][@POINT]", a variable of the file by
                          // its name for the object of the class with label id (POINT from 1)
};

// Parses curve groups:  energy | global VAR.. | material ID VAR.. | node ID VAR.. |
// element ID VAR.. | wall N fn | interface N fx|fy|fz|fm.. | mili CLASS LABEL VAR.. (Mili
// databases: the file's own variables, VAR = LEAF[:CONTAINER][@POINT], e.g. mili beam 1 tor,
// mili shell 5 sx:stress_in, mili beam 2 sx@2)  ("energy": kinetic, internal, total and the hourglass energy of every
// material, plus per-material internal/kinetic energy when there are several).  Throws
// std::invalid_argument with the offending word.
std::vector<HistoryCurve> parse_history(const std::vector<std::string>& words, const Database& db);

struct HistoryData {
    std::vector<double> time;
    std::vector<Series> series;   // raw values (database units)
    std::vector<Dim> dims;
};
HistoryData extract_history(Database& db, const std::vector<HistoryCurve>& curves);

// Writes the PNG plot and the CSV (same data, raw values, one row per state).
void write_csv(const std::string& path, const HistoryData& h, const Units& u);
Image plot_history(const HistoryData& h, const std::string& title, const Units& u, int width,
                   int height, const Font& font);

}  // namespace postimpact
