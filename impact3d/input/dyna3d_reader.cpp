// DYNA3D fixed-format deck reader.  The layout is documented card by card in
// docs/deck-format.md; every field read here names its card, field and columns in messages.

#include <algorithm>
#include <optional>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "impact3d/input/deck_reader.h"
#include "impact3d/input/element_shapes.h"
#include "impact3d/init/shell_init.h"
#include "impact3d/material/eos.h"
#include "impact3d/material/material_types.h"

namespace impact3d {

namespace {

struct EndOfDeck {};   // thrown when the deck ends while cards are still expected
struct TooManyErrors {};

class Dyna3dReader {
 public:
  Dyna3dReader(DeckFile& deck, Model& model, Diagnostics& diag)
      : deck_(deck), m_(model), diag_(diag) {}

  void read() {
    read_title();
    if (stop_) return;
    read_control_cards();
    if (stop_) return;
    read_materials();
    read_nodes();
    read_solids();
    read_shells();
    read_time_history_blocks();
    read_load_curves();
    read_nodal_loads();
    read_pressure_loads();
    read_prescribed_motions();
    read_stonewalls();
    read_initial_velocities();
    read_sliding_interfaces();
    read_base_accelerations();
    report_unused_curves();
    if (const DeckLine* l = deck_.peek_card()) {
      Location loc;
      loc.file = deck_.name();
      loc.line = l->number;
      loc.found = l->text;
      loc.show_found = true;
      int left = 0;
      while (deck_.next_card()) ++left;
      diag_.add(1005, loc, std::to_string(left) + " card(s) after the sliding interfaces");
    }
  }

 private:
  DeckFile& deck_;
  Model& m_;
  Diagnostics& diag_;
  bool stop_ = false;
  int idw_ = 8;  // width of id fields: 8 large, 5 small
  std::vector<int> curve_lines_;   // header line of each load curve
  std::vector<char> curve_used_;   // a load or motion refers to it
  int numels_ = 0;                 // control card 2 NUMELS: 4-node shells
  int shell_th_blocks_ = 0;        // control card 3 field 4
  std::vector<int> rot_code_line_; // per node: line of a node card with a rotational code (0: none)

  Card next(const std::string& card_name, const std::string& expected = {}) {
    if (diag_.error_count() > 500) {
      Location loc;
      loc.file = deck_.name();
      diag_.add(1013, loc);
      throw TooManyErrors{};
    }
    const DeckLine* l = deck_.next_card();
    if (!l) {
      Location loc;
      loc.file = deck_.name();
      loc.line = deck_.last_line_number();
      loc.card = card_name;
      diag_.add(1004, loc, expected.empty() ? "the deck ends before this card" : expected);
      throw EndOfDeck{};
    }
    return Card(deck_.name(), *l, card_name, diag_);
  }

  // Remaining non-comment lines, to bound counts before allocating.
  long remaining_cards() { return deck_.cards_left(); }

  // Fast paths for the bulk cards (nodes, solids): the next card is read without a Card when
  // it is plain (is_plain_fixed_card) and every field reads and passes its checks, so that no
  // message can come from it.  Anything else returns false and the card is read again, the
  // normal way, by the code that reports every problem.
  const DeckLine* plain_next_card() {
    if (diag_.error_count() > 500) return nullptr;  // next() stops the reading
    const DeckLine* l = deck_.peek_card();
    return l && is_plain_fixed_card(l->text) ? l : nullptr;
  }
  static bool fast_int(std::string_view line, int c1, int c2, int& v) {
    long long x = 0;
    const FieldStatus st = parse_fortran_int(card_columns(line, c1, c2), x);
    if (st == FieldStatus::bad) return false;
    v = st == FieldStatus::ok ? int(x) : 0;
    return true;
  }
  static bool fast_real(std::string_view line, int c1, int c2, double& v) {
    double x = 0;
    const FieldStatus st = parse_fortran_real(card_columns(line, c1, c2), x);
    if (st == FieldStatus::bad) return false;
    v = st == FieldStatus::ok ? x : 0.0;
    return true;
  }

  void read_title() {
    Card c = next("title card");
    m_.title = c.a(1, 72);
    while (!m_.title.empty() && m_.title.back() == ' ') m_.title.pop_back();
    std::string digits = c.a(73, 74);
    std::string large = c.a(76, 80);
    for (auto& ch : large) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    bool is_large = large.find("large") != std::string::npos;
    if (is_large && digits == "10") {
      c.error(1101, 73, 80, "format flag", "\"10 large\" free-format control cards are not supported; use \"88 large\"");
      stop_ = true;
      return;
    }
    if (!is_large && !c.blank(76, 80)) {
      c.error(1006, 76, 80, "format flag", "expected \"large\" or blank");
    }
    m_.large_format = is_large;
    idw_ = is_large ? 8 : 5;
    if (is_keyword_line(c.a(1, 80))) {
      c.error(1101, 1, 72, "title", "this looks like an LS-DYNA keyword deck (*KEYWORD); only the DYNA3D fixed format is read");
      stop_ = true;
    }
  }

  void require_zero(Card& c, int c1, int c2, const char* field, const char* feature) {
    long long v = c.i(c1, c2, field, 0);
    if (v != 0) c.error(1102, c1, c2, field, feature);
  }

