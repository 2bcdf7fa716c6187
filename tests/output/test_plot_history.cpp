// The plot database carries the materials' history values (NEIPH): a Johnson-Cook Taylor bar
// (type 15: temperature rise, damage and the spall flag per solid) written with 8-byte words reads back with
// NEIPH = 3, NV3D = 10 and the State's history values bit for bit; restart dumps carry them.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "common/messages.h"
#include "common/plot_database.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/material/material_types.h"
#include "impact3d/output/plot_output.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"

using namespace impact3d;
namespace fs = std::filesystem;

TEST(PlotHistory, JohnsonCookHistoryValuesAreWrittenAsNeiph) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/taylor_bar.dyn", m, diag));
  // OFHC copper (Johnson and Cook 1985), SI units: heats as it flows
  MaterialData& md = m.materials[0];
  const MaterialType& t = material_type(15);
  const double E = md.E, nu = md.nu;
  md.type = 15;
  set_param_defaults(md, t);
  md.E = E, md.nu = nu;
  const std::pair<const char*, double> jc[] = {{"G", 46e9}, {"A", 90e6}, {"B", 292e6}, {"N", 0.31}, {"C", 0.025},
                                               {"M", 1.09}, {"TM", 1356}, {"TR", 293}, {"EPSO", 1}, {"CP", 383},
                                               {"D1", 0.54}, {"D2", 4.89}, {"D3", -3.03}, {"D4", 0.014}, {"D5", 1.12}};
  for (const auto& [k, v] : jc) param_value(md, *find_param(t, k)) = v;
  Engine eng(m);
  ASSERT_EQ(eng.initialize(), StepStatus::ok);
  for (int c = 0; c < 300; ++c) ASSERT_EQ(eng.step(), StepStatus::ok);
  const State& s = eng.state();
  ASSERT_EQ(s.hist_stride, 3);
  const fs::path dir = fs::temp_directory_path() / ("impact3d_plot_history_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string root = (dir / "d3plot").string();
  {
    PlotOutput out;
    out.open(m, root, 8);
    out.write(m, s, InterfaceForces(m.interfaces.size()));
  }
  PlotReader r;
  r.open(root);
  EXPECT_EQ(r.control().neiph, 3);
  EXPECT_EQ(r.control().nv3d, 10);
  ASSERT_EQ(r.num_states(), 1);
  const PlotState ps = r.state(0);
  ASSERT_EQ(ps.history.size(), s.hist.size());
  double tmax = 0;
  for (std::size_t k = 0; k < s.hist.size(); ++k) {
    EXPECT_EQ(ps.history[k], s.hist[k]) << k;
    if (k % 3 == 0) tmax = std::max(tmax, s.hist[k]);
  }
  EXPECT_GT(tmax, 10.0);  // the impact face has heated by more than 10 K
  EXPECT_EQ(ps.eps, s.eps_p);
  fs::remove_all(dir);
}

// Restart dumps carry the history values: a Johnson-Cook Taylor bar dumped after 200 cycles
// and restored into a fresh State goes on bit for bit like the uninterrupted run.
TEST(PlotHistory, RestartDumpCarriesTheHistoryValues) {
  Model m;
  Diagnostics diag;
  ASSERT_TRUE(read_and_check_deck(std::string(IMPACT3D_SOURCE_DIR) + "/decks/taylor_bar.dyn", m, diag));
  MaterialData& md = m.materials[0];
  const MaterialType& t = material_type(15);
  const double E = md.E, nu = md.nu;
  md.type = 15;
  set_param_defaults(md, t);
  md.E = E, md.nu = nu;
  const std::pair<const char*, double> jc[] = {{"G", 46e9}, {"A", 90e6}, {"B", 292e6}, {"N", 0.31}, {"C", 0.025},
                                               {"M", 1.09}, {"TM", 1356}, {"TR", 293}, {"EPSO", 1}, {"CP", 383},
                                               {"D1", 0.54}, {"D2", 4.89}, {"D3", -3.03}, {"D4", 0.014}, {"D5", 1.12}};
  for (const auto& [k, v] : jc) param_value(md, *find_param(t, k)) = v;
  const fs::path dir = fs::temp_directory_path() / ("impact3d_hist_dump_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string path = (dir / "d3dump01").string();
  Engine a(m);
  ASSERT_EQ(a.initialize(), StepStatus::ok);
  for (int c = 0; c < 200; ++c) ASSERT_EQ(a.step(), StepStatus::ok);
  DumpHeader h;
  h.deck_name = "taylor_bar.dyn";
  write_restart_dump(path, h, a.state(), a.contact().restart_data());
  Engine b(m);
  ASSERT_EQ(b.initialize(), StepStatus::ok);
  SlidingInterfaces::RestartData cd;
  read_restart_dump_state(path, b.state(), cd);
  b.contact().restore(cd);
  EXPECT_EQ(b.state().hist, a.state().hist);
  for (int c = 0; c < 100; ++c) {
    ASSERT_EQ(a.step(), StepStatus::ok);
    ASSERT_EQ(b.step(), StepStatus::ok);
  }
  EXPECT_TRUE(a.state().hist == b.state().hist && a.state().sig == b.state().sig && a.state().x == b.state().x);
  double tmax = 0;
  for (std::size_t k = 0; k < a.state().hist.size(); k += 3) tmax = std::max(tmax, a.state().hist[k]);
  EXPECT_GT(tmax, 1.0);
  fs::remove_all(dir);
}
