// sdfreel(1) from the CLI's own definitions: every command with its arguments and options as
// `--help` prints them, then what --help cannot say (exit status, environment, files).
#include <string>
#include <vector>

#include "cli/cli_walk.h"
#include "cli/generate.h"

namespace sdfreel {

namespace {

// Text for roff: backslashes and hyphens escaped, no line starting with a control character.
std::string roff(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '\\')
      out += "\\e";
    else if (c == '-')
      out += "\\-";
    else
      out += c;
  }
  if (!out.empty() && (out[0] == '.' || out[0] == '\'')) out = "\\&" + out;
  return out;
}

std::vector<const CLI::Option*> options_of(CLI::App& cmd, bool positional) {
  std::vector<const CLI::Option*> out;
  for (const CLI::Option* o : all_options(cmd))
    if (o->get_positional() == positional && !o->get_group().empty() &&
        o->get_lnames().size() + o->get_snames().size() + (positional ? 1 : 0) > 0 &&
        (positional || o->get_lnames() != std::vector<std::string>{"help"}))
      out.push_back(o);
  return out;
}

// CLI11's type name without what the description says anyway: "TEXT:{cpu,gl}" -> "{cpu,gl}",
// "INT:INT in [1 - 1024]" -> "INT".
std::string value_name(const std::string& type) {
  const size_t colon = type.find(':');
  if (colon == std::string::npos) return type;
  const std::string after = type.substr(colon + 1);
  return after.rfind('{', 0) == 0 ? after : type.substr(0, colon);
}

// "\fB\-o\fR, \fB\-\-output\fR \fITEXT\fR"
std::string option_head(const CLI::Option& o) {
  std::string head;
  for (const std::string& flag : flags_of(o))
    head += (head.empty() ? "" : ", ") + ("\\fB" + roff(flag) + "\\fR");
  if (o.get_items_expected_max() != 0 && !o.get_type_name().empty())
    head += " \\fI" + roff(value_name(o.get_type_name())) + "\\fR";
  return head;
}

std::string synopsis(CLI::App& cmd) {
  std::string s = "sdfreel " + cmd.get_name();
  for (const CLI::Option* p : options_of(cmd, true)) {
    const std::string name = p->get_name(true) + (p->get_items_expected_max() > 1 ? "..." : "");
    s += " " + (p->get_required() ? name : "[" + name + "]");
  }
  return s + " [options]";
}

const char* const kAfterCommands = R"(.SH EXIT STATUS
.TP
.B 0
success: every asked\-for frame is written (or verified)
.TP
.B 1
a render, encode or verification failed (a hash differs, a frame file is damaged, the backend
cannot start, a write failed)
.TP
.B 2
bad usage or bad input (a bad timeline is reported as FILE:LINE:COLUMN: error: WHAT); nothing is
written
.TP
.B 130, 143
a render stopped by SIGINT or SIGTERM; its finished frames are kept and \fB\-\-resume\fR renders
the rest
.SH ENVIRONMENT
.TP
.B SDFREEL_CACHE_DIR
the folder for files sdfreel can make again (generated textures, the lenticular card's source
views); default \fI$XDG_CACHE_HOME/sdfreel\fR, else \fI~/.cache/sdfreel\fR
.TP
.B SDFREEL_SIMD
\fB0\fR runs the CPU backend's scalar path (the same bits, slower)
.TP
.B SDFREEL_SHADER_DIR
the folder of the GLSL shaders
.TP
.B SDFREEL_OCIO_CONFIG
the OpenColorIO config that \fBconfig = "builtin"\fR means
.TP
.B SDFREEL_EGL_LIBRARY, SDFREEL_OSMESA_LIBRARY
the libEGL and libOSMesa to open
.TP
.B SDFREEL_GL_PLATFORM, SDFREEL_GL_DEVICE
the GL backend's platform and device when \fB\-\-gl\-platform\fR and \fB\-\-gl\-device\fR
are not given
.TP
.B LP_NUM_THREADS
llvmpipe's threads (set from \fB\-\-threads\fR unless given)
.SH FILES
.TP
.I /usr/share/sdfreel/shaders
the GLSL of the built\-in scenes
.TP
.I /usr/share/sdfreel/ocio/config.ocio
the shipped OpenColorIO config
.TP
.I /usr/share/doc/sdfreel/docs/
the manual: the timeline format (timeline.md), the commands (cli.md), your own shader
(shaders.md), outputs, farms, determinism and one page per scene
.SH EXAMPLES
.nf
sdfreel render timelines/lantern_festival.toml --preview
sdfreel still timelines/water_lily.toml --time 2.5 -o still.png
sdfreel render my_shader.toml --shard 0/2 --no-video
sdfreel verify timelines/sdf_morph.toml --manifest golden.framemd5
.fi
.SH SEE ALSO
.BR ffmpeg (1),
.BR sbatch (1)
)";

}  // namespace

std::string man_page(CLI::App& app) {
  std::string out = ".TH SDFREEL 1 \"\" \"sdfreel " SDFREEL_VERSION "\" \"User Commands\"\n";
  out +=
      ".SH NAME\nsdfreel \\- deterministic renders of procedural shader scenes to frames and "
      "video\n";
  out += ".SH SYNOPSIS\n.B sdfreel\n.I command\n[\\fIoptions\\fR]\n";
  out +=
      ".SH DESCRIPTION\nsdfreel renders procedural shader scenes (ray\\-marched signed distance "
      "fields and their kin, or a Shadertoy shader) into frame sequences and video, driven by a "
      "timeline file (TOML), with every frame reproducible bit for bit. "
      "Every command prints its options with \\fB\\-\\-help\\fR.\n";
  out += ".SH COMMANDS\n";
  for (CLI::App* cmd : all_commands(app)) {
    out += ".SS \"" + roff(synopsis(*cmd)) + "\"\n" + roff(cmd->get_description()) + "\n";
    for (const CLI::Option* p : options_of(*cmd, true))
      out += ".TP\n\\fI" + roff(p->get_name(true)) + "\\fR\n" + roff(p->get_description()) + "\n";
    for (const CLI::Option* o : options_of(*cmd, false))
      out += ".TP\n" + option_head(*o) + "\n" + roff(o->get_description()) + "\n";
  }
  return out + kAfterCommands;
}

}  // namespace sdfreel
