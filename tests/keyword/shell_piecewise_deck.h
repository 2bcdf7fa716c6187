#pragma once
// The type 24 shell strip deck of tests/keyword/test_keyword_shell_piecewise.cpp and
// test_keyword_shell_refusals.cpp, written as LS-DYNA users write it, and reading helpers.

#include <cstdio>
#include <sstream>
#include <string>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"

namespace shell_piecewise_test {

using namespace impact3d;

constexpr double kFail = 0.06;

inline std::string I(long v, int w) {
  char b[32];
  std::snprintf(b, sizeof b, "%*ld", w, v);
  return b;
}
inline std::string F(double v, int w) {
  char b[64];
  std::snprintf(b, sizeof b, "%*.*g", w, w > 10 ? 9 : 6, v);
  return b;
}

// The strip: 0.1 m x 20 mm, 2 mm, 10 x 2 shells (NIP 2, LS-DYNA's default: blank); x = 0 held
// in x (node 1 also in y and z), x = 0.1 pulled at 10 m/s (100 /s) after a 10 us ramp; the
// flow curve (plastic strain, stress): 250, 300, 380, 420 MPa at 0, 0.01, 0.05, 0.15.
// `table`: the curve as EPS/ES instead of LCSS; `tdel`: a TDEL value.
inline std::string strip_deck(bool table = false, double tdel = 0) {
  const int nx = 10, ny = 2;
  std::ostringstream d;
  d << "*KEYWORD\n*TITLE\nsteel strip pulled to failure (type 24 shells)\n"
    << "*CONTROL_TERMINATION\n$#  endtim\n   1.2e-03\n"
    << "*DATABASE_BINARY_D3PLOT\n$#      dt\n   1.0e-04\n"
    << "*PART\n$# title\nstrip\n$#     pid     secid       mid\n         1         1         1\n"
    << "*SECTION_SHELL\n$#   secid    elform      shrf       nip\n         1         2  0.833333\n"
    << "$#      t1        t2        t3        t4\n     0.002     0.002     0.002     0.002\n"
    << "*MAT_PIECEWISE_LINEAR_PLASTICITY\n"
    << "$#     mid        ro         e        pr      sigy      etan      fail      tdel\n"
    << "         1    7850.0   2.1e+11       0.3   2.5e+08       0.0" << F(kFail, 10) << F(tdel, 10) << "\n"
    << "$#       c         p      lcss      lcsr        vp\n"
    << "      40.0       5.0" << I(table ? 0 : 1, 10) << "         0         0\n";
  if (table) {
    d << "$#    eps1      eps2      eps3      eps4\n       0.0      0.01      0.05      0.15\n"
      << "$#     es1       es2       es3       es4\n   2.5e+08   3.0e+08   3.8e+08   4.2e+08\n";
  } else {
    d << "$#    eps1      eps2      eps3      eps4      eps5      eps6      eps7      eps8\n\n"
      << "$#     es1       es2       es3       es4       es5       es6       es7       es8\n\n"
      << "*DEFINE_CURVE\n$#    lcid\n         1\n$#                a1                  o1\n"
      << "                 0.0             2.5e+08\n                0.01             3.0e+08\n"
      << "                0.05             3.8e+08\n                0.15             4.2e+08\n";
  }
  d << "*DEFINE_CURVE\n         2\n                 0.0                 0.0\n"
    << "             1.0e-05                10.0\n                 1.0                10.0\n";
  d << "*NODE\n";
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      d << I(1 + i + (nx + 1) * j, 8) << F(0.1 * i / nx, 16) << F(0.01 * j, 16) << F(0, 16) << "\n";
  d << "*ELEMENT_SHELL\n";
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n1 = 1 + i + (nx + 1) * j;
      d << I(1 + i + nx * j, 8) << I(1, 8) << I(n1, 8) << I(n1 + 1, 8) << I(n1 + nx + 2, 8) << I(n1 + nx + 1, 8) << "\n";
    }
  d << "*SET_NODE_LIST\n         1\n";
  for (int j = 0; j <= ny; ++j) d << I(1 + (nx + 1) * j, 10);
  d << "\n*SET_NODE_LIST\n         2\n";
  for (int j = 0; j <= ny; ++j) d << I(nx + 1 + (nx + 1) * j, 10);
  d << "\n*BOUNDARY_SPC_SET\n$#    nsid       cid      dofx      dofy      dofz\n         1         0         1         0         0\n"
    << "*BOUNDARY_SPC_NODE\n         1         0         1         1         1\n"
    << "*BOUNDARY_PRESCRIBED_MOTION_SET\n$#    nsid       dof       vad      lcid        sf\n         2         1         0         2       1.0\n"
    << "*END\n";
  return d.str();
}

inline bool read_text(const std::string& text, const std::string& name, Model& m, Diagnostics& d) {
  DeckFile deck;
  deck.load_from_string(name, text);
  return read_deck(deck, m, d, InputOptions{}) && check_model(m, d);
}

inline std::string messages(const Diagnostics& d) {
  std::ostringstream os;
  d.print(os);
  return os.str();
}


}  // namespace shell_piecewise_test
