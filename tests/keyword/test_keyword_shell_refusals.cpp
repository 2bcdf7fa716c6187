// Type 24 on shells: what the readers refuse, in the deck of test_keyword_shell_piecewise.cpp
// (strip_deck, shared through tests/keyword/shell_piecewise_deck.h): TDEL > 0 on a shell part
// reads in both formats; a material with no shell form is 1103 listing the
// shell materials from the one table (init/shell_init.cpp kShellMaterials).

#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "impact3d/input/deck_writer.h"
#include "impact3d/material/material_types.h"
#include "tests/keyword/shell_piecewise_deck.h"

using namespace impact3d;
using namespace shell_piecewise_test;

// TDEL > 0 on a shell part: read in the keyword deck and in its fixed-format twin (the shells
// are deleted below it: tests/keyword/test_keyword_shell_tdel_damping.cpp), the same value.
TEST(KeywordShellPiecewise, TdelOnShellsIsReadInBothFormats) {
  Model m;
  Diagnostics d;
  ASSERT_TRUE(read_text(strip_deck(false, 1e-8), "tdel.k", m, d)) << messages(d);
  const MaterialParam& tdel = *find_param(material_type(24), "TDEL");
  EXPECT_EQ(param_value(m.materials[0], tdel), 1e-8);
  // the fixed format: written from the keyword deck, read back with the same TDEL
  std::ostringstream fixed;
  write_fixed_deck(fixed, m, nullptr);
  Model f;
  Diagnostics df;
  ASSERT_TRUE(read_text(fixed.str(), "tdel.dyn", f, df)) << messages(df) << fixed.str();
  EXPECT_EQ(param_value(f.materials[0], tdel), 1e-8);
  // a material with no shell form: 1103 listing the shell materials from the one table
  std::string pl = strip_deck();
  const std::size_t at = pl.find("*MAT_PIECEWISE_LINEAR_PLASTICITY");
  pl.replace(at, pl.find("*DEFINE_CURVE") - at,
             "*MAT_SIMPLIFIED_JOHNSON_COOK\n         1    7850.0   2.1e+11       0.3\n     5.e+8     3.e+8       0.2\n");
  Model pm;
  Diagnostics pd;
  EXPECT_FALSE(read_text(pl, "power.k", pm, pd));
  EXPECT_EQ(pd.count(1103), 1) << messages(pd);
  EXPECT_NE(messages(pd).find("supported for shells: *MAT_ELASTIC, *MAT_PLASTIC_KINEMATIC, *MAT_POWER_LAW_PLASTICITY, "
                              "*MAT_RIGID, *MAT_PIECEWISE_LINEAR_PLASTICITY, *MAT_MOONEY-RIVLIN_RUBBER"),
            std::string::npos) << messages(pd);
}
