// Whole-run tests of the output segment: the impact3d binary is run on shipped decks (and a
// shortened Taylor bar) and its outputs are checked:
//   * a restart from a dump reproduces every output file of the uninterrupted run bit for bit;
//   * every shipped deck that runs gives a plot database that VTK's LS-DYNA reader reads with
//     the expected counts and the same times and coordinates as our PlotReader;
//   * plotwords=8 databases hold the same values as the 4-byte ones (to float rounding);
//   * a run killed with SIGKILL leaves only complete, readable states;
//   * SIGINT stops with a dump that restarts to the same results; SIGUSR1 / SIGUSR2 work;
//   * damaged restart dumps are refused with a clear error (no crash);
//   * an output file that cannot be written stops the run with message 3004.

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "common/messages.h"
#include "common/plot_database.h"
#include "impact3d/input/deck_reader.h"
#include "impact3d/output/restart_dump.h"
#include "impact3d/solve/engine.h"

extern char** environ;

namespace fs = std::filesystem;
using impact3d::PlotReader;
using impact3d::PlotState;

namespace {

const std::string kImpact3d = IMPACT3D_BINARY_DIR "/impact3d";
const std::string kDecks = IMPACT3D_SOURCE_DIR "/decks";
const std::string kProbe = IMPACT3D_SOURCE_DIR "/tests/support/vtk_d3plot_check.py";
const char* kEpoch = "SOURCE_DATE_EPOCH=1700000000";

// ------------------------------------------------------------------ small helpers

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void spit(const fs::path& p, const std::string& s) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << s;
}

// One scratch folder per test process, removed at the end when every test passed.
fs::path scratch_root() {
  static fs::path root = [] {
    fs::path r = fs::temp_directory_path() / ("impact3d_run_outputs_" + std::to_string(::getpid()));
    fs::remove_all(r);
    fs::create_directories(r);
    return r;
  }();
  return root;
}

fs::path fresh_dir(const std::string& name) {
  fs::path d = scratch_root() / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

// Starts impact3d in dir with args; stdout and stderr go to dir/<tag>.out and dir/<tag>.err.
// SOURCE_DATE_EPOCH is set so the plot root files are reproducible.  One thread (ncpu=1) unless
// args say otherwise: results do not depend on it, and OpenMP threads on a busy shared machine
// make a run ten times slower.
pid_t spawn(const fs::path& dir, const std::vector<std::string>& args, const std::string& tag) {
  std::vector<std::string> argv_s{kImpact3d};
  argv_s.insert(argv_s.end(), args.begin(), args.end());
  if (std::none_of(args.begin(), args.end(), [](const std::string& a) { return a.rfind("ncpu=", 0) == 0; }))
    argv_s.push_back("ncpu=1");
  std::vector<char*> argv;
  for (auto& a : argv_s) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::vector<std::string> env_s;
  for (char** e = environ; *e; ++e)
    if (std::strncmp(*e, "SOURCE_DATE_EPOCH=", 18) != 0) env_s.push_back(*e);
  env_s.push_back(kEpoch);
  std::vector<char*> envp;
  for (auto& e : env_s) envp.push_back(e.data());
  envp.push_back(nullptr);
  const std::string dir_s = dir.string();
  const std::string out = (dir / (tag + ".out")).string(), err = (dir / (tag + ".err")).string();
  pid_t pid = ::fork();
  if (pid == 0) {
    // child: async-signal-safe calls only
    if (::chdir(dir_s.c_str()) != 0) ::_exit(120);
    int fo = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    int fe = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fo < 0 || fe < 0) ::_exit(121);
    ::dup2(fo, 1);
    ::dup2(fe, 2);
    ::execve(argv[0], argv.data(), envp.data());
    ::_exit(122);
  }
  return pid;
}

// Exit status, or 128 + signal number.
int wait_exit(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return -1;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return -1;
}

struct RunResult {
  int code = -1;
  std::string out, err;
};

RunResult run_impact3d(const fs::path& dir, const std::vector<std::string>& args, const std::string& tag) {
  RunResult r;
  r.code = wait_exit(spawn(dir, args, tag));
  r.out = slurp(dir / (tag + ".out"));
  r.err = slurp(dir / (tag + ".err"));
  return r;
}

std::string describe(const RunResult& r) {
  auto tail = [](const std::string& s) { return s.size() > 1500 ? "..." + s.substr(s.size() - 1500) : s; };
  return "exit " + std::to_string(r.code) + "\n--- stdout (tail):\n" + tail(r.out) + "\n--- stderr:\n" + tail(r.err);
}

