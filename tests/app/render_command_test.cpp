// SPDX-License-Identifier: MIT
// `tutti render` in-process on the real Vulkan device (lavapipe on CI): stills and PNG-folder
// slices of the shipped piano scene are deterministic, a slice has exactly the full render's
// pixels, and bad options give one-line errors.
#include <tutti/cli/render_command.hpp>

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>

#include <tutti/audio/onset_detection.hpp>
#include <tutti/audio/wav_file.hpp>
#include <tutti/render/vulkan_context.hpp>

namespace tutti::cli {
namespace {

std::filesystem::path scene_path() {
  return std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "piano.json";
}

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// ffprobe's "codec_type,duration" lines for every stream of `file` (Debian's ffmpeg package).
std::string probe_streams(const std::filesystem::path& file) {
  const std::string command =
      "ffprobe -v error -show_entries stream=codec_type,duration -of csv=p=0 '" + file.string() +
      "'";
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[256];
    while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) out += buffer;
    pclose(pipe);
  }
  return out;
}

class RenderCommandTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto devices = render::list_vulkan_devices();
    if (!devices || devices->empty()) GTEST_SKIP() << "SKIPPED: no Vulkan device";
    dir_ =
        std::filesystem::temp_directory_path() / ("tutti-render-test-" + std::to_string(getpid()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  int run(RenderOptions o, std::string* error = nullptr) {
    o.progress = false;
    o.validate = true;
    if (o.size.empty()) o.size = "160x90";
    std::ostringstream out;
    std::ostringstream err;
    const int code = run_render(o, out, err);
    if (error != nullptr) *error = err.str();
    return code;
  }

  std::filesystem::path dir_;
};

TEST_F(RenderCommandTest, StillIsDeterministicAndValidationClean) {
  RenderOptions o;
  o.scene = scene_path();
  o.still = "6.0";
  o.output = dir_ / "a.png";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  o.output = dir_ / "b.png";
  ASSERT_EQ(run(o, &error), 0) << error;
  const std::string a = read_bytes(dir_ / "a.png");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, read_bytes(dir_ / "b.png"));
}

TEST_F(RenderCommandTest, ASliceHasExactlyTheFullRendersPixels) {
  RenderOptions o;
  o.scene = scene_path();
  o.fps = 10;
  o.frames = "40:46";  // across the cut to the "hands" camera at 4.4 s
  o.output = dir_ / "full";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  o.frames = "43:46";
  o.output = dir_ / "slice";
  ASSERT_EQ(run(o, &error), 0) << error;
  for (int k = 43; k < 46; ++k) {
    const std::string name = "frame_0000" + std::to_string(k) + ".png";
    const std::string slice = read_bytes(dir_ / "slice" / name);
    ASSERT_FALSE(slice.empty()) << name;
    EXPECT_EQ(slice, read_bytes(dir_ / "full" / name)) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(dir_ / "slice" / "frame_000042.png"));
  // Frames differ over time (the camera cuts at 4.4 s, the hands move).
  EXPECT_NE(read_bytes(dir_ / "full" / "frame_000040.png"),
            read_bytes(dir_ / "full" / "frame_000045.png"));
}

TEST_F(RenderCommandTest, VideoOfTheSameSliceIsByteIdentical) {
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "quartet.json";
  o.frames = "100:110";
  o.output = dir_ / "a.mp4";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  o.output = dir_ / "b.mp4";
  ASSERT_EQ(run(o, &error), 0) << error;
  const std::string a = read_bytes(dir_ / "a.mp4");
  EXPECT_GT(a.size(), 1000u);
  EXPECT_EQ(a, read_bytes(dir_ / "b.mp4"));
}

TEST_F(RenderCommandTest, VideoCarriesTheMusicAsAacOfTheSlicesLength) {
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "quartet.json";
  o.frames = "60:120";
  o.output = dir_ / "with.mp4";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  EXPECT_EQ(probe_streams(dir_ / "with.mp4"), "video,2.000000\naudio,2.000000\n");
  EXPECT_FALSE(std::filesystem::exists(dir_ / "with.mp4.tutti-audio.wav")) << "temporary kept";
  o.audio = false;
  o.output = dir_ / "without.mp4";
  ASSERT_EQ(run(o, &error), 0) << error;
  EXPECT_EQ(probe_streams(dir_ / "without.mp4"), "video,2.000000\n");
}

