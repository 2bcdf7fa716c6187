// Mili databases (LLNL): what DYNA3D, ParaDyn and Diablo write and GRIZ reads.  A database
// "NAME" is the A file NAMEA (directory, mesh, variable and record definitions), state files
// NAME00, NAME01, ... (time, record id, packed subrecords) and, from file version 3, a T file
// NAMET holding the state maps.  The format, as this reader follows it (learned from the
// MIT-licensed mili-python reader and the Mili programmer's reference; see README.md, "POST-IMPACT
// on Mili databases"):
//
//   A file   16-byte header: "mili", file version, directory version, endian flag (1 big,
//            2 little), precision flag, state-file suffix length, partition scheme, 6 zero bytes;
//            the directories' data (from byte 16 on); the string table; the directory entries
//            (6 words each: type, modifier 1, modifier 2, string count, offset, length; int32 for
//            directory version <= 2, int64 for 3); the state maps (file version <= 2 or no T
//            file; 20 bytes each: int32 file number, int64 offset, float32 time, int32 record id);
//            a 16-byte footer (int32 string-table bytes, commits, directory entries, state maps).
//   T file   the state maps, then one byte '~'.
//   state    float32 time, int32 record-format id, then the subrecords in their order.
//
// Directory types: 0 nodes (block + coordinates), 1 element connectivity (superclass, blocks,
// per element its nodes, material and part), 2 class identifiers (a block of ordinals),
// 3 state-variable dictionary, 4 subrecord definitions, 5/6/9 Mili/application/TI parameters
// (labels, titles, counts), 7 class definitions (short and long name, superclass).
//
// Every count and offset is checked against the file (64-bit arithmetic) before it is used;
// bad input throws std::runtime_error naming the file, the byte offset and what was expected.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "common/plot_database.h"

namespace impact3d {

// Mili superclasses (element families) and data types, by their numbers in the file.
enum MiliSuperclass : int {
    kMiliUnit = 0, kMiliNode = 1, kMiliTruss = 2, kMiliBeam = 3, kMiliTri = 4, kMiliQuad = 5,
    kMiliTet = 6, kMiliPyramid = 7, kMiliWedge = 8, kMiliHex = 9, kMiliMat = 10, kMiliMesh = 11,
    kMiliSurface = 12, kMiliParticle = 13, kMiliTet10 = 14, kMiliInode = 15
};
enum MiliType : int {
    kMiliString = 1, kMiliFloat = 2, kMiliFloat4 = 3, kMiliFloat8 = 4, kMiliInt = 5, kMiliInt4 = 6,
    kMiliInt8 = 7
};
// Nodes per element of a superclass (connectivity words before material and part), 0 if none.
int mili_nodes_per_element(int superclass);

struct MiliClass {
    std::string name, title;        // short name ("brick", "beam", "node") and long name
    int superclass = -1;
    std::int64_t count = 0;         // objects (elements, nodes, materials ...)
    int nodes_per_element = 0;
    std::vector<int> conn;          // count * nodes_per_element, 0-based node ordinals
    std::vector<int> material;      // count, as in the file (1-based)
    std::vector<int> part;          // count
    std::vector<int> labels;        // count user labels (1..count when the file has none)
};

struct MiliVariable {
    std::string name, title;
    int aggregate = 0;              // 0 scalar, 1 vector, 2 array, 3 vector array
    int type = 0;                   // MiliType
    std::vector<int> dims;          // arrays
    std::vector<int> components;    // vectors: indices into variables()
};

// One scalar slot of a subrecord's object: a leaf variable, the top variable the subrecord
// lists, the containers between them and the array index (-1 outside arrays).
struct MiliAtom {
    int leaf = -1, top = -1, point = -1;
    int top_pos = 0;                // index of the top variable in the subrecord's list
    std::vector<int> path;          // variables from top to leaf (inclusive)
    std::int64_t offset = 0;        // object order: bytes from the object's start;
                                    // result order: bytes from the start of the top's block
    int type = 0;
};

struct MiliSubrecord {
    std::string name, class_name;
    int cls = -1;                   // index into classes()
    int organization = 0;           // 0 result ordered, 1 object ordered
    std::vector<int> variables;     // top variables
    std::vector<std::pair<std::int64_t, std::int64_t>> blocks;  // (first 0-based ordinal, count)
    std::int64_t objects = 0;       // sum of the block counts (1 for a mesh-wide subrecord)
    std::int64_t offset = 0;        // bytes from the start of the record data (after time, id)
    std::int64_t bytes = 0;
    std::int64_t object_bytes = 0;  // bytes per object (object order)
    std::vector<std::int64_t> top_block;   // result order: byte offset of each top variable's block
    std::vector<std::int64_t> top_bytes;   // bytes per object of each top variable
    std::vector<MiliAtom> atoms;    // every slot of one object, in file order
};

class MiliReader {
public:
    // True when the file starts with the Mili magic "mili" and a plausible file version,
    // directory version and endian flag (content, not the name, decides).
    static bool is_mili_file(const std::string& path);

