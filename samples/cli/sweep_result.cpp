#include "sweep_result.hpp"

#include <algorithm>
#include <cstdio>

#include <hush/core/error.hpp>
#include <hush/core/read_file.hpp>

namespace hush::cli {

const std::vector<SweepMetric>& sweepMetrics() {
    static const std::vector<SweepMetric> metrics{
        {"rmse", "RMSE", false, [](const SweepQuality& q) { return q.rmse; }},
        {"relmse", "relative MSE", false, [](const SweepQuality& q) { return q.relMse; }},
        {"psnr", "PSNR dB", true, [](const SweepQuality& q) { return q.psnr; }},
        {"ssim", "SSIM", true, [](const SweepQuality& q) { return q.ssim; }},
        {"temporal", "temporal error", false, [](const SweepQuality& q) { return q.temporal; }},
    };
    return metrics;
}

const SweepMetric& sweepMetric(const std::string& key) {
    std::string keys;
    for (const auto& m : sweepMetrics()) {
        if (key == m.key) return m;
        keys += (keys.empty() ? "" : ", ") + std::string(m.key);
    }
    throw Error(ErrorKind::InvalidArgument, "unknown quality metric '" + key + "' (known: " + keys + ")");
}

SweepExtent sweepExtent(const std::vector<const SweepPoint*>& points, const SweepMetric& metric, double noisy) {
    SweepExtent e{0.0, noisy, noisy};
    for (const auto* p : points) {
        e.msHi = std::max(e.msHi, p->gpuMs);
        e.lo = std::min(e.lo, metric.of(p->quality));
        e.hi = std::max(e.hi, metric.of(p->quality));
    }
    return e;
}

std::vector<size_t> paretoFront(const std::vector<const SweepPoint*>& points, const SweepMetric& metric) {
    // Quality as "higher is better" so one comparison serves every metric.
    auto quality = [&](size_t i) { return metric.higherIsBetter ? metric.of(points[i]->quality) : -metric.of(points[i]->quality); };
    std::vector<size_t> front;
    for (size_t i = 0; i < points.size(); ++i) {
        bool dominated = false;
        for (size_t j = 0; j < points.size() && !dominated; ++j) {
            if (j == i) continue;
            const bool noWorse = points[j]->gpuMs <= points[i]->gpuMs && quality(j) >= quality(i);
            const bool better = points[j]->gpuMs < points[i]->gpuMs || quality(j) > quality(i);
            // Two identical points: the first stays on the front.
            const bool identical = !better && noWorse;
            dominated = noWorse && (better || (identical && j < i));
        }
        if (!dominated) front.push_back(i);
    }
    std::sort(front.begin(), front.end(), [&](size_t a, size_t b) { return points[a]->gpuMs < points[b]->gpuMs; });
    return front;
}

const SweepPoint* SweepResult::find(const std::string& source, const std::string& config) const {
    for (const auto& p : points)
        if (p.source == source && p.config == config) return &p;
    return nullptr;
}

std::vector<const SweepPoint*> SweepResult::pointsOf(const std::string& source) const {
    std::vector<const SweepPoint*> out;
    for (const auto& p : points)
        if (p.source == source) out.push_back(&p);
    return out;
}

const SweepConfig& SweepResult::config(const std::string& name) const {
    for (const auto& c : configs)
        if (c.name == name) return c;
    throw Error(ErrorKind::InvalidArgument, "no configuration named '" + name + "' in the sweep");
}

namespace {

// A number at full precision (JsonValue::number() is a float, for settings).
double numberOf(const core::JsonValue& value) {
    if (!value.json().is_number()) value.fail("expected a number");
    return value.json().get<double>();
}

core::Json qualityJson(const SweepQuality& q) {
    return {{"rmse", q.rmse}, {"relmse", q.relMse}, {"psnr", q.psnr}, {"ssim", q.ssim},
            {"temporal", q.temporal}, {"ghosting", q.ghosting}, {"flicker", q.flicker},
            {"lag", q.lag}, {"lag_frames", q.lagFrames},
            {"scored_frames", q.scoredFrames}};
}

SweepQuality readQuality(const core::JsonValue& value) {
    core::JsonObject o(value);
    SweepQuality q;
    q.rmse = numberOf(o.require("rmse"));
    q.relMse = numberOf(o.require("relmse"));
    q.psnr = numberOf(o.require("psnr"));
    q.ssim = numberOf(o.require("ssim"));
    q.temporal = numberOf(o.require("temporal"));
    // Absent in the files of earlier versions: not measured.
    if (const auto v = o.get("ghosting")) q.ghosting = numberOf(*v);
    if (const auto v = o.get("flicker")) q.flicker = numberOf(*v);
    if (const auto v = o.get("lag")) q.lag = numberOf(*v);
    if (const auto v = o.get("lag_frames")) q.lagFrames = v->index();
    q.scoredFrames = o.require("scored_frames").index();
    o.finish();
    return q;
}

} // namespace

std::string sweepJson(const SweepResult& r) {
    core::Json j = {{"format", "hush-sweep/1"}, {"complete", r.complete}, {"metric", r.metric},
                    {"environment", r.environment}};
    j["sources"] = core::Json::array();
    for (const auto& s : r.sources)
        j["sources"].push_back({{"key", s.key}, {"description", s.description}, {"width", s.width},
                                {"height", s.height}, {"frames", s.frames}, {"shown_frame", s.shownFrame},
                                {"exposure", s.exposure}, {"family", s.family},
                                {"noisy", qualityJson(s.noisy)}});
    j["configs"] = core::Json::array();
    for (const auto& c : r.configs)
        j["configs"].push_back({{"name", c.name}, {"chain", c.chain}, {"label", c.label},
                                {"chain_file", "configs/" + c.name + ".json"}, {"chain_json", c.chainJson}});
    j["results"] = core::Json::array();
    for (const auto& p : r.points)
        j["results"].push_back({{"source", p.source}, {"config", p.config}, {"gpu_ms_median", p.gpuMs},
                                {"other_processes_cpu_share", p.otherCpuShare}, {"device_bytes", p.deviceBytes},
                                {"non_finite_outputs", p.nonFiniteOutputs}, {"quality", qualityJson(p.quality)}});
    // The fronts, for every metric: what a reader of the file wants first.
    j["fronts"] = core::Json::object();
    for (const auto& s : r.sources) {
        const auto points = r.pointsOf(s.key);
        for (const auto& m : sweepMetrics())
            for (size_t i : paretoFront(points, m)) j["fronts"][s.key][m.key].push_back(points[i]->config);
    }
    return j.dump(1) + "\n";
}

SweepResult readSweepJson(const std::string& path) {
    const core::Json document = core::parseJson(core::readFile(path, "sweep results"), path);
    core::JsonObject root(core::JsonValue(document, path, ""));
    if (root.require("format").string() != "hush-sweep/1")
        root.require("format").fail("not a hush sweep's results (expected \"hush-sweep/1\")");
    SweepResult r;
    r.complete = root.require("complete").boolean();
    r.metric = root.require("metric").string();
    r.environment = root.require("environment").json();
    const auto sources = root.require("sources");
    for (size_t i = 0; i < sources.arraySize(); ++i) {
        core::JsonObject o(sources[i]);
        SweepSource s{.key = o.require("key").string(), .description = o.require("description").string(),
                      .width = o.require("width").index(), .height = o.require("height").index(), .frames = o.require("frames").index()};
        s.shownFrame = o.require("shown_frame").index();
        s.exposure = 1.0, s.family = s.key;   // absent in earlier versions' files
        if (const auto v = o.get("exposure")) s.exposure = numberOf(*v);
        if (const auto v = o.get("family")) s.family = v->string();
        s.noisy = readQuality(o.require("noisy"));
        o.finish();
        r.sources.push_back(s);
    }
    const auto configs = root.require("configs");
    for (size_t i = 0; i < configs.arraySize(); ++i) {
        core::JsonObject o(configs[i]);
        r.configs.push_back({.chain = o.require("chain").string(), .name = o.require("name").string(), .label = o.require("label").string(),
                             .chainJson = o.require("chain_json").string()});
        o.allow("chain_file");
        o.finish();
    }
    const auto results = root.require("results");
    for (size_t i = 0; i < results.arraySize(); ++i) {
        core::JsonObject o(results[i]);
        SweepPoint p{.source = o.require("source").string(), .config = o.require("config").string()};
        p.gpuMs = numberOf(o.require("gpu_ms_median"));
        p.otherCpuShare = numberOf(o.require("other_processes_cpu_share"));
        p.deviceBytes = uint64_t(numberOf(o.require("device_bytes")));
        p.nonFiniteOutputs = uint64_t(numberOf(o.require("non_finite_outputs")));
        p.quality = readQuality(o.require("quality"));
        o.finish();
        r.points.push_back(p);
    }
    root.allow("fronts");
    root.finish();
    return r;
}

std::string sweepCsv(const SweepResult& r) {
    std::string csv = "source,config,label,gpu_ms_median,other_processes_cpu_share,device_bytes,rmse,relmse,psnr,ssim,"
                      "temporal,ghosting,flicker,lag,lag_frames,on_front_" + r.metric + "\n";
    const auto& metric = sweepMetric(r.metric);
    for (const auto& s : r.sources) {
        const auto points = r.pointsOf(s.key);
        const auto front = paretoFront(points, metric);
        for (size_t i = 0; i < points.size(); ++i) {
            const auto& p = *points[i];
            char line[512];
            std::snprintf(line, sizeof line, "%s,%s,\"%s\",%.4f,%.3f,%llu,%.6f,%.6f,%.4f,%.6f,%.6f,%.4f,%.4f,%.0f,%u,%d\n",
                          p.source.c_str(), p.config.c_str(), r.config(p.config).label.c_str(), p.gpuMs,
                          p.otherCpuShare, static_cast<unsigned long long>(p.deviceBytes), p.quality.rmse,
                          p.quality.relMse, p.quality.psnr, p.quality.ssim, p.quality.temporal, p.quality.ghosting,
                          p.quality.flicker, p.quality.lag, p.quality.lagFrames,
                          std::find(front.begin(), front.end(), i) != front.end() ? 1 : 0);
            csv += line;
        }
    }
    return csv;
}

std::string ratioText(double value) {
    if (value < 0.0) return "-";
    char text[32];
    std::snprintf(text, sizeof text, "%.3f", value);
    return text;
}

std::string lagText(const SweepQuality& q) {
    if (q.lag < 0.0) return "-";
    if (q.lag > q.lagFrames) return "> " + std::to_string(q.lagFrames);
    return std::to_string(int(q.lag));
}

std::string sweepTable(const SweepResult& r) {
    const auto& metric = sweepMetric(r.metric);
    std::string out;
    char line[640];
    for (const auto& s : r.sources) {
        std::snprintf(line, sizeof line, "\n%s (front on GPU ms and %s: *)\n| | configuration | settings | GPU ms | MiB | RMSE | "
                      "relMSE | PSNR dB | SSIM | temporal | ghosting | flicker | lag |\n| --- | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n"
                      "| | noisy input | | - | - | %.4f | %.4f | %.2f | %.4f | %.5f | %s | %s | - |\n",
                      s.description.c_str(), metric.title, s.noisy.rmse, s.noisy.relMse, s.noisy.psnr, s.noisy.ssim,
                      s.noisy.temporal, ratioText(s.noisy.ghosting).c_str(), ratioText(s.noisy.flicker).c_str());
        out += line;
        const auto points = r.pointsOf(s.key);
        const auto front = paretoFront(points, metric);
        for (size_t i = 0; i < points.size(); ++i) {
            const auto& p = *points[i];
            const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
            std::snprintf(line, sizeof line, "| %s | %s | %s | %.2f | %.1f | %.4f | %.4f | %.2f | %.4f | %.5f | %s | %s | %s |\n",
                          onFront ? "*" : "", p.config.c_str(), r.config(p.config).label.c_str(), p.gpuMs,
                          double(p.deviceBytes) / (1024.0 * 1024.0), p.quality.rmse, p.quality.relMse, p.quality.psnr,
                          p.quality.ssim, p.quality.temporal, ratioText(p.quality.ghosting).c_str(),
                          ratioText(p.quality.flicker).c_str(), lagText(p.quality).c_str());
            out += line;
        }
    }
    return out;
}

} // namespace hush::cli

