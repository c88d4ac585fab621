// SPDX-License-Identifier: MIT
#include <tutti/cli/brass_command.hpp>
#include <tutti/cli/check_pose_command.hpp>
#include <tutti/cli/rig_command.hpp>
#include <tutti/cli/scene_command.hpp>
#include <tutti/cli/commands.hpp>
#include <tutti/cli/concat_command.hpp>
#include <tutti/cli/export_command.hpp>
#include <tutti/cli/fingering_command.hpp>
#include <tutti/cli/fit_fingering_command.hpp>
#include <tutti/cli/info_command.hpp>
#include <tutti/cli/perform_command.hpp>
#include <tutti/cli/play_command.hpp>
#include <tutti/cli/render_command.hpp>
#include <tutti/cli/sync_report_command.hpp>

namespace tutti::cli {

void register_commands(Commands& commands) {
  register_info_command(commands);
  register_concat_command(commands);
  register_export_command(commands);
  register_perform_command(commands);
  register_fingering_command(commands);
  register_fit_fingering_command(commands);
  register_brass_command(commands);
  register_scene_command(commands);
  register_render_command(commands);
  register_sync_report_command(commands);
  register_check_pose_command(commands);
  register_rig_command(commands);
  register_play_command(commands);
}

}  // namespace tutti::cli
