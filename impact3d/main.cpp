// impact3d: the driver.  Reads the command line (DYNA3D/LS-DYNA style name=value words), runs
// the input phase (read and check the whole deck), then the solver.

#include <zlib.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "common/messages.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/input/fixed_cards.h"
#include "impact3d/input/keyword_cards.h"
#include "impact3d/init/mesh_order.h"
#include "impact3d/input/deck_writer.h"
#include "impact3d/output/printed_output.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/parallel/comm.h"
#include "impact3d/parallel/distributed_cycle.h"
#include "impact3d/solve/run.h"
#include "impact3d/solve/thread_policy.h"
#include "version.h"

using namespace impact3d;

namespace {

const char* kUsage =
    "usage: impact3d i=DECK [o=PRINTED] [g=PLOTDB] [d=DUMP] [s=INTFOR] [ncpu=N] [plotwords=4|8] [x=N]\n"
    "                [reorder=auto|on|off] [sync=SECONDS] [--check]\n"
    "       impact3d r=DUMP [o=PRINTED] [g=PLOTDB] [d=DUMP] [s=INTFOR] [ncpu=N] [sync=SECONDS]\n"
    "       impact3d --help | --version | --messages | --card-tables | --keyword-tables\n"
    "\n"
    "  i=DECK     input deck: DYNA3D fixed format or LS-DYNA keyword (chosen by content)\n"
    "  o=FILE     printed output file (default d3hsp)\n"
    "  g=FILE     plot database root name (default d3plot)\n"
    "  d=FILE     restart dump root: dumps are FILE01, FILE02, ... (default d3dump)\n"
    "  s=FILE     interface-force database root (*DATABASE_BINARY_INTFOR; default intfor\n"
    "             beside the plot database)\n"
    "  r=FILE     restart from this dump (the deck is inside it; o= and g= default to the\n"
    "             names of the run that wrote it)\n"
    "  plotwords=N  4 (default) or 8 byte words in the plot and time-history databases\n"
    "  x=N        plot database family members of at most N x 512 x 512 words (default 7)\n"
    "  case=ID    keyword decks with *CASE: run case ID (default: the base case); its outputs\n"
    "             go to a folder named by the case's JOBID (or caseID) unless o=, g=, d= are given\n"
    "  ncpu=N     number of threads (default: OMP_NUM_THREADS or all cores); results do not\n"
    "             depend on it\n"
    "  reorder=M  renumber nodes and solids internally for memory locality: auto (default:\n"
    "             when the model is large and the deck's numbering scattered), on, off; ids in\n"
    "             every input and output stay the deck's\n"
    "  sync=S     make the plot and time-history databases durable (fsync) at most every S\n"
    "             seconds, before each restart dump and at the end (default 1; 0: after every\n"
    "             state); a killed run keeps every state written either way\n"
    "  --check    read and check the deck only; print the summary; write nothing else\n"
    "  --lenient-keywords  unsupported LS-DYNA keywords are warnings, not errors\n"
    "  --strict   a run that ends normally but that the run checks find suspect (hourglass,\n"
    "             energy ratio, contact energy, added mass, contact misses) exits with 7\n"
    "  --write-keyword=FILE, --write-fixed=FILE  convert: write the deck read as an LS-DYNA\n"
    "             keyword / DYNA3D fixed-format deck; nothing is run\n"
    "  --messages list the message catalog\n"
    "  --card-tables  print the DYNA3D fixed-format card tables (Markdown, as in README.md)\n"
    "  --keyword-tables  print the keyword card tables (Markdown, as in docs/keyword-tables.md)\n"
    "\n"
    "exit codes: 0 normal termination, 2 input errors, 3 bad command line, 4 file error,\n"
    "            5 error termination, 6 stopped by signal, 7 suspect run (--strict),\n"
    "            9 internal error\n";

// CRC-32 and size of a file, read in pieces (no copy of it kept).
bool file_crc(const std::string& path, unsigned long& crc, std::uint64_t& size) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::vector<char> buf(1 << 20);
  crc = crc32(0L, Z_NULL, 0);
  size = 0;
  while (in) {
    in.read(buf.data(), std::streamsize(buf.size()));
    const std::streamsize n = in.gcount();
    if (n <= 0) break;
    crc = crc32(crc, reinterpret_cast<const Bytef*>(buf.data()), uInt(n));
    size += std::uint64_t(n);
  }
  return true;
}

