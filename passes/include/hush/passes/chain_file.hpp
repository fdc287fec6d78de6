#pragma once
// Chains by name or from a JSON file (docs/passes/chain-files.md), so that a user
// composes a denoiser without C++:
//   { "base": "svgf", "settings": { "atrous": { "iterations": 3 } } }
// or, node by node,
//   { "name": "mine", "nodes": [ { "id": "demod", "node": "demodulate",
//       "inputs": { "radiance": "input.color", "albedo": "input.albedo" } }, ... ],
//     "outputs": { "display": "tonemap", "radiance": "remod" } }
// Every error names the file, the JSON path and what is wrong: an unknown node type,
// field or port, a reference to a node not defined before, a missing output.
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <hush/passes/chain.hpp>

namespace hush::passes {

// "svgf", "eaw", "bmfr": the built-in chains with the papers' defaults.
std::vector<std::string> builtinChainNames();
// A built-in chain by name, or nullptr.
std::unique_ptr<Chain> makeBuiltinChain(std::string_view name);

// Parses a chain description; `source` names it in errors (a file name).
std::unique_ptr<Chain> parseChainJson(std::string_view text, const std::string& source);
// A chain file with "base" gives the built-in chain wrapped under the file's name
// ("name", else the file stem); this returns the built-in chain inside (for its
// settings), or `chain` itself.
const Chain& unwrapChain(const Chain& chain);
// Reads and parses a chain file; hush::Error (NotFound) names a missing file.
std::unique_ptr<Chain> loadChainFile(const std::string& path);
// A built-in name, else a file path.
std::unique_ptr<Chain> makeChain(const std::string& nameOrPath);

// A chain's name names its output folder and its entries in reports, so it is
// restricted to 1 to 64 letters, digits, '-', '_' and '.', not starting with '.':
// no path separator, no "..", nothing outside the output folder.
bool isValidChainName(std::string_view name);
inline constexpr std::string_view kChainNameRule =
    "1 to 64 letters, digits, '-', '_' and '.', not starting with '.'";

// The node types a chain file may use, with their ports, for `hush denoise --help`.
std::string describeChainNodes();

} // namespace hush::passes
