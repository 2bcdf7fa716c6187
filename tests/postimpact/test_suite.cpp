// postimpact suite (docs/regression-suites.md, "Regression suites for users"): a suite of three of the project's
// regression decks whose references `--update` stores; one reference is then damaged (one
// stress value of one state scaled by 1 + 1e-3, a change a billion times its tolerance).  The
// suite must fail exactly that deck and name the field, state, element and component, in its
// exit status, junit.xml (parsed by Python's XML parser: well-formed, one failure) and
// report.html (every deck listed, with its pictures); the per-deck job mode (--job K, as a
// Slurm array runs it) followed by --gather gives the same verdicts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

#include "postimpact/database.h"
#include "postimpact/image.h"
#include "postimpact/png_io.h"
#include "postimpact/suite.h"

namespace fs = std::filesystem;

namespace {

const std::string kPostimpact = IMPACT3D_BINARY_DIR "/postimpact/postimpact";
const std::string kImpact3d = IMPACT3D_BINARY_DIR "/impact3d";

std::string slurp(const fs::path& p) {
    std::ifstream f(p, std::ios::binary);
    std::stringstream ss;
    ss << f.rdbuf();
    return ss.str();
}

int run(const std::string& cmd) {
    const int st = std::system(cmd.c_str());
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

struct Damage {
    int state = 0;  // 1-based
    int elem = 0;   // user id
    std::string comp;
};

// Scales one stress value of the reference (state >= 2) whose 8 bytes occur exactly once in the
// family's files, so that the damage is that value and nothing else.
Damage damage_one_stress(const fs::path& ref) {
    postimpact::Database db((ref / "d3plot").string());
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(ref))
        if (e.path().filename().string().rfind("d3plot", 0) == 0) files.push_back(e.path());
    const char* comps[6] = {"sxx", "syy", "szz", "sxy", "syz", "szx"};
    for (int i = 2; i < db.num_states(); ++i) {  // 0-based: the third state on
        const auto& st = db.state(i);
        for (std::size_t k = 0; k < st.stress.size(); ++k) {
            const double v = st.stress[k];
            if (std::fabs(v) < 1e6) continue;
            char pat[8];
            std::memcpy(pat, &v, 8);
            int hits = 0;
            fs::path where;
            std::size_t at = 0;
            for (const auto& f : files) {
                const std::string bytes = slurp(f);
                for (std::size_t p = bytes.find(std::string(pat, 8)); p != std::string::npos;
                     p = bytes.find(std::string(pat, 8), p + 1))
                    ++hits, where = f, at = p;
            }
            if (hits != 1) continue;
            std::string bytes = slurp(where);
            const double bad = v * (1.0 + 1e-3);
            std::memcpy(&bytes[at], &bad, 8);
            std::ofstream(where, std::ios::binary | std::ios::trunc) << bytes;
            return Damage{i + 1, db.element_id(static_cast<int>(k / 6)), comps[k % 6]};
        }
    }
    return {};
}

}  // namespace

