// The DYNA3D fixed-format card tables (fixed_cards.h).  One entry a card and vintage; the
// columns of a field are written here and nowhere else.

#include "impact3d/input/fixed_cards.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace impact3d {

namespace {

using K = FieldKind;
using U = FieldUse;

constexpr FieldUse R = U::read;
constexpr FieldUse I = U::ignored;
constexpr FieldUse X = U::refused;

constexpr FieldKind S = K::strict_integer;

const char* const kNodeN[8] = {"node n1", "node n2", "node n3", "node n4", "node n5", "node n6", "node n7", "node n8"};
const char* const kListNode[16] = {"node 1", "node 2", "node 3", "node 4", "node 5", "node 6", "node 7", "node 8",
                                   "node 9", "node 10", "node 11", "node 12", "node 13", "node 14", "node 15", "node 16"};

// `count` fields of width `w` from column `c1`, named by `names`.
void add_run(FixedCardLayout& l, const char* const* names, int count, int c1, int w, FieldKind kind, const char* meaning) {
  for (int k = 0; k < count; ++k)
    l.fields.push_back({names[k], c1 + k * w, c1 + k * w + w - 1, kind, 0, R, nullptr, k == 0 ? meaning : ""});
}

// The element cards: id, material label, nodes (id width w: 8 large format, 5 small).
FixedCardLayout element_card(const char* id, int w, int nodes, const char* node_meaning) {
  FixedCardLayout l{id, "88 later", {
      {"element number", 1, w, S, 0, R, nullptr, "1..count, each once"},
      {"material number", w + 1, w + 5, S, 0, R, nullptr, "a material label of the deck"},
  }};
  add_run(l, kNodeN, nodes, w + 6, w, S, node_meaning);
  return l;
}

FixedCardLayout node_card(const char* id, int w) {
  return {id, "88 later", {
      {"node number", 1, w, S, 0, R, nullptr, "1..NUMNP, each once"},
      {"boundary code", w + 1, w + 5, K::integer, 0, R, nullptr, "0 free, 1-3 x y z, 4 x y, 5 y z, 6 z x, 7 all fixed (\"7.\" reads as 7)"},
      {"x", w + 6, w + 25, K::real, 0, R, nullptr, "coordinates"},
      {"y", w + 26, w + 45, K::real, 0, R, nullptr, ""},
      {"z", w + 46, w + 65, K::real, 0, R, nullptr, ""},
      {"rotational code", w + 66, w + 70, K::integer, 0, R, nullptr, "rotations fixed on shell and beam nodes, codes as above"},
  }};
}

// Material card 1, the title card and the node and element cards.
void add_model_cards(std::vector<FixedCardLayout>& t) {
  t.push_back({"material card 1", "88 later", {
      {"material number", 1, 5, S, 0, R, nullptr, "a label (elements refer to it)"},
      {"material type", 6, 10, S, 0, R, nullptr, "Material sets in deck-format.md (71: read as type 3)"},
      {"density", 11, 20, K::real, 0, R, nullptr, "mass density"},
      {"EOS type", 21, 25, S, 0, R, nullptr, "equation of state form (its cards after card 8)"},
      {"hourglass type", 26, 30, S, 1, R, nullptr, "1-5 (0: 1; 6-10 read as 5)"},
      {"hourglass coefficient", 31, 40, K::real, 0.10, R, nullptr, "(0: 0.10)"},
      {"bulk viscosity type", 41, 45, S, 1, R, nullptr, "1 only (0: 1)"},
      {"quadratic bulk viscosity Q1", 46, 55, K::real, 1.5, R, nullptr, "(0: 1.5)"},
      {"linear bulk viscosity Q2", 56, 65, K::real, 0.06, R, nullptr, "(0: 0.06)"},
      {"element type", 66, 70, S, 0, R, nullptr, "0 solid, 1 beam, 2 shell (3 thick shell refused)"},
      {"unused", 71, 75, S, 0, R, nullptr, "read as an integer, no meaning"},
      {"element formulation", 76, 80, S, 0, R, nullptr, "solids 0/1, shells 0/2 (Belytschko-Tsay), beams 0/1 (Hughes-Liu)"},
  }});
  t.push_back({"material title card", "88 later", {
      {"title", 1, 80, K::text, 0, R, nullptr, "material card 2: the material's title (INGRID: \"material type # 3 (...)\")"},
  }});
  t.push_back({"material property card", "88 later", {
      {"field 1", 1, 10, K::real, 0, R, nullptr, "material cards 3-8: each type's parameters where its table puts them (Material sets in deck-format.md)"},
      {"field 2", 11, 20, K::real, 0, R, nullptr, "a field no parameter of the type uses: warning 2006 when nonzero"},
      {"field 3", 21, 30, K::real, 0, R, nullptr, ""},
      {"field 4", 31, 40, K::real, 0, R, nullptr, ""},
      {"field 5", 41, 50, K::real, 0, R, nullptr, ""},
      {"field 6", 51, 60, K::real, 0, R, nullptr, ""},
      {"field 7", 61, 70, K::real, 0, R, nullptr, ""},
      {"field 8", 71, 80, K::real, 0, R, nullptr, ""},
  }});
  t.push_back(node_card("node card", 8));
  t.push_back(element_card("solid element card", 8, 8, "the hexahedron's nodes (degenerate patterns allowed)"));
  t.push_back(element_card("shell element card", 8, 4, "n4 blank or = n3: a triangle"));
  t.push_back({"shell thickness card", "88 later", {
      {"thickness t1", 1, 10, K::real, 0, R, nullptr, "nodal thicknesses (all blank: the section's T1-T4)"},
      {"thickness t2", 11, 20, K::real, 0, R, nullptr, ""},
      {"thickness t3", 21, 30, K::real, 0, R, nullptr, ""},
      {"thickness t4", 31, 40, K::real, 0, R, nullptr, ""},
  }});
  t.push_back({"beam integration rule header card", "88 later", {
      {"number of points", 1, 5, S, 0, R, nullptr, "points of the rule (control card 8 field 5 at most)"},
      {"rule area factor", 6, 15, K::real, 0, R, nullptr, "read, not used (the weights sum to 4)"},
  }});
  t.push_back({"beam integration point card", "88 later", {
      {"s", 1, 10, K::real, 0, R, nullptr, "point in [-1, 1]"},
      {"t", 11, 20, K::real, 0, R, nullptr, "point in [-1, 1]"},
      {"weight", 21, 30, K::real, 0, R, nullptr, "the weights of a rule sum to 4"},
  }});
}

// The cards after the elements: load curves, loads, stonewalls, initial velocities, segments.
void add_load_cards(std::vector<FixedCardLayout>& t) {
  t.push_back({"load curve header card", "88 later", {
      {"curve number", 1, 5, S, 0, R, nullptr, "1..NUMLC, each once"},
      {"NPTS", 6, 10, S, 0, R, nullptr, "points (a card each, at least 2)"},
  }});
  t.push_back({"load curve point card", "88 later", {
      {"time", 1, 10, K::real, 0, R, nullptr, "increasing"},
      {"value", 11, 20, K::real, 0, R, nullptr, ""},
  }});
  t.push_back({"nodal load card", "88 later", {
      {"node", 1, 8, S, 0, R, nullptr, "node number"},
      {"direction", 9, 13, S, 0, R, nullptr, "1-3 x y z (4-6 moments refused)"},
      {"load curve", 14, 18, S, 0, R, nullptr, "load curve number"},
      {"scale factor", 19, 28, K::real, 1, R, nullptr, "(blank: 1)"},
  }});
  t.push_back({"stonewall card", "88 later", {
      {"NSN", 1, 5, S, 0, R, nullptr, "slave nodes listed after the wall's cards (0: all nodes)"},
      {"moving flag", 6, 10, S, 0, R, nullptr, "0 fixed, 1 moving (the moving stonewall card follows)"},
      {"XT", 11, 20, K::real, 0, R, nullptr, "tail of the outward normal: a point of the wall"},
      {"YT", 21, 30, K::real, 0, R, nullptr, ""},
      {"ZT", 31, 40, K::real, 0, R, nullptr, ""},
      {"XH", 41, 50, K::real, 0, R, nullptr, "head of the normal"},
      {"YH", 51, 60, K::real, 0, R, nullptr, ""},
      {"ZH", 61, 70, K::real, 0, R, nullptr, ""},
      {"FRIC", 71, 80, K::real, 0, R, nullptr, "0 frictionless, 1 stick, between: Coulomb"},
  }});
  t.push_back({"moving stonewall card", "88 later", {
      {"MASS", 1, 10, K::real, 0, R, nullptr, "IMPACT-3D: the moving wall's mass"},
      {"V0", 11, 20, K::real, 0, R, nullptr, "IMPACT-3D: its initial velocity along the normal"},
  }});
  FixedCardLayout list{"node list card", "88 later", {}};
  add_run(list, kListNode, 10, 1, 8, S, "stonewall slave nodes, ten a card");
  t.push_back(std::move(list));
  t.push_back({"initial velocity range card", "88 later", {
      {"first node", 1, 8, S, 0, R, nullptr, "IMPACT-3D: 0 all nodes, else the range's first node"},
      {"vx", 9, 18, K::real, 0, R, nullptr, "initial velocity"},
      {"vy", 19, 28, K::real, 0, R, nullptr, ""},
      {"vz", 29, 38, K::real, 0, R, nullptr, ""},
      {"last node", 39, 46, S, 0, R, nullptr, "(blank: the first)"},
      {"increment", 47, 51, S, 1, R, nullptr, "(0: 1)"},
  }});
  FixedCardLayout seg{"segment card", "88 later", {{"segment number", 1, 8, S, 0, R, nullptr, "read, not used"}}};
  add_run(seg, kNodeN, 4, 9, 8, S, "the segment's nodes");
  t.push_back(std::move(seg));
  t.push_back({"base acceleration card", "88 later", {
      {"load curve", 1, 5, S, 0, R, nullptr, "IMPACT-3D: one card per axis flagged on control card 5, x y z"},
      {"scale factor", 6, 15, K::real, 1, R, nullptr, "(blank: 1); every node gets -scale x curve"},
  }});
}

// The small format (no "large" on the title card): ids in 5 columns.
void add_small_format_cards(std::vector<FixedCardLayout>& t) {
  t.push_back({"control card 2 (small format)", "88 later", {
      {"NMMAT", 1, 5, S, 0, R, nullptr, "number of materials"},
      {"NUMNP", 6, 10, S, 0, R, nullptr, "number of nodes"},
      {"NUMELH", 11, 15, S, 0, R, nullptr, "number of solid hexahedra"},
      {"NUMELB", 16, 20, S, 0, R, nullptr, "number of beams"},
      {"NUMELS", 21, 25, S, 0, R, nullptr, "number of 4-node shells"},
      {"NUMELT", 26, 30, S, 0, X, "thick shell elements", "number of 8-node thick shells"},
      {"interface segments", 31, 35, S, 0, R, nullptr, "interface segments written to the interface database"},
      {"interface output interval", 36, 45, K::real, 0, R, nullptr, "interval of the interface database"},
  }});
  t.push_back(node_card("node card (small format)", 5));
  t.push_back(element_card("solid element card (small format)", 5, 8, "the hexahedron's nodes"));
  t.push_back(element_card("shell element card (small format)", 5, 4, "n4 blank or = n3: a triangle"));
  t.push_back({"nodal load card (small format)", "88 later", {
      {"node", 1, 5, S, 0, R, nullptr, "node number"},
      {"direction", 6, 10, S, 0, R, nullptr, "1-3 x y z"},
      {"load curve", 11, 15, S, 0, R, nullptr, "load curve number"},
      {"scale factor", 16, 25, K::real, 1, R, nullptr, "(blank: 1)"},
  }});
  FixedCardLayout p{"pressure card (small format)", "88 later", {{"load curve", 1, 5, S, 0, R, nullptr, "load curve number"}}};
  add_run(p, kNodeN, 4, 6, 5, S, "the loaded face's nodes");
  const char* const mult[4] = {"multiplier 1", "multiplier 2", "multiplier 3", "multiplier 4"};
  for (int q = 0; q < 4; ++q) p.fields.push_back({mult[q], 26 + 10 * q, 35 + 10 * q, K::real, 1, R, nullptr, q == 0 ? "nodal multipliers (blank: 1)" : ""});
  p.fields.push_back({"arrival time", 71, 80, K::real, 0, R, nullptr, "IMPACT-3D: the load starts then"});
  t.push_back(std::move(p));
  FixedCardLayout list{"node list card (small format)", "88 later", {}};
  add_run(list, kListNode, 16, 1, 5, S, "stonewall slave nodes, sixteen a card");
  t.push_back(std::move(list));
  FixedCardLayout seg{"segment card (small format)", "88 later", {{"segment number", 1, 5, S, 0, R, nullptr, "read, not used"}}};
  add_run(seg, kNodeN, 4, 6, 5, S, "the segment's nodes");
  t.push_back(std::move(seg));
}

// The title card and control cards 2 to 5.
void add_control_cards_1_to_5(std::vector<FixedCardLayout>& t) {
  t.push_back({"title card", "88 later", {
      {"title", 1, 72, K::text, 0, R, nullptr, "the problem's title"},
      {"format digits", 73, 74, K::text, 0, R, nullptr, "\"88\" (\"10\" with \"large\": refused)"},
      {"format flag", 76, 80, K::text, 0, R, nullptr, "\"large\": the large format (8-column ids); blank: the small format"},
  }});
  // ---- control cards (after the title card) ----
  t.push_back({"control card 2", "88 later", {
      {"NMMAT", 1, 5, K::integer, 0, R, nullptr, "number of materials"},
      {"NUMNP", 6, 15, K::integer, 0, R, nullptr, "number of nodes"},
      {"NUMELH", 16, 25, K::integer, 0, R, nullptr, "number of solid hexahedra"},
      {"NUMELB", 26, 35, K::integer, 0, R, nullptr, "number of beams"},
      {"NUMELS", 36, 45, K::integer, 0, R, nullptr, "number of 4-node shells"},
      {"NUMELT", 46, 55, K::integer, 0, X, "thick shell elements", "number of 8-node thick shells"},
      {"interface segments", 56, 65, K::integer, 0, R, nullptr, "interface segments written to the interface database"},
      {"interface output interval", 66, 75, K::real, 0, R, nullptr, "interval of the interface database"},
      {"minimum shell time step", 76, 80, K::real, 0, X, "shell deletion below a minimum time step", "later vintage"},
  }});
  t.push_back({"control card 3", "88 later", {
      {"node time-history blocks", 1, 5, K::integer, 0, R, nullptr, "node blocks of the time-history database"},
      {"solid time-history blocks", 6, 10, K::integer, 0, R, nullptr, "solid blocks"},
      {"beam time-history blocks", 11, 15, K::integer, 0, R, nullptr, "beam blocks"},
      {"shell time-history blocks", 16, 20, K::integer, 0, R, nullptr, "shell blocks"},
      {"thick shell time-history blocks", 21, 25, K::integer, 0, X, "thick shell time histories", "thick shell blocks"},
      {"report interval", 26, 30, K::integer, 100, R, nullptr, "cycles between printed reports (0: 100)"},
      {"reaction-force print flag", 31, 35, K::integer, 0, R, nullptr, "later vintage"},
      {"discrete-element print flag", 36, 40, K::integer, 0, X, "discrete elements", "later vintage"},
      {"element deletion flag", 41, 45, K::integer, 0, R, nullptr, "0/1: deletion flags in the plot database (later vintage)"},
  }});
  t.push_back({"control card 4", "88", {
      {"DYNA3D-JOY interface nodes", 1, 5, K::integer, 0, X, "the DYNA3D-JOY interface", "nodes shared with JOY"},
      {"sliding boundary planes", 6, 10, K::integer, 0, X, "sliding boundary planes", ""},
      {"sliding planes with failure", 11, 15, K::integer, 0, X, "sliding planes with failure", ""},
      {"density-versus-depth points", 16, 20, K::integer, 0, X, "density versus depth", ""},
      {"Brode function flag", 21, 25, K::integer, 0, X, "the Brode function", ""},
      {"rigid-body merge cards", 26, 30, K::integer, 0, X, "rigid-body merging", ""},
      {"coordinate format", 31, 35, K::text, 0, R, nullptr, "format of the node coordinates (e20.x; blank: e20.0)"},
  }});
  t.push_back({"control card 4", "later", {
      {"sliding boundary planes", 1, 10, K::integer, 0, X, "sliding boundary planes", ""},
      {"sliding planes with failure", 11, 15, K::integer, 0, X, "sliding planes with failure", ""},
      {"density-versus-depth points", 16, 20, K::integer, 0, X, "density versus depth", ""},
      {"Brode function flag", 21, 25, K::integer, 0, X, "the Brode function", ""},
      {"rigid-body merge cards", 26, 30, K::integer, 0, X, "rigid-body merging", ""},
      {"coordinate format", 31, 35, K::text, 0, R, nullptr, "format of the node coordinates (e20.x; blank: e20.0)"},
      {"force cross-sections", 36, 40, K::integer, 0, X, "force cross-sections", ""},
      {"cross-section output interval", 41, 50, K::real, 0, I, "cross-section force output", ""},
  }});
  t.push_back({"control card 5", "88 later", {
      {"NUMLC", 1, 5, K::integer, 0, R, nullptr, "number of load curves"},
      {"concentrated nodal loads", 6, 10, K::integer, 0, R, nullptr, "nodal load cards"},
      {"pressure-loaded sides", 11, 15, K::integer, 0, R, nullptr, "pressure cards"},
      {"velocity/acceleration boundary cards", 16, 20, K::integer, 0, R, nullptr, "prescribed motion cards"},
      {"stonewalls", 21, 25, K::integer, 0, R, nullptr, "rigid walls"},
      {"nodal constraint cards", 26, 30, K::integer, 0, X, "nodal constraints", ""},
      {"initial condition parameter", 31, 35, K::integer, 0, R, nullptr, "0 at rest; 1 nodal velocity cards follow"},
      {"sliding interfaces", 36, 40, K::integer, 0, R, nullptr, "number of sliding interfaces"},
      {"base acceleration x", 41, 45, K::integer, 0, R, nullptr, "0/1"},
      {"base acceleration y", 46, 50, K::integer, 0, R, nullptr, "0/1"},
      {"base acceleration z", 51, 55, K::integer, 0, R, nullptr, "0/1"},
      {"angular velocity x", 56, 60, K::integer, 0, X, "angular velocities", ""},
      {"angular velocity y", 61, 65, K::integer, 0, X, "angular velocities", ""},
      {"angular velocity z", 66, 70, K::integer, 0, X, "angular velocities", ""},
      {"momentum deposit", 71, 75, K::integer, 0, X, "momentum deposition", ""},
      {"detonation points", 76, 80, K::integer, 0, X, "detonation (high explosives)", ""},
  }});
}

// Control cards 6 to 9.
void add_control_cards_6_to_9(std::vector<FixedCardLayout>& t) {
  t.push_back({"control card 6", "88 later", {
      {"termination time", 1, 10, K::real, 0, R, nullptr, "end time"},
      {"time-history interval", 11, 20, K::real, 0, R, nullptr, "(0: end time / 1000)"},
      {"plot interval", 21, 30, K::real, 0, R, nullptr, "(0: end time / 20)"},
      {"restart dump cycles", 31, 35, K::integer, 0, R, nullptr, "cycles between restart dumps"},
      {"running restart cycles", 36, 40, K::integer, 0, R, nullptr, "cycles between running restart dumps"},
      {"initial time step", 41, 50, K::real, 0, R, nullptr, "(0: computed)"},
      {"penalty scale factor", 51, 60, K::real, 0.10, R, nullptr, "sliding interface penalty factor (0: 0.10)"},
      {"thermal option", 61, 65, K::integer, 0, X, "thermal effects", ""},
      {"default viscosity flag", 66, 70, K::integer, 0, R, nullptr, ""},
      {"time-step scale factor", 71, 80, K::real, 0.90, R, nullptr, "(0: 0.90)"},
  }});
  // control card 7: fields 10 and 11 differ between the vintages
  const FixedField card7_common[9] = {
      {"joints", 1, 5, K::integer, 0, X, "joints", ""},
      {"rigid bodies with extra nodes", 6, 10, K::integer, 0, X, "rigid bodies with extra nodes", ""},
      {"shell-solid interfaces", 11, 15, K::integer, 0, X, "shell-solid interfaces", ""},
      {"tie-breaking shell slidelines", 16, 20, K::integer, 0, X, "tie-breaking shell slidelines", ""},
      {"tied node sets with failure", 21, 25, K::integer, 0, X, "tied node sets with failure", ""},
      {"time-step load curve", 26, 30, K::integer, 0, X, "a load curve limiting the time step", ""},
      {"springs/dampers/masses", 31, 35, K::integer, 0, X, "springs, dampers and masses", ""},
      {"rigid bodies with inertia", 36, 40, K::integer, 0, X, "rigid bodies with inertial properties", ""},
      {"shell strain dump", 41, 45, K::integer, 0, I, "shell strains in the plot database", ""},
  };
  const FixedField card7_tail[4] = {
      {"Hughes-Liu shell update", 56, 60, K::integer, 0, I, "the Hughes-Liu shell update (IMPACT-3D's shells are Belytschko-Tsay)", ""},
      {"shell thickness change", 61, 65, K::integer, 0, X, "shell thickness change", ""},
      {"shell formulation", 66, 70, K::integer, 0, I, "the default shell formulation (the material card chooses)", ""},
      {"non-reflecting boundary segments", 71, 75, K::integer, 0, X, "non-reflecting boundaries", ""},
  };
  {
    FixedCardLayout c88{"control card 7", "88", {}};
    FixedCardLayout cl{"control card 7", "later", {}};
    for (const auto& f : card7_common) { c88.fields.push_back(f); cl.fields.push_back(f); }
    c88.fields.push_back({"shadow burn flag", 46, 50, K::integer, 0, X, "shadow burn (high explosives)", ""});
    c88.fields.push_back({"hydro variables dump flag", 51, 55, K::integer, 0, I, "hydrodynamic variables in the plot database", ""});
    cl.fields.push_back({"deformable-rigid switching groups", 46, 50, K::integer, 0, X, "deformable-rigid switching", ""});
    cl.fields.push_back({"mass damping sets", 51, 55, K::integer, 0, R, nullptr, "mass-proportional damping cards (also free-format mdamp)"});
    for (const auto& f : card7_tail) { c88.fields.push_back(f); cl.fields.push_back(f); }
    t.push_back(std::move(c88));
    t.push_back(std::move(cl));
  }
  t.push_back({"control card 8", "88 later", {
      {"point-constraint nodes", 1, 5, K::integer, 0, X, "point constraints", ""},
      {"constraint coordinate systems", 6, 10, K::integer, 0, X, "constraint coordinate systems", ""},
      {"minimum step factor", 11, 20, K::real, 0, R, nullptr, "the run stops below this fraction of the first step"},
      {"beam integration rules", 21, 25, K::integer, 0, R, nullptr, "user-defined beam integration rules (cards after the materials)"},
      {"beam integration points", 26, 30, K::integer, 0, R, nullptr, "most points in a user beam rule"},
      {"shell integration rules", 31, 35, K::integer, 0, X, "user-defined shell integration rules", ""},
      {"shell integration points", 36, 40, K::integer, 0, I, "most points in a user shell rule", ""},
      {"relaxation check iterations", 41, 45, K::integer, 0, I, "dynamic relaxation", ""},
      {"relaxation tolerance", 46, 55, K::real, 0, I, "dynamic relaxation", ""},
      {"dynamic relaxation factor", 56, 65, K::real, 0, I, "dynamic relaxation", ""},
      {"relaxation time-step factor", 66, 75, K::real, 0, I, "dynamic relaxation", ""},
      {"shell time-step option", 76, 80, K::integer, 0, I, "the shell time-step length choice", ""},
  }});
  t.push_back({"control card 9", "88 later", {
      {"plane-stress plasticity option", 1, 5, K::integer, 0, I, "the plane-stress return (IMPACT-3D iterates it)", ""},
      {"printout flag", 6, 10, K::integer, 0, I, "printed output options", ""},
      {"1-D slidelines", 11, 15, K::integer, 0, X, "1-D slidelines", ""},
      {"relaxation database flag", 16, 20, K::integer, 0, I, "the dynamic-relaxation database", ""},
      {"Rayleigh coefficient", 21, 30, K::real, 0, X, "Rayleigh damping", ""},
      {"materials with Rayleigh damping", 31, 35, K::integer, 0, X, "Rayleigh damping", ""},
      {"materials with initial rotation", 36, 40, K::integer, 0, X, "initial rotation", ""},
      {"materials with body force", 41, 45, K::integer, 0, X, "body forces", ""},
      {"DT2MS", 46, 55, K::real, 0, R, nullptr, "IMPACT-3D: mass-scaling step (LS-DYNA's DT2MS)"},
      {"MS1ST", 56, 60, K::integer, 0, R, nullptr, "IMPACT-3D: 1 = mass scaling at the first cycle only"},
      {"ENDMAS", 61, 70, K::real, 0, R, nullptr, "IMPACT-3D: added-mass limit, percent"},
      {"ERODE", 71, 75, K::integer, 0, R, nullptr, "IMPACT-3D: 1 = solids below the minimum step are deleted"},
  }});
}

// The cards after the control cards: time-history blocks, pressures, prescribed motions,
// initial velocities, sliding interfaces, and the old IMPACT-3D forms of some of them.
void add_interface_and_boundary_cards(std::vector<FixedCardLayout>& t) {
  t.push_back({"time-history block card", "88 later", {
      {"first 1", 1, 8, K::integer, 0, R, nullptr, "five blocks a card: first and last id of each"},
      {"last 1", 9, 16, K::integer, 0, R, nullptr, ""},
      {"first 2", 17, 24, K::integer, 0, R, nullptr, ""},
      {"last 2", 25, 32, K::integer, 0, R, nullptr, ""},
      {"first 3", 33, 40, K::integer, 0, R, nullptr, ""},
      {"last 3", 41, 48, K::integer, 0, R, nullptr, ""},
      {"first 4", 49, 56, K::integer, 0, R, nullptr, ""},
      {"last 4", 57, 64, K::integer, 0, R, nullptr, ""},
      {"first 5", 65, 72, K::integer, 0, R, nullptr, ""},
      {"last 5", 73, 80, K::integer, 0, R, nullptr, ""},
  }});
  t.push_back({"pressure card", "88 later", {
      {"load curve", 1, 5, K::integer, 0, R, nullptr, "load curve number"},
      {"node n1", 6, 13, K::integer, 0, R, nullptr, "the loaded face's nodes"},
      {"node n2", 14, 21, K::integer, 0, R, nullptr, ""},
      {"node n3", 22, 29, K::integer, 0, R, nullptr, ""},
      {"node n4", 30, 37, K::integer, 0, R, nullptr, ""},
      {"multiplier 1", 38, 47, K::real, 1, R, nullptr, "nodal multipliers of the curve (blank: 1)"},
      {"multiplier 2", 48, 57, K::real, 1, R, nullptr, ""},
      {"multiplier 3", 58, 67, K::real, 1, R, nullptr, ""},
      {"multiplier 4", 68, 77, K::real, 1, R, nullptr, ""},
  }});
  t.push_back({"velocity/acceleration boundary card", "88 later", {
      {"node", 1, 8, K::integer, 0, R, nullptr, "node number"},
      {"load curve", 9, 13, K::integer, 0, R, nullptr, "load curve number"},
      {"DOF", 14, 18, K::integer, 0, R, nullptr, "1-3 x y z, 4 along (vx, vy, vz), 5-7 rotation about x y z"},
      {"scale factor", 19, 28, K::real, 1, R, nullptr, "(blank: 1)"},
      {"vx", 29, 38, K::real, 0, R, nullptr, "direction vector of DOF 4"},
      {"vy", 39, 48, K::real, 0, R, nullptr, ""},
      {"vz", 49, 58, K::real, 0, R, nullptr, ""},
      {"type", 59, 63, K::integer, 0, R, nullptr, "0 velocity, 1 acceleration, 2 displacement"},
      {"birth time", 64, 73, K::real, 0, R, nullptr, "IMPACT-3D: start of the motion"},
      {"death time", 74, 80, K::real, 0, R, nullptr, "IMPACT-3D: end of the motion (0: never)"},
  }});
  t.push_back({"initial velocity card", "88 later", {
      {"node", 1, 8, K::integer, 0, R, nullptr, "node number (nodes skipped between two cards: interpolated)"},
      {"vx", 9, 18, K::real, 0, R, nullptr, "initial velocity"},
      {"vy", 19, 28, K::real, 0, R, nullptr, ""},
      {"vz", 29, 38, K::real, 0, R, nullptr, ""},
  }});
  t.push_back({"sliding interface control card", "88 later", {
      {"NSS", 1, 8, K::integer, 0, R, nullptr, "slave segments"},
      {"NMS", 9, 16, K::integer, 0, R, nullptr, "master segments (0 for type 4)"},
      {"type", 17, 21, K::integer, 0, R, nullptr, "3 sliding with impact and friction, 4 single surface"},
      {"static friction", 22, 31, K::real, 0, R, nullptr, ""},
      {"dynamic friction", 32, 41, K::real, 0, R, nullptr, ""},
      {"decay coefficient", 42, 51, K::real, 0, R, nullptr, ""},
      {"stiffness method", 52, 56, K::integer, 0, R, nullptr, "IMPACT-3D: 0 DYNA3D, 1 IMPACT-3D maximum stable"},
      {"one-pass flag", 57, 61, K::integer, 0, R, nullptr, "IMPACT-3D: 1 one pass (slave nodes only)"},
      {"option 3", 62, 66, K::integer, 0, I, "an interface option of DYNA3D not known here", ""},
      {"penalty scale factor", 67, 73, K::real, 0, R, nullptr, "this interface's penalty factor (0: control card 6)"},
      {"option 5", 74, 80, K::real, 0, I, "an interface option of DYNA3D not known here", ""},
  }});
  // IMPACT-3D's own interface control card before the real decks were found: still read
  // (warning 2041) when column 22 holds the decimal point of a friction written from column 21
  t.push_back({"old IMPACT-3D sliding interface control card", "88 later", {
      {"NSS", 1, 8, K::integer, 0, R, nullptr, "slave segments"},
      {"NMS", 9, 16, K::integer, 0, R, nullptr, "master segments"},
      {"type", 17, 20, K::integer, 0, R, nullptr, "3 or 4"},
      {"static friction", 21, 30, K::real, 0, R, nullptr, ""},
      {"dynamic friction", 31, 40, K::real, 0, R, nullptr, ""},
      {"decay coefficient", 41, 50, K::real, 0, R, nullptr, ""},
      {"penalty scale factor", 51, 60, K::real, 0, R, nullptr, ""},
      {"stiffness method", 61, 65, K::integer, 0, R, nullptr, ""},
      {"one-pass flag", 66, 70, K::integer, 0, R, nullptr, ""},
  }});
  // IMPACT-3D's own motion card before the real decks were found: refused (1006) with the
  // columns to move
  t.push_back({"old IMPACT-3D velocity/acceleration boundary card", "88 later", {
      {"node", 1, 8, S, 0, R, nullptr, "node number"},
      {"direction", 9, 13, S, 0, R, nullptr, "1-3 x y z"},
      {"curve", 14, 18, S, 0, R, nullptr, "load curve number"},
      {"scale", 19, 28, K::real, 1, R, nullptr, ""},
      {"type", 29, 33, S, 0, R, nullptr, "an I5 without a decimal point: tells this layout"},
      {"birth", 34, 43, K::real, 0, R, nullptr, ""},
      {"death", 44, 53, K::real, 0, R, nullptr, ""},
  }});
  // IMPACT-3D's old large-format pressure layout: the multipliers on a second card (still read,
  // warning 2041, when the card after a pressure card is unmistakably this one)
  t.push_back({"old IMPACT-3D pressure multiplier card", "88 later", {
      {"multiplier 1", 1, 10, K::real, 1, R, nullptr, "nodal multipliers (blank: 1), each with a decimal point or exponent"},
      {"multiplier 2", 11, 20, K::real, 1, R, nullptr, ""},
      {"multiplier 3", 21, 30, K::real, 1, R, nullptr, ""},
      {"multiplier 4", 31, 40, K::real, 1, R, nullptr, ""},
      {"arrival time", 71, 80, K::real, 0, R, nullptr, "the load starts then"},
  }});
  // IMPACT-3D's old one-card shell section (still read, warning 2041, when no section title
  // line follows card 8 of a shell material)
  t.push_back({"old IMPACT-3D shell section card", "88 later", {
      {"shear factor SHRF", 1, 10, K::real, 1, R, nullptr, "(0: 1)"},
      {"NIP", 11, 20, K::real, 2, R, nullptr, "through-thickness points (0: 2)"},
      {"quadrature rule QR", 21, 30, K::real, 0, R, nullptr, "0 Gauss only"},
      {"T1", 31, 40, K::real, 0, R, nullptr, "thicknesses (T2-T4 0: T1)"},
      {"T2", 41, 50, K::real, 0, R, nullptr, ""},
      {"T3", 51, 60, K::real, 0, R, nullptr, ""},
      {"T4", 61, 70, K::real, 0, R, nullptr, ""},
  }});
}

// Mass damping, beam elements, beam and shell sections.
void add_section_cards(std::vector<FixedCardLayout>& t) {
  t.push_back({"mass damping card", "later", {
      {"damping ratio", 1, 10, K::real, 0, R, nullptr, "fraction of critical at the frequency below"},
      {"frequency", 11, 20, K::real, 0, R, nullptr, "circular frequency (rad per time unit)"},
      {"start time", 21, 30, K::real, 0, R, nullptr, ""},
      {"end time", 31, 40, K::real, 0, R, nullptr, "(0: never ends)"},
  }});
  t.push_back({"beam element card", "88 later", {
      {"element number", 1, 8, K::integer, 0, R, nullptr, ""},
      {"material number", 9, 13, K::integer, 0, R, nullptr, "a beam material (element type 1)"},
      {"node n1", 14, 21, K::integer, 0, R, nullptr, ""},
      {"node n2", 22, 29, K::integer, 0, R, nullptr, ""},
      {"orientation node n3", 30, 37, K::integer, 0, R, nullptr, "with n1 and n2, the beam's local s axis plane"},
      {"field 6", 38, 45, K::real, 0, R, nullptr, "this beam's TS1 (an inference; 0: the section's)"},
      {"field 7", 46, 53, K::real, 0, R, nullptr, "TS2"},
      {"field 8", 54, 61, K::real, 0, R, nullptr, "TT1"},
      {"field 9", 62, 69, K::real, 0, R, nullptr, "TT2"},
  }});
  t.push_back({"beam section card 1", "88 later", {
      {"shear factor", 1, 10, K::real, 0, R, nullptr, "(0: 1)"},
      {"quadrature rule", 11, 20, K::real, 0, R, nullptr, "1-5 built-in rules, -n user rule n (0: 2)"},
      {"cross-section type", 21, 30, K::real, 0, R, nullptr, "0 rectangular, 1 tubular, 2 user rule"},
      {"field 4", 31, 40, K::real, 0, I, "a beam-section field of DYNA3D not known here", ""},
  }});
  t.push_back({"beam section card 2", "88 later", {
      {"TS1", 1, 10, K::real, 0, R, nullptr, "thickness in s at node 1 (tube: outer diameter)"},
      {"TS2", 11, 20, K::real, 0, R, nullptr, "thickness in s at node 2"},
      {"TT1", 21, 30, K::real, 0, R, nullptr, "thickness in t at node 1 (tube: inner diameter)"},
      {"TT2", 31, 40, K::real, 0, R, nullptr, "thickness in t at node 2"},
      {"NSLOC", 41, 50, K::real, 0, I, "a reference-line offset in s", ""},
      {"NTLOC", 51, 60, K::real, 0, I, "a reference-line offset in t", ""},
  }});
  t.push_back({"shell section card 1", "88 later", {
      {"shear factor SHRF", 1, 10, K::real, 0, R, nullptr, "(0: 1)"},
      {"NIP", 11, 20, K::real, 0, R, nullptr, "through-thickness points (0: 2)"},
      {"quadrature rule QR", 21, 30, K::real, 0, R, nullptr, "0 Gauss (user rules refused)"},
      {"field 4", 31, 40, K::real, 0, I, "a shell-section field of DYNA3D not known here", ""},
  }});
  t.push_back({"shell section card 2", "88 later", {
      {"T1", 1, 10, K::real, 0, R, nullptr, "thickness at node 1 (element cards may give their own)"},
      {"T2", 11, 20, K::real, 0, R, nullptr, "(0: T1)"},
      {"T3", 21, 30, K::real, 0, R, nullptr, "(0: T1)"},
      {"T4", 31, 40, K::real, 0, R, nullptr, "(0: T1)"},
      {"field 5", 41, 50, K::real, 0, I, "a shell-section field of DYNA3D not known here", ""},
  }});
}

std::vector<FixedCardLayout> make_layouts() {
  std::vector<FixedCardLayout> t;
  add_control_cards_1_to_5(t);
  add_control_cards_6_to_9(t);
  add_interface_and_boundary_cards(t);
  add_section_cards(t);
  add_model_cards(t);
  add_load_cards(t);
  add_small_format_cards(t);
  return t;
}

bool has_vintage(const FixedCardLayout& l, FixedVintage v) {
  const std::string_view s = l.vintages;
  return s.find(v == FixedVintage::dyna3d_88 ? "88" : "later") != std::string_view::npos;
}

}  // namespace

