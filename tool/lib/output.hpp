// Output (phase 7), writing generated files: atomically (temp file + rename) and only when the
// content changed, so builds do not cascade and an error never leaves half a
// file behind.
#pragma once

#include <string>
#include <vector>

namespace dpgen {

struct PendingFile {
  std::string path;
  std::string content;
};

/// Writes every file whose content differs from what is on disk. Returns false
/// and sets `error` if a write fails; files already replaced stay valid.
bool write_if_changed(const std::vector<PendingFile>& files, std::string& error,
                      int* written = nullptr);

} // namespace dpgen
