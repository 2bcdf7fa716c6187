#pragma once
// Mesh ordering: the starter renumbers the nodes and solids of a checked Model so that an
// element's gather of its 8 nodes and the node pass's gather of its corner forces touch nearby
// memory.  Nodes take the reverse Cuthill-McKee numbering of the node graph (nodes joined by a
// solid or shell), solids follow their lowest new node.  The deck's ids go to node_user_id /
// hex_user_id (every message and output shows them), node_order / hex_order record where each
// deck number went.  The numbering is a function of the model alone (no threads, ties broken by
// deck order): a restart renumbers identically.
//
// Automatic mode keeps the deck's order unless the model is large (>= kMeshOrderMinElements
// solids and shells: smaller ones stay in the caches), the deck's locality cost
// (mesh_locality_cost) is above 2 N^(2/3) for N nodes (below it the numbering is as local as a
// 3-D mesh allows, and no other numbering is computed) and the new numbering's cost is at most
// half the deck's: decks already in good order run unchanged.

#include <string>
#include <vector>

#include "impact3d/model/model.h"

namespace impact3d {

enum class MeshOrderMode { automatic, on, off };

// "auto", "on", "off" (the command line's reorder=); false for anything else.
bool parse_mesh_order_mode(const std::string& text, MeshOrderMode& mode);

constexpr int kMeshOrderMinElements = 8192;

struct MeshOrderReport {
  bool renumbered = false;
  double deck_cost = 0;     // mesh_locality_cost of the deck's numbering
  double ordered_cost = 0;  // of the reverse Cuthill-McKee numbering (0: not computed)
  double local_bound = 0;   // 2 N^(2/3) for N nodes (0: not computed)
  MeshOrderMode mode = MeshOrderMode::automatic;
};

// Locality of a numbering: the mean over solids and shells of the spread of their node indices
// (largest - smallest), plus the mean jump of the smallest node index from one solid to the
// next.  A bar of n x n x 4n solids numbered plane by plane costs about n^2 + n + 2.
double mesh_locality_cost(const Model& m);

// The reverse Cuthill-McKee numbering: new index of every node and solid (by old index).
void compute_locality_order(const Model& m, std::vector<int>& node_new_of_old, std::vector<int>& hex_new_of_old);

// Renumbers every node and solid reference of the model (arrays per node and per solid, element
// connectivity, walls, interfaces, transducers, loads, prescribed motions) and records the
// deck ids and the order maps.  Shells keep their order.
void permute_model(Model& m, const std::vector<int>& node_new_of_old, const std::vector<int>& hex_new_of_old);

// Decides (mode) and renumbers.  Deterministic.
MeshOrderReport order_mesh_for_locality(Model& m, MeshOrderMode mode);

// A copy of a renumbered model back in deck order (the restart dump's deck text is written from it).
Model model_in_deck_order(const Model& m);

// The printed output's line about it.
std::string mesh_order_line(const MeshOrderReport& r);

}  // namespace impact3d
