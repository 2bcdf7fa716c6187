// Keyword decks, the control and database cards' resolve step: *DATABASE_HISTORY_... ids (and
// sets) into the Model's time-history blocks.  The records, and the controls themselves
// (build_controls), are in keyword_control_database.cpp; KeywordReader::resolve
// (keyword_reader.cpp) runs the step (ResolveContext, keyword_resolve.h).

#include "impact3d/input/keyword_resolve.h"

#include <algorithm>

namespace impact3d::kw {

void resolve_history(ResolveContext& rc) {
  for (const RHistory& h : rc.ctl.histories) {
    std::vector<int> idx;
    for (std::size_t j = 0; h.sets && j < h.ids.size(); ++j) {  // _SET: the members, in order
      const std::string card = h.solid ? "*DATABASE_HISTORY_SOLID_SET" : "*DATABASE_HISTORY_NODE_SET";
      if (h.solid) {
        if (const RIdList* s = find_solid_set(rc, h.ids[j], h.refs[j], card, "ID")) {
          std::vector<int> e = set_solids(rc, *s, "*SET_SOLID " + std::to_string(h.ids[j]));
          idx.insert(idx.end(), e.begin(), e.end());
        }
      } else if (const RIdList* s = find_node_set(rc, h.ids[j], h.refs[j], card, "ID")) {
        std::vector<int> n = set_nodes(rc, *s, "*SET_NODE " + std::to_string(h.ids[j]));
        idx.insert(idx.end(), n.begin(), n.end());
      }
    }
    for (std::size_t j = 0; !h.sets && j < h.ids.size(); ++j) {
      int v = -1;
      if (h.beam) {  // beam ids: Model::beam_user_id or 1..N
        const auto& ids = rc.m.beam_user_id;
        if (ids.empty()) v = h.ids[j] >= 1 && h.ids[j] <= rc.m.num_beams() ? h.ids[j] - 1 : -1;
        else if (auto it = std::find(ids.begin(), ids.end(), h.ids[j]); it != ids.end()) v = int(it - ids.begin());
        if (v < 0) rc.err(1201, h.refs[j], "*DATABASE_HISTORY_BEAM", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_BEAM");
      } else if (h.shell) {  // shell ids: Model::shell_user_id (increasing) or 1..N
        const auto& ids = rc.m.shell_user_id;
        if (ids.empty()) v = h.ids[j] >= 1 && h.ids[j] <= rc.m.num_shells() ? h.ids[j] - 1 : -1;
        else if (auto it = std::lower_bound(ids.begin(), ids.end(), h.ids[j]); it != ids.end() && *it == h.ids[j]) v = int(it - ids.begin());
        if (v < 0) rc.err(1201, h.refs[j], "*DATABASE_HISTORY_SHELL", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_SHELL");
      } else if (h.solid) {
        auto it = std::lower_bound(rc.elem_ids.begin(), rc.elem_ids.end(), h.ids[j]);
        if (it != rc.elem_ids.end() && *it == h.ids[j]) v = int(it - rc.elem_ids.begin());
        else rc.err(1201, h.refs[j], "*DATABASE_HISTORY_SOLID", "EID", "element " + std::to_string(h.ids[j]) + " is not defined by *ELEMENT_SOLID");
      } else {
        v = rc.node_index(h.ids[j]);
        if (v < 0) rc.err(1202, h.refs[j], "*DATABASE_HISTORY_NODE", "NID", "node " + std::to_string(h.ids[j]) + " is not defined by *NODE");
      }
      if (v >= 0) idx.push_back(v);
    }
    auto& blocks = h.beam ? rc.m.beam_th_blocks : h.shell ? rc.m.shell_th_blocks : h.solid ? rc.m.solid_th_blocks : rc.m.node_th_blocks;
    for (std::size_t j = 0; j < idx.size();) {
      std::size_t e = j;
      while (e + 1 < idx.size() && idx[e + 1] == idx[e] + 1) ++e;
      blocks.push_back({idx[j] + 1, idx[e] + 1});
      j = e + 1;
    }
  }
  rc.m.control.node_th_blocks = int(rc.m.node_th_blocks.size());
  rc.m.control.solid_th_blocks = int(rc.m.solid_th_blocks.size());
}

}  // namespace impact3d::kw