namespace hush::cli {

std::string sweepExposureTable(const SweepResult& r) {
    std::vector<double> exposures;
    for (const auto& s : r.sources)
        if (std::find(exposures.begin(), exposures.end(), s.exposure) == exposures.end()) exposures.push_back(s.exposure);
    if (exposures.size() < 2) return "";
    std::sort(exposures.begin(), exposures.end());
    char cell[160];
    std::string out = "\nexposure stability: RMSE with radiance x exposure, over RMSE at exposure 1 "
                      "(the reference and the tonemap scaled alike)\n| source | configuration |";
    for (double e : exposures) std::snprintf(cell, sizeof cell, " x%g |", e), out += cell;
    out += "\n| --- | --- |";
    for (size_t i = 0; i < exposures.size(); ++i) out += " ---: |";
    out += "\n";
    std::vector<std::string> families;
    for (const auto& s : r.sources)
        if (std::find(families.begin(), families.end(), s.family) == families.end()) families.push_back(s.family);
    for (const auto& family : families)
        for (const std::string& config : [&] {
                 std::vector<std::string> names{"noisy"};
                 for (const auto& c : r.configs) names.push_back(c.name);
                 return names;
             }()) {
            auto rmseAt = [&](double e) -> double {
                for (const auto& s : r.sources)
                    if (s.family == family && s.exposure == e) {
                        if (config == "noisy") return s.noisy.rmse;
                        if (const auto* p = r.find(s.key, config)) return p->quality.rmse;
                    }
                return -1.0;
            };
            const double base = rmseAt(1.0);
            out += "| " + family + " | " + (config == "noisy" ? std::string("noisy input") : r.config(config).label) + " |";
            for (double e : exposures) {
                const double v = rmseAt(e);
                if (v < 0.0) std::snprintf(cell, sizeof cell, " - |");
                else if (base > 0.0) std::snprintf(cell, sizeof cell, " %.4f |", v / base);
                else std::snprintf(cell, sizeof cell, " %.4g |", v);
                out += cell;
            }
            out += "\n";
        }
    return out;
}

BudgetChoice chooseWithinBudget(const SweepResult& r, double budgetMs) {
    const auto& metric = sweepMetric(r.metric);
    struct Candidate {
        const SweepConfig* config;
        double worstMs = 0.0, quality = 0.0;
    };
    std::vector<Candidate> candidates;
    for (const auto& c : r.configs) {
        Candidate k{&c};
        size_t measured = 0;
        for (const auto& s : r.sources)
            if (const auto* p = r.find(s.key, c.name)) {
                k.worstMs = std::max(k.worstMs, p->gpuMs);
                k.quality += metric.of(p->quality);
                ++measured;
            }
        if (measured != r.sources.size() || measured == 0) continue;   // an unfinished sweep's partial rows
        k.quality /= double(measured);
        candidates.push_back(k);
    }
    if (candidates.empty()) throw Error(ErrorKind::InvalidArgument, "the sweep holds no configuration measured on every source");
    auto better = [&](const Candidate& a, const Candidate& b) {
        return metric.higherIsBetter ? a.quality > b.quality : a.quality < b.quality;
    };
    const Candidate *best = nullptr, *second = nullptr, *overBudget = nullptr, *fastest = &candidates.front();
    for (const auto& k : candidates) {
        if (k.worstMs < fastest->worstMs) fastest = &k;
        if (k.worstMs > budgetMs) {
            if (!overBudget || better(k, *overBudget)) overBudget = &k;
            continue;
        }
        if (!best || better(k, *best)) second = best, best = &k;
        else if (!second || better(k, *second)) second = &k;
    }
    char text[1024];
    if (!best) {
        std::snprintf(text, sizeof text, "no configuration of the sweep runs within %.3g ms: the fastest, '%s' (%s), "
                      "takes %.3g ms", budgetMs, fastest->config->name.c_str(), fastest->config->label.c_str(),
                      fastest->worstMs);
        throw Error(ErrorKind::InvalidArgument, text);
    }
    std::snprintf(text, sizeof text, "'%s' (%s): the best mean %s (%.4f over %zu source(s)) of the %s within %.3g ms; "
                  "it takes %.3g ms at most", best->config->name.c_str(), best->config->label.c_str(), metric.title,
                  best->quality, r.sources.size(), "configurations", budgetMs, best->worstMs);
    std::string why = text;
    if (second) {
        std::snprintf(text, sizeof text, "; next within the budget: '%s' (%s, %.4f, %.3g ms)",
                      second->config->name.c_str(), second->config->label.c_str(), second->quality, second->worstMs);
        why += text;
    }
    if (overBudget && better(*overBudget, *best)) {
        std::snprintf(text, sizeof text, "; better but over the budget: '%s' (%s, %.4f, %.3g ms)",
                      overBudget->config->name.c_str(), overBudget->config->label.c_str(), overBudget->quality,
                      overBudget->worstMs);
        why += text;
    }
    return {best->config->name, why};
}

} // namespace hush::cli
