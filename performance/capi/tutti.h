// SPDX-License-Identifier: MIT
/* tutti's C API: a scene's performance for any engine or language (C#, Python with ctypes, Godot
 * GDExtension, Unreal plugins). Opaque handles, plain structs, status codes; no Vulkan, window or
 * sound device. The library is libtutti.so (CMake: tutti::c).
 *
 *   tutti_performance* p = NULL;
 *   if (tutti_open("quartet.json", NULL, &p) != TUTTI_OK) puts(tutti_last_error());
 *   tutti_sample(p, 12.5);                      // pose everything at 12.5 s of the music
 *   tutti_poses(p, roots, m, nodes, n);         // every model's root and local TRS at once
 *   tutti_close(p);
 *
 * Strings returned are owned by the performance (or static) and live until tutti_close. Indices
 * are 0-based. Every call that fails says why in tutti_last_error(): a status code other than
 * TUTTI_OK, NULL for a string, -1 for a count or an index.
 *
 * Threads: a performance is used by one thread at a time (tutti_sample writes the pose the getters
 * read); different performances are independent and may be used on different threads at once.
 * To sample one performance from many threads, give each thread a tutti_context.
 * The calls marked "any thread" take no performance, or only read what tutti_open fixed, and may
 * be called from any thread at any time while the performance is open. */
#ifndef TUTTI_TUTTI_H
#define TUTTI_TUTTI_H

#include <stdint.h>

/* The version of this header. tutti_version_number() is the library's: a host built against
 * MAJOR.MINOR runs with any library of the same MAJOR.MINOR (0.x: every minor may change the ABI). */
#define TUTTI_VERSION_MAJOR 0
#define TUTTI_VERSION_MINOR 4
#define TUTTI_VERSION_PATCH 0
#define TUTTI_VERSION_NUMBER \
  (TUTTI_VERSION_MAJOR * 10000 + TUTTI_VERSION_MINOR * 100 + TUTTI_VERSION_PATCH)

/* Exported from libtutti, imported by its users. Define TUTTI_STATIC when linking tutti
 * statically; TUTTI_BUILDING is set only while building the library itself. */
