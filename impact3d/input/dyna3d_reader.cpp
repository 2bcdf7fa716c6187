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
#include "impact3d/input/fixed_cards.h"
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
    deck_.set_star_comments(true);  // in the fixed format every '*' line is a comment
    read_control_cards();
    if (stop_) return;
    read_free_format_blocks();
    read_materials();
    read_beam_integration_rules();
    read_nodes();
    read_solids();
    read_beams();
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
    read_mass_damping();
    report_unused_curves();
    report_ignored();
    if (const DeckLine* l = deck_.peek_card()) {
      Location loc;
      loc.file = deck_.name();
      loc.line = l->number;
      loc.found = l->text;
      loc.show_found = true;
      int left = 0;
      while (deck_.next_card()) ++left;
      diag_.add(1005, loc, std::to_string(left) + " card(s) after the last section");
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
  int numelb_ = 0;                 // control card 2 NUMELB: beams
  int beam_th_blocks_ = 0;         // control card 3 field 3
  int beam_rules_ = 0;             // control card 8 field 4: user beam integration rules
  int beam_rule_points_ = 0;       // control card 8 field 5
  int mass_damping_sets_ = 0;      // control card 7 field 11 (later vintage) or free-format mdamp
  bool deletion_flag_ = false;     // control card 3 field 9
  FixedVintage vintage_ = FixedVintage::dyna3d_later;
  // fields and free-format options read but without effect here: (line, what), listed once (2040)
  std::vector<std::pair<int, std::string>> ignored_fields_;
  // what the deck holds of beams, read and checked (refused as a family until beams exist)
  int beam_lines_first_ = 0;
  int card2_line_ = 0;
  int beam_material_count_ = 0;
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
  // A code written as an integral real ("7.", as INGRID writes node codes), or an integer.
  static bool fast_code(std::string_view line, int c1, int c2, int& v) {
    if (fast_int(line, c1, c2, v)) return true;
    double x = 0;
    if (parse_fortran_real(card_columns(line, c1, c2), x) != FieldStatus::ok || x != std::floor(x) || std::fabs(x) > 1e9) return false;
    v = int(x);
    return true;
  }
  static bool fast_real(std::string_view line, int c1, int c2, double& v) {
    double x = 0;
    const FieldStatus st = parse_fortran_real(card_columns(line, c1, c2), x);
    if (st == FieldStatus::bad) return false;
    v = st == FieldStatus::ok ? x : 0.0;
    return true;
  }

  // The title card (title card table): the title kept as written (leading blanks too), the
  // format flag choosing the large or small format.
  void read_title() {
    Card c = next("title card");
    const FixedCardLayout& t = fixed_card_layout("title card", vintage_);
    const FixedField &ft = t.field("title"), &fd = t.field("format digits"), &ff = t.field("format flag");
    m_.title = c.a(ft.c1, ft.c2);
    while (!m_.title.empty() && m_.title.back() == ' ') m_.title.pop_back();
    std::string digits = c.a(fd.c1, fd.c2);
    std::string large = c.a(ff.c1, ff.c2);
    for (auto& ch : large) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    bool is_large = large.find("large") != std::string::npos;
    if (is_large && digits == "10") {
      c.error(1101, fd.c1, ff.c2, ff.name, "\"10 large\" free-format control cards are not supported; use \"88 large\"");
      stop_ = true;
      return;
    }
    if (!is_large && !c.blank(ff.c1, ff.c2)) {
      c.error(1006, fd.c1, ff.c2, ff.name, "expected \"large\" or blank");
    }
    m_.large_format = is_large;
    idw_ = is_large ? 8 : 5;
    if (is_keyword_line(c.a(1, 80))) {
      c.error(1101, ft.c1, ft.c2, ft.name, "this looks like an LS-DYNA keyword deck (*KEYWORD); only the DYNA3D fixed format is read");
      stop_ = true;
    }
  }

  // The layout of a card whose id fields are 8 columns wide in the large format and 5 in the
  // small one (its table "<id> (small format)").
  const FixedCardLayout& sized_layout(const std::string& id) const {
    return fixed_card_layout(m_.large_format ? id : id + " (small format)", vintage_);
  }

  // A count field bounded by what the deck can still hold (before anything is allocated).
  int bounded_count(const FixedValues& v, const char* name, long avail, long per_item = 1) {
    long long n = v.integer(name);
    if (n < 0) { v.error(1003, name, "must not be negative"); return 0; }
    if (n > avail / per_item) {
      v.error(1205, name, "the deck has only " + std::to_string(avail) + " cards left");
      return 0;
    }
    return int(n);
  }

  void note_ignored(const FixedValues& v) {
    for (const std::string& s : v.ignored()) ignored_fields_.push_back({v.card().line(), s});
  }

  // Control cards 2-9, each read by its table (fixed_cards.cpp); the vintage of the layout is
  // told by control card 4 (detect_fixed_vintage).
  void read_control_cards() {
    read_control_card_2();
    read_control_card_3();
    read_control_card_4();
    read_control_card_5();
    read_control_card_6();
    read_control_card_7();
    read_control_card_8();
    read_control_card_9();
  }

  void read_control_card_2() {
    ControlData& k = m_.control;
    Card c = next("control card 2");
    card2_line_ = c.line();
    FixedValues v(c, sized_layout("control card 2"));
    note_ignored(v);
    k.nmmat = int(v.integer("NMMAT"));
    k.numnp = int(v.integer("NUMNP"));
    k.numelh = int(v.integer("NUMELH"));
    numelb_ = int(v.integer("NUMELB"));
    numels_ = int(v.integer("NUMELS"));
    k.interface_segments_out = int(v.integer("interface segments"));
    k.interface_out_interval = v["interface output interval"];
    if (k.interface_out_interval < 0) v.error(1221, "interface output interval");
    if (m_.large_format) check_counts(v);
    else check_small_counts(v);
  }

  void read_control_card_3() {
    ControlData& k = m_.control;
    Card c = next("control card 3");
    FixedValues v(c, fixed_card_layout("control card 3", vintage_));
    note_ignored(v);
    const long avail = remaining_cards();
    k.node_th_blocks = bounded_count(v, "node time-history blocks", avail);
    k.solid_th_blocks = bounded_count(v, "solid time-history blocks", avail);
    beam_th_blocks_ = bounded_count(v, "beam time-history blocks", avail);
    shell_th_blocks_ = bounded_count(v, "shell time-history blocks", avail);
    k.report_interval = int(v.integer("report interval"));
    if (k.report_interval < 0) v.error(1003, "report interval", "must not be negative");
    if (k.report_interval <= 0) k.report_interval = 100;
    k.reaction_print_flag = int(v.integer("reaction-force print flag"));
    deletion_flag_ = v.flag01("element deletion flag", "0 or 1 (deletion flags in the plot database)");
  }

  void read_control_card_4() {
    Card c = next("control card 4");
    vintage_ = detect_fixed_vintage(deck_.lines()[std::size_t(c.line() - 1)].text);
    m_.fixed_vintage = int(vintage_);
    FixedValues v(c, fixed_card_layout("control card 4", vintage_));
    note_ignored(v);
    const std::string& fmt = v.text("coordinate format");
    if (!fmt.empty() && fmt.rfind("e20", 0) != 0 && fmt.rfind("E20", 0) != 0)
      v.error(1006, "coordinate format", "e20.x (node coordinates in 20 columns)");
  }

  void read_control_card_5() {
    ControlData& k = m_.control;
    Card c = next("control card 5");
    FixedValues v(c, fixed_card_layout("control card 5", vintage_));
    note_ignored(v);
    const long avail = remaining_cards();
    k.numlc = bounded_count(v, "NUMLC", avail);
    k.num_nodal_load_cards = bounded_count(v, "concentrated nodal loads", avail);
    k.num_pressure_cards = bounded_count(v, "pressure-loaded sides", avail);
    k.num_motion_cards = bounded_count(v, "velocity/acceleration boundary cards", avail);
    k.num_walls = bounded_count(v, "stonewalls", avail);
    k.num_init_velocity_cards = bounded_count(v, "initial condition parameter", avail);
    k.num_interfaces = bounded_count(v, "sliding interfaces", avail);
    static const char* const base[3] = {"base acceleration x", "base acceleration y", "base acceleration z"};
    for (int f = 0; f < 3; ++f)
      k.base_acceleration[std::size_t(f)] = v.flag01(base[f], "0 none, 1 one base-acceleration card") ? 1 : 0;
  }

  void read_control_card_6() {
    ControlData& k = m_.control;
    Card c = next("control card 6");
    FixedValues v(c, fixed_card_layout("control card 6", vintage_));
    note_ignored(v);
    k.end_time = v["termination time"];
    if (!(k.end_time > 0)) v.error(1214, "termination time");
    k.th_interval = v["time-history interval"];
    k.plot_interval = v["plot interval"];
    if (k.th_interval < 0) v.error(1221, "time-history interval");
    if (k.plot_interval < 0) v.error(1221, "plot interval");
    if (k.th_interval == 0) k.th_interval = k.end_time / 1000;
    if (k.plot_interval == 0) k.plot_interval = k.end_time / 20;
    k.restart_dump_cycles = int(v.integer("restart dump cycles"));
    k.running_restart_cycles = int(v.integer("running restart cycles"));
    if (k.restart_dump_cycles < 0) v.error(1003, "restart dump cycles", "must not be negative");
    if (k.running_restart_cycles < 0) v.error(1003, "running restart cycles", "must not be negative");
    k.initial_dt = v["initial time step"];
    if (k.initial_dt < 0) v.error(1003, "initial time step", "must not be negative");
    k.penalty_scale = v["penalty scale factor"];
    if (k.penalty_scale == 0) k.penalty_scale = 0.10;
    if (k.penalty_scale < 0) v.error(1003, "penalty scale factor", "must be positive");
    k.viscosity_flag = int(v.integer("default viscosity flag"));
    k.tssf = v["time-step scale factor"];
    if (k.tssf == 0) k.tssf = 0.90;
    if (!(k.tssf > 0 && k.tssf <= 1)) v.error(1215, "time-step scale factor");
  }

  void read_control_card_7() {
    Card c = next("control card 7");
    FixedValues v(c, fixed_card_layout("control card 7", vintage_));
    note_ignored(v);
    if (vintage_ == FixedVintage::dyna3d_later) mass_damping_sets_ = bounded_count(v, "mass damping sets", remaining_cards());
  }

  void read_control_card_8() {
    ControlData& k = m_.control;
    Card c = next("control card 8");
    FixedValues v(c, fixed_card_layout("control card 8", vintage_));
    note_ignored(v);
    k.min_step_factor = v["minimum step factor"];
    if (k.min_step_factor < 0 || k.min_step_factor >= 1) v.error(1003, "minimum step factor", "must be in [0, 1)");
    beam_rules_ = bounded_count(v, "beam integration rules", remaining_cards());
    beam_rule_points_ = int(v.integer("beam integration points"));
  }

  void read_control_card_9() {
    ControlData& k = m_.control;
    Card c = next("control card 9");
    FixedValues v(c, fixed_card_layout("control card 9", vintage_));
    note_ignored(v);
    // mass scaling (IMPACT-3D choice: no DYNA3D manual places it; LS-DYNA's DT2MS, MS1ST, ENDMAS)
    k.mass_scaling_dt = v["DT2MS"];
    k.mass_scaling_first_only = v.flag01("MS1ST", "0 (mass scaling every cycle) or 1 (the first cycle only)");
    k.end_mass_percent = v["ENDMAS"];
    if (k.end_mass_percent < 0) v.error(1003, "ENDMAS", "must not be negative (0 or blank: no limit)");
    // ERODE: an IMPACT-3D choice, LS-DYNA's *CONTROL_TIMESTEP ERODE
    k.erode_small_steps = v.flag01("ERODE", "0 (the run ends below the minimum step) or 1 (solids below it are deleted)");
  }

  // The counts of control card 2 of the small format (no DYNA3D deck of this vintage is known):
  // as the large format's, without its messages' detail.
  void check_small_counts(const FixedValues& v) {
    ControlData& k = m_.control;
    if (k.nmmat < 1) v.error(1003, "NMMAT", "at least 1 material");
    if (k.numnp < 1) v.error(1003, "NUMNP", "at least 1 node");
    if (k.numelh < 0 || (k.numelh == 0 && numels_ < 1 && numelb_ < 1))
      v.error(1003, "NUMELH", "at least 1 element (solids NUMELH, beams NUMELB or shells NUMELS)");
    const long avail = remaining_cards();
    if (k.numnp > avail) { v.error(1205, "NUMNP"); k.numnp = 0; }
    if (k.numelh > avail) { v.error(1205, "NUMELH"); k.numelh = 0; }
    if (numelb_ < 0 || numelb_ > avail) { v.error(1205, "NUMELB"); numelb_ = 0; }
    if (numels_ < 0 || numels_ > avail / 2) { v.error(1205, "NUMELS"); numels_ = 0; }
    if (k.nmmat > avail / 8 + 1) { v.error(1205, "NMMAT"); k.nmmat = 0; }
    k.nmmat = std::max(k.nmmat, 0);
    k.numnp = std::max(k.numnp, 0);
    k.numelh = std::max(k.numelh, 0);
  }

  // The counts of control card 2 (large format): at least a material, a node and an element,
  // and no more than the deck can hold.
  void check_counts(const FixedValues& v) {
    ControlData& k = m_.control;
    if (k.nmmat < 1) v.error(1003, "NMMAT", "at least 1 material");
    if (k.numnp < 1) v.error(1003, "NUMNP", "at least 1 node");
    if (k.numelh < 0 || (k.numelh == 0 && numels_ < 1 && numelb_ < 1))
      v.error(1003, "NUMELH", "at least 1 element (solids NUMELH, beams NUMELB or shells NUMELS)");
    if (numels_ < 0) v.error(1003, "NUMELS", "must not be negative");
    if (numelb_ < 0) v.error(1003, "NUMELB", "must not be negative");
    const long avail = remaining_cards();
    const std::string left = "the deck has only " + std::to_string(avail) + " cards left";
    if (k.numnp > avail) { v.error(1205, "NUMNP", left); k.numnp = 0; }
    if (k.numelh > avail) { v.error(1205, "NUMELH", left); k.numelh = 0; }
    if (numelb_ > avail) { v.error(1205, "NUMELB", left); numelb_ = 0; }
    if (numels_ > avail / 2) { v.error(1205, "NUMELS", left + " (two per shell)"); numels_ = 0; }
    if (k.nmmat > avail / 8 + 1) { v.error(1205, "NMMAT", "the deck cannot hold that many 8-card material sets"); k.nmmat = 0; }
    numels_ = std::max(numels_, 0);
    numelb_ = std::max(numelb_, 0);
    k.nmmat = std::max(k.nmmat, 0);
    k.numnp = std::max(k.numnp, 0);
    k.numelh = std::max(k.numelh, 0);
  }

  // Warning 2006 for each field of material cards 3-8 (material property card table) that no
  // parameter of the type uses and that holds a nonzero value (DYNA3D deck writers fill unused
  // fields with 0.000E+00).
  void warn_unused_property_fields(std::vector<Card>& cards, const bool (&used)[6][8], const std::string& detail) {
    const FixedCardLayout& layout = fixed_card_layout("material property card", vintage_);
    for (std::size_t k = 0; k < 6; ++k)
      for (std::size_t f = 0; f < 8; ++f) {
        const FixedField& fd = layout.fields[f];
        double v = 1;
        if (used[k][f] || cards[k].blank(fd.c1, fd.c2) || (parse_fortran_real(cards[k].columns(fd.c1, fd.c2), v) == FieldStatus::ok && v == 0)) continue;
        diag_.add(2006, cards[k].where(fd.c1, fd.c2, "parameter"), detail);
      }
  }

  // Cards 3-8 of a material: each parameter where its type's table puts it (material_types.h),
  // the fields no parameter uses warned about, then the type's checks.
  void read_material_params(MaterialData& md, const MaterialType& t, std::vector<Card>& cards) {
    set_param_defaults(md, t);
    if (t.one_per_card) {  // the original layout, or its packed alternative (8 per card from card 3)
      const FixedCardLayout& pc = fixed_card_layout("material property card", vintage_);
      const FixedField &f1 = pc.fields.front(), &f2 = pc.fields[1], &f8 = pc.fields.back();
      bool lower_blank = true;
      for (std::size_t k = 1; k < 6; ++k) lower_blank = lower_blank && cards[k].blank(f1.c1, f1.c2);
      md.packed = lower_blank && !cards[0].blank(f2.c1, f8.c2);
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
    warn_unused_property_fields(cards, used, "not used by material type " + std::to_string(t.number));
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
    if (skip_section_title()) {
      read_dyna3d_shell_section(md, name);
      return;
    }
    Card c = next(name + " shell section card", "a shell material (element type 2) has a section card after card 8");
    diag_.add(2041, c.where(1, 80), "the shell section as one card (SHRF, NIP, QR, T1-T4) is IMPACT-3D's old layout; DYNA3D's is a "
                                    "\"section properties\" line and two cards (impact3d i=DECK --write-fixed=NEW writes it)");
    FixedValues v(c, fixed_card_layout("old IMPACT-3D shell section card", vintage_));
    ShellSectionData& sec = md.shell_section;
    sec.line = c.line();
    sec.shrf = v["shear factor SHRF"];
    if (sec.shrf == 0) sec.shrf = 1.0;
    if (!(sec.shrf > 0 && sec.shrf <= 1)) v.error(1003, "shear factor SHRF", "shear factor in (0, 1] (5/6 for isotropic shells)");
    const double nip = v["NIP"];
    sec.nip = 2;
    if (nip != std::floor(nip) || nip < 0 || nip > 1e9) v.error(1003, "NIP", "integration points 1-10");
    else if (nip > 10) v.error(1102, "NIP", "more than 10 Gauss points (user-defined integration rules)");
    else if (nip != 0) sec.nip = int(nip);
    if (v["quadrature rule QR"] != 0) v.error(1102, "quadrature rule QR", "user-defined and trapezoidal integration rules (Gauss only)");
    static const char* const tn[4] = {"T1", "T2", "T3", "T4"};
    for (int j = 0; j < 4; ++j) sec.t[std::size_t(j)] = v[tn[j]];
    for (int j = 1; j < 4; ++j)
      if (sec.t[std::size_t(j)] == 0) sec.t[std::size_t(j)] = sec.t[0];
    for (int j = 0; j < 4; ++j)
      if (sec.t[std::size_t(j)] < 0) v.error(1241, tn[j]);
  }

  // DYNA3D's shell section: after the title line, card 1 (SHRF, NIP, QR) and card 2 (T1-T4).
  void read_dyna3d_shell_section(MaterialData& md, const std::string& name) {
    ShellSectionData& sec = md.shell_section;
    Card a = next(name + " shell section card 1");
    FixedValues va(a, fixed_card_layout("shell section card 1", vintage_));
    note_ignored(va);
    sec.line = a.line();
    sec.shrf = va["shear factor SHRF"];
    if (sec.shrf == 0) sec.shrf = 1.0;
    if (!(sec.shrf > 0 && sec.shrf <= 1)) va.error(1003, "shear factor SHRF", "shear factor in (0, 1] (5/6 for isotropic shells)");
    const double nip = va["NIP"];
    sec.nip = 2;
    if (nip != std::floor(nip) || nip < 0 || nip > 10) va.error(1003, "NIP", "integration points 1-10");
    else if (nip != 0) sec.nip = int(nip);
    if (va["quadrature rule QR"] != 0) va.error(1102, "quadrature rule QR", "user-defined and trapezoidal integration rules (Gauss only)");
    Card b = next(name + " shell section card 2");
    FixedValues vb(b, fixed_card_layout("shell section card 2", vintage_));
    note_ignored(vb);
    static const char* const tn[4] = {"T1", "T2", "T3", "T4"};
    for (int j = 0; j < 4; ++j) {
      sec.t[std::size_t(j)] = vb[tn[j]];
      if (sec.t[std::size_t(j)] < 0) vb.error(1241, tn[j]);
    }
    for (int j = 1; j < 4; ++j)
      if (sec.t[std::size_t(j)] == 0) sec.t[std::size_t(j)] = sec.t[0];
  }

  // Material type 71 as LLNL's regression decks write it: type 3's parameters packed by pairs,
  // E and nu on card 3 (columns 1-20), yield stress and tangent modulus on card 4 (1-20), beta
  // on card 6 (1-10).  What else the cards hold is warned about (2006) and not used.
  void read_type71_params(MaterialData& md, const MaterialType& t, std::vector<Card>& cards) {
    struct Slot { const char* key; int card, col; };
    static const Slot kType71[] = {{"E", 3, 1}, {"PR", 3, 11}, {"SIGY", 4, 1}, {"ETAN", 4, 11}, {"BETA", 6, 1}};
    set_param_defaults(md, t);
    bool used[6][8] = {};
    for (const Slot& sl : kType71) {
      const MaterialParam* p = find_param(t, sl.key);
      if (!p) continue;
      Card& c = cards[std::size_t(sl.card - 3)];
      param_value(md, *p) = c.blank(sl.col, sl.col + 9) ? p->def : c.e(sl.col, sl.col + 9, p->fname ? p->fname : p->key, p->def);
      used[sl.card - 3][(sl.col - 1) / 10] = true;
    }
    warn_unused_property_fields(cards, used, "not used by material type 71 (read as type 3: E, nu / yield stress, tangent modulus / beta)");
    check_material_params(md, t, [&](const MaterialParam& p, int msg, const std::string& detail) {
      for (const Slot& sl : kType71)
        if (std::string_view(sl.key) == p.key) {
          Card& c = cards[std::size_t(sl.card - 3)];
          if (msg >= 2000) diag_.add(msg, c.where(sl.col, sl.col + 9, sl.key), detail);
          else c.error(msg, sl.col, sl.col + 9, sl.key, detail);
          return;
        }
      Location loc = cards[0].where(1, 80);
      diag_.add(msg, loc, std::string(p.key) + ": " + detail);
    });
    md.title += md.title.empty() ? "(DYNA3D type 71, read as type 3)" : "";
  }

  // What material card 1 settles for the cards after it.
  struct MaterialHead {
    const MaterialType* mt = nullptr;
    const EosForm* eos_form = nullptr;
    bool type71 = false;
    long long et = 0;   // element type
    int slot = -1;      // 0-based slot in m_.materials (-1: a bad or repeated number)
  };

  void read_materials() {
    const int n = m_.control.nmmat;
    m_.materials.assign(static_cast<std::size_t>(n), MaterialData{});
    std::vector<int> first_line(static_cast<std::size_t>(n), 0);
    for (int s = 1; s <= n; ++s) read_material_set(s, first_line);
    for (int k = 0; k < n; ++k) {
      if (first_line[std::size_t(k)] == 0 && n > 0) {
        Location loc;
        loc.file = deck_.name();
        diag_.add(1204, loc, "material " + std::to_string(k + 1) + " is never defined");
      }
    }
  }

  // One material set: card 1, rgb lines, the title card, cards 3-8, then the section and EOS
  // cards its element type and EOS form ask for.
  void read_material_set(int s, std::vector<int>& first_line) {
    const int n = m_.control.nmmat;
    Card c1 = next("material set " + std::to_string(s) + " card 1", "expected " + std::to_string(n) + " material sets (control card 2 NMMAT)");
    FixedValues v(c1, fixed_card_layout("material card 1", vintage_));
    MaterialData md;
    md.line = c1.line();
    MaterialHead h;
    h.slot = material_number(v, md, first_line);
    read_material_card1(v, md, h);
    const std::string name = "material " + std::to_string(md.number);
    while (skip_rgb_line()) {}
    Card c2 = next(name + " card 2 (title)");
    const FixedField& ft = fixed_card_layout("material title card", vintage_).field("title");
    md.title = c2.a(ft.c1, ft.c2);
    while (!md.title.empty() && md.title.back() == ' ') md.title.pop_back();
    std::vector<Card> cards;
    for (int k = 3; k <= 8; ++k) cards.push_back(next(name + " card " + std::to_string(k)));
    if (h.mt && h.type71) read_type71_params(md, *h.mt, cards);
    else if (h.mt) read_material_params(md, *h.mt, cards);
    if (const char* feature = nullptr; h.mt && md.shell) {
      if (const MaterialParam* q = refused_shell_param(md, &feature); q && q->fcard >= 3)
        cards[std::size_t(q->fcard - 3)].error(1102, q->fcol, q->fcol + 9, q->key, std::string(feature) + " (a shell material, element type 2)");
    }
    if (md.shell) read_shell_section(md, name);
    if (h.et == 1) read_beam_section(md, name);
    if (h.eos_form && (!h.mt || h.mt->accepts_eos) && !md.shell) read_eos_cards(md, *h.eos_form, name);  // (a type that takes none: reported, no cards read)
    // rigid-body constraints in a local system need *DEFINE_COORDINATE_SYSTEM (keyword decks)
    if (const MaterialParam* cmo = h.mt && md.type == 20 ? find_param(*h.mt, "CMO") : nullptr; cmo && md.par.size() > 3 && md.par[3] == -1)
      cards[std::size_t(cmo->fcard - 3)].error(1102, cmo->fcol, cmo->fcol + 9, cmo->fname,
                                               "constraints in a local system (CMO = -1: keyword decks, *DEFINE_COORDINATE_SYSTEM)");
    if (h.slot >= 0) m_.materials[std::size_t(h.slot)] = md;
  }

  // Material numbers are labels (INGRID numbers sets 1, 13, 12 with NMMAT 3): a label 1..NMMAT
  // takes its own slot when free, any other the first free slot; elements refer to labels
  // (material_slot).  Returns the slot, or -1 for a bad or repeated number.
  int material_number(const FixedValues& v, MaterialData& md, std::vector<int>& first_line) {
    const int n = m_.control.nmmat;
    md.number = int(v.integer("material number"));
    if (md.number < 1 || md.number > 99999) {
      v.error(1201, "material number", "must be a positive number");
      return -1;
    }
    if (const int prev = material_slot(md.number); prev > 0) {
      v.error(1200, "material number", "already defined on line " + std::to_string(first_line[std::size_t(prev - 1)]));
      return -1;
    }
    int slot = md.number <= n && first_line[std::size_t(md.number - 1)] == 0 ? md.number - 1 : -1;
    for (int q = 0; q < n && slot < 0; ++q)
      if (first_line[std::size_t(q)] == 0) slot = q;
    if (slot >= 0) {
      if (label_slot_.size() <= std::size_t(md.number)) label_slot_.resize(std::size_t(md.number) + 1, 0);
      label_slot_[std::size_t(md.number)] = slot + 1;
      first_line[std::size_t(slot)] = md.line;
    }
    return slot;
  }

  // Material card 1 (material card 1 table): type, density, EOS form, hourglass and bulk
  // viscosity, element type and formulation.
  void read_material_card1(const FixedValues& v, MaterialData& md, MaterialHead& h) {
    md.type = int(v.integer("material type"));
    // type 71 as LLNL's regression decks use it: type 3's model, parameters packed by pairs
    // (read_type71_params; the evidence: docs/dyna3d-decks.md)
    h.type71 = md.type == 71;
    if (h.type71) md.type = 3;
    h.mt = find_material_type(md.type);
    if (!h.mt) v.error(1103, "material type", "supported: " + supported_material_types());
    md.rho = v["density"];
    if (!(md.rho > 0)) v.error(1207, "density");
    read_material_eos(v, md, h);
    read_material_viscosity(v, md);
    read_element_type(v, md, h);
  }

  // The EOS form of card 1 (material/eos.h): form 1, 4 or 9, its cards after card 8.
  void read_material_eos(const FixedValues& v, MaterialData& md, MaterialHead& h) {
    const long long eos = v.integer("EOS type");
    h.eos_form = eos != 0 ? find_eos_form(int(eos)) : nullptr;
    const MaterialType* mt = h.mt;
    if (eos != 0 && !h.eos_form)
      v.error(1102, "EOS type", "EOS form " + std::to_string(eos) + " (supported: " + supported_eos_forms() + ")");
    else if (h.eos_form && mt && !mt->accepts_eos)
      v.error(1102, "EOS type", std::string("an equation of state with material type ") + std::to_string(md.type) + " " + mt->name + " (types that take one: " + eos_material_types() + ")");
    else if (eos == 0 && mt && mt->needs_eos)
      v.error(1204, "EOS type", std::string("material type ") + std::to_string(md.type) + " " + mt->name + " needs an equation of state (" + supported_eos_forms() + ")");
    md.eos.form = h.eos_form ? h.eos_form->form : 0;
  }

  // Hourglass and bulk viscosity of card 1: blank or 0 are the defaults (DYNA3D deck writers
  // fill the fields with 0.0000E+00; LS-DYNA reads 0 the same way).
  void read_material_viscosity(const FixedValues& v, MaterialData& md) {
    md.hourglass_type = int(v.integer("hourglass type"));
    if (md.hourglass_type == 0) md.hourglass_type = 1;
    if (md.hourglass_type > 5 && md.hourglass_type <= 10) {
      // DYNA3D's and LS-DYNA's later forms (6-10: assumed-strain and enhanced stiffness forms):
      // the nearest here, the exact-volume stiffness form 5, listed once (2040)
      const FixedField& f = v.field("hourglass type");
      ignored_fields_.push_back({v.card().line(), "material " + std::to_string(md.number) + " hourglass type " + std::to_string(md.hourglass_type) +
                                                      " (cols " + std::to_string(f.c1) + "-" + std::to_string(f.c2) + ") read as type 5 (stiffness, exact volume)"});
      md.hourglass_type = 5;
    } else if (md.hourglass_type < 1 || md.hourglass_type > 5)
      v.error(1006, "hourglass type", "1 viscous (DYNA3D), 2/3 Flanagan-Belytschko viscous, 4/5 stiffness");
    md.hourglass_coef = v["hourglass coefficient"];
    if (md.hourglass_coef == 0) md.hourglass_coef = 0.10;
    if (md.hourglass_coef < 0) v.error(1220, "hourglass coefficient");
    md.bulk_type = int(v.integer("bulk viscosity type"));
    if (md.bulk_type == 0) md.bulk_type = 1;
    if (md.bulk_type != 1) v.error(1006, "bulk viscosity type", "only 1 (standard)");
    md.q1 = v["quadratic bulk viscosity Q1"];
    if (md.q1 == 0) md.q1 = 1.5;
    md.q2 = v["linear bulk viscosity Q2"];
    if (md.q2 == 0) md.q2 = 0.06;
    if (md.q1 < 0) v.error(1220, "quadratic bulk viscosity Q1");
    if (md.q2 < 0) v.error(1220, "linear bulk viscosity Q2");
  }

  // Element type as DYNA3D deck writers (FEMGV's DYNA interface) settle it: 0 solid, 1 beam,
  // 2 shell, 3 thick shell; and the element formulation each takes.
  void read_element_type(const FixedValues& v, MaterialData& md, MaterialHead& h) {
    const long long et = v.integer("element type");
    h.et = et;
    if (et == 3) v.error(1102, "element type", "thick shells (element type 3): IMPACT-3D has solids (0) and shells (2)");
    else if (et != 0 && et != 1 && et != 2) v.error(1006, "element type", "0 solid, 1 beam, 2 shell, 3 thick shell");
    md.shell = et == 2;
    if (md.shell && h.mt && !has_shell_kernel(md.type))
      v.error(1103, "material type", "type " + std::to_string(md.type) + " has no shell form; shells (element type 2) take types " + shell_material_numbers());
    if (md.shell && v.integer("EOS type") != 0) v.error(1102, "EOS type", "an equation of state for shells (element type 2)");
    const long long ef = v.integer("element formulation");
    if (md.shell) {  // shells: Belytschko-Tsay (LS-DYNA ELFORM 2; 0 = the default, 2)
      if (ef != 0 && ef != 2) v.error(1102, "element formulation", "shell formulation " + std::to_string(ef) + "; only 2 (Belytschko-Tsay, also 0)");
    } else if (et != 1 && ef != 0 && ef != 1) {  // (beams: 1 Hughes-Liu)
      v.error(1102, "element formulation", "only the one-point hexahedron (0 or 1)");
    }
  }

  // The EOS cards after card 8, each parameter where its form's table puts it (material/eos.h).
  void read_eos_cards(MaterialData& md, const EosForm& form, const std::string& name) {
    std::vector<Card> ec;
    const std::vector<int>& ew = eos_fixed_widths(form);
    for (std::size_t c = 0; c < ew.size(); ++c) ec.push_back(next(name + " EOS card " + std::to_string(c + 1)));
    for (const EosParam& p : form.params) {
      if (p.fcard < 0) continue;
      const int w = ew[std::size_t(p.fcard)], a = 1 + w * p.ffield;
      eos_value(md.eos, p) = ec[std::size_t(p.fcard)].e(a, a + w - 1, p.key, p.slot == kEosSlotV0 ? 1.0 : 0.0);
    }
    check_eos(md.eos, md.rho, [&](const EosParam& p, int msg, const std::string& detail) {
      const int c = p.fcard < 0 ? 0 : p.fcard, w = ew[std::size_t(c)], a = 1 + w * (p.fcard < 0 ? 0 : p.ffield);
      ec[std::size_t(c)].error(msg, a, a + w - 1, p.key, detail);
    });
  }

  // 1-based slot of material label `label` (0: no such material).
  int material_slot(long long label) const {
    return label >= 0 && std::size_t(label) < label_slot_.size() ? label_slot_[std::size_t(label)] : 0;
  }
  std::vector<int> label_slot_;

  // Node cards (node card table): number, boundary code, x y z, rotational code.  Plain cards
  // whose every field reads and passes are taken by the fast path (read_plain_node).
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
    const FixedCardLayout& layout = sized_layout("node card");
    const int after = layout.field("rotational code").c2 + 1;  // the first column not read
    // the columns after the rotational code are not read: some writers put a code there
    read_numbered_cards(
        n, layout, after, {"node", "NUMNP", "node", "the rotational code"}, seen,
        [&] { return read_plain_node(layout, seen); }, [&](FixedValues& v) { read_node_card(v, seen); });
  }

  // Card number id (1..n, control card 2's `count`) of a numbered table, seen on the card's line;
  // false (error 1201 or 1200 on `field`, "<what> N already defined") when it is out of range
  // or seen before.
  static bool claim_number(const FixedValues& v, long long id, int n, const char* field, const char* what, const char* count,
                           std::vector<int>& seen) {
    if (id < 1 || id > n) {
      v.error(1201, field, "must be 1.." + std::to_string(n) + " (" + count + ")");
      return false;
    }
    if (seen[std::size_t(id - 1)]) {
      v.error(1200, field, std::string(what) + " " + std::to_string(id) + " already defined on line " + std::to_string(seen[std::size_t(id - 1)]));
      return false;
    }
    seen[std::size_t(id - 1)] = v.card().line();
    return true;
  }

  // How read_numbered_cards names a table's cards in messages.
  struct NumberedCards {
    const char* what;     // "node": "node card 3 of 8", "node number(s) never defined"
    const char* count;    // control card 2's count: "NUMNP"
    const char* id_word;  // "node card for node 17"
    const char* last;     // the last field read: "after the rotational code"
  };

  // The n cards of a numbered table (nodes, solid elements): each taken by plain() (the fast
  // path) or else read as a Card by full(); text in the columns from `after` on (not read) is
  // warning 2020 (counted, the first named); numbers never defined are error 1204.
  template <class Plain, class Full>
  void read_numbered_cards(int n, const FixedCardLayout& layout, int after, const NumberedCards& names, std::vector<int>& seen,
                           Plain&& plain, Full&& full) {
    int unread = 0;  // cards with text after the last field
    Location unread_where;
    const std::string what = names.what, id_word = names.id_word;
    for (int k = 0; k < n; ++k) {
      if (plain()) continue;
      Card c = next(what + " card " + std::to_string(k + 1) + " of " + std::to_string(n),
                    "expected " + std::to_string(n) + " " + what + " cards (control card 2 " + names.count + "), found " + std::to_string(k));
      FixedValues v(c, layout, [&](long long id) { return what + " card for " + id_word + " " + std::to_string(id); });
      if (!c.blank(after, 80) && unread++ == 0) unread_where = c.where(after, 80, "unread columns");
      full(v);
    }
    if (unread)
      diag_.add(2020, unread_where, std::to_string(unread) + " " + what + " card(s) (this is the first) hold text in columns " +
                                        std::to_string(after) + "-80, after " + names.last + ": IMPACT-3D reads nothing there");
    report_missing(seen, what.c_str());
  }

  // The next node card read without a Card when it is plain and every field passes (nothing to
  // report); false leaves it for read_node_card.
  bool read_plain_node(const FixedCardLayout& layout, std::vector<int>& seen) {
    const DeckLine* l = plain_next_card();
    if (!l) return false;
    const std::string_view t = l->text;
    const FixedField &fi = layout.fields[0], &fb = layout.fields[1], &fx = layout.fields[2], &fy = layout.fields[3],
                     &fz = layout.fields[4], &fr = layout.fields[5];
    const int n = m_.control.numnp;
    int id = 0, code = 0, rc = 0;
    double x = 0, y = 0, z = 0;
    if (!(fast_int(t, fi.c1, fi.c2, id) && fast_code(t, fb.c1, fb.c2, code) && fast_real(t, fx.c1, fx.c2, x) &&
          fast_real(t, fy.c1, fy.c2, y) && fast_real(t, fz.c1, fz.c2, z) && fast_code(t, fr.c1, fr.c2, rc) && code >= 0 &&
          code <= 7 && rc == 0 && id >= 1 && id <= n && !seen[std::size_t(id - 1)] &&
          card_columns(t, fr.c2 + 1, 80).find_first_not_of(" \r") == std::string_view::npos))
      return false;
    deck_.next_card();
    seen[std::size_t(id - 1)] = l->number;
    m_.x[std::size_t(id - 1)] = x;
    m_.y[std::size_t(id - 1)] = y;
    m_.z[std::size_t(id - 1)] = z;
    m_.bc[std::size_t(id - 1)] = code;
    return true;
  }

  // One node card read by its table, every problem reported.
  void read_node_card(const FixedValues& v, std::vector<int>& seen) {
    const int n = m_.control.numnp;
    const int id = int(v.integer("node number"));
    const int code = int(v.integer("boundary code"));
    const int rc = int(v.integer("rotational code"));
    if (code < 0 || code > 7) v.error(1216, "boundary code");
    if (rc < 0 || rc > 7) v.error(1216, "rotational code");
    else if (rc != 0 && id >= 1 && id <= n) {
      // the rotations it fixes act on shell nodes (read_shells); on the others: warning 2005
      if (m_.rot_bc.empty()) m_.rot_bc.assign(std::size_t(n), 0);
      if (rot_code_line_.empty()) rot_code_line_.assign(std::size_t(n), 0);
      static const std::uint8_t bits[8] = {0, 1, 2, 4, 3, 6, 5, 7};  // code 0-7 -> bit 0 rx, 1 ry, 2 rz
      m_.rot_bc[std::size_t(id - 1)] = bits[rc];
      rot_code_line_[std::size_t(id - 1)] = v.card().line();
    }
    if (!claim_number(v, id, n, "node number", "node", "NUMNP", seen)) return;
    m_.x[std::size_t(id - 1)] = v["x"];
    m_.y[std::size_t(id - 1)] = v["y"];
    m_.z[std::size_t(id - 1)] = v["z"];
    m_.bc[std::size_t(id - 1)] = (code >= 0 && code <= 7) ? code : 0;
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

  // Solid element cards (solid element card table): number, material label, nodes n1-n8.
  // Plain cards whose every field reads and passes take the fast path (read_plain_solid).
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
    const FixedCardLayout& layout = sized_layout("solid element card");
    const int after = layout.field("node n8").c2 + 1;  // the first column not read
    read_numbered_cards(
        n, layout, after, {"solid element", "NUMELH", "element", "node n8"}, seen,
        [&] { return read_plain_solid(layout, seen); }, [&](FixedValues& v) { read_solid_card(v, seen); });
  }

  // The next solid element card read without a Card when it is plain and every field passes;
  // false leaves it for read_solid_card.  (Fields in the table's order: number, material, n1-n8.)
  bool read_plain_solid(const FixedCardLayout& layout, std::vector<int>& seen) {
    const DeckLine* l = plain_next_card();
    if (!l) return false;
    const std::string_view t = l->text;
    const FixedField &fi = layout.fields[0], &fm = layout.fields[1];
    const int n = m_.control.numelh;
    int id = 0, mat = 0;
    std::array<int, 8> nodes{};
    bool ok = fast_int(t, fi.c1, fi.c2, id) && fast_int(t, fm.c1, fm.c2, mat) && (mat = material_slot(mat)) > 0 && id >= 1 && id <= n &&
              !seen[std::size_t(id - 1)] && mat >= 1 && mat <= m_.control.nmmat;
    for (int j = 0; j < 8 && ok; ++j) {
      const FixedField& f = layout.fields[std::size_t(2 + j)];
      ok = fast_int(t, f.c1, f.c2, nodes[std::size_t(j)]) && nodes[std::size_t(j)] >= 1 && nodes[std::size_t(j)] <= m_.control.numnp;
      --nodes[std::size_t(j)];
    }
    if (!ok || !is_valid_solid_node_pattern(nodes) ||
        card_columns(t, layout.fields[9].c2 + 1, 80).find_first_not_of(" \r") != std::string_view::npos)
      return false;
    deck_.next_card();
    seen[std::size_t(id - 1)] = l->number;
    make_canonical_solid_node_pattern(nodes);
    m_.hex_line[std::size_t(id - 1)] = l->number;
    m_.hex_nodes[std::size_t(id - 1)] = nodes;
    m_.hex_material[std::size_t(id - 1)] = mat - 1;
    return true;
  }

  // One solid element card read by its table, every problem reported.
  void read_solid_card(const FixedValues& v, std::vector<int>& seen) {
    const int n = m_.control.numelh;
    const int id = int(v.integer("element number"));
    const long long label = v.integer("material number");
    const int mat = material_slot(label);
    std::array<int, 8> nodes{};
    bool ok = read_element_nodes(v, nodes.data(), 8);
    if (mat < 1 || mat > m_.control.nmmat) {
      v.error(1203, "material number", "material " + std::to_string(label) + " is not defined");
      ok = false;
    }
    if (ok && !is_valid_solid_node_pattern(nodes)) {
      const Location a = v.where("node n1"), b = v.where("node n8");
      v.card().error(1222, a.col_first, b.col_last, "nodes n1-n8");
      ok = false;
    }
    if (!claim_number(v, id, n, "element number", "element", "NUMELH", seen)) return;
    if (!ok) nodes.fill(-1);
    else make_canonical_solid_node_pattern(nodes);
    m_.hex_line[std::size_t(id - 1)] = v.card().line();
    m_.hex_nodes[std::size_t(id - 1)] = nodes;
    m_.hex_material[std::size_t(id - 1)] = ok ? mat - 1 : -1;
  }

  // Nodes n1..n<count> of an element card (0-based into `nodes`); false (error 1202) when one
  // is not a node of the deck.  A blank n4 of a shell is n3 (a triangle given with three nodes).
  bool read_element_nodes(const FixedValues& v, int* nodes, int count) {
    static const char* const nf[8] = {"node n1", "node n2", "node n3", "node n4", "node n5", "node n6", "node n7", "node n8"};
    bool ok = true;
    for (int j = 0; j < count; ++j) {
      int nid = int(v.integer(nf[j]));
      if (count == 4 && j == 3 && v.blank(nf[j])) nid = nodes[2] + 1;
      if (nid < 1 || nid > m_.control.numnp) {
        v.error(1202, nf[j], "nodes are 1.." + std::to_string(m_.control.numnp));
        ok = false;
      }
      nodes[j] = nid - 1;
    }
    return ok;
  }

  // One shell element: its card (shell element card table) and its thickness card (shell
  // thickness card table).
  void read_shell_cards(const FixedValues& v, std::vector<int>& seen) {
    const int n = numels_;
    const int id = int(v.integer("element number"));
    const long long label = v.integer("material number");
    const int mat = material_slot(label);
    std::array<int, 4> nodes{};
    bool ok = read_element_nodes(v, nodes.data(), 4);
    const int after = v.field("node n4").c2 + 1;
    if (!v.card().blank(after, 80))
      diag_.add(2020, v.card().where(after, 80, "unread columns"), "after node n4: IMPACT-3D reads nothing there");
    ok = shell_material_ok(v, mat, label) && ok;
    if (ok && (nodes[0] == nodes[1] || nodes[0] == nodes[2] || nodes[1] == nodes[2] || nodes[0] == nodes[3] || nodes[1] == nodes[3])) {
      v.card().error(1222, v.field("node n1").c1, v.field("node n4").c2, "nodes n1-n4", "a shell is a quadrilateral or a triangle with n4 = n3");
      ok = false;
    }
    std::array<double, 4> t{};
    ok = read_shell_thickness(id, t) && ok;
    if (!claim_number(v, id, n, "element number", "shell", "NUMELS", seen)) return;
    m_.shell_line[std::size_t(id - 1)] = v.card().line();
    if (!ok) return;
    if (t[0] == 0 && t[1] == 0 && t[2] == 0 && t[3] == 0) t = m_.materials[std::size_t(mat - 1)].shell_section.t;
    m_.shell_nodes[std::size_t(id - 1)] = nodes;
    m_.shell_material[std::size_t(id - 1)] = mat - 1;
    m_.shell_thickness[std::size_t(id - 1)] = t;
  }

  // A shell's material label must name a shell material (element type 2); else 1203.
  bool shell_material_ok(const FixedValues& v, int mat, long long label) {
    if (mat < 1 || mat > m_.control.nmmat) {
      v.error(1203, "material number", "material " + std::to_string(label) + " is not defined");
      return false;
    }
    if (!(mat <= int(m_.materials.size()) && m_.materials[std::size_t(mat - 1)].shell)) {
      v.error(1203, "material number", "material " + std::to_string(label) + " is not a shell material (material card 1 columns 66-70 element type 2)");
      return false;
    }
    return true;
  }

  // The thickness card of shell `id`: t1-t4 (all 0: the section's); false for a negative one.
  bool read_shell_thickness(int id, std::array<double, 4>& t) {
    Card c2 = next("shell element " + std::to_string(id) + " thickness card",
                   "each shell element has a second card with its thicknesses t1-t4");
    FixedValues v(c2, fixed_card_layout("shell thickness card", vintage_));
    static const char* const tf[4] = {"thickness t1", "thickness t2", "thickness t3", "thickness t4"};
    bool ok = true;
    for (int j = 0; j < 4; ++j) {
      t[std::size_t(j)] = v[tf[j]];
      if (t[std::size_t(j)] < 0) { v.error(1241, tf[j]); ok = false; }
    }
    const int after = v.field("thickness t4").c2 + 1;
    if (!c2.blank(after, 80)) diag_.add(2020, c2.where(after, 80, "unread columns"), "after t4: IMPACT-3D reads nothing there");
    return ok;
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
    const FixedCardLayout& layout = sized_layout("shell element card");
    for (int k = 0; k < n; ++k) {
      Card c = next("shell element card " + std::to_string(k + 1) + " of " + std::to_string(n),
                    "expected " + std::to_string(n) + " shell elements, two cards each (control card 2 NUMELS), found " + std::to_string(k));
      FixedValues v(c, layout, [](long long id) { return "shell element card for element " + std::to_string(id); });
      read_shell_cards(v, seen);
    }
    report_missing(seen, "shell element");
    refuse_solids_of_shell_materials();
    drop_unused_rotation_codes();
  }

  // Solid element cards that name a shell material (element type 2): error 1203 on the card's
  // material field (its columns from the solid element card table).
  void refuse_solids_of_shell_materials() {
    const FixedField& f = sized_layout("solid element card").field("material number");
    for (std::size_t e = 0; e < m_.hex_material.size(); ++e) {
      const int mat = m_.hex_material[e];
      if (mat < 0 || !m_.materials[std::size_t(mat)].shell) continue;
      Location loc;
      loc.file = deck_.name();
      loc.line = m_.hex_line[e];
      loc.card = "solid element card for element " + std::to_string(e + 1);
      loc.field = f.name;
      loc.col_first = f.c1;
      loc.col_last = f.c2;
      diag_.add(1203, loc, "material " + std::to_string(mat + 1) + " is a shell material (element type 2); solids need element type 0");
      m_.hex_material[e] = -1;
      m_.hex_nodes[e].fill(-1);
    }
  }

  // Rotational codes of node cards act on shell and beam nodes; on the others they are dropped
  // (warning 2005, one for all, at the first such card's line).
  void drop_unused_rotation_codes() {
    if (rot_code_line_.empty()) return;
    const std::vector<char>& shell_node = rotation_nodes();
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

  // A node (or other id) field of a card read by its table: 1..limit, else id_error and -1.
  int read_id(const FixedValues& v, const char* field, int limit, int id_error) {
    const long long id = v.integer(field);
    if (id < 1 || id > limit) {
      v.error(id_error, field, "must be 1.." + std::to_string(limit));
      return -1;
    }
    return int(id);
  }

  bool warned_old_th_ = false;
  bool warned_old_interface_ = false;
  // Time-history blocks (control card 3): nodes, solids, beams, shells in that order, five
  // blocks (first, last) a card, each kind starting on a new card.
  void read_time_history_blocks() {
    const FixedCardLayout& layout = fixed_card_layout("time-history block card", vintage_);
    for (int which = 0; which < 4; ++which) {
      const int nb = which == 0 ? m_.control.node_th_blocks : which == 1 ? m_.control.solid_th_blocks
                   : which == 2 ? beam_th_blocks_ : shell_th_blocks_;
      const int limit = which == 0 ? m_.control.numnp : which == 1 ? m_.control.numelh : which == 2 ? numelb_ : numels_;
      const char* what = which == 0 ? "node" : which == 1 ? "solid" : which == 2 ? "beam" : "shell";
      const int err = which == 0 ? 1202 : 1201;
      for (int b = 0; b < nb;) {
        Card c = next(std::string(what) + " time-history block card " + std::to_string(b / 5 + 1),
                      "expected " + std::to_string(nb) + " " + what + " time-history blocks, five a card (control card 3)");
        FixedValues v(c, layout);
        // IMPACT-3D's old layout: one block a card (columns 17-80 blank while more blocks follow)
        const int per_card = nb - b > 1 && c.blank(v.field("first 2").c1, 80) ? 1 : 5;
        if (per_card == 1 && !warned_old_th_) {
          diag_.add(2041, c.where(v.field("first 1").c1, v.field("last 1").c2), "one time-history block a card is IMPACT-3D's old layout; DYNA3D's has five a card "
                                          "(impact3d i=DECK --write-fixed=NEW writes it)");
          warned_old_th_ = true;
        }
        const int start = b;
        b += per_card;
        for (int j = 0; j < per_card && start + j < nb; ++j) {
          const std::string fn = "first " + std::to_string(j + 1), ln = "last " + std::to_string(j + 1);
          const long long first = v.integer(fn);
          const long long last = v.blank(ln) ? first : v.integer(ln);
          if (first < 1 || first > limit) { v.error(err, fn, "must be 1.." + std::to_string(limit)); continue; }
          if (last < 1 || last > limit) { v.error(err, ln, "must be 1.." + std::to_string(limit)); continue; }
          if (last < first) { v.error(1003, ln, "must not be below first"); continue; }
          const std::array<int, 2> blk{int(first), int(last)};
          if (which == 0) m_.node_th_blocks.push_back(blk);
          else if (which == 1) m_.solid_th_blocks.push_back(blk);
          else if (which == 2) m_.beam_th_blocks.push_back(blk);
          else if (which == 3) m_.shell_th_blocks.push_back(blk);
        }
      }
    }
  }

  // Load curves (control card 5 NUMLC): a header card (load curve header card table), then a
  // card a point (load curve point card table).
  void read_load_curves() {
    for (int k = 0; k < m_.control.numlc; ++k) {
      Card c = next("load curve " + std::to_string(k + 1) + " header card",
                    "expected " + std::to_string(m_.control.numlc) + " load curves (control card 5 NUMLC)");
      FixedValues v(c, fixed_card_layout("load curve header card", vintage_));
      LoadCurve lc;
      lc.number = int(v.integer("curve number"));
      int npts = int(v.integer("NPTS"));
      if (lc.number < 1 || lc.number > m_.control.numlc)
        v.error(1201, "curve number", "must be 1.." + std::to_string(m_.control.numlc));
      for (const auto& o : m_.load_curves)
        if (o.number == lc.number) v.error(1200, "curve number");
      long avail = remaining_cards();
      if (npts < 2 || npts > avail) {
        v.error(1003, "NPTS", npts < 2 ? "at least 2 points" : "more points than cards left in the deck");
        npts = std::clamp(npts, 0, int(avail));
      }
      read_curve_points(lc, npts);
      bool used = false;  // by a material (a flow stress curve)
      for (const MaterialData& md : m_.materials) used = used || material_uses_curve(md, lc.number);
      m_.load_curves.push_back(std::move(lc));
      curve_lines_.push_back(c.line());
      curve_used_.push_back(used ? 1 : 0);
    }
  }

  void read_curve_points(LoadCurve& lc, int npts) {
    const FixedCardLayout& layout = fixed_card_layout("load curve point card", vintage_);
    for (int p = 0; p < npts; ++p) {
      Card pc = next("load curve " + std::to_string(lc.number) + " point " + std::to_string(p + 1));
      FixedValues v(pc, layout);
      const double t = v["time"], f = v["value"];
      if (!lc.t.empty() && !(t > lc.t.back())) v.error(1217, "time");
      lc.t.push_back(t);
      lc.f.push_back(f);
    }
  }

  // 0-based index of the load curve named in field `field` (1..NUMLC), or -1 (error 1201)
  int read_curve_ref(const FixedValues& v, const char* field = "load curve") {
    const long long n = v.integer(field);
    for (std::size_t k = 0; k < m_.load_curves.size(); ++k)
      if (m_.load_curves[k].number == n) {
        curve_used_[k] = 1;
        return int(k);
      }
    v.error(1201, field, "must be one of the deck's curves 1.." + std::to_string(m_.control.numlc));
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

  // direction 1-3 (x y z) of field "direction" as a unit vector; false (error) otherwise
  bool read_direction(const FixedValues& v, std::array<double, 3>& dir) {
    const long long d = v.integer("direction");
    if (d < 1 || d > 3) {
      v.error(d >= 4 && d <= 6 ? 1102 : 1006, "direction", d >= 4 && d <= 6 ? "moments and rotations (solid nodes have none)" : "1 x, 2 y, 3 z");
      return false;
    }
    dir = {0, 0, 0};
    dir[std::size_t(d - 1)] = 1;
    return true;
  }

  // Concentrated nodal loads (card 5 field 2), nodal load card table: node, direction 1-3,
  // load curve, scale.
  void read_nodal_loads() {
    const int n = m_.control.num_nodal_load_cards;
    const FixedCardLayout& layout = sized_layout("nodal load card");
    for (int k = 0; k < n; ++k) {
      Card c = next("nodal load card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " nodal load cards (control card 5)");
      FixedValues v(c, layout);
      NodalLoad l;
      const int node = read_id(v, "node", m_.control.numnp, 1202);
      bool ok = node >= 1;
      ok = read_direction(v, l.dir) && ok;
      l.curve = read_curve_ref(v);
      l.scale = v["scale factor"];
      l.node = node - 1;
      l.line = c.line();
      if (ok && l.curve >= 0) m_.nodal_loads.push_back(l);
    }
  }

  // Pressure-loaded element sides (card 5 field 3), one card each (pressure card table): load
  // curve, four nodes, four nodal multipliers (blank: 1).  IMPACT-3D's old large-format layout
  // put the multipliers on a second card with an arrival time in 71-80: still read (warning
  // 2041) when the second card is unmistakably that.
  void read_pressure_loads() {
    const int n = m_.control.num_pressure_cards;
    const FixedCardLayout& layout = sized_layout("pressure card");
    static const char* const mult[4] = {"multiplier 1", "multiplier 2", "multiplier 3", "multiplier 4"};
    for (int k = 0; k < n; ++k) {
      Card c = next("pressure card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " pressure cards (control card 5)");
      FixedValues v(c, layout);
      PressureLoad p;
      p.line = c.line();
      p.curve = read_curve_ref(v);
      bool ok = read_pressure_nodes(v, p) && p.curve >= 0;
      const int after = v.field("node n4").c2 + 1;
      if (m_.large_format && c.blank(after, 80) && old_pressure_multiplier_card_follows()) {
        read_old_pressure_multipliers(p, k);
      } else {
        for (int q = 0; q < 4; ++q) p.factor[std::size_t(q)] = v[mult[q]];
        if (!m_.large_format) p.birth = v["arrival time"];
      }
      if (ok) m_.pressure_loads.push_back(p);
    }
  }

  // The four nodes of a pressure card; false when one is not a node of the deck (1202).
  bool read_pressure_nodes(const FixedValues& v, PressureLoad& p) {
    static const char* const nf[4] = {"node n1", "node n2", "node n3", "node n4"};
    bool ok = true;
    for (int q = 0; q < 4; ++q) {
      const int id = read_id(v, nf[q], m_.control.numnp, 1202);
      if (id < 1) ok = false;
      p.nodes[std::size_t(q)] = id - 1;
    }
    return ok;
  }

  // IMPACT-3D's old large-format pressure layout: the multipliers on a second card, an
  // arrival time in 71-80 (old pressure multiplier card table; warning 2041 once).
  void read_old_pressure_multipliers(PressureLoad& p, int k) {
    Card c2 = next("pressure card " + std::to_string(k + 1) + " multipliers (old IMPACT-3D layout)");
    if (!warned_old_pressure_) {
      const FixedCardLayout& now = fixed_card_layout("pressure card", vintage_);
      diag_.add(2041, c2.where(1, 80), "pressure multipliers on a second card are IMPACT-3D's old layout; DYNA3D's is one card with them in columns " +
                                           std::to_string(now.field("multiplier 1").c1) + "-" + std::to_string(now.field("multiplier 4").c2) +
                                           " (impact3d i=DECK --write-fixed=NEW writes it)");
      warned_old_pressure_ = true;
    }
    FixedValues v(c2, fixed_card_layout("old IMPACT-3D pressure multiplier card", vintage_));
    static const char* const mult[4] = {"multiplier 1", "multiplier 2", "multiplier 3", "multiplier 4"};
    for (int q = 0; q < 4; ++q) p.factor[std::size_t(q)] = v[mult[q]];
    p.birth = v["arrival time"];
  }
  bool warned_old_pressure_ = false;

  // The old layout's second pressure card: reals in 1-40 (with a decimal point or exponent)
  // and nothing in 41-70; a DYNA3D pressure card starts with an I5 curve and I8 nodes instead.
  bool old_pressure_multiplier_card_follows() {
    const DeckLine* l = deck_.peek_card();
    if (!l) return false;
    const std::string_view t = l->text;
    const FixedCardLayout& old = fixed_card_layout("old IMPACT-3D pressure multiplier card", vintage_);
    const FixedField &last = old.field("multiplier 4"), &arrival = old.field("arrival time");
    if (card_columns(t, last.c2 + 1, arrival.c1 - 1).find_first_not_of(' ') != std::string_view::npos) return false;
    for (int q = 0; q < 4; ++q) {
      const FixedField& m = old.fields[std::size_t(q)];
      const std::string_view f = card_columns(t, m.c1, m.c2);
      double x = 0;
      if (f.find_first_of(".eEdD") == std::string_view::npos || parse_fortran_real(f, x) != FieldStatus::ok) return false;
    }
    return true;
  }

  // Velocity / acceleration / displacement boundary conditions (card 5 field 4), one card each
  // as DYNA3D decks write them (velocity/acceleration boundary card table): node, load curve,
  // DOF (1-3 an axis, 4 along the vector vx vy vz; 5-7 rotations: refused), scale, the vector,
  // type (0 velocity, 1 acceleration, 2 displacement), birth time (IMPACT-3D: 64-73).
  void read_prescribed_motions() {
    const int n = m_.control.num_motion_cards;
    const FixedCardLayout& layout = fixed_card_layout("velocity/acceleration boundary card", vintage_);
    for (int k = 0; k < n; ++k) {
      Card c = next("velocity/acceleration boundary card " + std::to_string(k + 1),
                    "expected " + std::to_string(n) + " velocity/acceleration boundary cards (control card 5)");
      if (old_motion_layout(c)) {
        refuse_old_motion_card(c, layout);
        continue;
      }
      FixedValues v(c, layout);
      PrescribedMotion pm;
      const long long node = v.integer("node");
      bool ok = true;
      if (node < 1 || node > m_.control.numnp) { v.error(1202, "node", "must be 1.." + std::to_string(m_.control.numnp)); ok = false; }
      pm.curve = read_curve_ref(v);
      ok = motion_direction(v, node, pm) && ok;
      pm.scale = v["scale factor"];
      const long long type = v.integer("type");
      if (type < 0 || type > 2) { v.error(1006, "type", "0 velocity, 1 acceleration, 2 displacement"); ok = false; }
      pm.kind = MotionKind(int(std::clamp<long long>(type, 0, 2)));
      pm.birth = v["birth time"];
      const double death = v["death time"];
      pm.death = death > 0 ? death : 1e28;
      if (death < 0) v.error(1003, "death time", "must not be negative (0 or blank: never)");
      pm.node = int(node) - 1;
      pm.line = c.line();
      if (ok && pm.curve >= 0) m_.prescribed_motions.push_back(pm);
    }
  }

  // The direction of a motion card's DOF: 1-3 an axis, 4 along (vx, vy, vz), 5-7 a rotation
  // about an axis (type 0 only, of a node with rotations); false after an error.
  bool motion_direction(const FixedValues& v, long long node, PrescribedMotion& pm) {
    const long long dof = v.integer("DOF");
    pm.dir = {0, 0, 0};
    if (dof >= 1 && dof <= 3) {
      pm.dir[std::size_t(dof - 1)] = 1;
      return true;
    }
    if (dof == 4) {
      const double vx = v["vx"], vy = v["vy"], vz = v["vz"];
      const double len = std::sqrt(vx * vx + vy * vy + vz * vz);
      if (!(len > 0)) { v.error(1213, "vx", "DOF 4 moves along the vector (vx, vy, vz), which is zero"); return false; }
      pm.dir = {vx / len, vy / len, vz / len};
      return true;
    }
    if (dof < 5 || dof > 7) {
      v.error(1006, "DOF", "1-3 x y z, 4 along a vector, 5-7 rotations");
      return false;
    }
    pm.rotation = true;  // a rotational velocity about x, y, z of a shell or beam node
    pm.dir[std::size_t(dof - 5)] = 1;
    bool ok = true;
    if (v.integer("type") != 0) { v.error(1102, "type", "prescribed rotational accelerations and displacements (DOF 5-7 take type 0)"); ok = false; }
    if (node >= 1 && node <= m_.control.numnp && !has_rotations(int(node) - 1)) {
      v.error(1102, "node", "a prescribed rotation of a node no shell or beam uses (it has no rotations)");
      ok = false;
    }
    return ok;
  }

  // Whether node n (0-based) carries rotations: a shell's or a beam's end node.
  bool has_rotations(int n) { return n >= 0 && std::size_t(n) < rotation_nodes().size() && rotation_nodes()[std::size_t(n)]; }
  // Per node: 1 when a shell or a beam end uses it (built once, after the element cards).
  const std::vector<char>& rotation_nodes() {
    if (rotation_nodes_.size() != std::size_t(m_.control.numnp)) {
      rotation_nodes_.assign(std::size_t(m_.control.numnp), 0);
      for (const auto& q : m_.shell_nodes)
        for (int v : q)
          if (v >= 0) rotation_nodes_[std::size_t(v)] = 1;
      for (const auto& b : m_.beam_nodes)
        for (int j = 0; j < 2; ++j)
          if (b[std::size_t(j)] >= 0) rotation_nodes_[std::size_t(b[std::size_t(j)])] = 1;
    }
    return rotation_nodes_;
  }
  std::vector<char> rotation_nodes_;

  // IMPACT-3D's old motion card (its table): an I5 type (no decimal point, no exponent)
  // followed by a real birth time, where DYNA3D's layout has one real (vx).
  static bool old_motion_layout(const Card& c) {
    const FixedCardLayout& old = fixed_card_layout("old IMPACT-3D velocity/acceleration boundary card", FixedVintage::dyna3d_later);
    const FixedField &ft = old.field("type"), &fb = old.field("birth");
    const std::string_view type = c.columns(ft.c1, ft.c2), birth = c.columns(fb.c1, fb.c2);
    if (type.find_first_not_of(' ') == std::string_view::npos) return false;
    if (type.find_first_of(".eEdD") != std::string_view::npos) return false;
    long long t = 0;
    double b = 0;
    return parse_fortran_int(type, t) == FieldStatus::ok && birth.find_first_not_of(' ') != std::string_view::npos &&
           parse_fortran_real(birth, b) == FieldStatus::ok;
  }

  // Error 1006 over the old card's fields, naming the columns of both layouts.
  static void refuse_old_motion_card(Card& c, const FixedCardLayout& now) {
    const FixedCardLayout& old = fixed_card_layout("old IMPACT-3D velocity/acceleration boundary card", FixedVintage::dyna3d_later);
    auto cols = [](const FixedField& f) { return std::to_string(f.c1) + "-" + std::to_string(f.c2); };
    auto span = [](const FixedField& a, const FixedField& b) { return std::to_string(a.c1) + "-" + std::to_string(b.c2); };
    const FixedField &od = old.field("direction"), &oc = old.field("curve");
    c.error(1006, od.c1, old.field("death").c2, "node/direction/curve/scale/type/birth/death",
            "this is IMPACT-3D's old layout (direction " + cols(od) + ", curve " + cols(oc) + ", type " + cols(old.field("type")) +
                ", birth " + cols(old.field("birth")) + ", death " + cols(old.field("death")) + "); DYNA3D's is curve " +
                cols(now.field("load curve")) + ", DOF " + cols(now.field("DOF")) + ", scale " + cols(now.field("scale factor")) +
                ", vector " + span(now.field("vx"), now.field("vz")) + ", type " + cols(now.field("type")) + ": swap columns " +
                cols(od) + " and " + cols(oc) + " and move the type to " + cols(now.field("type")));
  }

  // Base accelerations (card 5 fields 9-11), one card per direction flagged, in x y z order
  // (an IMPACT-3D layout, base acceleration card table): load curve, scale.  Every node gets
  // the acceleration -scale * curve(t) along the axis (LS-DYNA's *LOAD_BODY sign).
  void read_base_accelerations() {
    for (int a = 0; a < 3; ++a) {
      if (!m_.control.base_acceleration[std::size_t(a)]) continue;
      const char* axis = a == 0 ? "x" : a == 1 ? "y" : "z";
      Card c = next(std::string("base acceleration card (") + axis + ")");
      FixedValues v(c, fixed_card_layout("base acceleration card", vintage_));
      BodyLoad b;
      b.dir[std::size_t(a)] = 1;
      b.curve = read_curve_ref(v);
      b.scale = v["scale factor"];
      b.line = c.line();
      if (b.curve >= 0) m_.body_loads.push_back(b);
    }
  }

  // `count` nodes on node list cards (node list card table: ten I8 a card, sixteen I5 in the
  // small format).
  void read_node_list(std::vector<int>& out, int count, const std::string& what) {
    const FixedCardLayout& layout = sized_layout("node list card");
    const int per = int(layout.fields.size());
    const int cards = (count + per - 1) / per;
    int k = 0;
    for (int cc = 0; cc < cards; ++cc) {
      Card c = next(what + " node card " + std::to_string(cc + 1));
      FixedValues v(c, layout);
      for (int f = 0; f < per && k < count; ++f, ++k) {
        const int id = read_id(v, layout.fields[std::size_t(f)].name, m_.control.numnp, 1202);
        if (id > 0) out.push_back(id - 1);
      }
    }
  }

  // Stonewalls (control card 5 field 5): the stonewall card, the moving stonewall card when
  // flagged, then NSN slave nodes on node list cards.
  void read_stonewalls() {
    for (int w = 0; w < m_.control.num_walls; ++w) {
      const std::string name = "stonewall " + std::to_string(w + 1);
      Card c = next(name + " card 1", "expected " + std::to_string(m_.control.num_walls) + " stonewalls (control card 5)");
      FixedValues v(c, fixed_card_layout("stonewall card", vintage_));
      StoneWall sw;
      sw.line = c.line();
      const int nsn = read_stonewall_card(v, sw);
      if (v.integer("moving flag") != 0) {  // IMPACT-3D choice: MASS and V0
        Card c2 = next(name + " card 2 (moving wall)", "expected the moving wall's MASS and V0 card");
        FixedValues v2(c2, fixed_card_layout("moving stonewall card", vintage_));
        sw.mass = v2["MASS"];
        sw.v0 = v2["V0"];
        if (!(sw.mass > 0)) v2.error(1003, "MASS", "a moving wall needs a positive mass");
      }
      read_node_list(sw.nodes, nsn, name);
      remove_repeated_nodes(sw.nodes);
      m_.walls.push_back(std::move(sw));
    }
  }

  // The stonewall card: the plane (tail, head of its normal), friction; returns NSN.
  int read_stonewall_card(const FixedValues& v, StoneWall& sw) {
    int nsn = int(v.integer("NSN"));
    v.flag01("moving flag", "0 fixed, 1 moving (a card with MASS and V0 follows)");  // read again by the caller
    static const char* const names[] = {"XT", "YT", "ZT", "XH", "YH", "ZH"};
    for (int f = 0; f < 3; ++f) sw.tail[std::size_t(f)] = v[names[f]];
    for (int f = 0; f < 3; ++f) sw.head[std::size_t(f)] = v[names[3 + f]];
    sw.friction = v["FRIC"];
    double dx = sw.head[0] - sw.tail[0], dy = sw.head[1] - sw.tail[1], dz = sw.head[2] - sw.tail[2];
    double len = std::sqrt(dx * dx + dy * dy + dz * dz);
    double scale = 0;
    for (int f = 0; f < 3; ++f) scale = std::max({scale, std::fabs(sw.head[std::size_t(f)]), std::fabs(sw.tail[std::size_t(f)])});
    if (!(len > 1e-12 * scale) || len == 0) v.card().error(1213, v.field("XT").c1, v.field("ZH").c2, "XT-ZH", {}, false);
    if (!(sw.friction >= 0 && sw.friction <= 1)) v.error(1219, "FRIC");
    if (nsn < 0 || nsn > m_.control.numnp) {
      v.error(1003, "NSN", "0 (all nodes) to NUMNP");
      nsn = 0;
    }
    return nsn;
  }

  // Initial conditions (control card 5 field 7).  1: nodal velocity cards as DYNA3D reads
  // them (initial velocity card table), until the last node (NUMNP) is given; nodes skipped
  // between two cards get velocities interpolated linearly in the node number.  IMPACT-3D's own
  // extension stays readable: node 0 (all nodes), or a last node (39-46) and increment (47-51)
  // after the velocities; with such a card, or a parameter above 1 (IMPACT-3D's old meaning:
  // that many cards), the count of cards is the parameter.
  void read_initial_velocities() {
    const int param = m_.control.num_init_velocity_cards;
    if (param == 0) return;
    const int nn = m_.control.numnp;
    const FixedCardLayout& layout = fixed_card_layout("initial velocity card", vintage_);
    int prev_node = 0;
    std::array<double, 3> prev_v{};
    for (int k = 0;; ++k) {
      if (param > 1 && k >= param) return;
      const DeckLine* l = deck_.peek_card();
      const bool extended = l && (card_columns(l->text, 39, 51).find_first_not_of(' ') != std::string_view::npos ||
                                  card_columns(l->text, 1, 8).find_first_not_of(" 0") == std::string_view::npos);
      if (k == 0 && extended && param == 1) {  // one IMPACT-3D card: a range or all nodes
        read_range_velocity_card(1);
        return;
      }
      if (param > 1) {
        read_range_velocity_card(k + 1);
        continue;
      }
      Card c = next("initial velocity card " + std::to_string(k + 1),
                    "initial velocities are read until node " + std::to_string(nn) + " (NUMNP) is given (control card 5 field 7 = 1)");
      FixedValues v(c, layout);
      const long long node = v.integer("node");
      const std::array<double, 3> vel{v["vx"], v["vy"], v["vz"]};
      if (node <= prev_node || node > nn) {
        v.error(node > nn || node < 1 ? 1202 : 1223, "node", "nodes in increasing order, " + std::to_string(prev_node + 1) + ".." + std::to_string(nn));
        if (node > nn || node < 1) return;
        continue;
      }
      for (long long j = prev_node + 1; j <= node; ++j) {  // skipped nodes interpolated (first card: its own velocity)
        InitialVelocity iv;
        iv.first = iv.last = int(j);
        const double f = prev_node == 0 ? 1.0 : double(j - prev_node) / double(node - prev_node);
        for (int q = 0; q < 3; ++q) iv.v[std::size_t(q)] = prev_v[std::size_t(q)] + f * (vel[std::size_t(q)] - prev_v[std::size_t(q)]);
        if (iv.v[0] != 0 || iv.v[1] != 0 || iv.v[2] != 0) append_velocity(iv);
      }
      prev_node = int(node);
      prev_v = vel;
      if (node == nn) return;
    }
  }

  // Consecutive single-node cards with the same velocity become one range (the model keeps
  // few records for a deck that lists every node).
  void append_velocity(const InitialVelocity& iv) {
    auto& all = m_.init_velocities;
    if (!all.empty() && all.back().v == iv.v && all.back().increment == 1 && all.back().last + 1 == iv.first && all.back().first != 0) {
      all.back().last = iv.last;
      return;
    }
    all.push_back(iv);
  }

  // IMPACT-3D's initial velocity card (initial velocity range card table): all nodes (node 0)
  // or the nodes first..last by increment.
  void read_range_velocity_card(int k) {
    Card c = next("initial-velocity card " + std::to_string(k),
                  "expected " + std::to_string(m_.control.num_init_velocity_cards) + " initial-velocity cards (control card 5)");
    FixedValues v(c, fixed_card_layout("initial velocity range card", vintage_));
    InitialVelocity iv;
    iv.first = int(v.integer("first node"));
    iv.v = {v["vx"], v["vy"], v["vz"]};
    iv.last = v.blank("last node") ? iv.first : int(v.integer("last node"));
    iv.increment = int(v.integer("increment"));
    if (iv.increment == 0) iv.increment = 1;
    bool ok = true;
    const int nn = m_.control.numnp;
    if (iv.first < 0 || iv.first > nn) { v.error(1202, "first node", "0 (all nodes) or 1.." + std::to_string(nn)); ok = false; }
    if (iv.first != 0 && (iv.last < 1 || iv.last > nn)) { v.error(1202, "last node", "1.." + std::to_string(nn)); ok = false; }
    if (iv.increment < 0) { v.error(1003, "increment", "must be positive"); ok = false; }
    if (ok && iv.first != 0 && iv.last < iv.first) { v.error(1223, "last node"); ok = false; }
    if (ok) m_.init_velocities.push_back(iv);
  }

  // Segment cards (segment card table): segment number (read, not used), nodes n1-n4.
  void read_segments(std::vector<std::array<int, 4>>& out, std::vector<int>& lines, int count,
                     const std::string& what) {
    const FixedCardLayout& layout = sized_layout("segment card");
    static const char* const nf[4] = {"node n1", "node n2", "node n3", "node n4"};
    for (int s = 0; s < count; ++s) {
      Card c = next(what + " segment card " + std::to_string(s + 1) + " of " + std::to_string(count));
      FixedValues v(c, layout);
      std::array<int, 4> seg{};
      bool ok = true;
      for (int j = 0; j < 4; ++j) {
        const int id = read_id(v, nf[j], m_.control.numnp, 1202);
        if (id < 1) ok = false;
        seg[std::size_t(j)] = id - 1;
      }
      if (ok) {
        out.push_back(seg);
        lines.push_back(c.line());
      }
    }
  }

  // Sliding interfaces (control card 5 field 8): every control card first, then each
  // interface's slave and master segment cards.  A "lagop ... endfree" free-format block may
  // follow a control card (its "name NAME" names the interface).
  void read_sliding_interfaces() {
    const int n = m_.control.num_interfaces;
    std::vector<std::array<int, 2>> counts;
    for (int k = 0; k < n; ++k) {
      Card c = next("sliding interface " + std::to_string(k + 1) + " control card",
                    "expected " + std::to_string(n) + " sliding interface control cards (control card 5)");
      FixedValues v(c, interface_layout(c));
      note_ignored(v);
      SlidingInterface si;
      si.line = c.line();
      counts.push_back(read_interface_card(v, si));
      read_interface_options(si);
      m_.interfaces.push_back(std::move(si));
    }
    for (int k = 0; k < n; ++k) {
      std::string name = "sliding interface " + std::to_string(k + 1);
      SlidingInterface& si = m_.interfaces[std::size_t(k)];
      read_segments(si.slave, si.slave_line, counts[std::size_t(k)][0], name + " slave");
      read_segments(si.master, si.master_line, counts[std::size_t(k)][1], name + " master");
    }
  }

  // The table of an interface control card: IMPACT-3D's old layout when the decimal point of a
  // friction written from its old first column stands in the column after it (warning 2041
  // once), else DYNA3D's.
  const FixedCardLayout& interface_layout(const Card& c) {
    const FixedCardLayout& now = fixed_card_layout("sliding interface control card", vintage_);
    const FixedCardLayout& old = fixed_card_layout("old IMPACT-3D sliding interface control card", vintage_);
    const FixedField &ot = old.field("type"), &of = old.field("static friction"), &nt = now.field("type"), &nf = now.field("static friction");
    if (c.columns(of.c1 + 1, of.c1 + 1) != ".") return now;
    if (!warned_old_interface_) {
      auto cols = [](const FixedField& f) { return std::to_string(f.c1) + "-" + std::to_string(f.c2); };
      diag_.add(2041, c.where(ot.c1, of.c2), "type in " + cols(ot) + " and friction from column " + std::to_string(of.c1) +
                                                 " are IMPACT-3D's old layout; DYNA3D's has the type in " + cols(nt) + " and the friction from column " +
                                                 std::to_string(nf.c1) + " (impact3d i=DECK --write-fixed=NEW writes it)");
      warned_old_interface_ = true;
    }
    return old;
  }

  // The fields of an interface control card; returns {NSS, NMS} bounded by the deck.
  std::array<int, 2> read_interface_card(const FixedValues& v, SlidingInterface& si) {
    int nss = int(v.integer("NSS"));
    int nms = int(v.integer("NMS"));
    si.type = int(v.integer("type"));
    if (si.type != 3 && si.type != 4) {
      static const char* const names[] = {"", "1 sliding only", "2 tied", "3 sliding with impact and friction", "4 single surface",
                                          "5 nodes to surface", "6 nodes tied to surface", "7 shell edge tied to surface",
                                          "8 spot weld", "9 tiebreak"};
      if (si.type >= 1 && si.type <= 9)
        v.error(1104, "type", std::string("type ") + names[si.type] + ": IMPACT-3D has types 3 (sliding with impact, separation and friction) and 4 (single surface)");
      else
        v.error(1006, "type", "DYNA3D sliding interface types are 1-9; IMPACT-3D has types 3 and 4");
    }
    si.fs = v["static friction"];
    si.fd = v["dynamic friction"];
    si.decay = v["decay coefficient"];
    si.penalty_scale = v["penalty scale factor"];
    si.stiffness_method = int(v.integer("stiffness method"));
    const long long one_pass = v.integer("one-pass flag");
    si.symmetric = one_pass == 0 && si.type != 4;  // (single surface: one pass over its own nodes)
    // DYNA3D's sliding interfaces meet shells at their mid-surface (single surface: both sides)
    si.shell_thickness = si.type == 4 ? 2 : 0;
    if (si.fs < 0) v.error(1219, "static friction");
    if (si.fd < 0) v.error(1219, "dynamic friction");
    if (si.decay < 0) v.error(1003, "decay coefficient", "must not be negative");
    if (si.penalty_scale < 0) v.error(1003, "penalty scale factor", "must not be negative");
    if (si.stiffness_method != 0 && si.stiffness_method != 1) v.error(1006, "stiffness method", "0 DYNA3D or 1 IMPACT-3D maximum stable");
    if (one_pass != 0 && one_pass != 1) v.error(1006, "one-pass flag", "0 or 1");
    const long avail = remaining_cards();
    if (nss < 1 || nss > avail) { v.error(1003, "NSS", "1 to the cards left in the deck"); nss = 0; }
    if (si.type == 4) {  // single surface: the NSS segments against themselves, no master side
      if (nms != 0) { v.error(1003, "NMS", "must be 0 for a single-surface interface (type 4)"); nms = 0; }
    } else if (nms < 1 || nms > avail) { v.error(1003, "NMS", "1 to the cards left in the deck"); nms = 0; }
    return {nss, nms};
  }

  // "lagop N name NAME endfree" after an interface control card: the name is kept (echo,
  // messages); the other words are listed as ignored.
  void read_interface_options(SlidingInterface& si) {
    read_free_block([&](const DeckLine& line, const std::vector<std::string>& w, std::size_t k) -> std::size_t {
      if (w[k] == "name" && k + 1 < w.size()) {
        si.name = w[k + 1];
        return k + 2;
      }
      if (w[k] == "lagop" && k + 1 < w.size()) {
        ignored_fields_.push_back({line.number, "interface option \"lagop " + w[k + 1] + "\""});
        return k + 2;
      }
      ignored_fields_.push_back({line.number, "interface option \"" + w[k] + "\""});
      return k + 1;
    });
  }

  // ---- DYNA3D free format: "word ... endfree" blocks after the control cards ----

  static bool starts_with_letter(std::string_view t) {
    const std::size_t b = t.find_first_not_of(" \t");
    return b != std::string_view::npos && std::isalpha(static_cast<unsigned char>(t[b]));
  }
  static std::vector<std::string> words_of(std::string_view t) {
    std::vector<std::string> w;
    std::size_t k = 0;
    while (k < t.size()) {
      while (k < t.size() && (t[k] == ' ' || t[k] == '\t' || t[k] == '\r')) ++k;
      std::size_t e = k;
      while (e < t.size() && t[e] != ' ' && t[e] != '\t' && t[e] != '\r') ++e;
      if (e > k) w.emplace_back(t.substr(k, e - k));
      k = e;
    }
    return w;
  }

  // Reads free-format lines from the next card up to the word "endfree"; calls `word` for each
  // word with the words after it on its line (a word consumes what it needs).
  template <class OnWord>
  void read_free_block(OnWord&& on_word) {
    while (const DeckLine* l = deck_.peek_card()) {
      if (!starts_with_letter(l->text)) return;  // not free format: the cards resume
      deck_.next_card();
      const std::vector<std::string> w = words_of(l->text);
      for (std::size_t k = 0; k < w.size();) {
        if (w[k] == "endfree") return;
        k = on_word(*l, w, k);
      }
    }
  }

  // The blocks between control card 9 and the materials: output names and times are honoured
  // (basename, exact_output_time), "mdamp N" counts the mass damping cards; the rest is listed
  // once as read but without effect (2040).
  void read_free_format_blocks() {
    while (const DeckLine* l = deck_.peek_card()) {
      if (!starts_with_letter(l->text)) return;
      read_free_block([&](const DeckLine& line, const std::vector<std::string>& w, std::size_t k) -> std::size_t {
        const std::string& word = w[k];
        auto ignore = [&](std::size_t n) {
          std::string what = "free format \"" + word;
          for (std::size_t j = k + 1; j < std::min(k + 1 + n, w.size()); ++j) what += " " + w[j];
          ignored_fields_.push_back({line.number, what + "\""});
          return std::min(k + 1 + n, w.size());
        };
        if (word == "basename" && k + 1 < w.size()) {
          m_.basename = w[k + 1];
          return k + 2;
        }
        if (word == "exact_output_time") {
          m_.exact_output_times = true;
          return k + 1;
        }
        if (word == "mdamp" && k + 1 < w.size()) {
          long long n = 0;
          if (parse_fortran_int(w[k + 1], n) != FieldStatus::ok || n < 0) {
            Location loc = line_location(line, "free format mdamp");
            diag_.add(1001, loc, "mdamp takes a count of mass damping cards");
          } else {
            mass_damping_sets_ = int(n);
          }
          return k + 2;
        }
        if (word == "options") return k + 1;  // the words up to its endfree are listed one by one
        if (word == "element_set") return ignore(w.size());  // "element_set N rgb r g b name X"
        // "xxx on|off" switches and lone words (output requests of DYNA3D's own databases)
        if (k + 1 < w.size() && (w[k + 1] == "on" || w[k + 1] == "off")) return ignore(1);
        return ignore(0);
      });
    }
  }

  Location line_location(const DeckLine& l, const std::string& card) const {
    Location loc;
    loc.file = deck_.name();
    loc.line = l.number;
    loc.card = card;
    loc.found = l.text;
    loc.show_found = true;
    return loc;
  }

  // Every field and option read but without effect here, one warning (2040) with its lines.
  void report_ignored() {
    if (ignored_fields_.empty()) return;
    std::string list;
    for (std::size_t k = 0; k < ignored_fields_.size() && k < 12; ++k)
      list += "\n    line " + std::to_string(ignored_fields_[k].first) + ": " + ignored_fields_[k].second;
    if (ignored_fields_.size() > 12) list += "\n    ... " + std::to_string(ignored_fields_.size() - 12) + " more";
    Location loc;
    loc.file = deck_.name();
    loc.line = ignored_fields_.front().first;
    diag_.add(2040, loc, std::to_string(ignored_fields_.size()) + " item(s):" + list);
  }

  // An rgb line after material card 1 ("rgb r g b", a colour for LLNL's post-processors).
  bool skip_rgb_line() {
    const DeckLine* l = deck_.peek_card();
    if (!l) return false;
    const std::vector<std::string> w = words_of(l->text);
    if (w.empty() || w[0] != "rgb") return false;
    deck_.next_card();
    ignored_fields_.push_back({l->number, "material colour \"" + std::string(l->text.substr(0, 40)) + "\""});
    return true;
  }

  // A section-properties title line ("section properties", "BLT Shell Section Properties",
  // "Hughes-Liu Beam Section Properties") before the two section cards of a beam or shell
  // material.  Absent (the old IMPACT-3D one-card shell section): false.
  bool skip_section_title() {
    const DeckLine* l = deck_.peek_card();
    if (!l || !starts_with_letter(l->text)) return false;
    std::string t(l->text);
    for (auto& ch : t) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (t.find("section") == std::string::npos) return false;
    deck_.next_card();
    return true;
  }

  // The two section cards of a beam material (element type 1), as DYNA3D decks write them:
  // Hughes-Liu (the material card's formulation 0 or 1), shear factor (0: 1), quadrature rule
  // (0: 2; -n: user rule n, read after the materials), cross section (0 rectangular, 1 tubular,
  // 2 a rectangle integrated by a user rule), sizes TS1 TS2 TT1 TT2.
  void read_beam_section(MaterialData& md, const std::string& name) {
    md.beam = true;
    BeamSectionData& sec = md.beam_section;
    sec.elform = 1;
    if (!skip_section_title()) {
      Location loc;
      loc.file = deck_.name();
      loc.line = deck_.peek_card() ? deck_.peek_card()->number : deck_.last_line_number();
      diag_.add(1004, loc, name + ": a beam material (element type 1) has a section-properties line and two section cards after card 8");
    }
    Card a = next(name + " beam section card 1");
    FixedValues va(a, fixed_card_layout("beam section card 1", vintage_));
    note_ignored(va);
    sec.line = a.line();
    sec.shrf = va["shear factor"] == 0 ? 1.0 : va["shear factor"];
    if (!(sec.shrf > 0 && sec.shrf <= 1)) va.error(1003, "shear factor", "shear factor in (0, 1]");
    const double qr = va["quadrature rule"];
    const double cst = va["cross-section type"];
    const bool qr_ok = qr == std::floor(qr) && qr <= 5 && qr >= -1e6;
    if (!qr_ok) va.error(1006, "quadrature rule", "1-5 built-in rules, -n a user rule (0: 2)");
    else if (qr < 0 && -qr > beam_rules_) va.error(1201, "quadrature rule", "user rule " + std::to_string(int(-qr)) + " (control card 8 has " + std::to_string(beam_rules_) + ")");
    sec.qr = qr == 0 || !qr_ok ? 2 : int(qr);
    if (cst != 0 && cst != 1 && cst != 2) va.error(1006, "cross-section type", "0 rectangular, 1 tubular, 2 user rule");
    if (cst == 2 && qr >= 0) va.error(1006, "cross-section type", "2 (a user rule) needs a negative quadrature rule -n");
    if (cst == 1 && qr < 0) va.error(1102, "quadrature rule", "a user integration rule on a tubular section");
    sec.cst = cst == 1 ? BeamCrossSection::tubular : BeamCrossSection::rectangular;
    Card b = next(name + " beam section card 2");
    FixedValues vb(b, fixed_card_layout("beam section card 2", vintage_));
    note_ignored(vb);
    sec.ts1 = vb["TS1"];
    sec.ts2 = vb["TS2"];
    sec.tt1 = vb["TT1"];
    sec.tt2 = vb["TT2"];
    for (const char* f : {"TS1", "TS2", "TT1", "TT2"})
      if (vb[f] < 0) vb.error(1241, f);
    ++beam_material_count_;
  }

  // The user-defined beam integration rules (control card 8 field 4), after the materials:
  // a header (points I5, a real E10) and one card a point (s, t, weight: 3 E10; the weights of
  // a rule sum to 4, the area of [-1, 1]^2).  Each beam section with rule -n gets rule n.
  void read_beam_integration_rules() {
    std::vector<std::vector<std::array<double, 3>>> rules;
    for (int r = 0; r < beam_rules_; ++r) rules.push_back(read_beam_rule(r));
    for (MaterialData& md : m_.materials)
      if (md.beam && md.beam_section.qr < 0 && std::size_t(-md.beam_section.qr) <= rules.size())
        md.beam_section.user_rule = rules[std::size_t(-md.beam_section.qr - 1)];
  }

  // Rule r (0-based): the beam integration rule header card, then a beam integration point
  // card a point.
  std::vector<std::array<double, 3>> read_beam_rule(int r) {
    const std::string name = "beam integration rule " + std::to_string(r + 1);
    Card h = next(name + " header card", "control card 8 announces " + std::to_string(beam_rules_) + " user beam integration rules");
    FixedValues vh(h, fixed_card_layout("beam integration rule header card", vintage_));
    long long npts = vh.integer("number of points");
    if (npts < 1 || npts > remaining_cards() || (beam_rule_points_ > 0 && npts > beam_rule_points_)) {
      vh.error(1003, "number of points", "1 to control card 8's largest rule (" + std::to_string(beam_rule_points_) + ")");
      npts = std::clamp<long long>(npts, 0, remaining_cards());
    }
    const FixedCardLayout& layout = fixed_card_layout("beam integration point card", vintage_);
    std::vector<std::array<double, 3>> rule;
    double wsum = 0;
    for (long long p = 0; p < npts; ++p) {
      Card c = next(name + " point " + std::to_string(p + 1));
      FixedValues v(c, layout);
      const double sp = v["s"], tp = v["t"], w = v["weight"];
      if (std::fabs(sp) > 1 || std::fabs(tp) > 1) c.error(1003, v.field("s").c1, v.field("t").c2, "s, t", "points lie in [-1, 1] x [-1, 1]");
      if (w < 0) v.error(1003, "weight", "must not be negative");
      wsum += w;
      rule.push_back({sp, tp, w});
    }
    if (npts > 0 && std::fabs(wsum - 4) > 1e-3) vh.error(1003, "number of points", "the weights sum to " + std::to_string(wsum) + ", not 4 (the area of [-1, 1]^2)");
    return rule;
  }

  // Beam element cards (control card 2 NUMELB), after the solids: id, material (element type
  // 1), n1, n2, the orientation node n3 (0: none), and TS1 TS2 TT1 TT2 of this beam (all 0: the
  // section's; an inference: TrueGrid writes four reals there, 0.0 in LLNL's decks).
  void read_beams() {
    const int n = numelb_;
    std::vector<int> seen(std::size_t(n), 0);
    m_.beam_nodes.assign(std::size_t(n), {-1, -1, -1});
    m_.beam_material.assign(std::size_t(n), -1);
    m_.beam_thickness.assign(std::size_t(n), {0, 0, 0, 0});
    m_.beam_line.assign(std::size_t(n), 0);
    const FixedCardLayout& layout = fixed_card_layout("beam element card", vintage_);
    for (int k = 0; k < n; ++k) {
      Card c = next("beam element card " + std::to_string(k + 1) + " of " + std::to_string(n),
                    "expected " + std::to_string(n) + " beam element cards (control card 2 NUMELB), found " + std::to_string(k));
      FixedValues v(c, layout);
      const long long id = v.integer("element number");
      const long long label = v.integer("material number");
      const int mat = material_slot(label);
      bool ok = true;
      if (mat < 1) { v.error(1203, "material number", "material " + std::to_string(label) + " is not defined"); ok = false; }
      else if (!m_.materials[std::size_t(mat - 1)].beam) {
        v.error(1203, "material number", "material " + std::to_string(label) + " is not a beam material (material card 1 columns 66-70 element type 1)");
        ok = false;
      }
      std::array<int, 3> nodes{-1, -1, -1};
      static const char* const nf[3] = {"node n1", "node n2", "orientation node n3"};
      for (int j = 0; j < 3; ++j) {
        const long long nid = v.integer(nf[j]);
        if (j == 2 && nid == 0) continue;
        if (nid < 1 || nid > m_.control.numnp) { v.error(1202, nf[j], "nodes are 1.." + std::to_string(m_.control.numnp)); ok = false; }
        else nodes[std::size_t(j)] = int(nid) - 1;
      }
      if (ok && nodes[0] == nodes[1]) { v.error(1250, "node n2", "n1 = n2"); ok = false; }
      std::array<double, 4> t{v["field 6"], v["field 7"], v["field 8"], v["field 9"]};
      if (!claim_number(v, id, n, "element number", "beam", "NUMELB", seen)) continue;
      m_.beam_line[std::size_t(id - 1)] = c.line();
      if (!ok) continue;
      m_.beam_nodes[std::size_t(id - 1)] = nodes;
      m_.beam_material[std::size_t(id - 1)] = mat - 1;
      m_.beam_thickness[std::size_t(id - 1)] = t;
    }
    report_missing(seen, "beam element");
  }


  // Mass-proportional damping cards (control card 7 field 11 or free-format mdamp): the damping
  // ratio xi at the circular frequency omega gives every node f = -2 xi omega m v (the global
  // damping of *DAMPING_GLOBAL, D = 2 xi omega) between the start and end times.
  void read_mass_damping() {
    for (int k = 0; k < mass_damping_sets_; ++k) {
      Card c = next("mass damping card " + std::to_string(k + 1),
                    "expected " + std::to_string(mass_damping_sets_) + " mass damping cards (mdamp / control card 7)");
      FixedValues v(c, fixed_card_layout("mass damping card", FixedVintage::dyna3d_later));
      const double xi = v["damping ratio"], omega = v["frequency"];
      const double t0 = v["start time"], t1 = v["end time"];
      if (xi < 0) v.error(1003, "damping ratio", "must not be negative");
      if (omega < 0) v.error(1003, "frequency", "must not be negative");
      if (t0 != 0) v.error(1102, "start time", "mass damping that starts after time 0");
      if (t1 != 0 && t1 < m_.control.end_time) v.error(1102, "end time", "mass damping that ends before the termination time");
      if (k > 0) {
        v.error(1102, "damping ratio", "more than one mass damping set");
        continue;
      }
      m_.damping.active = xi > 0 && omega > 0;
      m_.damping.d = 2 * xi * omega;
      m_.damping.line = c.line();
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
