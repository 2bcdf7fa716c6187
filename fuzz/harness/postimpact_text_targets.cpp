// Fuzz harnesses of POST-IMPACT's text inputs: command files and tolerance (and summary) files.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "common/plot_database.h"
#include "fuzz/harness/fuzz_util.h"
#include "fuzz/harness/targets.h"
#include "postimpact/command_file.h"
#include "postimpact/compare.h"
#include "postimpact/summary.h"

#ifndef IMPACT3D_SOURCE_DIR
#error "IMPACT3D_SOURCE_DIR must name the source tree (the command-file target opens a stored database)"
#endif

namespace impact3d_fuzz {

namespace {

// Two databases for the command files: the stored one_hex reference (11 states) as "d3plot",
// and its root file alone (no states) as "empty/d3plot".
struct Databases {
  std::string full, empty;
  Databases() {
    namespace fs = std::filesystem;
    const fs::path ref = fs::path(IMPACT3D_SOURCE_DIR) / "tests/regression/reference/one_hex";
    const fs::path dir = scratch_dir() / "commands";
    fs::create_directories(dir / "empty");
    fs::copy_file(ref / "d3plot", dir / "d3plot", fs::copy_options::overwrite_existing);
    fs::copy_file(ref / "d3plot01", dir / "d3plot01", fs::copy_options::overwrite_existing);
    fs::copy_file(ref / "d3plot", dir / "empty/d3plot", fs::copy_options::overwrite_existing);
    full = (dir / "d3plot").string();
    empty = (dir / "empty/d3plot").string();
  }
};

}  // namespace

int fuzz_command_file(const std::uint8_t* data, std::size_t size) {
  static const Databases dbs;
  std::ostringstream log;
  postimpact::Session session(log);
  session.set_dry_run(true);
  session.execute({"open", dbs.full});
  std::istringstream in{std::string(as_text(data, size))};
  std::string line;
  int ln = 0;
  while (std::getline(in, line)) {
    ++ln;
    try {
      std::vector<std::string> w = postimpact::split_command(line);
      if (w.empty()) continue;
      // The files a command names stay inside the sandbox: "open" reaches the two databases
      // only, "outdir" and "font" are not run (they touch the file system, nothing to parse).
      if (w[0] == "outdir" || w[0] == "font") continue;
      if ((w[0] == "open" || w[0] == "database") && w.size() == 2)
        w[1] = w[1] == "empty" ? dbs.empty : dbs.full;
      session.execute(w, "fuzz:" + std::to_string(ln));
    } catch (const postimpact::CommandError&) {
      // a command file stops here; the harness goes on with the next line (more coverage)
    }
  }
  return 0;
}

int fuzz_tolerances(const std::uint8_t* data, std::size_t size) {
  const auto parts = split_parts(as_text(data, size), "$$FUZZ-FILE$$\n", 3);
  postimpact::Tolerances tol;
  try {
    tol = postimpact::Tolerances::parse(std::string(parts[0]), "fuzz.tol");
  } catch (const std::runtime_error&) {
    return 0;
  }
  for (const char* f : postimpact::Tolerances::kFields) tol.get(f);
  if (parts.size() < 3) return 0;
  static const std::filesystem::path a = scratch_dir() / "a.summary", b = scratch_dir() / "b.summary";
  write_file(a, parts[1]);
  write_file(b, parts[2]);
  try {
    const postimpact::Summary sa = postimpact::read_summary(a.string());
    const postimpact::Summary sb = postimpact::read_summary(b.string());
    std::ostringstream out;
    postimpact::compare_summaries(sa, sb, tol, out);
  } catch (const std::runtime_error&) {
  }
  return 0;
}

}  // namespace impact3d_fuzz