  void read_control_cards() {
    ControlData& k = m_.control;
    {
      Card c = next("control card 2");
      if (m_.large_format) {
        k.nmmat = int(c.i(1, 5, "NMMAT"));
        k.numnp = int(c.i(6, 15, "NUMNP"));
        k.numelh = int(c.i(16, 25, "NUMELH"));
        require_zero(c, 26, 35, "NUMELB", "beam elements");
        numels_ = int(c.i(36, 45, "NUMELS"));
        require_zero(c, 46, 55, "NUMELT", "thick shell elements");
        k.interface_segments_out = int(c.i(56, 65, "interface segments"));
        k.interface_out_interval = c.e(66, 75, "interface output interval");
      } else {
        k.nmmat = int(c.i(1, 5, "NMMAT"));
        k.numnp = int(c.i(6, 10, "NUMNP"));
        k.numelh = int(c.i(11, 15, "NUMELH"));
        require_zero(c, 16, 20, "NUMELB", "beam elements");
        numels_ = int(c.i(21, 25, "NUMELS"));
        require_zero(c, 26, 30, "NUMELT", "thick shell elements");
        k.interface_segments_out = int(c.i(31, 35, "interface segments"));
        k.interface_out_interval = c.e(36, 45, "interface output interval");
      }
      if (k.nmmat < 1) c.error(1003, 1, 5, "NMMAT", "at least 1 material");
      int w = m_.large_format ? 10 : 5;
      if (k.numnp < 1) c.error(1003, 6, 5 + w, "NUMNP", "at least 1 node");
      if (k.numelh < 0 || (k.numelh == 0 && numels_ < 1))
        c.error(1003, 6 + w, 5 + 2 * w, "NUMELH", "at least 1 element (solids NUMELH or shells NUMELS)");
      const int s1 = m_.large_format ? 36 : 21, s2 = m_.large_format ? 45 : 25;
      if (numels_ < 0) c.error(1003, s1, s2, "NUMELS", "must not be negative");
      if (k.interface_out_interval < 0) {
        if (m_.large_format) c.error(1221, 66, 75, "interface output interval");
        else c.error(1221, 36, 45, "interface output interval");
      }
      // Counts cannot exceed what the file holds: bound them before anything is allocated.
      long avail = remaining_cards();
      if (k.numnp > avail) {
        c.error(1205, 6, 5 + w, "NUMNP", "the deck has only " + std::to_string(avail) + " cards left");
        k.numnp = 0;
      }
      if (k.numelh > avail) {
        c.error(1205, 6 + w, 5 + 2 * w, "NUMELH", "the deck has only " + std::to_string(avail) + " cards left");
        k.numelh = 0;
      }
      if (numels_ > avail / 2) {
        c.error(1205, s1, s2, "NUMELS", "the deck has only " + std::to_string(avail) + " cards left (two per shell)");
        numels_ = 0;
      }
      numels_ = std::max(numels_, 0);
      if (k.nmmat > avail / 8 + 1) {
        c.error(1205, 1, 5, "NMMAT", "the deck cannot hold that many 8-card material sets");
        k.nmmat = 0;
      }
      k.nmmat = std::max(k.nmmat, 0);
      k.numnp = std::max(k.numnp, 0);
      k.numelh = std::max(k.numelh, 0);
    }
    {
      Card c = next("control card 3");
      k.node_th_blocks = int(c.i(1, 5, "node time-history blocks"));
      k.solid_th_blocks = int(c.i(6, 10, "solid time-history blocks"));
      require_zero(c, 11, 15, "beam time-history blocks", "beam time histories");
      shell_th_blocks_ = int(c.i(16, 20, "shell time-history blocks"));
      require_zero(c, 21, 25, "thick shell time-history blocks", "thick shell time histories");
      k.report_interval = int(c.i(26, 30, "report interval", 100));
      if (k.report_interval == 0) k.report_interval = 100;
      k.reaction_print_flag = int(c.i(31, 35, "reaction-force print flag"));
      require_zero(c, 36, 40, "discrete-element print flag", "discrete elements");
      require_zero(c, 41, 45, "element deletion flag", "element deletion / SAND database");
      if (k.node_th_blocks < 0) c.error(1003, 1, 5, "node time-history blocks", "must not be negative");
      if (k.solid_th_blocks < 0) c.error(1003, 6, 10, "solid time-history blocks", "must not be negative");
      if (k.report_interval < 0) c.error(1003, 26, 30, "report interval", "must not be negative");
      long avail = remaining_cards();
      if (k.node_th_blocks > avail) { c.error(1205, 1, 5, "node time-history blocks"); k.node_th_blocks = 0; }
      if (k.solid_th_blocks > avail) { c.error(1205, 6, 10, "solid time-history blocks"); k.solid_th_blocks = 0; }
      if (shell_th_blocks_ < 0) { c.error(1003, 16, 20, "shell time-history blocks", "must not be negative"); shell_th_blocks_ = 0; }
      if (shell_th_blocks_ > avail) { c.error(1205, 16, 20, "shell time-history blocks"); shell_th_blocks_ = 0; }
      k.node_th_blocks = std::max(k.node_th_blocks, 0);
      k.solid_th_blocks = std::max(k.solid_th_blocks, 0);
    }
    {
      Card c = next("control card 4");
      require_zero(c, 1, 10, "sliding boundary planes", "sliding boundary planes");
      require_zero(c, 11, 15, "sliding planes with failure", "sliding planes with failure");
      require_zero(c, 16, 20, "density-versus-depth points", "density versus depth");
      require_zero(c, 21, 25, "Brode function flag", "Brode function");
      require_zero(c, 26, 30, "rigid-body merge cards", "rigid-body merging");
      require_zero(c, 36, 40, "force cross-sections", "force cross-sections");
      c.e(41, 50, "cross-section output interval");
    }
    {
      Card c = next("control card 5");
      k.numlc = int(c.i(1, 5, "NUMLC"));
      k.num_nodal_load_cards = int(c.i(6, 10, "concentrated nodal loads"));
      k.num_pressure_cards = int(c.i(11, 15, "pressure-loaded sides"));
      k.num_motion_cards = int(c.i(16, 20, "velocity/acceleration boundary cards"));
      k.num_walls = int(c.i(21, 25, "stonewalls"));
      require_zero(c, 26, 30, "nodal constraint cards", "nodal constraints");
      k.num_init_velocity_cards = int(c.i(31, 35, "initial-velocity cards"));
      k.num_interfaces = int(c.i(36, 40, "sliding interfaces"));
      const char* names[] = {"base acceleration x", "base acceleration y", "base acceleration z",
                             "angular velocity x", "angular velocity y", "angular velocity z",
                             "momentum deposit", "detonation points"};
      const char* features[] = {"base accelerations", "base accelerations", "base accelerations",
                                "angular velocities", "angular velocities", "angular velocities",
                                "momentum deposition", "detonation (high explosives)"};
      for (int f = 0; f < 3; ++f) {
        const long long flag = c.i(41 + 5 * f, 45 + 5 * f, names[f]);
        if (flag != 0 && flag != 1) c.error(1006, 41 + 5 * f, 45 + 5 * f, names[f], "0 none, 1 one base-acceleration card");
        k.base_acceleration[std::size_t(f)] = flag == 1 ? 1 : 0;
      }
      for (int f = 3; f < 8; ++f) require_zero(c, 41 + 5 * f, 45 + 5 * f, names[f], features[f]);
      long avail = remaining_cards();
      auto bound = [&](int& v, int c1, const char* field) {
        if (v < 0) { c.error(1003, c1, c1 + 4, field, "must not be negative"); v = 0; }
        if (v > avail) { c.error(1205, c1, c1 + 4, field, "the deck has only " + std::to_string(avail) + " cards left"); v = 0; }
      };
      bound(k.numlc, 1, "NUMLC");
      bound(k.num_nodal_load_cards, 6, "concentrated nodal loads");
      bound(k.num_pressure_cards, 11, "pressure-loaded sides");
      bound(k.num_motion_cards, 16, "velocity/acceleration boundary cards");
      bound(k.num_walls, 21, "stonewalls");
      bound(k.num_init_velocity_cards, 31, "initial-velocity cards");
      bound(k.num_interfaces, 36, "sliding interfaces");
    }
    {
      Card c = next("control card 6");
      k.end_time = c.e(1, 10, "termination time");
      if (!(k.end_time > 0)) c.error(1214, 1, 10, "termination time");
      k.th_interval = c.e(11, 20, "time-history interval");
      k.plot_interval = c.e(21, 30, "plot interval");
      if (k.th_interval < 0) c.error(1221, 11, 20, "time-history interval");
      if (k.plot_interval < 0) c.error(1221, 21, 30, "plot interval");
      if (k.th_interval == 0) k.th_interval = k.end_time / 1000;
      if (k.plot_interval == 0) k.plot_interval = k.end_time / 20;
      k.restart_dump_cycles = int(c.i(31, 35, "restart dump cycles"));
      k.running_restart_cycles = int(c.i(36, 40, "running restart cycles"));
      if (k.restart_dump_cycles < 0) c.error(1003, 31, 35, "restart dump cycles", "must not be negative");
      if (k.running_restart_cycles < 0) c.error(1003, 36, 40, "running restart cycles", "must not be negative");
      k.initial_dt = c.e(41, 50, "initial time step");
      if (k.initial_dt < 0) c.error(1003, 41, 50, "initial time step", "must not be negative");
      k.penalty_scale = c.e(51, 60, "penalty scale factor", 0.10);
      if (k.penalty_scale == 0) k.penalty_scale = 0.10;
      if (k.penalty_scale < 0) c.error(1003, 51, 60, "penalty scale factor", "must be positive");
      require_zero(c, 61, 65, "thermal option", "thermal effects");
      k.viscosity_flag = int(c.i(66, 70, "default viscosity flag"));
      k.tssf = c.e(71, 80, "time-step scale factor", 0.90);
      if (k.tssf == 0) k.tssf = 0.90;
      if (!(k.tssf > 0 && k.tssf <= 1)) c.error(1215, 71, 80, "time-step scale factor");
    }
    {
      Card c = next("control card 7");
      const char* names[] = {"joints", "rigid bodies with extra nodes", "shell-solid interfaces",
                             "tie-breaking shell slidelines", "tied node sets with failure",
                             "time-step load curve", "springs/dampers/masses",
                             "rigid bodies with inertia", "shell strain dump",
                             "deformable-rigid switching", "mass damping sets",
                             "Hughes-Liu update", "shell thickness change", "shell formulation",
                             "non-reflecting boundary segments"};
      for (int f = 0; f < 15; ++f) require_zero(c, 1 + 5 * f, 5 + 5 * f, names[f], names[f]);
    }
    {
      Card c = next("control card 8");
      require_zero(c, 1, 5, "point-constraint nodes", "point constraints");
      require_zero(c, 6, 10, "constraint coordinate systems", "constraint coordinate systems");
      k.min_step_factor = c.e(11, 20, "minimum step factor");
      if (k.min_step_factor < 0 || k.min_step_factor >= 1)
        c.error(1003, 11, 20, "minimum step factor", "must be in [0, 1)");
      for (int f = 0; f < 5; ++f) c.i(21 + 5 * f, 25 + 5 * f, "integration rule / relaxation field");
      for (int f = 0; f < 3; ++f) c.e(46 + 10 * f, 55 + 10 * f, "dynamic-relaxation field");
      c.i(76, 80, "shell time-step option");
    }
    {
      Card c = next("control card 9");
      c.i(1, 5, "plane-stress plasticity option");
      c.i(6, 10, "printout flag");
      require_zero(c, 11, 15, "1-D slidelines", "1-D slidelines");
      c.i(16, 20, "relaxation database flag");
      double rayleigh = c.e(21, 30, "Rayleigh coefficient");
      if (rayleigh != 0) c.error(1102, 21, 30, "Rayleigh coefficient", "Rayleigh damping");
      require_zero(c, 31, 35, "materials with Rayleigh damping", "Rayleigh damping");
      require_zero(c, 36, 40, "materials with initial rotation", "initial rotation");
      require_zero(c, 41, 45, "materials with body force", "body forces");
      // mass scaling (IMPACT-3D choice: no DYNA3D manual places it; LS-DYNA's DT2MS, MS1ST, ENDMAS)
      k.mass_scaling_dt = c.e(46, 55, "mass-scaling step DT2MS");
      const long long ms1st = c.i(56, 60, "mass scaling at the first cycle only MS1ST");
      if (ms1st != 0 && ms1st != 1) c.error(1006, 56, 60, "MS1ST", "0 (mass scaling every cycle) or 1 (the first cycle only)");
      k.mass_scaling_first_only = ms1st == 1;
      k.end_mass_percent = c.e(61, 70, "added-mass limit ENDMAS (percent)");
      if (k.end_mass_percent < 0) c.error(1003, 61, 70, "ENDMAS", "must not be negative (0 or blank: no limit)");
      const long long erode = c.i(71, 75, "ERODE");  // IMPACT-3D choice: LS-DYNA's *CONTROL_TIMESTEP ERODE
      if (erode != 0 && erode != 1) c.error(1006, 71, 75, "ERODE", "0 (the run ends below the minimum step) or 1 (solids below it are deleted)");
      k.erode_small_steps = erode == 1;
    }
  }