// Polls the plot database in dir until it holds at least n states (or the child has exited, or
// the time limit passed).  Returns the count seen (-1 if the child exited first; its exit
// status goes to *exited).
int wait_for_states(pid_t pid, const fs::path& root, int n, int* exited, double limit_s = 120) {
  const auto t0 = std::chrono::steady_clock::now();
  for (;;) {
    int status = 0;
    pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) {
      *exited = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
      return -1;
    }
    try {
      PlotReader r;
      r.open(root.string());
      if (r.num_states() >= n) return r.num_states();
    } catch (const std::exception&) {
      // root not written yet
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > limit_s) return 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

// Waits until the running child's plot database holds n states; on failure (the child exited
// or the time ran out) kills the child and says why.
::testing::AssertionResult reached_states(pid_t pid, const fs::path& root, int n) {
  int exited = -1;
  const int seen = wait_for_states(pid, root, n, &exited);
  if (seen > 0) return ::testing::AssertionSuccess();
  if (seen == 0) {
    ::kill(pid, SIGKILL);
    wait_exit(pid);
  }
  return ::testing::AssertionFailure() << "the run never showed " << n << " plot states (exit " << exited << ")";
}

// ------------------------------------------------------------------ decks

struct Card6 {
  double end_time = 0, plot_dt = 0;
};

// The line after the "CONTROL CARD #6" comment (0-based line index).
std::size_t card6_line(const std::vector<std::string>& lines) {
  for (std::size_t i = 0; i + 1 < lines.size(); ++i)
    if (lines[i].find("CONTROL CARD #6") != std::string::npos) return i + 1;
  throw std::runtime_error("no control card 6 comment in the deck");
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

Card6 read_card6(const std::string& deck_path) {
  const auto lines = split_lines(slurp(deck_path));
  const std::string& l = lines.at(card6_line(lines));
  Card6 c;
  c.end_time = std::stod(l.substr(0, 10));
  c.plot_dt = std::stod(l.substr(20, 10));
  return c;
}

// The Taylor bar with end time (cols 1-10) and restart dump cycles (cols 31-35) replaced.
std::string taylor_variant(const std::string& end_time, int dump_cycles) {
  const std::string text = slurp(kDecks + "/taylor_bar.dyn");
  auto lines = split_lines(text);
  const std::size_t k = card6_line(lines);
  std::string& l = lines[k];
  if (l != "8.0000e-051.0000e-064.0000e-06    0    0                        0    09.0000e-01")
    throw std::runtime_error("taylor_bar.dyn control card 6 changed: " + l);
  char dump[8];
  std::snprintf(dump, sizeof dump, "%5d", dump_cycles);
  l.replace(0, 10, end_time);
  l.replace(30, 5, dump);
  std::string out;
  for (const auto& s : lines) out += s + "\n";
  return out;
}

// The shortened Taylor bar: 40 us (~2300 cycles, 11 plot states), a restart dump every 1000
// cycles.  (20 us would be only ~460 cycles: the time step shrinks as the bar mushrooms.)
std::string short_taylor() { return taylor_variant("4.0000e-05", 1000); }

// ------------------------------------------------------------------ output families

bool is_output_file(const std::string& name) {
  static const char* ascii[] = {"glstat", "matsum", "rwforc", "rcforc", "nodout", "elout"};
  for (const char* a : ascii)
    if (name == a) return true;
  return name.rfind("d3plot", 0) == 0 || name.rfind("d3thdt", 0) == 0;
}

std::map<std::string, std::string> output_files(const fs::path& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.is_regular_file() && is_output_file(e.path().filename().string()))
      m[e.path().filename().string()] = slurp(e.path());
  return m;
}

// Every output file of a and b is present in both and equal byte for byte.
void expect_same_outputs(const fs::path& a, const fs::path& b, const std::vector<std::string>& required) {
  const auto fa = output_files(a), fb = output_files(b);
  std::vector<std::string> na, nb;
  for (const auto& [n, c] : fa) na.push_back(n);
  for (const auto& [n, c] : fb) nb.push_back(n);
  EXPECT_EQ(na, nb) << "output file sets differ between " << a << " and " << b;
  for (const auto& r : required) EXPECT_TRUE(fa.count(r)) << r << " missing in " << a;
  for (const auto& [n, ca] : fa) {
    auto it = fb.find(n);
    if (it == fb.end()) continue;
    const std::string& cb = it->second;
    if (ca == cb) continue;
    std::size_t k = 0;
    while (k < ca.size() && k < cb.size() && ca[k] == cb[k]) ++k;
    ADD_FAILURE() << n << " differs: sizes " << ca.size() << " and " << cb.size()
                  << ", first difference at byte " << k;
  }
}

const std::vector<std::string> kTaylorOutputs = {"d3plot", "d3plot01", "d3thdt", "d3thdt01", "glstat",
                                                 "matsum", "rwforc", "nodout", "elout"};

// ------------------------------------------------------------------ a minimal JSON reader
// (for the probe's --json output: objects, arrays, numbers, strings, true/false/null, and
// Python's NaN / Infinity)

struct Json {
  enum Kind { Null, Bool, Num, Str, Arr, Obj } kind = Null;
  double num = 0;
  std::string str;
  std::vector<Json> arr;
  std::vector<std::pair<std::string, Json>> obj;
  const Json* find(const std::string& k) const {
    for (const auto& [key, v] : obj)
      if (key == k) return &v;
    return nullptr;
  }
  const Json& at(const std::string& k) const {
    const Json* v = find(k);
    if (!v) throw std::runtime_error("JSON: no key " + k);
    return *v;
  }
};

class JsonParser {
 public:
  // Values of the keys in skip are not kept (large arrays the caller does not need).
  explicit JsonParser(const std::string& s, std::set<std::string> skip = {}) : s_(s), skip_(std::move(skip)) {}
  Json parse() {
    Json v = value();
    ws();
    if (p_ != s_.size()) fail("trailing data");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const {
    throw std::runtime_error("JSON: " + what + " at byte " + std::to_string(p_));
  }
  void ws() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_]))) ++p_;
  }
  bool lit(const char* w) {
    const std::size_t n = std::strlen(w);
    if (s_.compare(p_, n, w) == 0) {
      p_ += n;
      return true;
    }
    return false;
  }
  std::string string() {
    std::string out;
    ++p_;  // opening quote
    while (p_ < s_.size() && s_[p_] != '"') {
      char c = s_[p_++];
      if (c == '\\') {
        if (p_ >= s_.size()) fail("bad escape");
        char e = s_[p_++];
        switch (e) {
          case 'n': out += '\n'; break;
          case 't': out += '\t'; break;
          case 'u': out += '?'; p_ += 4; break;
          default: out += e;
        }
      } else {
        out += c;
      }
    }
    if (p_ >= s_.size()) fail("unterminated string");
    ++p_;
    return out;
  }
  Json value() {
    ws();
    if (p_ >= s_.size()) fail("unexpected end");
    Json v;
    const char c = s_[p_];
    if (c == '{') {
      v.kind = Json::Obj;
      ++p_;
      ws();
      if (s_[p_] == '}') { ++p_; return v; }
      for (;;) {
        ws();
        if (s_[p_] != '"') fail("expected a key");
        std::string k = string();
        ws();
        if (s_[p_++] != ':') fail("expected ':'");
        if (skip_.count(k)) {
          skip_value();
        } else {
          v.obj.emplace_back(std::move(k), value());
        }
        ws();
        if (s_[p_] == ',') { ++p_; continue; }
        if (s_[p_] == '}') { ++p_; return v; }
        fail("expected ',' or '}'");
      }
    }
    if (c == '[') {
      v.kind = Json::Arr;
      ++p_;
      ws();
      if (s_[p_] == ']') { ++p_; return v; }
      for (;;) {
        v.arr.push_back(value());
        ws();
        if (s_[p_] == ',') { ++p_; continue; }
        if (s_[p_] == ']') { ++p_; return v; }
        fail("expected ',' or ']'");
      }
    }
    if (c == '"') {
      v.kind = Json::Str;
      v.str = string();
      return v;
    }
    if (lit("true")) { v.kind = Json::Bool; v.num = 1; return v; }
    if (lit("false")) { v.kind = Json::Bool; return v; }
    if (lit("null")) return v;
    v.kind = Json::Num;
    if (lit("NaN")) { v.num = std::nan(""); return v; }
    if (lit("Infinity")) { v.num = HUGE_VAL; return v; }
    if (lit("-Infinity")) { v.num = -HUGE_VAL; return v; }
    const char* b = s_.c_str() + p_;
    char* e = nullptr;
    v.num = std::strtod(b, &e);
    if (e == b) fail("bad value");
    p_ += std::size_t(e - b);
    return v;
  }
  // Skips one value: brackets are counted outside strings.
  void skip_value() {
    ws();
    int depth = 0;
    while (p_ < s_.size()) {
      const char c = s_[p_];
      if (c == '"') {
        string();
        if (depth == 0) return;
        continue;
      }
      if (c == '[' || c == '{') ++depth;
      if (c == ']' || c == '}') {
        if (depth == 0) return;  // end of the enclosing container
        if (--depth == 0) { ++p_; return; }
      }
      if (depth == 0 && c == ',') return;
      ++p_;
    }
    fail("unexpected end");
  }
  const std::string& s_;
  std::set<std::string> skip_;
  std::size_t p_ = 0;
};

