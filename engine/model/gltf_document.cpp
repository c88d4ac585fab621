// SPDX-License-Identifier: MIT
#include <tutti/model/gltf_document.hpp>

#include <algorithm>
#include <cstring>
#include <exception>
#include <nlohmann/json.hpp>
#include <set>
#include <vector>

#include <tutti/core/file_io.hpp>
#include <tutti/model/gltf_extensions.hpp>

namespace tutti::model::detail {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;  // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;
constexpr std::uint32_t kChunkBin = 0x004E4942;
constexpr std::size_t kMaxMessage = 300;

// A JSON pre-pass that tinygltf never sees fail: nlohmann's SAX parser is iterative, so depth and
// size are checked before anything recursive or large runs. Also collects buffers[i].uri and
// images[i].uri (the files a .gltf may read next to it).
class JsonScan {
 public:
  using json = nlohmann::json;

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(json::number_integer_t) { return value(); }
  bool number_unsigned(json::number_unsigned_t) { return value(); }
  bool number_float(json::number_float_t, const json::string_t&) { return value(); }
  bool binary(json::binary_t&) { return value(); }
  bool string(json::string_t& text) {
    if (stack_.size() == 3 && !stack_[0].array &&
        (stack_[0].key == "buffers" || stack_[0].key == "images") && stack_[1].array &&
        !stack_[2].array && stack_[2].key == "uri") {
      buffer_uris_.push_back(text);
    }
    return value();
  }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(json::string_t& name) {
    if (!stack_.empty()) stack_.back().key = name;
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception&) {
    if (error_.empty()) error_ = "invalid JSON at byte " + std::to_string(position);
    return false;
  }

  const std::string& error() const { return error_; }
  const std::vector<std::string>& buffer_uris() const { return buffer_uris_; }

 private:
  struct Frame {
    bool array = false;
    std::string key;
  };

  bool value() {
    if (++values_ > kMaxJsonValues) {
      error_ = "JSON has more than " + std::to_string(kMaxJsonValues) + " values, refused";
      return false;
    }
    return true;
  }
  bool open(bool array) {
    if (!value()) return false;
    if (stack_.size() >= kMaxJsonDepth) {
      error_ = "JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels, refused";
      return false;
    }
    stack_.push_back({array, {}});
    return true;
  }
  bool close() {
    if (!stack_.empty()) stack_.pop_back();
    return true;
  }

  std::vector<Frame> stack_;
  std::size_t values_ = 0;
  std::vector<std::string> buffer_uris_;
  std::string error_;
};

Status scan_json(std::span<const std::uint8_t> json_bytes, JsonScan& scan) {
  const char* begin = reinterpret_cast<const char*>(json_bytes.data());
  const bool ok = nlohmann::json::sax_parse(begin, begin + json_bytes.size(), &scan);
  if (!ok) return Error{scan.error().empty() ? "invalid JSON" : scan.error()};
  return {};
}

// The .glb layout (spec "Binary glTF Layout"), checked so that tinygltf's reads stay in bounds.
// Returns the JSON chunk.
Result<std::span<const std::uint8_t>> check_glb(std::span<const std::uint8_t> bytes) {
  if (bytes.size() < 20) {
    return Error{"truncated .glb (" + std::to_string(bytes.size()) +
                 " bytes, the header alone is 20)"};
  }
  const std::uint32_t version = read_u32(bytes, 4);
  const std::uint32_t length = read_u32(bytes, 8);
  if (version != 2) return Error{".glb version " + std::to_string(version) + ", only 2 is read"};
  if (length > bytes.size()) {
    return Error{"truncated .glb: header says " + std::to_string(length) + " bytes, file has " +
                 std::to_string(bytes.size())};
  }
  if (length < 20) return Error{".glb header length " + std::to_string(length) + " is too small"};
  const std::uint64_t json_length = read_u32(bytes, 12);
  if (read_u32(bytes, 16) != kChunkJson) return Error{".glb: first chunk is not JSON"};
  if (json_length == 0 || 20 + json_length > length) {
    return Error{".glb: JSON chunk of " + std::to_string(json_length) +
                 " bytes runs past the end of the file (" + std::to_string(length) + " bytes)"};
  }
  const std::uint64_t bin_header = 20 + json_length;
  if (bin_header < length) {
    if (bin_header + 8 > length) return Error{".glb: truncated BIN chunk header"};
    const std::uint64_t bin_length = read_u32(bytes, static_cast<std::size_t>(bin_header));
    const std::uint32_t bin_type = read_u32(bytes, static_cast<std::size_t>(bin_header) + 4);
    if (bin_type != kChunkBin) return Error{".glb: second chunk is not BIN"};
    if (bin_header + 8 + bin_length > length) {
      return Error{".glb: BIN chunk of " + std::to_string(bin_length) +
                   " bytes runs past the end of the file (" + std::to_string(length) + " bytes)"};
    }
  }
  return bytes.subspan(20, static_cast<std::size_t>(json_length));
}

// tinygltf's urldecode, so a buffer's uri maps to the path tinygltf asks for.
std::string url_decode(const std::string& text) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;
  };
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '+') {
      out += ' ';
    } else if (text[i] == '%' && text.size() > i + 2) {
      out += static_cast<char>((hex(text[i + 1]) << 4) | hex(text[i + 2]));
      i += 2;
    } else {
      out += text[i];
    }
  }
  return out;
}

