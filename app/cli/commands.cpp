#include <tutti/cli/commands.hpp>

#include <tutti/cli/brass_command.hpp>
#include <tutti/cli/concat_command.hpp>
#include <tutti/cli/export_command.hpp>
#include <tutti/cli/fingering_command.hpp>
#include <tutti/cli/fit_fingering_command.hpp>
#include <tutti/cli/info_command.hpp>
#include <tutti/cli/perform_command.hpp>
#include <tutti/cli/play_command.hpp>
#include <tutti/cli/render_command.hpp>
#include <tutti/cli/sync_report_command.hpp>

namespace tutti::app {

void register_commands(CLI::App& tutti, Commands& commands) {
  register_info_command(tutti, commands);
  register_concat_command(tutti, commands);
  register_export_command(tutti, commands);
  register_perform_command(tutti, commands);
  register_fingering_command(tutti, commands);
  register_fit_fingering_command(tutti, commands);
  register_brass_command(tutti, commands);
  register_render_command(tutti, commands);
  register_sync_report_command(tutti, commands);
  register_play_command(tutti, commands);
}

}  // namespace tutti::app
