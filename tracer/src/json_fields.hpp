#pragma once
// Private helpers for reading a JSON document with errors that name the file and the
// JSON path of the offending value ("scene.json: meshes[2].material: ..."). Every
// accessor checks the type first, so no nlohmann exception escapes from reading.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include <hush/rhi/error.hpp>

namespace hush::tracer::detail {

using Json = nlohmann::json;

// Parses JSON text (// and /* */ comments allowed); syntax errors become
// hush::Error "name:line:column: ..." with the line and column computed from the
// byte offset nlohmann reports.
Json parseJson(std::string_view text, const std::string& name);

// Line and column (both from 1) of the byte at `offset` (0-based) in `text`.
struct TextPosition {
    std::size_t line = 1;
    std::size_t column = 1;
};
TextPosition positionOf(std::string_view text, std::size_t offset);

class JsonFields {
public:
    explicit JsonFields(std::string file) : file_(std::move(file)) {}

    const std::string& file() const { return file_; }

    static std::string child(const std::string& path, std::string_view key) {
        return path.empty() ? std::string(key) : path + "." + std::string(key);
    }
    static std::string item(const std::string& path, std::size_t i) { return path + "[" + std::to_string(i) + "]"; }

    [[noreturn]] void fail(const std::string& path, const std::string& what,
                           ErrorKind kind = ErrorKind::InvalidArgument) const;

    // The value must be an object whose keys are all in `known` (the message lists them).
    void object(const Json& v, const std::string& path, std::initializer_list<std::string_view> known) const;
    const Json& array(const Json& v, const std::string& path) const;
    std::string string(const Json& v, const std::string& path) const;
    bool boolean(const Json& v, const std::string& path) const;
    float number(const Json& v, const std::string& path) const;          // finite, fits a float
    float nonNegative(const Json& v, const std::string& path) const;
    float positive(const Json& v, const std::string& path) const;
    std::uint32_t index(const Json& v, const std::string& path) const;   // an integer in [0, 2^32)
    glm::vec3 vec3(const Json& v, const std::string& path) const;        // [x, y, z]
    glm::vec3 colour(const Json& v, const std::string& path) const;      // [r, g, b], none negative

private:
    std::string file_;
};

} // namespace hush::tracer::detail
