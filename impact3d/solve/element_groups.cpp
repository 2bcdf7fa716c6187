#include "impact3d/solve/element_groups.h"

#include "impact3d/material/eos.h"

#include <stdexcept>
#include <string>

namespace impact3d {

HexKernel hex_kernel_for_material_type(int type) {
  const MaterialType* t = find_material_type(type);
  if (!t) throw std::logic_error("no solid kernel for material type " + std::to_string(type));
  return t->solid.kind;
}

bool group_carries_back_stress(const SolidKernel& kernel, const MaterialConstants& mc) {
  // the kinematic part of type 3 (isotropic-only types keep beta = 1)
  return kernel.plastic_strain && (1.0 - mc.beta) * mc.E_p != 0.0;
}

bool group_carries_hourglass_state(const MaterialData& md) {
  return md.hourglass_coef != 0.0;
}

void build_element_groups(State& s) {
  const std::size_t nmat = s.mats.size();
  std::vector<int> count(nmat, 0);
  for (int e = 0; e < s.ne; ++e) ++count[std::size_t(s.mat[std::size_t(e)])];
  s.groups.clear();
  std::vector<int> first_slot(nmat, 0);
  int blocks = 0;
  for (std::size_t k = 0; k < nmat; ++k) {
    if (count[k] == 0) continue;
    ElementGroup g;
    const MaterialType& t = material_type(s.mats[k].type);
    g.kernel = t.solid.kind;
    g.solid = &t.solid;
    g.history = int(t.history.size()) + eos_history_count(s.mats[k].eos_form);  // and the EOS's
    g.material = int(k);
    g.first_block = blocks;
    g.num_elems = count[k];
    g.num_blocks = (count[k] + kLanes - 1) / kLanes;
    first_slot[k] = blocks * kLanes;
    blocks += g.num_blocks;
    s.groups.push_back(g);
  }
  s.slot_elem.assign(std::size_t(blocks) * kLanes, -1);
  s.elem_slot.assign(std::size_t(s.ne), -1);
  for (int e = 0; e < s.ne; ++e) {
    const int slot = first_slot[std::size_t(s.mat[std::size_t(e)])]++;
    s.slot_elem[std::size_t(slot)] = e;
    s.elem_slot[std::size_t(e)] = slot;
  }
  s.block_results.assign(std::size_t(blocks), BlockResult{});
}

}  // namespace impact3d
