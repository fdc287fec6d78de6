#pragma once
// Settings structs from JSON objects: every field of every settings struct has the
// name it has in C++ (docs/passes/chain-files.md lists them).
#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/svgf/chain.hpp>

#include "chain_file/json_reader.hpp"

namespace hush::passes::chain_file {

void readSettings(ObjectReader& r, SanitizeSettings& s);
void readSettings(ObjectReader& r, DemodulateSettings& s);
void readSettings(ObjectReader& r, ReprojectSettings& s);
void readSettings(ObjectReader& r, SvgfTemporalSettings& s);
void readSettings(ObjectReader& r, SvgfVarianceSettings& s);
void readSettings(ObjectReader& r, SvgfAtrousSettings& s);
void readSettings(ObjectReader& r, EawSettings& s);
void readSettings(ObjectReader& r, TonemapSettings& s);
void readSettings(ObjectReader& r, TaaSettings& s);
void readSettings(ObjectReader& r, BmfrAccumulateSettings& s);
// "features" is an array of names: "one", "normalX" .. "positionZ2", "albedoR", ...
void readSettings(ObjectReader& r, BmfrFitSettings& s);
// A whole chain's settings: one object per stage ("atrous": {...}) plus its flags.
void readSettings(ObjectReader& r, SvgfSettings& s);
void readSettings(ObjectReader& r, EawChainSettings& s);
void readSettings(ObjectReader& r, BmfrSettings& s);

// Reads `key` (an object) of `parent` into `s`, when present.
template <class S> void readSection(ObjectReader& parent, std::string_view key, S& s) {
    if (const Json* v = parent.child(key)) {
        ObjectReader r(*v, parent.source(), parent.path(key));
        readSettings(r, s);
        r.finish();
    }
}

} // namespace hush::passes::chain_file