struct FileAccess {
  std::set<std::string> allowed;  // the only files tinygltf may read: external buffers
  std::string read_error;
};

bool file_exists(const std::string& path, void* user) {
  const auto* access = static_cast<const FileAccess*>(user);
  if (access->allowed.count(path) == 0) return false;
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::string expand_path(const std::string& path, void*) { return path; }

bool read_whole_file(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                     void* user) {
  auto* access = static_cast<FileAccess*>(user);
  if (access->allowed.count(path) == 0) return false;
  auto bytes = read_file_bytes(path, kMaxModelFileBytes);
  if (!bytes) {
    access->read_error = bytes.error().message;
    if (err) *err += bytes.error().message;
    return false;
  }
  *out = std::move(*bytes);
  return true;
}

bool write_whole_file(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
  return false;
}

// Images are kept as their files' bytes (PNG, JPEG, WebP), never decoded here: load_model
// decodes them (gltf_images.hpp), with its own caps.
bool keep_image_bytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image == nullptr) return false;
  image->image.assign(bytes, bytes + std::max(size, 0));
  image->width = -1;  // marks `image` as encoded bytes, not pixels
  image->height = -1;
  return true;
}

std::string join_path(const std::string& dir, const std::string& file) {
  if (dir.empty()) return file;
  return dir.back() == '/' ? dir + file : dir + "/" + file;
}

}  // namespace

std::string fold_message(const std::string& text) {
  std::string out;
  bool space = false;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) {
      space = !out.empty();
      continue;
    }
    if (space) {
      out += "; ";
      space = false;
    }
    out += c;
    if (out.size() > kMaxMessage) {
      out.resize(kMaxMessage);
      out += "...";
      break;
    }
  }
  return out.empty() ? std::string("invalid glTF") : out;
}

Result<tinygltf::Model> parse_gltf(std::span<const std::uint8_t> bytes,
                                   const std::optional<std::string>& base_dir) {
  if (bytes.empty()) return Error{"empty file"};
  if (bytes.size() > kMaxModelFileBytes) return Error{"larger than 256 MiB, refused"};
  const bool binary = bytes.size() >= 4 && read_u32(bytes, 0) == kGlbMagic;

  std::span<const std::uint8_t> json = bytes;
  if (binary) {
    auto chunk = check_glb(bytes);
    if (!chunk) return chunk.error();
    json = *chunk;
  }
  JsonScan scan;
  if (auto scanned = scan_json(json, scan); !scanned) return scanned.error();
  auto prepared = prepare_extensions(bytes, binary, json);
  if (!prepared) return prepared.error();
  if (prepared->rewritten) bytes = prepared->bytes;

  FileAccess access;
  if (base_dir) {
    for (const std::string& uri : scan.buffer_uris()) {
      if (uri.rfind("data:", 0) == 0) continue;
      access.allowed.insert(join_path(*base_dir, url_decode(uri)));
    }
  }

  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(&keep_image_bytes, nullptr);
  gltf.SetFsCallbacks({&file_exists, &expand_path, &read_whole_file, &write_whole_file, &access});
  tinygltf::Model model;
  std::string err;
  std::string warn;
  const std::string dir = base_dir.value_or("");
  bool ok = false;
  // tinygltf reports errors as text, but nlohmann (inside it) may still throw on odd JSON.
  try {
    ok = binary ? gltf.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(),
                                            static_cast<unsigned int>(bytes.size()), dir)
                : gltf.LoadASCIIFromString(&model, &err, &warn,
                                           reinterpret_cast<const char*>(bytes.data()),
                                           static_cast<unsigned int>(bytes.size()), dir);
  } catch (const std::exception& e) {
    return Error{fold_message(std::string("invalid glTF (") + e.what() + ")")};
  }
  if (!ok) {
    if (!access.read_error.empty()) return Error{fold_message(access.read_error)};
    return Error{fold_message(err.empty() ? warn : err)};
  }
  if (auto resolved = resolve_extensions(model, *prepared); !resolved) return resolved.error();
  return model;
}

}  // namespace tutti::model::detail
