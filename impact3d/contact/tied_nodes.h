#pragma once
// Constraint-based tied contacts (*CONTACT_SPOTWELD, *CONTACT_TIED_NODES_TO_SURFACE; Model::
// TiedContact): each slave node is projected once, when the deck is read, onto the nearest master
// segment within reach, moved onto it and tied there (Model::NodeTie); solve/node_ties.h moves
// it with the segment.

#include <vector>

#include "impact3d/model/model.h"

namespace impact3d {

// How far (in xi, eta) beyond a segment's square a projection still counts as on it: the
// sliding interfaces' 1 % extension.
constexpr double kTieSegmentExtension = 0.01;

// The default reach of a master segment: a slave node at most this far from it (normal to the
// segment, inside its projection) is tied: 5 % of its shorter diagonal.
double tie_default_reach(const Model& m, const std::array<int, 4>& seg);

// Ties the slave nodes of Model::tied_contacts[c]: each to its nearest segment within reach (on
// equal distances the first in the contact's order), the node moved onto the segment, a NodeTie
// appended to m.node_ties; sets the contact's `tied` count.  Returns the slave nodes left untied
// (out of every segment's reach).  The search looks at the segments a uniform grid of their boxes
// lists for the node (grid), or at every segment (every_segment: the reference the grid is tested
// against, and what a contact whose slave nodes are also master nodes uses); both tie every node
// to the same segment at the same point.
enum class TieSearch { grid, every_segment };
std::vector<int> tie_slave_nodes(Model& m, int c, TieSearch search = TieSearch::grid);

}  // namespace impact3d
