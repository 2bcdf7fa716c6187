#pragma once
// A block of kLanes material points, one SIMD lane per point (struct-of-arrays [field][lane]):
// what the material block kernels (material_block.h, MaterialType::solid.update_block) read and
// write.  One kernel per material serves every element family: the solids' HexBlock is a
// MaterialPointBlock with the hexahedron's kinematics around it (element/hex_block.h), the
// shells run their plane-stress trials through one (element/shell_block.h).

namespace impact3d {

// Points per block.  Fixed at 8 for every instruction set: the slot layout of the element
// groups (and with it every sum) does not depend on the machine.
constexpr int kLanes = 8;
using Lanes = double[kLanes];
// Per-point history values a material may carry beyond stress, back stress and plastic strain
// (material_types.h); a group gathers only as many as its material has (at most: Mooney-Rivlin's
// six, the left Cauchy-Green tensor; Johnson-Cook's three and a two-value equation of state).
constexpr int kMaxHistory = 6;

#define IMPACT3D_FOR_LANES _Pragma("omp simd") for (int l = 0; l < kLanes; ++l)

struct alignas(64) MaterialPointBlock {
  Lanes d[6], w[3];                 // strain rate (xx yy zz xy yz zx), spin (W_xy W_yz W_zx)
  Lanes sig[6], back[6], eps_p, yielded;  // stress, back stress, plastic strain, yield flag (0/1)
  Lanes hist[kMaxHistory];          // the material's history values
};

}  // namespace impact3d