// The model written as one keyword deck, if it reads back as the same model (else empty).  A
// renumbered model (reorder=) is written in deck order: the restart renumbers it again.
std::string model_as_keyword_text(const std::string& path, const Model& renumbered_or_not) {
  const Model deck_order = renumbered_or_not.renumbered() ? model_in_deck_order(renumbered_or_not) : Model{};
  const Model& model = renumbered_or_not.renumbered() ? deck_order : renumbered_or_not;
  std::ostringstream os;
  write_keyword_deck(os, model);
  DeckFile back;
  back.load_from_string(path, os.str());
  Model again;
  Diagnostics d;
  if (!read_deck(back, again, d, InputOptions{})) return {};
  again.deck_file = model.deck_file;
  return model_differences(model, again).empty() ? os.str() : std::string();
}

// The deck text a restart dump carries, made when the first dump is written.  A fixed-format
// deck is its own file (its CRC is taken at the start: if the file changed since, the model is
// written as a keyword deck instead).  A keyword deck may pull in *INCLUDE files or need
// --lenient-keywords, so the dump gets the model written back as one keyword deck, after
// checking that it reads back as the same model (if it did not, the original text is kept: a
// restart then needs the include files in place).
std::function<std::string()> self_contained_deck_text_source(const std::string& path, const Model& model) {
  unsigned long crc0 = 0;
  std::uint64_t size0 = 0;
  const bool have_crc = !model.keyword_deck && file_crc(path, crc0, size0);
  return [path, &model, have_crc, crc0, size0]() -> std::string {
    auto original = [&] {
      std::ifstream in(path, std::ios::binary);
      return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    if (!model.keyword_deck) {
      std::string text = original();
      if (have_crc && text.size() == size0 &&
          crc32_z(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(text.data()), text.size()) == crc0)
        return text;
      std::string kw = model_as_keyword_text(path, model);
      return kw.empty() ? text : kw;
    }
    std::string kw = model_as_keyword_text(path, model);
    return kw.empty() ? original() : kw;
  };
}

// A whole-word real in [lo, hi] (command-line values); false if it is not one.
bool parse_real_in(const char* text, double lo, double hi, double& out) {
  char* end = nullptr;
  const double x = std::strtod(text, &end);
  if (!*text || *end || !(x >= lo && x <= hi)) return false;
  out = x;
  return true;
}

// A whole-word integer in [lo, hi] (command-line values); false if it is not one.
bool parse_count(const char* text, long lo, long hi, int& out) {
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  if (!*text || *end || n < lo || n > hi) return false;
  out = int(n);
  return true;
}

void print_banner(std::ostream& os) {
  os << " IMPACT-3D " << IMPACT3D_VERSION
     << "  explicit finite elements for impact (DYNA3D lineage)\n";
}

}  // namespace

namespace {

// What the command line asks for.
struct CommandLine {
  RunOptions opt;
  bool check_only = false;
  InputOptions input_opt;
  std::string write_keyword, write_fixed;
  bool printed_given = false, plot_given = false, dump_given = false, words_given = false, x_given = false,
       intfor_given = false, reorder_given = false;
  MeshOrderMode mesh_order = MeshOrderMode::automatic;
};

// --help, --version, --messages, --card-tables, --keyword-tables: printed on stdout; false for
// any other word.
bool print_information(const std::string& arg) {
  if (arg == "--help" || arg == "-h") {
    std::cout << kUsage;
  } else if (arg == "--version") {
    std::cout << "impact3d " << IMPACT3D_VERSION << "\n";
  } else if (arg == "--messages") {
    for (const auto& m : message_catalog())
      std::cout << m.id << " "
                << (m.severity == Severity::error ? "error" : m.severity == Severity::warning ? "warning" : "info")
                << " " << m.text << "\n";
  } else if (arg == "--card-tables") {
    std::cout << fixed_card_tables_markdown();
  } else if (arg == "--keyword-tables") {
    std::cout << keyword_tables_markdown();
  } else {
    return false;
  }
  return true;
}

// A flag word (--check, --strict, ...) into cl; false for any other word.
bool read_flag(const std::string& arg, CommandLine& cl) {
  if (arg == "--check") cl.check_only = true;
  else if (arg == "--strict") cl.opt.strict = true;
  else if (arg == "--lenient-keywords") cl.input_opt.lenient_keywords = true;
  else return false;
  return true;
}

// A file-name word (i=, o=, g=, s=, d=, r=, --write-keyword=, --write-fixed=) into cl; false
// for any other word.
bool read_file_name(const std::string& arg, CommandLine& cl) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos) return false;
  const std::string key = arg.substr(0, eq + 1), v = arg.substr(eq + 1);
  RunOptions& opt = cl.opt;
  if (key == "--write-keyword=") cl.write_keyword = v, cl.check_only = true;
  else if (key == "--write-fixed=") cl.write_fixed = v, cl.check_only = true;
  else if (key == "i=") opt.deck = v;
  else if (key == "o=") opt.printed = v, cl.printed_given = true;
  else if (key == "g=") opt.plot = v, cl.plot_given = true;
  else if (key == "s=") opt.intfor = v, cl.intfor_given = true;
  else if (key == "d=") opt.dump = v, cl.dump_given = true;
  else if (key == "r=") opt.restart = v;
  else return false;
  return true;
}

