// Validated reads from a JSON document. Each reader is a view of one JSON object with
// its file and JSON path, so that every error names the file, the field, what was
// expected and what was found.
#pragma once

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "glint/core/Math.hpp"

namespace glint {

// Bad input from the user: a scene file, an override or a command-line value.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An allowed interval of numbers, with the words that describe it in messages.
struct Range {
  double min = -kInfinity;
  double max = kInfinity;
  bool minOpen = false;
  bool maxOpen = false;

  static Range Any() { return {}; }
  static Range Positive() { return {0.0, kInfinity, true, false}; }
  static Range AtLeast(double a) { return {a, kInfinity, false, false}; }
  static Range Closed(double a, double b) { return {a, b, false, false}; }
  bool Contains(double x) const;
  std::string Describe() const;
};

class JsonReader {
 public:
  JsonReader(const nlohmann::json& value, std::string file, std::string path);

  bool Has(const char* key) const { return value_.contains(key); }
  const nlohmann::json& Json() const { return value_; }
  JsonReader Object(const char* key) const;
  // An array of objects with between minSize and maxSize elements.
  std::vector<JsonReader> Objects(const char* key, std::size_t minSize, std::size_t maxSize) const;
  double Number(const char* key, const Range& range) const;
  double NumberOr(const char* key, double fallback, const Range& range) const;
  int Integer(const char* key, const Range& range) const;
  int IntegerOr(const char* key, int fallback, const Range& range) const;
  vec3 Vec3(const char* key, const Range& range) const;
  std::string String(const char* key, std::initializer_list<const char*> allowed) const;
  std::string Text(const char* key) const;  // any non-empty string
  std::string StringOr(const char* key, const char* fallback,
                       std::initializer_list<const char*> allowed) const;

  // Rejects keys other than `known`, suggesting the closest known key.
  void RejectUnknownKeys(std::initializer_list<const char*> known) const;

  [[noreturn]] void Fail(const char* key, const std::string& expected,
                         const std::string& found) const;
  // "file: /path/key: sentence", for a field that is there but must not be.
  [[noreturn]] void Refuse(const char* key, const std::string& sentence) const;
  std::string PathOf(const char* key) const { return path_ + "/" + key; }
  // The JSON pointer of this object ("" for the document itself).
  const std::string& Path() const { return path_; }
  const std::string& File() const { return file_; }

 private:
  const nlohmann::json& Field(const char* key) const;  // throws when missing

  const nlohmann::json& value_;
  std::string file_;
  std::string path_;
};

// A short description of a JSON value for messages: `a string "x"`, `the number -1`.
std::string DescribeJson(const nlohmann::json& value);

// Levenshtein edit distance, for "did you mean" suggestions.
std::size_t EditDistance(const std::string& a, const std::string& b);

}  // namespace glint
