#pragma once
// State: the struct-of-arrays data the cycle loop works on.  Allocated once at initialization;
// nothing is allocated per cycle.

#include <array>
#include <cstdint>
#include <limits>
#include <vector>

#include "impact3d/element/hex_block.h"
#include "impact3d/material/material.h"
#include "impact3d/material/material_types.h"
#include "impact3d/model/beam_state.h"
#include "impact3d/model/shell_state.h"

namespace impact3d {

struct RigidBody {
  int material = -1;            // 0-based material index
  std::vector<int> nodes;       // 0-based node indices (sorted)
  double mass = 0;
  std::array<double, 3> com{}, vcom{};      // centre of mass, its velocity
  std::array<double, 3> com0{};             // initial centre of mass (prescribed displacements)
  std::array<double, 9> inertia0{};         // inertia about the COM in the initial configuration
  std::array<double, 9> rot{1, 0, 0, 0, 1, 0, 0, 0, 1};  // rotation from initial configuration
  std::array<double, 3> omega{};            // angular velocity
  std::array<double, 3> omega_old{};        // omega^{n-1/2} (prescribed rotations: loads.cpp)
  std::array<double, 3> ang_mom{};          // angular momentum
  std::vector<double> r0;                   // 3 per node: initial position relative to the COM
  // *MAT_RIGID CMO/CON1/CON2: constrained translations and rotations of the body (bits x=1,
  // y=2, z=4, global axes): those components of vcom and omega stay zero
  unsigned fix_translation = 0, fix_rotation = 0;
  // A spot weld's body (Model::spot_welds[weld]; -1: a rigid material's body): its nodes' rotary
  // inertias are in inertia0; per node its normal in the initial configuration (3 per node:
  // towards the centre of the weld's nodes, or CID's z axis, then `axis_normal`); released:
  // the weld has failed and its nodes move freely
  int weld = -1;
  std::vector<double> n0;
  bool axis_normal = false;
  bool released = false;
};

// Tied contacts (Model::node_ties; solve/node_ties.h): per tie its slave node, the indices of its
// segment's nodes among the ties' master nodes (sorted, unique), its weights and whether it ties
// rotations too; per master this cycle's sums (its net force and mass plus its slaves' shares;
// with rotational degrees of freedom the moments and rotary inertias likewise) and its angular
// velocity before the cycle's rotational update.  Allocated once (initialize_state); empty
// without tied contacts.
struct TieState {
  std::vector<int> masters;
  std::vector<int> slave;
  std::vector<std::array<int, 4>> tie_master;
  std::vector<std::array<double, 4>> w;
  std::vector<std::uint8_t> turns;
  // How a turning tie treats the rotation about its segment's normal: 0 tied as the others
  // (*CONTACT_TIED_NODES_TO_SURFACE), 1 the slave's own (*CONTACT_SPOTWELD), 2 the segment's
  // in-plane spin (*CONTACT_SPOTWELD_WITH_TORSION); solve/node_ties.h.
  std::vector<std::uint8_t> twist;
  // Per tie, from the segment at x^n (tie_translations): its unit normal and the spin weights
  // g_a (omega . n = sum_a g_a . v_a); recomputed every cycle, not in restart dumps.
  std::vector<std::array<double, 3>> normal;
  std::vector<std::array<double, 12>> spin;
  std::vector<double> fx, fy, fz, m;
  std::vector<double> mx, my, mz, j;
  std::vector<double> wx0, wy0, wz0;
  // _OFFSET ties (penalty springs, solve/node_ties.h; apart from the constraint ties above): per
  // tie its slave, its segment's nodes and weights, the offset along the normal and the rest, the
  // spring's stiffness (once the first step is known) and its last forces (slave, then the
  // segment's four nodes) for the energy.
  std::vector<int> pen_slave;
  std::vector<std::array<int, 4>> pen_seg;
  std::vector<std::array<double, 4>> pen_w;
  std::vector<double> pen_gap, pen_k;
  std::vector<std::array<double, 3>> pen_rest;
  std::vector<std::array<double, 15>> pen_f;
  bool empty() const { return masters.empty(); }  // no constraint ties
};

struct ElementGroup {
  HexKernel kernel = HexKernel::rigid;
  const SolidKernel* solid = nullptr;  // the material type's kernel (material_types.h)
  int material = 0;          // 0-based material index
  int history = 0;           // history values per solid (State::hist)
  int first_block = 0, num_blocks = 0, num_elems = 0;
  // *SECTION_SOLID ELFORM: 1 the one-point hexahedron (block kernels, hourglass control), 2 the
  // fully integrated selective-reduced hexahedron (element/hex_sri.h: scalar, per-point state
  // in State::pt_*)
  int formulation = 1;
};

// What one block of the element pass hands to the reductions.
struct BlockResult {
  double die = 0, dhg = 0, dbv = 0;   // energy increments, summed over the lanes in lane order
  double dsrc = 0;                     // energy deposited by equations of state (in die too)
  double hg_old = 0, hg_new = 0;       // viscous hourglass: old and new resultants' power (not yet booked)
  double dt_min = 0;                   // smallest element step and its element (lowest on ties)
  int dt_elem = -1;
  int bad_volume_elem = -1, non_finite_elem = -1;  // lowest such element, or -1
  int failed_now = 0;                  // solids that failed in this pass
  // smallest elastic step V / A_max / c of the block's computed solids (contact's maximum
  // stable stiffness, State::elastic_dt_wanted; +inf otherwise)
  double dt_elastic = std::numeric_limits<double>::infinity();
};

// What deleted a solid (message 5004): the value State::failed holds during the cycle it fails.
enum class FailCause : std::uint8_t {
  none = 0,
  plastic_strain = 2,  // effective plastic strain reached the material's failure strain (FAIL)
  time_step,           // its time step fell below TDEL
  damage,              // its damage (the material's failure history value) reached 1
  volume_high,         // relative volume above the erosion limit (*MAT_NULL TEROD)
  volume_low,          // relative volume below the erosion limit (*MAT_NULL CEROD)
  erosion,             // *MAT_ADD_EROSION criteria
};

struct State {
  int nn = 0, ne = 0;
  // nodes
  std::vector<double> x, y, z;        // current coordinates x^n
  std::vector<double> vx, vy, vz;     // velocities v^{n-1/2} before the update, v^{n+1/2} after
  std::vector<double> ax, ay, az;     // accelerations a^n
  std::vector<double> vx_old, vy_old, vz_old;  // v^{n-1/2} kept during the cycle (energy books)
  std::vector<double> fx, fy, fz;     // net nodal force (external - internal); empty without rigid bodies
  std::vector<double> fext_x, fext_y, fext_z;  // contact forces this cycle; empty without sliding interfaces
  std::vector<double> mass;
  std::vector<uint8_t> fix;           // bit 0 x, bit 1 y, bit 2 z
  std::vector<int> rigid_of_node;     // -1 or rigid-body index
  // node -> element corners, CSR in increasing (element, corner) order: fixed summation order.
  // The entries are corner indices into cfx/cfy/cfz (corner_index).
  std::vector<int> corner_start, corner_list;