// A numeric or mode word (plotwords=, x=, case=, reorder=, sync=, ncpu=) into cl, a bad value as error
// 3005 into cmd; false for any other word.
bool read_setting(const std::string& arg, CommandLine& cl, Diagnostics& cmd) {
  const auto eq = arg.find('=');
  if (eq == std::string::npos) return false;
  const std::string key = arg.substr(0, eq + 1);
  const char* v = arg.c_str() + eq + 1;
  auto bad_value = [&](const char* why) {
    Location loc;
    loc.found = arg;
    loc.show_found = true;
    cmd.add(3005, loc, why);
  };
  RunOptions& opt = cl.opt;
  if (key == "plotwords=") {
    int n = 0;
    if (parse_count(v, 4, 8, n) && (n == 4 || n == 8)) {
      opt.plot_word_size = n;
      cl.words_given = true;
    } else {
      bad_value("plotwords must be 4 or 8");
    }
  } else if (key == "x=") {
    if (parse_count(v, 1, 1024, opt.member_size_factor)) cl.x_given = true;
    else bad_value("x must be an integer 1-1024 (member size in units of 512 x 512 words)");
  } else if (key == "case=") {
    if (!parse_count(v, 1, 2147483647, cl.input_opt.case_id)) bad_value("case must be a positive case id (*CASE)");
  } else if (key == "reorder=") {
    if (parse_mesh_order_mode(v, cl.mesh_order)) cl.reorder_given = true;
    else bad_value("reorder must be auto, on or off");
  } else if (key == "sync=") {
    if (!parse_real_in(v, 0, 1e9, opt.sync_seconds)) bad_value("sync must be a number of seconds >= 0");
  } else if (key == "ncpu=") {
    if (!parse_count(v, 1, 1024, opt.threads)) bad_value("ncpu must be an integer 1-1024");
  } else {
    return false;
  }
  return true;
}

// The command line into cl: an exit code when the run ends here (information printed, or
// usage errors reported with the usage), else -1.
int parse_command_line(int argc, char** argv, CommandLine& cl) {
  Diagnostics cmd;
  for (int a = 1; a < argc; ++a) {
    const std::string arg = argv[a];
    if (print_information(arg)) return exit_code::ok;
    if (read_flag(arg, cl) || read_file_name(arg, cl) || read_setting(arg, cl, cmd)) continue;
    Location loc;
    loc.found = arg;
    loc.show_found = true;
    cmd.add(3001, loc);
  }
  if (cl.opt.deck.empty() && cl.opt.restart.empty()) cmd.add(3002, Location{});
  if (!parallel::built_with_mpi() && parallel::launcher_size() > 1)
    cmd.add(3008, Location{}, std::to_string(parallel::launcher_size()) + " processes");
  if (!cmd.error_count()) return -1;
  for (const auto& d : cmd.all()) std::cerr << "impact3d: " << render(d) << "\n";
  std::cerr << kUsage;
  return exit_code::usage_error;
}

