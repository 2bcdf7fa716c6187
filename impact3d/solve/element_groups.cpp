#include "impact3d/solve/element_groups.h"

#include "impact3d/element/hex_sri.h"
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
  return md.hourglass_coef != 0.0 && md.solid_elform != 2;  // ELFORM 2 has no hourglass modes
}

void build_element_groups(State& s, const Model& m) {
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
    g.formulation = t.solid.kind == HexKernel::deformable ? m.materials[k].solid_elform : 1;
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

void init_point_state(State& s) {
  s.pt_first.clear();
  for (auto* v : {&s.pt_sig, &s.pt_back, &s.pt_eps_p, &s.pt_yielded, &s.pt_hist}) v->clear();
  int points = 0;
  for (const ElementGroup& g : s.groups) points += g.formulation == 2 ? kSriPoints * g.num_elems : 0;
  if (points == 0) return;
  std::vector<char> sri(s.mats.size(), 0);
  for (const ElementGroup& g : s.groups) sri[std::size_t(g.material)] = g.formulation == 2;
  s.pt_first.assign(std::size_t(s.ne), -1);
  int next = 0;
  for (int e = 0; e < s.ne; ++e)
    if (sri[std::size_t(s.mat[std::size_t(e)])]) {
      s.pt_first[std::size_t(e)] = next;
      next += kSriPoints;
    }
  const std::size_t np = std::size_t(points), hs = std::size_t(s.hist_stride);
  s.pt_sig.assign(6 * np, 0.0);
  s.pt_back.assign(s.back.empty() ? 0 : 6 * np, 0.0);
  s.pt_eps_p.assign(np, 0.0);
  s.pt_yielded.assign(np, 0.0);
  s.pt_hist.assign(hs * np, 0.0);
  for (int e = 0; e < s.ne; ++e) {
    const int p0 = s.pt_first[std::size_t(e)];
    if (p0 < 0) continue;
    const std::size_t E = std::size_t(e);
    for (std::size_t p = std::size_t(p0); p < std::size_t(p0 + kSriPoints); ++p) {
      for (std::size_t c = 0; c < 6; ++c) s.pt_sig[6 * p + c] = s.sig[6 * E + c];
      if (!s.back.empty())
        for (std::size_t c = 0; c < 6; ++c) s.pt_back[6 * p + c] = s.back[6 * E + c];
      s.pt_eps_p[p] = s.eps_p[E];
      s.pt_yielded[p] = s.yielded[E];
      for (std::size_t h = 0; h < hs; ++h) s.pt_hist[hs * p + h] = s.hist[hs * E + h];
    }
  }
}

}  // namespace impact3d
