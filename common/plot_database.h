// Plot state database (d3plot family: DYNA3D / TAURUS / LS-DYNA "plot" files).  The writer
// writes 8-node solids; the reader reads what LS-DYNA writes for solids, thick shells, beams and
// shells (see PlotReader).
//
// Layout written (see shared/spec/plot-database.md, section 8, the recipe that VTK's
// vtkLSDynaReader and lasso-python both read):
//   d3plot      64 control words, initial coordinates, hex connectivity + material, the NARBS
//               user-id section, -999999.0, the 90001 part-title record, the 90000 title record,
//               -999999.0.  No states.
//   d3plot01,   k >= 1 complete states each, then -999999.0.  A state never straddles two
//   d3plot02 .. members; a new member is started before member_size_limit_words would be crossed.
// Words are 4 bytes (int32/float32) or 8 bytes (int64/float64), little-endian.
//
// Crash safety: at every moment of a run the family reads as "all committed states, then a
// marker":
//   * appending to a member: the new state's body (all words but its time word) and a new end
//     marker are written after the old end marker; then the time word is written over the old
//     marker (a single aligned word is the commit point);
//   * a new member is written to "<name>.tmp" and renamed into place.
// The writes reach the operating system in that order before write_state() returns, so a run
// killed at any moment leaves every completed state readable by this reader and by VTK.
// Against the machine going down (power loss, kernel crash), the writes are also made durable
// (fsync) between the body and the commit word and after the commit: for every state when the
// sync interval is 0 (the default), else for the first state written at least that many seconds
// (wall clock) after the last durable one, and always for a new member (before its rename), in
// sync() and in close(); states written in between are durable at the next of these.
// PlotReader additionally ignores an incomplete trailing state at the end of the last member.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace impact3d {

// Static model description (root file).
struct PlotGeometry {
    std::string title;                     // model title (40 chars in control words, 72 in 90000 record)
    int num_materials = 0;                 // NMMAT = NUMMAT8 (parts)
    // Rigid walls: one global word each after the per-part block (the normal force, as LS-DYNA
    // writes for VERSION < 971).  The reader infers it from NGLBV.
    int num_rigid_walls = 0;
    // Sliding interfaces (IMPACT-3D): three global words each after the rigid-wall words, the x y z
    // resultant force on the interface's slave side (as in rcforc).  Their count is control word
    // 63 (zero in LS-DYNA d3plot files); readers that do not know it count the words as further
    // rigid walls (lasso) or skip them with the other globals (VTK).
    int num_interfaces = 0;
    // Extra history values per solid (NEIPH; NV3D = 7 + NEIPH), written after the effective
    // plastic strain: the materials' history values (IMPACT-3D: material_types.h).
    int num_solid_history = 0;
    std::vector<double> x0;                // 3*numnp initial coordinates, x y z per node
    std::vector<int> node_user_ids;        // numnp user node ids, or empty (= 1..numnp)
    std::vector<int> hex_nodes;            // 8*numelh, 0-based node indices, LS-DYNA hex order
    std::vector<int> hex_material;         // numelh, 1-based material number (1..num_materials)
    std::vector<int> hex_user_ids;         // numelh user element ids, or empty (= 1..numelh)
    std::vector<std::string> part_titles;  // num_materials titles (<= 72 chars), or empty ("part N")
    std::vector<int> part_user_ids;        // num_materials user part ids, strictly ascending, or empty (= 1..n)

    // ---- Further element families (filled by PlotReader from LS-DYNA databases; PlotWriter
    //      writes shells and beams too and refuses thick shells).  Nodes 0-based,
    //      materials 1-based in the same 1..num_materials numbering as the solids.
    std::vector<int> tshell_nodes;         // 8*nelt, thick shells (hexahedron node order)
    std::vector<int> tshell_material;      // nelt
    std::vector<int> tshell_user_ids;      // nelt
    std::vector<int> beam_nodes;           // 2*nel2, the two end nodes
    std::vector<int> beam_material;        // nel2
    std::vector<int> beam_user_ids;        // nel2
    // writer: each beam's orientation node n3 (0-based, -1 none; written after n1 n2 in IX2), or
    // empty (none); and the integration points per beam record (NV1D = 6 + 5 beam_points)
    std::vector<int> beam_orientation;     // nel2
    int beam_points = 0;
    std::vector<int> shell_nodes;          // 4*nel4 (n3 == n4: triangle)
    std::vector<int> shell_material;       // nel4
    std::vector<int> shell_user_ids;       // nel4
    std::vector<int> part_types;           // NDIM 5: LS-DYNA material type per part (20 = rigid), else empty