const char* vintage_name(FixedVintage v) {
  return v == FixedVintage::dyna3d_88 ? "DYNA3D 88 (INGRID)" : "DYNA3D later (TrueGrid 2.2, IMPACT-3D)";
}

const FixedField& FixedCardLayout::field(std::string_view name) const {
  for (const FixedField& f : fields)
    if (name == f.name) return f;
  throw std::logic_error(std::string("fixed card table: ") + id + " has no field " + std::string(name));
}

const std::vector<FixedCardLayout>& all_fixed_card_layouts() {
  static const std::vector<FixedCardLayout> t = make_layouts();
  return t;
}

const FixedCardLayout& fixed_card_layout(std::string_view id, FixedVintage v) {
  for (const FixedCardLayout& l : all_fixed_card_layouts())
    if (id == l.id && has_vintage(l, v)) return l;
  throw std::logic_error("fixed card table: no layout for " + std::string(id));
}

FixedVintage detect_fixed_vintage(std::string_view card4) {
  const std::string_view head = card_columns(card4, 1, 5);
  return head.find_first_not_of(' ') == std::string_view::npos ? FixedVintage::dyna3d_later : FixedVintage::dyna3d_88;
}

std::string fixed_card_tables_markdown() {
  std::ostringstream os;
  static const char* const kind[] = {"I", "E", "A", "I"};
  for (const FixedCardLayout& l : all_fixed_card_layouts()) {
    const std::string v = l.vintages;
    os << "#### " << l.id << (v == "88 later" ? "" : v == "88" ? " (88 vintage)" : " (later vintage)") << "\n\n";
    os << "| columns | field | format | blank | meaning |\n|---|---|---|---|---|\n";
    for (const FixedField& f : l.fields) {
      std::ostringstream blank;
      blank << f.blank;
      std::string meaning = f.meaning ? f.meaning : "";
      if (f.use == FieldUse::refused) meaning += std::string(meaning.empty() ? "" : "; ") + "nonzero refused (" + f.feature + ")";
      if (f.use == FieldUse::ignored) meaning += std::string(meaning.empty() ? "" : "; ") + "read, no effect here (" + f.feature + ")";
      os << "| " << f.c1 << "-" << f.c2 << " | " << f.name << " | " << kind[int(f.kind)] << f.c2 - f.c1 + 1 << " | "
         << (f.kind == FieldKind::text ? "" : blank.str()) << " | " << meaning << " |\n";
    }
    os << "\n";
  }
  return os.str();
}