TEST(Suite, DamagedReferenceFailsExactlyThatDeck) {
    const fs::path dir = fs::path(IMPACT3D_BINARY_DIR) / ("test_suite_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const fs::path suite = dir / "suite";
    fs::create_directories(suite / "decks");
    const fs::path reg = fs::path(IMPACT3D_SOURCE_DIR) / "tests/regression";
    const std::vector<std::string> names = {"column_rate_failure", "column_uniaxial_strain", "one_hex"};
    for (const auto& n : names) fs::copy_file(reg / "decks" / (n + ".dyn"), suite / "decks" / (n + ".dyn"));
    fs::copy_file(reg / "tolerances.txt", suite / "tolerances.txt");
    const std::string base = "'" + kPostimpact + "' suite '" + suite.string() + "' --impact3d '" + kImpact3d + "' ";

    // the decks, and references stored from a first run
    ASSERT_EQ(run(base + "--list > '" + (dir / "list.txt").string() + "'"), 0);
    EXPECT_EQ(slurp(dir / "list.txt"), "column_rate_failure\ncolumn_uniaxial_strain\none_hex\n");
    ASSERT_EQ(run(base + "--update --no-pictures -j 2 -o '" + (dir / "update").string() + "' > /dev/null"), 0);
    for (const auto& n : names) ASSERT_TRUE(fs::exists(suite / "reference" / n / "d3plot")) << n;

    // unchanged: every deck passes
    ASSERT_EQ(run(base + "--no-pictures -j 2 -o '" + (dir / "same").string() + "' > '" + (dir / "same.log").string() + "'"), 0)
        << slurp(dir / "same.log");
    EXPECT_NE(slurp(dir / "same.log").find("3 passed, 0 failed, 0 error(s)"), std::string::npos) << slurp(dir / "same.log");

    // one damaged value in one reference
    const Damage dmg = damage_one_stress(suite / "reference" / "column_uniaxial_strain");
    ASSERT_GT(dmg.state, 0) << "no unique stress value to damage";
    const fs::path out = dir / "out";
    const std::string log = (dir / "run.log").string();
    EXPECT_EQ(run(base + "-j 2 -o '" + out.string() + "' > '" + log + "'"), 1) << slurp(log);
    const std::string where = "stress at state " + std::to_string(dmg.state);
    const std::string what = "elem " + std::to_string(dmg.elem) + " " + dmg.comp;
    const std::string text = slurp(log);
    EXPECT_NE(text.find("2 passed, 1 failed, 0 error(s)"), std::string::npos) << text;
    EXPECT_NE(text.find("column_uniaxial_strain: fail: worst: " + where), std::string::npos) << text;
    EXPECT_NE(text.find(what + ": reference "), std::string::npos) << text;
    EXPECT_NE(text.find("values outside tolerance: 1 stress"), std::string::npos) << text;

    // junit.xml: well-formed, 3 test cases, exactly one failure, on the damaged deck, naming it
    const std::string py =
        "import sys, xml.etree.ElementTree as ET\n"
        "r = ET.parse(sys.argv[1]).getroot()\n"
        "cases = r.findall('./testsuite/testcase')\n"
        "print(r.get('tests'), r.get('failures'), r.get('errors'), len(cases))\n"
        "for c in cases:\n"
        "    f = c.find('failure')\n"
        "    print(c.get('name'), 'FAILED' if f is not None else 'ok', f.get('message') if f is not None else '')\n";
    std::ofstream(dir / "check.py") << py;
    ASSERT_EQ(run("python3 '" + (dir / "check.py").string() + "' '" + (out / "junit.xml").string() + "' > '" +
                  (dir / "junit.txt").string() + "'"),
              0)
        << slurp(out / "junit.xml");
    const std::string junit = slurp(dir / "junit.txt");
    EXPECT_EQ(junit.substr(0, junit.find('\n')), "3 1 0 3") << junit;
    EXPECT_NE(junit.find("column_rate_failure ok"), std::string::npos) << junit;
    EXPECT_NE(junit.find("one_hex ok"), std::string::npos) << junit;
    EXPECT_NE(junit.find("column_uniaxial_strain FAILED worst: " + where), std::string::npos) << junit;
    EXPECT_NE(junit.find(what), std::string::npos) << junit;

    // report.html: every deck, the failed one marked, pictures side by side that exist
    const std::string html = slurp(out / "report.html");
    for (const auto& n : names) {
        EXPECT_NE(html.find("<section class=\"" + std::string(n == "column_uniaxial_strain" ? "fail" : "pass") +
                            "\" id=\"" + n + "\">"),
                  std::string::npos)
            << n;
        for (const char* pic : {"ref.png", "new.png", "energies.png"}) {
            EXPECT_NE(html.find("<img src=\"" + n + "/" + pic + "\""), std::string::npos) << n << " " << pic;
            EXPECT_GT(fs::exists(out / n / pic) ? fs::file_size(out / n / pic) : 0, 1000u) << n << " " << pic;
        }
    }
    // the failed deck: the damaged component drawn, and its history at the element overlaid
    EXPECT_TRUE(fs::exists(out / "column_uniaxial_strain" / "worst.png"));
    EXPECT_NE(html.find("element " + std::to_string(dmg.elem) + " " + dmg.comp + ": reference and new run"),
              std::string::npos);

    // the worst location marked: the HTML names the element and quantity, and both pictures ring
    // it (magenta pixels centred on the spot recorded in result.txt; none on a passing deck's)
    EXPECT_NE(html.find("Marked on the pictures (magenta ring): " + what + " (" + where + ":"), std::string::npos) << html;
    const std::string result = slurp(out / "column_uniaxial_strain" / "result.txt");
    auto magenta = [](postimpact::Rgb p) { return p.r >= 200 && p.g <= 80 && p.b >= 200; };
    auto count_magenta = [&](const postimpact::Image& img, double cx, double cy, double radius, double& mx, double& my) {
        int n = 0;
        mx = my = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x)
                if (std::hypot(x - cx, y - cy) < radius && magenta(img.get(x, y))) mx += x, my += y, ++n;
        if (n) mx /= n, my /= n;
        return n;
    };
    for (const char* pic : {"ref.png", "new.png"}) {
        const auto at = result.find(std::string("\nmark_") + pic + " ");
        ASSERT_NE(at, std::string::npos) << pic << "\n" << result;
        double sx = 0, sy = 0;
        std::istringstream(result.substr(at + 7 + std::strlen(pic))) >> sx >> sy;
        const postimpact::Image img = postimpact::read_png((out / "column_uniaxial_strain" / pic).string());
        ASSERT_TRUE(img.inside(static_cast<int>(sx), static_cast<int>(sy))) << pic << " " << sx << " " << sy;
        double mx = 0, my = 0;
        EXPECT_GT(count_magenta(img, sx, sy, 32, mx, my), 60) << pic;
        EXPECT_NEAR(mx, sx, 1.5) << pic;
        EXPECT_NEAR(my, sy, 1.5) << pic;
        double ax = 0, ay = 0;  // nothing magenta away from the ring
        EXPECT_EQ(count_magenta(img, 0, 0, 1e9, ax, ay), count_magenta(img, sx, sy, 32, mx, my)) << pic;
    }
    {
        double ax = 0, ay = 0;
        EXPECT_EQ(count_magenta(postimpact::read_png((out / "one_hex" / "ref.png").string()), 0, 0, 1e9, ax, ay), 0);
    }

    // the per-deck job mode (a Slurm array: --job 1..3) and the gather step agree
    const fs::path jobs = dir / "jobs";
    for (int k = 1; k <= 3; ++k)
        EXPECT_EQ(run(base + "--no-pictures --job " + std::to_string(k) + " -o '" + jobs.string() + "' > /dev/null"),
                  names[static_cast<std::size_t>(k - 1)] == "column_uniaxial_strain" ? 1 : 0)
            << k;
    EXPECT_EQ(run(base + "--gather -o '" + jobs.string() + "' > '" + (dir / "gather.log").string() + "'"), 1);
    EXPECT_NE(slurp(dir / "gather.log").find("2 passed, 1 failed, 0 error(s)"), std::string::npos)
        << slurp(dir / "gather.log");
    // a deck whose job never ran is an error, not a pass
    fs::remove(jobs / "one_hex" / "result.txt");
    EXPECT_EQ(run(base + "--gather -o '" + jobs.string() + "' > '" + (dir / "gather.log").string() + "'"), 1);
    EXPECT_NE(slurp(dir / "gather.log").find("1 passed, 1 failed, 1 error(s)"), std::string::npos)
        << slurp(dir / "gather.log");
    fs::remove_all(dir);
}