    int num_nodes() const { return static_cast<int>(x0.size() / 3); }
    int num_hexes() const { return static_cast<int>(hex_material.size()); }
    int num_tshells() const { return static_cast<int>(tshell_material.size()); }
    int num_beams() const { return static_cast<int>(beam_material.size()); }
    int num_shells() const { return static_cast<int>(shell_material.size()); }
};

// Words per shell and state (NV2D, the writer's layout): MAXINT = 3 layers (mid-surface, inner,
// outer) of sigma_x sigma_y sigma_z sigma_xy sigma_yz sigma_zx (global axes) and the effective
// plastic strain, then the resultants per unit width Mx My Mxy Qx Qy Nx Ny Nxy (local axes),
// then thickness, two element-dependent words and the internal energy (IOSHL(1..4) = 1000).
constexpr int kShellPlotVars = 3 * 7 + 8 + 4;

// One output time.  Global words are written in the spec's NGLBV = 6 + 7*NMMAT + NUMRW order,
// then the interface words (NGLBV = 6 + 7*NMMAT + NUMRW + 3*NINTF):
//   kinetic, internal, total energy, velocity x y z (whole model),
//   mat_internal_energy[NMMAT], mat_kinetic_energy[NMMAT], mat_velocity[3*NMMAT] (the part's
//   mean velocity, momentum / mass, x y z per material interleaved), mat_mass[NMMAT],
//   mat_hourglass_energy[NMMAT],
//   rigid_wall_forces[NUMRW], interface_forces[3*NINTF].
// For the writer, every per-material / per-node / per-solid vector may be left empty (written as
// zeros; alive: all alive); otherwise it must have exactly the stated size.
struct PlotState {
    double time = 0.0;
    double kinetic_energy = 0.0;
    double internal_energy = 0.0;
    double total_energy = 0.0;
    std::array<double, 3> velocity{};          // x/y/z velocity of the whole model
    std::vector<double> mat_internal_energy;   // NMMAT
    std::vector<double> mat_kinetic_energy;    // NMMAT
    std::vector<double> mat_velocity;          // 3*NMMAT, x y z mean velocity per material
    std::vector<double> mat_mass;              // NMMAT
    std::vector<double> mat_hourglass_energy;  // NMMAT
    std::vector<double> rigid_wall_forces;     // num_rigid_walls normal forces
    std::vector<double> interface_forces;      // 3*num_interfaces: x y z force on the slave side
    std::vector<double> coords;                // 3*numnp current coordinates (x+u, not displacements)
    std::vector<double> vel;                   // 3*numnp
    std::vector<double> acc;                   // 3*numnp (reader: empty if the file has IA = 0)
    std::vector<double> stress;                // 6*numelh: xx yy zz xy yz zx per solid
    std::vector<double> eps;                   // numelh effective plastic strain
    std::vector<double> history;               // NEIPH*numelh extra history values per solid (writer: or empty = zeros)
    std::vector<unsigned char> alive;          // numelh element deletion flags, 1 = alive, 0 = deleted

    // ---- Read only (PlotReader; the writer ignores them).  Empty when the database has none.
    // Record layouts: PlotLayout.  Solids with several integration points: stress and eps above
    // are the means over the points, solid_vars holds every point.
    std::vector<double> temperature;           // numnp nodal temperatures (IT 3: the middle-layer array)
    std::vector<double> solid_vars;            // NV3D*numelh raw solid records, only when NV3D > 7
    std::vector<double> tshell_vars;           // NV3DT*nelt raw thick-shell records
    std::vector<double> beam_vars;             // NV1D*nel2 raw beam records (writer: or empty = zeros):
                                               // N, Q_s, Q_t, M_s, M_t, T, then per point tau_rs,
                                               // tau_tr, sigma_rr, eps_p, eps_rr
    std::vector<double> shell_vars;            // NV2D*nel4 raw shell records (rigid shells: zeros)
    std::vector<unsigned char> tshell_alive;   // nelt, 1/0 (empty: all alive)
    std::vector<unsigned char> beam_alive;     // nel2
    std::vector<unsigned char> shell_alive;    // nel4
    std::vector<unsigned char> node_alive;     // numnp (MDLOPT 1 databases only)
};

