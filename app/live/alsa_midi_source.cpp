// SPDX-License-Identifier: MIT
#include <tutti/live/alsa_midi_source.hpp>

#include <alsa/asoundlib.h>

#include <cstring>

namespace tutti::live {
namespace {

// ALSA prints its own diagnostics to stderr ("ALSA lib seq_hw.c:...: open /dev/snd/seq
// failed"); the caller's one-line error says it better.
void ignore_alsa_error(const char*, int, const char*, int, const char*, ...) {}

bool is_system_or_through(snd_seq_client_info_t* client) {
  const int id = snd_seq_client_info_get_client(client);
  const char* name = snd_seq_client_info_get_name(client);
  return id == SND_SEQ_CLIENT_SYSTEM || std::strstr(name, "Midi Through") != nullptr;
}

}  // namespace

struct AlsaMidiSource::Impl {
  snd_seq_t* seq = nullptr;
  int port = -1;
  ~Impl() {
    if (seq != nullptr) snd_seq_close(seq);
  }
};

const char* alsa_sequencer_device() { return "/dev/snd/seq"; }

Result<std::unique_ptr<AlsaMidiSource>> AlsaMidiSource::open(const std::string& port) {
  snd_lib_error_set_handler(ignore_alsa_error);
  std::unique_ptr<AlsaMidiSource> source(new AlsaMidiSource());
  source->impl_ = std::make_unique<Impl>();
  Impl& impl = *source->impl_;
  if (int rc = snd_seq_open(&impl.seq, "default", SND_SEQ_OPEN_INPUT, SND_SEQ_NONBLOCK); rc < 0) {
    impl.seq = nullptr;
    return Error{std::string("ALSA sequencer: cannot open ") + alsa_sequencer_device() + " (" +
                 snd_strerror(rc) + ")"};
  }
  snd_seq_set_client_name(impl.seq, "tutti");
  impl.port = snd_seq_create_simple_port(
      impl.seq, "live in", SND_SEQ_PORT_CAP_WRITE | SND_SEQ_PORT_CAP_SUBS_WRITE,
      SND_SEQ_PORT_TYPE_MIDI_GENERIC | SND_SEQ_PORT_TYPE_APPLICATION);
  if (impl.port < 0) {
    return Error{std::string("ALSA sequencer: cannot create an input port (") +
                 snd_strerror(impl.port) + ")"};
  }
  const int self = snd_seq_client_id(impl.seq);
  source->name_ = "ALSA " + std::to_string(self) + ":" + std::to_string(impl.port) + " (tutti)";
  if (port.empty()) return source;
  if (port == "auto") {
    snd_seq_client_info_t* client = nullptr;
    snd_seq_port_info_t* info = nullptr;
    snd_seq_client_info_alloca(&client);
    snd_seq_port_info_alloca(&info);
    snd_seq_client_info_set_client(client, -1);
    while (snd_seq_query_next_client(impl.seq, client) >= 0) {
      const int id = snd_seq_client_info_get_client(client);
      if (id == self || is_system_or_through(client)) continue;
      snd_seq_port_info_set_client(info, id);
      snd_seq_port_info_set_port(info, -1);
      while (snd_seq_query_next_port(impl.seq, info) >= 0) {
        const unsigned caps = snd_seq_port_info_get_capability(info);
        const unsigned wanted = SND_SEQ_PORT_CAP_READ | SND_SEQ_PORT_CAP_SUBS_READ;
        if ((caps & wanted) != wanted) continue;
        if (snd_seq_connect_from(impl.seq, impl.port, id, snd_seq_port_info_get_port(info)) >= 0)
          ++source->connections_;
      }
    }
    return source;
  }
  snd_seq_addr_t address{};
  if (snd_seq_parse_address(impl.seq, &address, port.c_str()) < 0) {
    return Error{"ALSA sequencer: no port \"" + port +
                 "\" (expected client:port or a client name)"};
  }
  if (int rc = snd_seq_connect_from(impl.seq, impl.port, address.client, address.port); rc < 0) {
    return Error{"ALSA sequencer: cannot connect from " + port + " (" + snd_strerror(rc) + ")"};
  }
  source->connections_ = 1;
  return source;
}

AlsaMidiSource::~AlsaMidiSource() = default;

void AlsaMidiSource::poll(double now_s, std::vector<LiveNoteEvent>& out) {
  snd_seq_event_t* event = nullptr;
  for (;;) {
    const int rc = snd_seq_event_input(impl_->seq, &event);
    if (rc == -EAGAIN || rc == -ENOSPC) {
      if (rc == -EAGAIN) return;
      continue;  // the input buffer overran: events were lost; go on with what follows
    }
    if (rc < 0 || event == nullptr) return;
    if (event->type == SND_SEQ_EVENT_NOTEON || event->type == SND_SEQ_EVENT_NOTEOFF) {
      const bool on = event->type == SND_SEQ_EVENT_NOTEON && event->data.note.velocity > 0;
      out.push_back({now_s, event->data.note.note, event->data.note.velocity, on});
    }
  }
}

}  // namespace tutti::live
