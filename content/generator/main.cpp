// SPDX-License-Identifier: MIT
// tutti_content_generator OUT_DIR [--content DIR]: writes the default glTF assets (README.md).
#include <cstdio>
#include <string>

#include <tutti/content/content_dir.hpp>
#include <tutti/generator/generate.hpp>

int main(int argc, char** argv) {
  std::filesystem::path out_dir;
  std::filesystem::path content_dir = tutti::content::default_content_dir();
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--content" && i + 1 < argc) {
      content_dir = argv[++i];
    } else if (arg == "-h" || arg == "--help") {
      std::printf("usage: tutti_content_generator OUT_DIR [--content DIR]\n");
      return 0;
    } else if (out_dir.empty() && !arg.starts_with("-")) {
      out_dir = arg;
    } else {
      std::fprintf(stderr,
                   "error: unexpected argument '%s' (usage: tutti_content_generator "
                   "OUT_DIR [--content DIR])\n",
                   arg.c_str());
      return 2;
    }
  }
  if (out_dir.empty()) {
    std::fprintf(stderr,
                 "error: missing OUT_DIR (usage: tutti_content_generator OUT_DIR "
                 "[--content DIR])\n");
    return 2;
  }
  if (const tutti::Status status = tutti::content_generator::generate_assets(content_dir, out_dir);
      !status.ok()) {
    std::fprintf(stderr, "error: %s\n", status.error().message.c_str());
    return 2;
  }
  return 0;
}
