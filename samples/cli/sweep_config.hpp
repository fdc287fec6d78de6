#pragma once
// The configurations a sweep runs: each chain with every combination of the values
// its knobs (`--vary <chain>.<setting path>=<values>`) take. A knob's path is the
// chain file's settings path ("svgf.atrous.iterations" is "atrous": {"iterations": }
// of a chain file with "base": "svgf"), so every setting is sweepable and a
// configuration is a chain file: the sweep writes each one, and a user reruns the one
// they pick with `hush denoise --chain <it>`.
#include <string>
#include <string_view>
#include <vector>

#include <hush/core/json.hpp>

namespace hush::cli {

struct Knob {
    std::string chain;               // the chain's name ("svgf", a chain file's name)
    std::vector<std::string> path;   // setting keys below the chain ("atrous", "iterations")
    std::vector<core::Json> values;  // in the order given
    std::string text;                // as given, for errors
};

// "svgf.atrous.iterations=1..5" (whole numbers lo..hi), "bmfr.fit.blockSize=16,32,64",
// "svgf.useTaa=true,false", "eaw.tonemap.op=aces,reinhard". hush::Error names the
// text and what is wrong.
Knob parseKnob(std::string_view text);

struct SweepConfig {
    std::string chain;       // the chain it varies
    std::string name;        // a valid chain name: "<chain>", or "<chain>-<k>" for k >= 1
    std::string label;       // "svgf atrous.iterations=3 useTaa=false" ("svgf (defaults)")
    std::string chainJson;   // the chain file
};

// Every chain (built-in name or chain file) with the cartesian product of its knobs'
// values; a chain without knobs runs once, at its settings. Each configuration is
// parsed as a chain file before any work, so an unknown setting or a value out of
// range fails here, naming the knob. A knob for a chain not listed fails too.
std::vector<SweepConfig> expandConfigs(const std::vector<std::string>& chains, const std::vector<Knob>& knobs);

// The chain file `chainJson` for inputs whose radiance is multiplied by `exposure`:
// its tonemap's exposure divided by it (the top-level "tonemap" of a built-in chain's
// settings, or every "tonemap" node's), so that its display images are comparable
// with the unscaled run's. An exposure sweep's configuration.
std::string withExposure(const std::string& chainJson, double exposure);

} // namespace hush::cli