  // Element groups (solve/element_groups.h): the elements of one family, material and
  // formulation, processed kLanes at a time by one kernel.  Each group fills whole blocks of
  // kLanes slots (its last block padded); blocks are numbered group after group.
  std::vector<ElementGroup> groups;
  std::vector<int> slot_elem;   // element in each slot, -1 for padding
  std::vector<int> elem_slot;   // slot of each element
  // per block, written by the element pass and combined in block order (same bits for any
  // thread count)
  std::vector<BlockResult> block_results;
  std::vector<double> chunk_kinetic;  // kinetic energy per chunk of nodes (node_processing.cpp)
  std::vector<double> chunk_walls;    // per chunk and fixed wall: impulse x y z, energy change
  // Corner j of element e in cfx/cfy/cfz: a block's corner forces are [corner][lane].
  std::size_t corner_index(int e, int j) const {
    const std::size_t slot = std::size_t(elem_slot[std::size_t(e)]);
    return (slot / kLanes) * (8 * kLanes) + std::size_t(j) * kLanes + slot % kLanes;
  }
  // (-1 for a shell or beam corner: those follow the solids' corners, ShellState::corner_base,
  // BeamState::corner_base)
  int corner_element(std::size_t c) const {
    if (c >= 8 * slot_elem.size()) return -1;
    return slot_elem[(c / (8 * kLanes)) * kLanes + c % kLanes];
  }

