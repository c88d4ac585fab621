// SPDX-License-Identifier: MIT
#pragma once
// `tutti rig FILE` — what tutti recognises in a character model by itself (engine/humanoid):
// every role with the node it chose, the missing ones, units, height, up and facing, rest pose,
// finger segments and face morphs. `--mapping -o X.mapping.json` writes a mapping file (the
// format of scene/asset_mapping.hpp) the user can edit. Exit 2 when the model does not load or
// lacks a role a character needs.

#include <filesystem>
#include <iosfwd>

#include <tutti/cli/command.hpp>

namespace tutti::cli {

struct RigOptions {
  std::filesystem::path model;
  bool json = false;
  bool mapping = false;
  std::filesystem::path output;  // with --mapping
};

int run_rig(const RigOptions& options, std::ostream& out, std::ostream& err);

void register_rig_command(Commands& commands);

}  // namespace tutti::cli
