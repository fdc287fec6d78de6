// report.html: per frame source the plot, the table (front rows marked, and the
// metrics whose front each configuration is on) and side-by-side crops of the last
// scored frame: noisy | each configuration on the front of any metric | reference,
// each labelled with its fronts. The crops are the frame's own PNGs shown through a CSS
// window (the centre, magnified 2x with square pixels), so the page needs nothing
// but the files the sweep wrote.
#include <algorithm>
#include <cstdio>

#include "sweep_result.hpp"

namespace hush::cli {
namespace {

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else if (c == '"') out += "&quot;";
        else out += c;
    }
    return out;
}

// A window of at most 96x96 source pixels around the centre, shown at 2x.
std::string crop(const SweepSource& s, const std::string& src, const std::string& caption) {
    const uint32_t w = std::min(s.width, 96u), h = std::min(s.height, 96u);
    char style[256];
    std::snprintf(style, sizeof style, "<figure><div class=\"crop\" style=\"width:%upx;height:%upx\"><img src=\"", 2 * w,
                  2 * h);
    std::string html = style + escape(src);
    std::snprintf(style, sizeof style, "\" style=\"width:%upx;height:%upx;left:-%upx;top:-%upx\" alt=\"", 2 * s.width,
                  2 * s.height, s.width - w, s.height - h);
    return html + style + escape(caption) + "\"></div><figcaption>" + escape(caption) + "</figcaption></figure>\n";
}

// Per point, the titles of the metrics on whose Pareto front it is ("RMSE, SSIM").
std::vector<std::string> frontsOf(const std::vector<const SweepPoint*>& points) {
    std::vector<std::string> fronts(points.size());
    for (const auto& metric : sweepMetrics())
        for (size_t i : paretoFront(points, metric)) fronts[i] += (fronts[i].empty() ? "" : ", ") + std::string(metric.title);
    return fronts;
}

// Noisy | every configuration on some metric's front, fastest first | reference.
std::string crops(const SweepResult& r, const SweepSource& s, const SweepReportFiles& files,
                  const std::vector<const SweepPoint*>& points, const std::vector<std::string>& fronts) {
    std::vector<size_t> shown;
    for (size_t i = 0; i < points.size(); ++i)
        if (!fronts[i].empty()) shown.push_back(i);
    std::stable_sort(shown.begin(), shown.end(), [&](size_t a, size_t b) { return points[a]->gpuMs < points[b]->gpuMs; });
    std::string html = crop(s, files.image(s, "noisy"), "noisy input");
    for (size_t i : shown)
        html += crop(s, files.image(s, points[i]->config), r.config(points[i]->config).label + " (front: " + fronts[i] + ")");
    return html + crop(s, files.image(s, "reference"), "reference");
}

std::string table(const SweepResult& r, const SweepSource& s, const std::vector<const SweepPoint*>& points,
                  const std::vector<size_t>& front, const std::vector<std::string>& fronts) {
    std::string html = "<table><tr><th></th><th>configuration</th><th>GPU ms</th><th>MiB</th><th>RMSE</th>"
                       "<th>relMSE</th><th>PSNR dB</th><th>SSIM</th><th>temporal</th><th>ghosting</th><th>flicker</th><th>lag</th><th>on the front of</th></tr>\n";
    char row[1024];
    std::snprintf(row, sizeof row, "<tr><td></td><td>noisy input</td><td>-</td><td>-</td><td>%.4f</td><td>%.4f</td>"
                  "<td>%.2f</td><td>%.4f</td><td>%.5f</td><td>%s</td><td>%s</td><td>-</td><td></td></tr>\n",
                  s.noisy.rmse, s.noisy.relMse, s.noisy.psnr, s.noisy.ssim, s.noisy.temporal,
                  ratioText(s.noisy.ghosting).c_str(), ratioText(s.noisy.flicker).c_str());
    html += row;
    for (size_t i = 0; i < points.size(); ++i) {
        const auto& p = *points[i];
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        std::snprintf(row, sizeof row, "<tr%s><td>%s</td><td>%s<br><small>%s</small></td><td>%.2f</td><td>%.1f</td>"
                      "<td>%.4f</td><td>%.4f</td><td>%.2f</td><td>%.4f</td><td>%.5f</td><td>%s</td><td>%s</td><td>%s</td>",
                      onFront ? " class=\"front\"" : "", onFront ? "&#9733;" : "", escape(p.config).c_str(),
                      escape(r.config(p.config).label).c_str(), p.gpuMs, double(p.deviceBytes) / (1024.0 * 1024.0),
                      p.quality.rmse, p.quality.relMse, p.quality.psnr, p.quality.ssim, p.quality.temporal,
                      ratioText(p.quality.ghosting).c_str(), ratioText(p.quality.flicker).c_str(),
                      escape(lagText(p.quality)).c_str());
        html += row + ("<td>" + escape(fronts[i]) + "</td></tr>\n");
    }
    return html + "</table>\n";
}

} // namespace

std::string SweepReportFiles::image(const SweepSource& s, const std::string& folder) const {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04u.png", s.shownFrame);
    return "runs/" + s.key + "/" + folder + "/" + name;
}

std::string sweepHtml(const SweepResult& r, const SweepReportFiles& files) {
    const auto& metric = sweepMetric(r.metric);
    std::string html =
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>hush sweep</title><style>\n"
        "body{font-family:sans-serif;margin:2em;color:#222}table{border-collapse:collapse;margin:1em 0}"
        "td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}td:nth-child(2){text-align:left}"
        "tr.front{background:#fff6d5}figure{display:inline-block;vertical-align:top;margin:0 8px 8px 0}"
        ".crop{overflow:hidden;position:relative}.crop img{position:absolute;image-rendering:pixelated}"
        "figcaption{font-size:12px;max-width:200px}\n</style></head><body>\n<h1>hush sweep</h1>\n";
    html += "<p>GPU time against " + std::string(metric.title) +
            "; the Pareto front (configurations no other beats on both) is ringed in the plot and starred in the "
            "table, which also names every metric whose front a configuration is on; the crops show each of them. Quality is measured on the tonemapped images against the reference, over the frames that "
            "have one. " + std::string(r.complete ? "" : "<b>This sweep is not complete.</b>") + "</p>\n";
    for (const auto& s : r.sources) {
        const auto points = r.pointsOf(s.key);
        const auto front = paretoFront(points, metric);
        const auto fronts = frontsOf(points);
        html += "<h2>" + escape(s.description) + "</h2>\n";
        html += "<a href=\"" + files.plotSvg(s) + "\"><img src=\"" + files.plotPng(s) + "\" alt=\"plot " +
                escape(s.key) + "\" width=\"800\"></a>\n";
        html += table(r, s, points, front, fronts);
        html += "<h3>Frame " + std::to_string(s.shownFrame) + ", centre crop at 2x</h3>\n<div>\n";
        html += crops(r, s, files, points, fronts);
        html += "</div>\n";
    }
    return html + "</body></html>\n";
}

} // namespace hush::cli