TEST(Suite, XmlEscape) {
    EXPECT_EQ(postimpact::xml_escape("a<b & \"c\" 'd'>\x01"), "a&lt;b &amp; &quot;c&quot; &#39;d&#39;&gt;?");
}

// Per-deck options and summary decks (docs/regression-suites.md, "Regression suites for users"): a deck with
// extra impact3d words (ncpu=2 against a reference run on one thread: the same bits, so it
// passes), a deck kept by its summary through options ("reference summary"), two big decks of
// summary_decks.txt outside the suite folder (tests/regression's layout), one of them with a
// damaged summary value, the other killed by its timeout and reported as such in junit.xml
// and report.html; a bad options file is refused naming file, line and option.
TEST(Suite, DeckOptionsTimeoutAndSummaryDecks) {
    const fs::path dir = fs::path(IMPACT3D_BINARY_DIR) / ("test_suite_opts_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const fs::path suite = dir / "suite";
    fs::create_directories(suite / "decks");
    fs::create_directories(suite / "options");
    fs::create_directories(dir / "big");
    const fs::path reg = fs::path(IMPACT3D_SOURCE_DIR) / "tests/regression";
    for (const char* n : {"one_hex", "column_uniaxial_strain"})
        fs::copy_file(reg / "decks" / (std::string(n) + ".dyn"), suite / "decks" / (std::string(n) + ".dyn"));
    for (const char* n : {"taylor_bar", "crossed_cylinders"})
        fs::copy_file(fs::path(IMPACT3D_SOURCE_DIR) / "decks" / (std::string(n) + ".dyn"), dir / "big" / (std::string(n) + ".dyn"));
    fs::copy_file(reg / "tolerances.txt", suite / "tolerances.txt");
    std::ofstream(suite / "summary_decks.txt") << "# big decks, from this folder\n../big/taylor_bar.dyn\n\n"
                                               << (dir / "big" / "crossed_cylinders.dyn").string() << "\n";
    std::ofstream(suite / "options" / "column_uniaxial_strain.txt") << "reference summary   # keep a summary only\n";
    const std::string base = "'" + kPostimpact + "' suite '" + suite.string() + "' --impact3d '" + kImpact3d + "' ";
    ASSERT_EQ(run(base + "--list > '" + (dir / "list.txt").string() + "'"), 0);
    EXPECT_EQ(slurp(dir / "list.txt"), "column_uniaxial_strain\ncrossed_cylinders\none_hex\ntaylor_bar\n");

    // --update: plot database for one_hex, summaries for the other three (and nothing else)
    const fs::path upd = dir / "update";
    ASSERT_EQ(run(base + "--update --no-pictures -j 2 -o '" + upd.string() + "' > '" + (dir / "update.log").string() + "'"), 0)
        << slurp(dir / "update.log");
    EXPECT_TRUE(fs::exists(suite / "reference" / "one_hex" / "d3plot"));
    EXPECT_FALSE(fs::exists(suite / "summaries" / "one_hex.txt"));
    for (const char* n : {"column_uniaxial_strain", "crossed_cylinders", "taylor_bar"}) {
        EXPECT_FALSE(fs::exists(suite / "reference" / n)) << n;
        // the stored summary is `postimpact summary` of that run, byte for byte
        const fs::path r = upd / n / "run";
        ASSERT_EQ(run("'" + kPostimpact + "' summary '" + (r / "d3plot").string() + "' --printed '" + (r / "d3hsp").string() +
                      "' -o '" + (dir / (std::string(n) + ".txt")).string() + "'"),
                  0);
        EXPECT_EQ(slurp(suite / "summaries" / (std::string(n) + ".txt")), slurp(dir / (std::string(n) + ".txt"))) << n;
    }
    EXPECT_NE(slurp(suite / "summaries" / "taylor_bar.txt").find("\nsolids 972\n"), std::string::npos);

    // options: one_hex on two threads, taylor_bar limited to 0.1 s (its run takes about 1 s and
    // more); one crossed_cylinders summary value damaged by 1% (its tolerance: 0.2%)
    std::ofstream(suite / "options" / "one_hex.txt") << "# threads: results are the same bits\nargs ncpu=2\n";
    std::ofstream(suite / "options" / "taylor_bar.txt") << "timeout 0.1\n";
    {
        std::string s = slurp(suite / "summaries" / "crossed_cylinders.txt");
        const auto at = s.find("\nmax_eps ");
        ASSERT_NE(at, std::string::npos);
        const auto end = s.find('\n', at + 1);
        const double v = std::stod(s.substr(at + 9, end - at - 9));
        char b[64];
        std::snprintf(b, sizeof b, "%.17g", v * 1.01);
        s.replace(at + 9, end - at - 9, b);
        std::ofstream(suite / "summaries" / "crossed_cylinders.txt", std::ios::trunc) << s;
    }
    const fs::path out = dir / "out";
    const std::string log = (dir / "run.log").string();
    EXPECT_EQ(run(base + "-j 2 -o '" + out.string() + "' > '" + log + "'"), 1) << slurp(log);
    const std::string text = slurp(log);
    EXPECT_NE(text.find("2 passed, 2 failed, 0 error(s)"), std::string::npos) << text;
    EXPECT_NE(text.find("taylor_bar: fail: timeout after 0.1 s (impact3d killed)"), std::string::npos) << text;
    EXPECT_NE(text.find("crossed_cylinders: fail: summary max_eps"), std::string::npos) << text;
    // the extra word reached impact3d, and the run passed against its one-thread reference
    EXPECT_NE(slurp(out / "one_hex" / "run" / "d3hsp").find("threads: 2"), std::string::npos);
    EXPECT_NE(("\n" + slurp(out / "one_hex" / "result.txt")).find("\nargs ncpu=2\n"), std::string::npos);
    EXPECT_NE(slurp(out / "column_uniaxial_strain" / "result.txt").find("\nmode summary\n"), std::string::npos);
    // killed on time: the run stopped well before its normal end
    {
        const std::string r = slurp(out / "taylor_bar" / "result.txt");
        const auto at = r.find("\nrun_seconds ");
        ASSERT_NE(at, std::string::npos) << r;
        const double t = std::stod(r.substr(at + 13));
        EXPECT_GE(t, 0.1);
        EXPECT_LT(t, 0.6);
        EXPECT_EQ(slurp(out / "taylor_bar" / "run" / "d3hsp").find("N o r m a l"), std::string::npos);
    }
    // junit.xml: the timeout is a failure of type timeout with its reason
    const std::string py =
        "import sys, xml.etree.ElementTree as ET\n"
        "r = ET.parse(sys.argv[1]).getroot()\n"
        "print(r.get('tests'), r.get('failures'), r.get('errors'))\n"
        "for c in r.findall('./testsuite/testcase'):\n"
        "    f = c.find('failure')\n"
        "    print(c.get('name'), 'ok' if f is None else f.get('type') + ': ' + f.get('message'))\n";
    std::ofstream(dir / "check.py") << py;
    ASSERT_EQ(run("python3 '" + (dir / "check.py").string() + "' '" + (out / "junit.xml").string() + "' > '" +
                  (dir / "junit.txt").string() + "'"),
              0);
    const std::string junit = slurp(dir / "junit.txt");
    EXPECT_EQ(junit.substr(0, junit.find('\n')), "4 2 0") << junit;
    EXPECT_NE(junit.find("taylor_bar timeout: timeout after 0.1 s (impact3d killed)"), std::string::npos) << junit;
    EXPECT_NE(junit.find("crossed_cylinders outside tolerance: summary max_eps"), std::string::npos) << junit;
    EXPECT_NE(junit.find("one_hex ok"), std::string::npos) << junit;
    EXPECT_NE(junit.find("column_uniaxial_strain ok"), std::string::npos) << junit;
    const std::string html = slurp(out / "report.html");
    EXPECT_NE(html.find("<section class=\"fail\" id=\"taylor_bar\">"), std::string::npos);
    EXPECT_NE(html.find("<td>timeout after 0.1 s (impact3d killed)</td>"), std::string::npos) << html;

    // a bad options file: the suite is refused (exit 2) naming file, line and option
    std::ofstream(suite / "options" / "one_hex.txt", std::ios::trunc) << "args ncpu=2\nthreads 2\n";
    EXPECT_EQ(run(base + "--list > /dev/null 2> '" + (dir / "err.txt").string() + "'"), 2);
    EXPECT_NE(slurp(dir / "err.txt").find((suite / "options" / "one_hex.txt").string() + ":2: unknown option 'threads'"),
              std::string::npos)
        << slurp(dir / "err.txt");
    std::ofstream(suite / "options" / "one_hex.txt", std::ios::trunc) << "timeout soon\n";
    EXPECT_EQ(run(base + "--list > /dev/null 2> '" + (dir / "err.txt").string() + "'"), 2);
    EXPECT_NE(slurp(dir / "err.txt").find("one_hex.txt:1: timeout: expected seconds"), std::string::npos) << slurp(dir / "err.txt");
    fs::remove_all(dir);
}