  // Cards 3-8 of a material: each parameter where its type's table puts it (material_types.h),
  // the fields no parameter uses warned about, then the type's checks.
  void read_material_params(MaterialData& md, const MaterialType& t, std::vector<Card>& cards) {
    set_param_defaults(md, t);
    if (t.one_per_card) {  // the original layout, or its packed alternative (8 per card from card 3)
      bool lower_blank = true;
      for (std::size_t k = 1; k < 6; ++k) lower_blank = lower_blank && cards[k].blank(1, 10);
      md.packed = lower_blank && !cards[0].blank(11, 80);
      if (md.packed) diag_.add(2001, cards[0].where(1, 80));
    }
    auto pos = [&](const MaterialParam& p) -> std::pair<Card*, int> {
      if (p.fcard < 3) return {&cards[0], 1};
      if (md.packed && p.fcol == 1) return {&cards[0], 1 + 10 * (p.fcard - 3)};
      return {&cards[std::size_t(p.fcard - 3)], p.fcol};
    };
    auto name = [](const MaterialParam& p) { return p.fname ? p.fname : p.key; };
    bool used[6][8] = {};
    for (const MaterialParam& p : t.params) {
      if (p.fcard < 3) continue;
      auto [c, col] = pos(p);
      double v = c->e(col, col + 9, name(p), p.def);
      if (c->blank(col, col + 9)) v = p.def;
      param_value(md, p) = v;
      used[c - &cards[0]][(col - 1) / 10] = true;
    }
    for (int k = 0; k < 6; ++k)
      for (int f = 0; f < 8; ++f)
        if (!used[k][f] && !cards[std::size_t(k)].blank(1 + 10 * f, 10 + 10 * f))
          diag_.add(2006, cards[std::size_t(k)].where(1 + 10 * f, 10 + 10 * f, "parameter"),
                    "not used by material type " + std::to_string(t.number));
    check_material_params(md, t, [&](const MaterialParam& p, int msg, const std::string& detail) {
      auto [c, col] = pos(p);
      if (msg >= 2000) diag_.add(msg, c->where(col, col + 9, name(p)), detail);
      else c->error(msg, col, col + 9, name(p), detail);
    });
  }

  // The shell section card of a shell material (element type 2), after card 8 (IMPACT-3D
  // choice, LS-DYNA's *SECTION_SHELL fields): SHRF (1-10), NIP (11-20), QR (21-30, 0 Gauss only),
  // T1-T4 (31-70; T2-T4 blank = T1).
  void read_shell_section(MaterialData& md, const std::string& name) {
    Card c = next(name + " shell section card", "a shell material (element type 2) has a section card after card 8");
    ShellSectionData& sec = md.shell_section;
    sec.line = c.line();
    sec.shrf = c.e(1, 10, "shear factor SHRF", 1.0);
    if (c.blank(1, 10) || sec.shrf == 0) sec.shrf = 1.0;
    if (!(sec.shrf > 0 && sec.shrf <= 1)) c.error(1003, 1, 10, "shear factor SHRF", "shear factor in (0, 1] (5/6 for isotropic shells)");
    const double nip = c.e(11, 20, "NIP", 2);
    sec.nip = (c.blank(11, 20) || nip == 0) ? 2 : int(nip);
    if (nip != std::floor(nip) || nip < 0 || nip > 1e9) { c.error(1003, 11, 20, "NIP", "integration points 1-10"); sec.nip = 2; }
    else if (nip > 10) { c.error(1102, 11, 20, "NIP", "more than 10 Gauss points (user-defined integration rules)"); sec.nip = 2; }
    if (c.e(21, 30, "quadrature rule QR") != 0) c.error(1102, 21, 30, "quadrature rule QR", "user-defined and trapezoidal integration rules (Gauss only)");
    for (int j = 0; j < 4; ++j) {
      const std::string f = "T" + std::to_string(j + 1);
      sec.t[std::size_t(j)] = c.e(31 + 10 * j, 40 + 10 * j, f.c_str());
    }
    for (int j = 1; j < 4; ++j)
      if (sec.t[std::size_t(j)] == 0) sec.t[std::size_t(j)] = sec.t[0];
    for (int j = 0; j < 4; ++j)
      if (sec.t[std::size_t(j)] < 0) {
        const std::string f = "T" + std::to_string(j + 1);
        c.error(1241, 31 + 10 * j, 40 + 10 * j, f.c_str());
      }
  }

