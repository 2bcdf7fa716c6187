// postimpact: offscreen post-processor of IMPACT-3D plot databases (d3plot family).
// Usage: README.md, section POST-IMPACT, and `postimpact --help`.
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "postimpact/command_file.h"
#include "postimpact/compare.h"
#include "postimpact/quantities.h"
#include "postimpact/suite.h"
#include "postimpact/summary.h"
#include "version.h"

namespace {

const char* kUsage =
    "usage: postimpact [DATABASE] [OPTIONS]        pictures and time histories\n"
    "       postimpact compare A B [--tol FILE] [--report N] [--by-time]\n"
    "       postimpact summary DATABASE [--printed FILE] [-o FILE]\n"
    "       postimpact compare-summary A.txt B.txt [--tol FILE]\n"
    "       postimpact suite SUITE [-o OUT] [-j N] [--deck NAME].. [--impact3d PATH]\n"
    "                        [--no-pictures] [--update | --list | --job NAME|K | --gather]\n"
    "\n"
    "DATABASE is the root file of a d3plot family (d3plot) or the A file of a Mili database\n"
    "(DYNA3D's NAME.pltA, or NAME.plt), told apart by content.  With no -c/-e/-o/--sequence/\n"
    "--frames/--history option the default set is written: eps_first.png, eps_middle.png,\n"
    "eps_last.png (effective plastic strain), eps_sequence.png, energies.png + energies.csv,\n"
    "and forces.png + forces.csv when there are rigid walls or sliding interfaces.\n"
    "Options apply in order, as the commands of a command file (README.md, POST-IMPACT):\n"
    "  -c, --commands FILE    run a command file\n"
    "  -e, --exec 'COMMAND'   run one command (e.g. -e 'history v.png node 1333 vz')\n"
    "  -o FILE                picture of the current state\n"
    "  --sequence FILE        the states side by side (--states first selects them)\n"
    "  --states S,S,..        states for --sequence/--frames (numbers from 1, first,\n"
    "                         middle, last, t=TIME, A:B, all, every K, count N)\n"
    "  --frames PREFIX        numbered frames PREFIX0001.png ... for an animation\n"
    "  --history FILE         energies (PNG + CSV)\n"
    "  -d, --outdir DIR       directory of the files written\n"
    "  --state S              current state (default: last)\n"
    "  --fringe Q             none, material, or a quantity (default eps); Q@top,\n"
    "                         Q@bottom, Q@mid, Q@ipK: shell surface / integration point\n"
    "  --view V               iso (default), front, back, left, right, top, bottom,\n"
    "                         +x -x +y -y +z -z, or AZ,EL in degrees\n"
    "  --up x|y|z             axis shown upward (default z)\n"
    "  --mirror M             reflect across coordinate planes: x, y, z, xy, ... none\n"
    "  --range auto|MIN,MAX   fringe range     --bands N     number of colour bands\n"
    "  --size WxH             picture size (1600x1200)    --plotsize WxH (1200x800)\n"
    "  --title TEXT           --units si|none   --scale F (displacement magnification)\n"
    "  --no-edges  --no-average  --no-legend  --no-triad   --font PATH.ttf\n"
    "  --timing               print the time each file took\n"
    "  -h, --help   --version\n"
    "compare: --tol FILE (lines 'FIELD REL ABS', FIELD time coords vel acc stress eps\n"
    "energy force mass default; without it values must be equal), --report N (10),\n"
    "--by-time: states matched by time, B interpolated between its states (on by itself\n"
    "when A or B is a Mili database).  Nodes and elements are matched by user label.\n"
    "summary: 'key value' lines (final length, radius, extents, max plastic strain,\n"
    "energies, cycle count read from --printed FILE, default d3hsp beside DATABASE).\n"
    "compare-summary: two summaries with the tolerances of --tol FILE (lines summary.KEY,\n"
    "summary.FIELD, FIELD, default, most specific first; field cycles too).\n"
    "suite: runs every deck of SUITE/decks and SUITE/summary_decks.txt (N at a time, default\n"
    "the cores; per-deck timeout and impact3d words from SUITE/options.txt and\n"
    "SUITE/options/NAME.txt), compares each with\n"
    "its reference (SUITE/reference/NAME/d3plot or SUITE/summaries/NAME.txt) with the\n"
    "tolerances of SUITE/tolerances.txt (+ SUITE/tolerances/NAME.txt), writes OUT/junit.xml and\n"
    "OUT/report.html (OUT default suite_out); --job NAME|K runs one deck (K from 1, e.g.\n"
    "$SLURM_ARRAY_TASK_ID) and --gather writes the reports of jobs run so; --list prints the\n"
    "decks; --update stores each run as its deck's reference.  Exit 1: a deck failed.\n"
    "Exit status: 0 done (compare, compare-summary: same within tolerance), 1 different,\n"
    "2 usage, input or rendering error.\n";

// --tol FILE (--tolerances, -t) at argument i.
bool is_tol_option(const std::string& a, int i, int argc) {
    return (a == "--tol" || a == "--tolerances" || a == "-t") && i + 1 < argc;
}

// A word of command cmd that is no option it knows: an operand (into pos), or an unknown option
// (false, reported with the usage).
bool operand(const std::string& a, const char* cmd, std::vector<std::string>& pos) {
    if (!a.empty() && a[0] == '-') {
        std::cerr << "postimpact " << cmd << ": unknown option " << a << "\n" << kUsage;
        return false;
    }
    pos.push_back(a);
    return true;
}

// The two operands of cmd (what: what they are), or false (reported with the usage).
bool two_operands(const std::vector<std::string>& pos, const char* cmd, const char* what) {
    if (pos.size() == 2) return true;
    std::cerr << "postimpact " << cmd << ": expected two " << what << "\n" << kUsage;
    return false;
}

int run_compare(int argc, char** argv) {
    std::vector<std::string> pos;
    postimpact::CompareOptions opt;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (is_tol_option(a, i, argc)) {
            opt.tol = postimpact::Tolerances::read(argv[++i]);
        } else if (a == "--report" && i + 1 < argc) {
            const char* v = argv[++i];
            char* end = nullptr;
            const long n = std::strtol(v, &end, 10);
            if (*v == '\0' || *end != '\0' || n < 0 || n > 1000000) {
                std::cerr << "postimpact compare: --report: expected a count 0..1000000, found '" << v << "'\n";
                return 2;
            }
            opt.report = static_cast<int>(n);
        } else if (a == "--by-time") {
            opt.by_time = true;
        } else if (!operand(a, "compare", pos)) {
            return 2;
        }
    }
    if (!two_operands(pos, "compare", "databases")) return 2;
    return postimpact::compare_databases(pos[0], pos[1], opt, std::cout);
}

