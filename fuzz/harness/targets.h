// The fuzz harnesses, one per reader.  Each takes one input and returns 0; a crash, a sanitizer
// report, a hang or an oversized allocation is a finding.  fuzz/libfuzzer_main.cpp turns each
// into a libFuzzer target (fuzz_NAME); tests/fuzz/test_fuzz_replay.cpp replays the stored
// crash inputs through the same functions in the normal build.
#pragma once

#include <cstddef>
#include <cstdint>

namespace impact3d_fuzz {

// DYNA3D fixed-format deck: read, model checks, both deck writers.
int fuzz_fixed_deck(const std::uint8_t* data, std::size_t size);
// LS-DYNA keyword deck with *INCLUDE: the input is cut at lines "$$FUZZ-FILE$$" into the main
// deck and up to three include files (inc1.k, inc2.k, inc3.k next to it).
int fuzz_keyword_deck(const std::uint8_t* data, std::size_t size);
// d3plot family (common/plot_database): 4-byte root length, root file, member d3plot01.
int fuzz_plot_database(const std::uint8_t* data, std::size_t size);
// Mili database (common/mili_database): the A file, state files 00 and 01 and the T file, cut
// at lines "$$FUZZ-FILE$$".
int fuzz_mili_database(const std::uint8_t* data, std::size_t size);
// The same input through POST-IMPACT: Database, surface, quantities, histories, summary, compare.
int fuzz_postimpact_database(const std::uint8_t* data, std::size_t size);
// Restart dump: header, deck inside, state.  An input that starts with the dump magic and has
// a zero byte 36 gets its payload size and CRC-32 fixed, so that mutations reach the payload.
int fuzz_restart_dump(const std::uint8_t* data, std::size_t size);
// POST-IMPACT command file, run (dry: nothing rendered or written) on a small database.
int fuzz_command_file(const std::uint8_t* data, std::size_t size);
// compare tolerance file, and two summaries compared with it (parts cut at "$$FUZZ-FILE$$").
int fuzz_tolerances(const std::uint8_t* data, std::size_t size);

}  // namespace impact3d_fuzz
