#pragma once
// dV/dx of the 8-node hexahedron at its nodes: the derivative of the exact volume with respect
// to one node's coordinates, written in terms of the six nodes that share a face with it (the
// classic form of LULESH's CalcElemVolumeDerivative / VoluDer).  One formula and one table of
// neighbours serve the scalar kernel (hexahedron.cpp calc_hex_volume_derivatives) and its block
// form (hex_block.h calc_hex_volume_derivatives_block, one lane each), so the two give the same
// bits.

namespace impact3d {

// Per node, in the order the kernels compute them: the node, then its six face neighbours.
constexpr int kVolumeDerivativeNeighbours[8][7] = {
    {0, 1, 2, 3, 4, 5, 7}, {3, 0, 1, 2, 7, 4, 6}, {2, 3, 0, 1, 6, 7, 5}, {1, 2, 3, 0, 5, 6, 4},
    {4, 7, 6, 5, 0, 3, 1}, {5, 4, 7, 6, 1, 0, 2}, {6, 5, 4, 7, 2, 1, 3}, {7, 6, 5, 4, 3, 2, 0},
};

// dV/dx, dV/dy, dV/dz at a node from the coordinates x(k), y(k), z(k) of its neighbours
// n[0..5] (a row of kVolumeDerivativeNeighbours after the node).  Always inlined: the block
// form's lane loops vectorize only with the formula inside them.
template <class X, class Y, class Z>
[[gnu::always_inline]] inline void volume_derivative(const X& x, const Y& y, const Z& z, const int* n, double& dx, double& dy, double& dz) {
  constexpr double twelfth = 1.0 / 12.0;
  const double x0 = x(n[0]), x1 = x(n[1]), x2 = x(n[2]), x3 = x(n[3]), x4 = x(n[4]), x5 = x(n[5]);
  const double y0 = y(n[0]), y1 = y(n[1]), y2 = y(n[2]), y3 = y(n[3]), y4 = y(n[4]), y5 = y(n[5]);
  const double z0 = z(n[0]), z1 = z(n[1]), z2 = z(n[2]), z3 = z(n[3]), z4 = z(n[4]), z5 = z(n[5]);
  const double ddx = (y1 + y2) * (z0 + z1) - (y0 + y1) * (z1 + z2) + (y0 + y4) * (z3 + z4) -
                     (y3 + y4) * (z0 + z4) - (y2 + y5) * (z3 + z5) + (y3 + y5) * (z2 + z5);
  const double ddy = -(x1 + x2) * (z0 + z1) + (x0 + x1) * (z1 + z2) - (x0 + x4) * (z3 + z4) +
                     (x3 + x4) * (z0 + z4) + (x2 + x5) * (z3 + z5) - (x3 + x5) * (z2 + z5);
  const double ddz = -(y1 + y2) * (x0 + x1) + (y0 + y1) * (x1 + x2) - (y0 + y4) * (x3 + x4) +
                     (y3 + y4) * (x0 + x4) + (y2 + y5) * (x3 + x5) - (y3 + y5) * (x2 + x5);
  dx = ddx * twelfth;
  dy = ddy * twelfth;
  dz = ddz * twelfth;
}

}  // namespace impact3d
