// The denoise job's report: tables for stdout and report.json.
#include <cmath>
#include <cstdio>
#include <limits>

#include <nlohmann/json.hpp>

#include <hush/tracer/frame_io.hpp>

#include "denoise_job.hpp"

namespace hush::cli {

namespace {

double mean(const std::vector<double>& v) {
    double sum = 0.0;
    for (double x : v) sum += x;
    return v.empty() ? 0.0 : sum / double(v.size());
}

template <class F> double meanOf(const std::vector<ScoredFrame>& frames, F field) {
    std::vector<double> values;
    for (const auto& s : frames) values.push_back(field(s.metrics));
    return mean(values);
}

// PSNR averaged in dB over frames; infinite when any frame matched exactly.
double meanPsnr(const std::vector<ScoredFrame>& frames) {
    for (const auto& s : frames)
        if (!std::isfinite(s.metrics.psnr)) return std::numeric_limits<double>::infinity();
    return meanOf(frames, [](const passes::ImageMetrics& m) { return m.psnr; });
}

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

} // namespace

std::string formatReportTables(const DenoiseJobResult& r) {
    std::string out;
    char line[256];
    std::snprintf(line, sizeof line, "\nquality: %ux%u, %u frames; metrics on tonemapped images, mean over the %zu "
                  "frame(s) with a reference; temporal error: mean over %u consecutive pairs\n",
                  r.width, r.height, r.frames, r.chains.empty() ? size_t(0) : r.chains[0].scored.size(),
                  r.frames > 0 ? r.frames - 1 : 0);
    out += line;
    out += "| chain | RMSE | relMSE | PSNR dB | SSIM | temporal error | GPU ms/frame (median) |\n";
    out += "| --- | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    for (const auto& c : r.chains) {
        const bool scored = !c.scored.empty();
        auto field = [&](double v, const char* format) {
            if (!scored) return std::string("-");
            char b[32];
            std::snprintf(b, sizeof b, format, v);
            return std::string(b);
        };
        std::snprintf(line, sizeof line, "| %s | %s | %s | %s | %s | %.5f | %s |\n", c.name.c_str(),
                      field(meanOf(c.scored, [](auto& m) { return m.rmse; }), "%.5f").c_str(),
                      field(meanOf(c.scored, [](auto& m) { return m.relMse; }), "%.5f").c_str(),
                      field(meanPsnr(c.scored), "%.2f").c_str(),
                      field(meanOf(c.scored, [](auto& m) { return m.ssim; }), "%.4f").c_str(), mean(c.temporalError),
                      c.frameMs.empty() ? "-" : std::to_string(median(c.frameMs)).substr(0, 6).c_str());
        out += line;
    }
    for (const auto& c : r.chains) {
        if (c.passOrder.empty()) continue;
        const double total = median(c.frameMs);
        std::snprintf(line, sizeof line, "\n%s: GPU ms per pass (median of %zu frames; total %.3f ms, barriers "
                      "included)\n| pass | ms | share |\n| --- | ---: | ---: |\n",
                      c.name.c_str(), c.frameMs.size(), total);
        out += line;
        for (const auto& p : c.passOrder) {
            auto it = c.passMs.find(p);
            const double ms = it == c.passMs.end() ? 0.0 : median(it->second);
            std::snprintf(line, sizeof line, "| %s | %.3f | %.1f %% |\n", p.c_str(), ms,
                          total > 0.0 ? 100.0 * ms / total : 0.0);
            out += line;
        }
    }
    return out;
}

std::string reportJson(const DenoiseJobResult& r, const std::string& adapterName) {
    nlohmann::json j;
    j["version"] = 1;
    j["adapter"] = adapterName;
    j["width"] = r.width;
    j["height"] = r.height;
    j["frames"] = r.frames;
    j["seconds"] = r.seconds;
    j["metricsOn"] = "tonemapped display values (ACES fit), RGB";
    j["warnings"] = r.warnings;
    for (const auto& c : r.chains) {
        nlohmann::json cj;
        cj["name"] = c.name;
        cj["sanitizedPixels"] = c.sanitizedPixels;
        cj["nonFiniteOutputs"] = c.nonFiniteOutputs;
        cj["nonFiniteFrames"] = c.nonFiniteFrames;
        cj["temporalErrorMean"] = mean(c.temporalError);
        cj["temporalError"] = c.temporalError;
        // Per scored frame (temporal_artifacts.hpp): recently disoccluded over elsewhere
        // RMSE; per pair of consecutive references, temporal error over theirs.
        cj["ghosting"] = c.ghosting;
        cj["flicker"] = c.flicker;
        if (!c.scored.empty()) {
            cj["quality"] = {{"rmse", meanOf(c.scored, [](auto& m) { return m.rmse; })},
                             {"relMse", meanOf(c.scored, [](auto& m) { return m.relMse; })},
                             {"psnr", number(meanPsnr(c.scored))},
                             {"ssim", meanOf(c.scored, [](auto& m) { return m.ssim; })}};
            for (const auto& s : c.scored)
                cj["scoredFrames"].push_back({{"frame", s.frame},
                                              {"rmse", s.metrics.rmse},
                                              {"relMse", s.metrics.relMse},
                                              {"psnr", number(s.metrics.psnr)},
                                              {"ssim", s.metrics.ssim}});
        }
        if (!c.passOrder.empty()) {
            cj["gpuMsPerFrameMedian"] = median(c.frameMs);
            for (const auto& p : c.passOrder) {
                auto it = c.passMs.find(p);
                cj["passes"].push_back({{"name", p}, {"msMedian", it == c.passMs.end() ? 0.0 : median(it->second)}});
            }
            cj["memory"] = {{"transientAliasedBytes", c.transientBytes},
                            {"transientUnaliasedBytes", c.transientUnaliasedBytes},
                            {"historyBytes", c.historyBytes}};
        }
        j["chains"].push_back(cj);
    }
    return j.dump(2) + "\n";
}

} // namespace hush::cli