    // Opens NAMEA (path of the A file; a path not ending in "A" whose "A" sibling exists is
    // taken as the base name).  Reads header, footer, directories, strings, parameters, mesh,
    // variables, subrecords and state maps, and checks that every state lies inside its file.
    void open(const std::string& path);

    // The format as read.
    int file_version() const { return file_version_; }
    int directory_version() const { return dir_version_; }
    bool big_endian() const { return big_endian_; }
    const std::string& base() const { return base_; }
    const std::vector<MiliClass>& classes() const { return classes_; }
    const std::vector<MiliVariable>& variables() const { return vars_; }
    const std::vector<MiliSubrecord>& subrecords() const { return srecs_; }
    int find_class(const std::string& name) const;       // -1 if none
    int find_variable(const std::string& name) const;    // -1 if none
    std::string param_string(const std::string& name) const;  // "" if absent
    std::int64_t param_int(const std::string& name, std::int64_t dflt) const;
    std::vector<std::string> state_files() const;   // the files the states lie in

    // Raw results: the value of scalar `leaf` for every object of class `cls` (ordinal order)
    // at state i, NaN where no subrecord holds it.  `container` ("" = any) must be the top
    // variable or one on the path to the leaf ("stress_in", "es_1a"); `point` (-1 = outside
    // arrays, or the first point) selects an array index.  When several slots match, the first in
    // file order is taken.  Returns false when no subrecord of the class has the slot.
    bool result(int state, int cls, const std::string& leaf, std::vector<double>& out,
                const std::string& container = "", int point = -1) const;
    // Whether result() finds the slot.
    bool has_result(int cls, const std::string& leaf, const std::string& container = "", int point = -1) const {
        return cls >= 0 && cls < static_cast<int>(classes_.size()) && !matches(cls, leaf, container, point).empty();
    }
    // Array sizes a leaf appears with in a class (the integration points), 0 if outside arrays.
    int points(int cls, const std::string& leaf, const std::string& container = "") const;

    // The same database in the d3plot model POST-IMPACT uses (PlotReader's interface): solids
    // (hex classes; tetrahedra as degenerate hexes), shells (quad and tri classes except contact
    // segments), beams (beam and truss classes), node labels, element labels, materials; each
    // state: time, node positions, velocities, accelerations, solid stresses and plastic
    // strain, shell layers (mid, inner, outer), resultants, thickness, strains, beam
    // resultants, element status, the global and per-material energies and velocities.
    // Materials: 1 .. the largest material of an element drawn (contact-segment materials,
    // DYNA3D's numbers for the sides of sliding interfaces, are left out).
    const PlotGeometry& geometry() const { return geom_; }
    const PlotLayout& layout() const { return layout_; }
    int num_states() const { return static_cast<int>(smaps_.size()); }
    double time(int i) const;
    PlotState state(int i) const { return state(i, geom_.num_materials); }
    // ... with per-material values for materials 1..materials (those the mat class has; zeros
    // beyond): a processor of a parallel run draws fewer materials than the model has.
    PlotState state(int i, int materials) const;
    // Classes not drawn (contact segments, other superclasses), "name (title)".
    const std::vector<std::string>& skipped_classes() const { return skipped_; }

private:
    struct StateMap { std::int32_t file = 0; std::int64_t offset = 0; float time = 0; std::int32_t id = 0; };
    struct Param { int type = 0; bool array = false; std::vector<std::int64_t> dims; std::int64_t offset = 0, length = 0; };
    struct Match { int srec; int atom; };

    std::vector<char> read_record(int state) const;
    std::vector<Match> matches(int cls, const std::string& leaf, const std::string& container, int point) const;
    bool fill(const std::vector<char>& rec, const std::vector<Match>& m, std::vector<double>& out,
              int stride, int slot) const;
    double load(const std::vector<char>& rec, std::int64_t at, int type) const;
    void build_geometry();

    // state()'s steps, in order (mili_database.cpp); rec is the state's record
    bool read_leaf(const std::vector<char>& rec, int cls, const std::string& leaf, const std::string& container,
                   int point, std::vector<double>& out, int stride, int slot) const;
    void read_node_state(const std::vector<char>& rec, PlotState& s) const;
    void read_element_status(const std::vector<char>& rec, const std::vector<std::pair<int, int>>& cls, std::size_t n,
                             std::vector<unsigned char>& alive) const;
    void read_hex_state(const std::vector<char>& rec, PlotState& s) const;
    void read_beam_points(const std::vector<char>& rec, int c, int first, int words, const PlotState& s,
                          std::vector<double>& b) const;
    void read_beam_state(const std::vector<char>& rec, PlotState& s) const;
    void read_shell_class(const std::vector<char>& rec, int c, std::vector<double>& r) const;
    void read_shell_state(const std::vector<char>& rec, PlotState& s) const;
    void read_global_state(const std::vector<char>& rec, PlotState& s) const;
    void read_material_state(const std::vector<char>& rec, int materials, PlotState& s) const;

