#include "text_parse.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <system_error>

#include <hush/core/read_file.hpp>
#include <hush/tracer/obj_loader.hpp>

namespace hush::tracer {

FileText readTextFile(const std::string& path) {
    return FileText{path, core::readFile(path)};
}

FileReader folderReader(const std::string& folder) {
    return [folder](const std::string& written) {
        return readTextFile((std::filesystem::path(folder) / written).lexically_normal().string());
    };
}

} // namespace hush::tracer

namespace hush::tracer::detail {

bool LineReader::next(std::string_view& line) {
    if (done_) return false;
    const std::size_t end = rest_.find('\n');
    if (end == std::string_view::npos) {
        // The last line: present even without a final newline, absent when the text
        // ends with one (rest_ is then empty).
        done_ = true;
        if (rest_.empty()) return false;
        line = rest_;
        rest_ = {};
    } else {
        line = rest_.substr(0, end);
        rest_.remove_prefix(end + 1);
    }
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    ++line_;
    return true;
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

std::string_view stripComment(std::string_view line) {
    for (std::size_t i = 0; i < line.size(); ++i)
        if (line[i] == '#' && (i == 0 || isSpace(line[i - 1]))) return line.substr(0, i);
    return line;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && isSpace(s.front())) s.remove_prefix(1);
    while (!s.empty() && isSpace(s.back())) s.remove_suffix(1);
    return s;
}

std::string_view nextToken(std::string_view& rest) {
    std::size_t begin = 0;
    while (begin < rest.size() && isSpace(rest[begin])) ++begin;
    std::size_t end = begin;
    while (end < rest.size() && !isSpace(rest[end])) ++end;
    const std::string_view token = rest.substr(begin, end - begin);
    rest.remove_prefix(end);
    return token;
}

bool parseFloat(std::string_view token, float& out) {
    // from_chars rejects a leading '+', which some exporters write; take one, but not "+-1".
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
        if (token.empty() || token.front() == '-' || token.front() == '+') return false;
    }
    if (token.empty()) return false;
    // Parse as double so that float subnormals ("1e-40") are accepted; a double out
    // of range (1e999, 1e-999) is an error rather than a silent inf or 0.
    double value = 0.0;
    const char* last = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), last, value, std::chars_format::general);
    if (ec != std::errc() || ptr != last || !std::isfinite(value)) return false;
    if (std::fabs(value) > static_cast<double>(std::numeric_limits<float>::max())) return false;
    out = static_cast<float>(value);
    return true;
}

bool parseInt(std::string_view token, std::int64_t& out) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1);
        if (token.empty() || token.front() == '-' || token.front() == '+') return false;
    }
    if (token.empty()) return false;
    const char* last = token.data() + token.size();
    const auto [ptr, ec] = std::from_chars(token.data(), last, out);
    return ec == std::errc() && ptr == last;
}

std::string quote(std::string_view token) {
    constexpr std::size_t kMax = 40;
    std::string s = "'";
    for (std::size_t i = 0; i < token.size() && i < kMax; ++i) {
        const auto c = static_cast<unsigned char>(token[i]);
        if (c >= 0x20 && c < 0x7f) {
            s += static_cast<char>(c);
        } else {
            static constexpr char kHex[] = "0123456789abcdef";
            s += "\\x";
            s += kHex[c >> 4];
            s += kHex[c & 15];
        }
    }
    if (token.size() > kMax) s += "...";
    return s + "'";
}

void failAt(ErrorKind kind, const std::string& name, std::size_t line, const std::string& what) {
    throw Error(kind, name + ":" + std::to_string(line) + ": " + what);
}

std::string fileStem(const std::string& name) {
    const std::string stem = std::filesystem::path(name).stem().string();
    return stem.empty() ? std::string("mesh") : stem;
}

} // namespace hush::tracer::detail
