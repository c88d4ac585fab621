// SPDX-License-Identifier: MIT
// tutti.h over tutti::performance: handles own a Performance and its last Sample; errors become
// status codes and a thread-local message; nothing throws across the boundary.
#include "tutti.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <vector>

#include <tutti/performance/performance.hpp>

static_assert(TUTTI_VERSION_MAJOR == TUTTI_PROJECT_VERSION_MAJOR &&
                  TUTTI_VERSION_MINOR == TUTTI_PROJECT_VERSION_MINOR &&
                  TUTTI_VERSION_PATCH == TUTTI_PROJECT_VERSION_PATCH,
              "tutti.h's version macros must match CMakeLists.txt's project(VERSION)");

struct tutti_performance {
  std::unique_ptr<tutti::performance::Performance> performance;
  std::vector<int32_t> node_offsets;  // per model, into the nodes of all models; then the total
  tutti::performance::Sample sample;
  bool sampled = false;
};

struct tutti_context {
  const tutti_performance* owner = nullptr;
  tutti::performance::SampleContext context;
  tutti::performance::Sample sample;
  bool sampled = false;
};

namespace {

thread_local std::string last_error;

tutti_status fail(tutti_status status, std::string message) {
  last_error = std::move(message);
  return status;
}

// For the getters that answer NULL or -1: the message, then the value.
template <typename T>
T fail_with(T value, std::string message) {
  last_error = std::move(message);
  return value;
}

// Runs `body` and answers what it answers; an exception answers `on_error` and says what it was:
// nothing throws across the C boundary.
template <typename T, typename Body>
T guarded(const char* function, T on_error, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::exception& e) {
    try {
      last_error = std::string(function) + ": " + e.what();
    } catch (...) {
      last_error.clear();
    }
  } catch (...) {
    try {
      last_error = std::string(function) + ": an unknown exception";
    } catch (...) {
      last_error.clear();
    }
  }
  return on_error;
}

tutti_status status_of(const tutti::Error& error) {
  switch (error.code) {
    case tutti::ErrorCode::bad_input:
      return fail(TUTTI_BAD_INPUT, error.message);
    case tutti::ErrorCode::environment:
      return fail(TUTTI_ENVIRONMENT, error.message);
    case tutti::ErrorCode::internal:
      break;
  }
  return fail(TUTTI_INTERNAL, error.message);
}

// What went wrong with a handle or an index, for the message of the call `function`; empty when
// nothing did.
std::string bad_performance(const char* function, const tutti_performance* p) {
  return p == nullptr ? std::string(function) + ": the performance is NULL" : std::string();
}

std::string bad_index(const char* function, const char* what, int32_t index, std::size_t count) {
  if (index >= 0 && static_cast<std::size_t>(index) < count) return {};
  return std::string(function) + ": no " + what + " " + std::to_string(index) + " (there are " +
         std::to_string(count) + ")";
}

std::string bad_model(const char* function, const tutti_performance* p, int32_t model) {
  if (std::string e = bad_performance(function, p); !e.empty()) return e;
  return bad_index(function, "model", model, p->performance->models().size());
}

std::string bad_performer(const char* function, const tutti_performance* p, int32_t performer) {
  if (std::string e = bad_performance(function, p); !e.empty()) return e;
  return bad_index(function, "performer", performer, p->performance->performers().size());
}

const tutti::performance::ModelInfo& model_info(const tutti_performance* p, int32_t model) {
  return p->performance->models()[static_cast<std::size_t>(model)];
}

const tutti::performance::PerformerInfo& performer_info(const tutti_performance* p,
                                                        int32_t performer) {
  return p->performance->performers()[static_cast<std::size_t>(performer)];
}

void copy_trs(const tutti::performance::Trs& from, tutti_trs& to) {
  for (int i = 0; i < 3; ++i) to.translation[i] = from.translation[static_cast<std::size_t>(i)];
  for (int i = 0; i < 4; ++i) to.rotation[i] = from.rotation[static_cast<std::size_t>(i)];
  for (int i = 0; i < 3; ++i) to.scale[i] = from.scale[static_cast<std::size_t>(i)];
}

