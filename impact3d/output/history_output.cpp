#include "impact3d/output/history_output.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "impact3d/material/material.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/solve/mass_scaling.h"
#include "version.h"

namespace impact3d {

namespace {
enum { kGlstat, kMatsum, kRwforc, kRcforc, kNodout, kElout };
const char* kNames[HistoryOutput::kNumAscii] = {"glstat", "matsum", "rwforc", "rcforc", "nodout", "elout"};

[[noreturn]] void fail(const std::string& what, const std::string& file) {
  throw std::runtime_error(what + " " + file + ": " + std::strerror(errno));
}

// A block's heading in nodout and elout (LS-DYNA's words, letters spaced): "<title> for time
// step <cycle> ( at time <time> )", then the columns' line.
void time_step_heading(FILE* f, const char* spaced_title, const char* columns, const State& s) {
  std::fprintf(f, "\n %s   f o r   t i m e   s t e p %8d   ( at time %12.5E )\n%s", spaced_title, s.cycle, s.time, columns);
}

}  // namespace

const char* HistoryOutput::ascii_name(int k) { return kNames[k]; }

HistoryOutput::~HistoryOutput() {
  for (FILE*& f : files_)
    if (f) std::fclose(f);
}

void HistoryOutput::open(const Model& m, const std::string& dir, const std::string& thdt_root,
                         int word_size, bool resume, const std::uint64_t* ascii_bytes,
                         int thdt_states) {
  dir_ = dir.empty() ? "." : dir;
  th_nodes_.clear();
  th_solids_.clear();
  th_shells_.clear();
  th_beams_.clear();
  for (const auto& b : m.shell_th_blocks)
    for (int k = b[0]; k <= b[1]; ++k) th_shells_.push_back(k - 1);
  for (const auto& b : m.beam_th_blocks)
    for (int k = b[0]; k <= b[1]; ++k) th_beams_.push_back(k - 1);
  beam_points_ = beam_plot_points(m);
  for (const auto& b : m.node_th_blocks)  // deck numbers (init/mesh_order.h)
    for (int n = b[0]; n <= b[1]; ++n) th_nodes_.push_back(m.node_of_deck_number(n));
  for (const auto& b : m.solid_th_blocks)
    for (int e = b[0]; e <= b[1]; ++e) th_solids_.push_back(m.hex_of_deck_number(e));
  bool want[kNumAscii] = {true, true, !m.walls.empty(), m.num_interface_outputs() > 0, !th_nodes_.empty(),
                          !th_solids_.empty() || !th_shells_.empty() || !th_beams_.empty()};
  for (int k = 0; k < kNumAscii; ++k) {
    if (!want[k]) continue;
    const std::string path = dir_ + "/" + kNames[k];
    if (resume) {
      // a file shorter than the dump recorded cannot be continued (truncate would pad it with
      // zero bytes)
      struct stat st {};
      if (::stat(path.c_str(), &st) != 0) fail("cannot cut back", path);
      if (static_cast<std::uint64_t>(st.st_size) < ascii_bytes[k])
        throw std::runtime_error("cannot resume " + path + ": " + std::to_string(st.st_size) +
                                 " bytes, shorter than the " + std::to_string(ascii_bytes[k]) +
                                 " bytes the restart dump expects");
      if (::truncate(path.c_str(), static_cast<off_t>(ascii_bytes[k])) != 0) fail("cannot cut back", path);
      files_[k] = std::fopen(path.c_str(), "ab");
    } else {
      files_[k] = std::fopen(path.c_str(), "wb");
    }
    if (!files_[k]) fail("cannot open", path);
    if (!resume) {
      std::fprintf(files_[k], " %s   IMPACT-3D %s\n %s\n\n", kNames[k], IMPACT3D_VERSION, m.title.c_str());
      if (k == kRwforc)
        std::fprintf(files_[k], " r i g i d   w a l l   f o r c e s  (force on the wall, global axes)\n"
                                "        time  wall#   normal-force        x-force        y-force        z-force\n");
      if (k == kRcforc)
        std::fprintf(files_[k], " r e s u l t a n t   i n t e r f a c e   f o r c e s  (force on the slave side; the master side carries the opposite)\n"
                                "        time  interface#        x-force        y-force        z-force\n");
      if (k == kRcforc && !m.force_transducers.empty())
        std::fprintf(files_[k], " (interfaces 1-%zu: sliding interfaces; %zu-%zu: force transducers, the force on their side A)\n",
                     m.interfaces.size(), m.interfaces.size() + 1, m.interfaces.size() + m.force_transducers.size());
    }
  }
  // binary time histories: the solids', shells' and beams' nodes (a beam's orientation node
  // too) plus the listed nodes, in deck order
  if (!th_nodes_.empty() || !th_solids_.empty() || !th_shells_.empty() || !th_beams_.empty()) {
    thdt_node_of_.assign(std::size_t(m.num_nodes()), -1);
    std::vector<int> nodes = th_nodes_;
    for (int e : th_solids_)
      for (int n : m.hex_nodes[std::size_t(e)]) nodes.push_back(n);
    for (int k : th_shells_)
      for (int n : m.shell_nodes[std::size_t(k)]) nodes.push_back(n);
    for (int b : th_beams_)
      for (int n : m.beam_nodes[std::size_t(b)])
        if (n >= 0) nodes.push_back(n);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    subset_nodes_ = nodes;
    for (std::size_t k = 0; k < nodes.size(); ++k) thdt_node_of_[std::size_t(nodes[k])] = int(k);
    PlotGeometry g;
    g.title = m.title;
    g.num_materials = int(m.materials.size());
    g.num_rigid_walls = int(m.walls.size());
    g.num_interfaces = m.num_interface_outputs();
    for (int n : nodes) {
      g.x0.insert(g.x0.end(), {m.x[std::size_t(n)], m.y[std::size_t(n)], m.z[std::size_t(n)]});
      g.node_user_ids.push_back(m.node_id(n));
    }
    for (int e : th_solids_) {
      for (int n : m.hex_nodes[std::size_t(e)]) g.hex_nodes.push_back(thdt_node_of_[std::size_t(n)]);
      g.hex_material.push_back(m.hex_material[std::size_t(e)] + 1);
      g.hex_user_ids.push_back(m.hex_id(e));
    }
    for (int k : th_shells_) {
      for (int n : m.shell_nodes[std::size_t(k)]) g.shell_nodes.push_back(thdt_node_of_[std::size_t(n)]);
      g.shell_material.push_back(m.shell_material[std::size_t(k)] + 1);
      g.shell_user_ids.push_back(m.shell_id(k));
    }
    for (int b : th_beams_) {
      const auto& c = m.beam_nodes[std::size_t(b)];
      for (int j = 0; j < 2; ++j) g.beam_nodes.push_back(thdt_node_of_[std::size_t(c[std::size_t(j)])]);
      g.beam_orientation.push_back(c[2] >= 0 ? thdt_node_of_[std::size_t(c[2])] : -1);
      g.beam_material.push_back(m.beam_material[std::size_t(b)] + 1);
      g.beam_user_ids.push_back(m.beam_id(b));
    }
    g.beam_points = beam_points_;
    for (const auto& md : m.materials)
      g.part_titles.push_back(md.title.empty() ? "material " + std::to_string(md.number) : md.title.substr(0, 72));
    thdt_ = std::make_unique<PlotWriter>();
    if (resume)
      thdt_->resume(thdt_root, g, word_size, PlotWriter::kDefaultMemberSizeLimitWords, thdt_states);
    else
      thdt_->open(thdt_root, g, word_size);
  }
}

// glstat: the energies, step and global velocity of the output time (LS-DYNA's layout).
void HistoryOutput::write_glstat(FILE* f, const Model& m, const State& s) {
  std::fprintf(f,
               "\n dt of cycle %9d is controlled by solid %9d\n\n"
               " time...........................  %12.5E\n"
               " time step......................  %12.5E\n"
               " kinetic energy.................  %12.5E\n"
               " internal energy................  %12.5E\n"
               " hourglass energy ..............  %12.5E\n"
               " bulk viscosity energy..........  %12.5E\n"
               " sliding interface energy.......  %12.5E\n"
               " rigid wall energy..............  %12.5E\n"
               " external work..................  %12.5E\n"
               " total energy...................  %12.5E\n"
               " total energy / initial energy..  %12.5E\n"
               " global x velocity..............  %12.5E\n"
               " global y velocity..............  %12.5E\n"
               " global z velocity..............  %12.5E\n",
               s.cycle, s.dt_elem >= 0 ? m.hex_id(s.dt_elem) : 0, s.time, s.dt_next, s.kinetic, s.internal, s.hourglass,
               s.bulk_viscous, s.contact, s.wall_work, s.external_work, s.total_energy(),
               s.energy_ratio(), ps_.velocity[0], ps_.velocity[1], ps_.velocity[2]);
  if (m.control.mass_scaling_dt != 0)  // LS-DYNA's two mass-scaling lines
    std::fprintf(f,
                 " added mass.....................  %12.5E\n"
                 " percentage increase............  %12.5E\n",
                 s.added_mass, added_mass_percent(s));
}

// matsum: per material the energies, mass and momentum (mass x mean velocity).
void HistoryOutput::write_matsum(FILE* f, const Model& m, const State& s) {
  const auto& ie = ps_.mat_internal_energy;
  const auto& ke = ps_.mat_kinetic_energy;
  const auto& hg = ps_.mat_hourglass_energy;
  const auto& mass = ps_.mat_mass;
  const auto& vel = ps_.mat_velocity;
  const std::size_t nm = m.materials.size();
  std::fprintf(f, "\n time = %12.5E\n", s.time);
  for (std::size_t k = 0; k < nm; ++k) {
    std::fprintf(f,
                 " mat.#=%5d   inten=  %12.4E  kinen=  %12.4E  hgeng=  %12.4E  mass=  %12.4E\n"
                 "               x-mom=  %12.4E  y-mom=  %12.4E  z-mom=  %12.4E\n",
                 m.materials[k].number, ie[k], ke[k], hg[k], mass[k], mass[k] * vel[3 * k], mass[k] * vel[3 * k + 1],
                 mass[k] * vel[3 * k + 2]);
    if (!s.mat_added_mass.empty()) std::fprintf(f, "               added mass=  %12.4E\n", s.mat_added_mass[k]);
  }
}

// rwforc: per rigid wall its normal force and force vector.
void HistoryOutput::write_rwforc(FILE* f, const Model& m, const State& s) {
  // normal force (the push of the body on the wall, positive in compression): the global word
  for (std::size_t w = 0; w < m.walls.size(); ++w) {
    const auto& F = s.wall_force[w];
    // (+ 0.0 turns a negative zero into zero)
    std::fprintf(f, " %12.5E %5zu %14.6E %14.6E %14.6E %14.6E\n", s.time, w + 1, ps_.rigid_wall_forces[w],
                 F[0] + 0.0, F[1] + 0.0, F[2] + 0.0);
  }
}

// rcforc: per interface (and transducer) its resultant force.
void HistoryOutput::write_rcforc(FILE* f, const State& s, const std::vector<std::array<double, 3>>& contact_forces) {
  for (std::size_t i = 0; i < contact_forces.size(); ++i)
    std::fprintf(f, " %12.5E %11zu %14.6E %14.6E %14.6E\n", s.time, i + 1, contact_forces[i][0],
                 contact_forces[i][1], contact_forces[i][2]);
}

// nodout: the listed nodes' displacements, velocities, accelerations and coordinates.
void HistoryOutput::write_nodout(FILE* f, const Model& m, const State& s) {
  time_step_heading(f, "n o d a l   p r i n t   o u t",
                    " nodal point   x-disp       y-disp       z-disp       x-vel        y-vel        z-vel"
                    "        x-accl       y-accl       z-accl       x-coor       y-coor       z-coor\n",
                    s);
  for (int n : th_nodes_) {
    const std::size_t i = std::size_t(n);
    std::fprintf(f, "%10d %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E\n",
                 m.node_id(n), s.x[i] - m.x[i], s.y[i] - m.y[i], s.z[i] - m.z[i], s.vx[i], s.vy[i], s.vz[i],
                 s.ax[i], s.ay[i], s.az[i], s.x[i], s.y[i], s.z[i]);
  }
}

// elout, solids: stresses, pressure, von Mises stress and plastic strain.
void HistoryOutput::write_elout_solids(FILE* f, const Model& m, const State& s) {
  time_step_heading(f, "e l e m e n t   s t r e s s   c a l c u l a t i o n s",
                    "  element  materl     sig-xx       sig-yy       sig-zz       sig-xy       sig-yz       sig-zx"
                    "     pressure    von-mises   eff-plastic\n",
                    s);
  for (int e : th_solids_) {
    const double* sg = &s.sig[6 * std::size_t(e)];
    std::fprintf(f, "%9d %7d %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E\n", m.hex_id(e),
                 m.materials[std::size_t(s.mat[std::size_t(e)])].number, sg[0], sg[1], sg[2], sg[3], sg[4],
                 sg[5], -(sg[0] + sg[1] + sg[2]) / 3 + 0.0, calc_von_mises(sg), s.eps_p[std::size_t(e)]);
  }
}

// elout, shells: the mid-surface, inner and outer stresses (global axes, the plot database's
// words) and the plastic strain of the middle, lowest and highest integration point.
void HistoryOutput::write_elout_shells(FILE* f, const Model& m, const State& s) {
  time_step_heading(f, "s h e l l   e l e m e n t   s t r e s s e s",
                    "  element  materl surface      sig-xx       sig-yy       sig-zz       sig-xy       sig-yz       sig-zx"
                    "    von-mises   eff-plastic\n",
                    s);
  static const char* const kSurface[3] = {"mid", "inner", "outer"};
  shell_words_.resize(kShellPlotVars);
  for (int k : th_shells_) {
    fill_shell_plot_vars(s, k, shell_words_.data());
    const int mat = m.materials[std::size_t(m.shell_material[std::size_t(k)])].number;
    for (int layer = 0; layer < 3; ++layer) {
      const double* sg = &shell_words_[std::size_t(7 * layer)];
      std::fprintf(f, "%9d %7d %7s %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E%s\n", m.shell_id(k), mat,
                   kSurface[layer], sg[0] + 0.0, sg[1] + 0.0, sg[2] + 0.0, sg[3] + 0.0, sg[4] + 0.0, sg[5] + 0.0,
                   calc_von_mises(sg), sg[6], s.shells.failed.empty() || !s.shells.failed[std::size_t(k)] ? "" : "  deleted");
    }
  }
}

// elout, beams: the resultants in the beam's local axes (r axial, s and t of the section), as
// LS-DYNA's elout lays out its beam block: axial force, shear forces, bending moments, torsion.
void HistoryOutput::write_elout_beams(FILE* f, const Model& m, const State& s) {
  // beams: the resultants in the beam's local axes (r axial, s and t of the section), as
  // LS-DYNA's elout lays out its beam block: axial force, shear forces, bending moments, torsion
  time_step_heading(f, "r e s u l t a n t s   f o r   b e a m s",
                    "  element  materl       axial      shear-s      shear-t     moment-s     moment-t      torsion\n", s);
  for (int b : th_beams_) {
    const double* r = &s.beams.res[6 * std::size_t(b)];  // N, Q_s, Q_t, T, M_s, M_t
    std::fprintf(f, "%9d %7d %12.4E %12.4E %12.4E %12.4E %12.4E %12.4E%s\n", m.beam_id(b),
                 m.materials[std::size_t(m.beam_material[std::size_t(b)])].number, r[0] + 0.0, r[1] + 0.0, r[2] + 0.0,
                 r[4] + 0.0, r[5] + 0.0, r[3] + 0.0, s.beams.failed[std::size_t(b)] ? "  deleted" : "");
  }
}

// The d3thdt state: the subset's nodes, solids, shells and beams with the global block.
void HistoryOutput::write_thdt_state(const State& s) {
  const std::size_t ns = subset_nodes_.size(), nsol = th_solids_.size();
  ps_.coords.resize(3 * ns);
  ps_.vel.resize(3 * ns);
  ps_.acc.resize(3 * ns);
  for (std::size_t k = 0; k < ns; ++k) {
    const std::size_t i = std::size_t(subset_nodes_[k]);
    ps_.coords[3 * k] = s.x[i]; ps_.coords[3 * k + 1] = s.y[i]; ps_.coords[3 * k + 2] = s.z[i];
    ps_.vel[3 * k] = s.vx[i]; ps_.vel[3 * k + 1] = s.vy[i]; ps_.vel[3 * k + 2] = s.vz[i];
    ps_.acc[3 * k] = s.ax[i]; ps_.acc[3 * k + 1] = s.ay[i]; ps_.acc[3 * k + 2] = s.az[i];
  }
  ps_.stress.resize(6 * nsol);
  ps_.eps.resize(nsol);
  ps_.alive.resize(nsol);
  for (std::size_t k = 0; k < nsol; ++k) {
    const std::size_t e = std::size_t(th_solids_[k]);
    ps_.alive[k] = s.failed[e] ? 0 : 1;
    for (int c = 0; c < 6; ++c) ps_.stress[6 * k + std::size_t(c)] = s.sig[6 * e + std::size_t(c)];
    ps_.eps[k] = s.eps_p[e];
  }
  const std::size_t nsh = th_shells_.size();
  ps_.shell_vars.resize(std::size_t(kShellPlotVars) * nsh);
  ps_.shell_alive.resize(nsh);
  for (std::size_t k = 0; k < nsh; ++k) {
    const int q = th_shells_[k];
    fill_shell_plot_vars(s, q, &ps_.shell_vars[std::size_t(kShellPlotVars) * k]);
    ps_.shell_alive[k] = !s.shells.failed.empty() && s.shells.failed[std::size_t(q)] ? 0 : 1;
  }
  const std::size_t nbh = th_beams_.size(), nv1d = std::size_t(6 + 5 * beam_points_);
  ps_.beam_vars.resize(nv1d * nbh);
  ps_.beam_alive.resize(nbh);
  for (std::size_t k = 0; k < nbh; ++k) {
    const int b = th_beams_[k];
    fill_beam_plot_vars(s, b, beam_points_, &ps_.beam_vars[nv1d * k]);
    ps_.beam_alive[k] = s.beams.failed[std::size_t(b)] ? 0 : 1;
  }
  thdt_->write_state(ps_);
}

void HistoryOutput::write(const Model& m, const State& s,
                          const std::vector<std::array<double, 3>>& contact_forces,
                          double cpu_per_zone_ns) {
  // the global block (energies, per-material books, wall and interface forces): the same
  // numbers as the plot database's, for glstat, matsum and the d3thdt family
  fill_plot_globals(m, s, contact_forces, ps_);
  (void)cpu_per_zone_ns;  // kept out of the files: the tables are bit-reproducible
  if (FILE* f = files_[kGlstat]) write_glstat(f, m, s);
  if (FILE* f = files_[kMatsum]) write_matsum(f, m, s);
  if (FILE* f = files_[kRwforc]) write_rwforc(f, m, s);
  if (FILE* f = files_[kRcforc]) write_rcforc(f, s, contact_forces);
  if (FILE* f = files_[kNodout]) write_nodout(f, m, s);
  if (FILE* f = files_[kElout]; f && !th_solids_.empty()) write_elout_solids(f, m, s);
  if (FILE* f = files_[kElout]; f && !th_shells_.empty()) write_elout_shells(f, m, s);
  if (FILE* f = files_[kElout]; f && !th_beams_.empty()) write_elout_beams(f, m, s);
  for (FILE* f : files_)
    if (f && std::ferror(f)) throw std::runtime_error("write error on a time-history file in " + dir_);
  if (thdt_) write_thdt_state(s);
}

void HistoryOutput::current_sizes(std::uint64_t out[kNumAscii]) const {
  for (int k = 0; k < kNumAscii; ++k) {
    out[k] = 0;
    if (files_[k]) {
      std::fflush(files_[k]);
      long pos = std::ftell(files_[k]);
      out[k] = pos > 0 ? std::uint64_t(pos) : 0;
    }
  }
}

void HistoryOutput::flush() {
  for (FILE* f : files_)
    if (f) std::fflush(f);
}

}  // namespace impact3d