  void read_materials() {
    int n = m_.control.nmmat;
    m_.materials.assign(static_cast<std::size_t>(n), MaterialData{});
    std::vector<int> first_line(static_cast<std::size_t>(n), 0);
    for (int s = 1; s <= n; ++s) {
      std::string set = "material set " + std::to_string(s);
      Card c1 = next(set + " card 1", "expected " + std::to_string(n) + " material sets (control card 2 NMMAT)");
      MaterialData md;
      md.line = c1.line();
      md.number = int(c1.i(1, 5, "material number"));
      std::string name = "material " + std::to_string(md.number);
      bool number_ok = true;
      if (md.number < 1 || md.number > n) {
        c1.error(1201, 1, 5, "material number", "must be 1.." + std::to_string(n) + " (NMMAT)");
        number_ok = false;
      } else if (first_line[md.number - 1] != 0) {
        c1.error(1200, 1, 5, "material number", "already defined on line " + std::to_string(first_line[md.number - 1]));
        number_ok = false;
      }
      md.type = int(c1.i(6, 10, "material type"));
      const MaterialType* mt = find_material_type(md.type);
      if (!mt) c1.error(1103, 6, 10, "material type", "supported: " + supported_material_types());
      md.rho = c1.e(11, 20, "density");
      if (!(md.rho > 0)) c1.error(1207, 11, 20, "density");
      // equation of state (material/eos.h): form 1, 4 or 9, its cards after card 8
      const long long eos = c1.i(21, 25, "EOS type");
      const EosForm* eos_form = eos != 0 ? find_eos_form(int(eos)) : nullptr;
      if (eos != 0 && !eos_form)
        c1.error(1102, 21, 25, "EOS type", "EOS form " + std::to_string(eos) + " (supported: " + supported_eos_forms() + ")");
      else if (eos_form && mt && !mt->accepts_eos)
        c1.error(1102, 21, 25, "EOS type", std::string("an equation of state with material type ") + std::to_string(md.type) + " " + mt->name + " (types that take one: " + eos_material_types() + ")");
      else if (eos == 0 && mt && mt->needs_eos)
        c1.error(1204, 21, 25, "EOS type", std::string("material type ") + std::to_string(md.type) + " " + mt->name + " needs an equation of state (" + supported_eos_forms() + ")");
      md.eos.form = eos_form ? eos_form->form : 0;
      md.hourglass_type = int(c1.i(26, 30, "hourglass type", 1));
      if (md.hourglass_type == 0) md.hourglass_type = 1;
      if (md.hourglass_type < 1 || md.hourglass_type > 5)
        c1.error(1006, 26, 30, "hourglass type", "1 viscous (DYNA3D), 2/3 Flanagan-Belytschko viscous, 4/5 stiffness");
      md.hourglass_coef = c1.e(31, 40, "hourglass coefficient", 0.10);
      if (c1.blank(31, 40) || md.hourglass_coef == 0) md.hourglass_coef = 0.10;
      if (md.hourglass_coef < 0) c1.error(1220, 31, 40, "hourglass coefficient");
      md.bulk_type = int(c1.i(41, 45, "bulk viscosity type", 1));
      if (md.bulk_type == 0) md.bulk_type = 1;
      if (md.bulk_type != 1) c1.error(1006, 41, 45, "bulk viscosity type", "only 1 (standard)");
      md.q1 = c1.e(46, 55, "quadratic bulk viscosity Q1", 1.5);
      if (c1.blank(46, 55)) md.q1 = 1.5;
      md.q2 = c1.e(56, 65, "linear bulk viscosity Q2", 0.06);
      if (c1.blank(56, 65)) md.q2 = 0.06;
      if (md.q1 < 0) c1.error(1220, 46, 55, "quadratic bulk viscosity Q1");
      if (md.q2 < 0) c1.error(1220, 56, 65, "linear bulk viscosity Q2");
      // element type as DYNA3D deck writers (FEMGV's DYNA interface) settle it: 0 solid, 1
      // beam, 2 shell, 3 thick shell
      long long et = c1.i(66, 70, "element type");
      if (et == 1 || et == 3) {
        static const char* const kind[] = {"", "beams (element type 1)", "", "thick shells (element type 3)"};
        c1.error(1102, 66, 70, "element type", std::string(kind[et]) + ": IMPACT-3D has solids (0) and shells (2)");
      } else if (et != 0 && et != 2) {
        c1.error(1006, 66, 70, "element type", "0 solid, 1 beam, 2 shell, 3 thick shell");
      }
      md.shell = et == 2;
      if (md.shell && mt && !has_shell_kernel(md.type))
        c1.error(1103, 6, 10, "material type", "type " + std::to_string(md.type) + " has no shell form; shells (element type 2) take types " + shell_material_numbers());
      if (md.shell && eos != 0) c1.error(1102, 21, 25, "EOS type", "an equation of state for shells (element type 2)");
      c1.i(71, 75, "unused");
      long long ef = c1.i(76, 80, "element formulation");
      if (md.shell) {  // shells: Belytschko-Tsay (LS-DYNA ELFORM 2; 0 = the default, 2)
        if (ef != 0 && ef != 2) c1.error(1102, 76, 80, "element formulation", "shell formulation " + std::to_string(ef) + "; only 2 (Belytschko-Tsay, also 0)");
      } else if (ef != 0 && ef != 1) {
        c1.error(1102, 76, 80, "element formulation", "only the one-point hexahedron (0 or 1)");
      }

      Card c2 = next(name + " card 2 (title)");
      md.title = c2.a(1, 80);
      while (!md.title.empty() && md.title.back() == ' ') md.title.pop_back();

      std::vector<Card> cards;
      for (int k = 3; k <= 8; ++k) cards.push_back(next(name + " card " + std::to_string(k)));
      if (mt) read_material_params(md, *mt, cards);
      if (const char* feature = nullptr; mt && md.shell) {
        if (const MaterialParam* q = refused_shell_param(md, &feature); q && q->fcard >= 3)
          cards[std::size_t(q->fcard - 3)].error(1102, q->fcol, q->fcol + 9, q->key, std::string(feature) + " (a shell material, element type 2)");
      }
      if (md.shell) read_shell_section(md, name);
      if (eos_form && (!mt || mt->accepts_eos) && !md.shell) {  // (a type that takes none: reported above, no cards read)
        std::vector<Card> ec;
        const std::vector<int>& ew = eos_fixed_widths(*eos_form);
        for (std::size_t c = 0; c < ew.size(); ++c) ec.push_back(next(name + " EOS card " + std::to_string(c + 1)));
        for (const EosParam& p : eos_form->params) {
          if (p.fcard < 0) continue;
          const int w = ew[std::size_t(p.fcard)], a = 1 + w * p.ffield;
          eos_value(md.eos, p) = ec[std::size_t(p.fcard)].e(a, a + w - 1, p.key, p.slot == kEosSlotV0 ? 1.0 : 0.0);
        }
        check_eos(md.eos, md.rho, [&](const EosParam& p, int msg, const std::string& detail) {
          const int c = p.fcard < 0 ? 0 : p.fcard, w = ew[std::size_t(c)], a = 1 + w * (p.fcard < 0 ? 0 : p.ffield);
          ec[std::size_t(c)].error(msg, a, a + w - 1, p.key, detail);
        });
      }
      // rigid-body constraints in a local system need *DEFINE_COORDINATE_SYSTEM (keyword decks)
      if (md.type == 20 && md.par.size() > 3 && md.par[3] == -1)
        cards[2].error(1102, 1, 10, "constraint option CMO", "constraints in a local system (CMO = -1: keyword decks, *DEFINE_COORDINATE_SYSTEM)");
      if (number_ok) {
        first_line[md.number - 1] = md.line;
        m_.materials[md.number - 1] = md;
      }
    }
    for (int k = 0; k < n; ++k) {
      if (first_line[k] == 0 && n > 0) {
        Location loc;
        loc.file = deck_.name();
        diag_.add(1204, loc, "material " + std::to_string(k + 1) + " is never defined");
      }
    }
  }

  void read_nodes() {
    int n = m_.control.numnp;
    // Nodes never defined (reported as 1204) keep NaN coordinates: the volume check skips the
    // elements that use them instead of reporting a second, misleading error.
    const double undefined = std::numeric_limits<double>::quiet_NaN();
    assign_huge(m_.x, std::size_t(n), undefined);
    assign_huge(m_.y, std::size_t(n), undefined);
    assign_huge(m_.z, std::size_t(n), undefined);
    assign_huge(m_.bc, std::size_t(n), 0);
    std::vector<int> seen(std::size_t(n), 0);
    const bool L = m_.large_format;
    const int i1 = 1, i2 = L ? 8 : 5, b1 = i2 + 1, b2 = i2 + 5;
    const int x1 = b2 + 1, y1 = x1 + 20, z1 = y1 + 20, r1 = z1 + 20;
    int unread = 0;  // node cards with text in the columns after the rotational code
    Location unread_where;
    for (int k = 0; k < n; ++k) {
      if (const DeckLine* l = plain_next_card()) {
        const std::string_view t = l->text;
        int id = 0, code = 0, rc = 0;
        double x = 0, y = 0, z = 0;
        if (fast_int(t, i1, i2, id) && fast_int(t, b1, b2, code) && fast_real(t, x1, x1 + 19, x) &&
            fast_real(t, y1, y1 + 19, y) && fast_real(t, z1, z1 + 19, z) &&
            fast_int(t, r1, r1 + 4, rc) && code >= 0 && code <= 7 && rc == 0 && id >= 1 &&
            id <= n && !seen[std::size_t(id - 1)] && card_columns(t, r1 + 5, 80).find_first_not_of(" \r") == std::string_view::npos) {
          deck_.next_card();
          seen[std::size_t(id - 1)] = l->number;
          m_.x[std::size_t(id - 1)] = x;
          m_.y[std::size_t(id - 1)] = y;
          m_.z[std::size_t(id - 1)] = z;
          m_.bc[std::size_t(id - 1)] = code;
          continue;
        }
      }
      Card c = next("node card " + std::to_string(k + 1) + " of " + std::to_string(n),
                    "expected " + std::to_string(n) + " node cards (control card 2 NUMNP), found " + std::to_string(k));
      int id = int(c.i(i1, i2, "node number"));
      c.set_name("node card for node " + std::to_string(id));
      int code = int(c.i(b1, b2, "boundary code"));
      double x = c.e(x1, x1 + 19, "x");
      double y = c.e(y1, y1 + 19, "y");
      double z = c.e(z1, z1 + 19, "z");
      int rc = int(c.i(r1, r1 + 4, "rotational code"));
      // the columns after the rotational code are not read: some writers put a code there
      if (!c.blank(r1 + 5, 80) && unread++ == 0) unread_where = c.where(r1 + 5, 80, "unread columns");
      if (code < 0 || code > 7) c.error(1216, b1, b2, "boundary code");
      if (rc < 0 || rc > 7) c.error(1216, r1, r1 + 4, "rotational code");
      else if (rc != 0 && id >= 1 && id <= n) {
        // the rotations it fixes act on shell nodes (read_shells); on the others: warning 2005
        if (m_.rot_bc.empty()) m_.rot_bc.assign(std::size_t(n), 0);
        if (rot_code_line_.empty()) rot_code_line_.assign(std::size_t(n), 0);
        static const std::uint8_t bits[8] = {0, 1, 2, 4, 3, 6, 5, 7};  // code 0-7 -> bit 0 rx, 1 ry, 2 rz
        m_.rot_bc[std::size_t(id - 1)] = bits[rc];
        rot_code_line_[std::size_t(id - 1)] = c.line();
      }
      if (id < 1 || id > n) {
        c.error(1201, i1, i2, "node number", "must be 1.." + std::to_string(n) + " (NUMNP)");
        continue;
      }
      if (seen[std::size_t(id - 1)]) {
        c.error(1200, i1, i2, "node number", "node " + std::to_string(id) + " already defined on line " + std::to_string(seen[std::size_t(id - 1)]));
        continue;
      }
      seen[std::size_t(id - 1)] = c.line();
      m_.x[std::size_t(id - 1)] = x;
      m_.y[std::size_t(id - 1)] = y;
      m_.z[std::size_t(id - 1)] = z;
      m_.bc[std::size_t(id - 1)] = (code >= 0 && code <= 7) ? code : 0;
    }
    if (unread)
      diag_.add(2020, unread_where, std::to_string(unread) + " node card(s) (this is the first) hold text in columns " +
                                        std::to_string(r1 + 5) + "-80, after the rotational code: IMPACT-3D reads nothing there");
    report_missing(seen, "node");
  }

