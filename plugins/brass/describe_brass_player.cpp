// SPDX-License-Identifier: MIT
// What the editor shows of a brass player (stage/player_view.hpp): their instrument and part,
// and their expression spans as the scene file writes them.
#include <tutti/brass/brass_players.hpp>
#include <tutti/brass/brass_plugin.hpp>
#include <tutti/stage/player_view.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::brass {

void BrassPlugin::describe_player(const stage::Stage& stage, ecs::Entity performer,
                                  stage::PlayerView& out) const {
  const auto* seat = stage.world().try_get<stage::Seat>(performer);
  const auto& players = brass_players(stage.scene());
  if (seat == nullptr || seat->index >= players.size()) return;
  const BrassPlayer& player = players[seat->index];
  out.summary =
      player.instrument + ", part \"" + player.part + "\"" + (player.lead ? ", lead" : "");
  out.variation = player.variation;
  out.expressive = true;
  out.expressions = player.expressions;
}

}  // namespace tutti::brass
