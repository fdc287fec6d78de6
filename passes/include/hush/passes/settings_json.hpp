#pragma once
// Settings structs to and from JSON through their describe() (settings.hpp): the
// chain-file reader (every key named as the C++ field, ranges and names checked,
// unknown keys refused with the list of known ones) and the writer of reports.
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include <hush/core/json.hpp>
#include <hush/passes/settings.hpp>

namespace hush::passes {

namespace detail {

template <class E, size_t N> std::string nameList(const EnumNames<E, N>& names) {
    std::string list;
    for (const auto& [name, value] : names) list += (list.empty() ? "'" : ", '") + std::string(name) + "'";
    return list;
}

template <class E, size_t N> E enumFromJson(const core::JsonValue& v, const EnumNames<E, N>& names) {
    const std::string text = v.string();
    for (const auto& [name, value] : names)
        if (name == text) return value;
    v.fail("unknown value '" + text + "'; one of " + nameList(names));
}

class SettingsReader {
public:
    explicit SettingsReader(core::JsonObject& object) : o_(object) {}

    void field(std::string_view key, float& out, Range r) { o_.read(key, out, float(r.lo), float(r.hi)); }
    void field(std::string_view key, uint32_t& out, Range r) { o_.read(key, out, uint32_t(r.lo), uint32_t(r.hi)); }
    void field(std::string_view key, int& out, Range r) {
        if (auto v = o_.get(key)) out = int(v->integer(uint32_t(r.lo), uint32_t(r.hi)));
    }
    template <size_t N> void field(std::string_view key, uint32_t& out, Choices<N> choices) {
        auto v = o_.get(key);
        if (!v) return;
        const uint32_t value = v->integer(0, ~0u);
        std::string list;
        for (size_t i = 0; i < N; ++i) {
            if (choices.values[i] == value) {
                out = value;
                return;
            }
            list += (i ? (i + 1 == N ? " or " : ", ") : "") + std::to_string(choices.values[i]);
        }
        v->fail("must be " + list);
    }
    void field(std::string_view key, bool& out) { o_.read(key, out); }
    void field(std::string_view key, std::string& out) { o_.read(key, out); }
    template <class E, size_t N> void field(std::string_view key, E& out, const EnumNames<E, N>& names) {
        if (auto v = o_.get(key)) out = enumFromJson(*v, names);
    }
    template <class E, size_t N>
    void field(std::string_view key, std::vector<E>& out, const EnumNames<E, N>& names, size_t maxItems) {
        auto v = o_.get(key);
        if (!v) return;
        const size_t n = v->arraySize(1, maxItems);
        out.clear();
        for (size_t i = 0; i < n; ++i) out.push_back(enumFromJson((*v)[i], names));
    }
    template <class S> void section(std::string_view key, S& sub) {
        auto v = o_.get(key);
        if (!v) return;
        core::JsonObject object(*v);
        describe(SettingsReader(object), sub);
        object.finish();
    }
    template <class S> void flatten(S& sub) { describe(*this, sub); }

private:
    core::JsonObject& o_;
};

class SettingsWriter {
public:
    explicit SettingsWriter(nlohmann::ordered_json& out) : out_(out) {}
    template <class T> void field(std::string_view key, T& v, Range) { out_[std::string(key)] = v; }
    template <size_t N> void field(std::string_view key, uint32_t& v, Choices<N>) { out_[std::string(key)] = v; }
    void field(std::string_view key, bool& v) { out_[std::string(key)] = v; }
    void field(std::string_view key, std::string& v) { out_[std::string(key)] = v; }
    template <class E, size_t N> void field(std::string_view key, E& v, const EnumNames<E, N>& names) {
        out_[std::string(key)] = nameOf(v, names);
    }
    template <class E, size_t N> void field(std::string_view key, std::vector<E>& v, const EnumNames<E, N>& names, size_t) {
        auto list = nlohmann::ordered_json::array();
        for (const E& e : v) list.push_back(nameOf(e, names));
        out_[std::string(key)] = list;
    }
    template <class S> void section(std::string_view key, S& sub) {
        nlohmann::ordered_json object = nlohmann::ordered_json::object();
        describe(SettingsWriter(object), sub);
        out_[std::string(key)] = object;
    }
    template <class S> void flatten(S& sub) { describe(*this, sub); }

private:
    template <class E, size_t N> static std::string nameOf(E v, const EnumNames<E, N>& names) {
        for (const auto& [name, value] : names)
            if (value == v) return std::string(name);
        return "?";
    }
    nlohmann::ordered_json& out_;
};

} // namespace detail

// Reads the keys of `object` into `settings` (absent keys keep their values) and
// refuses keys that are no field, naming the path and listing the fields.
template <class S> void readSettings(core::JsonObject& object, S& settings) {
    describe(detail::SettingsReader(object), settings);
    object.finish();
}

// Every field of `settings`, as a chain file spells it.
template <class S> nlohmann::ordered_json settingsToJson(S settings) {
    nlohmann::ordered_json out = nlohmann::ordered_json::object();
    describe(detail::SettingsWriter(out), settings);
    return out;
}

} // namespace hush::passes
