// postimpact suite (README.md, "Regression suites for users"): a suite of three of the project's
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
