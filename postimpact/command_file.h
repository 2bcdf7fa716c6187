// The POST-IMPACT command language (one command per line, in the spirit of LS-PrePost command
// files; README.md, section POST-IMPACT): settings (open, size, view, mirror, fringe, ...) apply
// to the actions after them (picture, sequence, frames, history).  The command line is
// translated into the same commands.
#pragma once

#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "postimpact/database.h"
#include "postimpact/picture.h"
#include "postimpact/render_osmesa.h"
#include "postimpact/text_freetype.h"

namespace postimpact {

// Error in a command: message prefixed with "FILE:LINE: " by the session.
struct CommandError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Splits a line into words: blanks separate, "double quotes" group, '#' starts a comment.
std::vector<std::string> split_command(const std::string& line);

class Session {
public:
    explicit Session(std::ostream& log);
    ~Session();

    // Executes one command; where = "file:line" for messages.  Throws CommandError.
    void execute(const std::vector<std::string>& words, const std::string& where = "");
    void execute_line(const std::string& line, const std::string& where = "");
    // Runs a command file; stops at the first error (CommandError "file:line: message").
    void run_file(const std::string& path);
    void run_text(const std::string& text, const std::string& name);
    // The default set: effective plastic strain at the first, middle and last state, a sequence
    // of five states, and the energies (PNG + CSV).
    void default_set();

    // Dry run: every command is checked and the actions read the states they name (and extract
    // their histories), but nothing is rendered or written (the command-file fuzz target).
    void set_dry_run(bool on) { dry_run_ = on; }

    bool has_database() const { return db_ != nullptr; }
    int actions() const { return actions_; }  // pictures / plots written so far
    const std::vector<std::string>& written() const { return written_; }
    PictureSettings& settings() { return ps_; }
    // Where the last picture drew its marks (`mark`), in pixels from its top-left corner.
    const std::vector<MarkSpot>& mark_spots() const { return mark_spots_; }

private:
    using Words = std::vector<std::string>;
    struct CommandEntry {
        const char* name;
        void (Session::*run)(const Words&);
    };
    static const std::vector<CommandEntry>& commands();
    // One member a command (w[0] is the command word as written).
    void cmd_open(const Words& w);
    void cmd_outdir(const Words& w);
    void cmd_size(const Words& w);
    void cmd_view(const Words& w);
    void cmd_up(const Words& w);
    void cmd_mirror(const Words& w);
    void cmd_fringe(const Words& w);
    void cmd_range(const Words& w);
    void cmd_bands(const Words& w);
    void cmd_supersample(const Words& w);
    void cmd_timing(const Words& w);
    void cmd_switch(const Words& w);
    void cmd_units(const Words& w);
    void cmd_scale(const Words& w);
    void cmd_font(const Words& w);
    void cmd_title(const Words& w);
    void cmd_mark(const Words& w);
    void cmd_state(const Words& w);
    void cmd_picture(const Words& w);
    void cmd_sequence(const Words& w);
    void cmd_frames(const Words& w);
    void cmd_history(const Words& w);
    void cmd_echo(const Words& w);
    void cmd_default(const Words& w);

    Database& db(const std::string& cmd);
    Renderer& renderer();
    const Font& font();
    std::string out_path(const std::string& name) const;
    int parse_state(const std::string& spec, const std::string& cmd);
    std::vector<int> parse_states(const std::vector<std::string>& w, std::size_t from, const std::string& cmd);
    void wrote(const std::string& path);

    std::ostream& log_;
    std::unique_ptr<Database> db_;
    std::unique_ptr<Renderer> renderer_;
    std::unique_ptr<Font> font_;
    std::string font_path_;
    PictureSettings ps_;
    int state_ = -1;  // current state (0-based); -1: last
    std::string outdir_;
    int plot_w_ = 1200, plot_h_ = 800;
    bool timing_ = false;
    bool dry_run_ = false;
    double t0_wall_ = 0, t0_cpu_ = 0;  // start of the current action
    int actions_ = 0;
    std::vector<std::string> written_;
    std::vector<MarkSpot> mark_spots_;
};

}  // namespace postimpact
