// hush sweep's pieces without a GPU: the Pareto front, knobs and configurations;
// and (run by tests/cli/sweep.sh on a sweep it made) the checks of a sweep's output.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <hush/core/error.hpp>

#include "plot_labels.hpp"
#include "sweep_config.hpp"
#include "sweep_result.hpp"

using namespace hush;
using namespace hush::cli;

namespace {

SweepPoint point(const std::string& config, double ms, double ssim) {
    SweepPoint p{.source = "s", .config = config, .gpuMs = ms};
    p.quality.ssim = ssim;
    p.quality.rmse = 1.0 - ssim;
    return p;
}

// True when some point is at least as fast and as good as points[i], and better in one.
bool dominated(const std::vector<const SweepPoint*>& points, size_t i, const SweepMetric& m) {
    auto q = [&](size_t k) { return m.higherIsBetter ? m.of(points[k]->quality) : -m.of(points[k]->quality); };
    for (size_t j = 0; j < points.size(); ++j)
        if (j != i && points[j]->gpuMs <= points[i]->gpuMs && q(j) >= q(i) &&
            (points[j]->gpuMs < points[i]->gpuMs || q(j) > q(i)))
            return true;
    return false;
}

} // namespace

TEST_CASE("the pareto front holds exactly the points no other beats on time and quality", "[sweep]") {
    const std::vector<SweepPoint> all{point("a", 1.0, 0.80), point("b", 2.0, 0.90), point("c", 3.0, 0.85),
                                      point("d", 0.5, 0.70), point("e", 4.0, 0.95), point("f", 2.0, 0.90)};
    std::vector<const SweepPoint*> points;
    for (const auto& p : all) points.push_back(&p);
    for (const auto* key : {"ssim", "rmse"}) {
        const auto front = paretoFront(points, sweepMetric(key));
        std::vector<std::string> names;
        for (size_t i : front) names.push_back(points[i]->config);
        // c is beaten by b; f ties b exactly and only the first of a tie stays.
        CHECK(names == std::vector<std::string>{"d", "a", "b", "e"});
    }
    CHECK_THROWS_WITH(sweepMetric("mse"), Catch::Contains("known: rmse, relmse, psnr, ssim, temporal"));
}

TEST_CASE("knobs expand into one chain file per combination of their values", "[sweep]") {
    const auto configs = expandConfigs({"svgf", "eaw"}, {parseKnob("svgf.atrous.iterations=1..3"),
                                                        parseKnob("svgf.useTaa=true,false")});
    REQUIRE(configs.size() == 7);   // 3 x 2 for svgf, eaw once
    CHECK(configs[0].name == "svgf");
    CHECK(configs[0].label == "svgf atrous.iterations=1 useTaa=true");
    CHECK(configs[5].label == "svgf atrous.iterations=3 useTaa=false");
    CHECK(configs[5].name == "svgf-5");
    CHECK(configs[6].label == "eaw (its settings)");
    CHECK(configs[5].chainJson.find("\"iterations\": 3") != std::string::npos);

    CHECK_THROWS_WITH(expandConfigs({"svgf"}, {parseKnob("bmfr.fit.blockSize=16")}),
                      Catch::Contains("no chain named 'bmfr' among --chain"));
    CHECK_THROWS_WITH(expandConfigs({"svgf"}, {parseKnob("svgf.atrous.iterashuns=2")}),
                      Catch::Contains("unknown field 'iterashuns'"));
    CHECK_THROWS_WITH(expandConfigs({"bmfr"}, {parseKnob("bmfr.fit.blockSize=16,48")}),
                      Catch::Contains("must be 0, 8, 16, 32 or 64"));
    CHECK_THROWS_WITH(parseKnob("svgf.atrous.iterations"), Catch::Contains("expected <chain>.<setting>=<values>"));
    CHECK_THROWS_WITH(parseKnob("svgf=1"), Catch::Contains("expected <chain>.<setting>"));
}

