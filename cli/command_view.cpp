// cueball view: a saved result drawn by the self-contained HTML viewer.
#include <memory>

#include "common.hpp"
#include "cueball/io/viewer_json.hpp"
#include "cueball/io/viewer_page.hpp"

namespace cueball::cli {

namespace {

struct ViewFlags {
  std::string result;
  std::string output;
};

void run_view(const ViewFlags& f, std::ostream& out) {
  const std::string json = checked_result_for_viewer(f.result, read_text_file(f.result, "the result file", kMaxResultFileBytes));
  write_text_file(f.output, viewer_page(viewer_template(), json), "-o", "the viewer page");
  out << "viewer written to " << f.output << " (open it in a browser; it needs no network)\n";
}

}  // namespace

Command add_view_command(CLI::App& app) {
  auto flags = std::make_shared<ViewFlags>();
  CLI::App* sub = app.add_subcommand(
      "view",
      "Writes one self-contained HTML page (no network needed) that draws the table to scale and\n"
      "animates the shot in RESULT.json (written by `cueball simulate -o`) along its exact trajectory:\n"
      "play/pause, speed, scrubber, trails (sliding vs rolling), an event timeline, a ball's speed and\n"
      "spin over time. `cueball simulate --html PAGE` does the same in one step.");
  sub->add_option("result", flags->result, "Result JSON written by `cueball simulate -o`")->required();
  sub->add_option("-o,--output", flags->output, "The HTML page to write")->required();
  return [flags](std::ostream& out, std::ostream&) { run_view(*flags, out); };
}

}  // namespace cueball::cli