  // elements
  std::vector<std::array<int, 8>> conn;
  std::vector<int> mat;                // 0-based material index
  std::vector<uint8_t> rigid_elem;     // 1 if the element is rigid (no internal forces)
  std::vector<double> vol0, vol;       // initial and current volume
  std::vector<double> mass_e;          // element mass rho0 * V0
  std::vector<double> sig;             // 6 per element: xx yy zz xy yz zx
  std::vector<double> back;            // 6 per element: back stress (empty when no group has one)
  std::vector<double> eps_p;           // effective plastic strain
  std::vector<uint8_t> yielded;
  std::vector<uint8_t> failed;         // 1: failed (deleted) solid; its FailCause (>= 2) during the cycle it fails
  std::vector<int> newly_failed;       // solids that failed in the last cycle, in element order
  std::vector<FailCause> newly_failed_cause;  // and what deleted each
  std::vector<double> hist;            // hist_stride per element: the material's history values (empty when none)
  int hist_stride = 0;
  std::vector<double> hgs;             // 12 per element: hourglass resultants (empty without hourglass control)
  // Fully integrated solids (ELFORM 2 groups): their Gauss points' material state, 8 points per
  // solid from pt_first[e] (-1: a one-point solid), in element order; point g of solid e is
  // pt_first[e] + g.  pt_sig 6 per point, pt_back 6 per point (empty when no such group carries
  // a back stress), pt_eps_p and pt_yielded 1, pt_hist hist_stride.  The element arrays (sig,
  // eps_p, yielded, hist) hold the mean of the points (the plot database's stress and plastic
  // strain, the failure criteria).  Empty without such solids.
  std::vector<int> pt_first;
  std::vector<double> pt_sig, pt_back, pt_eps_p, pt_yielded, pt_hist;
  // viscous hourglass forms, per element group: the power of the resultants of the last pass at
  // the velocities they were computed from, booked with their power at the next velocities over
  // the velocity step dt_vel between (hexahedron.h, element_processing.cpp)
  std::vector<double> hg_pending;
  std::vector<double> q;               // bulk viscosity
  std::vector<double> cfx, cfy, cfz;   // 8 per slot: corner internal forces (corner_index)
  std::vector<double> dt_e;            // element time step
  // mass scaling (*CONTROL_TIMESTEP DT2MS; solve/mass_scaling.h): each solid's mass factor
  // (its mass is factor x rho0 V0 on its nodes; empty without mass scaling), the mass added
  // so far (all elements, and per material) and the model's mass before any was added
  std::vector<double> ms_factor;
  double added_mass = 0, physical_mass = 0;
  std::vector<double> mat_added_mass;

  std::vector<MaterialConstants> mats;
  std::vector<RigidBody> rigid;
  std::vector<int> newly_released;     // spot welds (rigid-body indices) released in the last cycle
  TieState ties;                       // tied contacts (node_ties.h)
  ShellState shells;                   // the Belytschko-Tsay shells (shell_state.h)
  BeamState beams;                     // the beams (beam_state.h)

