// SPDX-License-Identifier: MIT
#pragma once
// tutti::performance — a scene's performance for any engine or renderer, with no Vulkan, window or
// sound device. A host opens a scene once (it is loaded, planned and staged with the default
// instrument families) and then asks, for any time t, in any order:
//
//   auto performance = performance::Performance::open("content/scenes/quartet.json");
//   performance::Sample sample;
//   every frame: (*performance)->sample(music_time_s, sample);
//     sample.models[m].local[n]   model m's node n (models()[m].nodes[n], the model's own node
//                                 names), local translation / rotation / scale (glTF conventions)
//     sample.models[m].morph_weights[k]   morph target models()[m].morphs[k]
//     sample.events[p]            performer p's events around t: notes on and off, keys, valves
//                                 and slides reaching their stops, breaths, cues
//
// sample(t) is a pure function of the plans and t (seekable, shardable, the same bytes every
// time), and allocation-free once `out` has its sizes. `tutti export` writes exactly these poses.

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <tutti/core/result.hpp>

// Only named here: a host's code sees no stage, ECS or scene internals (nor glm) through this
// header. Code that works on the staged scene includes <tutti/stage/stage.hpp> itself.
namespace tutti::scene {
struct Scene;
}
namespace tutti::stage {
class Stage;
class StageContext;
}

namespace tutti::performance {

struct Options {
  // Where tutti's data and generated models are: empty = $TUTTI_CONTENT_DIR / $TUTTI_ASSET_DIR,
  // else the folders tutti was built with.
  std::filesystem::path content_dir;
  std::filesystem::path asset_dir;
  // The grid on which key, valve and slide contacts are looked for (their times are placed
  // between grid points); 0 = no contact events.
  double contact_step_s = 0.001;
  // The frames per second on which the contacts (contacts()) are recorded, from the start to the
  // end of the stage's range; 0 = none. Recording poses the whole piece once more at open.
  double contact_fps = 30.0;
};

// A local transform in glTF's conventions: metres, a unit quaternion (x, y, z, w), scale.
struct Trs {
  std::array<float, 3> translation{0.0f, 0.0f, 0.0f};
  std::array<float, 4> rotation{0.0f, 0.0f, 0.0f, 1.0f};
  std::array<float, 3> scale{1.0f, 1.0f, 1.0f};
};

struct ModelInfo {
  std::string name;            // unique: "Trumpet 1", "Trumpet 1 trumpet", "piano", "chair 1"
  std::string file;            // the glTF it was loaded from
  std::int32_t performer = -1;  // index into performers(); -1 = scenery (floor, chairs, stands)
  std::vector<std::string> nodes;     // the model's own node names, in its file's order
  std::vector<std::int32_t> parents;  // per node, -1 = a root
  std::vector<std::string> morphs;    // morph targets of all its meshes, in order
};

struct PerformerInfo {
  std::string name;
  std::string family;      // "brass", "piano"
  std::string instrument;  // "trumpet_bb", "trombone_tenor", ..., "piano", "organ"
  std::vector<std::size_t> models;  // indices into models()
};

// The kinds of event, by name: the performance's own (note_on, note_off: value the MIDI key, as
// heard; breath_start, breath_end: value the breath's index; cue: the entrance a cue leads to,
// value 1 = gives it, the lead, 0 = answers), then the stops each default family reports, family
// by family (the keyboards' key_down and key_up, value the MIDI key; brass valve_down and
// valve_up, value the valve's number, 1-based; slide_arrives, value the position, 1..7; ...).
// Event::kind is an index into this list; a host looks kinds up by name, since a family added
// to the list adds kinds of its own.
std::span<const std::string_view> event_kinds();
// event_kinds()[kind], or "" when kind is out of range.
std::string_view event_kind_name(std::uint16_t kind);
// The kind called `name`, or -1 when there is none.
std::int32_t find_event_kind(std::string_view name);

struct Event {
  double t_s = 0.0;  // seconds of the music
  std::uint16_t kind = 0;  // index into event_kinds()
  std::int32_t performer = 0;  // index into performers()
  std::int32_t value = 0;
};

// One span of time over which a performer's body node touches a node of their instrument: a
// fingertip on a key (which stops `midi`), a fingertip on a valve button, a palm on a grip, the
// lips on the mouthpiece. `part_point_m` is the touching point in the part node's frame: where
// the body node was there, on average over the span's frames. Nodes are indices into
// models()[model].nodes.
struct Contact {
  double from_s = 0.0;  // seconds of the music: the first and last recorded frame touching
  double to_s = 0.0;
  std::int32_t performer = 0;  // index into performers()
  std::int32_t body_model = 0;
  std::int32_t body_node = 0;
  std::int32_t part_model = 0;
  std::int32_t part_node = 0;
  std::array<float, 3> part_point_m{0.0f, 0.0f, 0.0f};
  std::int32_t midi = -1;  // the pitch the contact stops, else -1
};

struct ModelPose {
  Trs root;  // where the model is on the stage (the scene's frame: metres, +Y up)
  std::vector<Trs> local;
  std::vector<float> morph_weights;
};

struct Sample {
  double t_s = 0.0;
  std::vector<ModelPose> models;          // one per models()
  std::vector<std::vector<Event>> events;  // one list per performer, in time order
};

class Performance;

// A caller's own sampling state (ozz-animation's sampling context): the scratch space and the
// world its frames are computed in; the plans stay in the Performance, shared and only read.
// Made by Performance::make_context; one per thread.
class SampleContext {
 public:
  SampleContext(SampleContext&&) noexcept;
  SampleContext& operator=(SampleContext&&) noexcept;
  ~SampleContext();

