// One description per settings struct (passes/settings.hpp): every field of every
// settings struct is described (the struct has as many fields as describe() visits),
// and every described field is read from a chain file (a value different from the
// default, given in a chain file's settings, changes the chain's settings).
#include <catch2/catch.hpp>

#include <algorithm>

#include <hush/passes/bmfr/chain.hpp>
#include <hush/passes/chain_file.hpp>
#include <hush/passes/eaw/chain.hpp>
#include <hush/passes/mara/chain.hpp>
#include <hush/passes/rdae/chain.hpp>
#include <hush/passes/settings_json.hpp>
#include <hush/passes/svgf/chain.hpp>

using namespace hush;
using passes::Range;
using OrderedJson = nlohmann::ordered_json;

namespace {

// Counts the fields describe() visits at one level (a section or a flattened struct
// is one field of the struct that holds it).
struct FieldCounter {
    size_t count = 0;
    template <class... A> void field(std::string_view, A&&...) { ++count; }
    template <class S> void section(std::string_view, S&) { ++count; }
    template <class S> void flatten(S&) { ++count; }
};

template <class S> size_t describedFields() {
    S s{};
    FieldCounter counter;
    describe(counter, s);
    return counter.count;
}

// Writes, for every described field, a JSON value that is accepted and differs from
// the field's default.
class Perturber {
public:
    explicit Perturber(OrderedJson& out) : out_(out) {}
    void field(std::string_view key, float& v, Range r) { out_[std::string(key)] = other(double(v), r); }
    void field(std::string_view key, uint32_t& v, Range r) { out_[std::string(key)] = uint32_t(other(double(v), r)); }
    void field(std::string_view key, int& v, Range r) { out_[std::string(key)] = int(other(double(v), r)); }
    template <size_t N> void field(std::string_view key, uint32_t& v, passes::Choices<N> c) {
        out_[std::string(key)] = c.values[0] == v ? c.values[1] : c.values[0];
    }
    void field(std::string_view key, bool& v) { out_[std::string(key)] = !v; }
    void field(std::string_view key, std::string& v) { out_[std::string(key)] = v + "-other"; }
    template <class E, size_t N> void field(std::string_view key, E& v, const passes::EnumNames<E, N>& names) {
        out_[std::string(key)] = std::string(names[0].second == v ? names[1].first : names[0].first);
    }
    template <class E, size_t N>
    void field(std::string_view key, std::vector<E>& v, const passes::EnumNames<E, N>& names, size_t) {
        const bool firstOnly = v.size() == 1 && v[0] == names[0].second;
        out_[std::string(key)] = OrderedJson::array({std::string(names[firstOnly ? 1 : 0].first)});
    }
    template <class S> void section(std::string_view key, S& sub) {
        OrderedJson object = OrderedJson::object();
        describe(Perturber(object), sub);
        out_[std::string(key)] = object;
    }
    template <class S> void flatten(S& sub) { describe(*this, sub); }

private:
    static double other(double value, Range r) { return value == r.hi ? r.lo : r.hi; }
    OrderedJson& out_;
};

template <class S> OrderedJson perturbed() {
    OrderedJson out = OrderedJson::object();
    S s{};
    describe(Perturber(out), s);
    return out;
}

// Every leaf of `changed` differs from the same leaf of `defaults`.
void requireEveryLeafChanged(const OrderedJson& defaults, const OrderedJson& changed, const std::string& path) {
    for (auto it = defaults.begin(); it != defaults.end(); ++it) {
        const std::string at = path + "." + it.key();
        INFO(at);
        REQUIRE(changed.contains(it.key()));
        if (it->is_object()) requireEveryLeafChanged(*it, changed[it.key()], at);
        else CHECK(*it != changed[it.key()]);
    }
}

template <class Chain, class S> void requireEverySettingReachable(const std::string& base) {
    const OrderedJson settings = perturbed<S>();
    const OrderedJson file = {{"base", base}, {"settings", settings}};
    const auto chain = passes::parseChainJson(file.dump(), base + ".json");
    const auto* typed = dynamic_cast<const Chain*>(&passes::unwrapChain(*chain));
    REQUIRE(typed);
    requireEveryLeafChanged(passes::settingsToJson(S{}), passes::settingsToJson(typed->settings()), base);
}

} // namespace