  // time integration
  double time = 0;
  int cycle = 0;
  double dt_half = 0;       // dt^{n-1/2}: the step that led to the current positions
  double dt_next = 0;       // dt^{n+1/2}
  double dt_vel = 0;        // dt^n: the velocity step of the cycle just done (0 before the first)
  int dt_elem = -1;         // element controlling the step (0-based)
  double dt0 = 0;           // first step (for the minimum step check)
  // Contact's maximum stable stiffness needs the solids' elastic step V / A_max / c at x^n
  // (sliding_interface.cpp elastic_step): when elastic_dt_wanted, the element pass leaves the
  // smallest over the solids it computed (deformable, not failed) in elastic_dt_solids and its
  // cycle in elastic_dt_cycle (-1: none; not in restart dumps, reset when one is read).
  bool elastic_dt_wanted = false;
  double elastic_dt_solids = std::numeric_limits<double>::infinity();
  int elastic_dt_cycle = -1;

  // energies (accumulated)
  double kinetic = 0, internal = 0, hourglass = 0, bulk_viscous = 0;
  double wall_work = 0, contact = 0, external_work = 0;
  double initial_total = 0;
  // per material: accumulated stress work and hourglass energy (the plot database's
  // per-material books), summed per block and the blocks in order
  std::vector<double> mat_internal, mat_hourglass;
  std::vector<std::array<double, 3>> wall_force;  // force on each wall this cycle
  std::vector<double> wall_disp, wall_vel;        // moving walls: displacement and velocity along the normal
  // per prescribed motion: the angle a rigid rotation's body has turned about its axis since
  // the start (the displacement form's u; 0 for the other motions)
  std::vector<double> motion_angle;

  // Every field that changes during the run, for restart dumps: a dump restores these on top
  // of a State built by initialize_state from the same Model, and the run goes on bit for bit.
  // A new dynamic field must be added here (the restart test catches a missing one).
  template <class V>
  void visit_dynamic_fields(V&& v) {
    v(x); v(y); v(z); v(vx); v(vy); v(vz); v(ax); v(ay); v(az);
    v(vx_old); v(vy_old); v(vz_old); v(fx); v(fy); v(fz); v(fext_x); v(fext_y); v(fext_z);
    v(vol); v(sig); v(back); v(eps_p); v(hist); v(yielded); v(failed); v(hgs);
    v(pt_sig); v(pt_back); v(pt_eps_p); v(pt_yielded); v(pt_hist); v(hg_pending); v(q); v(cfx); v(cfy); v(cfz);
    v(dt_e); v(mat_internal); v(mat_hourglass);
    v(mass); v(shells.inertia); v(ms_factor); v(shells.ms_factor); v(added_mass); v(mat_added_mass);
    v(time); v(cycle); v(dt_half); v(dt_next); v(dt_vel); v(dt_elem); v(dt0);
    v(kinetic); v(internal); v(hourglass); v(bulk_viscous); v(wall_work); v(contact);
    v(external_work); v(initial_total); v(wall_force); v(wall_disp); v(wall_vel); v(motion_angle);
    v(shells.area); v(shells.sig); v(shells.back); v(shells.eps_p); v(shells.yielded);
    v(shells.hgq); v(shells.drill); v(shells.dt_e); v(shells.energy); v(shells.failed); v(shells.cmx); v(shells.cmy); v(shells.cmz);
    v(shells.wx); v(shells.wy); v(shells.wz); v(shells.rot_kinetic);
    v(beams.length); v(beams.e2); v(beams.sig); v(beams.eps_rr); v(beams.back); v(beams.eps_p); v(beams.yielded);
    v(beams.res); v(beams.bs); v(beams.dt_e); v(beams.energy); v(beams.failed);
    v(beams.weld_res); v(beams.weld_res_count);
    v(rigid_of_node);
    for (RigidBody& rb : rigid) {
      v(rb.com); v(rb.vcom); v(rb.rot); v(rb.omega); v(rb.omega_old); v(rb.ang_mom); v(rb.released);
    }
  }

  double total_energy() const {
    return kinetic + internal + hourglass + bulk_viscous + wall_work + contact;
  }
  double energy_ratio() const {
    double ref = initial_total + external_work;
    return ref != 0 ? total_energy() / ref : 1.0;
  }
};

}  // namespace impact3d
