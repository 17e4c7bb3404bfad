#pragma once
// Whole-file reads and atomic writes. Every output Metrofit writes goes through writeFileAtomic:
// a temporary file in the same folder, written, flushed and fsync'ed, then renamed over the
// target, so a crash or a kill at any point leaves either the old file or the new one, never a
// half-written one (docs/file-formats.md#exit-status-and-output, STYLE.md §7).
#include <cstddef>
#include <string>
#include <string_view>

namespace metrofit {

/// Reads a whole file; FileError naming the path when it is missing, a folder, unreadable or
/// larger than maxBytes. The path "-" is standard input
/// (docs/file-formats.md#csv-dialects-and-standard-input: `-` as a file name), read to its end on the first
/// call and kept, so later reads of "-" in the same process (a reader that sniffs the format, then parses)
/// get the same text.
std::string readFile(const std::string& path, std::size_t maxBytes = std::size_t{1} << 30);

/// The name of a path in messages: "<stdin>" for "-", else the path itself.
std::string displayPath(const std::string& path);

/// Writes `content` to `path` atomically (see above); FileError on failure (the target is untouched
/// and no temporary file is left behind). A target that exists and is not a regular file (a device
/// such as /dev/null, a FIFO) is written directly: it has no old content to protect and must not be
/// replaced by a regular file.
void writeFileAtomic(const std::string& path, std::string_view content);

/// The folder part of a path ("." when there is none).
std::string parentFolder(const std::string& path);
/// Joins a folder and a relative path; absolute `rel` is returned unchanged.
std::string joinPath(const std::string& folder, const std::string& rel);

}  // namespace metrofit