    // open()'s steps, in order (mili_database.cpp)
    struct Dir { std::int64_t type, m1, m2, nstr, offset, length; std::vector<std::string> s; };  // a directory entry
    struct Tokens;  // the integers and names of a variable dictionary or record format
    void read_header(const std::string& path);
    std::vector<Dir> read_directory();
    void read_parameters(const std::vector<Dir>& dirs);
    void read_classes(const std::vector<Dir>& dirs);
    void read_class_definitions(const std::vector<Dir>& dirs);
    std::vector<std::int64_t> objects_with_data(const std::vector<Dir>& dirs) const;
    void read_node_coordinates(const std::vector<Dir>& dirs, const std::vector<std::int64_t>& backed,
                               std::vector<std::vector<double>>& coords, std::vector<std::vector<unsigned char>>& have);
    void read_connectivity(const std::vector<Dir>& dirs, const std::vector<std::int64_t>& backed,
                           std::vector<std::vector<unsigned char>>& has_conn);
    void finish_classes(std::vector<std::vector<double>>& coords, std::vector<std::vector<unsigned char>>& have,
                        std::vector<std::vector<unsigned char>>& has_conn);
    int class_of(const std::string& name, const char* dir) const;  // the class a directory entry names
    void read_labels(const std::vector<Dir>& dirs);
    void read_variables(const std::vector<Dir>& dirs);
    void read_variable(Tokens& t, int depth, std::vector<std::vector<std::string>>& comp_names);
    void read_record_format(const std::vector<Dir>& dirs);
    MiliSubrecord read_subrecord(Tokens& t, std::int64_t k) const;
    std::int64_t atoms_of(int var, int depth) const;
    void flatten(MiliSubrecord& s, std::size_t top, int var, int point, std::vector<int>& path, int depth,
                 std::int64_t object_bytes, std::int64_t& top_bytes) const;
    void check_state_maps() const;

    std::string a_file_, base_;
    int file_version_ = 0, dir_version_ = 0, suffix_length_ = 2;
    bool big_endian_ = false;
    std::vector<char> a_;   // the A file
    std::map<std::string, Param> params_;
    std::vector<MiliClass> classes_;
    std::vector<MiliVariable> vars_;
    std::vector<MiliSubrecord> srecs_;
    std::int64_t record_bytes_ = 0;
    std::vector<StateMap> smaps_;
    PlotGeometry geom_;
    PlotLayout layout_;
    std::vector<std::string> skipped_;
    // (class, index of its first element in the geometry), per family
    std::vector<std::pair<int, int>> hex_cls_, beam_cls_, shell_cls_;
    std::vector<double> x0_;        // node coordinates of the node class
    int node_cls_ = -1, mat_cls_ = -1, mesh_cls_ = -1;
};

// A Mili database of one processor (NAMEA) or of several (a parallel run writes one A file per
// processor, NAME000A, NAME001A, ..., each with its own state files NAME00000, ...), merged
// by label: a node the processors share (same label) is one node, elements are matched per
// family by label (a label two processors both hold takes the first's values), the states are
// the processors' states, which must have the same count and times.  The interface is
// MiliReader's d3plot model plus raw results by class name and label.
class MiliDatabase {
public:
    // The A files of the database at path: path itself when it is a Mili A file, NAMEA when it
    // exists, else the processors' NAME<digits>A in processor order; empty if none.
    static std::vector<std::string> a_files(const std::string& path);
    void open(const std::string& path);  // throws std::runtime_error

    int num_parts() const { return static_cast<int>(parts_.size()); }
    const MiliReader& part(int k) const { return *parts_[static_cast<std::size_t>(k)]; }
    const PlotGeometry& geometry() const { return parts_.size() == 1 ? parts_[0]->geometry() : geom_; }
    const PlotLayout& layout() const { return parts_.size() == 1 ? parts_[0]->layout() : layout_; }
    int num_states() const { return num_states_; }
    double time(int i) const { return part(0).time(i); }
    PlotState state(int i) const;

    // Raw results of the object with this label in class cls_name (of the first processor that
    // holds it): false when no processor has it or the variable (MiliReader::result).
    bool has_object(const std::string& cls_name, int label) const;
    bool has_result(const std::string& cls_name, const std::string& leaf, const std::string& container = "",
                    int point = -1) const;
    bool result(int state, const std::string& cls_name, int label, const std::string& leaf, double& value,
                const std::string& container = "", int point = -1) const;

private:
    bool locate(const std::string& cls_name, int label, int& part, int& cls, std::int64_t& ordinal) const;
    std::vector<std::unique_ptr<MiliReader>> parts_;
    PlotGeometry geom_;
    PlotLayout layout_;
    int num_states_ = 0;
    // per processor: merged index of each of its nodes / solids / beams / shells
    std::vector<std::vector<int>> node_map_, hex_map_, beam_map_, shell_map_;
};

}  // namespace impact3d
