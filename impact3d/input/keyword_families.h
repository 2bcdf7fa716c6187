#pragma once
// The keyword reader's families (internal to impact3d/input/keyword_*.cpp): each family reads
// its keywords' cards by their tables (keyword_cards.h) into its records, and builds its part
// of the Model from them once the whole deck is read.

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "impact3d/input/coordinate_systems.h"
#include "impact3d/input/keyword_blocks.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"
#include "impact3d/model/model.h"

namespace impact3d::kw {

// ---------------------------------------------------------------- nodes and elements
// (keyword_nodes_elements.cpp).  Nodes and solids are the bulk of a deck: they keep their card
// (file and line) and the widths it was read with, and find the columns of a field again
// (field_ref) only when a message needs them.

// *NODE columns by format: 0 standard (I8 3E16 I8 I8), 1 long (6 x 20), 2 I10 (I10 3E16 I10 I10).
const std::vector<int>& node_widths(int format);
// *ELEMENT_... columns: n fields (2 or 10) of an id width (8, 10 or 20).
const std::vector<int>& id_widths(int n, int idw);
// Boundary code 0-7 -> fixed translational components (bit 0 x, bit 1 y, bit 2 z).
int bc_bits(int code);

struct RNode {
  int id = 0;
  std::int8_t tc = 0;
  std::uint8_t format = 0;  // node_widths
  double x = 0, y = 0, z = 0;
  KLine card;
  Ref ref() const { return field_ref(card, node_widths(format), 0); }  // id field
};
struct RElem {
  int id = 0, pid = 0;
  std::array<int, 8> n{};
  KLine card;                        // EID PID (and N1-N8 in the one-line form)
  const DeckLine* node_card = nullptr;  // N1-N10 of the two-line form (same file), else null
  std::uint8_t idw = 8;
  const std::vector<int>& widths1() const { return id_widths(node_card ? 2 : 10, idw); }
  Ref ref() const { return field_ref(card, widths1(), 0); }      // id field
  Ref pid_ref() const { return field_ref(card, widths1(), 1); }
  Ref node_ref(int j) const {
    return node_card ? field_ref({card.file, node_card}, id_widths(10, idw), j)
                     : field_ref(card, widths1(), 2 + j);
  }
};
// *ELEMENT_SHELL (and _THICKNESS) card
struct RShell {
  int id = 0, pid = 0;
  std::array<int, 4> n{};
  std::array<double, 4> t{};   // THIC1-THIC4 (0: the section's)
  Ref ref, pid_ref;
  std::array<Ref, 4> node_refs;
  int line = 0;
  const DeckFile* file = nullptr;
};
// *ELEMENT_BEAM (and _THICKNESS) card
struct RBeam {
  int id = 0, pid = 0;
  std::array<int, 3> n{};      // N1 N2 N3 (N3 0: none)
  std::array<double, 4> t{};   // _THICKNESS: TS1 TS2 TT1 TT2 (0: the section's)
  std::array<double, 3> v{};   // _ORIENTATION: VX VY VZ (all 0: none)
  Ref ref, pid_ref;
  std::array<Ref, 3> node_refs;
  int line = 0;
  const DeckFile* file = nullptr;
};

struct KeywordMesh {
  std::vector<RNode, HugePageAllocator<RNode>> nodes;  // in deck order
  std::vector<RElem, HugePageAllocator<RElem>> elems;
  std::vector<RShell> shells;
  std::vector<RBeam> beams;
  std::vector<std::pair<int, int>> node_rc;  // *NODE RC: node id, rotation bits
  // *ELEMENT_SOLID cards of 10-node tetrahedra (N9 or N10 not 0): refused in one message
  long long tet10_count = 0;
  std::pair<Ref, int> tet10_first;
};

// Reads *NODE, *ELEMENT_SOLID, *ELEMENT_SHELL (_THICKNESS) and *ELEMENT_BEAM (_THICKNESS) into
// m; false if the keyword is none of them.
bool read_nodes_elements(const Block& b, KeywordContext& ctx, KeywordMesh& m);

// ---------------------------------------------------------------- materials and equations of state
// (keyword_materials.cpp; the cards are those of the material and EOS tables)
struct RMat {
  const MaterialType* type = nullptr;  // material_types.h
  MaterialData md;                     // type, rho and the type's parameters
  std::vector<Ref> refs;               // where each of the type's parameters was read
  std::string title;
  Ref ref;
};
struct REos {  // *EOS_... (material/eos.h)
  EosData eos;
  Ref ref;
  Ref lcid_ref;  // form 6: the LCID field
};

struct KeywordMaterials {
  std::map<int, RMat> mats;                              // by MID
  std::map<int, REos> eos;                               // by EOSID
  std::map<int, std::pair<ErosionData, Ref>> erosion;    // *MAT_ADD_EROSION by MID
};

// Reads *MAT_... (the material table's types), *EOS_... (the EOS table's forms) and
// *MAT_ADD_EROSION into m; false if the keyword is none of them.
bool read_materials(const Block& b, KeywordContext& ctx, KeywordMaterials& m);

// ---------------------------------------------------------------- parts and sections
// (keyword_parts_sections.cpp)
// *SECTION_BEAM
struct RBeamSection {
  BeamSectionData sec;
  Ref ref;
};
// *SECTION_SHELL
struct RShellSection {
  int elform = 2;  // 2 (0 and blank read as 2) or 16
  int nip = 2;
  double shrf = 1.0;
  std::array<double, 4> t{};
  Ref ref;
};
struct RPart {
  int pid = 0, secid = 0, mid = 0, eosid = 0, hgid = 0;
  std::string title;
  Ref ref, sec_ref, mid_ref, eos_ref, hg_ref;
  int line = 0;
};
struct RSection {
  int elform = 1;
  Ref ref;
};
struct RHourglass {
  int ihq = 0;
  double qm = 0, q1 = 0, q2 = 0;
  bool q1_blank = true, q2_blank = true;
  Ref ref, ihq_ref;
};

struct KeywordParts {
  std::vector<RPart> parts;  // in deck order
  std::map<int, RSection> sections;
  std::map<int, RShellSection> shell_sections;
  std::map<int, RBeamSection> beam_sections;
  std::map<int, RHourglass> hourglasses;
};

// Reads *PART, *SECTION_SOLID / _SHELL / _BEAM and *HOURGLASS into p; false if the keyword is
// none of them.
bool read_parts_sections(const Block& b, KeywordContext& ctx, KeywordParts& p);

// ---------------------------------------------------------------- loads, motions, initial conditions, constraints
// (keyword_loads_bcs.cpp)
struct RLoad {            // one load or prescribed-motion card, resolved after sets and curves
  enum Kind { node, node_set, segment, segment_set, body, rigid_body, motion_node, motion_set, motion_rigid } kind = node;
  std::string keyword;    // as written
  int id = 0;             // node, set or part id
  Ref ref;
  int dof = 0;            // 1-3: x y z (motions: 4 / -4, 5-8 / -8 as LS-DYNA's DOF)
  MotionKind vad = MotionKind::velocity;
  int lcid = 0;
  Ref lc_ref;
  double sf = 1, birth = 0, death = 1e28;
  std::array<int, 4> nodes{};     // *LOAD_SEGMENT
  std::array<Ref, 4> node_refs{};
  std::array<double, 3> dir{};    // *LOAD_BODY_*
  int cid = 0, vid = 0;           // local system of DOF (loads), vector of DOF 4 (motions)
  Ref cid_ref, vid_ref;
  double offset1 = 0, offset2 = 0; // motions DOF 9-11: card 2's point of the axis
};

// *PARAMETER and *PARAMETER_EXPRESSION (keyword_parameters.cpp): the blocks' parameters into
// `params` (the plain values first, then the expressions), errors into `diag`.
void read_parameters(const std::vector<Block>& blocks, ParamTable& params, Diagnostics& diag);

// *CASE (keyword_cases.cpp): the *CASE_BEGIN_n sections open while the deck is scanned; marker
// takes a *CASE_BEGIN_n / *CASE_END_n keyword (name upper case; true if it is one, errors 1006).
struct CaseSections {
  std::vector<int> open;
  bool marker(const std::string& name, const DeckFile& f, const DeckLine& l, Diagnostics& diag);
};
// CID=n on a keyword line (after the keyword name): the keyword belongs to child case n (0: none).
int keyword_case_option(std::string_view t);
// Reads the master *CASE blocks and leaves out the blocks of the child cases case `want` (0: the
// base case) does not hold (warning 2008); its job name into m.case_job.
void select_case(std::vector<Block>& blocks, const CaseSections& sections, int want, const std::string& main_file, KeywordContext& ctx,
                 Model& m);

// *BOUNDARY_PRESCRIBED_MOTION DOF 4, -4 (along VID) and 8, -8 (about VID): the direction is a
// *DEFINE_VECTOR; DOF 5-8 and -8 are rotations (rigid bodies)
inline bool motion_along_vector(int dof) { return dof == 4 || dof == -4 || dof == 8 || dof == -8; }
inline bool motion_is_rotation(int dof) { return (dof >= 5 && dof <= 8) || dof == -8; }
// DOF 9-11: a node turning about an axis along x, y, z through card 2's OFFSET1, OFFSET2;
// -11 to -9 the same with its distance from the axis free (radial motion allowed)
inline bool motion_is_orbit(int dof) { return (dof >= 9 && dof <= 11) || (dof >= -11 && dof <= -9); }
// A *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET record's kind of motion: a rotation (DOF 5-8, -8)
// or turning about the axis through card 2's point (DOF 9-11, PrescribedMotion::center).
void set_node_motion_kind(const RLoad& l, PrescribedMotion& pm);

struct RTemperature {    // one *INITIAL_TEMPERATURE_NODE / _SET card, in deck order
  bool set = false;       // NSID (0: all nodes), else NID
  int id = 0;
  double temp = 0;
  Ref ref;
};

struct RVelocity {       // one initial-velocity definition, in deck order
  enum Kind { all, node_set, node, part, part_set } kind = all;
  int id = 0;
  Ref ref;
  std::array<double, 3> v{};
  // *INITIAL_VELOCITY_GENERATION: rotation OMEGA about the axis through xc along n (unit)
  double omega = 0;
  std::array<double, 3> xc{}, n{};
  // *INITIAL_VELOCITY: exempted node set (its nodes take ve), box (only nodes inside), and the
  // local system of the velocities (ICID)
  std::string keyword;  // as written
  int nsidex = 0, boxid = 0, icid = 0;
  Ref nsidex_ref, boxid_ref, icid_ref;
  std::array<double, 3> ve{};
  std::array<double, 3> w{};  // VXR VYR VZR: rotational velocities (shell nodes)
  bool has_w = false;
};
struct RSpc {
  std::string keyword;  // as written (*BOUNDARY_SPC_SET_ID, ...)
  bool set = false;
  int id = 0;
  int bits = 0;  // fixed local directions (global when cid is 0)
  int rbits = 0;  // rotations: bit 0 rx, 1 ry, 2 rz (they act on shell nodes)
  int cid = 0;
  Ref ref, cid_ref;
  // *BOUNDARY_SPC_..._BIRTH_DEATH: the constraint holds from birth to death only
  bool birth_death = false;
  double birth = 0, death = 1e20;
};
struct RGlobalConstraint {  // *CONSTRAINED_GLOBAL: one plane
  int tc = 0, rc = 0;        // codes 0-7 (1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all)
  int dir = 1;               // normal: 1 x, 2 y, 3 z
  double at = 0;             // the plane's coordinate along dir
  double tol = 0;            // 0: from the mesh
  Ref ref;                   // TC
};

// *RIGIDWALL_PLANAR (_MOVING) and *RIGIDWALL_GEOMETRIC_CYLINDER (_DISPLAY) (the cylinders are
// resolved after the planar walls)
struct RWall {
  std::string keyword;  // as written (*RIGIDWALL_PLANAR_ID, ...)
  int nsid = 0;         // 0: all nodes
  Ref nsid_ref;
  int nsidex = 0, boxid = 0;  // exempted node set, box (only the nodes inside)
  Ref nsidex_ref, boxid_ref;
  StoneWall w;
};
struct RWeld {            // *CONSTRAINED_SPOTWELD or *CONSTRAINED_GENERALIZED_WELD_SPOT, resolved after nodes and sets
  std::string keyword;
  bool generalized = false;  // a node set (NSID) instead of two nodes
  int n1 = 0, n2 = 0, nsid = 0, cid = 0, wid = 0;
  double sn = 0, ss = 0, n = 0, m = 0, tfail = 0;
  double epsf = 0;           // EP / EPSF: ductile failure strain (0: none)
  Ref ref, ref2, cid_ref;    // N1 (NSID), N2, CID
};

struct KeywordLoads {
  std::vector<LoadCurve> curves;  // *DEFINE_CURVE, in deck order
  std::vector<Ref> curve_refs;    // their LCID fields
  std::vector<RLoad> loads;  // in deck order
  std::vector<RVelocity> velocities;
  std::vector<RTemperature> temperatures;
  std::vector<RSpc> spcs;
  std::vector<RGlobalConstraint> globals;  // *CONSTRAINED_GLOBAL, in deck order
  std::vector<RWall> walls;            // *RIGIDWALL_PLANAR (_MOVING), in deck order
  std::vector<RWall> geometric_walls;  // *RIGIDWALL_GEOMETRIC_CYLINDER, in deck order
  std::vector<RWeld> welds;            // spot welds, in deck order
  std::vector<Ref> rot_refs;  // first rotational field of each *BOUNDARY_SPC card that has one
  Ref w_ref;                  // last rotational initial velocity (message when no shell node takes it)
  RLoad damping;             // *DAMPING_GLOBAL (lcid, sf = VALDMP, dir = STX STY STZ)
  bool damping_given = false, damping_rotations = false;
  int body_parts_psid = 0;   // *LOAD_BODY_PARTS
  Ref body_parts_ref;
};

// Reads *LOAD_NODE_POINT / _SET, *LOAD_RIGID_BODY, *LOAD_SEGMENT (_SET), *LOAD_BODY_X / _Y / _Z
// / _VECTOR / _PARTS, *DEFINE_CURVE, *DAMPING_GLOBAL, *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET / _RIGID,
// *BOUNDARY_SPC_NODE / _SET (_BIRTH_DEATH), *CONSTRAINED_GLOBAL, *CONSTRAINED_SPOTWELD,
// *CONSTRAINED_GENERALIZED_WELD_SPOT, *RIGIDWALL_PLANAR (_MOVING), *RIGIDWALL_GEOMETRIC_CYLINDER, *INITIAL_VELOCITY (_NODE, _GENERATION) and *INITIAL_TEMPERATURE_NODE
// / _SET into l; false if the keyword is none of them.
bool read_loads_bcs(const Block& b, KeywordContext& ctx, KeywordLoads& l);

// ---------------------------------------------------------------- sets, boxes and coordinate systems
// (keyword_sets_boxes.cpp)
struct RBox {  // *DEFINE_BOX
  Box box;
  Ref ref;
};

// One card of a *SET_..._GENERAL (OPTION E1-E7, continued by cards of 8 more ids), or the
// member sets of a *SET_..._ADD (option "SET"): applied in deck order, a "D" option removes.
struct RSetTerm {
  std::string option;  // upper case, without the D of a removing option
  bool remove = false;
  std::vector<int> ids;
  std::vector<Ref> refs;
  Ref ref;  // the OPTION field
};
struct RIdList {  // node, part, solid or shell set, or history list
  std::vector<int> ids;
  std::vector<Ref> refs;
  // _GENERATE (_INCREMENT): id ranges BBEG..BEND by INC, kept as ranges (a range may be huge;
  // the entities it holds are found in the sorted ids when the set is resolved)
  std::vector<std::array<long long, 3>> ranges;
  std::vector<RSetTerm> terms;  // _GENERAL and _ADD
  std::string keyword;          // as written (*SET_NODE_GENERAL, ...), upper case
  Ref ref;
};
struct RSegSet {
  std::vector<std::array<int, 4>> segs;
  std::vector<std::array<Ref, 4>> refs;
  std::vector<RSetTerm> terms;  // *SET_SEGMENT_ADD (SET) and _GENERAL (PART, SET_SOLID, ...)
  Ref ref;
};
struct RCoordSystem {  // *DEFINE_COORDINATE_SYSTEM (_NODES, _VECTOR), *DEFINE_VECTOR (_NODES)
  enum Kind { points, nodes, vectors, vector } kind = points;
  int id = 0;
  std::array<double, 9> v{};  // points: O, PX, PXY; vectors: X, XY; vector: tail, head
  std::array<int, 3> n{};     // _NODES: N1 N2 N3; *DEFINE_VECTOR_NODES: tail, head
  int cid = 0;                // CIDL / CID: the values are in this system
  std::string keyword;
  Ref ref, cid_ref;
  std::array<Ref, 3> node_refs;
};
// *DEFINE_TRANSFORMATION: the cards' TRANSL, SCALE and ROTATE composed in order.
struct RTransformation {
  AffineMap map;
  Ref ref;
};

struct KeywordSetsBoxes {
  std::map<int, RIdList> node_sets, part_sets, solid_sets, shell_sets;  // by SID (shell sets: kept for shell elements)
  std::map<int, RSegSet> seg_sets;
  std::map<int, RBox> boxes;  // by BOXID
  std::vector<RCoordSystem> systems;  // in deck order; resolved once the nodes are known
  std::map<int, RTransformation> transformations;  // by TRANID
};

// Reads *SET_NODE / _PART / _SOLID / _SHELL (list, _GENERATE (_INCREMENT), _ADD, _GENERAL),
// *SET_SEGMENT (_ADD, _GENERAL), *DEFINE_BOX, *DEFINE_COORDINATE_SYSTEM / _NODES / _VECTOR, *DEFINE_VECTOR (_NODES) and
// *DEFINE_TRANSFORMATION into s; false if the keyword is none of the family's tables.
bool read_sets_boxes(const Block& b, KeywordContext& ctx, KeywordSetsBoxes& s);

// ---------------------------------------------------------------- contacts
// (keyword_contacts.cpp)
struct RSide {
  int id = 0, type = 0;
  Ref id_ref, type_ref;
  int boxid = 0;  // SABOXID / SBBOXID: only the segments whose centroid is in the box
  Ref box_ref;
};
struct RContact {
  RSide a, b;
  bool symmetric = true;
  double fs = 0, fd = 0, dc = 0;
  double sfsa = 1;
  int soft = 0;
  double sofscl = 0.1;              // optional card A SOFSCL (SOFT 1)
  bool sapr = false, sbpr = false;  // SAPR / SBPR = 1: the side goes to the intfor database
  bool transducer = false;          // *CONTACT_FORCE_TRANSDUCER_PENALTY
  bool single = false;              // *CONTACT_AUTOMATIC_SINGLE_SURFACE (SURFA only)
  bool eroding = false;             // *CONTACT_ERODING_* with EROSOP 1: interior faces join
  bool automatic = false;           // _AUTOMATIC_, single surface, eroding: shells always at +-t/2
  int thkopt = 0, shlthk = 0;       // optional card B (THKOPT 1: SHLTHK of the card; 2: none)
  bool isym = false;                // ISYM 1 (optional card B or the _ERODING_ card): part sides leave out symmetry-plane faces
  int cid = 0;                      // _ID: the contact id
  int tied = 0;                     // 1 *CONTACT_TIED_NODES_TO_SURFACE, 2 *CONTACT_SPOTWELD, 3 _WITH_TORSION (constraint ties)
  int offset = 0;                   // a tied contact's _OFFSET (1: penalty springs) or _CONSTRAINED_OFFSET (2)
  double sast = 0;                  // card 3 SAST of a tied contact (negative: its magnitude is the reach)
  Ref ref;
  std::string keyword;
  std::string name;                 // the keyword without its options (_ID, _TITLE): kept for the converter
};

// Reads a *CONTACT_... keyword (one contact a block) into out; false if the keyword is none of
// the family's.
bool read_contacts(const Block& b, KeywordContext& ctx, std::vector<RContact>& out);

// ---------------------------------------------------------------- control and database cards
// (keyword_control_database.cpp)
struct RHistory {  // one *DATABASE_HISTORY_... block
  bool solid = false;
  bool shell = false;  // *DATABASE_HISTORY_SHELL (_ID): shell ids
  bool beam = false;   // *DATABASE_HISTORY_BEAM (_ID): beam ids
  bool sets = false;   // *DATABASE_HISTORY_NODE_SET / _SOLID_SET: the ids are set ids
  std::vector<int> ids;
  std::vector<Ref> refs;
};

struct KeywordControls {
  bool have_termination = false;
  double end_time = 0, dtmin = 0;
  int end_cycle = 0;
  double dtinit = 0, tssfac = 0.9;
  double dt2ms = 0, endmas = 0;
  bool ms1st = false, erode = false;
  double slsfac = 0.1;
  int penopt = 1;  // *CONTROL_CONTACT PENOPT (LS-DYNA's default: the smaller stiffness)
  int shlthk = 0;  // *CONTROL_CONTACT SHLTHK (non-automatic contacts: 0 shells at mid-surface)
  int ikedit = 100;
  double d3plot_dt = 0, d3thdt_dt = -1, nodout_dt = -1, elout_dt = -1, glstat_dt = -1, ncforc_dt = 0;
  int spcforc = 0;
  int d3dump = 0, runrsf = 0;
  bool intfor_given = false;
  double intfor_dt = 0;
  int ihq = 0;  // *CONTROL_HOURGLASS
  double qh = 0.1;
  double q1 = 1.5, q2 = 0.06;  // *CONTROL_BULK_VISCOSITY
  int btype = 1;
  double rotascl = 1.0;  // *CONTROL_SHELL ROTASCL
  std::vector<RHistory> histories;  // *DATABASE_HISTORY_..., in deck order
  std::optional<std::string> title;  // the last *TITLE's
  // *COMMENT's IMPACT-3D lines (the converter's, for fields LS-DYNA has no keyword for)
  std::optional<int> interface_segments, viscosity_flag;
  int reaction_flag = -1;  // REACTION_PRINT_FLAG (-1 none)
  std::set<int> initially_elastic;  // INITIALLY_ELASTIC PART pid
};

// Reads a control or database keyword (or one read and ignored, warning 2008), *TITLE or
// *COMMENT into c; false if the keyword (upper case, options stripped) is none of them.
bool read_control_database(const Block& b, KeywordContext& ctx, KeywordControls& c);
// The run controls of the Model (model.control) and its title from the cards; error 1311
// without *CONTROL_TERMINATION.
void build_controls(const KeywordControls& c, const std::string& main_deck, Model& m, Diagnostics& diag);

}  // namespace impact3d::kw
