// SPDX-License-Identifier: MIT
#pragma once
// How well the picture and the sound agree, measured rather than assumed. Two independent
// sides:
//   - contact times read off the animation: the stage's systems are evaluated on a fine time
//     grid and the posed components watched for the moments a sound must start — a piano key
//     reaches its bottom, a valve is fully down (or back up while the player sounds), the slide
//     arrives, the tongue releases the air (the mouth starts to buzz);
//   - note onsets found in the rendered audio by audio::detect_onsets, which never sees a plan.
// Contacts closer together than the ear can separate are one expected onset; each is matched to
// the nearest detected onset within a tolerance. The figures are the matched offsets
// (sound − contact), and what did not match on either side.

#include <string>
#include <vector>

#include <tutti/audio/offline_synth.hpp>
#include <tutti/audio/onset_detection.hpp>
#include <tutti/stage/contact_detector.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::cli {

struct Contact {
  double time_s = 0.0;  // music time
  // The family's kind of stop (stage/contact_detector.hpp): a sound starts here, called
  // kind->sync_label in the report.
  const stage::StopKind* kind = nullptr;
  std::string performer;
  // The sound it starts is struck (its player's part has a struck General MIDI program:
  // audio::is_struck_program), so it is heard where its energy jumps.
  bool struck = false;
  int detail = -1;  // the stop's value: a MIDI key, a valve number (1-based), a slide position
};

// Samples evaluate-phase state at from_s, from_s + step_s, ... < to_s (the one contact
// detector) and keeps the stops where a sound starts (a kind with a sync_label) while the player
// sounds (a valve let go or a slide come to rest in a rest makes no sound).
// Runs in a sampling context of its own: the stage is only read.
std::vector<Contact> sample_contacts(const stage::Stage& stage, double from_s, double to_s,
                                     double step_s);

struct SyncMatch {
  double contact_s = 0.0;  // music time of the expected onset (its earliest contact)
  double onset_s = 0.0;    // music time of the detected onset
  std::vector<const Contact*> contacts;
  double offset_ms() const { return (onset_s - contact_s) * 1000.0; }
};

struct SyncFigures {
  std::size_t contacts = 0;                  // contact events sampled
  std::size_t expected = 0;                  // expected onsets (contacts merged)
  std::size_t detected = 0;                  // onsets in the audio
  std::vector<SyncMatch> matches;            // in time order
  std::vector<double> unmatched_expected_s;  // expected onsets with no sound near them
  std::vector<double> unmatched_detected_s;  // detected onsets with no contact near them
  double mean_abs_ms = 0.0;
  double max_abs_ms = 0.0;
  double mean_signed_ms = 0.0;  // > 0: the sound comes after the contact
};

struct SyncOptions {
  double step_s = 0.0005;      // contact sampling grid
  double merge_s = 0.030;      // contacts this close are one expected onset
  double tolerance_s = 0.050;  // the furthest a detected onset may be from its contact
  double tempo_factor = 1.0;   // audio at this tempo (music time = start + audio time * tempo)
  audio::OnsetOptions onsets;
};

// `contacts` from sample_contacts; `audio` starts at music time `audio_start_s`.
SyncFigures measure_sync(const std::vector<Contact>& contacts, const audio::AudioBuffer& audio,
                         double audio_start_s, const SyncOptions& options);

}  // namespace tutti::cli