// `tutti render PIECE -o out.mp4` on a bare third-party MusicXML file with a trumpet, a horn
// and a piano part: the scene `tutti scene new` would write, staged in memory, to a video with
// its music.
TEST_F(RenderCommandTest, ABarePieceWithBrassAndPianoRendersToAVideoWithSound) {
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_TESTDATA_DIR) / "musicxml" / "lilypond-test-suite" /
            "72a-TransposingInstruments.xml";
  if (!std::filesystem::exists(o.scene)) GTEST_SKIP() << "SKIPPED: no ../shared/testdata";
  o.seconds = "0:3";
  o.output = dir_ / "piece.mp4";
  o.wav = dir_ / "piece.wav";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  EXPECT_EQ(probe_streams(dir_ / "piece.mp4"), "video,3.000000\naudio,3.000000\n");
  auto sound = audio::read_wav(dir_ / "piece.wav");
  ASSERT_TRUE(sound) << sound.error().message;
  double sum = 0.0;
  for (std::int16_t v : sound->samples) sum += static_cast<double>(v) * v;
  EXPECT_GT(std::sqrt(sum / static_cast<double>(sound->samples.size())), 300.0) << "audible";

}

// A machine without ffmpeg lacks something; the input is fine: exit 3, one line saying what.
TEST_F(RenderCommandTest, NoFfmpegIsAMissingEnvironmentNotBadInput) {
  const char* path = std::getenv("PATH");
  const std::string saved = path != nullptr ? path : "";
  ::setenv("PATH", "/nonexistent", 1);
  RenderOptions o;
  o.scene = scene_path();
  o.frames = "0:2";
  o.audio = false;
  o.output = dir_ / "no_ffmpeg.mp4";
  std::string error;
  const int code = run(o, &error);
  ::setenv("PATH", saved.c_str(), 1);
  EXPECT_EQ(code, 3) << error;
  EXPECT_EQ(error, "error: " + o.output.string() +
                       ": ffmpeg not found (install the ffmpeg package)\n");
}

TEST_F(RenderCommandTest, ASlicesWavHasExactlyTheFullRendersSamples) {
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "quartet.json";
  o.size = "32x18";
  o.frames = "90:180";  // 0.5 .. 3.5 s of the music (the scene starts 2.5 s before it)
  o.output = dir_ / "full/";
  o.wav = dir_ / "full.wav";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  o.frames = "135:180";
  o.output = dir_ / "slice/";
  o.wav = dir_ / "slice.wav";
  ASSERT_EQ(run(o, &error), 0) << error;
  auto full = audio::read_wav(dir_ / "full.wav");
  auto slice = audio::read_wav(dir_ / "slice.wav");
  ASSERT_TRUE(full && slice);
  ASSERT_EQ(full->frames(), 90 * 1600);  // 30 fps at 48 kHz: 1600 samples a frame
  ASSERT_EQ(slice->frames(), 45 * 1600);
  const std::vector<std::int16_t> tail(full->samples.begin() + 45 * 1600 * 2, full->samples.end());
  EXPECT_EQ(slice->samples, tail);
  // Three seconds of the quartet playing are not silence.
  std::int64_t loud = 0;
  for (std::int16_t v : full->samples) loud += std::abs(v) > 1000 ? 1 : 0;
  EXPECT_GT(loud, 48000);
}

TEST_F(RenderCommandTest, AFixedCameraOverridesTheShotList) {
  // At 3.0 s the quartet's shot list shows "wide"; at 5.0 s "lead_trumpet".
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "quartet.json";
  o.size = "160x90";
  std::string error;
  const auto still = [&](const char* t, const char* camera, const char* name) {
    o.still = t;
    o.camera = camera;
    o.output = dir_ / name;
    EXPECT_EQ(run(o, &error), 0) << error;
    return read_bytes(dir_ / name);
  };
  const std::string shots = still("5.0", "", "shots.png");
  const std::string lead = still("5.0", "lead_trumpet", "lead.png");
  const std::string wide = still("5.0", "wide", "wide.png");
  EXPECT_EQ(shots, lead);
  EXPECT_NE(shots, wide);
}