// Where the values lie in one element record of a state (derived by PlotReader from the control
// words, checked against NV3D / NV3DT / NV1D / NV2D).  Offsets in words from the record start;
// -1 = not in the database.
struct PlotLayout {
    // solids: solid_points blocks of solid_point_words: 6 stresses, EPS, NEIPH history values
    int solid_points = 1, solid_point_words = 7, solid_history = 0;
    // shells and thick shells: `layers` blocks (through the thickness, in the manual's order:
    // the mid surface, the inner surface, the outer surface, then the further integration
    // points when MAXINT > 3) of layer_words: [6 stresses] [EPS] [NEIPS history]; then the
    // non-layer words.
    int layers = 0, layer_words = 0, layer_stress = -1, layer_eps = -1, layer_history = -1;
    int shell_forces = -1;           // 8 resultants: Mxx Myy Mxy, Qyz Qzx, Nxx Nyy Nxy (per unit width)
    int shell_thickness = -1;        // current thickness (then 2 element-dependent words)
    int shell_strain = -1;           // 12 strains: inner surface xx yy zz xy yz zx, then outer
    int shell_internal_energy = -1;  // internal energy density
    int tshell_strain = -1;          // 12 strains (inner, outer) after the thick-shell layers
    // beams: 6 resultants (axial force, shear s, shear t, moment s, moment t, torsion), then
    // beam_points blocks of 5 (axial stress, shear stress rs, tr, plastic strain, axial strain)
    int beam_points = 0, beam_history = 0;
};

// Control words of a d3plot root file, as read (any LS-DYNA d3plot, not only ours).
struct PlotControl {
    int word_size = 0;          // 4 or 8
    bool byte_swapped = false;  // file is big-endian
    std::string title;          // words 0-9, trailing blanks removed
    std::int64_t runtime = 0, filetype = 0, source_version = 0;
    double version = 0.0;       // word 14
    std::int64_t ndim = 0, numnp = 0, icode = 0, nglbv = 0, it = 0, iu = 0, iv = 0, ia = 0;
    std::int64_t nel8 = 0, nummat8 = 0, numds = 0, numst = 0, nv3d = 0;
    std::int64_t nel2 = 0, nummat2 = 0, nv1d = 0, nel4 = 0, nummat4 = 0, nv2d = 0;
    std::int64_t neiph = 0, neips = 0, maxint = 0, nmsph = 0, ngpsph = 0, narbs = 0;
    std::int64_t nelt = 0, nummatt = 0, nv3dt = 0;
    std::array<std::int64_t, 4> ioshl{};
    std::int64_t ialemat = 0, ncfdv1 = 0, ncfdv2 = 0, nadapt = 0, nmmat = 0, numfluid = 0;
    std::int64_t inn = 0, npefg = 0, nel48 = 0, idtdt = 0, extra = 0;
    std::int64_t nintf = 0;     // word 63: IMPACT-3D sliding interfaces in the globals (0 elsewhere)
    // EXTRA words 64.. (zero when EXTRA = 0)
    std::int64_t nel20 = 0, nt3d = 0, nel27 = 0, neipb = 0, nel21p = 0, nel15t = 0, soleng = 0;
    std::int64_t nel20t = 0, nel40p = 0, nel64 = 0, quadr = 0, cubic = 0, tsheng = 0;
};

class PlotWriter {
public:
    static constexpr std::int64_t kDefaultMemberSizeLimitWords = 7LL * 512 * 512;

    PlotWriter() = default;
    ~PlotWriter();  // closes (never throws)
    PlotWriter(const PlotWriter&) = delete;
    PlotWriter& operator=(const PlotWriter&) = delete;

    // Writes the root file (durably) and removes stale family members "<root><digits>" (and
    // "<root><digits>.tmp") left in the same directory by an earlier run.  Throws
    // std::invalid_argument for an inconsistent geometry or word_size not 4/8, std::runtime_error
    // (file name + errno text) for I/O errors.
    void open(const std::string& root_path, const PlotGeometry& geometry, int word_size = 4,
              std::int64_t member_size_limit_words = kDefaultMemberSizeLimitWords);

    // Restart: the same as open() for a family that already holds at least keep_states states
    // written with the same geometry, word size and member limit: keeps the root and those
    // states, removes what follows them, and appends after them.  Throws std::runtime_error
    // when the family is missing or shorter.
    void resume(const std::string& root_path, const PlotGeometry& geometry, int word_size,
                std::int64_t member_size_limit_words, int keep_states);

    // Appends one state to d3plot01, d3plot02, ... (and fsyncs as the sync interval says).
    // Throws std::invalid_argument for wrong vector sizes, std::logic_error if not open,
    // std::runtime_error for I/O errors (states written before stay intact and readable; the
    // writer stays usable).
    void write_state(const PlotState& state);

