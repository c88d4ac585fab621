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
#include <tutti/stage/contact_detector.hpp>
#include <tutti/stage/contact_recorder.hpp>
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

// The performance's own event kinds, first in event_kinds().
constexpr std::uint16_t kNoteOn = 0, kNoteOff = 1, kBreathStart = 2, kBreathEnd = 3, kCue = 4;

bool event_before(const Event& a, const Event& b) {
  return std::tie(a.t_s, a.performer, a.kind, a.value) <
         std::tie(b.t_s, b.performer, b.kind, b.value);
}

// The stops the families' players reach (stage/contact_detector.hpp): keys, valves, ..., on a grid of
// `step_s` over the stage's range, as events of the performers they belong to.
void add_contact_events(stage::Stage& stage, const std::map<std::uint64_t, std::int32_t>& index_of,
                        double step_s, std::vector<Event>& out) {
  const auto stops =
      stage::detect_stops(stage, {stage.start_s(), stage.end_s(), step_s, /*include_end=*/true});
  for (const stage::Stop& stop : stops) {
    const auto it = index_of.find(stop.performer.bits());
    if (it == index_of.end()) continue;
    if (!stop.kind->host_event) continue;  // another event says it (a tongue: the note_on)
    const std::int32_t kind = find_event_kind(stop.kind->name);
    if (kind < 0) continue;  // a family outside the default list
    out.push_back({stop.t_s, static_cast<std::uint16_t>(kind), it->second, stop.value});
  }
}

// Where bodies touch instruments (stage/contact_recorder.hpp), recorded on `fps` frames over
// the stage's range, as spans of the performers they belong to, by start time.
std::vector<Contact> record_contacts(stage::Stage& stage,
                                     const std::map<std::uint64_t, std::int32_t>& index_of,
                                     double fps) {
  std::vector<Contact> out;
  if (!(fps > 0.0)) return out;
  stage::ContactRecorder recorder;
  const double range_s = stage.end_s() - stage.start_s();
  const auto frames = static_cast<std::int64_t>(std::floor(std::max(range_s, 0.0) * fps)) + 1;
  for (std::int64_t k = 0; k < frames; ++k) {
    const double t = stage.start_s() + static_cast<double>(k) / fps;
    stage::evaluate_stage(stage, t);
    recorder.record(stage, t);
  }
  for (const stage::Contact& contact : recorder.contacts()) {
    const auto it = index_of.find(contact.performer.bits());
    if (it == index_of.end()) continue;
    for (const stage::ContactSpan& span : contact.spans) {
      Contact c;
      c.from_s = span.from_s;
      c.to_s = span.to_s;
      c.performer = it->second;
      c.body_model = static_cast<std::int32_t>(contact.body_instance);
      c.body_node = contact.body_node;
      c.part_model = static_cast<std::int32_t>(contact.part_instance);
      c.part_node = contact.part_node;
      c.part_point_m = {static_cast<float>(span.part_point_m.x),
                        static_cast<float>(span.part_point_m.y),
                        static_cast<float>(span.part_point_m.z)};
      c.midi = span.midi;
      out.push_back(c);
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const Contact& a, const Contact& b) {
    return std::tie(a.from_s, a.performer, a.body_model, a.body_node, a.part_model, a.part_node) <
           std::tie(b.from_s, b.performer, b.body_model, b.body_node, b.part_model, b.part_node);
  });
  return out;
}