FixedValues::FixedValues(Card& card, const FixedCardLayout& layout, const NameByFirst& name_by_first)
    : card_(card), layout_(layout) {
  const std::size_t n = layout.fields.size();
  values_.assign(n, 0.0);
  texts_.assign(n, std::string());
  blank_.assign(n, 1);
  for (std::size_t k = 0; k < n; ++k) {
    read_field(k);
    if (k == 0 && name_by_first) card.set_name(name_by_first(static_cast<long long>(values_[0])));
  }
}

void FixedValues::read_field(std::size_t k) {
  const FixedField& f = layout_.fields[k];
  blank_[k] = card_.blank(f.c1, f.c2) ? 1 : 0;
  if (f.kind == FieldKind::text) {
    std::string s = card_.a(f.c1, f.c2);
    while (!s.empty() && s.back() == ' ') s.pop_back();
    s.erase(0, std::min(s.find_first_not_of(' '), s.size()));
    texts_[k] = s;
    return;
  }
  if (f.kind == FieldKind::integer && integral_real(f, values_[k])) return;
  if (f.kind == FieldKind::real) values_[k] = card_.e(f.c1, f.c2, f.name, f.blank);
  else values_[k] = double(card_.i(f.c1, f.c2, f.name, static_cast<long long>(f.blank)));
  if (blank_[k]) values_[k] = f.blank;
  if (values_[k] == 0 || blank_[k]) return;
  if (f.use == FieldUse::refused) card_.error(1102, f.c1, f.c2, f.name, f.feature);
  else if (f.use == FieldUse::ignored)
    ignored_.push_back(std::string(layout_.id) + " " + f.name + " (cols " + std::to_string(f.c1) + "-" + std::to_string(f.c2) + "): " + f.feature);
}

