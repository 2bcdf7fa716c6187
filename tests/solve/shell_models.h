#pragma once
// Programmatic shell models for the verification tests: a flat rectangular plate of
// Belytschko-Tsay shells in the x-y plane (steel), node (i, j) = i + (nx + 1) j.

#include <array>

#include "impact3d/model/model.h"

namespace shell_test {

inline impact3d::MaterialData steel_shell(int type = 1, int nip = 2) {
  impact3d::MaterialData m;
  m.number = 1;
  m.type = type;
  m.rho = 7850;
  m.E = 210e9;
  m.nu = 0.3;
  m.sigma_y = 250e6;
  m.E_tan = 2e9;
  m.beta = 1;
  m.shell = true;
  m.shell_section.nip = nip;
  m.shell_section.shrf = 5.0 / 6.0;
  m.title = "steel shell";
  return m;
}

inline int plate_node(int nx, int i, int j) { return i + (nx + 1) * j; }

// A plate [0, lx] x [0, ly] at z = 0 of nx * ny shells of thickness h.
inline impact3d::Model make_plate(int nx, int ny, double lx, double ly, double h,
                                  const impact3d::MaterialData& mat, double end_time) {
  impact3d::Model m;
  m.title = "programmatic plate";
  m.materials = {mat};
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i) {
      m.x.push_back(lx * i / nx);
      m.y.push_back(ly * j / ny);
      m.z.push_back(0.0);
      m.bc.push_back(0);
    }
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      m.shell_nodes.push_back({plate_node(nx, i, j), plate_node(nx, i + 1, j),
                               plate_node(nx, i + 1, j + 1), plate_node(nx, i, j + 1)});
      m.shell_material.push_back(0);
      m.shell_thickness.push_back({h, h, h, h});
    }
  m.control.nmmat = 1;
  m.control.numnp = m.num_nodes();
  m.control.end_time = end_time;
  return m;
}

}  // namespace shell_test
