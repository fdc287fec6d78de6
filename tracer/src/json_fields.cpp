#include "json_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "text_parse.hpp"

namespace hush::tracer::detail {

namespace {

// nlohmann's messages quote the input they stopped at, which may be any bytes.
std::string printable(std::string_view s) {
    std::string out;
    for (const char ch : s.substr(0, 300)) {
        const auto c = static_cast<unsigned char>(ch);
        if (c >= 0x20 && c < 0x7f) {
            out += ch;
        } else {
            static constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    return out;
}

// "[json.exception.parse_error.101] parse error at line 1, column 2: what" -> "what":
// we put our own position in front.
std::string stripPrefix(const std::string& message) {
    const std::size_t at = message.find("parse error");
    const std::size_t colon = message.find(": ", at == std::string::npos ? 0 : at);
    if (colon != std::string::npos) return message.substr(colon + 2);
    const std::size_t bracket = message.find("] ");
    return bracket == std::string::npos ? message : message.substr(bracket + 2);
}

} // namespace

TextPosition positionOf(std::string_view text, std::size_t offset) {
    offset = std::min(offset, text.size());
    const std::string_view before = text.substr(0, offset);
    TextPosition p;
    p.line = 1 + static_cast<std::size_t>(std::count(before.begin(), before.end(), '\n'));
    const std::size_t lastNewline = before.rfind('\n');
    p.column = lastNewline == std::string_view::npos ? offset + 1 : offset - lastNewline;
    return p;
}

Json parseJson(std::string_view text, const std::string& name) {
    try {
        return Json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    } catch (const Json::parse_error& e) {
        // e.byte counts from 1 and names the last byte read: the one that broke the syntax.
        std::string where = name;
        if (e.byte > 0) {
            const TextPosition p = positionOf(text, e.byte - 1);
            where += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
        }
        throw Error(ErrorKind::InvalidArgument, where + ": JSON syntax error: " + printable(stripPrefix(e.what())));
    } catch (const Json::exception& e) {
        // e.g. out_of_range.406, "number overflow parsing '1e999'": no position given.
        throw Error(ErrorKind::InvalidArgument, name + ": JSON error: " + printable(stripPrefix(e.what())));
    }
}

void JsonFields::fail(const std::string& path, const std::string& what, ErrorKind kind) const {
    throw Error(kind, file_ + ": " + (path.empty() ? std::string() : path + ": ") + what);
}

void JsonFields::object(const Json& v, const std::string& path, std::initializer_list<std::string_view> known) const {
    if (!v.is_object()) fail(path.empty() ? "(top level)" : path, "must be a JSON object");
    for (const auto& [key, value] : v.items()) {
        if (std::find(known.begin(), known.end(), key) != known.end()) continue;
        std::string list;
        for (const std::string_view k : known) list += (list.empty() ? "" : ", ") + std::string(k);
        fail(path, "unknown field " + quote(key) + " (known fields: " + list + ")");
    }
}

const Json& JsonFields::array(const Json& v, const std::string& path) const {
    if (!v.is_array()) fail(path, "must be an array");
    return v;
}

std::string JsonFields::string(const Json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "must be a string");
    return v.get<std::string>();
}

bool JsonFields::boolean(const Json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, "must be true or false");
    return v.get<bool>();
}

float JsonFields::number(const Json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d) || std::fabs(d) > static_cast<double>(std::numeric_limits<float>::max()))
        fail(path, "number out of range for a float");
    return static_cast<float>(d);
}

float JsonFields::nonNegative(const Json& v, const std::string& path) const {
    const float f = number(v, path);
    if (f < 0.0f) fail(path, "must be >= 0, got " + std::to_string(f));
    return f;
}

float JsonFields::positive(const Json& v, const std::string& path) const {
    const float f = number(v, path);
    if (!(f > 0.0f)) fail(path, "must be > 0, got " + std::to_string(f));
    return f;
}

std::uint32_t JsonFields::index(const Json& v, const std::string& path) const {
    if (!v.is_number_unsigned()) fail(path, "must be a non-negative integer");
    const auto u = v.get<std::uint64_t>();
    if (u > std::numeric_limits<std::uint32_t>::max()) fail(path, "index " + std::to_string(u) + " is too large");
    return static_cast<std::uint32_t>(u);
}

glm::vec3 JsonFields::vec3(const Json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) fail(path, "must be an array of 3 numbers");
    return {number(v[0], item(path, 0)), number(v[1], item(path, 1)), number(v[2], item(path, 2))};
}

glm::vec3 JsonFields::colour(const Json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 3) fail(path, "must be an RGB array of 3 numbers");
    return {nonNegative(v[0], item(path, 0)), nonNegative(v[1], item(path, 1)), nonNegative(v[2], item(path, 2))};
}

} // namespace hush::tracer::detail
