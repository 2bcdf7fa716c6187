// The malformed-deck corpus (tests/input/malformed/, manifest EXPECTED): every deck is refused
// with the expected message numbers at the expected lines, fields and columns; and the
// impact3d binary refuses them with exit code 2, prints the rendered messages and writes no
// plot database.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "input_test_util.h"

using namespace impact3d;
using namespace impact3d::testing;
namespace fs = std::filesystem;

namespace {

struct Expectation {
  std::string file;
  int id = 0;
  int line = 0;
  std::string field;  // "-" = not checked
  int col_first = -1, col_last = -1;
  std::string text;   // "-" = not checked
  int manifest_line = 0;
};

std::string trim(const std::string& s) {
  std::size_t b = s.find_first_not_of(' '), e = s.find_last_not_of(' ');
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::string corpus_dir() { return source_path("tests/input/malformed"); }

std::vector<Expectation> load_manifest() {
  std::vector<Expectation> out;
  std::ifstream in(corpus_dir() + "/EXPECTED");
  EXPECT_TRUE(in.good()) << "cannot read the manifest EXPECTED";
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (trim(line).empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::size_t p = 0;
    while (true) {
      std::size_t q = line.find('|', p);
      f.push_back(trim(line.substr(p, q == std::string::npos ? std::string::npos : q - p)));
      if (q == std::string::npos) break;
      p = q + 1;
    }
    // the text column may itself contain '|': join what follows the fifth separator
    if (f.size() > 6) {
      for (std::size_t k = 6; k < f.size(); ++k) f[5] += "|" + f[k];
      f.resize(6);
    }
    EXPECT_EQ(f.size(), 6u) << "EXPECTED line " << n << ": " << line;
    if (f.size() != 6) continue;
    Expectation e;
    e.file = f[0];
    e.id = std::stoi(f[1]);
    e.line = std::stoi(f[2]);
    e.field = f[3];
    if (f[4] != "-") {
      std::size_t dash = f[4].find('-');
      e.col_first = std::stoi(f[4].substr(0, dash));
      e.col_last = std::stoi(f[4].substr(dash + 1));
    }
    e.text = f[5];
    e.manifest_line = n;
    out.push_back(e);
  }
  return out;
}

bool matches(const Diagnostic& d, const Expectation& e, const std::string& shown) {
  if (d.id != e.id || d.where.line != e.line) return false;
  if (e.field != "-" && d.where.field != e.field) return false;
  if (e.col_first >= 0 && (d.where.col_first != e.col_first || d.where.col_last != e.col_last)) return false;
  if (e.text != "-" && render(d).find(e.text) == std::string::npos) return false;
  (void)shown;
  return true;
}

struct RunResult {
  int exit_code = -1;
  std::string err;
};

// Runs a shell command with stderr captured (stdout discarded); returns the exit status.
RunResult run_capture_stderr(const std::string& cmd) {
  RunResult r;
  FILE* p = popen((cmd + " 2>&1 >/dev/null").c_str(), "r");
  if (!p) return r;
  char buf[4096];
  std::size_t n;
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) r.err.append(buf, n);
  int st = pclose(p);
  if (st != -1 && WIFEXITED(st)) r.exit_code = WEXITSTATUS(st);
  return r;
}

std::string impact3d_binary() { return std::string(IMPACT3D_BINARY_DIR) + "/impact3d"; }

std::string quote(const std::string& s) { return "'" + s + "'"; }

struct TempDir {
  fs::path path;
  TempDir() {
    path = fs::temp_directory_path() / ("impact3d_malformed_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter()++));
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path, ec);
  }
  static int& counter() {
    static int c = 0;
    return c;
  }
};

}  // namespace

TEST(MalformedCorpus, ManifestCoversEveryDeck) {
  auto exp = load_manifest();
  std::set<std::string> listed;
  for (const auto& e : exp) listed.insert(e.file);
  std::set<std::string> on_disk;
  for (const auto& entry : fs::directory_iterator(corpus_dir()))
    if (entry.path().extension() == ".dyn") on_disk.insert(entry.path().filename().string());
  on_disk.erase("tiny.dyn");  // the valid deck the corpus is made from
  EXPECT_EQ(listed, on_disk);
  EXPECT_GE(on_disk.size(), 30u);
}

TEST(MalformedCorpus, BaseDeckIsValid) {
  Model m;
  Diagnostics diag;
  EXPECT_TRUE(read_and_check_deck(corpus_dir() + "/tiny.dyn", m, diag)) << all_messages(diag);
  EXPECT_EQ(diag.error_count(), 0);
  EXPECT_EQ(diag.warning_count(), 0);
}

