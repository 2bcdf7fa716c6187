#pragma once
// The one table of material types.  Each type (impact3d/material/types/mat_*.cpp) describes
// everything about itself in one MaterialType value: its numbers and keyword names, the
// layout of its parameters in both deck formats (the readers and the converter loop over
// them), their checks and defaults, its printed echo, the constants its kernel needs (wave
// speed and moduli for the time step and hourglass forms), its solid kernel (scalar reference
// and block form) and its per-element history values.  Nothing else in the code compares
// material type numbers: it asks this table.

#include <array>
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "impact3d/material/material_point_block.h"
#include "impact3d/material/material.h"
#include "impact3d/model/model.h"

namespace impact3d {

// What the element pass does with a group's solids.
enum class HexKernel : uint8_t {
  rigid,       // no internal forces, no step (the nodes move with the rigid body)
  deformable,  // the type's stress update, then the common bulk viscosity, forces, hourglass, step
};

// The per-element state a solid material works on at one point (the scalar kernels' argument;
// the block kernels have the same fields as lanes of a MaterialPointBlock).
struct SolidPointState {
  double sig[6] = {0, 0, 0, 0, 0, 0};
  double back[6] = {0, 0, 0, 0, 0, 0};
  double eps_p = 0;
  double yielded = 0;
  double hist[kMaxHistory] = {};
  double w[3] = {0, 0, 0};  // the spin (W_xy, W_yz, W_zx; read by kernels of the whole velocity gradient)
};

// The block form of a point kernel whose work does not vectorize (Newton loops, pow/log/exp):
// each lane's stress, plastic strain, yield flag and first nh history values copied to a
// SolidPointState, update_point(m, d, dt, state), copied back: the scalar kernel's bits.
template <class PointUpdate>
inline void update_block_lane_by_lane(const MaterialConstants& m, MaterialPointBlock& k, double dt, int nh, PointUpdate update_point) {
  for (int l = 0; l < kLanes; ++l) {
    SolidPointState st;
    double d[6];
    for (int c = 0; c < 6; ++c) d[c] = k.d[c][l], st.sig[c] = k.sig[c][l];
    st.eps_p = k.eps_p[l];
    st.yielded = k.yielded[l];
    for (int h = 0; h < nh; ++h) st.hist[h] = k.hist[h][l];
    for (int c = 0; c < 3; ++c) st.w[c] = k.w[c][l];
    update_point(m, d, dt, st);
    for (int c = 0; c < 6; ++c) k.sig[c][l] = st.sig[c];
    k.eps_p[l] = st.eps_p;
    k.yielded[l] = st.yielded;
    for (int h = 0; h < nh; ++h) k.hist[h][l] = st.hist[h];
  }
}

// A solid kernel: the stress update after the caller's Jaumann rotation of sig (and of back
// when the material carries one).  The block form does, per lane, the scalar form's
// operations in the same order (tests/element/test_hex_block.cpp checks the bits).
struct SolidKernel {
  HexKernel kind = HexKernel::rigid;
  void (*update_point)(const MaterialConstants&, const double d[6], double dt, SolidPointState&) = nullptr;
  void (*update_block)(const MaterialConstants&, MaterialPointBlock&, double dt) = nullptr;
  bool plastic_strain = false;  // reads and writes eps_p / yielded
};

// The 3-D point update of type 24 (*MAT_PIECEWISE_LINEAR_PLASTICITY: elastic trial, the
// radial return on its flow curve with its rate factor; types/mat_piecewise_linear.cpp), the
// solid kernel's scalar form, shared with the shells' plane-stress form (plane_stress.h).
void update_stress_piecewise_linear(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s);
// The same for type 18 (*MAT_POWER_LAW_PLASTICITY, types/mat_power_law.cpp).
void update_stress_power_law(const MaterialConstants& m, const double d[6], double dt, SolidPointState& s);

// A plane-stress kernel for shells: empty today (the shell family still picks its kernel in
// impact3d/init/shell_init.cpp, shell_kernel_for_material_type; to move here).
struct PlaneStressKernel {
  void (*update_point)(const MaterialConstants&, const double d[6], double dt, SolidPointState&) = nullptr;
};

// Checks a parameter gets when the deck is read (both formats), with its message.
enum class ParamCheck : uint8_t {
  none,
  positive,          // > 0
  non_negative,      // >= 0
  fraction,          // in [0, 1]
  poisson,           // in [0, 0.5)
  below_E,           // in [0, E)
  flag01,            // 0 or 1
  integer,           // a whole number >= 0 (flags)
  curve,             // a load-curve reference (0 = none): the readers map and check it
  unsupported,       // LS-DYNA field IMPACT-3D does not implement: nonzero is message 1102
  ignored,           // read, no effect: nonzero is warning 2006
};

// One parameter of a material type.
struct MaterialParam {
  const char* key = "";       // keyword field name ("SIGY")
  const char* fname = nullptr;  // fixed-format field name in messages ("yield stress"); nullptr: key
  const char* label = nullptr;  // the printed echo's name; nullptr: not echoed by the generic echo
  int kcard = -1, kfield = 0;  // keyword: card (0 = the card with MID) and field 0-7; kcard < 0: not in keyword decks
  int fcard = 0, fcol = 0;    // fixed format: card 3-8 and first column (10 columns); fcard 0: not in fixed decks
  double MaterialData::* field = nullptr;  // where the value goes, or (nullptr) MaterialData::par[index]
  int index = 0;
  double def = 0;     // value of a blank field
  ParamCheck check = ParamCheck::none;
  int msg = 1003;     // message of a failed check (1003 value out of range, or a dedicated one)
  const char* detail = "";  // the message's detail (or the feature, for unsupported / ignored)
  const char* unit = "";    // echo unit ("stress"); "" prints the plain number
  bool optional_write = false;  // the fixed-format converter writes it only when nonzero
  bool keyword_write = true;    // the keyword converter writes it
};

// Reports a problem with a parameter (the reader maps it to its file, line, card and columns).
using ParamReport = std::function<void(const MaterialParam& p, int msg, const std::string& detail)>;

struct MaterialType {
  int number = 0;                         // DYNA3D type number (LS-DYNA's *MAT_0nn)
  const char* name = "";                  // printed name
  std::vector<const char*> keywords{};    // LS-DYNA keywords (without '*'; the first is written)
  std::vector<MaterialParam> params{};    // card layouts, checks, defaults
  int num_par = 0;                        // size of MaterialData::par
  int keyword_cards = 1;                  // cards the keyword reader reads (and the converter writes)
  std::vector<const char*> keyword_heads{};  // the converter's comment line above card k (nullptr: the keys)
  const char* extra_card_feature = nullptr;  // non-null: a card after those is message 1102 naming this
  bool one_per_card = false;              // fixed format: the original one parameter per card (cols 1-10),
                                          // with the packed 8-per-card alternative (warning 2001)
  bool rigid = false;
  bool takes_eos = false;
  // after the per-parameter checks: cross-field checks and defaults (may be null)
  void (*check)(MaterialData&, const MaterialType&, const ParamReport&) = nullptr;
  // the kernel's constants (rho, E, nu are set; derive_material_constants has run)
  void (*derive)(const MaterialData&, const Model&, MaterialConstants&) = nullptr;
  // extra echo lines after the parameters (may be null)
  void (*echo)(std::ostream&, const MaterialData&) = nullptr;
  SolidKernel solid{};
  PlaneStressKernel shell{};
  // equations of state (material/eos.h): whether the type takes one (its pressure then comes
  // from the EOS, its deviatoric stress from the kernel), and whether it needs one
  bool accepts_eos = false;
  bool needs_eos = false;
  std::vector<const char*> history{};     // names of the per-element history values (<= kMaxHistory)
  // the history value that holds a solid's absolute temperature (-1: none): the starter sets it
  // to the mean of its nodes' *INITIAL_TEMPERATURE (Model::node_temperature), a node without one
  // counting as initial_temperature(md)
  int temperature_history = -1;
  double (*initial_temperature)(const MaterialData&) = nullptr;
};

// Type 100 (*MAT_SPOTWELD, types/mat_spotweld.cpp): MaterialConstants::k holds the beams'
// failure resultants NRR NRS NRT MRR MSS MTT (0: not used) from index kSpotWeldNRR on, the
// failure time TFAIL (0: none) at kSpotWeldTFAIL and NF (the number of resultant vectors whose
// mean the failure rule takes; 0: this cycle's alone) at kSpotWeldNF.
constexpr int kSpotWeldNRR = 0, kSpotWeldTFAIL = 6, kSpotWeldNF = 7;
constexpr int kSpotWeldMaxNF = 30;

// E and nu, which every type has (keyword card 1, fields 2 and 3 unless the type places them
// elsewhere; fixed format where given).
inline MaterialParam young_modulus_param(int fcard, int fcol, int kfield = 2) {
  return {.key = "E", .label = nullptr, .kcard = 0, .kfield = kfield, .fcard = fcard, .fcol = fcol, .field = &MaterialData::E,
          .check = ParamCheck::positive, .msg = 1208};
}
inline MaterialParam poisson_param(int fcard, int fcol, int kfield = 3) {
  return {.key = "PR", .fname = "nu", .kcard = 0, .kfield = kfield, .fcard = fcard, .fcol = fcol, .field = &MaterialData::nu,
          .check = ParamCheck::poisson, .msg = 1209};
}
// MaterialData::par[i], or 0 where a programmatic MaterialData leaves par short.
inline double par(const MaterialData& md, int i) { return std::size_t(i) < md.par.size() ? md.par[std::size_t(i)] : 0.0; }
// The checks of a flow table's first n points (plastic strains par[eps1 + i], yield stresses
// par[es1 + i], named eps_names[i] and es_names[i]), message 1003: the strains start at 0 or
// more and increase; the stresses are not negative and do not decrease (no softening).
void check_flow_table(const MaterialData& md, const MaterialType& t, const ParamReport& report, int n, int eps1, int es1,
                      const char* const eps_names[], const char* const es_names[]);
// The parameter with this keyword name, or nullptr.
const MaterialParam* find_param(const MaterialType& t, std::string_view key);

// *MAT_RIGID (type 20) constraints CMO/CON1/CON2 as bits (x=1, y=2, z=4, global axes) of the
// body's fixed translations and rotations (the keyword reader has turned CMO = -1 into CMO = 1).
void rigid_body_constraints(const MaterialData& md, unsigned& fix_translation, unsigned& fix_rotation);

// The table: every supported material type, in increasing number.
std::span<const MaterialType* const> material_types();
// The type with this DYNA3D number, or nullptr (refused when the deck is read).
const MaterialType* find_material_type(int number);
// The type a keyword (upper case, without '*' and _TITLE) names, or nullptr.
const MaterialType* find_material_type_by_keyword(std::string_view keyword);
// The type of a material the deck reader accepted (throws std::logic_error for an unknown one).
const MaterialType& material_type(int number);
// "1 elastic, 3 elastic-plastic, ..." and "*MAT_ELASTIC, ..." for messages.
std::string supported_material_types();
std::string supported_material_keywords();
// "9 null (fluid...), 15 Johnson-Cook": the types that take an equation of state.
std::string eos_material_types();
// For the material types an element family takes (messages): "*MAT_ELASTIC, *MAT_..." (each
// type's first keyword) and "1, 3 and 24".
std::string keywords_of_types(const std::vector<int>& types);
std::string numbers_of_types(const std::vector<int>& types);

// The parameter's value in a material.
double& param_value(MaterialData& md, const MaterialParam& p);
double param_value(const MaterialData& md, const MaterialParam& p);
// Sizes md.par for its type and sets every parameter to its default.
void set_param_defaults(MaterialData& md, const MaterialType& t);
// The per-parameter checks, then the type's own; problems go to report.
void check_material_params(MaterialData& md, const MaterialType& t, const ParamReport& report);
// The material's kernel constants from the deck's values.
MaterialConstants derive_constants(const MaterialData& md, const Model& m);
// The printed echo of the type's parameters (one line each) and the type's extra lines.
void echo_material_params(std::ostream& os, const MaterialData& md, const MaterialType& t);
// One echo line "     label ..... value" in the printed output's layout.
void echo_line(std::ostream& os, const std::string& label, const std::string& value);
// A real value as the echo lines print it ("%.6e").
std::string echo_number(double v);
// Whether a curve parameter of the material (ParamCheck::curve) names this curve.
bool material_uses_curve(const MaterialData& md, int curve);
// The history values a material's solids carry (0 for none).
int material_history_count(int type);
// The history values a material's solids carry: its type's, then (with an equation of state)
// the internal energy per reference volume.
int material_history_count(const MaterialData& md);

}  // namespace impact3d
