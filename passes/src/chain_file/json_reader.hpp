#pragma once
// Reading a chain file's JSON with errors that name the file and the JSON path
// ("chain.json: nodes[2].settings.sigmaL: ..."). Objects are read by binding each
// known key to a variable; finish() rejects any key left unread, listing the known
// ones, so a misspelt setting never silently keeps its default.
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace hush::passes::chain_file {

using Json = nlohmann::json;

// Parses text (comments allowed); a syntax error names source:line:column.
Json parse(std::string_view text, const std::string& source);

[[noreturn]] void fail(const std::string& source, const std::string& path, const std::string& what);

class ObjectReader {
public:
    // Throws unless `value` is an object.
    ObjectReader(const Json& value, std::string source, std::string path);

    bool has(std::string_view key) const { return value_.contains(key); }
    std::string path(std::string_view key) const;
    const std::string& source() const { return source_; }

    // Each reads `key` if present (marking it known), checking type and range.
    void read(std::string_view key, float& out, float lo, float hi);
    void read(std::string_view key, uint32_t& out, uint32_t lo, uint32_t hi);
    void read(std::string_view key, bool& out);
    void read(std::string_view key, std::string& out);
    // The raw value (nullptr when absent), marking the key known.
    const Json* child(std::string_view key);
    // Marks a key as known without reading it.
    void allow(std::string_view key) { known_.emplace_back(key); }
    // Throws on the first key that nothing read or allowed.
    void finish() const;

private:
    const Json& value_;
    std::string source_, path_;
    std::vector<std::string> known_;
};

} // namespace hush::passes::chain_file