// The sample of `model`, or a status saying why there is none.
tutti_status pose_of(const char* function, const tutti_performance* p, int32_t model,
                     const tutti::performance::ModelPose** out) {
  if (std::string e = bad_model(function, p, model); !e.empty()) {
    return fail(TUTTI_INVALID_ARGUMENT, e);
  }
  if (!p->sampled) {
    return fail(TUTTI_INVALID_ARGUMENT, std::string(function) + ": call tutti_sample first");
  }
  *out = &p->sample.models[static_cast<std::size_t>(model)];
  return TUTTI_OK;
}

// Every model's root and local transforms of `sample` into the caller's buffers (tutti_poses).
tutti_status write_poses(const std::string& function, const tutti::performance::Sample& sample,
                         const std::vector<int32_t>& node_offsets, tutti_trs* roots,
                         int32_t root_capacity, tutti_trs* nodes, int32_t node_capacity) {
  const std::size_t models = sample.models.size();
  if (root_capacity != 0 && (roots == nullptr || root_capacity < 0 ||
                             static_cast<std::size_t>(root_capacity) < models)) {
    return fail(TUTTI_INVALID_ARGUMENT, function +
                                            ": the roots buffer holds fewer transforms than " +
                                            std::to_string(models) + " models");
  }
  const int32_t total = node_offsets.back();
  if (node_capacity < total || (nodes == nullptr && total > 0)) {
    return fail(TUTTI_INVALID_ARGUMENT, function +
                                            ": the nodes buffer holds fewer transforms than " +
                                            std::to_string(total) + " nodes of all models");
  }
  for (std::size_t m = 0; m < models; ++m) {
    const tutti::performance::ModelPose& pose = sample.models[m];
    if (root_capacity != 0) copy_trs(pose.root, roots[m]);
    tutti_trs* first = nodes + node_offsets[m];
    for (std::size_t n = 0; n < pose.local.size(); ++n) copy_trs(pose.local[n], first[n]);
  }
  return TUTTI_OK;
}

// A model's morph weights of `sample` into the caller's buffer (tutti_model_morph_weights).
tutti_status write_morph_weights(const std::string& function,
                                 const tutti::performance::Sample& sample, int32_t model,
                                 float* out, int32_t capacity) {
  if (std::string e = bad_index(function.c_str(), "model", model, sample.models.size());
      !e.empty()) {
    return fail(TUTTI_INVALID_ARGUMENT, e);
  }
  const std::vector<float>& weights = sample.models[static_cast<std::size_t>(model)].morph_weights;
  if (capacity < 0 || static_cast<std::size_t>(capacity) < weights.size() ||
      (out == nullptr && !weights.empty())) {
    return fail(TUTTI_INVALID_ARGUMENT, function + ": the buffer holds fewer weights than " +
                                            std::to_string(weights.size()) + " morph targets");
  }
  std::copy(weights.begin(), weights.end(), out);
  return TUTTI_OK;
}

}  // namespace

