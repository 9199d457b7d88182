#include "glint/core/JsonReader.hpp"

#include <sstream>

#include "glint/core/Format.hpp"

namespace glint {

namespace {

std::string JoinQuoted(std::initializer_list<const char*> words) {
  std::string out;
  std::size_t i = 0;
  for (const char* w : words) {
    if (i > 0) out += (i + 1 == words.size()) ? " or " : ", ";
    out += std::string("\"") + w + "\"";
    ++i;
  }
  return out;
}

}  // namespace

bool Range::Contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool aboveMin = minOpen ? x > min : x >= min;
  const bool belowMax = maxOpen ? x < max : x <= max;
  return aboveMin && belowMax;
}

std::string Range::Describe() const {
  const bool hasMin = min > -kInfinity;
  const bool hasMax = max < kInfinity;
  if (hasMin && hasMax) {
    return std::string("in ") + (minOpen ? "(" : "[") + FormatNumber(min) + ", " +
           FormatNumber(max) + (maxOpen ? ")" : "]");
  }
  if (hasMin) return (minOpen ? "> " : ">= ") + FormatNumber(min);
  if (hasMax) return (maxOpen ? "< " : "<= ") + FormatNumber(max);
  return "finite";
}

std::string DescribeJson(const nlohmann::json& value) {
  switch (value.type()) {
    case nlohmann::json::value_t::null:
      return "null";
    case nlohmann::json::value_t::boolean:
      return std::string("the boolean ") + (value.get<bool>() ? "true" : "false");
    case nlohmann::json::value_t::string:
      return "the string " + value.dump();
    case nlohmann::json::value_t::number_integer:
    case nlohmann::json::value_t::number_unsigned:
    case nlohmann::json::value_t::number_float:
      return "the number " + value.dump();
    case nlohmann::json::value_t::array:
      return "an array of " + std::to_string(value.size()) + " element" +
             (value.size() == 1 ? "" : "s");
    case nlohmann::json::value_t::object:
      return "an object";
    default:
      return "a value of another kind";
  }
}

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

JsonReader::JsonReader(const nlohmann::json& value, std::string file, std::string path)
    : value_(value), file_(std::move(file)), path_(std::move(path)) {
  if (!value_.is_object()) {
    throw InputError(file_ + ": " + (path_.empty() ? "/" : path_) + ": expected an object, found " +
                     DescribeJson(value_));
  }
}

void JsonReader::Fail(const char* key, const std::string& expected,
                      const std::string& found) const {
  throw InputError(file_ + ": " + PathOf(key) + ": expected " + expected + ", found " + found);
}

void JsonReader::Refuse(const char* key, const std::string& sentence) const {
  throw InputError(file_ + ": " + PathOf(key) + ": " + sentence);
}

const nlohmann::json& JsonReader::Field(const char* key) const {
  const auto it = value_.find(key);
  if (it == value_.end()) Fail(key, "a value (the field is required)", "nothing");
  return *it;
}

JsonReader JsonReader::Object(const char* key) const {
  const nlohmann::json& v = Field(key);
  if (!v.is_object()) Fail(key, "an object", DescribeJson(v));
  return {v, file_, PathOf(key)};
}

std::vector<JsonReader> JsonReader::Objects(const char* key, std::size_t minSize,
                                            std::size_t maxSize) const {
  const nlohmann::json& v = Field(key);
  const std::string sizes = minSize == maxSize
                                ? std::to_string(minSize)
                                : std::to_string(minSize) + " to " + std::to_string(maxSize);
  if (!v.is_array() || v.size() < minSize || v.size() > maxSize) {
    Fail(key, "an array of " + sizes + " objects", DescribeJson(v));
  }
  std::vector<JsonReader> out;
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.emplace_back(v[i], file_, PathOf(key) + "/" + std::to_string(i));
  }
  return out;
}

double JsonReader::Number(const char* key, const Range& range) const {
  const nlohmann::json& v = Field(key);
  if (!v.is_number()) Fail(key, "a number " + range.Describe(), DescribeJson(v));
  const auto x = v.get<double>();
  if (!range.Contains(x)) Fail(key, "a number " + range.Describe(), DescribeJson(v));
  return x;
}

double JsonReader::NumberOr(const char* key, double fallback, const Range& range) const {
  return Has(key) ? Number(key, range) : fallback;
}

int JsonReader::Integer(const char* key, const Range& range) const {
  const nlohmann::json& v = Field(key);
  const std::string expected = "a whole number " + range.Describe();
  if (!v.is_number_integer()) Fail(key, expected, DescribeJson(v));
  const auto x = v.get<long long>();
  if (!range.Contains(static_cast<double>(x)) || x > 2147483647LL || x < -2147483647LL) {
    Fail(key, expected, DescribeJson(v));
  }
  return static_cast<int>(x);
}

int JsonReader::IntegerOr(const char* key, int fallback, const Range& range) const {
  return Has(key) ? Integer(key, range) : fallback;
}

vec3 JsonReader::Vec3(const char* key, const Range& range) const {
  const nlohmann::json& v = Field(key);
  const std::string expected = "an array of 3 numbers " + range.Describe();
  if (!v.is_array() || v.size() != 3) Fail(key, expected, DescribeJson(v));
  vec3 out(0.0);
  for (int i = 0; i < 3; ++i) {
    const nlohmann::json& e = v[static_cast<std::size_t>(i)];
    if (!e.is_number() || !range.Contains(e.get<double>())) {
      Fail(key, expected, "element " + std::to_string(i) + " = " + e.dump());
    }
    out[i] = e.get<double>();
  }
  return out;
}

std::string JsonReader::String(const char* key, std::initializer_list<const char*> allowed) const {
  const nlohmann::json& v = Field(key);
  const std::string expected = "one of " + JoinQuoted(allowed);
  if (!v.is_string()) Fail(key, expected, DescribeJson(v));
  auto s = v.get<std::string>();
  for (const char* a : allowed) {
    if (s == a) return s;
  }
  Fail(key, expected, DescribeJson(v));
}

std::string JsonReader::Text(const char* key) const {
  const nlohmann::json& v = Field(key);
  if (!v.is_string() || v.get<std::string>().empty()) {
    Fail(key, "a non-empty string", DescribeJson(v));
  }
  return v.get<std::string>();
}

std::string JsonReader::StringOr(const char* key, const char* fallback,
                                 std::initializer_list<const char*> allowed) const {
  return Has(key) ? String(key, allowed) : std::string(fallback);
}

void JsonReader::RejectUnknownKeys(std::initializer_list<const char*> known) const {
  for (const auto& item : value_.items()) {
    bool ok = false;
    std::string best;
    std::size_t bestDistance = 1000;
    for (const char* k : known) {
      if (item.key() == k) ok = true;
      const std::size_t d = EditDistance(item.key(), k);
      if (d < bestDistance) {
        bestDistance = d;
        best = k;
      }
    }
    if (ok) continue;
    std::string message =
        file_ + ": " + PathOf(item.key().c_str()) + ": unknown field \"" + item.key() + "\"";
    if (!best.empty() && bestDistance <= std::max<std::size_t>(2, item.key().size() / 3)) {
      message += " (did you mean \"" + best + "\"?)";
    } else {
      message += "; expected one of " + JoinQuoted(known);
    }
    throw InputError(message);
  }
}

}  // namespace glint
