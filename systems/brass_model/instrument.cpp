// SPDX-License-Identifier: MIT
#include <tutti/brass_model/instrument.hpp>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <system_error>

#include <tutti/brass_model/fingering_chart.hpp>
#include <tutti/brass_model/fingering_names.hpp>
#include <tutti/brass_model/instrument_file.hpp>
#include <tutti/content/content_dir.hpp>
#include <tutti/content/json_reader.hpp>

namespace tutti::brass_model {

const std::string& Instrument::model_name() const {
  static const std::string trombone = "trombone";
  static const std::string trumpet = "trumpet";
  if (!model.empty()) return model;
  return mechanism == Mechanism::slide ? trombone : trumpet;
}

std::span<const Fingering> Instrument::fingerings(int written) const {
  if (!in_range_written(written)) return {};
  const auto index = static_cast<std::size_t>(written - lowest_written);
  if (index + 1 >= chart_begin.size()) return {};
  const auto begin = static_cast<std::size_t>(chart_begin[index]);
  const auto end = static_cast<std::size_t>(chart_begin[index + 1]);
  return std::span<const Fingering>(chart).subspan(begin, end - begin);
}

Result<Instrument> load_instrument(const std::filesystem::path& file) {
  auto document = content::read_json_file(file);
  if (!document) return document.error();
  auto parsed = parse_instrument_file(*document, file.string(), file.stem().string());
  if (!parsed) return parsed.error();
  if (auto ok = derive_chart(*parsed); !ok) return ok.error();
  return std::move(parsed->instrument);
}

Result<Instrument> load_instrument_by_id(std::string_view id) {
  return load_instrument_by_id(id, content::default_content_dir());
}

Result<Instrument> load_instrument_by_id(std::string_view id,
                                         const std::filesystem::path& content_dir) {
  const bool plain = !id.empty() && std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
  });
  if (!plain) return Error{"\"" + std::string(id) + "\" is not an instrument id"};
  return load_instrument(content_dir / "instruments" / (std::string(id) + ".json"));
}

Result<std::vector<Instrument>> load_all_instruments() {
  const std::filesystem::path folder = content::default_content_dir() / "instruments";
  std::error_code ec;
  std::vector<std::filesystem::path> files;
  for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end;
       it.increment(ec)) {
    if (it->path().extension() == ".json") files.push_back(it->path());
  }
  if (ec) return Error{folder.string() + ": cannot list (" + ec.message() + ")"};
  if (files.empty()) return Error{folder.string() + ": no instrument files (*.json)"};
  std::sort(files.begin(), files.end(),
            [](const auto& a, const auto& b) { return a.stem().string() < b.stem().string(); });
  std::vector<Instrument> instruments;
  for (const auto& file : files) {
    auto instrument = load_instrument(file);
    if (!instrument) return instrument.error();
    instruments.push_back(std::move(*instrument));
  }
  return instruments;
}

std::string fingering_name(const Instrument& instrument, const Fingering& fingering,
                           bool with_partial) {
  std::string name =
      instrument.mechanism == Mechanism::slide
          ? slide_fingering_name(instrument.valves, fingering.valves, fingering.position)
          : combination_name(instrument.valves, fingering.valves);
  if (with_partial) name += " (partial " + std::to_string(fingering.partial) + ")";
  return name;
}

}  // namespace tutti::brass_model