int run_summary(int argc, char** argv) {
    std::string db, printed, output;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--printed" && i + 1 < argc) printed = argv[++i];
        else if (a == "-o" && i + 1 < argc) output = argv[++i];
        else if ((!a.empty() && a[0] == '-') || !db.empty()) {
            std::cerr << "postimpact summary: unexpected argument " << a << "\n" << kUsage;
            return 2;
        } else db = a;
    }
    if (db.empty()) {
        std::cerr << "postimpact summary: no database given\n" << kUsage;
        return 2;
    }
    const postimpact::Summary s = postimpact::summarize(db, printed);
    if (output.empty()) {
        postimpact::write_summary(s, std::cout);
        return 0;
    }
    std::ofstream f(output);
    postimpact::write_summary(s, f);
    f.close();
    if (!f) {
        std::cerr << "postimpact summary: cannot write " << output << "\n";
        return 2;
    }
    return 0;
}

int run_compare_summary(int argc, char** argv) {
    std::vector<std::string> pos;
    postimpact::Tolerances tol;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (is_tol_option(a, i, argc)) {
            tol = postimpact::Tolerances::read(argv[++i]);
        } else if (!operand(a, "compare-summary", pos)) {
            return 2;
        }
    }
    if (!two_operands(pos, "compare-summary", "summary files")) return 2;
    const auto a = postimpact::read_summary(pos[0]);
    const auto b = postimpact::read_summary(pos[1]);
    return postimpact::compare_summaries(a, b, tol, std::cout, pos[0], pos[1]);
}

int run_suite_command(int argc, char** argv) {
    postimpact::SuiteOptions opt;
    std::string job;
    bool list = false, gather = false;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        auto value = [&]() -> std::string {
            if (i + 1 >= argc) throw std::runtime_error("option " + a + " needs a value");
            return argv[++i];
        };
        if (a == "-o" || a == "--outdir") opt.outdir = value();
        else if (a == "-j" || a == "--jobs") {
            const std::string v = value();
            char* end = nullptr;
            const long n = std::strtol(v.c_str(), &end, 10);
            if (v.empty() || *end != '\0' || n < 1 || n > 4096) throw std::runtime_error("-j: expected a count 1..4096, found '" + v + "'");
            opt.jobs = static_cast<int>(n);
        } else if (a == "--deck") opt.decks.push_back(value());
        else if (a == "--impact3d") opt.impact3d = value();
        else if (a == "--job") job = value();
        else if (a == "--no-pictures") opt.pictures = false;
        else if (a == "--update") opt.update = true;
        else if (a == "--list") list = true;
        else if (a == "--gather") gather = true;
        else if (!a.empty() && a[0] == '-') {
            std::cerr << "postimpact suite: unknown option " << a << "\n" << kUsage;
            return 2;
        } else if (opt.suite.empty()) opt.suite = a;
        else {
            std::cerr << "postimpact suite: unexpected argument " << a << "\n" << kUsage;
            return 2;
        }
    }
    if (opt.suite.empty()) {
        std::cerr << "postimpact suite: no suite folder given\n" << kUsage;
        return 2;
    }
    if (static_cast<int>(list) + static_cast<int>(gather) + static_cast<int>(!job.empty()) > 1) {
        std::cerr << "postimpact suite: --list, --job and --gather exclude one another\n";
        return 2;
    }
    const auto decks = postimpact::list_suite(opt.suite);
    if (list) {
        for (const auto& d : decks) std::cout << d.name << "\n";
        return 0;
    }
    if (!job.empty()) {
        const postimpact::SuiteDeck* d = nullptr;
        char* end = nullptr;
        const long k = std::strtol(job.c_str(), &end, 10);
        if (*end == '\0' && k >= 1 && k <= static_cast<long>(decks.size())) d = &decks[static_cast<std::size_t>(k - 1)];
        for (const auto& x : decks)
            if (x.name == job) d = &x;
        if (!d) throw std::runtime_error("--job " + job + ": no such deck (a name, or a number 1.." + std::to_string(decks.size()) + ")");
        return postimpact::run_suite_deck(opt, *d, std::cout);
    }
    if (gather) return postimpact::gather_suite(opt, std::cout);
    std::error_code ec;
    opt.self = std::filesystem::read_symlink("/proc/self/exe", ec).string();
    if (ec || opt.self.empty()) opt.self = argv[0];
    return postimpact::run_suite(opt, std::cout);
}

