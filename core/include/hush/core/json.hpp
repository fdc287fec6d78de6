#pragma once
// Reading JSON documents (scene files, chain files, weight headers, results files)
// with errors a user can act on: every message names the document and the JSON path
// of the offending value ("scene.json: meshes[2].material: unknown material 'gold'"),
// or line:column for a syntax error. No nlohmann exception escapes from here.
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include <hush/core/error.hpp>

namespace hush::core {

using Json = nlohmann::json;

// Line and column (both from 1) of the byte at `offset` (0-based) in `text`.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
TextPosition positionOf(std::string_view text, std::size_t offset);

// Parses `text` (// and /* */ comments allowed). A syntax error is hush::Error
// "<source>:<line>:<column>: JSON syntax error: ..."; any other JSON failure (a number
// too large for a double, "1e999") "<source>: JSON error: ...".
Json parseJson(std::string_view text, const std::string& source);

// "a.b" from ("a", "b"); "b" from ("", "b").
std::string jsonChildPath(std::string_view path, std::string_view key);
// "a[3]" from ("a", 3).
std::string jsonItemPath(std::string_view path, std::size_t index);

// "<source>: <path>: <what>" (no path: "<source>: <what>").
[[noreturn]] void failAt(const std::string& source, const std::string& path, const std::string& what,
                         ErrorKind kind = ErrorKind::InvalidArgument);

// One value of a parsed document, with the document's name and the value's path.
// The accessors check the type (and range) first and fail naming the path.
class JsonValue {
public:
    JsonValue(const Json& value, std::string source, std::string path)
        : value_(&value), source_(std::move(source)), path_(std::move(path)) {}

    const Json& json() const { return *value_; }
    const std::string& source() const { return source_; }
    const std::string& path() const { return path_; }
    [[noreturn]] void fail(const std::string& what, ErrorKind kind = ErrorKind::InvalidArgument) const;

    std::string string() const;
    bool boolean() const;
    float number() const;                       // finite and within a float's range
    float number(float lo, float hi) const;     // within [lo, hi]
    float nonNegative() const;
    float positive() const;
    uint32_t index() const;                     // an integer in [0, 2^32)
    uint32_t integer(uint32_t lo, uint32_t hi) const;
    // An array (with minItems .. maxItems items): its size, and its items.
    std::size_t arraySize(std::size_t minItems = 0, std::size_t maxItems = std::numeric_limits<std::size_t>::max()) const;
    JsonValue operator[](std::size_t index) const;

private:
    const Json* value_;   // the document outlives its readers
    std::string source_;
    std::string path_;
};

// An object read key by key. Each key that is read, looked up or allowed becomes
// known; finish() rejects any other key, listing the known ones, so a misspelt key
// never silently keeps its default.
class JsonObject {
public:
    // Throws unless the value is an object.
    explicit JsonObject(const JsonValue& value);
    JsonObject(const Json& value, const std::string& source, std::string path)
        : JsonObject(JsonValue(value, source, std::move(path))) {}

    const std::string& source() const { return value_.source(); }
    const std::string& path() const { return value_.path(); }
    std::string path(std::string_view key) const { return jsonChildPath(value_.path(), key); }
    bool has(std::string_view key) const { return value_.json().contains(key); }
    [[noreturn]] void fail(const std::string& what) const { value_.fail(what); }

    // The value of `key`, marking it known; nullopt when absent.
    std::optional<JsonValue> get(std::string_view key);
    // As get(), but a missing key is an error ("missing field '<key>'").
    JsonValue require(std::string_view key);
    // Reads `key` into `out` when present, checking type and range.
    void read(std::string_view key, float& out, float lo, float hi);
    void read(std::string_view key, uint32_t& out, uint32_t lo, uint32_t hi);
    void read(std::string_view key, bool& out);
    void read(std::string_view key, std::string& out);
    // Marks keys known without reading them.
    void allow(std::string_view key) { known_.emplace_back(key); }
    // Marks `known` as the object's keys and fails now, before anything is read, on
    // any other key (listing these in this order).
    void only(std::initializer_list<std::string_view> known);
    // Throws on the first key that nothing read or allowed.
    void finish() const;

private:
    JsonValue value_;
    std::vector<std::string> known_;
};

} // namespace hush::core
