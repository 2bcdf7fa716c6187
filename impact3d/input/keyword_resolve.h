#pragma once
// The keyword reader's resolve steps (internal to impact3d/input/keyword_*_resolve.cpp): once
// every block is read into the families' records (keyword_families.h), each family's builder
// turns its records into the Model.  The steps share one ResolveContext: the Model, the message
// sink, the records, and the id maps the earlier steps fill for the later ones (node and
// element ids -> indices, parts -> their elements and materials, curves, coordinate systems).
// KeywordReader::resolve (keyword_reader.cpp) runs them in their order.

#include <algorithm>
#include <array>
#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "impact3d/input/keyword_families.h"

namespace impact3d::kw {

// What keywords IMPACT-3D refuses define, so that a reference to it names the keyword: ids of
// materials, sections and EOS (id -> "keyword at file:line"), and sets, boxes and parts (kind
// 'N' node set, 'P' part set, 'S' segment set, 'H' solid set, 'B' box, 'p' part; id -> the same).
struct RefusedKeywords {
  std::map<int, std::string> mids, secids, eosids;
  std::map<std::pair<char, int>, std::string> defs;
};

// *INCLUDE_TRANSFORM: FILENAME; IDNOFF IDEOFF IDPOFF IDMOFF IDSOFF IDFOFF IDDOFF; IDROFF;
// FCTMAS FCTTIM FCTLEN FCTTEM INCOUT1; TRANID (read by keyword_include.cpp).
struct IncludeTransform {
  long long idnoff = 0, ideoff = 0, idpoff = 0, idmoff = 0, idsoff = 0, idfoff = 0, iddoff = 0, idroff = 0;
  double fctlen = 1;
  int tranid = 0;
  Ref tranid_ref;
  AffineMap map;  // FCTLEN scaling, then *DEFINE_TRANSFORMATION TRANID
  bool moves = false;
};
// The deck's transforms, and the files read under each (a file included by a transformed
// file inherits its transform).
struct IncludeTransforms {
  std::deque<IncludeTransform> list;
  std::map<const DeckFile*, const IncludeTransform*> of_file;
  const IncludeTransform* of(const DeckFile* f) const {
    auto it = of_file.find(f);
    return it == of_file.end() ? nullptr : it->second;
  }
};

// The deck cut into keyword blocks (keyword_include.cpp, the reader's first pass): the blocks of
// the main deck and of the files it includes (which `includes` holds: the blocks point into
// them), the *INCLUDE_TRANSFORM cards, the *CASE sections.  `m` gets *KEYWORD NCPU=.
struct ScannedDeck {
  std::deque<std::unique_ptr<DeckFile>> includes;
  std::vector<Block> blocks;
  IncludeTransforms transforms;
  CaseSections cases;
};
void scan_deck(const DeckFile& main, KeywordContext& ctx, Model& m, ScannedDeck& out);

// The indices of `recs` in increasing id order (a stable sort, skipped when they are in order
// already) into `order`, the first record of each id kept: returns how many are kept
// (order[0, n)); duplicate(record, first) is called for each record left out.
template <class Records, class Duplicate>
std::size_t order_by_id(const Records& recs, std::vector<std::uint32_t>& order, Duplicate&& duplicate) {
  order.resize(recs.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = std::uint32_t(k);
  const auto by_id = [&](std::uint32_t a, std::uint32_t b) { return recs[a].id < recs[b].id; };
  if (!std::is_sorted(order.begin(), order.end(), by_id)) std::stable_sort(order.begin(), order.end(), by_id);
  std::size_t n = 0;  // order is filtered in place
  for (std::size_t q = 0; q < order.size(); ++q) {
    const auto& r = recs[order[q]];
    if (n > 0 && recs[order[n - 1]].id == r.id) {
      duplicate(r, recs[order[n - 1]]);
      continue;
    }
    order[n++] = order[q];
  }
  return n;
}

struct ResolveContext {
  ResolveContext(Model& model, Diagnostics& d, std::string main, KeywordMesh& mesh, KeywordParts& parts, KeywordMaterials& mats,
                 KeywordSetsBoxes& sets, KeywordLoads& loads, KeywordControls& controls, std::vector<RContact>& cts,
                 const RefusedKeywords& r)
      : m(model), diag(d), main_file(std::move(main)), me(mesh), ps(parts), mt(mats), sb(sets), ld(loads), ctl(controls),
        contacts(cts), refused(r) {}

  Model& m;
  Diagnostics& diag;
  std::string main_file;  // the main deck's name (messages about the whole deck)
  // the records, as the families read them
  KeywordMesh& me;
  KeywordParts& ps;
  KeywordMaterials& mt;
  KeywordSetsBoxes& sb;
  KeywordLoads& ld;
  KeywordControls& ctl;
  std::vector<RContact>& contacts;
  const RefusedKeywords& refused;

  // id maps, filled by the steps for the later ones
  std::vector<int> node_ids;  // sorted user ids (resolve_nodes)
  bool node_ids_identity = false;  // node_ids is 1..N: the index is id - 1
  std::vector<int> elem_ids;  // sorted solid ids (resolve_parts_and_elements)
  std::map<int, int> part_index;  // pid -> index in ps.parts
  std::vector<std::vector<int>> part_elems;   // part index -> solid indices
  std::vector<std::vector<int>> part_shells;  // part index -> shell indices (resolve_shells)
  std::vector<std::vector<int>> part_beams;   // part index -> beam indices (resolve_beams)
  std::vector<int> part_material;  // part index -> material index or -1 (resolve_materials)
  CoordinateTable coords;  // resolve_coordinate_systems
  std::map<int, int> curve_index;  // LCID -> index in ld.curves (= Model::load_curves; resolve_curves)
  std::vector<char> curve_used;

  // the steps' own state
  std::set<const RIdList*> resolving;  // the sets being resolved: a set that contains itself is an error
  std::set<const RSegSet*> resolving_segments;
  const std::vector<int>* element_filter = nullptr;  // exterior_faces of these elements instead of parts'
  bool all_faces = false;  // exterior_faces gives every face (an eroding contact's sides), one per solid
  bool isym = false;  // the contact being resolved has ISYM 1: its part sides leave out symmetry-plane faces
  std::vector<char> shell_node;  // per node: it has rotations (a shell's or a beam end's)
  int rotational_spc = 0;  // rotational constraints on nodes without rotations (warning 2005)
  Ref rotational_ref;

  // 0-based index of a node id, or -1
  int node_index(int id) const {
    if (node_ids_identity) return id >= 1 && id <= int(node_ids.size()) ? id - 1 : -1;
    auto it = std::lower_bound(node_ids.begin(), node_ids.end(), id);
    return it != node_ids.end() && *it == id ? int(it - node_ids.begin()) : -1;
  }
  // 0-based index of a solid id, or -1
  int elem_index(int id) const {
    auto it = std::lower_bound(elem_ids.begin(), elem_ids.end(), id);
    return it != elem_ids.end() && *it == id ? int(it - elem_ids.begin()) : -1;
  }
  void err(int id, const Ref& r, const std::string& card, const char* field, std::string detail = {}) {
    diag.add(id, loc_of(r, card, field), std::move(detail));
  }
  // index of a file in Model::source_files (registered on first use)
  int file_index(const DeckFile* f) {
    if (!f) return -1;
    for (std::size_t k = 0; k < m.source_files.size(); ++k)
      if (m.source_files[k] == f->name()) return int(k);
    m.source_files.push_back(f->name());
    return int(m.source_files.size()) - 1;
  }
  // " (it is defined by *KEYWORD at FILE:LINE, a keyword IMPACT-3D does not support)" when a
  // refused keyword defines what a reference names.
  std::string refused_note(char kind, int id) const {
    auto it = refused.defs.find({kind, id});
    if (it == refused.defs.end()) return {};
    return " (it is defined by " + it->second + ", a keyword IMPACT-3D does not support)";
  }
};

// ---------------------------------------------------------------- the steps, in their order
// (keyword_include_transform.cpp) before the others: the records of transformed files get
// their id offsets and coordinates
void apply_include_transforms(ResolveContext& rc, IncludeTransforms& inc);

// (keyword_nodes_elements_resolve.cpp) nodes, then solids (and the parts' index), shells, beams:
// renumbered 1..N in increasing id order; an element's material is -2 - its part index until
// the part steps
void resolve_nodes(ResolveContext& rc);
void resolve_parts_and_elements(ResolveContext& rc);
void resolve_shells(ResolveContext& rc);
void resolve_beams(ResolveContext& rc);

// (keyword_sets_boxes_resolve.cpp) coordinate systems and vectors, once the nodes are known
void resolve_coordinate_systems(ResolveContext& rc);

// (keyword_parts_resolve.cpp) solid, shell and beam parts -> MaterialData
void resolve_materials(ResolveContext& rc);
void resolve_shell_materials(ResolveContext& rc);
void resolve_beam_materials(ResolveContext& rc);

// (keyword_loads_bcs_resolve.cpp) constraints and spot welds
void resolve_spc(ResolveContext& rc);
void resolve_spot_welds(ResolveContext& rc);

// (keyword_control_database_resolve.cpp) time histories
void resolve_history(ResolveContext& rc);

// (keyword_loads_bcs_resolve.cpp) curves, walls, initial conditions
void resolve_curves(ResolveContext& rc);
void resolve_walls(ResolveContext& rc);
void resolve_velocities(ResolveContext& rc);
void resolve_temperatures(ResolveContext& rc);

// (keyword_contacts_resolve.cpp) sliding interfaces, force transducers, tied contacts
void resolve_contacts(ResolveContext& rc);

// (keyword_loads_bcs_resolve.cpp) loads, motions and damping (the unused curves reported), then
// the timed constraints (their zero curve after the deck's)
void resolve_loads(ResolveContext& rc);
void resolve_timed_spc(ResolveContext& rc);

// ---------------------------------------------------------------- lookups the steps share
// (keyword_sets_boxes_resolve.cpp); each reports an undefined id (naming a refused keyword
// that defines it) and returns null or nothing
const RIdList* find_node_set(ResolveContext& rc, int sid, const Ref& r, const std::string& card, const char* field);
const RIdList* find_solid_set(ResolveContext& rc, int sid, const Ref& r, const std::string& card, const char* field);
const Box* find_box(ResolveContext& rc, int id, const Ref& r, const std::string& card, const char* field);
// Node set members as 0-based node indices (a list keeps its order; a set with _ADD or
// _GENERAL terms is sorted, each node once).
std::vector<int> set_nodes(ResolveContext& rc, const RIdList& s, const std::string& card);
// Solid set members as element indices, sorted, each once.
std::vector<int> set_solids(ResolveContext& rc, const RIdList& s, const std::string& card);
// Parts of a part or part set, as part indices.
std::vector<int> parts_of(ResolveContext& rc, bool is_set, int id, const Ref& r, const std::string& card, const char* field);
// The nodes of the parts' solids and shells, sorted, each once.
std::vector<int> nodes_of_parts(ResolveContext& rc, const std::vector<int>& parts);
// A direction given in system cid (0: global) in global components; false (reported) if cid
// is not defined.
bool global_direction(ResolveContext& rc, int cid, const Ref& r, const std::string& card, const char* field, std::array<double, 3>& v);

}  // namespace impact3d::kw