// Every placed model's pose as a host reads it: rotations normalised, roots as TRS.
template <typename Placed>
void read_posed_models(const Placed& placed_model, std::size_t count, std::vector<ModelPose>& out) {
  out.resize(count);
  for (std::size_t i = 0; i < out.size(); ++i) {
    const stage::PlacedModel& placed = placed_model(i);
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

}  // namespace

std::span<const std::string_view> event_kinds() {
  static const std::vector<std::string_view> kinds = [] {
    // In the order of kNoteOn ... kCue. Every name is a string literal (stage::StopName), as the C
    // API's tutti_event_kind_name needs.
    std::vector<std::string_view> out{"note_on", "note_off", "breath_start", "breath_end", "cue"};
    for (const stage::FamilyPlugin* family : default_families()) {
      for (const stage::StopKind* kind : family->stop_kinds()) {
        if (kind->host_event && std::find(out.begin(), out.end(), kind->name.view()) == out.end()) {
          out.push_back(kind->name.view());
        }
      }
    }
    return out;
  }();
  return kinds;
}

std::string_view event_kind_name(std::uint16_t kind) {
  const auto kinds = event_kinds();
  return kind < kinds.size() ? kinds[kind] : std::string_view{};
}

std::int32_t find_event_kind(std::string_view name) {
  const auto kinds = event_kinds();
  const auto it = std::find(kinds.begin(), kinds.end(), name);
  return it == kinds.end() ? -1 : static_cast<std::int32_t>(it - kinds.begin());
}

void read_poses(const stage::Stage& stage, std::vector<ModelPose>& out) {
  read_posed_models([&stage](std::size_t i) -> const stage::PlacedModel& { return stage.placed(i); },
                    stage.instances().size(), out);
}

void read_poses(const stage::Stage& stage, const stage::StageContext& context,
                std::vector<ModelPose>& out) {
  read_posed_models(
      [&context](std::size_t i) -> const stage::PlacedModel& { return context.placed(i); },
      stage.instances().size(), out);
}

Performance::~Performance() = default;

double Performance::start_s() const { return stage_->start_s(); }
double Performance::end_s() const { return stage_->end_s(); }
const std::vector<std::string>& Performance::notes() const { return stage_->notes(); }

Result<std::unique_ptr<Performance>> Performance::open(const std::filesystem::path& scene_file,
                                                       const Options& options) {
  auto scene = load_scene_or_music(scene_file, options.content_dir);
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
    if (const auto* seat = world.try_get<stage::Seat>(entity)) {
      info.family = seat->family;
      info.instrument = seat->instrument;
    }
    performers_.push_back(std::move(info));
  }

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
    events_.push_back({note.onset_s, kNoteOn, it->second, note.pitch});
    events_.push_back({note.offset_s, kNoteOff, it->second, note.pitch});
  });
  for (std::size_t p = 0; p < stage_->performers().size(); ++p) {
    const ecs::Entity entity = stage_->performers()[p];
    const auto performer = static_cast<std::int32_t>(p);
    if (const auto* schedule = world.try_get<components::BreathSchedule>(entity)) {
      for (std::size_t b = 0; b < schedule->breaths.size(); ++b) {
        const auto index = static_cast<std::int32_t>(b);
        events_.push_back({schedule->breaths[b].start_s, kBreathStart, performer, index});
        events_.push_back({schedule->breaths[b].end_s, kBreathEnd, performer, index});
      }
    }
    if (const auto* ensemble = world.try_get<ensemble_variation::EnsembleMotionHandle>(entity);
        ensemble != nullptr && ensemble->plan && ensemble->performer < ensemble->plan->performers.size()) {
      const bool lead = ensemble->plan->lead == static_cast<int>(ensemble->performer);
      for (const ensemble_variation::CueMotion& cue : ensemble->plan->performers[ensemble->performer].cues) {
        events_.push_back({cue.dip_s, kCue, performer, lead ? 1 : 0});
      }
    }
  }
  add_contact_events(*stage_, index_of, options.contact_step_s, events_);
  std::sort(events_.begin(), events_.end(), event_before);
  contacts_ = record_contacts(*stage_, index_of, options.contact_fps);
  return Status::success();
}

std::span<const Event> Performance::events_between(double from_s, double to_s) const {
  const auto first = std::lower_bound(events_.begin(), events_.end(), from_s,
                                      [](const Event& e, double t) { return e.t_s < t; });
  const auto last = std::lower_bound(first, events_.end(), to_s,
                                     [](const Event& e, double t) { return e.t_s < t; });
  return {first, last};
}

struct SampleContext::State {
  stage::StageContext context;
};

SampleContext::SampleContext(std::unique_ptr<State> state) : state_(std::move(state)) {}
SampleContext::SampleContext(SampleContext&&) noexcept = default;
SampleContext& SampleContext::operator=(SampleContext&&) noexcept = default;
SampleContext::~SampleContext() = default;

SampleContext Performance::make_context() const {
  return SampleContext(std::make_unique<SampleContext::State>(
      SampleContext::State{stage_->make_context()}));
}

void Performance::sample(SampleContext& context, double t_s, Sample& out,
                         double events_window_s) const {
  if (!context.state_) throw std::invalid_argument("Performance::sample: a moved-from context");
  stage_->run(context.state_->context, {t_s, 0.0});
  read_poses(*stage_, context.state_->context, out.models);
  fill_events(t_s, out, events_window_s);
}

void Performance::sample(double t_s, Sample& out, double events_window_s) {
  stage_->run({t_s, 0.0});
  read_poses(*stage_, out.models);
  fill_events(t_s, out, events_window_s);
}

void Performance::fill_events(double t_s, Sample& out, double events_window_s) const {
  out.t_s = t_s;
  out.events.resize(performers_.size());
  for (std::vector<Event>& list : out.events) list.clear();
  const double window = std::max(events_window_s, 0.0);
  for (const Event& e : events_between(t_s - window, std::nextafter(t_s + window, INFINITY))) {
    out.events[static_cast<std::size_t>(e.performer)].push_back(e);
  }
}

}  // namespace tutti::performance
