// Progress lines and output folders shared by the examples.
#pragma once

#include "dpgen/train.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

namespace dpgen_examples {

/// One line per iteration: iteration, loss, gradient norm, time.
inline void print_progress(const dpgen::TrainProgress& p) {
  std::printf("iter %4d  loss %.6e  |grad| %.3e  %.4f s\n", p.iteration, p.loss, p.grad_norm,
              p.seconds);
  std::fflush(stdout);
}

/// Creates `dir` (and parents); returns it with a trailing slash.
inline std::string output_dir(const std::string& dir) {
  std::filesystem::create_directories(dir);
  return dir.empty() || dir.back() == '/' ? dir : dir + "/";
}

} // namespace dpgen_examples