// ------------------------------------------------------------------ the VTK probe

struct ProbeResult {
  int code = -1;
  std::string output;
};

ProbeResult run_probe(const fs::path& root, const std::string& extra) {
  const fs::path log = root.parent_path() / "probe.log";
  const std::string cmd = "/usr/bin/python3 '" + fs::absolute(kProbe).string() + "' '" +
                          fs::absolute(root).string() + "' --quiet-cells " + extra + " > '" +
                          log.string() + "' 2>&1";
  ProbeResult r;
  const int st = std::system(cmd.c_str());
  r.code = WIFEXITED(st) ? WEXITSTATUS(st) : 128 + WTERMSIG(st);
  r.output = slurp(log);
  return r;
}

// The check needs VTK in /usr/bin/python3 (python3-vtk9, which the install step installs).
bool probe_available() {
  static const bool ok = fs::exists(kProbe) && fs::exists("/usr/bin/python3") &&
                         std::system("/usr/bin/python3 -c 'import vtkmodules.vtkIOLSDyna' >/dev/null 2>&1") == 0;
  return ok;
}

// Reads root with PlotReader and with the VTK probe and checks counts, times and one node's
// coordinates (the node that moved most by the last state) against each other.
void check_with_probe(const fs::path& root, int nodes, int solids, int steps) {
  PlotReader pr;
  ASSERT_NO_THROW(pr.open(root.string()));
  ASSERT_EQ(pr.num_states(), steps);
  const auto& g = pr.geometry();
  ASSERT_EQ(g.num_nodes(), nodes);
  ASSERT_EQ(g.num_hexes(), solids);
  // the node with the largest displacement at the last state
  const PlotState last = pr.state(steps - 1);
  int node = 0;
  double dmax = -1;
  for (int i = 0; i < nodes; ++i) {
    double d = 0;
    for (int a = 0; a < 3; ++a) d += std::pow(last.coords[3 * i + a] - g.x0[3 * i + a], 2);
    if (d > dmax) {
      dmax = d;
      node = i;
    }
  }
  double size = 0;
  for (double v : g.x0) size = std::max(size, std::fabs(v));
  char xyz[200];
  std::snprintf(xyz, sizeof xyz, "%.9g,%.9g,%.9g", g.x0[3 * node], g.x0[3 * node + 1], g.x0[3 * node + 2]);
  const fs::path json = root.parent_path() / "probe.json";
  const ProbeResult p = run_probe(root, "--expect-nodes " + std::to_string(nodes) + " --expect-solids " +
                                            std::to_string(solids) + " --expect-steps " +
                                            std::to_string(steps) + " --node-xyz=" + xyz +
                                            " --json '" + json.string() + "'");
  ASSERT_EQ(p.code, 0) << p.output;
  EXPECT_NE(p.output.find("RESULT: OK"), std::string::npos) << p.output;
  EXPECT_NE(p.output.find("selected node(s)"), std::string::npos) << p.output;
  Json j;
  const std::string text = slurp(json);
  ASSERT_NO_THROW(j = JsonParser(text, {"cell_arrays", "acceleration", "UserID", "temperature"}).parse());
  EXPECT_EQ(int(j.at("nodes").num), nodes);
  EXPECT_EQ(int(j.at("solids").num), solids);
  const Json& times = j.at("times");
  ASSERT_EQ(int(times.arr.size()), steps);
  for (int s = 0; s < steps; ++s)
    EXPECT_NEAR(times.arr[std::size_t(s)].num, pr.time(s), 1e-6 * std::fabs(pr.time(s)) + 1e-30)
        << "time of state " << s;
  const Json& jsteps = j.at("steps");
  ASSERT_EQ(int(jsteps.arr.size()), steps);
  const double tol = 1e-6 * size;
  for (int s = 0; s < steps; ++s) {
    const PlotState st = pr.state(s);
    int found = 0;
    for (const Json& part : jsteps.arr[std::size_t(s)].at("parts").arr) {
      const auto& init = part.at("initial").arr;
      const auto& pos = part.at("position").arr;
      const Json* vel = part.find("velocity");
      for (std::size_t q = 0; q < init.size(); ++q) {
        double d = 0;
        for (int a = 0; a < 3; ++a) d += std::pow(init[q].arr[std::size_t(a)].num - g.x0[3 * node + a], 2);
        if (std::sqrt(d) > 1e-6 * size) continue;
        ++found;
        for (int a = 0; a < 3; ++a) {
          EXPECT_NEAR(pos[q].arr[std::size_t(a)].num, st.coords[3 * node + a], tol)
              << "state " << s << " node " << node + 1 << " component " << a;
          if (vel) {
            EXPECT_NEAR(vel->arr[q].arr[std::size_t(a)].num, st.vel[3 * node + a],
                        1e-6 * std::fabs(st.vel[3 * node + a]) + 1e-12)
                << "velocity, state " << s << " node " << node + 1 << " component " << a;
          }
        }
      }
    }
    EXPECT_GE(found, 1) << "node " << node + 1 << " not found in the probe's output at step " << s;
  }
}

