// The `tutti` command: parse arguments, call one subcommand, return its exit code. Each
// subcommand lives in its own <name>_command.cpp.

#include <CLI/CLI.hpp>
#include <iostream>

#include <tutti/cli/brass_command.hpp>
#include <tutti/cli/concat_command.hpp>
#include <tutti/cli/exit_codes.hpp>
#include <tutti/cli/export_command.hpp>
#include <tutti/cli/fingering_command.hpp>
#include <tutti/cli/fit_fingering_command.hpp>
#include <tutti/cli/info_command.hpp>
#include <tutti/cli/perform_command.hpp>
#include <tutti/cli/play_command.hpp>
#include <tutti/cli/render_command.hpp>
#include <tutti/cli/sync_report_command.hpp>

int main(int argc, char** argv) {
  CLI::App app{"tutti: music to animated performances"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("tutti ") + TUTTI_VERSION);

  tutti::app::InfoOptions info;
  CLI::App* info_cmd = app.add_subcommand("info",
                                          "Parts, notes, duration, tempo and ranges of a "
                                          "MIDI, MusicXML (.xml/.musicxml/.mxl) or PIG file");
  info_cmd->add_option("FILE", info.file, "score file")->required();
  info_cmd->add_flag("--json", info.json, "print JSON instead of text");
  info_cmd->add_flag("--schedule", info.schedule,
                     "FILE is a scene: print the frame (phases, systems, components)");

  tutti::app::ConcatOptions concat;
  bool concat_no_audio = false;
  CLI::App* concat_cmd = app.add_subcommand(
      "concat",
      "Join slices of one render (tutti render SCENE --frames A:B --no-audio -o slice.mp4) into "
      "one video: frames copied exactly, the sound rendered once for the whole range");
  concat_cmd->add_option("SCENE", concat.scene, "the scene the slices were rendered from")
      ->required();
  concat_cmd->add_option("SLICES", concat.slices, "slice .mp4 files, any order")->required();
  concat_cmd->add_option("-o,--output", concat.output, "OUT.mp4")->required();
  concat_cmd->add_option("--soundfont", concat.soundfont, "General MIDI .sf2");
  concat_cmd->add_option("--assets", concat.assets, "folder of the generated .glb assets");
  concat_cmd->add_flag("--no-audio", concat_no_audio, "no sound track");

  tutti::app::ExportOptions exporting;
  CLI::App* export_cmd = app.add_subcommand(
      "export",
      "Write the scene as binary glTF 2.0: characters, hands, piano, instruments and props with "
      "the performance baked as animation (one clip per performer plus the whole scene)");
  export_cmd->add_option("SCENE", exporting.scene, "scene file (.json)")->required();
  export_cmd->add_option("-o,--output", exporting.output, "performance.glb")->required();
  export_cmd->add_option("--fps", exporting.fps, "keyframe rate (default: the scene's)");
  export_cmd->add_option("--seconds", exporting.seconds,
                         "A:B: the frames whose times are in [A, B)");
  export_cmd->add_option("--frames", exporting.frames,
                         "A:B: frames A (inclusive) to B (exclusive)");
  export_cmd->add_option("--assets", exporting.assets, "folder of the generated .glb assets");
  export_cmd->add_flag("--json", exporting.json_summary, "print the summary as JSON");

  tutti::app::PerformOptions perform;
  CLI::App* perform_cmd = app.add_subcommand(
      "perform",
      "Play a MIDI or MusicXML file on the simulated piano in a performance style: the notes as "
      "the keys sound them (escapement time, velocity from key speed), written as MIDI, and a "
      "report of onset deviation, velocity spread and missed notes");
  perform_cmd->add_option("IN", perform.input, "score file")->required();
  perform_cmd->add_option("-o,--output", perform.output, "write the performed notes (.mid)");
  perform_cmd->add_option("--style", perform.style,
                          "precise (default), gentle, beginner, or all (report only)");
  perform_cmd->add_option("--seed", perform.seed, "motor-noise seed (default 1)");
  perform_cmd->add_option("--hand-size", perform.hand_size, "small, medium or large");
  perform_cmd->add_option("--report-json", perform.report_json,
                          "write the report and every note's outcome as JSON");

  tutti::app::FingeringOptions fingering;
  CLI::App* fingering_cmd = app.add_subcommand(
      "fingering",
      "Plan piano fingering and hand paths for a MIDI, MusicXML or PIG file; write MusicXML "
      "(marks added to the input), PIG, MIDI (lyric events \"RH3:64\") or JSON");
  fingering_cmd->add_option("IN", fingering.input, "score file")->required();
  fingering_cmd->add_option("-o,--output", fingering.output,
                            "output file (format from .musicxml/.xml, .txt/.pig, .mid, .json); "
                            "none = a listing on stdout");
  fingering_cmd->add_option("--format", fingering.format, "musicxml, pig, midi or json");
  fingering_cmd->add_option("--mode", fingering.mode, "exact (default) or lookahead");
  fingering_cmd->add_option("--lookahead", fingering.lookahead, "events, for --mode lookahead");
  fingering_cmd->add_option("--hand-size", fingering.hand_size, "small, medium or large");
  fingering_cmd->add_option("--weights", fingering.weights,
                            "cost weights: default, paper, or a .json file");
  fingering_cmd->add_flag("--keep-fingers", fingering.keep_fingers,
                          "keep the file's finger marks as pins (else they are ignored)");
  fingering_cmd->add_option("--smoothing", fingering.smoothing,
                            "hand-path smoothing: monotone_quintic (default), pchip, "
                            "natural_spline or none");
  fingering_cmd->add_option("--plot", fingering.plot, "write a piano-roll PNG");
  fingering_cmd->add_option("--plot-seconds", fingering.plot_seconds, "plot window A:B seconds");

  tutti::app::FitFingeringOptions fit;
  CLI::App* fit_cmd = app.add_subcommand(
      "fit-fingering",
      "Fit the fingering cost weights to annotated pieces (PIG text or MusicXML with fingering "
      "marks) and write them as JSON for `tutti fingering --weights`");
  fit_cmd->add_option("FILES", fit.inputs, "annotated score files")->required();
  fit_cmd->add_option("-o,--output", fit.output, "weights .json to write")->required();
  fit_cmd->add_option("--start", fit.start,
                      "preset (default, paper) or weights file to start from");
  fit_cmd->add_option("--hand-size", fit.hand_size, "small, medium or large");
  fit_cmd->add_option("--rounds", fit.rounds, "coordinate-descent rounds at most (1..100)");

  tutti::app::BrassOptions brass;
  CLI::App* brass_cmd = app.add_subcommand(
      "brass",
      "How every brass player of a score plays: valves or slide position per note (alternates "
      "marked), mouth tension, breaths, notes out of range");
  brass_cmd->add_option("FILE", brass.file, "score file")->required();
  brass_cmd->add_option("--part", brass.part, "part name (or part of it) or 1-based index");
  brass_cmd->add_option("--voice", brass.voice, "1-based player within the part (default: all)");
  brass_cmd->add_option("--instrument", brass.instrument,
                        "instrument id from content/instruments (default: detected)");
  brass_cmd->add_flag("--json", brass.json, "print JSON instead of text");

  tutti::app::RenderOptions render;
  CLI::App* render_cmd = app.add_subcommand(
      "render",
      "Render a scene (content/scenes/*.json) offline on the Vulkan device: H.264 .mp4, a folder "
      "of PNG frames, or one .png with --still");
  render_cmd->add_option("SCENE", render.scene, "scene file")->required();
  render_cmd->add_option("-o,--output", render.output, "OUT.mp4, OUT.png (--still) or FOLDER/")
      ->required();
  render_cmd->add_option("--size", render.size, "WxH (default: the scene's)");
  render_cmd->add_option("--fps", render.fps, "frames per second (default: the scene's)");
  render_cmd->add_option("--msaa", render.msaa, "samples per pixel: 1, 2, 4 or 8");
  render_cmd->add_option("--wav", render.wav, "also write the rendered range's audio (WAV)");
  render_cmd->add_option("--soundfont", render.soundfont,
                         "General MIDI .sf2 (default: $TUTTI_SOUNDFONT, then Debian's)");
  bool no_audio = false;
  render_cmd->add_flag("--no-audio", no_audio, "an .mp4 without a sound track");
  render_cmd->add_flag("--lossless", render.lossless,
                       "lossless H.264: slices joined by tutti concat equal a single render");
  render_cmd->add_option("--tempo", render.tempo,
                         "practice tempo, 0.1..4 (0.5 = half speed: picture and sound)");
  render_cmd->add_option("--camera", render.camera,
                         "render every frame through this scene camera (ignore the shot list)");
  render_cmd->add_option("--shadows", render.shadows,
                         "hard (one shadow-map comparison per pixel) or soft (four)");
  render_cmd->add_option("--frames", render.frames, "A:B, frames A (inclusive) to B (exclusive)");
  render_cmd->add_option("--seconds", render.seconds, "A:B, the frames whose times are in [A, B)");
  render_cmd->add_option("--still", render.still, "one frame at this time (seconds) to a .png");
  render_cmd->add_option("--device", render.device, "Vulkan device: index or part of its name");
  render_cmd->add_option("--assets", render.assets, "folder of the generated .glb assets");
  render_cmd->add_flag("--validate", render.validate,
                       "run with the Vulkan validation layer; any message is an error");
  bool no_progress = false;
  render_cmd->add_flag("--no-progress", no_progress, "no progress output");

  tutti::app::SyncReportOptions sync;
  CLI::App* sync_cmd = app.add_subcommand(
      "sync-report",
      "How far the sound is from the picture: note onsets detected in the rendered audio against "
      "the animation's contact times (key bottom, valve down, slide arrives, tongue)");
  sync_cmd->add_option("SCENE", sync.scene, "scene file")->required();
  sync_cmd->add_option("--assets", sync.assets, "folder of the generated .glb assets");
  sync_cmd->add_option("--soundfont", sync.soundfont,
                       "General MIDI .sf2 (default: $TUTTI_SOUNDFONT, then Debian's)");
  sync_cmd->add_option("--wav", sync.wav, "also write the analysed audio (WAV)");
  sync_cmd->add_option("--tempo", sync.tempo, "practice tempo, 0.1..4");
  sync_cmd->add_option("--step-ms", sync.step_ms, "animation sampling step (default 0.5)");
  sync_cmd->add_option("--tolerance-ms", sync.tolerance_ms, "furthest match (default 50)");
  sync_cmd->add_option("--worst", sync.worst, "list this many largest offsets (default 5)");
  bool no_compensation = false;
  sync_cmd->add_flag("--no-attack-compensation", no_compensation,
                     "every note at its score time, not early by its sample's attack");
  sync_cmd->add_flag("--check", sync.check, "exit 1 unless mean <= 5 ms and max <= 16.67 ms");

  tutti::app::PlayOptions play;
  CLI::App* play_cmd = app.add_subcommand(
      "play",
      "Play a scene live in a window with its sound (keys: Space play/pause, Left/Right seek, "
      "Home start, 0 director, 1-9 camera, F or drag free camera, [ ] \\ loop, - = tempo, Esc)");
  play_cmd->add_option("SCENE", play.scene, "scene file")->required();
  play_cmd->add_option("--tempo", play.tempo, "practice tempo, 0.25..2 (0.5 = half speed)");
  play_cmd->add_option("--camera", play.camera, "start on this scene camera (not the shot list)");
  play_cmd->add_option("--start", play.start, "start at this time (seconds of the music)");
  play_cmd->add_option("--loop", play.loop, "A:B, play seconds [A, B) over and over");
  play_cmd->add_option("--soundfont", play.soundfont,
                       "General MIDI .sf2 (default: $TUTTI_SOUNDFONT or the system's)");
  play_cmd->add_option("--assets", play.assets, "folder of the generated .glb assets");
  play_cmd->add_option("--audio-driver", play.audio_driver,
                       "FluidSynth audio driver (pulseaudio, alsa, ...; simulated: none)");
  play_cmd->add_option("--device", play.device, "Vulkan device: index or part of its name");
  play_cmd->add_option("--frames", play.frames, "quit after this many frames");
  play_cmd->add_option("--screenshot", play.screenshot, "write the last frame to this .png");
  play_cmd->add_option("--midi-in", play.midi_in,
                       "live MIDI (ALSA sequencer): auto, none, CLIENT:PORT or a client name; the "
                       "pianist plays it");
  play_cmd->add_flag(
      "--keyboard-piano", play.keyboard_piano,
      "the computer keyboard as a piano (A S D ... white, W E T ... black, Z/X octave)");
  play_cmd->add_flag("--validate", play.validate,
                     "Vulkan validation layer on; any message is an error");

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see tutti --help)\n";
    return tutti::app::kExitBadInput;
  }

  if (*info_cmd) return tutti::app::run_info(info, std::cout, std::cerr);
  if (*concat_cmd) {
    concat.audio = !concat_no_audio;
    return tutti::app::run_concat(concat, std::cout, std::cerr);
  }
  if (*export_cmd) return tutti::app::run_export(exporting, std::cout, std::cerr);
  if (*perform_cmd) return tutti::app::run_perform(perform, std::cout, std::cerr);
  if (*fingering_cmd) return tutti::app::run_fingering(fingering, std::cout, std::cerr);
  if (*fit_cmd) return tutti::app::run_fit_fingering(fit, std::cout, std::cerr);
  if (*brass_cmd) return tutti::app::run_brass(brass, std::cout, std::cerr);
  if (*sync_cmd) {
    sync.compensate_attacks = !no_compensation;
    return tutti::app::run_sync_report(sync, std::cout, std::cerr);
  }
  if (*play_cmd) return tutti::app::run_play(play, std::cout, std::cerr);
  if (*render_cmd) {
    render.progress = !no_progress;
    render.audio = !no_audio;
    return tutti::app::run_render(render, std::cout, std::cerr);
  }
  return tutti::app::kExitBadInput;
}
