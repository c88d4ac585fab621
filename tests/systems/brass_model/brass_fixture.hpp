// SPDX-License-Identifier: MIT
#pragma once
// Shared by the brass_model tests: the shipped instruments, loaded once.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include <tutti/brass_model/instrument.hpp>
#include <tutti/music/pitch.hpp>

namespace tutti::brass_model::test {

inline const std::vector<Instrument>& shipped() {
  static const std::vector<Instrument> all = [] {
    auto loaded = load_all_instruments();
    if (!loaded) ADD_FAILURE() << loaded.error().message;
    return loaded ? std::move(*loaded) : std::vector<Instrument>{};
  }();
  return all;
}

inline const Instrument& instrument(const std::string& id) {
  for (const Instrument& i : shipped()) {
    if (i.id == id) return i;
  }
  ADD_FAILURE() << "no instrument " << id;
  static const Instrument none;
  return none;
}

inline int key(const char* name) {
  auto k = music::parse_pitch_name(name);
  if (!k) ADD_FAILURE() << "bad pitch " << name;
  return k.value_or(0);
}

// The names of every fingering of a written pitch, standard first.
inline std::vector<std::string> names(const Instrument& i, int written) {
  std::vector<std::string> out;
  for (const Fingering& f : i.fingerings(written)) out.push_back(fingering_name(i, f));
  return out;
}

inline std::string standard(const Instrument& i, int written) {
  const auto all = i.fingerings(written);
  return all.empty() ? std::string("(none)") : fingering_name(i, all.front());
}

}  // namespace tutti::brass_model::test
