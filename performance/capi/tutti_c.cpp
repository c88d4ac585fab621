// tutti.h over tutti::performance: handles own a Performance and its last Sample; errors become
// status codes and a thread-local message; nothing throws across the boundary.
#include "tutti.h"

#include <cmath>
#include <exception>
#include <memory>
#include <string>

#include <tutti/performance/performance.hpp>

struct tutti_performance {
  std::unique_ptr<tutti::performance::Performance> performance;
  tutti::performance::Sample sample;
  bool sampled = false;
};

namespace {

thread_local std::string last_error;

tutti_status fail(tutti_status status, std::string message) {
  last_error = std::move(message);
  return status;
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

bool valid_model(const tutti_performance* p, int32_t model) {
  return p != nullptr && model >= 0 &&
         static_cast<std::size_t>(model) < p->performance->models().size();
}

bool valid_performer(const tutti_performance* p, int32_t performer) {
  return p != nullptr && performer >= 0 &&
         static_cast<std::size_t>(performer) < p->performance->performers().size();
}

const tutti::performance::ModelInfo* model_info(const tutti_performance* p, int32_t model) {
  return valid_model(p, model) ? &p->performance->models()[static_cast<std::size_t>(model)]
                               : nullptr;
}

void copy_trs(const tutti::performance::Trs& from, tutti_trs& to) {
  for (int i = 0; i < 3; ++i) to.translation[i] = from.translation[static_cast<std::size_t>(i)];
  for (int i = 0; i < 4; ++i) to.rotation[i] = from.rotation[static_cast<std::size_t>(i)];
  for (int i = 0; i < 3; ++i) to.scale[i] = from.scale[static_cast<std::size_t>(i)];
}

// The sample of `model`, or a status saying why there is none.
tutti_status pose_of(const tutti_performance* p, int32_t model,
                     const tutti::performance::ModelPose** out) {
  if (!valid_model(p, model)) return fail(TUTTI_INVALID_ARGUMENT, "tutti: no such model");
  if (!p->sampled) return fail(TUTTI_INVALID_ARGUMENT, "tutti: call tutti_sample first");
  *out = &p->sample.models[static_cast<std::size_t>(model)];
  return TUTTI_OK;
}

}  // namespace

extern "C" {

const char* tutti_version(void) { return TUTTI_VERSION; }

const char* tutti_last_error(void) { return last_error.c_str(); }

const char* tutti_event_kind_name(int32_t kind) {
  if (kind < 0 || kind > TUTTI_CUE) return "unknown";
  return tutti::performance::event_kind_name(static_cast<tutti::performance::EventKind>(kind));
}

void tutti_default_options(tutti_options* options) {
  if (options == nullptr) return;
  options->content_dir = nullptr;
  options->asset_dir = nullptr;
  options->contact_step_s = tutti::performance::Options{}.contact_step_s;
}

tutti_status tutti_open(const char* scene_file, const tutti_options* options,
                        tutti_performance** out) {
  if (out == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: out is NULL");
  *out = nullptr;
  if (scene_file == nullptr || *scene_file == '\0') {
    return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: no scene file given");
  }
  try {
    tutti::performance::Options o;
    if (options != nullptr) {
      if (options->content_dir != nullptr) o.content_dir = options->content_dir;
      if (options->asset_dir != nullptr) o.asset_dir = options->asset_dir;
      if (!(options->contact_step_s >= 0.0)) {
        return fail(TUTTI_INVALID_ARGUMENT, "tutti_open: contact_step_s must be >= 0");
      }
      o.contact_step_s = options->contact_step_s;
    }
    auto opened = tutti::performance::Performance::open(scene_file, o);
    if (!opened) return status_of(opened.error());
    auto handle = std::make_unique<tutti_performance>();
    handle->performance = std::move(*opened);
    *out = handle.release();
    last_error.clear();
    return TUTTI_OK;
  } catch (const std::exception& e) {
    return fail(TUTTI_INTERNAL, std::string("tutti_open: ") + e.what());
  }
}

void tutti_close(tutti_performance* performance) { delete performance; }

double tutti_start_s(const tutti_performance* p) {
  return p != nullptr ? p->performance->start_s() : 0.0;
}

double tutti_end_s(const tutti_performance* p) {
  return p != nullptr ? p->performance->end_s() : 0.0;
}

int32_t tutti_performer_count(const tutti_performance* p) {
  return p != nullptr ? static_cast<int32_t>(p->performance->performers().size()) : -1;
}

const char* tutti_performer_name(const tutti_performance* p, int32_t performer) {
  if (!valid_performer(p, performer)) return nullptr;
  return p->performance->performers()[static_cast<std::size_t>(performer)].name.c_str();
}

const char* tutti_performer_family(const tutti_performance* p, int32_t performer) {
  if (!valid_performer(p, performer)) return nullptr;
  return p->performance->performers()[static_cast<std::size_t>(performer)].family.c_str();
}

const char* tutti_performer_instrument(const tutti_performance* p, int32_t performer) {
  if (!valid_performer(p, performer)) return nullptr;
  return p->performance->performers()[static_cast<std::size_t>(performer)].instrument.c_str();
}

int32_t tutti_model_count(const tutti_performance* p) {
  return p != nullptr ? static_cast<int32_t>(p->performance->models().size()) : -1;
}

const char* tutti_model_name(const tutti_performance* p, int32_t model) {
  const auto* info = model_info(p, model);
  return info != nullptr ? info->name.c_str() : nullptr;
}

const char* tutti_model_file(const tutti_performance* p, int32_t model) {
  const auto* info = model_info(p, model);
  return info != nullptr ? info->file.c_str() : nullptr;
}

int32_t tutti_model_performer(const tutti_performance* p, int32_t model) {
  const auto* info = model_info(p, model);
  return info != nullptr ? info->performer : -1;
}

int32_t tutti_node_count(const tutti_performance* p, int32_t model) {
  const auto* info = model_info(p, model);
  return info != nullptr ? static_cast<int32_t>(info->nodes.size()) : -1;
}

const char* tutti_node_name(const tutti_performance* p, int32_t model, int32_t node) {
  const auto* info = model_info(p, model);
  if (info == nullptr || node < 0 || static_cast<std::size_t>(node) >= info->nodes.size()) {
    return nullptr;
  }
  return info->nodes[static_cast<std::size_t>(node)].c_str();
}

int32_t tutti_node_parent(const tutti_performance* p, int32_t model, int32_t node) {
  const auto* info = model_info(p, model);
  if (info == nullptr || node < 0 || static_cast<std::size_t>(node) >= info->parents.size()) {
    return -1;
  }
  return info->parents[static_cast<std::size_t>(node)];
}

int32_t tutti_morph_count(const tutti_performance* p, int32_t model) {
  const auto* info = model_info(p, model);
  return info != nullptr ? static_cast<int32_t>(info->morphs.size()) : -1;
}

const char* tutti_morph_name(const tutti_performance* p, int32_t model, int32_t morph) {
  const auto* info = model_info(p, model);
  if (info == nullptr || morph < 0 || static_cast<std::size_t>(morph) >= info->morphs.size()) {
    return nullptr;
  }
  return info->morphs[static_cast<std::size_t>(morph)].c_str();
}

tutti_status tutti_sample(tutti_performance* p, double t_s) {
  if (p == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_sample: null performance");
  if (!std::isfinite(t_s)) {
    return fail(TUTTI_INVALID_ARGUMENT, "tutti_sample: the time must be a finite number of seconds");
  }
  try {
    p->performance->sample(t_s, p->sample, 0.0);
    p->sampled = true;
    return TUTTI_OK;
  } catch (const std::exception& e) {
    return fail(TUTTI_INTERNAL, std::string("tutti_sample: ") + e.what());
  }
}

tutti_status tutti_model_root(const tutti_performance* p, int32_t model, tutti_trs* out) {
  const tutti::performance::ModelPose* pose = nullptr;
  if (tutti_status s = pose_of(p, model, &pose); s != TUTTI_OK) return s;
  if (out == nullptr) return fail(TUTTI_INVALID_ARGUMENT, "tutti_model_root: out is NULL");
  copy_trs(pose->root, *out);
  return TUTTI_OK;
}

tutti_status tutti_model_pose(const tutti_performance* p, int32_t model, tutti_trs* out,
                              int32_t capacity) {
  const tutti::performance::ModelPose* pose = nullptr;
  if (tutti_status s = pose_of(p, model, &pose); s != TUTTI_OK) return s;
  if (out == nullptr || capacity < 0 || static_cast<std::size_t>(capacity) < pose->local.size()) {
    return fail(TUTTI_INVALID_ARGUMENT, "tutti_model_pose: the buffer holds fewer transforms than " +
                                            std::to_string(pose->local.size()) + " nodes");
  }
  for (std::size_t n = 0; n < pose->local.size(); ++n) copy_trs(pose->local[n], out[n]);
  return TUTTI_OK;
}

tutti_status tutti_model_morph_weights(const tutti_performance* p, int32_t model, float* out,
                                       int32_t capacity) {
  const tutti::performance::ModelPose* pose = nullptr;
  if (tutti_status s = pose_of(p, model, &pose); s != TUTTI_OK) return s;
  if (capacity < 0 || static_cast<std::size_t>(capacity) < pose->morph_weights.size() ||
      (out == nullptr && !pose->morph_weights.empty())) {
    return fail(TUTTI_INVALID_ARGUMENT,
                "tutti_model_morph_weights: the buffer holds fewer weights than " +
                    std::to_string(pose->morph_weights.size()) + " morph targets");
  }
  for (std::size_t k = 0; k < pose->morph_weights.size(); ++k) out[k] = pose->morph_weights[k];
  return TUTTI_OK;
}

int32_t tutti_events(const tutti_performance* p, double from_s, double to_s, tutti_event* out,
                     int32_t capacity) {
  if (p == nullptr) return -1;
  const auto events = p->performance->events_between(from_s, to_s);
  const std::size_t room = out != nullptr && capacity > 0 ? static_cast<std::size_t>(capacity) : 0;
  for (std::size_t i = 0; i < events.size() && i < room; ++i) {
    out[i].t_s = events[i].t_s;
    out[i].kind = static_cast<int32_t>(events[i].kind);
    out[i].performer = events[i].performer;
    out[i].value = events[i].value;
    out[i].reserved = 0;
  }
  return static_cast<int32_t>(events.size());
}

}  // extern "C"