 private:
  friend class Performance;
  struct State;
  explicit SampleContext(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

class Performance {
 public:
  // Loads the scene file and stages it; a piece of music (.mid, .musicxml, ...) is staged with
  // the scene tutti drafts for it (draft_scene.hpp).
  static Result<std::unique_ptr<Performance>> open(const std::filesystem::path& scene_file,
                                                   const Options& options = {});
  // Stages a scene already loaded.
  static Result<std::unique_ptr<Performance>> stage(const scene::Scene& scene,
                                                    const Options& options = {});

  ~Performance();
  Performance(const Performance&) = delete;
  Performance& operator=(const Performance&) = delete;

  double start_s() const;
  double end_s() const;
  const std::vector<PerformerInfo>& performers() const { return performers_; }
  const std::vector<ModelInfo>& models() const { return models_; }
  // Every event of the piece, in time order (ties: by performer, then kind).
  const std::vector<Event>& events() const { return events_; }
  // The events with from_s <= t_s < to_s.
  std::span<const Event> events_between(double from_s, double to_s) const;
  // Every contact span of the piece (Options::contact_fps), by start time (ties: performer,
  // body model and node, part model and node).
  const std::vector<Contact>& contacts() const { return contacts_; }
  // Planning diagnostics worth showing (notes out of range, ...).
  const std::vector<std::string>& notes() const;

  // Poses everything at t_s and fills `out`: every model's pose, and each performer's events
  // within `events_window_s` of t_s (before or after).
  void sample(double t_s, Sample& out, double events_window_s = 0.5);

  // Sampling from many threads: each thread makes a context (on the thread that owns the
  // performance, while no sample(t) runs), then samples with it; sample(context, ...) is const
  // and runs beside other contexts' samples. The same t gives the same bytes as sample(t).
  // Allocation-free after a context's first frame. Throws std::invalid_argument for a context
  // made by another performance or moved from.
  SampleContext make_context() const;
  void sample(SampleContext& context, double t_s, Sample& out,
              double events_window_s = 0.5) const;

  // The staged scene under it (the renderer and the editor work on it).
  stage::Stage& stage() { return *stage_; }
  const stage::Stage& stage() const { return *stage_; }

 private:
  Performance() = default;
  Status init(const Options& options);
  void fill_events(double t_s, Sample& out, double events_window_s) const;

  std::unique_ptr<stage::Stage> stage_;
  std::vector<PerformerInfo> performers_;
  std::vector<ModelInfo> models_;
  std::vector<Event> events_;
  std::vector<Contact> contacts_;
};

// The models' poses as the stage's last run left them (what sample(t) and `tutti export` read):
// rotations normalised, roots decomposed into TRS. `out` is resized to the stage's instances.
void read_poses(const stage::Stage& stage, std::vector<ModelPose>& out);
// The same as a context of the stage was last posed (Stage::run(context, ...)).
void read_poses(const stage::Stage& stage, const stage::StageContext& context,
                std::vector<ModelPose>& out);

}  // namespace tutti::performance
