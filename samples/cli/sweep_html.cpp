// report.html: per frame source the plot, the table (front rows marked) and
// side-by-side crops of the last scored frame: noisy | each front configuration |
// reference, each labelled. The crops are the frame's own PNGs shown through a CSS
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
    char html[1024];
    std::snprintf(html, sizeof html,
                  "<figure><div class=\"crop\" style=\"width:%upx;height:%upx\"><img src=\"%s\" "
                  "style=\"width:%upx;height:%upx;left:-%upx;top:-%upx\" alt=\"%s\"></div>"
                  "<figcaption>%s</figcaption></figure>\n",
                  2 * w, 2 * h, escape(src).c_str(), 2 * s.width, 2 * s.height, s.width - w, s.height - h,
                  escape(caption).c_str(), escape(caption).c_str());
    return html;
}

std::string table(const SweepResult& r, const SweepSource& s, const std::vector<const SweepPoint*>& points,
                  const std::vector<size_t>& front) {
    std::string html = "<table><tr><th></th><th>configuration</th><th>GPU ms</th><th>MiB</th><th>RMSE</th>"
                       "<th>relMSE</th><th>PSNR dB</th><th>SSIM</th><th>temporal</th><th>ghosting</th><th>flicker</th><th>lag</th></tr>\n";
    char row[1024];
    std::snprintf(row, sizeof row, "<tr><td></td><td>noisy input</td><td>-</td><td>-</td><td>%.4f</td><td>%.4f</td>"
                  "<td>%.2f</td><td>%.4f</td><td>%.5f</td><td>%s</td><td>%s</td><td>-</td></tr>\n",
                  s.noisy.rmse, s.noisy.relMse, s.noisy.psnr, s.noisy.ssim, s.noisy.temporal,
                  ratioText(s.noisy.ghosting).c_str(), ratioText(s.noisy.flicker).c_str());
    html += row;
    for (size_t i = 0; i < points.size(); ++i) {
        const auto& p = *points[i];
        const bool onFront = std::find(front.begin(), front.end(), i) != front.end();
        std::snprintf(row, sizeof row, "<tr%s><td>%s</td><td>%s<br><small>%s</small></td><td>%.2f</td><td>%.1f</td>"
                      "<td>%.4f</td><td>%.4f</td><td>%.2f</td><td>%.4f</td><td>%.5f</td><td>%s</td><td>%s</td><td>%s</td></tr>\n",
                      onFront ? " class=\"front\"" : "", onFront ? "&#9733;" : "", escape(p.config).c_str(),
                      escape(r.config(p.config).label).c_str(), p.gpuMs, double(p.deviceBytes) / (1024.0 * 1024.0),
                      p.quality.rmse, p.quality.relMse, p.quality.psnr, p.quality.ssim, p.quality.temporal,
                      ratioText(p.quality.ghosting).c_str(), ratioText(p.quality.flicker).c_str(),
                      escape(lagText(p.quality)).c_str());
        html += row;
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
            "table. Quality is measured on the tonemapped images against the reference, over the frames that "
            "have one. " + std::string(r.complete ? "" : "<b>This sweep is not complete.</b>") + "</p>\n";
    for (const auto& s : r.sources) {
        const auto points = r.pointsOf(s.key);
        const auto front = paretoFront(points, metric);
        html += "<h2>" + escape(s.description) + "</h2>\n";
        html += "<a href=\"" + files.plotSvg(s) + "\"><img src=\"" + files.plotPng(s) + "\" alt=\"plot " +
                escape(s.key) + "\" width=\"800\"></a>\n";
        html += table(r, s, points, front);
        html += "<h3>Frame " + std::to_string(s.shownFrame) + ", centre crop at 2x</h3>\n<div>\n";
        html += crop(s, files.image(s, "noisy"), "noisy input");
        for (size_t i : front) html += crop(s, files.image(s, points[i]->config), r.config(points[i]->config).label);
        html += crop(s, files.image(s, "reference"), "reference");
        html += "</div>\n";
    }
    return html + "</body></html>\n";
}

} // namespace hush::cli