  void report_missing(const std::vector<int>& seen, const char* what) {
    int missing = 0;
    std::string list;
    for (std::size_t k = 0; k < seen.size(); ++k) {
      if (!seen[k]) {
        if (missing < 10) list += (missing ? ", " : "") + std::to_string(k + 1);
        ++missing;
      }
    }
    if (missing) {
      Location loc;
      loc.file = deck_.name();
      diag_.add(1204, loc, std::to_string(missing) + " " + what + " number(s) never defined: " + list + (missing > 10 ? ", ..." : ""));
    }
  }

  void read_solids() {
    int n = m_.control.numelh;
    // Elements never defined (reported as 1204) keep node -1, so that the model checks skip
    // them instead of computing the volume of a degenerate element at node 1.
    std::array<int, 8> undefined;
    undefined.fill(-1);
    assign_huge(m_.hex_nodes, std::size_t(n), undefined);
    assign_huge(m_.hex_material, std::size_t(n), -1);
    assign_huge(m_.hex_line, std::size_t(n), 0);
    std::vector<int> seen(std::size_t(n), 0);
    const int w = idw_;
    const int last = w + 5 + 8 * w;  // the last column read (node n8)
    int unread = 0;                  // element cards with text after node n8
    Location unread_where;
    for (int k = 0; k < n; ++k) {
      if (const DeckLine* l = plain_next_card()) {
        const std::string_view t = l->text;
        int id = 0, mat = 0;
        std::array<int, 8> nodes{};
        bool ok = fast_int(t, 1, w, id) && fast_int(t, w + 1, w + 5, mat) && id >= 1 && id <= n &&
                  !seen[std::size_t(id - 1)] && mat >= 1 && mat <= m_.control.nmmat;
        for (int j = 0; j < 8 && ok; ++j) {
          const int c1 = w + 6 + j * w;
          ok = fast_int(t, c1, c1 + w - 1, nodes[std::size_t(j)]) && nodes[std::size_t(j)] >= 1 &&
               nodes[std::size_t(j)] <= m_.control.numnp;
          --nodes[std::size_t(j)];
        }
        if (ok && is_valid_solid_node_pattern(nodes) &&
            card_columns(t, last + 1, 80).find_first_not_of(" \r") == std::string_view::npos) {
          deck_.next_card();
          seen[std::size_t(id - 1)] = l->number;
          make_canonical_solid_node_pattern(nodes);
          m_.hex_line[std::size_t(id - 1)] = l->number;
          m_.hex_nodes[std::size_t(id - 1)] = nodes;
          m_.hex_material[std::size_t(id - 1)] = mat - 1;
          continue;
        }
      }
      Card c = next("solid element card " + std::to_string(k + 1) + " of " + std::to_string(n),
                    "expected " + std::to_string(n) + " solid element cards (control card 2 NUMELH), found " + std::to_string(k));
      int id = int(c.i(1, w, "element number"));
      c.set_name("solid element card for element " + std::to_string(id));
      Card& e = c;
      int mat = int(c.i(w + 1, w + 5, "material number"));
      if (!c.blank(last + 1, 80) && unread++ == 0) unread_where = c.where(last + 1, 80, "unread columns");
      std::array<int, 8> nodes{};
      bool ok = true;
      for (int j = 0; j < 8; ++j) {
        int c1 = w + 6 + j * w;
        std::string fname = "node n" + std::to_string(j + 1);
        int nid = int(c.i(c1, c1 + w - 1, fname.c_str()));
        if (nid < 1 || nid > m_.control.numnp) {
          e.error(1202, c1, c1 + w - 1, fname.c_str(), "nodes are 1.." + std::to_string(m_.control.numnp));
          ok = false;
        }
        nodes[std::size_t(j)] = nid - 1;
      }
      if (mat < 1 || mat > m_.control.nmmat) {
        e.error(1203, w + 1, w + 5, "material number", "materials are 1.." + std::to_string(m_.control.nmmat));
        ok = false;
      }
      if (ok && !is_valid_solid_node_pattern(nodes)) {
        e.error(1222, w + 6, w + 5 + 8 * w, "nodes n1-n8");
        ok = false;
      }
      if (id < 1 || id > n) {
        c.error(1201, 1, w, "element number", "must be 1.." + std::to_string(n) + " (NUMELH)");
        continue;
      }
      if (seen[std::size_t(id - 1)]) {
        c.error(1200, 1, w, "element number", "element " + std::to_string(id) + " already defined on line " + std::to_string(seen[std::size_t(id - 1)]));
        continue;
      }
      seen[std::size_t(id - 1)] = c.line();
      if (!ok) nodes.fill(-1);
      else make_canonical_solid_node_pattern(nodes);
      m_.hex_line[std::size_t(id - 1)] = c.line();
      m_.hex_nodes[std::size_t(id - 1)] = nodes;
      m_.hex_material[std::size_t(id - 1)] = ok ? mat - 1 : -1;
    }
    if (unread)
      diag_.add(2020, unread_where, std::to_string(unread) + " solid element card(s) (this is the first) hold text in columns " +
                                        std::to_string(last + 1) + "-80, after node n8: IMPACT-3D reads nothing there");
    report_missing(seen, "solid element");
  }

