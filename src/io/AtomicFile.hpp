#pragma once
/// Crash-safe file output: a reader (ParaView, a restart) sees either the old or the new content, never a
/// half-written file. Used for case.pvd, uniform/time and the .vtp files.

#include <filesystem>
#include <string>

namespace poro {

/// Writes `content` to `path` atomically: writes a temporary sibling `.<name>.tmp.<pid>`, flushes and
/// fsyncs it, then renames it over `path`. Throws OutputError naming the path and the OS reason; the
/// temporary file is removed on failure.
void writeFileAtomically(const std::filesystem::path& path, const std::string& content);

/// Replaces the directory (or file) `to` by `from` so that `to` is complete at every moment: an existing `to`
/// is exchanged with `from` in one step (renameat2 RENAME_EXCHANGE) and then deleted; where the file system
/// cannot exchange, it is renamed aside to `.<name>.old` first and put back if the rename fails. Throws
/// OutputError; after a failure `to` is as it was.
void renameAtomically(const std::filesystem::path& from, const std::filesystem::path& to);

/// The temporary sibling writeFileAtomically uses for `path`: `<dir>/.<name>.tmp.<pid>`.
/// For writers that must create the file themselves (VTK); finish with commitTemporaryFile.
std::filesystem::path temporarySibling(const std::filesystem::path& path);

/// Fsyncs the already written and closed file `temporary` and renames it over `path`. On failure removes
/// `temporary` and throws OutputError naming `path` and the OS reason.
void commitTemporaryFile(const std::filesystem::path& temporary, const std::filesystem::path& path);

} // namespace poro