    // Seconds of wall clock between durable states (see "Crash safety" above); 0: every state.
    void set_sync_interval(double seconds) { sync_interval_ = seconds; }
    // Makes every state written so far durable (fsync); throws std::runtime_error on failure.
    void sync();
    int num_syncs() const { return syncs_; }  // fsync calls of write_state() and sync()

    // Closes the current member, fsync'ed first when states were written since the last sync
    // (an error there is ignored: call sync() to see it).
    void close() noexcept;
    bool is_open() const { return root_written_; }

    int word_size() const { return ws_; }
    std::int64_t state_words() const { return state_words_; }  // words per state record
    int num_states_written() const { return states_written_; }
    int num_members() const { return members_; }                // state files written so far
    static std::string member_name(const std::string& root_path, int member);  // 0 = root

private:
    void open_impl(const std::string& root_path, const PlotGeometry& geometry, int word_size,
                   std::int64_t member_size_limit_words, int keep_states);
    void resume_members(int keep_states);
    // open_impl's steps (plot_database.cpp)
    static void check_geometry(const PlotGeometry& g, int word_size, std::int64_t member_size_limit_words);
    void set_sizes(const PlotGeometry& g, int word_size, std::int64_t member_size_limit_words);
    std::vector<char> root_file(const PlotGeometry& g) const;
    void put_control_words(std::vector<char>& b, const PlotGeometry& g) const;
    void start_member(const std::vector<char>& buf);
    void append_to_member(const std::vector<char>& buf);

    std::string root_;
    std::vector<double> x0_;      // initial coordinates (written when a state has no coords)
    int ws_ = 4;
    std::int64_t limit_words_ = kDefaultMemberSizeLimitWords;
    int numnp_ = 0, nel8_ = 0, nmmat_ = 0, nrw_ = 0, nif_ = 0, nel4_ = 0, neiph_ = 0, nel2_ = 0, nv1d_ = 0;
    std::int64_t nglbv_ = 0, state_words_ = 0;
    bool root_written_ = false;
    int fd_ = -1;                 // current member
    int members_ = 0;             // number of state members created
    int states_in_member_ = 0;
    std::int64_t marker_pos_ = 0; // byte offset of the end marker in the current member
    int states_written_ = 0;
    double sync_interval_ = 0;    // seconds; 0 = every state
    bool unsynced_ = false;       // states written to fd_ since its last fsync
    std::int64_t last_sync_ns_ = 0;  // steady clock of the last fsync
    int syncs_ = 0;
};

class PlotReader {
public:
    // Reads only the 64 control words of any d3plot root file (word size and byte order detected
    // as VTK does).  Throws std::runtime_error (file, byte offset, what was expected).
    static PlotControl read_control(const std::string& root_path);

    // Reads control words, geometry, user ids and titles, then scans the family for states.
    // Reads 8-node solids (1 or 8 integration points, NEIPH history values), thick shells,
    // beams (resultants and integration points), shells (MAXINT layers, NEIPS, resultants,
    // strains), nodal temperatures (IT), mass scaling and IDTDT node words, element or node
    // deletion flags, NDIM 4 or 5 (rigid shells without data), NARBS user ids, part titles.
    // Refuses (std::runtime_error naming the file and the control word) femzip-compressed
    // databases and features it does not read: 10-node tets, higher-order solids, 8-node
    // shells, SPH, ALE, airbags, CFD, adaptivity, rigid-body data, thermal solid data (NT3D).
    // Never crashes on truncated or corrupt input: every read is bounds-checked.  An incomplete
    // trailing state at the end of the last member (a killed run) is ignored.
    void open(const std::string& root_path);

    const PlotControl& control() const { return ctl_; }
    const PlotGeometry& geometry() const { return geom_; }
    const PlotLayout& layout() const { return layout_; }
    int num_states() const { return static_cast<int>(states_.size()); }
    double time(int i) const;     // time of state i (from the scan)
    PlotState state(int i) const; // throws std::out_of_range / std::runtime_error
    int num_members() const { return num_members_; }  // state files found (d3plot01 ...)

private:
    struct StateLoc { int member; std::int64_t offset; double time; };
    std::string root_;
    PlotControl ctl_;
    PlotGeometry geom_;
    PlotLayout layout_;
    std::int64_t rigid_shells_ = 0;  // NDIM 5: shells with no state data (parts of type 20)
    std::vector<StateLoc> states_;
    std::int64_t state_bytes_ = 0;
    std::int64_t static_end_ = 0;  // byte offset in the root file where state scanning starts
    int num_members_ = 0;
};

}  // namespace impact3d
