#include <hush/core/json.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace hush::core {

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
// our own position goes in front.
std::string stripPrefix(const std::string& message) {
    const std::size_t at = message.find("parse error");
    const std::size_t colon = message.find(": ", at == std::string::npos ? 0 : at);
    if (colon != std::string::npos) return message.substr(colon + 2);
    const std::size_t bracket = message.find("] ");
    return bracket == std::string::npos ? message : message.substr(bracket + 2);
}

std::string singleQuoted(std::string_view s) { return "'" + printable(s) + "'"; }

// nlohmann keeps the last of two equal keys; a file that says a thing twice is
// ambiguous (which one did the user mean?), so it is an error. The parser callback
// sees each key as it is read; every open object is a frame on a stack.
class DuplicateKeyCheck {
public:
    explicit DuplicateKeyCheck(const std::string& source) : source_(source) {}

    bool operator()(int, Json::parse_event_t event, Json& parsed) {
        if (event == Json::parse_event_t::object_start) {
            // An object in an array is named after the array's key: close enough to find it.
            objects_.push_back({objects_.empty() ? "" : jsonChildPath(objects_.back().path, objects_.back().lastKey)});
        } else if (event == Json::parse_event_t::object_end) {
            objects_.pop_back();
        } else if (event == Json::parse_event_t::key) {
            onKey(parsed.get<std::string>());
        }
        return true;
    }

private:
    struct Frame {
        std::string path;
        std::set<std::string> keys;
        std::string lastKey;
    };

    void onKey(const std::string& key) {
        Frame& object = objects_.back();
        if (!object.keys.insert(key).second) {
            throw Error(ErrorKind::InvalidArgument, source_ + ": " + (object.path.empty() ? "" : object.path + ": ") +
                                                        "key " + singleQuoted(key) + " appears twice in one object");
        }
        object.lastKey = key;
    }

    const std::string& source_;
    std::vector<Frame> objects_;
};

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

Json parseJson(std::string_view text, const std::string& source) {
    try {
        return Json::parse(text.begin(), text.end(), DuplicateKeyCheck(source), /*allow_exceptions=*/true,
                           /*ignore_comments=*/true);
    } catch (const Json::parse_error& e) {
        // e.byte counts from 1 and names the last byte read: the one that broke the syntax.
        std::string where = source;
        if (e.byte > 0) {
            const TextPosition p = positionOf(text, e.byte - 1);
            where += ":" + std::to_string(p.line) + ":" + std::to_string(p.column);
        }
        throw Error(ErrorKind::InvalidArgument, where + ": JSON syntax error: " + printable(stripPrefix(e.what())));
    } catch (const Json::exception& e) {
        // e.g. out_of_range.406, "number overflow parsing '1e999'": nlohmann gives no position.
        throw Error(ErrorKind::InvalidArgument, source + ": JSON error: " + printable(stripPrefix(e.what())));
    }
}

std::string jsonChildPath(std::string_view path, std::string_view key) {
    return path.empty() ? std::string(key) : std::string(path) + "." + std::string(key);
}

std::string jsonItemPath(std::string_view path, std::size_t index) {
    return std::string(path) + "[" + std::to_string(index) + "]";
}

void failAt(const std::string& source, const std::string& path, const std::string& what, ErrorKind kind) {
    throw Error(kind, source + ": " + (path.empty() ? std::string() : path + ": ") + what);
}

void JsonValue::fail(const std::string& what, ErrorKind kind) const { failAt(source(), path_, what, kind); }

std::string JsonValue::string() const {
    if (!value_->is_string()) fail("must be a string");
    return value_->get<std::string>();
}

bool JsonValue::boolean() const {
    if (!value_->is_boolean()) fail("must be true or false");
    return value_->get<bool>();
}

float JsonValue::number() const {
    if (!value_->is_number()) fail("must be a number");
    const double d = value_->get<double>();
    if (!std::isfinite(d) || std::fabs(d) > double(std::numeric_limits<float>::max()))
        fail("number out of range for a float");
    return float(d);
}

