#pragma once
// Private helpers shared by the OBJ and MTL parsers: line splitting that copes with
// \n, \r\n and a missing final newline; whitespace tokens; strict number parsing;
// and "file:line: message" errors. Everything works on string_views into the
// caller's buffer and never reads past its end.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <hush/core/error.hpp>

namespace hush::tracer::detail {

// Walks a text one line at a time. Lines come without their terminator and without
// a trailing '\r'; line numbers start at 1.
class LineReader {
public:
    explicit LineReader(std::string_view text) : rest_(text) {}
    bool next(std::string_view& line);
    std::size_t lineNumber() const { return line_; }

private:
    std::string_view rest_;
    std::size_t line_ = 0;
    bool done_ = false;
};

bool isSpace(char c);
// Cuts a comment off a line: '#' at the start of the line or after whitespace, so
// that "f 1 2 3 # note" works while names like "mat#1" stay whole.
std::string_view stripComment(std::string_view line);
std::string_view trim(std::string_view s);
// Removes and returns the first whitespace-separated token of `rest` (empty: none left).
std::string_view nextToken(std::string_view& rest);

// The whole token must be a finite number that fits a float (a leading '+' is
// allowed; "nan", "inf" and hex are not).
bool parseFloat(std::string_view token, float& out);
// The whole token must be a decimal integer within int64 (a leading '+' or '-' is allowed).
bool parseInt(std::string_view token, std::int64_t& out);

// A token as it should appear in a message: quoted, at most 40 bytes, with bytes
// that are not printable ASCII written as \xNN (fuzzed input ends up in messages).
std::string quote(std::string_view token);

// Throws hush::Error "name:line: what".
[[noreturn]] void failAt(ErrorKind kind, const std::string& name, std::size_t line, const std::string& what);

// "folder/name.ext" -> "name": meshes outside any o/g statement are named after their file.
std::string fileStem(const std::string& name);

} // namespace hush::tracer::detail
