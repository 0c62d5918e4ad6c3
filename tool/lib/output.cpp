// Output (phase 7): atomic write-if-changed (see output.hpp).
#include "output.hpp"

#include <llvm/Support/FileSystem.h>
#include <llvm/Support/MemoryBuffer.h>
#include <llvm/Support/raw_ostream.h>

namespace dpgen {

bool write_if_changed(const std::vector<PendingFile>& files, std::string& error, int* written) {
  if (written)
    *written = 0;
  for (const auto& f : files) {
    auto existing = llvm::MemoryBuffer::getFile(f.path);
    if (existing && (*existing)->getBuffer() == f.content)
      continue;
    // Temp file in the same directory, then rename over the target.
    llvm::SmallString<256> tmp;
    int fd = -1;
    if (auto ec = llvm::sys::fs::createUniqueFile(f.path + ".tmp-%%%%%%", fd, tmp)) {
      error = f.path + ": cannot create a temporary file: " + ec.message();
      return false;
    }
    {
      llvm::raw_fd_ostream os(fd, /*shouldClose=*/true);
      os << f.content;
      os.close();
      if (os.has_error()) {
        error = f.path + ": write failed: " + os.error().message();
        os.clear_error();
        llvm::sys::fs::remove(tmp);
        return false;
      }
    }
    if (auto ec = llvm::sys::fs::rename(tmp, f.path)) {
      error = f.path + ": cannot replace: " + ec.message();
      llvm::sys::fs::remove(tmp);
      return false;
    }
    if (written)
      ++*written;
  }
  return true;
}

} // namespace dpgen
