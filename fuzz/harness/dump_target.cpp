// Fuzz harness of the restart-dump reader (impact3d/output/restart_dump), as impact3d r= uses
// it: the header, the deck inside it read back into a model, the state read into that model.
#include <zlib.h>

#include <cstring>
#include <filesystem>
#include <string>

#include "fuzz/harness/fuzz_util.h"
#include "fuzz/harness/targets.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"

namespace impact3d_fuzz {

int fuzz_restart_dump(const std::uint8_t* data, std::size_t size) {
  namespace fs = std::filesystem;
  static const fs::path path = scratch_dir() / "d3dump01";
  std::string bytes(as_text(data, size));
  // header: magic(16) version(4) reserved(4) payload size(8) crc32(4) reserved(4)
  static const char kMagic[16] = {'I', 'M', 'P', 'A', 'C', 'T', '3', 'D', '-', 'D', 'U', 'M', 'P', 0, 0, 0};
  if (bytes.size() >= 40 && std::memcmp(bytes.data(), kMagic, 16) == 0 && bytes[36] == 0) {
    const std::uint64_t n = bytes.size() - 40;
    std::memcpy(bytes.data() + 24, &n, 8);
    const std::uint32_t crc = static_cast<std::uint32_t>(
        crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(bytes.data() + 40), static_cast<uInt>(n)));
    std::memcpy(bytes.data() + 32, &crc, 4);
  }
  write_file(path, bytes);
  impact3d::DumpHeader h;
  try {
    h = impact3d::read_restart_dump_header(path.string());
  } catch (const std::runtime_error&) {
    return 0;
  }
  // The model is rebuilt from the deck inside the dump (impact3d main.cpp); only small models,
  // so that one input stays fast.
  impact3d::DeckFile deck;
  deck.load_from_string(h.deck_name.empty() ? "dump-deck" : h.deck_name, h.deck_text);
  impact3d::Model model;
  impact3d::Diagnostics diag;
  if (!impact3d::read_deck(deck, model, diag) || diag.error_count() > 0) return 0;
  if (model.num_nodes() != model.control.numnp || model.num_hexes() != model.control.numelh) return 0;
  impact3d::orient_interface_segments(model, diag);  // as impact3d main.cpp does
  if (!impact3d::check_model(model, diag) || diag.has(1225)) return 0;
  if (model.num_nodes() > 5000 || model.num_hexes() > 5000) return 0;
  impact3d::Engine engine(model);
  engine.initialize();
  try {
    impact3d::SlidingInterfaces::RestartData cd;
    impact3d::read_restart_dump_state(path.string(), engine.state(), cd);
    engine.contact().restore(cd);
  } catch (const std::runtime_error&) {
  }
  return 0;
}

}  // namespace impact3d_fuzz