extern "C" {

const char* tutti_version(void) { return TUTTI_VERSION; }

int32_t tutti_version_number(void) { return TUTTI_VERSION_NUMBER; }

const char* tutti_last_error(void) { return last_error.c_str(); }

int32_t tutti_event_kind_count(void) {
  return guarded<int32_t>("tutti_event_kind_count", 0, [&]() -> int32_t {
    return static_cast<int32_t>(tutti::performance::event_kinds().size());
  });
}

const char* tutti_event_kind_name(int32_t kind) {
  return guarded<const char*>("tutti_event_kind_name", nullptr, [&]() -> const char* {
    const auto kinds = tutti::performance::event_kinds();
    if (std::string e = bad_index("tutti_event_kind_name", "event kind", kind, kinds.size());
        !e.empty()) {
      return fail_with<const char*>(nullptr, e);
    }
    // The names are string literals (performance::event_kinds, stage::StopName): NUL-terminated
    // and static.
    return kinds[static_cast<std::size_t>(kind)].data();
  });
}

int32_t tutti_event_kind_by_name(const char* name) {
  return guarded<int32_t>("tutti_event_kind_by_name", -1, [&]() -> int32_t {
    if (name == nullptr) return fail_with(-1, "tutti_event_kind_by_name: the name is NULL");
    if (const int32_t kind = tutti::performance::find_event_kind(name); kind >= 0) return kind;
    return fail_with(-1, std::string("tutti_event_kind_by_name: no event kind \"") + name + "\"");
  });
}

void tutti_default_options(tutti_options* options) {
  if (options == nullptr) {
    try {
      last_error = "tutti_default_options: options is NULL";
    } catch (...) {
      last_error.clear();
    }
    return;
  }
  options->struct_size = sizeof(tutti_options);
  options->content_dir = nullptr;
  options->asset_dir = nullptr;
  options->contact_step_s = tutti::performance::Options{}.contact_step_s;
  options->contact_fps = tutti::performance::Options{}.contact_fps;
}

tutti_status tutti_open(const char* file, const tutti_options* options,
                        tutti_performance** out) {
  return guarded<tutti_status>("tutti_open", TUTTI_INTERNAL, [&]() -> tutti_status {
    if (out == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: out is NULL");
    *out = nullptr;
    if (file == nullptr || *file == '\0') {
      return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: no scene or music file given");
    }
    tutti::performance::Options o;
    if (options != nullptr) {
      // Only the fields the host's struct_size covers are read: a host built against an older
      // header passes a shorter struct.
      const auto covers = [&](std::size_t offset, std::size_t size) {
        return options->struct_size >= offset + size;
      };
      if (!covers(offsetof(tutti_options, content_dir), sizeof(const char*))) {
        return fail(TUTTI_INVALID_ARGUMENT,
                    "tutti_open: options->struct_size is " + std::to_string(options->struct_size) +
                        "; fill the options with tutti_default_options first");
      }
      if (options->content_dir != nullptr) o.content_dir = options->content_dir;
      if (covers(offsetof(tutti_options, asset_dir), sizeof(const char*)) &&
          options->asset_dir != nullptr) {
        o.asset_dir = options->asset_dir;
      }
      if (covers(offsetof(tutti_options, contact_step_s), sizeof(double))) {
        if (!(options->contact_step_s >= 0.0)) {
          return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: contact_step_s must be >= 0");
        }
        o.contact_step_s = options->contact_step_s;
      }
      if (covers(offsetof(tutti_options, contact_fps), sizeof(double))) {
        if (!(options->contact_fps >= 0.0) || !std::isfinite(options->contact_fps)) {
          return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: contact_fps must be >= 0");
        }
        o.contact_fps = options->contact_fps;
      }
    }
    auto opened = tutti::performance::Performance::open(file, o);
    if (!opened) return status_of(opened.error());
    auto handle = std::make_unique<tutti_performance>();
    handle->performance = std::move(*opened);
    int32_t total = 0;
    for (const auto& model : handle->performance->models()) {
      handle->node_offsets.push_back(total);
      total += static_cast<int32_t>(model.nodes.size());
    }
    handle->node_offsets.push_back(total);
    *out = handle.release();
    last_error.clear();
    return TUTTI_OK;
  });
}

void tutti_close(tutti_performance* performance) { delete performance; }

double tutti_start_s(const tutti_performance* p) {
  return guarded<double>("tutti_start_s", 0.0, [&] {
    if (std::string e = bad_performance("tutti_start_s", p); !e.empty()) return fail_with(0.0, e);
    return p->performance->start_s();
  });
}

double tutti_end_s(const tutti_performance* p) {
  return guarded<double>("tutti_end_s", 0.0, [&] {
    if (std::string e = bad_performance("tutti_end_s", p); !e.empty()) return fail_with(0.0, e);
    return p->performance->end_s();
  });
}

int32_t tutti_performer_count(const tutti_performance* p) {
  return guarded<int32_t>("tutti_performer_count", -1, [&] {
    if (std::string e = bad_performance("tutti_performer_count", p); !e.empty()) {
      return fail_with(-1, e);
    }
    return static_cast<int32_t>(p->performance->performers().size());
  });
}

// A performer's name, family or instrument.
#define TUTTI_PERFORMER_STRING(function, field)                                       \
  const char* function(const tutti_performance* p, int32_t performer) {              \
    return guarded<const char*>(#function, nullptr, [&]() -> const char* {           \
      if (std::string e = bad_performer(#function, p, performer); !e.empty()) {      \
        return fail_with<const char*>(nullptr, e);                                   \
      }                                                                              \
      return performer_info(p, performer).field.c_str();                             \
    });                                                                              \
  }
TUTTI_PERFORMER_STRING(tutti_performer_name, name)
TUTTI_PERFORMER_STRING(tutti_performer_family, family)
TUTTI_PERFORMER_STRING(tutti_performer_instrument, instrument)
#undef TUTTI_PERFORMER_STRING

int32_t tutti_model_count(const tutti_performance* p) {
  return guarded<int32_t>("tutti_model_count", -1, [&] {
    if (std::string e = bad_performance("tutti_model_count", p); !e.empty()) return fail_with(-1, e);
    return static_cast<int32_t>(p->performance->models().size());
  });
}

const char* tutti_model_name(const tutti_performance* p, int32_t model) {
  return guarded<const char*>("tutti_model_name", nullptr, [&]() -> const char* {
    if (std::string e = bad_model("tutti_model_name", p, model); !e.empty()) {
      return fail_with<const char*>(nullptr, e);
    }
    return model_info(p, model).name.c_str();
  });
}

const char* tutti_model_file(const tutti_performance* p, int32_t model) {
  return guarded<const char*>("tutti_model_file", nullptr, [&]() -> const char* {
    if (std::string e = bad_model("tutti_model_file", p, model); !e.empty()) {
      return fail_with<const char*>(nullptr, e);
    }
    return model_info(p, model).file.c_str();
  });
}

int32_t tutti_model_performer(const tutti_performance* p, int32_t model) {
  return guarded<int32_t>("tutti_model_performer", -1, [&] {
    if (std::string e = bad_model("tutti_model_performer", p, model); !e.empty()) {
      return fail_with(-1, e);
    }
    return model_info(p, model).performer;
  });
}

int32_t tutti_node_count(const tutti_performance* p, int32_t model) {
  return guarded<int32_t>("tutti_node_count", -1, [&] {
    if (std::string e = bad_model("tutti_node_count", p, model); !e.empty()) return fail_with(-1, e);
    return static_cast<int32_t>(model_info(p, model).nodes.size());
  });
}

const char* tutti_node_name(const tutti_performance* p, int32_t model, int32_t node) {
  return guarded<const char*>("tutti_node_name", nullptr, [&]() -> const char* {
    std::string e = bad_model("tutti_node_name", p, model);
    if (e.empty()) e = bad_index("tutti_node_name", "node", node, model_info(p, model).nodes.size());
    if (!e.empty()) return fail_with<const char*>(nullptr, e);
    return model_info(p, model).nodes[static_cast<std::size_t>(node)].c_str();
  });
}

int32_t tutti_node_parent(const tutti_performance* p, int32_t model, int32_t node) {
  return guarded<int32_t>("tutti_node_parent", -1, [&] {
    std::string e = bad_model("tutti_node_parent", p, model);
    if (e.empty()) {
      e = bad_index("tutti_node_parent", "node", node, model_info(p, model).parents.size());
    }
    if (!e.empty()) return fail_with(-1, e);
    return model_info(p, model).parents[static_cast<std::size_t>(node)];
  });
}

int32_t tutti_morph_count(const tutti_performance* p, int32_t model) {
  return guarded<int32_t>("tutti_morph_count", -1, [&] {
    if (std::string e = bad_model("tutti_morph_count", p, model); !e.empty()) {
      return fail_with(-1, e);
    }
    return static_cast<int32_t>(model_info(p, model).morphs.size());
  });
}

const char* tutti_morph_name(const tutti_performance* p, int32_t model, int32_t morph) {
  return guarded<const char*>("tutti_morph_name", nullptr, [&]() -> const char* {
    std::string e = bad_model("tutti_morph_name", p, model);
    if (e.empty()) {
      e = bad_index("tutti_morph_name", "morph", morph, model_info(p, model).morphs.size());
    }
    if (!e.empty()) return fail_with<const char*>(nullptr, e);
    return model_info(p, model).morphs[static_cast<std::size_t>(morph)].c_str();
  });
}

int32_t tutti_node_total(const tutti_performance* p) {
  return guarded<int32_t>("tutti_node_total", -1, [&] {
    if (std::string e = bad_performance("tutti_node_total", p); !e.empty()) return fail_with(-1, e);
    return p->node_offsets.back();
  });
}

int32_t tutti_node_offset(const tutti_performance* p, int32_t model) {
  return guarded<int32_t>("tutti_node_offset", -1, [&] {
    if (std::string e = bad_model("tutti_node_offset", p, model); !e.empty()) {
      return fail_with(-1, e);
    }
    return p->node_offsets[static_cast<std::size_t>(model)];
  });
}

tutti_status tutti_sample(tutti_performance* p, double t_s) {
  return guarded<tutti_status>("tutti_sample", TUTTI_INTERNAL, [&] {
    if (std::string e = bad_performance("tutti_sample", p); !e.empty()) {
      return fail(TUTTI_INVALID_ARGUMENT, e);
    }
    if (!std::isfinite(t_s)) {
      return fail(TUTTI_INVALID_ARGUMENT,
                  "tutti_sample: the time must be a finite number of seconds");
    }
    p->sampled = false;  // until the sample is whole
    p->performance->sample(t_s, p->sample, 0.0);
    p->sampled = true;
    return TUTTI_OK;
  });
}

tutti_status tutti_model_root(const tutti_performance* p, int32_t model, tutti_trs* out) {
  return guarded<tutti_status>("tutti_model_root", TUTTI_INTERNAL, [&] {
    const tutti::performance::ModelPose* pose = nullptr;
    if (tutti_status s = pose_of("tutti_model_root", p, model, &pose); s != TUTTI_OK) return s;
    if (out == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_model_root: out is NULL");
    copy_trs(pose->root, *out);
    return TUTTI_OK;
  });
}

tutti_status tutti_model_pose(const tutti_performance* p, int32_t model, tutti_trs* out,
                              int32_t capacity) {
  return guarded<tutti_status>("tutti_model_pose", TUTTI_INTERNAL, [&] {
    const tutti::performance::ModelPose* pose = nullptr;
    if (tutti_status s = pose_of("tutti_model_pose", p, model, &pose); s != TUTTI_OK) return s;
    if (out == nullptr || capacity < 0 || static_cast<std::size_t>(capacity) < pose->local.size()) {
      return fail(TUTTI_INVALID_ARGUMENT,
                  "tutti_model_pose: the buffer holds fewer transforms than " +
                      std::to_string(pose->local.size()) + " nodes");
    }
    for (std::size_t n = 0; n < pose->local.size(); ++n) copy_trs(pose->local[n], out[n]);
    return TUTTI_OK;
  });
}

tutti_status tutti_poses(const tutti_performance* p, tutti_trs* roots, int32_t root_capacity,
                         tutti_trs* nodes, int32_t node_capacity) {
  return guarded<tutti_status>("tutti_poses", TUTTI_INTERNAL, [&] {
    if (std::string e = bad_performance("tutti_poses", p); !e.empty()) {
      return fail(TUTTI_INVALID_ARGUMENT, e);
    }
    if (!p->sampled) return fail(TUTTI_INVALID_ARGUMENT, "tutti_poses: call tutti_sample first");
    return write_poses("tutti_poses", p->sample, p->node_offsets, roots, root_capacity, nodes,
                       node_capacity);
  });
}

tutti_status tutti_context_new(const tutti_performance* p, tutti_context** out) {
  return guarded<tutti_status>("tutti_context_new", TUTTI_INTERNAL, [&]() -> tutti_status {
    if (out == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_context_new: out is NULL");
    *out = nullptr;
    if (std::string e = bad_performance("tutti_context_new", p); !e.empty()) {
      return fail(TUTTI_INVALID_ARGUMENT, e);
    }
    *out = new tutti_context{p, p->performance->make_context(), {}, false};
    return TUTTI_OK;
  });
}

void tutti_context_free(tutti_context* context) { delete context; }

tutti_status tutti_context_sample(tutti_context* c, double t_s) {
  return guarded<tutti_status>("tutti_context_sample", TUTTI_INTERNAL, [&] {
    if (c == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_context_sample: the context is NULL");
    if (!std::isfinite(t_s)) {
      return fail(TUTTI_INVALID_ARGUMENT,
                  "tutti_context_sample: the time must be a finite number of seconds");
    }
    c->sampled = false;  // until the sample is whole
    c->owner->performance->sample(c->context, t_s, c->sample, 0.0);
    c->sampled = true;
    return TUTTI_OK;
  });
}

tutti_status tutti_context_poses(const tutti_context* c, tutti_trs* roots, int32_t root_capacity,
                                 tutti_trs* nodes, int32_t node_capacity) {
  return guarded<tutti_status>("tutti_context_poses", TUTTI_INTERNAL, [&] {
    if (c == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_context_poses: the context is NULL");
    if (!c->sampled) {
      return fail(TUTTI_INVALID_ARGUMENT, "tutti_context_poses: call tutti_context_sample first");
    }
    return write_poses("tutti_context_poses", c->sample, c->owner->node_offsets, roots,
                       root_capacity, nodes, node_capacity);
  });
}

tutti_status tutti_context_morph_weights(const tutti_context* c, int32_t model, float* out,
                                         int32_t capacity) {
  return guarded<tutti_status>("tutti_context_morph_weights", TUTTI_INTERNAL, [&] {
    if (c == nullptr) {
      return fail(TUTTI_INVALID_ARGUMENT, "tutti_context_morph_weights: the context is NULL");
    }
    if (!c->sampled) {
      return fail(TUTTI_INVALID_ARGUMENT,
                  "tutti_context_morph_weights: call tutti_context_sample first");
    }
    return write_morph_weights("tutti_context_morph_weights", c->sample, model, out, capacity);
  });
}

tutti_status tutti_model_morph_weights(const tutti_performance* p, int32_t model, float* out,
                                       int32_t capacity) {
  return guarded<tutti_status>("tutti_model_morph_weights", TUTTI_INTERNAL, [&] {
    const tutti::performance::ModelPose* pose = nullptr;
    if (tutti_status s = pose_of("tutti_model_morph_weights", p, model, &pose); s != TUTTI_OK) {
      return s;
    }
    return write_morph_weights("tutti_model_morph_weights", p->sample, model, out, capacity);
  });
}

int32_t tutti_events(const tutti_performance* p, double from_s, double to_s, tutti_event* out,
                     int32_t capacity) {
  return guarded<int32_t>("tutti_events", -1, [&] {
    if (std::string e = bad_performance("tutti_events", p); !e.empty()) return fail_with(-1, e);
    if (std::isnan(from_s) || std::isnan(to_s)) {
      return fail_with(-1, "tutti_events: the times must be numbers of seconds, not NaN");
    }
    const auto events = p->performance->events_between(from_s, to_s);
    const std::size_t room =
        out != nullptr && capacity > 0 ? static_cast<std::size_t>(capacity) : 0;
    for (std::size_t i = 0; i < events.size() && i < room; ++i) {
      out[i].t_s = events[i].t_s;
      out[i].kind = static_cast<int32_t>(events[i].kind);
      out[i].performer = events[i].performer;
      out[i].value = events[i].value;
      out[i].reserved = 0;
    }
    return static_cast<int32_t>(events.size());
  });
}

int32_t tutti_contacts(const tutti_performance* p, double from_s, double to_s, tutti_contact* out,
                       int32_t capacity) {
  return guarded<int32_t>("tutti_contacts", -1, [&] {
    if (std::string e = bad_performance("tutti_contacts", p); !e.empty()) return fail_with(-1, e);
    if (std::isnan(from_s) || std::isnan(to_s)) {
      return fail_with(-1, "tutti_contacts: the times must be numbers of seconds, not NaN");
    }
    const std::size_t room =
        out != nullptr && capacity > 0 ? static_cast<std::size_t>(capacity) : 0;
    std::size_t count = 0;
    for (const tutti::performance::Contact& c : p->performance->contacts()) {
      if (c.from_s >= to_s) break;  // by start time: none later overlaps
      if (c.to_s < from_s) continue;
      if (count < room) {
        tutti_contact& o = out[count];
        o.from_s = c.from_s;
        o.to_s = c.to_s;
        o.performer = c.performer;
        o.body_model = c.body_model;
        o.body_node = c.body_node;
        o.part_model = c.part_model;
        o.part_node = c.part_node;
        o.midi = c.midi;
        for (int k = 0; k < 3; ++k) o.part_point_m[k] = c.part_point_m[static_cast<std::size_t>(k)];
        o.reserved = 0;
      }
      ++count;
    }
    return static_cast<int32_t>(count);
  });
}

}  // extern "C"
