#pragma once
// The keyword reader's families (internal to impact3d/input/keyword_*.cpp): each family reads
// its keywords' cards by their tables (keyword_cards.h) into its records, and builds its part
// of the Model from them once the whole deck is read.

#include <string>

#include "impact3d/input/keyword_blocks.h"
#include "impact3d/model/model.h"

namespace impact3d::kw {

// ---------------------------------------------------------------- control and database cards
// (keyword_control_database.cpp)
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
};

// Reads a control or database keyword (or one read and ignored, warning 2008) into c; false if
// the keyword (upper case, options stripped) is none of them.
bool read_control_database(const Block& b, KeywordContext& ctx, KeywordControls& c);
// The run controls of the Model (model.control) from the cards; error 1311 without
// *CONTROL_TERMINATION.  reaction_flag: the *COMMENT IMPACT-3D REACTION_PRINT_FLAG (-1 none).
void build_controls(const KeywordControls& c, const std::string& main_deck, int reaction_flag, Model& m,
                    Diagnostics& diag);

}  // namespace impact3d::kw