TEST_CASE("plot labels never cover each other or a point; the front's always show", "[sweep]") {
    // Twelve configurations within a few pixels of each other (a knob that changes
    // nothing measurable), two front points near them, one alone.
    std::vector<PlotLabel> labels;
    std::vector<PlotBox> dots;
    auto add = [&](double x, double y, bool front) {
        labels.push_back({x, y, 40.0, 12.0, front});
        const double r = front ? 8.5 : 4.0;
        dots.push_back({x - r, y - r, x + r, y + r});
    };
    for (int i = 0; i < 12; ++i) add(200.0 + (i % 4), 200.0 + (i / 4), false);
    add(205.0, 235.0, true);
    add(150.0, 260.0, true);
    add(600.0, 100.0, true);
    const PlotBox area{80, 50, 770, 460};
    const auto boxes = placeLabels(labels, dots, area);
    REQUIRE(boxes.size() == labels.size());
    size_t shown = 0;
    for (size_t i = 0; i < boxes.size(); ++i) {
        if (labels[i].required) REQUIRE(boxes[i].has_value());
        if (!boxes[i]) continue;
        ++shown;
        CHECK(boxes[i]->inside(area));
        // Beside its own point: the nearest edge within a label's size of it.
        const double dx = std::max({boxes[i]->x0 - labels[i].pointX, labels[i].pointX - boxes[i]->x1, 0.0});
        const double dy = std::max({boxes[i]->y0 - labels[i].pointY, labels[i].pointY - boxes[i]->y1, 0.0});
        CHECK(dx <= 10.0);
        CHECK(dy <= 10.0);
        for (size_t j = 0; j < i; ++j)
            if (boxes[j]) CHECK(boxes[i]->overlap(*boxes[j]) == 0.0);
        for (const auto& dot : dots) CHECK(boxes[i]->overlap(dot) == 0.0);
    }
    // The cluster cannot hold twelve labels apart: some are left out, some shown.
    CHECK(shown > 3);
    CHECK(shown < labels.size());
    // A label at the plot's right edge goes to the left of its point.
    const auto edge = placeLabels({{765.0, 300.0, 40.0, 12.0, true}}, {}, area);
    REQUIRE(edge[0].has_value());
    CHECK(edge[0]->x1 < 765.0);
}

TEST_CASE("the text plot puts better configurations higher and faster ones further left, the front in capitals",
          "[sweep]") {
    SweepResult r;
    r.metric = "ssim";
    SweepSource source{.key = "s", .description = "scene s"};
    source.noisy.ssim = 0.5;
    r.sources.push_back(source);
    for (const char* name : {"a", "b", "c"}) r.configs.push_back({.chain = "eaw", .name = name, .label = name});
    r.points = {point("a", 1.0, 0.9), point("b", 4.0, 0.7), point("c", 4.0, 0.95)};
    const auto plot = sweepTextPlot(r, r.sources[0], 40, 11);
    std::vector<std::string> lines;
    std::istringstream in(plot);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    auto where = [&](char glyph) {
        for (size_t y = 0; y < lines.size(); ++y)
            if (lines[y].size() > 12 && lines[y].find(glyph, 12) != std::string::npos && lines[y].find('|') == 11)
                return std::pair<size_t, size_t>{y, lines[y].find(glyph, 12)};
        FAIL("no '" << glyph << "' in the plot:\n" << plot);
        return std::pair<size_t, size_t>{0, 0};
    };
    const auto a = where('A'), b = where('b'), c = where('C');   // b is beaten by c
    CHECK(c.first < a.first);    // higher SSIM, higher up
    CHECK(a.first < b.first);
    CHECK(a.second < c.second);  // faster, further left
    CHECK(b.second == c.second);
    CHECK(plot.find("  A a (front)") != std::string::npos);
    CHECK(plot.find("  b b\n") != std::string::npos);
    CHECK(plot.find("----- noisy input\n") != std::string::npos);
    CHECK(plot.find("4 ms") != std::string::npos);
    // RMSE: lower is better and still up.
    r.metric = "rmse";
    const auto rmse = sweepTextPlot(r, r.sources[0], 40, 11);
    CHECK(rmse.find("RMSE (better is up)") != std::string::npos);
    CHECK(rmse.find('C') < rmse.find('A'));
}