  // Shell element cards (NUMELS shells after the solids, two cards each, as the Silo reader of
  // TrueGrid's DYNA3D decks finds them): card 1 the shell number (ID), material (I5) and n1-n4
  // (4 ID), the solid card's columns; card 2 the nodal thicknesses t1-t4 (4 E10, columns 1-40;
  // all blank: the material's shell section T1-T4).  n4 = n3 (or blank) is a triangle.  Then the
  // solids' materials must be solid materials, the shells' shell materials (element type 2), and
  // the rotational codes of the node cards act on shell nodes (warning 2005 for the others).
  void read_shells() {
    const int n = numels_;
    std::array<int, 4> undefined;
    undefined.fill(-1);
    m_.shell_nodes.assign(std::size_t(n), undefined);
    m_.shell_material.assign(std::size_t(n), -1);
    m_.shell_thickness.assign(std::size_t(n), std::array<double, 4>{});
    m_.shell_line.assign(std::size_t(n), 0);
    std::vector<int> seen(std::size_t(n), 0);
    const int w = idw_;
    const int last = w + 5 + 4 * w;  // the last column read (node n4)
    const auto is_shell_mat = [&](int mat) {  // 1-based
      return mat >= 1 && mat <= int(m_.materials.size()) && m_.materials[std::size_t(mat - 1)].shell;
    };
    for (int k = 0; k < n; ++k) {
      Card c = next("shell element card " + std::to_string(k + 1) + " of " + std::to_string(n),
                    "expected " + std::to_string(n) + " shell elements, two cards each (control card 2 NUMELS), found " + std::to_string(k));
      const int id = int(c.i(1, w, "element number"));
      c.set_name("shell element card for element " + std::to_string(id));
      const int mat = int(c.i(w + 1, w + 5, "material number"));
      std::array<int, 4> nodes{};
      bool ok = true;
      for (int j = 0; j < 4; ++j) {
        const int c1 = w + 6 + j * w;
        const std::string fname = "node n" + std::to_string(j + 1);
        int nid = int(c.i(c1, c1 + w - 1, fname.c_str()));
        if (j == 3 && c.blank(c1, c1 + w - 1)) nid = nodes[2] + 1;  // a triangle given with three nodes
        if (nid < 1 || nid > m_.control.numnp) {
          c.error(1202, c1, c1 + w - 1, fname.c_str(), "nodes are 1.." + std::to_string(m_.control.numnp));
          ok = false;
        }
        nodes[std::size_t(j)] = nid - 1;
      }
      if (!c.blank(last + 1, 80))
        diag_.add(2020, c.where(last + 1, 80, "unread columns"), "after node n4: IMPACT-3D reads nothing there");
      if (mat < 1 || mat > m_.control.nmmat) {
        c.error(1203, w + 1, w + 5, "material number", "materials are 1.." + std::to_string(m_.control.nmmat));
        ok = false;
      } else if (!is_shell_mat(mat)) {
        c.error(1203, w + 1, w + 5, "material number", "material " + std::to_string(mat) + " is not a shell material (material card 1 columns 66-70 element type 2)");
        ok = false;
      }
      if (ok && (nodes[0] == nodes[1] || nodes[0] == nodes[2] || nodes[1] == nodes[2] || nodes[0] == nodes[3] || nodes[1] == nodes[3])) {
        c.error(1222, w + 6, last, "nodes n1-n4", "a shell is a quadrilateral or a triangle with n4 = n3");
        ok = false;
      }
      Card c2 = next("shell element " + std::to_string(id) + " thickness card",
                     "each shell element has a second card with its thicknesses t1-t4");
      std::array<double, 4> t{};
      for (int j = 0; j < 4; ++j) {
        const std::string f = "thickness t" + std::to_string(j + 1);
        t[std::size_t(j)] = c2.e(1 + 10 * j, 10 + 10 * j, f.c_str());
        if (t[std::size_t(j)] < 0) { c2.error(1241, 1 + 10 * j, 10 + 10 * j, f.c_str()); ok = false; }
      }
      if (!c2.blank(41, 80)) diag_.add(2020, c2.where(41, 80, "unread columns"), "after t4: IMPACT-3D reads nothing there");
      if (id < 1 || id > n) {
        c.error(1201, 1, w, "element number", "must be 1.." + std::to_string(n) + " (NUMELS)");
        continue;
      }
      if (seen[std::size_t(id - 1)]) {
        c.error(1200, 1, w, "element number", "shell " + std::to_string(id) + " already defined on line " + std::to_string(seen[std::size_t(id - 1)]));
        continue;
      }
      seen[std::size_t(id - 1)] = c.line();
      m_.shell_line[std::size_t(id - 1)] = c.line();
      if (!ok) continue;
      if (t[0] == 0 && t[1] == 0 && t[2] == 0 && t[3] == 0) t = m_.materials[std::size_t(mat - 1)].shell_section.t;
      m_.shell_nodes[std::size_t(id - 1)] = nodes;
      m_.shell_material[std::size_t(id - 1)] = mat - 1;
      m_.shell_thickness[std::size_t(id - 1)] = t;
    }
    report_missing(seen, "shell element");
    // solids of shell materials
    int solid_of_shell = 0;
    for (std::size_t e = 0; e < m_.hex_material.size(); ++e) {
      const int mat = m_.hex_material[e];
      if (mat < 0 || !m_.materials[std::size_t(mat)].shell) continue;
      Location loc;
      loc.file = deck_.name();
      loc.line = m_.hex_line[e];
      loc.card = "solid element card for element " + std::to_string(e + 1);
      loc.field = "material number";
      loc.col_first = idw_ + 1;
      loc.col_last = idw_ + 5;
      ++solid_of_shell;
      diag_.add(1203, loc, "material " + std::to_string(mat + 1) + " is a shell material (element type 2); solids need element type 0");
      m_.hex_material[e] = -1;
      m_.hex_nodes[e].fill(-1);
    }
    // rotational codes on nodes no shell uses
    if (!rot_code_line_.empty()) {
      std::vector<char> shell_node(std::size_t(m_.control.numnp), 0);
      for (const auto& q : m_.shell_nodes)
        for (int v : q)
          if (v >= 0) shell_node[std::size_t(v)] = 1;
      int count = 0, first_line = 0;
      for (std::size_t i = 0; i < rot_code_line_.size(); ++i)
        if (rot_code_line_[i] && !shell_node[i]) {
          if (!first_line || rot_code_line_[i] < first_line) first_line = rot_code_line_[i];
          ++count;
          m_.rot_bc[i] = 0;
        }
      if (count) {
        Location loc;
        loc.file = deck_.name();
        loc.line = first_line;
        diag_.add(2005, loc, std::to_string(count) + " node(s) that no shell uses");
      }
    }
  }

  int read_id(Card& c, int c1, const char* field, int limit, int id_error) {
    int v = int(c.i(c1, c1 + idw_ - 1, field));
    if (v < 1 || v > limit) {
      c.error(id_error, c1, c1 + idw_ - 1, field, "must be 1.." + std::to_string(limit));
      return -1;
    }
    return v;
  }

  void read_time_history_blocks() {
    for (int which = 0; which < 3; ++which) {  // nodes, solids, shells (control card 3 order)
      int nb = which == 0 ? m_.control.node_th_blocks : which == 1 ? m_.control.solid_th_blocks : shell_th_blocks_;
      int limit = which == 0 ? m_.control.numnp : which == 1 ? m_.control.numelh : numels_;
      const char* what = which == 0 ? "node" : which == 1 ? "solid" : "shell";
      for (int b = 0; b < nb; ++b) {
        Card c = next(std::string(what) + " time-history block " + std::to_string(b + 1),
                      "expected " + std::to_string(nb) + " " + what + " time-history blocks (control card 3)");
        int err = which == 0 ? 1202 : 1201;
        int first = read_id(c, 1, "first", limit, err);
        int last = c.blank(1 + idw_, 2 * idw_) ? first : read_id(c, 1 + idw_, "last", limit, err);
        if (first > 0 && last > 0) {
          if (last < first) c.error(1003, 1 + idw_, 2 * idw_, "last", "must not be below first");
          else (which == 0 ? m_.node_th_blocks : which == 1 ? m_.solid_th_blocks : m_.shell_th_blocks).push_back({first, last});
        }
      }
    }
  }

  void read_load_curves() {
    for (int k = 0; k < m_.control.numlc; ++k) {
      Card c = next("load curve " + std::to_string(k + 1) + " header card",
                    "expected " + std::to_string(m_.control.numlc) + " load curves (control card 5 NUMLC)");
      LoadCurve lc;
      lc.number = int(c.i(1, 5, "curve number"));
      int npts = int(c.i(6, 10, "NPTS"));
      if (lc.number < 1 || lc.number > m_.control.numlc)
        c.error(1201, 1, 5, "curve number", "must be 1.." + std::to_string(m_.control.numlc));
      for (const auto& o : m_.load_curves)
        if (o.number == lc.number) c.error(1200, 1, 5, "curve number");
      long avail = remaining_cards();
      if (npts < 2 || npts > avail) {
        c.error(1003, 6, 10, "NPTS", npts < 2 ? "at least 2 points" : "more points than cards left in the deck");
        npts = std::clamp(npts, 0, int(avail));
      }
      for (int p = 0; p < npts; ++p) {
        Card pc = next("load curve " + std::to_string(lc.number) + " point " + std::to_string(p + 1));
        double t = pc.e(1, 10, "time");
        double f = pc.e(11, 20, "value");
        if (!lc.t.empty() && !(t > lc.t.back())) pc.error(1217, 1, 10, "time");
        lc.t.push_back(t);
        lc.f.push_back(f);
      }
      bool used = false;  // by a material (a flow stress curve)
      for (const MaterialData& md : m_.materials) used = used || material_uses_curve(md, lc.number);
      m_.load_curves.push_back(std::move(lc));
      curve_lines_.push_back(c.line());
      curve_used_.push_back(used ? 1 : 0);
    }
  }

