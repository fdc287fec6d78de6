#include "chain_file/json_reader.hpp"

#include <algorithm>
#include <cmath>

#include <hush/core/error.hpp>

namespace hush::passes::chain_file {

Json parse(std::string_view text, const std::string& source) {
    try {
        return Json::parse(text.begin(), text.end(), nullptr, true, /*ignore_comments=*/true);
    } catch (const Json::parse_error& e) {
        // nlohmann gives a byte offset; users need line:column.
        size_t line = 1, column = 1;
        const size_t end = std::min<size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
        for (size_t i = 0; i < end; ++i) {
            if (text[i] == '\n') ++line, column = 1;
            else ++column;
        }
        std::string what = e.what();
        if (auto colon = what.find("syntax error"); colon != std::string::npos) what = what.substr(colon);
        throw Error(ErrorKind::InvalidArgument,
                    source + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + what);
    }
}

void fail(const std::string& source, const std::string& path, const std::string& what) {
    throw Error(ErrorKind::InvalidArgument, source + ": " + (path.empty() ? "" : path + ": ") + what);
}

ObjectReader::ObjectReader(const Json& value, std::string source, std::string path)
    : value_(value), source_(std::move(source)), path_(std::move(path)) {
    if (!value_.is_object()) fail(source_, path_, std::string("expected an object, got ") + value_.type_name());
}

std::string ObjectReader::path(std::string_view key) const {
    return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

const Json* ObjectReader::child(std::string_view key) {
    known_.emplace_back(key);
    auto it = value_.find(key);
    return it == value_.end() ? nullptr : &*it;
}

void ObjectReader::read(std::string_view key, float& out, float lo, float hi) {
    const Json* v = child(key);
    if (!v) return;
    if (!v->is_number()) fail(source_, path(key), std::string("expected a number, got ") + v->type_name());
    const double d = v->get<double>();
    if (!std::isfinite(d) || d < lo || d > hi)
        fail(source_, path(key), "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + v->dump());
    out = float(d);
}

void ObjectReader::read(std::string_view key, uint32_t& out, uint32_t lo, uint32_t hi) {
    const Json* v = child(key);
    if (!v) return;
    if (!v->is_number_integer() || v->get<int64_t>() < int64_t(lo) || v->get<int64_t>() > int64_t(hi))
        fail(source_, path(key),
             "must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + v->dump());
    out = uint32_t(v->get<int64_t>());
}

void ObjectReader::read(std::string_view key, bool& out) {
    const Json* v = child(key);
    if (!v) return;
    if (!v->is_boolean()) fail(source_, path(key), std::string("expected true or false, got ") + v->dump());
    out = v->get<bool>();
}

void ObjectReader::read(std::string_view key, std::string& out) {
    const Json* v = child(key);
    if (!v) return;
    if (!v->is_string()) fail(source_, path(key), std::string("expected a string, got ") + v->dump());
    out = v->get<std::string>();
}

void ObjectReader::finish() const {
    for (auto it = value_.begin(); it != value_.end(); ++it) {
        if (std::find(known_.begin(), known_.end(), it.key()) != known_.end()) continue;
        std::string list;
        for (const auto& k : known_) list += (list.empty() ? "'" : ", '") + k + "'";
        fail(source_, path(it.key()), "unknown field; known fields here: " + (list.empty() ? "none" : list));
    }
}

} // namespace hush::passes::chain_file