std::vector<std::string> split_commas(const std::string& s) {
    std::vector<std::string> out;
    std::string cur;
    for (char c : s) {
        if (c == ',') { out.push_back(cur); cur.clear(); }
        else cur += c;
    }
    out.push_back(cur);
    return out;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::strcmp(argv[1], "compare") == 0) {
        try {
            return run_compare(argc, argv);
        } catch (const std::exception& e) {
            std::cerr << "postimpact compare: " << e.what() << "\n";
            return 2;
        }
    }
    if (argc >= 2 && (std::strcmp(argv[1], "summary") == 0 || std::strcmp(argv[1], "compare-summary") == 0)) {
        const bool summary = std::strcmp(argv[1], "summary") == 0;
        try {
            return summary ? run_summary(argc, argv) : run_compare_summary(argc, argv);
        } catch (const std::exception& e) {
            std::cerr << "postimpact " << argv[1] << ": " << e.what() << "\n";
            return 2;
        }
    }
    if (argc >= 2 && std::strcmp(argv[1], "suite") == 0) {
        try {
            return run_suite_command(argc, argv);
        } catch (const std::exception& e) {
            std::cerr << "postimpact suite: " << e.what() << "\n";
            return 2;
        }
    }
    postimpact::Session s(std::cout);
    bool explicit_actions = false;
    std::vector<std::string> states;  // for --sequence / --frames
    try {
        for (int i = 1; i < argc; ++i) {
            const std::string a = argv[i];
            auto value = [&]() -> std::string {
                if (i + 1 >= argc) throw postimpact::CommandError("option " + a + " needs a value");
                return argv[++i];
            };
            auto cmd = [&](std::vector<std::string> w) { s.execute(w, "option " + a); };
            if (a == "-h" || a == "--help") { std::cout << kUsage; return 0; }
            if (a == "--version") { std::cout << "postimpact (IMPACT-3D " << IMPACT3D_VERSION << ")\n"; return 0; }
            if (a == "-c" || a == "--commands") { s.run_file(value()); explicit_actions = true; }
            else if (a == "-e" || a == "--exec") { s.execute_line(value(), "option -e"); explicit_actions = true; }
            else if (a == "-o") { cmd({"picture", value()}); explicit_actions = true; }
            else if (a == "--states") states = split_commas(value());
            else if (a == "--sequence" || a == "--frames") {
                std::vector<std::string> w{a.substr(2), value()};
                w.insert(w.end(), states.begin(), states.end());
                if (a == "--frames" && states.empty()) w.push_back("all");
                cmd(w);
                explicit_actions = true;
            } else if (a == "--history") { cmd({"history", value(), "energy"}); explicit_actions = true; }
            else if (a == "-d" || a == "--outdir") cmd({"outdir", value()});
            else if (a == "--title" || a == "--font") cmd({a.substr(2), value()});
            else if (a == "--timing") cmd({"timing", "on"});
            else if (a == "--no-edges" || a == "--no-average" || a == "--no-legend" || a == "--no-triad") cmd({a.substr(5), "off"});
            else if (a == "--state" || a == "--fringe" || a == "--view" || a == "--up" || a == "--mirror" ||
                     a == "--range" || a == "--bands" || a == "--size" || a == "--plotsize" || a == "--units" ||
                     a == "--scale" || a == "--supersample") {
                std::vector<std::string> w{a.substr(2)};
                for (const auto& v : split_commas(value())) w.push_back(v);
                cmd(w);
            } else if (!a.empty() && a[0] == '-') {
                std::cerr << "postimpact: unknown option " << a << "\n" << kUsage;
                return 2;
            } else if (!s.has_database()) {
                cmd({"open", a});
            } else {
                std::cerr << "postimpact: unexpected argument " << a << "\n" << kUsage;
                return 2;
            }
        }
        if (!explicit_actions) {
            if (!s.has_database()) {
                std::cerr << "postimpact: no database given\n" << kUsage;
                return 2;
            }
            s.default_set();
        }
    } catch (const std::exception& e) {
        std::cerr << "postimpact: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