// Expected plot state count and times for a run to the deck's end time: a state at the first
// cycle at or after each k * plot_dt, and the final state at the end time.  (When the last grid
// time falls inside the last cycle, that state is the final state.)
void check_schedule(const PlotReader& r, const Card6& c) {
  const int n = r.num_states();
  ASSERT_GE(n, 2);
  EXPECT_NEAR(r.time(n - 1), c.end_time, 1e-6 * c.end_time) << "final state at the end time";
  const int full = int(std::floor(c.end_time / c.plot_dt + 1e-6));
  const bool on_grid = std::fabs(full * c.plot_dt - c.end_time) < 1e-6 * c.end_time;
  if (on_grid) {
    EXPECT_EQ(n, full + 1);
  } else {
    EXPECT_TRUE(n == full + 1 || n == full + 2) << n << " states for " << full + 1 << " grid times";
  }
  EXPECT_EQ(r.time(0), 0.0);
  for (int k = 1; k < n - 1; ++k) {
    EXPECT_GE(r.time(k), k * c.plot_dt * (1 - 1e-6)) << "state " << k;
    EXPECT_LT(r.time(k), (k + 1) * c.plot_dt) << "state " << k;
  }
}

// ------------------------------------------------------------------ shared runs (once per process)

// The shortened Taylor bar run to the end without interruption (the reference for tests 1, 3, 5).
const fs::path& reference_short_run() {
  static fs::path dir = [] {
    fs::path d = fresh_dir("short_reference");
    spit(d / "deck.dyn", short_taylor());
    RunResult r = run_impact3d(d, {"i=deck.dyn"}, "run");
    if (r.code != 0) throw std::runtime_error("reference short run failed: " + describe(r));
    return d;
  }();
  return dir;
}

// The full shipped Taylor bar (80 us, ~8000 cycles).
const fs::path& full_taylor_run() {
  static fs::path dir = [] {
    fs::path d = fresh_dir("full_taylor");
    RunResult r = run_impact3d(d, {"i=" + kDecks + "/taylor_bar.dyn"}, "run");
    if (r.code != 0) throw std::runtime_error("full Taylor run failed: " + describe(r));
    return d;
  }();
  return dir;
}

// one_hex with a restart dump every 10 cycles (a small dump for the damage tests).
std::string one_hex_with_dumps() {
  auto lines = split_lines(slurp(kDecks + "/one_hex.dyn"));
  std::string& l = lines.at(card6_line(lines));
  l.replace(30, 5, "   10");
  std::string out;
  for (const auto& s : lines) out += s + "\n";
  return out;
}

bool g_any_failure = false;

class Cleanup : public ::testing::Environment {
 public:
  void TearDown() override {
    if (!g_any_failure && !std::getenv("IMPACT3D_KEEP_TEST_RUNS")) {
      std::error_code ec;
      fs::remove_all(scratch_root(), ec);
    }
  }
};
const auto* const g_cleanup = ::testing::AddGlobalTestEnvironment(new Cleanup);

class RunOutputs : public ::testing::Test {
 protected:
  void TearDown() override {
    if (HasFailure()) g_any_failure = true;
  }
};

}  // namespace

// 1. A restart from the first dump reproduces every output of the uninterrupted run bit for bit.
TEST_F(RunOutputs, RestartEqualsUninterruptedRunBitForBit) {
  const fs::path a = reference_short_run();
  const fs::path b = fresh_dir("restart_b");
  spit(b / "deck.dyn", short_taylor());
  RunResult rb = run_impact3d(b, {"i=deck.dyn"}, "run");
  ASSERT_EQ(rb.code, 0) << describe(rb);
  ASSERT_TRUE(fs::exists(b / "d3dump01")) << describe(rb);
  ASSERT_TRUE(fs::exists(b / "d3dump02")) << describe(rb);
  // two uninterrupted runs agree (reproducible outputs)
  expect_same_outputs(a, b, kTaylorOutputs);
  // restart from cycle 1000: the outputs are cut back to the dump and continued
  RunResult rr = run_impact3d(b, {"r=d3dump01"}, "restart");
  ASSERT_EQ(rr.code, 0) << describe(rr);
  EXPECT_NE(rr.out.find("restart from d3dump01 at cycle 1000"), std::string::npos) << describe(rr);
  EXPECT_NE(rr.out.find("N o r m a l   t e r m i n a t i o n"), std::string::npos) << describe(rr);
  expect_same_outputs(a, b, kTaylorOutputs);
  // the restart wrote the second dump again, identical in content
  EXPECT_TRUE(fs::exists(b / "d3dump02"));
  // the printed file of the first run was appended to, not overwritten
  const std::string hsp = slurp(b / "d3hsp");
  EXPECT_NE(hsp.find("restart from d3dump01"), std::string::npos);
  EXPECT_NE(hsp.find("N o r m a l   t e r m i n a t i o n"), std::string::npos);
}

// 1b. Restart with the names of the first run given explicitly (o=, g=), from a dump written in
// another folder: the same outputs.
TEST_F(RunOutputs, RestartFromSecondDumpWithExplicitNames) {
  const fs::path a = reference_short_run();
  const fs::path b = fresh_dir("restart_c");
  spit(b / "deck.dyn", short_taylor());
  fs::create_directories(b / "dumps");
  RunResult rb = run_impact3d(b, {"i=deck.dyn", "o=d3hsp", "g=d3plot", "d=dumps/rs"}, "run");
  ASSERT_EQ(rb.code, 0) << describe(rb);
  ASSERT_TRUE(fs::exists(b / "dumps/rs02")) << describe(rb);
  RunResult rr = run_impact3d(b, {"r=dumps/rs02", "o=d3hsp", "g=d3plot", "d=dumps/rs"}, "restart");
  ASSERT_EQ(rr.code, 0) << describe(rr);
  expect_same_outputs(a, b, kTaylorOutputs);
}

