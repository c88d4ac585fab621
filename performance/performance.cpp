// SPDX-License-Identifier: MIT
#include <tutti/performance/performance.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include <glm/gtc/quaternion.hpp>

#include <tutti/components/breath_schedule.hpp>
#include <tutti/components/finger.hpp>
#include <tutti/components/hand.hpp>
#include <tutti/components/instrument.hpp>
#include <tutti/components/note.hpp>
#include <tutti/components/performer.hpp>
#include <tutti/components/slide.hpp>
#include <tutti/components/valve.hpp>
#include <tutti/ensemble_variation/ensemble_variation_system.hpp>
#include <tutti/performance/draft_scene.hpp>
#include <tutti/performance/families.hpp>
#include <tutti/performance/model_names.hpp>
#include <tutti/scene/load_scene.hpp>
#include <tutti/scene/scene.hpp>
#include <tutti/stage/stage.hpp>

namespace tutti::performance {
namespace {

// A placement matrix (rotation, positive scale, translation: what the families and the mapping
// files make) as TRS.
model::NodeTransform decompose(const glm::mat4& m) {
  model::NodeTransform t;
  t.translation = glm::vec3(m[3]);
  glm::vec3 axes[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
  for (int i = 0; i < 3; ++i) t.scale[i] = glm::length(axes[i]);
  if (glm::dot(glm::cross(axes[0], axes[1]), axes[2]) < 0.0f) t.scale.x = -t.scale.x;
  glm::mat3 rotation(1.0f);
  for (int i = 0; i < 3; ++i) {
    if (t.scale[i] != 0.0f) rotation[i] = axes[i] / t.scale[i];
  }
  t.rotation = glm::normalize(glm::quat_cast(rotation));
  return t;
}

Trs to_trs(const model::NodeTransform& t) {
  Trs out;
  out.translation = {t.translation.x, t.translation.y, t.translation.z};
  out.rotation = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
  out.scale = {t.scale.x, t.scale.y, t.scale.z};
  return out;
}

bool event_before(const Event& a, const Event& b) {
  return std::tie(a.t_s, a.performer, a.kind, a.value) <
         std::tie(b.t_s, b.performer, b.kind, b.value);
}

// Linear crossing time of `level` between (t0, v0) and (t1, v1).
double crossing(double t0, double v0, double t1, double v1, double level) {
  if (v1 == v0) return t1;
  return t0 + (t1 - t0) * std::clamp((level - v0) / (v1 - v0), 0.0, 1.0);
}

// Keys, valves and slides reaching their stops, read off the evaluated components on a grid of
// `step_s` over the stage's range (the crossing placed between grid points).
void add_contact_events(stage::Stage& stage, const std::map<std::uint64_t, std::int32_t>& index_of,
                        double step_s, std::vector<Event>& out) {
  constexpr double kDown = 0.999;
  constexpr double kUp = 0.001;
  ecs::World& world = stage.world();
  const auto performer_of = [&](ecs::Entity e) {
    const auto it = index_of.find(e.bits());
    return it == index_of.end() ? -1 : it->second;
  };
  struct FingerTrack {
    ecs::Entity entity;
    std::int32_t performer;
    double depth = 0.0;
    int key_down = -1;  // the key this finger holds at its bed
  };
  struct InstrumentTrack {
    ecs::Entity entity;
    std::int32_t performer;
    std::array<double, components::Valve::kMax> press{};
    bool moving = false;
  };
  std::vector<FingerTrack> fingers;
  world.view<const components::Finger>().each([&](ecs::Entity e, const components::Finger& f) {
    const auto* hand = world.try_get<components::Hand>(f.hand);
    const std::int32_t p = performer_of(hand != nullptr ? hand->performer : ecs::Entity::null);
    if (p >= 0) fingers.push_back({e, p});
  });
  std::vector<InstrumentTrack> instruments;
  world.view<const components::Instrument>().each(
      [&](ecs::Entity e, const components::Instrument& instrument) {
        const std::int32_t p = performer_of(instrument.performer);
        if (p >= 0) instruments.push_back({e, p});
      });
  if (!(step_s > 0.0) || (fingers.empty() && instruments.empty())) return;
  const auto steps =
      static_cast<std::int64_t>(std::ceil((stage.end_s() - stage.start_s()) / step_s)) + 1;
  double previous_t = stage.start_s();
  for (std::int64_t i = 0; i < steps; ++i) {
    const double t = stage.start_s() + static_cast<double>(i) * step_s;
    stage.run({t, step_s}, ecs::Phase::evaluate);
    const bool first = i == 0;
    for (FingerTrack& track : fingers) {
      const auto& finger = world.get<components::Finger>(track.entity);
      const double depth = finger.press_depth;
      if (!first && track.depth < kDown && depth >= kDown && finger.key >= 0) {
        out.push_back({crossing(previous_t, track.depth, t, depth, kDown), EventKind::key_down,
                       track.performer, finger.key});
        track.key_down = finger.key;
      } else if (!first && track.depth > kUp && depth <= kUp && track.key_down >= 0) {
        out.push_back({crossing(previous_t, track.depth, t, depth, kUp), EventKind::key_up,
                       track.performer, track.key_down});
        track.key_down = -1;
      }
      track.depth = depth;
    }
    for (InstrumentTrack& track : instruments) {
      if (const auto* valve = world.try_get<components::Valve>(track.entity)) {
        for (std::size_t v = 0; v < valve->count && v < track.press.size(); ++v) {
          const double now = valve->press[v];
          const double before = track.press[v];
          const auto number = static_cast<std::int32_t>(v + 1);
          if (!first && before < kDown && now >= kDown) {
            out.push_back({crossing(previous_t, before, t, now, kDown), EventKind::valve_down,
                           track.performer, number});
          } else if (!first && before > kUp && now <= kUp) {
            out.push_back({crossing(previous_t, before, t, now, kUp), EventKind::valve_up,
                           track.performer, number});
          }
          track.press[v] = now;
        }
      }
      if (const auto* slide = world.try_get<components::Slide>(track.entity)) {
        const bool moving = slide->speed_mm_per_s != 0.0;
        if (!first && track.moving && !moving) {
          out.push_back({t, EventKind::slide_arrives, track.performer,
                         static_cast<std::int32_t>(std::lround(slide->position))});
        }
        track.moving = moving;
      }
    }
    previous_t = t;
  }
}

}  // namespace

const char* event_kind_name(EventKind kind) {
  switch (kind) {
    case EventKind::note_on:
      return "note_on";
    case EventKind::note_off:
      return "note_off";
    case EventKind::key_down:
      return "key_down";
    case EventKind::key_up:
      return "key_up";
    case EventKind::valve_down:
      return "valve_down";
    case EventKind::valve_up:
      return "valve_up";
    case EventKind::slide_arrives:
      return "slide_arrives";
    case EventKind::breath_start:
      return "breath_start";
    case EventKind::breath_end:
      return "breath_end";
    case EventKind::cue:
      return "cue";
  }
  return "unknown";
}

void read_poses(const stage::Stage& stage, std::vector<ModelPose>& out) {
  out.resize(stage.instances().size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    const stage::PlacedModel& placed = stage.placed(i);
    ModelPose& pose = out[i];
    pose.root = to_trs(decompose(placed.root));
    pose.local.resize(placed.pose.local.size());
    for (std::size_t n = 0; n < pose.local.size(); ++n) {
      model::NodeTransform local = placed.pose.local[n];
      local.rotation = glm::normalize(local.rotation);
      pose.local[n] = to_trs(local);
    }
    pose.morph_weights.assign(placed.pose.morph_weights.begin(), placed.pose.morph_weights.end());
  }
}

Performance::~Performance() = default;

double Performance::start_s() const { return stage_->start_s(); }
double Performance::end_s() const { return stage_->end_s(); }
const std::vector<std::string>& Performance::notes() const { return stage_->notes(); }

Result<std::unique_ptr<Performance>> Performance::open(const std::filesystem::path& scene_file,
                                                       const Options& options) {
  scene::LoadOptions load_options;
  load_options.content_dir = options.content_dir;
  auto scene = load_scene_or_music(scene_file, load_options);
  if (!scene) return scene.error();
  return stage(*scene, options);
}

Result<std::unique_ptr<Performance>> Performance::stage(const scene::Scene& scene,
                                                        const Options& options) {
  stage::StageOptions stage_options;
  stage_options.content_dir = options.content_dir;
  stage_options.asset_dir = options.asset_dir;
  auto staged = build_stage(scene, stage_options);
  if (!staged) return Error{scene.source + ": " + staged.error().message, staged.error().code};
  std::unique_ptr<Performance> performance(new Performance());
  performance->stage_ = std::move(*staged);
  if (Status s = performance->init(options); !s) return s.error();
  return performance;
}

Status Performance::init(const Options& options) {
  ecs::World& world = stage_->world();
  const std::vector<std::string> clips = clip_names(*stage_);
  std::map<std::uint64_t, std::int32_t> index_of;
  for (std::size_t p = 0; p < stage_->performers().size(); ++p) {
    const ecs::Entity entity = stage_->performers()[p];
    index_of[entity.bits()] = static_cast<std::int32_t>(p);
    PerformerInfo info;
    info.name = clips[p];
    if (const auto* seat = world.try_get<stage::Seat>(entity)) info.family = seat->family;
    info.instrument = info.family == "piano" ? "piano" : "";
    performers_.push_back(std::move(info));
  }
  world.view<const components::Instrument>().each([&](const components::Instrument& instrument) {
    const auto it = index_of.find(instrument.performer.bits());
    if (it != index_of.end()) performers_[static_cast<std::size_t>(it->second)].instrument = instrument.id;
  });

  const std::vector<InstanceLabel> labels = label_instances(*stage_);
  for (std::size_t i = 0; i < stage_->instances().size(); ++i) {
    const stage::PlacedModel& placed = stage_->placed(i);
    ModelInfo info;
    info.name = labels[i].name;
    info.file = stage_->model_files()[placed.model];
    const auto it = index_of.find(placed.performer.bits());
    if (!placed.performer.is_null() && it != index_of.end()) {
      info.performer = it->second;
      performers_[static_cast<std::size_t>(it->second)].models.push_back(i);
    }
    for (const model::Node& node : placed.asset->nodes) {
      info.nodes.push_back(node.name);
      info.parents.push_back(node.parent);
    }
    for (const model::Mesh& mesh : placed.asset->meshes) {
      info.morphs.insert(info.morphs.end(), mesh.target_names.begin(), mesh.target_names.end());
    }
    models_.push_back(std::move(info));
  }

  // The events: the notes as heard, the breaths and cues as planned, the contacts as evaluated.
  world.view<const components::Note>().each([&](const components::Note& note) {
    const auto it = index_of.find(note.performer.bits());
    if (note.performer.is_null() || it == index_of.end() || note.silent) return;
    events_.push_back({note.onset_s, EventKind::note_on, it->second, note.pitch});
    events_.push_back({note.offset_s, EventKind::note_off, it->second, note.pitch});
  });
  for (std::size_t p = 0; p < stage_->performers().size(); ++p) {
    const ecs::Entity entity = stage_->performers()[p];
    const auto performer = static_cast<std::int32_t>(p);
    if (const auto* schedule = world.try_get<components::BreathSchedule>(entity)) {
      for (std::size_t b = 0; b < schedule->breaths.size(); ++b) {
        const auto index = static_cast<std::int32_t>(b);
        events_.push_back({schedule->breaths[b].start_s, EventKind::breath_start, performer, index});
        events_.push_back({schedule->breaths[b].end_s, EventKind::breath_end, performer, index});
      }
    }
    if (const auto* ensemble = world.try_get<ensemble::EnsembleMotionHandle>(entity);
        ensemble != nullptr && ensemble->plan && ensemble->performer < ensemble->plan->performers.size()) {
      const bool lead = ensemble->plan->lead == static_cast<int>(ensemble->performer);
      for (const ensemble::CueMotion& cue : ensemble->plan->performers[ensemble->performer].cues) {
        events_.push_back({cue.dip_s, EventKind::cue, performer, lead ? 1 : 0});
      }
    }
  }
  add_contact_events(*stage_, index_of, options.contact_step_s, events_);
  std::sort(events_.begin(), events_.end(), event_before);
  return Status::success();
}

std::span<const Event> Performance::events_between(double from_s, double to_s) const {
  const auto first = std::lower_bound(events_.begin(), events_.end(), from_s,
                                      [](const Event& e, double t) { return e.t_s < t; });
  const auto last = std::lower_bound(first, events_.end(), to_s,
                                     [](const Event& e, double t) { return e.t_s < t; });
  return {first, last};
}

void Performance::sample(double t_s, Sample& out, double events_window_s) {
  stage_->run({t_s, 0.0});
  out.t_s = t_s;
  read_poses(*stage_, out.models);
  out.events.resize(performers_.size());
  for (std::vector<Event>& list : out.events) list.clear();
  const double window = std::max(events_window_s, 0.0);
  for (const Event& e : events_between(t_s - window, std::nextafter(t_s + window, INFINITY))) {
    out.events[static_cast<std::size_t>(e.performer)].push_back(e);
  }
}

}  // namespace tutti::performance
