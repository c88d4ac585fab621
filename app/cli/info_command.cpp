#include <tutti/cli/info_command.hpp>

#include <ostream>

#include <tutti/cli/exit_codes.hpp>
#include <tutti/cli/score_summary.hpp>
#include <tutti/core/file_io.hpp>
#include <tutti/music/load_score.hpp>

namespace tutti::app {

int run_info(const InfoOptions& options, std::ostream& out, std::ostream& err) {
  auto score = music::load_score(options.file);
  if (!score) {
    err << "error: " << score.error().message << "\n";
    return kExitBadInput;
  }
  // load_score already succeeded, so the bytes are readable; detect again only for the label.
  auto bytes = read_file_bytes(options.file);
  const auto format = bytes ? music::detect_score_format(*bytes, options.file)
                            : std::optional<music::ScoreFormat>{};
  const ScoreSummary summary = summarize(*score, format ? music::format_name(*format) : "unknown");
  out << (options.json ? summary_json(summary) : summary_text(summary));
  return kExitOk;
}

}  // namespace tutti::app