// 1c. The running restart dump (control card 6 cols 36-40, runrsf, overwritten each time)
// restarts to the same outputs; a restart refuses history files shorter than the dump expects.
TEST_F(RunOutputs, RunningRestartDumpAndShortenedHistoryFile) {
  const fs::path a = reference_short_run();
  const fs::path b = fresh_dir("runrsf");
  {
    auto lines = split_lines(short_taylor());
    lines.at(card6_line(lines)).replace(35, 5, "  700");
    std::string text;
    for (const auto& x : lines) text += x + "\n";
    spit(b / "deck.dyn", text);
  }
  RunResult rb = run_impact3d(b, {"i=deck.dyn"}, "run");
  ASSERT_EQ(rb.code, 0) << describe(rb);
  ASSERT_TRUE(fs::exists(b / "runrsf")) << describe(rb);
  EXPECT_NE(rb.out.find("restart dump ./runrsf written at cycle 2100"), std::string::npos) << describe(rb);
  EXPECT_EQ(impact3d::read_restart_dump_header((b / "runrsf").string()).cursor.dumps_written, 2);
  RunResult rr = run_impact3d(b, {"r=runrsf"}, "restart");
  ASSERT_EQ(rr.code, 0) << describe(rr);
  EXPECT_NE(rr.out.find("restart from runrsf at cycle 2100"), std::string::npos) << describe(rr);
  expect_same_outputs(a, b, kTaylorOutputs);
  // glstat shorter than the dump recorded: refused (was: padded with zero bytes, exit 0)
  fs::resize_file(b / "glstat", 100);
  RunResult rs = run_impact3d(b, {"r=d3dump01"}, "restart_short");
  EXPECT_EQ(rs.code, 4) << describe(rs);
  EXPECT_NE(rs.err.find("error 4006"), std::string::npos) << describe(rs);
  EXPECT_NE(rs.err.find("glstat"), std::string::npos) << describe(rs);
  EXPECT_EQ(slurp(b / "glstat").find('\0'), std::string::npos) << "glstat padded with zero bytes";
  // a missing plot family member
  fs::resize_file(b / "glstat", fs::file_size(a / "glstat"));
  fs::remove(b / "d3plot01");
  RunResult rp = run_impact3d(b, {"r=d3dump01"}, "restart_noplot");
  EXPECT_EQ(rp.code, 4) << describe(rp);
  EXPECT_NE(rp.err.find("error 4006"), std::string::npos) << describe(rp);
  EXPECT_NE(rp.err.find("d3plot01"), std::string::npos) << describe(rp);
}

// 2. Every shipped deck that runs: the VTK probe reads the database with the expected counts,
// and its times and one node's coordinates equal our reader's.
TEST_F(RunOutputs, ShippedDecksReadByVtkAndPlotReaderAlike) {
  if (!probe_available()) GTEST_SKIP() << "VTK check not available (" << kProbe << ", python3-vtk9)";
  struct Expect {
    std::string deck;
    int nodes, solids;
  };
  const std::vector<Expect> decks = {{"taylor_bar", 1369, 972},
                                     {"one_hex", 8, 1},
                                     {"bar_wall_elastic", 369, 160},
                                     {"column_uniaxial_strain", 164, 40}};
  for (const auto& e : decks) {
    SCOPED_TRACE(e.deck);
    fs::path dir;
    if (e.deck == "taylor_bar") {
      dir = full_taylor_run();
    } else {
      dir = fresh_dir("deck_" + e.deck);
      RunResult r = run_impact3d(dir, {"i=" + kDecks + "/" + e.deck + ".dyn"}, "run");
      ASSERT_EQ(r.code, 0) << describe(r);
    }
    PlotReader pr;
    ASSERT_NO_THROW(pr.open((dir / "d3plot").string()));
    check_schedule(pr, read_card6(kDecks + "/" + e.deck + ".dyn"));
    if (e.deck == "taylor_bar") {
      EXPECT_EQ(pr.num_states(), 21);
    }
    check_with_probe(dir / "d3plot", e.nodes, e.solids, pr.num_states());
  }
}