TEST_F(RenderCommandTest, HalfTempoSlowsPictureAndSoundTogether) {
  RenderOptions o;
  o.scene = std::filesystem::path(TUTTI_SOURCE_DIR) / "content" / "scenes" / "quartet.json";
  o.size = "32x18";
  std::string error;
  // Frame 31 at half tempo shows the score at -2.5 + 31 / 30 x 0.5 s.
  o.tempo = 0.5;
  o.frames = "31:32";
  o.output = dir_ / "slow/";
  ASSERT_EQ(run(o, &error), 0) << error;
  RenderOptions still = o;
  still.tempo = 1.0;
  still.frames.clear();
  still.still = std::to_string(-2.5 + 31.0 / 30.0 * 0.5);
  still.output = dir_ / "still.png";
  ASSERT_EQ(run(still, &error), 0) << error;
  EXPECT_EQ(read_bytes(dir_ / "slow" / "frame_000031.png"), read_bytes(dir_ / "still.png"));
  // The music starts at score time 0, 2.5 s into the scene: heard 2.5 s in at full tempo,
  // 5 s in at half tempo. A one-second slice from a third of a second before that.
  for (const double tempo : {1.0, 0.5}) {
    const int first_frame = static_cast<int>(std::lround((2.5 / tempo - 1.0 / 3.0) * 30.0));
    o.tempo = tempo;
    o.frames = std::to_string(first_frame) + ":" + std::to_string(first_frame + 30);
    o.output = dir_ / "audio/";
    o.wav = dir_ / "audio.wav";
    ASSERT_EQ(run(o, &error), 0) << error;
    auto wav = audio::read_wav(dir_ / "audio.wav");
    ASSERT_TRUE(wav);
    EXPECT_EQ(wav->frames(), 30 * 1600);
    // Heard a third of a second into the slice (the brass sent early by their attacks,
    // audio/attack_time.hpp: the same in seconds at any tempo), within 6 ms.
    const std::vector<audio::Onset> onsets = audio::detect_onsets(*wav);
    ASSERT_FALSE(onsets.empty()) << tempo;
    EXPECT_NEAR(onsets.front().time_s, 1.0 / 3.0, 0.006) << tempo;
  }
}

TEST_F(RenderCommandTest, SoftShadowsChangeThePicture) {
  RenderOptions o;
  o.scene = scene_path();
  o.still = "6.0";
  o.size = "320x180";
  o.output = dir_ / "hard.png";
  std::string error;
  ASSERT_EQ(run(o, &error), 0) << error;
  o.shadows = "soft";
  o.output = dir_ / "soft.png";
  ASSERT_EQ(run(o, &error), 0) << error;
  EXPECT_NE(read_bytes(dir_ / "hard.png"), read_bytes(dir_ / "soft.png"));
}

TEST_F(RenderCommandTest, BadOptionsAreOneLineErrors) {
  struct Case {
    RenderOptions options;
    std::string expected;
  };
  std::vector<Case> cases;
  auto base = [&] {
    RenderOptions o;
    o.scene = scene_path();
    o.output = dir_ / "out.mp4";
    return o;
  };
  {
    Case c{base(), "--size \"12x9\""};
    c.options.size = "12x9";
    cases.push_back(c);
  }
  {
    Case c{base(), "/nonexistent/gm.sf2: no such sound font (given with --soundfont)"};
    c.options.soundfont = "/nonexistent/gm.sf2";
    cases.push_back(c);
  }
  {
    Case c{base(), "--camera \"drone\": "};
    c.options.camera = "drone";
    cases.push_back(c);
  }
  {
    Case c{base(), "--tempo: must be in [0.1, 4]"};
    c.options.tempo = 0.0;
    cases.push_back(c);
  }
  {
    Case c{base(), "--shadows \"blurry\": must be hard or soft"};
    c.options.shadows = "blurry";
    cases.push_back(c);
  }
  {
    Case c{base(), "--frames \"5:2\""};
    c.options.frames = "5:2";
    cases.push_back(c);
  }
  {
    Case c{base(), "no_such_scene.json: no such file"};
    c.options.scene = dir_ / "no_such_scene.json";
    cases.push_back(c);
  }
  {
    Case c{base(), "the output must be .mp4"};
    c.options.output = dir_ / "out.avi";
    cases.push_back(c);
  }
  {
    Case c{base(), "--still writes a .png"};
    c.options.still = "1";
    cases.push_back(c);
  }
  for (const Case& c : cases) {
    std::string error;
    EXPECT_EQ(run(c.options, &error), 2) << c.expected;
    EXPECT_NE(error.find(c.expected), std::string::npos) << error;
    EXPECT_EQ(error.rfind("error: ", 0), 0u) << error;
    EXPECT_EQ(std::count(error.begin(), error.end(), '\n'), 1) << error;
  }
}

}  // namespace
}  // namespace tutti::cli
