// SPDX-License-Identifier: MIT
// What an edit costs in the editor: Session::apply re-plans what the edit touches (the
// players whose inputs changed, the ensemble; for a pin the span around it) before accepting it.
// Each iteration applies an edit and undoes it, so the document stays the same.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <tutti/editor/session.hpp>

namespace {

using tutti::editor::Session;

// A copy of a shipped scene with its music path made absolute.
std::filesystem::path scene_copy(const std::string& name) {
  const std::filesystem::path source = TUTTI_SOURCE_DIR;
  std::ifstream in(source / "content" / "scenes" / name);
  std::stringstream text;
  text << in.rdbuf();
  std::string json = text.str();
  const std::string music = "\"../music/";
  const std::string absolute = "\"" + (source / "content" / "music").string() + "/";
  for (auto at = json.find(music); at != std::string::npos; at = json.find(music, at)) {
    json.replace(at, music.size(), absolute);
    at += absolute.size();
  }
  const auto out = std::filesystem::temp_directory_path() / ("tutti_bench_" + name);
  std::ofstream(out) << json;
  return out;
}

std::unique_ptr<Session> open(const std::string& name, benchmark::State& state) {
  auto session = Session::open(scene_copy(name));
  if (!session) {
    state.SkipWithError(session.error().message.c_str());
    return nullptr;
  }
  return std::move(*session);
}

void BM_QuartetVariationEdit(benchmark::State& state) {
  auto s = open("quartet.json", state);
  if (!s) return;
  for (auto _ : state) {
    if (!s->apply(tutti::editor::set_variation(s->document().json(), {"/performers/1", ""},
                                               "sway_amount", 0.9)) ||
        !s->undo()) {
      state.SkipWithError("edit refused");
      break;
    }
  }
}
BENCHMARK(BM_QuartetVariationEdit)->Unit(benchmark::kMillisecond);

void BM_QuartetBreathMark(benchmark::State& state) {
  auto s = open("quartet.json", state);
  if (!s) return;
  const tutti::editor::PlayerRef trombone_1{"/performers/2", ""};
  const double boundary = s->breath_boundary(trombone_1, 6.5);
  for (auto _ : state) {
    if (!s->apply(tutti::editor::add_breath(s->document().json(), trombone_1, boundary)) ||
        !s->undo()) {
      state.SkipWithError("edit refused");
      break;
    }
  }
}
BENCHMARK(BM_QuartetBreathMark)->Unit(benchmark::kMillisecond);

void BM_PianoFingerPin(benchmark::State& state) {
  auto s = open("piano.json", state);
  if (!s) return;
  const tutti::editor::TimelineLane& lane = s->timeline().lanes.back();
  const tutti::editor::PlayerRef pianist{lane.player, lane.name};
  const tutti::editor::TimelineNote note = lane.notes[12];
  const int finger = note.finger == 5 ? 4 : 5;
  for (auto _ : state) {
    if (!s->apply(tutti::editor::pin_finger(s->document().json(), pianist, note.start_s, note.key,
                                            finger)) ||
        !s->undo()) {
      state.SkipWithError("edit refused");
      break;
    }
  }
}
BENCHMARK(BM_PianoFingerPin)->Unit(benchmark::kMillisecond);

}  // namespace