float JsonValue::number(float lo, float hi) const {
    if (!value_->is_number()) fail("must be a number");
    const double d = value_->get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
        fail("must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + value_->dump());
    return float(d);
}

float JsonValue::nonNegative() const {
    const float f = number();
    if (f < 0.0f) fail("must be >= 0, got " + std::to_string(f));
    return f;
}

float JsonValue::positive() const {
    const float f = number();
    if (!(f > 0.0f)) fail("must be > 0, got " + std::to_string(f));
    return f;
}

uint32_t JsonValue::index() const {
    if (!value_->is_number_unsigned()) fail("must be a non-negative integer");
    const auto u = value_->get<uint64_t>();
    if (u > std::numeric_limits<uint32_t>::max()) fail("index " + std::to_string(u) + " is too large");
    return uint32_t(u);
}

uint32_t JsonValue::integer(uint32_t lo, uint32_t hi) const {
    const bool integral = value_->is_number_integer();
    if (!integral || value_->get<int64_t>() < int64_t(lo) || value_->get<int64_t>() > int64_t(hi))
        fail("must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + value_->dump());
    return uint32_t(value_->get<int64_t>());
}

std::size_t JsonValue::arraySize(std::size_t minItems, std::size_t maxItems) const {
    if (!value_->is_array()) fail("must be an array");
    const std::size_t n = value_->size();
    if (n < minItems || n > maxItems)
        fail("must have " +
             (maxItems == std::numeric_limits<std::size_t>::max()
                  ? "at least " + std::to_string(minItems)
                  : std::to_string(minItems) + " to " + std::to_string(maxItems)) +
             " items, has " + std::to_string(n));
    return n;
}

JsonValue JsonValue::operator[](std::size_t index) const {
    return JsonValue((*value_)[index], source_, jsonItemPath(path_, index));
}

JsonObject::JsonObject(const JsonValue& value) : value_(value) {
    if (!value.json().is_object())
        failAt(value.source(), value.path().empty() ? "(top level)" : value.path(), "must be a JSON object");
}

std::optional<JsonValue> JsonObject::get(std::string_view key) {
    known_.emplace_back(key);
    const auto it = value_.json().find(key);
    if (it == value_.json().end()) return std::nullopt;
    return JsonValue(*it, value_.source(), path(key));
}

JsonValue JsonObject::require(std::string_view key) {
    auto v = get(key);
    if (!v) failAt(value_.source(), value_.path(), "missing field " + singleQuoted(key));
    return *v;
}

void JsonObject::read(std::string_view key, float& out, float lo, float hi) {
    if (auto v = get(key)) out = v->number(lo, hi);
}

void JsonObject::read(std::string_view key, uint32_t& out, uint32_t lo, uint32_t hi) {
    if (auto v = get(key)) out = v->integer(lo, hi);
}

void JsonObject::read(std::string_view key, bool& out) {
    if (auto v = get(key)) out = v->boolean();
}

void JsonObject::read(std::string_view key, std::string& out) {
    if (auto v = get(key)) out = v->string();
}

void JsonObject::only(std::initializer_list<std::string_view> known) {
    for (const auto k : known) known_.emplace_back(k);
    finish();
}

void JsonObject::finish() const {
    for (auto it = value_.json().begin(); it != value_.json().end(); ++it) {
        if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
        std::vector<std::string> names;   // in the order they were read, each once
        for (const auto& k : known_)
            if (std::find(names.begin(), names.end(), k) == names.end()) names.push_back(k);
        std::string list;
        for (const auto& k : names) list += (list.empty() ? "" : ", ") + k;
        failAt(value_.source(), value_.path(),
               "unknown field " + singleQuoted(it.key()) + " (known fields: " + (list.empty() ? "none" : list) + ")");
    }
}

} // namespace hush::core
