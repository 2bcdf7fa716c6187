#pragma once
// The node patterns an 8-node solid card may use, shared by both deck readers.

#include <algorithm>
#include <array>

namespace impact3d {

// Hexahedron (8 distinct nodes), wedge (n5=n6 and n7=n8, or n3=n4 and n7=n8), tetrahedron
// (n3=n4 and n5=n6=n7=n8, or the NIKE3D/LS-DYNA form n4=n5=n6=n7=n8).
inline bool is_valid_solid_node_pattern(const std::array<int, 8>& n) {
  std::array<int, 8> s = n;
  std::sort(s.begin(), s.end());
  const int distinct = int(std::unique(s.begin(), s.end()) - s.begin());
  if (distinct == 8) return true;
  if (distinct == 6 && n[4] == n[5] && n[6] == n[7]) return true;
  if (distinct == 6 && n[2] == n[3] && n[6] == n[7]) return true;
  if (distinct == 4 && n[2] == n[3] && n[4] == n[5] && n[5] == n[6] && n[6] == n[7]) return true;
  if (distinct == 4 && n[3] == n[4] && n[4] == n[5] && n[5] == n[6] && n[6] == n[7]) return true;
  return false;
}

// The tetrahedron form n1,n2,n3,n4,n4,n4,n4,n4 (NIKE3D/LS-DYNA) spans, as a trilinear
// hexahedron, only half the tetrahedron's volume (the collapsed face n1-n4 is not planar).
// Store it as the DYNA3D form n1,n2,n3,n3,n4,n4,n4,n4: same base n1-n2-n3 and apex n4, whose
// trilinear volume is the exact tetrahedron volume.
inline void make_canonical_solid_node_pattern(std::array<int, 8>& n) {
  if (n[2] != n[3] && n[3] == n[4] && n[4] == n[5] && n[5] == n[6] && n[6] == n[7])
    n = {n[0], n[1], n[2], n[2], n[3], n[3], n[3], n[3]};
}

}  // namespace impact3d