// 2b. Decks with sliding interfaces: when the engine refuses them (exit 2, contact not in this
// version) the test is skipped; when they run, the same checks as above.
TEST_F(RunOutputs, ShippedContactDecksReadByVtkWhenTheyRun) {
  if (!probe_available()) GTEST_SKIP() << "VTK check not available (" << kProbe << ", python3-vtk9)";
  std::vector<std::string> skipped;
  for (const std::string deck : {"crossed_cylinders", "two_bars", "oblique_rod"}) {
    SCOPED_TRACE(deck);
    const fs::path dir = fresh_dir("deck_" + deck);
    std::string deck_path = kDecks + "/" + deck + ".dyn";
    if (deck == "oblique_rod") {
      // 2.6 ms is ~80000 cycles (minutes): the first 50 us, with a plot state every 25 us
      auto lines = split_lines(slurp(deck_path));
      std::string& l = lines.at(card6_line(lines));
      l.replace(0, 10, "5.0000e-05");
      l.replace(20, 10, "2.5000e-05");
      std::string text;
      for (const auto& x : lines) text += x + "\n";
      deck_path = (dir / "oblique_rod_50us.dyn").string();
      spit(deck_path, text);
    }
    const pid_t pid = spawn(dir, {"i=" + deck_path}, "run");
    // these may be long once contact runs: give each at most 60 s
    int code = -1;
    const auto t0 = std::chrono::steady_clock::now();
    for (;;) {
      int status = 0;
      if (::waitpid(pid, &status, WNOHANG) == pid) {
        code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        break;
      }
      if (std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() > 60) {
        ::kill(pid, SIGKILL);
        wait_exit(pid);
        code = -2;
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    if (code == 2 || code == -2) {
      skipped.push_back(deck + (code == 2 ? " (refused, exit 2)" : " (longer than 60 s)"));
      continue;
    }
    ASSERT_EQ(code, 0) << slurp(dir / "run.out") << slurp(dir / "run.err");
    PlotReader pr;
    ASSERT_NO_THROW(pr.open((dir / "d3plot").string()));
    check_schedule(pr, read_card6(deck_path));
    check_with_probe(dir / "d3plot", pr.geometry().num_nodes(), pr.geometry().num_hexes(), pr.num_states());
  }
  if (skipped.size() == 3) {
    std::string s;
    for (const auto& k : skipped) s += " " + k;
    GTEST_SKIP() << "no contact deck ran:" << s;
  }
}

// 3. plotwords=8: the same values as the 4-byte database, to float rounding; 8-byte time
// histories likewise.
TEST_F(RunOutputs, EightByteWordsHoldTheFourByteValues) {
  const fs::path a = reference_short_run();
  const fs::path d = fresh_dir("plotwords8");
  spit(d / "deck.dyn", short_taylor());
  RunResult r = run_impact3d(d, {"i=deck.dyn", "plotwords=8"}, "run");
  ASSERT_EQ(r.code, 0) << describe(r);
  // the ASCII tables do not depend on the word size
  for (const char* f : {"glstat", "matsum", "rwforc", "nodout", "elout"})
    EXPECT_EQ(slurp(a / f), slurp(d / f)) << f;
  for (const char* root : {"d3plot", "d3thdt"}) {
    SCOPED_TRACE(root);
    PlotReader r4, r8;
    ASSERT_NO_THROW(r4.open((a / root).string()));
    ASSERT_NO_THROW(r8.open((d / root).string()));
    EXPECT_EQ(r4.control().word_size, 4);
    EXPECT_EQ(r8.control().word_size, 8);
    ASSERT_EQ(r8.num_states(), r4.num_states());
    ASSERT_GE(r4.num_states(), 2);
    const auto& g4 = r4.geometry();
    const auto& g8 = r8.geometry();
    ASSERT_EQ(g8.x0.size(), g4.x0.size());
    EXPECT_EQ(g8.hex_nodes, g4.hex_nodes);
    EXPECT_EQ(g8.hex_material, g4.hex_material);
    EXPECT_EQ(g8.node_user_ids, g4.node_user_ids);
    EXPECT_EQ(g8.title, g4.title);
    auto same = [](const std::vector<double>& v8, const std::vector<double>& v4, const char* what, int s) {
      ASSERT_EQ(v8.size(), v4.size()) << what;
      int bad = 0;
      std::size_t first = 0;
      for (std::size_t k = 0; k < v8.size(); ++k)
        if (static_cast<float>(v8[k]) != static_cast<float>(v4[k])) {
          if (!bad) first = k;
          ++bad;
        }
      EXPECT_EQ(bad, 0) << what << " of state " << s << ": " << bad << " values differ beyond float rounding, first at "
                        << first << ": " << v8[first] << " vs " << v4[first];
    };
    same(g8.x0, g4.x0, "initial coordinates", -1);
    bool some_not_float = false;  // the 8-byte file really holds more than float precision
    for (int s = 0; s < r4.num_states(); ++s) {
      EXPECT_EQ(static_cast<float>(r8.time(s)), static_cast<float>(r4.time(s)));
      const PlotState p4 = r4.state(s), p8 = r8.state(s);
      same(p8.coords, p4.coords, "coordinates", s);
      same(p8.vel, p4.vel, "velocities", s);
      same(p8.acc, p4.acc, "accelerations", s);
      same(p8.stress, p4.stress, "stresses", s);
      same(p8.eps, p4.eps, "plastic strain", s);
      same(p8.mat_internal_energy, p4.mat_internal_energy, "material internal energy", s);
      same(p8.mat_kinetic_energy, p4.mat_kinetic_energy, "material kinetic energy", s);
      same({p8.kinetic_energy, p8.internal_energy, p8.total_energy},
           {p4.kinetic_energy, p4.internal_energy, p4.total_energy}, "global energies", s);
      EXPECT_EQ(p8.alive, p4.alive);
      for (double v : p8.coords)
        if (double(static_cast<float>(v)) != v) some_not_float = true;
    }
    EXPECT_TRUE(some_not_float) << "the 8-byte database holds only float values";
  }
}

// 4. A run killed with SIGKILL mid-way leaves only complete, readable states.
TEST_F(RunOutputs, SigkillLeavesOnlyCompleteStates) {
  const fs::path d = fresh_dir("sigkill");
  const pid_t pid = spawn(d, {"i=" + kDecks + "/taylor_bar.dyn"}, "run");
  ASSERT_TRUE(reached_states(pid, d / "d3plot", 3));
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  EXPECT_EQ(wait_exit(pid), 128 + SIGKILL);
  for (const char* root : {"d3plot", "d3thdt"}) {
    SCOPED_TRACE(root);
    PlotReader r;
    ASSERT_NO_THROW(r.open((d / root).string()));
    const int n = r.num_states();
    if (std::string(root) == "d3plot") {
      EXPECT_GE(n, 3);
      EXPECT_LT(n, 21) << "the run was killed before its end";
    }
    double prev = -1;
    for (int s = 0; s < n; ++s) {
      EXPECT_TRUE(std::isfinite(r.time(s)));
      EXPECT_GT(r.time(s), prev) << "state " << s;
      prev = r.time(s);
      PlotState st;
      ASSERT_NO_THROW(st = r.state(s)) << "state " << s;
      for (double v : st.coords) ASSERT_TRUE(std::isfinite(v)) << "state " << s;
      for (double v : st.stress) ASSERT_TRUE(std::isfinite(v)) << "state " << s;
    }
    if (std::string(root) == "d3plot" && probe_available()) {
      const ProbeResult p = run_probe(d / root, "--expect-nodes 1369 --expect-solids 972 --expect-steps " + std::to_string(n));
      EXPECT_EQ(p.code, 0) << p.output;
    }
  }
  // no temporary member left readable as a state file
  for (const auto& e : fs::directory_iterator(d)) {
    const std::string n = e.path().filename().string();
    if (n.size() > 4 && n.substr(n.size() - 4) == ".tmp") {
      EXPECT_EQ(n.rfind("d3plot", 0), std::string::npos) << "leftover " << n << " (harmless only if ignored)";
    }
  }
}

// 5. SIGINT (sense switch sw1): a dump and a plot state, exit 6; the dump restarts to the same
// results as the uninterrupted run.
TEST_F(RunOutputs, SigintDumpRestartsToTheUninterruptedResults) {
  const fs::path a = reference_short_run();
  const fs::path d = fresh_dir("sigint");
  spit(d / "deck.dyn", short_taylor());
  const pid_t pid = spawn(d, {"i=deck.dyn"}, "run");
  ASSERT_TRUE(reached_states(pid, d / "d3plot", 2));
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  const int code = wait_exit(pid);
  const std::string out = slurp(d / "run.out"), hsp = slurp(d / "d3hsp");
  ASSERT_EQ(code, 6) << out << slurp(d / "run.err");
  EXPECT_NE(hsp.find("sense switch sw1"), std::string::npos) << hsp;
  EXPECT_NE(hsp.find("E r r o r   t e r m i n a t i o n"), std::string::npos) << hsp;
  EXPECT_NE(out.find("E r r o r   t e r m i n a t i o n"), std::string::npos) << out;
  // the dump named in the termination line
  const std::string key = "restart with r=";
  const std::size_t k = out.find(key);
  ASSERT_NE(k, std::string::npos) << out;
  const std::string dump = out.substr(k + key.size(), out.find(')', k) - k - key.size());
  ASSERT_TRUE(fs::exists(d / dump)) << dump;
  // the stop wrote a plot state at the dump's time, after the scheduled ones (or the signal
  // landed on a cycle that had just written one: then that state serves, no time repeats)
  {
    PlotReader r;
    ASSERT_NO_THROW(r.open((d / "d3plot").string()));
    EXPECT_GE(r.num_states(), 2);
    const std::string w = " restart dump " + dump + " written at cycle ";
    const std::size_t q = out.rfind(w);
    ASSERT_NE(q, std::string::npos) << out;
    const std::size_t tpos = out.find("time ", q);
    const double t = std::stod(out.substr(tpos + 5, 14));
    EXPECT_NEAR(r.time(r.num_states() - 1), t, 1e-5 * t);
  }
  RunResult rr = run_impact3d(d, {"r=" + dump}, "restart");
  ASSERT_EQ(rr.code, 0) << describe(rr);
  EXPECT_NE(rr.out.find("N o r m a l   t e r m i n a t i o n"), std::string::npos) << describe(rr);
  expect_same_outputs(a, d, kTaylorOutputs);
}

// 5b. SIGTERM is the same switch as SIGINT.
TEST_F(RunOutputs, SigtermStopsWithADump) {
  const fs::path d = fresh_dir("sigterm");
  spit(d / "deck.dyn", short_taylor());
  const pid_t pid = spawn(d, {"i=deck.dyn"}, "run");
  ASSERT_TRUE(reached_states(pid, d / "d3plot", 2));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  EXPECT_EQ(wait_exit(pid), 6) << slurp(d / "run.out");
  EXPECT_NE(slurp(d / "d3hsp").find("sense switch sw1"), std::string::npos);
  EXPECT_TRUE(fs::exists(d / "d3dump01"));
}

// 5c. SIGUSR1 prints a status line; SIGUSR2 writes one extra plot state; the run ends normally.
TEST_F(RunOutputs, Sigusr1StatusAndSigusr2ExtraPlotState) {
  const fs::path a = reference_short_run();
  const fs::path d = fresh_dir("sigusr");
  spit(d / "deck.dyn", short_taylor());
  const pid_t pid = spawn(d, {"i=deck.dyn"}, "run");
  ASSERT_TRUE(reached_states(pid, d / "d3plot", 2));
  ASSERT_EQ(::kill(pid, SIGUSR1), 0);
  // one switch per cycle poll: let the status be seen before the plot request
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  ASSERT_EQ(::kill(pid, SIGUSR2), 0);
  const int code = wait_exit(pid);
  const std::string out = slurp(d / "run.out"), hsp = slurp(d / "d3hsp");
  ASSERT_EQ(code, 0) << out << slurp(d / "run.err");
  EXPECT_NE(out.find("status (SIGUSR1"), std::string::npos) << out;
  EXPECT_NE(hsp.find("status (SIGUSR1"), std::string::npos);
  EXPECT_NE(hsp.find("N o r m a l   t e r m i n a t i o n"), std::string::npos);
  PlotReader ref, r;
  ASSERT_NO_THROW(ref.open((a / "d3plot").string()));
  ASSERT_NO_THROW(r.open((d / "d3plot").string()));
  ASSERT_EQ(r.num_states(), ref.num_states() + 1) << "one state more than scheduled";
  // the scheduled states are all there, at the same times; the extra one lies between two
  int extra = -1;
  for (int s = 0, k = 0; s < r.num_states(); ++s) {
    if (k < ref.num_states() && r.time(s) == ref.time(k)) {
      ++k;
    } else {
      EXPECT_EQ(extra, -1) << "more than one unscheduled state";
      extra = s;
    }
    // (a request that falls on a scheduled state's cycle gives a second state at that time)
    if (s) {
      EXPECT_GE(r.time(s), r.time(s - 1));
    }
  }
  EXPECT_GT(extra, 0);
  // the time histories do not change
  for (const char* f : {"glstat", "matsum", "rwforc", "nodout", "elout", "d3thdt01"})
    EXPECT_EQ(slurp(a / f), slurp(d / f)) << f;
}

// 6. Truncated and corrupted dumps: clear errors naming the file, no crash; the binary exits 4
// with message 4005.
TEST_F(RunOutputs, DamagedDumpsAreRefusedClearly) {
  const fs::path d = fresh_dir("damaged");
  spit(d / "deck.dyn", one_hex_with_dumps());
  RunResult r = run_impact3d(d, {"i=deck.dyn"}, "run");
  ASSERT_EQ(r.code, 0) << describe(r);
  ASSERT_TRUE(fs::exists(d / "d3dump01")) << describe(r);
  const std::string good = slurp(d / "d3dump01");
  ASSERT_GT(good.size(), 200u);

  // the model, to read states into
  impact3d::Model model;
  impact3d::Diagnostics diag;
  ASSERT_TRUE(impact3d::read_and_check_deck((d / "deck.dyn").string(), model, diag));
  impact3d::Engine engine(model);
  engine.initialize();
  impact3d::SlidingInterfaces::RestartData contact;
  // the good dump reads
  ASSERT_NO_THROW(impact3d::read_restart_dump_header((d / "d3dump01").string()));
  ASSERT_NO_THROW(impact3d::read_restart_dump_state((d / "d3dump01").string(), engine.state(), contact));
  EXPECT_EQ(engine.state().cycle, 10);

  std::vector<std::pair<std::string, std::string>> damaged;  // name, content
  // 10 truncations: empty, inside the header, just after it, inside the payload, one byte short
  const std::size_t n = good.size();
  for (std::size_t len : {std::size_t(0), std::size_t(1), std::size_t(15), std::size_t(39), std::size_t(40),
                          std::size_t(41), n / 4, n / 2, n - 9, n - 1})
    damaged.emplace_back("trunc_" + std::to_string(len), good.substr(0, len));
  // an extended file
  damaged.emplace_back("extended", good + "x");
  // 50 flipped bytes: magic, version, size, checksum, and spread over the payload.  (Bytes 20-23
  // and 36-39 are reserved and not checked.)
  std::vector<std::size_t> pos = {0, 5, 12, 16, 17, 19, 24, 25, 31, 32, 33, 35};
  for (std::size_t k = 0; pos.size() < 50; ++k) pos.push_back(40 + (k * 7919) % (n - 40));
  for (std::size_t p : pos) {
    std::string c = good;
    c[p] = static_cast<char>(c[p] ^ 0x5a);
    damaged.emplace_back("flip_" + std::to_string(p), c);
  }
  ASSERT_EQ(damaged.size(), 61u);
  for (const auto& [name, content] : damaged) {
    SCOPED_TRACE(name);
    const fs::path p = d / name;
    spit(p, content);
    for (int which = 0; which < 2; ++which) {
      try {
        if (which == 0) impact3d::read_restart_dump_header(p.string());
        else impact3d::read_restart_dump_state(p.string(), engine.state(), contact);
        ADD_FAILURE() << (which ? "read_restart_dump_state" : "read_restart_dump_header") << " accepted " << name;
      } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(p.string()), std::string::npos) << e.what();
      } catch (const std::exception& e) {
        ADD_FAILURE() << "not a std::runtime_error: " << e.what();
      }
    }
    RunResult rr = run_impact3d(d, {"r=" + name}, "restart_" + name);
    EXPECT_EQ(rr.code, 4) << describe(rr);
    EXPECT_NE(rr.err.find("error 4005"), std::string::npos) << describe(rr);
    EXPECT_NE(rr.err.find(name), std::string::npos) << describe(rr);
  }
  // a dump of another format version (the checksum covers only the payload)
  {
    std::string c = good;
    const std::uint32_t v = impact3d::kDumpVersion + 1;
    std::memcpy(c.data() + 16, &v, 4);
    const fs::path p = d / "other_version";
    spit(p, c);
    try {
      impact3d::read_restart_dump_header(p.string());
      ADD_FAILURE() << "a dump of another version was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("format version " + std::to_string(v)), std::string::npos) << e.what();
    }
  }
  // a missing dump
  RunResult rm = run_impact3d(d, {"r=no_such_dump"}, "missing");
  EXPECT_EQ(rm.code, 4) << describe(rm);
  EXPECT_NE(rm.err.find("error 4005"), std::string::npos) << describe(rm);
  // a dump of another model (the Taylor bar) into the one-hex state
  {
    const fs::path b = reference_short_run();
    ASSERT_TRUE(fs::exists(b / "d3dump01"));
    try {
      impact3d::read_restart_dump_state((b / "d3dump01").string(), engine.state(), contact);
      ADD_FAILURE() << "a dump of another model was accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("d3dump01"), std::string::npos) << e.what();
    }
  }
}

