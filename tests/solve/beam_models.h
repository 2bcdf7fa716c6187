#pragma once
// Programmatic beam models for the verification tests: a straight line of beams along x
// (node i at x = i L / n), oriented by a node off the line in +y (the s axis along y).

#include <array>

#include "impact3d/model/model.h"

namespace beam_test {

// Steel, Hughes-Liu rectangular section TS (along s = y) x TT (along t = z), QR rule.
inline impact3d::MaterialData steel_beam(int type, double ts, double tt, int qr = 2) {
  impact3d::MaterialData m;
  m.number = 1;
  m.type = type;
  m.rho = 7850;
  m.E = 210e9;
  m.nu = 0.3;
  m.sigma_y = 250e6;
  m.E_tan = 0;
  m.beta = 1;
  m.beam = true;
  m.beam_section.elform = 1;
  m.beam_section.qr = qr;
  m.beam_section.shrf = 5.0 / 6.0;
  m.beam_section.ts1 = m.beam_section.ts2 = ts;
  m.beam_section.tt1 = m.beam_section.tt2 = tt;
  m.title = "steel beam";
  return m;
}

// n beams from (0, 0, 0) to (L, 0, 0); node n + 1 at (0, 1, 0) orients them all.
inline impact3d::Model make_beam_line(int n, double L, const impact3d::MaterialData& mat, double end_time) {
  impact3d::Model m;
  m.title = "programmatic beam line";
  m.materials = {mat};
  for (int i = 0; i <= n; ++i) {
    m.x.push_back(L * i / n);
    m.y.push_back(0.0);
    m.z.push_back(0.0);
    m.bc.push_back(0);
  }
  m.x.push_back(0.0);
  m.y.push_back(1.0);
  m.z.push_back(0.0);
  m.bc.push_back(7);
  for (int i = 0; i < n; ++i) {
    m.beam_nodes.push_back({i, i + 1, n + 1});
    m.beam_material.push_back(0);
    m.beam_thickness.push_back({0, 0, 0, 0});
  }
  m.control.nmmat = 1;
  m.control.numnp = m.num_nodes();
  m.control.end_time = end_time;
  return m;
}

// Clamps node i: translations (bc 7) and rotations.
inline void clamp_node(impact3d::Model& m, int i) {
  m.bc[std::size_t(i)] = 7;
  if (m.rot_bc.empty()) m.rot_bc.assign(std::size_t(m.num_nodes()), 0);
  m.rot_bc[std::size_t(i)] = 7;
}

}  // namespace beam_test