// A restart: the dump's header gives the output names, word size, member size and numbering of
// the run that wrote it (plotwords=, x= and reorder= cannot change them), and the deck text,
// read and checked as the first run did.  An exit code when the dump cannot be used, else -1.
int read_restart_deck(CommandLine& cl, Model& model, Diagnostics& diag, bool& ok) {
  RunOptions& opt = cl.opt;
  DumpHeader h;
  try {
    h = read_restart_dump_header(opt.restart);
  } catch (const std::exception& ex) {
    Location loc;
    loc.file = opt.restart;
    Diagnostic d{4005, Severity::error, loc, ex.what()};
    std::cerr << "impact3d: " << render(d) << "\n";
    std::cout << "\n E r r o r   t e r m i n a t i o n   (restart dump is invalid)\n";
    return exit_code::file_error;
  }
  if (cl.words_given || cl.x_given || cl.reorder_given) {
    Location loc;
    loc.found = cl.words_given ? "plotwords=" : cl.x_given ? "x=" : "reorder=";
    loc.show_found = true;
    Diagnostic d{3005, Severity::error, loc,
                 "plotwords=, x= and reorder= cannot change on a restart: the plot database and the dump's "
                 "numbering continue"};
    std::cerr << "impact3d: " << render(d) << "\n";
    return exit_code::usage_error;
  }
  if (!cl.printed_given) opt.printed = h.printed;
  if (!cl.plot_given) opt.plot = h.plot_root;
  if (!cl.dump_given && !h.dump_root.empty()) opt.dump = h.dump_root;
  if (!cl.intfor_given && !h.intfor_root.empty()) opt.intfor = h.intfor_root;
  opt.plot_word_size = h.plot_word_size;
  opt.member_size_factor = h.member_size_factor;
  cl.mesh_order = h.mesh_renumbered ? MeshOrderMode::on : MeshOrderMode::off;  // as the dump's run
  opt.deck = h.deck_name;
  opt.deck_text = h.deck_text;
  DeckFile deck;
  deck.load_from_string(h.deck_name, h.deck_text);
  ok = read_deck(deck, model, diag, cl.input_opt);  // fixed format or keyword, by content
  if (ok) {
    orient_interface_segments(model, diag);  // as read_and_check_deck does
    ok = check_model(model, diag) && !diag.has(1225);
  }
  return -1;
}

// The deck's say in the outputs: *KEYWORD NCPU=, DYNA3D's free-format "basename NAME" (the plot
// database's root unless g= is given), *CASE (a case's outputs go to a folder named by its
// JOBID, or caseN, unless given).
void apply_deck_output_names(CommandLine& cl, const Model& model) {
  RunOptions& opt = cl.opt;
  if (opt.threads == 0 && model.deck_threads > 0) opt.threads = model.deck_threads;  // *KEYWORD NCPU=
  if (!opt.restart.empty() || cl.check_only) return;
  if (!model.basename.empty() && !cl.plot_given)
    opt.plot = (std::filesystem::path(opt.plot).parent_path() / model.basename).string();
  if (model.case_job.empty()) return;
  const std::filesystem::path dir = std::filesystem::path(opt.printed).parent_path() / model.case_job;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (!cl.printed_given) opt.printed = (dir / std::filesystem::path(opt.printed).filename()).string();
  if (!cl.plot_given) opt.plot = (dir / std::filesystem::path(opt.plot).filename()).string();
  if (!cl.dump_given) opt.dump = (dir / std::filesystem::path(opt.dump).filename()).string();
  if (!cl.intfor_given && !opt.intfor.empty()) opt.intfor = (dir / std::filesystem::path(opt.intfor).filename()).string();
}

// The printed file (rank 0's; appended to on a restart), with the banner: false (error 3004
// reported) when it cannot be opened.
bool open_printed_file(RunOptions& opt, std::ofstream& printed) {
  if (parallel::rank() != 0) opt.printed = "/dev/null";  // rank 0 writes the printed file
  printed.open(opt.printed, opt.restart.empty() ? std::ios::out : std::ios::app);
  if (!printed) {
    Location loc;
    loc.file = opt.printed;
    Diagnostic d{3004, Severity::error, loc, std::strerror(errno)};
    std::cerr << "impact3d: " << render(d) << "\n";
    return false;
  }
  print_banner(printed);
  return true;
}

// A deck with input errors: the counts and "Error termination" on the terminal and in the
// printed file; exit code 4 when the deck could not be opened, else 2.
int end_with_input_errors(const Diagnostics& diag, const std::string& deck, std::ofstream& printed) {
  if (printed) diag.print(printed);
  std::cout << "\n " << diag.error_count() << " input error(s), " << diag.warning_count() << " warning(s) in " << deck
            << "\n";
  std::cout << "\n E r r o r   t e r m i n a t i o n   (input errors)\n";
  if (printed)
    printed << "\n " << diag.error_count() << " input error(s)\n\n E r r o r   t e r m i n a t i o n   (input errors)\n";
  // Also report 3003 (cannot open) as a file error rather than an input error.
  if (diag.has(3003) || diag.has(3006)) return exit_code::file_error;
  return exit_code::input_error;
}

