// Helpers of the output tests that read a keyword or fixed-format deck from text and run it to
// its output files in a folder of the build tree (tests/output/test_*_histories.cpp).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "impact3d/input/deck_reader.h"
#include "impact3d/solve/run.h"
#include "deck_text.h"

namespace test_support {

// The Model of a deck given as text (`name` tells the format by its extension); a failed read
// or check fails the test with the messages.
inline impact3d::Model read_model_text(const std::string& text, const std::string& name) {
  ReadDeck r = read_deck_text(text, name);
  EXPECT_TRUE(r.ok) << r.messages();
  return std::move(r.m);
}

// Runs m on one thread with its d3hsp, d3plot and d3dump in IMPACT3D_BINARY_DIR/group/name
// (emptied first), databases of `plot_word_size` byte words; the run must end normally.
inline std::filesystem::path run_model_in(const impact3d::Model& m, const std::string& group, const std::string& name,
                                          int plot_word_size = 4) {
  const std::filesystem::path dir = empty_run_folder(group, name);
  impact3d::RunOptions o = run_options_in(dir);
  o.plot_word_size = plot_word_size;
  std::ofstream printed(o.printed);
  EXPECT_EQ(impact3d::run_simulation(m, o, printed), 0);
  return dir;
}

}  // namespace test_support