  // 0-based index of load curve `number` (1..NUMLC) read in columns c1-c2, or -1 (error)
  int read_curve_ref(Card& c, int c1, int c2) {
    const int n = int(c.i(c1, c2, "load curve"));
    for (std::size_t k = 0; k < m_.load_curves.size(); ++k)
      if (m_.load_curves[k].number == n) {
        curve_used_[k] = 1;
        return int(k);
      }
    c.error(1201, c1, c2, "load curve", "must be one of the deck's curves 1.." + std::to_string(m_.control.numlc));
    return -1;
  }

  void report_unused_curves() {
    for (std::size_t k = 0; k < m_.load_curves.size(); ++k) {
      if (curve_used_[k]) continue;
      Location loc;
      loc.file = deck_.name();
      loc.line = curve_lines_[k];
      loc.card = "load curve " + std::to_string(m_.load_curves[k].number) + " header card";
      diag_.add(2004, loc);
    }
  }

  // direction 1-3 (x y z) read in columns c1-c2 as a unit vector; false (error) otherwise
  bool read_direction(Card& c, int c1, int c2, std::array<double, 3>& dir) {
    const long long d = c.i(c1, c2, "direction");
    if (d < 1 || d > 3) {
      c.error(d >= 4 && d <= 6 ? 1102 : 1006, c1, c2, "direction", d >= 4 && d <= 6 ? "moments and rotations (solid nodes have none)" : "1 x, 2 y, 3 z");
      return false;
    }
    dir = {0, 0, 0};
    dir[std::size_t(d - 1)] = 1;
    return true;
  }

