// SPDX-License-Identifier: MIT
#pragma once
// How a player holds an instrument, read from content/instruments/holds/<model>.json: where each
// palm rests, which fingertip works which valve, how far the fingers curl, how the instrument is
// carried (bell angle, standing and seated) and where the elbows go. The pose system turns it
// into arm IK toward those contacts and finger IK onto the buttons.

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include <glm/glm.hpp>

#include <tutti/core/result.hpp>

#include <tutti/stage/fingertip_reach.hpp>

namespace tutti::brass {

struct HandHold {
  std::string palm_at;  // instrument node the palm's centre holds; empty: the fingertips place it
  // Instrument node under each fingertip (thumb .. little), empty for none.
  std::array<std::string, 5> fingertip_on{};
  float pad_above_button_m = 0.006f;  // fingertip node above the button's top (the pad's flesh)
  float metacarpal_lean_rad = 0.0f;   // knuckles leaning over the buttons from the upright
  std::array<float, 3> finger_curl_rad{};  // MCP, PIP, DIP flexion of the fingers not on a button
  std::array<float, 3> little_curl_rad{};  // the little finger's, when it has its own
  bool little_own_curl = false;
  float thumb_curl_rad = 0.0f;
  // The thumb turned in at its base, about the palm's normal, toward the index: along the fingers
  // (the horn's hand in the bell); 0 leaves the rig's rest.
  float thumb_adduct_rad = 0.0f;
  bool wraps_valves = false;
  // This arm's elbow pole (down, out, back), when it differs from the hold's `elbows`.
  std::optional<glm::vec3> elbow_pole;  // the palm holds the valve casings (check-pose: wrist to their axis)

  stage::FingerCurls curls() const {
    return {finger_curl_rad, little_curl_rad, little_own_curl, thumb_curl_rad, thumb_adduct_rad};
  }
};

struct Hold {
  float bell_tilt_standing_rad = 0.0f;
  float bell_tilt_seated_rad = 0.0f;
  // How far the bell may dip further when a grip is out of reach after the chest and shoulder
  // have turned toward it (the trombone's far positions).
  float reach_dip_rad = 0.0f;
  glm::vec3 elbow_pole{1.0f, 0.8f, 0.3f};  // down, out to the side, back
  // Between phrases (rests of several seconds, before the first entrance, after the last note)
  // the instrument comes down from the lips to this place in front of the body; has_rest false:
  // it stays up.
  bool has_rest = false;
  float rest_below_lips_m = 0.0f;
  float rest_forward_m = 0.0f;
  float rest_bell_tilt_rad = 0.0f;
  // Where the player's music stand stands, from the feet: forward, and to the player's left (a
  // trombonist reads beside the slide, which would otherwise pass through the desk).
  float stand_forward_m = 0.75f;
  float stand_left_m = 0.0f;
  std::array<HandHold, 2> hands;             // left, right

  bool fingertips_place(int hand) const {
    return hands[static_cast<std::size_t>(hand)].palm_at.empty();
  }
};

// Reads and checks one hold file; errors name the file and the JSON path.
Result<Hold> load_hold(const std::filesystem::path& file);

}  // namespace tutti::brass
