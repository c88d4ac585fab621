// SPDX-License-Identifier: MIT
#include <tutti/scene/performance_marks.hpp>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace tutti::scene {
namespace {

Result<double> time_at(const FieldReader& reader, const nlohmann::json& value,
                       const std::string& where) {
  if (!value.is_number()) return reader.error(where, "expected a time in seconds");
  const double t = value.get<double>();
  if (!std::isfinite(t) || t < kEarliestMark_s || t > kLatestMark_s) {
    return reader.error(where, "must be in [" + format_number(kEarliestMark_s) + ", " +
                                   format_number(kLatestMark_s) + "] s");
  }
  return t;
}

// An array of times, sorted on reading (the order in the file does not matter).
Status time_list(const FieldReader& reader, const nlohmann::json& object, const std::string& path,
                 const char* key, std::vector<double>& out) {
  if (!object.contains(key)) return Status::success();
  const std::string where = join_path(path, key);
  const nlohmann::json& list = object.at(key);
  if (!list.is_array()) return reader.error(where, "expected an array of times in seconds");
  for (std::size_t i = 0; i < list.size(); ++i) {
    auto t = time_at(reader, list[i], where + "/" + std::to_string(i));
    if (!t) return t.error();
    out.push_back(*t);
  }
  std::sort(out.begin(), out.end());
  return Status::success();
}

Status parse_expression(const FieldReader& reader, const nlohmann::json& object,
                        const std::string& path, Expression& out) {
  if (auto ok = reader.json().check_keys(object, path, {"kind", "start_s", "end_s", "amount"});
      !ok) {
    return ok;
  }
  auto kind = reader.string(object, path, "kind");
  if (!kind) return kind.error();
  if (*kind == "strain") {
    out.kind = ExpressionKind::strain;
  } else if (*kind == "relaxed") {
    out.kind = ExpressionKind::relaxed;
  } else {
    return reader.error(join_path(path, "kind"), "must be \"strain\" or \"relaxed\"");
  }
  auto start = reader.number(object, path, "start_s", kEarliestMark_s, kLatestMark_s);
  if (!start) return start.error();
  auto end = reader.number(object, path, "end_s", kEarliestMark_s, kLatestMark_s);
  if (!end) return end.error();
  if (*end <= *start) {
    return reader.error(join_path(path, "end_s"),
                        "must be later than start_s (" + format_number(*start) + " s)");
  }
  auto amount = reader.number_or(object, path, "amount", 0.0, 1.0, 1.0);
  if (!amount) return amount.error();
  out.start_s = *start;
  out.end_s = *end;
  out.amount = *amount;
  return Status::success();
}

}  // namespace

Status parse_performer_marks(const FieldReader& reader, const nlohmann::json& performer,
                             const std::string& path, BreathMarks& breath_marks,
                             std::vector<Expression>& expressions) {
  if (performer.contains("breaths")) {
    const std::string where = path + "/breaths";
    const nlohmann::json& breaths = performer.at("breaths");
    if (auto ok = reader.json().check_keys(breaths, where, {"add", "remove"}); !ok) return ok;
    if (auto ok = time_list(reader, breaths, where, "add", breath_marks.add_s); !ok) return ok;
    if (auto ok = time_list(reader, breaths, where, "remove", breath_marks.remove_s); !ok) {
      return ok;
    }
  }
  if (performer.contains("expressions")) {
    const std::string where = path + "/expressions";
    const nlohmann::json& list = performer.at("expressions");
    if (!list.is_array()) return reader.error(where, "expected an array");
    for (std::size_t i = 0; i < list.size(); ++i) {
      Expression expression;
      if (auto ok = parse_expression(reader, list[i], where + "/" + std::to_string(i), expression);
          !ok) {
        return ok;
      }
      expressions.push_back(expression);
    }
    std::stable_sort(
        expressions.begin(), expressions.end(),
        [](const Expression& a, const Expression& b) { return a.start_s < b.start_s; });
  }
  return Status::success();
}

Status parse_cues(const FieldReader& reader, const nlohmann::json& document,
                  std::optional<std::vector<double>>& out) {
  if (!document.contains("cues")) return Status::success();
  std::vector<double> cues;
  if (auto ok = time_list(reader, document, "", "cues", cues); !ok) return ok;
  out = std::move(cues);
  return Status::success();
}

}  // namespace tutti::scene
