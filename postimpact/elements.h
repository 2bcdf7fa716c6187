// All element families of a plot database under one element numbering: solids, thick shells,
// beams, shells (in that order), so that faces, fringes, histories and the material plot address
// any element by one 0-based index.
#pragma once

#include <vector>

#include "common/plot_database.h"

namespace postimpact {

enum class Family { Solid, ThickShell, Beam, Shell };

struct ElementRef {
    Family family = Family::Solid;
    int index = 0;  // within its family
};

int num_elements(const impact3d::PlotGeometry& g);
ElementRef element_ref(const impact3d::PlotGeometry& g, int e);
int family_offset(const impact3d::PlotGeometry& g, Family f);
const char* family_name(Family f);                  // "solid", "thick shell", "beam", "shell"
int element_user_id(const impact3d::PlotGeometry& g, int e);
int element_material(const impact3d::PlotGeometry& g, int e);
// The element's nodes (0-based) and their count: 8, 8, 2 or 4.
const int* element_nodes(const impact3d::PlotGeometry& g, int e, int& count);
// 1 alive, 0 deleted (empty flag vectors: alive).
bool element_alive(const impact3d::PlotState& s, const impact3d::PlotGeometry& g, int e);

}  // namespace postimpact