TEST_CASE("settings: every field of every settings struct is described", "[settings]") {
    CHECK(passes::fieldCount<passes::SanitizeSettings>() == describedFields<passes::SanitizeSettings>());
    CHECK(passes::fieldCount<passes::DemodulateSettings>() == describedFields<passes::DemodulateSettings>());
    CHECK(passes::fieldCount<passes::ReprojectSettings>() == describedFields<passes::ReprojectSettings>());
    CHECK(passes::fieldCount<passes::TonemapSettings>() == describedFields<passes::TonemapSettings>());
    CHECK(passes::fieldCount<passes::TaaSettings>() == describedFields<passes::TaaSettings>());
    CHECK(passes::fieldCount<passes::SvgfTemporalSettings>() == describedFields<passes::SvgfTemporalSettings>());
    CHECK(passes::fieldCount<passes::SvgfVarianceSettings>() == describedFields<passes::SvgfVarianceSettings>());
    CHECK(passes::fieldCount<passes::SvgfAtrousSettings>() == describedFields<passes::SvgfAtrousSettings>());
    CHECK(passes::fieldCount<passes::EawSettings>() == describedFields<passes::EawSettings>());
    CHECK(passes::fieldCount<passes::BmfrAccumulateSettings>() == describedFields<passes::BmfrAccumulateSettings>());
    CHECK(passes::fieldCount<passes::BmfrFitSettings>() == describedFields<passes::BmfrFitSettings>());
    CHECK(passes::fieldCount<passes::ChainFrontSettings>() == describedFields<passes::ChainFrontSettings>());
    CHECK(passes::fieldCount<passes::ChainBackSettings>() == describedFields<passes::ChainBackSettings>());
    CHECK(passes::fieldCount<passes::SvgfSettings>() == describedFields<passes::SvgfSettings>());
    CHECK(passes::fieldCount<passes::EawChainSettings>() == describedFields<passes::EawChainSettings>());
    CHECK(passes::fieldCount<passes::BmfrSettings>() == describedFields<passes::BmfrSettings>());
    CHECK(passes::fieldCount<passes::MaraTemporalSettings>() == describedFields<passes::MaraTemporalSettings>());
    CHECK(passes::fieldCount<passes::MaraSparseBilateralSettings>() ==
          describedFields<passes::MaraSparseBilateralSettings>());
    CHECK(passes::fieldCount<passes::MaraDisocclusionSettings>() == describedFields<passes::MaraDisocclusionSettings>());
    CHECK(passes::fieldCount<passes::MaraGlossyBilateralSettings>() ==
          describedFields<passes::MaraGlossyBilateralSettings>());
    CHECK(passes::fieldCount<passes::MaraSettings>() == describedFields<passes::MaraSettings>());
    CHECK(passes::fieldCount<passes::RdaeSettings>() == describedFields<passes::RdaeSettings>());
}

TEST_CASE("settings: the field counter sees a field that describe() leaves out", "[settings]") {
    struct Two {
        float a = 0;
        float b = 0;
    };
    CHECK(passes::fieldCount<Two>() == 2);
    CHECK(passes::fieldCount<passes::BmfrFitSettings>() == 6);   // blockSize, epsilon, features, offsetBlocks, nonNegative, format
}

TEST_CASE("settings: every field of every built-in chain is set from a chain file", "[settings][chain-file]") {
    requireEverySettingReachable<passes::SvgfChain, passes::SvgfSettings>("svgf");
    requireEverySettingReachable<passes::EawChain, passes::EawChainSettings>("eaw");
    requireEverySettingReachable<passes::BmfrChain, passes::BmfrSettings>("bmfr");
    requireEverySettingReachable<passes::MaraChain, passes::MaraSettings>("mara");
    requireEverySettingReachable<passes::RdaeChain, passes::RdaeSettings>("rdae");
}

TEST_CASE("settings: the JSON writer spells every field as a chain file does, and reads back", "[settings]") {
    passes::SvgfSettings s;
    s.atrous.iterations = 3;
    s.back.taa.historyFilter = passes::TaaHistoryFilter::Bilinear;
    const OrderedJson json = passes::settingsToJson(s);
    CHECK(json["atrous"]["iterations"] == 3);
    CHECK(json["taa"]["historyFilter"] == "bilinear");
    CHECK(json["useTaa"] == true);
    const auto chain = passes::parseChainJson(OrderedJson{{"base", "svgf"}, {"settings", json}}.dump(), "x.json");
    const auto& back = dynamic_cast<const passes::SvgfChain&>(passes::unwrapChain(*chain)).settings();
    CHECK(passes::settingsToJson(back) == json);
}