// Under mpirun with more than one rank: what the distributed cycle does not carry yet is
// refused (3007) with its exit code; -1 when the run may go on.
int refuse_if_not_distributable(const Model& model, std::ofstream& printed) {
  if (parallel::size() <= 1) return -1;
  const std::string why = parallel::distributed_refusal(model, parallel::size());
  if (why.empty()) return -1;
  const Diagnostic d{3007, Severity::error, Location{}, why + " (" + std::to_string(parallel::size()) + " ranks)"};
  std::cerr << "impact3d: " << render(d) << "\n";
  printed << render(d) << "\n\n E r r o r   t e r m i n a t i o n   (not for a distributed run)\n";
  std::cout << "\n E r r o r   t e r m i n a t i o n   (not for a distributed run)\n";
  return exit_code::usage_error;
}

int run_main(int argc, char** argv) {
  CommandLine cl;
  if (const int rc = parse_command_line(argc, argv, cl); rc >= 0) return rc;
  RunOptions& opt = cl.opt;
  print_banner(std::cout);
  Model model;
  Diagnostics diag;
  bool ok = false;
  if (!opt.restart.empty()) {  // the deck text travels inside the dump
    if (const int rc = read_restart_deck(cl, model, diag, ok); rc >= 0) return rc;
  } else {
    ok = read_and_check_deck(opt.deck, model, diag, cl.input_opt);
    if (ok && !cl.check_only) opt.deck_text_source = self_contained_deck_text_source(opt.deck, model);
  }
  // The printed output file gets the echo and all messages; the terminal gets the messages.
  apply_deck_output_names(cl, model);
  std::ofstream printed;
  if (!cl.check_only && !open_printed_file(opt, printed)) return exit_code::file_error;
  diag.print(std::cerr);
  if (!ok) return end_with_input_errors(diag, opt.deck, printed);
  if (!cl.write_keyword.empty() || !cl.write_fixed.empty())
    return write_converted_decks(model, cl.write_keyword, cl.write_fixed, std::cout);
  if (cl.check_only) {
    write_model_summary(std::cout, model);
    std::cout << " input check: 0 errors, " << diag.warning_count() << " warning(s)\n";
    return exit_code::ok;
  }
  if (const int rc = refuse_if_not_distributable(model, printed); rc >= 0) return rc;
  if (opt.restart.empty()) write_model_summary(printed, model);
  if (diag.warning_count()) diag.print(printed);
  // the starter's last step: the mesh in memory order (init/mesh_order.h); the summary above
  // and every output show the deck's ids
  const MeshOrderReport r = order_mesh_for_locality(model, cl.mesh_order);
  const std::string line = mesh_order_line(r) + (opt.restart.empty() ? "" : " (as the run that wrote the dump)");
  std::cout << line << "\n";
  printed << line << "\n";
  return run_simulation(model, opt, printed);
}

}  // namespace

// Anything that escapes (a bug, or memory exhausted) ends the run with exit code 9 and a line
// on stderr, never an abort.
// Under mpirun an internal error on one rank stops them all (parallel::abort).
// Ranks other than 0 of a distributed run print nothing (their internal errors aside).
int main(int argc, char** argv) {
  ensure_passive_openmp_wait(argv);
  parallel::init(&argc, &argv);
  std::ostream errors(std::cerr.rdbuf());
  struct NullBuffer : std::streambuf {
    int overflow(int c) override { return c; }
  };
  static NullBuffer null_buffer;  // (outlives the standard streams' final flush)
  if (parallel::rank() != 0) {
    std::cout.rdbuf(&null_buffer);
    std::cerr.rdbuf(&null_buffer);
  }
  const std::string who = parallel::size() > 1 ? "impact3d (rank " + std::to_string(parallel::rank()) + "): " : "impact3d: ";
  int code = exit_code::internal_error;
  try {
    code = run_main(argc, argv);
  } catch (const std::bad_alloc&) {
    errors << who << "internal error: out of memory\n";
  } catch (const std::exception& e) {
    errors << who << "internal error: " << e.what() << "\n";
  } catch (...) {
    errors << who << "internal error\n";
  }
  if (code == exit_code::internal_error && parallel::size() > 1) parallel::abort(code);
  parallel::finalize();
  return code;
}