  // Concentrated nodal loads (card 5 field 2): node, direction 1-3, load curve, scale;
  // small format I5 I5 I5 E10, large I8 I5 I5 E10.
  void read_nodal_loads() {
    const int n = m_.control.num_nodal_load_cards;
    const int w = idw_;
    for (int k = 0; k < n; ++k) {
      Card c = next("nodal load card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " nodal load cards (control card 5)");
      NodalLoad l;
      const int node = read_id(c, 1, "node", m_.control.numnp, 1202);
      bool ok = node >= 1;
      ok = read_direction(c, w + 1, w + 5, l.dir) && ok;
      l.curve = read_curve_ref(c, w + 6, w + 10);
      l.scale = c.e(w + 11, w + 20, "scale factor", 1.0);
      l.node = node - 1;
      l.line = c.line();
      if (ok && l.curve >= 0) m_.nodal_loads.push_back(l);
    }
  }

  // Pressure-loaded element sides (card 5 field 3): load curve, four nodes, four nodal
  // multipliers and an arrival time.  Small format: I5, 4I5 (6-25), 4E10 (26-65), arrival time
  // E10 (71-80).  Large format (an IMPACT-3D choice): I5, 4I8 (6-37) on the first card, the
  // four multipliers 4E10 (1-40) and the arrival time (71-80) on a second card.  Blank
  // multipliers are 1.
  void read_pressure_loads() {
    const int n = m_.control.num_pressure_cards;
    const bool large = m_.large_format;
    for (int k = 0; k < n; ++k) {
      Card c = next("pressure card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " pressure cards (control card 5)");
      PressureLoad p;
      p.line = c.line();
      p.curve = read_curve_ref(c, 1, 5);
      bool ok = p.curve >= 0;
      for (int q = 0; q < 4; ++q) {
        const std::string f = "node n" + std::to_string(q + 1);
        const int id = read_id(c, 6 + idw_ * q, f.c_str(), m_.control.numnp, 1202);
        if (id < 1) ok = false;
        p.nodes[std::size_t(q)] = id - 1;
      }
      Card* mc = &c;
      std::optional<Card> c2;
      if (large) {
        c2.emplace(next("pressure card " + std::to_string(k + 1) + " multipliers"));
        mc = &*c2;
      }
      const int m1 = large ? 1 : 26;
      for (int q = 0; q < 4; ++q) {
        const std::string f = "multiplier " + std::to_string(q + 1);
        const double v = mc->e(m1 + 10 * q, m1 + 9 + 10 * q, f.c_str(), 1.0);
        p.factor[std::size_t(q)] = v;
      }
      p.birth = mc->e(71, 80, "arrival time");
      if (ok) m_.pressure_loads.push_back(p);
    }
  }

  // Velocity / acceleration / displacement boundary conditions (card 5 field 4), one card each
  // (an IMPACT-3D layout: no DYNA3D manual text fixes it): node (I5 small, I8 large), direction
  // 1-3 (I5), load curve (I5), scale (E10), type (I5: 0 velocity, 1 acceleration,
  // 2 displacement), birth time (E10), death time (E10; blank or 0 = never).
  void read_prescribed_motions() {
    const int n = m_.control.num_motion_cards;
    const int w = idw_;
    for (int k = 0; k < n; ++k) {
      Card c = next("velocity/acceleration boundary card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " velocity/acceleration boundary cards (control card 5)");
      PrescribedMotion pm;
      const int node = read_id(c, 1, "node", m_.control.numnp, 1202);
      bool ok = node >= 1;
      ok = read_direction(c, w + 1, w + 5, pm.dir) && ok;
      pm.curve = read_curve_ref(c, w + 6, w + 10);
      pm.scale = c.e(w + 11, w + 20, "scale factor", 1.0);
      const long long type = c.i(w + 21, w + 25, "type");
      if (type < 0 || type > 2) { c.error(1006, w + 21, w + 25, "type", "0 velocity, 1 acceleration, 2 displacement"); ok = false; }
      pm.kind = MotionKind(int(type));
      pm.birth = c.e(w + 26, w + 35, "birth time");
      const double death = c.e(w + 36, w + 45, "death time");
      pm.death = death > 0 ? death : 1e28;
      pm.node = node - 1;
      pm.line = c.line();
      if (ok && pm.curve >= 0) m_.prescribed_motions.push_back(pm);
    }
  }

  // Base accelerations (card 5 fields 9-11), one card per direction flagged, in x y z order
  // (an IMPACT-3D layout): load curve (I5), scale (E10).  Every node gets the acceleration
  // -scale * curve(t) along the axis (LS-DYNA's *LOAD_BODY sign).
  void read_base_accelerations() {
    for (int a = 0; a < 3; ++a) {
      if (!m_.control.base_acceleration[std::size_t(a)]) continue;
      const char* axis = a == 0 ? "x" : a == 1 ? "y" : "z";
      Card c = next(std::string("base acceleration card (") + axis + ")");
      BodyLoad b;
      b.dir[std::size_t(a)] = 1;
      b.curve = read_curve_ref(c, 1, 5);
      b.scale = c.e(6, 15, "scale factor", 1.0);
      b.line = c.line();
      if (b.curve >= 0) m_.body_loads.push_back(b);
    }
  }

  void read_node_list(std::vector<int>& out, int count, const std::string& what) {
    int per = m_.large_format ? 10 : 16;
    int cards = (count + per - 1) / per;
    int k = 0;
    for (int cc = 0; cc < cards; ++cc) {
      Card c = next(what + " node card " + std::to_string(cc + 1));
      for (int f = 0; f < per && k < count; ++f, ++k) {
        int c1 = 1 + f * idw_;
        int id = read_id(c, c1, "node", m_.control.numnp, 1202);
        if (id > 0) out.push_back(id - 1);
      }
    }
  }

  void read_stonewalls() {
    for (int w = 0; w < m_.control.num_walls; ++w) {
      std::string name = "stonewall " + std::to_string(w + 1);
      Card c = next(name + " card 1", "expected " + std::to_string(m_.control.num_walls) + " stonewalls (control card 5)");
      StoneWall sw;
      sw.line = c.line();
      int nsn = int(c.i(1, 5, "NSN"));
      const long long moving = c.i(6, 10, "moving flag");
      if (moving != 0 && moving != 1) c.error(1006, 6, 10, "moving flag", "0 fixed, 1 moving (a card with MASS and V0 follows)");
      const char* names[] = {"XT", "YT", "ZT", "XH", "YH", "ZH"};
      for (int f = 0; f < 3; ++f) sw.tail[std::size_t(f)] = c.e(11 + 10 * f, 20 + 10 * f, names[f]);
      for (int f = 0; f < 3; ++f) sw.head[std::size_t(f)] = c.e(41 + 10 * f, 50 + 10 * f, names[3 + f]);
      sw.friction = c.e(71, 80, "FRIC");
      double dx = sw.head[0] - sw.tail[0], dy = sw.head[1] - sw.tail[1], dz = sw.head[2] - sw.tail[2];
      double len = std::sqrt(dx * dx + dy * dy + dz * dz);
      double scale = 0;
      for (int f = 0; f < 3; ++f) scale = std::max({scale, std::fabs(sw.head[std::size_t(f)]), std::fabs(sw.tail[std::size_t(f)])});
      if (!(len > 1e-12 * scale) || len == 0) c.error(1213, 11, 70, "XT-ZH", {}, false);
      if (!(sw.friction >= 0 && sw.friction <= 1)) c.error(1219, 71, 80, "FRIC");
      if (nsn < 0 || nsn > m_.control.numnp) {
        c.error(1003, 1, 5, "NSN", "0 (all nodes) to NUMNP");
        nsn = 0;
      }
      if (moving != 0) {  // IMPACT-3D choice: card 2, MASS (cols 1-10) and V0 (11-20)
        Card c2 = next(name + " card 2 (moving wall)", "expected the moving wall's MASS and V0 card");
        sw.mass = c2.e(1, 10, "MASS");
        sw.v0 = c2.e(11, 20, "V0");
        if (!(sw.mass > 0)) c2.error(1003, 1, 10, "MASS", "a moving wall needs a positive mass");
      }
      read_node_list(sw.nodes, nsn, name);
      remove_repeated_nodes(sw.nodes);
      m_.walls.push_back(std::move(sw));
    }
  }

  void read_initial_velocities() {
    int n = m_.control.num_init_velocity_cards;
    for (int k = 0; k < n; ++k) {
      Card c = next("initial-velocity card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " initial-velocity cards (control card 5)");
      InitialVelocity iv;
      iv.first = int(c.i(1, 8, "first node"));
      iv.v[0] = c.e(9, 18, "vx");
      iv.v[1] = c.e(19, 28, "vy");
      iv.v[2] = c.e(29, 38, "vz");
      iv.last = c.blank(39, 46) ? iv.first : int(c.i(39, 46, "last node"));
      iv.increment = int(c.i(47, 51, "increment", 1));
      if (iv.increment == 0) iv.increment = 1;
      bool ok = true;
      int nn = m_.control.numnp;
      if (iv.first < 0 || iv.first > nn) { c.error(1202, 1, 8, "first node", "0 (all nodes) or 1.." + std::to_string(nn)); ok = false; }
      if (iv.first != 0 && (iv.last < 1 || iv.last > nn)) { c.error(1202, 39, 46, "last node", "1.." + std::to_string(nn)); ok = false; }
      if (iv.increment < 0) { c.error(1003, 47, 51, "increment", "must be positive"); ok = false; }
      if (ok && iv.first != 0 && iv.last < iv.first) { c.error(1223, 39, 46, "last node"); ok = false; }
      if (ok) m_.init_velocities.push_back(iv);
    }
  }

  void read_segments(std::vector<std::array<int, 4>>& out, std::vector<int>& lines, int count,
                     const std::string& what) {
    for (int s = 0; s < count; ++s) {
      Card c = next(what + " segment card " + std::to_string(s + 1) + " of " + std::to_string(count));
      c.i(1, idw_, "segment number");
      std::array<int, 4> seg{};
      bool ok = true;
      for (int j = 0; j < 4; ++j) {
        std::string f = "node n" + std::to_string(j + 1);
        int id = read_id(c, 1 + idw_ * (j + 1), f.c_str(), m_.control.numnp, 1202);
        if (id < 1) ok = false;
        seg[std::size_t(j)] = id - 1;
      }
      if (ok) {
        out.push_back(seg);
        lines.push_back(c.line());
      }
    }
  }

  void read_sliding_interfaces() {
    int n = m_.control.num_interfaces;
    std::vector<std::array<int, 2>> counts;
    for (int k = 0; k < n; ++k) {
      Card c = next("sliding interface " + std::to_string(k + 1) + " control card",
                    "expected " + std::to_string(n) + " sliding interface control cards (control card 5)");
      SlidingInterface si;
      si.line = c.line();
      int nss = int(c.i(1, 8, "NSS"));
      int nms = int(c.i(9, 16, "NMS"));
      si.type = int(c.i(17, 20, "type"));
      if (si.type != 3 && si.type != 4) {
        // the DYNA3D types, by name (after deck writers of DYNA3D decks)
        static const char* const names[] = {"", "1 sliding only", "2 tied", "3 sliding with impact and friction", "4 single surface",
                                            "5 nodes to surface", "6 nodes tied to surface", "7 shell edge tied to surface",
                                            "8 spot weld", "9 tiebreak"};
        if (si.type >= 1 && si.type <= 9)
          c.error(1104, 17, 20, "type", std::string("type ") + names[si.type] + ": IMPACT-3D has types 3 (sliding with impact, separation and friction) and 4 (single surface)");
        else
          c.error(1006, 17, 20, "type", "DYNA3D sliding interface types are 1-9; IMPACT-3D has types 3 and 4");
      }
      si.fs = c.e(21, 30, "static friction");
      si.fd = c.e(31, 40, "dynamic friction");
      si.decay = c.e(41, 50, "decay coefficient");
      si.penalty_scale = c.e(51, 60, "penalty scale factor");
      si.stiffness_method = int(c.i(61, 65, "stiffness method"));
      int one_pass = int(c.i(66, 70, "one-pass flag"));
      si.symmetric = one_pass == 0 && si.type != 4;  // (single surface: one pass over its own nodes)
      if (si.fs < 0) c.error(1219, 21, 30, "static friction");
      if (si.fd < 0) c.error(1219, 31, 40, "dynamic friction");
      if (si.decay < 0) c.error(1003, 41, 50, "decay coefficient", "must not be negative");
      if (si.penalty_scale < 0) c.error(1003, 51, 60, "penalty scale factor", "must not be negative");
      if (si.stiffness_method != 0 && si.stiffness_method != 1) c.error(1006, 61, 65, "stiffness method", "0 DYNA3D or 1 IMPACT-3D maximum stable");
      if (one_pass != 0 && one_pass != 1) c.error(1006, 66, 70, "one-pass flag", "0 or 1");
      long avail = remaining_cards();
      if (nss < 1 || nss > avail) { c.error(1003, 1, 8, "NSS", "1 to the cards left in the deck"); nss = 0; }
      if (si.type == 4) {  // single surface: the NSS segments against themselves, no master side
        if (nms != 0) { c.error(1003, 9, 16, "NMS", "must be 0 for a single-surface interface (type 4)"); nms = 0; }
      } else if (nms < 1 || nms > avail) { c.error(1003, 9, 16, "NMS", "1 to the cards left in the deck"); nms = 0; }
      counts.push_back({nss, nms});
      m_.interfaces.push_back(std::move(si));
    }
    for (int k = 0; k < n; ++k) {
      std::string name = "sliding interface " + std::to_string(k + 1);
      SlidingInterface& si = m_.interfaces[std::size_t(k)];
      read_segments(si.slave, si.slave_line, counts[std::size_t(k)][0], name + " slave");
      read_segments(si.master, si.master_line, counts[std::size_t(k)][1], name + " master");
    }
  }

  friend bool impact3d::read_dyna3d_deck(DeckFile&, Model&, Diagnostics&);
};

}  // namespace

bool read_dyna3d_deck(DeckFile& deck, Model& model, Diagnostics& diag) {
  model.deck_file = deck.name();
  Dyna3dReader r(deck, model, diag);
  try {
    r.read();
  } catch (const EndOfDeck&) {
  } catch (const TooManyErrors&) {
  }
  return diag.error_count() == 0;
}

}  // namespace impact3d
