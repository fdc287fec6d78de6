#include <hush/core/arguments.hpp>

#include <charconv>
#include <cmath>

#include <hush/core/error.hpp>

namespace hush::core {

namespace {
bool parseUnsigned(std::string_view text, uint32_t& out) {
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), out);
    return error == std::errc() && end == text.data() + text.size() && !text.empty();
}

[[noreturn]] void bad(std::string_view option, std::string_view text, const std::string& expected) {
    throw Error(ErrorKind::InvalidArgument,
                std::string(option) + " '" + std::string(text) + "' " + expected);
}
} // namespace

bool takeOption(std::span<const std::string_view> args, size_t& i, std::string_view name, std::string& value) {
    const std::string_view arg = args[i];
    if (arg.substr(0, name.size()) != name) return false;
    if (arg.size() > name.size()) {
        if (arg[name.size()] != '=') return false;   // a longer option that merely starts with `name`
        value = std::string(arg.substr(name.size() + 1));
        return true;
    }
    if (i + 1 >= args.size()) throw Error(ErrorKind::InvalidArgument, "option " + std::string(name) + " needs a value");
    value = std::string(args[++i]);
    return true;
}

uint32_t parseCount(std::string_view text, std::string_view option, uint32_t minimum, uint32_t maximum) {
    uint32_t value = 0;
    if (!parseUnsigned(text, value) || value < minimum || value > maximum)
        bad(option, text, "must be a whole number from " + std::to_string(minimum) + " to " + std::to_string(maximum));
    return value;
}

double parseNumber(std::string_view text, std::string_view option, double minimum, double maximum) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty() || !std::isfinite(value) ||
        value < minimum || value > maximum)
        bad(option, text, "must be a number from " + std::to_string(minimum) + " to " + std::to_string(maximum));
    return value;
}

Size2D parseSize(std::string_view text, std::string_view option, uint32_t maxSide, bool square) {
    Size2D size;
    const size_t x = text.find('x');
    const bool ok = x == std::string_view::npos
                        ? square && parseUnsigned(text, size.width) && (size.height = size.width, true)
                        : parseUnsigned(text.substr(0, x), size.width) && parseUnsigned(text.substr(x + 1), size.height);
    if (!ok || size.width == 0 || size.height == 0 || size.width > maxSide || size.height > maxSide)
        bad(option, text, std::string("is not a size like 640x360") + (square ? " or 256" : "") + " (1 to " +
                              std::to_string(maxSide) + " each)");
    return size;
}

std::vector<std::string> splitList(std::string_view text, char separator) {
    std::vector<std::string> items;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find(separator, start), text.size());
        if (end > start) items.emplace_back(text.substr(start, end - start));
        start = end + 1;
    }
    return items;
}

} // namespace hush::core
