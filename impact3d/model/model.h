#pragma once
// Model: what the deck says, in the deck's own numbering, after the input phase has read and
// checked it.  Nodes and solids are numbered 1..NUMNP and 1..NUMELH in the deck (each number
// once, any order); the arrays here are indexed by number - 1, until the starter renumbers the
// mesh for locality (init/mesh_order.h: then node_order / hex_order say where each deck number
// went and node_user_id / hex_user_id hold the deck's ids).  Element node references are
// 0-based node indices.

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace impact3d {

struct ControlData {
  // card 2
  int nmmat = 0, numnp = 0, numelh = 0;
  int interface_segments_out = 0;
  double interface_out_interval = 0;
  // card 3
  int node_th_blocks = 0, solid_th_blocks = 0;
  int report_interval = 100;  // cycles between run-log lines
  int reaction_print_flag = 0;
  // card 5
  int numlc = 0, num_walls = 0, num_init_velocity_cards = 0, num_interfaces = 0;
  int num_nodal_load_cards = 0, num_pressure_cards = 0, num_motion_cards = 0;
  std::array<int, 3> base_acceleration{};  // card 5 fields 9-11: 1 = a base-acceleration card for x, y, z
  // card 6
  double end_time = 0;
  int end_cycle = 0;         // also stop after this many cycles (0: no limit; keyword ENDCYC)
  double th_interval = 0;    // time-history output interval (0 -> end_time / 1000)
  double plot_interval = 0;  // plot-state interval (0 -> end_time / 20)
  double intfor_interval = -1;  // *DATABASE_BINARY_INTFOR DT: interface-force database interval (< 0: none; 0 -> plot interval)
  int restart_dump_cycles = 0, running_restart_cycles = 0;
  double initial_dt = 0;     // 0 = computed
  double penalty_scale = 0.10;
  int viscosity_flag = 0;
  double tssf = 0.90;
  // mass scaling (keyword *CONTROL_TIMESTEP DT2MS, MS1ST; fixed format control card 9):
  // elements whose step is below |mass_scaling_dt| get mass so that it equals |mass_scaling_dt|;
  // > 0 also takes mass from elements above it (at the first cycle); 0 = none
  double mass_scaling_dt = 0;
  bool mass_scaling_first_only = false;  // MS1ST = 1: only at the first cycle
  double end_mass_percent = 0;           // ENDMAS: stop when the added mass reaches this % (0: never)
  // ERODE (*CONTROL_TIMESTEP): solids whose step falls below min_step_factor x the first step
  // are deleted instead of the run ending (message 4003)
  bool erode_small_steps = false;
  // card 8
  double min_step_factor = 0;  // error termination when dt < factor * dt0 (0 = no check)
};

// *SECTION_SHELL of a shell part (LS-DYNA ELFORM 2 Belytschko-Tsay, 16 fully integrated).
struct ShellSectionData {
  int elform = 2;                    // 2 (element/shell_bt.h) or 16 (element/shell_fi.h)
  int nip = 2;                       // Gauss points through the thickness, 1-10
  double shrf = 1.0;                 // transverse shear factor (LS-DYNA: blank/0 -> 1; 5/6 advised)
  std::array<double, 4> t{};         // default nodal thicknesses T1-T4
  int line = 0;
};

// The section of a beam part (LS-DYNA *SECTION_BEAM; a DYNA3D beam material's section cards).
// A reader fills these fields; the starter (init/beam_init.h) builds the integration points.
// Beam local axes: r from node 1 to node 2; s normal to r in the plane of n1, n2 and the
// orientation node n3; t = r x s.
enum class BeamCrossSection : int { rectangular = 0, tubular = 1 };  // LS-DYNA CST 0, 1
struct BeamSectionData {
  // formulation (LS-DYNA ELFORM): 1 Hughes-Liu (integrated over the cross section,
  // co-rotational, transverse shear), 2 Belytschko-Schwer resultant beam (elastic, Euler-
  // Bernoulli), 3 truss (axial force only, no rotations)
  int elform = 1;
  // ELFORM 9 on the card (LS-DYNA's spot-weld beam, *MAT_SPOTWELD only): run as ELFORM 1, the
  // Hughes-Liu kernel, with the card's section (CST 1: TS the weld's diameter, TT 0 a solid
  // round bar); kept to write the card back and to check the material
  bool spot_weld_beam = false;
  double shrf = 1.0;  // transverse shear factor SHRF (0 -> 1; 5/6 for a rectangle is usual)
  // quadrature rule QR (ELFORM 1): 1 one point (no bending stiffness), 2 2x2 Gauss, 3 3x3
  // Gauss, 4 3x3 Lobatto, 5 4x4 Gauss (a tube: 1 point, else 2, 3, 3, 4 Gauss points through
  // the wall times 8 points around); 0 or negative: the user rule below (user_rule not empty)
  int qr = 2;
  BeamCrossSection cst = BeamCrossSection::rectangular;
  // ELFORM 1 sizes at node 1 and node 2: rectangular: TS width along s, TT along t; tubular:
  // TS outer and TT inner diameter (TT 0: a solid bar).  The element uses their means.
  double ts1 = 0, ts2 = 0, tt1 = 0, tt2 = 0;
  double area = 0;  // ELFORM 2 and 3: cross-section area A
  // ELFORM 2: second moments ISS (about s: bending in the r-t plane), ITT (about t), torsional
  // constant J (0: ISS + ITT), shear area SA (read; Euler-Bernoulli bending has no shear strain)
  double iss = 0, itt = 0, jt = 0, sa = 0;
  // A user integration rule (QR <= 0; rectangular only): points (s, t, w) with s, t in
  // [-1, 1] along TS and TT and weights summing to 4 (the area of [-1, 1]^2, DYNA3D's rules).
  std::vector<std::array<double, 3>> user_rule;
  int line = 0;  // deck line of the section card (messages)
};

// *MAT_ADD_EROSION of a material (solids): failure criteria besides the material's own.  A
// criterion whose value equals EXCL (0 by default) is not used; a solid fails when NCS of the
// used criteria hold at once (solve/element_processing, material/material.h erosion_criteria_met).
struct ErosionData {
  bool active = false;
  double excl = 0;
  double mxpres = 0;   // pressure (compression positive) >= MXPRES
  double mnpres = 0;   // pressure <= MNPRES
  double sigp1 = 0;    // largest principal stress >= SIGP1
  double sigvm = 0;    // von Mises stress >= SIGVM
  double voleps = 0;   // volumetric strain V/V0 - 1 beyond VOLEPS (its sign: tension or compression)
  // true (logarithmic) strains from the deformation gradient at the solid's centre
  double mneps = 0;    // smallest principal strain <= MNEPS
  double effeps = 0;   // effective strain sqrt(2/3 e':e') >= EFFEPS
  double mxeps = 0;    // largest principal strain >= MXEPS
  double epssh = 0;    // tensorial shear strain (e1 - e3) / 2 >= EPSSH
  double failtm = 0;   // time >= FAILTM
  int ncs = 1;         // criteria that must hold at once
  int line = 0;
};

// An equation of state of a material (the pressure of its solids; material/eos.h).  form: 0
// none, else DYNA3D's EOS form number (1 *EOS_LINEAR_POLYNOMIAL, 2 *EOS_JWL, 3
// *EOS_SACK_TUESDAY, 4 *EOS_GRUNEISEN, 5 *EOS_RATIO_OF_POLYNOMIALS, 6
// *EOS_LINEAR_POLYNOMIAL_WITH_ENERGY_LEAK, 8 *EOS_TABULATED_COMPACTION, 9 *EOS_TABULATED).
// c: the form's constants (material/eos.h names their places: form 1 C0-C6; form 4 C, S1, S2,
// S3, GAMMA0, A; form 9 EV1-EV10, C1-C10, T1-T10, GAMMA; form 8 those and K1-K10).  e0: the
// initial internal energy per reference volume; v0: the initial relative volume (1).
constexpr int kEosConstants = 41;
struct EosData {
  int form = 0;
  int id = 0;  // the keyword deck's EOSID (messages, the converter)
  std::array<double, kEosConstants> c{};
  double e0 = 0, v0 = 1;
};

struct MaterialData {
  int number = 0;
  int type = 0;          // DYNA3D type number (material_types.h)
  double rho = 0;
  int hourglass_type = 1;
  double hourglass_coef = 0.10;
  int bulk_type = 1;
  double q1 = 1.5;       // quadratic bulk viscosity
  double q2 = 0.06;      // linear bulk viscosity
  std::string title;
  double E = 0, nu = 0, sigma_y = 0, E_tan = 0, beta = 0;
  // type 3: Cowper-Symonds strain-rate scaling of the yield stress, 1 + (rate / C)^(1/P)
  // (C = 0: none), and the effective plastic strain at which a solid fails and is deleted
  // (0: never)
  double rate_c = 0, rate_p = 0, fail_strain = 0;
  bool initially_elastic = false;
  // the type's other parameters (material_types.h: each type's table names their places)
  std::vector<double> par;
  bool packed = false;   // parameters were read 8 per card
  int line = 0;          // line of card 1, for messages
  bool shell = false;    // the part is a shell part (its elements are in Model::shell_nodes)
  bool beam = false;     // the part is a beam part (its elements are in Model::beam_nodes)
  // a solid part's formulation (*SECTION_SOLID ELFORM): 1 the one-point hexahedron, 2 the fully
  // integrated selective-reduced hexahedron (element/hex_sri.h; no hourglass control)
  int solid_elform = 1;
  ErosionData erosion;   // *MAT_ADD_EROSION (keyword decks)
  EosData eos;           // its equation of state (form 0: none; material/eos.h)
  ShellSectionData shell_section;
  BeamSectionData beam_section;  // when beam
};

struct StoneWall {
  std::array<double, 3> tail{}, head{};
  double friction = 0;   // 0 frictionless, 1 stick, between Coulomb
  // moving wall (mass > 0): a rigid plate of this mass that translates along its normal, with
  // initial velocity v0 along the normal (tail -> head); the nodes' impulses act on it
  double mass = 0, v0 = 0;
  std::vector<int> nodes;  // 0-based; empty = all nodes
  int line = 0;
  // *RIGIDWALL_GEOMETRIC_CYLINDER (radius > 0): a fixed rigid cylinder whose axis runs from tail
  // toward head, of this radius and, when length > 0, this length from the tail (0: infinite);
  // nodes are kept outside it (a node past an end of a finite one is free)
  double radius = 0, length = 0;
  bool cylinder() const { return radius > 0; }
};

struct InitialVelocity {
  int first = 0, last = 0, increment = 1;  // deck node numbers; first = 0 means all nodes
  std::array<double, 3> v{};
};

struct SlidingInterface {
  int type = 3;
  double fs = 0, fd = 0, decay = 0;
  double penalty_scale = 0;   // 0 -> control penalty_scale
  // 0 DYNA3D mu K A^2 / V (keyword SOFT 0), 1 IMPACT-3D maximum stable (keyword SOFT -1),
  // 2 LS-DYNA soft constraint (keyword SOFT 1): max(k of choice 0, sofscl 0.5 m* / dt_c^2),
  // 3 LS-DYNA segment-based contact (keyword SOFT 2; docs/contact.md): points of each segment
  // against the other side's segments, k = 0.5 mu m1 m2 / (m1 + m2) / dt_c^2 per segment pair
  int stiffness_method = 0;
  double sofscl = 0.1;        // SOFSCL (choice 2)
  // PENOPT (choices 0 and 2): 1 the smaller of the segment's and the node's stiffness (LS-DYNA's
  // default), 2 the segment's (DYNA3D), 3 the node's
  int penopt = 2;
  bool symmetric = true;
  // Shell thickness in the contact (LS-DYNA's SHLTHK): 0 the shells meet at their mid-surface,
  // one-sided along the segment's normal as written (DYNA3D's sliding interfaces; LS-DYNA's
  // non-automatic contacts by default); 1 the contact surfaces at +-t/2 on both sides, rigid
  // shells at their mid-surface; 2 +-t/2 on every shell (automatic, single-surface and
  // eroding contacts)
  int shell_thickness = 2;
  // *CONTACT_ERODING_*: the sides hold every face of their solids (an interior face once per
  // solid, outward from it); a face is in the surface while its solid lives and the other solid
  // of the face (if any) has failed
  bool eroding = false;
  // *CONTACT card 1 SAPR / SBPR (LS-DYNA's SPR / MPR) = 1: the side's segments go to the
  // interface-force database (intfor)
  bool intfor_slave = false, intfor_master = false;
  std::string name;  // DYNA3D free-format "lagop ... name NAME endfree" (empty: none)
  // The *CONTACT keyword it was read from, options stripped (keyword decks; empty: fixed format):
  // the converter writes it back where it reads as this interface (deck_writer.cpp)
  std::string keyword;
  std::vector<std::array<int, 4>> slave, master;  // 0-based nodes
  // Beam nodes of each side (0-based, sorted, unique; none of them a node of the side's
  // segments): contact nodes without segments.  They search the other side's segments as the
  // segments' nodes do (slave side: pass 0; master side: the symmetric pass 1; a single surface:
  // its one pass); beams are never segments (docs/contact.md "Beams in contact").
  std::vector<int> slave_nodes, master_nodes;
  std::vector<int> slave_line, master_line;       // deck line of each segment card (messages)
  std::vector<int> slave_file, master_file;       // Model::source_files index of that line (empty: the deck)
  int line = 0;
};

// *CONTACT_FORCE_TRANSDUCER_PENALTY: a contact that applies no force and measures the contact
// forces the sliding interfaces put on the nodes of its side A (with a side B: only the forces
// between A and B).
struct ForceTransducer {
  std::vector<int> a_nodes, b_nodes;  // 0-based, sorted, unique; b_nodes empty: no side B
  bool has_b = false;
  int id = 0;    // the _ID card's CID (0: none)
  int line = 0;  // deck line of card 1
};

// A spot weld: *CONSTRAINED_SPOTWELD (two nodes) or *CONSTRAINED_GENERALIZED_WELD_SPOT (a node
// set).  Its nodes move as one rigid body (translations and, for nodes with rotations, their
// rotations) until it fails; then the constraint is released.  It fails when, at one of its
// nodes, (f_n / SN)^N + (f_s / SS)^M >= 1 (f_n the constraint force's tensile component along
// the node's normal, f_s its shear component; a term with SN or SS 0 is not used), or at the
// time TFAIL.  A node's normal points from it to the centre of the weld's nodes (for two nodes,
// along the line joining them); when the nodes coincide the local z axis of CID gives it.
struct SpotWeld {
  std::vector<int> nodes;            // 0-based, >= 2, in the card's or set's order
  double sn = 0, ss = 0;             // failure forces (0: not used)
  double n = 0, m = 0;               // exponents of the normal and shear terms
  double tfail = 1e20;               // failure time
  double epsf = 0;                   // ductile failure: the plastic strain at a weld node (EP, EPSF; 0: not used)
  bool has_axis = false;             // coincident nodes: the normal from CID
  std::array<double, 3> axis{};      // ... its local z axis (global, unit)
  int id = 0;                        // the _ID card's WID (0: none)
  bool generalized = false;          // *CONSTRAINED_GENERALIZED_WELD_SPOT
  int line = 0;                      // deck line of the node card (messages)
  int file = -1;                     // Model::source_files index of that line (-1: the deck)
};

// *CONTACT_SPOTWELD (_WITH_TORSION) and *CONTACT_TIED_{NODES,SURFACE,SHELL_EDGE}_TO_SURFACE
// (solve/node_ties.h): constraint-based tied contacts.  Each slave node within reach of a master segment is projected onto it once
// (when the deck is read: the node is moved onto the segment) and then moves with the segment:
// a NodeTie per tied node.
struct TiedContact {
  bool spotweld = false;                      // *CONTACT_SPOTWELD (else _TIED_NODES_TO_SURFACE)
  bool torsion = false;                       // *CONTACT_SPOTWELD_WITH_TORSION (spotweld too)
  bool rotations = false;                     // rotations tied too (spot welds, _SHELL_EDGE_TO_SURFACE)
  int offset = 0;                             // 1 _OFFSET (penalty springs), 2 _CONSTRAINED_OFFSET: the slaves not moved
  std::string keyword;                        // the keyword read, options stripped (the converter's; empty: by the flags)
  int id = 0;                                 // the _ID card's CID (0: none)
  std::vector<int> slave_nodes;               // 0-based, sorted, unique
  std::vector<std::array<int, 4>> master;     // master segments (0-based nodes)
  double tolerance = 0;                       // |SST| of a negative SST (0: the default reach)
  int tied = 0;                               // slave nodes tied (the rest out of reach: warning)
  int line = 0;                               // deck line of card 1 (messages)
};
struct NodeTie {
  int node = -1;                              // the slave node (0-based)
  int contact = 0;                            // Model::tied_contacts index
  std::array<int, 4> seg{};                   // the master segment's nodes (a triangle repeats n3)
  std::array<double, 4> w{};                  // the shape functions at the projection (sum 1)
  double gap = 0;                             // _OFFSET: the slave's offset along the segment's normal
  std::array<double, 3> rest{};               // _OFFSET: the rest of its offset (global; 0 on a flat segment)
};

struct LoadCurve {
  int number = 0;
  std::vector<double> t, f;
};

// Loads and prescribed motions (the engine applies them: impact3d/solve/loads.*).  Each is
// driven by a load curve: `curve` is the 0-based index into Model::load_curves, and the value at
// time t is scale * curve(t).
struct NodalLoad {             // *LOAD_NODE_POINT / _SET, *LOAD_RIGID_BODY; DYNA3D nodal load cards
  int node = 0;                // 0-based
  std::array<double, 3> dir{}; // unit direction of the force
  int curve = 0;
  double scale = 1;
  int line = 0;                // deck line (messages, echo)
};

// *LOAD_RIGID_BODY: a force at a rigid body's centre of mass
struct RigidBodyLoad {
  int material = 0;            // 0-based material index of the rigid body
  std::array<double, 3> dir{};
  int curve = 0;
  double scale = 1;
  int line = 0;
};

struct PressureLoad {          // *LOAD_SEGMENT / _SET; DYNA3D pressure cards
  std::array<int, 4> nodes{};  // 0-based; nodes[2] == nodes[3]: a triangle
  int curve = 0;
  double scale = 1;            // a positive pressure pushes against the face's right-hand normal
  std::array<double, 4> factor{1, 1, 1, 1};  // per-node multipliers (DYNA3D pressure cards)
  double birth = 0;            // the pressure acts from this time on (LS-DYNA AT, DYNA3D arrival time)
  double death = 1e28;         // ... until this time (*LOAD_SEGMENT_SET DT)
  int line = 0;
};

// Body force (base acceleration): every node of the loaded materials gets the acceleration
// -scale * curve(t) * dir (LS-DYNA's sign: a positive *LOAD_BODY_Z pulls bodies toward -z).
struct BodyLoad {
  std::array<double, 3> dir{};
  int curve = 0;
  double scale = 1;
  int line = 0;
};

// Global mass-weighted damping (*DAMPING_GLOBAL): every node feels f = -D m (sx vx, sy vy, sz vz)
// with D = scale (VALDMP) or, when curve >= 0, the curve's value at t; its work is external work.
struct GlobalDamping {
  bool active = false;
  int curve = -1;                         // 0-based load curve, -1: the constant D
  double d = 0;                           // VALDMP (1/time) when no curve
  std::array<double, 3> factor{1, 1, 1}; // STX STY STZ
  int line = 0;
};

// A prescribed translation of a node (or of a rigid body's centre of mass) along a unit
// direction, between its birth and death times; outside them the motion is free.
enum class MotionKind : int { velocity = 0, acceleration = 1, displacement = 2 };  // LS-DYNA VAD
struct PrescribedMotion {      // *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET / _RIGID; DYNA3D cards
  int node = -1;               // 0-based node, or -1 for a rigid body
  int rigid_material = -1;     // 0-based material index of a rigid body (node == -1)
  std::array<double, 3> dir{};
  MotionKind kind = MotionKind::velocity;
  // a prescribed rotational velocity about dir (DYNA3D DOF 5-7) of a node with rotations
  // (a shell's or a beam's): the velocity form only; of a rigid body (LS-DYNA DOF 5-8): its
  // angular velocity, acceleration or angle about the axis dir through its centre of mass
  bool rotation = false;
  // LS-DYNA DOF -4 / -8: the components normal to dir (velocity, or angular velocity) held at 0
  bool hold_normal = false;
  // LS-DYNA DOF 9-11 of a node: it turns about the axis dir through `center` (its distance from
  // the axis kept; the motion along the axis free); the curve is the angular velocity (kind
  // velocity) or the angle turned (displacement)
  bool orbit = false;
  // LS-DYNA DOF -11 to -9: turning so, its distance from the axis free (the radial motion from
  // the forces on the node and the centrifugal acceleration r omega^2)
  bool radial_free = false;
  std::array<double, 3> center{};
  int curve = 0;
  double scale = 1;
  double birth = 0, death = 1e28;
  int line = 0;
};

struct Model {
  std::string title;
  std::string deck_file;
  bool large_format = true;
  bool keyword_deck = false;  // read from an LS-DYNA keyword deck
  // DYNA3D fixed-format decks: the layout's vintage (FixedVintage: 0 DYNA3D 88, 1 later; -1 a
  // keyword deck) and what the free-format block after the control cards asked for
  int fixed_vintage = -1;
  std::string basename;             // "basename NAME": the plot database's root when g= is not given
  bool exact_output_times = false;  // "exact_output_time": cycles end on the output times
  // *CASE: the case this model is (its JOBID, or "caseN"); empty for the base case.  The run's
  // outputs go to a folder of that name unless o=, g=, d= say otherwise.
  std::string case_job;
  // *KEYWORD NCPU=n: the thread count when the command line gives no ncpu= (0: none given)
  int deck_threads = 0;
  ControlData control;
  std::vector<MaterialData> materials;  // indexed by material number - 1

  // nodes (index = node number - 1)
  std::vector<double> x, y, z;
  std::vector<int> bc;       // 0-7 displacement code
  // solids (index = element number - 1)
  std::vector<std::array<int, 8>> hex_nodes;  // 0-based node indices
  std::vector<int> hex_material;              // 0-based material index
  std::vector<int> hex_line;                  // deck line of each solid card, 0 = not read
  std::vector<int> hex_file;                  // source_files index of that line (empty: the deck)
  std::vector<std::string> source_files;      // include files that lines refer to (keyword decks)
  // the file a line recorded with index `idx` of `files` is in (messages)
  const std::string& file_of(const std::vector<int>& files, std::size_t idx) const {
    if (idx < files.size() && files[idx] >= 0 && std::size_t(files[idx]) < source_files.size())
      return source_files[std::size_t(files[idx])];
    return deck_file;
  }
  // Ids in the deck when they are not 1..N (keyword decks have arbitrary sparse ids and are
  // renumbered 1..N in increasing id order); empty = identity.
  std::vector<int> node_user_id, hex_user_id;

  // Shells (Belytschko-Tsay, index = shell number - 1): nodes n1-n4 (0-based, n3 == n4 for a
  // triangle), material, nodal thicknesses, and where each card is.
  std::vector<std::array<int, 4>> shell_nodes;
  std::vector<int> shell_material;
  std::vector<std::array<double, 4>> shell_thickness;
  std::vector<int> shell_line, shell_file;
  std::vector<int> shell_user_id;            // deck ids when not 1..N (empty: identity)
  // Rotational constraints per node (bit 0 rx, 1 ry, 2 rz; empty: none) and initial
  // rotational velocities (empty: none); they act on nodes that shells use.
  std::vector<std::uint8_t> rot_bc;
  std::vector<std::array<double, 3>> init_omega;
  // Initial nodal temperatures (*INITIAL_TEMPERATURE_NODE / _SET; NaN: none given for the node;
  // empty: none at all): a material with a temperature (type 107) starts each solid at the mean
  // of its nodes'.
  std::vector<double> node_temperature;
  double shell_rotary_scale = 1.0;           // *CONTROL_SHELL ROTASCL: scales the rotary inertia
  int num_shells() const { return static_cast<int>(shell_nodes.size()); }
  int shell_id(int k) const { return shell_user_id.empty() ? k + 1 : shell_user_id[std::size_t(k)]; }

  // Beams (the third family, index = beam number - 1): nodes n1, n2 and the orientation node
  // n3 (0-based; -1: none, then the s axis is the global axis least aligned with the beam,
  // projected normal to it), material (a MaterialData with beam = true and its
  // beam_section), per-element section sizes TS1 TS2 TT1 TT2 (LS-DYNA *ELEMENT_BEAM_THICKNESS;
  // all 0: the section's), where each card is, and the deck ids when not 1..N.  Rotational
  // constraints (rot_bc) and initial rotational velocities (init_omega) act on beam nodes as on
  // shell nodes; the two families share the rotations of common nodes.
  std::vector<std::array<int, 3>> beam_nodes;
  std::vector<int> beam_material;
  std::vector<std::array<double, 4>> beam_thickness;
  // LS-DYNA *ELEMENT_BEAM_ORIENTATION: per beam the vector VX VY VZ from n1 towards a virtual
  // orientation node, used where n3 is -1 (empty, or all 0: none given).
  std::vector<std::array<double, 3>> beam_orientation;
  std::vector<int> beam_line, beam_file;
  std::vector<int> beam_user_id;
  int num_beams() const { return static_cast<int>(beam_nodes.size()); }
  int beam_id(int b) const { return beam_user_id.empty() ? b + 1 : beam_user_id[std::size_t(b)]; }

  std::vector<std::array<int, 2>> node_th_blocks, solid_th_blocks;  // deck numbers, inclusive
  std::vector<std::array<int, 2>> shell_th_blocks;                  // shell numbers 1..N, inclusive
  std::vector<std::array<int, 2>> beam_th_blocks;                   // beam numbers 1..N, inclusive
  std::vector<LoadCurve> load_curves;
  std::vector<StoneWall> walls;
  std::vector<InitialVelocity> init_velocities;
  std::vector<SlidingInterface> interfaces;
  std::vector<ForceTransducer> force_transducers;  // reported after the interfaces (rcforc, globals)
  // interface-force lines of rcforc and the plot globals: the interfaces, then the transducers
  int num_interface_outputs() const { return int(interfaces.size() + force_transducers.size()); }
  std::vector<NodalLoad> nodal_loads;
  std::vector<RigidBodyLoad> rigid_body_loads;
  std::vector<PressureLoad> pressure_loads;
  std::vector<BodyLoad> body_loads;
  std::vector<int> body_load_materials;   // 0-based materials the body loads act on; empty = all
  std::vector<PrescribedMotion> prescribed_motions;
  std::vector<SpotWeld> spot_welds;
  std::vector<TiedContact> tied_contacts;
  std::vector<NodeTie> node_ties;          // in contact order, each contact's slaves in node order
  GlobalDamping damping;
  bool has_loads() const {
    return !nodal_loads.empty() || !rigid_body_loads.empty() || !pressure_loads.empty() || !body_loads.empty() ||
           damping.active;
  }

  int num_nodes() const { return static_cast<int>(x.size()); }
  // The deck's number of node i / solid e (0-based indices): what every message and output shows.
  int node_id(int i) const { return node_user_id.empty() ? i + 1 : node_user_id[std::size_t(i)]; }
  // (an index past the solids is a shell: num_hexes() + shell index, and past the shells a
  // beam: num_hexes() + num_shells() + beam index, as the element pass reports the element
  // controlling the step)
  int hex_id(int e) const {
    if (e >= num_hexes() + num_shells()) return beam_id(e - num_hexes() - num_shells());
    if (e >= num_hexes()) return shell_id(e - num_hexes());
    return hex_user_id.empty() ? e + 1 : hex_user_id[std::size_t(e)];
  }
  int num_hexes() const { return static_cast<int>(hex_nodes.size()); }

  // Mesh ordering (init/mesh_order.h): when the starter renumbered the nodes and solids for
  // locality, node_order[k] / hex_order[k] is the internal index of the node / solid that is
  // k-th in deck order (the readers' numbering 1..N); empty: not renumbered (identity).  The
  // time-history blocks and initial-velocity ranges keep deck-order numbers: resolve them with
  // node_of_deck_number / hex_of_deck_number.
  std::vector<int> node_order, hex_order;
  bool renumbered() const { return !node_order.empty() || !hex_order.empty(); }
  int node_of_deck_number(int n) const { return node_order.empty() ? n - 1 : node_order[std::size_t(n - 1)]; }
  int hex_of_deck_number(int e) const { return hex_order.empty() ? e - 1 : hex_order[std::size_t(e - 1)]; }
};

// Which translational components a boundary-condition code 0-7 fixes.
inline bool bc_fixes_x(int code) { return code == 1 || code == 4 || code == 6 || code == 7; }
inline bool bc_fixes_y(int code) { return code == 2 || code == 4 || code == 5 || code == 7; }
inline bool bc_fixes_z(int code) { return code == 3 || code == 5 || code == 6 || code == 7; }

// A node list as a set: later repeats of a node removed, the order of first appearance kept (a
// wall's nodes are a set: a repeated node must not count twice).
inline void remove_repeated_nodes(std::vector<int>& nodes) {
  std::vector<int> out;
  out.reserve(nodes.size());
  std::vector<int> sorted = nodes;
  std::sort(sorted.begin(), sorted.end());
  if (std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end()) return;  // none
  std::vector<char> seen(sorted.empty() ? 0 : std::size_t(sorted.back()) + 1, 0);
  for (int n : nodes)
    if (n >= 0 && !seen[std::size_t(n)]) seen[std::size_t(n)] = 1, out.push_back(n);
  nodes.swap(out);
}

}  // namespace impact3d