// Hidden: tests/cli/sweep.sh runs it on the folder it swept (HUSH_SWEEP_OUTPUT).
TEST_CASE("a sweep's output: complete results, non-dominated fronts, plots and a report whose images exist",
          "[.sweep-output]") {
    const char* folderText = std::getenv("HUSH_SWEEP_OUTPUT");
    REQUIRE(folderText != nullptr);
    const std::filesystem::path folder(folderText);
    const auto result = readSweepJson((folder / "sweep.json").string());
    CHECK(result.complete);
    REQUIRE(!result.sources.empty());
    CHECK(result.points.size() == result.sources.size() * result.configs.size());
    for (const auto& source : result.sources) {
        const auto points = result.pointsOf(source.key);
        for (const auto& metric : sweepMetrics()) {
            const auto front = paretoFront(points, metric);
            REQUIRE(!front.empty());
            for (size_t i = 0; i < points.size(); ++i) {
                const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
                if (onFront) CHECK_FALSE(dominated(points, i, metric));
            }
        }
        for (const auto* p : points) {
            CHECK(p->gpuMs > 0.0);
            CHECK(p->deviceBytes > 0);
            CHECK(p->quality.scoredFrames > 0);
            // sweep.sh asks for reference pairs: both temporal artefacts are measured,
            // and SVGF's history makes it steadier than the 1-spp input.
            CHECK(p->quality.ghosting > 0.0);
            CHECK(p->quality.flicker > 0.0);
            if (result.config(p->config).chain == "svgf") CHECK(p->quality.flicker < source.noisy.flicker);
            // And --lag: EAW keeps no history, so it follows a lighting step at once.
            CHECK(p->quality.lag >= 0.0);
            CHECK(p->quality.lagFrames > 0);
            if (result.config(p->config).chain == "eaw") CHECK(p->quality.lag == 0.0);
        }
        const SweepReportFiles files;
        CHECK(std::filesystem::file_size(folder / files.plotPng(source)) > 1000);
        CHECK(std::filesystem::file_size(folder / files.plotSvg(source)) > 1000);
    }
    std::ifstream html(folder / "report.html");
    std::stringstream text;
    text << html.rdbuf();
    const std::string page = text.str();
    const std::regex imageSource("src=\"([^\"]+)\"");
    size_t images = 0;
    for (auto it = std::sregex_iterator(page.begin(), page.end(), imageSource); it != std::sregex_iterator(); ++it, ++images)
        CHECK(std::filesystem::exists(folder / (*it)[1].str()));
    // Per source: its plot, noisy, reference and at least one front configuration.
    CHECK(images >= 4 * result.sources.size());
    // Every configuration on any metric's front is shown in a crop.
    const SweepReportFiles files;
    for (const auto& source : result.sources) {
        const auto points = result.pointsOf(source.key);
        for (const auto& metric : sweepMetrics())
            for (size_t i : paretoFront(points, metric))
                CHECK(page.find("src=\"" + files.image(source, points[i]->config) + "\"") != std::string::npos);
    }
}

TEST_CASE("budget mode picks the best quality within the budget on every source, and says why", "[sweep]") {
    SweepResult r;
    r.metric = "ssim";
    r.sources = {{.key = "s"}, {.key = "t"}};
    r.configs = {{.chain = "eaw", .name = "eaw", .label = "eaw"}, {.chain = "svgf", .name = "svgf", .label = "svgf"},
                 {.chain = "svgf", .name = "svgf-1", .label = "svgf fast"}};
    auto add = [&](const std::string& source, const std::string& config, double ms, double ssim) {
        r.points.push_back(point(config, ms, ssim));
        r.points.back().source = source;
    };
    add("s", "eaw", 1.0, 0.80), add("t", "eaw", 1.2, 0.82);
    add("s", "svgf", 3.0, 0.95), add("t", "svgf", 5.0, 0.93);       // 5 ms on t: over a 4 ms budget
    add("s", "svgf-1", 2.0, 0.90), add("t", "svgf-1", 2.5, 0.88);
    const auto within4 = chooseWithinBudget(r, 4.0);
    CHECK(within4.config == "svgf-1");
    CHECK_THAT(within4.why, Catch::Contains("next within the budget: 'eaw'") &&
                                Catch::Contains("better but over the budget: 'svgf'"));
    CHECK(chooseWithinBudget(r, 10.0).config == "svgf");
    CHECK_THROWS_WITH(chooseWithinBudget(r, 0.5), Catch::Contains("the fastest, 'eaw' (eaw), takes 1.2 ms"));
}