TEST(MalformedCorpus, EveryDeckGivesTheExpectedMessages) {
  auto exp = load_manifest();
  std::map<std::string, std::vector<Expectation>> by_file;
  for (const auto& e : exp) by_file[e.file].push_back(e);
  for (const auto& [file, list] : by_file) {
    SCOPED_TRACE(file);
    Model m;
    Diagnostics diag;
    bool ok = read_and_check_deck(corpus_dir() + "/" + file, m, diag);
    std::string shown = all_messages(diag);
    EXPECT_FALSE(ok) << shown;
    EXPECT_GE(diag.error_count(), 1) << shown;
    for (const auto& e : list) {
      bool found = false;
      for (const auto& d : diag.all()) found = found || matches(d, e, shown);
      EXPECT_TRUE(found) << "EXPECTED line " << e.manifest_line << ": message " << e.id << " at line "
                         << e.line << " field \"" << e.field << "\" cols " << e.col_first << "-"
                         << e.col_last << " text \"" << e.text << "\" not reported; got:\n"
                         << shown;
    }
    // every message that has a line points into the file
    int last = 0;
    {
      std::ifstream in(corpus_dir() + "/" + file, std::ios::binary);
      std::string l;
      while (std::getline(in, l)) ++last;
    }
    for (const auto& d : diag.all()) {
      EXPECT_GE(d.where.line, 0);
      EXPECT_LE(d.where.line, last) << render(d);
      EXPECT_EQ(d.where.file, corpus_dir() + "/" + file);
      EXPECT_LE(d.where.col_first, d.where.col_last) << render(d);
    }
  }
}

TEST(MalformedCorpus, SeveralErrorsAllReportedInOnePass) {
  Model m;
  Diagnostics diag;
  EXPECT_FALSE(read_and_check_deck(corpus_dir() + "/several_errors.dyn", m, diag));
  std::set<int> ids;
  for (const auto& d : diag.all()) ids.insert(d.id);
  EXPECT_GE(ids.size(), 4u) << all_messages(diag);
  EXPECT_EQ(diag.error_count(), 5) << all_messages(diag);
}

// ---------------------------------------------------------------- the binary

class Binary : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!fs::exists(impact3d_binary()))
      GTEST_SKIP() << impact3d_binary() << " not built (make impact3d)";
  }
};

TEST_F(Binary, CheckRefusesMalformedDecksWithExitCode2AndTheRenderedMessage) {
  const char* files[] = {"tterm_zero.dyn", "nu_06.dyn", "inverted_element.dyn", "tab.dyn",
                         "several_errors.dyn", "empty.dyn", "keyword_deck.dyn", "segment_not_face.dyn"};
  for (const char* f : files) {
    SCOPED_TRACE(f);
    std::string path = corpus_dir() + "/" + f;
    RunResult r = run_capture_stderr(impact3d_binary() + " --check i=" + quote(path));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    // the same messages as the library reports, one line each
    Model m;
    Diagnostics diag;
    read_and_check_deck(path, m, diag);
    ASSERT_GE(diag.all().size(), 1u);
    for (const auto& d : diag.all()) EXPECT_NE(r.err.find(render(d) + "\n"), std::string::npos) << render(d) << "\n" << r.err;
  }
}

TEST_F(Binary, RenderedMessageIsExact) {
  std::string path = corpus_dir() + "/tterm_zero.dyn";
  RunResult r = run_capture_stderr(impact3d_binary() + " --check i=" + quote(path));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find(path + ":8: error 1214: control card 6, field \"termination time\" (cols 1-10): "
                              "termination time must be positive [found \"0.0000e+00\"]\n"),
            std::string::npos)
      << r.err;
}

TEST_F(Binary, ValidDeckChecksWithExitCode0) {
  RunResult r = run_capture_stderr(impact3d_binary() + " --check i=" + quote(corpus_dir() + "/tiny.dyn"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
}

TEST_F(Binary, MissingFileGivesExitCode4) {
  TempDir t;
  std::string missing = (t.path / "no_such_deck.dyn").string();
  RunResult r = run_capture_stderr(impact3d_binary() + " --check i=" + quote(missing));
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_NE(r.err.find("error 3003"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
}

TEST_F(Binary, NothingIsWrittenToThePlotDatabaseWhenTheInputIsBad) {
  const char* files[] = {"several_errors.dyn", "inverted_element.dyn", "binary_garbage.dyn"};
  for (const char* f : files) {
    SCOPED_TRACE(f);
    TempDir t;
    std::string plot = (t.path / "d3plot").string();
    std::string printed = (t.path / "d3hsp").string();
    std::string dump = (t.path / "d3dump").string();
    RunResult r = run_capture_stderr("cd " + quote(t.path.string()) + " && " + impact3d_binary() +
                                     " i=" + quote(corpus_dir() + "/" + f) + " o=" + quote(printed) +
                                     " g=" + quote(plot) + " d=" + quote(dump));
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_FALSE(fs::exists(plot));
    EXPECT_FALSE(fs::exists(dump));
    for (const auto& entry : fs::directory_iterator(t.path)) {
      std::string name = entry.path().filename().string();
      EXPECT_TRUE(name.rfind("d3plot", 0) != 0) << "plot file written: " << name;
      EXPECT_TRUE(name.rfind("d3dump", 0) != 0) << "dump written: " << name;
    }
    // the printed output holds the messages and the error termination
    std::string out = read_text(printed);
    EXPECT_NE(out.find("E r r o r   t e r m i n a t i o n"), std::string::npos) << out;
  }
}

TEST_F(Binary, UsageErrorGivesExitCode3) {
  RunResult r = run_capture_stderr(impact3d_binary() + " --check");
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(r.err.find("3002"), std::string::npos) << r.err;
}