// 7. Output that cannot be written stops the run with message 3004 and exit 4.
TEST_F(RunOutputs, UnwritableOutputsStopWithMessage3004) {
  const fs::path d = fresh_dir("unwritable");
  spit(d / "deck.dyn", one_hex_with_dumps());
  const std::string missing = (d / "no_such_dir").string();
  {
    RunResult r = run_impact3d(d, {"i=deck.dyn", "g=" + missing + "/d3plot"}, "plot");
    EXPECT_EQ(r.code, 4) << describe(r);
    EXPECT_NE(r.err.find("error 3004"), std::string::npos) << describe(r);
    EXPECT_NE(r.err.find(missing), std::string::npos) << describe(r);
    EXPECT_NE(r.out.find("E r r o r   t e r m i n a t i o n"), std::string::npos) << describe(r);
  }
  {
    RunResult r = run_impact3d(d, {"i=deck.dyn", "o=" + missing + "/d3hsp"}, "printed");
    EXPECT_EQ(r.code, 4) << describe(r);
    EXPECT_NE(r.err.find("error 3004"), std::string::npos) << describe(r);
    EXPECT_NE(r.err.find(missing), std::string::npos) << describe(r);
  }
  {
    // restart dumps every 10 cycles into a missing folder: the first dump fails
    RunResult r = run_impact3d(d, {"i=deck.dyn", "d=" + missing + "/d3dump"}, "dump");
    EXPECT_EQ(r.code, 4) << describe(r);
    EXPECT_NE(r.err.find("error 3004"), std::string::npos) << describe(r);
    EXPECT_NE(r.err.find(missing), std::string::npos) << describe(r);
    EXPECT_NE(r.out.find("E r r o r   t e r m i n a t i o n"), std::string::npos) << describe(r);
    // the states written before the failure stay readable
    PlotReader pr;
    EXPECT_NO_THROW(pr.open((d / "d3plot").string()));
    EXPECT_GE(pr.num_states(), 1);
  }
  {
    // a plot root that is a directory
    fs::create_directories(d / "adir");
    RunResult r = run_impact3d(d, {"i=deck.dyn", "g=adir"}, "plotdir");
    EXPECT_EQ(r.code, 4) << describe(r);
    EXPECT_NE(r.err.find("error 3004"), std::string::npos) << describe(r);
  }
}