#if defined(TUTTI_STATIC)
#define TUTTI_API
#elif defined(_WIN32)
#if defined(TUTTI_BUILDING)
#define TUTTI_API __declspec(dllexport)
#else
#define TUTTI_API __declspec(dllimport)
#endif
#else
#define TUTTI_API __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
extern "C" {
#endif

typedef struct tutti_performance tutti_performance;
/* (0.3) A caller's own sampling state over a performance's shared plan: one per thread. */
typedef struct tutti_context tutti_context;

typedef enum tutti_status {
  TUTTI_OK = 0,
  TUTTI_INTERNAL = 1,          /* tutti's own fault */
  TUTTI_BAD_INPUT = 2,         /* a file or value given is wrong (the message names it) */
  TUTTI_ENVIRONMENT = 3,       /* the machine lacks something tutti needs */
  TUTTI_INVALID_ARGUMENT = 4   /* a null handle or pointer, an index out of range, a short buffer */
} tutti_status;

typedef struct tutti_options {
  /* sizeof(tutti_options), as tutti_default_options sets it: a later library that adds fields
   * reads only those a host built against this header knows. */
  uint32_t struct_size;
  const char* content_dir; /* NULL or "": $TUTTI_CONTENT_DIR, else the content tutti was built with */
  const char* asset_dir;   /* NULL or "": $TUTTI_ASSET_DIR, else the generated models it was built with */
  double contact_step_s;   /* grid for key / valve / slide contact events; 0 = none */
  double contact_fps;      /* (0.3) frames per second on which contacts are recorded; 0 = none */
} tutti_options;

/* glTF conventions: metres, a unit quaternion (x, y, z, w), scale. */
typedef struct tutti_trs {
  float translation[3];
  float rotation[4];
  float scale[3];
} tutti_trs;

typedef struct tutti_event {
  double t_s;            /* seconds of the music */
  int32_t kind;          /* index of its kind: tutti_event_kind_name, tutti_event_kind_by_name */
  int32_t performer;     /* index of the performer */
  int32_t value;
  int32_t reserved;      /* 0 */
} tutti_event;

/* A span of time over which a performer's body node touches a node of their instrument: a
 * fingertip on a key (which stops `midi`), a fingertip on a valve button, a palm on a grip, the
 * lips on the mouthpiece. Nodes are indices into their models' nodes (tutti_node_name);
 * part_point_m is the touching point in the part node's frame (where the body node was there, on
 * average over the span). */
typedef struct tutti_contact {
  double from_s;         /* seconds of the music: the first and last recorded frame touching */
  double to_s;
  int32_t performer;
  int32_t body_model;
  int32_t body_node;
  int32_t part_model;
  int32_t part_node;
  int32_t midi;          /* the pitch the contact stops, else -1 */
  float part_point_m[3];
  int32_t reserved;      /* 0 */
} tutti_contact;

/* Any thread. "0.4.0" and MAJOR * 10000 + MINOR * 100 + PATCH of the library loaded. */
TUTTI_API const char* tutti_version(void);
TUTTI_API int32_t tutti_version_number(void);
/* Any thread. The message of this thread's last failed call ("" when none): one line naming the
 * file or the argument and what is wrong. */
TUTTI_API const char* tutti_last_error(void);
/* Any thread. The kinds of event, by name: kinds 0 to tutti_event_kind_count() - 1. The
 * performance's own come first: "note_on", "note_off" (value: the MIDI key, as heard),
 * "breath_start", "breath_end" (value: the breath's index), "cue" (the entrance a cue leads to;
 * value 1 = gives it, 0 = answers); then each instrument family's, family by family: the
 * keyboards' "key_down", "key_up" (a key at its bed and back up), "pedal_down", "pedal_up" (an
 * organ pedal under a foot; value: the MIDI key), the winds' "valve_down", "valve_up" (value: the
 * valve's number, 1-based) and "slide_arrives" (value: the position, 1..7). (0.4) The numbers
 * depend on the families the library was built with, so look kinds up by name; the names stay.
 * tutti_event_kind_name gives NULL for a kind out of range, and tutti_event_kind_by_name -1 for a
 * name tutti does not know. */
TUTTI_API int32_t tutti_event_kind_count(void);
TUTTI_API const char* tutti_event_kind_name(int32_t kind);
TUTTI_API int32_t tutti_event_kind_by_name(const char* name);
/* Any thread. Fills the defaults and struct_size. */
TUTTI_API void tutti_default_options(tutti_options* options);

/* Any thread (each call makes a performance of its own). Loads, plans and stages a scene file
 * (.json), or a piece of music (.mid, .midi, .kar, .musicxml, .xml, .mxl) with the scene tutti
 * drafts for it, as `tutti render PIECE.mid` does. `options` may be NULL; when given, its
 * struct_size must be set (tutti_default_options). */
TUTTI_API tutti_status tutti_open(const char* file, const tutti_options* options,
                                  tutti_performance** out);
/* The performance's thread. NULL is allowed. */
TUTTI_API void tutti_close(tutti_performance* performance);

/* Any thread: these read only what tutti_open fixed. */
TUTTI_API double tutti_start_s(const tutti_performance* performance);
TUTTI_API double tutti_end_s(const tutti_performance* performance);

TUTTI_API int32_t tutti_performer_count(const tutti_performance* performance);
TUTTI_API const char* tutti_performer_name(const tutti_performance* performance, int32_t performer);
TUTTI_API const char* tutti_performer_family(const tutti_performance* performance,
                                             int32_t performer);
TUTTI_API const char* tutti_performer_instrument(const tutti_performance* performance,
                                                 int32_t performer);

/* Every model on stage: the performers' bodies, instruments and hands, and the scenery. */
TUTTI_API int32_t tutti_model_count(const tutti_performance* performance);
TUTTI_API const char* tutti_model_name(const tutti_performance* performance, int32_t model);
TUTTI_API const char* tutti_model_file(const tutti_performance* performance, int32_t model);
/* The performer the model belongs to, -1 for scenery (or out of range, with an error). */
TUTTI_API int32_t tutti_model_performer(const tutti_performance* performance, int32_t model);
TUTTI_API int32_t tutti_node_count(const tutti_performance* performance, int32_t model);
TUTTI_API const char* tutti_node_name(const tutti_performance* performance, int32_t model,
                                      int32_t node);
/* The node's parent, -1 for a root (or out of range, with an error). */
TUTTI_API int32_t tutti_node_parent(const tutti_performance* performance, int32_t model,
                                    int32_t node);
TUTTI_API int32_t tutti_morph_count(const tutti_performance* performance, int32_t model);
TUTTI_API const char* tutti_morph_name(const tutti_performance* performance, int32_t model,
                                       int32_t morph);
/* The nodes of all models together (the sum of tutti_node_count), and where model `model`'s
 * nodes start among them: the layout tutti_poses writes. */
TUTTI_API int32_t tutti_node_total(const tutti_performance* performance);
TUTTI_API int32_t tutti_node_offset(const tutti_performance* performance, int32_t model);

/* The performance's thread, as the getters below. Poses everything at t_s (seconds of the
 * music); the getters read that pose until the next tutti_sample. */
TUTTI_API tutti_status tutti_sample(tutti_performance* performance, double t_s);
TUTTI_API tutti_status tutti_model_root(const tutti_performance* performance, int32_t model,
                                        tutti_trs* out);
/* Writes tutti_node_count(model) transforms; `capacity` must be at least that. */
TUTTI_API tutti_status tutti_model_pose(const tutti_performance* performance, int32_t model,
                                        tutti_trs* out, int32_t capacity);
/* Every model's pose in one call: `roots` gets one root transform per model (model order; it may
 * be NULL when root_capacity is 0), `nodes` every model's local transforms, model after model,
 * model m's from tutti_node_offset(m). Capacities must be at least tutti_model_count and
 * tutti_node_total. */
TUTTI_API tutti_status tutti_poses(const tutti_performance* performance, tutti_trs* roots,
                                   int32_t root_capacity, tutti_trs* nodes, int32_t node_capacity);
/* Writes tutti_morph_count(model) weights; `capacity` must be at least that. */
TUTTI_API tutti_status tutti_model_morph_weights(const tutti_performance* performance,
                                                 int32_t model, float* out, int32_t capacity);

/* Any thread. The events with from_s <= t < to_s, in time order: writes up to `capacity` of them
 * into `out` (which may be NULL when capacity is 0) and returns how many there are (-1 on a null
 * handle or a NaN time, with an error). */
TUTTI_API int32_t tutti_events(const tutti_performance* performance, double from_s, double to_s,
                               tutti_event* out, int32_t capacity);

/* (0.3) Sampling from many threads. A context is a caller's own copy of what a frame writes;
 * the plans stay in the performance, shared and only read. Make the contexts on the
 * performance's thread while no tutti_sample runs, give each thread its own, and free them before
 * tutti_close. tutti_context_sample poses everything at t_s in that context (any thread, one
 * thread per context at a time, beside other contexts); the same t gives the same transforms
 * as tutti_sample. tutti_context_poses and tutti_context_morph_weights read its last sample, as
 * tutti_poses and tutti_model_morph_weights read the performance's. */
TUTTI_API tutti_status tutti_context_new(const tutti_performance* performance,
                                         tutti_context** out);
TUTTI_API void tutti_context_free(tutti_context* context);
TUTTI_API tutti_status tutti_context_sample(tutti_context* context, double t_s);
TUTTI_API tutti_status tutti_context_poses(const tutti_context* context, tutti_trs* roots,
                                           int32_t root_capacity, tutti_trs* nodes,
                                           int32_t node_capacity);
TUTTI_API tutti_status tutti_context_morph_weights(const tutti_context* context, int32_t model,
                                                   float* out, int32_t capacity);

/* Any thread. The contact spans that overlap [from_s, to_s) (from_s <= span.to_s and
 * span.from_s < to_s), by start time: writes up to `capacity` of them into `out` (which may be
 * NULL when capacity is 0) and returns how many there are (-1 on a null handle or a NaN time,
 * with an error). Linear in the piece's spans. None when tutti_options.contact_fps was 0. */
TUTTI_API int32_t tutti_contacts(const tutti_performance* performance, double from_s,
                                 double to_s, tutti_contact* out, int32_t capacity);

#ifdef __cplusplus
}
#endif

#endif /* TUTTI_TUTTI_H */
