#include "sweep_config.hpp"

#include <algorithm>
#include <cmath>

#include <hush/core/arguments.hpp>
#include <hush/core/error.hpp>
#include <hush/core/read_file.hpp>
#include <hush/passes/chain_file.hpp>

namespace hush::cli {
namespace {

[[noreturn]] void badKnob(std::string_view text, const std::string& what) {
    throw Error(ErrorKind::InvalidArgument, "--vary '" + std::string(text) + "': " + what);
}

// A value as JSON: a number, true/false, else a string (an enum's name).
core::Json knobValue(const std::string& item) {
    if (item == "true") return true;
    if (item == "false") return false;
    try {
        size_t used = 0;
        const double number = std::stod(item, &used);
        if (used != item.size()) return item;
        // Whole numbers stay integers, as integer settings read them.
        if (number == double(int64_t(number)) && std::abs(number) < 1e15) return int64_t(number);
        return number;
    } catch (const std::exception&) {
    }
    return item;
}

std::vector<core::Json> knobValues(std::string_view text, const std::string& list) {
    if (const auto dots = list.find(".."); dots != std::string::npos) {
        const uint32_t lo = core::parseCount(list.substr(0, dots), "--vary range start", 0);
        const uint32_t hi = core::parseCount(list.substr(dots + 2), "--vary range end", lo);
        if (hi - lo >= 256) badKnob(text, "a range of more than 256 values");
        std::vector<core::Json> values;
        for (uint32_t v = lo; v <= hi; ++v) values.push_back(v);
        return values;
    }
    std::vector<core::Json> values;
    for (const auto& item : core::splitList(list)) values.push_back(knobValue(item));
    if (values.empty()) badKnob(text, "no values after '='");
    return values;
}

// The chain file of `nameOrPath` as JSON: a built-in name becomes {"base": name}.
core::Json chainDocument(const std::string& nameOrPath) {
    for (const auto& builtin : passes::builtinChainNames())
        if (builtin == nameOrPath) return core::Json{{"base", nameOrPath}};
    return core::parseJson(core::readFile(nameOrPath, "chain file"), nameOrPath);
}

// Where a knob's path lands in a chain document: under "settings" for a built-in
// chain with other settings; under the node's "settings" (path[0] is the node id)
// for a chain written node by node.
core::Json& settingsRoot(core::Json& document, const Knob& knob, std::vector<std::string>& path) {
    path = knob.path;
    if (!document.contains("nodes")) return document["settings"];
    if (document["nodes"].is_array())
        for (auto& node : document["nodes"])
            if (node.is_object() && node.value("id", "") == path.front()) {
                path.erase(path.begin());
                if (path.empty()) badKnob(knob.text, "names node '" + node.value("id", "") + "' but none of its settings");
                return node["settings"];
            }
    badKnob(knob.text, "chain '" + knob.chain + "' has no node '" + path.front() + "'");
}

void setKnob(core::Json& document, const Knob& knob, const core::Json& value) {
    std::vector<std::string> path;
    core::Json* target = &settingsRoot(document, knob, path);
    for (const auto& key : path) {
        if (!target->is_null() && !target->is_object()) badKnob(knob.text, "'" + key + "' is below a plain value");
        target = &(*target)[key];
    }
    *target = value;
}

std::string valueText(const core::Json& value) {
    return value.is_string() ? value.get<std::string>() : value.dump();
}

} // namespace

Knob parseKnob(std::string_view text) {
    const auto equals = text.find('=');
    if (equals == std::string_view::npos) badKnob(text, "expected <chain>.<setting>=<values>, e.g. svgf.atrous.iterations=1..5");
    Knob knob{.text = std::string(text)};
    const auto keys = core::splitList(text.substr(0, equals), '.');
    if (keys.size() < 2) badKnob(text, "expected <chain>.<setting>, e.g. svgf.atrous.iterations");
    knob.chain = keys.front();
    knob.path.assign(keys.begin() + 1, keys.end());
    knob.values = knobValues(text, std::string(text.substr(equals + 1)));
    return knob;
}

std::vector<SweepConfig> expandConfigs(const std::vector<std::string>& chains, const std::vector<Knob>& knobs) {
    std::vector<std::string> names;
    for (const auto& chain : chains) names.push_back(passes::makeChain(chain)->name());
    for (const auto& knob : knobs)
        if (std::find(names.begin(), names.end(), knob.chain) == names.end())
            badKnob(knob.text, "no chain named '" + knob.chain + "' among --chain");

    std::vector<SweepConfig> configs;
    for (size_t c = 0; c < chains.size(); ++c) {
        std::vector<const Knob*> own;
        for (const auto& knob : knobs)
            if (knob.chain == names[c]) own.push_back(&knob);
        std::vector<size_t> digit(own.size(), 0);   // an odometer over the knobs' values
        for (size_t k = 0;; ++k) {
            core::Json document = chainDocument(chains[c]);
            SweepConfig config{.chain = names[c], .name = k ? names[c] + "-" + std::to_string(k) : names[c]};
            config.label = names[c];
            for (size_t i = 0; i < own.size(); ++i) {
                setKnob(document, *own[i], own[i]->values[digit[i]]);
                std::string key;
                for (const auto& part : own[i]->path) key += (key.empty() ? "" : ".") + part;
                config.label += " " + key + "=" + valueText(own[i]->values[digit[i]]);
            }
            if (own.empty()) config.label += " (its settings)";
            document["name"] = config.name;
            config.chainJson = document.dump(1);
            try {
                passes::parseChainJson(config.chainJson, "--vary (" + config.label + ")");
            } catch (const Error& e) {
                throw Error(ErrorKind::InvalidArgument, e.what());
            }
            configs.push_back(std::move(config));
            size_t i = 0;
            while (i < own.size() && ++digit[i] == own[i]->values.size()) digit[i++] = 0;
            if (i == own.size()) break;
        }
    }
    return configs;
}

std::string withExposure(const std::string& chainJson, double exposure) {
    core::Json document = core::parseJson(chainJson, "a sweep configuration");
    auto divide = [&](core::Json& settings) {
        const double current = settings.is_object() && settings.contains("exposure") ? settings["exposure"].get<double>() : 1.0;
        settings["exposure"] = current / exposure;
    };
    if (document.contains("nodes")) {
        for (auto& node : document["nodes"])
            if (node.value("node", "") == "tonemap") divide(node["settings"]);
    } else {
        divide(document["settings"]["tonemap"]);
    }
    return document.dump(1);
}

} // namespace hush::cli
