#pragma once
// Restart dumps (d=, default d3dump): the deck text, the output schedule and every dynamic
// field of the State, with a format version and a CRC-32 checksum.  A damaged or foreign dump
// is refused with a message saying what is wrong.

#include <cstdint>
#include <string>

#include "impact3d/contact/sliding_interface.h"
#include "impact3d/model/state.h"

namespace impact3d {

// Where the outputs stood when the dump was written, so a restart continues them exactly.
struct OutputCursor {
  double next_plot = 0;        // time of the next scheduled plot state
  double next_history = 0;     // time of the next time-history output
  int plot_states = 0;         // plot states to keep in the family on restart
  int history_states = 0;      // time-history (d3thdt) states to keep
  int dumps_written = 0;       // numbered dumps written so far
  double next_intfor = 0;      // time of the next interface-force database (intfor) state
  int intfor_states = 0;       // intfor states to keep
  std::uint64_t ascii_bytes[8] = {};  // sizes of the ASCII history files (glstat, ...)
};

struct DumpHeader {
  std::string deck_name;       // the deck file as given on the first run
  std::string deck_text;       // its complete content (the model is rebuilt from it)
  std::string plot_root;       // g= of the run that wrote the dump
  std::string printed;         // o= of that run
  std::string dump_root;       // d= of that run
  std::string intfor_root;     // s= of that run (the interface-force database)
  int plot_word_size = 4;
  int member_size_factor = 7;  // x= of that run
  OutputCursor cursor;
  // 1: that run renumbered the mesh for locality (init/mesh_order.h): the restart renumbers
  // the model read from deck_text the same way before it reads the State
  int mesh_renumbered = 0;
};

// 1: first format; 2: the sliding interfaces' restart data after the State; 3: d= in the header;
// 4: x= in the header; 5: the failed-solid flags in the State; 6: moving walls; 8: per-element
// material history (State::hist) or shells (two branches); 9: both (State::hist and
// State::shells: stresses, history, rotations); 11: the interface-force database (s=, its
// cursor) in the header; 12: the shells' corner drilling moments; 13: the mesh-order flag in
// the header; 14: the beams (State::beams: lengths, section axes, stresses, history, resultants,
// energies); 15: the beams' failure flags, the spot welds (rigid bodies' released flags, the
// node-to-body map); 16: the viscous hourglass forms' resultants (State::hgs) and their pending
// power (State::hg_pending, State::dt_vel); 17: the spot-weld beams' stored resultants (NF,
// BeamState::weld_res, weld_res_count); 18: the fully integrated solids' points (State::pt_*);
// 20: the shells' points' state in runs (blocks of 8 in block order, model/shell_state.h).
constexpr std::uint32_t kDumpVersion = 20;

// Writes the dump atomically (temporary file, fsync, rename).  Throws std::runtime_error.
// The contact state (energy books of the sliding interfaces) travels with the State.
void write_restart_dump(const std::string& path, const DumpHeader& h, State& s,
                        const SlidingInterfaces::RestartData& contact);

// Reads the header (deck text, cursor) of a dump, after checking magic, version, size and
// checksum.  Throws std::runtime_error naming the file and the problem.
DumpHeader read_restart_dump_header(const std::string& path);

// Restores the dynamic fields into a State built from the same model (sizes must match).
void read_restart_dump_state(const std::string& path, State& s,
                             SlidingInterfaces::RestartData& contact);

}  // namespace impact3d
