// Reading files the user names (scene files, models, their buffers, sky
// faces, shader sources) so that no path can hang or flood the program.
//
// A path may name anything: a FIFO, whose open() waits for a writer forever;
// /dev/zero or /dev/urandom, which never end; a socket; a link to nothing or
// a loop of links. Only regular files are read. The type is checked with
// stat() before opening, and again with fstat() on the descriptor, which is
// opened with O_NONBLOCK so that a file swapped for a FIFO in between still
// cannot block. Reads stop one byte past the caller's limit.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace swell::detail {

// Checks that `path` is a regular file that can be opened for reading.
// Throws InputError whose place is `path` and whose message reads
// "cannot read the WHAT: it is a FIFO (named pipe), not a regular file", or
// "WHAT not found", and so on. `what` names the file's role ("scene file").
void checkInputFile(const std::filesystem::path& path, const std::string& what);

// The bytes of the regular file at `path`, at most `maxBytes` of them.
// Throws InputError as checkInputFile, and when the file is larger.
std::string readInputFile(const std::filesystem::path& path, std::uintmax_t maxBytes, const std::string& what);

} // namespace swell::detail