// An integer field written as a real with an integral value ("7.", as INGRID writes codes).
bool FixedValues::integral_real(const FixedField& f, double& v) const {
  const std::string_view raw = card_.columns(f.c1, f.c2);
  long long iv = 0;
  if (parse_fortran_int(raw, iv) != FieldStatus::bad) return false;
  double dv = 0;
  if (parse_fortran_real(raw, dv) != FieldStatus::ok || dv != std::floor(dv) || std::fabs(dv) >= 1e15) return false;
  v = dv;
  return true;
}

std::size_t FixedValues::index(std::string_view name) const {
  for (std::size_t k = 0; k < layout_.fields.size(); ++k)
    if (name == layout_.fields[k].name) return k;
  throw std::logic_error(std::string("fixed card table: ") + layout_.id + " has no field " + std::string(name));
}

double FixedValues::operator[](std::string_view name) const { return values_[index(name)]; }
const std::string& FixedValues::text(std::string_view name) const { return texts_[index(name)]; }
bool FixedValues::blank(std::string_view name) const { return blank_[index(name)] != 0; }

void FixedValues::error(int id, std::string_view name, std::string detail) const {
  const FixedField& f = layout_.fields[index(name)];
  card_.error(id, f.c1, f.c2, f.name, std::move(detail));
}

bool FixedValues::flag01(std::string_view name, std::string choices) const {
  const long long x = integer(name);
  if (x != 0 && x != 1) error(1006, name, std::move(choices));
  return x == 1;
}

Location FixedValues::where(std::string_view name) const {
  const FixedField& f = layout_.fields[index(name)];
  return card_.where(f.c1, f.c2, f.name);
}

}  // namespace impact3d
